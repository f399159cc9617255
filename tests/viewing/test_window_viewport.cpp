// Window to viewport through NDC: exam cases worked by hand; 5,000 random rectangles and points
// against independent computations (GLM's translate/scale matrices, and the closed form in
// long double); the composed matrix against the product; aspect-ratio warnings; errors;
// determinism and the picture.
#include <catch2/catch.hpp>

#include "support/replay.hpp"

#define GLM_ENABLE_EXPERIMENTAL
#include <cmath>
#include <glm/gtx/matrix_transform_2d.hpp>
#include <limits>

#include "core/timeline.hpp"
#include "io/registry.hpp"
#include "viewing/window_viewport.hpp"
#include "support/traced.hpp"

using cg::WindowViewport;
using glm::dvec2;
using Rect = WindowViewport::Rect;

namespace {

struct Traced {
    WindowViewport::Result result;
    std::vector<cg::StepInfo> steps;
};

Traced run_traced(const WindowViewport::Input& in) {
    Traced t;
    auto s = WindowViewport::start(in);
    while (!WindowViewport::done(s)) {
        cg::StepInfo info;
        WindowViewport::step(s, &info);
        t.steps.push_back(info);
    }
    t.result = WindowViewport::result(s);
    return t;
}

using cg::test::events;

// Row r of a glm matrix (glm is m[column][row]).
std::array<double, 3> row(const glm::dmat3& m, int r) {
    return {m[0][r], m[1][r], m[2][r]};
}

// |a − b| within 1e-12 of the size of the numbers that made it.
bool close(long double a, long double b, long double size) {
    return std::fabs(a - b) <= 1e-12L * std::max<long double>(1, size);
}

}  // namespace

