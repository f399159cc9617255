// Boids: Reynolds' flocking in 2D, every boid steered by local rules only
//
// The course (animation, flocking): the members of a flock move semi-independently, each aware
// only of itself and a few neighbours, with no leader; they avoid collisions with obstacles and
// one another and try to stay with the flock ("flock centering"). Reynolds' three rules give
// exactly that. For boid i at x_i with velocity v_i, with d_j = x_j − x_i (the shortest way
// round in a wrapped world), its neighbours are
//
//   N_i = { j ≠ i : |d_j| < r, and d_j within ±fov/2 of v_i }   (all round when v_i = 0)
//
//   separation  s = Σ_{j ∈ N_i, |d_j| < r_sep} −d̂_j / max(|d_j|, ε)   (away, weighted 1/distance)
//   alignment   a = (1/|N_i|) Σ v_j − v_i                           (toward the mean velocity)
//   cohesion    c = (1/|N_i|) Σ d_j  = centre of N_i − x_i          (flock centering)
//   avoidance   o = Σ_{obstacles seen} n̂ / max(|x_i − c_o| − R_o, ε)  (seen: that gap < r)
//   bounds      b = per axis, (depth into the margin band)/margin, pointing inward (steer only)
//
//   F = w_s s + w_a a + w_c c + w_o o + w_b b, truncated to |F| ≤ max_force
//   v_i' = v_i + dt F with its speed clamped to [min_speed, max_speed],  x_i' = x_i + dt v_i'
//
// with ε = max(10⁻³ r, 10⁻⁶) so that a push stays finite. Every boid is updated from the SAME
// previous state (x, v) into new buffers (x', v'), which then replace it: updating in place would
// let boid 5 see boid 3's new position, and the result would depend on the order of the list.
//
// Coincident boids (d_j = 0) have no direction between them: the push is along their relative
// velocity v_i − v_j (so the two are pushed apart, each the opposite way), with the largest
// weight 1/ε; when their velocities are equal too, nothing can tell them apart without using
// their order in the list, so they exert no separation on each other. A boid with v = 0 sees all
// round; one at an obstacle's centre is pushed against its velocity (or along +x when still).
//
// Order of the flock, after every step: the polarisation φ = |(1/n) Σ v̂_i| (1: all fly the same
// way, near 0: no common heading; a still boid counts as 0) and the mean distance from each boid
// to its nearest neighbour (0 for a single boid).
//
// A boid or an obstacle given outside a wrapped world is taken round into it; a start faster
// than max_speed is scaled down to it; r_sep above r acts as r (only neighbours are pushed).
// Refused: no boids, more than kMaxBoids boids or kMaxObstacles obstacles, coordinates not
// finite or above 1e6 in size, r or r_sep negative or above 1e6, fov outside [0, 360] degrees,
// weights, speeds or max_force negative or above 1e6, min_speed above max_speed, dt outside
// (0, 10], steps outside 1..kMaxSteps or steps × boids² above kMaxWork, a world with max ≤ min,
// a wrapped world narrower than 2r, a margin outside [1e-6, 1e6], an obstacle radius ≤ 0, the
// focus out of range, both boids and a random flock, a random flock of 0 or more than kMaxBoids.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct Boids {
    static constexpr int kMaxBoids = 1000;
    static constexpr int kMaxObstacles = 64;
    static constexpr int kMaxSteps = 100000;
    static constexpr long long kMaxWork = 50000000;  // steps × boids²
    static constexpr double kMaxCoordinate = 1e6;
    static constexpr double kMaxValue = 1e6;  // weights, speeds, max_force

    enum class Edges : std::uint8_t { Wrap, Steer };

    struct Boid {
        glm::dvec2 position{0, 0};
        glm::dvec2 velocity{0, 0};
        bool operator==(const Boid&) const = default;
    };
    struct Obstacle {
        glm::dvec2 center{0, 0};
        double radius = 1;
        bool operator==(const Obstacle&) const = default;
    };
    struct Weights {
        double separation = 1.5, alignment = 1, cohesion = 1, avoidance = 2, bounds = 2;
        bool operator==(const Weights&) const = default;
    };
    // A random start: `count` boids uniform in the world (outside the obstacles), headings
    // uniform, speeds uniform in [max(min_speed, max_speed/2), max_speed], from `seed`.
    struct Random {
        int count = 0;  // 0: the boids are given
        std::uint64_t seed = 0;
        bool operator==(const Random&) const = default;
    };

    struct Input {
        std::vector<Boid> boids;
        Random random;
        glm::dvec2 world_min{-10, -10}, world_max{10, 10};
        Edges edges = Edges::Wrap;
        double margin = -1;  // steer: the band inside the edges that pushes back (−1: 1/10 side)
        std::vector<Obstacle> obstacles;
        double radius = 3;              // r, perception radius
        double separation_radius = -1;  // r_sep ≤ r (−1: r)
        double fov = 360;               // field of view, degrees
        Weights weights;
        double max_speed = 2, min_speed = 0, max_force = 4;
        double dt = 0.05;
        int steps = 200;
        int focus = 0;  // the boid narrated and drawn in detail
        // Set by resolve() when it has drawn the boids from `random` (then reset to count 0), so
        // that a resolved input resolves again to itself and the picture offers no handles on
        // boids the user's input does not list.
        bool generated = false;
        bool operator==(const Input&) const = default;
    };

    // One boid's rules at one state.
    struct Rules {
        glm::dvec2 separation{0, 0}, alignment{0, 0}, cohesion{0, 0}, avoidance{0, 0},
            bounds{0, 0};
        glm::dvec2 sum{0, 0};       // w_s s + w_a a + w_c c + w_o o + w_b b
        glm::dvec2 steering{0, 0};  // the sum truncated to max_force: F
        int neighbours = 0;         // |N_i|
        int close = 0;              // of them, closer than r_sep
        int obstacles = 0;          // obstacles seen
        bool operator==(const Rules&) const = default;
    };

    // Who one boid sees: the neighbours' indices and their offsets d_j = x_j − x_i.
    struct Seen {
        std::vector<int> ids;
        std::vector<glm::dvec2> offsets;
        void clear() { ids.clear(), offsets.clear(); }
        bool operator==(const Seen&) const = default;
    };

    // Buffers a step works in: not part of the state's value (copies start empty, == ignores).
    struct Scratch {
        std::vector<glm::dvec2> nx, nv;
        Scratch() = default;
        Scratch(const Scratch&) {}
        Scratch& operator=(const Scratch&) { return *this; }
        bool operator==(const Scratch&) const { return true; }
    };

    struct Result {
        double dt = 0;
        int steps = 0;
        double t = 0;
        std::vector<glm::dvec2> positions, velocities;  // final, every boid
        int focus = 0;
        Rules rules;                        // the focus boid's, in the last step
        glm::dvec2 x{0, 0}, v{0, 0};        // the focus boid at the end
        std::vector<double> polarisation;   // after 0, 1, …, steps steps
        std::vector<double> nearest;        // mean nearest-neighbour distance, likewise
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Step, Summary, Done };

    struct State {
        Shared<Input> in;  // resolved: boids generated, r_sep and margin filled
        Phase phase = Phase::Step;
        Phase last = Phase::Step;
        int k = 0;  // steps taken
        std::vector<glm::dvec2> x, v;
        Rules rules;                     // the focus boid's rules in the last step
        Seen seen;                       // its neighbours then
        glm::dvec2 x0{0, 0}, v0{0, 0};   // the focus boid before the last step
        std::vector<double> polarisation, nearest;
        Scratch scratch;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static Input resolve(const Input& in);  // validates; generates a random flock, fills defaults
    static State start(const Input& in);    // resolve(), then begin()
    static State begin(Shared<Input> resolved);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.x) + heap_bytes(s.v) + heap_bytes(s.seen.ids) + heap_bytes(s.seen.offsets) +
               heap_bytes(s.polarisation) + heap_bytes(s.nearest);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields() {
        return {"focus/separation", "focus/alignment", "focus/cohesion", "focus/v"};
    }

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use (on a resolved input).
    // x_j − x_i, the shortest way round in a wrapped world.
    static glm::dvec2 offset(const Input& in, glm::dvec2 from, glm::dvec2 to);
    // Boid i's rules at (x, v); who it sees appended to `seen` when given.
    static Rules rules(const Input& in, const std::vector<glm::dvec2>& x,
                       const std::vector<glm::dvec2>& v, std::size_t i, Seen* seen = nullptr);
    // One frame: every boid from (x, v) into (x1, v1); the focus boid's rules and neighbours.
    static void advance(const Input& in, const std::vector<glm::dvec2>& x,
                        const std::vector<glm::dvec2>& v, std::vector<glm::dvec2>& x1,
                        std::vector<glm::dvec2>& v1, Rules& focus_rules, Seen& focus_seen);
    static double polarisation(const std::vector<glm::dvec2>& v);
    static double mean_nearest(const Input& in, const std::vector<glm::dvec2>& x);
    // |w| ≤ cap: w scaled down when longer (exactly: the result's length never exceeds cap).
    static glm::dvec2 truncate(glm::dvec2 w, double cap);
    static double epsilon(const Input& in);  // ε = max(10⁻³ r, 10⁻⁶)
    static const char* edges_name(Edges e);

  private:
    static void take_step(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
