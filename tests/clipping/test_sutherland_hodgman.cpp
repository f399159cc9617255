// Sutherland-Hodgman: exam cases worked by hand (with the degenerate ones), refusals, and
// 10,000 random window/polygon pairs against Clipper's exact integer intersection; plus the
// determinism of the trace and of stepping back, and the picture.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "clipping/sutherland_hodgman.hpp"
#include "core/rng.hpp"
#include "core/timeline.hpp"
#include "io/registry.hpp"
#include "polygon_reference.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::SutherlandHodgman;
using glm::dvec2;
using Points = std::vector<dvec2>;
using polygon_reference::shoelace;

namespace {

struct Traced {
    SutherlandHodgman::Result result;
    std::vector<cg::StepInfo> steps;
};

Traced run_traced(const SutherlandHodgman::Input& in) {
    Traced t;
    auto s = SutherlandHodgman::start(in);
    while (!SutherlandHodgman::done(s)) {
        cg::StepInfo info;
        SutherlandHodgman::step(s, &info);
        t.steps.push_back(info);
    }
    t.result = SutherlandHodgman::result(s);
    return t;
}

using cg::test::events;

// "setup", then per window edge its cases and "edge-done", then "done".
std::vector<std::string> expected_events(const std::vector<std::vector<std::string>>& passes,
                                         const char* last = "done") {
    std::vector<std::string> e = {"setup"};
    for (const auto& pass : passes) {
        e.insert(e.end(), pass.begin(), pass.end());
        e.push_back("edge-done");
    }
    if (std::string(last) == "empty")
        e.back() = "empty";
    else
        e.push_back(last);
    return e;
}

std::vector<std::string> repeat(const char* event, int n) {
    return std::vector<std::string>(n, event);
}

void check_declared(const Traced& t) {
    const cg::Spec& spec = SutherlandHodgman::spec();
    for (const auto& s : t.steps) {
        bool declared = false;
        for (const auto& e : spec.events) declared = declared || e.id == s.event;
        CHECK(declared);
        CHECK(s.line >= 1);
        CHECK(s.line <= int(spec.pseudocode.size()));
        CHECK(!s.narration.empty());
    }
}

const Points kSquare = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};  // [0, 4]², counter-clockwise

}  // namespace

