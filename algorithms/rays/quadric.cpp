// Sections: [kinds] [coefficients and preparation] [validate] [intersection]
#include "rays/quadric.hpp"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <vector>

#include "core/format.hpp"
#include "core/step.hpp"

namespace cg {

using glm::dmat3;
using glm::dvec3;

// ---- [kinds] --------------------------------------------------------------------------------

const char* quadric_kind_id(QuadricKind k) {
    switch (k) {
        case QuadricKind::Sphere:
            return "sphere";
        case QuadricKind::Ellipsoid:
            return "ellipsoid";
        case QuadricKind::Paraboloid:
            return "paraboloid";
        case QuadricKind::Hyperboloid:
            return "hyperboloid";
        case QuadricKind::Cone:
            return "cone";
        case QuadricKind::Cylinder:
            return "cylinder";
    }
    return "?";
}

const char* quadric_kind_name(QuadricKind k) {
    switch (k) {
        case QuadricKind::Sphere:
            return "sphere";
        case QuadricKind::Ellipsoid:
            return "ellipsoid";
        case QuadricKind::Paraboloid:
            return "elliptic paraboloid";
        case QuadricKind::Hyperboloid:
            return "hyperboloid of one sheet";
        case QuadricKind::Cone:
            return "elliptic cone";
        case QuadricKind::Cylinder:
            return "elliptic cylinder";
    }
    return "?";
}

// ---- [coefficients and preparation] ---------------------------------------------------------

QuadricCoefficients coefficients(const Quadric& s) {
    auto inv2 = [](double v) { return 1 / (v * v); };
    switch (s.kind) {
        case QuadricKind::Sphere:
            return {1, 1, 1, 0, -s.r * s.r};
        case QuadricKind::Ellipsoid:
            return {inv2(s.a), inv2(s.b), inv2(s.c), 0, -1};
        case QuadricKind::Paraboloid:
            return {inv2(s.p), inv2(s.q), 0, -1, 0};
        case QuadricKind::Hyperboloid:
            return {inv2(s.a), inv2(s.b), -inv2(s.c), 0, -1};
        case QuadricKind::Cone:
            return {inv2(s.p), inv2(s.q), -inv2(s.r), 0, 0};
        case QuadricKind::Cylinder:
            return {inv2(s.p), inv2(s.q), 0, 0, -1};
    }
    return {};
}

PreparedQuadric prepare(const Quadric& s) {
    PreparedQuadric p;
    p.f = coefficients(s);
    p.zmin = s.zmin;
    p.zmax = s.zmax;
    p.transformed = s.world_from_model != glm::dmat4(1.0);
    if (p.transformed) {
        const dmat3 linear(s.world_from_model);
        p.linear_inv = glm::inverse(linear);
        p.translation = dvec3(s.world_from_model[3]);
    }
    return p;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

struct NamedParam {
    const char* name;
    double value;
};

std::vector<NamedParam> params_of(const Quadric& s) {
    switch (s.kind) {
        case QuadricKind::Sphere:
            return {{"r", s.r}};
        case QuadricKind::Ellipsoid:
        case QuadricKind::Hyperboloid:
            return {{"a", s.a}, {"b", s.b}, {"c", s.c}};
        case QuadricKind::Paraboloid:
        case QuadricKind::Cylinder:
            return {{"p", s.p}, {"q", s.q}};
        case QuadricKind::Cone:
            return {{"p", s.p}, {"q", s.q}, {"r", s.r}};
    }
    return {};
}

}  // namespace

void validate_quadric(const Quadric& s, const std::string& prefix) {
    for (const NamedParam& np : params_of(s)) {
        const std::string field = prefix + ".params." + np.name;
        if (!std::isfinite(np.value))
            throw InputError(field, "must be a finite number (got " + given(np.value) + ")");
        if (np.value <= 0)
            throw InputError(
                field, "must be positive: it is a semi-axis length (got " + given(np.value) + ")");
        // 1/v² must be a normal, finite number.
        const double inv = 1 / (np.value * np.value);
        if (!std::isfinite(inv) || inv == 0 || !std::isnormal(np.value * np.value))
            throw InputError(field,
                             "is too large or too small to square (got " + given(np.value) + ")");
    }
    const glm::dmat4& m = s.world_from_model;  // m[column][row]
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(m[c][r]))
                throw InputError(
                    prefix + ".transform[" + std::to_string(r) + "][" + std::to_string(c) + "]",
                    "must be a finite number (got " + given(m[c][r]) + ")");
    if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1)
        throw InputError(prefix + ".transform[3]",
                         "must be [0, 0, 0, 1]: the model transform must be affine (got [" +
                             given(m[0][3]) + ", " + given(m[1][3]) + ", " + given(m[2][3]) + ", " +
                             given(m[3][3]) + "])");
    const dmat3 linear(m);
    const double det = glm::determinant(linear);
    // Hadamard's bound: |det| ≤ |col0||col1||col2|. A determinant far below it is a matrix
    // that squashes space flat up to round-off.
    const double bound = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    if (!(std::fabs(det) > 1e-12 * bound) || !std::isfinite(det))
        throw InputError(prefix + ".transform",
                         "is singular (determinant " + given(det) +
                             "): it flattens space, so rays cannot be carried into model space");
    const dmat3 inv = glm::inverse(linear);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(inv[c][r]))
                throw InputError(prefix + ".transform", "cannot be inverted in double precision");
    if (std::isnan(s.zmin) || s.zmin == Quadric::kInf)
        throw InputError(prefix + ".zmin", "must be a finite number (got " + given(s.zmin) + ")");
    if (std::isnan(s.zmax) || s.zmax == -Quadric::kInf)
        throw InputError(prefix + ".zmax", "must be a finite number (got " + given(s.zmax) + ")");
    if (!(s.zmin < s.zmax))
        throw InputError(prefix + ".zmax", "must be greater than zmin (" + given(s.zmax) + " ≤ " +
                                               given(s.zmin) + "): the slab is empty");
}

