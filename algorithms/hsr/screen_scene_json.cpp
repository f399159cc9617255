#include "hsr/screen_scene_json.hpp"

namespace cg::hsr {

ScreenScene read_screen_scene(const Reader& r) {
    ScreenScene scene;
    scene.width = r.integer("width");
    scene.height = r.integer("height");
    const json& polys = r.get("polygons");
    const std::string field = r.field("polygons");
    if (!polys.is_array()) throw InputError(field, "must be a list of polygons (got " + describe(polys) + ")");
    if (polys.size() > kMaxPolygons)
        throw InputError(field, "at most " + std::to_string(kMaxPolygons) +
                                    " polygons (the limit; got " + std::to_string(polys.size()) + ")");
    for (std::size_t k = 0; k < polys.size(); ++k) {
        Reader p(polys[k], field + "[" + std::to_string(k) + "]");
        p.only({"vertices", "color"});
        ScreenPolygon poly;
        poly.vertices = p.points3("vertices");
        if (p.has("color")) poly.color = p.point3("color");
        scene.polygons.push_back(std::move(poly));
    }
    return scene;
}

void write_screen_scene(const ScreenScene& scene, json& out) {
    out["width"] = scene.width;
    out["height"] = scene.height;
    json polys = json::array();
    for (const auto& p : scene.polygons) {
        json verts = json::array();
        for (const auto& v : p.vertices) verts.push_back(nice_point(v));
        polys.push_back(json{{"vertices", verts}, {"color", nice_point(p.color)}});
    }
    out["polygons"] = polys;
}

json ids_json(const std::vector<int>& ids, long long width, long long height) {
    json rows = json::array();
    for (long long j = 0; j < height; ++j) {
        json row = json::array();
        for (long long i = 0; i < width; ++i) row.push_back(ids[static_cast<std::size_t>(j * width + i)]);
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace cg::hsr
