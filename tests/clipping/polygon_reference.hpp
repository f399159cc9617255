// The independent reference for polygon clipping, shared by the Sutherland-Hodgman tests:
// Clipper's intersection, computed exactly on integer coordinates; the shoelace area; and an
// exact simplicity test for polygons on a grid.
//
// Points are scaled by 2^40 and truncated to integers. Inputs on a grid of 1/4 or 1/1024
// inside [−8, 8]² (the random tests), or integers (the exam problems), are then integers below
// 2^44: Clipper reads them exactly, computes in exact integer arithmetic (128-bit where
// needed), and only rounds its own output vertices to integers, which is an error of at most
// 0.71 / 2^40 ≈ 6e-13 per vertex in our units.
#pragma once

#include <algorithm>
#include <glm/vec2.hpp>
#include <polyclipping/clipper.hpp>
#include <vector>

namespace polygon_reference {

using Points = std::vector<glm::dvec2>;

inline constexpr double kScale = 1099511627776.0;  // 2^40

inline ClipperLib::Path to_path(const Points& points) {
    ClipperLib::Path path;
    for (glm::dvec2 p : points)
        path.emplace_back(static_cast<ClipperLib::cInt>(p.x * kScale),
                          static_cast<ClipperLib::cInt>(p.y * kScale));
    return path;
}

// window ∩ polygon, as Clipper's list of outer boundaries (non-zero fill for both).
inline std::vector<Points> intersection(const Points& window, const Points& polygon) {
    ClipperLib::Clipper clipper;
    clipper.AddPath(to_path(polygon), ClipperLib::ptSubject, true);
    clipper.AddPath(to_path(window), ClipperLib::ptClip, true);
    ClipperLib::Paths solution;
    clipper.Execute(ClipperLib::ctIntersection, solution, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    std::vector<Points> out;
    for (const auto& path : solution) {
        Points pts;
        for (const auto& p : path) pts.push_back({double(p.X) / kScale, double(p.Y) / kScale});
        out.push_back(pts);
    }
    return out;
}

// Signed area, positive counter-clockwise.
inline double shoelace(const Points& p) {
    double a2 = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()];
        a2 += a.x * b.y - a.y * b.x;
    }
    return a2 / 2;
}

inline double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

// Exact on grid points: coordinates have at most 14 significant bits, so the products do too.
inline bool segments_touch(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
    auto orient = [](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {
        const double v = cross(q - p, r - p);
        return (v > 0) - (v < 0);
    };
    auto on = [&](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {  // r on segment pq, given collinear
        return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
               std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
    };
    const int o1 = orient(a, b, c), o2 = orient(a, b, d);
    const int o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 != o2 && o3 != o4) return true;
    return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
           (o4 == 0 && on(c, d, b));
}

// Simple: no two edges meet except neighbours at their shared vertex, nonzero area.
inline bool simple(const Points& p) {
    const std::size_t n = p.size();
    if (n < 3 || shoelace(p) == 0) return false;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = p[i], b = p[(i + 1) % n], c = p[(i + 2) % n];
        if (a == b) return false;
        // Adjacent edges may meet only at their shared vertex: no folding back.
        if (cross(b - a, c - b) == 0 && (b - a).x * (c - b).x + (b - a).y * (c - b).y < 0)
            return false;
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
            if (segments_touch(a, b, p[j], p[(j + 1) % n])) return false;
        }
    }
    return true;
}

// |window ∩ polygon|.
inline double intersection_area(const Points& window, const Points& polygon) {
    double area = 0;
    for (const Points& p : intersection(window, polygon)) area += shoelace(p);
    return area < 0 ? -area : area;
}

}  // namespace polygon_reference
