// Phong and Blinn-Phong lighting: hand cases worked from the course's formulas (a 3-4-5 light,
// directional and attenuated lights, a light behind the surface, colours, p = 0); 5,000 random
// inputs against the independent long-double evaluation of phong_reference.hpp; the state
// machine against the plain function; errors; exam problems; determinism and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "rays/phong_lighting.hpp"
#include "rays/phong_reference.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"

using cg::PhongLighting;
using glm::dvec3;

namespace {

using cg::test::events;
using cg::test::registry;
using Traced = cg::test::JsonTraced;

cg::test::JsonTraced run_json(const cg::json& input) {
    return cg::test::run_json("phong-lighting", input);
}

std::string error_of(const std::string& text) {
    return cg::test::error_of("phong-lighting", text);
}

// The example with changes applied.
cg::json base() {
    return registry().find("phong-lighting")->example();
}

using Events = std::vector<std::string>;

double num(const cg::json& j) {
    return j.get<double>();
}

}  // namespace

TEST_CASE("phong-lighting: a 3-4-5 light worked by hand, both models", "[rays][phong-lighting]") {
    // P = 0, n = z, E = (0, 0, 4): v = (0, 0, 1). Light at (3, 0, 4): l = (0.6, 0, 0.8), l·n = 0.8.
    // ambient 0.5·0.2 = 0.1; diffuse 0.6·0.8 = 0.48.
    // Blinn: v + l = (0.6, 0, 1.8), (h·n)² = 3.24/3.6 = 0.9, so (h·n)^20 = 0.9^10.
    // Phong: r = −l + 1.6 n = (−0.6, 0, 0.8), r·v = 0.8, 0.8^20.
    cg::json in = base();
    const Traced blinn = run_json(in);
    CHECK(events(blinn) ==
          Events{"view", "ambient", "point-light", "diffuse", "blinn-specular", "total"});
    const cg::json& r = blinn.result;
    CHECK(num(r["ambient"]) == Approx(0.1).epsilon(1e-15));
    CHECK(num(r["diffuse"]) == Approx(0.48).epsilon(1e-15));
    CHECK(num(r["specular"]) == Approx(0.4 * std::pow(0.9, 10)).epsilon(1e-14));
    CHECK(num(r["intensity"]) == Approx(0.58 + 0.4 * std::pow(0.9, 10)).epsilon(1e-14));
    CHECK(num(r["lights"][0]["n_dot_l"]) == Approx(0.8));
    CHECK(num(r["lights"][0]["n_dot_h"]) == Approx(std::sqrt(0.9)));
    CHECK(num(r["lights"][0]["attenuation"]) == 1);
    CHECK(r["v"] == cg::json::parse("[0, 0, 1]"));
    CHECK(blinn.steps[4].narration.find("h = (v + l)/|v + l|") != std::string::npos);

    in["model"] = "phong";
    const Traced phong = run_json(in);
    CHECK(events(phong)[4] == "phong-specular");
    CHECK(num(phong.result["specular"]) == Approx(0.4 * std::pow(0.8, 20)).epsilon(1e-13));
    CHECK(num(phong.result["lights"][0]["r_dot_v"]) == Approx(0.8));
    const cg::json rr = phong.result["lights"][0]["r"];
    CHECK(num(rr[0]) == Approx(-0.6));
    CHECK(num(rr[2]) == Approx(0.8));
    CHECK(phong.steps[4].math.find("r = -l + 2(l \\cdot n)n") != std::string::npos);
}

