// The scene every hidden-surface algorithm works on: polygons already in screen space.
//
// x and y are in pixels, z is depth: smaller z is nearer the viewer. Pixel (i, j) covers
// [i, i+1) × [j, j+1), origin bottom-left, and is sampled at its centre (i + ½, j + ½). A
// polygon covers a centre by the same rule the triangle scan conversion uses (the top-left
// rule, see raster/scan_triangle.hpp), so that Warnock, the z-buffer and the painter's
// algorithm decide every pixel alike and neighbouring polygons never share a pixel.
//
// Depth at a pixel centre comes from the polygon's plane. Ties are broken one way everywhere:
// the nearer (smaller z) wins, and at equal z the polygon with the lower index wins.
//
// Polygons must be planar (to a tolerance relative to their size), convex in the xy-plane,
// with at least 3 vertices and a non-zero projected area (a polygon seen edge-on is refused:
// it covers no pixel centre reliably and has no depth plane to interpolate).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace cg::hsr {

struct ScreenPolygon {
    std::vector<glm::dvec3> vertices;  // (x, y, z): pixels, pixels, depth
    glm::dvec3 color{1, 1, 1};         // r, g, b in [0, 1]
    bool operator==(const ScreenPolygon&) const = default;
};

struct ScreenScene {
    long long width = 0, height = 0;  // pixels; at most kMaxSide each
    std::vector<ScreenPolygon> polygons;
    bool operator==(const ScreenScene&) const = default;
};

// The heap memory of a scene (for the algorithms' state sizes; see Run::bytes).
inline std::size_t heap_bytes(const ScreenScene& s) {
    std::size_t n = s.polygons.capacity() * sizeof(ScreenPolygon);
    for (const auto& p : s.polygons) n += p.vertices.capacity() * sizeof(glm::dvec3);
    return n;
}

constexpr long long kMaxSide = 1024;       // pixels per side: a limit, said in the error
constexpr std::size_t kMaxPolygons = 10'000;

// Throws InputError naming the field: "polygons[2].vertices[1][2]", "width", ...
void validate(const ScreenScene& scene);

// The plane a·x + b·y + c·z + d = 0 of a polygon (c ≠ 0 for a valid polygon).
struct Plane {
    double a = 0, b = 0, c = 0, d = 0;
    bool operator==(const Plane&) const = default;
};
Plane plane_of(const ScreenPolygon& p);
double depth_at(const Plane& plane, double x, double y);  // z on the plane above (x, y)

// Does the polygon cover the point (normally a pixel centre), by the top-left rule?
bool covers(const ScreenPolygon& p, double x, double y);

// Is candidate (z, index) in front of incumbent (z, index)? The one tie-break rule.
inline bool in_front(double z, int index, double other_z, int other_index) {
    return z < other_z || (z == other_z && index < other_index);
}

// The visible polygon's index at every pixel centre, −1 for background: row-major, row 0 the
// bottom row. The brute-force definition every algorithm must agree with.
std::vector<int> visible_ids(const ScreenScene& scene);

// ---- Shared helpers (screen_scene.cpp) -------------------------------------------------------

// The polygon's outline in the xy-plane, counter-clockwise (reversed if given clockwise).
std::vector<glm::dvec2> ccw_outline(const ScreenPolygon& p);

// The pixels a polygon covers on scanline j: i_first ≤ i < i_end (clipped to the grid).
struct PixelSpan {
    int j = 0, i_first = 0, i_end = 0;
    bool operator==(const PixelSpan&) const = default;
};
// Scan conversion of a convex polygon as the fan of triangles (v0, v_k, v_k+1), each by the
// triangle scan conversion's exact top-left rule (raster/triangle_spans.hpp). The fan's inner
// edges are left on one side and right on the other, so the union is exactly the centres that
// covers() accepts, and each lies in one triangle. Spans bottom to top, non-empty only.
std::vector<PixelSpan> polygon_spans(const ScreenPolygon& p, long long width, long long height);

}  // namespace cg::hsr
