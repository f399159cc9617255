// Bézier patch exam problems: a bilinear (2 × 2) or biquadratic (3 × 3) patch over a regular
// grid in the xz-plane (rows along z, columns along x) with small integer heights y (up on the
// 3D canvas, and ∂P/∂s × ∂P/∂t points up), evaluated at
// s, t ∈ {1/4, 1/2, 3/4} (bilinear) or s = t = 1/2 (biquadratic), so every Q_j and the point
// are short decimals. Now and then the heights are all 0 (a flat patch: the normal is (0, 1, 0)),
// or the first row collapses to a single point (a degenerate corner edge, away from (s, t)).
#include "core/format.hpp"
#include "curves/bezier_patch.hpp"

namespace cg {

namespace {

std::string parameter_text(double u) {
    if (u == 0.25) return "1/4";
    if (u == 0.5) return "1/2";
    if (u == 0.75) return "3/4";
    return num(u);
}

}  // namespace

BezierPatch::Input BezierPatch::exam_input(Rng& rng) {
    static constexpr double kParameters[] = {0.25, 0.5, 0.75};
    Input in;
    const bool bilinear = rng.chance(0.5);
    const int size = bilinear ? 2 : 3;
    const double spacing = bilinear ? 4 : 2;
    const long long roll = rng.integer(0, 11);
    const bool flat = roll == 0, collapsed = roll == 1;
    for (int i = 0; i < size; ++i) {
        std::vector<glm::dvec3> row;
        for (int j = 0; j < size; ++j)
            row.push_back({spacing * j, flat ? 0.0 : static_cast<double>(rng.integer(0, 4)),
                           spacing * i});
        in.control_points.push_back(std::move(row));
    }
    if (collapsed)
        for (auto& p : in.control_points[0]) p = in.control_points[0][0];
    if (bilinear) {
        in.s = kParameters[rng.integer(0, 2)];
        in.t = kParameters[rng.integer(0, 2)];
    } else {
        in.s = in.t = 0.5;
    }
    return in;
}

std::string BezierPatch::question(const Input& in) {
    const int m = static_cast<int>(in.control_points.size()) - 1;
    const int n = static_cast<int>(in.control_points[0].size()) - 1;
    std::string points;
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j)
            points += (i + j ? ", " : "") + std::string("P") + std::to_string(i) +
                      std::to_string(j) + " = " +
                      num(in.control_points[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
    const std::string kind = m == 1 && n == 1 ? "bilinear" : m == 2 && n == 2 ? "biquadratic"
                                                                             : "tensor-product";
    return "The " + kind +
           " Bézier patch P(s, t) = Σ_i Σ_j P_ij B_i(s) B_j(t) has the control points " + points +
           " (first index i with s, second index j with t). Evaluate P(" + parameter_text(in.s) +
           ", " + parameter_text(in.t) +
           ") by de Casteljau, first along s: give the points Q_j = Σ_i P_ij B_i(s) of each column, "
           "the surface point, the partial derivatives ∂P/∂s and ∂P/∂t there, and the unit normal "
           "(∂P/∂s × ∂P/∂t, normalised).";
}

std::vector<std::string> BezierPatch::answer_fields() {
    return {"column_points", "point", "ds", "dt", "normal"};
}

}  // namespace cg
