// Slab-test exam problems: a box with integer corners (sides 1 to 4), a direction whose
// components are ±1, ±2 or ±0.5 (sometimes 0), and an origin chosen so that every t is a
// multiple of 1/4. Most rays are aimed at a point of the box from outside; the rest cover what
// exams ask about: a ray that misses (slabs disjoint), a component 0 inside or outside its slab,
// an origin inside the box or on a face, and a box behind the ray.
#include <cmath>

#include "accel/ray_aabb.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

double nice_component(Rng& rng) {
    static constexpr double kSteps[] = {1, 2, 0.5, 1, 2};
    const double d = kSteps[rng.integer(0, 4)];
    return rng.chance(0.5) ? d : -d;
}

// A point of the box with whole or half coordinates.
glm::dvec3 point_in(Rng& rng, const RayAabb::Input& in) {
    glm::dvec3 p;
    for (int i = 0; i < 3; ++i)
        p[i] = in.min[i] + 0.5 * static_cast<double>(rng.integer(
                                     0, static_cast<long long>(2 * (in.max[i] - in.min[i]))));
    return p;
}

}  // namespace

RayAabb::Input RayAabb::exam_input(Rng& rng) {
    Input in;
    for (int i = 0; i < 3; ++i) {
        in.min[i] = static_cast<double>(rng.integer(-2, 1));
        in.max[i] = in.min[i] + static_cast<double>(rng.integer(1, 4));
    }
    in.direction = {nice_component(rng), nice_component(rng), nice_component(rng)};
    const glm::dvec3 target = point_in(rng, in);
    const double k = static_cast<double>(rng.integer(2, 4));  // steps back from the target
    const int axis = static_cast<int>(rng.integer(0, 2));
    switch (rng.integer(0, 9)) {
        case 0:  // anywhere near the box: often a miss with disjoint slabs
            for (int i = 0; i < 3; ++i)
                in.origin[i] = static_cast<double>(rng.integer(
                    static_cast<long long>(in.min[i]) - 4, static_cast<long long>(in.max[i]) + 4));
            break;
        case 1:  // a component 0, the origin between that axis's planes
            in.direction[axis] = 0;
            in.origin = target - k * in.direction;
            break;
        case 2:  // a component 0, the origin outside that slab: a miss
            in.direction[axis] = 0;
            in.origin = target - k * in.direction;
            in.origin[axis] = rng.chance(0.5)
                                  ? in.max[axis] + static_cast<double>(rng.integer(1, 2))
                                  : in.min[axis] - static_cast<double>(rng.integer(1, 2));
            break;
        case 3:  // the origin inside the box
            in.origin = target;
            break;
        case 4:  // the origin on a face
            in.origin = target;
            in.origin[axis] = rng.chance(0.5) ? in.min[axis] : in.max[axis];
            break;
        case 5:  // the box behind the ray
            in.origin = target - k * in.direction;
            in.direction = -in.direction;
            break;
        default:  // aimed at a point of the box from outside
            in.origin = target - k * in.direction;
            break;
    }
    return in;
}

std::string RayAabb::question(const Input& in) {
    return "Does the ray P(t) = E + t d, t ≥ 0, with E = " + num(in.origin) +
           " and d = " + num(in.direction) + " meet the box with corners min = " + num(in.min) +
           " and max = " + num(in.max) +
           " (closed: its faces belong to it)? Use the slab test, axis by axis in the order x, y, "
           "z: give t_near and t_far of each axis (axes: a list of {\"t_near\": …, \"t_far\": …}, "
           "x first), swapping the two when d_i < 0. A component d_i = 0 gives (−∞, +∞) when E_i "
           "is between the two planes (on one counts) and the empty slab (+∞, −∞) otherwise; write "
           "∞ as \"inf\" and −∞ as \"-inf\". Keep t_min = the largest t_near and t_max = the "
           "smallest t_far so far, and stop as soon as t_min > t_max (list only the axes worked). "
           "Then give t_min, t_max, and whether the ray hits the box (hit: t_min ≤ t_max and "
           "t_max ≥ 0).";
}

std::vector<std::string> RayAabb::answer_fields() {
    return {"axes", "t_min", "t_max", "hit"};
}

}  // namespace cg
