#include "hsr/screen_scene.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "core/format.hpp"
#include "core/step.hpp"
#include "raster/orient2d.hpp"
#include "raster/triangle_spans.hpp"

namespace cg::hsr {

namespace {

constexpr double kMaxCoordinate = 1e6;  // |x|, |y|, |z|: far beyond any screen, products stay exact-safe
constexpr double kPlanarTolerance = 1e-9;  // distance off the plane, relative to the polygon's size

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

// Twice the signed area of the projected outline (shoelace): > 0 counter-clockwise.
double twice_area(const std::vector<glm::dvec3>& v) {
    double a = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
        const auto& p = v[k];
        const auto& q = v[(k + 1) % v.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return a;
}

}  // namespace

void validate(const ScreenScene& scene) {
    const std::string max = std::to_string(kMaxSide);
    if (scene.width < 1 || scene.width > kMaxSide)
        throw InputError("width", "must be a whole number of pixels from 1 to " + max +
                                      " (the limit; got " + std::to_string(scene.width) + ")");
    if (scene.height < 1 || scene.height > kMaxSide)
        throw InputError("height", "must be a whole number of pixels from 1 to " + max +
                                       " (the limit; got " + std::to_string(scene.height) + ")");
    if (scene.polygons.size() > kMaxPolygons)
        throw InputError("polygons", "at most " + std::to_string(kMaxPolygons) +
                                         " polygons (the limit; got " +
                                         std::to_string(scene.polygons.size()) + ")");
    for (std::size_t k = 0; k < scene.polygons.size(); ++k) {
        const std::string field = "polygons[" + std::to_string(k) + "]";
        const ScreenPolygon& p = scene.polygons[k];
        const auto& v = p.vertices;
        if (v.size() < 3)
            throw InputError(field + ".vertices", "a polygon needs at least 3 vertices (got " +
                                                      std::to_string(v.size()) + ")");
        if (v.size() > 1000)
            throw InputError(field + ".vertices", "at most 1000 vertices per polygon (the limit; got " +
                                                      std::to_string(v.size()) + ")");
        for (std::size_t i = 0; i < v.size(); ++i)
            for (int d = 0; d < 3; ++d) {
                const std::string f = field + ".vertices[" + std::to_string(i) + "][" + std::to_string(d) + "]";
                check_finite(v[i][d], f);
                if (std::fabs(v[i][d]) > kMaxCoordinate)
                    throw InputError(f, "must lie within ±1e6 of the origin (got " + given(v[i][d]) + ")");
                if (v[i][d] != 0 && std::fabs(v[i][d]) < 1e-100)
                    throw InputError(f, "must be 0 or at least 1e-100 in size (got " + given(v[i][d]) + ")");
            }
        for (int d = 0; d < 3; ++d) {
            const std::string f = field + ".color[" + std::to_string(d) + "]";
            check_finite(p.color[d], f);
            if (p.color[d] < 0 || p.color[d] > 1)
                throw InputError(f, "must be from 0 to 1 (got " + given(p.color[d]) + ")");
        }
        const std::size_t n = v.size();
        for (std::size_t i = 0; i < n; ++i)
            if (glm::dvec2(v[i]) == glm::dvec2(v[(i + 1) % n]))
                throw InputError(field + ".vertices[" + std::to_string((i + 1) % n) + "]",
                                 "repeats the previous vertex's (x, y): edges must have length");
        const double area = twice_area(v);
        if (area == 0)
            throw InputError(field + ".vertices",
                             "has no area on the screen (seen edge-on, or all on one line)");
        // Convex: every turn the same way (collinear vertices allowed), and one turn in all.
        const int sense = area > 0 ? 1 : -1;
        double turning = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec2 a(v[i]), b(v[(i + 1) % n]), c(v[(i + 2) % n]);
            const int o = orient2d(a, b, c);
            const glm::dvec2 e1 = b - a, e2 = c - b;
            if (o == -sense || (o == 0 && e1.x * e2.x + e1.y * e2.y < 0))
                throw InputError(field + ".vertices[" + std::to_string((i + 1) % n) + "]",
                                 "makes the polygon non-convex in the xy-plane (it turns the "
                                 "other way there)");
            turning += std::atan2(e1.x * e2.y - e1.y * e2.x, e1.x * e2.x + e1.y * e2.y);
        }
        if (std::fabs(turning) > 7)  // 2π for a convex polygon; 4π or more winds twice
            throw InputError(field + ".vertices", "winds around more than once: not a convex polygon");
        // Planar: every vertex on the plane through them, to a tolerance relative to the size.
        const Plane pl = plane_of(p);
        const double norm = std::sqrt(pl.a * pl.a + pl.b * pl.b + pl.c * pl.c);
        glm::dvec3 lo = v[0], hi = v[0];
        for (const auto& q : v) lo = glm::min(lo, q), hi = glm::max(hi, q);
        const double size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
        for (std::size_t i = 0; i < n; ++i) {
            const double dist = std::fabs(pl.a * v[i].x + pl.b * v[i].y + pl.c * v[i].z + pl.d) / norm;
            if (dist > kPlanarTolerance * size)
                throw InputError(field + ".vertices[" + std::to_string(i) + "]",
                                 "is " + given(dist, 3) +
                                     " off the plane of the others: a polygon must be planar");
        }
    }
}

// Newell's method: the normal from all edges (robust to collinear vertices), the plane through
// the centroid. c = twice the projected area, non-zero for a valid polygon.
Plane plane_of(const ScreenPolygon& p) {
    const auto& v = p.vertices;
    Plane pl;
    glm::dvec3 centroid(0);
    for (std::size_t k = 0; k < v.size(); ++k) {
        const glm::dvec3& a = v[k];
        const glm::dvec3& b = v[(k + 1) % v.size()];
        pl.a += (a.y - b.y) * (a.z + b.z);
        pl.b += (a.z - b.z) * (a.x + b.x);
        pl.c += (a.x - b.x) * (a.y + b.y);
        centroid += a;
    }
    centroid /= static_cast<double>(v.size());
    pl.d = -(pl.a * centroid.x + pl.b * centroid.y + pl.c * centroid.z);
    return pl;
}

double depth_at(const Plane& pl, double x, double y) { return -(pl.a * x + pl.b * y + pl.d) / pl.c; }

std::vector<glm::dvec2> ccw_outline(const ScreenPolygon& p) {
    std::vector<glm::dvec2> out;
    out.reserve(p.vertices.size());
    for (const auto& v : p.vertices) out.emplace_back(v.x, v.y);
    if (twice_area(p.vertices) < 0) std::reverse(out.begin(), out.end());
    return out;
}

// Inside every edge of the counter-clockwise outline; on an edge, in when the edge is a left
// edge (going down: the inside is on its +x side) or a top edge (horizontal, going −x: the
// inside below). That is the scan conversion's top-left rule, edge by edge.
bool covers(const ScreenPolygon& p, double x, double y) {
    const auto& v = p.vertices;
    const std::size_t n = v.size();
    const bool reversed = twice_area(v) < 0;  // walk the outline counter-clockwise either way
    const glm::dvec2 c{x, y};
    for (std::size_t k = 0; k < n; ++k) {
        glm::dvec2 a(v[k]), b(v[(k + 1) % n]);
        if (reversed) std::swap(a, b);
        const int o = orient2d(a, b, c);
        if (o < 0) return false;
        if (o == 0 && !(b.y < a.y || (b.y == a.y && b.x < a.x))) return false;
    }
    return true;
}

std::vector<int> visible_ids(const ScreenScene& scene) {
    const long long W = scene.width, H = scene.height;
    std::vector<int> ids(static_cast<std::size_t>(W * H), -1);
    std::vector<double> best(ids.size(), 0);
    for (std::size_t k = 0; k < scene.polygons.size(); ++k) {
        const ScreenPolygon& p = scene.polygons[k];
        const Plane pl = plane_of(p);
        for (long long j = 0; j < H; ++j)
            for (long long i = 0; i < W; ++i) {
                const double x = i + 0.5, y = j + 0.5;
                if (!covers(p, x, y)) continue;
                const double z = depth_at(pl, x, y);
                const std::size_t at = static_cast<std::size_t>(j * W + i);
                if (ids[at] < 0 || in_front(z, static_cast<int>(k), best[at], ids[at]))
                    ids[at] = static_cast<int>(k), best[at] = z;
            }
    }
    return ids;
}

std::vector<PixelSpan> polygon_spans(const ScreenPolygon& p, long long width, long long height) {
    const auto& v = p.vertices;
    const int W = static_cast<int>(width), H = static_cast<int>(height);
    std::vector<raster::TriangleSetup> fan;
    fan.reserve(v.size() - 2);
    int j_lo = H, j_hi = 0;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
        fan.push_back(raster::setup_triangle(glm::dvec2(v[0]), glm::dvec2(v[k]), glm::dvec2(v[k + 1]), H));
        const auto& t = fan.back();
        if (t.orient != 0 && t.j_begin < t.j_end) j_lo = std::min(j_lo, t.j_begin), j_hi = std::max(j_hi, t.j_end);
    }
    std::vector<PixelSpan> spans;
    for (int j = j_lo; j < j_hi; ++j) {
        PixelSpan s{j, W, 0};
        for (const auto& t : fan) {
            if (t.orient == 0 || j < t.j_begin || j >= t.j_end) continue;
            const raster::TriangleRow r = raster::row_at(t.v, t.m, t.orient, j, W);
            if (r.i_first < r.i_end) s.i_first = std::min(s.i_first, r.i_first), s.i_end = std::max(s.i_end, r.i_end);
        }
        if (s.i_first < s.i_end) spans.push_back(s);
    }
    return spans;
}

}  // namespace cg::hsr
