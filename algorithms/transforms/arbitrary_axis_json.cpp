// Rotation about an arbitrary axis, JSON:
//   input  {"axis": [x, y, z] (≠ 0, any length), "angle_deg": θ,
//           "points": [[x, y, z], …] (optional, may be empty)}
//   result {"matrix": R as 4×4 homogeneous rows, "phi_deg": φ, "gamma_deg": γ,
//           "canonical_axis": "x" | "y" | "z", "points": [[x, y, z], …] (R P each)}
#include "io/registry.hpp"
#include "transforms/arbitrary_axis.hpp"

namespace cg {

template <>
struct JsonIo<ArbitraryAxis> {
    static ArbitraryAxis::Input input(const json& j) {
        Reader r(j);
        r.only({"axis", "angle_deg", "points"});
        ArbitraryAxis::Input in;
        in.axis = r.point3("axis");
        in.angle_deg = r.number("angle_deg");
        in.points.clear();
        if (r.has("points")) in.points = r.points3("points");
        return in;
    }

    static json input_json(const ArbitraryAxis::Input& in) {
        json ps = json::array();
        for (const glm::dvec3& p : in.points) ps.push_back(nice_point(p));
        return json{{"axis", nice_point(in.axis)},
                    {"angle_deg", nice_number(in.angle_deg)},
                    {"points", std::move(ps)}};
    }

    static json result(const ArbitraryAxis::Result& r) {
        json ps = json::array();
        for (const glm::dvec3& p : r.points) ps.push_back(to_json(p));
        return json{{"matrix", to_json(Value(rot::rows4(r.matrix)))},
                    {"phi_deg", r.phi_deg},
                    {"gamma_deg", r.gamma_deg},
                    {"canonical_axis", std::string(1, rot::axis_name(r.canonical))},
                    {"points", std::move(ps)}};
    }

    static json example() {
        // The exam classic: 90° about (1, 1, 0); φ = 0 (already in the xy plane), γ = 45°.
        return json{{"axis", {1, 1, 0}}, {"angle_deg", 90}, {"points", {{1, 0, 0}, {0, 0, 1}}}};
    }
};

Algorithm arbitrary_axis_algorithm() {
    return make_algorithm<ArbitraryAxis>(
        [](const ArbitraryAxis::Input& in) { return ArbitraryAxis::rotate(in); });
}

}  // namespace cg
