// Phong lighting's JSON (a "colour" is a number or [r, g, b]):
//   input  {"model": "phong" | "blinn-phong", "point": [x, y, z], "normal": [x, y, z],
//           "eye": [x, y, z], "ambient": colour,
//           "material": {"ka", "kd", "ks": colours, "shininess": p},
//           "lights": [{"position": [x, y, z] | "direction": [x, y, z] (the way the light
//                       travels), "intensity": colour, "attenuation": [c1, c2, c3] (optional,
//                       point lights only)}, …]}
//   result {"intensity", "ambient", "diffuse", "specular": colours (numbers when every input
//           colour was a number), "lights": [{"l", "r", "h", "n_dot_l", "r_dot_v", "n_dot_h",
//           "attenuation"}, …], "v": [x, y, z]}
#include "rays/phong_lighting_json.hpp"

#include "io/registry.hpp"
#include "rays/phong_lighting.hpp"
#include "rays/rays_json.hpp"

namespace cg {

namespace {

using rays_json::color;
using rays_json::color_json;
using rays_json::read_lighting_model;

}  // namespace

// ---- the lighting fields, shared (phong_lighting_json.hpp) ----------------------------------

PhongLighting::Model rays_json::read_lighting_model(const Reader& r) {
    const std::string model = r.string("model");
    if (model == "phong") return PhongLighting::Model::Phong;
    if (model == "blinn-phong") return PhongLighting::Model::BlinnPhong;
    throw InputError(r.field("model"),
                     "must be \"phong\" or \"blinn-phong\" (got \"" + model + "\")");
}

void rays_json::read_lighting(const Reader& r, PhongLighting::Input& in) {
    in.model = read_lighting_model(r);
    in.eye = r.point3("eye");
    in.ambient = color(r, "ambient", in.rgb);
    const Reader m = r.object("material");
    m.only({"ka", "kd", "ks", "shininess"});
    in.material.ka = color(m, "ka", in.rgb);
    in.material.kd = color(m, "kd", in.rgb);
    in.material.ks = color(m, "ks", in.rgb);
    in.material.shininess = m.number("shininess");
    const json& lights = r.get("lights");
    if (!lights.is_array())
        throw InputError(r.field("lights"), "must be a list of lights, got " + describe(lights));
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Reader l(lights[i], r.field("lights") + "[" + std::to_string(i) + "]");
        l.only({"position", "direction", "intensity", "attenuation"});
        PhongLighting::Light light;
        if (l.has("position") == l.has("direction"))
            throw InputError(l.path(),
                             "needs exactly one of \"position\" (a point light) and "
                             "\"direction\" (a directional light)");
        light.directional = l.has("direction");
        if (light.directional)
            light.direction = l.point3("direction");
        else
            light.position = l.point3("position");
        light.intensity = color(l, "intensity", in.rgb);
        if (l.has("attenuation")) light.attenuation = l.point3("attenuation");
        in.lights.push_back(light);
    }
}

json rays_json::lighting_json(const PhongLighting::Input& in) {
    json lights = json::array();
    for (const auto& L : in.lights) {
        json l = json::object();
        if (L.directional)
            l["direction"] = nice_point(L.direction);
        else
            l["position"] = nice_point(L.position);
        l["intensity"] = color_json(L.intensity, in.rgb, true);
        if (!L.directional && L.attenuation != glm::dvec3(1, 0, 0))
            l["attenuation"] = nice_point(L.attenuation);
        lights.push_back(std::move(l));
    }
    const auto& m = in.material;
    return json{{"model", in.model == PhongLighting::Model::Phong ? "phong" : "blinn-phong"},
                {"eye", nice_point(in.eye)},
                {"ambient", color_json(in.ambient, in.rgb, true)},
                {"material",
                 {{"ka", color_json(m.ka, in.rgb, true)},
                  {"kd", color_json(m.kd, in.rgb, true)},
                  {"ks", color_json(m.ks, in.rgb, true)},
                  {"shininess", nice_number(m.shininess)}}},
                {"lights", std::move(lights)}};
}

template <>
struct JsonIo<PhongLighting> {
    static PhongLighting::Input input(const json& j) {
        Reader r(j);
        r.only({"model", "point", "normal", "eye", "ambient", "material", "lights"});
        PhongLighting::Input in;
        // The fields in the order they are written, so the first error is the first bad field.
        read_lighting_model(r);
        in.point = r.point3("point");
        in.normal = r.point3("normal");
        rays_json::read_lighting(r, in);
        return in;
    }

    static json input_json(const PhongLighting::Input& in) {
        json lighting = rays_json::lighting_json(in);
        json j{{"model", std::move(lighting["model"])},
               {"point", nice_point(in.point)},
               {"normal", nice_point(in.normal)}};
        for (auto it = lighting.begin(); it != lighting.end(); ++it)
            if (it.key() != "model") j[it.key()] = std::move(it.value());
        return j;
    }

    static json result(const PhongLighting::Result& r) {
        json lights = json::array();
        for (const auto& t : r.lights)
            lights.push_back(json{{"l", to_json(t.l)},
                                  {"r", to_json(t.r)},
                                  {"h", to_json(t.h)},
                                  {"n_dot_l", t.n_dot_l},
                                  {"r_dot_v", t.r_dot_v},
                                  {"n_dot_h", t.n_dot_h},
                                  {"attenuation", t.attenuation}});
        return json{{"intensity", color_json(r.intensity, r.rgb, false)},
                    {"ambient", color_json(r.ambient, r.rgb, false)},
                    {"diffuse", color_json(r.diffuse, r.rgb, false)},
                    {"specular", color_json(r.specular, r.rgb, false)},
                    {"lights", std::move(lights)},
                    {"v", to_json(r.v)}};
    }

    static json example() {
        // A white point light up and to the side, the eye straight above: Blinn-Phong.
        return json{{"model", "blinn-phong"},
                    {"point", {0, 0, 0}},
                    {"normal", {0, 0, 1}},
                    {"eye", {0, 0, 4}},
                    {"ambient", 0.2},
                    {"material", {{"ka", 0.5}, {"kd", 0.6}, {"ks", 0.4}, {"shininess", 20}}},
                    {"lights", {{{"position", {3, 0, 4}}, {"intensity", 1}}}}};
    }
};

Algorithm phong_lighting_algorithm() {
    return make_algorithm<PhongLighting>(
        [](const PhongLighting::Input& in) { return PhongLighting::shade(in); });
}

}  // namespace cg
