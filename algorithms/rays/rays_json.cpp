#include "rays/rays_json.hpp"

namespace cg::rays_json {

glm::dvec3 color(const Reader& r, const char* key, bool& rgb) {
    const json& v = r.get(key);
    if (v.is_number()) return glm::dvec3(as_number(v, r.field(key)));
    if (v.is_array() && v.size() == 3) {
        rgb = true;
        return as_point3(v, r.field(key));
    }
    throw InputError(r.field(key), "must be a number or a colour [r, g, b], got " + describe(v));
}

json color_json(const glm::dvec3& c, bool rgb, bool nice) {
    if (!rgb) return nice ? nice_number(c.x) : json(c.x);
    return nice ? nice_point(c) : to_json(c);
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

json matrix4_json(const glm::dmat4& m) {
    json rows = json::array();
    for (int r = 0; r < 4; ++r) {
        json row = json::array();
        for (int c = 0; c < 4; ++c) row.push_back(nice_number(m[c][r]));
        rows.push_back(std::move(row));
    }
    return rows;
}

namespace {

QuadricKind kind_from(const Reader& r) {
    const std::string t = r.string("type");
    for (QuadricKind k : {QuadricKind::Sphere, QuadricKind::Ellipsoid, QuadricKind::Paraboloid,
                          QuadricKind::Hyperboloid, QuadricKind::Cone, QuadricKind::Cylinder})
        if (t == quadric_kind_id(k)) return k;
    throw InputError(r.field("type"),
                     std::string("must be one of ") + kQuadricTypes + " (got \"" + t + "\")");
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

}  // namespace

Quadric quadric(const Reader& r) {
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

json quadric_json(const Quadric& q) {
    json j{{"type", quadric_kind_id(q.kind)}, {"params", params_json(q)}};
    if (q.world_from_model != glm::dmat4(1.0)) j["transform"] = matrix4_json(q.world_from_model);
    if (std::isfinite(q.zmin)) j["zmin"] = nice_number(q.zmin);
    if (std::isfinite(q.zmax)) j["zmax"] = nice_number(q.zmax);
    return j;
}

json point_or_null(bool has, glm::dvec3 p) {
    return has ? to_json(p) : json(nullptr);
}

}  // namespace cg::rays_json
