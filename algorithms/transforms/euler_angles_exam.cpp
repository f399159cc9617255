// Euler-angle exam problems: one of the six orders, angles that are multiples of 30° or 45°
// (so every entry is 0, ±1/2, ±√2/2, ±√3/2 or ±1 and products stay short), and about one
// problem in three with the middle angle at ±90°: the gimbal lock.
#include "core/format.hpp"
#include "transforms/euler_angles.hpp"

namespace cg {

EulerAngles::Input EulerAngles::exam_input(Rng& rng) {
    static const char* kOrders[] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx"};
    static constexpr double kAngles[] = {0, 30, 45, 60, 90, -30, -45, -60, -90, 120, 180};
    Input in;
    in.order = kOrders[rng.integer(0, 5)];
    for (int n = 0; n < 3; ++n) in.angles_deg[n] = kAngles[rng.integer(0, std::size(kAngles) - 1)];
    if (rng.chance(1.0 / 3)) in.angles_deg[1] = rng.chance(0.5) ? 90 : -90;
    return in;
}

std::string EulerAngles::question(const Input& in) {
    const std::string& o = in.order;
    return std::string("An object is rolled about the fixed world axes: first about ") + o[0] +
           " by θ1 = " + num(in.angles_deg[0]) + "°, then about " + o[1] +
           " by θ2 = " + num(in.angles_deg[1]) + "°, then about " + o[2] +
           " by θ3 = " + num(in.angles_deg[2]) +
           "° (right-handed, column vectors). Give the 3×3 rotation matrix R = R_" + o[2] +
           "(θ3) R_" + o[1] + "(θ2) R_" + o[0] +
           "(θ1) (matrix, rows), and say whether these angles are in gimbal lock (gimbal_lock: "
           "true or false).";
}

std::vector<std::string> EulerAngles::answer_fields() {
    return {"matrix", "gimbal_lock"};
}

}  // namespace cg
