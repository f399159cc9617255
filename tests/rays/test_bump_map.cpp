// Bump mapping: the floor's sine bumps worked by hand; Blinn's normal against the normal of the
// displaced surface P + B n̂ by finite differences in long double — on 2,000 random planes
// (exact in the limit) and 1,500 spheres, cylinders and mirrored triangles with small bumps
// (within the dropped B-terms' size); a constant B leaves n unchanged; the pole; the state
// machine bit for bit against the plain function; errors; exam problems against the derivatives
// by hand; determinism and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <set>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "rays/bump_map.hpp"
#include "rays/texture_reference.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::BumpMap;
using glm::dvec2;
using glm::dvec3;
namespace t = cg::test;

namespace {

const cg::Algorithm& algo() {
    return cg::test::algorithm("bump-map");
}

BumpMap::Input input_of(const cg::json& j) {
    return cg::test::input_of<BumpMap>("bump-map", j);
}

std::string error_of(const std::string& text) {
    return cg::test::error_of("bump-map", text);
}

constexpr double kPi = std::numbers::pi;

// The height function in long double, as the algorithm defines it (sines only).
t::LD sines_ref(const cg::HeightField& h, t::LD u, t::LD v) {
    return h.amplitude * std::sin(2 * t::kPiL * h.frequency.x * u) *
           std::sin(2 * t::kPiL * h.frequency.y * v);
}

// The angle between the algorithm's n' and the reference's, in radians.
double angle_to(dvec3 a, t::LVec b) {
    const t::LD c = t::dot(t::lv(a), t::normalized(b));
    return static_cast<double>(std::acos(std::min<t::LD>(1, std::max<t::LD>(-1, c))));
}

}  // namespace

TEST_CASE("bump-map: sine bumps on the floor, worked by hand", "[rays][bump-map]") {
    // B = 0.02 sin(4πu) sin(4πv) at (u, v) = (1/16, 1/16): both sines √½, so B = 0.01 and
    // B_u = B_v = 0.02·4π·cos(π/4) sin(π/4) = 0.04π; on the plane n' ∝ (−B_u, −B_v, 1).
    const auto tr = cg::test::run_traced<BumpMap>(input_of(algo().example()));
    CHECK(cg::test::events(tr) ==
          std::vector<std::string>{"partials", "height", "differences", "normal", "perturbed"});
    const cg::BumpResult& b = tr.result.bump;
    const double d = 0.04 * kPi;
    CHECK(b.B == Approx(0.01));
    // Central differences with h = 1e-4 are off by (4πh)²/6 ≈ 2.6e-7 of the slope.
    CHECK(b.B_u == Approx(d).epsilon(1e-6));
    CHECK(b.B_v == Approx(d).epsilon(1e-6));
    CHECK(b.B_u != Approx(d).epsilon(1e-8));  // ... and not better: they are differences
    CHECK(b.n == dvec3(0, 0, 1));
    CHECK(glm::length(b.perturbed - glm::normalize(dvec3(-d, -d, 1))) < 1e-7);
    CHECK(tr.result.tilt_deg == Approx(std::atan(d * std::sqrt(2.0)) * 180 / kPi).epsilon(1e-6));
    CHECK(tr.steps[4].narration.find("tilted") != std::string::npos);
}

