#include "rays/rt_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>

namespace cg::rt {

using glm::dvec3;

std::size_t MeshBvh::bytes() const {
    return nodes.size() * sizeof(MeshNode) + triangles.size() * sizeof(MeshTriangle) +
           ids.size() * sizeof(std::uint32_t);
}

namespace {

constexpr int kBins = 32;
constexpr float kTraversalCost = 1;  // C_trav, in triangle tests
constexpr int kMaxLeaf = 16;         // a node larger than this is always split
constexpr int kMedianDepth = 40;     // below this depth, split by the middle of the list
constexpr int kParallelMin = 4096;   // a root this large builds its subtrees on two threads

// A float box; empty when lo > hi.
struct Box {
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    void grow(const Box& b) {
        for (int a = 0; a < 3; ++a)
            lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
    }
    float area() const {
        const float x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
        return 2 * (x * y + y * z + z * x);
    }
};

// The float nearest to v on the side that keeps the box containing v.
float down(double v) {
    float f = static_cast<float>(v);
    return f > v ? std::nextafter(f, -INFINITY) : f;
}
float up(double v) {
    float f = static_cast<float>(v);
    return f < v ? std::nextafter(f, INFINITY) : f;
}

struct Prim {
    Box box;
    float centre[3];
};

struct Ref {
    std::int32_t index = 0, count = 0;  // count 0: a node
};

struct Builder {
    std::vector<Prim>& prims;
    std::vector<std::uint32_t>& order;  // triangle indices, partitioned as the tree is built
};

struct Split {
    int axis = -1, bin = 0;
    float lo = 0, scale = 0;  // bin of c: (c − lo) · scale
    Box left, right;
    int left_count = 0;
};

int bin_of(float c, float lo, float scale) {
    return std::clamp(static_cast<int>((c - lo) * scale), 0, kBins - 1);
}

// The SAH's best bin boundary over the three axes, or axis −1 when no cut beats a leaf (count
// small enough) or every centre is in one place.
Split best_split(const Builder& B, int begin, int end, const Box& box) {
    Box centres;
    for (int k = begin; k < end; ++k) {
        const Prim& p = B.prims[B.order[k]];
        for (int a = 0; a < 3; ++a)
            centres.lo[a] = std::min(centres.lo[a], p.centre[a]),
            centres.hi[a] = std::max(centres.hi[a], p.centre[a]);
    }
    std::array<std::array<Box, kBins>, 3> bin_box;
    std::array<std::array<int, kBins>, 3> bin_count{};
    float lo[3], scale[3];
    for (int a = 0; a < 3; ++a) {
        const float extent = centres.hi[a] - centres.lo[a];
        lo[a] = centres.lo[a];
        scale[a] = extent > 0 ? kBins * (1 - 1e-6f) / extent : 0;
    }
    for (int k = begin; k < end; ++k) {
        const Prim& p = B.prims[B.order[k]];
        for (int a = 0; a < 3; ++a) {
            const int b = bin_of(p.centre[a], lo[a], scale[a]);
            bin_box[a][b].grow(p.box);
            ++bin_count[a][b];
        }
    }
    const int n = end - begin;
    const float area = box.area();
    Split best;
    float best_cost = n <= kMaxLeaf ? static_cast<float>(n) : INFINITY;
    for (int a = 0; a < 3; ++a) {
        if (scale[a] == 0) continue;
        std::array<float, kBins> right_area{};
        std::array<int, kBins> right_count{};
        Box acc;
        int m = 0;
        for (int b = kBins - 1; b > 0; --b) {
            acc.grow(bin_box[a][b]);
            m += bin_count[a][b];
            right_area[b] = acc.area();
            right_count[b] = m;
        }
        acc = Box{};
        m = 0;
        for (int b = 1; b < kBins; ++b) {  // boundary b: bins [0, b) left, [b, kBins) right
            acc.grow(bin_box[a][b - 1]);
            m += bin_count[a][b - 1];
            if (m == 0 || right_count[b] == 0) continue;
            const float cost =
                area > 0 ? kTraversalCost + (acc.area() * m + right_area[b] * right_count[b]) / area
                         : kTraversalCost + n;
            if (cost < best_cost) {
                best_cost = cost;
                best.axis = a, best.bin = b, best.lo = lo[a], best.scale = scale[a];
                best.left_count = m;
            }
        }
    }
    if (best.axis >= 0) {
        for (int b = 0; b < kBins; ++b)
            (b < best.bin ? best.left : best.right).grow(bin_box[best.axis][b]);
    }
    return best;
}

Box range_box(const Builder& B, int begin, int end) {
    Box box;
    for (int k = begin; k < end; ++k) box.grow(B.prims[B.order[k]].box);
    return box;
}

void set_child(MeshNode& n, int k, const Box& b, Ref r) {
    for (int a = 0; a < 3; ++a) n.lo[a][k] = b.lo[a], n.hi[a][k] = b.hi[a];
    n.child[k] = r.index;
    n.count[k] = r.count;
}

// Builds the subtree over order[begin, end) (its box given) into `nodes`, whose first node has
// global index `base`; returns its reference. Nodes are laid out depth first, left before right.
Ref build(const Builder& B, std::vector<MeshNode>& nodes, int base, int begin, int end,
          const Box& box, int level, int& depth, int threads) {
    depth = std::max(depth, level);
    const int n = end - begin;
    if (n == 1) return {begin, 1};
    Split s;
    int mid;
    if (level < kMedianDepth) s = best_split(B, begin, end, box);
    if (s.axis >= 0) {
        auto first = B.order.begin() + begin, last = B.order.begin() + end;
        mid = static_cast<int>(std::partition(first, last,
                                              [&](std::uint32_t t) {
                                                  return bin_of(B.prims[t].centre[s.axis], s.lo,
                                                                s.scale) < s.bin;
                                              }) -
                               B.order.begin());
    } else {
        if (n <= kMaxLeaf) return {begin, n};
        mid = begin + n / 2;  // every centre in one place (or deep): the middle of the list
        s.left = range_box(B, begin, mid);
        s.right = range_box(B, mid, end);
    }
    const int index = static_cast<int>(nodes.size());
    nodes.emplace_back();
    Ref left, right;
    if (threads > 1 && n >= kParallelMin) {
        // The right subtree on a second thread, into its own nodes (indices from 0, moved after).
        std::vector<MeshNode> right_nodes;
        int right_depth = 0;
        std::thread worker([&] {
            right = build(B, right_nodes, 0, mid, end, s.right, level + 1, right_depth, 1);
        });
        left = build(B, nodes, base, begin, mid, s.left, level + 1, depth, 1);
        worker.join();
        const int offset = base + static_cast<int>(nodes.size());
        for (MeshNode& m : right_nodes)
            for (int k = 0; k < 2; ++k)
                if (m.count[k] == 0) m.child[k] += offset;
        if (right.count == 0) right.index += offset;
        nodes.insert(nodes.end(), right_nodes.begin(), right_nodes.end());
        depth = std::max(depth, right_depth);
    } else {
        left = build(B, nodes, base, begin, mid, s.left, level + 1, depth, 1);
        right = build(B, nodes, base, mid, end, s.right, level + 1, depth, 1);
    }
    set_child(nodes[index], 0, s.left, left);
    set_child(nodes[index], 1, s.right, right);
    return {base + index, 0};
}

}  // namespace

MeshBvh build_mesh_bvh(const mesh::Mesh& m, int threads) {
    if (threads <= 0) threads = 2;
    MeshBvh out;
    const std::size_t n = m.triangles.size();
    std::vector<Prim> prims(n);
    std::vector<std::uint32_t> order(n);
    for (std::size_t k = 0; k < n; ++k) {
        const dvec3 &a = m.vertices[m.triangles[k][0]], &b = m.vertices[m.triangles[k][1]],
                    &c = m.vertices[m.triangles[k][2]];
        double big = 0;
        for (int i = 0; i < 3; ++i)
            big = std::max({big, std::fabs(a[i]), std::fabs(b[i]), std::fabs(c[i])});
        const double pad = std::ldexp(big, -30);
        Prim& p = prims[k];
        for (int i = 0; i < 3; ++i) {
            p.box.lo[i] = down(std::min({a[i], b[i], c[i]}) - pad);
            p.box.hi[i] = up(std::max({a[i], b[i], c[i]}) + pad);
            p.centre[i] = 0.5f * p.box.lo[i] + 0.5f * p.box.hi[i];
        }
        order[k] = static_cast<std::uint32_t>(k);
    }
    if (n == 0) return out;
    const Builder B{prims, order};
    const Box root = range_box(B, 0, static_cast<int>(n));
    for (int a = 0; a < 3; ++a) out.root_lo[a] = root.lo[a], out.root_hi[a] = root.hi[a];
    out.nodes.reserve(n / 2 + 1);
    int depth = 0;
    const Ref r = build(B, out.nodes, 0, 0, static_cast<int>(n), root, 1, depth, threads);
    out.root = r.index;
    out.root_count = r.count;
    out.depth = depth;
    out.triangles.resize(n);
    out.ids = std::move(order);
    for (std::size_t k = 0; k < n; ++k) {
        const auto& t = m.triangles[out.ids[k]];
        const dvec3 p0 = m.vertices[t[0]];
        out.triangles[k] = {p0, m.vertices[t[1]] - p0, m.vertices[t[2]] - p0};
    }
    return out;
}

namespace {

// The ray as the slab tests want it (rt_bvh.hpp's BoxRay: 1/0 taken as ±10³⁰⁰, never NaN).
struct SlabRay {
    double o[3], inv[3];
};

SlabRay slab_ray(dvec3 origin, dvec3 d) {
    SlabRay r;
    for (int a = 0; a < 3; ++a) {
        r.o[a] = origin[a];
        const double inv = 1 / d[a];
        r.inv[a] = std::isfinite(inv) ? inv : std::copysign(1e300, d[a]);
    }
    return r;
}

// Where the ray enters each child's box within [t0, t1], or +∞ for a miss; both at once.
inline void child_entries(const MeshNode& n, const SlabRay& r, double t0, double t1,
                          double out[2]) {
    double near[2] = {t0, t0}, far[2] = {t1, t1};
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 2; ++k) {
            double x = (n.lo[a][k] - r.o[a]) * r.inv[a], y = (n.hi[a][k] - r.o[a]) * r.inv[a];
            if (x > y) std::swap(x, y);
            near[k] = std::max(near[k], x);
            far[k] = std::min(far[k], y);
        }
    for (int k = 0; k < 2; ++k) out[k] = near[k] <= far[k] ? near[k] : INFINITY;
}

double root_entry(const MeshBvh& b, const SlabRay& r, double t0, double t1) {
    for (int a = 0; a < 3; ++a) {
        double x = (b.root_lo[a] - r.o[a]) * r.inv[a], y = (b.root_hi[a] - r.o[a]) * r.inv[a];
        if (x > y) std::swap(x, y);
        t0 = std::max(t0, x);
        t1 = std::min(t1, y);
    }
    return t0 <= t1 ? t0 : INFINITY;
}

// Front-to-back traversal; leaf(first, count) returns true to stop; limit() is the best t.
template <class Leaf, class Limit>
void walk(const MeshBvh& bvh, const SlabRay& r, double t_min, Limit limit, Leaf leaf,
          long long* box_tests) {
    if (bvh.triangles.empty()) return;
    struct Entry {
        std::int32_t index, count;
        double t;
    };
    Entry stack[2 * kMedianDepth + 64];
    int top = 0;
    const double t_root = root_entry(bvh, r, t_min, limit());
    if (box_tests) ++*box_tests;
    if (t_root == INFINITY) return;
    stack[top++] = {bvh.root, bvh.root_count, t_root};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.t > limit()) continue;  // entered beyond the best hit: nothing nearer inside
        if (e.count > 0) {
            if (leaf(e.index, e.count)) return;
            continue;
        }
        const MeshNode& n = bvh.nodes[e.index];
        double t[2];
        child_entries(n, r, t_min, limit(), t);
        if (box_tests) *box_tests += 2;
        const int near = t[1] < t[0] ? 1 : 0, far = 1 - near;
        if (t[far] != INFINITY) stack[top++] = {n.child[far], n.count[far], t[far]};
        if (t[near] != INFINITY) stack[top++] = {n.child[near], n.count[near], t[near]};
    }
}

}  // namespace

