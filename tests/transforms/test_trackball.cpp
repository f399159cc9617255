// Virtual sphere and arcball drags: exam cases worked by hand; 3,000 random drags of each kind
// against an independent computation (the ball mapping and every pair's rotation redone in long
// double with Rodrigues' formula, and for the arcball GLM's glm::rotation(s, t) squared); the
// course's contrast, numerically: random paths between the same two ends give the same
// arcball rotation (to 1e-12) but different virtual-sphere rotations, and closed mouse loops
// return the arcball to the identity but not the virtual sphere; errors; determinism; the
// picture; exam problems.
#include <catch2/catch.hpp>

#include "support/traced.hpp"
#include "support/replay.hpp"

#define GLM_ENABLE_EXPERIMENTAL
#include <array>
#include <cmath>
#include <glm/gtx/quaternion.hpp>
#include <limits>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "transforms/trackball_drag.hpp"

using cg::Arcball;
using cg::VirtualSphere;
using glm::dvec2;
using glm::dvec3;

namespace {

using ld = long double;
using M3 = std::array<std::array<ld, 3>, 3>;  // rows
using V3 = std::array<ld, 3>;

constexpr ld kPiL = 3.141592653589793238462643383279502884L;
constexpr double kPi = 3.14159265358979323846;

using cg::test::run_traced;
using cg::test::Traced;

template <class A>
std::vector<std::string> events(const Traced<A>& t) {
    std::vector<std::string> e;
    for (const auto& s : t.steps) e.push_back(s.event);
    return e;
}

M3 identity() { return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; }

M3 mul(const M3& a, const M3& b) {
    M3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
    return c;
}

// Rodrigues: R = I + sin θ K + (1 − cos θ) K², K the cross-product matrix of the unit axis.
M3 rodrigues(V3 axis, ld angle) {
    const ld len = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (len == 0) return identity();
    for (ld& a : axis) a /= len;
    const M3 k = {{{0, -axis[2], axis[1]}, {axis[2], 0, -axis[0]}, {-axis[1], axis[0], 0}}};
    const M3 k2 = mul(k, k);
    M3 r = identity();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] += std::sin(angle) * k[i][j] + (1 - std::cos(angle)) * k2[i][j];
    return r;
}

V3 cross(V3 a, V3 b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
ld dot(V3 a, V3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
ld norm(V3 a) { return std::sqrt(dot(a, a)); }

struct Ball {
    ld mx, my;
    V3 p;
    bool rim;
};

// The ball mapping written out again, in long double.
Ball ball(dvec2 mouse, dvec2 viewport) {
    const ld d = std::min<ld>(viewport.x, viewport.y);
    Ball b;
    b.mx = 2 * (mouse.x - ld(viewport.x) / 2) / d;
    b.my = 2 * (mouse.y - ld(viewport.y) / 2) / d;
    const ld r2 = b.mx * b.mx + b.my * b.my;
    b.rim = r2 > 1;
    if (b.rim)
        b.p = {b.mx / std::sqrt(r2), b.my / std::sqrt(r2), 0};
    else
        b.p = {b.mx, b.my, std::sqrt(1 - r2)};
    return b;
}

M3 reference_pair(bool arcball, const Ball& s, const Ball& t) {
    if (arcball) {
        const V3 axis = cross(s.p, t.p);
        return rodrigues(axis, 2 * std::atan2(norm(axis), dot(s.p, t.p)));
    }
    if (s.rim) return rodrigues({0, 0, 1}, std::atan2(s.mx * t.my - s.my * t.mx, s.mx * t.mx + s.my * t.my));
    const V3 v = {t.mx - s.mx, t.my - s.my, 0};
    return rodrigues(cross(s.p, v), norm(v));
}

M3 reference_drag(bool arcball, const std::vector<dvec2>& samples, dvec2 viewport) {
    M3 r = identity();
    for (std::size_t k = 1; k < samples.size(); ++k)
        r = mul(reference_pair(arcball, ball(samples[k - 1], viewport), ball(samples[k], viewport)), r);
    return r;
}

ld max_diff(const glm::dmat3& m, const M3& r) {
    ld e = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) e = std::max(e, std::fabs(ld(m[j][i]) - r[i][j]));
    return e;
}

ld max_diff(const glm::dmat3& a, const glm::dmat3& b) {
    ld e = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) e = std::max(e, std::fabs(ld(a[j][i]) - b[j][i]));
    return e;
}

