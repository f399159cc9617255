// Random screen scenes: for the hidden-surface tests and the complexity table (cgsandbox
// complexity hsr). Seeded, so a trial number names one scene everywhere.
#pragma once

#include <algorithm>
#include <cmath>
#include <exception>

#include "core/rng.hpp"
#include "hsr/screen_scene.hpp"

namespace cg::hsr {

// A convex polygon: vertices on an ellipse at sorted random angles, snapped to halves of a pixel
// (so centres often lie exactly on edges and vertices), on the plane z = a·x + b·y + c. Ties:
// with `flat`, a = b = 0 and c from a few values, so equal depths are common.
inline ScreenPolygon random_polygon(Rng& rng, double W, double H, bool flat) {
    ScreenPolygon p;
    const double cx = rng.uniform(-0.2 * W, 1.2 * W), cy = rng.uniform(-0.2 * H, 1.2 * H);
    const double rx = rng.uniform(0.5, 0.7 * W + 1), ry = rng.uniform(0.5, 0.7 * H + 1);
    const int n = static_cast<int>(rng.integer(3, 7));
    std::vector<double> angle(static_cast<std::size_t>(n));
    for (double& t : angle) t = rng.uniform(0, 6.283185307179586);
    std::sort(angle.begin(), angle.end());
    const double a = flat ? 0 : rng.uniform(-1, 1), b = flat ? 0 : rng.uniform(-1, 1);
    const double c = flat ? static_cast<double>(rng.integer(1, 3)) : rng.uniform(-10, 10);
    for (double t : angle) {
        const double x = std::round(2 * (cx + rx * std::cos(t))) / 2, y = std::round(2 * (cy + ry * std::sin(t))) / 2;
        p.vertices.push_back({x, y, a * x + b * y + c});
    }
    if (rng.chance(0.5)) std::reverse(p.vertices.begin(), p.vertices.end());  // clockwise too
    p.color = {rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)};
    return p;
}

// A valid polygon: random ones that snapping made degenerate or non-convex are drawn again.
inline ScreenPolygon valid_polygon(Rng& rng, double W, double H, bool flat) {
    for (;;) {
        ScreenScene one{1, 1, {random_polygon(rng, W, H, flat)}};
        try {
            validate(one);
            return one.polygons[0];
        } catch (const std::exception&) {
        }
    }
}

inline ScreenScene random_scene(Rng& rng, long long W, long long H, int n) {
    ScreenScene s{W, H, {}};
    const bool flat = rng.chance(0.3);
    for (int k = 0; k < n; ++k) s.polygons.push_back(valid_polygon(rng, double(W), double(H), flat));
    return s;
}

}  // namespace cg::hsr
