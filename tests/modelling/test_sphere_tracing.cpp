// Sphere tracing: hand-worked marches toward one sphere (head-on, off-centre, passing beside
// it, starting inside); an independent long-double reference for where the ray first meets the
// scene — the ray–sphere quadratic, the slab test for boxes (rays parallel to a face included),
// the torus's quartic (x²+y²+z²+R²−r²)² = 4R²(x²+z²) located by a fine scan and bisection —
// combined as interval lists along the ray (union, intersection, difference), and for the
// smooth union a scan of its long-double field; the distances themselves against formulas
// written apart (the closest point of a box by clamping, of a torus's centre circle by
// projection). On 4,000 seeded random scenes and rays, including grazing rays, rays starting
// inside, rays lying in a box face's plane, tiny and large ε and short max_distance: a hit is
// within ε and never beyond the true first intersection; an escape never skipped one; on a
// single sphere or box hit cleanly the hit is within ε/cos θ before it. The smooth union
// under-estimates (below the plain minimum, 1-Lipschitz). The state machine against compute;
// replay; errors naming the field; the exam against a long-double march.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "modelling/sphere_tracing.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::SphereTracing;
using Input = SphereTracing::Input;
using Shape = SphereTracing::Shape;
using Kind = SphereTracing::Kind;
using Combine = SphereTracing::Combine;
using Outcome = SphereTracing::Outcome;
using LD = long double;