// All windows below run counter-clockwise (inside = left, side(X) ≥ 0) unless said otherwise.
// For the square [0, 4]² the side values are, edge by edge (k = 0 bottom, 1 right, 2 top,
// 3 left): side = 4y, 4(4 − x), 4(4 − y), 4x. Intersections on these axis-parallel edges are
// exact. S starts as the last vertex of each pass's input list, so an edge's output begins
// with what S→P = (last → first) gives.
TEST_CASE("sutherland-hodgman: exam cases worked by hand", "[clipping][sutherland-hodgman]") {
    struct Case {
        const char* name;
        Points window, polygon;
        Points expected;
        std::vector<std::string> events;
    };
    const auto in4 = repeat("in-in", 4);
    const std::vector<Case> cases = {
        // The example: V0 = (2, 1), V1 = (6, 3), V2 = (2, 6).
        //  edge 0 (y ≥ 0): all inside, list unchanged.
        //  edge 1 (x ≤ 4): V2→V0 in-in: V0. V0→V1: side 8, −8, going out, t = 8/16 = 0.5,
        //    I = (4, 2). V1→V2: −8, 8, going in, t = 0.5, I = (4, 4.5), then V2.
        //    List (2, 1), (4, 2), (4, 4.5), (2, 6).
        //  edge 2 (y ≤ 4): (2, 6)→(2, 1): −8, 12, going in, t = 0.4, I = (2, 4), then (2, 1).
        //    (2, 1)→(4, 2): in-in, (4, 2). (4, 2)→(4, 4.5): 8, −2, going out, t = 0.8,
        //    I = (4, 4). (4, 4.5)→(2, 6): out-out. List (2, 4), (2, 1), (4, 2), (4, 4).
        //  edge 3 (x ≥ 0): all inside.
        {"triangle poking out right and top",
         kSquare,
         {{2, 1}, {6, 3}, {2, 6}},
         {{2, 4}, {2, 1}, {4, 2}, {4, 4}},
         expected_events({repeat("in-in", 3),
                          {"in-in", "in-out", "out-in"},
                          {"out-in", "in-in", "in-out", "out-out"},
                          in4})},
        // The same with the window clockwise: W0→W1 is the left edge (side 4x), then top
        // (4(4 − y)), right (4(4 − x)), bottom (4y).
        //  edge 0: all inside.
        //  edge 1 (y ≤ 4): (2, 6)→(2, 1): −8, 12, going in, I = (2, 4), then (2, 1).
        //    (2, 1)→(6, 3): in-in. (6, 3)→(2, 6): 4, −8, going out, t = 1/3, I = (14/3, 4).
        //  edge 2 (x ≤ 4): (14/3, 4)→(2, 4): −8/3, 8, going in, t = 0.25, I = (4, 4), then
        //    (2, 4). (2, 4)→(2, 1): in-in. (2, 1)→(6, 3): going out, I = (4, 2).
        //    (6, 3)→(14/3, 4): out-out. List (4, 4), (2, 4), (2, 1), (4, 2).
        //  edge 3 (y ≥ 0): all inside. The same polygon as before, started elsewhere.
        {"clockwise window",
         {{0, 0}, {0, 4}, {4, 4}, {4, 0}},
         {{2, 1}, {6, 3}, {2, 6}},
         {{4, 4}, {2, 4}, {2, 1}, {4, 2}},
         expected_events({repeat("in-in", 3),
                          {"out-in", "in-in", "in-out"},
                          {"out-in", "in-in", "in-out", "out-out"},
                          in4})},
        // A concave pentagon with a notch at (2, 2), its two tips cut off by the top edge.
        //  edges 0, 1: all inside.
        //  edge 2 (y ≤ 4): (1, 6)→(1, 1): going in, I = (1, 4), then (1, 1). (1, 1)→(3, 1):
        //    in-in. (3, 1)→(3, 6): going out, I = (3, 4). (3, 6)→(2, 2): −8, 8, going in,
        //    t = 0.5, I = (2.5, 4), then (2, 2). (2, 2)→(1, 6): 8, −8, going out, t = 0.5,
        //    I = (1.5, 4).
        //  edge 3: all inside. Area 2·3 − 1·2/2 = 5.
        {"concave pentagon, one piece",
         kSquare,
         {{1, 1}, {3, 1}, {3, 6}, {2, 2}, {1, 6}},
         {{1, 4}, {1, 1}, {3, 1}, {3, 4}, {2.5, 4}, {2, 2}, {1.5, 4}},
         expected_events({repeat("in-in", 5),
                          repeat("in-in", 5),
                          {"out-in", "in-in", "in-out", "out-in", "in-out"},
                          repeat("in-in", 7)})},
        // An arch ∩ whose bar lies above the window [0, 6] × [0, 4]: two legs survive, joined
        // by the degenerate bridge (2, 4)→(4, 4) and the closing edge (5, 4)→(1, 4) along the
        // top edge. Area 2 · 1·3 = 6.
        //  edges 0, 1: all inside.
        //  edge 2 (y ≤ 4): (1, 6)→(1, 1) going in: (1, 4), (1, 1). →(2, 1) in-in.
        //    →(2, 5) going out: (2, 4). →(4, 5) out-out. →(4, 1) going in: (4, 4), (4, 1).
        //    →(5, 1) in-in. →(5, 6) going out: (5, 4). →(1, 6) out-out.
        //  edge 3: all inside.
        {"concave arch cut in two, bridged",
         {{0, 0}, {6, 0}, {6, 4}, {0, 4}},
         {{1, 1}, {2, 1}, {2, 5}, {4, 5}, {4, 1}, {5, 1}, {5, 6}, {1, 6}},
         {{1, 4}, {1, 1}, {2, 1}, {2, 4}, {4, 4}, {4, 1}, {5, 1}, {5, 4}},
         expected_events(
             {repeat("in-in", 8),
              repeat("in-in", 8),
              {"out-in", "in-in", "in-out", "out-out", "out-in", "in-in", "in-out", "out-out"},
              repeat("in-in", 8)})},
        // Entirely inside: every pass keeps the list as it is.
        {"polygon entirely inside",
         kSquare,
         {{1, 1}, {3, 1}, {2, 3}},
         {{1, 1}, {3, 1}, {2, 3}},
         expected_events(
             {repeat("in-in", 3), repeat("in-in", 3), repeat("in-in", 3), repeat("in-in", 3)})},
        // Entirely outside (beyond the right edge): edge 0 keeps everything, edge 1 nothing.
        {"polygon entirely outside",
         kSquare,
         {{5, 5}, {6, 5}, {6, 6}},
         {},
         expected_events({repeat("in-in", 3), repeat("out-out", 3)}, "empty")},
        // The window inside the polygon: the result is the window.
        //  edge 0 (y ≥ 0): (−1, 5)→(−1, −1) going out: (−1, 0). →(5, −1) out-out.
        //    →(5, 5) going in: (5, 0), (5, 5). →(−1, 5) in-in.
        //  edge 1 (x ≤ 4): →(−1, 0) in-in. →(5, 0) going out: (4, 0). →(5, 5) out-out.
        //    →(−1, 5) going in: (4, 5), (−1, 5).
        //  edge 2 (y ≤ 4): →(−1, 0) going in: (−1, 4), (−1, 0). →(4, 0) in-in.
        //    →(4, 5) going out: (4, 4). →(−1, 5) out-out.
        //  edge 3 (x ≥ 0): →(−1, 4) going out: (0, 4). →(−1, 0) out-out.
        //    →(4, 0) going in: (0, 0), (4, 0). →(4, 4) in-in.
        {"window inside the polygon",
         kSquare,
         {{-1, -1}, {5, -1}, {5, 5}, {-1, 5}},
         {{0, 4}, {0, 0}, {4, 0}, {4, 4}},
         expected_events({{"in-out", "out-out", "out-in", "in-in"},
                          {"in-in", "in-out", "out-out", "out-in"},
                          {"out-in", "in-in", "in-out", "out-out"},
                          {"in-out", "out-out", "out-in", "in-in"}})},
        // Sharing the bottom edge's line: points on it (side 0) count as inside.
        //  edge 1 (x ≤ 4): (2, 2)→(2, 0) in-in. →(6, 0) going out: (4, 0). →(6, 2) out-out.
        //    →(2, 2) going in: (4, 2), (2, 2).
        {"shared edge",
         kSquare,
         {{2, 0}, {6, 0}, {6, 2}, {2, 2}},
         {{2, 0}, {4, 0}, {4, 2}, {2, 2}},
         expected_events({in4, {"in-in", "in-out", "out-out", "out-in"}, in4, in4})},
        {"polygon equal to the window", kSquare, kSquare, kSquare,
         expected_events({in4, in4, in4, in4})},
        // A vertex on the right edge from inside: side 0 is inside, nothing changes.
        {"vertex on a window edge, from inside",
         kSquare,
         {{1, 1}, {4, 2}, {1, 3}},
         {{1, 1}, {4, 2}, {1, 3}},
         expected_events(
             {repeat("in-in", 3), repeat("in-in", 3), repeat("in-in", 3), repeat("in-in", 3)})},
        // Touching the right edge from outside at (4, 2): the classic algorithm keeps the
        // touching point, three times, and a zero-area list, not an empty one.
        //  edge 1: (6, 3)→(4, 2): −8, 0, going in, t = 1, I = (4, 2), then P = (4, 2).
        //    (4, 2)→(6, 1): 0, −8, going out, t = 0, I = (4, 2). (6, 1)→(6, 3) out-out.
        {"touching a window edge from outside",
         kSquare,
         {{4, 2}, {6, 1}, {6, 3}},
         {{4, 2}, {4, 2}, {4, 2}},
         expected_events({repeat("in-in", 3),
                          {"out-in", "in-out", "out-out"},
                          repeat("in-in", 3),
                          repeat("in-in", 3)})},
        // Collinear polygon vertices along y = 1 through the right edge at (4, 1):
        //  edge 1: (2, 3)→(2, 1) in-in. →(4, 1) in-in (on the edge). →(6, 1) going out,
        //    t = 0, I = (4, 1) again. →(6, 3) out-out. →(2, 3) going in: (4, 3), (2, 3).
        {"collinear vertices",
         kSquare,
         {{2, 1}, {4, 1}, {6, 1}, {6, 3}, {2, 3}},
         {{2, 1}, {4, 1}, {4, 1}, {4, 3}, {2, 3}},
         expected_events({repeat("in-in", 5),
                          {"in-in", "in-in", "in-out", "out-out", "out-in"},
                          repeat("in-in", 5),
                          repeat("in-in", 5)})},
        // A triangle window x ≥ 0, y ≥ 0, x + y ≤ 6; edge 1 (6, 0)→(0, 6) has
        // side = 6(6 − x − y). The square's corners (5, 1) and (1, 5) lie on it.
        //  edge 1: (1, 5)→(1, 1): 0, 24, in-in. →(5, 1): in-in (on). →(5, 5): 0, −24, going
        //    out, t = 0, I = (5, 1). →(1, 5): −24, 0, going in, t = 1, I = (1, 5), then (1, 5).
        {"triangle window",
         {{0, 0}, {6, 0}, {0, 6}},
         {{1, 1}, {5, 1}, {5, 5}, {1, 5}},
         {{1, 1}, {5, 1}, {5, 1}, {1, 5}, {1, 5}},
         expected_events({in4, {"in-in", "in-in", "in-out", "out-in"}, repeat("in-in", 5)})},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.name) {
            const SutherlandHodgman::Input in{c.window, c.polygon};
            Traced t = run_traced(in);
            CHECK(events(t) == c.events);
            REQUIRE(t.result.polygon.size() == c.expected.size());
            for (std::size_t i = 0; i < c.expected.size(); ++i) {
                CAPTURE(i);
                // Exact: every intersection here is on an axis-parallel edge or at t = 0 or 1,
                // except (14/3, 4), which the clockwise case loses again.
                CHECK(t.result.polygon[i] == c.expected[i]);
            }
            // One output list per window edge processed (up to the one that came out empty),
            // the last of them the result.
            const auto passes = std::count(c.events.begin(), c.events.end(), "edge-done") +
                                std::count(c.events.begin(), c.events.end(), "empty");
            REQUIRE(t.result.after_edge.size() == std::size_t(passes));
            CHECK(t.result.after_edge.back() == t.result.polygon);
            check_declared(t);
            // The straight-line version agrees with the state machine exactly.
            CHECK(SutherlandHodgman::clip(c.window, c.polygon) == t.result);
            CHECK(cg::run_to_end<SutherlandHodgman>(SutherlandHodgman::start(in)) == t.result);
        }
    }
}

