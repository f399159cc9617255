// Bernstein exam problems: the weights B_i^n(t) of a cubic (now and then a quadratic) at t in
// {1/4, 1/3, 1/2, 2/3, 3/4} and the curve point they give, for integer control points in
// [0, 8] × [0, 6]. The weights are simple fractions (denominators 27 or 64 at most).
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "curves/bernstein.hpp"

namespace cg {

namespace {

std::string parameter_text(double t) {
    for (int den : {2, 3, 4}) {
        const double top = t * den;
        const long long rounded = std::llround(top);
        if (rounded > 0 && rounded < den && std::abs(top - static_cast<double>(rounded)) < 1e-12)
            return std::to_string(rounded) + "/" + std::to_string(den);
    }
    return num(t);
}

}  // namespace

Bernstein::Input Bernstein::exam_input(Rng& rng) {
    static constexpr double kParameters[] = {0.25, 1.0 / 3, 0.5, 2.0 / 3, 0.75};
    Input in;
    const int n = rng.integer(0, 3) == 0 ? 2 : 3;
    double x = static_cast<double>(rng.integer(0, 1));
    for (int i = 0; i <= n; ++i) {
        in.control_points.push_back({x, static_cast<double>(rng.integer(0, 6))});
        x = std::min(8.0, x + static_cast<double>(rng.integer(1, 8 / n)));
    }
    in.t = kParameters[rng.integer(0, 4)];
    return in;
}

std::string Bernstein::question(const Input& in) {
    const int n = static_cast<int>(in.control_points.size()) - 1;
    std::string points;
    for (int i = 0; i <= n; ++i)
        points += (i ? ", " : "") + std::string("P") + std::to_string(i) + " = " +
                  num(in.control_points[static_cast<std::size_t>(i)]);
    const std::string t = parameter_text(in.t);
    return "A Bézier curve of degree " + std::to_string(n) + " has the control points " + points +
           ". Give the Bernstein weights B_i^" + std::to_string(n) + "(" + t + ") for i = 0 .. " +
           std::to_string(n) + " (as a list, i = 0 first) and the curve point P(" + t +
           ") = Σ B_i P_i. (Check: the weights add up to 1.)";
}

std::vector<std::string> Bernstein::answer_fields() {
    return {"basis", "point"};
}

}  // namespace cg
