#include "rays/rt_bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <limits>

namespace cg::rt {

using glm::dvec3;

namespace {

constexpr int kBins = 16;
constexpr double kTraversalCost = 0.5;  // C_trav, in units of one object test
constexpr int kMaxLeaf = 16;            // a node this large is split even when SAH says not

struct Builder {
    const std::vector<Bounds>& bounds;
    std::vector<dvec3> centre;
    std::vector<int>& items;
    std::vector<BvhNode>& nodes;
    int depth = 0;
};

// Grown by 2⁻³⁰ of its largest coordinate: see the header.
Bounds padded(Bounds b) {
    const dvec3 m = glm::max(glm::abs(b.min), glm::abs(b.max));
    const double pad = std::ldexp(std::max({m.x, m.y, m.z}), -30);
    b.min -= dvec3(pad);
    b.max += dvec3(pad);
    return b;
}

int build(Builder& B, int first, int count, int level) {
    const int index = static_cast<int>(B.nodes.size());
    B.nodes.emplace_back();
    B.depth = std::max(B.depth, level + 1);
    Bounds box, centres;
    for (int k = first; k < first + count; ++k) {
        box.grow(B.bounds[B.items[k]]);
        centres.grow(B.centre[B.items[k]]);
    }
    B.nodes[index].box = padded(box);
    auto leaf = [&] {
        B.nodes[index].first = first;
        B.nodes[index].count = count;
        return index;
    };
    if (count <= 2 || level + 1 >= kMaxBvhDepth) return leaf();
    const dvec3 extent = centres.extent();
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    if (!(extent[axis] > 0)) return leaf();  // every centre in one place: nothing to split by

    // Bin the centres along the axis; then sweep for each boundary's left and right areas.
    const double lo = centres.min[axis], scale = kBins / extent[axis];
    auto bin_of = [&](int item) {
        return std::min(kBins - 1, static_cast<int>((B.centre[item][axis] - lo) * scale));
    };
    std::array<Bounds, kBins> bin_box{};
    std::array<int, kBins> bin_count{};
    for (int k = first; k < first + count; ++k) {
        const int b = bin_of(B.items[k]);
        bin_box[b].grow(B.bounds[B.items[k]]);
        ++bin_count[b];
    }
    std::array<double, kBins> right_area{};
    std::array<int, kBins> right_count{};
    Bounds acc;
    int n = 0;
    for (int b = kBins - 1; b > 0; --b) {
        acc.grow(bin_box[b]);
        n += bin_count[b];
        right_area[b] = acc.surface_area();
        right_count[b] = n;
    }
    const double area = box.surface_area();
    double best_cost = std::numeric_limits<double>::infinity();
    int best = -1;
    acc = Bounds{};
    n = 0;
    for (int b = 1; b < kBins; ++b) {  // boundary b: bins [0, b) left, [b, kBins) right
        acc.grow(bin_box[b - 1]);
        n += bin_count[b - 1];
        if (n == 0 || right_count[b] == 0) continue;
        const double cost =
            area > 0
                ? kTraversalCost + (acc.surface_area() * n + right_area[b] * right_count[b]) / area
                : kTraversalCost + count;
        if (cost < best_cost) best_cost = cost, best = b;
    }
    if (best < 0 || (best_cost >= count && count <= kMaxLeaf)) return leaf();

    int* mid = std::partition(B.items.data() + first, B.items.data() + first + count,
                              [&](int item) { return bin_of(item) < best; });
    const int left_count = static_cast<int>(mid - (B.items.data() + first));
    B.nodes[index].axis = static_cast<std::uint8_t>(axis);
    build(B, first, left_count, level + 1);
    const int right = build(B, first + left_count, count - left_count, level + 1);
    B.nodes[index].right = right;
    return index;
}

}  // namespace

ObjectBvh build_bvh(const std::vector<Bounds>& bounds) {
    ObjectBvh out;
    for (int k = 0; k < static_cast<int>(bounds.size()); ++k) {
        if (bounds[k].empty())
            out.unbounded.push_back(k);
        else
            out.items.push_back(k);
    }
    // A single bounded object needs no tree: everything goes on the every-ray list.
    if (static_cast<int>(out.items.size()) < kMinTreeObjects) {
        out.items.clear();
        out.unbounded.resize(bounds.size());
        for (int k = 0; k < static_cast<int>(bounds.size()); ++k) out.unbounded[k] = k;
        return out;
    }
    Builder B{bounds, std::vector<dvec3>(bounds.size()), out.items, out.nodes};
    for (int k : out.items) B.centre[k] = bounds[k].centre();
    out.nodes.reserve(2 * out.items.size() / 2 + 1);
    build(B, 0, static_cast<int>(out.items.size()), 0);
    out.depth = B.depth;
    return out;
}

}  // namespace cg::rt
