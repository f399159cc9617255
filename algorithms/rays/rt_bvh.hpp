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

#include <cstdint>
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

}  // namespace cg::rt
