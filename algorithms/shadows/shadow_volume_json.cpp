// Shadow volume, JSON:
//   input  {"occluder": {"vertices": [[x, y, z], ...] (4 to 64),
//                        "faces": [[i, j, k], ...] (4 to 128 triangles, counter-clockwise seen
//                                 from outside; the mesh closed)},
//           "light": [x, y, z] (a point light), "eye": [x, y, z],
//           "targets": [[x, y, z], ...] (1 to 16: each eye ray runs from the eye through one),
//           "floor": y (optional: the receiving floor plane y = floor; without it the rays can
//                    only land on the occluder)}
//   result {"lit": [bool per face], "silhouette": [[a, b], ...] (as each runs in its lit face),
//           "quads": the number of shadow quads,
//           "rays": [{"surface": "floor" | "face" | "none", "face": index (when "face"),
//                     "hit": P | null, "start": the count at the eye, "crossings": [+1 | −1, ...]
//                     (the shadow quads passed before P, in order), "behind": quads crossed
//                     behind P (not counted), "count", "in_shadow": count > 0,
//                     "shadow_ray": the shadow ray from P to the light is blocked}, ...]}
#include "io/registry.hpp"
#include "shadows/shadow_volume.hpp"

namespace cg {

template <>
struct JsonIo<ShadowVolume> {
    static ShadowVolume::Input input(const json& j) {
        Reader r(j);
        r.only({"occluder", "light", "eye", "targets", "floor"});
        ShadowVolume::Input in;
        const Reader occ = r.object("occluder");
        occ.only({"vertices", "faces"});
        in.vertices = occ.points3("vertices");
        const json& faces = occ.get("faces");
        const std::string ff = occ.field("faces");
        if (!faces.is_array())
            throw InputError(ff, "must be a list of triangles [i, j, k], got " + describe(faces));
        for (std::size_t f = 0; f < faces.size(); ++f) {
            const std::string field = element(ff, f);
            const json& t = faces[f];
            if (!t.is_array() || t.size() != 3)
                throw InputError(
                    field, "must be a triangle [i, j, k] of vertex indices, got " + describe(t));
            std::array<int, 3> tri{};
            for (int i = 0; i < 3; ++i) {
                const double v = as_number(t[i], element(field, i));
                if (v != std::floor(v) || v < -1e9 || v > 1e9)
                    throw InputError(element(field, i),
                                     "must be a whole vertex index, got " + describe(t[i]));
                tri[i] = int(v);
            }
            in.faces.push_back(tri);
        }
        in.light = r.point3("light");
        in.eye = r.point3("eye");
        in.targets = r.points3("targets");
        in.has_floor = r.has("floor");
        if (in.has_floor) in.floor = r.number("floor");
        return in;
    }

    static json input_json(const ShadowVolume::Input& in) {
        json verts = json::array(), faces = json::array(), targets = json::array();
        for (const auto& v : in.vertices) verts.push_back(nice_point(v));
        for (const auto& f : in.faces) faces.push_back({f[0], f[1], f[2]});
        for (const auto& t : in.targets) targets.push_back(nice_point(t));
        json j{{"occluder", {{"vertices", verts}, {"faces", faces}}},
               {"light", nice_point(in.light)},
               {"eye", nice_point(in.eye)},
               {"targets", targets}};
        if (in.has_floor) j["floor"] = nice_number(in.floor);
        return j;
    }

    static json result(const ShadowVolume::Result& r) {
        json sil = json::array(), rays = json::array();
        for (const auto& q : r.silhouette) sil.push_back({q[0], q[1]});
        for (const auto& ray : r.rays) {
            json o;
            o["surface"] = ray.surface == ShadowVolume::kFloor  ? "floor"
                           : ray.surface == ShadowVolume::kNone ? "none"
                                                                : "face";
            if (ray.surface >= 0) o["face"] = ray.surface;
            o["hit"] = ray.surface == ShadowVolume::kNone ? json(nullptr) : to_json(ray.hit);
            o["start"] = ray.start;
            o["crossings"] = ray.crossings;
            o["behind"] = ray.behind;
            o["count"] = ray.count;
            o["in_shadow"] = ray.in_shadow;
            o["shadow_ray"] = ray.shadow_ray;
            rays.push_back(o);
        }
        return json{
            {"lit", r.lit}, {"silhouette", sil}, {"quads", r.silhouette.size()}, {"rays", rays}};
    }

    static json example() {
        // A box floating over the floor y = 0 under a light; one eye ray lands in its shadow,
        // one beside it.
        return json::parse(R"({
            "occluder": {
                "vertices": [[-1, 1, -1], [1, 1, -1], [1, 1, 1], [-1, 1, 1],
                             [-1, 3, -1], [1, 3, -1], [1, 3, 1], [-1, 3, 1]],
                "faces": [[0, 1, 2], [0, 2, 3], [4, 6, 5], [4, 7, 6], [3, 2, 6], [3, 6, 7],
                          [0, 5, 1], [0, 4, 5], [1, 5, 6], [1, 6, 2], [0, 3, 7], [0, 7, 4]]},
            "light": [0, 6, 0],
            "eye": [6, 4, 3],
            "targets": [[0, 0, 0], [3, 0, -1]],
            "floor": 0})");
    }
};

Algorithm shadow_volume_algorithm() {
    return make_algorithm<ShadowVolume>(
        [](const ShadowVolume::Input& in) { return ShadowVolume::solve(in); });
}

}  // namespace cg
