// De Casteljau's algorithm: a point of a Bézier curve by repeated linear interpolation.
//
// The n + 1 control points are level 0, P_i^0 = P_i. Each level interpolates neighbours of the
// one before at the same ratio t : (1 − t),
//
//     P_i^k = (1 − t) P_i^{k−1} + t P_{i+1}^{k−1},    i = 0 .. n − k,
//
// so level k has n + 1 − k points and level n the single point P(t) = P_0^n. The last segment,
// P_0^{n−1} → P_1^{n−1}, is tangent to the curve there: P'(t) = n (P_1^{n−1} − P_0^{n−1}).
// The triangle's two outer edges are the control polygons of the two halves of the curve split
// at t: left = [P_0^0, P_0^1, …, P_0^n] covers [0, t], right = [P_0^n, P_1^{n−1}, …, P_n^0]
// covers [t, 1] (subdivision).
//
// Steps: one per level 1 .. n − 1 (the points of that level), then the curve point (level n),
// the tangent, and the subdivision.
//
// Conventions: any degree 1 .. 50; points 2D or 3D, stored as dvec3 with z = 0 in 2D (3D
// control points are drawn on the 3D canvas). t must lie in [0, 1] unless `extrapolate` is set: the same construction then gives
// the polynomial's continuation (the points are no longer convex combinations), |t| ≤ 1000.
// The triangle is stored flat, level by level: P_i^k at index k (n + 1) − k (k − 1) / 2 + i.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "curves/bezier.hpp"

namespace cg {

struct DeCasteljau {
    // The triangle of a cubic (10 points) lives inside the state: no allocation per run.
    using Triangle = curves::InlinePoints<10>;

    struct Input {
        std::vector<glm::dvec3> control_points;  // P_0 .. P_n, n ≥ 1; z = 0 when dim = 2
        int dim = 2;                             // 2 or 3
        double t = 0.5;                          // the parameter to evaluate at
        bool extrapolate = false;                // allow t outside [0, 1]
        bool operator==(const Input&) const = default;
    };

    struct Result {
        int dim = 2;
        int n = 0;  // the degree
        double t = 0;
        glm::dvec3 point{0};    // P(t) = P_0^n
        glm::dvec3 tangent{0};  // P'(t) = n (P_1^{n−1} − P_0^{n−1})
        Triangle levels;        // the whole triangle, flat (see the header comment)

        glm::dvec3 at(int k, int i) const {
            return levels[offset(n, k) + static_cast<std::size_t>(i)];
        }
        std::vector<glm::dvec3> level(int k) const;  // P_0^k .. P_{n−k}^k
        std::vector<glm::dvec3> left() const;        // [P_0^0, P_0^1, …, P_0^n]
        std::vector<glm::dvec3> right() const;       // [P_0^n, P_1^{n−1}, …, P_n^0]
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Level, Point, Tangent, Subdivide, Done };

    struct State {
        // The input: the control points are level 0 of the triangle.
        int dim = 2;
        int n = 0;  // the degree
        double t = 0;
        bool extrapolate = false;
        // The construction.
        Phase phase = Phase::Level;
        int k = 0;        // the last level computed (0: only the control points so far)
        Triangle levels;  // (n + 1)(n + 2) / 2 points once allocated; filled up to level k
        glm::dvec3 point{0}, tangent{0};
        bool operator==(const State&) const = default;
    };

    // Index of P_i^k in the flat triangle of degree n is offset(n, k) + i.
    static constexpr std::size_t offset(int n, int k) {
        return static_cast<std::size_t>(k * (n + 1) - k * (k - 1) / 2);
    }

    static const Spec& spec();
    static void validate(const Input& in);       // throws InputError naming the field
    static State start(const Input& in);         // validate, then begin
    static State begin(const Input& in);         // the initial state of a known-good input
    static void step(State& s, StepInfo* info);  // advance, then narrate if info is given
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static void draw3(const State& s, Scene& scene);  // 3D control points: the 3D canvas

    // Exam practice (de_casteljau_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same evaluation as one straight-line function, for the benchmark's comparison.
    static Result evaluate(const Input& in);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