// A random mouse position: mostly inside the ball, sometimes outside it (the rim case).
dvec2 random_sample(cg::Rng& rng, dvec2 vp, bool inside = false) {
    const double d = std::min(vp.x, vp.y);
    const double reach = !inside && rng.chance(0.15) ? 1.6 : 0.98;
    const double r = reach * std::sqrt(rng.uniform(0, 1)), a = rng.uniform(0, 2 * 3.14159265358979);
    return vp * 0.5 + 0.5 * d * r * dvec2(std::cos(a), std::sin(a));
}

dvec2 random_viewport(cg::Rng& rng) { return {rng.uniform(50, 2000), rng.uniform(50, 2000)}; }

// One random drag against the long-double reference; returns the number of rim pairs.
template <class A>
int check_random_drag(dvec2 vp, const std::vector<dvec2>& samples) {
    constexpr bool arcball = A::kArcball;
    CAPTURE(arcball);
    const int n = static_cast<int>(samples.size());
    const auto r = cg::run_to_end<A>(A::start({vp, samples, {}}));
    REQUIRE(A::drag({vp, samples, {}}) == r);
    REQUIRE(r.pairs.size() == samples.size() - 1);
    REQUIRE(max_diff(r.matrix, reference_drag(arcball, samples, vp)) < 1e-12L * n);
    // The matrix is the quaternion's, and the quaternion is canonical and unit.
    REQUIRE(r.rotation.w >= 0);
    REQUIRE(std::fabs(glm::length(r.rotation) - 1) < 1e-14);
    REQUIRE(max_diff(glm::mat3_cast(r.rotation), r.matrix) < 1e-14);
    int rim = 0;
    for (std::size_t k = 0; k + 1 < samples.size(); ++k) {
        const Ball s = ball(samples[k], vp), t = ball(samples[k + 1], vp);
        REQUIRE(r.pairs[k].rim == (arcball ? s.rim || t.rim : s.rim));
        rim += r.pairs[k].rim;
        // Each pair's axis and angle make the reference pair's rotation.
        const M3 pair = rodrigues({r.pairs[k].axis.x, r.pairs[k].axis.y, r.pairs[k].axis.z},
                                  r.pairs[k].angle_deg * kPiL / 180);
        const M3 ref = reference_pair(arcball, s, t);
        ld e = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) e = std::max(e, std::fabs(pair[i][j] - ref[i][j]));
        REQUIRE(e < 1e-12L);
        if (arcball) {
            // GLM's shortest-arc rotation from s to t, applied twice.
            const dvec3 sp(double(s.p[0]), double(s.p[1]), double(s.p[2]));
            const dvec3 tp(double(t.p[0]), double(t.p[1]), double(t.p[2]));
            if (glm::dot(sp, tp) > -0.999) {
                const glm::dquat g = glm::rotation(sp, tp);
                const glm::dmat3 g2 = glm::mat3_cast(g * g);
                ld e2 = 0;
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) e2 = std::max(e2, std::fabs(ld(g2[j][i]) - ref[i][j]));
                REQUIRE(e2 < 1e-9L);
            }
        }
    }
    return rim;
}

}  // namespace

