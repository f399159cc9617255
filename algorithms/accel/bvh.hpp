// A bounding volume hierarchy (BVH) over spheres, triangles and boxes: built node by node, then
// one ray traced through it with a stack and closest-hit pruning.
//
// Build (one step per node made, depth first, the left child first; node ids in that order,
// the root 0). A node holds a range of the primitives; its bounds are the union of their
// bounds. It becomes a leaf when it holds ≤ max_leaf primitives; otherwise its primitives are
// sorted along the longest axis of their centroid bounds (ties: x before y before z) by
// (centroid on that axis, index) — a stable, deterministic order — and cut in two:
//   "median": the first ⌊n/2⌋ go left, the rest right;
//   "sah":    every cut k = 1 … n−1 of the sorted list is a candidate (left: the first k),
//             costed by the surface area heuristic
//                 C(k) = C_trav + (S_L/S)·N_L·C_isect + (S_R/S)·N_R·C_isect,
//             with S, S_L, S_R the surface areas of the node's and the two sides' bounds,
//             N_L = k, N_R = n − k, and the constants C_trav = 1, C_isect = 1 (costs in units
//             of one primitive test; a box test counted as one too). The cheapest wins (ties:
//             the smallest k); if it is not cheaper than the leaf, C_leaf = n·C_isect, no split
//             helps and the node is a leaf even with more than max_leaf primitives. S = 0 (every
//             primitive a single point) is a leaf too: no cut can separate rays.
//
// Traversal (one step per node popped): the stack starts with the root. A popped node's box is
// tested with the slab test (RayAabb; the box grown by a hair, kPad); the ray is in it for
// t ∈ [t_enter, t_exit] with t_enter = max(t_min, 0). The node is skipped when the box is missed,
// or pruned when t_enter > t_best, the closest hit so far (whatever it holds is farther). Otherwise
// a leaf's primitives are intersected (primitive.hpp: the nearest t ≥ 0), and an inner node's
// children are pushed, the far one first so the near one is popped next: left is near when d[split
// axis] ≥ 0. A hit replaces the best when t < t_best, or t = t_best with a smaller primitive index
// — the rule of the brute-force loop over all primitives, so both find the same primitive even at
// exact ties. The ray is the half-line E + t d, t ≥ 0, as in ray-aabb.
//
// The counts: box_tests = nodes popped, primitive_tests = primitives intersected; brute force
// makes n primitive tests. Without a ray only the build is stepped. Limits (a lesson's size):
// 1 to 64 primitives, max_leaf 1 to 16, every coordinate within ±1e150.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

#include "accel/primitive.hpp"
#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct Bvh {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    static constexpr std::size_t kMaxPrimitives = 64;  // a lesson's size: every node is a step
    static constexpr int kMaxLeafLimit = 16;           // max_leaf ∈ [1, 16]
    static constexpr double kTraversalCost = 1.0;      // C_trav
    static constexpr double kIntersectCost = 1.0;      // C_isect
    // A node's box is slab-tested grown by kPad × the largest |coordinate| of the box and E on
    // every side: a primitive's own test (Möller–Trumbore, the sphere's roots) may accept a
    // point a few ulps outside its bounds — a triangle's corner on the box's corner — which an
    // exact box test would then lose. 2^-36 ≈ 1.5e-11: far above rounding, far below anything
    // a picture or a hand calculation shows.
    static constexpr double kPad = 0x1p-36;

    enum class Split : std::uint8_t { Median, Sah };

    struct Input {
        std::vector<Primitive> primitives;  // 1 … kMaxPrimitives
        Split split = Split::Sah;
        int max_leaf = 2;               // a node with ≤ max_leaf primitives is a leaf
        bool has_ray = true;            // without a ray only the build is stepped
        glm::dvec3 origin{0.0};         // E
        glm::dvec3 direction{1, 0, 0};  // d ≠ 0, any length
        bool operator==(const Input&) const = default;
    };

    enum class NodeKind : std::uint8_t {
        Inner,   // split in two
        Leaf,    // ≤ max_leaf primitives
        NoGain,  // a leaf because no SAH split is cheaper than the leaf (or S = 0)
    };

    struct Node {
        Bounds bounds;             // the union of its primitives' bounds
        int first = 0, count = 0;  // its primitives: order[first … first + count − 1]
        int depth = 0;
        int parent = -1;
        int left = -1, right = -1;  // children (inner nodes)
        int axis = 0;               // the sort axis (inner nodes, and SAH leaves considered)
        int cut = 0;                // N_L: how many of the sorted primitives went left
        double cost = 0;            // the chosen split's SAH cost, or the leaf's n·C_isect
        NodeKind kind = NodeKind::Leaf;
        bool leaf() const { return kind != NodeKind::Inner; }
        bool operator==(const Node&) const = default;
    };

    struct Hit {
        int primitive = -1;  // -1: no hit
        double t = kInf;
        glm::dvec3 point{0.0};
        bool operator==(const Hit&) const = default;
    };

    struct Result {
        std::vector<Node> nodes;  // build order, the root first
        std::vector<int> order;   // primitive indices; a node's are order[first, first + count)
        Split split = Split::Sah;
        bool traced = false;  // a ray was given
        Hit hit;
        int box_tests = 0, primitive_tests = 0;
        int brute_force_tests = 0;  // n
        std::vector<int> visited;   // the nodes popped, in order (each one box test)
        bool operator==(const Result&) const = default;
    };

    // What a traversal step found at the node it popped.
    enum class Visit : std::uint8_t {
        None,
        Missed,  // the slab test misses the box
        Pruned,  // the box is hit, but t_enter > t_best
        Pushed,  // an inner node: its children pushed
        Leaf,    // a leaf: its primitives tested
    };

    // One pending build job: a range of `order` and the node it becomes.
    struct Job {
        int first = 0, count = 0, depth = 0, parent = -1;
        bool is_left = false;
        bool operator==(const Job&) const = default;
    };

    enum class Phase : std::uint8_t { Build, Trace, Report, Done };

    struct State {
        Shared<Input> in;
        Shared<std::vector<Bounds>> boxes;  // every primitive's bounds, computed once
        Phase phase = Phase::Build;
        Phase last = Phase::Build;  // the phase of the step just taken
        Result r;
        std::vector<Job> jobs;   // the build's stack
        std::vector<int> stack;  // the traversal's stack of node ids
        int node = -1;           // the node the last step made or popped
        // The last traversal step: its slab test and what it found.
        Visit visit = Visit::None;
        double t_enter = 0, t_exit = 0;
        int best_before = -1;       // the best primitive before the step
        std::vector<Visit> visits;  // what each popped node gave (parallel to r.visited)
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);   // validate, then begin
    static State begin(Shared<Input> in);  // a fresh state for a valid input
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static Result result(State&& s) { return std::move(s.r); }
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Build and trace in one call (the same numbers, no narration), for the benchmark; `in`
    // must be valid (validate).
    static Result build_and_trace(const Input& in);

    // The SAH cost of cutting a node with bounds `node` into sides with bounds `l` (n_l
    // primitives) and `r` (n_r): C_trav + (S_L/S)·N_L·C_isect + (S_R/S)·N_R·C_isect, computed
    // as C_trav + C_isect·(S_L·N_L + S_R·N_R)/S with the areas scaled by the node's longest side
    // (huge and tiny scenes neither overflow nor underflow). `node` must have a side > 0.
    static double sah_cost(const Bounds& node, const Bounds& l, int n_l, const Bounds& r, int n_r);

  private:
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
