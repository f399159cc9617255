// The ray tracer's JSON: a scene file (rays/rt_scene_json.hpp) with an optional "stepping":
//   "stepping": {"granularity": "pixels" | "rows" | "ray-tree" (default "pixels"),
//                "pixel": [x, y]   (ray-tree: the pixel containing this point, in pixel units
//                                   from the screen's bottom-left corner; default its centre),
//                "ray": {"origin": [x, y, z], "direction": [x, y, z]}  (ray-tree: this primary
//                                   ray instead of a pixel's)}
//   result (pixels, rows) {"granularity", "size": [w, h], "rays": {"primary", "shadow",
//           "reflected", "refracted", "total"}, "checksum": FNV-1a of the RGBA bytes, top row
//           first (as in the PNG), "mean": the image's mean [r, g, b] in [0, 1]}
//   result (ray-tree) {"granularity", "size", "rays", "pixel": [i, j] | null,
//           "color": [r, g, b] (unclamped), "rgb8": [R, G, B], "hit": bool, "object": name | null,
//           "t", "point", "normal" (the primary ray's hit, or null), "shadowed": [bool per light
//           tested by a shadow ray from the primary hit], "reflected": the mirror ray's
//           direction | null, "refracted": the refracted ray's direction | null,
//           "tree": [{"ray", "kind", "parent", "depth", "origin", "direction", "object", "t",
//           "color", "weight"}, …]; distributed scenes also give each node its "time", a
//           primary ray its "sample", a shadow ray to an area light its "light_sample", a glossy
//           ray "glossy": true, and "distributed": {"primary": what primary rays are spread
//           over (of "pixel area", "lens aperture", "shutter time"; [] for one ray through the
//           pixel's centre), "shadow": "light area" | null,
//           "reflected": "Phong lobe" (about the mirror direction) | null, "samples": [[x, y,
//           weight, time], …]}, and "distributed_over": for each effect the scene has, what its
//           rays are spread over: {"anti_aliasing": "pixel area", "depth_of_field": "lens
//           aperture", "motion_blur": "shutter time", "soft_shadows": "light area",
//           "glossy_reflection": "Phong lobe"}}
#include "io/registry.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"

namespace cg {

namespace {

using Granularity = RayTracer::Granularity;
using RayKind = RayTracer::RayKind;

const char* granularity_id(Granularity g) {
    switch (g) {
        case Granularity::Pixels:
            return "pixels";
        case Granularity::Rows:
            return "rows";
        case Granularity::RayTree:
            return "ray-tree";
    }
    return "";
}

json rays_json_of(const rt::RayCounts& c) {
    return json{{"primary", c.primary},
                {"shadow", c.shadow},
                {"reflected", c.reflected},
                {"refracted", c.refracted},
                {"total", c.total()}};
}

json rgb8(std::uint32_t v) {
    return json{v >> 24, (v >> 16) & 0xff, (v >> 8) & 0xff};
}

}  // namespace

template <>
struct JsonIo<RayTracer> {
    static RayTracer::Input input(const json& j) {
        RayTracer::Input in;
        in.scene = rt::scene_from_json(j, {"stepping"});
        const Reader r(j);
        if (!r.has("stepping")) return in;
        const Reader st = r.object("stepping");
        st.only({"granularity", "pixel", "ray"});
        if (st.has("granularity")) {
            const std::string g = st.string("granularity");
            if (g == "pixels")
                in.granularity = Granularity::Pixels;
            else if (g == "rows")
                in.granularity = Granularity::Rows;
            else if (g == "ray-tree")
                in.granularity = Granularity::RayTree;
            else
                throw InputError(
                    st.field("granularity"),
                    "must be \"pixels\", \"rows\" or \"ray-tree\" (got \"" + g + "\")");
        }
        if (st.has("pixel") && st.has("ray"))
            throw InputError(st.path(), "give \"pixel\" or \"ray\", not both");
        if ((st.has("pixel") || st.has("ray")) && in.granularity != Granularity::RayTree)
            throw InputError(st.field(st.has("pixel") ? "pixel" : "ray"),
                             "is for \"granularity\": \"ray-tree\" (one pixel's ray tree)");
        if (st.has("pixel")) {
            in.pixel = st.point2("pixel");
        } else {
            in.pixel = {in.scene.camera.width / 2.0, in.scene.camera.height / 2.0};
        }
        if (st.has("ray")) {
            const Reader ray = st.object("ray");
            ray.only({"origin", "direction"});
            in.explicit_ray = true;
            in.ray_origin = ray.point3("origin");
            in.ray_direction = ray.point3("direction");
        }
        return in;
    }