TEST_CASE("sutherland-hodgman: areas of the hand cases", "[clipping][sutherland-hodgman]") {
    auto area = [](const Points& w, const Points& p) {
        return std::fabs(shoelace(SutherlandHodgman::clip(w, p).polygon));
    };
    CHECK(area(kSquare, {{2, 1}, {6, 3}, {2, 6}}) == 5);  // the trapezoid (2,1),(4,2),(4,4),(2,4)
    CHECK(area(kSquare, {{1, 1}, {3, 1}, {3, 6}, {2, 2}, {1, 6}}) == 5);
    // The bridge is walked there and back, so it adds nothing.
    CHECK(area({{0, 0}, {6, 0}, {6, 4}, {0, 4}},
               {{1, 1}, {2, 1}, {2, 5}, {4, 5}, {4, 1}, {5, 1}, {5, 6}, {1, 6}}) == 6);
    CHECK(area(kSquare, {{4, 2}, {6, 1}, {6, 3}}) == 0);
}

TEST_CASE("sutherland-hodgman: each step reports its line, numbers and variables",
          "[clipping][sutherland-hodgman]") {
    Traced t = run_traced({kSquare, {{2, 1}, {6, 3}, {2, 6}}});
    REQUIRE(t.steps.size() == 1 + 4 + 4 + 5 + 5 + 1);
    CHECK(t.steps[0].line == 2);
    CHECK(t.steps[0].narration ==
          "The window's signed area is 16 > 0, so it runs counter-clockwise and inside means "
          "left of each edge (on the edge counts as inside); the input list is the polygon's 3 "
          "vertices.");
    // Window edge 1, first polygon edge.
    CHECK(t.steps[5].event == "in-in");
    CHECK(t.steps[5].line == 8);
    CHECK(t.steps[5].narration ==
          "Window edge 1, W1→W2 = (4, 0)→(4, 4); S starts as the last input vertex. "
          "S = (2, 6) is inside (side 8 ≥ 0) and P = (2, 1) is inside (side 8 ≥ 0): case 1 "
          "(in → in), output P = (2, 1).");
    CHECK(t.steps[6].line == 10);
    CHECK(t.steps[6].narration ==
          "S = (2, 1) is inside (side 8 ≥ 0) and P = (6, 3) is outside (side −8 < 0): case 2 "
          "(going out); SP crosses AB at t = 8/(8 − (−8)) = 0.5, I = (4, 2), output I.");
    CHECK(t.steps[7].line == 14);
    CHECK(t.steps[7].narration ==
          "S = (6, 3) is outside (side −8 < 0) and P = (2, 6) is inside (side 8 ≥ 0): case 4 "
          "(going in); SP crosses AB at t = −8/(−8 − 8) = 0.5, I = (4, 4.5), output I, then "
          "P = (2, 6).");
    CHECK(t.steps[8].event == "edge-done");
    CHECK(t.steps[8].line == 16);
    CHECK(t.steps[8].narration ==
          "Window edge 1 done: its output list of 4 vertices, (2, 1), (4, 2), (4, 4.5), (2, 6), "
          "becomes the input list for window edge 2.");
    CHECK(t.steps[12].event == "out-out");
    CHECK(t.steps[12].line == 12);
    CHECK(t.steps.back().line == 18);
    CHECK(t.steps.back().narration ==
          "All 4 window edges done: the clipped polygon is (2, 4), (2, 1), (4, 2), (4, 4).");

    // The formulas with the step's numbers, in LaTeX.
    CHECK(t.steps[0].math ==
          "\\text{area} = \\tfrac{1}{2} \\sum_i (W_i - W_0) \\times (W_{i+1} - W_0) = 16 > 0 "
          "\\Rightarrow \\text{orient} = +1");
    CHECK(t.steps[5].math ==
          "\\mathrm{side}(S) = (B - A) \\times (S - A) = (0, 4) \\times (-2, 6) = 8 \\ge 0,"
          "\\quad \\mathrm{side}(P) = (B - A) \\times (P - A) = (0, 4) \\times (-2, 1) = 8 "
          "\\ge 0");
    CHECK(t.steps[6].math ==
          "\\mathrm{side}(S) = (B - A) \\times (S - A) = (0, 4) \\times (-2, 1) = 8 \\ge 0,"
          "\\quad \\mathrm{side}(P) = (B - A) \\times (P - A) = (0, 4) \\times (2, 3) = -8 < 0,"
          "\\quad t = \\frac{\\mathrm{side}(S)}{\\mathrm{side}(S) - \\mathrm{side}(P)} = "
          "\\frac{8}{8 - (-8)} = 0.5,\\quad I = S + t\\,(P - S) = (2, 1) + 0.5\\,(4, 2) = (4, 2)");
    CHECK(t.steps[8].math ==
          "\\text{input} \\leftarrow \\text{output} = [(2, 1), (4, 2), (4, 4.5), (2, 6)]");
    CHECK(t.steps.back().math == "\\text{result} = [(2, 4), (2, 1), (4, 2), (4, 4)]");
    // The output list of every window edge is kept for the result.
    CHECK(t.result.after_edge == std::vector<Points>{{{2, 1}, {6, 3}, {2, 6}},
                                                     {{2, 1}, {4, 2}, {4, 4.5}, {2, 6}},
                                                     {{2, 4}, {2, 1}, {4, 2}, {4, 4}},
                                                     {{2, 4}, {2, 1}, {4, 2}, {4, 4}}});

    auto find = [](const cg::StepInfo& step, const std::string& name) {
        for (const auto& v : step.vars)
            if (v.name == name) return v.value;
        FAIL("no variable " << name);
        return cg::Value{};
    };
    const auto& going_in = t.steps[7];
    CHECK(std::get<long long>(find(going_in, "orient")) == 1);
    CHECK(std::get<long long>(find(going_in, "edge")) == 1);
    CHECK(std::get<std::vector<double>>(find(going_in, "A")) == std::vector<double>{4, 0});
    CHECK(std::get<std::vector<double>>(find(going_in, "B")) == std::vector<double>{4, 4});
    CHECK(std::get<std::vector<double>>(find(going_in, "S")) == std::vector<double>{6, 3});
    CHECK(std::get<std::vector<double>>(find(going_in, "P")) == std::vector<double>{2, 6});
    CHECK(std::get<double>(find(going_in, "side_S")) == -8);
    CHECK(std::get<double>(find(going_in, "side_P")) == 8);
    CHECK(std::get<std::string>(find(going_in, "case")) == "4 (going in)");
    CHECK(std::get<double>(find(going_in, "t")) == 0.5);
    CHECK(std::get<std::vector<double>>(find(going_in, "I")) == std::vector<double>{4, 4.5});
    using Matrix = std::vector<std::vector<double>>;
    CHECK(std::get<Matrix>(find(going_in, "output")) == Matrix{{2, 1}, {4, 2}, {4, 4.5}, {2, 6}});
    CHECK(std::get<Matrix>(find(t.steps[8], "input")) == Matrix{{2, 1}, {4, 2}, {4, 4.5}, {2, 6}});
    CHECK(std::get<Matrix>(find(t.steps[8], "output")).empty());

    Traced cw = run_traced({{{0, 0}, {0, 4}, {4, 4}, {4, 0}}, {{2, 1}, {6, 3}, {2, 6}}});
    CHECK(cw.steps[0].narration ==
          "The window's signed area is −16 < 0, so it runs clockwise and inside means right of "
          "each edge (on the edge counts as inside); the input list is the polygon's 3 "
          "vertices.");
    CHECK(std::get<long long>(find(cw.steps[0], "orient")) == -1);
    CHECK(cw.steps[1].math ==
          "\\mathrm{side}(S) = -(B - A) \\times (S - A) = -\\big((0, 4) \\times (2, 6)\\big) = 8 "
          "\\ge 0,\\quad \\mathrm{side}(P) = -(B - A) \\times (P - A) = -\\big((0, 4) \\times "
          "(2, 1)\\big) = 8 \\ge 0");

    Traced out = run_traced({kSquare, {{5, 5}, {6, 5}, {6, 6}}});
    CHECK(out.steps.back().event == "empty");
    CHECK(out.steps.back().line == 17);
    CHECK(out.steps.back().narration ==
          "Window edge 1 done: nothing of the input list lies on its inner side, so the output "
          "list is empty and the polygon lies outside the window: stop, nothing is visible.");
    CHECK(out.steps.back().math == "\\text{output} = [\\,] \\Rightarrow \\text{stop}");
    CHECK(out.result.after_edge == std::vector<Points>{{{5, 5}, {6, 5}, {6, 6}}, {}});
}

