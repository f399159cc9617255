// CSG exam problems in the course's style ("the ray (0, 0, −5) + t(0, 0, 1) meets A = sphere
// (r = 2) minus B = sphere (r = 1, centre (0, 0, −1)); give each list of segments and the
// hit"). The ray runs along the z axis (now and then off it, at (3, 0) or (0, 4)), so every
// primitive is met where z is a short decimal: spheres whose distance ρ from the ray and radius
// r make a whole half-chord (r, ρ, h) = (1, 0, 1), (2, 0, 2), (3, 0, 3), (5, 3, 4), (5, 4, 3), or
// (1, 1, 0) — a tangent ray —, boxes with integer corners around the ray (or with a face through
// it: it only touches), cylinders along z with integer caps. Two or three leaves under union,
// intersection and difference, sometimes the whole tree moved by a translation; the ray's
// direction is 1 or 2 units long, so every t is a multiple of 1/2. Touching segments, an eye
// inside a primitive and misses come up by themselves.
#include <array>
#include <cmath>
#include <glm/vec2.hpp>

#include "core/format.hpp"
#include "rays/csg_ray.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;

template <class T, std::size_t N>
const T& pick(Rng& rng, const std::array<T, N>& values) {
    return values[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(N) - 1))];
}

double integer(Rng& rng, int lo, int hi) {
    return static_cast<double>(rng.integer(lo, hi));
}

glm::dmat4 translation(dvec3 t) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(t, 1.0);
    return m;
}

CsgNode leaf(Rng& rng, dvec2 ray, const std::string& name) {
    CsgNode n;
    n.name = name;
    const double kind = rng.uniform(0, 1);
    if (kind < 0.55) {  // a sphere at distance ρ from the ray
        static const std::array<std::array<double, 3>, 7> chords{
            {{1, 0, 1}, {2, 0, 2}, {3, 0, 3}, {5, 3, 4}, {5, 4, 3}, {2, 0, 2}, {1, 1, 0}}};
        const auto& c = pick(rng, chords);
        static const std::array<dvec2, 4> sides{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
        const dvec2 at = ray - c[1] * pick(rng, sides);
        n.quadric.kind = QuadricKind::Sphere;
        n.quadric.r = c[0];
        n.quadric.world_from_model = translation({at.x, at.y, integer(rng, -3, 3)});
    } else if (kind < 0.8) {  // a box around the ray, now and then with a face through it
        n.kind = CsgPrimitive::Box;
        n.box.min = {ray.x - integer(rng, 1, 2), ray.y - integer(rng, 1, 2), integer(rng, -4, 2)};
        n.box.max = {ray.x + integer(rng, 1, 2), ray.y + integer(rng, 1, 2),
                     n.box.min.z + integer(rng, 1, 4)};
        if (rng.chance(0.1)) n.box.min.x = ray.x;  // the ray runs along a face
    } else {  // a cylinder along z, capped
        n.quadric.kind = QuadricKind::Cylinder;
        n.quadric.p = n.quadric.q = ray == dvec2(0.0) ? integer(rng, 1, 3) : 5;
        n.quadric.zmin = integer(rng, -4, 0);
        n.quadric.zmax = n.quadric.zmin + integer(rng, 1, 4);
    }
    return n;
}

CsgOp op(Rng& rng) {
    return static_cast<CsgOp>(rng.integer(0, 2));
}

// Appends an internal node over the last two subtrees' roots a and b.
int join(CsgTree& t, CsgOp o, int a, int b, const std::string& name) {
    CsgNode n;
    n.leaf = false;
    n.op = o;
    n.left = a, n.right = b;
    n.name = name;
    t.nodes.push_back(n);
    return static_cast<int>(t.nodes.size()) - 1;
}

int add_leaf(CsgTree& t, CsgNode n) {
    n.leaf_index = t.leaves++;
    t.nodes.push_back(n);
    return static_cast<int>(t.nodes.size()) - 1;
}

// Paths and depths as the JSON reader would give them, from the root down.
void name_paths(CsgTree& t, int k, const std::string& path, int depth) {
    CsgNode& n = t.nodes[k];
    n.path = path;
    n.depth = depth;
    if (n.leaf) return;
    name_paths(t, n.left, path + ".left", depth + 1);
    name_paths(t, n.right, path + ".right", depth + 1);
}

}  // namespace

CsgRay::Input CsgRay::exam_input(Rng& rng) {
    Input in;
    static const std::array<dvec2, 4> off_axis{{{3, 0}, {0, 3}, {0, 4}, {4, 0}}};
    const dvec2 ray = rng.chance(0.7) ? dvec2(0.0) : pick(rng, off_axis);
    const double s = rng.chance(0.5) ? 1.0 : -1.0;
    const double L = pick(rng, std::array<double, 3>{5, 6, 8});
    in.origin = {ray.x, ray.y, -s * L};
    in.direction = {0, 0, s * (rng.chance(0.25) ? 2.0 : 1.0)};

    CsgTree& t = in.tree;
    const double shape = rng.uniform(0, 1);
    const CsgOp o1 = op(rng), o2 = op(rng);
    const std::string s1 = csg_op_symbol(o1), s2 = csg_op_symbol(o2);
    const int a = add_leaf(t, leaf(rng, ray, "A"));
    const int b = add_leaf(t, leaf(rng, ray, "B"));
    if (shape < 0.7) {  // A op B
        join(t, o1, a, b, "A " + s1 + " B");
    } else if (shape < 0.85) {  // (A op B) op C
        const int l = join(t, o1, a, b, "A " + s1 + " B");
        const int c = add_leaf(t, leaf(rng, ray, "C"));
        join(t, o2, l, c, "(A " + s1 + " B) " + s2 + " C");
    } else {  // A op (B op C)
        const int c = add_leaf(t, leaf(rng, ray, "C"));
        const int r = join(t, o2, b, c, "B " + s2 + " C");
        join(t, o1, a, r, "A " + s1 + " (B " + s2 + " C)");
    }
    if (rng.chance(0.2)) {  // the whole solid moved along the ray's line
        CsgNode& root = t.nodes.back();
        root.has_transform = true;
        root.transform = translation({0, 0, rng.chance(0.5) ? 1.0 : -2.0});
    }
    name_paths(t, static_cast<int>(t.nodes.size()) - 1, "tree", 0);
    return in;
}

std::string CsgRay::question(const Input& in) {
    const CsgTree& t = in.tree;
    std::string leaves, names;
    for (const CsgNode& n : t.nodes) {
        if (n.leaf) leaves += (leaves.empty() ? "" : "; ") + csg_node_label(n) + " = " +
                              csg_primitive_text(n);
        names += (names.empty() ? "" : ", ") + csg_node_label(n);
    }
    const CsgNode& root = t.root();
    std::string s = "The ray E + t·d = " + num(in.origin) + " + t·" + num(in.direction) +
                    " meets the solid " + csg_node_label(root) + ", where " + leaves + ".";
    if (root.has_transform)
        s += " The whole solid is moved by the root's transform, a translation by " +
             num(glm::dvec3(root.transform[3])) + ".";
    s += " Give each list of segments [t_in, t_out] where the ray is inside (lists: " + names +
         "), whether the ray hits the solid ahead of the eye (hit), and the hit's t, point "
         "E + t·d and unit normal n (t, point, normal; null where there is none).";
    return s;
}

std::vector<std::string> CsgRay::answer_fields() {
    return {"lists", "hit", "t", "point", "normal"};
}

}  // namespace cg
