// BVH exam problems: 4 to 6 spheres of radius 1 (or ½) with integer centres, spread along a
// line or a plane so that the longest centroid axis is clear; the median split with max_leaf 1
// or 2 (worked by sorting, no areas); a ray along an axis or a diagonal with small integer
// components, aimed at one sphere, between two, or past them all. The student gives the leaves
// (left to right), the nodes whose boxes the ray tests (the popped nodes, in order) and the
// primitive it hits.
#include <algorithm>

#include "accel/bvh.hpp"
#include "core/format.hpp"

namespace cg {

Bvh::Input Bvh::exam_input(Rng& rng) {
    Input in;
    in.split = Split::Median;
    in.max_leaf = static_cast<int>(rng.integer(1, 2));
    const int n = static_cast<int>(rng.integer(4, 6));
    const bool plane = rng.chance(0.5);
    const double radius = rng.chance(0.75) ? 1.0 : 0.5;
    // Distinct centres on a grid with spacing 3 (x from 0 to 15; y 0, 4 or 8 in a plane), so
    // that no two spheres overlap and the centroid order along x is strict.
    std::vector<int> xs;
    for (int x = 0; x <= 5; ++x) xs.push_back(3 * x);
    for (int i = 5; i > 0; --i) std::swap(xs[i], xs[rng.integer(0, i)]);
    for (int i = 0; i < n; ++i) {
        Primitive p;
        p.kind = PrimitiveKind::Sphere;
        p.radius = radius;
        p.a = glm::dvec3(xs[i], plane ? 4.0 * static_cast<double>(rng.integer(0, 1)) : 0.0, 0);
        in.primitives.push_back(p);
    }
    // The ray: from the left along +x at a sphere row, from above along −y at a column, a
    // diagonal, or one that misses.
    in.has_ray = true;
    const Primitive& target = in.primitives[rng.integer(0, n - 1)];
    switch (rng.integer(0, 3)) {
        case 0:
            in.origin = {-3, target.a.y, 0}, in.direction = {1, 0, 0};
            break;
        case 1:
            in.origin = {target.a.x, 12, 0}, in.direction = {0, -1, 0};
            break;
        case 2:
            in.origin = target.a - glm::dvec3(4, 4, 0), in.direction = {1, 1, 0};
            break;
        default:
            in.origin = {-3, target.a.y, 3}, in.direction = {1, 0, 0};  // passes above: a miss
            break;
    }
    if (rng.chance(0.25)) in.direction = -in.direction, in.origin = 2.0 * target.a - in.origin;
    return in;
}

std::string Bvh::question(const Input& in) {
    std::string list;
    bool spheres = true;
    for (std::size_t i = 0; i < in.primitives.size(); ++i) {
        list += (i ? "; " : "") + std::to_string(i) + ": " + describe(in.primitives[i]);
        spheres = spheres && in.primitives[i].kind == PrimitiveKind::Sphere;
    }
    const std::string what = spheres ? "spheres" : "primitives";
    std::string q =
        "Build a bounding volume hierarchy over these " + what + " (" + list + ") with ";
    q += in.split == Split::Median
             ? "the median split: a node with at most max_leaf = " + std::to_string(in.max_leaf) +
                   " primitives is a leaf; otherwise sort its primitives by their centre along "
                   "the axis where the centres spread most (ties: x, then y, then z; equal "
                   "centres by index) and send the first ⌊n/2⌋ left, the rest right."
             : "the surface area heuristic: a node with at most max_leaf = " +
                   std::to_string(in.max_leaf) +
                   " primitives is a leaf; otherwise sort its primitives by the centre of their "
                   "bounding boxes along the axis where the centres spread most (ties: x, then "
                   "y, then z; equal centres by index), cost every cut k = 1 … n−1 (the first k "
                   "left) by C(k) = 1 + (S_L/S)·N_L + (S_R/S)·N_R (S: surface areas of the "
                   "boxes) and take the cheapest (ties: the smallest k) — unless it is not below "
                   "n, the cost of a leaf, which then keeps them all.";
    q += " Number the nodes in the order they are made, depth first, the left child first (the "
         "root is node 0).";
    if (!in.has_ray)
        return q +
               " Give the leaves left to right (leaves: a list of lists of primitive indices, "
               "each ascending).";
    return q + " Then trace the ray P(t) = E + t d, t ≥ 0, with E = " + num(in.origin) +
           " and d = " + num(in.direction) +
           ": start with the stack [0]; pop a node and test its box (the slab test); skip it if "
           "missed or if it is entered beyond the closest hit so far; at a leaf test its " +
           what +
           "; at an inner node push the far child, then the near one (the left child is near "
           "when d's component along the node's split axis is ≥ 0). Give the leaves left to "
           "right (leaves: a list of lists of primitive indices, each ascending), the nodes "
           "popped in order (visited), and the primitive hit first (hit/primitive, null for "
           "none; on a tie in t the smaller index).";
}

std::vector<std::string> Bvh::answer_fields(const Input& in) {
    if (!in.has_ray) return {"leaves"};
    return {"leaves", "visited", "hit/primitive"};
}

}  // namespace cg
