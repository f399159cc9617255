// Spring-mass exam problems: one explicit Euler step of one spring. A mass m hangs on a spring
// (stiffness k, rest length L, damping c) from a pinned anchor at the origin, given its position
// and velocity; compute the force, then x ← x + dt v and v ← v + dt F/m. Three times in four the
// spring lies along x without gravity; otherwise it hangs along y under g = (0, −10). One time in
// ten the mass starts at rest at the rest length (no force: nothing changes but nothing moves).
#include "animation/spring_mass.hpp"
#include "core/format.hpp"

namespace cg {

SpringMass::Input SpringMass::exam_input(Rng& rng) {
    const double masses[] = {1, 2, 4};
    const double ks[] = {2, 4, 10, 20};
    const double stretches[] = {-0.5, 0.5, 1};
    const double speeds[] = {0, 1, -1, 2};
    const double dampings[] = {0, 0, 0.5, 1};
    Input in;
    const bool hanging = rng.chance(0.25);
    const bool at_rest = rng.chance(0.1);
    const double L = double(rng.integer(1, 2));
    const double s = at_rest ? 0 : stretches[rng.integer(0, 2)];
    const double u = at_rest ? 0 : speeds[rng.integer(0, 3)];
    Mass anchor;
    anchor.pinned = true;
    Mass m;
    m.mass = masses[rng.integer(0, 2)];
    const glm::dvec3 dir = hanging ? glm::dvec3(0, -1, 0) : glm::dvec3(1, 0, 0);
    m.position = (L + s) * dir;
    m.velocity = u * dir;
    in.masses = {anchor, m};
    Spring sp;
    sp.i = 0;
    sp.j = 1;
    sp.stiffness = ks[rng.integer(0, 3)];
    sp.rest = L;
    sp.has_rest = true;
    sp.damping = dampings[rng.integer(0, 3)];
    in.springs = {sp};
    in.gravity = hanging ? glm::dvec3(0, -10, 0) : glm::dvec3(0);
    in.dt = rng.chance(0.5) ? 0.1 : 0.05;
    in.steps = 1;
    in.integrator = Integrator::ExplicitEuler;
    in.watch = 1;
    return in;
}

std::string SpringMass::question(const Input& in) {
    const Mass& m = in.masses.at(1);
    const Spring& s = in.springs.at(0);
    return "A point mass m = " + num(m.mass) + " at x = " + num(m.position) +
           " with velocity v = " + num(m.velocity) +
           " is attached by a spring (stiffness k = " + num(s.stiffness) +
           ", rest length L = " + num(s.rest) + ", damping c = " + num(s.damping) +
           " along the spring) to a fixed point at the origin; gravity is g = " + num(in.gravity) +
           ". With d = x − anchor, the spring force on the mass is " +
           "−k (|d| − L) d̂ − c (v·d̂) d̂, plus m g. Take one explicit Euler step of dt = " +
           num(in.dt) +
           ": x ← x + dt v, v ← v + dt F/m, both from the old state. Give the new "
           "position (x) and velocity (v) as [x, y, z].";
}

}  // namespace cg
