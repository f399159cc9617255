// Supersampling exam problems: a pixel (i, j) with small indices, an edge through a point with
// quarter-pixel coordinates at one of the course's angles (0°, 30°, 45°, 60°, 90°, …), and 4
// or 9 samples — jittered mostly, sometimes regular — with the box filter. The question gives
// the jittered pattern's uniform numbers ξ for the seed (a student cannot run the generator),
// and asks for the sample positions, the estimate and the exact covered fraction.
#include "core/format.hpp"
#include "sampling/supersampling.hpp"

namespace cg {

Supersampling::Input Supersampling::exam_input(Rng& rng) {
    static constexpr double kAngles[] = {0,   30,  45,  60,  90,  120, 135,
                                         150, 180, 210, 225, 270, 300, 315};
    Input in;
    in.pattern = rng.chance(0.75) ? sampling::Pattern::Jittered : sampling::Pattern::Regular;
    in.samples = rng.chance(0.6) ? 4 : 9;
    in.filter = sampling::Filter::Box;
    in.i = static_cast<int>(rng.integer(0, 5));
    in.j = static_cast<int>(rng.integer(0, 5));
    in.scene.kind = sampling::RegionKind::Edge;
    const double px = in.i + rng.integer(1, 3) / 4.0;
    const double py = in.j + rng.integer(1, 3) / 4.0;
    in.scene.point = {px, py};
    in.scene.angle_deg = kAngles[rng.integer(0, std::size(kAngles) - 1)];
    in.seed = static_cast<std::uint64_t>(rng.integer(1, 9999));
    return in;
}

std::string Supersampling::question(const Input& in) {
    const int n = sampling::grid_side(in.samples);
    const std::string N = std::to_string(n);
    std::string q = "Pixel (" + std::to_string(in.i) + ", " + std::to_string(in.j) + ") covers [" +
                    std::to_string(in.i) + ", " + std::to_string(in.i + 1) + ") × [" +
                    std::to_string(in.j) + ", " + std::to_string(in.j + 1) +
                    ") (y up). The scene is the half-plane to the left of the directed edge "
                    "through " +
                    num(in.scene.point) + " at " + num(in.scene.angle_deg) +
                    "° (counter-clockwise from +x): value 1 there (points on the edge "
                    "included), 0 elsewhere. ";
    if (in.pattern == sampling::Pattern::Regular) {
        q += "Sample it with a regular " + N + " × " + N +
             " grid at the cell centres, x = i + (a + ½)/" + N + ", y = j + (b + ½)/" + N + ". ";
    } else {
        q += "Sample it with a jittered " + N + " × " + N + " pattern, x = i + (a + ξx)/" + N +
             ", y = j + (b + ξy)/" + N +
             ", cells row by row from the bottom (b outer, a inner); "
             "the generator (seed " +
             std::to_string(in.seed) + ") gives, cell by cell, ξ = ";
        const auto pts = sampling::generate(in.pattern, in.samples, in.seed);
        for (std::size_t k = 0; k < pts.size(); ++k) q += (k ? ", " : "") + num(pts[k].xi, 6);
        q += ". ";
    }
    q += "With the box filter (every weight 1), give the samples as [x, y, value, weight] in that "
         "order (samples), the estimate (the average of the values) and the exact covered "
         "fraction of the pixel by area sampling (exact).";
    return q;
}

std::vector<std::string> Supersampling::answer_fields() {
    return {"samples", "estimate", "exact"};
}

}  // namespace cg
