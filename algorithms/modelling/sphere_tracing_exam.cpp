// Sphere tracing exam problems: a ray from the origin along +x toward one sphere in the plane
// z = 0, centre (c_x, c_y, 0) with small integers, ε = 0.1. The student lists the distances d_k
// of the samples (d_k = √((c_x − t_k)² + c_y²) − r, then t_k+1 = t_k + d_k) until one is below ε
// or t passes max_distance, counts the samples, and says hit or miss. Kept to at most 6 samples.
// The cases: head-on (c_y = 0: the first step lands exactly on the sphere), passing off-centre
// (a few shrinking steps), passing beside it (a miss: the steps shrink to c_y − r, then grow),
// and one time in ten the origin inside the sphere (d₀ < 0: a hit at t = 0).
#include "core/format.hpp"
#include "modelling/sphere_tracing.hpp"

namespace cg {

SphereTracing::Input SphereTracing::exam_input(Rng& rng) {
    Input in;
    in.origin = {0, 0, 0};
    in.direction = {1, 0, 0};
    in.epsilon = 0.1;
    in.max_steps = 20;
    Shape s;
    s.kind = Kind::Sphere;
    if (rng.chance(0.1)) {  // the origin inside
        const double r = double(rng.integer(3, 5));
        s.centre = {double(rng.integer(1, 2)), double(rng.integer(-1, 1)), 0};
        s.size = {r, 0, 0};
        in.shapes = {s};
        in.max_distance = 20;
        return in;
    }
    const bool miss = rng.chance(0.2);
    for (;;) {
        const double r = double(rng.integer(2, 6));
        const double cy = miss ? r + double(rng.integer(1, 2)) : double(rng.integer(0, int(r) - 1));
        const double cx = r + double(rng.integer(3, 10));
        s.centre = {cx, rng.chance(0.5) ? cy : -cy, 0};
        s.size = {r, 0, 0};
        in.shapes = {s};
        in.max_distance = 2 * cx;
        if (compute(in).samples <= 6) return in;
    }
}

std::string SphereTracing::question(const Input& in) {
    const Shape& s = in.shapes.at(0);
    return "A ray starts at o = " + num(in.origin) +
           " with direction d̂ = " + num(unit(in.direction)) + ". The scene is one sphere, centre " +
           num(s.centre) + ", radius " + num(s.size.x) +
           ", with signed distance f(p) = |p − c| − r. Sphere-trace "
           "it with ε = " +
           num(in.epsilon) + " and max_distance = " + num(in.max_distance) +
           ": starting at t = 0, sample d_k = f(o + t_k·d̂); stop with a hit when d_k < ε, "
           "otherwise step t_k+1 = t_k + d_k and stop with a miss once t exceeds max_distance. "
           "Give the distances d_0, d_1, … of every sample (distances), how many samples were "
           "taken (steps), and whether the ray hits (hit).";
}

std::vector<std::string> SphereTracing::answer_fields() {
    return {"distances", "steps", "hit"};
}

}  // namespace cg