TEST_CASE("phong-lighting: hand cases", "[rays][phong-lighting]") {
    SECTION("a directional light is given by the way it travels and is not attenuated") {
        cg::json in = base();
        in["lights"] = cg::json::parse(R"([{"direction": [0, 0, -2], "intensity": 0.5}])");
        const Traced t = run_json(in);
        CHECK(events(t)[2] == "directional-light");
        CHECK(t.result["lights"][0]["l"] == cg::json::parse("[0, 0, 1]"));
        CHECK(num(t.result["diffuse"]) == Approx(0.3));  // 0.5 · 0.6 · 1
        // Blinn: h = n, so the highlight is full: 0.5 · 0.4.
        CHECK(num(t.result["specular"]) == Approx(0.2));
    }
    SECTION("a point light attenuated by 1/(c1 + c2 r + c3 r²)") {
        cg::json in = base();
        in["lights"][0]["attenuation"] = {1, 0.1, 0.01};  // r = 5: 1/(1 + 0.5 + 0.25)
        const Traced t = run_json(in);
        CHECK(num(t.result["lights"][0]["attenuation"]) == Approx(1 / 1.75));
        CHECK(num(t.result["diffuse"]) == Approx(0.48 / 1.75));
        CHECK(t.steps[2].narration.find("1/(1 + 0.1·5 + 0.01·5²)") != std::string::npos);
    }
    SECTION("a light behind the surface adds nothing, even where r·v > 0") {
        cg::json in = base();
        in["eye"] = {0, 0, -4};  // the eye below too, so that r·v = 0.8 > 0
        in["lights"][0]["position"] = {3, 0, -4};
        const Traced t = run_json(in);
        CHECK(events(t) ==
              Events{"view", "ambient", "point-light", "light-behind", "no-specular", "total"});
        CHECK(num(t.result["lights"][0]["n_dot_l"]) == Approx(-0.8));
        CHECK(num(t.result["diffuse"]) == 0);
        CHECK(num(t.result["specular"]) == 0);
        CHECK(num(t.result["intensity"]) == Approx(0.1));
        CHECK(t.steps[0].narration.find("back of the surface") != std::string::npos);
    }
    SECTION("colours: per-channel products, and the result as [r, g, b]") {
        cg::json in = base();
        in["material"]["kd"] = {1, 0.5, 0};
        in["lights"][0]["intensity"] = {1, 1, 0.5};
        const Traced t = run_json(in);
        REQUIRE(t.result["diffuse"].is_array());
        CHECK(num(t.result["diffuse"][0]) == Approx(0.8));
        CHECK(num(t.result["diffuse"][1]) == Approx(0.4));
        CHECK(num(t.result["diffuse"][2]) == 0);
        CHECK(t.result["ambient"] == cg::json::parse("[0.1, 0.1, 0.1]"));
        CHECK(num(t.result["specular"][2]) == Approx(0.5 * 0.4 * std::pow(0.9, 10)));
    }
    SECTION("shininess 0: the highlight covers the whole lit side (0⁰ = 1)") {
        cg::json in = base();
        in["material"]["shininess"] = 0;
        in["model"] = "phong";
        in["eye"] = {-4, 0, 0.001};  // r·v ≈ −0.6 < 0: clamped to 0, and 0⁰ = 1
        const Traced t = run_json(in);
        CHECK(num(t.result["specular"]) == Approx(0.4));
    }
    SECTION("several lights sum; an unnormalised normal is normalised; zero intensity is fine") {
        cg::json in = base();
        in["normal"] = {0, 0, 5};
        in["lights"].push_back(cg::json::parse(R"({"position": [-3, 0, 4], "intensity": 1})"));
        in["lights"].push_back(cg::json::parse(R"({"direction": [1, 1, 1], "intensity": 0})"));
        const Traced t = run_json(in);
        CHECK(num(t.result["diffuse"]) == Approx(0.96));
        CHECK(num(t.result["specular"]) == Approx(0.8 * std::pow(0.9, 10)));
        CHECK(t.result["lights"].size() == 3);
    }
    SECTION("no lights: ambient only") {
        cg::json in = base();
        in["lights"] = cg::json::array();
        const Traced t = run_json(in);
        CHECK(events(t) == Events{"view", "ambient", "total"});
        CHECK(num(t.result["intensity"]) == Approx(0.1));
    }
}

