// Warnock exam problems: an 8 × 8 screen (so areas halve 8, 4, 2, 1) with three polygons —
// rectangles and right triangles with integer corners on simple planes (hsr_exam_shapes.hpp);
// about one problem in three has a far polygon surrounding the whole screen, the case where the
// surrounding-polygon rule saves the most work.
#include "core/format.hpp"
#include "hsr/hsr_exam_shapes.hpp"
#include "hsr/warnock.hpp"

namespace cg {

Warnock::Input Warnock::exam_input(Rng& rng) {
    Input in;
    in.scene.width = in.scene.height = 8;
    const bool backdrop = rng.chance(1.0 / 3);
    if (backdrop) {
        hsr::ScreenPolygon p;
        p.vertices = {{-1, -1, 20}, {9, -1, 20}, {9, 9, 20}, {-1, 9, 20}};
        p.color = {0.8, 0.8, 0.6};
        in.scene.polygons.push_back(p);
    }
    while (in.scene.polygons.size() < 3)
        in.scene.polygons.push_back(hsr::exam_polygon(rng, 8, static_cast<double>(rng.integer(2, 9))));
    return in;
}

std::string Warnock::question(const Input& in) {
    std::string q = "Apply Warnock's algorithm to this " + std::to_string(in.scene.width) + " × " +
                    std::to_string(in.scene.height) +
                    " screen (smaller z nearer; pixel (i, j) sampled at its centre (i + ½, j + ½)) with "
                    "the polygons";
    for (std::size_t k = 0; k < in.scene.polygons.size(); ++k) {
        q += " P" + std::to_string(k) + ":";
        for (const auto& v : in.scene.polygons[k].vertices) q += " " + num(v);
        q += k + 1 < in.scene.polygons.size() ? ";" : ".";
    }
    q += " An area is simple when no polygon overlaps it, one polygon does, a surrounding polygon is "
         "nearer than all others at the area's four corners, or it is one pixel; otherwise split it "
         "into bottom-left, bottom-right, top-left, top-right quarters, examined in that order. How "
         "many areas are examined, and which polygon is drawn at each pixel (ids: rows from the "
         "bottom row up, −1 for background)?";
    return q;
}

std::vector<std::string> Warnock::answer_fields() { return {"areas", "ids"}; }

}  // namespace cg
