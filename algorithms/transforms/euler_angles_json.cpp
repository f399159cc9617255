// Euler angles, JSON:
//   input  {"order": "xyz" | "xzy" | "yxz" | "yzx" | "zxy" | "zyx" (the first letter's roll is
//           applied first; "xyz": R = R_z(θ3) R_y(θ2) R_x(θ1)),
//           "angles_deg": [θ1, θ2, θ3] (for the letters of order, in that order)}
//   result {"matrix": 3×3 rows, "gimbal_lock": bool (θ2 = ±90°),
//           "lock_sign": s (±1 when locked: R depends only on θ3 + s θ1; else 0),
//           "lock_angle_deg": θ3 + s θ1 wrapped to (−180, 180] when locked, else 0}
#include "io/registry.hpp"
#include "transforms/euler_angles.hpp"

namespace cg {

template <>
struct JsonIo<EulerAngles> {
    static EulerAngles::Input input(const json& j) {
        Reader r(j);
        r.only({"order", "angles_deg"});
        EulerAngles::Input in;
        in.order = r.string("order");
        in.angles_deg = r.point3("angles_deg");
        return in;
    }

    static json input_json(const EulerAngles::Input& in) {
        return json{{"order", in.order}, {"angles_deg", nice_point(in.angles_deg)}};
    }

    static json result(const EulerAngles::Result& r) {
        return json{{"matrix", to_json(Value(rot::rows3(r.matrix)))},
                    {"gimbal_lock", r.gimbal_lock},
                    {"lock_sign", r.lock_sign},
                    {"lock_angle_deg", r.lock_angle_deg}};
    }

    static json example() {
        // x, then y by 90°, then z: locked — the x and z rolls turn about the same line.
        return json{{"order", "xyz"}, {"angles_deg", {30, 90, 45}}};
    }
};

Algorithm euler_angles_algorithm() {
    return make_algorithm<EulerAngles>(
        [](const EulerAngles::Input& in) { return EulerAngles::compose(in); });
}

}  // namespace cg
