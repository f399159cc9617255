#include "accel/primitive.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "accel/ray_aabb.hpp"
#include "core/format.hpp"

namespace cg {

using glm::dvec3;

void Bounds::grow(dvec3 p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Bounds::grow(const Bounds& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
}

double Bounds::surface_area() const {
    if (empty()) return 0;
    const dvec3 e = extent();
    return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

Bounds bounds(const Primitive& p) {
    Bounds b;
    switch (p.kind) {
        case PrimitiveKind::Sphere:
            b.min = p.a - dvec3(p.radius);
            b.max = p.a + dvec3(p.radius);
            break;
        case PrimitiveKind::Triangle:
            b.grow(p.a), b.grow(p.b), b.grow(p.c);
            break;
        case PrimitiveKind::Box:
            b.min = p.a, b.max = p.b;
            break;
    }
    return b;
}

dvec3 centroid(const Primitive& p) {
    return bounds(p).centre();
}

namespace {

// |E + t d − C|² = r²:  (d·d) t² + 2 (d·m) t + (m·m − r²) = 0 with m = E − C. The roots by the
// stable form q = −(h + sign(h) √disc), t = q/a and c/q (no cancellation between h and √disc).
PrimitiveHit hit_sphere(const Primitive& p, dvec3 e, dvec3 d) {
    const dvec3 m = e - p.a;
    const double a = glm::dot(d, d);
    const double h = glm::dot(d, m);
    const double c = glm::dot(m, m) - p.radius * p.radius;
    const double disc = h * h - a * c;
    PrimitiveHit out;
    if (disc < 0) return out;
    const double q = -(h + std::copysign(std::sqrt(disc), h));
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 >= 0)
        out.t = t0;
    else if (t1 >= 0)
        out.t = t1;  // E is inside: the exit
    return out;
}

// Möller–Trumbore: with e1 = B − A, e2 = C − A, s = E − A,
//   det = e1·(d × e2),  β = s·(d × e2)/det,  γ = d·(s × e1)/det,  t = e2·(s × e1)/det.
PrimitiveHit hit_triangle(const Primitive& p, dvec3 e, dvec3 d) {
    const dvec3 e1 = p.b - p.a, e2 = p.c - p.a;
    const dvec3 pv = glm::cross(d, e2);
    const double det = glm::dot(e1, pv);
    PrimitiveHit out;
    if (det == 0) return out;  // d lies in the triangle's plane
    const double inv = 1 / det;
    const dvec3 s = e - p.a;
    const double beta = glm::dot(s, pv) * inv;
    if (!(beta >= 0 && beta <= 1)) return out;
    const dvec3 qv = glm::cross(s, e1);
    const double gamma = glm::dot(d, qv) * inv;
    if (!(gamma >= 0 && beta + gamma <= 1)) return out;
    const double t = glm::dot(e2, qv) * inv;
    if (!(t >= 0)) return out;
    out.t = t, out.beta = beta, out.gamma = gamma;
    return out;
}

PrimitiveHit hit_box(const Primitive& p, dvec3 e, dvec3 d) {
    const RayAabb::Result r = RayAabb::intersect({p.a, p.b, e, d});
    PrimitiveHit out;
    if (r.hit) out.t = r.t_hit;
    return out;
}

}  // namespace

PrimitiveHit intersect(const Primitive& p, dvec3 origin, dvec3 direction) {
    switch (p.kind) {
        case PrimitiveKind::Sphere:
            return hit_sphere(p, origin, direction);
        case PrimitiveKind::Triangle:
            return hit_triangle(p, origin, direction);
        case PrimitiveKind::Box:
            return hit_box(p, origin, direction);
    }
    return {};
}

namespace {

bool overlaps_bounds(const Bounds& a, const Bounds& b) {
    for (int i = 0; i < 3; ++i)
        if (a.max[i] < b.min[i] || b.max[i] < a.min[i]) return false;
    return true;
}

bool sphere_meets_box(const Primitive& p, const Bounds& b) {
    double d2 = 0;
    for (int i = 0; i < 3; ++i) {
        const double c = p.a[i];
        const double gap = c < b.min[i] ? b.min[i] - c : c > b.max[i] ? c - b.max[i] : 0.0;
        d2 += gap * gap;
    }
    return d2 <= p.radius * p.radius;
}

// Separating axes, with the box centred at the origin (half sizes h) and the corners v0..v2
// moved with it: on an axis L the triangle projects to [min, max] of L·v and the box to
// [−r, r] with r = Σ h_i |L_i|; disjoint projections separate them.
bool triangle_meets_box(const Primitive& p, const Bounds& b) {
    if (!overlaps_bounds(bounds(p), b)) return false;  // the box's own three axes
    const dvec3 c = b.centre(), h = 0.5 * b.extent();
    const dvec3 v[3] = {p.a - c, p.b - c, p.c - c};
    auto separated = [&](dvec3 L) {
        const double p0 = glm::dot(L, v[0]), p1 = glm::dot(L, v[1]), p2 = glm::dot(L, v[2]);
        const double r = h.x * std::fabs(L.x) + h.y * std::fabs(L.y) + h.z * std::fabs(L.z);
        return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
    };
    const dvec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    if (separated(glm::cross(e[0], e[1]))) return false;  // the triangle's plane
    for (const dvec3& edge : e)
        for (int i = 0; i < 3; ++i) {
            dvec3 axis(0.0);
            axis[i] = 1;
            if (separated(glm::cross(edge, axis))) return false;
        }
    return true;
}

}  // namespace

bool overlaps(const Primitive& p, const Bounds& b) {
    switch (p.kind) {
        case PrimitiveKind::Sphere:
            return sphere_meets_box(p, b);
        case PrimitiveKind::Triangle:
            return triangle_meets_box(p, b);
        case PrimitiveKind::Box:
            return overlaps_bounds(bounds(p), b);
    }
    return true;
}

const char* kind_name(PrimitiveKind k) {
    switch (k) {
        case PrimitiveKind::Sphere:
            return "sphere";
        case PrimitiveKind::Triangle:
            return "triangle";
        case PrimitiveKind::Box:
            return "box";
    }
    return "?";
}

std::string describe(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Sphere:
            return "sphere C " + num(p.a) + " r " + num(p.radius);
        case PrimitiveKind::Triangle:
            return "triangle " + num(p.a) + " " + num(p.b) + " " + num(p.c);
        case PrimitiveKind::Box:
            return "box " + num(p.a) + "–" + num(p.b);
    }
    return "?";
}

}  // namespace cg
