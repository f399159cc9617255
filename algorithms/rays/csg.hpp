// Constructive solid geometry on ray segments: the course's method for ray tracing a CSG tree.
//
// "In CSG all primitives are solids": each leaf of the tree is a solid (a quadric's inside, cut
// to its z slab, so a cylinder with zmin/zmax is closed by two caps; or a box), each internal
// node a boolean operation on its two subtrees (union, intersection, difference). To intersect
// a ray with the tree, intersect it with every primitive and keep, per leaf, the list of
// segments [t_in, t_out] where the ray is inside; then combine the lists at each node on the way
// up the tree:
//
//   union         inside A or B       intersection  inside A and B       difference  inside A, not B
//
// The first end of the root's list with t > ε is the hit: normally where the ray enters the
// solid (an eye inside the solid sees the surface where the ray leaves it). Its normal is that
// of the surface the end came from, reversed when it came from the subtracted operand of a
// difference (B's outward normal where the ray leaves B is A − B's inward one).
//
// Transforms, as in hierarchical models: a node's transform (parent_from_node) applies to its
// whole subtree, so a leaf's surface is placed in the world by the product of the transforms on
// the path from the root down to it (then the quadric's own). The ray is carried into each
// leaf's frame by the inverse, E_m = M⁻¹ E, d_m = M⁻¹ d; because the map is affine and d is
// carried as a direction, the point E_m + t d_m is M⁻¹ of E + t d: t is the same parameter in
// every frame, so the segments need no transforming on the way back up — only the hit's normal
// does, by the inverse transpose (M⁻¹)ᵀ.
//
// Conventions and rules:
// - A segment is where the ray is strictly inside a solid. Where it only touches the surface (a
//   tangent ray, Δ = 0 with the solid on one side; a ray along a ruling or a face; through an
//   edge or a corner of a box) it is not inside: such zero-length segments are dropped.
// - Ends are combined by a sweep along t; ends at the same t are taken together, so segments
//   that touch end to end in a union join into one ([1, 2] ∪ [2, 3] = [1, 3]) and a touch in an
//   intersection vanishes ([1, 2] ∩ [2, 3] = ∅). Every list is ascending, disjoint, with gaps
//   between its segments, each of positive length.
// - An unbounded solid (an uncut cylinder, a cone, a hyperboloid, a paraboloid) may hold the
//   ray at t → ±∞: that end is t = ±∞ with no surface (the JSON writes it as null).
// - t is in units of the given direction (not normalised), as in ray-quadric.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "rays/quadric.hpp"
#include "rays/slab.hpp"