namespace {

struct V {
    LD x = 0, y = 0, z = 0;
};
V operator+(V a, V b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V operator-(V a, V b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V operator*(LD s, V a) {
    return {s * a.x, s * a.y, s * a.z};
}
LD dot(V a, V b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
LD len(V a) {
    return std::sqrt(dot(a, a));
}
V ld(glm::dvec3 p) {
    return {p.x, p.y, p.z};
}
LD comp(V v, int a) {
    return a == 0 ? v.x : a == 1 ? v.y : v.z;
}

Shape sphere(glm::dvec3 c, double r) {
    return {Kind::Sphere, c, {r, 0, 0}};
}
Shape box(glm::dvec3 c, glm::dvec3 h) {
    return {Kind::Box, c, h};
}
Shape torus(glm::dvec3 c, double R, double r) {
    return {Kind::Torus, c, {R, r, 0}};
}

Input scene(std::vector<Shape> shapes, glm::dvec3 o, glm::dvec3 d, double eps = 0.1,
            double max_distance = 30, int max_steps = 20) {
    Input in;
    in.shapes = std::move(shapes);
    in.origin = o;
    in.direction = d;
    in.epsilon = eps;
    in.max_distance = max_distance;
    in.max_steps = max_steps;
    return in;
}

// ---- distances written apart, in long double ----

LD ref_shape_distance(const Shape& s, V p) {
    const V c = ld(s.centre);
    switch (s.kind) {
        case Kind::Sphere:
            return len(p - c) - s.size.x;
        case Kind::Box: {
            // Outside: the distance to the closest point of the box, p clamped to it. Inside:
            // minus the distance to the nearest face.
            V q;
            bool inside = true;
            LD face = 1e300L;
            for (int a = 0; a < 3; ++a) {
                const LD lo = comp(c, a) - s.size[a], hi = comp(c, a) + s.size[a];
                const LD v = comp(p, a);
                const LD cl = std::clamp(v, lo, hi);
                (a == 0 ? q.x : a == 1 ? q.y : q.z) = cl;
                if (v < lo || v > hi) inside = false;
                face = std::min(face, std::min(v - lo, hi - v));
            }
            return inside ? -face : len(p - q);
        }
        case Kind::Torus: {
            // The closest point of the centre circle: p's projection on the plane y = c.y,
            // scaled out to radius R (any point of the circle when p is on the axis).
            const V q = p - c;
            const LD rho = std::sqrt(q.x * q.x + q.z * q.z);
            const V on = rho > 0 ? V{q.x * LD(s.size.x) / rho, 0, q.z * LD(s.size.x) / rho}
                                 : V{LD(s.size.x), 0, 0};
            return len(q - on) - s.size.y;
        }
    }
    return 0;
}

LD ref_smin(LD a, LD b, LD k) {
    const LD h = std::clamp(0.5L + 0.5L * (b - a) / k, 0.0L, 1.0L);
    return b * (1 - h) + a * h - k * h * (1 - h);
}

LD ref_distance(const Input& in, V p) {
    LD d = ref_shape_distance(in.shapes[0], p);
    for (std::size_t i = 1; i < in.shapes.size(); ++i) {
        const LD e = ref_shape_distance(in.shapes[i], p);
        switch (in.combine) {
            case Combine::Union:
                d = std::min(d, e);
                break;
            case Combine::Intersection:
                d = std::max(d, e);
                break;
            case Combine::Difference:
                d = std::max(d, -e);
                break;
            case Combine::SmoothUnion:
                d = ref_smin(d, e, in.k);
                break;
        }
    }
    return d;
}

// ---- where the ray is inside: interval lists in t, in long double ----

struct Iv {
    LD a, b;
};
using Ivs = std::vector<Iv>;
constexpr LD kFar = 1e7L;

V unit_of(const Input& in) {
    const V d = ld(in.direction);
    return (1 / len(d)) * d;
}

Ivs sphere_ivs(const Shape& s, V o, V d) {
    const V q = o - ld(s.centre);
    const LD b = dot(q, d), c = dot(q, q) - LD(s.size.x) * s.size.x;
    const LD disc = b * b - c;
    if (disc < 0) return {};
    const LD r = std::sqrt(disc);
    return {{-b - r, -b + r}};
}

// The slab test; `axis` gets the slab that the ray enters last (whose face it hits).
Ivs box_ivs(const Shape& s, V o, V d, int* axis = nullptr) {
    LD t0 = -kFar, t1 = kFar;
    int enter = 0;
    for (int a = 0; a < 3; ++a) {
        const LD lo = LD(s.centre[a]) - s.size[a], hi = LD(s.centre[a]) + s.size[a];
        const LD oa = comp(o, a), da = comp(d, a);
        if (da == 0) {
            if (oa < lo || oa > hi) return {};
            continue;
        }
        LD ta = (lo - oa) / da, tb = (hi - oa) / da;
        if (ta > tb) std::swap(ta, tb);
        if (ta > t0) {
            t0 = ta;
            enter = a;
        }
        t1 = std::min(t1, tb);
    }
    if (t0 > t1) return {};
    if (axis) *axis = enter;
    return {{t0, t1}};
}

// The quartic g(t) = (|q|² + R² − r²)² − 4R²(q_x² + q_z²), q = o + t·d − c, negative inside;
// scanned in steps of r/200 over the ray's chord through the bounding sphere, each sign change
// bisected to the last bit.
Ivs torus_ivs(const Shape& s, V o, V d) {
    const LD R = s.size.x, r = s.size.y;
    auto g = [&](LD t) {
        const V q = o + t * d - ld(s.centre);
        const LD a = dot(q, q) + R * R - r * r;
        return a * a - 4 * R * R * (q.x * q.x + q.z * q.z);
    };
    const Ivs hull = sphere_ivs(sphere(s.centre, double(R + r) * 1.001), o, d);
    if (hull.empty()) return {};
    const LD h = r / 200;
    auto root = [&](LD a, LD b) {
        const bool ga = g(a) < 0;
        for (int i = 0; i < 200; ++i) {
            const LD m = (a + b) / 2;
            if (m == a || m == b) break;
            ((g(m) < 0) == ga ? a : b) = m;
        }
        return (a + b) / 2;
    };
    Ivs out;
    LD t = hull[0].a;
    bool in = g(t) < 0;
    LD start = t;
    while (t < hull[0].b) {
        const LD next = std::min(t + h, hull[0].b);
        const bool n = g(next) < 0;
        if (n != in) {
            const LD x = root(t, next);
            if (n)
                start = x;
            else
                out.push_back({start, x});
            in = n;
        }
        t = next;
    }
    if (in) out.push_back({start, hull[0].b});
    return out;
}

Ivs shape_ivs(const Shape& s, V o, V d) {
    switch (s.kind) {
        case Kind::Sphere:
            return sphere_ivs(s, o, d);
        case Kind::Box:
            return box_ivs(s, o, d);
        case Kind::Torus:
            return torus_ivs(s, o, d);
    }
    return {};
}

Ivs unite(Ivs a, const Ivs& b) {
    a.insert(a.end(), b.begin(), b.end());
    std::sort(a.begin(), a.end(), [](Iv x, Iv y) { return x.a < y.a; });
    Ivs out;
    for (Iv v : a) {
        if (!out.empty() && v.a <= out.back().b)
            out.back().b = std::max(out.back().b, v.b);
        else
            out.push_back(v);
    }
    return out;
}

Ivs intersect(const Ivs& a, const Ivs& b) {
    Ivs out;
    for (Iv x : a)
        for (Iv y : b) {
            const LD lo = std::max(x.a, y.a), hi = std::min(x.b, y.b);
            if (lo <= hi) out.push_back({lo, hi});
        }
    return unite(out, {});
}

// a minus b: the closure of what is left (a solid's boundary belongs to it).
Ivs subtract(const Ivs& a, const Ivs& b) {
    Ivs out = a;
    for (Iv y : b) {
        Ivs next;
        for (Iv x : out) {
            if (y.b <= x.a || y.a >= x.b) {
                next.push_back(x);
                continue;
            }
            if (x.a < y.a) next.push_back({x.a, y.a});
            if (y.b < x.b) next.push_back({y.b, x.b});
        }
        out = next;
    }
    return out;
}

// The first t ≥ 0 at which the ray is in the solid (0 if the origin is), by the intervals.
std::optional<LD> first_root(const Input& in) {
    const V o = ld(in.origin), d = unit_of(in);
    Ivs all = shape_ivs(in.shapes[0], o, d);
    for (std::size_t i = 1; i < in.shapes.size(); ++i) {
        const Ivs e = shape_ivs(in.shapes[i], o, d);
        switch (in.combine) {
            case Combine::Union:
                all = unite(all, e);
                break;
            case Combine::Intersection:
                all = intersect(all, e);
                break;
            case Combine::Difference:
                all = subtract(all, e);
                break;
            case Combine::SmoothUnion:
                return std::nullopt;  // not by intervals
        }
    }
    for (Iv v : all)
        if (v.b >= 0) return std::max(v.a, LD(0));
    return std::nullopt;
}

// The first t ≥ 0 where the long-double field is ≤ 0, by a scan in steps of `h` and bisection.
std::optional<LD> first_root_scan(const Input& in, LD until, LD h) {
    const V o = ld(in.origin), d = unit_of(in);
    auto f = [&](LD t) { return ref_distance(in, o + t * d); };
    if (f(0) <= 0) return LD(0);
    for (LD t = 0; t < until; t += h) {
        if (f(t + h) <= 0) {
            LD a = t, b = t + h;
            for (int i = 0; i < 200; ++i) {
                const LD m = (a + b) / 2;
                if (m == a || m == b) break;
                (f(m) <= 0 ? b : a) = m;
            }
            return b;
        }
    }
    return std::nullopt;
}

// ---- random scenes ----

glm::dvec3 rand3(cg::Rng& rng, double lo, double hi) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

glm::dvec3 rand_unit(cg::Rng& rng) {
    for (;;) {
        const glm::dvec3 v = rand3(rng, -1, 1);
        const double l = glm::length(v);
        if (l > 0.1 && l <= 1) return v / l;
    }
}

Shape random_shape(cg::Rng& rng) {
    const glm::dvec3 c = rand3(rng, -4, 4);
    switch (rng.integer(0, 2)) {
        case 0:
            return sphere(c, rng.uniform(0.5, 3));
        case 1:
            return box(c, rand3(rng, 0.3, 2.5));
        default: {
            const double R = rng.uniform(1, 3);
            return torus(c, R, rng.uniform(0.15, 0.85) * R);
        }
    }
}

// A random scene and ray; `kind` picks the special case (see the test).
Input random_case(cg::Rng& rng, int kind) {
    Input in;
    const int n = int(rng.integer(1, 3));
    for (int i = 0; i < n; ++i) in.shapes.push_back(random_shape(rng));
    static const Combine combos[] = {Combine::Union, Combine::Intersection, Combine::Difference,
                                     Combine::Union};
    in.combine = combos[rng.integer(0, 3)];
    in.origin = rand3(rng, -12, 12);
    const Shape& aim = in.shapes[std::size_t(rng.integer(0, n - 1))];
    in.direction = aim.centre + rand3(rng, -1.5, 1.5) - in.origin;
    if (glm::length(in.direction) < 1e-9) in.direction = {1, 0, 0};
    in.epsilon = std::pow(10.0, rng.uniform(-6, -2));
    in.max_distance = 100;
    in.max_steps = 3000;
    switch (kind) {
        case 1: {  // starting inside a shape
            const Shape& s = in.shapes[0];
            in.origin = s.centre;
            if (s.kind == Kind::Torus) in.origin += glm::dvec3(s.size.x, 0, 0);
            break;
        }
        case 2: {  // along an axis, in the plane of a face of a box (or just off it)
            Shape b = box(rand3(rng, -3, 3), rand3(rng, 0.5, 2));
            in.shapes[0] = b;
            const int a = int(rng.integer(0, 2)), f = (a + 1 + int(rng.integer(0, 1))) % 3;
            glm::dvec3 d(0);
            d[a] = rng.chance(0.5) ? 1 : -1;
            in.direction = d;
            in.origin = b.centre - 8.0 * d;
            const double off = rng.chance(0.5) ? 0 : rng.uniform(-1e-9, 1e-9);
            in.origin[f] = b.centre[f] + (rng.chance(0.5) ? b.size[f] : -b.size[f]) + off;
            const int g = 3 - a - f;
            in.origin[g] = b.centre[g] + rng.uniform(-1.2, 1.2) * b.size[g];
            break;
        }
        case 3: {  // grazing a sphere: tangent at distance 10, or just inside or outside it
            Shape s = sphere(rand3(rng, -3, 3), rng.uniform(0.5, 3));
            in.shapes[0] = s;
            const glm::dvec3 d = rand_unit(rng);
            glm::dvec3 n = glm::cross(d, rand_unit(rng));
            n /= glm::length(n);
            const double miss = rng.uniform(-1e-6, 1e-6);
            in.origin = s.centre + (s.size.x + miss) * n - 10.0 * d;
            in.direction = d;
            break;
        }
        case 4:  // ε at its extremes
            in.epsilon = rng.chance(0.5) ? 1.0 : 1e-12;
            break;
        case 5:  // a short reach
            in.max_distance = rng.uniform(0.5, 20);
            break;
        case 6:  // a few steps only
            in.max_steps = int(rng.integer(1, 8));
            break;
        default:
            break;
    }
    return in;
}

// How squarely the ray meets a single sphere or box at its first root: cos θ (0: no root).
LD incidence(const Input& in, LD t) {
    const Shape& s = in.shapes[0];
    const V o = ld(in.origin), d = unit_of(in);
    if (s.kind == Kind::Sphere) return std::abs(dot(d, o + t * d - ld(s.centre))) / s.size.x;
    int axis = 0;
    box_ivs(s, o, d, &axis);
    return std::abs(comp(d, axis));
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("sphere-tracing");
    if (!l) throw std::runtime_error("no lesson for sphere-tracing");
    return *l;
}

}  // namespace

TEST_CASE("sphere-tracing: marches toward one sphere, by hand", "[modelling][sphere-tracing]") {
    SECTION("off-centre: 3 below the centre of a sphere of radius 5, three samples") {
        // d₀ = √(12² + 3²) − 5 = √153 − 5; t₁ = d₀; d₁ = √((12 − t₁)² + 9) − 5; …
        const auto r = SphereTracing::compute(scene({sphere({12, 3, 0}, 5)}, {0, 0, 0}, {1, 0, 0}));
        CHECK(r.outcome == Outcome::Hit);
        REQUIRE(r.samples == 3);
        CHECK(r.ds[0] == Approx(7.369316876852981).epsilon(1e-14));
        CHECK(r.ds[1] == Approx(0.5175380548754385).epsilon(1e-12));
        CHECK(r.ds[2] == Approx(0.09096870474046703).epsilon(1e-10));
        CHECK(r.t == Approx(7.886854931728419).epsilon(1e-14));
        CHECK(r.t < 8.0);  // the true hit: (12 − t)² + 9 = 25, t = 8
        CHECK(r.point.x == Approx(r.t));
    }
    SECTION("head-on: one step lands on the sphere exactly") {
        const auto r = SphereTracing::compute(scene({sphere({10, 0, 0}, 4)}, {0, 0, 0}, {2, 0, 0}));
        CHECK(r.outcome == Outcome::Hit);
        CHECK(r.ds == std::vector<double>{6, 0});
        CHECK(r.t == 6);
    }
    SECTION("passing beside it: the steps shrink to about c_y − r, then grow, and it escapes") {
        const auto r =
            SphereTracing::compute(scene({sphere({10, 7, 0}, 5)}, {0, 0, 0}, {1, 0, 0}, 0.1, 20));
        CHECK(r.outcome == Outcome::Escaped);
        REQUIRE(r.samples == 6);
        CHECK(r.ds[0] == Approx(7.206555615733702));
        CHECK(r.ds[2] == Approx(2.0047032137964997));
        CHECK(r.ds[5] == Approx(4.904443422515685));
        CHECK(r.t == Approx(21.911439891033005));
    }
    SECTION("starting inside: d₀ < 0, a hit at t = 0") {
        const auto r = SphereTracing::compute(scene({sphere({2, 0, 0}, 4)}, {0, 0, 0}, {1, 0, 0}));
        CHECK(r.outcome == Outcome::Hit);
        CHECK(r.ds == std::vector<double>{-2});
        CHECK(r.t == 0);
    }
    SECTION("out of steps: two samples are not enough") {
        const auto r = SphereTracing::compute(
            scene({sphere({12, 3, 0}, 5)}, {0, 0, 0}, {1, 0, 0}, 0.1, 30, 2));
        CHECK(r.outcome == Outcome::OutOfSteps);
        CHECK(r.samples == 2);
        CHECK(r.t == Approx(7.886854931728419));
    }
    SECTION("a box head-on and a torus through its hole") {
        auto r =
            SphereTracing::compute(scene({box({5, 0, 0}, {1, 2, 3})}, {0, 0, 0}, {1, 0, 0}, 1e-9));
        CHECK(r.outcome == Outcome::Hit);
        CHECK(r.t == 4);
        // Down the axis of a torus (R = 2, r = 0.5): the hole, no hit; beside it, the tube.
        r = SphereTracing::compute(
            scene({torus({0, 0, 0}, 2, 0.5)}, {0, 10, 0}, {0, -1, 0}, 1e-6, 30, 200));
        CHECK(r.outcome == Outcome::Escaped);
        r = SphereTracing::compute(
            scene({torus({0, 0, 0}, 2, 0.5)}, {2, 10, 0}, {0, -1, 0}, 1e-9, 30, 200));
        CHECK(r.outcome == Outcome::Hit);
        CHECK(r.t == Approx(9.5).margin(1e-9));
    }
}

TEST_CASE("sphere-tracing: the distances against formulas written apart",
          "[modelling][sphere-tracing]") {
    cg::Rng rng(11);
    for (int k = 0; k < 3000; ++k) {
        Input in;
        in.shapes = {random_shape(rng), random_shape(rng), random_shape(rng)};
        in.combine = Combine(rng.integer(0, 3));
        in.k = rng.uniform(0.1, 2);
        const glm::dvec3 p = rand3(rng, -8, 8);
        CAPTURE(k);
        for (const Shape& s : in.shapes)
            CHECK(std::abs(SphereTracing::shape_distance(s, p) -
                           double(ref_shape_distance(s, ld(p)))) < 1e-12);
        const double f = SphereTracing::distance(in, p);
        CHECK(std::abs(f - double(ref_distance(in, ld(p)))) < 1e-12);
        // Every field is 1-Lipschitz — the march's safety — and the smooth union lies below
        // the plain minimum: it under-estimates the distance to its own surface.
        const glm::dvec3 q = p + rand3(rng, -1, 1);
        CHECK(std::abs(SphereTracing::distance(in, q) - f) <=
              glm::length(q - p) * (1 + 1e-12) + 1e-13);
        Input u = in;
        u.combine = Combine::Union;
        if (in.combine == Combine::SmoothUnion) CHECK(f <= SphereTracing::distance(u, p) + 1e-13);
    }
}

TEST_CASE("sphere-tracing: 4,000 random scenes and rays against the long-double first hit",
          "[modelling][sphere-tracing]") {
    cg::Rng rng(2026);
    int hits = 0, escapes = 0, clean = 0, inside = 0, faces = 0, grazing = 0, out_of_steps = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const int kind = trial % 8;
        const Input in = random_case(rng, kind);
        CAPTURE(trial, kind);
        SphereTracing::validate(in);
        const auto r = SphereTracing::compute(in);
        const auto root = first_root(in);
        const V o = ld(in.origin), d = unit_of(in);
        const LD tol = 1e-9L * (1 + std::abs(double(r.t)));
        if (r.outcome == Outcome::Hit) {
            ++hits;
            const LD f = ref_distance(in, o + LD(r.t) * d);
            CHECK(f < LD(in.epsilon) + tol);
            if (r.t > 0) CHECK(f > -tol);  // never stepped past the surface
            if (r.t == 0) inside += f < 0;
            // (No root at all: a ray passing within ε of the surface, a hit by the rule.)
            if (root) CHECK(LD(r.t) <= *root + tol);
        } else if (r.outcome == Outcome::Escaped) {
            ++escapes;
            if (root) CHECK(*root > LD(in.max_distance) - tol);
        } else {
            ++out_of_steps;
            CHECK(r.samples == in.max_steps);
        }
        faces += kind == 2 && r.outcome == Outcome::Hit;
        grazing += kind == 3 && r.outcome == Outcome::Hit;
        // A single sphere or box met squarely: the hit is at most ε/cos θ before the true one
        // (the surface lies beyond the tangent plane there).
        if (in.shapes.size() == 1 && in.shapes[0].kind != Kind::Torus && root && *root > 0 &&
            *root < in.max_distance - 1 && in.max_steps >= 1000 && in.epsilon < 1) {
            const LD c = incidence(in, *root);
            if (c > 0.2L && ref_distance(in, o) > LD(in.epsilon)) {
                ++clean;
                REQUIRE(r.outcome == Outcome::Hit);
                CHECK(*root - LD(r.t) <= LD(in.epsilon) / c + tol);
            }
        }
    }
    CHECK(hits > 1200);
    CHECK(escapes > 600);
    CHECK(clean > 300);
    CHECK(inside > 150);
    CHECK(faces > 100);
    CHECK(grazing > 50);
    CHECK(out_of_steps > 100);
}

TEST_CASE("sphere-tracing: a torus alone against its quartic, the smooth union against a scan",
          "[modelling][sphere-tracing]") {
    cg::Rng rng(7);
    int torus_hits = 0, smooth_hits = 0, smooth_escapes = 0;
    for (int trial = 0; trial < 1500; ++trial) {
        CAPTURE(trial);
        Input in;
        const double R = rng.uniform(1, 3);
        in.shapes = {torus(rand3(rng, -2, 2), R, rng.uniform(0.15, 0.85) * R)};
        in.origin = rand3(rng, -10, 10);
        in.direction = in.shapes[0].centre + rand3(rng, -R, R) - in.origin;
        in.epsilon = 1e-7;
        in.max_distance = 50;
        in.max_steps = 5000;
        const auto r = SphereTracing::compute(in);
        const auto root = first_root(in);
        const V o = ld(in.origin), d = unit_of(in);
        if (r.outcome == Outcome::Hit) {
            ++torus_hits;
            REQUIRE(root.has_value());
            CHECK(LD(r.t) <= *root + 1e-9L);
            if (r.t == 0) continue;  // the origin inside the tube
            // Within ε of the surface and, for a ray that is not grazing, of the root.
            CHECK(std::abs(ref_distance(in, o + LD(r.t) * d)) < 1e-7L + 1e-12L);
            CHECK(*root - LD(r.t) < 1e-3L);
        } else if (r.outcome == Outcome::Escaped) {
            if (root) CHECK(*root > 50 - 1e-9L);
        }
    }
    for (int trial = 0; trial < 1000; ++trial) {
        CAPTURE(trial);
        Input in;
        in.shapes = {sphere(rand3(rng, -2, 2), rng.uniform(0.5, 2)), random_shape(rng)};
        in.combine = Combine::SmoothUnion;
        in.k = rng.uniform(0.1, 1.5);
        in.origin = rand3(rng, -10, 10);
        in.direction = rand3(rng, -2, 2) - in.origin;
        in.epsilon = 1e-6;
        in.max_distance = 40;
        in.max_steps = 5000;
        const auto r = SphereTracing::compute(in);
        const auto scan = first_root_scan(in, 40, 0.002L);
        Input plain = in;
        plain.combine = Combine::Union;
        const auto hard = first_root(plain);
        const V o = ld(in.origin), d = unit_of(in);
        if (r.outcome == Outcome::Hit) {
            ++smooth_hits;
            CHECK(ref_distance(in, o + LD(r.t) * d) < 1e-6L + 1e-12L);
            if (scan) CHECK(LD(r.t) <= *scan + 1e-9L);
        } else if (r.outcome == Outcome::Escaped) {
            ++smooth_escapes;
            if (scan) CHECK(*scan > 40 - 1e-9L);
        }
        // The blend only adds material: where the plain union is hit, so is the smooth one,
        // no later.
        if (hard && *hard < 39 && scan) CHECK(*scan <= *hard + 0.002L);
    }
    CHECK(torus_hits > 300);
    CHECK(smooth_hits > 300);
    CHECK(smooth_escapes > 100);
}

TEST_CASE("sphere-tracing: the state machine gives what compute gives, through the registry",
          "[modelling][sphere-tracing]") {
    cg::Rng rng(5);
    for (int trial = 0; trial < 400; ++trial) {
        Input in = random_case(rng, trial % 8);
        in.max_steps = std::min(in.max_steps, 300);
        if (trial % 5 == 4) in.combine = Combine::SmoothUnion;
        CAPTURE(trial);
        const auto traced = cg::test::run_traced<SphereTracing>(in);
        const auto r = SphereTracing::compute(in);
        CHECK(traced.result == r);
        // One step a sample, and a verdict step for a miss.
        CHECK(traced.steps.size() == std::size_t(r.samples) + (r.outcome != Outcome::Hit));
        CHECK(traced.steps.back().event == SphereTracing::outcome_name(r.outcome));
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const Input in = cg::test::input_of<SphereTracing>("sphere-tracing", p.input);
        const auto j = cg::test::result_of("sphere-tracing", p.input);
        const auto r = SphereTracing::compute(in);
        CHECK(j["steps"] == r.samples);
        CHECK(j["outcome"] == SphereTracing::outcome_name(r.outcome));
        CHECK(j["distances"] == cg::json(r.ds));
    }
}

TEST_CASE("sphere-tracing: the steps and their narration", "[modelling][sphere-tracing]") {
    const auto t =
        cg::test::run_traced<SphereTracing>(scene({sphere({12, 3, 0}, 5)}, {0, 0, 0}, {1, 0, 0}));
    CHECK(cg::test::events(t) == std::vector<std::string>{"march", "march", "hit"});
    CHECK(t.steps[0].line == 5);
    CHECK(t.steps[2].line == 4);
    CHECK(t.steps[0].narration.find("d_0 = 7.36932") != std::string::npos);
    CHECK(t.steps[0].narration.find("t = 0 + 7.36932 = 7.36932") != std::string::npos);
    CHECK(t.steps[2].narration.find("a hit at t = 7.88685 after 3 samples") != std::string::npos);
    const auto miss = cg::test::run_traced<SphereTracing>(
        scene({sphere({10, 7, 0}, 5)}, {0, 0, 0}, {1, 0, 0}, 0.1, 20));
    CHECK(cg::test::events(miss).back() == "escaped");
    CHECK(miss.steps.back().narration.find("past max_distance = 20") != std::string::npos);
    const auto in =
        cg::test::run_traced<SphereTracing>(scene({sphere({2, 0, 0}, 4)}, {0, 0, 0}, {1, 0, 0}));
    CHECK(in.steps.size() == 1);
    CHECK(in.steps[0].narration.find("starts inside") != std::string::npos);
    // Every declared predictable and mistakable variable is reported by its event.
    const auto& spec = SphereTracing::spec();
    for (const auto& m : spec.study.mistakes) {
        if (m.var.empty()) continue;
        bool seen = false;
        for (const auto& s : t.steps)
            if (s.event == m.event)
                for (const auto& v : s.vars) seen = seen || v.name == m.var;
        CHECK(seen);
    }
}

TEST_CASE("sphere-tracing: degenerate and bad input", "[modelling][sphere-tracing]") {
    auto err = [](const std::string& text) { return cg::test::error_of("sphere-tracing", text); };
    const std::string ray = R"("origin": [0, 0, 0], "direction": [1, 0, 0])";
    CHECK(err(R"({"shapes": [], )" + ray + "}") == "shapes: must list at least one shape");
    CHECK(err(R"({"shapes": [{"type": "sphere", "centre": [5, 0, 0], "radius": 0}], )" + ray + "}")
              .rfind("shapes[0].radius: must be a length above 0", 0) == 0);
    CHECK(err(R"({"shapes": [{"type": "box", "centre": [5, 0, 0], "half_size": [1, -1, 1]}], )" +
              ray + "}")
              .rfind("shapes[0].half_size: must be a length above 0", 0) == 0);
    CHECK(
        err(R"({"shapes": [{"type": "torus", "centre": [5, 0, 0], "major_radius": 1, "minor_radius": 1}], )" +
            ray + "}")
            .rfind("shapes[0].minor_radius: must be below the major radius", 0) == 0);
    CHECK(err(R"({"shapes": [{"type": "cone", "centre": [5, 0, 0]}], )" + ray + "}")
              .rfind("shapes[0].type: must be \"sphere\", \"box\" or \"torus\"", 0) == 0);
    CHECK(err(R"({"shapes": [{"type": "sphere", "centre": [5, 0], "radius": 1}], )" + ray + "}")
              .rfind("shapes[0].centre: must be a point [x, y, z]", 0) == 0);
    CHECK(err(R"({"shapes": [{"type": "sphere", "centre": [5, 0, 0], "radius": 1, "size": 2}], )" +
              ray + "}")
              .rfind("shapes[0].size: is not a known field", 0) == 0);
    const std::string one =
        R"({"shapes": [{"type": "sphere", "centre": [5, 0, 0], "radius": 1}], )";
    CHECK(err(one + R"("origin": [0, 0, 0], "direction": [0, 0, 0]})") ==
          "direction: must not be the zero vector (a ray needs a direction)");
    CHECK(err(one + ray + R"(, "epsilon": 0})").rfind("epsilon: must be above 0", 0) == 0);
    CHECK(err(one + ray + R"(, "max_distance": -1})").rfind("max_distance: must be above 0", 0) ==
          0);
    CHECK(err(one + ray + R"(, "max_steps": 0})") == "max_steps: must be 1 to 10000 (got 0)");
    CHECK(err(one + ray + R"(, "combine": "xor"})").rfind("combine: must be", 0) == 0);
    CHECK(err(one + ray + R"(, "combine": "smooth-union", "k": 0})")
              .rfind("k: must be a length above 0", 0) == 0);
    CHECK(err(one + R"("origin": [1e300, 0, 0], "direction": [1, 0, 0]})")
              .rfind("origin: must be finite numbers of magnitude at most 1e6", 0) == 0);
    // A tiny direction normalises exactly; ε below what doubles resolve runs out of steps or
    // lands exactly on the surface — a defined result either way.
    auto r = SphereTracing::compute(scene({sphere({5, 0, 0}, 1)}, {0, 0, 0}, {1e-300, 0, 0}));
    CHECK(r.t == 4);
    r = SphereTracing::compute(
        scene({sphere({5, 0.5, 0}, 1)}, {0, 0, 0}, {1, 0, 0}, 1e-300, 30, 500));
    CHECK((r.outcome == Outcome::OutOfSteps || r.ds.back() <= 0));
    // One shape only: intersection and difference of one shape are the shape.
    Input a = scene({sphere({5, 0, 0}, 1)}, {0, 0, 0}, {1, 0, 0});
    Input b = a;
    b.combine = Combine::Difference;
    CHECK(SphereTracing::compute(a) == SphereTracing::compute(b));
}

TEST_CASE("sphere-tracing: replay on the example and the presets", "[modelling][sphere-tracing]") {
    const auto& a = cg::test::algorithm("sphere-tracing");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 2);
    }
    CHECK(lesson().presets.size() >= 4);
}

