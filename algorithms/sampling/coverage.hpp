// A 2D scene function for anti-aliasing — a polygon edge (a half-plane) or a simple polygon, of
// value 1 inside and 0 outside — and the exact (area-sampled) value of a pixel over it.
//
// Area sampling, the course's integral: a pixel's value is ∫∫ w·f over its footprint divided by
// ∫∫ w. For the box filter that is the covered fraction of the pixel square, the area of the
// scene's polygon clipped to the square (Sutherland-Hodgman against the square's four edges; a
// half-plane clips the square itself, one pass), by the shoelace formula: closed form. For the
// tent and Gaussian filters the weight is separable, w = w(x) w(y), and Green's theorem turns the
// area integral into one along the clipped polygon's edges, ∫∫ w(x) w(y) dA = ∮ W(x) w(y) dy
// with W' = w; each edge is cut where it crosses the pixel's centre lines (the tent's kinks) and
// integrated by 16-point Gauss-Legendre: exact for the tent (cubic pieces), and to about 1e-15
// for the Gaussian (W is an erf).
//
// Conventions: pixel (i, j) covers [i, i+1) × [j, j+1), y up. An edge is the directed line
// through `point` at `angle_deg` (counter-clockwise from +x); its inside is the half-plane on
// the left, points on the line included. A polygon is simple, either way round; a point is
// inside by the even-odd crossing rule (on a horizontal ray to +x, half-open in y).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "sampling/patterns.hpp"

namespace cg::sampling {

enum class RegionKind : std::uint8_t { Edge, Polygon };

struct Region {
    RegionKind kind = RegionKind::Edge;
    glm::dvec2 point{0.0};           // edge: a point on the line
    double angle_deg = 0;            // edge: its direction, degrees counter-clockwise from +x
    std::vector<glm::dvec2> points;  // polygon: simple, ≥ 3 vertices, either orientation
    bool operator==(const Region&) const = default;
};

// The edge's unit direction (cos, sin of the angle, with exact values at multiples of 90°).
glm::dvec2 edge_direction(double angle_deg);

// f(p): 1 inside the region, 0 outside.
double region_value(const Region& r, glm::dvec2 p);
// The same for an edge with its direction computed once (the inner loop of image sampling).
inline double edge_value(glm::dvec2 point, glm::dvec2 dir, glm::dvec2 p) {
    const glm::dvec2 q = p - point;
    return dir.x * q.y - dir.y * q.x >= 0 ? 1.0 : 0.0;
}

// The part of pixel (i, j)'s square inside the region, counter-clockwise (a concave polygon cut
// into pieces comes out as one list joined by zero-width bridges along the square's border, as
// Sutherland-Hodgman gives it; the bridges add no area). Empty when nothing is covered.
std::vector<glm::dvec2> covered_polygon(const Region& r, int i, int j);

// ∫∫ over `poly` (counter-clockwise, any shape) of the filter's weight about `centre`.
double weighted_area(Filter f, const std::vector<glm::dvec2>& poly, glm::dvec2 centre);
// Shoelace area (signed: counter-clockwise positive).
double signed_area(const std::vector<glm::dvec2>& poly);

// The exact value of pixel (i, j): ∫∫ w f / ∫∫ w over the pixel, in [0, 1].
double exact_coverage(const Region& r, Filter f, int i, int j);

}  // namespace cg::sampling
