#include "accel/primitive_json.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

namespace cg::accel_json {

Primitive primitive(const Reader& o) {
    const std::string type = o.string("type");
    Primitive p;
    if (type == "sphere") {
        o.only({"type", "center", "radius"});
        p.kind = PrimitiveKind::Sphere;
        p.a = o.point3("center");
        p.radius = o.number("radius");
        if (!(p.radius > 0))
            throw InputError(o.field("radius"), "must be > 0, got " + describe(o.get("radius")));
        if (!std::isfinite(glm::length(p.a) + p.radius))
            throw InputError(o.field("radius"), "makes the sphere's bounds overflow");
    } else if (type == "triangle") {
        o.only({"type", "vertices"});
        p.kind = PrimitiveKind::Triangle;
        const std::vector<glm::dvec3> v = o.points3("vertices");
        if (v.size() != 3)
            throw InputError(o.field("vertices"),
                             "must be 3 points, got " + std::to_string(v.size()));
        p.a = v[0], p.b = v[1], p.c = v[2];
        const glm::dvec3 n = glm::cross(p.b - p.a, p.c - p.a);
        if (!std::isfinite(glm::dot(n, n)))
            throw InputError(o.field("vertices"), "are too far apart: the area overflows");
        if (glm::dot(n, n) == 0)
            throw InputError(o.field("vertices"),
                             "are collinear: the triangle has no area (no plane, no normal)");
    } else if (type == "box") {
        o.only({"type", "min", "max"});
        p.kind = PrimitiveKind::Box;
        p.a = o.point3("min");
        p.b = o.point3("max");
        for (int i = 0; i < 3; ++i)
            if (!(p.a[i] <= p.b[i]))
                throw InputError(o.field("max"), std::string("is below min on the ") + "xyz"[i] +
                                                     " axis: min must be ≤ max");
    } else {
        throw InputError(o.field("type"), "must be \"sphere\", \"triangle\" or \"box\", got " +
                                              cg::describe(o.get("type")));
    }
    return p;
}

json primitive_json(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Sphere:
            return json{
                {"type", "sphere"}, {"center", nice_point(p.a)}, {"radius", nice_number(p.radius)}};
        case PrimitiveKind::Triangle:
            return json{{"type", "triangle"},
                        {"vertices", {nice_point(p.a), nice_point(p.b), nice_point(p.c)}}};
        case PrimitiveKind::Box:
            return json{{"type", "box"}, {"min", nice_point(p.a)}, {"max", nice_point(p.b)}};
    }
    return json();
}

std::vector<Primitive> primitives(const Reader& r, const char* key, std::size_t max_count) {
    const json& list = r.get(key);
    if (!list.is_array())
        throw InputError(r.field(key), "must be a list of primitives, got " + cg::describe(list));
    if (list.empty()) throw InputError(r.field(key), "must list at least one primitive");
    if (list.size() > max_count)
        throw InputError(r.field(key), "lists " + std::to_string(list.size()) +
                                           " primitives; at most " + std::to_string(max_count));
    std::vector<Primitive> out;
    out.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i)
        out.push_back(primitive(Reader(list[i], element(r.field(key), i))));
    return out;
}

json primitives_json(const std::vector<Primitive>& ps) {
    json out = json::array();
    for (const Primitive& p : ps) out.push_back(primitive_json(p));
    return out;
}

}  // namespace cg::accel_json
