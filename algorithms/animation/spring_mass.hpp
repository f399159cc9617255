// Spring-mass systems: point masses joined by damped springs, moved by Newton's law
//
// The course (physically-based animation): "a mesh of point masses connected with springs;
// compute the motion according to differential equations". Here the equations are
//
//   x_i' = v_i,   m_i v_i' = F_i = m_i g − drag v_i + Σ_springs (Hooke + damping)
//
// and for a spring (i, j) with stiffness k, rest length L and damping c, d = x_i − x_j,
// d̂ = d/|d|, the force on mass i (mass j gets its negative, so internal forces sum to zero):
//
//   Hooke    F_s = −k (|d| − L) d̂          damping  F_d = −c ((v_i − v_j)·d̂) d̂
//
// A spring whose ends coincide (|d| = 0) has no direction: it exerts no force at that instant
// (both terms are taken as 0), so no NaN appears; its energy ½kL² is still counted.
// Pinned masses never move (their v stays 0; the springs still pull on them).
//
// One step advances the whole system by dt with the chosen integrator, a(x, v) = F/m:
//   explicit Euler     x ← x + dt v,            v ← v + dt a(x, v)      (both from the old state)
//   symplectic Euler   v ← v + dt a(x, v),      x ← x + dt v_new        (semi-implicit)
//   RK4                k1 = f(y), k2 = f(y + dt/2 k1), k3 = f(y + dt/2 k2), k4 = f(y + dt k3),
//                      y ← y + dt/6 (k1 + 2k2 + 2k3 + k4),  y = (x, v), f = (v, a)
// The energies after each step: kinetic Σ ½ m v², spring Σ ½ k (|d| − L)², gravitational
// −Σ m g·x over the free masses (height measured from the origin). Undamped, without drag,
// the total is conserved by the motion; explicit Euler gains energy every step (by the factor
// 1 + ω²dt² for one undamped spring), symplectic Euler's error stays bounded, RK4's is O(dt⁴).
//
// Blow-up: a step whose new state is not finite, or whose total energy exceeds 1e12 times the
// energy scale E_scale = max(|E_0|, K_0 + S_0 + |G_0|) (1 when that is 0), is not taken: the
// run stops there with a "blow-up" step and keeps the last finite state, so no NaN is reported.
//
// Positions are 3D (x right, y up, z toward the viewer); [x, y] in the input means z = 0.
// Refused: no masses, more than kMaxMasses masses or kMaxSprings springs, a mass ≤ 0 or not
// finite, coordinates or velocities above 1e6 in size, a spring from a mass to itself or to a
// mass out of range, k, c or L negative or not finite, dt ≤ 0 or not finite, steps outside
// 1..kMaxSteps or steps × (masses + springs) above kMaxWork, a watched mass out of range,
// a velocity on a pinned mass, drag < 0.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct SpringMass {
    static constexpr int kMaxMasses = 1024;
    static constexpr int kMaxSprings = 4096;
    static constexpr int kMaxSteps = 100000;
    static constexpr long long kMaxWork = 20000000;  // steps × (masses + springs)
    static constexpr double kMaxCoordinate = 1e6;
    static constexpr double kMaxMass = 1e12;
    static constexpr double kMaxStiffness = 1e12;
    static constexpr double kBlowUp = 1e12;  // energy above kBlowUp × E_scale: blown up

    enum class Integrator : std::uint8_t { ExplicitEuler, SymplecticEuler, RK4 };

    struct Mass {
        glm::dvec3 position{0, 0, 0};
        glm::dvec3 velocity{0, 0, 0};
        double mass = 1;
        bool pinned = false;
        bool operator==(const Mass&) const = default;
    };
    struct Spring {
        int i = 0, j = 1;
        double stiffness = 1;   // k, force per unit of stretch
        double rest = 0;        // L (resolved at the start when not given)
        bool has_rest = false;  // false: L is the initial distance |x_i − x_j|
        double damping = 0;     // c, force per unit of relative speed along the spring
        bool operator==(const Spring&) const = default;
    };

    struct Input {
        std::vector<Mass> masses;
        std::vector<Spring> springs;
        glm::dvec3 gravity{0, -9.81, 0};
        double drag = 0;  // global: F = −drag v on every mass
        double dt = 0.01;
        int steps = 200;
        Integrator integrator = Integrator::SymplecticEuler;
        int watch = -1;  // the mass narrated and drawn in detail (−1: the first free one)
        bool operator==(const Input&) const = default;
    };

    // Buffers a step works in: not part of the state's value (copies start empty, == ignores).
    struct Scratch {
        std::vector<glm::dvec3> nx, nv;                 // the new state
        std::vector<glm::dvec3> x, v, a, kx[4], kv[4];  // stages
        Scratch() = default;
        Scratch(const Scratch&) {}
        Scratch& operator=(const Scratch&) { return *this; }
        bool operator==(const Scratch&) const { return true; }
    };

    struct Energy {
        double kinetic = 0, spring = 0, gravity = 0;
        double total() const { return kinetic + spring + gravity; }
        bool operator==(const Energy&) const = default;
    };

    struct Result {
        double dt = 0;
        int steps = 0;  // time steps taken
        double t = 0;
        std::vector<glm::dvec3> positions, velocities;
        glm::dvec3 x{0, 0, 0}, v{0, 0, 0};  // the watched mass
        std::vector<double> energy;         // total energy after 0, 1, …, steps steps
        Energy final_energy;
        double energy_scale = 1;
        double max_drift = 0;  // max |E_k − E_0| / E_scale
        bool blew_up = false;
        int blow_up_step = -1;  // the step refused (−1: none)
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Step, BlowUp, Summary, Done };

    struct State {
        Shared<Input> in;  // rest lengths resolved, watch resolved
        Phase phase = Phase::Step;
        Phase last = Phase::Step;
        int k = 0;  // time steps taken
        std::vector<glm::dvec3> x, v;
        glm::dvec3 force{0, 0, 0};  // on the watched mass at the start of the last step
        Energy energy;
        double energy_scale = 1;
        std::vector<double> history;   // total energy after every step
        std::vector<glm::dvec3> path;  // the watched mass after every step
        double max_drift = 0;
        bool blew_up = false;
        bool not_finite = false;  // the refused step was not finite (else: energy too high)
        double refused_energy = 0;
        Scratch scratch;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static Input resolve(const Input& in);  // validates; fills rest lengths and watch
    static State start(const Input& in);    // resolve(), then begin()
    static State begin(Shared<Input> resolved);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.x) + heap_bytes(s.v) + heap_bytes(s.history) + heap_bytes(s.path);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields() { return {"x", "v"}; }

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use (on a resolved input).
    // The force on every mass at (x, v); pinned masses get their force too.
    static void forces(const Input& in, const std::vector<glm::dvec3>& x,
                       const std::vector<glm::dvec3>& v, std::vector<glm::dvec3>& f);
    // The force of spring s on its mass i (mass j gets the negative): Hooke and damping apart.
    static void spring_force(const Spring& s, glm::dvec3 xi, glm::dvec3 xj, glm::dvec3 vi,
                             glm::dvec3 vj, glm::dvec3& hooke, glm::dvec3& damping);
    static Energy energy(const Input& in, const std::vector<glm::dvec3>& x,
                         const std::vector<glm::dvec3>& v);
    static double energy_scale(const Energy& e0);
    // One time step from (x, v) into (x1, v1); returns the force on `watch` at the start.
    static glm::dvec3 advance(const Input& in, const std::vector<glm::dvec3>& x,
                              const std::vector<glm::dvec3>& v, std::vector<glm::dvec3>& x1,
                              std::vector<glm::dvec3>& v1, Scratch& w);
    // Whether a new state is refused: not finite, or its energy above kBlowUp × scale.
    static bool blows_up(const std::vector<glm::dvec3>& x, const std::vector<glm::dvec3>& v,
                         const Energy& e, double scale);
    static const char* integrator_name(Integrator i);

  private:
    static void take_step(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
