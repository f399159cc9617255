// Photon map, JSON:
//   input  {"objects": [{"type": "sphere", "center": [x, y, z], "radius": r, "material": m, …}
//                      | {"type": "plane", "point": [x, y, z], "normal": [x, y, z], "material": m, …}]
//                      (1 to 32; m is "diffuse" (with "albedo" ρ in [0, 1], default 0.5), "mirror",
//                      or "glass" (with "ior" in [1, 3], default 1.5)),
//           "lights": [{"position": [x, y, z], "power": Φ (> 0), "direction": [x, y, z] and
//                      "cone_deg": α (a spot; default 180: every direction)}] (1 to 8),
//           "photons": n (1 to 1000000, emitted in all), "max_bounces" (1 to 64, default 8),
//           "seed" (default 1), "query": [x, y, z], "k" (1 to 10000)}
//   result {"power_per_photon": Φ_L / n_L per light, "emitted": n_L per light,
//           "stored", "caustic", "escaped", "absorbed", "limited": photon counts,
//           "tree_depth", "visited", "pruned": the kd-tree and the search,
//           "nearest": [{"photon", "position", "power", "distance"}] nearest first,
//           "radius", "sum_power", "irradiance" (Σ Φ_p / (π r²)), "direct_irradiance" (ray
//           traced), "degenerate" (no photon, or r = 0)}
#include "gi/photon_map.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

PhotonMap::Material material(const Reader& r) {
    const std::string m = r.string("material");
    if (m == "diffuse") return PhotonMap::Material::Diffuse;
    if (m == "mirror") return PhotonMap::Material::Mirror;
    if (m == "glass") return PhotonMap::Material::Glass;
    throw InputError(r.field("material"),
                     "must be \"diffuse\", \"mirror\" or \"glass\", got \"" + m + "\"");
}

PhotonMap::Object object(const Reader& r) {
    PhotonMap::Object o;
    const std::string type = r.string("type");
    o.material = material(r);
    const bool diffuse = o.material == PhotonMap::Material::Diffuse;
    const bool glass = o.material == PhotonMap::Material::Glass;
    if (type == "sphere") {
        if (diffuse) r.only({"type", "center", "radius", "material", "albedo"});
        else if (glass) r.only({"type", "center", "radius", "material", "ior"});
        else r.only({"type", "center", "radius", "material"});
        o.shape = PhotonMap::Shape::Sphere;
        o.center = r.point3("center");
        o.radius = r.number("radius");
    } else if (type == "plane") {
        if (diffuse) r.only({"type", "point", "normal", "material", "albedo"});
        else if (glass) r.only({"type", "point", "normal", "material", "ior"});
        else r.only({"type", "point", "normal", "material"});
        o.shape = PhotonMap::Shape::Plane;
        o.center = r.point3("point");
        o.normal = r.point3("normal");
    } else {
        throw InputError(r.field("type"), "must be \"sphere\" or \"plane\", got \"" + type + "\"");
    }
    if (diffuse && r.has("albedo")) o.albedo = r.number("albedo");
    if (glass && r.has("ior")) o.ior = r.number("ior");
    return o;
}

const char* material_id(PhotonMap::Material m) {
    return m == PhotonMap::Material::Mirror  ? "mirror"
           : m == PhotonMap::Material::Glass ? "glass"
                                             : "diffuse";
}

}  // namespace

