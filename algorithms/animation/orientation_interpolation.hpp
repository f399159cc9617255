// Orientation interpolation: key orientations of an animation, in-betweened four ways
//
// The course (animation, "Orientation and Interpolation"): interpolate the angles, not the
// transformation matrix; Euler angles are easy but the order of the axes matters and they lock;
// unit quaternions are interpolated by slerp,
//   ω = acos(q1 · q2),   q(u) = (q1 sin((1 − u) ω) + q2 sin(u ω)) / sin ω,   u ∈ [0, 1],
// which "gives better results than interpolation of Euler angles". Here two or more keys
// (each given as Euler angles in the run's order, as an axis and an angle, or as a quaternion
// [w, x, y, z]) are in-betweened frame by frame by four methods at once:
//   Euler    e(u) = (1 − u) e_i + u e_{i+1} angle by angle, R = R_c(e3) R_b(e2) R_a(e1) for the
//            order "abc" (see transforms/rotation_common.hpp): uneven speed, detours, gimbal lock.
//   matrix   M(u) = (1 − u) M_i + u M_{i+1} entry by entry: not a rotation in between; its
//            det M (= cos²(θ/2) half way through a turn θ) and orthogonality error
//            max |MᵀM − I| are reported — the object shrinks and shears.
//   slerp    between consecutive keys, after choosing the sign of q_{i+1} (q and −q are the same
//            rotation) so that q_i · q_{i+1} ≥ 0: the shorter arc. Constant angular speed 2ω per
//            segment time within a segment (transforms/slerp.hpp computes it).
//   squad    (Shoemake) through all the keys with continuous angular velocity:
//            s_i = q_i exp(−(log(q_i⁻¹ q_{i+1}) + log(q_i⁻¹ q_{i−1})) / 4), s_0 = q_0, s_n = q_n,
//            q(u) = slerp(slerp(q_i, q_{i+1}, u), slerp(s_i, s_{i+1}, u), 2u(1 − u)), these
//            slerps along the arc as given (a (a⁻¹b)^t, no sign choice, as Shoemake and GLM: the
//            short-way choice would make the curve jump where the inner points are 90° apart
//            in 4D). With two keys it is the same as slerp.
// The time between keys is `segment_time` seconds, split into `frames` frames; the angular
// speed of a method at frame k is the angle of the turn from frame k − 1 to frame k divided by
// dt (degrees per second).
//
// Steps: key ×n (each key's quaternion, matrix and Euler angles), align or flip ×(n − 1) (the
// sign of q_{i+1}, ω_i), tangents (squad's s_i, three keys or more), frame ×(frames·(n − 1) + 1)
// (one frame of animation: the clock `t` advances by dt), summary.
// Refused: fewer than 2 or more than kMaxKeys keys, a key with no form or two, non-finite
// numbers, angles above 3600° in size, a zero axis or quaternion, an unknown order, frames
// outside 1..kMaxFrames or more than kMaxTotalFrames in all, segment_time ≤ 0 or above 10⁴.
#pragma once

