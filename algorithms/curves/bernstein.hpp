// The Bernstein basis and what it says about Bézier curves.
//
// A Bézier curve of degree n is the weighted sum of its control points
//
//     P(t) = Σ_i P_i B_i^n(t),   B_i^n(t) = C(n, i) (1 − t)^(n−i) t^i,   i = 0 .. n.
//
// The weights add up to 1 for every t (the binomial theorem: ((1 − t) + t)^n = 1), so P(t) is
// an affine combination of the P_i; and for t in [0, 1] none is negative, so it is a convex
// combination: the curve lies in the convex hull of its control points. Because the sum is
// affine, an affine map T commutes with it: T(P(t)) = Σ_i B_i^n(t) T(P_i) (affine invariance).
//
// Steps: one per basis function B_0^n(t) .. B_n^n(t); their sum; their signs; the point as
// the weighted sum; the convex hull of the control points (Andrew's monotone chain) and
// whether P(t) lies in it; with a transform, the affine-invariance check.
//
// Conventions: 2D points, degree 1 .. 50. t in [0, 1] unless `extrapolate` (then some weights
// are negative and the point may leave the hull; |t| ≤ 1000). The transform is 3 × 3 rows of a
// 2D homogeneous matrix acting on column vectors (x', y', 1) = M (x, y, 1); its last row must
// be [0, 0, 1] (an affine map: a projective one does not keep Bézier curves). "Inside the hull"
// and "invariant" allow 1e-9 relative to the largest coordinate (rounding, not geometry). The
// hull is counter-clockwise from the lowest-leftmost point, without collinear vertices; for
// collinear control points it is the two extreme points (or one point).
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

struct Bernstein {
    using Rows = std::array<glm::dvec3, 3>;  // a 3 × 3 matrix as its rows

    struct Input {
        std::vector<glm::dvec2> control_points;  // P_0 .. P_n, n ≥ 1
        double t = 0.5;
        bool extrapolate = false;  // allow t outside [0, 1]
        std::optional<Rows>
            transform;  // an affine map in homogeneous rows, for the invariance check
        bool operator==(const Input&) const = default;
    };

    struct Result {
        std::vector<double> basis;     // B_0^n(t) .. B_n^n(t)
        double sum = 0;                // Σ B_i (1 up to rounding)
        bool non_negative = true;      // every B_i ≥ 0 (always so for t in [0, 1])
        glm::dvec2 point{0};           // Σ B_i P_i
        std::vector<glm::dvec2> hull;  // convex hull of the control points, counter-clockwise
        bool inside_hull = true;       // P(t) in the hull
        std::optional<glm::dvec2> transformed_point;  // Σ B_i T(P_i), with a transform
        std::optional<glm::dvec2> image_of_point;     // T(P(t)), with a transform
        std::optional<bool> affine_invariant;         // the two agree
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Basis, Sum, Sign, Point, Hull, Affine, Done };

    struct State {
        Input in;
        Phase phase = Phase::Basis;
        int i = -1;                 // the basis function computed last (−1: none yet)
        std::vector<double> basis;  // B_0 .. B_n, filled up to i
        double sum = 0;
        int negative = 0;  // how many B_i are negative
        glm::dvec2 point{0};
        std::vector<glm::dvec2> hull;
        bool inside_hull = false;
        std::vector<glm::dvec2> transformed;  // T(P_i), once the affine step ran
        glm::dvec2 transformed_point{0}, image_of_point{0};
        double affine_error = 0;  // |Σ B_i T(P_i) − T(P(t))|
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (bernstein_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // Andrew's monotone chain: sort by x (then y), build the lower and the upper chain, popping
    // every point that does not turn left. Counter-clockwise, no collinear vertices.
    static std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> points);
    // Whether p lies in the convex polygon `hull` (as convex_hull returns it), within `tolerance`.
    static bool in_hull(const std::vector<glm::dvec2>& hull, glm::dvec2 p, double tolerance);
    static glm::dvec2 apply(const Rows& m, glm::dvec2 p);  // (x', y') of M (x, y, 1)

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