    static json input_json(const RayTracer::Input& in) {
        json j = rt::scene_to_json(in.scene);
        json st{{"granularity", granularity_id(in.granularity)}};
        if (in.granularity == Granularity::RayTree) {
            if (in.explicit_ray)
                st["ray"] = json{{"origin", nice_point(in.ray_origin)},
                                 {"direction", nice_point(in.ray_direction)}};
            else
                st["pixel"] = nice_point(in.pixel);
        }
        j["stepping"] = std::move(st);
        return j;
    }

    static json result(const RayTracer::Result& r) {
        json j{{"granularity", granularity_id(r.granularity)},
               {"size", {r.width, r.height}},
               {"rays", rays_json_of(r.rays)}};
        if (r.granularity != Granularity::RayTree) {
            j["checksum"] = rt::image_checksum(r.image, r.width, r.height);
            glm::dvec3 sum(0.0);
            for (std::uint32_t v : r.image)
                sum += glm::dvec3(v >> 24, (v >> 16) & 0xff, (v >> 8) & 0xff);
            j["mean"] = to_json(sum / (255.0 * std::max<std::size_t>(1, r.image.size())));
            return j;
        }
        const RayTracer::RayNode& primary = r.tree.front();
        const bool hit = primary.hit.object >= 0;
        j["pixel"] = r.explicit_ray ? json(nullptr) : json{r.pixel_i, r.pixel_j};
        j["color"] = to_json(r.color);
        j["rgb8"] = rgb8(pack_rgba(r.color));
        j["hit"] = hit;
        j["t"] = hit ? json(primary.hit.t) : json(nullptr);
        j["point"] = hit ? to_json(primary.hit.point) : json(nullptr);
        j["normal"] = hit ? to_json(primary.hit.normal) : json(nullptr);
        json shadowed = json::array(), tree = json::array();
        json reflected = nullptr, refracted = nullptr;
        for (std::size_t k = 0; k < r.tree.size(); ++k) {
            const RayTracer::RayNode& n = r.tree[k];
            if (n.parent == 0) {
                if (n.kind == RayKind::Shadow) shadowed.push_back(n.blocker >= 0);
                if (n.kind == RayKind::Reflected && !n.total_internal)
                    reflected = to_json(n.direction);
                if (n.kind == RayKind::Refracted) refracted = to_json(n.direction);
            }
            json node{{"ray", k},
                      {"kind", RayTracer::kind_id(n.kind)},
                      {"parent", n.parent < 0 ? json(nullptr) : json(n.parent)},
                      {"depth", n.depth},
                      {"origin", to_json(n.origin)},
                      {"direction", to_json(n.direction)}};
            if (r.distributed) {
                if (n.sample >= 0) node["sample"] = n.sample;
                if (n.light_sample >= 0) node["light_sample"] = n.light_sample;
                if (n.glossy) node["glossy"] = true;
                node["time"] = n.time;
            }
            if (n.kind == RayKind::Shadow) {
                node["light"] = n.light;
                node["blocked"] = n.blocker >= 0;
            } else {
                node["t"] = n.hit.object >= 0 ? json(n.hit.t) : json(nullptr);
                if (n.total_internal) node["total_internal_reflection"] = true;
            }
            if (n.detail >= 0) {  // the texture lookup at this ray's hit
                const rt::SurfaceDetail& d = r.details[n.detail];
                json t = json::object();
                if (d.textured || d.bumped) t["uv"] = to_json(d.frame.uv);
                if (d.textured) {
                    t["texel"] = json{d.lookup.taps.texel[0].x, d.lookup.taps.texel[0].y};
                    t["color"] = to_json(d.lookup.color);
                }
                if (d.solid) {
                    t["solid_point"] = to_json(d.solid_point);
                    t["color"] = to_json(d.solid_sample.color);
                }
                if (d.bumped) t["perturbed_normal"] = to_json(n.surface.normal);
                node["texture"] = std::move(t);
            }
            node["color"] = to_json(n.color);
            node["weight"] = to_json(n.weight);
            tree.push_back(std::move(node));
        }
        j["shadowed"] = std::move(shadowed);
        j["reflected"] = std::move(reflected);
        j["refracted"] = std::move(refracted);
        j["tree"] = std::move(tree);
        if (r.distributed) {
            j["distributed"] = distributed_json(r);
            j["distributed_over"] = distributed_over_json(r.distribution);
        }
        return j;
    }

