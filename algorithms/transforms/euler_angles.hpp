// Euler angles: an orientation as three rolls about the coordinate axes, and gimbal lock.
//
// The input names the order of the rolls, "xyz", "xzy", "yxz", "yzx", "zxy" or "zyx", and
// three angles (θ1, θ2, θ3) in the order of its letters. The letters say which roll is applied
// FIRST: "xyz" rolls about x by θ1, then about y by θ2, then about z by θ3, each about the fixed
// world axes. With column vectors the matrix applied first stands on the right:
//     order "abc":  R = R_c(θ3) R_b(θ2) R_a(θ1)      ("xyz": R = R_z(θ3) R_y(θ2) R_x(θ1)).
// (Read from the left the same product is the rolls about the body's own, moving axes in the
// reverse order c, b', a'' — the gimbal picture: c is the outer ring, a the inner one.)
// In GLM's naming the product is glm::eulerAngleCBA(θ3, θ2, θ1).
//
// Gimbal lock: when the middle angle is ±90° (cos θ2 = 0), R_b(θ2) turns axis a onto ±c, so
// R_b(θ2) R_a(θ1) = R_c(±θ1) R_b(θ2) and R = R_c(θ3 ± θ1) R_b(θ2): the first and last rolls
// turn about the same line and only θ3 + sθ1 (s = ±1) matters. One degree of freedom is lost —
// no small change of the three angles turns the object about the third direction. The run
// shows it by changing θ1 by +30° and θ3 by −s·30° and getting the same matrix (and, away
// from the lock, a different one).
//
// Steps: roll ×3 (each matrix and the product so far), compose, then gimbal-lock or no-lock.
#pragma once

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "transforms/rotation_common.hpp"

namespace cg {

struct EulerAngles {
    static constexpr double kLockCos = 1e-12;  // |cos θ2| below this counts as locked
    static constexpr double kDemoDeg = 30;     // the change of θ1 and θ3 in the lock demo

    struct Input {
        std::string order = "xyz";       // the axes in the order the rolls are applied
        glm::dvec3 angles_deg{0, 0, 0};  // θ1, θ2, θ3 for the letters of `order`, degrees
        bool operator==(const Input&) const = default;
    };
    struct Result {
        glm::dmat3 matrix{1.0};
        bool gimbal_lock = false;
        int lock_sign = 0;          // s when locked (R depends on θ3 + sθ1 only), else 0
        double lock_angle_deg = 0;  // θ3 + sθ1, wrapped to (−180, 180], when locked
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Roll, Compose, Gimbal, Done };

    struct State {
        Input in;
        Phase phase = Phase::Roll;
        Phase last = Phase::Roll;
        int k = -1;         // the roll applied last (0, 1, 2)
        glm::dmat3 R{1.0};  // the rolls applied so far, multiplied (all three: R)
        bool lock = false;
        int sign = 0;
        double cos_mid = 1;  // cos θ2
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

    // The matrix and the lock test as one straight-line function, for the benchmark.
    static Result compose(const Input& in);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