TEST_CASE("sutherland-hodgman: bad input names the field", "[clipping][sutherland-hodgman]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const Points tri = {{1, 1}, {3, 1}, {2, 3}};
    auto refuse = [&](const Points& window, const Points& polygon) -> std::string {
        try {
            SutherlandHodgman::start({window, polygon});
        } catch (const cg::InputError& e) {
            return e.what();
        }
        return "accepted";
    };
    CHECK(refuse({{0, 0}, {4, 0}}, tri) == "window: needs at least 3 vertices, got 2");
    CHECK(refuse(kSquare, {{0, 0}, {4, 0}}) == "polygon: needs at least 3 vertices, got 2");
    CHECK(refuse({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}, tri) ==
          "window: must be convex (turns the other way at vertex 3, (2, 1))");
    // The same window clockwise is refused at the same vertex.
    CHECK(refuse({{0, 4}, {2, 1}, {4, 4}, {4, 0}, {0, 0}}, tri) ==
          "window: must be convex (turns the other way at vertex 1, (2, 1))");
    CHECK(refuse({{0, 0}, {4, 0}, {4, 0}, {0, 4}}, tri) ==
          "window: vertices 1 and 2 are the same point (4, 0)");
    CHECK(refuse({{0, 0}, {4, 0}, {4, 4}, {0, 0}}, tri) ==
          "window: vertices 3 and 0 are the same point (0, 0) (list each vertex once: the "
          "polygon closes itself)");
    CHECK(refuse({{0, 0}, {1, 1}, {3, 3}}, tri) ==
          "window: has zero area (all its vertices lie on one line)");
    CHECK(refuse({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}, tri) ==
          "window: vertices 0, 1 and 2 are collinear (a straight angle at vertex 1, (2, 0)); "
          "remove vertex 1");
    CHECK(refuse({{0, 0}, {4, 0}, {2, 0}, {2, 3}}, tri) ==
          "window: must be convex (doubles back at vertex 1, (4, 0))");
    // A pentagram: every turn is a left turn, but it winds round twice.
    Points star;
    for (int i = 0; i < 5; ++i) {
        const double a = 2 * std::numbers::pi * (2 * i) / 5;
        star.push_back({std::cos(a), std::sin(a)});
    }
    CHECK(refuse(star, tri) ==
          "window: must be convex (it crosses itself: its edges turn through 720°, not 360°)");
    // A bow tie has zero area, or turns both ways.
    CHECK(refuse({{0, 0}, {4, 4}, {4, 0}, {0, 4}}, tri) == "window: has zero area");
    // Typed input (as the viewer passes it) can hold what JSON cannot.
    CHECK(refuse(kSquare, {{1, 1}, {3, nan}, {2, 3}}) ==
          "polygon[1][1]: must be a finite number (got NaN)");
    CHECK(refuse({{-inf, 0}, {4, 0}, {4, 4}}, tri) ==
          "window[0][0]: must be a finite number (got -inf)");
    CHECK(refuse(kSquare, {{1, 1}, {3, 1}, {2e200, 3}}) ==
          "polygon[2][0]: must be at most 1e100 in size (got 2 × 10²⁰⁰)");
    CHECK_THROWS_AS(SutherlandHodgman::start({kSquare, {{1, 1}, {inf, 1}, {2, 3}}}),
                    cg::InputError);
    // Accepted: a polygon with repeated or collinear vertices, and a self-crossing one.
    CHECK(refuse(kSquare, {{1, 1}, {1, 1}, {3, 1}, {2, 3}}) == "accepted");
    CHECK(refuse(kSquare, {{0, 0}, {4, 4}, {4, 0}, {0, 4}}) == "accepted");
}

