// The slab test: a ray against an axis-aligned box, as the intersection of three slabs.
//
// The box [min, max] is the set min_i ≤ x_i ≤ max_i for i = x, y, z: three slabs, each the
// space between two parallel planes. The ray E + t d is between the planes of slab i for t
// between t0_i = (min_i − E_i)/d_i and t1_i = (max_i − E_i)/d_i (swapped when d_i < 0), and
// inside the box where it is inside all three at once:
//
//   t_near = max_i t0_i,   t_far = min_i t1_i,   inside for t_near < t < t_far.
//
// A ray parallel to slab i (d_i = 0) is inside it for every t when min_i < E_i < max_i and
// for none otherwise. The ray is inside the box's interior only: a ray that only touches it
// (through an edge or a corner, or along a face, t_near = t_far or E_i on a face plane with
// d_i = 0) is not inside. t is in units of the given direction; the ends may be ±∞ (a
// direction parallel to every slab it is inside). Reusable by anything that needs a ray-box
// test (CSG's box primitive; a bounding box's quick rejection).
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <limits>

namespace cg {

struct Box {
    glm::dvec3 min{-1.0}, max{1.0};  // min_i < max_i on every axis
    bool operator==(const Box&) const = default;
};

struct SlabHit {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    bool hit = false;                    // t_near < t_far: the ray is inside for a while
    double t_near = -kInf, t_far = kInf;  // the box's entry and exit (±∞: never enters/leaves)
    int axis_near = -1, axis_far = -1;    // the slab that gave each end (-1: none, an infinite end)
    // Per slab, for the narration: where the ray is between its two planes ([t0, t1], ±∞ when
    // parallel and inside), and whether it is parallel and outside (then no t is inside).
    std::array<double, 3> t0{-kInf, -kInf, -kInf}, t1{kInf, kInf, kInf};
    std::array<bool, 3> parallel_outside{false, false, false};
    bool operator==(const SlabHit&) const = default;
};

SlabHit ray_slabs(const Box& b, glm::dvec3 origin, glm::dvec3 direction);

// The box face's outward unit normal: face 2i is the min_i plane (−e_i), 2i + 1 the max_i
// plane (+e_i). The face the ray enters through at t_near and leaves through at t_far:
inline int entry_face(const SlabHit& h, glm::dvec3 direction) {
    return h.axis_near < 0 ? -1 : 2 * h.axis_near + (direction[h.axis_near] < 0 ? 1 : 0);
}
inline int exit_face(const SlabHit& h, glm::dvec3 direction) {
    return h.axis_far < 0 ? -1 : 2 * h.axis_far + (direction[h.axis_far] < 0 ? 0 : 1);
}
inline glm::dvec3 box_face_normal(int face) {
    glm::dvec3 n(0.0);
    n[face / 2] = face % 2 ? 1.0 : -1.0;
    return n;
}

}  // namespace cg
