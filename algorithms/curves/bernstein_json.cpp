// Bernstein's JSON:
//   input  {"control_points": [[x, y], …], "t": t, "extrapolate": false,
//           "transform": [[a, b, c], [d, e, f], [0, 0, 1]] (optional, rows)}
//   result {"basis": [B_0, …, B_n], "sum", "non_negative", "point": [x, y],
//           "hull": [[x, y], …], "inside_hull",
//           "transformed_point": Σ B_i T(P_i) | null, "image_of_point": T(P(t)) | null,
//           "affine_invariant": bool | null}
#include "curves/bernstein.hpp"
#include "curves/curves_json.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<Bernstein> {
    static Bernstein::Input input(const json& j) {
        Reader r(j);
        r.only({"control_points", "t", "extrapolate", "transform"});
        Bernstein::Input in;
        int dim = 2;
        for (const glm::dvec3& p : curves::read_points(r, "control_points", dim, false))
            in.control_points.push_back({p.x, p.y});
        in.t = r.number("t");
        if (r.has("extrapolate")) in.extrapolate = r.boolean("extrapolate");
        if (r.has("transform") && !r.get("transform").is_null()) {
            const json& m = r.get("transform");
            if (!m.is_array() || m.size() != 3)
                throw InputError("transform", "must be 3 rows of 3 numbers, got " + describe(m));
            Bernstein::Rows rows;
            for (std::size_t i = 0; i < 3; ++i) {
                const std::string field = "transform[" + std::to_string(i) + "]";
                if (!m[i].is_array() || m[i].size() != 3)
                    throw InputError(field, "must be a row of 3 numbers, got " + describe(m[i]));
                for (std::size_t c = 0; c < 3; ++c)
                    rows[i][static_cast<int>(c)] =
                        as_number(m[i][c], field + "[" + std::to_string(c) + "]");
            }
            in.transform = rows;
        }
        return in;
    }

    static json input_json(const Bernstein::Input& in) {
        json points = json::array();
        for (glm::dvec2 p : in.control_points) points.push_back(nice_point(p));
        json j{{"control_points", std::move(points)}, {"t", nice_number(in.t)}};
        if (in.extrapolate) j["extrapolate"] = true;
        if (in.transform) {
            json rows = json::array();
            for (const glm::dvec3& row : *in.transform) rows.push_back(nice_point(row));
            j["transform"] = std::move(rows);
        }
        return j;
    }

    static json result(const Bernstein::Result& r) {
        json hull = json::array();
        for (glm::dvec2 p : r.hull) hull.push_back(to_json(p));
        return json{
            {"basis", r.basis},
            {"sum", r.sum},
            {"non_negative", r.non_negative},
            {"point", to_json(r.point)},
            {"hull", std::move(hull)},
            {"inside_hull", r.inside_hull},
            {"transformed_point",
             r.transformed_point ? to_json(*r.transformed_point) : json(nullptr)},
            {"image_of_point", r.image_of_point ? to_json(*r.image_of_point) : json(nullptr)},
            {"affine_invariant", r.affine_invariant ? json(*r.affine_invariant) : json(nullptr)}};
    }

    static json example() {
        // A cubic at t = 1/3, and a rotation by 90° plus a shift to show affine invariance.
        return json{{"control_points", {{0, 0}, {1, 3}, {4, 4}, {6, 1}}},
                    {"t", 1.0 / 3},
                    {"transform", {{0, -1, 12}, {1, 0, -1}, {0, 0, 1}}}};
    }
};

Algorithm bernstein_algorithm() {
    return make_algorithm<Bernstein>(NoPlain{
        "the stepped sum is the only implementation; the tests hold it to de Casteljau, exact "
        "binomials and the partition of unity on 2,000 random curves"});
}

}  // namespace cg
