// Particle-system exam problems, three kinds:
//   - one semi-implicit Euler step of a particle under gravity g = (0, −10, 0) and linear drag c
//     (a = g − c v, v ← v + dt a, x ← x + dt v): the new position and velocity (40%);
//   - one bounce off the ground plane y = 0 with restitution e and friction μ, no gravity: the
//     velocity after it, v ← −e v_n + (1 − μ) v_t (30%);
//   - an emitter of rate r and lifetime L run for t seconds in frames of dt: how many were
//     emitted (⌊r t⌋) and how many are alive (those born within the last L seconds) (30%).
// Times are multiples of 0.25, so every number is exact in binary and the counts are what a
// student computes by hand. Sometimes degenerate: a particle at rest, e = 0 (it stays on the
// plane), t < L (nothing has died yet).
#include "animation/particles.hpp"
#include "core/format.hpp"

namespace cg {

Particles::Input Particles::exam_input(Rng& rng) {
    Input in;
    in.emitter.rate = 0;
    in.emitter.spread = 0;
    in.gravity = {0, -10, 0};
    in.frames = 1;
    in.seed = std::uint64_t(rng.integer(1, 1000));
    const double kind = rng.uniform(0, 1);
    if (kind < 0.4) {
        const double drags[] = {0, 0, 0.5, 1, 2};
        const double dts[] = {0.1, 0.5};
        Start p;
        p.position = {double(rng.integer(-2, 2)), double(rng.integer(0, 4)), 0};
        if (!rng.chance(0.1))
            p.velocity = {double(rng.integer(-3, 3)), double(rng.integer(-4, 6)), 0};
        in.start = {p};
        in.drag = drags[rng.integer(0, 4)];
        in.dt = dts[rng.integer(0, 1)];
    } else if (kind < 0.7) {
        const double es[] = {0, 0.5, 0.8, 1};
        const double mus[] = {0, 0.2, 0.5};
        Start p;
        p.velocity = {double(rng.integer(-2, 3)), -double(rng.integer(1, 5)), 0};
        in.start = {p};
        in.gravity = {0, 0, 0};
        in.plane.on = true;
        in.plane.restitution = es[rng.integer(0, 3)];
        in.plane.friction = mus[rng.integer(0, 2)];
        in.dt = 0.1;
    } else {
        const double rates[] = {2, 4, 6, 10};
        const double lives[] = {0.5, 1, 1.5, 2};
        const double dts[] = {0.25, 0.5};
        in.emitter.rate = rates[rng.integer(0, 3)];
        in.emitter.life_min = in.emitter.life_max = lives[rng.integer(0, 3)];
        in.dt = dts[rng.integer(0, 1)];
        in.frames = int(rng.integer(2, 12));
    }
    return in;
}

std::vector<std::string> Particles::answer_fields(const Input& in) {
    if (in.start.empty()) return {"emitted", "alive"};
    if (in.plane.on) return {"v"};
    return {"x", "v"};
}

std::string Particles::question(const Input& in) {
    if (in.start.empty()) {
        const double t = double(in.frames) * in.dt;
        return "An emitter makes rate = " + num(in.emitter.rate) +
               " particles per second, each living L = " + num(in.emitter.life_min) +
               " s. The simulation runs in frames of dt = " + num(in.dt) +
               " s; at the end of frame k (t = k·dt) the emitter has made N(t) = ⌊rate · t⌋ "
               "particles in all, the new ones born then with age 0, and a particle dies in the "
               "frame where its age reaches L. At t = " +
               num(t) + " s (" + std::to_string(in.frames) +
               " frames), how many particles have been emitted (emitted) and how many are "
               "alive (alive)?";
    }
    const Start& p = in.start.at(0);
    if (in.plane.on)
        return "A particle on the ground plane y = 0 moves with v = " + num(p.velocity) +
               " (no gravity, no drag). After one step of dt = " + num(in.dt) +
               " it is below the plane and bounces with restitution e = " +
               num(in.plane.restitution) + " and friction μ = " + num(in.plane.friction) +
               ": v ← −e v_n + (1 − μ) v_t, with v_n the part of v along the normal (0, 1, 0) "
               "and v_t the rest. Give the velocity after the bounce (v) as [x, y, z].";
    return "A particle at x = " + num(p.position) + " moves with v = " + num(p.velocity) +
           " under gravity g = " + num(in.gravity) + " and linear drag c = " + num(in.drag) +
           " (a = g − c v, per unit mass). Take one semi-implicit Euler step of dt = " +
           num(in.dt) +
           ": v ← v + dt a, then x ← x + dt v with the new v. Give the new position (x) and "
           "velocity (v) as [x, y, z].";
}

}  // namespace cg