TEST_CASE("trackball: exam cases worked by hand", "[transforms][arcball][virtual-sphere]") {
    SECTION("from the centre to (0.6, 0): arcball twice the angle, virtual sphere |v| radians") {
        // 200 × 200: the centre (100, 100), one ball radius = 100 px. s = (0, 0, 1), t = (0.6, 0,
        // 0.8). Arcball: q = (s · t, s × t) = (0.8, (0, 0.6, 0)): about y by 2·36.87° = 73.74°,
        // cos = 0.28, sin = 0.96. Virtual sphere: v = (0.6, 0, 0), axis s × v = (0, 0.6, 0), angle
        // 0.6 rad.
        const auto a = run_traced<Arcball>({{200, 200}, {{100, 100}, {160, 100}}, {}});
        CHECK(events(a) == std::vector<std::string>{"sample-on-sphere", "target-on-sphere",
                                                    "pair-rotation", "accumulate",
                                                    "path-independent"});
        CHECK(a.result.rotation.w == Approx(0.8));
        CHECK(a.result.rotation.x == Approx(0).margin(1e-15));
        CHECK(a.result.rotation.y == Approx(0.6));
        CHECK(a.result.rotation.z == Approx(0).margin(1e-15));
        REQUIRE(a.result.pairs.size() == 1);
        CHECK(a.result.pairs[0].axis == dvec3(0, 1, 0));
        CHECK(a.result.pairs[0].angle_deg == Approx(2 * std::atan2(0.6, 0.8) * 180 / kPi));
        CHECK_FALSE(a.result.pairs[0].rim);
        CHECK(a.result.matrix[0][0] == Approx(0.28));   // column 0, row 0
        CHECK(a.result.matrix[2][0] == Approx(0.96));   // row 0, column 2: sin
        CHECK(a.result.matrix[0][2] == Approx(-0.96));
        CHECK(a.result.matrix[1][1] == Approx(1));
        CHECK(a.steps[2].narration ==
              "s · t = 0.8 (the angle from s to t is 36.87°) and s × t = (0, 0.6, 0): q = [0.8, 0, "
              "0.6, 0], a turn of 73.74° about (0, 1, 0), twice the angle, so that s itself would "
              "move past t by as much again.");

        const auto v = run_traced<VirtualSphere>({{200, 200}, {{100, 100}, {160, 100}}, {}});
        CHECK(events(v) == std::vector<std::string>{"sample-on-sphere", "velocity", "pair-rotation",
                                                    "accumulate", "path-independent"});
        CHECK(v.result.rotation.w == Approx(std::cos(0.3)));
        CHECK(v.result.rotation.y == Approx(std::sin(0.3)));
        CHECK(v.result.pairs[0].axis == dvec3(0, 1, 0));
        CHECK(v.result.pairs[0].angle_deg == Approx(0.6 * 180 / kPi));
        CHECK(v.steps[1].narration ==
              "T = S1 = (160, 100) px, at m_T = (0.6, 0) in ball units: the mouse moved by v = m_T "
              "− m_S = (0.6, 0), |v| = 0.6 ball radii — a velocity along the sphere at s, not a "
              "second point on it.");
    }
    SECTION("S outside the ball: the virtual sphere turns about z, the arcball uses the rim") {
        // 300 × 200: centre (150, 100), d = 200. S = (270, 100): m = (1.2, 0), outside; T = (150,
        // 190): m = (0, 0.9). Virtual sphere: about z by ∠(S, T) = 90°. Arcball: s = (1, 0, 0),
        // t = (0, 0.9, √0.19): about s × t = (0, −√0.19, 0.9) by 2·90° = 180°.
        const auto v = run_traced<VirtualSphere>({{300, 200}, {{270, 100}, {150, 190}}, {}});
        CHECK(events(v) == std::vector<std::string>{"sample-outside", "velocity", "rim-rotation",
                                                    "accumulate", "path-independent"});
        CHECK(v.result.pairs[0].rim);
        CHECK(v.result.pairs[0].axis == dvec3(0, 0, 1));
        CHECK(v.result.pairs[0].angle_deg == Approx(90));
        CHECK(v.result.rotation.w == Approx(std::sqrt(0.5)));
        CHECK(v.result.rotation.z == Approx(std::sqrt(0.5)));

        const auto a = run_traced<Arcball>({{300, 200}, {{270, 100}, {150, 190}}, {}});
        CHECK(events(a)[0] == "sample-outside");
        CHECK(events(a)[1] == "target-on-sphere");
        CHECK(a.result.pairs[0].rim);
        CHECK(a.result.pairs[0].angle_deg == Approx(180));
        CHECK(a.result.pairs[0].axis.x == Approx(0).margin(1e-15));
        CHECK(a.result.pairs[0].axis.y == Approx(-std::sqrt(0.19)));
        CHECK(a.result.pairs[0].axis.z == Approx(0.9));
    }
    SECTION("a closed three-sample loop: the arcball returns, the virtual sphere does not") {
        const std::vector<dvec2> loop = {{100, 100}, {160, 100}, {100, 160}, {100, 100}};
        const auto a = run_traced<Arcball>({{200, 200}, loop, {}});
        CHECK(a.steps.back().event == "loop-returns");
        CHECK(a.result.closed);
        CHECK(a.result.net_angle_deg < 1e-9);
        CHECK(max_diff(a.result.matrix, glm::dmat3(1.0)) < 1e-14);
        const auto v = run_traced<VirtualSphere>({{200, 200}, loop, {}});
        CHECK(v.steps.back().event == "loop-drifts");
        CHECK(v.result.net_angle_deg > 5);
        CHECK_THAT(v.steps.back().narration,
                   Catch::EndsWith("the virtual sphere does not return when the mouse does."));
    }
    SECTION("a virtual-sphere path that stays outside the ball spins about z path-independently") {
        // 300 × 200: (290, 100) → m = (1.4, 0), (280, 190) → (1.3, 0.9), (10, 100) → (−1.4, 0):
        // 34.7° then 145.3° about z, 180° in all, as the straight step from the first to the last.
        const auto v = run_traced<VirtualSphere>({{300, 200}, {{290, 100}, {280, 190}, {10, 100}}, {}});
        CHECK(v.steps.back().event == "path-independent");
        CHECK(v.result.net_angle_deg == Approx(180));
        CHECK(v.result.path_gap_deg < 1e-9);
        CHECK_THAT(v.steps.back().narration, Catch::EndsWith("a pause adds nothing)."));
    }
    SECTION("no motion, and opposite rim points") {
        const auto v = run_traced<VirtualSphere>({{200, 200}, {{120, 130}, {120, 130}}, {}});
        CHECK(v.steps[2].event == "no-rotation");
        CHECK(v.result.rotation == glm::dquat(1, 0, 0, 0));
        CHECK(v.result.pairs[0].axis == dvec3(0, 0, 0));
        // Arcball from one rim point to the opposite: twice 180° is a full turn.
        const auto a = run_traced<Arcball>({{300, 100}, {{0, 50}, {300, 50}}, {}});
        CHECK(a.steps[2].event == "no-rotation");
        CHECK(a.result.net_angle_deg < 1e-12);
        CHECK_THAT(a.steps[2].narration, Catch::StartsWith("t = −s"));
    }
    SECTION("the object turns with the ball") {
        const auto a = run_traced<Arcball>({{200, 200}, {{100, 100}, {160, 100}}, {{1, 0, 0}, {0, 0, 1}}});
        REQUIRE(a.result.object.size() == 2);
        CHECK(a.result.object[0].x == Approx(0.28));
        CHECK(a.result.object[0].z == Approx(-0.96));
        CHECK(a.result.object[1].x == Approx(0.96));  // the front point follows the drag (+x)
    }
}

