// Shadow map, JSON:
//   input  {"triangles": [[[x, y, z], [x, y, z], [x, y, z]], ...]   (1 to 64, non-zero area),
//           "light": {"type": "directional", "position", "target", "up", "extent" (the
//                     orthographic box's half-width), "near", "far"}
//                  | {"type": "spot", "position", "target", "up", "fov_deg", "near" (> 0), "far"},
//           "map_size": N (1 to 64), "bias": b (≥ 0),
//           "eye": {"position", "target", "up", "fov_deg" (vertical), "width", "height" (1 to 64)}}
//   result {"depth_map": N rows of N depths (depth_map[j][i], j = 0 the bottom row; linear depth
//                        along the light's axis; far where nothing was drawn),
//           "texel_triangle": the triangle each texel holds (-1: none), same layout,
//           "image": height strings of width characters, image[j][i], j = 0 the bottom row:
//                    '.' background, 'o' outside the light's frustum (lit), 'L' lit, 'S' shadow,
//                    'A' acne, 'F' false shadow, 'K' false lit (light leaking),
//           "lit", "shadow", "background", "outside", "acne", "false_shadow", "false_lit": counts,
//           "light_from_world": 4×4 rows,
//           "last": the last pixel's lookup {"pixel", "verdict", "triangle", "p", "p_light",
//                   "d_p", "texel" [i, j], "d_map", "in_shadow", "shadow_ray_blocked"}}
#include "io/registry.hpp"
#include "shadows/shadow_map.hpp"

namespace cg {

namespace {

int bounded(const Reader& r, const char* key, int hi, const char* what) {
    const long long v = r.integer(key);
    if (v < 1 || v > hi)
        throw InputError(r.field(key), std::string("must be 1 to ") + std::to_string(hi) + what +
                                           " (got " + std::to_string(v) + ")");
    return int(v);
}

void camera(const Reader& r, ShadowMap::Camera& c) {
    c.position = r.point3("position");
    c.target = r.point3("target");
    c.up = r.point3("up");
}

json camera_json(const ShadowMap::Camera& c) {
    return json{{"position", nice_point(c.position)},
                {"target", nice_point(c.target)},
                {"up", nice_point(c.up)}};
}

}  // namespace

template <>
struct JsonIo<ShadowMap> {
    static ShadowMap::Input input(const json& j) {
        Reader r(j);
        r.only({"triangles", "light", "map_size", "bias", "eye"});
        ShadowMap::Input in;
        const json& tris = r.get("triangles");
        if (!tris.is_array())
            throw InputError(r.field("triangles"),
                             "must be a list of triangles [[x, y, z], [x, y, z], [x, y, z]], got " +
                                 describe(tris));
        for (std::size_t k = 0; k < tris.size(); ++k) {
            const std::string f = element(r.field("triangles"), k);
            if (!tris[k].is_array() || tris[k].size() != 3)
                throw InputError(f, "must be a triangle [[x, y, z], [x, y, z], [x, y, z]], got " +
                                        describe(tris[k]));
            ShadowMap::Triangle t;
            for (int v = 0; v < 3; ++v) t[v] = as_point3(tris[k][v], element(f, v));
            in.triangles.push_back(t);
        }
        const Reader light = r.object("light");
        const std::string type = light.string("type");
        if (type == "directional") {
            light.only({"type", "position", "target", "up", "extent", "near", "far"});
            in.light.type = ShadowMap::LightType::Directional;
            in.light.extent = light.number("extent");
        } else if (type == "spot") {
            light.only({"type", "position", "target", "up", "fov_deg", "near", "far"});
            in.light.type = ShadowMap::LightType::Spot;
            in.light.fov_deg = light.number("fov_deg");
        } else {
            throw InputError(light.field("type"),
                             "must be \"directional\" or \"spot\", got \"" + type + "\"");
        }
        camera(light, in.light);
        in.light.near = light.number("near");
        in.light.far = light.number("far");
        in.map_size = bounded(r, "map_size", ShadowMap::kMaxMap, "");
        in.bias = r.number("bias");
        const Reader eye = r.object("eye");
        eye.only({"position", "target", "up", "fov_deg", "width", "height"});
        camera(eye, in.eye);
        in.eye.fov_deg = eye.number("fov_deg");
        in.eye.width = bounded(eye, "width", ShadowMap::kMaxEye, " pixels");
        in.eye.height = bounded(eye, "height", ShadowMap::kMaxEye, " pixels");
        return in;
    }

