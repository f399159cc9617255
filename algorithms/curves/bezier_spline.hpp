// Piecewise cubic Bézier curves: building them from Hermite data or Catmull-Rom points, and
// checking how smoothly consecutive segments join.
//
// A joint between segments [P_0, P_1, P_2, P_3] and [Q_0, Q_1, Q_2, Q_3] is
//     C0  when P_3 = Q_0                                   (the pieces meet)
//     G1  when C0 and P_3 − P_2 = β (Q_1 − Q_0), β > 0     (same direction; β is reported)
//     C1  when C0 and P_3 − P_2 = Q_1 − Q_0                (same derivative: 3 (P_3 − P_2))
//     C2  when C1 and (P_3 − P_2) − (P_2 − P_1) = (Q_2 − Q_1) − (Q_1 − Q_0)
//                                                          (same second derivative; the A-frame:
//                                                           2 P_2 − P_1 = 2 Q_1 − Q_2)
// Each level includes the ones before (C2 ⇒ C1 ⇒ G1 ⇒ C0). β is reported when G1 holds with
// both vectors non-zero (β = 1 for C1); a C1 joint whose vectors are both zero has no β.
// Equalities allow 1e-9 times the largest coordinate of the spline (rounding, not geometry).
//
// Cubic Hermite interpolation: points P_0 .. P_N and derivatives v_0 .. v_N give one Bézier
// segment per interval, [P_i, P_i + v_i / 3, P_{i+1} − v_{i+1} / 3, P_{i+1}]: it passes through
// P_i and P_{i+1} with P'(0) = v_i and P'(1) = v_{i+1}, so the spline is C1 by construction.
// Catmull-Rom makes the derivatives up from the points: v_i = (P_{i+1} − P_{i−1}) / 2 inside;
// at the ends (our convention) the one-sided differences v_0 = P_1 − P_0, v_N = P_N − P_{N−1}.
// A closed Catmull-Rom spline (`closed`, at least 3 points, the last not repeating the first)
// has no ends: every v_i = (P_{i+1} − P_{i−1}) / 2 with the indices taken cyclically (P_{−1} =
// P_N, P_{N+1} = P_0), and one segment more, from P_N back to P_0 — so N + 1 segments and N + 1
// joints, the last (segment N into segment 0) the seam, C1 like every other joint. `closed`
// applies to Catmull-Rom only: segments and Hermite data are taken as given (a loop there is
// the user's to close, with its own tangents), so it is refused for them.
//
// Steps: Catmull-Rom's derivatives one point at a time; Hermite segments one at a time; one
// step per joint (its continuity); a summary (the weakest joint).
//
// Conventions: 2D or 3D points — all of one input the same dimension (`dim`; 2D points have
// z = 0 here); at least 1 segment or 2 points (3 when closed), at most 1,000 segments; every
// coordinate finite and within ±1e100. A 3D spline is drawn on the 3D canvas (no handles).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"

namespace cg {

struct BezierSpline {
    using Segment = std::array<glm::dvec3, 4>;  // one cubic's control points P_0 .. P_3
    enum class Mode : std::uint8_t { Segments, Hermite, CatmullRom };

    struct Input {
        Mode mode = Mode::Segments;
        int dim = 2;                       // 2 or 3 for every point of the input (2D: z = 0)
        std::vector<Segment> segments;     // Segments: the cubics as given
        std::vector<glm::dvec3> points;    // Hermite and Catmull-Rom: P_0 .. P_N
        std::vector<glm::dvec3> tangents;  // Hermite: v_0 .. v_N (derivatives at the points)
        bool closed = false;               // Catmull-Rom only: a loop back to P_0
        bool operator==(const Input&) const = default;
    };

    struct Joint {
        bool c0 = false, c1 = false, g1 = false;
        std::optional<double> beta;  // P_3 − P_2 = β (Q_1 − Q_0), when G1 with non-zero vectors
        bool c2 = false;
        bool operator==(const Joint&) const = default;
    };

    struct Result {
        int dim = 2;
        std::vector<Segment> segments;
        std::vector<Joint> joints;  // joints[j]: segments j and j + 1 (closed: the last, N and 0)
        std::optional<std::vector<glm::dvec3>> tangents;  // v_i (Hermite: given; Catmull-Rom: made)
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Tangent, Convert, Joint, Summary, Done };

    struct State {
        Input in;
        double tolerance = 0;              // 1e-9 × the largest coordinate
        Phase phase = Phase::Joint;        // the step to take next
        Phase taken = Phase::Done;         // the step taken last (Done: none yet)
        int index = -1;                    // the point, segment or joint that step handled
        std::vector<glm::dvec3> tangents;  // v_i: Catmull-Rom fills them one by one
        std::vector<Segment> segments;     // Hermite and Catmull-Rom fill them one by one
        std::vector<Joint> joints;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (bezier_spline_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The continuity of the joint between a and b (as in the header comment).
    static Joint classify(const Segment& a, const Segment& b, double tolerance);
    // "C2", "C1", "G1", "C0" or "broken": the strongest level that holds.
    static std::string level(const Joint& j);
    static Segment hermite_segment(glm::dvec3 p0, glm::dvec3 v0, glm::dvec3 p1, glm::dvec3 v1);
    // How many segments and joints the input makes (closed: one segment more, the seam joint).
    static std::size_t segment_count(const Input& in);
    static std::size_t joint_count(const Input& in) {
        return in.closed ? segment_count(in) : segment_count(in) - 1;
    }

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
