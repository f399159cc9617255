// Projective shadow, JSON:
//   input  {"plane": {"normal": [a, b, c], "d": d}   (the plane n · x + d = 0; n ≠ 0, any length),
//           "light": [x, y, z, 1] (a point light) | [l_x, l_y, l_z, 0] (a directional light,
//                    l toward the sun),
//           "polygon": [[x, y, z], ...] (3 to 64 vertices)}
//   result {"matrix": 4×4 rows (M = h_L I − L Pᵀ, acting on column vectors [x, y, z, 1]),
//           "shadow": [[x, y, z] | null, ...] (null: the vertex casts no shadow),
//           "valid": [bool, ...], "flipped": the plane's orientation was reversed (h_L < 0)}
#include "io/registry.hpp"
#include "shadows/projective_shadow.hpp"

namespace cg {

template <>
struct JsonIo<ProjectiveShadow> {
    static ProjectiveShadow::Input input(const json& j) {
        Reader r(j);
        r.only({"plane", "light", "polygon"});
        ProjectiveShadow::Input in;
        const Reader plane = r.object("plane");
        plane.only({"normal", "d"});
        in.normal = plane.point3("normal");
        in.d = plane.number("d");
        const json& light = r.get("light");
        if (!light.is_array() || light.size() != 4)
            throw InputError(r.field("light"),
                             "must be [x, y, z, 1] (a point light) or [l_x, l_y, l_z, 0] (a "
                             "directional light), got " +
                                 describe(light));
        for (int i = 0; i < 4; ++i) in.light[i] = as_number(light[i], element(r.field("light"), i));
        in.polygon = r.points3("polygon");
        return in;
    }

    static json input_json(const ProjectiveShadow::Input& in) {
        json poly = json::array();
        for (const auto& p : in.polygon) poly.push_back(nice_point(p));
        return json{{"plane", {{"normal", nice_point(in.normal)}, {"d", nice_number(in.d)}}},
                    {"light",
                     {nice_number(in.light.x), nice_number(in.light.y), nice_number(in.light.z),
                      nice_number(in.light.w)}},
                    {"polygon", poly}};
    }

    static json result(const ProjectiveShadow::Result& r) {
        json shadow = json::array();
        for (std::size_t k = 0; k < r.shadow.size(); ++k)
            shadow.push_back(r.valid[k] ? to_json(r.shadow[k]) : json(nullptr));
        return json{{"matrix", matrix_rows(r.matrix)},
                    {"shadow", shadow},
                    {"valid", r.valid},
                    {"flipped", r.flipped}};
    }

    static json example() {
        // A triangle under a point light, flattened onto the floor y = 0.
        return json{{"plane", {{"normal", {0, 1, 0}}, {"d", 0}}},
                    {"light", {0, 4, 0, 1}},
                    {"polygon", {{1, 2, 0}, {2, 2, 1}, {1, 1, 2}}}};
    }
};

Algorithm projective_shadow_algorithm() {
    return make_algorithm<ProjectiveShadow>(
        [](const ProjectiveShadow::Input& in) { return ProjectiveShadow::flatten(in); });
}

}  // namespace cg
