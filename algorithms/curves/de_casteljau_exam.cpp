// De Casteljau exam problems: a curve of degree 2 or 3 (now and then 1 or 4) with integer
// control points in [0, 8] × [0, 6], evaluated at t in {1/4, 1/3, 1/2, 2/3, 3/4}, so every
// level is a short decimal or a simple third. About one problem in six repeats a control point
// (a degenerate polygon the construction handles like any other).
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "curves/de_casteljau.hpp"

namespace cg {

namespace {

// "1/3" for the exam's parameters, else the decimal.
std::string parameter_text(double t) {
    for (int den : {2, 3, 4}) {
        const double top = t * den;
        const long long rounded = static_cast<long long>(top + 0.5);
        if (rounded > 0 && rounded < den && std::abs(top - static_cast<double>(rounded)) < 1e-12)
            return std::to_string(rounded) + "/" + std::to_string(den);
    }
    return num(t);
}

}  // namespace

DeCasteljau::Input DeCasteljau::exam_input(Rng& rng) {
    static constexpr double kParameters[] = {0.25, 1.0 / 3, 0.5, 2.0 / 3, 0.75};
    Input in;
    const long long roll = rng.integer(0, 19);
    const int n = roll < 11 ? 3 : roll < 17 ? 2 : roll < 18 ? 1 : 4;
    // x mostly increasing, so the curve reads left to right.
    double x = static_cast<double>(rng.integer(0, 1));
    for (int i = 0; i <= n; ++i) {
        in.control_points.push_back({x, static_cast<double>(rng.integer(0, 6)), 0});
        x = std::min(8.0, x + static_cast<double>(rng.integer(1, 8 / n)));
    }
    if (rng.chance(1.0 / 6)) in.control_points[1] = in.control_points[0];
    in.t = kParameters[rng.integer(0, 4)];
    return in;
}

std::string DeCasteljau::question(const Input& in) {
    static constexpr const char* kDegree[] = {"", "linear", "quadratic", "cubic", "quartic"};
    const int n = static_cast<int>(in.control_points.size()) - 1;
    std::string points;
    for (int i = 0; i <= n; ++i) {
        const glm::dvec3 p = in.control_points[static_cast<std::size_t>(i)];
        points += (i ? ", " : "") + std::string("P") + std::to_string(i) + " = " +
                  (in.dim == 3 ? num(p) : num(glm::dvec2(p.x, p.y)));
    }
    const std::string degree = n < 5 ? kDegree[n] : "degree-" + std::to_string(n);
    return "Evaluate the " + degree + " Bézier curve with control points " + points +
           " at t = " + parameter_text(in.t) +
           " with de Casteljau's algorithm, writing down every level of the construction. Give the "
           "point P(t), the tangent vector P′(t), and the control polygons of the two halves when "
           "the curve is split at t (left: P(0) to P(t); right: P(t) to P(1)).";
}

std::vector<std::string> DeCasteljau::answer_fields() {
    return {"point", "tangent", "left", "right"};
}

}  // namespace cg