namespace cg {

enum class CsgOp : std::uint8_t { Union, Intersection, Difference };
const char* csg_op_id(CsgOp op);      // "union", "intersection", "difference" (the JSON "op")
const char* csg_op_symbol(CsgOp op);  // "∪", "∩", "−"

enum class CsgPrimitive : std::uint8_t { Quadric, Box };

struct CsgNode {
    bool leaf = true;
    CsgOp op = CsgOp::Union;        // internal nodes
    int left = -1, right = -1;      // ... their operands, indices into CsgTree::nodes
    bool has_transform = false;     // a transform was given
    glm::dmat4 transform{1.0};      // parent_from_node: applies to the whole subtree
    CsgPrimitive kind = CsgPrimitive::Quadric;  // leaves
    Quadric quadric;                // ... a quadric solid (its inside F < 0, cut to its slab)
    Box box;                        // ... or a box
    std::string name;               // a leaf's name as given ("" when none)
    std::string path;               // where the node is in the input: "tree.left.right"
    int leaf_index = -1;            // leaves numbered 0, 1, ... from left to right
    int depth = 0;                  // the root is at depth 0
    bool operator==(const CsgNode&) const = default;
};

struct CsgTree {
    std::vector<CsgNode> nodes;  // post-order: both operands before their node, the root last
    int leaves = 0;
    const CsgNode& root() const { return nodes.back(); }
    bool operator==(const CsgTree&) const = default;
};

constexpr int kMaxCsgDepth = 32;    // levels below the root
constexpr int kMaxCsgLeaves = 256;  // primitives in one tree

// A leaf's name for the narration and the result: its "name", or "leaf k".
std::string csg_leaf_label(const CsgNode& leaf);

// Throws InputError naming the field ("tree.left.transform[3]", "tree.right.primitive.params.r",
// "tree.left.primitive.max[1]", "tree.left.right"): every transform affine, finite and
// invertible, every quadric valid, every box with min < max on each axis, the products of the
// transforms down to every leaf invertible in double precision, depth and size within limits.
void validate_csg(const CsgTree& t);

// One end of a segment: its t and the surface it lies on.
struct CsgEnd {
    double t = 0;
    int leaf = -1;      // the leaf whose surface this is; -1: an infinite end (no surface)
    int face = 0;       // quadric: 0 its surface, 1 its zmin cap, 2 its zmax cap; box: 0..5
    bool flip = false;  // the normal is reversed (from a subtracted operand, an odd number of times)
    bool operator==(const CsgEnd&) const = default;
};
struct CsgSpan {
    CsgEnd in, out;  // in.t < out.t
    bool operator==(const CsgSpan&) const = default;
};
using CsgSpans = std::vector<CsgSpan>;  // ascending, disjoint, with gaps between

// The tree made ready for rays: the structure, and each leaf with the whole world_from_model
// of its surface (the transforms from the root down, then the quadric's own) prepared once.
struct PreparedCsgLeaf {
    CsgPrimitive kind = CsgPrimitive::Quadric;
    PreparedQuadric quadric;  // a box uses only its frame: transformed, linear_inv, translation
    Box box;
    bool operator==(const PreparedCsgLeaf&) const = default;
};
struct PreparedCsgNode {
    bool leaf = true;
    CsgOp op = CsgOp::Union;
    int left = -1, right = -1;  // operands (node indices)
    int leaf_index = -1;        // leaves: index into PreparedCsg::leaves
    bool operator==(const PreparedCsgNode&) const = default;
};
struct PreparedCsg {
    std::vector<PreparedCsgNode> nodes;  // post-order, as CsgTree::nodes
    std::vector<PreparedCsgLeaf> leaves;
    bool operator==(const PreparedCsg&) const = default;
};
// Precondition: validate_csg(t) does not throw.
PreparedCsg prepare_csg(const CsgTree& t);
// world_from_model of a leaf's surface: the product of the transforms from the root down to the
// leaf (then the quadric's own). For drawing.
glm::dmat4 csg_world_from_leaf(const CsgTree& t, int node);

// What a leaf's intersection found, for the narration and the picture.
struct CsgLeafTrace {
    glm::dvec3 origin{0.0}, direction{0.0};  // the ray in the leaf's frame
    RayQuadratic quad;                       // a quadric: a, b, c
    QuadraticRoots roots;                    // ... the case and the roots
    bool cut = false;                        // ... has a z slab
    double z_t0 = 0, z_t1 = 0;               // ... where the ray is inside the slab
    bool z_parallel_outside = false;         // ... parallel to the slab, outside it
    SlabHit slabs;                           // a box: the three slabs
};

// The segments where the ray is inside one leaf (world-space origin and direction).
CsgSpans leaf_spans(const PreparedCsgLeaf& leaf, int leaf_index, glm::dvec3 origin,
                    glm::dvec3 direction, CsgLeafTrace* trace = nullptr);
// The boolean combination of two lists: the sweep along t.
CsgSpans combine(CsgOp op, const CsgSpans& a, const CsgSpans& b);

// Every node's list, in the order of the nodes (the root's last).
void csg_lists(const PreparedCsg& p, glm::dvec3 origin, glm::dvec3 direction,
               std::vector<CsgSpans>& lists);

// The first end of a list with t_min < t < ∞: an entry point, or (the ray starting inside)
// the exit of the segment holding t_min; nullptr when there is none.
const CsgEnd* first_end_after(const CsgSpans& spans, double t_min, bool* entering = nullptr);
// The unit normal at an end's surface, out of the leaf's solid, reversed when the end is
// flipped; 0 where the surface has none (a cone's apex).
glm::dvec3 csg_end_normal(const PreparedCsg& p, const CsgEnd& end, glm::dvec3 world_point);

struct CsgHit {
    bool hit = false;
    bool entering = true;  // the hit is an entry point (false: the ray starts inside the solid)
    double t = 0;
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};   // unit, the solid's outward normal (not turned toward the ray)
    bool has_normal = false;  // false at a miss and where the surface has none (an apex)
    CsgEnd end;               // the end hit: its leaf, surface and flip
    CsgSpans segments;        // the root's list (the whole line's)
    bool operator==(const CsgHit&) const = default;
};

// The hit on the root's list `h.segments` (already set): fills in the rest of h.
void csg_find_hit(const PreparedCsg& p, glm::dvec3 origin, glm::dvec3 direction, double t_min,
                  CsgHit& h);
// The whole intersection as one plain function (what a tracer calls).
CsgHit csg_intersect(const PreparedCsg& p, glm::dvec3 origin, glm::dvec3 direction,
                     double t_min = kRayEpsilon);
// Only the hit's t (+∞ at a miss): a tracer's nearest-hit search and shadow rays.
double csg_intersect_t(const PreparedCsg& p, glm::dvec3 origin, glm::dvec3 direction,
                       double t_min = kRayEpsilon);

}  // namespace cg
