// Exam-sized shapes for the hidden-surface generators: axis-aligned rectangles and right
// triangles with integer corners, on planes z = z0 + a·x + b·y with a, b in {−½, 0, ½} (often 0),
// so every depth at a pixel centre is a short decimal a student can work out.
#pragma once

#include "core/rng.hpp"
#include "hsr/screen_scene.hpp"

namespace cg::hsr {

inline ScreenPolygon exam_polygon(Rng& rng, int side, double z0) {
    const int x0 = static_cast<int>(rng.integer(0, side - 2)), y0 = static_cast<int>(rng.integer(0, side - 2));
    const int x1 = static_cast<int>(rng.integer(x0 + 2, side)), y1 = static_cast<int>(rng.integer(y0 + 2, side));
    std::vector<glm::dvec2> xy;
    switch (rng.integer(0, 3)) {
        case 0: xy = {{x0, y0}, {x1, y0}, {x0, y1}}; break;  // right triangles, each corner
        case 1: xy = {{x0, y0}, {x1, y0}, {x1, y1}}; break;
        default: xy = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; break;
    }
    static constexpr double kSlope[] = {-0.5, 0, 0, 0, 0.5};
    const double a = kSlope[rng.integer(0, 4)], b = kSlope[rng.integer(0, 4)];
    ScreenPolygon p;
    for (const auto& q : xy) p.vertices.push_back({q.x, q.y, z0 + a * q.x + b * q.y});
    static const glm::dvec3 kColours[] = {{0.85, 0.25, 0.2}, {0.2, 0.5, 0.9}, {0.3, 0.75, 0.3}, {0.95, 0.75, 0.2}};
    p.color = kColours[rng.integer(0, 3)];
    return p;
}

}  // namespace cg::hsr