TEST_CASE("window-viewport: exam cases worked by hand", "[viewing][window-viewport]") {
    SECTION("a 2:1 window in a 4:3 viewport: distorted") {
        const Traced t = run_traced({{0, 0, 8, 4}, {0, 0, 640, 480}, {{2, 1}, {6, 1}, {4, 3}}});
        CHECK(events(t) == std::vector<std::string>{
                               "distortion", "window-to-ndc", "point-to-ndc", "point-to-ndc",
                               "point-to-ndc", "ndc-to-viewport", "point-to-device",
                               "point-to-device", "point-to-device", "compose"});
        CHECK(t.result.ndc == std::vector<dvec2>{{-0.5, -0.5}, {0.5, -0.5}, {0, 0.5}});
        CHECK(t.result.device == std::vector<dvec2>{{160, 120}, {480, 120}, {320, 360}});
        CHECK(row(t.result.ndc_from_window, 0) == std::array<double, 3>{0.25, 0, -1});
        CHECK(row(t.result.ndc_from_window, 1) == std::array<double, 3>{0, 0.5, -1});
        CHECK(row(t.result.device_from_ndc, 0) == std::array<double, 3>{320, 0, 320});
        CHECK(row(t.result.device_from_ndc, 1) == std::array<double, 3>{0, 240, 240});
        CHECK(row(t.result.device_from_window, 0) == std::array<double, 3>{80, 0, 0});
        CHECK(row(t.result.device_from_window, 1) == std::array<double, 3>{0, 120, 0});
        CHECK(row(t.result.device_from_window, 2) == std::array<double, 3>{0, 0, 1});
        CHECK(t.result.distorted);
        CHECK(t.result.aspect_window == 2);
        CHECK(t.result.aspect_viewport == Approx(4.0 / 3));
    }
    SECTION("an off-centre window, same aspect, points on corners and outside") {
        // Window [-2, 2] × [1, 4] (4 × 3), viewport [100, 500] × [50, 350] (400 × 300): x_d =
        // 100 + (x + 2)·100, y_d = 50 + (y − 1)·100.
        const Traced t =
            run_traced({{-2, 1, 2, 4}, {100, 50, 500, 350}, {{-2, 1}, {2, 4}, {0, 2.5}, {3, 1}}});
        CHECK(t.steps[0].event == "aspect-match");
        CHECK_FALSE(t.result.distorted);
        CHECK(t.result.ndc == std::vector<dvec2>{{-1, -1}, {1, 1}, {0, 0}, {1.5, -1}});
        CHECK(t.result.device == std::vector<dvec2>{{100, 50}, {500, 350}, {300, 200}, {600, 50}});
        CHECK(row(t.result.ndc_from_window, 0) == std::array<double, 3>{0.5, 0, 0});
        CHECK(row(t.result.ndc_from_window, 1)[1] == Approx(2.0 / 3));
        CHECK(row(t.result.ndc_from_window, 1)[2] == Approx(-5.0 / 3));
        CHECK(row(t.result.device_from_window, 0) == std::array<double, 3>{100, 0, 300});
        CHECK(row(t.result.device_from_window, 1)[1] == Approx(100));
        CHECK(row(t.result.device_from_window, 1)[2] == Approx(-50));
        CHECK_THAT(t.steps[5].narration, Catch::EndsWith("outside [−1, 1]²: the point lies outside "
                                                         "the window (mapping does not clip)."));
    }
    SECTION("a screen whose rows run downward: the window's corners to (0, 768) and (1024, 0)") {
        // Window [0, 8] × [0, 6] onto a 1024×768 screen with the origin at its top-left: x_d =
        // 128 x, y_d = 768 − 128 y. Given either way, the same map.
        WindowViewport::Input corners{{0, 0, 8, 6}, {0, 768, 1024, 0}, {{0, 0}, {8, 6}, {2, 3}}};
        corners.form = WindowViewport::Form::Corners;
        const Traced t = run_traced(corners);
        CHECK(t.steps[0].event == "aspect-match");  // |1024/−768| = 8/6: a flip, no stretch
        CHECK_FALSE(t.result.distorted);
        CHECK(t.result.aspect_viewport == Approx(4.0 / 3));
        CHECK(t.result.device == std::vector<dvec2>{{0, 768}, {1024, 0}, {256, 384}});
        CHECK(row(t.result.device_from_ndc, 1) == std::array<double, 3>{0, -384, 384});
        CHECK(row(t.result.device_from_window, 0) == std::array<double, 3>{128, 0, 0});
        CHECK(row(t.result.device_from_window, 1) == std::array<double, 3>{0, -128, 768});
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("viewport 1024 × −768 (aspect |Lv/Hv| = 1.333)") &&
                       Catch::Contains("Hv < 0: y is flipped (a negative scale"));
        CHECK_THAT(t.steps[5].narration, Catch::Contains("y by Hv/2 = −768/2 = −384"));

        const cg::Registry registry = cg::builtin_registry();
        const cg::Algorithm& a = *registry.find("window-viewport");
        const std::string window = R"("window": {"xmin": 0, "ymin": 0, "xmax": 8, "ymax": 6})";
        for (const std::string viewport :
             {R"({"corners": [[0, 768], [1024, 0]]})",
              R"({"xmin": 0, "ymin": 0, "xmax": 1024, "ymax": 768, "y_down": true})"}) {
            CAPTURE(viewport);
            const cg::json in = cg::parse_json("{" + window + R"(, "viewport": )" + viewport +
                                               R"(, "points": [[0, 0], [8, 6], [2, 3]]})");
            auto run = a.create(in);
            while (!run->done()) run->step(nullptr);
            const cg::json r = a.result(*run);
            CHECK(r["device"] == cg::json::parse("[[0, 768], [1024, 0], [256, 384]]"));
            CHECK(r["matrix"][1] == cg::json::parse("[0, -128, 768]"));
            CHECK(r["distorted"] == false);
        }
    }
    SECTION("no points: only the matrices") {
        const Traced t = run_traced({{-1, -1, 1, 1}, {0, 0, 200, 100}, {}});
        CHECK(events(t) == std::vector<std::string>{"distortion", "window-to-ndc",
                                                    "ndc-to-viewport", "compose"});
        CHECK(t.result.ndc.empty());
        CHECK(t.result.ndc_from_window == glm::dmat3(1.0));  // the window already is NDC
        CHECK(row(t.result.device_from_window, 0) == std::array<double, 3>{100, 0, 100});
        CHECK(row(t.result.device_from_window, 1) == std::array<double, 3>{0, 50, 50});
    }
}

