// Flat, Gouraud and Phong shading's JSON (a "colour" is a number or [r, g, b]):
//   input  {"width": W, "height": H,
//           "mesh": {"vertices": [[x, y, z], …] (x, y in pixels, z depth: smaller is nearer),
//                    "normals": [[x, y, z], …] (optional: one per vertex; else the
//                               area-weighted average of the faces around each vertex),
//                    "triangles": [[i, j, k], …] (vertex indices)},
//           "model": "flat" | "gouraud" | "phong",
//           "lighting": {"model": "phong" | "blinn-phong", "eye", "ambient", "material",
//                        "lights"} (phong-lighting's fields: rays/phong_lighting_json.hpp),
//           "pixel": [i, j] (optional: the pixel shown in full; default: the one under the
//                    centroid of the largest triangle)}
//   result {"image": H rows (row 0 at the bottom) of W [r, g, b] (unclamped) | null (uncovered),
//           "ids": H rows of W triangle indices (−1 uncovered), "depth": H rows of W (null),
//           "normals": [[x, y, z] | null, …] (Gouraud, Phong: the unit vertex normals; null for
//                      a vertex of no triangle with area),
//           "vertex_colors": [colour | null, …] (Gouraud),
//           "evaluations": the number of lighting evaluations,
//           "pixel": [i, j], "pixel_color": colour | null (the chosen pixel)}
//   Colours in vertex_colors and pixel_color are numbers when every colour of the lighting was.
#include <cmath>

#include "io/registry.hpp"
#include "rays/phong_lighting_json.hpp"
#include "rays/rays_json.hpp"
#include "shading/shading.hpp"

namespace cg {

namespace {

Shading::Model model_from(const Reader& r) {
    const std::string m = r.string("model");
    for (Shading::Model model :
         {Shading::Model::Flat, Shading::Model::Gouraud, Shading::Model::Phong})
        if (m == Shading::model_id(model)) return model;
    throw InputError(r.field("model"),
                     "must be \"flat\", \"gouraud\" or \"phong\" (got \"" + m + "\")");
}

// A whole number (vertex index, pixel coordinate) as an element of a list.
long long whole(const json& v, const std::string& field, const char* what) {
    if (v.is_number_integer()) return v.get<long long>();
    if (v.is_number_float()) {
        const double d = v.get<double>();
        if (std::isfinite(d) && d == std::floor(d) && std::fabs(d) < 9e15)
            return static_cast<long long>(d);
    }
    throw InputError(field, std::string("must be ") + what + ", got " + describe(v));
}

std::vector<std::array<long long, 3>> triangles(const Reader& mesh) {
    const json& t = mesh.get("triangles");
    const std::string f = mesh.field("triangles");
    if (!t.is_array())
        throw InputError(f, "must be a list of triangles [i, j, k], got " + describe(t));
    std::vector<std::array<long long, 3>> out;
    out.reserve(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) {
        const std::string fk = f + "[" + std::to_string(k) + "]";
        if (!t[k].is_array() || t[k].size() != 3)
            throw InputError(
                fk, "must be a triangle [i, j, k] of 3 vertex indices, got " + describe(t[k]));
        std::array<long long, 3> tri;
        for (int m = 0; m < 3; ++m)
            tri[m] = whole(t[k][m], fk + "[" + std::to_string(m) + "]",
                           "a vertex index (an integer)");
        out.push_back(tri);
    }
    return out;
}

json color_or_null(bool present, const glm::dvec3& c, bool rgb) {
    return present ? rays_json::color_json(c, rgb, false) : json(nullptr);
}

}  // namespace

template <>
struct JsonIo<Shading> {
    static Shading::Input input(const json& j) {
        Reader r(j);
        r.only({"width", "height", "mesh", "model", "lighting", "pixel"});
        Shading::Input in;
        in.width = r.integer("width");
        in.height = r.integer("height");
        const Reader mesh = r.object("mesh");
        mesh.only({"vertices", "normals", "triangles"});
        in.mesh.vertices = mesh.points3("vertices");
        if (mesh.has("normals")) in.mesh.normals = mesh.points3("normals");
        in.mesh.triangles = triangles(mesh);
        in.model = model_from(r);
        const Reader lighting = r.object("lighting");
        lighting.only({"model", "eye", "ambient", "material", "lights"});
        rays_json::read_lighting(lighting, in.lighting);
        if (r.has("pixel")) {
            const json& p = r.get("pixel");
            if (!p.is_array() || p.size() != 2)
                throw InputError("pixel", "must be a pixel [i, j], got " + describe(p));
            in.has_pixel = true;
            in.pixel = {whole(p[0], "pixel[0]", "an integer"),
                        whole(p[1], "pixel[1]", "an integer")};
        }
        return in;
    }

