// Sections: [names] [validate] [prepare] [a leaf's segments] [combining lists] [the hit]
#include "rays/csg.hpp"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>

#include "core/format.hpp"
#include "core/step.hpp"

namespace cg {

using glm::dmat3;
using glm::dmat4;
using glm::dvec3;

namespace {
constexpr double kInf = Quadric::kInf;
}

// ---- [names] --------------------------------------------------------------------------------

const char* csg_op_id(CsgOp op) {
    switch (op) {
        case CsgOp::Union:
            return "union";
        case CsgOp::Intersection:
            return "intersection";
        case CsgOp::Difference:
            return "difference";
    }
    return "?";
}

const char* csg_op_symbol(CsgOp op) {
    switch (op) {
        case CsgOp::Union:
            return "∪";
        case CsgOp::Intersection:
            return "∩";
        case CsgOp::Difference:
            return "−";
    }
    return "?";
}

std::string csg_leaf_label(const CsgNode& leaf) {
    return leaf.name.empty() ? "leaf " + std::to_string(leaf.leaf_index) : leaf.name;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

// Every node's world_from_node: the product of the transforms from the root down to it.
// Reverse post-order visits a node before its operands.
std::vector<dmat4> world_from_nodes(const CsgTree& t) {
    std::vector<dmat4> w(t.nodes.size(), dmat4(1.0));
    if (t.nodes.empty()) return w;
    w.back() = t.nodes.back().transform;
    for (std::size_t k = t.nodes.size(); k-- > 0;) {
        const CsgNode& n = t.nodes[k];
        if (n.leaf) continue;
        w[n.left] = w[k] * t.nodes[n.left].transform;
        w[n.right] = w[k] * t.nodes[n.right].transform;
    }
    return w;
}

dmat4 surface_matrix(const CsgNode& leaf, const dmat4& world_from_leaf) {
    return leaf.kind == CsgPrimitive::Quadric ? world_from_leaf * leaf.quadric.world_from_model
                                              : world_from_leaf;
}

// A composed matrix must stay invertible in double precision (Hadamard's bound, as
// validate_quadric checks each given matrix).
bool usable(const dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    const dmat3 linear(m);
    const double det = glm::determinant(linear);
    const double bound = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    if (!(std::fabs(det) > 1e-12 * bound) || !std::isfinite(det)) return false;
    const dmat3 inv = glm::inverse(linear);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(inv[c][r])) return false;
    return true;
}

}  // namespace

void validate_csg(const CsgTree& t) {
    if (t.nodes.empty()) throw InputError("tree", "is missing: a CSG tree needs at least one leaf");
    if (t.leaves > kMaxCsgLeaves)
        throw InputError("tree", "has " + std::to_string(t.leaves) + " primitives; the limit is " +
                                     std::to_string(kMaxCsgLeaves));
    for (const CsgNode& n : t.nodes) {
        if (n.depth > kMaxCsgDepth)
            throw InputError(n.path, "is " + std::to_string(n.depth) +
                                         " levels below the root; the limit is " +
                                         std::to_string(kMaxCsgDepth));
        if (n.has_transform) {  // affine, finite, invertible: what a quadric's transform must be
            Quadric frame;
            frame.world_from_model = n.transform;
            validate_quadric(frame, n.path);
        }
        if (!n.leaf) continue;
        const std::string prim = n.path + ".primitive";
        if (n.kind == CsgPrimitive::Quadric) {
            validate_quadric(n.quadric, prim);
            continue;
        }
        for (int i = 0; i < 3; ++i) {
            const std::string k = "[" + std::to_string(i) + "]";
            if (!std::isfinite(n.box.min[i]))
                throw InputError(prim + ".min" + k,
                                 "must be a finite number (got " + given(n.box.min[i]) + ")");
            if (!std::isfinite(n.box.max[i]))
                throw InputError(prim + ".max" + k,
                                 "must be a finite number (got " + given(n.box.max[i]) + ")");
            if (!(n.box.min[i] < n.box.max[i]))
                throw InputError(prim + ".max" + k,
                                 "must be greater than min" + k + " (" + given(n.box.max[i]) +
                                     " ≤ " + given(n.box.min[i]) + "): the box is empty");
        }
    }
    const std::vector<dmat4> w = world_from_nodes(t);
    for (std::size_t k = 0; k < t.nodes.size(); ++k) {
        const CsgNode& n = t.nodes[k];
        if (n.leaf && !usable(surface_matrix(n, w[k])))
            throw InputError(n.path,
                             "the transforms from the root down to this leaf multiply to a "
                             "matrix that is singular or overflows in double precision");
    }
}

