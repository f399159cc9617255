// The bounding volume hierarchy, JSON:
//   input  {"primitives": [{"type": "sphere" | "triangle" | "box", …}, …] (1 to 64; see
//                         accel/primitive_json.hpp),
//           "split": "median" | "sah", "max_leaf": 1 … 16,
//           "ray": {"origin": [x, y, z], "direction": [x, y, z]}   optional: without it only
//                  the build is stepped}
//   result {"split",
//           "nodes": [{"id", "depth", "kind": "inner" | "leaf" | "leaf-no-gain",
//                      "bounds": {"min", "max"}, "children": [left, right] | null,
//                      "primitives": [its primitive indices, ascending],
//                      "axis": "x" | "y" | "z" | null (the sort axis; null for a leaf made for
//                              its size), "cut": N_L | null,
//                      "cost": the chosen split's SAH cost (sah), or the leaf's n·C_isect;
//                              null for a median split}, …]  in build order, the root first,
//           "leaves": [[primitive indices, ascending], …]  the leaves left to right,
//           "hit": {"primitive": index | null, "t": t | null, "point": [x, y, z] | null}
//                  (null without a ray),
//           "counts": {"box_tests", "primitive_tests"} (null without a ray),
//           "brute_force": {"primitive_tests": n},
//           "visited": [the nodes popped, in order] (null without a ray)}
#include <algorithm>

#include "accel/bvh.hpp"
#include "accel/primitive_json.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

json bvh_sorted_ids(const Bvh::Result& r, const Bvh::Node& nd) {
    std::vector<int> ids(r.order.begin() + nd.first, r.order.begin() + nd.first + nd.count);
    std::sort(ids.begin(), ids.end());
    return ids;
}

const char* bvh_kind_name(Bvh::NodeKind k) {
    switch (k) {
        case Bvh::NodeKind::Inner:
            return "inner";
        case Bvh::NodeKind::Leaf:
            return "leaf";
        case Bvh::NodeKind::NoGain:
            return "leaf-no-gain";
    }
    return "?";
}

json bvh_node_json(const Bvh::Result& r, int id, Bvh::Split split) {
    const Bvh::Node& nd = r.nodes[id];
    static const char* const axes[3] = {"x", "y", "z"};
    const bool sorted = nd.kind != Bvh::NodeKind::Leaf;
    json cost = nd.cost;
    if (nd.kind == Bvh::NodeKind::Inner && split == Bvh::Split::Median) cost = nullptr;
    return json{{"id", id},
                {"depth", nd.depth},
                {"kind", bvh_kind_name(nd.kind)},
                {"bounds", {{"min", to_json(nd.bounds.min)}, {"max", to_json(nd.bounds.max)}}},
                {"children", nd.leaf() ? json(nullptr) : json::array({nd.left, nd.right})},
                {"primitives", bvh_sorted_ids(r, nd)},
                {"axis", sorted ? json(axes[nd.axis]) : json(nullptr)},
                {"cut", nd.kind == Bvh::NodeKind::Inner ? json(nd.cut) : json(nullptr)},
                {"cost", cost}};
}

}  // namespace

template <>
struct JsonIo<Bvh> {
    static Bvh::Input input(const json& j) {
        Reader r(j);
        r.only({"primitives", "split", "max_leaf", "ray"});
        Bvh::Input in;
        in.primitives = accel_json::primitives(r, "primitives", Bvh::kMaxPrimitives);
        const std::string split = r.string("split");
        if (split == "median")
            in.split = Bvh::Split::Median;
        else if (split == "sah")
            in.split = Bvh::Split::Sah;
        else
            throw InputError(r.field("split"),
                             "must be \"median\" or \"sah\", got " + describe(r.get("split")));
        const long long max_leaf = r.integer("max_leaf");
        if (max_leaf < 1 || max_leaf > Bvh::kMaxLeafLimit)
            throw InputError(r.field("max_leaf"), "must be a whole number from 1 to " +
                                                      std::to_string(Bvh::kMaxLeafLimit) +
                                                      ", got " + std::to_string(max_leaf));
        in.max_leaf = static_cast<int>(max_leaf);
        in.has_ray = r.has("ray");
        if (in.has_ray) {
            const Reader ray = r.object("ray");
            ray.only({"origin", "direction"});
            in.origin = ray.point3("origin");
            in.direction = ray.point3("direction");
        }
        return in;
    }

    static json input_json(const Bvh::Input& in) {
        json j{{"primitives", accel_json::primitives_json(in.primitives)},
               {"split", in.split == Bvh::Split::Median ? "median" : "sah"},
               {"max_leaf", in.max_leaf}};
        if (in.has_ray)
            j["ray"] = {{"origin", nice_point(in.origin)}, {"direction", nice_point(in.direction)}};
        return j;
    }

    static json result(const Bvh::Result& r) {
        const Bvh::Split split = r.split;
        json nodes = json::array(), leaves = json::array();
        for (int id = 0; id < static_cast<int>(r.nodes.size()); ++id) {
            nodes.push_back(bvh_node_json(r, id, split));
            if (r.nodes[id].leaf()) leaves.push_back(bvh_sorted_ids(r, r.nodes[id]));
        }
        json out{{"split", split == Bvh::Split::Median ? "median" : "sah"},
                 {"nodes", std::move(nodes)},
                 {"leaves", std::move(leaves)}};
        if (r.traced) {
            const bool hit = r.hit.primitive >= 0;
            out["hit"] = {{"primitive", hit ? json(r.hit.primitive) : json(nullptr)},
                          {"t", hit ? json(r.hit.t) : json(nullptr)},
                          {"point", hit ? to_json(r.hit.point) : json(nullptr)}};
            out["counts"] = {{"box_tests", r.box_tests}, {"primitive_tests", r.primitive_tests}};
        } else {
            out["hit"] = nullptr;
            out["counts"] = nullptr;
        }
        out["brute_force"] = {{"primitive_tests", r.brute_force_tests}};
        out["visited"] = r.traced ? json(r.visited) : json(nullptr);
        return out;
    }

    static json example() {
        // The lesson's first preset: six spheres, two rows of three, the SAH with max_leaf 1.
        return json::parse(R"({
          "primitives": [
            {"type": "sphere", "center": [0, 0, 0], "radius": 1},
            {"type": "sphere", "center": [3, 0, 0], "radius": 1},
            {"type": "sphere", "center": [6, 0, 0], "radius": 1},
            {"type": "sphere", "center": [0, 4, 0], "radius": 1},
            {"type": "sphere", "center": [3, 4, 0], "radius": 1},
            {"type": "sphere", "center": [6, 4, 0], "radius": 1}
          ],
          "split": "sah", "max_leaf": 1,
          "ray": {"origin": [-3, 0.5, 0], "direction": [1, 0, 0]}})");
    }
};

Algorithm bvh_algorithm() {
    return make_algorithm<Bvh>([](const Bvh::Input& in) { return Bvh::build_and_trace(in); });
}

}  // namespace cg
