// Quaternion algebra: the product (and that it does not commute), the conjugate, the norm, the
// inverse, the rotation q (0, P) q̄ of a point, and axis-angle ↔ quaternion ↔ matrix. One
// operation per run, chosen by `op`.
//
// A quaternion q = (s, v) = s + v_x i + v_y j + v_z k is written [w, x, y, z] with w = s. The
// course's formulas, each one step or a few:
//   multiply          q1 q2 = (s1 s2 − v1 · v2, s1 v2 + s2 v1 + v1 × v2); q2 q1 has the same
//                     parts except the cross product, whose sign flips, so the two are equal
//                     exactly when v1 × v2 = 0 (the vector parts are parallel or one is zero).
//                     Any quaternions, the zero one included: this is algebra, not rotation.
//   conjugate         q̄ = (s, −v), and q q̄ = (|q|², 0) with |q| = √(s² + |v|²). Any q.
//   inverse           q⁻¹ = q̄ / |q|² (q ≠ 0), and q q⁻¹ = (1, 0).
//   rotate            q ← q / |q| (the unit quaternion of the same rotation; said so when the
//                     input was not unit), then (0, P′) = q (0, P) q̄ as two products.
//   from_axis_angle   q = (cos θ/2, sin θ/2 â), â = a / |a| (a ≠ 0). θ/2 a multiple of 30° or
//                     45° gives the exact values (√2/2, not 0.70710678118654746).
//   to_matrix         q ← q / |q|, then M = [1 − 2(y² + z²), 2(xy − wz), 2(xz + wy);
//                     2(xy + wz), 1 − 2(x² + z²), 2(yz − wx); 2(xz − wy), 2(yz + wx), 1 − 2(x² +
//                     y²)].
//   from_matrix       R must be a rotation: max |RᵀR − I| ≤ 1e-3 and |det R − 1| ≤ 1e-3 (a
//                     typed matrix with four significant digits passes; a reflection or a
//                     scaled matrix does not). Shepperd's method: 4w² = 1 + tr R,
//                     4x² = 1 + 2 r11 − tr R, 4y² = 1 + 2 r22 − tr R, 4z² = 1 + 2 r33 − tr R; the
//                     largest is taken by its square root (never a small one: no cancellation,
//                     also at 180°), the other three from sums and differences of opposite
//                     off-diagonal entries divided by 4 × it. Then normalised (a slightly-off
//                     typed matrix) and signed so that w ≥ 0 (w = 0: the first non-zero of x, y,
//                     z positive); q and −q are the same rotation.
// A unit q = (cos θ/2, sin θ/2 â) is the right-handed turn by θ about â (counter-clockwise seen
// from the tip of â). Results read back as angle θ = 2 atan2(|v|, w) ∈ [0°, 360°] and axis
// v / |v| (none when v = 0). Column vectors, matrices as rows at the interface.
#pragma once