// ---- [prepare] ------------------------------------------------------------------------------

glm::dmat4 csg_world_from_leaf(const CsgTree& t, int node) {
    const std::vector<dmat4> w = world_from_nodes(t);
    return surface_matrix(t.nodes[node], w[node]);
}

PreparedCsg prepare_csg(const CsgTree& t) {
    PreparedCsg p;
    const std::vector<dmat4> w = world_from_nodes(t);
    p.nodes.reserve(t.nodes.size());
    p.leaves.resize(static_cast<std::size_t>(t.leaves));
    for (std::size_t k = 0; k < t.nodes.size(); ++k) {
        const CsgNode& n = t.nodes[k];
        PreparedCsgNode pn;
        pn.leaf = n.leaf, pn.op = n.op, pn.left = n.left, pn.right = n.right;
        pn.leaf_index = n.leaf_index;
        p.nodes.push_back(pn);
        if (!n.leaf) continue;
        PreparedCsgLeaf& leaf = p.leaves[n.leaf_index];
        leaf.kind = n.kind;
        leaf.box = n.box;
        Quadric q = n.kind == CsgPrimitive::Quadric ? n.quadric : Quadric{};
        q.world_from_model = surface_matrix(n, w[k]);  // a box: only its frame is used
        leaf.quadric = prepare(q);
    }
    return p;
}

// ---- [a leaf's segments] --------------------------------------------------------------------

namespace {

CsgEnd surface_end(double t, int leaf, int face) {
    return std::isfinite(t) ? CsgEnd{t, leaf, face, false} : CsgEnd{t, -1, 0, false};
}

// Where F(E_m + t d_m) = a t² + b t + c is negative: the inside of the surface along the line.
void quadric_inside(const RayQuadratic& q, const QuadraticRoots& r, int leaf, CsgSpans& out) {
    const CsgEnd minus{-kInf, -1, 0, false}, plus{kInf, -1, 0, false};
    switch (r.kind) {
        case QuadraticCase::TwoRoots:
            if (q.a > 0) {  // a bowl in t: negative between the roots
                out.push_back({surface_end(r.t[0], leaf, 0), surface_end(r.t[1], leaf, 0)});
            } else {  // a cap in t: negative outside them (a hyperboloid, a cone's nappes)
                out.push_back({minus, surface_end(r.t[0], leaf, 0)});
                out.push_back({surface_end(r.t[1], leaf, 0), plus});
            }
            return;
        case QuadraticCase::Tangent:  // touches: never inside when a > 0, always when a < 0
        case QuadraticCase::NoRoots:
            if (q.a < 0) out.push_back({minus, plus});
            return;
        case QuadraticCase::Linear:  // b t + c < 0
            if (q.b > 0)
                out.push_back({minus, surface_end(r.t[0], leaf, 0)});
            else
                out.push_back({surface_end(r.t[0], leaf, 0), plus});
            return;
        case QuadraticCase::NoSolution:  // F = c all along the line
            if (q.c < 0) out.push_back({minus, plus});
            return;
        case QuadraticCase::InSurface:  // on the surface all along: never strictly inside
            return;
    }
}

// The spans cut to the z slab zmin ≤ z ≤ zmax of the leaf's frame (its caps).
void cut_to_slab(const PreparedQuadric& pq, dvec3 o, dvec3 d, int leaf, CsgSpans& spans,
                 CsgLeafTrace* trace) {
    const bool cut = std::isfinite(pq.zmin) || std::isfinite(pq.zmax);
    if (trace) trace->cut = cut;
    if (!cut) return;
    CsgEnd lo{-kInf, -1, 0, false}, hi{kInf, -1, 0, false};
    if (d.z == 0) {  // parallel to the caps: inside the slab everywhere or nowhere
        if (!(pq.zmin < o.z && o.z < pq.zmax)) {
            spans.clear();
            if (trace) trace->z_parallel_outside = true;
        }
        return;
    }
    lo = surface_end((pq.zmin - o.z) / d.z, leaf, 1);
    hi = surface_end((pq.zmax - o.z) / d.z, leaf, 2);
    if (lo.t > hi.t) std::swap(lo, hi);
    if (trace) trace->z_t0 = lo.t, trace->z_t1 = hi.t;
    CsgSpans kept;
    for (const CsgSpan& s : spans) {
        const CsgEnd in = lo.t > s.in.t ? lo : s.in;  // a tie stays on the curved surface
        const CsgEnd out = hi.t < s.out.t ? hi : s.out;
        if (in.t < out.t) kept.push_back({in, out});
    }
    spans.swap(kept);
}

}  // namespace

