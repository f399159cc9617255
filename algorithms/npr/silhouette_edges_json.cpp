// Silhouette edges' JSON:
//   input  a mesh (npr/npr_mesh_json.hpp: "vertices" and "faces", or "shape" and "segments"),
//          "eye": [x, y, z]; for the picture only, optional "light": [x, y, z] (default
//          [1, 2, 3]) and "thresholds": [t_1, …] (default [0.35, 0.7]), as toon-shading's
//   result {"front": [bool per face], "silhouette": [[i, j], …] sorted, i < j,
//           "boundary": [[i, j], …] sorted, "edges": number of distinct edges}
#include "io/registry.hpp"
#include "npr/npr_mesh_json.hpp"
#include "npr/silhouette_edges.hpp"

namespace cg {

template <>
struct JsonIo<SilhouetteEdges> {
    static SilhouetteEdges::Input input(const json& j) {
        Reader r(j);
        r.only({"vertices", "faces", "shape", "segments", "eye", "light", "thresholds"});
        SilhouetteEdges::Input in;
        in.mesh = npr::read_mesh(r);
        in.eye = r.point3("eye");
        if (r.has("light")) in.light = r.point3("light");
        if (r.has("thresholds")) {
            const json& t = r.get("thresholds");
            if (!t.is_array() || t.size() > 16)
                throw InputError(r.field("thresholds"), "must be a list of 1 to 7 numbers, got " + describe(t));
            in.thresholds.clear();
            for (std::size_t i = 0; i < t.size(); ++i)
                in.thresholds.push_back(as_number(t[i], element(r.field("thresholds"), i)));
        }
        return in;
    }

    static json input_json(const SilhouetteEdges::Input& in) {
        json j = json::object();
        npr::write_mesh(j, in.mesh);
        j["eye"] = nice_point(in.eye);
        j["light"] = nice_point(in.light);
        j["thresholds"] = in.thresholds;
        return j;
    }

    static json result(const SilhouetteEdges::Result& r) {
        json front = json::array();
        for (bool f : r.front) front.push_back(f);
        return json{{"front", std::move(front)},
                    {"silhouette", r.silhouette},
                    {"boundary", r.boundary},
                    {"edges", r.edges}};
    }

    static json example() {
        // The cube [0, 2]³ from a general point: three faces front, a six-edge silhouette.
        return json{{"vertices", {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}}},
                    {"faces", {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}}},
                    {"eye", {5, 4, 6}}};
    }
};

Algorithm silhouette_edges_algorithm() {
    return make_algorithm<SilhouetteEdges>(
        [](const SilhouetteEdges::Input& in) {  // validated first, as start() does
            SilhouetteEdges::validate(in);
            return SilhouetteEdges::compute(in);
        });
}

}  // namespace cg
