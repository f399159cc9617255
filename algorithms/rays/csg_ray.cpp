// Sections: [text] [spec] [validate and start] [advance] [narrate]; the picture (and the
// leaves' meshes the ray tracer draws too) is in csg_ray_draw.cpp.
#include "rays/csg_ray.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "core/format.hpp"
#include "rays/ray_quadric.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec3;
using Phase = CsgRay::Phase;

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineEach = 1,
    kLineFrame,
    kLineLeaf,
    kLineMerge,
    kLineSweep,
    kLineHit,
    kLineNormal,
};

std::string end_text(double t) {
    if (t == Quadric::kInf) return "∞";
    if (t == -Quadric::kInf) return "−∞";
    return num(t);
}

// "t² − 10t + 21" (or "t^2 - 10 t + 21" for LaTeX): a quadratic in t with its signs folded in
// and its zero terms left out.
std::string quadratic_text(double a, double b, double c, bool latex = false) {
    std::string s;
    auto term = [&](double k, const char* x) {
        if (k == 0) return;
        const bool first = s.empty();
        const char* minus = latex ? "-" : "−";
        s += k < 0 ? (first ? std::string(minus) : std::string(" ") + minus + " ")
                   : (first ? "" : " + ");
        const double m = std::fabs(k);
        const bool coefficient = !(m == 1 && *x);
        if (coefficient) s += latex ? tex(m) : num(m);
        if (*x) s += std::string(coefficient && latex ? " " : "") + x;
    };
    term(a, latex ? "t^2" : "t²");
    term(b, "t");
    term(c, "");
    return s.empty() ? "0" : s;
}

bool is_translation(const dmat4& m) {
    return dmat4(glm::dmat3(m)) == dmat4(1.0);
}

}  // namespace

// ---- [text] ---------------------------------------------------------------------------------

std::string csg_spans_text(const CsgSpans& spans) {
    if (spans.empty()) return "∅";
    std::string s;
    for (const CsgSpan& sp : spans) {
        if (!s.empty()) s += " ∪ ";
        s += (std::isfinite(sp.in.t) ? "[" : "(") + end_text(sp.in.t) + ", " + end_text(sp.out.t) +
             (std::isfinite(sp.out.t) ? "]" : ")");
    }
    return s;
}

std::string csg_node_label(const CsgNode& n) {
    if (!n.name.empty()) return n.name;
    return n.leaf ? csg_leaf_label(n) : n.path;
}

