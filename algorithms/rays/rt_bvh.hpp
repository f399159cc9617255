// The ray tracer's bounding volume hierarchy: what makes a ray's nearest hit cost about log n
// box tests instead of n object tests.
//
// Built once per scene (rt::prepare) over the objects that have finite bounds — triangles,
// spheres and ellipsoids, the other quadrics when a z slab cuts them — by the surface area
// heuristic over 16 bins per node (binned SAH): a node of n objects is split where
//   C = C_trav + (S_L/S) N_L C_isect + (S_R/S) N_R C_isect      (C_trav = ½, C_isect = 1)
// is least over the 15 bin boundaries on the axis along which the objects' centres spread
// most, and is a leaf when no cut is cheaper than testing its n objects (n C_isect), or when
// n ≤ 2. Planes, CSG objects, moving objects and unbounded quadrics are tested for every ray
// (`unbounded`). The nodes are flat: an inner node's left child follows it, its right child is
// at `right`; a leaf lists items[first, first + count).
//
// The boxes are padded by 2⁻³⁰ of the largest coordinate they hold, so that a hit on an
// object's edge is never lost to the rounding of a box test (the slab test of a box exactly
// the object's own size can round it out).
//
// Traversal (rt_scene.cpp): front to back — the nearer child first, a node skipped when its
// box is entered beyond the best hit so far. Ties in t go to the smaller object index, brute
// force's rule, so the image and the hits are the same with and without the hierarchy.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "accel/primitive.hpp"

namespace cg::rt {

struct BvhNode {
    Bounds box;
    int right = -1;            // an inner node's right child (its left child is the next node)
    int first = 0, count = 0;  // a leaf's items; count = 0 for an inner node
    std::uint8_t axis = 0;     // an inner node's split axis (which child is near)
    bool operator==(const BvhNode&) const = default;
};

struct ObjectBvh {
    std::vector<BvhNode> nodes;  // nodes[0] is the root (none when no object is bounded)
    std::vector<int> items;      // object indices, leaf by leaf
    std::vector<int> unbounded;  // objects tested for every ray, ascending
    int depth = 0;               // the longest root-to-leaf path (nodes)
    bool operator==(const ObjectBvh&) const = default;
};

// Below this many bounded objects there is no tree: every object is tested for every ray
// (brute force's own loop). Even the reference scene's six quadrics are faster through the
// tree (173 against 261 ms, LTO, one thread): a box test is cheaper than a transformed quadric.
inline constexpr int kMinTreeObjects = 2;

// bounds[k] empty (Bounds{}) marks object k as unbounded.
ObjectBvh build_bvh(const std::vector<Bounds>& bounds);

// The stack traversal needs at most depth + 1 entries; build_bvh keeps depth below this.
inline constexpr int kMaxBvhDepth = 64;

// ---- traversal (the tracer's nearest hit and shadow rays, the complexity lab's counts) ----

// The ray as the box tests want it: 1/d per axis. A zero component gets 1/d = 10³⁰⁰ instead
// of ∞, so that a box face through the origin gives 0 · 10³⁰⁰ = 0, never 0 · ∞ = NaN; the
// slab is then [0, ±huge], which is right: the origin is on the face.
struct BoxRay {
    glm::dvec3 origin, inv;
    int near_first[3];  // per split axis: 1 when the left child is the near one
};

inline BoxRay box_ray(glm::dvec3 origin, glm::dvec3 d) {
    BoxRay r;
    r.origin = origin;
    for (int i = 0; i < 3; ++i) {
        const double inv = 1 / d[i];
        r.inv[i] = std::isfinite(inv) ? inv : std::copysign(1e300, d[i]);
        r.near_first[i] = d[i] >= 0;
    }
    return r;
}

// The slab test on a node's box for t in [t0, t1]: where the ray enters it, or +∞ for a miss.
inline double box_entry(const Bounds& b, const BoxRay& r, double t0, double t1) {
    for (int i = 0; i < 3; ++i) {
        double a = (b.min[i] - r.origin[i]) * r.inv[i], c = (b.max[i] - r.origin[i]) * r.inv[i];
        if (a > c) std::swap(a, c);
        t0 = std::max(t0, a);
        t1 = std::min(t1, c);
    }
    return t0 <= t1 ? t0 : std::numeric_limits<double>::infinity();
}

// Front-to-back traversal: visit(object) for each object of each leaf whose box the ray meets
// at t ≤ limit(); visit returns true to stop.
template <class Limit, class Visit>
void traverse(const ObjectBvh& bvh, const BoxRay& r, double t_min, Limit limit, Visit visit,
              long long* box_tests = nullptr) {
    if (bvh.nodes.empty()) return;
    struct Entry {
        int node;
        double t;
    };
    Entry stack[kMaxBvhDepth + 2];
    int top = 0;
    const double t0 = box_entry(bvh.nodes[0].box, r, t_min, limit());
    if (box_tests) ++*box_tests;
    if (t0 == std::numeric_limits<double>::infinity()) return;
    stack[top++] = {0, t0};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.t > limit()) continue;  // entered beyond the best hit: nothing nearer inside
        const BvhNode& n = bvh.nodes[e.node];
        if (n.count > 0) {
            for (int k = n.first; k < n.first + n.count; ++k)
                if (visit(bvh.items[k])) return;
            continue;
        }
        const int left = e.node + 1, right = n.right;
        if (box_tests) *box_tests += 2;
        const double tl = box_entry(bvh.nodes[left].box, r, t_min, limit());
        const double tr = box_entry(bvh.nodes[right].box, r, t_min, limit());
        // Push the far child first so that the near one is popped next.
        const bool left_near = r.near_first[n.axis] != 0;
        const int far = left_near ? right : left, near = left_near ? left : right;
        const double t_far = left_near ? tr : tl, t_near = left_near ? tl : tr;
        if (t_far != std::numeric_limits<double>::infinity()) stack[top++] = {far, t_far};
        if (t_near != std::numeric_limits<double>::infinity()) stack[top++] = {near, t_near};
    }
}

}  // namespace cg::rt
