// Two independent references for CSG on ray segments, sharing no code with rays/csg.cpp:
//
// 1. Exact intervals in long double, written another way: each leaf's surface carried to the
//    world as a 4×4 matrix Q_w = M⁻ᵀ Q M⁻¹ (quadric_reference.hpp, with M the product of the
//    tree's transforms multiplied here in long double), the inside found by testing the sign of
//    F between consecutive roots (not by cases on a), the caps and box faces as planes in the
//    leaf's frame; lists combined by cutting the line at every end of both operands and
//    classifying each piece's midpoint, then joining neighbouring pieces.
// 2. Brute force: a point of the ray classified inside or outside every primitive (F < 0 in the
//    leaf's frame, within the caps; strictly inside the box) and the tree evaluated as booleans.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "rays/csg.hpp"
#include "rays/quadric_reference.hpp"

namespace cg::test {

using LSpan = std::pair<long double, long double>;
using LSpans = std::vector<LSpan>;
constexpr long double kLInf = std::numeric_limits<long double>::infinity();

struct LeafFrame {
    LMat world_from_model{}, model_from_world{};
};

inline LMat lidentity() {
    LMat m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1;
    return m;
}

// Each leaf's world_from_model: the product down the tree, recursively from the root.
inline void frames(const CsgTree& t, int k, const LMat& above, std::vector<LeafFrame>& out) {
    const CsgNode& n = t.nodes[k];
    const LMat here = mul(above, lmat(n.transform));
    if (!n.leaf) {
        frames(t, n.left, here, out);
        frames(t, n.right, here, out);
        return;
    }
    LeafFrame f;
    f.world_from_model =
        n.kind == CsgPrimitive::Quadric ? mul(here, lmat(n.quadric.world_from_model)) : here;
    f.model_from_world = inverse(f.world_from_model);
    out[n.leaf_index] = f;
}

inline std::vector<LeafFrame> leaf_frames(const CsgTree& t) {
    std::vector<LeafFrame> f(static_cast<std::size_t>(t.leaves));
    frames(t, static_cast<int>(t.nodes.size()) - 1, lidentity(), f);
    return f;
}

struct LRay {
    LVec E, D;  // world, homogeneous (w = 1, w = 0)
};

inline LRay model_ray(const LeafFrame& f, const LRay& r) {
    return {mul(f.model_from_world, r.E), mul(f.model_from_world, r.D)};
}

// Intersect [lo, hi] with a list.
inline LSpans clip(const LSpans& in, long double lo, long double hi) {
    LSpans out;
    for (const LSpan& s : in) {
        const long double a = std::max(s.first, lo), b = std::min(s.second, hi);
        if (a < b) out.push_back({a, b});
    }
    return out;
}

// Where the model-space coordinate `axis` of the ray lies strictly within (lo, hi).
inline LSpans between(const LRay& m, int axis, long double lo, long double hi) {
    const long double o = m.E[axis], d = m.D[axis];
    if (d == 0) return (lo < o && o < hi) ? LSpans{{-kLInf, kLInf}} : LSpans{};
    long double a = (lo - o) / d, b = (hi - o) / d;
    if (a > b) std::swap(a, b);  // ±∞ bounds divide to the right signed infinities
    return a < b ? LSpans{{a, b}} : LSpans{};
}

inline LSpans reference_leaf(const CsgNode& n, const LeafFrame& f, const LRay& ray) {
    const LRay m = model_ray(f, ray);
    if (n.kind == CsgPrimitive::Box) {
        LSpans s{{-kLInf, kLInf}};
        for (int i = 0; i < 3; ++i) {
            const LSpans b = between(m, i, n.box.min[i], n.box.max[i]);
            if (b.empty()) return {};
            s = clip(s, b[0].first, b[0].second);
        }
        return s;
    }
    const LMat Qw = mul(transpose(f.model_from_world), mul(model_matrix(n.quadric),
                                                           f.model_from_world));
    const long double a = dot(ray.D, mul(Qw, ray.D)), b = 2 * dot(ray.D, mul(Qw, ray.E)),
                      c = dot(ray.E, mul(Qw, ray.E));
    std::vector<long double> roots;
    if (a != 0) {
        const long double disc = b * b - 4 * a * c;
        if (disc > 0) {
            const long double s = std::sqrt(disc);
            const long double q = -0.5L * (b + (b < 0 ? -s : s));
            roots = {q / a, c / q};
            std::sort(roots.begin(), roots.end());
        }
    } else if (b != 0) {
        roots = {-c / b};
    }
    // The sign of F on each piece between roots, at a point inside the piece.
    auto F = [&](long double t) { return (a * t + b) * t + c; };
    std::vector<long double> cuts{-kLInf};
    cuts.insert(cuts.end(), roots.begin(), roots.end());
    cuts.push_back(kLInf);
    LSpans inside;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const long double lo = cuts[i], hi = cuts[i + 1];
        const long double probe = !std::isfinite(lo) && !std::isfinite(hi) ? 0
                                  : !std::isfinite(lo)                     ? hi - 1
                                  : !std::isfinite(hi)                     ? lo + 1
                                                                           : (lo + hi) / 2;
        if (F(probe) < 0) {
            if (!inside.empty() && inside.back().second == lo)
                inside.back().second = hi;
            else
                inside.push_back({lo, hi});
        }
    }
    const LSpans slab = between(m, 2, n.quadric.zmin, n.quadric.zmax);
    if (slab.empty()) return {};
    return clip(inside, slab[0].first, slab[0].second);
}