std::string csg_primitive_text(const CsgNode& leaf) {
    if (leaf.kind == CsgPrimitive::Box) {
        const Box& b = leaf.box;
        return "box [" + num(b.min.x) + ", " + num(b.max.x) + "]×[" + num(b.min.y) + ", " +
               num(b.max.y) + "]×[" + num(b.min.z) + ", " + num(b.max.z) + "]";
    }
    const Quadric& q = leaf.quadric;
    std::string s;
    if (q.kind == QuadricKind::Sphere) {
        s = "sphere r = " + num(q.r);
        if (is_translation(q.world_from_model))
            return s + " centred at " + num(dvec3(q.world_from_model[3]));
        s += " (" + quadric_equation(q, false) + ")";
    } else {
        s = std::string(quadric_kind_id(q.kind)) + " " + quadric_equation(q, false);
    }
    if (std::isfinite(q.zmin) || std::isfinite(q.zmax))
        s += ", capped at " + (std::isfinite(q.zmin) ? num(q.zmin) + " ≤ z" : "z") +
             (std::isfinite(q.zmax) ? " ≤ " + num(q.zmax) : "");
    if (q.world_from_model != dmat4(1.0)) {
        if (is_translation(q.world_from_model))
            s += ", moved by " + num(dvec3(q.world_from_model[3]));
        else
            s += ", placed by its transform";
    }
    return s;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& CsgRay::spec() {
    static const Spec spec{
        "csg-ray",
        "CSG on ray segments",
        "Ray Tracing",
        {
            "for each node of the tree, its operands first:",
            "  leaf: E_m ← M⁻¹E, d_m ← M⁻¹d   ▷ M: the transforms from the root down; t unchanged",
            "        roots of F(E_m + t d_m) = 0 (a box: its slabs) → L = {[t_in, t_out] : inside}",
            "  node: L ← L_left op L_right   ▷ ∪: in A or B;  ∩: in A and B;  −: in A, not in B",
            "        sweep the ends in t order: touching segments join, empty ones vanish",
            "hit ← the first end of L_root with t > ε (the eye inside: where the ray leaves)",
            "n ← normalize((M⁻¹)ᵀ ∇F) of that end's surface; reversed if it came from a subtracted "
            "B",
        },
        {
            {"leaf", "a primitive: the ray in its frame, its roots and the segments inside it"},
            {"tangent", "the ray only touches a primitive: a zero-length segment, dropped"},
            {"leaf-miss", "the ray's line never enters a primitive: its list is empty"},
            {"union", "a union: the ray is inside A or B"},
            {"intersection", "an intersection: the ray is inside A and B"},
            {"difference", "a difference: the ray is inside A and not inside B"},
            {"hit", "the first entry point of the root's list with t > ε is the hit"},
            {"exit-hit", "the eye is inside the solid: the hit is where the ray leaves it"},
            {"miss", "no end of the root's list lies ahead of the eye: the ray misses the solid"},
        },
        {},  // no sliders
        {
            .predict =
                {
                    {"leaf", {}},
                    {"hit", {"t", "n"}},
                    {"difference", {}},
                    {"union", {}},
                    {"intersection", {}},
                },
            .mistakes =
                {
                    {"hit", "n", "negate", "kept B's outward normal where A − B shows B's inside"},
                    {"difference", "A", "swap:B", "worked out B − A instead of A − B"},
                    {"leaf", "b", "negate", "took the sign of b wrong"},
                },
            .variants =
                {
                    {"union", "/tree/op", "\"union\""},
                    {"intersection", "/tree/op", "\"intersection\""},
                    {"difference", "/tree/op", "\"difference\""},
                },
        },
    };
    return spec;
}

// ---- [validate and start] -------------------------------------------------------------------

namespace {

void check_point(dvec3 v, const std::string& field) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]))
            throw InputError(field + "[" + std::to_string(i) + "]",
                             "must be a finite number (got " + given(v[i]) + ")");
}

double max_abs(dvec3 v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

}  // namespace

void CsgRay::validate(const Input& in) {
    validate_csg(in.tree);
    check_point(in.origin, "origin");
    check_point(in.direction, "direction");
    if (in.direction == dvec3(0.0))
        throw InputError("direction", "must not be the zero vector: a ray needs a direction");
    // The ray itself must be of a size whose squares neither overflow nor underflow ...
    const double dw = max_abs(in.direction), ow = max_abs(in.origin);
    if (!(dw >= 1e-100 && dw <= 1e100))
        throw InputError("direction",
                         "is too small or too large for double precision (largest "
                         "component " +
                             given(dw) + ")");
    if (!(ow <= 1e100))
        throw InputError("origin", "is too far away for double precision (" + given(ow) + ")");
    // ... and so must it be in every leaf's frame: a transform that takes it out of range is
    // the leaf's fault.
    const PreparedCsg p = prepare_csg(in.tree);
    for (const CsgNode& n : in.tree.nodes) {
        if (!n.leaf) continue;
        const PreparedQuadric& pq = p.leaves[n.leaf_index].quadric;
        const RayQuadratic q = ray_quadratic(pq, in.origin, in.direction);
        const double d = max_abs(q.direction), o = max_abs(q.origin);
        if (!(d >= 1e-100 && d <= 1e100) || !(o <= 1e100) ||
            (n.kind == CsgPrimitive::Quadric &&
             (!std::isfinite(q.a) || !std::isfinite(q.b) || !std::isfinite(q.c) ||
              !std::isfinite(q.b * q.b - 4 * q.a * q.c))))
            throw InputError(n.path,
                             "is placed so that the ray is too large or too small for "
                             "double precision in its frame (E_m = " +
                                 given(q.origin) + ", d_m = " + given(q.direction) + ")");
    }
}

