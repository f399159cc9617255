// What the acceleration structures buy, measured (`cgsandbox complexity accel`): on a seeded
// random scene of n primitives and R random rays, the mean tests per ray of
//   brute force  every primitive: n ray-primitive tests, O(n);
//   BVH          the tracer's hierarchy (rays/rt_bvh.hpp: binned SAH, flat nodes) traversed
//                front to back with closest-hit pruning (bvh_nearest below): box tests and
//                primitive tests, about O(log n) on such scenes;
//   grid         the teaching uniform grid (uniform_grid.hpp: UniformGrid::build and the
//                walk UniformGrid::trace(in, grid), its non-validating entry points) at
//                g = round(∛n) cells per axis, about one primitive per cell: cells visited and
//                primitive tests, O(∛n) cells for a ray that crosses the scene and misses,
//                O(1) tests per cell;
// plus each structure's build time. The scene (random_scene): n primitives in the unit cube
// [0, 1]³, each a sphere or a triangle with probability ½, their size
// shrinking like n^(−1/3) so that a ray across the cube meets about the same fraction of the
// scene at every n (sphere radius 0.25 u n^(−1/3), a triangle's corners within ±0.5 n^(−1/3)
// of its centre, u uniform in [0.2, 1)). The rays (random_rays): origin uniform in
// [−0.5, 1.5]³ (some inside the scene, most outside), aimed at a point uniform in [0, 1]³.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

#include "accel/primitive.hpp"
#include "core/rng.hpp"
#include "rays/rt_bvh.hpp"

namespace cg::accel {

struct Ray {
    glm::dvec3 origin{0.0}, direction{1, 0, 0};  // E, d ≠ 0
};

// A nearest hit and what it cost.
struct CountedHit {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    int primitive = -1;  // −1: no hit
    double t = kInf;
    long long box_tests = 0, primitive_tests = 0;
};

std::vector<Primitive> random_scene(Rng& rng, int n);
std::vector<Ray> random_rays(Rng& rng, int count);

// Every primitive, the nearest t ≥ 0, ties to the smaller index: n primitive tests.
CountedHit brute_nearest(const std::vector<Primitive>& prims, const Ray& ray);

// The nearest hit through a BVH built by rt::build_bvh over the primitives' bounds (every
// primitive bounded). A stack of (node, t_enter); a popped node entered beyond the best hit is
// pruned; a leaf's primitives are tested; an inner node's two children get a slab test each
// (box_tests counts every slab test, the root's included) and are pushed far first. The same
// tie rule as brute force, so the hit is the same.
CountedHit bvh_nearest(const rt::ObjectBvh& bvh, const std::vector<Primitive>& prims,
                       const Ray& ray);

struct ComplexityRow {
    int n = 0, rays = 0;
    int grid_side = 0;  // cells per axis
    int bvh_nodes = 0, bvh_depth = 0;
    double bvh_build_ms = 0, grid_build_ms = 0;
    long long bvh_box_tests = 0, bvh_primitive_tests = 0;  // sums over the rays
    long long grid_cells = 0, grid_primitive_tests = 0;
    long long hits = 0;     // rays that hit something (by the BVH)
    long long checked = 0;  // rays compared with brute force (0: n above the check limit)
    long long agree = 0;    // of those, rays where BVH and grid both give brute force's hit
    double per_ray(long long v) const { return rays > 0 ? static_cast<double>(v) / rays : 0.0; }
};

// One row per n: a scene and `rays` rays seeded from `seed` and n; the BVH and the grid built
// once per scene and timed; every ray traced through both. Brute force is run on every ray
// (and compared) only when n ≤ check_limit: its count is n by definition.
std::vector<ComplexityRow> complexity(const std::vector<int>& counts, int rays, std::uint64_t seed,
                                      int check_limit);
std::string complexity_table(const std::vector<ComplexityRow>& rows);

}  // namespace cg::accel
