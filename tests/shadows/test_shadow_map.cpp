// Shadow maps: the exam case by hand (a card straight under a directional light, a 4 × 4 map,
// exact texel values and verdicts); an independent reference in long double — each texel's
// depth by a plane-then-barycentric brute force over every triangle, each lookup's texel and
// map verdict from the reference map, and each shadow ray — on 2,000 random scenes (directional
// and spot lights, map sizes 1 to 16); bias 0 makes acne on a lit floor and a proper bias
// removes it; the disagreements fall as the map grows; errors naming the field; replay on the
// example and the presets; the exam problems; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>

#include "core/format.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "shadows/shadow_map.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::ShadowMap;
using glm::dvec3;
using Input = ShadowMap::Input;
using Verdict = ShadowMap::Verdict;

namespace {

using LD = long double;
struct V3 {
    LD x, y, z;
};
V3 v3(const dvec3& p) {
    return {p.x, p.y, p.z};
}
V3 sub(V3 a, V3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V3 add(V3 a, V3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V3 mul(LD s, V3 a) {
    return {s * a.x, s * a.y, s * a.z};
}
LD dot(V3 a, V3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
V3 cross(V3 a, V3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 unit(V3 a) {
    return mul(1 / std::sqrt(dot(a, a)), a);
}

ShadowMap::Triangle tri(dvec3 a, dvec3 b, dvec3 c) {
    return {a, b, c};
}

// The hand-worked scene: floor y = 0 over [−2, 2]², a card at height 2 over [−1, 1]², a
// directional light straight down from (0, 5, 0), a 4 × 4 map over ±2.
Input exam_scene() {
    Input in;
    in.triangles = {
        tri({-2, 0, -2}, {2, 0, -2}, {2, 0, 2}), tri({-2, 0, -2}, {2, 0, 2}, {-2, 0, 2}),
        tri({-1, 2, -1}, {1, 2, -1}, {1, 2, 1}), tri({-1, 2, -1}, {1, 2, 1}, {-1, 2, 1})};
    in.light.type = ShadowMap::LightType::Directional;
    in.light.position = {0, 5, 0};
    in.light.target = {0, 0, 0};
    in.light.up = {0, 0, -1};
    in.light.extent = 2;
    in.light.near = 0.5;
    in.light.far = 10;
    in.map_size = 4;
    in.bias = 0.1;
    in.eye.position = {0.25, 0.5, 4.75};
    in.eye.target = {0.25, 0, 0.25};
    in.eye.up = {0, 1, 0};
    in.eye.fov_deg = 30;
    in.eye.width = in.eye.height = 1;
    return in;
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("shadow-map");
    if (!l) throw std::runtime_error("no lesson for shadow-map");
    return *l;
}

Input input_of(const cg::json& j) {
    return cg::test::input_of<ShadowMap>("shadow-map", j);
}

Input example() {
    return input_of(cg::test::algorithm("shadow-map").example());
}

// ---- the reference, in long double ----

struct RefFrame {
    V3 o, r, u, f;
    LD half;
    bool spot;
};
RefFrame ref_light(const Input& in) {
    RefFrame F;
    F.o = v3(in.light.position);
    F.f = unit(sub(v3(in.light.target), F.o));
    F.r = unit(cross(F.f, v3(in.light.up)));
    F.u = cross(F.r, F.f);
    F.spot = in.light.type == ShadowMap::LightType::Spot;
    F.half = F.spot ? std::tan(LD(in.light.fov_deg) * 3.14159265358979323846264338L / 360)
                    : LD(in.light.extent);
    return F;
}

// A ray against a triangle through its plane and barycentric coordinates (not Möller–
// Trumbore): the t of the hit, the smallest barycentric coordinate (negative: outside).
bool ref_hit(const ShadowMap::Triangle& t, V3 o, V3 d, LD& tt, LD& margin) {
    const V3 a = v3(t[0]), b = v3(t[1]), c = v3(t[2]);
    const V3 n = cross(sub(b, a), sub(c, a));
    const LD den = dot(n, d);
    if (den == 0) return false;
    tt = dot(n, sub(a, o)) / den;
    const V3 q = add(o, mul(tt, d));
    const LD nn = dot(n, n);
    const LD wa = dot(cross(sub(b, q), sub(c, q)), n) / nn;
    const LD wb = dot(cross(sub(c, q), sub(a, q)), n) / nn;
    const LD wc = 1 - wa - wb;
    margin = std::min({wa, wb, wc});
    return true;
}

// Texel (i, j)'s depth: the nearest triangle its centre ray meets within [near, far]; `clear`
// is false when a triangle's edge or the near/far planes pass too close to call.
LD ref_texel(const Input& in, const RefFrame& F, int i, int j, bool& clear) {
    const int n = in.map_size;
    const LD x = (2 * (i + LD(0.5)) / n - 1) * F.half, y = (2 * (j + LD(0.5)) / n - 1) * F.half;
    V3 o = F.o, d = F.f;
    if (F.spot)
        d = add(F.f, add(mul(x, F.r), mul(y, F.u)));
    else
        o = add(F.o, add(mul(x, F.r), mul(y, F.u)));
    LD best = in.light.far;
    clear = true;
    for (const auto& t : in.triangles) {
        LD tt, m;
        if (!ref_hit(t, o, d, tt, m)) continue;
        if (std::fabs(m) < 1e-9 || std::fabs(tt - in.light.near) < 1e-9 ||
            std::fabs(tt - in.light.far) < 1e-9)
            clear = false;
        if (m >= 0 && tt >= in.light.near && tt <= in.light.far && tt < best) best = tt;
    }
    return best;
}

// The shadow ray from P (on triangle `self`) toward the light: blocked by another triangle?
bool ref_blocked(const Input& in, const RefFrame& F, V3 p, int self, bool& clear) {
    const V3 to = F.spot ? sub(F.o, p) : mul(-dot(sub(p, F.o), F.f), F.f);
    bool blocked = false;
    for (std::size_t k = 0; k < in.triangles.size(); ++k) {
        if (int(k) == self) continue;
        LD tt, m;
        if (!ref_hit(in.triangles[k], p, to, tt, m)) continue;
        if (std::fabs(m) < 1e-9 && tt > -1e-9 && tt < 1 + 1e-9) clear = false;
        if ((tt > 1e-9 && tt < 1e-6) || std::fabs(tt - 1) < 1e-9) clear = false;
        if (m >= 0 && tt > 1e-9 && tt < 1) blocked = true;
    }
    return blocked;
}

dvec3 rnd3(cg::Rng& rng, double lo, double hi) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

Input random_scene(cg::Rng& rng) {
    Input in;
    const double g = rng.uniform(2, 4);  // the floor, sometimes tilted
    const double tilt = rng.chance(0.3) ? rng.uniform(-0.3, 0.3) : 0;
    in.triangles = {tri({-g, -g * tilt, -g}, {g, g * tilt, -g}, {g, g * tilt, g}),
                    tri({-g, -g * tilt, -g}, {g, g * tilt, g}, {-g, -g * tilt, g})};
    const int extra = int(rng.integer(1, 5));
    for (int k = 0; k < extra; ++k) {
        const dvec3 c{rng.uniform(-1.5, 1.5), rng.uniform(0.2, 2.5), rng.uniform(-1.5, 1.5)};
        ShadowMap::Triangle t;
        for (auto& v : t) v = c + rnd3(rng, -1, 1);
        const dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
        if (glm::length(glm::cross(e1, e2)) < 0.05) continue;
        in.triangles.push_back(t);
    }
    const bool spot = rng.chance(0.4);
    in.light.type = spot ? ShadowMap::LightType::Spot : ShadowMap::LightType::Directional;
    in.light.position = {rng.uniform(-3, 3), rng.uniform(4, 7), rng.uniform(-3, 3)};
    in.light.target = {rng.uniform(-0.5, 0.5), 0, rng.uniform(-0.5, 0.5)};
    in.light.up = rng.chance(0.5) ? dvec3(0, 0, -1) : dvec3(1, 0, 0);
    if (glm::length(glm::cross(glm::normalize(in.light.target - in.light.position), in.light.up)) <
        0.1)
        in.light.up = {0, 1, 0};
    if (spot)
        in.light.fov_deg = rng.uniform(30, 100);
    else
        in.light.extent = rng.uniform(1.5, 4);
    in.light.near = rng.uniform(0.1, 1);
    in.light.far = rng.uniform(6, 14);
    in.map_size = int(rng.integer(1, 16));
    in.bias = rng.chance(0.2) ? 0 : rng.uniform(0, 0.3);
    in.eye.position = {rng.uniform(-4, 4), rng.uniform(2, 6), rng.uniform(3, 7)};
    in.eye.target = {0, rng.uniform(0, 1), 0};
    in.eye.up = {0, 1, 0};
    in.eye.fov_deg = rng.uniform(30, 70);
    in.eye.width = int(rng.integer(1, 10));
    in.eye.height = int(rng.integer(1, 8));
    return in;
}

}  // namespace

TEST_CASE("shadow-map: the exam case by hand, a card straight under the light",
          "[shadows][shadow-map]") {
    Input in = exam_scene();
    const auto t = cg::test::run_traced<ShadowMap>(in);
    CHECK(cg::test::events(t) == std::vector<std::string>{"setup", "rasterise", "rasterise",
                                                          "rasterise", "rasterise", "shadow",
                                                          "summary"});
    // The middle four texels hold the card (d = 5 − 2 = 3), the rest the floor (d = 5).
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            CAPTURE(i, j);
            const bool card = (i == 1 || i == 2) && (j == 1 || j == 2);
            CHECK(t.result.depth[j * 4 + i] == (card ? 3.0 : 5.0));
        }
    // light_from_world: rows [1, 0, 0, 0], [0, 0, −1, 0], [0, 1, 0, −5].
    const auto& M = t.result.light_from_world;
    CHECK(M[0][0] == 1);
    CHECK(M[2][1] == -1);
    CHECK(M[1][2] == 1);
    CHECK(M[3][2] == -5);
    CHECK(M[3][3] == 1);
    // P = (0.25, 0, 0.25): s = 0.5625, t = 0.4375, texel (2, 1), d_P = 5 > 3 + 0.1: shadow.
    const auto& l = t.result.last;
    CHECK(l.verdict == Verdict::Shadow);
    CHECK(l.ti == 2);
    CHECK(l.tj == 1);
    CHECK(l.d_p == Approx(5).epsilon(1e-12));
    CHECK(l.d_map == 3);
    CHECK(l.s == Approx(0.5625));
    CHECK(l.t == Approx(0.4375));
    CHECK(l.map_shadow);
    CHECK(l.exact_shadow);
    CHECK(l.blocker >= 2);
    CHECK_THAT(t.steps[5].narration, Catch::Contains("texel (i, j) = (2, 1)"));
    CHECK_THAT(t.steps[5].narration, Catch::Contains("= 4.9 > d_map = 3"));
    CHECK_THAT(t.steps[0].narration,
               Catch::Contains("light_from_world = [1, 0, 0, 0; 0, 0, −1, 0; 0, 1, 0, −5; 0, 0, "
                               "0, 1]"));
    // The floor's diagonal x = z passes through four texel centres: both halves cover them.
    CHECK_THAT(t.steps[1].narration, Catch::Contains("covers 10 texel centres"));

    SECTION("a floor point beside the card: lit") {
        in.eye.position = {-1.5, 0.5, 4.5};
        in.eye.target = {-1.5, 0, 0.25};  // texel (0, 1): the floor, d_map = 5
        const auto r = ShadowMap::render(in);
        CHECK(r.last.verdict == Verdict::Lit);
        CHECK(r.last.ti == 0);
        CHECK(r.last.tj == 1);
        CHECK(r.last.d_map == 5);
    }
    SECTION("a point on the card's top: d_P = d_map, lit with or without the bias") {
        in.eye.position = {0.5, 4, 3.5};
        in.eye.target = {0.5, 2, 0.5};
        for (double bias : {0.1, 0.0}) {
            in.bias = bias;
            const auto r = ShadowMap::render(in);
            CHECK(r.last.tri >= 2);
            CHECK(r.last.d_p == Approx(3).epsilon(1e-12));
            CHECK(r.last.d_map == 3);
            CHECK(r.last.verdict == (r.last.d_p > 3 && bias == 0 ? Verdict::Acne : Verdict::Lit));
        }
    }
    SECTION("a point beyond the light's box: outside, lit") {
        in.light.extent = 1;
        in.eye.target = {1.5, 0, 0.25};
        in.eye.position = {1.5, 0.5, 4.5};
        const auto r = ShadowMap::render(in);
        CHECK(r.last.verdict == Verdict::Outside);
        CHECK(r.last.ti == -1);
        CHECK(r.counts.outside == 1);
    }
}

TEST_CASE("shadow-map: 2,000 random scenes against a long-double reference",
          "[shadows][shadow-map]") {
    cg::Rng rng(272);
    long long texels = 0, lookups = 0, verdicts = 0, rays = 0, shadows = 0, lits = 0, spots = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        CAPTURE(trial);
        const Input in = random_scene(rng);
        REQUIRE_NOTHROW(ShadowMap::validate(in));
        const auto r = ShadowMap::render(in);
        if (trial % 5 == 0) CHECK(cg::run_to_end<ShadowMap>(ShadowMap::start(in)) == r);
        spots += in.light.type == ShadowMap::LightType::Spot;
        const RefFrame F = ref_light(in);
        const int n = in.map_size;
        std::vector<LD> ref(std::size_t(n) * n);
        std::vector<bool> ref_clear(ref.size());
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                bool clear;
                ref[j * n + i] = ref_texel(in, F, i, j, clear);
                ref_clear[j * n + i] = clear;
                if (!clear) continue;
                CAPTURE(i, j);
                CHECK(std::fabs(r.depth[j * n + i] - ref[j * n + i]) <=
                      1e-9L * (1 + std::fabs(ref[j * n + i])));
                ++texels;
            }
        // Each lookup again, from its P: the light-space point, the texel, the verdicts.
        const auto eye = ShadowMap::eye_frame(in.eye);
        const auto light = ShadowMap::light_frame(in.light);
        for (int j = 0; j < in.eye.height; ++j)
            for (int i = 0; i < in.eye.width; ++i) {
                const auto l =
                    ShadowMap::lookup(in, light, eye, r.light_from_world, r.depth, r.owner, i, j);
                CHECK(r.image[j * in.eye.width + i] == l.verdict);
                if (l.tri < 0) continue;
                ++lookups;
                CAPTURE(i, j);
                const V3 p = v3(l.p);
                const V3 rel = sub(p, F.o);
                const LD xl = dot(rel, F.r), yl = dot(rel, F.u), d = dot(rel, F.f);
                CHECK(std::fabs(l.d_p - d) <= 1e-9L * (1 + std::fabs(d)));
                CHECK(std::fabs(l.p_light.x - xl) <= 1e-9L * (1 + std::fabs(xl)));
                CHECK(std::fabs(l.p_light.y - yl) <= 1e-9L * (1 + std::fabs(yl)));
                const LD scale = F.spot ? d * F.half : F.half;
                const LD s = (xl / scale + 1) / 2, t = (yl / scale + 1) / 2;
                const bool in_depth = d >= in.light.near && d <= in.light.far;
                const bool inside = in_depth && s >= 0 && s < 1 && t >= 0 && t < 1;
                // Too close to a texel boundary, the frustum's side or near/far to call.
                const LD sn = s * n, tn = t * n;
                const bool edge = std::fabs(sn - std::round(sn)) < 1e-7 ||
                                  std::fabs(tn - std::round(tn)) < 1e-7 ||
                                  std::fabs(d - in.light.near) < 1e-7 ||
                                  std::fabs(d - in.light.far) < 1e-7;
                if (edge) continue;
                CHECK(inside == (l.verdict != Verdict::Outside));
                if (!inside) continue;
                const int ti = int(std::floor(sn)), tj = int(std::floor(tn));
                CHECK(l.ti == ti);
                CHECK(l.tj == tj);
                if (!ref_clear[tj * n + ti]) continue;
                const LD gap = d - LD(in.bias) - ref[tj * n + ti];
                if (std::fabs(gap) > 1e-7) {
                    CHECK(l.map_shadow == (gap > 0));
                    ++verdicts;
                }
                bool clear = true;
                const bool blocked = ref_blocked(in, F, p, l.tri, clear);
                if (clear) {
                    CHECK(l.exact_shadow == blocked);
                    ++rays;
                    blocked ? ++shadows : ++lits;
                }
            }
    }
    INFO(texels << " texels, " << lookups << " lookups, " << verdicts << " map verdicts, " << rays
                << " shadow rays (" << shadows << " blocked), " << spots << " spot lights");
    CHECK(texels > 100000);
    CHECK(verdicts > 15000);
    CHECK(shadows > 500);
    CHECK(lits > 8000);
    CHECK(spots > 600);
}

TEST_CASE("shadow-map: bias 0 gives acne on the lit floor, a proper bias none",
          "[shadows][shadow-map]") {
    Input in = example();
    in.eye.width = 48;
    in.eye.height = 36;
    in.bias = 0;
    const auto zero = ShadowMap::render(in);
    CHECK(zero.counts.acne > 100);
    // f = (−1, −5, 2) / √30: across the floor the depth changes by at most
    // tan(angle between f and the normal) = √5 / 5 ≈ 0.45 per unit, so 0.32 from a 1-unit
    // texel's centre to its corner (0.71 away); a bias of 0.35 clears every texel.
    in.bias = 0.35;
    const auto proper = ShadowMap::render(in);
    CHECK(proper.counts.acne == 0);
    CHECK(proper.counts.shadow > 10);
    // A bias larger than the card's height over the floor leaks light under it.
    in.bias = 1.5;
    const auto leak = ShadowMap::render(in);
    CHECK(leak.counts.false_lit > 10);
    CHECK(leak.counts.shadow == 0);
}

TEST_CASE("shadow-map: the disagreements with the shadow rays fall as the map grows",
          "[shadows][shadow-map]") {
    Input in = example();
    in.eye.width = 64;
    in.eye.height = 48;
    std::vector<double> wrong;
    for (int n : {4, 8, 16, 32, 64}) {
        in.map_size = n;
        in.bias = 2.9 / n;  // more than 0.45 × half a texel's diagonal (√2 · 4 / n)
        const auto r = ShadowMap::render(in);
        const auto& c = r.counts;
        const double seen = c.lit + c.shadow + c.acne + c.false_shadow + c.false_lit;
        wrong.push_back((c.acne + c.false_shadow + c.false_lit) / seen);
        CAPTURE(n, c.acne, c.false_shadow, c.false_lit);
        CHECK(c.acne == 0);
    }
    CAPTURE(wrong);
    // Not strictly monotone from one size to the next (where the edge falls in the texels
    // varies), but every fourfold finer map at least halves them.
    for (std::size_t k = 2; k < wrong.size(); ++k) CHECK(wrong[k] <= wrong[k - 2] / 2);
    CHECK(wrong.front() > 0.02);
    CHECK(wrong.back() < wrong.front() / 4);
}

TEST_CASE("shadow-map: bad input names the field", "[shadows][shadow-map]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Input good = exam_scene();
    auto fails = [&](auto edit, const std::string& start) {
        Input in = good;
        edit(in);
        CHECK_THROWS_WITH(ShadowMap::start(in), Catch::StartsWith(start));
    };
    fails([](Input& in) { in.triangles.clear(); }, "triangles: must have at least 1 triangle");
    fails([](Input& in) { in.triangles[1][2] = in.triangles[1][1]; },
          "triangles[1]: has zero area");
    fails(
        [](Input& in) {
            in.triangles[2][0] = {0, 1, 0}, in.triangles[2][1] = {1, 1, 0},
            in.triangles[2][2] = {3, 1, 0};
        },
        "triangles[2]: has zero area");
    fails([&](Input& in) { in.triangles[0][1].y = nan; },
          "triangles[0][1][1]: must be a finite number (got NaN)");
    fails([](Input& in) { in.triangles[0][1].y = 1e300; }, "triangles[0][1][1]: is too large");
    fails([](Input& in) { in.light.target = in.light.position; },
          "light.target: must differ from light.position");
    fails([](Input& in) { in.light.up = {0, 1, 0}; }, "light.up: is parallel to the view");
    fails([](Input& in) { in.light.extent = 0; }, "light.extent: must be > 0");
    fails([](Input& in) { in.light.far = 0.2; }, "light.far: must be greater than light.near");
    fails([](Input& in) { in.light.near = -1; }, "light.near: must be ≥ 0");
    fails(
        [](Input& in) {
            in.light.type = ShadowMap::LightType::Spot;
            in.light.fov_deg = 180;
        },
        "light.fov_deg: must be in (0, 170]");
    fails(
        [](Input& in) {
            in.light.type = ShadowMap::LightType::Spot;
            in.light.fov_deg = 60;
            in.light.near = 0;
        },
        "light.near: must be > 0 for a spot light");
    fails([](Input& in) { in.map_size = 0; }, "map_size: must be 1 to 64");
    fails([](Input& in) { in.bias = -0.1; }, "bias: must be ≥ 0");
    fails([&](Input& in) { in.bias = nan; }, "bias: must be a finite number");
    fails([](Input& in) { in.eye.fov_deg = 0; }, "eye.fov_deg: must be in (0, 170]");
    fails([](Input& in) { in.eye.width = 65; }, "eye.width: must be 1 to 64 pixels");
    fails([](Input& in) { in.triangles.resize(65, in.triangles[0]); },
          "triangles: has 65 triangles; at most 64");
    auto error = [](const std::string& text) { return cg::test::error_of("shadow-map", text); };
    cg::json j = cg::test::algorithm("shadow-map").example();
    j["light"]["type"] = "point";
    CHECK_THAT(error(j.dump()),
               Catch::StartsWith("light.type: must be \"directional\" or \"spot\""));
    j = cg::test::algorithm("shadow-map").example();
    j["light"]["fov_deg"] = 60;
    CHECK_THAT(error(j.dump()), Catch::StartsWith("light.fov_deg: is not a known field"));
    j = cg::test::algorithm("shadow-map").example();
    j["triangles"][1] = cg::json::parse("[[0, 0, 0], [1, 0, 0]]");
    CHECK_THAT(error(j.dump()), Catch::StartsWith("triangles[1]: must be a triangle"));
    j = cg::test::algorithm("shadow-map").example();
    j["map_size"] = 1000000000000LL;
    CHECK_THAT(error(j.dump()), Catch::StartsWith("map_size: must be 1 to 64 (got 1000000000000)"));
    j = cg::test::algorithm("shadow-map").example();
    j["eye"]["height"] = 2.5;
    CHECK_THAT(error(j.dump()), Catch::StartsWith("eye.height: must be an integer"));
}

TEST_CASE("shadow-map: the light inside a closed box shadows everything outside it",
          "[shadows][shadow-map]") {
    Input in = example();
    // A small closed box (12 triangles) around a spot light at (0, 2, 0) over the floor.
    const dvec3 c{0, 2, 0};
    const double h = 0.5;
    auto q = [&](int a, int b, int cc) { return c + h * dvec3(a, b, cc); };
    const std::array<std::array<dvec3, 4>, 6> faces{
        {{q(-1, -1, -1), q(1, -1, -1), q(1, -1, 1), q(-1, -1, 1)},
         {q(-1, 1, -1), q(1, 1, -1), q(1, 1, 1), q(-1, 1, 1)},
         {q(-1, -1, -1), q(1, -1, -1), q(1, 1, -1), q(-1, 1, -1)},
         {q(-1, -1, 1), q(1, -1, 1), q(1, 1, 1), q(-1, 1, 1)},
         {q(-1, -1, -1), q(-1, 1, -1), q(-1, 1, 1), q(-1, -1, 1)},
         {q(1, -1, -1), q(1, 1, -1), q(1, 1, 1), q(1, -1, 1)}}};
    for (const auto& f : faces) {
        in.triangles.push_back(tri(f[0], f[1], f[2]));
        in.triangles.push_back(tri(f[0], f[2], f[3]));
    }
    in.light.type = ShadowMap::LightType::Spot;
    in.light.position = c;
    in.light.target = {0, 0, 0};
    in.light.up = {0, 0, -1};
    in.light.fov_deg = 80;  // its pyramid meets only the box's bottom
    in.light.near = 0.1;
    const auto r = ShadowMap::render(in);
    // Every texel holds the box's bottom (depth 0.5), so every visible floor point is shadowed.
    for (double d : r.depth) CHECK(d == Approx(0.5));
    CHECK(r.counts.lit == 0);
    CHECK(r.counts.shadow + r.counts.outside > 20);
}

TEST_CASE("shadow-map: replay on the example and the presets, run-to-end is render",
          "[shadows][shadow-map]") {
    const cg::Algorithm& a = cg::test::algorithm("shadow-map");
    cg::test::check_replay(a, a.example(), 7);
    std::set<std::string> seen;
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, 9);
        const Input in = input_of(p.input);
        CHECK(cg::run_to_end<ShadowMap>(ShadowMap::start(in)) == ShadowMap::render(in));
        for (const auto& e : cg::test::events(cg::test::run_traced<ShadowMap>(in))) seen.insert(e);
    }
    for (const auto& e : ShadowMap::spec().events) {
        CAPTURE(e.id);
        CHECK(seen.count(e.id));
    }
    CHECK(lesson().presets[0].input == a.example());
    const cg::json r = cg::test::result_of("shadow-map", a.example());
    CHECK(r["depth_map"].size() == 8);
    CHECK(r["image"].size() == 12);
    CHECK(r["image"][0].get<std::string>().size() == 16);
    CHECK(r["acne"] == 0);
    CHECK(r["shadow"].get<int>() > 0);
}

