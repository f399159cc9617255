#include "rays/rt_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <thread>

#include "core/threads.hpp"

namespace cg::rt {

using glm::dvec3;

std::size_t MeshBvh::bytes() const {
    return nodes.size() * sizeof(MeshNode) + triangles.size() * sizeof(MeshTriangle) +
           ids.size() * sizeof(std::uint32_t);
}

namespace {

constexpr int kBins = 32;
constexpr float kTraversalCost = 2;  // C_trav, in triangle tests
constexpr int kMaxLeaf = 16;         // a node larger than this is always split
constexpr int kMedianDepth = 40;     // below this depth, split by the middle of the list
constexpr int kParallelMin = 4096;   // a root this large builds its subtrees on two threads

// A float box, four lanes wide so that growing it is two vector instructions (lane 3 unused);
// empty when lo > hi.
struct Box {
    alignas(16) float lo[4] = {INFINITY, INFINITY, INFINITY, 0};
    alignas(16) float hi[4] = {-INFINITY, -INFINITY, -INFINITY, 0};
    void grow(const Box& b) {
        for (int a = 0; a < 4; ++a) lo[a] = std::min(lo[a], b.lo[a]);
        for (int a = 0; a < 4; ++a) hi[a] = std::max(hi[a], b.hi[a]);
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

// A triangle as the build sees it: its box (whose lo + hi, twice the centre, is what is binned)
// and its index. The build partitions these in place, so that each pass reads them in order.
struct Prim {
    Box box;
    std::uint32_t id = 0;
    float centre2(int a) const { return box.lo[a] + box.hi[a]; }
};

struct Ref {
    std::int32_t index = 0, count = 0;  // count 0: a node
};

// The binary tree the build makes first (then collapsed into MeshNode's four-wide one).
struct Node2 {
    Box box[2];
    Ref child[2];
};

struct Split {
    int axis = -1, bin = 0;
    float lo = 0, scale = 0;  // bin of c: (c − lo) · scale
    Box left, right;
};

int bin_of(float c, float lo, float scale) {
    return std::clamp(static_cast<int>((c - lo) * scale), 0, kBins - 1);
}

// The SAH's best bin boundary over the three axes, or axis −1 when no cut beats a leaf (count
// small enough) or every centre is in one place.
Split best_split(const Prim* prims, int n, const Box& box) {
    Box centres;  // of lo + hi
    for (int k = 0; k < n; ++k) {
        Box c;
        for (int a = 0; a < 4; ++a) c.lo[a] = c.hi[a] = prims[k].box.lo[a] + prims[k].box.hi[a];
        centres.grow(c);
    }
    std::array<std::array<Box, kBins>, 3> bin_box;
    std::array<std::array<int, kBins>, 3> bin_count{};
    float lo[3], scale[3];
    for (int a = 0; a < 3; ++a) {
        const float extent = centres.hi[a] - centres.lo[a];
        lo[a] = centres.lo[a];
        scale[a] = extent > 0 ? kBins * (1 - 1e-6f) / extent : 0;
    }
    for (int k = 0; k < n; ++k) {
        const Prim& p = prims[k];
        for (int a = 0; a < 3; ++a) {
            const int b = bin_of(p.centre2(a), lo[a], scale[a]);
            bin_box[a][b].grow(p.box);
            ++bin_count[a][b];
        }
    }
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
            }
        }
    }
    if (best.axis >= 0) {
        for (int b = 0; b < kBins; ++b)
            (b < best.bin ? best.left : best.right).grow(bin_box[best.axis][b]);
    }
    return best;
}

Box range_box(const Prim* prims, int n) {
    Box box;
    for (int k = 0; k < n; ++k) box.grow(prims[k].box);
    return box;
}

// Builds the subtree over prims[begin, end) (its box given) into `nodes`, whose first node has
// global index `base`; returns its reference. Nodes are laid out depth first, left before right.
Ref build(Prim* prims, std::vector<Node2>& nodes, int base, int begin, int end, const Box& box,
          int level, int& depth, int threads) {
    depth = std::max(depth, level);
    const int n = end - begin;
    if (n == 1) return {begin, 1};
    Split s;
    int mid;
    if (level < kMedianDepth) s = best_split(prims + begin, n, box);
    if (s.axis >= 0) {
        mid = static_cast<int>(std::partition(prims + begin, prims + end,
                                              [&](const Prim& p) {
                                                  return bin_of(p.centre2(s.axis), s.lo, s.scale) <
                                                         s.bin;
                                              }) -
                               prims);
    } else {
        if (n <= kMaxLeaf) return {begin, n};
        mid = begin + n / 2;  // every centre in one place (or deep): the middle of the list
        s.left = range_box(prims + begin, mid - begin);
        s.right = range_box(prims + mid, end - mid);
    }
    const int index = static_cast<int>(nodes.size());
    nodes.emplace_back();
    Ref left, right;
    if (threads > 1 && n >= kParallelMin) {
        // The right subtree on a second thread, into its own nodes (indices from 0, moved after).
        std::vector<Node2> right_nodes;
        right_nodes.reserve(static_cast<std::size_t>(end - mid) / 2 + 1);
        int right_depth = 0;
        std::thread worker([&] {
            right = build(prims, right_nodes, 0, mid, end, s.right, level + 1, right_depth, 1);
        });
        left = build(prims, nodes, base, begin, mid, s.left, level + 1, depth, 1);
        worker.join();
        const int offset = base + static_cast<int>(nodes.size());
        for (Node2& m : right_nodes)
            for (Ref& c : m.child)
                if (c.count == 0) c.index += offset;
        if (right.count == 0) right.index += offset;
        nodes.insert(nodes.end(), right_nodes.begin(), right_nodes.end());
        depth = std::max(depth, right_depth);
    } else {
        left = build(prims, nodes, base, begin, mid, s.left, level + 1, depth, 1);
        right = build(prims, nodes, base, mid, end, s.right, level + 1, depth, 1);
    }
    nodes[index] = {{s.left, s.right}, {left, right}};
    return {base + index, 0};
}

// The four-wide node over binary node b: its two children, then, while there is room, the
// inner child of largest area replaced by its own two (the child a ray most often enters).
// Nodes are laid out depth first. Returns the node's index.
int collapse(const std::vector<Node2>& in, int b, std::vector<MeshNode>& out, int level,
             int& depth) {
    depth = std::max(depth, level);
    Box box[4] = {in[b].box[0], in[b].box[1]};
    Ref ref[4] = {in[b].child[0], in[b].child[1]};
    int m = 2;
    while (m < 4) {
        int open = -1;
        float open_area = -1;
        for (int k = 0; k < m; ++k)
            if (ref[k].count == 0 && box[k].area() > open_area) open = k, open_area = box[k].area();
        if (open < 0) break;
        const Node2& n = in[ref[open].index];
        box[open] = n.box[0], ref[open] = n.child[0];
        box[m] = n.box[1], ref[m] = n.child[1];
        ++m;
    }
    const int index = static_cast<int>(out.size());
    out.emplace_back();
    for (int k = 0; k < 4; ++k) {
        MeshNode& node = out[index];
        if (k >= m) {  // an empty slot: a box no ray enters
            for (int a = 0; a < 3; ++a) node.lo[a][k] = INFINITY, node.hi[a][k] = -INFINITY;
            node.child[k] = 0, node.count[k] = -1;
            continue;
        }
        for (int a = 0; a < 3; ++a) node.lo[a][k] = box[k].lo[a], node.hi[a][k] = box[k].hi[a];
        node.count[k] = ref[k].count;
        node.child[k] = ref[k].index;
        if (ref[k].count > 0) depth = std::max(depth, level + 1);
        if (ref[k].count == 0) {
            const int c = collapse(in, ref[k].index, out, level + 1, depth);
            out[index].child[k] = c;
        }
    }
    return index;
}

float slot_area(const MeshNode& n, int k) {
    const float x = n.hi[0][k] - n.lo[0][k], y = n.hi[1][k] - n.lo[1][k],
                z = n.hi[2][k] - n.lo[2][k];
    return 2 * (x * y + y * z + z * x);
}

// Σ over the node's children: P(entered) × (its four box tests, or its triangle tests).
double subtree_cost(const std::vector<MeshNode>& nodes, int index, double root_area) {
    const MeshNode& n = nodes[index];
    double c = 0;
    for (int k = 0; k < 4; ++k) {
        if (n.count[k] < 0) continue;
        const double p = root_area > 0 ? std::min(1.0, slot_area(n, k) / root_area) : 1.0;
        c += n.count[k] > 0 ? p * n.count[k] : p * 4 + subtree_cost(nodes, n.child[k], root_area);
    }
    return c;
}

}  // namespace

