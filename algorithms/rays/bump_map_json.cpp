// Bump-map's JSON (the height and surface formats are rays/texture_json.hpp's):
//   input  {"surface": a quadric, plane or triangle, "point": [x, y, z] (on the surface),
//           "height": {"type": "sines" | "noise" | "image", …, "step": h},
//           "light": [x, y, z] (optional: the picture's direction toward the light)}
//   result {"uv", "B", "B_u", "B_v", "P_u", "P_v", "n": P_u × P_v (outward), "D",
//           "normal": n/|n|, "perturbed_normal": (n + D)/|n + D|, "tilt_deg", "singular"}
#include "io/registry.hpp"
#include "rays/bump_map.hpp"
#include "rays/texture_json.hpp"

namespace cg {

template <>
struct JsonIo<BumpMap> {
    static BumpMap::Input input(const json& j) {
        Reader r(j);
        r.only({"surface", "point", "height", "light"});
        BumpMap::Input in;
        in.surface = texture_json::surface(r.object("surface"));
        in.point = r.point3("point");
        in.height = texture_json::height(r.object("height"));
        if (r.has("light")) {
            in.has_light = true;
            in.light = r.point3("light");
        }
        return in;
    }

    static json input_json(const BumpMap::Input& in) {
        json j{{"surface", texture_json::surface_json(in.surface)},
               {"point", nice_point(in.point)},
               {"height", texture_json::height_json(in.height)}};
        if (in.has_light) j["light"] = nice_point(in.light);
        return j;
    }

    static json result(const BumpMap::Result& r) {
        const BumpResult& b = r.bump;
        return json{{"uv", to_json(r.frame.uv)},
                    {"B", b.B},
                    {"B_u", b.B_u},
                    {"B_v", b.B_v},
                    {"P_u", to_json(r.frame.P_u)},
                    {"P_v", to_json(r.frame.P_v)},
                    {"n", to_json(b.n)},
                    {"D", to_json(b.D)},
                    {"normal", to_json(b.normal)},
                    {"perturbed_normal", to_json(b.perturbed)},
                    {"tilt_deg", r.tilt_deg},
                    {"singular", b.singular}};
    }

    static json example() {
        // The floor z = 0 with sine bumps four to a unit, at a point on a bump's flank.
        return parse_json(R"({
  "surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "u_axis": [1, 0, 0], "uv_scale": 1},
  "point": [0.0625, 0.0625, 0],
  "height": {"type": "sines", "amplitude": 0.02, "frequency": [2, 2], "step": 0.0001}
})");
    }
};

Algorithm bump_map_algorithm() {
    return make_algorithm<BumpMap>([](const BumpMap::Input& in) { return BumpMap::solve(in); });
}

}  // namespace cg