TEST_CASE("window-viewport: the steps say what they compute", "[viewing][window-viewport]") {
    const Traced t = run_traced({{0, 0, 8, 4}, {0, 0, 640, 480}, {{2, 1}, {6, 1}, {4, 3}}});
    CHECK(t.steps[0].narration ==
          "Window 8 × 4 (aspect Lw/Hw = 2), viewport 640 × 480 (aspect Lv/Hv = 1.333): the aspect "
          "ratios differ. x will be scaled by Lv/Lw = 80 but y by Hv/Hw = 120, so shapes come out "
          "stretched (a circle becomes an ellipse).");
    CHECK(t.steps[2].narration ==
          "P0 = (2, 1): x_ndc = 2·(2 − 0)/8 − 1 = −0.5, y_ndc = 2·(1 − 0)/4 "
          "− 1 = −0.5, so P0_ndc = (−0.5, −0.5).");
    CHECK(t.steps[8].narration ==
          "P2_ndc = (0, 0.5): x_d = 0 + (0 + 1)·640/2 = 320, y_d = 0 + (0.5 "
          "+ 1)·480/2 = 360, so P2_device = (320, 360).");
    CHECK_THAT(t.steps[9].narration, Catch::StartsWith("Window to device in one matrix: M = M_vp · "
                                                       "M_ndc = [80 0 0; 0 120 0; 0 0 1]"));
    CHECK_THAT(t.steps[1].math, Catch::EndsWith("\\begin{bmatrix} 0.25 & 0 & -1 \\\\ 0 & 0.5 & -1 "
                                                "\\\\ 0 & 0 & 1 \\end{bmatrix}"));
    for (const auto& s : t.steps) {
        bool declared = false;
        for (const auto& e : WindowViewport::spec().events) declared = declared || e.id == s.event;
        CHECK(declared);
        CHECK(s.line >= 1);
        CHECK(s.line <= int(WindowViewport::spec().pseudocode.size()));
    }
}