TEST_CASE("trackball: 3,000 random drags of each kind agree with Rodrigues in long double",
          "[transforms][arcball][virtual-sphere]") {
    int rim_pairs = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        cg::Rng rng(trial);
        const dvec2 vp = random_viewport(rng);
        std::vector<dvec2> samples;
        const int n = static_cast<int>(rng.integer(2, 12));
        for (int k = 0; k < n; ++k) samples.push_back(random_sample(rng, vp));
        if (trial % 50 == 0) samples[1] = samples[0];  // a pair without motion
        CAPTURE(trial);
        rim_pairs += check_random_drag<VirtualSphere>(vp, samples);
        rim_pairs += check_random_drag<Arcball>(vp, samples);
    }
    CHECK(rim_pairs > 1000);
}

TEST_CASE("trackball: the arcball is path independent, the virtual sphere is not",
          "[transforms][arcball][virtual-sphere]") {
    int compared = 0;
    for (int trial = 0; trial < 300; ++trial) {
        cg::Rng rng(1000 + trial);
        const dvec2 vp = random_viewport(rng);
        const dvec2 a = random_sample(rng, vp), b = random_sample(rng, vp);
        CAPTURE(trial);
        std::vector<glm::dmat3> arc, vs;
        for (int path = 0; path < 6; ++path) {
            // At least one sample inside the ball: a path that stays outside only spins the
            // virtual sphere about z, and those angles add up path-independently.
            std::vector<dvec2> samples{a, random_sample(rng, vp, true)};
            const int middle = static_cast<int>(rng.integer(0, 20));
            for (int k = 0; k < middle; ++k) samples.push_back(random_sample(rng, vp));
            samples.push_back(b);
            const auto ra = cg::run_to_end<Arcball>(Arcball::start({vp, samples, {}}));
            const auto rv = cg::run_to_end<VirtualSphere>(VirtualSphere::start({vp, samples, {}}));
            // The arcball's drag equals its one pair straight from a to b.
            REQUIRE(max_diff(ra.matrix, glm::mat3_cast(ra.direct)) < 1e-12);
            REQUIRE(ra.path_gap_deg < 1e-9);
            arc.push_back(ra.matrix);
            vs.push_back(rv.matrix);
            // The virtual sphere's differs from its straight step (a random path is no straight
            // line, so the gap is far above round-off).
            REQUIRE(rv.path_gap_deg > 1e-6);
        }
        for (std::size_t i = 1; i < arc.size(); ++i) {
            REQUIRE(max_diff(arc[i], arc[0]) < 1e-12);
            REQUIRE(max_diff(vs[i], vs[0]) > 1e-6);
            ++compared;
        }
    }
    CHECK(compared == 1500);
}

