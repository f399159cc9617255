// Ray-quadric exam problems in the course's style ("intersect the ray (1, 1, 5) + t(0, 0, −1)
// with the paraboloid x² + y² = z; give t, the point and the normal"). The generator picks a
// surface with small integer parameters and a point on it with simple coordinates (Pythagorean
// quadruples for the sphere, (0.6, 0.8, 0)-style unit vectors for the ellipsoid and cylinder,
// (1, 2, 2)-style points u² + v² − w² = 1 for the hyperboloid), a simple direction, and puts the
// eye a whole number of steps back along it, so t is a whole number; the other root must be a
// multiple of 1/8 too or the problem is drawn again. Now and then the direction is reversed
// (the roots lie behind the eye: a miss, or an eye inside), the ray runs along a paraboloid's
// axis (the linear case), goes through a cone's apex (no normal), or the quadric is placed by
// a translation and an axis scale (solve in model space, carry the normal back).
#include <array>
#include <cmath>

#include "core/format.hpp"
#include "rays/ray_quadric.hpp"

namespace cg {

namespace {

using glm::dvec3;

template <class T, std::size_t N>
const T& pick(Rng& rng, const std::array<T, N>& values) {
    return values[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(N) - 1))];
}

double sign(Rng& rng) {
    return rng.chance(0.5) ? 1.0 : -1.0;
}

dvec3 signs(Rng& rng, dvec3 v) {
    return {sign(rng) * v.x, sign(rng) * v.y, sign(rng) * v.z};
}

// A surface and a point on it, in model space.
dvec3 surface_and_point(Rng& rng, Quadric& q) {
    const std::array<double, 3> small{1, 2, 3};
    switch (q.kind) {
        case QuadricKind::Sphere: {
            // (point, r) with |point| = r.
            static const std::array<std::array<double, 4>, 8> quads{{{0, 0, 1, 1},
                                                                     {1, 2, 2, 3},
                                                                     {0, 3, 4, 5},
                                                                     {2, 3, 6, 7},
                                                                     {1, 4, 8, 9},
                                                                     {4, 4, 7, 9},
                                                                     {0, 0, 2, 2},
                                                                     {2, 0, 0, 2}}};
            const auto& e = pick(rng, quads);
            q.r = e[3];
            dvec3 p{e[0], e[1], e[2]};
            const int rot = static_cast<int>(rng.integer(0, 2));  // a cyclic permutation
            for (int i = 0; i < rot; ++i) p = {p.y, p.z, p.x};
            return signs(rng, p);
        }
        case QuadricKind::Ellipsoid: {
            static const std::array<dvec3, 6> units{
                {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.6, 0.8, 0}, {0, 0.6, 0.8}, {0.8, 0, 0.6}}};
            q.a = pick(rng, std::array<double, 4>{1, 2, 3, 5});
            q.b = pick(rng, std::array<double, 4>{1, 2, 3, 5});
            q.c = pick(rng, std::array<double, 4>{1, 2, 3, 5});
            const dvec3 u = signs(rng, pick(rng, units));
            return {q.a * u.x, q.b * u.y, q.c * u.z};
        }
        case QuadricKind::Paraboloid: {
            q.p = pick(rng, std::array<double, 3>{1, 1, 2});
            q.q = rng.chance(0.7) ? q.p : pick(rng, small);
            const double u = static_cast<double>(rng.integer(-2, 2)),
                         v = static_cast<double>(rng.integer(-2, 2));
            return {q.p * u, q.q * v, u * u + v * v};
        }
        case QuadricKind::Hyperboloid: {
            static const std::array<dvec3, 6> pts{
                {{1, 0, 0}, {0, 1, 0}, {1, 2, 2}, {2, 1, 2}, {3, 1, 3}, {1, 1, 1}}};
            q.a = pick(rng, std::array<double, 2>{1, 2});
            q.b = rng.chance(0.6) ? q.a : pick(rng, std::array<double, 2>{1, 2});
            q.c = pick(rng, std::array<double, 3>{1, 2, 3});
            const dvec3 u = signs(rng, pick(rng, pts));
            return {q.a * u.x, q.b * u.y, q.c * u.z};
        }
        case QuadricKind::Cone: {
            static const std::array<dvec3, 6> pts{
                {{3, 4, 5}, {4, 3, 5}, {1, 0, 1}, {0, 1, 1}, {0.6, 0.8, 1}, {0, 0, 0}}};
            q.p = pick(rng, std::array<double, 2>{1, 2});
            q.q = rng.chance(0.6) ? q.p : pick(rng, std::array<double, 2>{1, 2});
            q.r = pick(rng, std::array<double, 2>{1, 2});
            const dvec3 u = signs(rng, pick(rng, pts));
            return {q.p * u.x, q.q * u.y, q.r * u.z};
        }
        case QuadricKind::Cylinder: {
            static const std::array<dvec3, 4> pts{
                {{1, 0, 0}, {0, 1, 0}, {0.6, 0.8, 0}, {0.8, 0.6, 0}}};
            q.p = pick(rng, small);
            q.q = rng.chance(0.5) ? q.p : pick(rng, small);
            const dvec3 u = signs(rng, pick(rng, pts));
            return {q.p * u.x, q.q * u.y, static_cast<double>(rng.integer(-2, 2))};
        }
    }
    return {0, 0, 0};
}

