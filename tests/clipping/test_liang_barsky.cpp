// Liang-Barsky: exam cases worked by hand, degenerate cases, and 10,000 random segments
// against Cohen-Sutherland in long double (a different algorithm, so a shared mistake is
// unlikely), plus determinism of the trace and of stepping back.
#include <catch2/catch.hpp>

#include "support/replay.hpp"

#include <random>

#include "clipping/liang_barsky.hpp"
#include "core/timeline.hpp"
#include "io/registry.hpp"
#include "support/traced.hpp"

using cg::LiangBarsky;
using glm::dvec2;

namespace {

// ---- The reference: Cohen-Sutherland with outcodes, in long double --------------------------
struct ClipRef {
    bool visible = false;
    long double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

enum : int { kInside = 0, kLeft = 1, kRight = 2, kBottom = 4, kTop = 8 };

int outcode(long double x, long double y, const LiangBarsky::Window& w) {
    int code = kInside;
    if (x < w.xmin) code |= kLeft;
    else if (x > w.xmax) code |= kRight;
    if (y < w.ymin) code |= kBottom;
    else if (y > w.ymax) code |= kTop;
    return code;
}

ClipRef cohen_sutherland(const LiangBarsky::Input& in) {
    const auto& w = in.window;
    long double x0 = in.p0.x, y0 = in.p0.y, x1 = in.p1.x, y1 = in.p1.y;
    int c0 = outcode(x0, y0, w), c1 = outcode(x1, y1, w);
    for (int guard = 0; guard < 16; ++guard) {
        if ((c0 | c1) == 0) return {true, x0, y0, x1, y1};
        if (c0 & c1) return {};
        // Move the endpoint that is outside onto the boundary it violates.
        const int out = c0 ? c0 : c1;
        long double x = 0, y = 0;
        if (out & kTop) {
            x = x0 + (x1 - x0) * (w.ymax - y0) / (y1 - y0), y = w.ymax;
        } else if (out & kBottom) {
            x = x0 + (x1 - x0) * (w.ymin - y0) / (y1 - y0), y = w.ymin;
        } else if (out & kRight) {
            y = y0 + (y1 - y0) * (w.xmax - x0) / (x1 - x0), x = w.xmax;
        } else {
            y = y0 + (y1 - y0) * (w.xmin - x0) / (x1 - x0), x = w.xmin;
        }
        if (out == c0) x0 = x, y0 = y, c0 = outcode(x0, y0, w);
        else x1 = x, y1 = y, c1 = outcode(x1, y1, w);
    }
    return {};  // cannot happen: each pass fixes one bit of one outcode
}

struct Traced {
    LiangBarsky::Result result;
    std::vector<cg::StepInfo> steps;
};

Traced run_traced(const LiangBarsky::Input& in) {
    Traced t;
    auto s = LiangBarsky::start(in);
    while (!LiangBarsky::done(s)) {
        cg::StepInfo info;
        LiangBarsky::step(s, &info);
        t.steps.push_back(info);
    }
    t.result = LiangBarsky::result(s);
    return t;
}

using cg::test::events;

const LiangBarsky::Window kWindow{1, 1, 5, 4};  // [1, 5] x [1, 4]

}  // namespace

TEST_CASE("liang-barsky: exam cases worked by hand", "[clipping][liang-barsky]") {
    struct Case {
        const char* name;
        dvec2 p0, p1;
        bool visible;
        double t_enter, t_leave;
        dvec2 q0, q1;
        std::vector<std::string> events;
    };
    const std::vector<Case> cases = {
        {"fully inside", {2, 2}, {4, 3}, true, 0, 1, {2, 2}, {4, 3},
         {"setup", "entering", "leaving", "entering", "leaving", "accept"}},
        {"fully outside (right)", {6, 0}, {7, 3}, false, 0, -1, {}, {},
         {"setup", "entering", "leaving", "reject"}},
        {"crossing one edge", {3, 2}, {7, 3}, true, 0, 0.5, {3, 2}, {5, 2.5},
         {"setup", "entering", "leaving", "entering", "leaving", "accept"}},
        {"crossing two edges", {0, 2}, {4, 6}, true, 0.25, 0.5, {1, 3}, {2, 4},
         {"setup", "entering", "leaving", "entering", "leaving", "accept"}},
        {"reversed direction", {4, 6}, {0, 2}, true, 0.5, 0.75, {2, 4}, {1, 3},
         {"setup", "leaving", "entering", "leaving", "entering", "accept"}},
        {"through a corner", {0, 3}, {2, 5}, true, 0.5, 0.5, {1, 4}, {1, 4},
         {"setup", "entering", "leaving", "entering", "leaving", "accept"}},
        {"along the bottom edge", {0, 1}, {6, 1}, true, 1.0 / 6, 5.0 / 6, {1, 1}, {5, 1},
         {"setup", "entering", "leaving", "parallel-inside", "parallel-inside", "accept"}},
        {"horizontal, parallel inside", {0, 2}, {6, 2}, true, 1.0 / 6, 5.0 / 6, {1, 2}, {5, 2},
         {"setup", "entering", "leaving", "parallel-inside", "parallel-inside", "accept"}},
        {"horizontal, parallel outside", {0, 5}, {6, 5}, false, 1.0 / 6, 5.0 / 6, {}, {},
         {"setup", "entering", "leaving", "parallel-inside", "parallel-outside", "reject"}},
        {"vertical, parallel outside", {0, 0}, {0, 6}, false, 0, 1, {}, {},
         {"setup", "parallel-outside", "reject"}},
        {"vertical crossing", {3, 0}, {3, 5}, true, 0.2, 0.8, {3, 1}, {3, 4},
         {"setup", "parallel-inside", "parallel-inside", "entering", "leaving", "accept"}},
        {"zero length inside", {2, 2}, {2, 2}, true, 0, 1, {2, 2}, {2, 2},
         {"setup", "parallel-inside", "parallel-inside", "parallel-inside", "parallel-inside",
          "accept"}},
        {"zero length outside", {0, 0}, {0, 0}, false, 0, 1, {}, {},
         {"setup", "parallel-outside", "reject"}},
        {"zero length on the boundary", {1, 4}, {1, 4}, true, 0, 1, {1, 4}, {1, 4},
         {"setup", "parallel-inside", "parallel-inside", "parallel-inside", "parallel-inside",
          "accept"}},
        {"misses past a corner", {0, 4}, {2, 6}, false, 0.5, 0, {}, {},
         {"setup", "entering", "leaving", "entering", "leaving", "reject"}},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.name) {
            Traced t = run_traced({kWindow, c.p0, c.p1});
            CHECK(events(t) == c.events);
            CHECK(t.result.visible == c.visible);
            CHECK(t.result.t_enter == Approx(c.t_enter).margin(1e-15));
            CHECK(t.result.t_leave == Approx(c.t_leave).margin(1e-15));
            REQUIRE(t.result.q0.has_value() == c.visible);
            if (c.visible) {
                CHECK(t.result.q0->x == Approx(c.q0.x).margin(1e-12));
                CHECK(t.result.q0->y == Approx(c.q0.y).margin(1e-12));
                CHECK(t.result.q1->x == Approx(c.q1.x).margin(1e-12));
                CHECK(t.result.q1->y == Approx(c.q1.y).margin(1e-12));
            }
            // The straight-line version agrees with the state machine exactly.
            CHECK(LiangBarsky::clip({kWindow, c.p0, c.p1}) == t.result);
        }
    }
}

