// Fractal terrain, JSON:
//   input  {"method": "midpoint-triangle" (default) | "diamond-square",
//           "levels": n (0 … 8), "amplitude": a (≥ 0: the offsets' bound at level 1),
//           "roughness": H (0 … 4: a ← a · 2^(−H) per level), "seed": s (0 … 2^53),
//           midpoint-triangle: "triangle": [A, B, C] (points [x, y, z], y the height);
//           diamond-square: "size": the square's side (centred on the origin in x–z),
//                           "corners": the heights at (x, z) = (−w/2, −w/2), (w/2, −w/2),
//                                      (−w/2, w/2), (w/2, w/2)}
//   result {"vertices": [x, y, z] in lattice order (the triangle's rows j = 0 … N hold
//           N + 1 − j points; the grid's N + 1), "heights": their y, "triangles": index triples,
//           "amplitudes": a per level, "largest_offsets": max |r| per level,
//           "vertex_count", "triangle_count", "min_height", "max_height"}
#include "io/registry.hpp"
#include "modelling/fractal_terrain.hpp"

namespace cg {

template <>
struct JsonIo<FractalTerrain> {
    using Method = FractalTerrain::Method;
    static FractalTerrain::Input input(const json& j) {
        Reader r(j);
        r.only({"method", "levels", "amplitude", "roughness", "seed", "triangle", "size",
                "corners"});
        FractalTerrain::Input in;
        if (r.has("method")) {
            const std::string m = r.string("method");
            if (m == "midpoint-triangle")
                in.method = Method::Triangle;
            else if (m == "diamond-square")
                in.method = Method::Grid;
            else
                throw InputError(r.field("method"),
                                 "must be \"midpoint-triangle\" or \"diamond-square\", got \"" +
                                     m + "\"");
        }
        in.levels = int(r.integer("levels", 0, FractalTerrain::kMaxLevels,
                                  "0 to " + std::to_string(FractalTerrain::kMaxLevels) +
                                      " levels (each makes four times the triangles)"));
        in.amplitude = r.number("amplitude");
        in.roughness = r.number("roughness");
        if (r.has("seed")) in.seed = std::uint64_t(r.integer("seed", 0, 1LL << 53, "0 to 2^53"));
        if (in.method == Method::Triangle) {
            for (const char* other : {"size", "corners"})
                if (r.has(other))
                    throw InputError(r.field(other),
                                     "belongs to \"diamond-square\"; \"midpoint-triangle\" "
                                     "refines the \"triangle\"");
            const std::vector<glm::dvec3> t = r.points3("triangle");
            if (t.size() != 3)
                throw InputError(r.field("triangle"), "must be three points [x, y, z], got " +
                                                          std::to_string(t.size()));
            for (int k = 0; k < 3; ++k) in.triangle[k] = t[k];
        } else {
            if (r.has("triangle"))
                throw InputError(r.field("triangle"),
                                 "belongs to \"midpoint-triangle\"; \"diamond-square\" takes "
                                 "\"size\" and \"corners\"");
            in.size = r.number("size");
            const json& c = r.get("corners");
            if (!c.is_array() || c.size() != 4)
                throw InputError(r.field("corners"),
                                 "must be a list of four heights (the corners (0,0), (N,0), "
                                 "(0,N), (N,N)), got " +
                                     describe(c));
            for (std::size_t k = 0; k < 4; ++k)
                in.corners[k] = as_number(c[k], element(r.field("corners"), k));
        }
        return in;
    }

    static json input_json(const FractalTerrain::Input& in) {
        json j;
        j["method"] = in.method == Method::Triangle ? "midpoint-triangle" : "diamond-square";
        j["levels"] = in.levels;
        j["amplitude"] = nice_number(in.amplitude);
        j["roughness"] = nice_number(in.roughness);
        j["seed"] = in.seed;
        if (in.method == Method::Triangle) {
            json t = json::array();
            for (const auto& p : in.triangle) t.push_back(nice_point(p));
            j["triangle"] = t;
        } else {
            j["size"] = nice_number(in.size);
            json c = json::array();
            for (double h : in.corners) c.push_back(nice_number(h));
            j["corners"] = c;
        }
        return j;
    }

    static json result(const FractalTerrain::Result& r) {
        json j;
        json v = json::array(), h = json::array();
        for (const auto& p : r.vertices) {
            v.push_back(to_json(p));
            h.push_back(p.y);
        }
        j["vertices"] = v;
        j["heights"] = h;
        j["triangles"] = r.triangles;
        j["amplitudes"] = r.amplitudes;
        j["largest_offsets"] = r.largest_offsets;
        j["vertex_count"] = r.vertex_count;
        j["triangle_count"] = r.triangle_count;
        j["min_height"] = r.min_height;
        j["max_height"] = r.max_height;
        return j;
    }

    static json example() {
        // The course's picture: a triangle refined twice, its heights moved by scaled random
        // numbers that halve each level.
        return parse_json(R"({
            "method": "midpoint-triangle", "levels": 2, "amplitude": 1, "roughness": 1,
            "seed": 7, "triangle": [[-2, 0, 1.5], [2, 0.5, 1.5], [0, 1, -2]]})");
    }
};

Algorithm fractal_terrain_algorithm() {
    return make_algorithm<FractalTerrain>(
        [](const FractalTerrain::Input& in) { return FractalTerrain::compute(in); });
}

}  // namespace cg