TEST_CASE("sutherland-hodgman: bad JSON input names the field", "[clipping][sutherland-hodgman]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* sh = registry.find("sutherland-hodgman");
    REQUIRE(sh);
    CHECK(sh->spec->title == "Sutherland-Hodgman polygon clipping");
    CHECK(sh->spec->topic == "Polygons");
    auto field_of = [&](const std::string& text) -> std::string {
        try {
            sh->create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return e.field() + " | " + e.reason();
        }
        return "accepted";
    };
    const std::string tri = R"("polygon": [[1, 1], [3, 1], [2, 3]])";
    CHECK(field_of(R"({"window": [[0, 0], [4, 0], [4, 4], [0, 4]], )" + tri + "}") == "accepted");
    CHECK(field_of(R"({"window": [[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]], )" + tri + "}") ==
          "window | must be convex (turns the other way at vertex 3, (2, 1))");
    CHECK(field_of(R"({"window": [[0, 0], [4, 0]], )" + tri + "}") ==
          "window | needs at least 3 vertices, got 2");
    CHECK(field_of(R"({"window": [[0, 0], [4, 0], [4, 4]], "polygon": [[1, 1], [3]]})") ==
          "polygon[1] | must be a point [x, y], got an array ([3])");
    CHECK(field_of(R"({"window": [[0, 0], [4, 0], [4, "4"]], )" + tri + "}") ==
          "window[2][1] | must be a number, got a string (\"4\")");
    CHECK(field_of(R"({"window": [[0, 0], [4, 0], [4, 4]]})") == "polygon | is missing");
    CHECK(field_of(R"({"window": {"xmin": 0}, )" + tri + "}") ==
          R"(window | must be a list of points, got an object ({"xmin":0}))");
    CHECK(field_of(R"({"window": [[0, 0], [4, 0], [4, 4]], "polygons": [], )" + tri + "}") ==
          "polygons | is not a known field (expected: window, polygon)");
    CHECK(field_of(R"({"window": [[0, 0], [4, 0], [4, 4]], "polygon": [[1, 1], [3, 1]]})") ==
          "polygon | needs at least 3 vertices, got 2");

    // The result lists the clipped polygon, and [] when nothing is inside.
    auto result_of = [&](const std::string& text) {
        auto run = sh->create(cg::parse_json(text));
        while (!run->done()) run->step(nullptr);
        return sh->result(*run).dump();
    };
    // … and the output list of each window edge, up to the one that came out empty.
    CHECK(result_of(sh->example().dump()) ==
          R"({"polygon":[[2.0,4.0],[2.0,1.0],[4.0,2.0],[4.0,4.0]],"after_edge":[[[2.0,1.0],)"
          R"([6.0,3.0],[2.0,6.0]],[[2.0,1.0],[4.0,2.0],[4.0,4.5],[2.0,6.0]],[[2.0,4.0],[2.0,1.0],)"
          R"([4.0,2.0],[4.0,4.0]],[[2.0,4.0],[2.0,1.0],[4.0,2.0],[4.0,4.0]]]})");
    CHECK(
        result_of(R"({"window": [[0, 0], [4, 0], [4, 4]], "polygon": [[5, 0], [6, 0], [6, 1]]})") ==
        R"({"polygon":[],"after_edge":[[[5.0,0.0],[6.0,0.0],[6.0,1.0]],[]]})");
    // Generated inputs are written with integral coordinates as integers, as a student would.
    CHECK(sh->exam_input(1).dump().find(".0") == std::string::npos);
}