TEST_CASE("bump-map: on planes Blinn's normal is the displaced surface's normal",
          "[rays][bump-map][reference]") {
    cg::Rng rng(11);
    for (int trial = 0; trial < 2000; ++trial) {
        BumpMap::Input in;
        cg::UvSurface& s = in.surface;
        s.kind = cg::UvKind::Plane;
        s.normal = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        if (glm::length(s.normal) < 0.1) s.normal = {0, 0, 1};
        s.u_axis = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        if (glm::length(glm::cross(glm::normalize(s.normal), s.u_axis)) < 0.2)
            s.u_axis = cg::default_u_axis(s.normal);
        s.origin = {rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3)};
        s.scale = rng.uniform(0.2, 4);
        in.height.kind = cg::HeightKind::Sines;
        in.height.amplitude = rng.uniform(-0.3, 0.3);
        in.height.frequency = {rng.uniform(0.2, 4), rng.uniform(0.2, 4)};
        in.height.step = 1e-5;
        const cg::PreparedUv p = cg::prepare_uv(s);
        const dvec2 uv{rng.uniform(-2, 2), rng.uniform(-2, 2)};
        in.point = cg::uv_point(p, uv);
        CAPTURE(trial);
        const BumpMap::Result r = BumpMap::solve(in);
        REQUIRE_FALSE(r.bump.singular);
        // The reference: P(u, v) + B n̂ differentiated in long double.
        const t::LVec O = t::lv(p.origin), A = t::lv(p.a), B = t::lv(p.b), N = t::lv(p.n);
        const t::LD sc = p.scale;
        auto point = [&](t::LD u, t::LD v) { return O + (sc * u) * A + (sc * v) * B; };
        auto normal = [&](t::LD, t::LD) { return N; };
        auto height = [&](t::LD u, t::LD v) { return sines_ref(in.height, u, v); };
        const t::LVec want =
            t::displaced_normal_ref(point, normal, height, r.frame.uv.x, r.frame.uv.y, 1e-7L, N);
        CHECK(angle_to(r.bump.perturbed, want) < 1e-7);
        CHECK(glm::length(r.bump.normal - glm::normalize(s.normal)) < 1e-12);
        CHECK(glm::length(r.bump.perturbed) == Approx(1).epsilon(1e-14));
    }
}

TEST_CASE("bump-map: on curved and mirrored surfaces it agrees to the size of the dropped terms",
          "[rays][bump-map][reference]") {
    cg::Rng rng(12);
    double worst_ratio = 0;
    for (int trial = 0; trial < 1500; ++trial) {
        BumpMap::Input in;
        const int kind = trial % 3;
        const double A = std::exp2(rng.uniform(-14, -8));  // small bumps
        in.height.kind = cg::HeightKind::Sines;
        in.height.amplitude = A;
        in.height.frequency = {rng.uniform(1, 6), rng.uniform(1, 6)};
        in.height.step = 1e-5;
        std::function<t::LVec(t::LD, t::LD)> point, normal;
        if (kind == 0) {  // a sphere of radius r: P(u, v), n̂ = P/r
            in.surface.kind = cg::UvKind::Quadric;
            in.surface.quadric.r = rng.uniform(0.5, 2);
            const t::LD r = in.surface.quadric.r;
            point = [r](t::LD u, t::LD v) {
                const t::LD ph = 2 * t::kPiL * (u - 0.5L), th = t::kPiL * (1 - v);
                return t::LVec{r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                               r * std::cos(th)};
            };
            normal = [point, r](t::LD u, t::LD v) { return (1 / r) * point(u, v); };
            const double ph = rng.uniform(-3, 3), th = rng.uniform(0.3, 2.8);
            in.point = double(r) * dvec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                                         std::cos(th));
        } else if (kind == 1) {  // the cylinder x² + y² = 1, 0 ≤ z ≤ 2: v = z/2
            in.surface.kind = cg::UvKind::Quadric;
            in.surface.quadric.kind = cg::QuadricKind::Cylinder;
            in.surface.quadric.zmin = 0;
            in.surface.quadric.zmax = 2;
            point = [](t::LD u, t::LD v) {
                const t::LD ph = 2 * t::kPiL * (u - 0.5L);
                return t::LVec{std::cos(ph), std::sin(ph), 2 * v};
            };
            normal = [](t::LD u, t::LD) {
                const t::LD ph = 2 * t::kPiL * (u - 0.5L);
                return t::LVec{std::cos(ph), std::sin(ph), 0};
            };
            const double ph = rng.uniform(-3, 3);
            in.point = {std::cos(ph), std::sin(ph), rng.uniform(0.2, 1.8)};
        } else {  // a triangle whose (u, v) are mirrored: P_u × P_v points inward
            in.surface.kind = cg::UvKind::Triangle;
            in.surface.p = {dvec3(0, 0, 0), dvec3(2, 0, 0), dvec3(0, 2, 0)};
            in.surface.uv = {dvec2(1, 0), dvec2(0, 0), dvec2(1, 1)};
            const cg::PreparedUv p = cg::prepare_uv(in.surface);
            point = [p](t::LD u, t::LD v) {
                return t::lv(cg::uv_point(p, dvec2(double(u), double(v))));
            };
            normal = [](t::LD, t::LD) { return t::LVec{0, 0, 1}; };
            in.point = {rng.uniform(0.1, 0.8), rng.uniform(0.1, 0.8), 0};
        }
        CAPTURE(trial, kind, A);
        const BumpMap::Result r = BumpMap::solve(in);
        REQUIRE_FALSE(r.bump.singular);
        auto height = [&](t::LD u, t::LD v) { return sines_ref(in.height, u, v); };
        const t::LVec want = t::displaced_normal_ref(point, normal, height, r.frame.uv.x,
                                                     r.frame.uv.y, 1e-6L, t::lv(r.bump.normal));
        // The perturbed normal leans the right way, by the right amount, up to the B·n̂_u terms
        // Blinn drops: their size is |B| times the curvature, so the error is O(A).
        const double err = angle_to(r.bump.perturbed, want);
        const double tilt = angle_to(r.bump.perturbed, t::lv(r.bump.normal));
        if (kind == 2) {
            CHECK(r.bump.flipped);
            CHECK(err < 1e-7);  // flat: exact in the limit, with the orientation put right
        } else {
            CHECK(err < 4 * A + 1e-7);
            worst_ratio = std::max(worst_ratio, err / A);
        }
        CHECK(tilt > 0);
    }
    CAPTURE(worst_ratio);
    CHECK(worst_ratio > 0.01);  // the dropped terms are real, not a test that cannot fail
}