MeshBvh build_mesh_bvh(const mesh::Mesh& m, int threads) {
    threads = usable_threads(threads <= 0 ? 2 : threads);
    MeshBvh out;
    const std::size_t n = m.triangles.size();
    if (n == 0) return out;
    std::vector<Prim> prims(n);
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
        }
        p.id = static_cast<std::uint32_t>(k);
    }
    const Box root = range_box(prims.data(), static_cast<int>(n));
    for (int a = 0; a < 3; ++a) out.root_lo[a] = root.lo[a], out.root_hi[a] = root.hi[a];
    std::vector<Node2> binary;
    binary.reserve(n / 2 + 1);
    int binary_depth = 0;
    const Ref r =
        build(prims.data(), binary, 0, 0, static_cast<int>(n), root, 1, binary_depth, threads);
    out.root = r.index;
    out.root_count = r.count;
    out.depth = 1;
    if (r.count == 0) {
        out.nodes.reserve(binary.size() / 2 + 1);
        out.root = collapse(binary, r.index, out.nodes, 1, out.depth);
    }
    // The root's box test, then its four children's (or its triangles), then the subtrees'.
    out.cost = 1 + (r.count > 0 ? r.count : 4 + subtree_cost(out.nodes, out.root, root.area()));
    out.triangles.resize(n);
    out.ids.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const auto& t = m.triangles[prims[k].id];
        const dvec3 p0 = m.vertices[t[0]];
        out.triangles[k] = {p0, m.vertices[t[1]] - p0, m.vertices[t[2]] - p0};
        out.ids[k] = prims[k].id;
    }
    return out;
}