    static json input_json(const ShadowMap::Input& in) {
        json tris = json::array();
        for (const auto& t : in.triangles)
            tris.push_back({nice_point(t[0]), nice_point(t[1]), nice_point(t[2])});
        json light = camera_json(in.light);
        const bool spot = in.light.type == ShadowMap::LightType::Spot;
        light["type"] = spot ? "spot" : "directional";
        if (spot)
            light["fov_deg"] = nice_number(in.light.fov_deg);
        else
            light["extent"] = nice_number(in.light.extent);
        light["near"] = nice_number(in.light.near);
        light["far"] = nice_number(in.light.far);
        json eye = camera_json(in.eye);
        eye["fov_deg"] = nice_number(in.eye.fov_deg);
        eye["width"] = in.eye.width;
        eye["height"] = in.eye.height;
        return json{{"triangles", tris},
                    {"light", light},
                    {"map_size", in.map_size},
                    {"bias", nice_number(in.bias)},
                    {"eye", eye}};
    }

    static json result(const ShadowMap::Result& r) {
        const int n = r.map_size;
        json depth = json::array(), owner = json::array(), image = json::array();
        for (int j = 0; j < n; ++j) {
            json drow = json::array(), orow = json::array();
            for (int i = 0; i < n; ++i) {
                drow.push_back(r.depth[std::size_t(j) * n + i]);
                orow.push_back(r.owner[std::size_t(j) * n + i]);
            }
            depth.push_back(drow);
            owner.push_back(orow);
        }
        for (int j = 0; j < r.height; ++j) {
            std::string row;
            for (int i = 0; i < r.width; ++i)
                row += ShadowMap::verdict_char(r.image[std::size_t(j) * r.width + i]);
            image.push_back(row);
        }
        const auto& l = r.last;
        json last{{"pixel", {l.i, l.j}}, {"verdict", ShadowMap::verdict_id(l.verdict)}};
        if (l.tri >= 0) {
            last["triangle"] = l.tri;
            last["p"] = to_json(l.p);
            last["p_light"] = {l.p_light.x, l.p_light.y, l.p_light.z, l.p_light.w};
            last["d_p"] = l.d_p;
        }
        if (l.ti >= 0) {
            last["texel"] = {l.ti, l.tj};
            last["d_map"] = l.d_map;
            last["in_shadow"] = l.map_shadow;
            last["shadow_ray_blocked"] = l.exact_shadow;
        }
        const auto& c = r.counts;
        return json{{"depth_map", depth},
                    {"texel_triangle", owner},
                    {"image", image},
                    {"lit", c.lit},
                    {"shadow", c.shadow},
                    {"background", c.background},
                    {"outside", c.outside},
                    {"acne", c.acne},
                    {"false_shadow", c.false_shadow},
                    {"false_lit", c.false_lit},
                    {"light_from_world", matrix_rows(r.light_from_world)},
                    {"last", last}};
    }

    static json example() {
        // A square card at height 1 over a floor, a directional light from above and behind,
        // seen from the front: the card's shadow falls on the floor in front of it.
        return parse_json(R"({
            "triangles": [[[-3, 0, -3], [3, 0, -3], [3, 0, 3]], [[-3, 0, -3], [3, 0, 3], [-3, 0, 3]],
                          [[-1, 1, -1], [1, 1, -1], [1, 1, 1]],
                          [[-1, 1, -1], [1, 1, 1], [-1, 1, 1]]],
            "light": {"type": "directional", "position": [1, 5, -2], "target": [0, 0, 0],
                      "up": [0, 0, -1], "extent": 4, "near": 0.1, "far": 10},
            "map_size": 8, "bias": 0.3,
            "eye": {"position": [0, 3.5, 4], "target": [0, 0, 0.3], "up": [0, 1, 0], "fov_deg": 55,
                    "width": 16, "height": 12}})");
    }
};

Algorithm shadow_map_algorithm() {
    return make_algorithm<ShadowMap>(
        [](const ShadowMap::Input& in) { return ShadowMap::render(in); });
}

}  // namespace cg