TEST_CASE("phong-lighting: 5,000 random inputs agree with a long-double evaluation",
          "[rays][phong-lighting][reference]") {
    cg::Rng rng(77);
    auto rv = [&](double lo, double hi) {
        return dvec3(rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi));
    };
    int lit = 0, behind = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        CAPTURE(trial);
        PhongLighting::Input in;
        in.model = rng.chance(0.5) ? PhongLighting::Model::Phong : PhongLighting::Model::BlinnPhong;
        in.rgb = rng.chance(0.5);
        auto col = [&](double hi) {
            return in.rgb ? rv(0, hi) : PhongLighting::Color(rng.uniform(0, hi));
        };
        in.point = rv(-5, 5);
        in.normal = rv(-1, 1) * rng.uniform(0.01, 100);
        in.eye = in.point + rv(-10, 10);
        in.ambient = col(1);
        in.material = {col(1), col(1), col(1), rng.chance(0.1) ? 0.0 : rng.uniform(0, 200)};
        const int n = static_cast<int>(rng.integer(0, 4));
        for (int i = 0; i < n; ++i) {
            PhongLighting::Light L;
            L.intensity = col(2);
            if (rng.chance(0.3)) {
                L.directional = true;
                L.direction = rv(-1, 1);
            } else {
                L.position = in.point + rv(-10, 10);
                if (rng.chance(0.5))
                    L.attenuation = {rng.uniform(0, 1), rng.uniform(0, 0.5), rng.uniform(0, 0.1)};
                if (L.attenuation == dvec3(0.0)) L.attenuation.x = 1;
            }
            in.lights.push_back(L);
        }
        const PhongLighting::Result got = PhongLighting::shade(in);
        const cg::test::LongShade want = cg::test::reference_shade(in);
        auto close = [](double a, long double b) {
            return std::fabs(a - b) <= 1e-10L * (1 + std::fabs(b));
        };
        for (int c = 0; c < 3; ++c) {
            CHECK(close(got.ambient[c], want.ambient[c]));
            CHECK(close(got.diffuse[c], want.diffuse[c]));
            CHECK(close(got.specular[c], want.specular[c]));
            CHECK(close(got.intensity[c], want.intensity[c]));
            CHECK(close(got.v[c], want.v[c]));
        }
        REQUIRE(got.lights.size() == want.lights.size());
        for (std::size_t i = 0; i < got.lights.size(); ++i) {
            const auto& g = got.lights[i];
            const auto& w = want.lights[i];
            CHECK(close(g.n_dot_l, w.n_dot_l));
            CHECK(close(g.r_dot_v, w.r_dot_v));
            CHECK(close(g.n_dot_h, w.n_dot_h));
            CHECK(close(g.attenuation, w.attenuation));
            for (int c = 0; c < 3; ++c) {
                CHECK(close(g.l[c], w.l[c]));
                CHECK(close(g.r[c], w.r[c]));
                CHECK(close(g.h[c], w.h[c]));
            }
            (g.n_dot_l > 0 ? lit : behind)++;
        }
        // The state machine, quietly and narrated, gives the same result bit for bit.
        auto s = PhongLighting::start(in);
        auto narrated = s;
        CHECK(cg::run_to_end<PhongLighting>(s) == got);
        if (trial % 10 == 0) {
            while (!PhongLighting::done(narrated)) {
                cg::StepInfo info;
                PhongLighting::step(narrated, &info);
                CHECK(info.narration.find("nan") == std::string::npos);
            }
            CHECK(PhongLighting::result(narrated) == got);
        }
    }
    CHECK(lit > 1000);
    CHECK(behind > 1000);
}