TEST_CASE("trackball: closed mouse loops return the arcball to its start, not the virtual sphere",
          "[transforms][arcball][virtual-sphere]") {
    int drifting = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        cg::Rng rng(5000 + trial);
        const dvec2 vp = random_viewport(rng);
        std::vector<dvec2> samples{random_sample(rng, vp, true)};  // see above
        const int middle = static_cast<int>(rng.integer(2, 30));
        for (int k = 0; k < middle; ++k) samples.push_back(random_sample(rng, vp));
        samples.push_back(samples.front());
        CAPTURE(trial);
        const auto ta = run_traced<Arcball>({vp, samples, {}});
        REQUIRE(ta.result.closed);
        REQUIRE(max_diff(ta.result.matrix, glm::dmat3(1.0)) < 1e-12);
        REQUIRE(ta.result.net_angle_deg < 1e-9);
        REQUIRE(ta.steps.back().event == "loop-returns");
        const auto tv = run_traced<VirtualSphere>({vp, samples, {}});
        // The long-double reference agrees that the loop does not close.
        const M3 ref = reference_drag(false, samples, vp);
        const ld trace = ref[0][0] + ref[1][1] + ref[2][2];
        const ld ref_angle = std::acos(std::clamp<ld>((trace - 1) / 2, -1, 1)) * 180 / kPiL;
        REQUIRE(std::fabs(tv.result.net_angle_deg - double(ref_angle)) < 1e-6);
        REQUIRE(tv.result.net_angle_deg > 1e-3);
        REQUIRE(tv.steps.back().event == "loop-drifts");
        drifting += tv.result.net_angle_deg > 1;
    }
    CHECK(drifting > 900);
}

TEST_CASE("trackball: bad input names the field", "[transforms][arcball][virtual-sphere]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<dvec2> two = {{1, 1}, {2, 2}};
    CHECK_THROWS_WITH(Arcball::start({{0, 100}, two, {}}), "viewport[0]: the width must be positive (got 0)");
    CHECK_THROWS_WITH(VirtualSphere::start({{100, -5}, two, {}}),
                      "viewport[1]: the height must be positive (got −5)");
    CHECK_THROWS_WITH(Arcball::start({{nan, 100}, two, {}}), "viewport[0]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Arcball::start({{100, 100}, {{1, 1}}, {}}),
                      "samples: needs at least 2 mouse samples to make a drag (got 1)");
    CHECK_THROWS_WITH(VirtualSphere::start({{100, 100}, {{1, 1}, {nan, 2}}, {}}),
                      "samples[1][0]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(VirtualSphere::start({{1e-300, 1e-300}, {{1, 1}, {1e300, 2}}, {}}),
                      Catch::StartsWith("viewport[0]: must lie between 1e-100 and 1e100 pixels"));
    CHECK_THROWS_WITH(Arcball::start({{100, 100}, two, {{0, 0, nan}}}),
                      "object[0][2]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Arcball::start({{100, 100}, two, {{0, 0, 1e200}}}),
                      Catch::StartsWith("object[0]: is too large to rotate"));

    const cg::Registry registry = cg::builtin_registry();
    for (const char* id : {"arcball", "virtual-sphere"}) {
        const cg::Algorithm& a = *registry.find(id);
        auto error = [&](const std::string& text) {
            try {
                a.create(cg::parse_json(text));
            } catch (const cg::InputError& e) {
                return std::string(e.what());
            }
            return std::string("(accepted)");
        };
        CHECK(error(R"({"viewport": [100, 100], "samples": [[1, 1], [2, 2]]})") == "(accepted)");
        CHECK(error(R"({"viewport": [100, 100], "samples": [[1, 1], [2, 2]], "object": [[0, 0, 1]]})") ==
              "(accepted)");
        CHECK(error(R"({"viewport": [100], "samples": [[1, 1], [2, 2]]})") ==
              "viewport: must be [width, height] in pixels, got an array ([100])");
        CHECK(error(R"({"viewport": [100, 100], "samples": [[1, 1], [2, 2, 3]]})") ==
              "samples[1]: must be a point [x, y], got an array ([2,2,3])");
        CHECK_THAT(error(R"({"viewport": [100, 100], "sample": []})"),
                   Catch::StartsWith("sample: is not a known field"));
        CHECK_THAT(error(R"({"viewport": [100, 100]})"), Catch::StartsWith("samples: is missing"));
    }
}