CsgSpans leaf_spans(const PreparedCsgLeaf& leaf, int leaf_index, dvec3 origin, dvec3 direction,
                    CsgLeafTrace* trace) {
    CsgSpans spans;
    const PreparedQuadric& pq = leaf.quadric;
    if (leaf.kind == CsgPrimitive::Quadric) {
        const RayQuadratic q = ray_quadratic(pq, origin, direction);
        const QuadraticRoots r = solve_quadratic(q);
        if (trace) trace->origin = q.origin, trace->direction = q.direction, trace->quad = q,
                   trace->roots = r;
        quadric_inside(q, r, leaf_index, spans);
        cut_to_slab(pq, q.origin, q.direction, leaf_index, spans, trace);
        return spans;
    }
    const dvec3 o = pq.transformed ? pq.linear_inv * (origin - pq.translation) : origin;
    const dvec3 d = pq.transformed ? pq.linear_inv * direction : direction;
    const SlabHit h = ray_slabs(leaf.box, o, d);
    if (trace) trace->origin = o, trace->direction = d, trace->slabs = h;
    if (h.hit)
        spans.push_back({surface_end(h.t_near, leaf_index, entry_face(h, d)),
                         surface_end(h.t_far, leaf_index, exit_face(h, d))});
    return spans;
}

// ---- [combining lists] ----------------------------------------------------------------------

namespace {

bool inside(CsgOp op, bool a, bool b) {
    switch (op) {
        case CsgOp::Union:
            return a || b;
        case CsgOp::Intersection:
            return a && b;
        case CsgOp::Difference:
            return a && !b;
    }
    return false;
}

// The k-th end of a list (its ends alternate in, out, in, …, strictly ascending).
const CsgEnd& end_at(const CsgSpans& s, std::size_t k) {
    return k % 2 ? s[k / 2].out : s[k / 2].in;
}

}  // namespace

