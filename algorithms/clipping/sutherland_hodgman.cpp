// Sections: [geometry] side values and intersections, shared by the state machine and clip()
//           [spec] [validate] [advance] the math, one step  [narrate] the words
//           [clip] the straight-line version  [draw] the picture
#include "clipping/sutherland_hodgman.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec2;

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineOrient = 1,
    kLineInput,
    kLineEdgeLoop,
    kLineOutputEmpty,
    kLineStartS,
    kLineVertexLoop,
    kLineInInTest,
    kLineInIn,
    kLineInOutTest,
    kLineInOut,
    kLineOutOutTest,
    kLineOutOut,
    kLineOutInTest,
    kLineOutIn,
    kLineAdvanceS,
    kLineSwap,
    kLineEmpty,
    kLineReturn,
};

// Coordinates beyond this are refused so that the side values (products of differences) and
// the window's area stay finite.
constexpr double kMaxCoordinate = 1e100;

// ---- [geometry] ------------------------------------------------------------------------------
// One definition of each formula, used by advance() and clip() alike, so the two agree bit
// for bit.

double cross(dvec2 a, dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

// side(X) = orient · (B − A) × (X − A): twice the signed area of A, B, X, positive on the
// inner side of A→B. Multiplying by ±1 is exact, so both orientations round alike. The state
// machine keeps AB = B − A from the edge's first step (the same double each time it is formed).
double side_of(double orient, dvec2 A, dvec2 AB, dvec2 X) {
    return orient * cross(AB, X - A);
}
double side(double orient, dvec2 A, dvec2 B, dvec2 X) {
    return side_of(orient, A, B - A, X);
}

// Where S→P crosses line AB, given side values of opposite kinds (one ≥ 0, the other < 0, so
// the denominator is not zero): the side value is linear in t and vanishes at
// t = side_S / (side_S − side_P).
dvec2 intersection(dvec2 A, dvec2 AB, dvec2 S, dvec2 P, double side_S, double side_P, double& t) {
    t = side_S / (side_S - side_P);
    dvec2 I = S + t * (P - S);
    // An axis-parallel edge fixes one coordinate: set it exactly, so I lies on the line.
    // (B.x − A.x == 0 exactly when B.x == A.x: with gradual underflow a difference of two
    // distinct doubles is never 0.)
    if (AB.x == 0)
        I.x = A.x;
    else if (AB.y == 0)
        I.y = A.y;
    return I;
}

// Half the sum of (w_i − w_0) × (w_{i+1} − w_0): relative to w_0, so that a window far from
// the origin does not lose its area to cancellation.
double signed_area(const std::vector<dvec2>& w) {
    double a2 = 0;
    for (std::size_t i = 1; i + 1 < w.size(); ++i) a2 += cross(w[i] - w[0], w[i + 1] - w[0]);
    return a2 / 2;
}

// Room for the lists: a pass adds at most one vertex per two crossings, so this covers every
// convex polygon and most concave ones; beyond it the vectors grow as usual.
std::size_t list_capacity(const SutherlandHodgman::Input& in) {
    return 2 * (in.polygon.size() + in.window.size());
}

// The polygon edge S→P tested last (while phase is Clip or EdgeDone): P = input[j − 1] and S
// the vertex before it, cyclically. side(S) is recomputed where it is needed: the same
// formula on the same numbers gives the same double the step used.
dvec2 edge_P(const SutherlandHodgman::State& s) {
    return s.input[s.j - 1];
}
dvec2 edge_S(const SutherlandHodgman::State& s) {
    return s.input[s.j >= 2 ? s.j - 2 : s.input.size() - 1];
}

// ---- input checks ----

void check_points(const std::vector<dvec2>& points, const std::string& name) {
    if (points.size() < 3)
        throw InputError(name, "needs at least 3 vertices, got " + std::to_string(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (int c = 0; c < 2; ++c) {
            const double v = points[i][c];
            const std::string field =
                name + "[" + std::to_string(i) + "][" + std::to_string(c) + "]";
            if (!std::isfinite(v))
                throw InputError(field, "must be a finite number (got " + given(v) + ")");
            if (std::fabs(v) > kMaxCoordinate)
                throw InputError(field, "must be at most 1e100 in size (got " + given(v) + ")");
            // Below that, edge lengths and areas underflow to zero.
            if (v != 0 && std::fabs(v) < 1e-100)
                throw InputError(field,
                                 "must be 0 or at least 1e-100 in size (got " + given(v) + ")");
        }
    }
}

std::string vertex_text(const std::vector<dvec2>& w, std::size_t i) {
    return "vertex " + std::to_string(i) + ", " + num(w[i]);
}

// ---- narration helpers ----

std::string list_text(const std::vector<dvec2>& points) {
    if (points.empty()) return "()";
    std::string s;
    for (std::size_t i = 0; i < points.size(); ++i) s += (i ? ", " : "") + num(points[i]);
    return s;
}

std::vector<std::vector<double>> matrix(const std::vector<dvec2>& points) {
    std::vector<std::vector<double>> m;
    m.reserve(points.size());
    for (dvec2 p : points) m.push_back(vec(p));
    return m;
}

std::string vertices(std::size_t n) {
    return std::to_string(n) + (n == 1 ? " vertex" : " vertices");
}

// "P = (2, 1) is inside (side 8 ≥ 0)"
std::string where(const char* name, dvec2 p, double side_value) {
    return std::string(name) + " = " + num(p) +
           (side_value >= 0 ? " is inside (side " + num(side_value) + " ≥ 0)"
                            : " is outside (side " + num(side_value) + " < 0)");
}

const char* case_name(SutherlandHodgman::Case c) {
    switch (c) {
        case SutherlandHodgman::Case::InIn:
            return "1 (in → in)";
        case SutherlandHodgman::Case::InOut:
            return "2 (going out)";
        case SutherlandHodgman::Case::OutOut:
            return "3 (out → out)";
        case SutherlandHodgman::Case::OutIn:
            return "4 (going in)";
        default:
            return "";
    }
}

// The same formulas in LaTeX, with the step's numbers.
// "\mathrm{side}(S) = (B - A) \times (S - A) = (4, 0) \times (2, 6) = 24 \ge 0"
std::string side_tex(const char* name, double orient, dvec2 A, dvec2 B, dvec2 X, double value) {
    const std::string x = name;
    const std::string product = tex(B - A) + " \\times " + tex(X - A);
    return "\\mathrm{side}(" + x + ") = " + (orient < 0 ? "-" : "") + "(B - A) \\times (" + x +
           " - A) = " + (orient < 0 ? "-\\big(" + product + "\\big)" : product) + " = " +
           tex(value) + (value >= 0 ? " \\ge 0" : " < 0");
}

// "[(2, 1), (4, 2)]", or "[\,]" for the empty list.
std::string list_tex(const std::vector<dvec2>& points) {
    if (points.empty()) return "[\\,]";
    std::string s = "[";
    for (std::size_t i = 0; i < points.size(); ++i) s += (i ? ", " : "") + tex(points[i]);
    return s + "]";
}

std::string edge_text(const SutherlandHodgman::State& s) {
    const std::size_t m = s.in->window.size();
    return "Window edge " + std::to_string(s.k) + ", W" + std::to_string(s.k) + "→W" +
           std::to_string((s.k + 1) % m) + " = " + num(s.A) + "→" + num(s.B);
}

}  // namespace

// ---- [spec] ----------------------------------------------------------------------------------

const Spec& SutherlandHodgman::spec() {
    static const Spec spec{
        "sutherland-hodgman",
        "Sutherland-Hodgman polygon clipping",
        "Polygons",
        {
            "orient ← sign of the window's signed area   ▷ +1 counter-clockwise, −1 clockwise",
            "input ← polygon",
            "for each window edge A→B:                   ▷ side(X) = orient·(B − A)×(X − A)",
            "    output ← empty list",
            "    S ← last vertex of input",
            "    for each vertex P of input:             ▷ inside: side ≥ 0 (on the edge too)",
            "        if S inside and P inside:           ▷ case 1: in → in",
            "            output P",
            "        else if S inside:                   ▷ case 2: going out",
            "            output I = SP ∩ AB",
            "        else if P outside:                  ▷ case 3: out → out",
            "            output nothing",
            "        else:                               ▷ case 4: going in",
            "            output I = SP ∩ AB, then P",
            "        S ← P",
            "    input ← output",
            "    if input is empty: stop                 ▷ nothing lies inside the window",
            "return input",
        },
        {
            {"setup", "find the window's orientation; the input list is the polygon"},
            {"in-in", "case 1: S and P inside, output P"},
            {"in-out", "case 2: S inside, P outside (going out), output the intersection I"},
            {"out-out", "case 3: S and P outside, output nothing"},
            {"out-in", "case 4: S outside, P inside (going in), output I, then P"},
            {"edge-done",
             "every polygon edge was clipped against this window edge: the output "
             "list becomes the next input list"},
            {"empty", "the output list came out empty: the polygon lies outside the window"},
            {"done", "all window edges done: the list is the clipped polygon"},
        },
        {},  // no sliders
        {
            .predict =
                {
                    {"in-in", {}},
                    {"in-out", {"t", "I"}},
                    {"out-in", {"t", "I"}},
                    {"out-out", {}},
                },
            .mistakes =
                {
                    {"in-in", "side_P", "negate", "took the edge's inside on the wrong side"},
                    {"in-out", "I", "copy:P", "going out, emitted P instead of the crossing point"},
                    {"out-in", "", "event:in-out",
                     "coming in, emitted only the crossing point and lost P"},
                    {"in-out", "", "event:out-out",
                     "missed the crossing and emitted nothing on the way out"},
                },
        },
    };
    return spec;
}

// ---- [validate] ------------------------------------------------------------------------------

void SutherlandHodgman::validate(const Input& in) {
    const auto& w = in.window;
    check_points(w, "window");
    const std::size_t m = w.size();
    for (std::size_t i = 0; i < m; ++i) {
        const std::size_t next = (i + 1) % m;
        if (w[i] == w[next])
            throw InputError("window", "vertices " + std::to_string(i) + " and " +
                                           std::to_string(next) + " are the same point " +
                                           given(w[i]) +
                                           (next == 0 ? " (list each vertex once: the polygon "
                                                        "closes itself)"
                                                      : ""));
    }
    // The turn at each vertex: (w_i − w_{i−1}) × (w_{i+1} − w_i), > 0 for a left turn.
    std::vector<double> turn(m), along(m);
    bool any_turn = false;
    for (std::size_t i = 0; i < m; ++i) {
        const dvec2 in_dir = w[i] - w[(i + m - 1) % m], out_dir = w[(i + 1) % m] - w[i];
        turn[i] = cross(in_dir, out_dir);
        along[i] = in_dir.x * out_dir.x + in_dir.y * out_dir.y;
        any_turn = any_turn || turn[i] != 0;
    }
    if (!any_turn) throw InputError("window", "has zero area (all its vertices lie on one line)");
    const double area = signed_area(w);
    if (area == 0) throw InputError("window", "has zero area");
    for (std::size_t i = 0; i < m; ++i) {
        const std::size_t prev = (i + m - 1) % m, next = (i + 1) % m;
        if (turn[i] == 0 && along[i] > 0)
            throw InputError(
                "window", "vertices " + std::to_string(prev) + ", " + std::to_string(i) + " and " +
                              std::to_string(next) + " are collinear (a straight angle at " +
                              vertex_text(w, i) + "); remove vertex " + std::to_string(i));
        if (turn[i] == 0)
            throw InputError("window",
                             "must be convex (doubles back at " + vertex_text(w, i) + ")");
        if ((turn[i] > 0) != (area > 0))
            throw InputError("window",
                             "must be convex (turns the other way at " + vertex_text(w, i) + ")");
    }
    // All turns go one way; a simple convex polygon turns through 360° in total, a star-shaped
    // self-crossing one (a pentagram) through 720° or more.
    double total = 0;
    for (std::size_t i = 0; i < m; ++i) total += std::atan2(std::fabs(turn[i]), along[i]);
    const long long rounds = std::llround(total / (2 * std::numbers::pi));
    if (rounds != 1)
        throw InputError("window", "must be convex (it crosses itself: its edges turn through " +
                                       std::to_string(360 * rounds) + "°, not 360°)");
    check_points(in.polygon, "polygon");
}

SutherlandHodgman::State SutherlandHodgman::start(const Input& in) {
    return start(Shared<Input>(in));
}

SutherlandHodgman::State SutherlandHodgman::start(Shared<Input> in) {
    validate(*in);
    State s;
    s.in = std::move(in);
    return s;
}

// ---- [advance] -------------------------------------------------------------------------------
// The algorithm proper: one step of the math. Kept apart from the narration below so that
// running to completion (no StepInfo) costs about what the plain clip() does.
void SutherlandHodgman::advance(State& s) {
    // Nearly every step is a polygon edge; testing for it first spares those steps the
    // switch's jump table (an indirect jump, mispredicted at every change of phase).
    if (s.phase == Phase::Clip) return clip_polygon_edge(s);
    switch (s.phase) {
        case Phase::Setup:  // Find the window's orientation; the input list is the polygon
            s.window_area = signed_area(s.in->window);
            s.orient = s.window_area > 0 ? 1.0 : -1.0;
            s.input.reserve(list_capacity(*s.in));
            s.output.reserve(list_capacity(*s.in));
            s.after_edge.reserve(s.in->window.size());
            s.input.assign(s.in->polygon.begin(), s.in->polygon.end());
            s.phase = Phase::NextEdge;
            return;
        case Phase::NextEdge: {  // Take window edge A→B; S starts as the last input vertex
            const int m = static_cast<int>(s.in->window.size());
            ++s.k;
            s.j = 0;
            s.A = s.in->window[s.k];
            s.B = s.in->window[s.k + 1 == m ? 0 : s.k + 1];
            s.AB = s.B - s.A;
            s.n = static_cast<int>(s.input.size());
            s.output.clear();
            // As if the edge before had just left P = the last vertex: it becomes S below.
            s.side_P = side(s.orient, s.A, s.B, s.input.back());
            s.phase = Phase::Clip;
            return clip_polygon_edge(s);
        }
        case Phase::Clip:  // One polygon edge S→P against A→B: the four cases
            return clip_polygon_edge(s);
        case Phase::EdgeDone:  // The output list becomes the next input list
            // Kept before the swap, not after: the swap reads the vectors' pointers 16 bytes
            // at a time, and stalls (store-to-load forwarding fails) if the last push_back's
            // 8-byte store of output's end is still in flight (copying after the swap cost
            // run_to_end 13%).
            s.after_edge.push_back(s.output);
            std::swap(s.input, s.output);
            s.output.clear();
            if (s.input.empty())
                s.phase = Phase::Done;  // nothing inside: stop
            else if (s.k + 1 == static_cast<int>(s.in->window.size()))
                s.phase = Phase::Finish;
            else
                s.phase = Phase::NextEdge;
            return;
        case Phase::Finish:  // The last list is the clipped polygon
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// One polygon edge S→P = input[j − 1]→input[j] (cyclically) against window edge A→B.
void SutherlandHodgman::clip_polygon_edge(State& s) {
    // Only side(P) is stored (S, side(S), the case, t and I are found again when asked for:
    // which_case, crossing_t, intersection_I): the fewer stores per step, the closer run_to_end
    // comes to the plain loop. Worked in locals and stored once at the end, because the output
    // list's stores could alias the state's numbers and force reloads. P is read in place: copied
    // into a local, GCC loaded it as one 16-byte vector and split it into x and y through the
    // stack, a store-and-reload on the way to the case test (the step's hard-to-predict branch);
    // clip() reads its P the same way.
    const int j = s.j, n = s.n;
    const dvec2 A = s.A, AB = s.AB;
    const dvec2& P = s.input[j];
    const double side_S = s.side_P, side_P = side_of(s.orient, A, AB, P);
    if (side_S >= 0 && side_P >= 0) {  // case 1: in → in
        s.output.push_back(P);
    } else if (side_S >= 0) {  // case 2: going out
        const dvec2 S = s.input[j == 0 ? n - 1 : j - 1];
        double t;
        s.output.push_back(intersection(A, AB, S, P, side_S, side_P, t));
    } else if (side_P >= 0) {  // case 4: going in
        const dvec2 S = s.input[j == 0 ? n - 1 : j - 1];
        double t;
        s.output.push_back(intersection(A, AB, S, P, side_S, side_P, t));
        s.output.push_back(P);
    }  // case 3, out → out: nothing
    s.side_P = side_P;
    s.j = j + 1;
    if (j + 1 == n) s.phase = Phase::EdgeDone;
}

// ---- [narrate] -------------------------------------------------------------------------------
// What the step just taken means, told with its numbers. `s` is the state after the step.
void SutherlandHodgman::narrate(const State& s, StepInfo& info) {
    info.vars = {{"orient", static_cast<long long>(s.orient)}};
    const bool clipped = s.phase == Phase::Clip || s.phase == Phase::EdgeDone;
    const dvec2 S = clipped ? edge_S(s) : dvec2(0), P = clipped ? edge_P(s) : dvec2(0);
    const double side_S = clipped ? side(s.orient, s.A, s.B, S) : 0;
    const Case which = which_case(s);
    const double t = crossing_t(s);
    const bool crossed = which == Case::InOut || which == Case::OutIn;
    const dvec2 I = crossed ? intersection_I(s) : dvec2(0);
    if (s.k >= 0) {
        info.vars.push_back({"edge", static_cast<long long>(s.k)});
        info.vars.push_back({"A", vec(s.A)});
        info.vars.push_back({"B", vec(s.B)});
    }
    if (clipped) {
        info.vars.push_back({"S", vec(S)});
        info.vars.push_back({"P", vec(P)});
        info.vars.push_back({"side_S", side_S});
        info.vars.push_back({"side_P", s.side_P});
        info.vars.push_back({"case", std::string(case_name(which))});
        if (crossed) {
            info.vars.push_back({"t", t});
            info.vars.push_back({"I", vec(I)});
        }
    }
    info.vars.push_back({"input", matrix(s.input)});
    info.vars.push_back({"output", matrix(s.output)});

    if (s.k < 0) {  // setup
        info.event = "setup";
        info.line = kLineInput;
        const bool ccw = s.orient > 0;
        info.math = "\\text{area} = \\tfrac{1}{2} \\sum_i (W_i - W_0) \\times (W_{i+1} - W_0) = " +
                    tex(s.window_area) +
                    (ccw ? " > 0 \\Rightarrow \\text{orient} = +1"
                         : " < 0 \\Rightarrow \\text{orient} = -1");
        info.narration = "The window's signed area is " + num(s.window_area) +
                         (ccw ? " > 0, so it runs counter-clockwise and inside means left of"
                              : " < 0, so it runs clockwise and inside means right of") +
                         " each edge (on the edge counts as inside); the input list is the "
                         "polygon's " +
                         vertices(s.input.size()) + ".";
        return;
    }
    if (clipped) {
        std::string head;
        if (s.j == 1) head = edge_text(s) + "; S starts as the last input vertex. ";
        const std::string sp = where("S", S, side_S) + " and " + where("P", P, s.side_P) +
                               ": case " + case_name(which);
        // "t = 8/(8 − (-8)) = 0.5, I = (4, 2)"
        const std::string minus_P = s.side_P < 0 ? "(" + num(s.side_P) + ")" : num(s.side_P);
        const std::string cut = "SP crosses AB at t = " + num(side_S) + "/(" + num(side_S) + " − " +
                                minus_P + ") = " + num(t) + ", I = " + num(I);
        info.math = side_tex("S", s.orient, s.A, s.B, S, side_S) + ",\\quad " +
                    side_tex("P", s.orient, s.A, s.B, P, s.side_P);
        if (crossed) {
            const std::string minus_P_tex =
                s.side_P < 0 ? "(" + tex(s.side_P) + ")" : tex(s.side_P);
            info.math +=
                ",\\quad t = \\frac{\\mathrm{side}(S)}{\\mathrm{side}(S) - "
                "\\mathrm{side}(P)} = \\frac{" +
                tex(side_S) + "}{" + tex(side_S) + " - " + minus_P_tex + "} = " + tex(t) +
                ",\\quad I = S + t\\,(P - S) = " + tex(S) + " + " + tex(t) + "\\," + tex(P - S) +
                " = " + tex(I);
        }
        switch (which) {
            case Case::InIn:
                info.event = "in-in";
                info.line = kLineInIn;
                info.narration = head + sp + ", output P = " + num(P) + ".";
                break;
            case Case::InOut:
                info.event = "in-out";
                info.line = kLineInOut;
                info.narration = head + sp + "; " + cut + ", output I.";
                break;
            case Case::OutOut:
                info.event = "out-out";
                info.line = kLineOutOut;
                info.narration = head + sp + ", output nothing.";
                break;
            default:
                info.event = "out-in";
                info.line = kLineOutIn;
                info.narration = head + sp + "; " + cut + ", output I, then P = " + num(P) + ".";
                break;
        }
        return;
    }
    if (s.phase == Phase::Done && s.input.empty()) {
        info.event = "empty";
        info.line = kLineEmpty;
        info.math = "\\text{output} = [\\,] \\Rightarrow \\text{stop}";
        info.narration = "Window edge " + std::to_string(s.k) +
                         " done: nothing of the input list lies on its inner side, so the "
                         "output list is empty and the polygon lies outside the window: stop, "
                         "nothing is visible.";
        return;
    }
    if (s.phase == Phase::Done) {
        info.event = "done";
        info.line = kLineReturn;
        info.math = "\\text{result} = " + list_tex(s.input);
        info.narration = "All " + std::to_string(s.in->window.size()) +
                         " window edges done: the clipped polygon is " + list_text(s.input) + ".";
        return;
    }
    info.event = "edge-done";
    info.line = kLineSwap;
    info.math = "\\text{input} \\leftarrow \\text{output} = " + list_tex(s.input);
    info.narration = "Window edge " + std::to_string(s.k) + " done: its output list of " +
                     vertices(s.input.size()) + ", " + list_text(s.input) + ", becomes " +
                     (s.phase == Phase::Finish
                          ? "the final list; that was the last window edge."
                          : "the input list for window edge " + std::to_string(s.k + 1) + ".");
}

void SutherlandHodgman::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

SutherlandHodgman::Result SutherlandHodgman::result(const State& s) {
    if (s.phase == Phase::Setup) return {s.in->polygon, {}};
    return {s.input, s.after_edge};
}

// run_to_end's: the state is spent, so its lists move into the result as clip() moves its
// own (copying them instead costs 1 + m allocations and copies per run, +40% in the benchmark).
SutherlandHodgman::Result SutherlandHodgman::result(State&& s) {
    if (s.phase == Phase::Setup) return {s.in->polygon, {}};  // shared: copied
    return {std::move(s.input), std::move(s.after_edge)};
}

// The case tests of clip_polygon_edge again, on side(S) recomputed (the same double: see
// edge_S) and the stored side(P).
SutherlandHodgman::Case SutherlandHodgman::which_case(const State& s) {
    if (s.phase != Phase::Clip && s.phase != Phase::EdgeDone) return Case::None;
    const double side_S = side(s.orient, s.A, s.B, edge_S(s)), side_P = s.side_P;
    if (side_S >= 0) return side_P >= 0 ? Case::InIn : Case::InOut;
    return side_P >= 0 ? Case::OutIn : Case::OutOut;
}

double SutherlandHodgman::crossing_t(const State& s) {
    const Case c = which_case(s);
    if (c != Case::InOut && c != Case::OutIn) return 0;
    double t;
    intersection(s.A, s.AB, edge_S(s), edge_P(s), side(s.orient, s.A, s.B, edge_S(s)), s.side_P, t);
    return t;
}

dvec2 SutherlandHodgman::intersection_I(const State& s) {
    return s.output[s.output.size() - (which_case(s) == Case::OutIn ? 2 : 1)];
}

// ---- [clip] ----------------------------------------------------------------------------------

SutherlandHodgman::Result SutherlandHodgman::clip(const std::vector<dvec2>& window,
                                                  const std::vector<dvec2>& polygon) {
    const double orient = signed_area(window) > 0 ? 1.0 : -1.0;
    const std::size_t capacity = 2 * (polygon.size() + window.size());
    std::vector<dvec2> input, output;
    input.reserve(capacity);
    output.reserve(capacity);
    input.assign(polygon.begin(), polygon.end());
    const std::size_t m = window.size();
    std::vector<std::vector<dvec2>> after_edge;
    after_edge.reserve(m);
    for (std::size_t k = 0; k < m; ++k) {
        const dvec2 A = window[k], B = window[k + 1 == m ? 0 : k + 1], AB = B - A;
        output.clear();
        dvec2 S = input.back();
        double side_S = side_of(orient, A, AB, S);
        for (const dvec2& P : input) {  // in place, as clip_polygon_edge reads it
            const double side_P = side_of(orient, A, AB, P);
            double t;
            if (side_S >= 0 && side_P >= 0) {
                output.push_back(P);
            } else if (side_S >= 0) {
                output.push_back(intersection(A, AB, S, P, side_S, side_P, t));
            } else if (side_P >= 0) {
                output.push_back(intersection(A, AB, S, P, side_S, side_P, t));
                output.push_back(P);
            }
            S = P;
            side_S = side_P;
        }
        std::swap(input, output);
        after_edge.push_back(input);
        if (input.empty()) break;
    }
    return {std::move(input), std::move(after_edge)};
}

// ---- [draw] ----------------------------------------------------------------------------------

void SutherlandHodgman::draw(const State& s, Scene& scene) {
    const auto& w = s.in->window;
    const auto& poly = s.in->polygon;
    const bool finished = s.phase == Phase::Done;
    const bool clipped = s.phase == Phase::Clip || s.phase == Phase::EdgeDone;

    // The window edge being clipped against, as the half-plane it keeps.
    if (s.k >= 0 && !finished) {
        const dvec2 d = s.B - s.A;
        const dvec2 inward = s.orient * dvec2(-d.y, d.x) / std::sqrt(d.x * d.x + d.y * d.y);
        scene.half_planes.push_back({s.A,
                                     inward,
                                     "edge " + std::to_string(s.k) + ": W" + std::to_string(s.k) +
                                         "→W" + std::to_string((s.k + 1) % w.size()),
                                     {Role::Active, 2.5f}});
    }

    scene.polygons.push_back({w, {Role::Window, 2.0f}, true, true});
    // The polygon as given, faint once clipping has begun; red if nothing of it survived.
    if (s.phase != Phase::Setup) {
        const bool lost = finished && s.input.empty();
        scene.polygons.push_back(
            {poly,
             {lost ? Role::Discarded : Role::Construction, lost ? 2.0f : 1.0f, true},
             true,
             false});
    }
    if (finished) {
        if (!s.input.empty()) scene.polygons.push_back({s.input, {Role::Kept, 3.0f}, true, true});
    } else {
        // The list being clipped, and what this window edge has kept of it so far.
        scene.polygons.push_back(
            {s.phase == Phase::Setup ? poly : s.input, {Role::Subject, 2.0f, true}, true, false});
        if (!s.output.empty())
            scene.polygons.push_back({s.output, {Role::Kept, 4.0f}, false, false});
    }

    if (clipped) {
        const dvec2 S = edge_S(s), P = edge_P(s);
        scene.segments.push_back({S, P, "", {Role::Active, 3.0f}, true});
        scene.labels.push_back({S, "S", {Role::Active}});
        scene.labels.push_back({P, "P", {Role::Active}});
        const Case which = which_case(s);
        if (which == Case::InOut || which == Case::OutIn)
            scene.points.push_back({intersection_I(s),
                                    "I",
                                    {which == Case::OutIn ? Role::Entering : Role::Leaving},
                                    6.0f});
    }
    if (!finished)
        for (std::size_t i = 0; i < s.output.size(); ++i)
            scene.points.push_back({s.output[i], std::to_string(i), {Role::Kept}, 4.0f});

    for (std::size_t i = 0; i < w.size(); ++i) {
        const std::string n = std::to_string(i);
        scene.labels.push_back({w[i], "W" + n, {Role::Window}});
        scene.handles.push_back({w[i], "W" + n, "/window/" + n + "/0", "/window/" + n + "/1"});
    }
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const std::string n = std::to_string(i);
        scene.handles.push_back(
            {poly[i], "polygon " + n, "/polygon/" + n + "/0", "/polygon/" + n + "/1"});
    }
}

}  // namespace cg
