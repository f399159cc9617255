// Form factor exam problems: reciprocity. Two patches of a case with a formula — perpendicular
// rectangles sharing an edge (one problem in two), coaxial discs of different radii, or equal
// facing rectangles — with small integer sizes; the question gives F_ij (the formula's value) and
// asks for the areas and F_ji = A_i F_ij / A_j.
#include "core/format.hpp"
#include "radiosity/form_factor.hpp"

namespace cg {

FormFactor::Input FormFactor::exam_input(Rng& rng) {
    Input in;
    in.resolution = 8;
    in.samples = 2;
    in.rays = 500;
    in.seed = std::uint64_t(rng.integer(1, 1000));
    const int kind = int(rng.integer(0, 3));
    const double a = double(rng.integer(1, 3)), b = double(rng.integer(1, 3)),
                 c = double(rng.integer(1, 3));
    if (kind <= 1) {  // perpendicular, sharing the edge of length a along x
        in.from = Patch::rectangle({0, 0, 0}, {a, 0, 0}, {0, b, 0});
        in.to = Patch::rectangle({0, 0, 0}, {0, 0, c}, {a, 0, 0});
    } else if (kind == 2) {  // coaxial discs
        in.from = Patch::disc({0, 0, 0}, {0, 0, 1}, a);
        in.to = Patch::disc({0, 0, c}, {0, 0, -1}, b == a ? a + 1 : b);
    } else {  // parallel, directly opposed
        in.from = Patch::rectangle({0, 0, 0}, {a, 0, 0}, {0, b, 0});
        in.to = Patch::rectangle({0, 0, c}, {0, b, 0}, {a, 0, 0});
    }
    return in;
}

std::string FormFactor::question(const Input& in) {
    const ff::Analytic an = ff::analytic(in.from, in.to);
    std::string what;
    const auto& q = an.params;
    if (an.kase == ff::Case::PerpendicularRectangles)
        what = "Two rectangles meet at a right angle along a common edge of length " + num(q[0]) +
               ": patch i is " + num(q[1]) + " wide (away from the edge), patch j " + num(q[2]) +
               " tall.";
    else if (an.kase == ff::Case::CoaxialDiscs)
        what = "Two coaxial parallel discs face each other at distance " + num(q[2]) +
               ": patch i has radius " + num(q[0]) + ", patch j radius " + num(q[1]) + ".";
    else
        what = "Two " + num(q[0]) + " × " + num(q[1]) +
               " rectangles face each other directly at distance " + num(q[2]) + ".";
    return what + " The form factor from i to j is F_ij = " + num(an.value, 5) +
           ". Give the areas A_i (area_from) and A_j (area_to), and the form factor back from j "
           "to i by reciprocity, A_i F_ij = A_j F_ji (reciprocity/F_ji_expected).";
}

std::vector<std::string> FormFactor::answer_fields(const Input&) {
    return {"area_from", "area_to", "reciprocity/F_ji_expected"};
}

}  // namespace cg