inline bool in_list(const LSpans& s, long double t) {
    for (const LSpan& x : s)
        if (x.first < t && t < x.second) return true;
    return false;
}

inline bool op_inside(CsgOp op, bool a, bool b) {
    return op == CsgOp::Union ? (a || b) : op == CsgOp::Intersection ? (a && b) : (a && !b);
}

// Cut at every end of both lists, classify each piece's midpoint, join neighbours.
inline LSpans reference_combine(CsgOp op, const LSpans& A, const LSpans& B) {
    std::vector<long double> cuts{-kLInf, kLInf};
    for (const LSpans* l : {&A, &B})
        for (const LSpan& s : *l) cuts.push_back(s.first), cuts.push_back(s.second);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    LSpans out;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const long double lo = cuts[i], hi = cuts[i + 1];
        const long double mid = !std::isfinite(lo) && !std::isfinite(hi) ? 0
                                : !std::isfinite(lo)                     ? hi - 1
                                : !std::isfinite(hi)                     ? lo + 1
                                                                         : (lo + hi) / 2;
        if (!op_inside(op, in_list(A, mid), in_list(B, mid))) continue;
        if (!out.empty() && out.back().second == lo)
            out.back().second = hi;
        else
            out.push_back({lo, hi});
    }
    return out;
}

inline LSpans reference_node(const CsgTree& t, int k, const std::vector<LeafFrame>& f,
                             const LRay& ray) {
    const CsgNode& n = t.nodes[k];
    if (n.leaf) return reference_leaf(n, f[n.leaf_index], ray);
    return reference_combine(n.op, reference_node(t, n.left, f, ray),
                             reference_node(t, n.right, f, ray));
}

inline LSpans reference_segments(const CsgTree& t, glm::dvec3 o, glm::dvec3 d) {
    const std::vector<LeafFrame> f = leaf_frames(t);
    const LRay ray{{o.x, o.y, o.z, 1}, {d.x, d.y, d.z, 0}};
    return reference_node(t, static_cast<int>(t.nodes.size()) - 1, f, ray);
}

// ---- brute force ------------------------------------------------------------------------------

inline bool point_inside(const CsgNode& n, const LeafFrame& f, const LVec& P) {
    const LVec m = mul(f.model_from_world, P);
    if (n.kind == CsgPrimitive::Box) {
        for (int i = 0; i < 3; ++i)
            if (!(n.box.min[i] < m[i] && m[i] < n.box.max[i])) return false;
        return true;
    }
    if (!(n.quadric.zmin < m[2] && m[2] < n.quadric.zmax)) return false;
    return dot(m, mul(model_matrix(n.quadric), m)) < 0;
}

inline bool tree_inside(const CsgTree& t, int k, const std::vector<LeafFrame>& f, const LVec& P) {
    const CsgNode& n = t.nodes[k];
    if (n.leaf) return point_inside(n, f[n.leaf_index], P);
    return op_inside(n.op, tree_inside(t, n.left, f, P), tree_inside(t, n.right, f, P));
}

}  // namespace cg::test