    static json input_json(const Shading::Input& in) {
        json vertices = json::array(), triangles = json::array();
        for (const glm::dvec3& v : in.mesh.vertices) vertices.push_back(nice_point(v));
        for (const auto& t : in.mesh.triangles) triangles.push_back({t[0], t[1], t[2]});
        json mesh{{"vertices", std::move(vertices)}};
        if (!in.mesh.normals.empty()) {
            json normals = json::array();
            for (const glm::dvec3& n : in.mesh.normals) normals.push_back(nice_point(n));
            mesh["normals"] = std::move(normals);
        }
        mesh["triangles"] = std::move(triangles);
        json j{{"width", in.width},
               {"height", in.height},
               {"mesh", std::move(mesh)},
               {"model", Shading::model_id(in.model)},
               {"lighting", rays_json::lighting_json(in.lighting)}};
        if (in.has_pixel) j["pixel"] = {in.pixel[0], in.pixel[1]};
        return j;
    }

    static json result(const Shading::Result& r) {
        json image = json::array(), ids = json::array(), depth = json::array();
        for (int j = 0; j < r.height; ++j) {
            json image_row = json::array(), id_row = json::array(), depth_row = json::array();
            for (int i = 0; i < r.width; ++i) {
                const Shading::Sample& p = r.at(i, j);
                const bool covered = p.triangle >= 0;
                image_row.push_back(covered ? to_json(p.color) : json(nullptr));
                id_row.push_back(p.triangle);
                depth_row.push_back(covered ? json(p.z) : json(nullptr));
            }
            image.push_back(std::move(image_row));
            ids.push_back(std::move(id_row));
            depth.push_back(std::move(depth_row));
        }
        json out{{"image", std::move(image)}, {"ids", std::move(ids)}, {"depth", std::move(depth)}};
        if (r.model != Shading::Model::Flat) {
            json normals = json::array();
            for (std::size_t v = 0; v < r.normals.size(); ++v)
                normals.push_back(r.lit[v] ? to_json(r.normals[v]) : json(nullptr));
            out["normals"] = std::move(normals);
        }
        if (r.model == Shading::Model::Gouraud) {
            json colors = json::array();
            for (std::size_t v = 0; v < r.vertex_colors.size(); ++v)
                colors.push_back(color_or_null(r.lit[v], r.vertex_colors[v], r.rgb));
            out["vertex_colors"] = std::move(colors);
        }
        out["evaluations"] = r.evaluations;
        out["pixel"] = {r.pixel[0], r.pixel[1]};
        const Shading::Sample& p = r.at(r.pixel[0], r.pixel[1]);
        out["pixel_color"] = color_or_null(p.triangle >= 0, p.color, r.rgb);
        return out;
    }

    static json example() {
        // A low bump of eight triangles, lit from the upper left: Phong shading.
        return json{{"width", 16},
                    {"height", 12},
                    {"mesh",
                     {{"vertices",
                       {{1, 1, 8},
                        {8, 1, 6},
                        {15, 1, 8},
                        {1, 6, 6},
                        {8, 6, 2},
                        {15, 6, 6},
                        {1, 11, 8},
                        {8, 11, 6},
                        {15, 11, 8}}},
                      {"triangles",
                       {{0, 1, 4},
                        {0, 4, 3},
                        {1, 2, 5},
                        {1, 5, 4},
                        {3, 4, 7},
                        {3, 7, 6},
                        {4, 5, 8},
                        {4, 8, 7}}}}},
                    {"model", "phong"},
                    {"lighting",
                     {{"model", "blinn-phong"},
                      {"eye", {8, 6, -30}},
                      {"ambient", 0.2},
                      {"material", {{"ka", 0.5}, {"kd", 0.6}, {"ks", 0.5}, {"shininess", 20}}},
                      {"lights", {{{"position", {2, 10, -20}}, {"intensity", 1}}}}}},
                    {"pixel", {7, 6}}};
    }
};

Algorithm shading_algorithm() {
    return make_algorithm<Shading>([](const Shading::Input& in) { return Shading::render(in); });
}

}  // namespace cg