bool nice(double t) {
    return std::fabs(t * 8 - std::round(t * 8)) < 1e-9 && std::fabs(t) < 100;
}

std::string matrix_text(const glm::dmat4& m) {
    std::string t = "[";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) t += (c ? " " : "") + num(m[c][r]);
        t += "; ";
    }
    return t + "0 0 0 1]";
}

}  // namespace

RayQuadric::Input RayQuadric::exam_input(Rng& rng) {
    static const std::array<dvec3, 12> directions{{{0, 0, -1},
                                                   {0, 0, 1},
                                                   {1, 0, 0},
                                                   {-1, 0, 0},
                                                   {0, 1, 0},
                                                   {0, -1, 0},
                                                   {1, 1, 0},
                                                   {1, 0, -1},
                                                   {0, 1, -1},
                                                   {-1, -1, -1},
                                                   {1, 2, 2},
                                                   {2, 1, -2}}};
    static const std::array<QuadricKind, 8> kinds{QuadricKind::Sphere,      QuadricKind::Ellipsoid,
                                                  QuadricKind::Paraboloid,  QuadricKind::Paraboloid,
                                                  QuadricKind::Hyperboloid, QuadricKind::Cone,
                                                  QuadricKind::Cylinder,    QuadricKind::Sphere};
    for (int attempt = 0; attempt < 200; ++attempt) {
        Input in;
        Quadric& q = in.quadric;
        q.kind = pick(rng, kinds);
        const dvec3 p = surface_and_point(rng, q);
        dvec3 d = pick(rng, directions);
        if (q.kind == QuadricKind::Paraboloid && rng.chance(0.3)) d = {0, 0, -1};  // the course's
        const double t0 = static_cast<double>(rng.integer(1, 5));
        dvec3 o = p - t0 * d;
        if (rng.chance(0.1)) d = -d;  // roots behind the eye
        if (rng.chance(0.2)) {        // placed by a translation and an axis scale
            glm::dmat4 m(1.0);
            for (int i = 0; i < 3; ++i) {
                m[i][i] = pick(rng, std::array<double, 3>{1, 1, 2});
                m[3][i] = static_cast<double>(rng.integer(-2, 2));
            }
            q.world_from_model = m;
            o = dvec3(m * glm::dvec4(o, 1.0));
            d = dvec3(m * glm::dvec4(d, 0.0));
        }
        in.origin = o;
        in.direction = d;
        const QuadricHit h = solve(in);
        bool ok = h.root_count > 0;
        for (int i = 0; i < h.root_count; ++i) ok = ok && nice(h.roots[i]);
        if (ok) return in;
    }
    Input in;  // the course's own problem
    in.quadric.kind = QuadricKind::Paraboloid;
    in.origin = {1, 1, 5};
    in.direction = {0, 0, -1};
    return in;
}

std::string RayQuadric::question(const Input& in) {
    const Quadric& q = in.quadric;
    std::string s = "Intersect the ray " + num(in.origin) + " + t·" + num(in.direction) +
                    " with the " + quadric_kind_name(q.kind) + " " + quadric_equation(q, false);
    if (q.world_from_model != glm::dmat4(1.0))
        s += " (given in model space, placed in the world by M = " +
             matrix_text(q.world_from_model) + ")";
    if (std::isfinite(q.zmin) || std::isfinite(q.zmax))
        s += ", cut to " + num(q.zmin) + " ≤ z ≤ " + num(q.zmax) + " in model space";
    s += ". Is there a hit with t > 0 (hit)? Give the nearest such t, the point P = E + t·d "
         "(point) and the unit normal n along the gradient of F (normal) — null where there is "
         "none.";
    return s;
}

std::vector<std::string> RayQuadric::answer_fields() {
    return {"hit", "t", "point", "normal"};
}

}  // namespace cg
