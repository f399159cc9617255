// Barycentric coordinates, JSON:
//   input  {"triangle": [A, B, C], "points": [P, …]} — all 2D [x, y] or all 3D [x, y, z]
//   result {"area": 2D signed (> 0 counter-clockwise) | 3D |n|/2,
//           "normal": [nx, ny, nz] (3D only: n = (B − A) × (C − A)),
//           "results": [{"weights": [α, β, γ], "inside": bool (boundary included),
//                        "on_edge": bool, "areas": [A_a, A_b, A_c] (signed sub-areas of
//                        (P, B, C), (A, P, C), (A, B, P)),
//                        3D only: "distance": signed distance from the plane along n̂,
//                                 "projected": P′ = P − distance · n̂}, …]}
#include "io/registry.hpp"
#include "raster/barycentric.hpp"

namespace cg {

namespace {

// One point of either dimension; `dim` 0 accepts both, else it must match.
glm::dvec3 read_point(const json& v, const std::string& field, int& dim, const std::string& first,
                      const std::string& what) {
    if (!v.is_array() || (v.size() != 2 && v.size() != 3))
        throw InputError(field, "must be a point [x, y] or [x, y, z], got " + describe(v));
    const int d = static_cast<int>(v.size());
    if (dim != 0 && d != dim)
        throw InputError(field, "has " + std::to_string(d) + " coordinates but " + first + " has " +
                                    std::to_string(dim) + ": " + what);
    dim = d;
    glm::dvec3 p{0};
    for (int c = 0; c < d; ++c) p[c] = as_number(v[c], field + "[" + std::to_string(c) + "]");
    return p;
}

json point_json(int dim, const glm::dvec3& p) {
    return dim == 2 ? nice_point(glm::dvec2(p.x, p.y)) : nice_point(p);
}

}  // namespace

template <>
struct JsonIo<Barycentric> {
    static Barycentric::Input input(const json& j) {
        Reader r(j);
        r.only({"triangle", "points"});
        Barycentric::Input in;
        const json& t = r.get("triangle");
        if (!t.is_array() || t.size() != 3)
            throw InputError("triangle",
                             "must be a list of three points [A, B, C], got " + describe(t));
        int dim = 0;
        for (std::size_t i = 0; i < 3; ++i)
            in.triangle[i] =
                read_point(t[i], "triangle[" + std::to_string(i) + "]", dim, "triangle[0]",
                           "A, B and C must all be 2D [x, y] or all 3D [x, y, z]");
        in.dim = dim;
        const json& p = r.get("points");
        if (!p.is_array())
            throw InputError("points", "must be a list of points, got " + describe(p));
        if (p.size() > Barycentric::kMaxPoints)  // before reading a huge list
            throw InputError("points", "must list at most " +
                                           std::to_string(Barycentric::kMaxPoints) +
                                           " points (got " + std::to_string(p.size()) + ")");
        const std::string same =
            "every point must have the triangle's dimension (" + std::to_string(dim) + "D)";
        for (std::size_t k = 0; k < p.size(); ++k)
            in.points.push_back(
                read_point(p[k], "points[" + std::to_string(k) + "]", dim, "the triangle", same));
        return in;
    }

    static json input_json(const Barycentric::Input& in) {
        json t = json::array(), p = json::array();
        for (const auto& v : in.triangle) t.push_back(point_json(in.dim, v));
        for (const auto& v : in.points) p.push_back(point_json(in.dim, v));
        return json{{"triangle", std::move(t)}, {"points", std::move(p)}};
    }

    static json result(const Barycentric::Result& r) {
        json j{{"area", r.area}};
        if (r.dim == 3) j["normal"] = to_json(r.normal);
        json list = json::array();
        for (const auto& p : r.results) {
            json o{{"weights", to_json(p.weights)},
                   {"inside", p.inside},
                   {"on_edge", p.on_edge},
                   {"areas", to_json(p.areas)}};
            if (r.dim == 3) {
                o["distance"] = p.distance;
                o["projected"] = to_json(p.projected);
            }
            list.push_back(std::move(o));
        }
        j["results"] = std::move(list);
        return j;
    }

    static json example() {
        // Inside, on the edge BC, and outside beyond BC.
        return json{{"triangle", {{0, 0}, {4, 0}, {1, 3}}},
                    {"points", {{1, 1}, {2.5, 1.5}, {4, 2}}}};
    }
};

Algorithm barycentric_algorithm() {
    return make_algorithm<Barycentric>(
        [](const Barycentric::Input& in) { return Barycentric::compute(in); });
}

}  // namespace cg