TEST_CASE("sphere-tracing: exam problems answered by a long-double march",
          "[modelling][sphere-tracing][exam]") {
    const auto& a = cg::test::algorithm("sphere-tracing");
    int misses = 0, inside = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = cg::test::input_of<SphereTracing>("sphere-tracing", p.input);
        CAPTURE(seed, p.question);
        REQUIRE(in.shapes.size() == 1);
        const V c = ld(in.shapes[0].centre);
        const LD r = in.shapes[0].size.x;
        std::vector<LD> ds;
        LD t = 0;
        bool hit = false;
        for (int k = 0; k < in.max_steps; ++k) {
            const LD dd = len(V{t, 0, 0} - c) - r;
            ds.push_back(dd);
            if (dd < LD(in.epsilon)) {
                hit = true;
                break;
            }
            t += dd;
            if (t > LD(in.max_distance)) break;
        }
        REQUIRE(p.expected["distances"].size() == ds.size());
        for (std::size_t k = 0; k < ds.size(); ++k)
            CHECK(p.expected["distances"][k].get<double>() == Approx(double(ds[k])).margin(1e-9));
        CHECK(p.expected["steps"] == ds.size());
        CHECK(p.expected["hit"] == hit);
        CHECK(ds.size() <= 6);
        misses += !hit;
        inside += ds[0] < 0;
        CHECK(p.answers == std::vector<std::string>{"distances", "steps", "hit"});
    }
    CHECK(misses > 20);
    CHECK(inside > 10);
}

