// A triangle mesh as the ray tracer holds it: one object of up to millions of triangles, with its
// own bounding volume hierarchy, so that a ray costs about log n box tests and a handful of
// triangle tests instead of n.
//
// What is kept per triangle is what the ray test needs and nothing else, in the order the leaves
// list them: p0, e1 = p1 − p0, e2 = p2 − p0 (72 bytes, doubles, so that a hit is exactly the one
// a lone triangle object gives), and the triangle's index in the mesh (4 bytes), for its vertex
// normals and (u, v). A node holds the boxes of its four children (floats, rounded outward, so
// that a box only ever grows) in two 64-byte cache lines: one node visited is one short read
// and four slab tests, two at a time. Four children a node halve the tree's depth, and the
// depth is what a ray waits for: each level is a read from memory that cannot start before the
// one above is done.
//
// The build is the binned surface area heuristic (as rt_bvh.hpp's, over the three axes with 32
// bins each): a node of n triangles is split at the bin boundary where
//   C = C_trav + (S_L/S) N_L + (S_R/S) N_R          (C_trav = 1, a triangle test costing 1)
// is least, or made a leaf when n ≤ 16 and no split is cheaper than its n tests (larger nodes
// are split by the middle of the list when every centre is in one place, and at every level
// below 40, so that the depth stays below 64 whatever the input). The root's two
// subtrees are built on two threads; the tree is the same with one or two. Triangle boxes are
// padded by 2⁻³⁰ of their largest coordinate before rounding to float, so that a hit on an
// edge shared with a box face is never lost to a slab test's rounding, even for a flat terrain's
// boxes of zero height.
//
// The binary tree is then collapsed into the four-wide one: a node takes its two children and,
// while it has room, replaces the inner child of largest area by that child's two.
//
// Traversal: the nearer child first, a subtree skipped when entered beyond the best hit; ties in
// t go to the smaller triangle index, so the answer is brute force's, whatever the tree.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

#include "rays/mesh_gen.hpp"

namespace cg::rt {

struct alignas(64) MeshNode {
    float lo[3][4], hi[3][4];  // child k's box: [lo[axis][k], hi[axis][k]] per axis
    std::int32_t child[4];     // an inner child's node index, or a leaf's first triangle
    std::int32_t count[4];     // 0: an inner child; > 0 the leaf's triangle count; −1: empty
};
static_assert(sizeof(MeshNode) == 128);

struct MeshTriangle {
    glm::dvec3 p0, e1, e2;
};

struct MeshBvh {
    std::vector<MeshNode> nodes;            // nodes[0] is the root (none when a leaf)
    std::vector<MeshTriangle> triangles;    // leaf order
    std::vector<std::uint32_t> ids;         // leaf order → index in the mesh
    float root_lo[3]{}, root_hi[3]{};       // the whole mesh's box
    std::int32_t root = 0, root_count = 0;  // the root: a node (count 0) or a leaf
    int depth = 0;                          // nodes on the longest root-to-leaf path
    // What a ray that meets the mesh's box costs, expected (the surface area heuristic: a box is
    // entered with probability its area over the root's): box tests + triangle tests.
    double cost = 0;
    std::size_t bytes() const;  // what the structure holds (nodes, triangles, ids)
};

// Preconditions: the vertices are finite and the indices valid. threads 0: both cores (2).
MeshBvh build_mesh_bvh(const mesh::Mesh& m, int threads = 0);

// Möller-Trumbore: E + t d = P0 + β e1 + γ e2 by Cramer's rule, β = u/det, γ = v/det,
// t = w/det; +∞ when the ray misses, is parallel to the plane (|det| ≤ 10⁻¹⁵ |e1| |d × e2|) or
// meets it at t ≤ t_min. The ray tracer's triangle objects use the same test, so a mesh and its
// triangles give the same hits. The inside tests compare u, v and u + v with det (by det's
// sign) before anything is divided: most tests are misses, and a miss then costs no division.
inline double triangle_t(glm::dvec3 p0, glm::dvec3 e1, glm::dvec3 e2, glm::dvec3 origin,
                         glm::dvec3 d, double t_min, double* beta_out = nullptr,
                         double* gamma_out = nullptr) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const glm::dvec3 pv(d.y * e2.z - d.z * e2.y, d.z * e2.x - d.x * e2.z, d.x * e2.y - d.y * e2.x);
    const double det = e1.x * pv.x + e1.y * pv.y + e1.z * pv.z;
    // |det| ≤ 10⁻¹⁵ |e1| |pv|, compared squared (no square roots in the inner loop).
    if (det * det <= 1e-30 * (e1.x * e1.x + e1.y * e1.y + e1.z * e1.z) *
                         (pv.x * pv.x + pv.y * pv.y + pv.z * pv.z))
        return kInf;
    const glm::dvec3 tv = origin - p0;
    const double u = tv.x * pv.x + tv.y * pv.y + tv.z * pv.z;
    // 0 ≤ β ≤ 1: u between 0 and det, on det's side.
    if (det > 0 ? !(u >= 0 && u <= det) : !(u <= 0 && u >= det)) return kInf;
    const glm::dvec3 qv(tv.y * e1.z - tv.z * e1.y, tv.z * e1.x - tv.x * e1.z,
                        tv.x * e1.y - tv.y * e1.x);
    const double v = d.x * qv.x + d.y * qv.y + d.z * qv.z;
    // γ ≥ 0 and β + γ ≤ 1.
    if (det > 0 ? !(v >= 0 && u + v <= det) : !(v <= 0 && u + v >= det)) return kInf;
    const double inv = 1 / det;
    const double t = (e2.x * qv.x + e2.y * qv.y + e2.z * qv.z) * inv;
    if (!(t > t_min)) return kInf;
    if (beta_out) *beta_out = u * inv, *gamma_out = v * inv;
    return t;
}

struct MeshHit {
    double t = std::numeric_limits<double>::infinity();
    std::uint32_t triangle = 0;  // index in the mesh
    double beta = 0, gamma = 0;  // the hit is (1 − β − γ) p0 + β p1 + γ p2
};

// The nearest hit with t_min < t < t_max (ties: the smaller triangle index); false for none.
// box_tests/triangle_tests, when given, are incremented by what the search did.
bool mesh_nearest(const MeshBvh& bvh, glm::dvec3 origin, glm::dvec3 d, double t_min, double t_max,
                  MeshHit& hit, long long* box_tests = nullptr,
                  long long* triangle_tests = nullptr);
// Whether any triangle lies on the ray at t_min < t < t_max (stops at the first found).
bool mesh_occluded(const MeshBvh& bvh, glm::dvec3 origin, glm::dvec3 d, double t_min, double t_max);

}  // namespace cg::rt
