// Arc-length exam problems: a quadratic (now and then a straight line written as one) with
// integer control points in [0, 8] × [0, 6], sampled at N = 4 equal steps of u, and one
// distance s, a multiple of 1/2 strictly inside the curve, to turn into a parameter. The
// chords need a calculator (square roots), the rest is one linear interpolation.
#include <cmath>

#include "core/format.hpp"
#include "curves/arc_length.hpp"

namespace cg {

ArcLength::Input ArcLength::exam_input(Rng& rng) {
    Input in;
    in.samples = 4;
    const glm::dvec3 p0{static_cast<double>(rng.integer(0, 2)),
                        static_cast<double>(rng.integer(0, 3)), 0};
    const glm::dvec3 p2{static_cast<double>(rng.integer(5, 8)),
                        static_cast<double>(rng.integer(0, 3)), 0};
    glm::dvec3 p1{static_cast<double>(rng.integer(1, 7)), static_cast<double>(rng.integer(3, 6)),
                  0};
    if (rng.chance(0.15)) p1 = (p0 + p2) / 2.0;  // a straight line: the table is exact
    in.control_points = {p0, p1, p2};
    const double length = table_length(in.control_points, in.samples);
    static constexpr double kFractions[] = {0.25, 0.4, 0.5, 0.6, 0.75};
    double s = std::round(2 * length * kFractions[rng.integer(0, 4)]) / 2;
    if (s <= 0) s = 0.5;
    if (s >= length) s = std::floor(2 * length - 1e-9) / 2;
    in.distances = {s};
    return in;
}

std::string ArcLength::question(const Input& in) {
    std::string points;
    for (std::size_t i = 0; i < in.control_points.size(); ++i) {
        const glm::dvec3 p = in.control_points[i];
        points += (i ? ", " : "") + std::string("P") + std::to_string(i) + " = " +
                  (in.dim == 3 ? num(p) : num(glm::dvec2(p.x, p.y)));
    }
    std::string us;
    for (int j = 0; j <= in.samples; ++j)
        us += (j ? ", " : "") + num(static_cast<double>(j) / in.samples);
    std::string ds;
    for (std::size_t i = 0; i < in.distances.size(); ++i)
        ds += (i ? ", " : "") + num(in.distances[i]);
    return "A motion path is the Bézier curve with control points " + points +
           ". Sample it at u = " + us +
           " and build the arc-length table: the rows [u_j, s_j], where s_j adds up the chord "
           "lengths "
           "|P(u_j) − P(u_{j−1})| (s_0 = 0). Give the table, its total length L, and for the "
           "distance s = " +
           ds +
           " the parameter u found by linear interpolation between the bracketing rows, with the "
           "point P(u) "
           "(as queries: s, u, point).";
}

std::vector<std::string> ArcLength::answer_fields() {
    return {"table", "length", "queries"};
}

}  // namespace cg