TEST_CASE("bump-map: a constant height leaves the normal unchanged, and the pole has no frame",
          "[rays][bump-map]") {
    SECTION("amplitude 0") {
        const cg::json r = [] {
            auto run = algo().create(cg::parse_json(
                R"({"surface": {"type": "cylinder", "params": {"p": 1, "q": 1}, "zmin": 0, "zmax": 2}, "point": [1, 0, 1],
                    "height": {"type": "sines", "amplitude": 0, "frequency": 3}})"));
            while (!run->done()) run->step(nullptr);
            return algo().result(*run);
        }();
        CHECK(r["B_u"] == 0);
        CHECK(r["B_v"] == 0);
        CHECK(r["perturbed_normal"] == r["normal"]);
        CHECK(r["tilt_deg"] == 0);
    }
    SECTION("a constant height image") {
        BumpMap::Input in;
        in.surface.kind = cg::UvKind::Plane;
        in.point = {0.3, 0.4, 0};
        in.height.kind = cg::HeightKind::Image;
        in.height.amplitude = 0.5;
        in.height.image.image = cg::checker_image(4, 4, dvec3(0.7), dvec3(0.7));
        const BumpMap::Result r = BumpMap::solve(in);
        CHECK(r.bump.B == Approx(0.35));
        CHECK(r.bump.B_u == 0);
        CHECK(r.bump.perturbed == r.bump.normal);
    }
    SECTION("the pole") {
        const auto tr = cg::test::run_traced<BumpMap>(input_of(cg::parse_json(
            R"({"surface": {"type": "sphere", "params": {"r": 1}}, "point": [0, 0, 1],
                "height": {"type": "sines", "amplitude": 0.01, "frequency": 8}})")));
        CHECK(tr.steps.back().event == "singular");
        CHECK(tr.result.bump.singular);
        CHECK(tr.result.bump.perturbed == dvec3(0, 0, 1));
    }
}

TEST_CASE("bump-map: the state machine gives the plain function's answer, bit for bit",
          "[rays][bump-map]") {
    cg::Rng rng(13);
    std::set<std::string> events;
    for (int trial = 0; trial < 1000; ++trial) {
        BumpMap::Input in;
        in.surface.kind = trial % 2 ? cg::UvKind::Plane : cg::UvKind::Quadric;
        if (in.surface.kind == cg::UvKind::Quadric) {
            in.surface.quadric.r = rng.uniform(0.5, 2);
            in.point =
                in.surface.quadric.r *
                glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
            if (trial % 50 == 0) in.point = {0, 0, -in.surface.quadric.r};  // the south pole
        } else {
            in.point = {rng.uniform(-3, 3), rng.uniform(-3, 3), 0};
        }
        const int kind = static_cast<int>(rng.integer(0, 2));
        in.height.kind = static_cast<cg::HeightKind>(kind);
        in.height.amplitude = rng.uniform(-0.1, 0.1);
        in.height.frequency = {rng.uniform(1, 20), rng.uniform(1, 20)};
        in.height.seed = rng.next() >> 20;
        in.height.step = std::exp2(rng.uniform(-16, -6));
        if (kind == 2) {
            cg::TextureImage im;
            im.width = 8, im.height = 8;
            for (int k = 0; k < 64; ++k) im.texels.push_back(dvec3(rng.uniform(0, 1)));
            in.height.image.image = im;
        }
        CAPTURE(trial);
        const BumpMap::Result want = BumpMap::solve(in);
        auto s = BumpMap::start(in);
        CHECK(cg::run_to_end<BumpMap>(s) == want);
        const auto tr = cg::test::run_traced<BumpMap>(in);
        CHECK(tr.result == want);
        for (const auto& st : tr.steps) {
            events.insert(st.event);
            CHECK(st.narration.find("nan") == std::string::npos);
        }
    }
    for (const auto& e : BumpMap::spec().events) {
        CAPTURE(e.id);
        CHECK(events.count(e.id) == 1);
    }
}

TEST_CASE("bump-map: bad input is refused with the field named", "[rays][bump-map][errors]") {
    const std::string plane =
        R"("surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0, 0, 0])";
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "sines", "step": 0}})"),
               Catch::StartsWith("height.step: must be between 1e-9 and 0.1"));
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "sines", "step": 0.5}})"),
               Catch::StartsWith("height.step: must be between 1e-9 and 0.1"));
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "ripples"}})"),
               Catch::StartsWith("height.type: must be \"sines\", \"noise\" or \"image\""));
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "sines", "seed": 3}})"),
               Catch::StartsWith("height.seed: is not a known field"));
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "noise", "seed": -3}})"),
               Catch::StartsWith("height.seed: must be a whole number from 0 to 2^53"));
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "image"}})"),
               Catch::StartsWith("height: needs exactly one of \"image\""));
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "sines", "frequency": [1, 2, 3]}})"),
               Catch::StartsWith("height.frequency: must be a number or a pair [u, v]"));
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "sines", "amplitude": 1e7}})"),
               Catch::StartsWith("height.amplitude: must be a number of magnitude at most 1e6"));
    CHECK_THAT(error_of("{" + plane + R"(, "height": {"type": "sines"}, "light": [0, 0, 0]})"),
               Catch::StartsWith("light: must not be the zero vector"));
    CHECK_THAT(
        error_of(
            R"({"surface": {"type": "sphere", "params": {"r": 1}}, "point": [0, 0, 2], "height": {"type": "sines"}})"),
        Catch::StartsWith("point: must lie on the sphere"));
    CHECK_THAT(
        error_of(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "uv_scale": 0}, "point": [0, 0, 0], "height": {"type": "sines"}})"),
        Catch::StartsWith("surface.uv_scale: must be a length between 1e-9 and 1e12"));
}

