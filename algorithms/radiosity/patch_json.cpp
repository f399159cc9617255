#include "radiosity/patch_json.hpp"

namespace cg {

namespace {
// Reader::only with the caller's extra keys (emission, reflectance) allowed as well.
void only(const Reader& r, std::initializer_list<const char*> own,
          std::initializer_list<const char*> extra) {
    for (auto it = r.value().begin(); it != r.value().end(); ++it) {
        bool known = false;
        for (const char* k : own) known = known || it.key() == k;
        for (const char* k : extra) known = known || it.key() == k;
        if (known) continue;
        std::string list;
        for (const char* k : own) list += (list.empty() ? "" : ", ") + std::string(k);
        for (const char* k : extra) list += ", " + std::string(k);
        throw InputError(r.field(it.key().c_str()),
                         "is not a known field (expected: " + list + ")");
    }
}
}  // namespace

Patch read_patch(const Reader& r, std::initializer_list<const char*> extra) {
    const std::string type = r.string("type");
    if (type == "rectangle") {
        only(r, {"type", "corner", "edge_u", "edge_v"}, extra);
        return Patch::rectangle(r.point3("corner"), r.point3("edge_u"), r.point3("edge_v"));
    }
    if (type == "disc") {
        only(r, {"type", "center", "normal", "radius"}, extra);
        return Patch::disc(r.point3("center"), r.point3("normal"), r.number("radius"));
    }
    if (type == "triangle") {
        only(r, {"type", "points"}, extra);
        const auto pts = r.points3("points");
        if (pts.size() != 3)
            throw InputError(r.field("points"),
                             "a triangle has 3 points (got " + std::to_string(pts.size()) + ")");
        return Patch::triangle(pts[0], pts[1], pts[2]);
    }
    if (type == "point") {
        only(r, {"type", "center", "normal"}, extra);
        return Patch::point(r.point3("center"), r.point3("normal"));
    }
    throw InputError(
        r.field("type"),
        "must be \"rectangle\", \"disc\", \"triangle\" or \"point\", got \"" + type + "\"");
}

json patch_json(const Patch& p) {
    switch (p.type) {
        case Patch::Type::Rectangle:
            return json{{"type", "rectangle"},
                        {"corner", nice_point(p.a)},
                        {"edge_u", nice_point(p.b)},
                        {"edge_v", nice_point(p.c)}};
        case Patch::Type::Disc:
            return json{{"type", "disc"},
                        {"center", nice_point(p.a)},
                        {"normal", nice_point(p.b)},
                        {"radius", nice_number(p.radius)}};
        case Patch::Type::Triangle:
            return json{{"type", "triangle"},
                        {"points", {nice_point(p.a), nice_point(p.b), nice_point(p.c)}}};
        case Patch::Type::Point:
            return json{
                {"type", "point"}, {"center", nice_point(p.a)}, {"normal", nice_point(p.b)}};
    }
    return json();
}

}  // namespace cg
