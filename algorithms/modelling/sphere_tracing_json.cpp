// Sphere tracing, JSON:
//   input  {"shapes": [{"type": "sphere", "centre": [x, y, z], "radius": r},
//                      {"type": "box", "centre": [x, y, z], "half_size": [a, b, c]},
//                      {"type": "torus", "centre": [x, y, z], "major_radius": R,
//                       "minor_radius": r (below R; the torus's axis is parallel to y)}, …]
//                     (1 to 16 shapes),
//           "combine": "union" | "intersection" | "difference" (the first minus the rest) |
//                      "smooth-union" (optional, "union"),
//           "k": the smooth union's blending radius (optional, 0.5),
//           "origin": [x, y, z], "direction": [x, y, z] (nonzero, any length),
//           "epsilon": ε, a hit once d < ε (optional, 0.001; above 0, at most 1),
//           "max_distance": a miss once t exceeds it (optional, 100),
//           "max_steps": a miss after this many samples (optional, 100; 1 to 10,000)}
//   result {"hit": true/false, "outcome": "hit" | "escaped" | "out-of-steps",
//           "t": the hit's t (or the last t), "point": o + t·d̂, "steps": samples taken,
//           "distances": d_k of every sample, "t_values": t_k of every sample}
#include "io/registry.hpp"
#include "modelling/sphere_tracing.hpp"

namespace cg {

template <>
struct JsonIo<SphereTracing> {
    using ST = SphereTracing;

    static ST::Shape shape(const json& j, const std::string& field) {
        Reader r(j, field);
        const std::string type = r.string("type");
        ST::Shape s;
        if (type == "sphere") {
            r.only({"type", "centre", "radius"});
            s.kind = ST::Kind::Sphere;
            s.size = {r.number("radius"), 0, 0};
        } else if (type == "box") {
            r.only({"type", "centre", "half_size"});
            s.kind = ST::Kind::Box;
            s.size = r.point3("half_size");
        } else if (type == "torus") {
            r.only({"type", "centre", "major_radius", "minor_radius"});
            s.kind = ST::Kind::Torus;
            s.size = {r.number("major_radius"), r.number("minor_radius"), 0};
        } else {
            throw InputError(r.field("type"),
                             "must be \"sphere\", \"box\" or \"torus\" (got \"" + type + "\")");
        }
        s.centre = r.point3("centre");
        return s;
    }

    static ST::Input input(const json& j) {
        Reader r(j);
        r.only({"shapes", "combine", "k", "origin", "direction", "epsilon", "max_distance",
                "max_steps"});
        ST::Input in;
        const json& shapes = r.get("shapes");
        if (!shapes.is_array())
            throw InputError(r.field("shapes"),
                             "must be a list of shapes, got " + describe(shapes));
        if (shapes.size() > std::size_t(ST::kMaxShapes))
            throw InputError(r.field("shapes"), "at most " + std::to_string(ST::kMaxShapes) +
                                                    " shapes (got " +
                                                    std::to_string(shapes.size()) + ")");
        for (std::size_t i = 0; i < shapes.size(); ++i)
            in.shapes.push_back(shape(shapes[i], element(r.field("shapes"), i)));
        if (r.has("combine")) {
            const std::string c = r.string("combine");
            if (c == "union")
                in.combine = ST::Combine::Union;
            else if (c == "intersection")
                in.combine = ST::Combine::Intersection;
            else if (c == "difference")
                in.combine = ST::Combine::Difference;
            else if (c == "smooth-union")
                in.combine = ST::Combine::SmoothUnion;
            else
                throw InputError(r.field("combine"),
                                 "must be \"union\", \"intersection\", \"difference\" or "
                                 "\"smooth-union\" (got \"" +
                                     c + "\")");
        }
        if (r.has("k")) in.k = r.number("k");
        in.origin = r.point3("origin");
        in.direction = r.point3("direction");
        if (r.has("epsilon")) in.epsilon = r.number("epsilon");
        if (r.has("max_distance")) in.max_distance = r.number("max_distance");
        if (r.has("max_steps"))
            in.max_steps = int(
                r.integer("max_steps", 1, ST::kMaxSteps, "1 to " + std::to_string(ST::kMaxSteps)));
        return in;
    }

    static json input_json(const ST::Input& in) {
        json j;
        json shapes = json::array();
        for (const auto& s : in.shapes) {
            json o;
            o["type"] = ST::kind_name(s.kind);
            o["centre"] = nice_point(s.centre);
            switch (s.kind) {
                case ST::Kind::Sphere:
                    o["radius"] = nice_number(s.size.x);
                    break;
                case ST::Kind::Box:
                    o["half_size"] = nice_point(s.size);
                    break;
                case ST::Kind::Torus:
                    o["major_radius"] = nice_number(s.size.x);
                    o["minor_radius"] = nice_number(s.size.y);
                    break;
            }
            shapes.push_back(o);
        }
        j["shapes"] = shapes;
        j["combine"] = ST::combine_name(in.combine);
        j["k"] = nice_number(in.k);
        j["origin"] = nice_point(in.origin);
        j["direction"] = nice_point(in.direction);
        j["epsilon"] = nice_number(in.epsilon);
        j["max_distance"] = nice_number(in.max_distance);
        j["max_steps"] = in.max_steps;
        return j;
    }

    static json result(const ST::Result& r) {
        json j;
        j["hit"] = r.outcome == ST::Outcome::Hit;
        j["outcome"] = ST::outcome_name(r.outcome);
        j["t"] = r.t;
        j["point"] = to_json(r.point);
        j["steps"] = r.samples;
        j["distances"] = r.ds;
        j["t_values"] = r.ts;
        return j;
    }

    static json example() {
        // The exam's kind of case: a ray along x passing 3 below the centre of a sphere of
        // radius 5; three samples reach ε = 0.1.
        return parse_json(R"({"shapes": [{"type": "sphere", "centre": [12, 3, 0], "radius": 5}],
                              "origin": [0, 0, 0], "direction": [1, 0, 0], "epsilon": 0.1,
                              "max_distance": 30, "max_steps": 20})");
    }
};

Algorithm sphere_tracing_algorithm() {
    return make_algorithm<SphereTracing>(
        [](const SphereTracing::Input& in) { return SphereTracing::compute(in); });
}

}  // namespace cg
