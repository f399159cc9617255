#include "viewer/geometry.hpp"

#include <cmath>
#include <limits>

namespace cg::viewer {

namespace {

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

// Liang-Barsky on p + t·d for t in [t0, t1]: each box side is a test p_k·t <= q_k.
std::optional<Span> clip_parametric(glm::dvec2 p, glm::dvec2 d, double t0, double t1,
                                    const Box& box) {
    const double pk[4] = {-d.x, d.x, -d.y, d.y};
    const double qk[4] = {p.x - box.min.x, box.max.x - p.x, p.y - box.min.y, box.max.y - p.y};
    for (int k = 0; k < 4; ++k) {
        if (pk[k] == 0) {
            if (qk[k] < 0) return std::nullopt;
            continue;
        }
        const double r = qk[k] / pk[k];
        if (pk[k] < 0)
            t0 = std::max(t0, r);
        else
            t1 = std::min(t1, r);
        if (t0 > t1) return std::nullopt;
    }
    return Span{p + t0 * d, p + t1 * d};
}

double area2(const std::vector<glm::dvec2>& poly) {
    double a = 0;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        a += cross(poly[j], poly[i]);
    return a;
}

bool inside_triangle(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const double d1 = cross(b - a, p - a), d2 = cross(c - b, p - b), d3 = cross(a - c, p - c);
    const bool negative = d1 < 0 || d2 < 0 || d3<0, positive = d1> 0 || d2 > 0 || d3 > 0;
    return !(negative && positive);
}

}  // namespace

std::optional<Span> clip_segment(glm::dvec2 a, glm::dvec2 b, const Box& box) {
    return clip_parametric(a, b - a, 0, 1, box);
}

std::optional<Span> clip_line(glm::dvec2 p, glm::dvec2 dir, const Box& box) {
    if (dir.x == 0 && dir.y == 0) return std::nullopt;
    const double inf = std::numeric_limits<double>::infinity();
    return clip_parametric(p, dir, -inf, inf, box);
}

std::vector<glm::dvec2> clip_polygon(const std::vector<glm::dvec2>& polygon, glm::dvec2 p,
                                     glm::dvec2 n) {
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        const double da = (a.x - p.x) * n.x + (a.y - p.y) * n.y;
        const double db = (b.x - p.x) * n.x + (b.y - p.y) * n.y;
        if (da >= 0) out.push_back(a);
        if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

std::vector<glm::dvec2> clip_polygon_to_box(std::vector<glm::dvec2> polygon, const Box& box) {
    polygon = clip_polygon(polygon, box.min, {1, 0});
    polygon = clip_polygon(polygon, box.min, {0, 1});
    polygon = clip_polygon(polygon, box.max, {-1, 0});
    return clip_polygon(polygon, box.max, {0, -1});
}

std::vector<int> triangulate(const std::vector<glm::dvec2>& polygon) {
    std::vector<int> triangles;
    if (polygon.size() < 3) return triangles;
    const double orientation = area2(polygon) < 0 ? -1.0 : 1.0;
    std::vector<int> left;
    for (int i = 0; i < static_cast<int>(polygon.size()); ++i) left.push_back(i);

    // Ear clipping is quadratic; beyond a few thousand vertices a fan is the better deal.
    while (left.size() > 3 && polygon.size() <= 4000) {
        const std::size_t m = left.size();
        bool clipped = false;
        for (std::size_t i = 0; i < m && !clipped; ++i) {
            const int ia = left[(i + m - 1) % m], ib = left[i], ic = left[(i + 1) % m];
            const glm::dvec2 a = polygon[ia], b = polygon[ib], c = polygon[ic];
            const double turn = cross(b - a, c - b) * orientation;
            if (turn < 0) continue;  // a reflex corner is no ear
            bool empty = true;
            for (int j : left) {
                if (j == ia || j == ib || j == ic) continue;
                const glm::dvec2 q = polygon[j];
                if (q != a && q != b && q != c && inside_triangle(q, a, b, c)) {
                    empty = false;
                    break;
                }
            }
            if (!empty) continue;
            if (turn > 0) triangles.insert(triangles.end(), {ia, ib, ic});
            left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));  // a flat corner just goes
            clipped = true;
        }
        if (!clipped) break;
    }
    for (std::size_t i = 1; i + 1 < left.size(); ++i)
        triangles.insert(triangles.end(), {left[0], left[i], left[i + 1]});
    return triangles;
}

}  // namespace cg::viewer