namespace {

// Two doubles side by side (GCC's and Clang's vector extension: one SSE2 register on x86-64,
// plain code elsewhere): a node's four children are slab-tested two at a time.
using v2d = double __attribute__((vector_size(16)));

inline v2d load2(const float* p) {
    return v2d{p[0], p[1]};  // GCC makes this one load and one cvtps2pd
}

// The ray as the slab tests want it (rt_bvh.hpp's BoxRay: 1/0 taken as ±10³⁰⁰, never NaN), and
// per axis where in a node the plane the ray meets first lies (lo when d ≥ 0, as 1/d's sign
// says; hi otherwise), so that no per-box swap is needed.
struct SlabRay {
    double o[3], inv[3];
    v2d o2[3], inv2[3];
    int near_at[3], far_at[3];  // byte offsets of lo[a] or hi[a] in a MeshNode
};

SlabRay slab_ray(dvec3 origin, dvec3 d) {
    SlabRay r;
    for (int a = 0; a < 3; ++a) {
        r.o[a] = origin[a];
        const double inv = 1 / d[a];
        r.inv[a] = std::isfinite(inv) ? inv : std::copysign(1e300, d[a]);
        r.o2[a] = v2d{r.o[a], r.o[a]};
        r.inv2[a] = v2d{r.inv[a], r.inv[a]};
        const int lo = static_cast<int>(offsetof(MeshNode, lo) + 4 * sizeof(float) * a);
        const int hi = static_cast<int>(offsetof(MeshNode, hi) + 4 * sizeof(float) * a);
        r.near_at[a] = std::signbit(r.inv[a]) ? hi : lo;
        r.far_at[a] = std::signbit(r.inv[a]) ? lo : hi;
    }
    return r;
}

inline v2d vmax(v2d a, v2d b) {
    return a > b ? a : b;
}
inline v2d vmin(v2d a, v2d b) {
    return a < b ? a : b;
}

// Children `half` and half + 1 of a node: the planes at byte offset `at` of the node.
inline v2d plane(const MeshNode& n, int at, int half) {
    return load2(reinterpret_cast<const float*>(reinterpret_cast<const char*>(&n) + at) + half);
}

// Where the ray enters each child's box within [t0, t1], or +∞ for a miss (an empty slot's box
// is [+∞, −∞]: always a miss). Written out axis by axis: straight-line code.
inline void child_entries(const MeshNode& n, const SlabRay& r, double t0, double t1,
                          double out[4]) {
    for (int half = 0; half < 4; half += 2) {
        const v2d nx = (plane(n, r.near_at[0], half) - r.o2[0]) * r.inv2[0];
        const v2d ny = (plane(n, r.near_at[1], half) - r.o2[1]) * r.inv2[1];
        const v2d nz = (plane(n, r.near_at[2], half) - r.o2[2]) * r.inv2[2];
        const v2d fx = (plane(n, r.far_at[0], half) - r.o2[0]) * r.inv2[0];
        const v2d fy = (plane(n, r.far_at[1], half) - r.o2[1]) * r.inv2[1];
        const v2d fz = (plane(n, r.far_at[2], half) - r.o2[2]) * r.inv2[2];
        const v2d near = vmax(vmax(v2d{t0, t0}, nx), vmax(ny, nz));
        const v2d far = vmin(vmin(v2d{t1, t1}, fx), vmin(fy, fz));
        out[half] = near[0] <= far[0] ? near[0] : INFINITY;
        out[half + 1] = near[1] <= far[1] ? near[1] : INFINITY;
    }
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
// Sorted: the nearer child first (a nearest-hit search); else in the node's order (any hit will
// do, and an unblocked shadow ray visits every child it enters anyway).
template <bool Sorted, class Leaf, class Limit>
void walk(const MeshBvh& bvh, const SlabRay& r, double t_min, Limit limit, Leaf leaf,
          long long* box_tests) {
    if (bvh.triangles.empty()) return;
    struct Entry {
        std::int32_t index, count;
        double t;
    };
    Entry stack[4 * kMedianDepth + 256];  // three far children per level at most
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
        double t[4];
        child_entries(n, r, t_min, limit(), t);
        if (box_tests)
            for (int k = 0; k < 4; ++k) *box_tests += n.count[k] >= 0;
        // The children entered go on the stack nearest last (popped first): an insertion sort of
        // at most four, in place.
        Entry* hit = stack + top;
        int m = 0;
        for (int k = 0; k < 4; ++k) {
            if (t[k] == INFINITY) continue;
            int j = m++;
            if constexpr (Sorted)
                for (; j > 0 && hit[j - 1].t < t[k]; --j) hit[j] = hit[j - 1];
            hit[j] = {n.child[k], n.count[k], t[k]};
            // Ask for the child's memory now: by the time it is popped it may have arrived.
            if (n.count[k] == 0) {
                __builtin_prefetch(&bvh.nodes[n.child[k]]);
                __builtin_prefetch(reinterpret_cast<const char*>(&bvh.nodes[n.child[k]]) + 64);
            } else {
                __builtin_prefetch(&bvh.triangles[n.child[k]]);
            }
        }
        top += m;
    }
}

}  // namespace

bool mesh_nearest(const MeshBvh& bvh, dvec3 origin, dvec3 d, double t_min, double t_max,
                  MeshHit& hit, long long* box_tests, long long* triangle_tests) {
    double best = t_max;
    std::uint32_t best_id = 0;
    int best_k = -1;
    walk<true>(
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
    walk<false>(
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