TEST_CASE("window-viewport: 5,000 random maps agree with GLM matrices and the closed form",
          "[viewing][window-viewport]") {
    int distorted = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        auto rect = [&](double reach, double min_size, double max_size) {
            const double x = rng.uniform(-reach, reach), y = rng.uniform(-reach, reach);
            return Rect{x, y, x + rng.uniform(min_size, max_size),
                        y + rng.uniform(min_size, max_size)};
        };
        WindowViewport::Input in{rect(100, 0.5, 50), rect(1000, 10, 2000), {}};
        if (trial % 4 == 0) {  // same aspect ratio
            const double scale = rng.uniform(0.5, 100);
            in.viewport.xmax = in.viewport.xmin + scale * (in.window.xmax - in.window.xmin);
            in.viewport.ymax = in.viewport.ymin + scale * (in.window.ymax - in.window.ymin);
        }
        // Devices whose rows (or, rarely, columns) run the other way: the viewport given by the
        // images of the window's corners, flipped.
        if (trial % 3 == 1) std::swap(in.viewport.ymin, in.viewport.ymax);
        if (trial % 5 == 2) std::swap(in.viewport.xmin, in.viewport.xmax);
        if (trial % 3 == 1 || trial % 5 == 2) in.form = WindowViewport::Form::Corners;
        const int n = static_cast<int>(rng.integer(0, 6));
        for (int k = 0; k < n; ++k)
            in.points.push_back({rng.uniform(-200, 200), rng.uniform(-200, 200)});
        CAPTURE(trial);
        const auto r = cg::run_to_end<WindowViewport>(WindowViewport::start(in));
        REQUIRE(WindowViewport::map(in) == r);

        // GLM's own translate and scale: ndc = T(−1, −1) S(2/Lw, 2/Hw) T(−xmin, −ymin), and so on.
        const Rect &w = in.window, &v = in.viewport;
        const double lw = w.xmax - w.xmin, hw = w.ymax - w.ymin, lv = v.xmax - v.xmin,
                     hv = v.ymax - v.ymin;
        const glm::dmat3 ndc = glm::translate(
            glm::scale(glm::translate(glm::dmat3(1.0), dvec2(-1, -1)), dvec2(2 / lw, 2 / hw)),
            dvec2(-w.xmin, -w.ymin));
        const glm::dmat3 device =
            glm::translate(glm::scale(glm::translate(glm::dmat3(1.0), dvec2(v.xmin, v.ymin)),
                                      dvec2(lv / 2, hv / 2)),
                           dvec2(1, 1));
        for (int c = 0; c < 3; ++c)
            for (int rr = 0; rr < 3; ++rr) {
                CAPTURE(c, rr);
                REQUIRE(close(r.ndc_from_window[c][rr], ndc[c][rr],
                              std::fabs(w.xmin + w.xmax) / lw + std::fabs(w.ymin + w.ymax) / hw));
                REQUIRE(close(
                    r.device_from_ndc[c][rr], device[c][rr],
                    std::fabs(v.xmin) + std::fabs(v.xmax) + std::fabs(v.ymin) + std::fabs(v.ymax)));
            }
        // The composed matrix is the product, and the closed form x_d = xv_min + (x − xw_min)
        // Lv/Lw.
        REQUIRE(r.device_from_window == r.device_from_ndc * r.ndc_from_window);
        using ld = long double;
        const ld sx = ld(lv) / lw, sy = ld(hv) / hw;  // negative where the viewport flips
        const ld size = std::fabs(v.xmin) + std::fabs(v.ymin) +
                        (std::fabs(w.xmin) + 1) * std::fabs(sx) +
                        (std::fabs(w.ymin) + 1) * std::fabs(sy);
        REQUIRE(close(r.device_from_window[0][0], sx, size));
        REQUIRE(close(r.device_from_window[1][1], sy, size));
        REQUIRE(close(r.device_from_window[2][0], v.xmin - w.xmin * sx, size));
        REQUIRE(close(r.device_from_window[2][1], v.ymin - w.ymin * sy, size));
        REQUIRE(r.device_from_window[1][0] == 0);
        REQUIRE(r.device_from_window[0][1] == 0);

        REQUIRE(r.ndc.size() == in.points.size());
        REQUIRE(r.device.size() == in.points.size());
        for (std::size_t k = 0; k < in.points.size(); ++k) {
            const dvec2 p = in.points[k];
            const ld nx = 2 * (ld(p.x) - w.xmin) / lw - 1, ny = 2 * (ld(p.y) - w.ymin) / hw - 1;
            const ld dx = v.xmin + (ld(p.x) - w.xmin) * sx, dy = v.ymin + (ld(p.y) - w.ymin) * sy;
            const ld ndc_size =
                2 * (std::fabs(p.x) + std::fabs(w.xmin) + std::fabs(p.y) + std::fabs(w.ymin)) /
                    std::min(lw, hw) +
                1;
            const ld device_size = size + (std::fabs(p.x) + std::fabs(w.xmin)) * std::fabs(sx) +
                                   (std::fabs(p.y) + std::fabs(w.ymin)) * std::fabs(sy);
            CAPTURE(k, p.x, p.y);
            REQUIRE(close(r.ndc[k].x, nx, ndc_size));
            REQUIRE(close(r.ndc[k].y, ny, ndc_size));
            REQUIRE(close(r.device[k].x, dx, device_size));
            REQUIRE(close(r.device[k].y, dy, device_size));
            // One matrix does what the two did.
            const glm::dvec3 q = r.device_from_window * glm::dvec3(p, 1.0);
            REQUIRE(close(q.x, dx, device_size));
            REQUIRE(close(q.y, dy, device_size));
        }
        REQUIRE(r.distorted == (trial % 4 != 0));
        distorted += r.distorted;
    }
    CHECK(distorted == 3750);
}