TEST_CASE("liang-barsky: each step reports its line, numbers and variables", "[clipping][liang-barsky]") {
    Traced t = run_traced({kWindow, {0, 2}, {4, 6}});
    REQUIRE(t.steps.size() == 6);
    CHECK(t.steps[0].line == 2);
    CHECK(t.steps[0].narration ==
          "dx = x1 − x0 = 4, dy = y1 − y0 = 4; start with t_enter = 0 and t_leave = 1.");
    CHECK(t.steps[1].line == 8);
    CHECK(t.steps[1].narration ==
          "Edge 1 (left, x = 1): p_1 = −dx = −4, q_1 = x0 − xmin = −1. p < 0, entering: "
          "r_1 = q/p = −1/−4 = 0.25, so t_enter = max(0, 0.25) = 0.25.");
    CHECK(t.steps[4].line == 10);
    CHECK(t.steps[4].narration ==
          "Edge 4 (top, y = 4): p_4 = dy = 4, q_4 = ymax − y0 = 2. p > 0, leaving: "
          "r_4 = q/p = 2/4 = 0.5, so t_leave = min(1, 0.5) = 0.5.");
    CHECK(t.steps[5].narration ==
          "Q0 = P(0.25) = (1, 3) and Q1 = P(0.5) = (2, 4): this part of the segment is visible.");
    const auto& vars = t.steps[1].vars;
    auto find = [&](const std::string& name) {
        for (const auto& v : vars)
            if (v.name == name) return v.value;
        FAIL("no variable " << name);
        return cg::Value{};
    };
    CHECK(std::get<double>(find("p_k")) == -4);
    CHECK(std::get<double>(find("q_k")) == -1);
    CHECK(std::get<double>(find("r_k")) == 0.25);
    CHECK(std::get<double>(find("t_enter")) == 0.25);
    CHECK(std::get<std::string>(find("edge")) == "left");
    // Every event is one the spec declares, and every line exists.
    for (const auto& s : t.steps) {
        bool declared = false;
        for (const auto& e : LiangBarsky::spec().events) declared = declared || e.id == s.event;
        CHECK(declared);
        CHECK(s.line >= 1);
        CHECK(s.line <= int(LiangBarsky::spec().pseudocode.size()));
    }
}