TEST_CASE("shadow-map: exam problems ask about one point, away from texel edges",
          "[shadows][shadow-map]") {
    const cg::Algorithm& a = cg::test::algorithm("shadow-map");
    int shadows = 0, lits = 0, tops = 0;
    for (std::uint64_t seed = 0; seed < 500; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = input_of(p.input);
        const auto r = ShadowMap::render(in);
        REQUIRE(r.last.tri >= 0);
        REQUIRE(r.last.ti >= 0);
        CHECK(std::fabs(r.last.p.x - in.eye.target.x) < 1e-9);
        CHECK(std::fabs(r.last.p.z - in.eye.target.z) < 1e-9);
        // Under the card (x, z inside it) and on the floor: shadow; otherwise lit.
        const auto& c = in.triangles[2];
        const dvec3 P = in.eye.target;
        const bool under = P.y == 0 && P.x > c[0].x && P.x < c[1].x && P.z > c[0].z && P.z < c[2].z;
        CHECK(r.last.map_shadow == under);
        CHECK(r.last.verdict == (under ? Verdict::Shadow : Verdict::Lit));
        for (double d : r.depth) CHECK((d == 5 || d == 5 - c[0].y));
        CHECK(p.answers.size() == 5);
        CHECK_THAT(p.question, Catch::Contains(cg::num(P)));
        under ? ++shadows : ++lits;
        tops += P.y > 0;
    }
    CHECK(shadows > 50);
    CHECK(lits > 150);
    CHECK(tops > 60);
}

