// De Casteljau's JSON:
//   input  {"control_points": [[x, y], …] or [[x, y, z], …], "t": t, "extrapolate": false}
//   result {"point", "tangent", "levels": [[P_0^k, …], …] (level 0 = the control points),
//           "left": [P_0^0, …, P_0^n], "right": [P_0^n, …, P_n^0]}
#include "curves/curves_json.hpp"
#include "curves/de_casteljau.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<DeCasteljau> {
    static DeCasteljau::Input input(const json& j) {
        Reader r(j);
        r.only({"control_points", "t", "extrapolate"});
        DeCasteljau::Input in;
        in.control_points = curves::read_points(r, "control_points", in.dim);
        in.t = r.number("t");
        if (r.has("extrapolate")) in.extrapolate = r.boolean("extrapolate");
        return in;
    }

    static json input_json(const DeCasteljau::Input& in) {
        json j{{"control_points", curves::nice_points(in.control_points, in.dim)},
               {"t", nice_number(in.t)}};
        if (in.extrapolate) j["extrapolate"] = true;
        return j;
    }

    static json result(const DeCasteljau::Result& r) {
        json levels = json::array();
        for (int k = 0; k <= r.n; ++k) levels.push_back(curves::points_json(r.level(k), r.dim));
        return json{{"point", curves::point_json(r.point, r.dim)},
                    {"tangent", curves::point_json(r.tangent, r.dim)},
                    {"levels", std::move(levels)},
                    {"left", curves::points_json(r.left(), r.dim)},
                    {"right", curves::points_json(r.right(), r.dim)}};
    }

    static json example() {
        // A cubic evaluated half way: the classic picture of the construction.
        return json{{"control_points", {{0, 0}, {1, 3}, {4, 4}, {6, 1}}}, {"t", 0.5}};
    }
};

Algorithm de_casteljau_algorithm() {
    return make_algorithm<DeCasteljau>(
        [](const DeCasteljau::Input& in) { return DeCasteljau::evaluate(in); });
}

}  // namespace cg
