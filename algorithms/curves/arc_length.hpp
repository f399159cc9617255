// Approximate arc-length parameterisation of a Bézier curve by a table of chord lengths.
//
// A motion path P(u) moves at an uneven speed if u follows time: equal steps of u cover
// unequal distances. The fix is to find u as a function of the distance travelled s, i.e. to
// invert s = A(u) = ∫_0^u |P'(v)| dv. There is no closed form for a cubic, so we tabulate:
//
//     u_j = j / N,   s_0 = 0,   s_j = s_{j−1} + |P(u_j) − P(u_{j−1})|,   j = 0 .. N
//
// (the chord lengths add up to L = s_N, a little under the true length). For a distance s,
// find the entries with s_j ≤ s ≤ s_{j+1} and interpolate linearly,
//
//     u = u_j + (s − s_j) / (s_{j+1} − s_j) · (u_{j+1} − u_j),
//
// then P(u) is the point that far along the curve. Distances may also be given as fractions f
// of the length (s = f L), which gives points at equal spacing for equal steps of f.
//
// Steps: one per sample of the table; the total length, compared with an accurate integral
// (adaptive Simpson on |P'(u)| in long double); one per query.
//
// Conventions: control points of any degree 1 .. 50, 2D or 3D (pictures drop z); N in
// 1 .. 10,000 (default 10). Distances lie in [0, L] and fractions in [0, 1], checked at the
// start against the table's own L. s = 0 gives u = 0; of several equal s_j (a curve that stands
// still) the interval used is the first that reaches s with s_{j+1} > s_j.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"

namespace cg {

struct ArcLength {
    static constexpr int kMaxSamples = 10'000;

    struct Input {
        std::vector<glm::dvec3> control_points;  // P_0 .. P_n, n ≥ 1; z = 0 when dim = 2
        int dim = 2;
        int samples = 10;               // N: the table has N + 1 rows
        std::vector<double> distances;  // s values to invert, in [0, L] ...
        std::vector<double> fractions;  // ... or fractions of L, in [0, 1] (not both)
        bool operator==(const Input&) const = default;
    };

    struct Query {
        double s = 0;         // the distance along the curve
        double u = 0;         // the parameter found by interpolation
        glm::dvec3 point{0};  // P(u)
        int bracket = 0;      // j with s_j ≤ s ≤ s_{j+1}
        bool operator==(const Query&) const = default;
    };

    struct Result {
        int dim = 2;               // of the points
        std::vector<double> u, s;  // the table: u_j and s_j, N + 1 entries
        double length = 0;         // L = s_N
        double length_exact = 0;   // L* = ∫_0^1 |P'(u)| du, numerically to ~1e-12
        double length_error = 0;   // L − L* (≤ 0: chords are shorter than the arc)
        std::vector<Query> queries;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Sample, Length, Query, Done };

    struct State {
        Input in;
        Phase phase = Phase::Sample;     // the step to take next
        Phase taken = Phase::Done;       // the step taken last (Done: none yet)
        int j = -1;                      // the sample computed last (−1: none)
        std::vector<double> u, s;        // the table so far
        std::vector<glm::dvec3> points;  // P(u_j) so far
        double length = 0, length_exact = 0;
        std::vector<Query> queries;  // answered so far
        bool operator==(const State&) const = default;
    };
    // The state's heap memory, for the timeline's memory budget (see Run::bytes).
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.in.control_points) + heap_bytes(s.in.distances) + heap_bytes(s.in.fractions) +
               heap_bytes(s.u) + heap_bytes(s.s) + heap_bytes(s.points) + heap_bytes(s.queries);
    }

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (arc_length_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The table's length alone (what validation checks the distances against).
    static double table_length(const std::vector<glm::dvec3>& control_points, int samples);
    // ∫_0^1 |P'(u)| du by adaptive Simpson in long double, to about 1e-13 relative.
    static double exact_length(const std::vector<glm::dvec3>& control_points);
    // Inverts the table at s (the interpolation of the header comment).
    static Query invert(const std::vector<double>& u, const std::vector<double>& s,
                        double distance);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
