// Free-form deformation exam problems: a bilinear (1 × 1) or 2 × 1 lattice over the box
// [0, 4] × [0, 4], one or two control points moved by small whole numbers, and one point whose
// local coordinates are quarters (one time in six it lies outside the box, s = 1.25, and must
// stay put). The answer: (s, t) and X' = Σ_i Σ_j B_i^l(s) B_j^m(t) P_ij; by linear precision
// X' = X + Σ B_i(s) B_j(t) ΔP_ij, a few products of quarters, exact in binary.
#include "animation/morph_ffd.hpp"
#include "core/format.hpp"

namespace cg {

MorphFfd::Input MorphFfd::exam_input(Rng& rng) {
    Input in;
    in.box_min = {0, 0};
    in.box_max = {4, 4};
    in.l = int(rng.integer(1, 2));
    in.m = 1;
    const int moved = int(rng.integer(1, 2));
    for (int q = 0; q < moved; ++q) {
        Move mv;
        do {
            mv.i = int(rng.integer(0, in.l));
            mv.j = int(rng.integer(0, in.m));
        } while (q == 1 && mv.i == in.moves[0].i && mv.j == in.moves[0].j);
        do mv.value = {double(rng.integer(-2, 2)), double(rng.integer(-2, 2))};
        while (mv.value == glm::dvec2(0));
        in.moves.push_back(mv);
    }
    const double s = rng.chance(1.0 / 6) ? 1.25 : 0.25 * double(rng.integer(1, 3));
    const double t = 0.25 * double(rng.integer(1, 3));
    in.shape = {{4 * s, 4 * t}};
    return in;
}

std::string MorphFfd::question(const Input& in) {
    std::string q = "A 2D free-form deformation lattice of degree " + std::to_string(in.l) + " × " +
                    std::to_string(in.m) + " lies over the box " + num(in.box_min) + " to " +
                    num(in.box_max) + ": control points P_ij = X_0 + (i/" + std::to_string(in.l) +
                    ") S + (j/" + std::to_string(in.m) + ") T, i = 0.." + std::to_string(in.l) +
                    " along x, j = 0.." + std::to_string(in.m) + " along y. These move:";
    for (std::size_t k = 0; k < in.moves.size(); ++k)
        q += std::string(k ? ";" : "") + " P_" + std::to_string(in.moves[k].i) +
             std::to_string(in.moves[k].j) + " by " + num(in.moves[k].value);
    q += ". Where does the point X = " + num(in.shape.at(0)) +
         " go? Give its local coordinates (s, t) as \"local/0\" and the deformed point X' = "
         "Σ_i Σ_j B_i^l(s) B_j^m(t) P_ij as \"deformed/0\", to 3 decimals (a point outside the "
         "box stays where it is).";
    return q;
}

}  // namespace cg
