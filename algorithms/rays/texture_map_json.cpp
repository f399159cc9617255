// Texture-map's JSON (the texture and surface formats are rays/texture_json.hpp's):
//   input  {"surface": a quadric, plane or triangle, "point": [x, y, z] (on the surface),
//           "texture": {"image" | "grid" | "checker", "filter", "wrap"},
//           "footprint": the pixel's preimage side in (u, v) units (mipmap; default 0)}
//   result {"uv": [u, v], "st": [s, t] (wrapped), "texel": [i, j] (nearest: the texel;
//           bilinear: the lower-left of the four), "taps": [[i, j], …], "weights": […],
//           "color": [r, g, b], "barycentric": [α, β, γ] (triangles),
//           mipmap: "lambda", "levels": [k₀, k₁], "blend", "coarse_taps", "coarse_weights"}
#include "io/registry.hpp"
#include "rays/texture_json.hpp"
#include "rays/texture_map.hpp"

namespace cg {

namespace {

json taps_json(const TexelTaps& t) {
    json taps = json::array();
    for (int k = 0; k < t.count; ++k) taps.push_back(json{t.texel[k].x, t.texel[k].y});
    return taps;
}

json weights_json(const TexelTaps& t) {
    json w = json::array();
    for (int k = 0; k < t.count; ++k) w.push_back(t.weight[k]);
    return w;
}

}  // namespace

template <>
struct JsonIo<TextureMap> {
    static TextureMap::Input input(const json& j) {
        Reader r(j);
        r.only({"surface", "point", "texture", "footprint"});
        TextureMap::Input in;
        in.surface = texture_json::surface(r.object("surface"));
        in.point = r.point3("point");
        in.texture = texture_json::texture(r.object("texture"));
        if (r.has("footprint")) in.footprint = r.number("footprint");
        return in;
    }

    static json input_json(const TextureMap::Input& in) {
        json j{{"surface", texture_json::surface_json(in.surface)},
               {"point", nice_point(in.point)},
               {"texture", texture_json::texture_json(in.texture)}};
        if (in.texture.filter == TexFilter::Mipmap) j["footprint"] = nice_number(in.footprint);
        return j;
    }

    static json result(const TextureMap::Result& r) {
        const TextureLookup& l = r.lookup;
        json j{{"uv", to_json(r.frame.uv)},
               {"st", to_json(l.st)},
               {"texel", json{l.taps.texel[0].x, l.taps.texel[0].y}},
               {"taps", taps_json(l.taps)},
               {"weights", weights_json(l.taps)},
               {"color", to_json(l.color)}};
        if (r.frame.barycentric != glm::dvec3(0.0)) j["barycentric"] = to_json(r.frame.barycentric);
        if (r.levels > 1 || l.coarse.count > 0) {
            j["lambda"] = l.lambda;
            j["levels"] = json{l.level0, l.level1};
            j["blend"] = l.blend;
            j["coarse_taps"] = taps_json(l.coarse);
            j["coarse_weights"] = weights_json(l.coarse);
        }
        return j;
    }

    static json example() {
        // A globe: the unit sphere with its pole along z and a 4 × 2 texture of colours, read
        // bilinearly at longitude 90°, polar angle acos 0.6 ≈ 53.13°.
        return parse_json(R"({
  "surface": {"type": "sphere", "params": {"r": 1}},
  "point": [0, 0.8, 0.6],
  "texture": {"grid": {"width": 4, "height": 2,
                       "texels": [[[1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 1, 1]],
                                  [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 0, 0]]]},
              "filter": "bilinear", "wrap": "repeat"}
})");
    }
};

Algorithm texture_map_algorithm() {
    return make_algorithm<TextureMap>(
        [](const TextureMap::Input& in) { return TextureMap::solve(in); });
}

}  // namespace cg
