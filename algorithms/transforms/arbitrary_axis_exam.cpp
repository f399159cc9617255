// Arbitrary-axis exam problems: an axis with small integer components — on a diagonal of a
// coordinate plane like (1, 1, 0), a space diagonal (1, 1, 1), a (1, 2, 2)-type axis whose
// length is an integer, and now and then a coordinate axis itself (both turns are the
// identity) — with random signs; an angle from 30°, 45°, 60°, 90°, 120°, 180°, 270°, −90°;
// one or two integer points to rotate.
#include "core/format.hpp"
#include "transforms/arbitrary_axis.hpp"

namespace cg {

ArbitraryAxis::Input ArbitraryAxis::exam_input(Rng& rng) {
    static constexpr double kAxes[][3] = {{1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 2, 2},
                                          {2, 1, 2}, {2, 2, 1}, {0, 0, 1}, {1, 0, 0}, {0, 2, 0},
                                          {3, 4, 0}, {0, 3, 4}, {1, 1, 2}, {2, 1, 0}};
    static constexpr double kAngles[] = {30, 45, 60, 90, 90, 90, 120, 180, 270, -90};
    Input in;
    const auto& a = kAxes[rng.integer(0, std::size(kAxes) - 1)];
    for (int c = 0; c < 3; ++c) in.axis[c] = a[c] * (rng.chance(0.3) ? -1 : 1);
    in.angle_deg = kAngles[rng.integer(0, std::size(kAngles) - 1)];
    const int n = static_cast<int>(rng.integer(1, 2));
    for (int p = 0; p < n; ++p)
        in.points.push_back({static_cast<double>(rng.integer(-2, 2)),
                             static_cast<double>(rng.integer(-2, 2)),
                             static_cast<double>(rng.integer(-2, 2))});
    return in;
}

std::string ArbitraryAxis::question(const Input& in) {
    std::string q = "Rotate by θ = " + num(in.angle_deg) + "° about the axis a = " + num(in.axis) +
                    " through the origin (right-handed, column vectors, θ > 0 counter-clockwise "
                    "seen from the tip of a looking toward the origin). Use the construction that "
                    "maps a onto the closest coordinate axis i (largest |a_i|; a tie goes to the "
                    "earlier of x, y, z), with j, k the next two axes in the order x → y → z → x: "
                    "R = R_j(φ) R_k(γ) R_i(θ) R_k(−γ) R_j(−φ), where R_j(−φ) turns a into the "
                    "i–j plane and R_k(−γ) turns it onto axis i (for i = x: R = R_y(φ) R_z(γ) "
                    "R_x(θ) R_z(−γ) R_y(−φ)). Which axis is i (canonical_axis: \"x\", \"y\" or "
                    "\"z\"), what are φ and γ in degrees (phi_deg in (−180, 180], gamma_deg), and "
                    "what is R as a 4×4 homogeneous matrix (matrix, rows)? Rotate the point";
    q += in.points.size() > 1 ? "s " : " ";
    for (std::size_t p = 0; p < in.points.size(); ++p)
        q += (p ? ", " : "") + std::string("P") + std::to_string(p) + " = " + num(in.points[p]);
    return q + " (points).";
}

std::vector<std::string> ArbitraryAxis::answer_fields() {
    return {"canonical_axis", "phi_deg", "gamma_deg", "matrix", "points"};
}

}  // namespace cg