#include <array>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct OrientationInterpolation {
    static constexpr int kMaxKeys = 32;
    static constexpr int kMaxFrames = 240;         // per segment
    static constexpr int kMaxTotalFrames = 4000;   // frames · segments
    static constexpr double kMaxAngleDeg = 3600;   // Euler and axis-angle angles, in size
    static constexpr double kMaxSegmentTime = 1e4; // seconds

    enum class Form : std::uint8_t { Euler, AxisAngle, Quaternion };

    struct Key {
        Form form = Form::Quaternion;
        glm::dvec3 euler_deg{0, 0, 0};  // Euler: θ1, θ2, θ3 in the run's order, degrees
        glm::dvec3 axis{0, 0, 1};       // AxisAngle: any length ≠ 0
        double angle_deg = 0;           // AxisAngle: degrees
        glm::dquat q{1, 0, 0, 0};       // Quaternion: [w, x, y, z], any length ≠ 0
        bool operator==(const Key&) const = default;
    };

    struct Input {
        std::vector<Key> keys;
        std::string order = "xyz";  // the Euler order: the axes in the order the rolls apply
        int frames = 8;             // frames per segment (between two keys)
        double segment_time = 1;    // seconds from one key to the next
        bool operator==(const Input&) const = default;
    };

    // What the keys become before any frame: shared by the state machine and compute().
    struct Prepared {
        std::vector<glm::dquat> q;          // unit, signs aligned: q_i · q_{i+1} ≥ 0
        std::vector<glm::dmat3> m;          // the keys as matrices
        std::vector<glm::dvec3> e;          // ... and as Euler angles in the order (degrees)
        std::vector<glm::dquat> s;          // squad's inner control points
        std::vector<double> cos_omega;      // per segment, after the sign choice
        std::vector<double> omega_deg;      // per segment: acos(q_i · q_{i+1})
        std::vector<char> flipped;          // per segment: q_{i+1} was negated
        bool operator==(const Prepared&) const = default;
    };

    // One frame of the animation, by the four methods.
    struct Frame {
        double t = 0;
        int segment = 0;
        double u = 0;
        glm::dvec3 euler_deg{0, 0, 0};  // the lerped Euler angles
        glm::dquat euler_q{1, 0, 0, 0}; // ... as a unit quaternion (w ≥ 0)
        glm::dmat3 matrix{1.0};         // the lerped matrix
        double det = 1, orth_error = 0; // det M and max |MᵀM − I|
        glm::dquat slerp{1, 0, 0, 0}, squad{1, 0, 0, 0};
        // degrees per second from the frame before (0 at frame 0)
        double speed_euler = 0, speed_slerp = 0, speed_squad = 0;
        bool operator==(const Frame&) const = default;
    };

    struct Result {
        Prepared keys;
        std::vector<Frame> frames;
        double dt = 0;
        double min_det = 1, max_orth_error = 0;
        std::array<double, 3> speed_min{0, 0, 0}, speed_max{0, 0, 0};  // Euler, slerp, squad
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Key, Align, Tangents, Frame, Summary, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Key;
        Phase last = Phase::Key;
        int i = -1;  // the key, segment or frame handled last (its index)
        Prepared p;
        std::vector<Frame> frames;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> validated);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);  // run_to_end's spent state: its lists moved out
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.frames) + heap_bytes(s.p.q) + heap_bytes(s.p.m) + heap_bytes(s.p.e) +
               heap_bytes(s.p.s);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use.
    static int segments(const Input& in) { return int(in.keys.size()) - 1; }
    static int frame_count(const Input& in) { return segments(in) * in.frames + 1; }
    // Key i as a unit quaternion, a matrix and Euler angles in `order` (an Euler key keeps its
    // own angles, unwrapped: 350° stays 350°).
    static void key_forms(const Key& k, const std::string& order, glm::dquat& q, glm::dmat3& m,
                          glm::dvec3& e);
    // The Euler angles (degrees, in `order`) of a rotation matrix: θ2 ∈ [−90, 90], θ1 = 0 at
    // gimbal lock. Relabels the axes so that `order` reads "xyz", then rot::euler_xyz_of.
    static glm::dvec3 euler_of(const std::string& order, const glm::dmat3& m);
    static void align(Prepared& p, int segment);  // the sign of q_{segment+1}, ω
    static void tangents(Prepared& p);            // squad's s_i
    // Unit-quaternion log and exp: log(cos θ, sin θ v̂) = θ v̂ (a pure quaternion), and back.
    static glm::dvec3 log_unit(const glm::dquat& q);
    static glm::dquat exp_pure(glm::dvec3 v);
    // The turn from a to b in degrees, [0, 180] (q and −q alike).
    static double turn_deg(const glm::dquat& a, const glm::dquat& b);
    // Frame k (0 … frame_count − 1); `prev` is frame k − 1 (for the speeds), or null.
    static Frame frame(const Input& in, const Prepared& p, int k, const Frame* prev);
    static const char* form_name(Form f);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