TEST_CASE("window-viewport: the aspect ratio warning", "[viewing][window-viewport]") {
    struct Case {
        Rect window, viewport;
        bool distorted;
    };
    const std::vector<Case> cases = {
        {{0, 0, 4, 3}, {0, 0, 640, 480}, false},
        {{0, 0, 1.3333333333, 1}, {0, 0, 640, 480}, false},  // 4/3 to ten digits: the same shape
        {{0, 0, 1.33, 1}, {0, 0, 640, 480}, true},           // to three: not
        {{-1, -1, 1, 1}, {0, 0, 500, 500}, false},
        {{-1, -1, 1, 1}, {0, 0, 500, 501}, true},
        {{0, 0, 8, 4}, {0, 0, 640, 480}, true},
        {{10, 20, 11, 22},
         {-50, -50, 50, 150},
         false},  // both 1:2, viewport at negative device coordinates
    };
    for (const Case& c : cases) {
        CAPTURE(c.window.xmax, c.viewport.ymax);
        const Traced t = run_traced({c.window, c.viewport, {}});
        CHECK(t.result.distorted == c.distorted);
        CHECK(t.steps[0].event == (c.distorted ? "distortion" : "aspect-match"));
        cg::Scene scene;
        auto s = WindowViewport::start({c.window, c.viewport, {}});
        WindowViewport::step(s, nullptr);
        WindowViewport::draw(s, scene);
        // The warning is written under the viewport, in the device's chart.
        REQUIRE(scene.panels.size() == 2);
        bool warning = false;
        for (const auto& l : scene.panels[1].labels)
            warning = warning || l.style.role == cg::Role::Discarded;
        CHECK(warning == c.distorted);
    }
}

