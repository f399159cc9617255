// Ray-quadric's JSON:
//   input  {"quadric": {"type": "sphere" | "ellipsoid" | "paraboloid" | "hyperboloid" | "cone" |
//                       "cylinder",
//                       "params": {"r"} | {"a", "b", "c"} | {"p", "q"} | {"a", "b", "c"} |
//                                 {"p", "q", "r"} | {"p", "q"}  (in that order of types),
//                       "transform": 4×4 rows, world_from_model (optional, affine),
//                       "zmin", "zmax": the model-space slab kept (optional)},
//           "origin": [x, y, z], "direction": [x, y, z] (not necessarily unit)}
//   result {"hit": bool, "roots": [t, …] (every real root, ascending), "t": t | null,
//           "point": [x, y, z] | null, "normal": [x, y, z] | null (unit, along ∇F)}
#include "io/registry.hpp"
#include "rays/ray_quadric.hpp"
#include "rays/rays_json.hpp"

namespace cg {

namespace {

Quadric quadric_from(const Reader& r) {
    r.only({"type", "params", "transform", "zmin", "zmax"});
    return rays_json::quadric(r);
}

}  // namespace

template <>
struct JsonIo<RayQuadric> {
    static RayQuadric::Input input(const json& j) {
        Reader r(j);
        r.only({"quadric", "origin", "direction"});
        RayQuadric::Input in;
        in.quadric = quadric_from(r.object("quadric"));
        in.origin = r.point3("origin");
        in.direction = r.point3("direction");
        return in;
    }

    static json input_json(const RayQuadric::Input& in) {
        return json{{"quadric", rays_json::quadric_json(in.quadric)},
                    {"origin", nice_point(in.origin)},
                    {"direction", nice_point(in.direction)}};
    }

    static json result(const RayQuadric::Result& r) {
        json roots = json::array();
        for (int i = 0; i < r.root_count; ++i) roots.push_back(r.roots[i]);
        return json{{"hit", r.hit},
                    {"roots", std::move(roots)},
                    {"t", r.hit ? json(r.t) : json(nullptr)},
                    {"point", rays_json::point_or_null(r.hit, r.point)},
                    {"normal", rays_json::point_or_null(r.has_normal, r.normal)}};
    }

    static json example() {
        // The course's exam question: the paraboloid x² + y² = z and a ray straight down its
        // axis direction, the linear case.
        return json{{"quadric", {{"type", "paraboloid"}, {"params", {{"p", 1}, {"q", 1}}}}},
                    {"origin", {1, 1, 5}},
                    {"direction", {0, 0, -1}}};
    }
};

Algorithm ray_quadric_algorithm() {
    return make_algorithm<RayQuadric>(
        [](const RayQuadric::Input& in) { return RayQuadric::solve(in); });
}

}  // namespace cg