TEST_CASE("trackball: traces are deterministic and stepping back reproduces them",
          "[transforms][arcball][virtual-sphere]") {
    const cg::Registry registry = cg::builtin_registry();
    for (const char* id : {"arcball", "virtual-sphere"}) {
        const cg::Algorithm* a = registry.find(id);
        REQUIRE(a);
        cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);
        auto run = a->create(a->example());
        while (!run->done()) run->step(nullptr);
        const cg::json r = a->result(*run);
        CHECK(r["pairs"].size() == 4);
        CHECK(r["closed"] == true);
        CHECK(r["rotation"].size() == 4);
        CHECK(r["matrix"].size() == 3);
    }
}

TEST_CASE("trackball: the picture shows the viewport in 2D and the ball in 3D",
          "[transforms][arcball][virtual-sphere]") {
    const VirtualSphere::Input in{{200, 200}, {{100, 100}, {160, 100}, {160, 160}}, {}};
    auto v = VirtualSphere::start(in);
    VirtualSphere::step(v, nullptr);
    VirtualSphere::step(v, nullptr);  // S and the motion
    cg::Scene scene;
    VirtualSphere::draw(v, scene);
    CHECK(scene.has_2d());
    CHECK(scene.has_3d());
    REQUIRE(scene.handles.size() == 3);
    CHECK(scene.handles[1].x_field == "/samples/1/0");
    bool velocity2 = false, velocity3 = false;
    for (const auto& s : scene.segments) velocity2 = velocity2 || (s.arrow && s.style.role == cg::Role::Active);
    for (const auto& s : scene.segments3) velocity3 = velocity3 || (s.arrow && s.label == "v");
    CHECK(velocity2);
    CHECK(velocity3);
    int cube = 0;  // the object turned by the drag (a cube's 12 edges), its front point's trail
    for (const auto& s : scene.segments3) cube += s.style.role == cg::Role::Kept;
    CHECK(cube == 12);
    bool front = false;
    for (const auto& p : scene.points3) front = front || p.label == "R·(0, 0, 1)";
    CHECK(front);
    // The 2D view is a window round the path (60 px in a 200 px ball): no more of the viewport.
    CHECK(scene.polygons.size() >= 2);  // the disc's part and its rim
    for (const auto& poly : scene.polygons)
        for (const auto& q : poly.points) CHECK((q.x >= 50 && q.x <= 210 && q.y >= 50 && q.y <= 210));

    auto a = Arcball::start({{200, 200}, {{100, 100}, {160, 100}, {160, 160}}, {}});
    for (int k = 0; k < 3; ++k) Arcball::step(a, nullptr);  // s, t and the pair's rotation
    scene.clear();
    Arcball::draw(a, scene);
    bool s_and_t = false, axis = false;
    for (const auto& p : scene.points3) s_and_t = s_and_t || p.label == "t";
    for (const auto& s : scene.segments3) axis = axis || s.label.rfind("axis, 73.74°", 0) == 0;
    CHECK(s_and_t);
    CHECK(axis);
    // Before any step nothing is active yet.
    scene.clear();
    Arcball::draw(Arcball::start(Arcball::Input{{200, 200}, {{1, 1}, {2, 2}}, {}}), scene);
    for (const auto& p : scene.points3) CHECK(p.style.role != cg::Role::Active);
}

