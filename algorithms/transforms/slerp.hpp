// Unit quaternions as rotations, and spherical linear interpolation (slerp) between two
// orientations, beside the two naive alternatives.
//
// A quaternion q = (s, v) = s + v_x i + v_y j + v_z k, written [w, x, y, z] with w = s. The
// course's algebra: q1 q2 = (s1 s2 − v1 · v2, s1 v2 + s2 v1 + v1 × v2), conjugate q̄ = (s, −v),
// |q| = √(s² + |v|²). A unit quaternion q = (cos θ/2, sin θ/2 v̂) is the rotation by θ about v̂
// (right-handed, counter-clockwise seen from the tip of v̂): a point P, as the pure quaternion
// (0, P), goes to q (0, P) q̄ (q̄ = q⁻¹ for unit q). q and −q are the same rotation.
//
// Slerp (Shoemake), for u ∈ [0, 1]:
//   cos ω = q0 · q1 (the 4D dot product; if it is negative, q1 ← −q1 so the path is the
//   short way round — the same end orientation, half the turning);
//   q(u) = (sin((1 − u) ω) q0 + sin(u ω) q1) / sin ω.
// ω is computed as 2 atan2(|q0 − q1|, |q0 + q1|), which equals arccos(q0 · q1) but keeps its
// accuracy when the two are nearly equal (arccos near 1 loses half the digits). When
// sin ω < 1e-6 (nearly equal, or after the flip nearly opposite: the same orientation) the
// formula is 0/0 in the limit, so the normalised linear blend (1 − u) q0 + u q1 is used instead;
// the two differ by O(ω³), far below 1e-15 there. u outside [0, 1] is refused: slerp
// interpolates between two keys; extrapolating past them is not part of the method.
//
// Steps: normalise (both inputs to unit length, each as an angle and axis), dot (cos ω and the
// relative rotation q1 q̄0) or flip, angle (ω and the two weights) or nearly-equal (the
// fallback), blend (q(u)), rotate-point (q (0, x̂) q̄ worked as two products), matrix (q as
// a 3×3 rotation matrix), then sample ×9 (u = 0, 1/8, …, 1): where the rotated x axis's tip is
// under slerp, under a linear blend of the two matrices (not a rotation: the tip leaves the
// sphere) and under a linear blend of the Euler angles (order "xyz", see rotation_common.hpp).
#pragma once

#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "transforms/rotation_common.hpp"

namespace cg {

struct Slerp {
    static constexpr double kFallbackSin = 1e-6;  // below this sin ω: normalised linear blend
    static constexpr int kSamples = 9;            // u = 0, 1/8, …, 1 for the paths

    // How the in-between orientation at u is made: slerp, or for comparison one of the naive
    // blends (the same as the sampled paths): the two matrices lerped entry by entry (no
    // rotation in between), or the two sets of Euler angles (order xyz) lerped.
    enum class Method : std::uint8_t { Slerp, MatrixLerp, EulerLerp };

    struct Input {
        glm::dquat q0{1, 0, 0, 0};  // [w, x, y, z], any length ≠ 0
        glm::dquat q1{1, 0, 0, 0};
        double u = 0.5;  // in [0, 1]
        Method method = Method::Slerp;
        bool operator==(const Input&) const = default;
    };
    struct Result {
        glm::dquat q{1, 0, 0, 0};  // the unit quaternion at u
        double omega_deg = 0;      // ω after the flip, [0, 90]
        glm::dmat3 matrix{1.0};    // q as a rotation matrix (with another method: its blend at u)
        bool flipped = false;      // q1 was negated (q0 · q1 < 0)
        bool fallback = false;     // normalised linear blend (sin ω tiny)
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        Normalise,
        Dot,
        Angle,
        Blend,
        RotatePoint,
        Matrix,
        Sample,
        Done
    };

    struct State {
        Input in;
        Phase phase = Phase::Normalise;
        Phase last = Phase::Normalise;
        double norm0 = 1, norm1 = 1;
        glm::dquat q0{1, 0, 0, 0}, q1{1, 0, 0, 0};       // unit; q1 after the flip
        glm::dquat relative{1, 0, 0, 0};                 // q1 q̄0
        double cos_omega = 1, omega = 0, sin_omega = 0;  // ω in radians
        bool flipped = false, fallback = false;
        double w0 = 1, w1 = 0;  // the weights of q0 and q1
        glm::dquat q{1, 0, 0, 0};
        glm::dquat qp{0, 0, 0, 0}, qpq{0, 1, 0, 0};  // q (0, x̂) and q (0, x̂) q̄
        glm::dmat3 matrix{1.0};
        glm::dmat3 m0{1.0}, m1{1.0};  // the two orientations as matrices (for the paths)
        glm::dvec3 e0{0}, e1{0};      // ... and as Euler angles (order xyz, degrees)
        int k = -1;                   // the sample taken last
        std::vector<glm::dvec3> tip_slerp, tip_matrix, tip_euler;  // x-axis tips per sample
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // Slerp and its matrix as one straight-line function (no paths), for the benchmark.
    static Result interpolate(const Input& in);

    // The course's quaternion algebra, written out (the tests compare it with GLM's).
    static glm::dquat product(const glm::dquat& a, const glm::dquat& b);
    static glm::dquat conjugate(const glm::dquat& q) { return {q.w, -q.x, -q.y, -q.z}; }
    static glm::dmat3 to_matrix(const glm::dquat& q);  // unit q

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