#include <array>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct Quaternion {
    static constexpr double kRotationTolerance = 1e-3;  // from_matrix: RᵀR ≈ I, det R ≈ 1

    enum class Op : std::uint8_t {
        Multiply,
        Conjugate,
        Inverse,
        Rotate,
        FromAxisAngle,
        ToMatrix,
        FromMatrix
    };
    static const char* op_name(Op op);  // "multiply", "from_axis_angle", ...

    struct Input {
        Op op = Op::Multiply;
        glm::dquat q1{1, 0, 0, 0}, q2{1, 0, 0, 0};  // multiply: [w, x, y, z], any
        glm::dquat q{1, 0, 0, 0};   // conjugate (any), inverse, rotate, to_matrix (≠ 0)
        glm::dvec3 point{1, 0, 0};  // rotate: P
        glm::dvec3 axis{0, 0, 1};   // from_axis_angle: a, any length ≠ 0
        double angle_deg = 90;      // from_axis_angle: θ, degrees
        glm::dmat3 matrix{1.0};     // from_matrix: R (glm: m[column][row])
        bool operator==(const Input&) const = default;
    };

    struct Result {
        Op op = Op::Multiply;
        glm::dquat q{1, 0, 0, 0};  // q1 q2; q̄; q⁻¹; the unit q (rotate, to_matrix); the q built
        std::optional<glm::dquat> q2q1;    // multiply
        std::optional<bool> commute;       // multiply: q1 q2 = q2 q1
        std::optional<double> norm;        // |q| of the input (multiply: |q1 q2| = |q1| |q2|)
        std::optional<glm::dvec3> point;   // rotate: P′
        std::optional<glm::dmat3> matrix;  // to_matrix
        std::optional<double> angle_deg;   // the turn of the unit q: 2 atan2(|v|, w) ∈ [0, 360]
        std::optional<glm::dvec3> axis;    // ... about v / |v| (none when v = 0)
        bool operator==(const Result&) const = default;
    };

    // One phase per teachable step; each op walks its own subsequence (see quaternion.cpp).
    enum class Phase : std::uint8_t {
        ScalarPart,      // multiply: s1 s2, v1 · v2
        VectorPart,      // multiply: s1 v2, s2 v1, v1 × v2
        Product,         // multiply: the sum, q1 q2
        Reverse,         // multiply: q2 q1
        Compare,         // multiply: commute or differ
        Conjugate,       // conjugate, inverse
        Norm,            // conjugate, inverse: q q̄ = (|q|², 0)
        Invert,          // inverse: q̄ / |q|²
        CheckInverse,    // inverse: q q⁻¹ = (1, 0)
        Normalise,       // rotate, to_matrix
        QTimesP,         // rotate: q (0, P)
        TimesConjugate,  // rotate: (q (0, P)) q̄
        Image,           // rotate: P′, |P′| = |P|
        UnitAxis,        // from_axis_angle: â
        HalfAngle,       // from_axis_angle: cos θ/2, sin θ/2
        Build,           // from_axis_angle: q
        Terms,           // to_matrix: the products 2xy, 2wz, ...
        Matrix,          // to_matrix: M
        IsRotation,      // from_matrix: RᵀR, det R
        Candidates,      // from_matrix: 4w², 4x², 4y², 4z²
        Extract,         // from_matrix: the largest and the other three
        Sign,            // from_matrix: w ≥ 0
        CheckBack,       // from_matrix: M(q) against R
        Done
    };

    struct State {
        Shared<Input> in;  // shared by copies (core/shared.hpp)
        Phase phase = Phase::ScalarPart;
        Phase last = Phase::ScalarPart;
        // multiply
        double s1s2 = 0, v1v2 = 0;  // s1 s2 and v1 · v2
        glm::dvec3 s1v2{0}, s2v1{0}, cross{0};
        glm::dquat q2q1{1, 0, 0, 0};
        bool commute = false;
        // conjugate, inverse, rotate, to_matrix
        double norm = 0;  // |q| (multiply: |q1 q2|)
        glm::dquat conj{1, 0, 0, 0};
        glm::dquat check{1, 0, 0, 0};  // q q̄ or q q⁻¹
        glm::dquat unit{1, 0, 0, 0};   // q / |q|
        glm::dquat qp{0, 0, 0, 0};     // rotate: q (0, P)
        glm::dquat qpq{0, 0, 0, 0};    // rotate: q (0, P) q̄
        // from_axis_angle
        double axis_length = 0;
        glm::dvec3 axis_unit{0, 0, 1};
        double half_cos = 1, half_sin = 0;  // cos θ/2, sin θ/2
        // from_matrix
        glm::dmat3 rtr{1.0};  // RᵀR
        double orth_error = 0, det = 1;
        std::array<double, 4> four_sq{1, 0, 0, 0};  // 4w², 4x², 4y², 4z²
        int largest = 0;                            // 0 = w, 1 = x, 2 = y, 3 = z
        glm::dquat raw{1, 0, 0, 0};                 // before normalising
        bool negated = false;
        double residual = 0;  // max |M(q) − R|
        // the answer
        glm::dquat q{1, 0, 0, 0};  // the op's quaternion
        glm::dmat3 matrix{1.0};    // to_matrix: M; rotate: M(q) for the check
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static Phase first_phase(Op op);  // where a run of `op` starts
    static void validate(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // start() for an input already validated
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The operation as one straight-line function, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces, for the tests and for other algorithms.
    static double length(const glm::dquat& q);       // √(w² + x² + y² + z²) without overflow
    static glm::dquat inverse(const glm::dquat& q);  // q̄ / |q|², q ≠ 0
    static glm::dquat from_matrix(const glm::dmat3& r);  // Shepperd, normalised, w ≥ 0
    // The turn of unit q: angle in degrees [0, 360] and the axis (none when v = 0).
    static double angle_deg_of(const glm::dquat& q);
    static std::optional<glm::dvec3> axis_of(const glm::dquat& q);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
