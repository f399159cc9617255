// Z-buffer exam problems: a 6 × 6 screen with two or three rectangles and right triangles on
// simple planes (hsr_exam_shapes.hpp). About one problem in five gives two polygons the same
// constant depth, so the tie rule (the earlier polygon stays) decides the overlap.
#include "core/format.hpp"
#include "hsr/hsr_exam_shapes.hpp"
#include "hsr/z_buffer.hpp"

namespace cg {

ZBuffer::Input ZBuffer::exam_input(Rng& rng) {
    Input in;
    in.scene.width = in.scene.height = 6;
    const int n = static_cast<int>(rng.integer(2, 3));
    const bool tie = rng.chance(0.2);
    for (int k = 0; k < n; ++k) {
        const double z0 = tie && k > 0 ? in.scene.polygons[0].vertices[0].z : static_cast<double>(rng.integer(2, 9));
        auto p = hsr::exam_polygon(rng, 6, z0);
        if (tie && k > 0) for (auto& v : p.vertices) v.z = z0;  // the same flat depth as P0
        if (tie && k == 0) for (auto& v : p.vertices) v.z = z0;
        in.scene.polygons.push_back(std::move(p));
    }
    return in;
}

std::string ZBuffer::question(const Input& in) {
    std::string q = "Run the z-buffer algorithm on a " + std::to_string(in.scene.width) + " × " +
                    std::to_string(in.scene.height) +
                    " screen (pixel (i, j) sampled at its centre (i + ½, j + ½), smaller z nearer), "
                    "drawing the polygons in this order:";
    for (std::size_t k = 0; k < in.scene.polygons.size(); ++k) {
        q += " P" + std::to_string(k) + " with vertices";
        for (const auto& v : in.scene.polygons[k].vertices) q += " " + num(v);
        q += k + 1 < in.scene.polygons.size() ? ";" : ".";
    }
    q += " A centre on an edge belongs to the polygon by the top-left rule; a pixel is overwritten "
         "only by a strictly smaller z. Give the polygon index seen at every pixel (ids: rows from "
         "the bottom row j = 0 up, −1 for background) and how many times the buffers are written.";
    return q;
}

std::vector<std::string> ZBuffer::answer_fields() { return {"ids", "writes"}; }

}  // namespace cg