TEST_CASE("sphere-tracing: the picture — outline, ray, unbounding circles",
          "[modelling][sphere-tracing]") {
    auto s = SphereTracing::start(scene({sphere({12, 3, 0}, 5)}, {0, 0, 0}, {1, 0, 0}));
    cg::Scene before;
    SphereTracing::draw(s, before);
    CHECK(before.segments.size() > 20);  // the sphere's outline
    CHECK(before.polygons.empty());      // no circle before the first sample
    SphereTracing::step(s, nullptr);
    SphereTracing::step(s, nullptr);
    cg::Scene scene;
    SphereTracing::draw(s, scene);
    REQUIRE(scene.polygons.size() == 2);
    // The second circle: centre p₁ = (t₁, 0), radius d₁, in orange.
    const auto& c = scene.polygons[1];
    CHECK(c.style.role == cg::Role::Active);
    double rmax = 0;
    for (auto q : c.points) rmax = std::max(rmax, glm::length(q - glm::dvec2(s.ts[1], 0)));
    CHECK(rmax == Approx(s.ds[1]).epsilon(1e-9));
    // The outline passes within a cell of the true circle |p − (12, 3)| = 5.
    for (const auto& seg : before.segments) {
        if (seg.style.role != cg::Role::Neutral) continue;
        CHECK(std::abs(glm::length(seg.a - glm::dvec2(12, 3)) - 5) < 0.05);
    }
    CHECK(scene.handles.size() == 2);  // the origin and the centre, in world x and y
}
