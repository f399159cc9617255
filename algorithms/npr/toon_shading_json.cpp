// Toon shading's JSON:
//   input  a mesh (npr/npr_mesh_json.hpp: "vertices" and "faces", or "shape" and "segments"),
//          "light": [x, y, z] (towards the light), "thresholds": [t_1, …] increasing in (0, 1),
//          optional "colours": [[r, g, b], …] one per band in [0, 1], darkest first
//   result {"ndotl": [N̂·L̂ per face], "band": [b per face], "counts": [faces per band]}
#include "io/registry.hpp"
#include "npr/npr_mesh_json.hpp"
#include "npr/toon_shading.hpp"

namespace cg {

template <>
struct JsonIo<ToonShading> {
    static ToonShading::Input input(const json& j) {
        Reader r(j);
        r.only({"vertices", "faces", "shape", "segments", "light", "thresholds", "colours"});
        ToonShading::Input in;
        in.mesh = npr::read_mesh(r);
        in.light = r.point3("light");
        const json& t = r.get("thresholds");
        if (!t.is_array())
            throw InputError(r.field("thresholds"), "must be a list of numbers, got " + describe(t));
        if (t.size() > 16)
            throw InputError(r.field("thresholds"), "needs 1 to 7 thresholds (2 to 8 bands), got " +
                                                        std::to_string(t.size()));
        for (std::size_t i = 0; i < t.size(); ++i)
            in.thresholds.push_back(as_number(t[i], element(r.field("thresholds"), i)));
        if (r.has("colours")) {
            const json& c = r.get("colours");
            if (!c.is_array() || c.size() > 16)
                throw InputError(r.field("colours"), "must be a list of one [r, g, b] per band, got " + describe(c));
            for (std::size_t i = 0; i < c.size(); ++i)
                in.colours.push_back(as_point3(c[i], element(r.field("colours"), i)));
        }
        return in;
    }

    static json input_json(const ToonShading::Input& in) {
        json j = json::object();
        npr::write_mesh(j, in.mesh);
        j["light"] = nice_point(in.light);
        j["thresholds"] = in.thresholds;
        if (!in.colours.empty()) {
            json c = json::array();
            for (const auto& x : in.colours) c.push_back(to_json(x));
            j["colours"] = std::move(c);
        }
        return j;
    }

    static json result(const ToonShading::Result& r) {
        return json{{"ndotl", r.ndotl}, {"band", r.band}, {"counts", r.counts}};
    }

    static json example() {
        // A square pyramid on the unit square, the light from above and to the right: its four
        // sides and its base fall into three bands.
        return json{{"vertices", {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 1.5, 0}}},
                    {"faces", {{0, 1, 2, 3}, {3, 2, 4}, {2, 1, 4}, {1, 0, 4}, {0, 3, 4}}},
                    {"light", {3, 3, 1}},
                    {"thresholds", {0.3, 0.7}}};
    }
};

Algorithm toon_shading_algorithm() {
    // The plain function validates first, as start() does: compute() assumes a valid input.
    return make_algorithm<ToonShading>([](const ToonShading::Input& in) {
        ToonShading::validate(in);
        return ToonShading::compute(in);
    });
}

}  // namespace cg