TEST_CASE("window-viewport: bad input names the field", "[viewing][window-viewport]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Rect vp{0, 0, 640, 480};
    CHECK_THROWS_WITH(WindowViewport::start({{3, 0, 3, 4}, vp, {}}),
                      "window.xmax: must be greater than window.xmin: the window has zero width "
                      "(xmin = xmax = 3)");
    CHECK_THROWS_WITH(WindowViewport::start({{0, 0, 8, 4}, {0, 480, 640, 0}, {}}),
                      "viewport.ymax: must be greater than viewport.ymin (0 < 480): the rectangle "
                      "is inverted; for a device whose y runs downward add \"y_down\": true, or "
                      "give the images of the window's corners as \"corners\": [[x, y], [x, y]]");
    // Said to be flipped, the same corners are a map (see the exam case); zero size never is.
    WindowViewport::Input flipped{{0, 0, 8, 4}, {0, 480, 640, 0}, {}};
    flipped.form = WindowViewport::Form::Corners;
    CHECK_NOTHROW(WindowViewport::start(flipped));
    flipped.viewport.ymax = 480;
    CHECK_THROWS_WITH(WindowViewport::start(flipped),
                      "viewport.corners[1][1]: must differ from viewport.corners[0][1]: the "
                      "viewport has zero height (ymin = ymax = 480)");
    CHECK_THROWS_WITH(WindowViewport::start({{0, 0, 8, 4}, {0, 0, 640, 0}, {}}),
                      "viewport.ymax: must be greater than viewport.ymin: the viewport has zero "
                      "height (ymin = ymax = 0)");
    CHECK_THROWS_WITH(WindowViewport::start({{nan, 0, 8, 4}, vp, {}}),
                      "window.xmin: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(WindowViewport::start({{0, 0, 8, 4}, vp, {{1, 1}, {2, nan}}}),
                      "points[1][1]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(WindowViewport::start({{-1e308, 0, 1e308, 4}, vp, {}}),
                      "window: is too large or too small to map (inf × 4)");
    CHECK_THROWS_WITH(WindowViewport::start({{0, 0, 1e-320, 4}, vp, {}}),
                      Catch::StartsWith("window: is too large or too small to map"));

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("window-viewport");
    auto error = [&](const std::string& text) {
        try {
            a.create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    const std::string rects =
        R"("window": {"xmin": 0, "ymin": 0, "xmax": 8, "ymax": 4}, "viewport": {"xmin": 0, "ymin": 0, "xmax": 640, "ymax": 480})";
    CHECK(error("{" + rects + "}") == "(accepted)");  // points may be left out
    CHECK(error("{" + rects + R"(, "points": []})") == "(accepted)");
    CHECK(error("{" + rects + R"(, "points": [[1, 2, 3]]})") ==
          "points[0]: must be a point [x, y], got an array ([1,2,3])");
    CHECK_THAT(
        error(
            R"({"window": {"xmin": 0, "ymin": 0, "xmax": 8}, "viewport": {"xmin": 0, "ymin": 0, "xmax": 640, "ymax": 480}})"),
        Catch::StartsWith("window.ymax: is missing"));
    CHECK_THAT(error("{" + rects + R"(, "point": []})"),
               Catch::StartsWith("point: is not a known field"));
}

TEST_CASE("window-viewport: traces are deterministic and stepping back reproduces them",
          "[viewing][window-viewport]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("window-viewport");
    REQUIRE(a);
    const cg::json input = a->example();
    cg::test::check_replay(*a, input, 4);

    // The result's JSON: matrices as rows.
    auto run = a->create(input);
    while (!run->done()) run->step(nullptr);
    const cg::json r = a->result(*run);
    CHECK(r["matrix"] == cg::json::parse("[[80, 0, 0], [0, 120, 0], [0, 0, 1]]"));
    CHECK(r["window_to_ndc"][0] == cg::json::parse("[0.25, 0, -1]"));
    CHECK(r["device"][2] == cg::json::parse("[320, 360]"));
    CHECK(r["distorted"] == true);
}

TEST_CASE("window-viewport: the picture shows window, NDC and viewport side by side",
          "[viewing][window-viewport]") {
    auto s = WindowViewport::start({{0, 0, 8, 4}, {0, 0, 640, 480}, {{2, 1}, {6, 1}, {4, 3}}});
    for (int k = 0; k < 7; ++k) WindowViewport::step(s, nullptr);  // up to P0's device image
    cg::Scene scene;
    WindowViewport::draw(s, scene);
    // The window in the world, where it is: its handles edit the input directly.
    REQUIRE(scene.labels.size() == 1);
    CHECK(scene.labels[0].text == "window (world) [0, 8] × [0, 4]");
    REQUIRE(scene.handles.size() == 5);
    CHECK(scene.handles[0].p == dvec2(2, 1));
    CHECK(scene.handles[0].x_field == "/points/0/0");
    CHECK(scene.handles[4].y_field == "/window/ymax");
    // NDC and the device are charts in their own units, one scale for x and y each, so the
    // square stays square and a distortion shows.
    REQUIRE(scene.panels.size() == 2);
    const cg::Panel &ndc = scene.panels[0], &dev = scene.panels[1];
    CHECK(ndc.kind == cg::PanelKind::Chart);
    CHECK(ndc.title == "NDC [−1, 1] × [−1, 1]");
    CHECK(ndc.x.label == "x_ndc");
    CHECK((ndc.x.lo <= -1 && ndc.x.hi >= 1 && ndc.y.lo <= -1 && ndc.y.hi >= 1));
    CHECK(ndc.equal_aspect);
    CHECK(ndc.points.size() == 3);  // every point's image in NDC
    CHECK(dev.kind == cg::PanelKind::Chart);
    CHECK(dev.title == "viewport (device) [0, 640] × [0, 480]");
    CHECK(dev.equal_aspect);
    CHECK_FALSE(dev.y.reversed);
    REQUIRE(dev.polygons.size() >= 1);
    CHECK(dev.polygons[0].style.role == cg::Role::Window);
    bool distorted = false;
    for (const auto& l : dev.labels) distorted = distorted || l.text.rfind("distorted", 0) == 0;
    CHECK(distorted);
    // P0 just mapped to the device: orange there, with its coordinates.
    REQUIRE(dev.points.size() == 1);
    CHECK(dev.points[0].style.role == cg::Role::Active);
    CHECK(dev.points[0].label == "P0_device = (160, 120)");

    // A screen whose rows run downward: the device's y axis grows downward, so the image is
    // upright and the corners say where the window's corners land.
    WindowViewport::Input screen{{0, 0, 8, 6}, {0, 768, 1024, 0}, {{2, 3}}};
    screen.form = WindowViewport::Form::YDown;
    cg::Scene down;
    WindowViewport::draw(WindowViewport::start(screen), down);
    REQUIRE(down.panels.size() == 2);
    CHECK(down.panels[1].y.reversed);
    CHECK(down.panels[1].title == "viewport (device, y down)");
    bool corner = false;
    for (const auto& l : down.panels[1].labels) corner = corner || l.text == "(0, 768)";
    CHECK(corner);
}
