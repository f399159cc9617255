// Forward and inverse kinematics of a chain of links joined by hinge joints
//
// The course (kinematics): forward kinematics gives the positions of an articulated body from
// its joint angles; inverse kinematics derives the joint angles that put a key link (the end
// effector) where we want it. The chain: a base point p_0, links of lengths l_1..l_n, and at the
// start of each link a hinge joint turning by θ_i (degrees at the interface) about its axis a_i,
// given in the frame of the link before it (default z: a planar arm in the x-y plane). With
// Rot(a, θ) the rotation by θ about a, each link lying along its own x axis:
//
//   R_0 = I,   R_i = R_{i−1} Rot(a_i, θ_i),   p_i = p_{i−1} + R_i (l_i, 0, 0)      (FK)
//
// so the world axis of joint i is w_i = R_i a_i, and the end effector is p_n.
//
// Solvers (one step = one teachable piece of work):
//   forward     one link per step: R_i and p_i as above.
//   analytic    the planar two-link arm, by the law of cosines, d = |target − p_0|:
//                 cos θ_2 = (d² − l_1² − l_2²) / (2 l_1 l_2),   θ_2 = ±acos(·)
//                 θ_1 = atan2(t_y, t_x) − atan2(l_2 sin θ_2, l_1 + l_2 cos θ_2)
//               "elbow-up" is θ_2 ≤ 0 (the elbow on the left of base→target, above it when the
//               target is to the right), "elbow-down" θ_2 ≥ 0. Unreachable (d > l_1 + l_2 or
//               d < |l_1 − l_2|): the nearest reachable pose, stretched toward the target or
//               folded (θ_2 = 180°) with its end on the line to it. A target on the base with
//               l_1 = l_2 is reached by the folded arm at any θ_1; θ_1 = 0 is taken.
//   ccd         cyclic coordinate descent: from the last joint back to the first, joint j
//               turns so that u = p_n − p_j points at v = target − p_j, both projected onto
//               the plane ⊥ w_j:  Δθ_j = atan2(w_j·(u × v), u·v). One joint update a step;
//               an iteration is a full sweep over the n joints.
//   jacobian-transpose   J_i = ∂p_n/∂θ_i = w_i × (p_n − p_i) (per radian), e = target − p_n,
//               Δθ = α Jᵀe with α = (e·JJᵀe) / |JJᵀe|² (the step that minimises |e − J Δθ|
//               along Jᵀe). One iteration a step.
//   dls         damped least squares: Δθ = Jᵀ (J Jᵀ + λ² I)⁻¹ e = (JᵀJ + λ² I)⁻¹ Jᵀ e,
//               λ > 0 keeps the step bounded (|Δθ| ≤ |e| / 2λ) at a singularity.
// The iterative solvers stop when |e| ≤ tolerance (reached), when an iteration changes |e| by
// at most 10⁻¹⁴ × the chain's size (stalled: the best they can do, e.g. at an unreachable
// target), or after `iterations` iterations. Joint angles are kept in (−180°, 180°].
// Reachability: for a planar chain (every axis ±z, the target in the base's plane) the
// reachable set is the annulus r_min ≤ d ≤ Σl with r_min = max(0, 2 max l − Σl); in 3D only
// d ≤ Σl is checked (a necessary condition). No joint limits.
//
// Refused: no links or more than kMaxLinks, a length ≤ 0 or above 1e6 (a zero-length link has
// no direction), angles not finite or above 1e6 degrees in size, a zero or non-finite axis,
// a base or target not finite or above 1e6, a missing target (except for forward), analytic on
// anything but a planar two-link arm, λ ≤ 0 for dls, tolerance ≤ 0, iterations outside
// 1..kMaxIterations, more than kMaxSteps steps.
#pragma once

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct InverseKinematics {
    static constexpr int kMaxLinks = 32;
    static constexpr int kMaxIterations = 10000;
    static constexpr long long kMaxSteps = 200000;  // CCD: iterations × links
    static constexpr double kMaxCoordinate = 1e6;
    static constexpr double kMaxAngle = 1e6;  // degrees
    static constexpr double kStall = 1e-14;   // × the chain's size

    enum class Method : std::uint8_t { Forward, Analytic, CCD, JacobianTranspose, DLS };

    struct Input {
        std::vector<double> lengths;   // l_1..l_n, > 0
        std::vector<double> angles;    // θ_i in degrees: the start pose (default 0)
        std::vector<glm::dvec3> axes;  // a_i in the parent's frame (default z); unit at start
        glm::dvec3 base{0, 0, 0};      // p_0
        glm::dvec3 target{0, 0, 0};
        bool has_target = false;
        Method method = Method::CCD;
        bool elbow_up = true;     // analytic: which of the two poses is the result
        double damping = 0.2;     // λ for dls, a length
        int iterations = 100;     // at most (CCD: sweeps)
        double tolerance = 1e-9;  // |e| at which the target counts as reached
        bool operator==(const Input&) const = default;
    };

    // The two-link arm solved in closed form (angles in degrees).
    struct TwoLink {
        double d = 0;           // |target − base|
        double cos_theta2 = 0;  // before clamping
        bool reachable = false;
        double up[2] = {0, 0};    // θ_1, θ_2 with θ_2 ≤ 0
        double down[2] = {0, 0};  // θ_1, θ_2 with θ_2 ≥ 0
        bool operator==(const TwoLink&) const = default;
    };

    struct Result {
        Method method = Method::CCD;
        std::vector<double> angles;         // degrees, the final pose
        std::vector<glm::dvec3> positions;  // p_0..p_n
        glm::dvec3 end{0, 0, 0};            // p_n
        double error = 0;                   // |target − p_n| (0 without a target)
        bool reached = false;               // error ≤ tolerance
        bool reachable = false;             // see the header comment
        bool planar = false;
        int iterations = 0;          // Jacobian iterations or full CCD sweeps
        int updates = 0;             // steps of the solver (CCD: joint updates)
        std::vector<double> errors;  // |e| before the first and after every update
        std::string stop;            // reached, stalled, iterations, forward, analytic
        TwoLink two_link;            // analytic only
        int first_joint = -1;        // CCD: the first update's joint (0-based)
        double first_delta = 0;      // its Δθ in degrees
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        Link,      // forward: one link
        Distance,  // analytic
        Elbow,
        Shoulder,
        Update,  // ccd, jacobian: one update
        Summary,
        Done
    };

    struct State {
        Shared<Input> in;  // axes normalised
        Phase phase = Phase::Link;
        Phase last = Phase::Link;
        bool planar = false;
        double size = 1;               // max(Σl, |target − base|, 1e-300): the stall scale
        std::vector<double> theta;     // radians
        std::vector<glm::dvec3> p;     // p_0..p_n of the current pose
        std::vector<glm::dvec3> axes;  // w_1..w_n of the current pose (world)
        int links_done = 0;            // forward: p_0..p_links_done are known
        int k = 0;                     // updates taken
        int joint = -1;                // the joint of the last update (0-based)
        int iterations = 0;
        double error = 0;
        double sweep_start_error = 0;  // CCD: |e| when the sweep began
        std::vector<double> history;   // |e| after 0, 1, … updates
        TwoLink two_link;
        glm::dvec3 u{0}, v{0};       // CCD: p_n − p_j and target − p_j before the update
        glm::dvec3 w{0};             // CCD: the joint's world axis
        double delta = 0;            // CCD: Δθ_j (radians)
        std::vector<glm::dvec3> J;   // Jacobian columns before the last update
        glm::dvec3 e{0};             // the error vector before the last update
        std::vector<double> dtheta;  // Jacobian: Δθ (radians)
        double alpha = 0;            // jacobian-transpose: the step length
        std::string stop;
        int first_joint = -1;
        double first_delta = 0;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static Input resolve(const Input& in);  // validates; normalises the axes, fills defaults
    static State start(const Input& in);    // resolve(), then begin()
    static State begin(Shared<Input> resolved);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.theta) + heap_bytes(s.p) + heap_bytes(s.axes) + heap_bytes(s.history) +
               heap_bytes(s.J) + heap_bytes(s.dtheta);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use (on a resolved input; angles in radians).
    // p_0..p_n, and the world axes w_1..w_n when asked.
    static void forward(const Input& in, const std::vector<double>& theta,
                        std::vector<glm::dvec3>& p, std::vector<glm::dvec3>* w = nullptr);
    // J's columns w_i × (p_n − p_i).
    static void jacobian(const std::vector<glm::dvec3>& w, const std::vector<glm::dvec3>& p,
                         std::vector<glm::dvec3>& J);
    // Δθ = α Jᵀe (returns α; 0 when JJᵀe = 0).
    static double transpose_step(const std::vector<glm::dvec3>& J, glm::dvec3 e,
                                 std::vector<double>& dtheta);
    // Δθ = Jᵀ (JJᵀ + λ²I)⁻¹ e.
    static void dls_step(const std::vector<glm::dvec3>& J, glm::dvec3 e, double lambda,
                         std::vector<double>& dtheta);
    // CCD's turn of a joint at `pivot` about the unit axis w: end toward target (radians).
    static double ccd_delta(glm::dvec3 w, glm::dvec3 pivot, glm::dvec3 end, glm::dvec3 target,
                            glm::dvec3* u = nullptr, glm::dvec3* v = nullptr);
    static TwoLink two_link(double l1, double l2, double tx, double ty);
    static bool is_planar(const Input& in);
    static bool reachable(const Input& in);
    static double wrap(double radians);  // into (−π, π]
    static const char* method_name(Method m);

  private:
    static void take_step(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
