// A triangle's spans, scanline by scanline, by the top-left rule: the arithmetic of the
// triangle scan conversion (raster/scan_triangle.hpp explains the rule), shared by everything
// that fills triangles so that they all cover exactly the same pixel centres.
//
//   sort_vertices    v0 lowest, v1 middle, v2 highest (ties by x, then by index)
//   orient2d(v0, v2, v1)  +1: v1 left of the long edge, −1 right, 0 collinear (nothing filled)
//   inverse_slope    m = dx/dy of the long, lower and upper edges
//   first_centre_above(y0), first_centre_above(y2)   the scanlines j_begin ≤ j < j_end
//   row_at(j)        the span x_left ≤ i + ½ < x_right as pixels i_first ≤ i < i_end
//
// Everything is inline: the callers' run-to-completion loops inline it as a plain loop would.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>

#include "raster/orient2d.hpp"

namespace cg::raster {

enum class TriangleEdge : std::uint8_t { Long, Lower, Upper };  // v0→v2, v0→v1, v1→v2
constexpr TriangleEdge kTriangleEdges[] = {TriangleEdge::Long, TriangleEdge::Lower,
                                           TriangleEdge::Upper};

inline int index(TriangleEdge e) { return static_cast<int>(e); }

// An edge's lower and upper end (the vertices are sorted by y).
inline glm::dvec2 lower_end(const std::array<glm::dvec2, 3>& v, TriangleEdge e) {
    return e == TriangleEdge::Upper ? v[1] : v[0];
}
inline glm::dvec2 upper_end(const std::array<glm::dvec2, 3>& v, TriangleEdge e) {
    return e == TriangleEdge::Lower ? v[1] : v[2];
}
inline int lower_index(TriangleEdge e) { return e == TriangleEdge::Upper ? 1 : 0; }
inline int upper_index(TriangleEdge e) { return e == TriangleEdge::Lower ? 1 : 2; }

// The smallest j in [lo, hi] whose centre j + ½ lies above y (hi if none): ⌊y + ½⌋, with the
// rounding of y + ½ corrected by exact comparisons (j + ½ is exact).
inline int first_centre_above(double y, int lo, int hi) {
    int j = static_cast<int>(std::clamp(std::floor(y + 0.5), double(lo), double(hi)));
    while (j > lo && j - 0.5 > y) --j;
    while (j < hi && !(j + 0.5 > y)) ++j;
    return j;
}

// The smallest i in [0, w] whose centre (i + ½, y) is on or to the right of the upward edge
// a→b (w if none): ⌈x − ½⌉ for the edge's x at y, checked against the exact orientation test.
inline int first_centre_right_of(glm::dvec2 a, glm::dvec2 b, double x, double y, int w) {
    auto right_of = [&](int i) { return orient2d(a, b, {i + 0.5, y}) <= 0; };
    int i = static_cast<int>(std::clamp(std::ceil(x - 0.5), 0.0, double(w)));
    while (i > 0 && right_of(i - 1)) --i;
    while (i < w && !right_of(i)) ++i;
    return i;
}

// The span of scanline j: which part, the two edges' x at y = j + ½, the pixels i_first ≤ i < i_end.
struct TriangleRow {
    bool upper;
    TriangleEdge left, right;
    double y, x_left, x_right;
    int i_first, i_end;
};

inline TriangleRow row_at(const std::array<glm::dvec2, 3>& v, const std::array<double, 3>& m,
                          int orient, int j, int width) {
    TriangleRow r;
    r.y = j + 0.5;
    r.upper = r.y > v[1].y;
    const TriangleEdge short_edge = r.upper ? TriangleEdge::Upper : TriangleEdge::Lower;
    // orient > 0: v1 is left of the long edge, so the short edge bounds the span on the left.
    r.left = orient > 0 ? short_edge : TriangleEdge::Long;
    r.right = orient > 0 ? TriangleEdge::Long : short_edge;
    const glm::dvec2 la = lower_end(v, r.left), ra = lower_end(v, r.right);
    r.x_left = la.x + (r.y - la.y) * m[index(r.left)];
    r.x_right = ra.x + (r.y - ra.y) * m[index(r.right)];
    r.i_first = first_centre_right_of(la, upper_end(v, r.left), r.x_left, r.y, width);
    r.i_end = first_centre_right_of(ra, upper_end(v, r.right), r.x_right, r.y, width);
    return r;
}

// Where the long edge v0→v2 crosses y = y1 (v0.y < v2.y: not collinear).
inline double split_x(const std::array<glm::dvec2, 3>& v) {
    return v[0].x + (v[1].y - v[0].y) * (v[2].x - v[0].x) / (v[2].y - v[0].y);
}

// dx/dy of edge e; 0 for a horizontal edge, which never bounds a span.
inline double inverse_slope(const std::array<glm::dvec2, 3>& v, TriangleEdge e) {
    const glm::dvec2 a = lower_end(v, e), b = upper_end(v, e);
    return b.y > a.y ? (b.x - a.x) / (b.y - a.y) : 0;
}

// order[k] is the index (into t[0..2]) of the k-th lowest vertex: by y, then x, then index.
template <class Points>
void sort_vertices(const Points& t, std::array<int, 3>& order) {
    order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return t[a].y != t[b].y ? t[a].y < t[b].y : (t[a].x != t[b].x ? t[a].x < t[b].x : a < b);
    });
}

// A triangle made ready for its spans: sorted, oriented, slopes and the scanlines (clipped to
// a width × height grid) to visit. orient == 0 (collinear) covers nothing.
struct TriangleSetup {
    std::array<glm::dvec2, 3> v{};
    std::array<double, 3> m{};
    int orient = 0;
    int j_begin = 0, j_end = 0;
};

inline TriangleSetup setup_triangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, int height) {
    TriangleSetup t;
    const std::array<glm::dvec2, 3> in{a, b, c};
    std::array<int, 3> order;
    sort_vertices(in, order);
    for (int k = 0; k < 3; ++k) t.v[k] = in[order[k]];
    t.orient = orient2d(t.v[0], t.v[2], t.v[1]);
    if (t.orient == 0) return t;
    for (TriangleEdge e : kTriangleEdges) t.m[index(e)] = inverse_slope(t.v, e);
    t.j_begin = first_centre_above(t.v[0].y, 0, height);
    t.j_end = first_centre_above(t.v[2].y, 0, height);
    return t;
}

}  // namespace cg::raster
