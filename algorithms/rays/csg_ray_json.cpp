// CSG on ray segments' JSON:
//   input  {"tree": NODE (rays/csg_json.hpp), "origin": [x, y, z], "direction": [x, y, z]}
//   result {"hit": bool, "t": t | null, "point": [x, y, z] | null, "normal": [x, y, z] | null,
//           "from": the hit leaf's name, or its index when it has none | null,
//           "entering": bool | null (false: the eye is inside and the hit is where it leaves),
//           "segments": [[t_in, t_out], …] (the root's, ascending, the whole line's: not clipped
//                       to t ≥ 0; an end at ±∞ is null),
//           "lists": {node: [[t_in, t_out], …], …} (every node's list, operands first; a node is
//                    keyed by its name, or by its path "tree.left" when unnamed or named twice)}
#include <set>

#include "io/registry.hpp"
#include "rays/csg_json.hpp"
#include "rays/csg_ray.hpp"
#include "rays/rays_json.hpp"

namespace cg {

namespace {

json end_json(double t) {
    return std::isfinite(t) ? json(t) : json(nullptr);
}

json spans_json(const CsgSpans& spans) {
    json out = json::array();
    for (const CsgSpan& s : spans) out.push_back(json::array({end_json(s.in.t), end_json(s.out.t)}));
    return out;
}

}  // namespace

template <>
struct JsonIo<CsgRay> {
    static CsgRay::Input input(const json& j) {
        Reader r(j);
        r.only({"tree", "origin", "direction"});
        CsgRay::Input in;
        in.tree = csg_json::tree(r.get("tree"), "tree");
        in.origin = r.point3("origin");
        in.direction = r.point3("direction");
        return in;
    }

    static json input_json(const CsgRay::Input& in) {
        return json{{"tree", csg_json::tree_json(in.tree)},
                    {"origin", nice_point(in.origin)},
                    {"direction", nice_point(in.direction)}};
    }

    static json result(const CsgRay::Result& r) {
        const CsgTree& t = r.in->tree;
        const CsgHit& h = r.hit;
        json from = nullptr;
        if (h.hit)
            for (const CsgNode& n : t.nodes)
                if (n.leaf && n.leaf_index == h.end.leaf)
                    from = n.name.empty() ? json(n.leaf_index) : json(n.name);
        std::multiset<std::string> names;
        for (const CsgNode& n : t.nodes)
            if (!n.name.empty()) names.insert(n.name);
        json lists = json::object();
        for (std::size_t k = 0; k < t.nodes.size() && k < r.lists.size(); ++k) {
            const CsgNode& n = t.nodes[k];
            const bool by_name = !n.name.empty() && names.count(n.name) == 1;
            lists[by_name ? n.name : n.path] = spans_json(r.lists[k]);
        }
        return json{{"hit", h.hit},
                    {"t", h.hit ? json(h.t) : json(nullptr)},
                    {"point", rays_json::point_or_null(h.hit, h.point)},
                    {"normal", rays_json::point_or_null(h.hit && h.has_normal, h.normal)},
                    {"from", std::move(from)},
                    {"entering", h.hit ? json(h.entering) : json(nullptr)},
                    {"segments", spans_json(h.segments)},
                    {"lists", std::move(lists)}};
    }

    static json example() {
        // The course's kind of question: the ray (0, 0, −5) + t(0, 0, 1) and A − B, A the
        // sphere of radius 2 at the origin, B the sphere of radius 1 centred at (0, 0, −1).
        return parse_json(R"({
          "tree": {"op": "difference", "name": "A − B",
                   "left": {"name": "A", "primitive": {"type": "sphere", "params": {"r": 2}}},
                   "right": {"name": "B", "primitive": {"type": "sphere", "params": {"r": 1},
                             "transform": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1]]}}},
          "origin": [0, 0, -5], "direction": [0, 0, 1]})");
    }
};

Algorithm csg_ray_algorithm() {
    return make_algorithm<CsgRay>(
        [](const CsgRay::Input& in) { return CsgRay::solve(Shared<CsgRay::Input>(in)); });
}

}  // namespace cg
