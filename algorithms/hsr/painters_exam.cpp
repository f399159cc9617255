// Painter's algorithm exam problems: a 6 × 6 screen with two or three rectangles and right
// triangles on simple planes (hsr_exam_shapes.hpp), so every test can be done by hand: extents
// from the corners, plane sides from depths that are short decimals. About one problem in four
// puts a pair in one flat plane, where the tie rule orders them.
#include "core/format.hpp"
#include "hsr/hsr_exam_shapes.hpp"
#include "hsr/painters.hpp"

namespace cg {

Painters::Input Painters::exam_input(Rng& rng) {
    Input in;
    in.scene.width = in.scene.height = 6;
    const int n = static_cast<int>(rng.integer(2, 3));
    const bool tie = rng.chance(0.25);
    for (int k = 0; k < n; ++k) {
        auto p = hsr::exam_polygon(rng, 6, static_cast<double>(rng.integer(2, 9)));
        if (tie && k < 2) {  // P0 and P1 flat at one depth
            const double z = tie && k == 1 ? in.scene.polygons[0].vertices[0].z : p.vertices[0].z;
            for (auto& v : p.vertices) v.z = z;
        }
        in.scene.polygons.push_back(std::move(p));
    }
    return in;
}

std::string Painters::question(const Input& in) {
    std::string q = "Apply the painter's algorithm on a " + std::to_string(in.scene.width) + " × " +
                    std::to_string(in.scene.height) +
                    " screen (smaller z nearer; pixel (i, j) sampled at its centre (i + ½, j + ½)) to";
    for (std::size_t k = 0; k < in.scene.polygons.size(); ++k) {
        q += " P" + std::to_string(k) + ":";
        for (const auto& v : in.scene.polygons[k].vertices) q += " " + num(v);
        q += k + 1 < in.scene.polygons.size() ? ";" : ".";
    }
    q += " Sort on farthest z (equal: higher index first). For P, the farthest polygon of the list, "
         "and each Q whose z extent overlaps P's, which test first shows P may be drawn before Q "
         "(1 x extents apart, 2 y extents apart, 3 P behind Q's plane, 4 Q in front of P's plane, "
         "5 projections apart), or is Q moved (\"move\") or a polygon split (\"split\")? Give the "
         "tests in the order the pairs are tested, and the drawing order (polygon indices, back to "
         "front).";
    return q;
}

std::vector<std::string> Painters::answer_fields() { return {"tests", "order"}; }

}  // namespace cg
