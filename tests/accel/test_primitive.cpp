// The acceleration structures' primitives: each ray intersection against an independent
// long-double reference computed another way (the sphere by the ray's closest approach to the
// centre, the triangle by its plane and sub-triangle areas, the box by slab intervals) on
// random rays, tangent and edge cases excepted by a stated margin; bounds and surface areas
// worked by hand; the JSON's errors naming the field.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "accel/primitive.hpp"
#include "accel/primitive_json.hpp"
#include "core/rng.hpp"

using cg::Bounds;
using cg::Primitive;
using cg::PrimitiveKind;
using glm::dvec3;

namespace {

using LD = long double;
constexpr LD kLInf = std::numeric_limits<LD>::infinity();

struct LVec {
    LD x, y, z;
};
LVec lv(dvec3 v) {
    return {v.x, v.y, v.z};
}
LVec operator-(LVec a, LVec b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
LVec operator+(LVec a, LVec b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
LVec operator*(LD s, LVec a) {
    return {s * a.x, s * a.y, s * a.z};
}
LD dot(LVec a, LVec b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
LVec cross(LVec a, LVec b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

dvec3 random_point(cg::Rng& rng, double r) {
    return {rng.uniform(-r, r), rng.uniform(-r, r), rng.uniform(-r, r)};
}

// The reference's verdict: a t (kLInf for a miss) and whether the case is too close to a
// boundary (tangent, an edge) for double and long double to be sure to agree.
struct RefHit {
    LD t = kLInf;
    bool marginal = false;
};

// The sphere by closest approach: t_c = (C − E)·d/|d|², the squared distance h² of the
// centre from the line, and the half chord Δ = √((r² − h²)/|d|²): t = t_c ∓ Δ.
RefHit sphere_reference(const Primitive& p, dvec3 e, dvec3 d) {
    const LVec D = lv(d), M = lv(p.a) - lv(e);
    const LD dd = dot(D, D), tc = dot(M, D) / dd;
    const LVec off = M - tc * D;
    const LD h2 = dot(off, off), r2 = LD(p.radius) * LD(p.radius);
    RefHit out;
    out.marginal = std::fabs(r2 - h2) < 1e-6L * r2;
    if (h2 > r2) return out;
    const LD delta = std::sqrt((r2 - h2) / dd);
    const LD t0 = tc - delta, t1 = tc + delta;
    // E on the sphere (t0 or t1 ≈ 0) is marginal too: which root is "≥ 0" is decided by ulps.
    if (std::fabs(t0) < 1e-9L * (std::fabs(tc) + delta) ||
        std::fabs(t1) < 1e-9L * (std::fabs(tc) + delta))
        out.marginal = true;
    out.t = t0 >= 0 ? t0 : t1 >= 0 ? t1 : kLInf;
    return out;
}

// The triangle by its plane, n = (B − A) × (C − A): t = n·(A − E)/(n·d), then the point's
// weights as ratios of sub-triangle areas, β = n·((P − A) × (C − A))/|n|², γ =
// n·((B − A) × (P − A))/|n|².
RefHit triangle_reference(const Primitive& p, dvec3 e, dvec3 d, LD* beta_out = nullptr,
                          LD* gamma_out = nullptr) {
    const LVec A = lv(p.a), B = lv(p.b), C = lv(p.c), E = lv(e), D = lv(d);
    const LVec n = cross(B - A, C - A);
    const LD nd = dot(n, D), nn = dot(n, n);
    RefHit out;
    // A ray nearly in the plane: a hair's difference decides hit or miss.
    if (std::fabs(nd) < 1e-9L * std::sqrt(nn * dot(D, D))) {
        out.marginal = true;
        return out;
    }
    const LD t = dot(n, A - E) / nd;
    const LVec P = E + t * D;
    const LD beta = dot(n, cross(P - A, C - A)) / nn, gamma = dot(n, cross(B - A, P - A)) / nn;
    const LD eps = 1e-9L;
    const LD scale = std::sqrt(dot(E - A, E - A) / dot(B - A, B - A)) + 1;
    if (std::fabs(beta) < eps * scale || std::fabs(gamma) < eps * scale ||
        std::fabs(1 - beta - gamma) < eps * scale || std::fabs(t) < eps * scale)
        out.marginal = true;
    if (beta >= 0 && gamma >= 0 && beta + gamma <= 1 && t >= 0) out.t = t;
    if (beta_out) *beta_out = beta, *gamma_out = gamma;
    return out;
}

// The box as three long-double slab intervals; inside → the exit.
RefHit box_reference(const Primitive& p, dvec3 e, dvec3 d) {
    LD lo = -kLInf, hi = kLInf;
    RefHit out;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0) {
            if (e[i] < p.a[i] || e[i] > p.b[i]) return out;
            continue;
        }
        LD a = (LD(p.a[i]) - e[i]) / d[i], b = (LD(p.b[i]) - e[i]) / d[i];
        if (a > b) std::swap(a, b);
        lo = std::max(lo, a), hi = std::min(hi, b);
    }
    const LD scale = std::max(std::fabs(lo), std::fabs(hi));
    if (std::fabs(lo - hi) < 1e-9L * scale || std::fabs(lo) < 1e-9L * scale ||
        std::fabs(hi) < 1e-9L * scale)
        out.marginal = true;
    if (lo > hi || hi < 0) return out;
    out.t = lo >= 0 ? lo : hi;
    return out;
}

void check_against(const RefHit& ref, const cg::PrimitiveHit& h, int& checked) {
    if (ref.marginal) return;
    ++checked;
    if (ref.t == kLInf) {
        REQUIRE_FALSE(h.hit());
        return;
    }
    REQUIRE(h.hit());
    const LD err = std::fabs(LD(h.t) - ref.t) / std::max<LD>(1, std::fabs(ref.t));
    REQUIRE(double(err) < 1e-9);
}

using cg::prim::box;
using cg::prim::sphere;
using cg::prim::triangle;

}  // namespace

TEST_CASE("primitives: hand-worked hits", "[accel][primitive]") {
    // The unit sphere from (−3, 0, 0) along +x: in at t = 2, and from the centre out at t = 1.
    CHECK(cg::intersect(sphere({0, 0, 0}, 1), {-3, 0, 0}, {1, 0, 0}).t == 2);
    CHECK(cg::intersect(sphere({0, 0, 0}, 1), {0, 0, 0}, {2, 0, 0}).t == 0.5);
    CHECK_FALSE(cg::intersect(sphere({0, 0, 0}, 1), {3, 0, 0}, {1, 0, 0}).hit());   // behind
    CHECK_FALSE(cg::intersect(sphere({0, 0, 0}, 1), {-3, 2, 0}, {1, 0, 0}).hit());  // above
    // The triangle (0,0,0) (2,0,0) (0,2,0) from (0.5, 0.5, 4) straight down: t = 4 for d = −z,
    // β = γ = ¼; its corner (2, 0, 0) counts (edges and corners included).
    const Primitive tri = triangle({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
    const cg::PrimitiveHit th = cg::intersect(tri, {0.5, 0.5, 4}, {0, 0, -1});
    CHECK(th.t == 4);
    CHECK(th.beta == 0.25);
    CHECK(th.gamma == 0.25);
    CHECK(cg::intersect(tri, {2, 0, 1}, {0, 0, -1}).t == 1);
    CHECK_FALSE(cg::intersect(tri, {1.5, 1.5, 1}, {0, 0, -1}).hit());  // beyond the edge
    CHECK_FALSE(cg::intersect(tri, {-1, 0.5, 0}, {1, 0, 0}).hit());    // in its plane
    CHECK(cg::intersect(tri, {0.5, 0.5, -4}, {0, 0, 1}).t == 4);       // from behind too
    // The box [0, 1]³: from (−1, 0.5, 0.5) in at t = 1; from its centre out at t = ½.
    CHECK(cg::intersect(box({0, 0, 0}, {1, 1, 1}), {-1, 0.5, 0.5}, {1, 0, 0}).t == 1);
    CHECK(cg::intersect(box({0, 0, 0}, {1, 1, 1}), {0.5, 0.5, 0.5}, {0, 1, 0}).t == 0.5);
    CHECK_FALSE(cg::intersect(box({0, 0, 0}, {1, 1, 1}), {-1, 2, 0.5}, {1, 0, 0}).hit());
}

TEST_CASE("primitives: bounds and surface areas", "[accel][primitive]") {
    const Bounds s = cg::bounds(sphere({1, 2, 3}, 0.5));
    CHECK(s.min == dvec3(0.5, 1.5, 2.5));
    CHECK(s.max == dvec3(1.5, 2.5, 3.5));
    CHECK(s.surface_area() == 6 * 1.0);
    const Bounds t = cg::bounds(triangle({0, 0, 0}, {2, -1, 0}, {1, 3, 4}));
    CHECK(t.min == dvec3(0, -1, 0));
    CHECK(t.max == dvec3(2, 3, 4));
    CHECK(t.surface_area() == 2 * (2 * 4 + 4 * 4 + 4 * 2));
    CHECK(cg::centroid(triangle({0, 0, 0}, {2, -1, 0}, {1, 3, 4})) == dvec3(1, 1, 2));
    Bounds empty;
    CHECK(empty.empty());
    CHECK(empty.surface_area() == 0);
    empty.grow(dvec3(1, 1, 1));
    CHECK_FALSE(empty.empty());  // a point is a (flat) box
    CHECK(empty.surface_area() == 0);
    empty.grow(s);
    CHECK(empty.min == dvec3(0.5, 1, 1));
    CHECK(empty.max == dvec3(1.5, 2.5, 3.5));
}

TEST_CASE("primitives: 200,000 random rays against long-double references", "[accel][primitive]") {
    cg::Rng rng(19);
    int checked[3] = {0, 0, 0}, hits[3] = {0, 0, 0};
    for (int k = 0; k < 200000; ++k) {
        const int kind = k % 3;
        const double scale = k % 7 == 0 ? 1e-3 : k % 11 == 0 ? 1e3 : 1;
        Primitive p;
        if (kind == 0) {
            p = sphere(random_point(rng, 2 * scale), rng.uniform(0.01, 2) * scale);
        } else if (kind == 1) {
            p = triangle(random_point(rng, 2 * scale), random_point(rng, 2 * scale),
                         random_point(rng, 2 * scale));
        } else {
            const dvec3 a = random_point(rng, 2 * scale), b = random_point(rng, 2 * scale);
            p = box(glm::min(a, b), glm::max(a, b));
            if (k % 5 == 0) p.b.y = p.a.y;  // a flat box
        }
        // Origins outside and inside; directions aimed near the primitive, some with zero
        // components (axis-parallel rays), some not.
        const dvec3 e = k % 4 == 0 ? cg::centroid(p) + random_point(rng, 0.3 * scale)
                                   : random_point(rng, 5 * scale);
        dvec3 d = cg::centroid(p) + random_point(rng, 1.5 * scale) - e;
        if (k % 9 == 0) d.x = 0;
        if (k % 13 == 0) d.z = 0;
        if (d == dvec3(0)) continue;
        const cg::PrimitiveHit h = cg::intersect(p, e, d);
        const RefHit ref = kind == 0   ? sphere_reference(p, e, d)
                           : kind == 1 ? triangle_reference(p, e, d)
                                       : box_reference(p, e, d);
        check_against(ref, h, checked[kind]);
        if (!ref.marginal && ref.t != kLInf) {
            ++hits[kind];
            if (kind == 1) {  // the weights too
                LD beta = 0, gamma = 0;
                triangle_reference(p, e, d, &beta, &gamma);
                REQUIRE(std::fabs(LD(h.beta) - beta) < 1e-7L);
                REQUIRE(std::fabs(LD(h.gamma) - gamma) < 1e-7L);
            }
        }
    }
    // Most cases are decided, and a good share of them are hits: the test sees both verdicts.
    for (int kind = 0; kind < 3; ++kind) {
        INFO("kind " << kind);
        CHECK(checked[kind] > 60000);
        CHECK(hits[kind] > 10000);
        CHECK(checked[kind] - hits[kind] > 5000);
    }
}

TEST_CASE("primitives: JSON errors name the field", "[accel][primitive]") {
    using cg::json;
    auto error_of = [](const json& list) -> std::string {
        try {
            cg::accel_json::primitives(cg::Reader(json{{"primitives", list}}), "primitives", 4);
        } catch (const cg::InputError& e) {
            return e.what();
        }
        return "no error";
    };
    CHECK_THAT(error_of(json::array({{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 0}}})),
               Catch::Contains("primitives[0].radius") && Catch::Contains("> 0"));
    CHECK_THAT(error_of(json::array(
                   {{{"type", "triangle"}, {"vertices", {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}}})),
               Catch::Contains("primitives[0].vertices") && Catch::Contains("collinear"));
    CHECK_THAT(
        error_of(json::array({{{"type", "triangle"}, {"vertices", {{0, 0, 0}, {1, 1, 1}}}}})),
        Catch::Contains("primitives[0].vertices") && Catch::Contains("3 points"));
    CHECK_THAT(error_of(json::array({{{"type", "box"}, {"min", {0, 0, 0}}, {"max", {1, -1, 1}}}})),
               Catch::Contains("primitives[0].max") && Catch::Contains("y axis"));
    CHECK_THAT(error_of(json::array({{{"type", "cone"}}})), Catch::Contains("primitives[0].type"));
    CHECK_THAT(error_of(json::array(
                   {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"color", 1}}})),
               Catch::Contains("color"));
    CHECK_THAT(error_of(json::array()), Catch::Contains("at least one"));
    CHECK_THAT(error_of(json(3)), Catch::Contains("list"));
    const json s = {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}};
    CHECK_THAT(error_of(json::array({s, s, s, s, s})), Catch::Contains("at most 4"));
    CHECK(error_of(json::array({s, s})) == "no error");
    // Written back, read again: the same primitives.
    const json list =
        json::array({s,
                     {{"type", "triangle"}, {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}},
                     {{"type", "box"}, {"min", {0, 0, 0}}, {"max", {1, 2, 3}}}});
    const auto ps =
        cg::accel_json::primitives(cg::Reader(json{{"primitives", list}}), "primitives", 4);
    CHECK(cg::accel_json::primitives_json(ps) == list);
}
