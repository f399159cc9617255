// Image morphing exam problems: one feature line pair and one pixel, worked by hand. Two 4 × 4
// grey images of small integers; the line in A runs 2 or 3 pixels along a row or a column
// through pixel centres (either way round), the line in B is the same line moved by a small
// even offset, and α is 0.25, 0.5 or 0.75. For one pixel centre X the student computes u and v
// against the interpolated line, the source points X'_A and X'_B (with one line the weight
// does not matter: X' = X'_1), and the morph's value there, bilinear sampling included
// (clamped at the border). Answers to 3 decimals.
#include "animation/image_morph.hpp"
#include "core/format.hpp"

namespace cg {

ImageMorph::Input ImageMorph::exam_input(Rng& rng) {
    Input in;
    for (Image* img : {&in.image_a, &in.image_b}) {
        img->width = img->height = 4;
        for (int k = 0; k < 16; ++k) img->v.push_back(double(rng.integer(0, 9)) * 10);
    }
    const bool vertical = rng.chance(0.5);
    const double len = double(rng.integer(2, 3));
    const double s = double(rng.integer(0, vertical ? 3 : 3)) + 0.5;  // the column (or row)
    const double from = 0.5 + double(rng.integer(0, 3 - int(len)));
    Line a = vertical ? Line{{s, from}, {s, from + len}} : Line{{from, s}, {from + len, s}};
    if (rng.chance(0.5)) std::swap(a.p, a.q);
    glm::dvec2 shift{0, 0};
    while (shift == glm::dvec2(0))
        shift = {2.0 * double(rng.integer(-1, 1)), 2.0 * double(rng.integer(-1, 1))};
    in.lines = {{a, {a.p + shift, a.q + shift}}};
    const double alphas[] = {0.25, 0.5, 0.75};
    in.alphas = {alphas[rng.integer(0, 2)]};
    in.focus_x = int(rng.integer(0, 3));
    in.focus_y = int(rng.integer(0, 3));
    return in;
}

std::string ImageMorph::question(const Input& in) {
    auto rows = [](const Image& img) {
        std::string t;
        for (int r = 0; r < img.height; ++r) {
            t += r ? ", [" : "[";
            for (int c = 0; c < img.width; ++c) t += (c ? ", " : "") + num(img.at(c, r));
            t += "]";
        }
        return t;
    };
    const Pair& p = in.lines.at(0);
    const double x = in.focus_x + 0.5, y = in.focus_y + 0.5;
    return "Image A has the rows (top first) " + rows(in.image_a) + "; image B has " +
           rows(in.image_b) + ". Pixel (c, r) has its centre at (c + 0.5, r + 0.5). One feature "
           "line pair: P Q = " + num(p.a.p) + " → " + num(p.a.q) + " in A, P' Q' = " + num(p.b.p) +
           " → " + num(p.b.q) + " in B. For the frame α = " + num(in.alphas.at(0)) +
           ", interpolate the line's endpoints, and for the pixel centre X = (" + num(x) + ", " +
           num(y) + ") compute, against the interpolated line P_α Q_α, u = (X − P_α)·(Q_α − "
           "P_α)/|Q_α − P_α|² and v = (X − P_α)·perp(Q_α − P_α)/|Q_α − P_α| with perp(x, y) = "
           "(−y, x); the source point X'_A = P + u (Q − P) + v perp(Q − P)/|Q − P| in A and "
           "likewise X'_B in B; and the morph's value (1 − α) A(X'_A) + α B(X'_B), sampling "
           "bilinearly between pixel centres (clamped at the border). Give u, v, X'_A and X'_B "
           "as [x, y], and the value, to 3 decimals.";
}

}  // namespace cg