// ---- The reference: Clipper's intersection on integer coordinates ---------------------------
//
// Inputs are snapped to a grid of 1/4 or 1/1024 inside [−8, 8]², which Clipper reads exactly
// (see polygon_reference.hpp): its vertices are within 6e-13 of the true ones. The tolerances
// below are far larger than that and far smaller than any real mistake.
namespace {

constexpr double kOnBoundary = 1e-7;  // in input units (1e-7 × 2^40 in Clipper's)

using polygon_reference::cross;
using polygon_reference::intersection;
using polygon_reference::simple;

double segment_distance(dvec2 p, dvec2 a, dvec2 b) {
    const dvec2 d = b - a, ap = p - a;
    const double len2 = d.x * d.x + d.y * d.y;
    const double t = len2 > 0 ? std::clamp((ap.x * d.x + ap.y * d.y) / len2, 0.0, 1.0) : 0.0;
    const dvec2 q = a + t * d - p;
    return std::sqrt(q.x * q.x + q.y * q.y);
}

double boundary_distance(dvec2 p, const Points& polygon) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i)
        best = std::min(best, segment_distance(p, polygon[i], polygon[(i + 1) % polygon.size()]));
    return best;
}

double snap(double x, double grid) {
    return std::round(x / grid) * grid;
}