bool mesh_nearest(const MeshBvh& bvh, dvec3 origin, dvec3 d, double t_min, double t_max,
                  MeshHit& hit, long long* box_tests, long long* triangle_tests) {
    double best = t_max;
    std::uint32_t best_id = 0;
    int best_k = -1;
    walk(
        bvh, slab_ray(origin, d), t_min, [&] { return best; },
        [&](int first, int count) {
            if (triangle_tests) *triangle_tests += count;
            for (int k = first; k < first + count; ++k) {
                const MeshTriangle& tri = bvh.triangles[k];
                const double t = triangle_t(tri.p0, tri.e1, tri.e2, origin, d, t_min);
                if (t < best || (t == best && best_k >= 0 && bvh.ids[k] < best_id))
                    best = t, best_id = bvh.ids[k], best_k = k;
            }
            return false;
        },
        box_tests);
    if (best_k < 0) return false;
    const MeshTriangle& tri = bvh.triangles[best_k];
    hit.triangle = best_id;
    hit.t = triangle_t(tri.p0, tri.e1, tri.e2, origin, d, t_min, &hit.beta, &hit.gamma);
    return true;
}

bool mesh_occluded(const MeshBvh& bvh, dvec3 origin, dvec3 d, double t_min, double t_max) {
    bool found = false;
    walk(
        bvh, slab_ray(origin, d), t_min, [&] { return t_max; },
        [&](int first, int count) {
            for (int k = first; k < first + count; ++k) {
                const MeshTriangle& tri = bvh.triangles[k];
                if (triangle_t(tri.p0, tri.e1, tri.e2, origin, d, t_min) < t_max)
                    return found = true;
            }
            return false;
        },
        nullptr);
    return found;
}

}  // namespace cg::rt
