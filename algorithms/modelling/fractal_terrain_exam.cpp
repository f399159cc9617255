// Fractal terrain exam problems: one level by hand. Two times in three a triangle with digit
// heights (one time in ten all equal) and an amplitude of 1 or 2: "give the six heights after
// one level of midpoint displacement with these random offsets"; otherwise a square with digit
// corners, one diamond–square level (the centre, then the four edge midpoints, each averaging
// its three neighbours). The offsets are the generator's, stated in the question in the order
// they are used.
#include "core/format.hpp"
#include "modelling/fractal_terrain.hpp"

namespace cg {

FractalTerrain::Input FractalTerrain::exam_input(Rng& rng) {
    Input in;
    in.levels = 1;
    in.roughness = 1;
    in.amplitude = double(rng.integer(1, 2));
    in.seed = std::uint64_t(rng.integer(1, 1 << 30));
    if (rng.chance(2.0 / 3)) {
        in.method = Method::Triangle;
        const bool flat = rng.chance(0.1);
        const double c = double(rng.integer(0, 9));
        auto height = [&] { return flat ? c : double(rng.integer(0, 9)); };
        in.triangle = {glm::dvec3(0, height(), 0), glm::dvec3(4, height(), 0),
                       glm::dvec3(0, height(), 4)};
    } else {
        in.method = Method::Grid;
        in.size = 4;
        for (double& h : in.corners) h = double(rng.integer(0, 9));
    }
    return in;
}

std::string FractalTerrain::question(const Input& in) {
    // The offsets in the order the level uses them.
    Rng rng(in.seed);
    const int count = in.method == Method::Triangle ? 3 : 5;
    std::string offsets;
    for (int k = 0; k < count; ++k)
        offsets += (k ? ", " : "") + num(rng.uniform(-in.amplitude, in.amplitude), 6);
    if (in.method == Method::Triangle) {
        const auto& t = in.triangle;
        return "Midpoint displacement, one level: the triangle A = " + num(t[0]) + ", B = " +
               num(t[1]) + ", C = " + num(t[2]) +
               " (y is the height) is split into four through its edge midpoints. Each "
               "midpoint's height is the average of its edge's two ends plus a random offset; "
               "the offsets (amplitude " + num(in.amplitude) + ") are, in order, for AB, AC "
               "and BC: " + offsets +
               ". Give the six heights (heights) in the order A, mid AB, B, mid AC, mid BC, C, "
               "and how many triangles there are now (triangle_count).";
    }
    const auto& c = in.corners;
    // Row j = 0 lies at z = −size/2: the far side in the default view (z toward the viewer).
    return "Diamond–square, one level, on a square whose corners have heights " + num(c[0]) +
           " (back left), " + num(c[1]) + " (back right), " + num(c[2]) + " (front left) and " +
           num(c[3]) +
           " (front right). The diamond step gives the centre the average of the four corners "
           "plus a random offset; the square step gives each edge's midpoint the average of its "
           "three neighbours (its edge's two corners and the centre) plus an offset. The "
           "offsets (amplitude " + num(in.amplitude) + ") are, in order, for the centre, the "
           "back, left, right and front midpoints: " + offsets +
           ". Give the nine heights (heights) row by row from the back: back left, back "
           "midpoint, back right, left midpoint, centre, right midpoint, front left, front "
           "midpoint, front right.";
}

std::vector<std::string> FractalTerrain::answer_fields(const Input& in) {
    if (in.method == Method::Triangle) return {"heights", "triangle_count"};
    return {"heights"};
}

}  // namespace cg