TEST_CASE("bump-map: exam problems agree with the derivatives worked by hand",
          "[rays][bump-map][exam]") {
    int spheres = 0, flat = 0, singular = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(algo(), seed);
        const BumpMap::Input in = input_of(p.input);
        const BumpMap::Result r = BumpMap::solve(in);
        const cg::HeightField& h = in.height;
        const double u = r.frame.uv.x, v = r.frame.uv.y;
        const double w = 2 * kPi * h.frequency.x;
        const double Bu = h.amplitude * w * std::cos(w * u) * std::sin(w * v);
        const double Bv = h.amplitude * w * std::sin(w * u) * std::cos(w * v);
        if (r.bump.singular) {
            ++singular;
            continue;
        }
        CHECK(p.expected["B_u"].get<double>() == Approx(Bu).margin(1e-7));
        CHECK(p.expected["B_v"].get<double>() == Approx(Bv).margin(1e-7));
        flat += std::fabs(Bu) < 1e-12 && std::fabs(Bv) < 1e-12;
        if (in.surface.kind == cg::UvKind::Plane) {
            const dvec3 want = glm::normalize(dvec3(-Bu, -Bv, 1));
            CHECK(glm::length(r.bump.perturbed - want) < 1e-7);
        } else {
            ++spheres;
            // Equator, r = 1: n = 2π² x̂ (the outward point), D = −π B_u ŷ' − 2π B_v ẑ in the
            // point's frame (ŷ' the eastward unit vector).
            const dvec3 out = r.bump.normal, east = glm::normalize(r.frame.P_u);
            const dvec3 want = glm::normalize(2 * kPi * kPi * out - kPi * Bu * east -
                                              2 * kPi * Bv * dvec3(0, 0, 1));
            CHECK(glm::length(r.bump.perturbed - want) < 1e-6);
        }
        CHECK(cg::grade(p, p.expected)[2].correct);
    }
    CHECK(spheres > 40);
    CHECK(singular > 3);
    CHECK(flat > 10);
}

