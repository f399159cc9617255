// Sutherland-Hodgman polygon clipping against a convex window.
//
// The polygon is clipped against one window edge at a time: all of its edges in succession
// against window edge A→B, which gives an output list; that list is the input for the next
// window edge, and so on round the window. For each polygon edge S→P (S starts as the LAST
// vertex of the input list) one of four cases holds:
//
//     case 1  S inside,  P inside   (in → in)    output P
//     case 2  S inside,  P outside  (going out)  output I
//     case 3  S outside, P outside  (out → out)  output nothing
//     case 4  S outside, P inside   (going in)   output I, then P
//
// where I is where S→P crosses the line AB. If a list comes out empty the polygon lies
// wholly outside the window and the algorithm stops with an empty result.
// The result keeps every window edge's output list (after_edge) beside the final polygon:
// those intermediate lists are what an exam asks for.
//
// Conventions:
//   - Inside. side(X) = orient · (B − A) × (X − A), with orient = +1 for a counter-clockwise
//     window (inside = left of each edge) and −1 for a clockwise one (inside = right), found
//     from the sign of the window's signed area. X is inside when side(X) ≥ 0: a point ON the
//     window edge counts as inside.
//   - Intersection. I = S + t (P − S) with t = side(S) / (side(S) − side(P)), the parameter at
//     which the side value (linear along S→P) is zero. On an axis-parallel window edge the
//     coordinate the edge fixes is then set exactly (x = 5, not 5.000000000000001), so exam
//     numbers come out exact and later tests see I exactly on that line.
//   - Steps: setup; per window edge k (0-based, A = window[k], B = window[k+1 mod m]) one step
//     per polygon edge, named by its case (in-in, in-out, out-out, out-in), then edge-done (the
//     output list becomes the next input list) or empty (it came out empty: stop); then done.
//
// Window: convex, m ≥ 3 vertices, either orientation, finite, |coordinate| ≤ 1e100 (so cross
// products stay finite). Refused, naming "window": fewer than 3 vertices, two consecutive
// vertices equal, all vertices on one line or zero area, a reflex turn, self-crossing (all
// turns one way but winding round twice), and also three consecutive collinear vertices
// (a straight angle): we refuse those rather than silently drop the middle vertex, so window
// edge k is always window[k]→window[k+1] as the user wrote it.
//
// Polygon (the subject): n ≥ 3 vertices, finite, |coordinate| ≤ 1e100; concave is fine. It
// should be simple, but that is not checked: every pass is well defined for any closed
// polyline (the result then has the polygon's winding numbers inside the window).
//
// Known behaviour, kept because it is the classic algorithm the course teaches: the output is
// one list, so a concave polygon cut into several pieces comes out as one polygon whose pieces
// are joined by zero-width "bridges" along the window boundary; and vertices on a window edge
// give repeated or collinear output points (a polygon touching the window from outside gives
// a zero-area list of repeated points, not an empty one).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct SutherlandHodgman {
    struct Input {
        std::vector<glm::dvec2> window;  // the convex clip window, m ≥ 3 vertices, either way round
        std::vector<glm::dvec2> polygon;  // the polygon to clip, n ≥ 3 vertices, may be concave
        bool operator==(const Input&) const = default;
    };
    struct Result {
        std::vector<glm::dvec2> polygon;  // the clipped polygon, in the order made; may be empty
        // The output list of each window edge processed, in order: after_edge[k] is what edge k
        // kept (m lists, or fewer when one came out empty and the run stopped there); the last
        // equals `polygon`.
        std::vector<std::vector<glm::dvec2>> after_edge;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Setup, NextEdge, Clip, EdgeDone, Finish, Done };
    enum class Case : std::uint8_t { None, InIn, InOut, OutOut, OutIn };

    struct State {
        Shared<Input> in;  // never changes during a run: copies of the state share it
        Phase phase = Phase::Setup;
        double window_area = 0;  // signed area of the window (> 0: counter-clockwise)
        double orient = 0;       // +1 counter-clockwise window, −1 clockwise (0 before setup)
        int k = -1;              // the window edge being clipped against, 0..m−1 (−1 before)
        int j = 0;               // polygon edges of `input` done in this pass, 0..n
        int n = 0;               // input's size in this pass (read at every step)
        glm::dvec2 A{0}, B{0};   // window edge k: A = window[k], B = window[k + 1 mod m]
        glm::dvec2 AB{0};        // B − A, formed once per edge rather than at every step
        // The polygon edge S→P tested last is input[j − 2 mod n]→input[j − 1]. Only side(P)
        // is stored: S, side(S), the case, t and I are found again when asked for (which_case,
        // crossing_t, intersection_I), the same formulas on the same numbers giving the same
        // doubles. The fewer stores per step, the closer run_to_end comes to the plain loop.
        double side_P = 0;  // side(P), ≥ 0 inside (area units); the next step's side(S)
        std::vector<glm::dvec2> input;   // the list being clipped against edge k
        std::vector<glm::dvec2> output;  // what edge k keeps so far
        // The output list of each window edge finished, after_edge[k] for edge k: kept in the
        // result's own shape, one exact-size copy per edge as clip() makes them, so that
        // result(State&&) (what run_to_end calls) hands them over without copying again.
        std::vector<std::vector<glm::dvec2>> after_edge;
        bool operator==(const State&) const = default;
    };
    // The state's heap memory, for the timeline's memory budget (see Run::bytes).
    // The input is not counted: copies of a state share it (Shared<Input>).
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.input) + heap_bytes(s.output) + heap_bytes(s.after_edge);
    }

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State start(Shared<Input> in);        // the same, sharing an input already made
    static void step(State& s, StepInfo* info);  // advance, then narrate if info is given
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);  // the current list; the clipped polygon once done
    static Result result(State&& s);       // the same, moving the lists out of a spent state
    // The polygon edge just clipped (phase Clip or EdgeDone; Case::None otherwise): its case,
    static Case which_case(const State& s);
    // ... t = side(S) / (side(S) − side(P)) where it crossed AB (cases 2 and 4; 0 otherwise),
    static double crossing_t(const State& s);
    // ... and I, the output list's last vertex (case 2) or the one before it (case 4, which
    // then output P).
    static glm::dvec2 intersection_I(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (sutherland_hodgman_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same clipping as one straight-line function, for the benchmark's comparison.
    static Result clip(const std::vector<glm::dvec2>& window,
                       const std::vector<glm::dvec2>& polygon);

  private:
    static void advance(State& s);
    static void clip_polygon_edge(State& s);  // the Clip phase: one polygon edge, four cases
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
