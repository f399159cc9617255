// Solid-texture's JSON (the texture format is rays/texture_json.hpp's "solid"):
//   input  {"texture": {"type": "checker" | "stripes" | "wood" | "marble", …},
//           "points": [[x, y, z], …], "detail": index of the point whose noise is worked
//           (default 0)}
//   result {"colors": [[r, g, b], …], "t": [mix, …], "noise": [value | null, …] (wood: the
//           noise, marble: the turbulence, null for checker and stripes), "cells": [[X, Y, Z] |
//           null, …] (the noise lattice cell ⌊f p⌋, a checker's cube ⌊p/s⌋, null for stripes),
//           and for wood and marble "detail": {"q", "cell", "frac", "fade", "gradients": 8 ×
//           [gx, gy, gz] (corner (a, b, c) at 4a + 2b + c), "ramps", "along_z", "along_y",
//           "value"}, marble "octaves": [|noise(2^k q)|/2^k, …]}
#include <cmath>

#include "io/registry.hpp"
#include "rays/solid_texture.hpp"
#include "rays/texture_json.hpp"

namespace cg {

template <>
struct JsonIo<SolidTextureAlgo> {
    static SolidTextureAlgo::Input input(const json& j) {
        Reader r(j);
        r.only({"texture", "points", "detail"});
        SolidTextureAlgo::Input in;
        in.texture = texture_json::solid(r.object("texture"));
        const json& pts = r.get("points");
        if (pts.is_array() && pts.size() > SolidTextureAlgo::kMaxPoints)
            throw InputError("points", "has " + std::to_string(pts.size()) +
                                           " points; the limit is " +
                                           std::to_string(SolidTextureAlgo::kMaxPoints));
        in.points = r.points3("points");
        if (r.has("detail")) {
            const long long d = r.integer("detail");
            if (d < 0 || d >= static_cast<long long>(std::max<std::size_t>(in.points.size(), 1)))
                throw InputError("detail",
                                 "must be the index of a point, 0 to " +
                                     std::to_string(in.points.size() ? in.points.size() - 1 : 0) +
                                     " (got " + std::to_string(d) + ")");
            in.detail = static_cast<int>(d);
        }
        return in;
    }

    static json input_json(const SolidTextureAlgo::Input& in) {
        json pts = json::array();
        for (const glm::dvec3& p : in.points) pts.push_back(nice_point(p));
        json j{{"texture", texture_json::solid_json(in.texture)}, {"points", std::move(pts)}};
        if (in.detail != 0) j["detail"] = in.detail;
        return j;
    }

    static json result(const SolidTextureAlgo::Result& r) {
        json colors = json::array(), ts = json::array(), noise = json::array(),
             cells = json::array();
        for (const SolidSample& s : r.samples) {
            colors.push_back(to_json(s.color));
            ts.push_back(s.t);
            noise.push_back(r.noisy ? json(s.noise) : json(nullptr));
            cells.push_back(s.cell_known ? json{s.cell[0], s.cell[1], s.cell[2]} : json(nullptr));
        }
        json j{{"colors", std::move(colors)},
               {"t", std::move(ts)},
               {"noise", std::move(noise)},
               {"cells", std::move(cells)}};
        if (r.has_detail) {
            const NoiseDetail& d = r.detail;
            json g = json::array(), ramps = json::array();
            for (int k = 0; k < 8; ++k) {
                g.push_back(to_json(perlin_gradients()[d.gradient[k]]));
                ramps.push_back(d.dot[k]);
            }
            j["detail"] =
                json{{"q", to_json(d.p)},
                     {"cell", {d.cell[0], d.cell[1], d.cell[2]}},
                     {"frac", to_json(d.frac)},
                     {"fade", to_json(d.fade)},
                     {"gradients", std::move(g)},
                     {"ramps", std::move(ramps)},
                     {"along_z", {d.along_z[0], d.along_z[1], d.along_z[2], d.along_z[3]}},
                     {"along_y", {d.along_y[0], d.along_y[1]}},
                     {"value", d.value}};
        }
        if (!r.octaves.empty()) j["octaves"] = r.octaves;
        return j;
    }

    static json example() {
        // Marble around the z axis: three points, the first one's noise worked in full.
        return parse_json(R"({
  "texture": {"type": "marble", "colors": [[0.92, 0.9, 0.86], [0.3, 0.25, 0.35]], "axis": [0, 0, 1],
              "period": 1, "amplitude": 4, "frequency": 1.5, "octaves": 4, "seed": 7},
  "points": [[0.3, 0.7, 0.2], [1.25, -0.5, 0.75], [-0.4, 0.1, 1.6]]
})");
    }
};

Algorithm solid_texture_algorithm() {
    return make_algorithm<SolidTextureAlgo>(
        [](const SolidTextureAlgo::Input& in) { return SolidTextureAlgo::solve(in); });
}

}  // namespace cg
