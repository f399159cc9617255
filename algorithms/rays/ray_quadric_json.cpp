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

namespace cg {

namespace {

QuadricKind kind_from(const Reader& r) {
    const std::string t = r.string("type");
    for (QuadricKind k : {QuadricKind::Sphere, QuadricKind::Ellipsoid, QuadricKind::Paraboloid,
                          QuadricKind::Hyperboloid, QuadricKind::Cone, QuadricKind::Cylinder})
        if (t == quadric_kind_id(k)) return k;
    throw InputError(r.field("type"),
                     "must be one of sphere, ellipsoid, paraboloid, hyperboloid, cone, cylinder "
                     "(got \"" +
                         t + "\")");
}

glm::dmat4 matrix4(const Reader& r, const char* key) {
    const json& v = r.get(key);
    const std::string f = r.field(key);
    if (!v.is_array() || v.size() != 4)
        throw InputError(f, "must be a 4×4 matrix as a list of 4 rows, got " + describe(v));
    glm::dmat4 m(1.0);
    for (int row = 0; row < 4; ++row) {
        const json& rv = v[row];
        const std::string rf = f + "[" + std::to_string(row) + "]";
        if (!rv.is_array() || rv.size() != 4)
            throw InputError(rf, "must be a row of 4 numbers, got " + describe(rv));
        for (int c = 0; c < 4; ++c)
            m[c][row] = as_number(rv[c], rf + "[" + std::to_string(c) + "]");  // glm: m[col][row]
    }
    return m;
}

Quadric quadric_from(const Reader& r) {
    r.only({"type", "params", "transform", "zmin", "zmax"});
    Quadric q;
    q.kind = kind_from(r);
    const Reader p = r.object("params");
    switch (q.kind) {
        case QuadricKind::Sphere:
            p.only({"r"});
            q.r = p.number("r");
            break;
        case QuadricKind::Ellipsoid:
        case QuadricKind::Hyperboloid:
            p.only({"a", "b", "c"});
            q.a = p.number("a"), q.b = p.number("b"), q.c = p.number("c");
            break;
        case QuadricKind::Paraboloid:
        case QuadricKind::Cylinder:
            p.only({"p", "q"});
            q.p = p.number("p"), q.q = p.number("q");
            break;
        case QuadricKind::Cone:
            p.only({"p", "q", "r"});
            q.p = p.number("p"), q.q = p.number("q"), q.r = p.number("r");
            break;
    }
    if (r.has("transform")) q.world_from_model = matrix4(r, "transform");
    if (r.has("zmin")) q.zmin = r.number("zmin");
    if (r.has("zmax")) q.zmax = r.number("zmax");
    return q;
}

json params_json(const Quadric& q) {
    switch (q.kind) {
        case QuadricKind::Sphere:
            return json{{"r", nice_number(q.r)}};
        case QuadricKind::Ellipsoid:
        case QuadricKind::Hyperboloid:
            return json{{"a", nice_number(q.a)}, {"b", nice_number(q.b)}, {"c", nice_number(q.c)}};
        case QuadricKind::Paraboloid:
        case QuadricKind::Cylinder:
            return json{{"p", nice_number(q.p)}, {"q", nice_number(q.q)}};
        case QuadricKind::Cone:
            return json{{"p", nice_number(q.p)}, {"q", nice_number(q.q)}, {"r", nice_number(q.r)}};
    }
    return json::object();
}

json point_or_null(bool has, glm::dvec3 p) {
    return has ? to_json(p) : json(nullptr);
}

json quadric_json(const Quadric& q) {
    json j{{"type", quadric_kind_id(q.kind)}, {"params", params_json(q)}};
    if (q.world_from_model != glm::dmat4(1.0)) {
        json rows = json::array();
        for (int r = 0; r < 4; ++r) {
            json row = json::array();
            for (int c = 0; c < 4; ++c) row.push_back(nice_number(q.world_from_model[c][r]));
            rows.push_back(std::move(row));
        }
        j["transform"] = std::move(rows);
    }
    if (std::isfinite(q.zmin)) j["zmin"] = nice_number(q.zmin);
    if (std::isfinite(q.zmax)) j["zmax"] = nice_number(q.zmax);
    return j;
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
        return json{{"quadric", quadric_json(in.quadric)},
                    {"origin", nice_point(in.origin)},
                    {"direction", nice_point(in.direction)}};
    }

    static json result(const RayQuadric::Result& r) {
        json roots = json::array();
        for (int i = 0; i < r.root_count; ++i) roots.push_back(r.roots[i]);
        return json{{"hit", r.hit},
                    {"roots", std::move(roots)},
                    {"t", r.hit ? json(r.t) : json(nullptr)},
                    {"point", point_or_null(r.hit, r.point)},
                    {"normal", point_or_null(r.has_normal, r.normal)}};
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
    return make_algorithm<RayQuadric>();
}

}  // namespace cg
