// Slerp, JSON:
//   input  {"q0": [w, x, y, z], "q1": [w, x, y, z] (any length ≠ 0, normalised on input),
//           "u": u in [0, 1] (outside is refused: no extrapolation)}
//   result {"q": [w, x, y, z] (unit), "omega_deg": ω (after the flip, [0, 90]),
//           "matrix": 3×3 rows, "flipped": q1 was negated, "fallback": normalised lerp used}
#include "io/registry.hpp"
#include "transforms/slerp.hpp"

namespace cg {

namespace {


}  // namespace

template <>
struct JsonIo<Slerp> {
    static Slerp::Input input(const json& j) {
        Reader r(j);
        r.only({"q0", "q1", "u"});
        Slerp::Input in;
        in.q0 = r.quat("q0");
        in.q1 = r.quat("q1");
        in.u = r.number("u");
        return in;
    }

    static json input_json(const Slerp::Input& in) {
        return json{{"q0", nice_quat(in.q0)}, {"q1", nice_quat(in.q1)}, {"u", in.u}};
    }

    static json result(const Slerp::Result& r) {
        return json{{"q", quat_json(r.q)},
                    {"omega_deg", r.omega_deg},
                    {"matrix", to_json(Value(rot::rows3(r.matrix)))},
                    {"flipped", r.flipped},
                    {"fallback", r.fallback}};
    }

    static json example() {
        // A quarter turn about z to a quarter turn about x (unnormalised), a third of the way.
        return json{{"q0", {1, 0, 0, 1}}, {"q1", {1, 1, 0, 0}}, {"u", 1.0 / 3}};
    }
};

Algorithm slerp_algorithm() {
    return make_algorithm<Slerp>();
}

}  // namespace cg
