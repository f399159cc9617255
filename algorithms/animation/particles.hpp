// Particle systems: many small points, each born, moved by forces, bounced and killed
//
// The course (physically-based animation): simulate Newton's laws and steer objects through
// forces; a particle system is the case with no connections at all — each particle only has a
// position x, a velocity v, an age and a lifetime. One step is one frame of dt seconds:
//
//   t ← t + dt;  kill every particle whose age t − t_birth has reached its lifetime
//   a = g − c v                (gravity and linear drag, per unit mass)
//   v ← v + dt a,  x ← x + dt v          (semi-implicit Euler: the new v moves x)
//   if d = n·x − h < 0 (below the plane n·x = h):
//       x ← x − (1 + e) d n               (reflected at the plane, e of the overshoot kept)
//       v ← −e v_n + (1 − μ) v_t          (v_n = (v·n) n, v_t = v − v_n; only when v·n < 0)
//   N(t) = ⌊rate · t⌋ particles emitted by time t (exactly: t = k·dt is not rounded), so
//   N(t_k) − N(t_{k−1}) are born this frame, at age 0, at the emitter
//
// The emitter: a point, a disc (perpendicular to the mean velocity) or a line segment; each
// particle's velocity lies in the cone of half-angle `spread` around the mean velocity (uniform
// over the cap), its speed is |v̄| (1 + jitter u), u ∈ [−1, 1), its lifetime uniform in
// [life_min, life_max]. Every random number comes from one seeded generator in the state, in
// emission order, so the same seed gives the same particles bit for bit.
//
// Invariants: after every frame no particle is below the plane (the reflection is checked and,
// for the rare rounding case, nudged up); a bounce never speeds a particle up (e, μ in [0, 1]).
// Refused: dt ≤ 0, a rate < 0, lifetimes < 0 or min > max, a spread outside [0°, 180°], drag
// with c·dt > 1, a zero plane normal, e or μ outside [0, 1], an emitter below the plane, too
// many particles or too much work (see the limits below).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct Particles {
    static constexpr int kMaxFrames = 100000;
    static constexpr long long kMaxEmitted = 100000;  // particles the emitter may make in a run
    static constexpr int kMaxStart = 1000;            // particles given at the start
    static constexpr long long kMaxWork = 20000000;   // frames × the most alive at once
    static constexpr double kMaxCoordinate = 1e6;
    static constexpr double kMinDt = 1e-6;
    static constexpr double kMaxLifetime = 1e6;
    static constexpr double kForever = std::numeric_limits<double>::infinity();

    enum class Shape : std::uint8_t { Point, Disc, Line };

    struct Emitter {
        Shape shape = Shape::Point;
        glm::dvec3 position{0, 0, 0};       // the point, the disc's centre or the line's start
        glm::dvec3 end{1, 0, 0};            // the line's end
        double radius = 0.5;                // the disc's radius
        glm::dvec3 velocity{0, 5, 0};       // v̄: the cone's axis, its length the mean speed
        double spread = 15;                 // the cone's half-angle, degrees
        double jitter = 0;                  // speed = |v̄| (1 + jitter u), u ∈ [−1, 1)
        double life_min = 2, life_max = 2;  // seconds
        double rate = 20;                   // particles per second
        bool operator==(const Emitter&) const = default;
    };
    struct Start {  // a particle alive at t = 0
        glm::dvec3 position{0, 0, 0};
        glm::dvec3 velocity{0, 0, 0};
        double lifetime = kForever;
        bool operator==(const Start&) const = default;
    };
    struct Plane {
        bool on = false;
        glm::dvec3 point{0, 0, 0};
        glm::dvec3 normal{0, 1, 0};  // unit after resolve()
        double restitution = 0.5;    // e: the share of the normal speed kept
        double friction = 0;         // μ: the share of the tangential speed lost at a bounce
        double h = 0;                // n·point, after resolve()
        bool operator==(const Plane&) const = default;
    };

    struct Input {
        Emitter emitter;
        std::vector<Start> start;
        glm::dvec3 gravity{0, -9.81, 0};
        double drag = 0;  // c: a = g − c v
        Plane plane;
        double dt = 1.0 / 30;
        int frames = 90;
        std::uint64_t seed = 1;
        int focus = 0;  // the particle narrated: the start ones are 0.., then the emitted ones
        bool operator==(const Input&) const = default;
    };

    struct Particle {
        glm::dvec3 x{0, 0, 0}, v{0, 0, 0};
        double lifetime = kForever;
        int id = 0;
        int born = 0;  // the frame it was born in (0: at the start)
        bool operator==(const Particle&) const = default;
    };

    // What happened to the focus particle in the last frame (for the narration and picture).
    enum class Fate : std::uint8_t { NotBorn, Born, Moved, Died, Gone };
    struct Focus {
        Fate fate = Fate::NotBorn;
        glm::dvec3 x0{0, 0, 0}, v0{0, 0, 0};  // before the frame
        glm::dvec3 a{0, 0, 0};                // g − c v0
        glm::dvec3 v1{0, 0, 0}, x1{0, 0, 0};  // after the Euler step, before any bounce
        glm::dvec3 x{0, 0, 0}, v{0, 0, 0};    // after the frame (its last state once dead)
        double lifetime = kForever;
        int born = 0;
        bool hit = false;
        double d = 0;  // n·x1 − h, when it hit
        bool operator==(const Focus&) const = default;
    };

    struct Counts {
        int emitted = 0, killed = 0, bounced = 0;
        bool operator==(const Counts&) const = default;
    };

    struct Result {
        double dt = 0;
        int frames = 0;
        double t = 0;
        long long emitted = 0;  // by the emitter, N(t)
        long long killed = 0;
        int alive = 0;
        long long bounces = 0;
        std::vector<int> alive_per_frame, emitted_per_frame, killed_per_frame;
        std::vector<int> ids;  // the particles alive at the end, in id order
        std::vector<glm::dvec3> positions, velocities;
        std::vector<double> ages;
        int focus = 0;
        bool focus_born = false, focus_alive = false;
        glm::dvec3 x{0, 0, 0}, v{0, 0, 0};  // the focus particle's last state
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Frame, Summary, Done };

    struct State {
        Shared<Input> in;  // resolved
        Phase phase = Phase::Frame;
        Phase last = Phase::Frame;
        int k = 0;  // frames taken
        Rng rng{0};
        long long emitted = 0;  // N(t_k)
        long long killed = 0, bounces = 0;
        std::vector<Particle> alive;  // in id order
        Counts now;                   // the last frame's counts
        Focus focus;
        std::vector<int> alive_n, emitted_n, killed_n;  // per frame
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static Input resolve(const Input& in);  // validates; normalises the plane
    static State start(const Input& in);
    static State begin(Shared<Input> resolved);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.alive) + heap_bytes(s.alive_n) + heap_bytes(s.emitted_n) +
               heap_bytes(s.killed_n);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces (on a resolved input).
    // N(t_k) = ⌊rate · dt · k⌋ of the exact real product of the three numbers.
    static long long emitted_by(double rate, double dt, int k);
    // The fraction carried to the next frame, rate·dt·k − N (shown as 0 below 1e-9).
    static double carry(double rate, double dt, int k);
    // Whether a particle `frames` frames old has reached its lifetime: frames·dt ≥ L, exactly.
    static bool aged_out(int frames, double dt, double lifetime);
    static double distance(const Plane& p, glm::dvec3 x);  // n·x − h
    // The bounce of a particle found below the plane (d < 0): reflected, never left below.
    static void bounce(const Plane& p, double d, glm::dvec3& x, glm::dvec3& v);
    // A new particle from the emitter, drawing its random numbers from rng.
    static Particle emit(const Emitter& e, int id, int frame, Rng& rng);
    // One frame: kill, move, bounce, emit; the focus particle's story goes to `focus`.
    static Counts frame(const Input& in, int k, Rng& rng, long long& emitted,
                        std::vector<Particle>& alive, Focus& focus);
    static const char* shape_name(Shape s);
    static double max_lifetime(const Input& in);  // of everything that can be alive

  private:
    static void take_step(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