// Andrew's monotone chain: counter-clockwise, without collinear points.
Points convex_hull(Points pts) {
    std::sort(pts.begin(), pts.end(),
              [](dvec2 a, dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return {};
    Points hull(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1);
    return hull;
}

// Random start vertex, random orientation.
void shuffle_start(Points& p, cg::Rng& rng) {
    std::rotate(p.begin(), p.begin() + rng.integer(0, (long long)p.size() - 1), p.end());
    if (rng.chance(0.5)) std::reverse(p.begin(), p.end());
}

Points random_convex(cg::Rng& rng, double grid) {
    for (;;) {
        const dvec2 c{rng.uniform(-4, 4), rng.uniform(-4, 4)};
        const double r = rng.uniform(1, 6);
        Points pts(rng.integer(3, 12));
        for (dvec2& p : pts)
            p = {snap(std::clamp(c.x + rng.uniform(-r, r), -8.0, 8.0), grid),
                 snap(std::clamp(c.y + rng.uniform(-r, r), -8.0, 8.0), grid)};
        Points hull = convex_hull(pts);
        if (hull.size() < 3) continue;
        shuffle_start(hull, rng);
        return hull;
    }
}

// Star-shaped about a random centre: sorted random angles, random radii; mostly concave.
Points random_star(cg::Rng& rng, double grid) {
    for (;;) {
        const dvec2 c{rng.uniform(-3, 3), rng.uniform(-3, 3)};
        std::vector<double> angles(rng.integer(3, 14));
        for (double& a : angles) a = rng.uniform(0, 2 * std::numbers::pi);
        std::sort(angles.begin(), angles.end());
        Points pts;
        for (double a : angles) {
            const double r = rng.uniform(0.3, 6);
            pts.push_back({snap(std::clamp(c.x + r * std::cos(a), -8.0, 8.0), grid),
                           snap(std::clamp(c.y + r * std::sin(a), -8.0, 8.0), grid)});
        }
        if (!simple(pts)) continue;
        shuffle_start(pts, rng);
        return pts;
    }
}

bool inside_window(dvec2 p, const Points& window) {
    const double orient = shoelace(window) > 0 ? 1 : -1;
    for (std::size_t i = 0; i < window.size(); ++i) {
        const dvec2 a = window[i], b = window[(i + 1) % window.size()];
        const double len = std::sqrt((b - a).x * (b - a).x + (b - a).y * (b - a).y);
        if (orient * cross(b - a, p - a) < -kOnBoundary * len) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("sutherland-hodgman: 10,000 random polygons agree with Clipper",
          "[clipping][sutherland-hodgman]") {
    int nonempty = 0, empty = 0, concave = 0, bridged = 0, coarse_hits = 0;
    double worst_area = 0, worst_vertex = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(trial);
        const double grid = trial % 2 ? 1.0 / 1024 : 0.25;  // the coarse grid makes ties
        const Points window = random_convex(rng, grid);
        const bool convex_subject = trial % 3 == 0;
        Points polygon = convex_subject ? random_convex(rng, grid) : random_star(rng, grid);
        // Now and then a polygon vertex on a window vertex (if the polygon stays simple).
        if (trial % 7 == 0 && !convex_subject) {
            Points moved = polygon;
            moved[rng.integer(0, (long long)moved.size() - 1)] =
                window[rng.integer(0, (long long)window.size() - 1)];
            if (simple(moved)) polygon = moved;
        }
        concave += !convex_subject;
        const SutherlandHodgman::Input in{window, polygon};
        const auto r = cg::run_to_end<SutherlandHodgman>(SutherlandHodgman::start(in));
        REQUIRE(r == SutherlandHodgman::clip(window, polygon));

        const std::vector<Points> ref = intersection(window, polygon);
        double ref_area = 0;
        for (const Points& p : ref) ref_area += shoelace(p);
        ref_area = std::fabs(ref_area);
        const double area = std::fabs(shoelace(r.polygon));
        (ref.empty() ? empty : nonempty) += 1;
        const double area_error = std::fabs(area - ref_area);
        worst_area = std::max(worst_area, area_error / std::max(ref_area, 1e-3));
        CAPTURE(area, ref_area, r.polygon.size(), ref.size());
        CHECK(area_error <= 1e-9 * std::max(area, ref_area) + 1e-10);

        // Every vertex lies on the boundary of the true intersection, with one exception. A
        // concave polygon cut into pieces comes out as one list whose pieces are joined by
        // zero-width bridges along the window's boundary; a bridge can pass a window corner
        // (an intersection with the next window edge), or run where the true intersection has
        // no boundary at all. Every vertex SH makes is a polygon vertex (inside the window,
        // on the polygon's boundary, so on the intersection's) or lies on a window edge's line
        // and inside the window, that is on the window's boundary: so that is what we accept
        // for concave polygons. For convex ones each pass keeps exactly polygon ∩ half-planes,
        // no bridges, and the strict test applies (unless the polygon only touches the window:
        // then Clipper returns nothing and SH the touching points).
        const bool bridges_possible = !convex_subject || ref.empty();
        bool used_bridge = false;
        for (std::size_t i = 0; i < r.polygon.size(); ++i) {
            const dvec2 v = r.polygon[i];
            double d = std::numeric_limits<double>::infinity();
            for (const Points& p : ref) d = std::min(d, boundary_distance(v, p));
            if (d < kOnBoundary) {
                worst_vertex = std::max(worst_vertex, d);
                continue;
            }
            CAPTURE(i, v.x, v.y, d);
            const bool on_window =
                boundary_distance(v, window) < kOnBoundary && inside_window(v, window);
            CHECK(bridges_possible);
            CHECK(on_window);
            used_bridge = true;
        }
        bridged += used_bridge;
        if (grid == 0.25) {
            // Ties the coarse grid makes: polygon vertices exactly on a window edge's line
            // (exact: grid coordinates have few bits).
            for (dvec2 p : polygon)
                for (std::size_t k = 0; k < window.size(); ++k) {
                    const dvec2 a = window[k], b = window[(k + 1) % window.size()];
                    coarse_hits += cross(b - a, p - a) == 0;
                }
        }
    }
    // The generator must exercise every situation substantially. (Seen: 6426 non-empty, 3574
    // empty, 271 with bridges, 1524 ties; worst relative area error 3e-10 on tiny areas, worst
    // vertex distance 6e-13, which is Clipper's rounding to its integer grid.)
    CHECK(nonempty > 3000);
    CHECK(empty > 300);
    CHECK(concave > 6000);
    CHECK(bridged > 50);
    CHECK(coarse_hits > 300);
    CHECK(worst_area < 1e-9);
    CHECK(worst_vertex < 1e-11);
}

// The state keeps only side(P); the case, t and I of the edge just clipped are found again
// when asked for. Here the test walks each pass beside the quiet run with its own S, P and side
// values (the course's formula, in the same double arithmetic the step uses, so the numbers
// must agree exactly), and checks what the accessors report against them.
TEST_CASE("sutherland-hodgman: the case, t and I found again equal the step's",
          "[clipping][sutherland-hodgman]") {
    using Case = SutherlandHodgman::Case;
    int steps = 0, crossings = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(1000 + trial);
        const double grid = trial % 2 ? 1.0 / 1024 : 0.25;
        const Points window = random_convex(rng, grid), polygon = random_star(rng, grid);
        auto s = SutherlandHodgman::start(SutherlandHodgman::Input{window, polygon});
        while (!SutherlandHodgman::done(s)) {
            SutherlandHodgman::step(s, nullptr);
            if (s.phase != SutherlandHodgman::Phase::Clip &&
                s.phase != SutherlandHodgman::Phase::EdgeDone) {
                CHECK(SutherlandHodgman::which_case(s) == Case::None);
                CHECK(SutherlandHodgman::crossing_t(s) == 0);
                continue;
            }
            ++steps;
            const int n = static_cast<int>(s.input.size());
            const dvec2 P = s.input[s.j - 1], S = s.input[s.j >= 2 ? s.j - 2 : n - 1];
            const auto side = [&](dvec2 X) {
                return s.orient *
                       ((s.B.x - s.A.x) * (X.y - s.A.y) - (s.B.y - s.A.y) * (X.x - s.A.x));
            };
            const double side_S = side(S), side_P = side(P);
            REQUIRE(side_P == s.side_P);
            const Case expected = side_S >= 0 ? (side_P >= 0 ? Case::InIn : Case::InOut)
                                              : (side_P >= 0 ? Case::OutIn : Case::OutOut);
            REQUIRE(SutherlandHodgman::which_case(s) == expected);
            if (expected != Case::InOut && expected != Case::OutIn) {
                CHECK(SutherlandHodgman::crossing_t(s) == 0);
                continue;
            }
            ++crossings;
            const double t = side_S / (side_S - side_P);
            CHECK(SutherlandHodgman::crossing_t(s) == t);
            const dvec2 I = SutherlandHodgman::intersection_I(s);
            // I = S + t (P − S), with the coordinate an axis-parallel edge fixes set exactly.
            const dvec2 J = S + t * (P - S);
            CHECK((s.A.x == s.B.x ? s.A.x : J.x) == I.x);
            CHECK((s.A.x != s.B.x && s.A.y == s.B.y ? s.A.y : J.y) == I.y);
        }
    }
    CHECK(steps > 30000);
    CHECK(crossings > 5000);
}

TEST_CASE("sutherland-hodgman: traces are deterministic and stepping back reproduces them",
          "[clipping][sutherland-hodgman]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* sh = registry.find("sutherland-hodgman");
    REQUIRE(sh);
    const cg::json arch = cg::parse_json(
        R"({"window": [[0, 0], [6, 0], [6, 4], [0, 4]],
            "polygon": [[1, 1], [2, 1], [2, 5], [4, 5], [4, 1], [5, 1], [5, 6], [1, 6]]})");
    for (const cg::json& input : {sh->example(), arch}) {
        cg::test::check_replay(*sh, input, cg::test::kEveryStep);
        cg::Timeline t(sh->create(input));
        t.to_end();
        // A finished machine stays finished.
        auto run = t.current().clone();
        cg::StepInfo info;
        run->step(&info);
        CHECK(run->same_state(t.current()));
        CHECK(info.event.empty());
    }

    // The same with the plain State: a copy is a snapshot.
    auto s = SutherlandHodgman::start({kSquare, {{-1, -1}, {5, -1}, {5, 5}, {-1, 5}}});
    for (int i = 0; i < 9; ++i) SutherlandHodgman::step(s, nullptr);
    SutherlandHodgman::State copy = s;
    CHECK(copy == s);
    const auto rest = cg::run_to_end<SutherlandHodgman>(copy);
    CHECK(rest == cg::run_to_end<SutherlandHodgman>(s));
    CHECK(rest == SutherlandHodgman::clip(kSquare, {{-1, -1}, {5, -1}, {5, 5}, {-1, 5}}));
}

TEST_CASE("sutherland-hodgman: the picture shows the window, the lists and the edge under test",
          "[clipping][sutherland-hodgman]") {
    using cg::Role;
    auto s = SutherlandHodgman::start({kSquare, {{2, 1}, {6, 3}, {2, 6}}});
    cg::Scene scene;
    SutherlandHodgman::draw(s, scene);
    REQUIRE(scene.polygons.size() == 2);
    CHECK(scene.polygons[0].style.role == Role::Window);
    CHECK(scene.polygons[0].filled);
    CHECK(scene.polygons[1].style.role == Role::Subject);
    CHECK(scene.polygons[1].style.dashed);
    CHECK(scene.half_planes.empty());
    REQUIRE(scene.handles.size() == 7);
    CHECK(scene.handles[0].x_field == "/window/0/0");
    CHECK(scene.handles[3].y_field == "/window/3/1");
    CHECK(scene.handles[4].x_field == "/polygon/0/0");
    CHECK(scene.handles[6].y_field == "/polygon/2/1");
    CHECK(scene.handles[6].p == dvec2(2, 6));

    // Eight steps in: window edge 1 (x ≤ 4), S→P = (6, 3)→(2, 6), going in at (4, 4.5).
    for (int i = 0; i < 8; ++i) SutherlandHodgman::step(s, nullptr);
    scene.clear();
    SutherlandHodgman::draw(s, scene);
    REQUIRE(scene.half_planes.size() == 1);
    CHECK(scene.half_planes[0].style.role == Role::Active);
    CHECK(scene.half_planes[0].point == dvec2(4, 0));
    CHECK(scene.half_planes[0].inward == dvec2(-1, 0));
    bool arrow = false, entering = false, kept_line = false;
    for (const auto& seg : scene.segments)
        arrow = arrow || (seg.style.role == Role::Active && seg.arrow && seg.a == dvec2(6, 3) &&
                          seg.b == dvec2(2, 6));
    for (const auto& p : scene.points)
        entering = entering || (p.style.role == Role::Entering && p.p == dvec2(4, 4.5));
    for (const auto& poly : scene.polygons)
        kept_line = kept_line || (poly.style.role == Role::Kept && !poly.closed &&
                                  poly.points == Points{{2, 1}, {4, 2}, {4, 4.5}, {2, 6}});
    CHECK(arrow);
    CHECK(entering);
    CHECK(kept_line);
    std::vector<std::string> labels;
    for (const auto& p : scene.points)
        if (p.style.role == Role::Kept) labels.push_back(p.label);
    CHECK(labels == std::vector<std::string>{"0", "1", "2", "3"});
    int sp_labels = 0;
    for (const auto& l : scene.labels) sp_labels += l.text == "S" || l.text == "P";
    CHECK(sp_labels == 2);

    // One step back, going out at (4, 2): a leaving point.
    auto going_out = SutherlandHodgman::start({kSquare, {{2, 1}, {6, 3}, {2, 6}}});
    for (int i = 0; i < 7; ++i) SutherlandHodgman::step(going_out, nullptr);
    scene.clear();
    SutherlandHodgman::draw(going_out, scene);
    bool leaving = false;
    for (const auto& p : scene.points)
        leaving = leaving || (p.style.role == Role::Leaving && p.p == dvec2(4, 2));
    CHECK(leaving);

    // Done: the result filled in green, no edge under test.
    while (!SutherlandHodgman::done(s)) SutherlandHodgman::step(s, nullptr);
    scene.clear();
    SutherlandHodgman::draw(s, scene);
    CHECK(scene.half_planes.empty());
    bool result = false;
    for (const auto& poly : scene.polygons)
        result = result || (poly.style.role == Role::Kept && poly.filled && poly.closed &&
                            poly.points == Points{{2, 4}, {2, 1}, {4, 2}, {4, 4}});
    CHECK(result);
}