TEST_CASE("trackball: exam problems have exact sphere points and grade their own answers",
          "[transforms][arcball][virtual-sphere]") {
    const cg::Registry registry = cg::builtin_registry();
    int outside = 0, loops = 0;
    for (const char* id : {"arcball", "virtual-sphere"}) {
        const cg::Algorithm& a = *registry.find(id);
        for (std::uint64_t seed = 0; seed < 300; ++seed) {
            CAPTURE(id, seed);
            const cg::ExamProblem p = cg::make_exam(a, seed);
            CHECK(p.question.find("S0 = ") != std::string::npos);
            for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
            Arcball::Input in;
            in.viewport = {p.input["viewport"][0].get<double>(), p.input["viewport"][1].get<double>()};
            for (const auto& q : p.input["samples"]) in.samples.push_back({q[0].get<double>(), q[1].get<double>()});
            for (const dvec2& s : in.samples) {
                const auto b = cg::trackball::to_ball(s, in.viewport);
                outside += b.rim;
                // Lifted points are short decimals: z is 0, 0.6, 0.8 or 1 (to round-off).
                const double z = b.p.z;
                CHECK((std::fabs(z) < 1e-12 || std::fabs(z - 0.6) < 1e-12 ||
                       std::fabs(z - 0.8) < 1e-12 || std::fabs(z - 1) < 1e-12));
            }
            loops += in.samples.front() == in.samples.back();
        }
    }
    CHECK(outside > 30);
    CHECK(loops > 10);
}

TEST_CASE("trackball: the doubled angle is what closes the arcball's loops (the lesson's numbers)",
          "[transforms][arcball]") {
    namespace tb = cg::trackball;
    const dvec2 vp(400, 300);
    // The angle a quaternion turns by, in degrees.
    auto degrees = [](glm::dquat q) {
        return glm::degrees(2 * std::acos(std::min(1.0, std::abs(q.w))));
    };
    // A drag's rotation: Shoemake's q = t s* per pair, or the rotation that merely carries s
    // onto t (by α, not 2α: the half-way quaternion, normalise(1 + t s*)).
    auto drag = [&](const std::vector<dvec2>& samples, bool doubled) {
        glm::dquat total(1, 0, 0, 0);
        for (std::size_t k = 1; k < samples.size(); ++k) {
            glm::dquat q = tb::arcball(tb::to_ball(samples[k - 1], vp), tb::to_ball(samples[k], vp));
            if (!doubled) q = glm::normalize(glm::dquat(1 + q.w, q.x, q.y, q.z));
            total = q * total;
        }
        return degrees(total);
    };
    auto square = [](double side) {
        return std::vector<dvec2>{{200, 150}, {200 + side, 150}, {200 + side, 150 + side},
                                  {200, 150 + side}, {200, 150}};
    };
    // The lesson's preset is the 30-pixel square.
    CHECK(drag(square(30), true) < 1e-9);
    CHECK(drag(square(30), false) == Approx(2.34).margin(0.005));   // "2.3°"
    CHECK(drag(square(90), true) < 1e-9);
    CHECK(drag(square(90), false) == Approx(26.39).margin(0.005));  // "26.4°"
    // Twice as far per pixel as the virtual sphere near the centre ...
    const tb::BallPoint s = tb::to_ball({200, 150}, vp), t = tb::to_ball({201, 150}, vp);
    CHECK(degrees(tb::arcball(s, t)) / degrees(tb::virtual_sphere(s, t)) == Approx(2).epsilon(1e-4));
    // ... so from the centre to the rim is half a turn, and rim to rim a full one (q = −1).
    CHECK(degrees(tb::arcball(tb::to_ball({200, 150}, vp), tb::to_ball({350, 150}, vp))) ==
          Approx(180));
    CHECK(tb::arcball(tb::to_ball({50, 150}, vp), tb::to_ball({350, 150}, vp)).w == Approx(-1));
}
