// Liang-Barsky line clipping against an axis-aligned window.
//
// The segment is written parametrically, P(t) = P0 + t (P1 - P0) for t in [0, 1]. Each window
// edge k is a half-plane, and P(t) lies inside it exactly when p_k t <= q_k, with
//
//     k = 1 left:    p_1 = -dx,  q_1 = x0 - xmin
//     k = 2 right:   p_2 =  dx,  q_2 = xmax - x0
//     k = 3 bottom:  p_3 = -dy,  q_3 = y0 - ymin
//     k = 4 top:     p_4 =  dy,  q_4 = ymax - y0
//
// If p_k = 0 the segment is parallel to edge k: wholly inside it (q_k >= 0) or wholly outside
// (q_k < 0, reject). Otherwise the line crosses the edge at r_k = q_k / p_k; p_k < 0 means the
// line enters the half-plane there (t_enter = max(t_enter, r_k)), p_k > 0 that it leaves
// (t_leave = min(t_leave, r_k)). Once t_enter > t_leave nothing is left: reject. After all four
// edges the visible part is P(t_enter)..P(t_leave).
//
// Steps: setup, one per edge (entering / leaving / parallel), then reject or accept.
// Boundaries count as inside: a segment touching the window at one point is visible there.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/rng.hpp"
#include "core/run.hpp"

namespace cg {

struct LiangBarsky {
    struct Window {
        double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
        bool operator==(const Window&) const = default;
    };
    struct Input {
        Window window;
        glm::dvec2 p0{0}, p1{0};
        bool operator==(const Input&) const = default;
    };
    enum class Phase : std::uint8_t { Setup, Edge, Reject, Accept, Done };
    enum class Verdict : std::uint8_t { None, Entering, Leaving, ParallelInside, ParallelOutside };

    // Edge k's name as the course says it: 1 left, 2 right, 3 bottom, 4 top ("" for 0).
    static constexpr const char* kEdgeName[] = {"", "left", "right", "bottom", "top"};

    // One edge's test, as the student writes it in the table: p_k, q_k, r_k = q_k / p_k (0 when
    // p_k = 0) and what the line does there.
    struct EdgeTest {
        int k = 0;  // 1 left, 2 right, 3 bottom, 4 top
        double p = 0, q = 0, r = 0;
        Verdict verdict = Verdict::None;
        bool operator==(const EdgeTest&) const = default;
    };

    struct Result {
        bool visible = false;
        double t_enter = 0, t_leave = 1;  // at the end (or at the moment of rejection)
        std::optional<glm::dvec2> q0, q1;  // the visible part, when visible
        std::vector<EdgeTest> edges;       // the edges tested, in order, up to a rejection
        bool operator==(const Result&) const = default;
    };

    struct State {
        Input in;
        Phase phase = Phase::Setup;
        int k = 0;  // the edge tested last, 1..4 (0 before the first)
        Verdict verdict = Verdict::None;
        double dx = 0, dy = 0;
        double t_enter = 0, t_leave = 1;
        double p_k = 0, q_k = 0, r_k = 0;
        double t_before = 0;  // the t that edge k's test just changed, before it changed
        std::array<EdgeTest, 4> tested{};  // edges 1..k's tests
        bool visible = false;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);  // advance, then narrate if info is given
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (liang_barsky_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // The same clipping as one straight-line function, for the benchmark's comparison.
    static Result clip(const Input& in);
    // The part of segment a–b inside the window, in place (a = Q0, b = Q1; no table, no
    // allocation): for pictures that clip their own lines. False when none of it is inside.
    static bool clip_segment(const Window& w, glm::dvec2& a, glm::dvec2& b);

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
