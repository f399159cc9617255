// The independent reference for the sampling tests: a pixel's exact (area-sampled) value by
// vertical slices, in long double.
//
// For each x the part of the pixel's column inside the scene is a union of y intervals, found
// directly from the edge's line or the polygon's edge crossings (even-odd); the filter's y
// weight is integrated over them in closed form (box: length; tent: the tent's antiderivative;
// Gaussian: erf). That function of x is smooth between breakpoints — the polygon's vertices,
// where a boundary crosses the pixel's top, bottom or middle, the pixel's middle — so 24-point
// Gauss-Legendre on each piece integrates it to rounding. No clipping and no Green's theorem:
// nothing is shared with sampling/coverage.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/vec2.hpp>
#include <vector>

#include "sampling/coverage.hpp"

namespace sampling_reference {

using ld = long double;

struct Legendre {
    static constexpr int n = 24;
    ld x[n], w[n];  // on [0, 1]
    Legendre() {
        const ld pi = 3.141592653589793238462643383279502884L;
        for (int k = 0; k < n; ++k) {
            ld t = std::cos(pi * (k + 0.75L) / (n + 0.5L)), dp = 1;
            for (int it = 0; it < 100; ++it) {
                ld p0 = 1, p1 = t;
                for (int m = 2; m <= n; ++m) {
                    const ld p2 = ((2 * m - 1) * t * p1 - (m - 1) * p0) / m;
                    p0 = p1, p1 = p2;
                }
                dp = n * (t * p1 - p0) / (t * t - 1);
                const ld dt = p1 / dp;
                t -= dt;
                if (std::fabs(dt) < 1e-19L) break;
            }
            x[k] = (1 - t) / 2;
            w[k] = 1 / ((1 - t * t) * dp * dp);
        }
    }
};

inline const Legendre& legendre() {
    static const Legendre g;
    return g;
}

constexpr ld kSigma = 0.5L;

// The filter's 1D weight and its integral from the pixel's middle, offsets in pixel units.
inline ld w1(cg::sampling::Filter f, ld d) {
    using F = cg::sampling::Filter;
    if (f == F::Box) return 1;
    if (f == F::Tent) return std::max(ld(0), 1 - std::fabs(d));
    return std::exp(-d * d / (2 * kSigma * kSigma));
}
inline ld W1(cg::sampling::Filter f, ld d) {
    using F = cg::sampling::Filter;
    if (f == F::Box) return d;
    if (f == F::Tent) return d >= 0 ? d - d * d / 2 : d + d * d / 2;
    return kSigma * std::sqrt(3.141592653589793238462643383279502884L / 2) *
           std::erf(d / (kSigma * std::sqrt(ld(2))));
}

// The y intervals of column x inside the scene, clipped to [y0, y1].
inline std::vector<std::pair<ld, ld>> column(const cg::sampling::Region& r, ld x, ld y0, ld y1) {
    std::vector<std::pair<ld, ld>> out;
    if (r.kind == cg::sampling::RegionKind::Edge) {
        const glm::dvec2 d = cg::sampling::edge_direction(r.angle_deg);
        // inside: d.x (y − p.y) − d.y (x − p.x) ≥ 0
        const ld px = r.point.x, py = r.point.y;
        if (d.x == 0) {
            if (-ld(d.y) * (x - px) >= 0) out.push_back({y0, y1});
        } else {
            const ld y = py + ld(d.y) * (x - px) / ld(d.x);
            if (d.x > 0)
                out.push_back({std::max(y, y0), y1});
            else
                out.push_back({y0, std::min(y, y1)});
        }
    } else {
        std::vector<ld> ys;
        const auto& p = r.points;
        for (std::size_t k = 0, prev = p.size() - 1; k < p.size(); prev = k++) {
            const ld ax = p[prev].x, ay = p[prev].y, bx = p[k].x, by = p[k].y;
            if ((ax > x) != (bx > x)) ys.push_back(ay + (x - ax) * (by - ay) / (bx - ax));
        }
        std::sort(ys.begin(), ys.end());
        for (std::size_t k = 0; k + 1 < ys.size(); k += 2)
            out.push_back({std::max(ys[k], y0), std::min(ys[k + 1], y1)});
    }
    return out;
}

// ∫∫ w f / ∫∫ w over pixel (i, j).
inline ld exact(const cg::sampling::Region& r, cg::sampling::Filter f, int i, int j) {
    const ld x0 = i, x1 = i + 1, y0 = j, y1 = j + 1, cx = i + 0.5L, cy = j + 0.5L;
    std::vector<ld> cuts = {x0, x1, cx};
    auto add = [&](ld x) {
        if (x > x0 && x < x1) cuts.push_back(x);
    };
    if (r.kind == cg::sampling::RegionKind::Edge) {
        const glm::dvec2 d = cg::sampling::edge_direction(r.angle_deg);
        if (d.y != 0)
            for (ld y : {y0, y1, cy}) add(r.point.x + ld(d.x) * (y - r.point.y) / ld(d.y));
        if (d.x == 0) add(r.point.x);
    } else {
        const auto& p = r.points;
        for (std::size_t k = 0, prev = p.size() - 1; k < p.size(); prev = k++) {
            add(p[k].x);
            const ld ax = p[prev].x, ay = p[prev].y, bx = p[k].x, by = p[k].y;
            if (ay != by)
                for (ld y : {y0, y1, cy})
                    if ((ay < y) != (by < y)) add(ax + (y - ay) * (bx - ax) / (by - ay));
        }
    }
    std::sort(cuts.begin(), cuts.end());
    const Legendre& g = legendre();
    ld total = 0;
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
        const ld a = cuts[c], b = cuts[c + 1];
        if (b <= a) continue;
        ld piece = 0;
        for (int q = 0; q < Legendre::n; ++q) {
            const ld x = a + (b - a) * g.x[q];
            ld col = 0;
            for (auto [lo, hi] : column(r, x, y0, y1))
                if (hi > lo) col += W1(f, hi - cy) - W1(f, lo - cy);
            piece += g.w[q] * w1(f, x - cx) * col;
        }
        total += piece * (b - a);
    }
    const ld one = W1(f, 0.5L) - W1(f, -0.5L);
    return total / (one * one);
}

}  // namespace sampling_reference
