// CSG on ray segments, the picture.
// 3D: the leaves' solids translucent (those under the node in hand orange), the ray, the node's
// inside segments along it thick and green and what its operation threw away red, the hit P and
// its normal (at least 30 px). The ray runs left to right across the view, seen from the side
// (orthographic), so the segments read as a cross-section; the camera frames the ray and the
// solids.
// Chart: the t axis in the ray's own units, one row per node's list named on the y axis (leaves
// first, the root's last at the bottom): each inside segment a bar, an infinite end an arrow;
// the node in hand on a pale orange band, green, and its two operands teal, with their ends'
// values; what the operation threw away thin and red; the eye at t = 0 and the hit.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "core/format.hpp"
#include "rays/csg_ray.hpp"
#include "rays/quadric_mesh.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec2;
using glm::dvec3;
using Phase = CsgRay::Phase;

dvec3 apply(const dmat4& m, dvec3 p) {
    return dvec3(m * glm::dvec4(p, 1.0));
}

}  // namespace

// A quadric's mesh between its caps (or within ±reach), a box's six faces.
void add_csg_leaf_mesh(const CsgTree& t, int k, double reach, Style style, float alpha,
                       std::vector<Face3>& faces) {
    const CsgNode& n = t.nodes[k];
    const dmat4 m = csg_world_from_leaf(t, k);
    if (n.kind == CsgPrimitive::Box) {
        const Box& b = n.box;
        auto corner = [&](int i) {
            return apply(m, {i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y,
                             i & 4 ? b.max.z : b.min.z});
        };
        static const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                        {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
        for (const auto& q : quads)
            faces.push_back({{corner(q[0]), corner(q[1]), corner(q[2]), corner(q[3])},
                             style,
                             alpha,
                             true,
                             true});
        return;
    }
    Quadric q = n.quadric;
    q.world_from_model = m;
    double z_lo, z_hi;
    drawn_z_range(q, reach, z_lo, z_hi);
    add_quadric_mesh(q, z_lo, z_hi, style, alpha, 16, 8, faces);
}

namespace {

// Whether leaf node `leaf` lies in the subtree of node `k` (post-order: a subtree is the
// contiguous run of nodes ending at its root, as long as its own leaves).
bool in_subtree(const CsgTree& t, int k, int leaf) {
    if (leaf > k) return false;
    int lo = k;
    std::vector<int> stack{k};
    while (!stack.empty()) {
        const int j = stack.back();
        stack.pop_back();
        lo = std::min(lo, j);
        if (!t.nodes[j].leaf) stack.push_back(t.nodes[j].left), stack.push_back(t.nodes[j].right);
    }
    return leaf >= lo;
}

struct Range {
    double lo = 0, hi = 1;
};

// The t range worth drawing: the eye (t = 0) and every finite end computed so far.
Range t_range(const CsgRay::State& s) {
    Range r{0, 0};
    for (const CsgSpans& l : s.lists)
        for (const CsgSpan& sp : l)
            for (double t : {sp.in.t, sp.out.t})
                if (std::isfinite(t) && std::fabs(t) < 1e12)
                    r.lo = std::min(r.lo, t), r.hi = std::max(r.hi, t);
    if (!(r.hi > r.lo)) r.hi = r.lo + 1;
    const double pad = 0.12 * (r.hi - r.lo);
    r.lo -= pad, r.hi += pad;
    return r;
}

// One list on the chart at height y: its bars (an infinite end an arrow to the edge), and the
// ends' values when `values`.
void chart_row(const CsgSpans& l, double y, Range r, Style bar, bool values, Panel& chart) {
    for (const CsgSpan& sp : l) {
        const double a = std::max(r.lo, sp.in.t), b = std::min(r.hi, sp.out.t);
        if (!(a < b)) continue;
        chart.segments.push_back({{a, y}, {b, y}, "", bar, !std::isfinite(sp.out.t)});
        if (!std::isfinite(sp.in.t))  // −∞: an arrowhead at the left edge too
            chart.segments.push_back({{0.5 * (a + b), y}, {a, y}, "", bar, true});
        if (!values) continue;
        if (std::isfinite(sp.in.t))
            chart.labels.push_back({{a, y - 0.3}, num(sp.in.t, 4), {Role::Entering}});
        if (std::isfinite(sp.out.t))
            chart.labels.push_back({{b, y - 0.3}, num(sp.out.t, 4), {Role::Leaving}});
    }
}

// Looking across the ray, orthographic, the ray pointing right and world y (or z) up.
ViewHint3 side_view(dvec3 d) {
    const dvec3 dn = glm::normalize(d);
    dvec3 up = std::fabs(dn.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(0, 0, 1);
    up = glm::normalize(up - glm::dot(up, dn) * dn);
    return {glm::cross(up, dn), up, true};
}

}  // namespace

void CsgRay::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const CsgTree& t = in.tree;
    const Range r = t_range(s);
    const dvec3 E = in.origin, d = in.direction;
    const double speed = glm::length(d);
    const double reach = std::max(2.0, 0.6 * (r.hi - r.lo) * speed + glm::length(E));
    const int focus = s.last >= 0 ? s.last : static_cast<int>(t.nodes.size()) - 1;
    const bool done = s.phase == Phase::Done;

    // ---- 3D ----
    dvec3 lo = glm::min(E + r.lo * d, E + r.hi * d), hi = glm::max(E + r.lo * d, E + r.hi * d);
    for (std::size_t k = 0; k < t.nodes.size(); ++k) {
        if (!t.nodes[k].leaf) continue;
        const bool active = s.last >= 0 && in_subtree(t, focus, static_cast<int>(k));
        const std::size_t first = scene.faces3.size();
        add_csg_leaf_mesh(t, static_cast<int>(k), reach,
                          {active ? Role::Active : Role::Subject, 1.0f}, active ? 0.22f : 0.12f,
                          scene.faces3);
        for (std::size_t f = first; f < scene.faces3.size(); ++f)
            for (const dvec3& p : scene.faces3[f].points)
                lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    add_focus(scene, lo, hi);
    if (speed > 0) scene.view3 = side_view(d);

    scene.segments3.push_back(
        {E + r.lo * d, E + r.hi * d, "E + t d", {Role::Construction, 1.0f}, true});
    scene.points3.push_back({E, "E", {Role::Neutral}, 5.0f});
    const bool computed = s.last >= 0 || done;
    if (computed) {
        const CsgSpans& now = s.lists[focus];
        auto along = [&](const CsgSpans& l, Role role, float width) {
            for (const CsgSpan& sp : l) {
                const double a = std::max(r.lo, sp.in.t), b = std::min(r.hi, sp.out.t);
                if (!(a < b)) continue;
                scene.segments3.push_back({E + a * d, E + b * d, "", {role, width}, false});
                if (std::isfinite(sp.in.t)) scene.points3.push_back({E + a * d, "", {role}, 4.0f});
                if (std::isfinite(sp.out.t)) scene.points3.push_back({E + b * d, "", {role}, 4.0f});
            }
        };
        const CsgNode& n = t.nodes[focus];
        if (!n.leaf && s.last >= 0) {  // what the operation threw away, then what it kept
            const CsgSpans all = combine(CsgOp::Union, s.lists[n.left], s.lists[n.right]);
            along(combine(CsgOp::Difference, all, now), Role::Discarded, 4.0f);
        }
        along(now, Role::Kept, 5.0f);
    }
    if (done && s.hit.hit) {
        scene.points3.push_back({s.hit.point, "P", {Role::Active}, 7.0f, 2});
        if (s.hit.has_normal)
            scene.segments3.push_back({s.hit.point,
                                       s.hit.point + 0.25 * reach * s.hit.normal,
                                       "n",
                                       {Role::Active, 2.5f},
                                       true,
                                       30.0f,
                                       2});
    }
    scene.extent3 = 0.6 * reach;

    // ---- the chart: one row per list, the t axis in the ray's units ----
    std::vector<int> rows;
    const int computed_nodes = s.phase == Phase::Nodes ? s.next : static_cast<int>(t.nodes.size());
    if (computed_nodes <= 15) {
        for (int k = 0; k < computed_nodes; ++k) rows.push_back(k);
    } else if (s.last >= 0) {  // a big tree: only the step in hand
        const CsgNode& n = t.nodes[s.last];
        if (!n.leaf) rows = {n.left, n.right};
        rows.push_back(s.last);
    } else {
        rows.push_back(static_cast<int>(t.nodes.size()) - 1);
    }
    const int count = std::max<int>(1, static_cast<int>(rows.size()));
    // Row i at y = count − 1 − i (leaves on top, the root below), named on the y axis.
    // Short names, so the axis leaves the bars room: a node's own name, else its expression
    // ("pip 2 ∪ pip 3", not "tree.right.right"); the node in hand also with its expression.
    std::vector<std::string> names(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const CsgNode& n = t.nodes[rows[i]];
        std::string name = csg_node_label(n);
        if (!n.leaf) {
            const std::string expr = csg_node_label(t.nodes[n.left]) + " " + csg_op_symbol(n.op) +
                                     " " + csg_node_label(t.nodes[n.right]);
            if (n.name.empty())
                name = expr;
            else if (rows[i] == s.last && expr != name)
                name += " = " + expr;
        }
        names[static_cast<std::size_t>(count) - 1 - i] = name;
    }
    Axis y_axis{"", -0.9, count - 0.5};
    y_axis.names = std::move(names);
    Panel& chart = add_chart(scene, "each node's inside segments along the ray",
                             Axis{"t", r.lo, r.hi}, std::move(y_axis));
    chart.weight = 1.3;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const int k = rows[i];
        const double y = count - 1 - static_cast<double>(i);
        const CsgNode& n = t.nodes[k];
        const bool node = k == s.last || (s.last < 0 && done && k == focus);
        const bool operand = s.last >= 0 && !t.nodes[s.last].leaf &&
                             (k == t.nodes[s.last].left || k == t.nodes[s.last].right);
        const Style bar = node      ? Style{Role::Kept, 7.0f}
                          : operand ? Style{Role::Entering, 5.0f}
                                    : Style{Role::Subject, 4.0f};
        if (node)  // the row in hand on a pale orange band
            chart.polygons.push_back(
                {{{r.lo, y - 0.3}, {r.hi, y - 0.3}, {r.hi, y + 0.3}, {r.lo, y + 0.3}},
                 {Role::Active, 0.0f},
                 true,
                 true});
        chart_row(s.lists[k], y, r, bar, node || operand, chart);
        if (node && !n.leaf && s.last >= 0) {  // what the operation threw away, thin and red
            const CsgSpans all = combine(CsgOp::Union, s.lists[n.left], s.lists[n.right]);
            for (const CsgSpan& sp : combine(CsgOp::Difference, all, s.lists[k])) {
                const double a = std::max(r.lo, sp.in.t), b = std::min(r.hi, sp.out.t);
                if (a < b)
                    chart.segments.push_back(
                        {{a, y}, {b, y}, "", {Role::Discarded, 2.5f, true}, false});
            }
        }
    }
    // The eye at t = 0, and the hit.
    chart.segments.push_back({{0, -0.9}, {0, count - 0.5}, "", {Role::Construction, 1.0f, true}});
    chart.labels.push_back({{0, count - 0.6}, "eye", {Role::Construction}});
    if (done && s.hit.hit) {
        chart.segments.push_back(
            {{s.hit.t, -0.9}, {s.hit.t, count - 0.5}, "", {Role::Kept, 1.5f, true}, false});
        chart.points.push_back(
            {{s.hit.t, 0}, "hit t = " + num(s.hit.t, 4), {Role::Active}, 6.0f, 3});
    }
}

}  // namespace cg