TEST_CASE("liang-barsky: 10,000 random segments agree with Cohen-Sutherland", "[clipping][liang-barsky]") {
    int visible = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        std::mt19937_64 rng(trial);
        std::uniform_real_distribution<double> u(-10, 10);
        double a = u(rng), b = u(rng), c = u(rng), d = u(rng);
        LiangBarsky::Input in{{std::min(a, b), std::min(c, d), std::max(a, b), std::max(c, d)},
                              {u(rng) * 2, u(rng) * 2},
                              {u(rng) * 2, u(rng) * 2}};
        // Some degenerate ones: axis-parallel and zero-length segments.
        if (trial % 10 == 1) in.p1.x = in.p0.x;
        if (trial % 10 == 2) in.p1.y = in.p0.y;
        if (trial % 50 == 3) in.p1 = in.p0;
        CAPTURE(trial, in.window.xmin, in.window.ymin, in.window.xmax, in.window.ymax, in.p0.x,
                in.p0.y, in.p1.x, in.p1.y);
        const auto r = cg::run_to_end<LiangBarsky>(LiangBarsky::start(in));
        const ClipRef ref = cohen_sutherland(in);
        REQUIRE(r.visible == ref.visible);
        if (!r.visible) continue;
        ++visible;
        CHECK(double(std::fabs(r.q0->x - ref.x0)) < 1e-9);
        CHECK(double(std::fabs(r.q0->y - ref.y0)) < 1e-9);
        CHECK(double(std::fabs(r.q1->x - ref.x1)) < 1e-9);
        CHECK(double(std::fabs(r.q1->y - ref.y1)) < 1e-9);
    }
    // The generator must exercise both outcomes substantially.
    CHECK(visible > 2000);
    CHECK(visible < 8000);
}

TEST_CASE("liang-barsky: bad input names the field", "[clipping][liang-barsky]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(LiangBarsky::start({{5, 1, 1, 4}, {0, 0}, {1, 1}}),
                      "window.xmin: must not exceed window.xmax (5 > 1)");
    CHECK_THROWS_WITH(LiangBarsky::start({{1, 4, 5, 1}, {0, 0}, {1, 1}}),
                      "window.ymin: must not exceed window.ymax (4 > 1)");
    CHECK_THROWS_WITH(LiangBarsky::start({kWindow, {nan, 0}, {1, 1}}),
                      "p0[0]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(LiangBarsky::start({kWindow, {0, 0}, {1, -inf}}),
                      "p1[1]: must be a finite number (got -inf)");
    CHECK_THROWS_AS(LiangBarsky::start({kWindow, {-1e308, 0}, {1e308, 1}}), cg::InputError);
}

TEST_CASE("liang-barsky: traces are deterministic and stepping back reproduces them", "[clipping][liang-barsky]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* lb = registry.find("liang-barsky");
    REQUIRE(lb);
    cg::test::check_replay(*lb, lb->example(), 3);
}

TEST_CASE("liang-barsky: the picture shows the window, the segment and the kept part", "[clipping][liang-barsky]") {
    auto s = LiangBarsky::start({kWindow, {0, 2}, {4, 6}});
    while (!LiangBarsky::done(s)) LiangBarsky::step(s, nullptr);
    cg::Scene scene;
    LiangBarsky::draw(s, scene);
    REQUIRE(scene.polygons.size() == 1);
    CHECK(scene.polygons[0].style.role == cg::Role::Window);
    bool kept = false;
    for (const auto& seg : scene.segments)
        kept = kept || (seg.style.role == cg::Role::Kept && seg.a == dvec2(1, 3) && seg.b == dvec2(2, 4));
    CHECK(kept);
    CHECK(scene.handles.size() == 4);
    CHECK(scene.handles[0].x_field == "/p0/0");
}

TEST_CASE("liang-barsky: clip_segment, the pictures' clip, agrees with clip on random segments",
          "[clipping][liang-barsky]") {
    cg::Rng rng(4488);
    int visible = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        LiangBarsky::Input in;
        in.window = {rng.uniform(-5, 0), rng.uniform(-5, 0), rng.uniform(0, 5), rng.uniform(0, 5)};
        in.p0 = {rng.uniform(-8, 8), rng.uniform(-8, 8)};
        // A quarter of them axis-parallel: the p = 0 rows.
        in.p1 = trial % 4 == 0 ? glm::dvec2(rng.uniform(-8, 8), in.p0.y)
                               : glm::dvec2(rng.uniform(-8, 8), rng.uniform(-8, 8));
        const LiangBarsky::Result r = LiangBarsky::clip(in);
        glm::dvec2 a = in.p0, b = in.p1;
        CAPTURE(trial);
        REQUIRE(LiangBarsky::clip_segment(in.window, a, b) == r.visible);
        if (!r.visible) continue;
        ++visible;
        CHECK(a == *r.q0);
        CHECK(b == *r.q1);
    }
    CHECK(visible > 1000);
}