TEST_CASE("bump-map: traces are deterministic and stepping back reproduces them",
          "[rays][bump-map]") {
    cg::test::check_replay(algo(), algo().example(), cg::test::kEveryStep);
    cg::test::check_replay(
        algo(),
        cg::parse_json(
            R"({"surface": {"type": "sphere", "params": {"r": 1}}, "point": [0.6, 0, 0.8],
                           "height": {"type": "noise", "amplitude": 0.004, "frequency": [40, 20], "seed": 3}})"),
        cg::test::kEveryStep);
}

TEST_CASE("bump-map: the picture shows both normals and the lit patches", "[rays][bump-map]") {
    auto s = BumpMap::start(input_of(algo().example()));
    while (!BumpMap::done(s)) BumpMap::step(s, nullptr);
    cg::Scene scene;
    BumpMap::draw(s, scene);
    CHECK(scene.faces3.size() == 2 * 12 * 12);
    std::set<std::string> labels;
    for (const auto& seg : scene.segments3) labels.insert(seg.label);
    CHECK(labels.count("n") == 1);
    CHECK(labels.count("n'") == 1);
    for (const auto& seg : scene.segments3)
        if (seg.label == "n'") {
            CHECK(seg.min_pixels >= 30);  // the perturbed normal can be seen
            CHECK(seg.style.role == cg::Role::Active);
        }
    CHECK(scene.focus3.size() == 1);
    // The bumped patch's faces are not all lit alike; the smooth patch's are.
    std::set<std::uint32_t> bumped, smooth;
    for (std::size_t k = 0; k < scene.faces3.size(); ++k)
        (k < 12 * 12 ? bumped : smooth).insert(scene.faces3[k].style.rgba);
    CHECK(bumped.size() > 8);
    CHECK(smooth.size() == 1);
    // B along u and along v through P, each a chart in its own units with B at P and the
    // slope of the central difference through it.
    CHECK_FALSE(scene.has_2d());
    REQUIRE(scene.panels.size() == 2);
    for (const auto& chart : scene.panels) {
        CHECK(chart.kind == cg::PanelKind::Chart);
        CHECK(chart.y.label == "B");
        CHECK(chart.polygons.size() == 1);
        REQUIRE(chart.segments.size() == 1);
        CHECK(chart.segments[0].label.rfind("B_", 0) == 0);
    }
    CHECK(scene.panels[0].x.label == "u");
    CHECK(scene.panels[1].x.label == "v");
}