TEST_CASE("phong-lighting: bad input is refused with the field named",
          "[rays][phong-lighting][errors]") {
    auto with = [](auto change) {
        cg::json in = base();
        change(in);
        return error_of(in.dump());
    };
    CHECK(with([](cg::json&) {}) == "(accepted)");
    CHECK(with([](cg::json& j) {
              j["normal"] = {0, 0, 0};
          }) == "normal: must not be the zero vector: the surface needs a normal");
    CHECK_THAT(with([](cg::json& j) {
                   j["eye"] = {0, 0, 0};
               }),
               Catch::StartsWith("eye: must differ from point"));
    CHECK_THAT(with([](cg::json& j) { j["material"]["shininess"] = -1; }),
               Catch::StartsWith("material.shininess: must not be negative (got −1)"));
    CHECK(with([](cg::json& j) { j["material"]["kd"] = -0.5; }) ==
          "material.kd: must not be negative: a reflection coefficient (got −0.5)");
    CHECK(with([](cg::json& j) {
              j["material"]["ks"] = {0.1, -0.5, 0};
          }) == "material.ks[1]: must not be negative: a reflection coefficient (got −0.5)");
    CHECK_THAT(with([](cg::json& j) {
                   j["material"]["ka"] = {0.1, 0.5};
               }),
               Catch::StartsWith("material.ka: must be a number or a colour [r, g, b]"));
    CHECK_THAT(with([](cg::json& j) {
                   j["lights"][0]["position"] = {0, 0, 0};
               }),
               Catch::StartsWith("lights[0].position: must differ from point"));
    CHECK_THAT(with([](cg::json& j) {
                   j["lights"][0]["attenuation"] = {0, 0, 0};
               }),
               Catch::StartsWith("lights[0].attenuation: must not be all zero"));
    CHECK(with([](cg::json& j) {
              j["lights"][0]["attenuation"] = {1, -1, 0};
          }) == "lights[0].attenuation[1]: must not be negative (got −1)");
    CHECK_THAT(with([](cg::json& j) {
                   j["lights"][0] = cg::json::parse(
                       R"({"direction": [0, 0, -1], "intensity": 1, "attenuation": [1, 1, 0]})");
               }),
               Catch::StartsWith("lights[0].attenuation: is only for point lights"));
    CHECK(with([](cg::json& j) {
              j["lights"][0] = {{"direction", {0, 0, 0}}, {"intensity", 1}};
          }) == "lights[0].direction: must not be the zero vector");
    CHECK_THAT(with([](cg::json& j) {
                   j["lights"][0]["direction"] = {0, 0, -1};
               }),
               Catch::StartsWith("lights[0]: needs exactly one of \"position\""));
    CHECK_THAT(with([](cg::json& j) { j["lights"][0].erase("position"); }),
               Catch::StartsWith("lights[0]: needs exactly one of \"position\""));
    CHECK_THAT(with([](cg::json& j) { j["model"] = "gouraud"; }),
               Catch::StartsWith("model: must be \"phong\" or \"blinn-phong\""));
    CHECK_THAT(with([](cg::json& j) { j["lights"][0]["colour"] = 1; }),
               Catch::StartsWith("lights[0].colour: is not a known field"));

    // NaN from C++ (JSON cannot spell it): the field is named.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    PhongLighting::Input in;
    in.lights.push_back({});
    in.lights[0].position = {0, 0, 5};
    auto err = [&](auto change) {
        PhongLighting::Input copy = in;
        change(copy);
        try {
            PhongLighting::start(copy);
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(err([](auto&) {}) == "(accepted)");
    CHECK(err([&](auto& i) { i.point.x = nan; }) == "point[0]: must be a finite number (got NaN)");
    CHECK(err([&](auto& i) { i.normal.z = nan; }) ==
          "normal[2]: must be a finite number (got NaN)");
    CHECK(err([&](auto& i) { i.material.shininess = nan; }) ==
          "material.shininess: must be a finite number (got NaN)");
    CHECK(err([&](auto& i) { i.ambient = dvec3(nan); }) ==
          "ambient: must be a finite number (got NaN)");
    CHECK(err([&](auto& i) { i.lights[0].position.y = nan; }) ==
          "lights[0].position[1]: must be a finite number (got NaN)");
    CHECK(err([&](auto& i) {
              i.rgb = true;
              i.lights[0].intensity.z = nan;
          }) == "lights[0].intensity[2]: must be a finite number (got NaN)");
}

TEST_CASE("phong-lighting: exam problems are answered right", "[rays][phong-lighting][exam]") {
    const cg::Algorithm& a = *registry().find("phong-lighting");
    std::set<std::string> events;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        cg::Rng rng(seed);
        const PhongLighting::Input in = PhongLighting::exam_input(rng);
        const cg::test::LongShade want = cg::test::reference_shade(in);
        const cg::json& e = p.expected;
        for (int c = 0; c < (in.rgb ? 3 : 1); ++c) {
            auto at = [&](const char* f) { return in.rgb ? num(e[f][c]) : num(e[f]); };
            CHECK(at("ambient") == Approx(double(want.ambient[c])).margin(1e-12));
            CHECK(at("diffuse") == Approx(double(want.diffuse[c])).margin(1e-12));
            CHECK(at("specular") == Approx(double(want.specular[c])).margin(1e-12));
            CHECK(at("intensity") == Approx(double(want.intensity[c])).margin(1e-12));
        }
        CHECK(p.question.find("colour at P = ") != std::string::npos);
        const Traced t = run_json(p.input);
        for (const std::string& e : cg::test::events(t)) events.insert(e);
        for (const auto& g : cg::grade(p, e)) CHECK(g.correct);
    }
    for (const char* ev : {"point-light", "directional-light", "light-behind", "phong-specular",
                           "blinn-specular", "no-specular", "diffuse"}) {
        CAPTURE(ev);
        CHECK(events.count(ev) == 1);
    }
}

TEST_CASE("phong-lighting: traces are deterministic and the picture shows the vectors",
          "[rays][phong-lighting]") {
    const cg::Algorithm& a = *registry().find("phong-lighting");
    cg::json in = base();
    in["lights"].push_back(
        cg::json::parse(R"({"direction": [1, 0, -1], "intensity": [1, 0.5, 0.2]})"));
    cg::test::check_replay(a, in, cg::test::kEveryStep);

    auto run = a.create(base());
    for (int k = 0; k < 5; ++k) run->step(nullptr);  // through the specular step
    cg::Scene scene;
    run->draw(scene);
    CHECK(scene.has_3d());
    CHECK_FALSE(scene.has_2d());  // the highlight's fall-off is a chart, not in the world
    std::set<std::string> arrows;
    for (const auto& seg : scene.segments3)
        if (seg.arrow) {
            arrows.insert(seg.label);
            if (seg.label.size() == 1) CHECK(seg.min_pixels >= 30);  // n, v, l, h
        }
    CHECK(arrows == std::set<std::string>{"n", "v", "l", "h"});
    CHECK(scene.focus3.size() == 1);
    // n, l and v lie in the plane y = 0: seen face-on, orthographic.
    CHECK(scene.view3.orthographic);
    CHECK(std::fabs(scene.view3.look.y) == Approx(1));
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& chart = scene.panels[0];
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.x.label == "θ (°)");
    REQUIRE(chart.polygons.size() == 3);  // cos^p for p/4, 4p and p
    CHECK(chart.polygons.back().style.role == cg::Role::Active);
    REQUIRE(chart.legend.size() == 3);
    CHECK(chart.legend.back().text == "p = 20");
    bool half_width = false;
    for (const auto& seg : chart.segments)
        half_width = half_width || seg.label == "half-width 15°";  // acos(2^(−1/20))
    CHECK(half_width);
    REQUIRE(chart.points.size() == 1);  // this light's angle on the curve
    CHECK(chart.points[0].p.y == Approx(std::pow(0.9, 10)));
}
