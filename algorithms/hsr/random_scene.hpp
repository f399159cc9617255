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

// ---- Scenes without intersecting polygons, with cyclic overlaps (the painter's algorithm) ----

// Do a and b stay apart in depth: wherever their projections overlap, one is nearer than the
// other by more than `gap` (two flat polygons at one depth also count: the tie rule orders them)?
inline bool apart_in_depth(const ScreenPolygon& a, const ScreenPolygon& b, double gap) {
    std::vector<glm::dvec2> region = ccw_outline(a);
    const std::vector<glm::dvec2> clipper = ccw_outline(b);
    for (std::size_t k = 0; k < clipper.size() && !region.empty(); ++k) {
        const glm::dvec2 p = clipper[k], q = clipper[(k + 1) % clipper.size()];
        auto side = [&](glm::dvec2 r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
        std::vector<glm::dvec2> out;
        for (std::size_t i = 0; i < region.size(); ++i) {
            const glm::dvec2 u = region[i], v = region[(i + 1) % region.size()];
            const double su = side(u), sv = side(v);
            if (su >= 0) out.push_back(u);
            if ((su > 0 && sv < 0) || (su < 0 && sv > 0)) out.push_back(u + (v - u) * (su / (su - sv)));
        }
        region = std::move(out);
    }
    double area = 0;
    for (std::size_t i = 0; i < region.size(); ++i)
        area += region[i].x * region[(i + 1) % region.size()].y - region[(i + 1) % region.size()].x * region[i].y;
    if (region.size() < 3 || area < 1e-9) return true;  // projections apart, or touching
    const Plane pa = plane_of(a), pb = plane_of(b);
    if (pa.a == 0 && pa.b == 0 && pb.a == 0 && pb.b == 0 && depth_at(pa, 0, 0) == depth_at(pb, 0, 0)) return true;
    bool nearer = true, farther = true;
    for (const auto& r : region) {
        const double d = depth_at(pa, r.x, r.y) - depth_at(pb, r.x, r.y);
        nearer = nearer && d < -gap;
        farther = farther && d > gap;
    }
    return nearer || farther;
}

// Three strips woven over each other in a cycle (the first over the second, the second over
// the third, the third over the first), at a random place, size, turn and depth; vertices
// snapped to halves of a pixel and put back on their planes. Empty if the snapping spoilt it.
inline std::vector<ScreenPolygon> woven_triple(Rng& rng, double W, double H) {
    // The course picture in a 12 × 12 frame (see painters_json.cpp): a bar along the bottom, a
    // bar up the right and a diagonal band, each sloping in depth so each passes over the next.
    const double t = rng.uniform(0.6, 2.4);  // half-widths of the strips
    std::vector<std::vector<glm::dvec3>> strips = {
        {{0, 2 - t / 2, 6}, {10, 2 - t / 2, 1}, {10, 2 + t / 2, 1}, {0, 2 + t / 2, 6}},
        {{8 - t / 2, 0, 3}, {8 + t / 2, 0, 3}, {8 + t / 2, 11, 8.5}, {8 - t / 2, 11, 8.5}},
        {{2 - t / 2, 0, -4}, {2 + t / 2, 0, -4}, {10 + t / 2, 10, 16}, {10 - t / 2, 10, 16}},
    };
    const double angle = rng.uniform(0, 6.283185307179586), scale = rng.uniform(0.15, 0.12 * std::max(W, H) + 0.3);
    const glm::dvec2 at{rng.uniform(-0.2 * W, 1.2 * W), rng.uniform(-0.2 * H, 1.2 * H)};
    const double zscale = rng.uniform(0.1, 3), zshift = rng.uniform(-20, 20);
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<ScreenPolygon> out;
    for (auto& strip : strips) {
        ScreenPolygon p;
        for (const auto& v : strip) {
            const glm::dvec2 r{v.x - 6, v.y - 6};
            p.vertices.push_back({at.x + scale * (c * r.x - s * r.y), at.y + scale * (s * r.x + c * r.y), zshift + zscale * v.z});
        }
        const Plane pl = plane_of(p);
        for (auto& v : p.vertices) {
            v.x = std::round(2 * v.x) / 2, v.y = std::round(2 * v.y) / 2;
            v.z = depth_at(pl, v.x, v.y);
        }
        p.color = {rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)};
        try {
            validate(ScreenScene{1, 1, {p}});
        } catch (const std::exception&) {
            return {};
        }
        out.push_back(std::move(p));
    }
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i + 1; j < 3; ++j)
            if (!apart_in_depth(out[i], out[j], 1e-3)) return {};
    return out;
}

// A scene of n polygons (n ≥ 3 with a woven triple about half the time, two triples sometimes)
// no two of which intersect: every overlapping pair is apart in depth by more than 1e-3, or two
// flat polygons at one depth. Random polygons that would intersect one already placed are drawn
// again (up to a limit; the scene may then have fewer than n).
inline ScreenScene random_layered_scene(Rng& rng, long long W, long long H, int n) {
    ScreenScene scene{W, H, {}};
    const bool flat = rng.chance(0.3);
    auto fits = [&](const ScreenPolygon& p) {
        for (const auto& q : scene.polygons)
            if (!apart_in_depth(p, q, 1e-3)) return false;
        return true;
    };
    const int triples = n >= 3 && rng.chance(0.5) ? (n >= 6 && rng.chance(0.3) ? 2 : 1) : 0;
    for (int k = 0; k < triples; ++k)
        for (int attempt = 0; attempt < 50; ++attempt) {
            auto three = woven_triple(rng, double(W), double(H));
            if (three.empty() || !std::all_of(three.begin(), three.end(), fits)) continue;
            for (auto& p : three) scene.polygons.push_back(std::move(p));
            break;
        }
    for (int attempt = 0; static_cast<int>(scene.polygons.size()) < n && attempt < 40 * n; ++attempt) {
        ScreenPolygon p = valid_polygon(rng, double(W), double(H), flat);
        if (fits(p)) scene.polygons.push_back(std::move(p));
    }
    // Shuffle, so the triple is not always first (Fisher-Yates from the seeded generator).
    for (std::size_t i = scene.polygons.size(); i > 1; --i)
        std::swap(scene.polygons[i - 1], scene.polygons[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(i) - 1))]);
    return scene;
}

}  // namespace cg::hsr