// The sweep: walk both lists' ends in t order, all ends at one t together, tracking whether the
// ray is inside A and inside B; wherever op(A, B) changes, a segment of the result starts or
// stops. The end it starts or stops at is one whose own change moved op(A, B) that way (A's
// when both did): entering A, or B in a union or intersection, or leaving B in a difference
// (which flips B's normal).
CsgSpans combine(CsgOp op, const CsgSpans& a, const CsgSpans& b) {
    CsgSpans out;
    out.reserve(a.size() + b.size());
    const std::size_t na = 2 * a.size(), nb = 2 * b.size();
    std::size_t i = 0, j = 0;
    bool in_a = false, in_b = false, in_out = false;
    CsgEnd start;
    while (i < na || j < nb) {
        const double ta = i < na ? end_at(a, i).t : kInf, tb = j < nb ? end_at(b, j).t : kInf;
        const double t = std::min(ta, tb);
        const bool from_a = i < na && ta == t, from_b = j < nb && tb == t;
        const CsgEnd* ea = from_a ? &end_at(a, i) : nullptr;
        const CsgEnd* eb = from_b ? &end_at(b, j) : nullptr;
        if (from_a) in_a = i++ % 2 == 0;  // an even end is an entry
        if (from_b) in_b = j++ % 2 == 0;
        const bool now = inside(op, in_a, in_b);
        if (now == in_out) continue;
        // A's change moves op(A, B) with A; B's with B, or against it in a difference.
        const bool b_reversed = op == CsgOp::Difference;
        const bool a_moves = ea && in_a == now, b_moves = eb && (in_b != b_reversed) == now;
        const bool use_b = !a_moves && (b_moves || !ea);  // one of them moved it (see above)
        CsgEnd e = use_b ? *eb : *ea;
        if (use_b && b_reversed) e.flip = !e.flip;
        if (now) {
            start = e;
        } else {
            out.push_back({start, e});
        }
        in_out = now;
    }
    return out;
}

void csg_lists(const PreparedCsg& p, dvec3 origin, dvec3 direction, std::vector<CsgSpans>& lists) {
    lists.resize(p.nodes.size());
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
        const PreparedCsgNode& n = p.nodes[k];
        lists[k] = n.leaf ? leaf_spans(p.leaves[n.leaf_index], n.leaf_index, origin, direction)
                          : combine(n.op, lists[n.left], lists[n.right]);
    }
}

// ---- [the hit] ------------------------------------------------------------------------------

const CsgEnd* first_end_after(const CsgSpans& spans, double t_min, bool* entering) {
    for (const CsgSpan& s : spans) {
        if (s.in.t > t_min) {
            if (entering) *entering = true;
            return &s.in;
        }
        if (s.out.t > t_min) {  // the ray starts inside this segment
            if (!std::isfinite(s.out.t)) return nullptr;  // ... and never leaves
            if (entering) *entering = false;
            return &s.out;
        }
    }
    return nullptr;
}

dvec3 csg_end_normal(const PreparedCsg& p, const CsgEnd& end, dvec3 world_point) {
    const PreparedCsgLeaf& leaf = p.leaves[end.leaf];
    dvec3 n;
    if (leaf.kind == CsgPrimitive::Quadric && end.face == 0) {
        n = normal_at(leaf.quadric, world_point);
    } else {  // a flat face: the cap's ±z or the box face's ±e_i, by the inverse transpose
        const dvec3 m = leaf.kind == CsgPrimitive::Box ? box_face_normal(end.face)
                                                       : dvec3(0, 0, end.face == 1 ? -1 : 1);
        n = unit(leaf.quadric.transformed ? m * leaf.quadric.linear_inv : m);
    }
    return end.flip ? dvec3(0.0) - n : n;  // 0 − n: no −0 components
}

void csg_find_hit(const PreparedCsg& p, dvec3 origin, dvec3 direction, double t_min, CsgHit& h) {
    const CsgEnd* e = first_end_after(h.segments, t_min, &h.entering);
    if (!e) return;
    h.hit = true;
    h.end = *e;
    h.t = e->t;
    h.point = origin + e->t * direction;
    h.normal = csg_end_normal(p, *e, h.point);
    h.has_normal = h.normal != dvec3(0.0);
}

CsgHit csg_intersect(const PreparedCsg& p, dvec3 origin, dvec3 direction, double t_min) {
    std::vector<CsgSpans> lists;
    csg_lists(p, origin, direction, lists);
    CsgHit h;
    h.segments = std::move(lists.back());
    csg_find_hit(p, origin, direction, t_min, h);
    return h;
}

double csg_intersect_t(const PreparedCsg& p, dvec3 origin, dvec3 direction, double t_min) {
    std::vector<CsgSpans> lists;
    csg_lists(p, origin, direction, lists);
    const CsgEnd* e = first_end_after(lists.back(), t_min);
    return e ? e->t : kInf;
}

}  // namespace cg