    // The course's table, for the effects this scene has.
    static json distributed_over_json(const rt::Distribution& d) {
        json j = json::object();
        if (d.anti_aliasing) j["anti_aliasing"] = "pixel area";
        if (d.depth_of_field) j["depth_of_field"] = "lens aperture";
        if (d.motion_blur) j["motion_blur"] = "shutter time";
        if (d.soft_shadows) j["soft_shadows"] = "light area";
        if (d.glossy_reflection) j["glossy_reflection"] = "Phong lobe";
        return j;
    }

    // Which quantity each kind of ray is distributed over in this scene, and the pixel's
    // samples [x, y, weight, time] (x, y in the pixel, from its bottom-left corner).
    static json distributed_json(const RayTracer::Result& r) {
        json primary = json::array();
        if (r.distribution.anti_aliasing) primary.push_back("pixel area");
        bool lens = false, shutter = false, area = false, glossy = false;
        for (const auto& n : r.tree) {
            area = area || n.light_sample >= 0;
            glossy = glossy || n.glossy;
            shutter = shutter || n.time > 0;
        }
        for (const auto& ps : r.samples) lens = lens || ps.lens != glm::dvec2(0.0);
        if (lens) primary.push_back("lens aperture");
        if (shutter) primary.push_back("shutter time");
        json samples = json::array();
        for (const auto& ps : r.samples)
            samples.push_back(json::array({ps.pixel.x, ps.pixel.y, ps.weight, ps.time}));
        return json{
            {"primary", std::move(primary)},
            {"shadow", area ? json("light area") : json(nullptr)},
            {"reflected", glossy ? json("Phong lobe") : json(nullptr)},
            {"samples", std::move(samples)}};
    }

    static json example();
};

json JsonIo<RayTracer>::example() {
    // A red ball on a mirror-ish floor beside a glass ball, one point light and a dim sun:
    // shadows, a reflection and a refraction in one small picture.
    return parse_json(R"({
  "camera": {"eye": [0, 1.2, 6], "center": [0, 0.4, 0], "up": [0, 1, 0], "fov_y_deg": 40, "size": [48, 36]},
  "settings": {"max_depth": 3, "model": "phong"},
  "background": [0.08, 0.1, 0.18],
  "ambient": 0.15,
  "materials": [
    {"name": "red", "ka": [0.8, 0.15, 0.1], "kd": [0.8, 0.15, 0.1], "ks": 0.5, "shininess": 40},
    {"name": "glass", "ka": 0.02, "kd": 0.05, "ks": 0.6, "shininess": 120, "kr": 0.1, "kt": 0.85, "ior": 1.5},
    {"name": "floor", "ka": [0.5, 0.5, 0.45], "kd": [0.5, 0.5, 0.45], "ks": 0.1, "shininess": 10, "kr": 0.3}
  ],
  "lights": [
    {"position": [3, 5, 4], "intensity": 0.9},
    {"direction": [-1, -2, -1], "intensity": 0.3}
  ],
  "objects": [
    {"name": "red ball", "type": "sphere", "params": {"r": 1}, "material": "red",
     "transform": [[1, 0, 0, -1.1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]},
    {"name": "glass ball", "type": "sphere", "params": {"r": 0.7}, "material": "glass",
     "transform": [[1, 0, 0, 1.2], [0, 1, 0, -0.3], [0, 0, 1, 1], [0, 0, 0, 1]]},
    {"name": "floor", "type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "floor"}
  ],
  "stepping": {"granularity": "ray-tree", "pixel": [15.5, 5.5]}
})");
}

Algorithm ray_tracer_algorithm() {
    return make_algorithm<RayTracer>(NoPlain{
        "its straight-line twin, rt::render, makes the image alone (no ray tree, no "
        "per-pixel samples); the tests hold the stepped pixels and ray trees to it bit for bit"});
}

}  // namespace cg