CsgRay::State CsgRay::begin(Shared<Input> in) {
    State s;
    s.prepared = Shared<PreparedCsg>(prepare_csg(in->tree));
    s.lists.resize(in->tree.nodes.size());
    s.in = std::move(in);
    return s;
}

CsgRay::State CsgRay::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

CsgRay::Result CsgRay::solve(Shared<Input> in) {
    Result r;
    const PreparedCsg p = prepare_csg(in->tree);
    csg_lists(p, in->origin, in->direction, r.lists);
    r.hit.segments = r.lists.back();
    csg_find_hit(p, in->origin, in->direction, kRayEpsilon, r.hit);
    r.in = std::move(in);
    return r;
}

// ---- [advance] ------------------------------------------------------------------------------

void CsgRay::advance(State& s) {
    const Input& in = *s.in;
    const PreparedCsg& p = *s.prepared;
    switch (s.phase) {
        case Phase::Nodes: {  // one node: a leaf's intersection, or a node's merge
            const int k = s.next++;
            const PreparedCsgNode& n = p.nodes[k];
            s.lists[k] =
                n.leaf ? leaf_spans(p.leaves[n.leaf_index], n.leaf_index, in.origin, in.direction)
                       : combine(n.op, s.lists[n.left], s.lists[n.right]);
            s.last = k;
            if (s.next == static_cast<int>(p.nodes.size())) s.phase = Phase::Hit;
            return;
        }
        case Phase::Hit: {  // the first end ahead of the eye, and its normal
            s.hit.segments = s.lists.back();
            csg_find_hit(p, in.origin, in.direction, kRayEpsilon, s.hit);
            s.last = -1;
            s.phase = Phase::Done;
            return;
        }
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

void CsgRay::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string root_list(const QuadraticRoots& r) {
    std::string s;
    for (int i = 0; i < r.count; ++i) s += (i ? ", " : "") + num(r.t[i]);
    return s;
}

// Whether the line only touches the primitive (so its empty list is a dropped zero-length one).
bool touches(const CsgNode& n, const CsgLeafTrace& tr) {
    if (n.kind == CsgPrimitive::Quadric)
        return (tr.roots.kind == QuadraticCase::Tangent && tr.quad.a > 0) ||
               tr.roots.kind == QuadraticCase::InSurface;
    const SlabHit& h = tr.slabs;
    for (int i = 0; i < 3; ++i)
        if (h.parallel_outside[i] &&
            !(n.box.min[i] <= tr.origin[i] && tr.origin[i] <= n.box.max[i]))
            return false;
    return h.t_near <= h.t_far;
}

void narrate_leaf(const CsgRay::State& s, int k, StepInfo& info) {
    const CsgRay::Input& in = *s.in;
    const CsgNode& n = in.tree.nodes[k];
    const PreparedCsgLeaf& leaf = s.prepared->leaves[n.leaf_index];
    CsgLeafTrace tr;
    leaf_spans(leaf, n.leaf_index, in.origin, in.direction, &tr);
    const CsgSpans& L = s.lists[k];
    const std::string name = csg_node_label(n);
    std::string text = name + " = " + csg_primitive_text(n) + ". ";
    if (leaf.quadric.transformed)
        text += "In its frame (M⁻¹ of the transforms from the root down) the ray is E_m = " +
                num(tr.origin) + ", d_m = " + num(tr.direction) + " (t unchanged). ";
    info.vars.push_back({"node", n.path});
    if (leaf.quadric.transformed) {
        info.vars.push_back({"E_m", vec(tr.origin)});
        info.vars.push_back({"d_m", vec(tr.direction)});
    }
    if (n.kind == CsgPrimitive::Quadric) {
        const RayQuadratic& q = tr.quad;
        const QuadraticRoots& r = tr.roots;
        text += "F(E_m + t d_m) = " + quadratic_text(q.a, q.b, q.c) + ": ";
        switch (r.kind) {
            case QuadraticCase::TwoRoots:
                text += "roots " + root_list(r) +
                        (q.a > 0 ? ", F < 0 between them" : ", F < 0 outside them (a < 0)");
                break;
            case QuadraticCase::Tangent:
                text += "a double root t = " + num(r.t[0]) +
                        (q.a > 0 ? ": the ray only touches the surface — a zero-length segment, "
                                   "dropped (a tangent touches but is never inside)"
                                 : ": F ≤ 0 all along (a < 0), touching 0 once: inside throughout");
                break;
            case QuadraticCase::NoRoots:
                text += q.a > 0 ? "Δ < 0, no root: F > 0 all along, never inside"
                                : "Δ < 0, no root: F < 0 all along (a < 0), inside throughout";
                break;
            case QuadraticCase::Linear:
                text += "a = 0, one root t = " + num(r.t[0]) + ", F < 0 on its " +
                        (q.b > 0 ? "near" : "far") + " side";
                break;
            case QuadraticCase::NoSolution:
                text += q.c < 0 ? "a = b = 0 and F = c < 0 all along: inside throughout"
                                : "a = b = 0 and F = c > 0 all along: never inside";
                break;
            case QuadraticCase::InSurface:
                text += "F = 0 all along: the line lies in the surface, never strictly inside";
                break;
        }
        if (tr.cut) {
            if (tr.z_parallel_outside)
                text += "; the ray runs parallel to the caps, outside them";
            else if (tr.direction.z != 0)
                text += "; between the caps for t in [" + end_text(tr.z_t0) + ", " +
                        end_text(tr.z_t1) + "]";
        }
        info.vars.push_back({"a", q.a});
        info.vars.push_back({"b", q.b});
        info.vars.push_back({"c", q.c});
        std::vector<double> roots(r.t.begin(), r.t.begin() + r.count);
        info.vars.push_back({"roots", roots});
        info.math = "F(E_m + t\\,d_m) = a t^2 + b t + c = " + quadratic_text(q.a, q.b, q.c, true);
    } else {
        const SlabHit& h = tr.slabs;
        const char* axes = "xyz";
        std::string slabs;
        for (int i = 0; i < 3; ++i) {
            slabs += (i ? ", " : "") + std::string(1, axes[i]) + " ";
            if (tr.direction[i] == 0)
                slabs += h.parallel_outside[i] ? "parallel, outside" : "parallel, inside";
            else
                // A direction component so small that (plane − E)/d overflows: that end is
                // beyond every double, written ∓∞ as the spans are.
                slabs += "[" + end_text(h.t0[i]) + ", " + end_text(h.t1[i]) + "]";
        }
        text += "Slabs: " + slabs + "; t_near = max = " + end_text(h.t_near) +
                ", t_far = min = " + end_text(h.t_far);
        if (!h.hit && touches(n, tr))
            text += ": the ray only touches the box — a zero-length segment, dropped";
        info.math = "t_{near} = \\max_i t_{0,i},\\quad t_{far} = \\min_i t_{1,i}";
    }
    info.line = kLineLeaf;
    if (!L.empty())
        info.event = "leaf";
    else
        info.event = touches(n, tr) ? "tangent" : "leaf-miss";
    info.narration = text + " → " + name + " = " + csg_spans_text(L) + ".";
    info.vars.push_back({"list", csg_spans_text(L)});
}

void narrate_node(const CsgRay::State& s, int k, StepInfo& info) {
    const CsgTree& t = s.in->tree;
    const CsgNode& n = t.nodes[k];
    const CsgNode &A = t.nodes[n.left], &B = t.nodes[n.right];
    const std::string a = csg_node_label(A), b = csg_node_label(B), name = csg_node_label(n);
    const char* rule = n.op == CsgOp::Union          ? "inside A or B"
                       : n.op == CsgOp::Intersection ? "inside A and B"
                                                     : "inside A and not B";
    info.event = csg_op_id(n.op);
    info.line = kLineMerge;
    const std::string expression = a + " " + csg_op_symbol(n.op) + " " + b;
    info.narration = (name == expression ? name : name + " = " + expression) + ": " + a + " = " +
                     csg_spans_text(s.lists[n.left]) + ", " + b + " = " +
                     csg_spans_text(s.lists[n.right]) +
                     "; sweeping their ends in t order and "
                     "keeping what is " +
                     rule + " gives " + name + " = " + csg_spans_text(s.lists[k]) + ".";
    if (n.op == CsgOp::Difference)
        info.narration += " An end taken from " + b + " has its normal reversed.";
    info.vars.push_back({"node", n.path});
    info.vars.push_back({a, csg_spans_text(s.lists[n.left])});
    info.vars.push_back({b, csg_spans_text(s.lists[n.right])});
    info.vars.push_back({name, csg_spans_text(s.lists[k])});
}

void narrate_hit(const CsgRay::State& s, StepInfo& info) {
    const CsgRay::Input& in = *s.in;
    const CsgHit& h = s.hit;
    const std::string root = csg_spans_text(h.segments);
    info.line = kLineHit;
    info.vars.push_back({"segments", root});
    if (!h.hit) {
        info.event = "miss";
        info.narration = "The root's list is " + root +
                         ": no end lies ahead of the eye (t > ε), so the ray misses the solid.";
        return;
    }
    const CsgNode* leaf = nullptr;
    for (const CsgNode& n : in.tree.nodes)
        if (n.leaf && n.leaf_index == h.end.leaf) leaf = &n;
    const std::string from = leaf ? csg_node_label(*leaf) : "?";
    std::string surface = "the surface of " + from;
    if (leaf && leaf->kind == CsgPrimitive::Quadric && h.end.face != 0)
        surface = std::string("the ") + (h.end.face == 1 ? "zmin" : "zmax") + " cap of " + from;
    if (leaf && leaf->kind == CsgPrimitive::Box)
        surface = "the " + std::string(h.end.face % 2 ? "max " : "min ") + "xyz"[h.end.face / 2] +
                  " face of " + from;
    info.event = h.entering ? "hit" : "exit-hit";
    info.narration =
        "The root's list is " + root + ". " +
        (h.entering ? "Its first entry point ahead of the eye is t = " + num(h.t)
                    : "The eye is inside the solid; the ray leaves it at t = " + num(h.t)) +
        ", P = E + t d = " + num(h.point) + ", on " + surface + ".";
    if (h.has_normal)
        info.narration += " Its normal there is n = " + num(h.normal) +
                          (h.end.flip ? " — reversed, because the end came from a subtracted "
                                        "operand: B's outward normal points into A − B"
                                      : "") +
                          ".";
    else
        info.narration += " The surface has no normal there (a cone's apex).";
    info.line = kLineNormal;
    info.math = "P = " + tex(in.origin) + " + " + tex(h.t) + " \\cdot " + tex(in.direction) +
                " = " + tex(h.point);
    info.vars.push_back({"t", h.t});
    info.vars.push_back({"P", vec(h.point)});
    info.vars.push_back({"from", from});
    if (h.has_normal) info.vars.push_back({"n", vec(h.normal)});
}

}  // namespace

void CsgRay::narrate(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.math.clear();
    info.vars = {{"E", vec(in.origin)}, {"d", vec(in.direction)}};
    if (s.last < 0)
        narrate_hit(s, info);
    else if (in.tree.nodes[s.last].leaf)
        narrate_leaf(s, s.last, info);
    else
        narrate_node(s, s.last, info);
}

}  // namespace cg