// ---- [intersection] -------------------------------------------------------------------------

RayQuadratic ray_quadratic(const PreparedQuadric& s, dvec3 origin, dvec3 direction) {
    // The result is assembled at the end from locals rather than default-initialised and then
    // filled in: GCC cleared the default-initialised struct with `rep stos` on every call (about
    // 30 cycles, in the tracer's innermost loop).
    dvec3 o = origin, d = direction;
    if (s.transformed) {
        o = s.linear_inv * (origin - s.translation);
        d = s.linear_inv * direction;
    }
    const QuadricCoefficients& f = s.f;
    const double ax = f.A * d.x * d.x, ay = f.B * d.y * d.y, az = f.C * d.z * d.z;
    const double a = ax + ay + az;
    const double a_size = std::fabs(ax) + std::fabs(ay) + std::fabs(az);
    const double bx = 2 * f.A * o.x * d.x, by = 2 * f.B * o.y * d.y, bz = 2 * f.C * o.z * d.z,
                 bd = f.D * d.z;
    const double b = bx + by + bz + bd;
    const double b_size = std::fabs(bx) + std::fabs(by) + std::fabs(bz) + std::fabs(bd);
    return RayQuadratic{o, d, a, b, eval_F(f, o), a_size, b_size};
}

QuadraticRoots solve_quadratic(const RayQuadratic& q) {
    QuadraticRoots r;
    const double a = std::fabs(q.a) <= kRelZero * q.a_size ? 0.0 : q.a;
    const double b = std::fabs(q.b) <= kRelZero * q.b_size ? 0.0 : q.b;
    if (a == 0) {
        if (b != 0) {
            r.kind = QuadraticCase::Linear;
            r.t[0] = -q.c / b;
            r.count = 1;
        } else {
            r.kind = q.c == 0 ? QuadraticCase::InSurface : QuadraticCase::NoSolution;
        }
        return r;
    }
    const double b2 = b * b, ac4 = 4 * a * q.c;
    double disc = b2 - ac4;
    if (std::fabs(disc) <= kRelZero * (b2 + std::fabs(ac4))) disc = 0;
    r.discriminant = disc;
    if (disc < 0) {
        r.kind = QuadraticCase::NoRoots;
        return r;
    }
    if (disc == 0) {
        r.kind = QuadraticCase::Tangent;
        r.t[0] = -b / (2 * a);
        r.count = 1;
        return r;
    }
    r.kind = QuadraticCase::TwoRoots;
    // q = −(b + sign(b)√Δ)/2 adds numbers of one sign, so it loses nothing; the roots are
    // q/a and c/q (their product is c/a). q ≠ 0 since Δ > 0.
    const double h = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double t0 = h / a, t1 = q.c / h;
    if (t0 > t1) std::swap(t0, t1);
    r.t = {t0, t1};
    r.count = 2;
    return r;
}

[[gnu::flatten]] QuadricHit intersect(const PreparedQuadric& s, dvec3 origin, dvec3 direction,
                                      double t_min) {
    QuadricHit h;
    const RayQuadratic q = ray_quadratic(s, origin, direction);
    const QuadraticRoots roots = solve_quadratic(q);
    h.roots = roots.t;
    h.root_count = roots.count;
    for (int i = 0; i < roots.count; ++i) {
        const double t = roots.t[i];
        if (!(t > t_min)) continue;
        const double z = q.origin.z + t * q.direction.z;
        if (z < s.zmin || z > s.zmax) continue;
        h.hit = true;
        h.t = t;
        h.point = origin + t * direction;
        const dvec3 g = gradient(s.f, q.origin + t * q.direction);
        h.normal = unit(s.transformed ? g * s.linear_inv : g);
        h.has_normal = h.normal != dvec3(0.0);
        break;
    }
    return h;
}

double intersect_t(const PreparedQuadric& s, dvec3 origin, dvec3 direction, double t_min) {
    const RayQuadratic q = ray_quadratic(s, origin, direction);
    const QuadraticRoots roots = solve_quadratic(q);
    for (int i = 0; i < roots.count; ++i) {
        const double t = roots.t[i];
        if (!(t > t_min)) continue;
        const double z = q.origin.z + t * q.direction.z;
        if (z < s.zmin || z > s.zmax) continue;
        return t;
    }
    return Quadric::kInf;
}

dvec3 normal_at(const PreparedQuadric& s, dvec3 world_point) {
    if (!s.transformed) return unit(gradient(s.f, world_point));
    const dvec3 g = gradient(s.f, s.linear_inv * (world_point - s.translation));
    return unit(g * s.linear_inv);
}

QuadricHit intersect(const Quadric& s, dvec3 origin, dvec3 direction, double t_min) {
    return intersect(prepare(s), origin, direction, t_min);
}

}  // namespace cg