TEST_CASE("shadow-map: the picture — scene, frustum, map and eye image", "[shadows][shadow-map]") {
    auto s = ShadowMap::start(example());
    cg::Scene pic;
    ShadowMap::draw(s, pic);
    CHECK(pic.has_3d());
    CHECK(!pic.has_2d());  // the map and the image are panels, not drawn into a world
    CHECK(pic.faces3.size() == 4);
    CHECK(pic.focus3.size() == 1);
    REQUIRE(pic.panels.size() == 2);
    for (const auto& panel : pic.panels) {
        CHECK(panel.kind == cg::PanelKind::Image);
        REQUIRE(panel.grids.size() == 1);
    }
    CHECK(pic.panels[0].grids[0].width == 8);  // the depth map
    CHECK(pic.panels[1].grids[0].width == 16);  // the eye image
    for (int k = 0; k < 3; ++k) ShadowMap::step(s, nullptr);  // setup, two triangles
    cg::Scene mid;
    ShadowMap::draw(s, mid);
    int active = 0;
    for (const auto& poly : mid.panels[0].polygons) active += poly.style.role == cg::Role::Active;
    CHECK(active == s.written);  // the texels the triangle wrote, outlined in the map
    CHECK(active > 0);
    // The first lookup that finds a texel: the texel and the pixel outlined, in cell units.
    while (!(s.last == ShadowMap::Phase::Lookup && s.look.ti >= 0)) ShadowMap::step(s, nullptr);
    cg::Scene first;
    ShadowMap::draw(s, first);
    const auto& texel = first.panels[0].polygons.back();
    CHECK(texel.style.role == cg::Role::Active);
    CHECK(texel.points[0] == glm::dvec2(s.look.ti, s.look.tj));
    const auto& pixel = first.panels[1].polygons.back();
    CHECK(pixel.style.role == cg::Role::Active);
    CHECK(pixel.points[0] == glm::dvec2(s.look.i, s.look.j));
    CHECK(first.panels[1].labels.size() == 1);  // the pixel's verdict
    while (s.phase != ShadowMap::Phase::Summary) ShadowMap::step(s, nullptr);
    cg::Scene look;
    ShadowMap::draw(s, look);
    bool p = false, dmap = false;
    for (const auto& q : look.points3) p = p || q.label == "P", dmap = dmap || q.label == "d_map";
    CHECK(p == (s.look.tri >= 0));
    CHECK(dmap == (s.look.ti >= 0));
    // The eye image is filled in: no empty cell left, and its key names what it shows.
    for (auto c : look.panels[1].grids[0].rgba) CHECK(c != 0u);
    CHECK(!look.panels[1].legend.empty());
    CHECK(look.panels[1].legend[0].text == "lit");
}