template <>
struct JsonIo<PhotonMap> {
    static PhotonMap::Input input(const json& j) {
        Reader r(j);
        r.only({"objects", "lights", "photons", "max_bounces", "seed", "query", "k"});
        PhotonMap::Input in;
        const json& objects = r.get("objects");
        if (!objects.is_array())
            throw InputError(r.field("objects"), "must be a list of objects, got " + describe(objects));
        for (std::size_t i = 0; i < objects.size(); ++i)
            in.objects.push_back(object(Reader(objects[i], element(r.field("objects"), i))));
        const json& lights = r.get("lights");
        if (!lights.is_array())
            throw InputError(r.field("lights"), "must be a list of lights, got " + describe(lights));
        for (std::size_t i = 0; i < lights.size(); ++i) {
            const Reader l(lights[i], element(r.field("lights"), i));
            l.only({"position", "power", "direction", "cone_deg"});
            PhotonMap::Light light;
            light.position = l.point3("position");
            light.power = l.number("power");
            if (l.has("direction")) light.direction = l.point3("direction");
            if (l.has("cone_deg")) light.cone_deg = l.number("cone_deg");
            in.lights.push_back(light);
        }
        in.photons = int(r.integer("photons", 1, PhotonMap::kMaxPhotons, "1 to 1000000"));
        if (r.has("max_bounces"))
            in.max_bounces = int(r.integer("max_bounces", 1, PhotonMap::kMaxBounces, "1 to 64"));
        if (r.has("seed"))
            in.seed = std::uint64_t(r.integer("seed", 0, (1LL << 53), "0 to 2^53"));
        in.query = r.point3("query");
        in.k = int(r.integer("k", 1, PhotonMap::kMaxK, "1 to 10000"));
        return in;
    }

    static json input_json(const PhotonMap::Input& in) {
        json objects = json::array(), lights = json::array();
        for (const auto& o : in.objects) {
            json jo;
            if (o.shape == PhotonMap::Shape::Sphere)
                jo = {{"type", "sphere"}, {"center", nice_point(o.center)}, {"radius", nice_number(o.radius)}};
            else
                jo = {{"type", "plane"}, {"point", nice_point(o.center)}, {"normal", nice_point(o.normal)}};
            jo["material"] = material_id(o.material);
            if (o.material == PhotonMap::Material::Diffuse) jo["albedo"] = nice_number(o.albedo);
            if (o.material == PhotonMap::Material::Glass) jo["ior"] = nice_number(o.ior);
            objects.push_back(jo);
        }
        for (const auto& l : in.lights) {
            json jl{{"position", nice_point(l.position)}, {"power", nice_number(l.power)}};
            if (l.cone_deg < 180) {
                jl["direction"] = nice_point(l.direction);
                jl["cone_deg"] = nice_number(l.cone_deg);
            }
            lights.push_back(jl);
        }
        return json{{"objects", objects},   {"lights", lights},
                    {"photons", in.photons}, {"max_bounces", in.max_bounces},
                    {"seed", in.seed},       {"query", nice_point(in.query)},
                    {"k", in.k}};
    }

    static json result(const PhotonMap::Result& r) {
        json nearest = json::array();
        for (std::size_t i = 0; i < r.neighbours.size(); ++i) {
            const auto& ph = r.photons[std::size_t(r.neighbours[i])];
            nearest.push_back({{"photon", r.neighbours[i]},
                               {"position", to_json(ph.position)},
                               {"power", ph.power},
                               {"distance", r.distances[i]}});
        }
        return json{{"power_per_photon", r.power_per_photon},
                    {"emitted", r.emitted},
                    {"stored", r.photons.size()},
                    {"caustic", r.caustic},
                    {"escaped", r.escaped},
                    {"absorbed", r.absorbed},
                    {"limited", r.limited},
                    {"tree_depth", r.depth},
                    {"visited", r.visited},
                    {"pruned", r.pruned},
                    {"nearest", nearest},
                    {"radius", r.radius},
                    {"sum_power", r.sum_power},
                    {"irradiance", r.irradiance},
                    {"direct_irradiance", r.direct_irradiance},
                    {"degenerate", r.degenerate}};
    }

    static json example() {
        // The showcase: a glass ball over a grey floor, a spot light above it aimed at the ball:
        // the ball focuses its photons into a caustic on the floor below it; x is in the caustic.
        return parse_json(R"({
            "objects": [
                {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "diffuse", "albedo": 0.5},
                {"type": "sphere", "center": [0, 1.2, 0], "radius": 0.8, "material": "glass", "ior": 1.5}
            ],
            "lights": [{"position": [0, 4, 0], "power": 100, "direction": [0, -1, 0], "cone_deg": 20}],
            "photons": 300, "seed": 7, "query": [0, 0, 0], "k": 20})");
    }
};

Algorithm photon_map_algorithm() {
    return make_algorithm<PhotonMap>(
        [](const PhotonMap::Input& in) { return PhotonMap::compute(in); });
}

}  // namespace cg
