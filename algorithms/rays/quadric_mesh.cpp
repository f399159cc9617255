#include "rays/quadric_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>

namespace cg {

using glm::dvec3;

double largest_param(const Quadric& q) {
    switch (q.kind) {
        case QuadricKind::Sphere:
            return q.r;
        case QuadricKind::Ellipsoid:
        case QuadricKind::Hyperboloid:
            return std::max({q.a, q.b, q.c});
        case QuadricKind::Paraboloid:
        case QuadricKind::Cylinder:
            return std::max(q.p, q.q);
        case QuadricKind::Cone:
            return std::max({q.p, q.q, q.r});
    }
    return 1;
}

void drawn_z_range(const Quadric& q, double reach, double& z_lo, double& z_hi) {
    switch (q.kind) {
        case QuadricKind::Sphere:
            z_lo = -q.r, z_hi = q.r;
            break;
        case QuadricKind::Ellipsoid:
            z_lo = -q.c, z_hi = q.c;
            break;
        case QuadricKind::Paraboloid:
            z_lo = 0, z_hi = reach;
            break;
        default:
            z_lo = -reach, z_hi = reach;
            break;
    }
    z_lo = std::max(z_lo, q.zmin);
    z_hi = std::min(z_hi, q.zmax);
}

namespace {

// The model-space point of the surface at angle φ around the z axis and height z (for the
// closed surfaces, z is clamped to the surface's extent).
dvec3 surface_point(const Quadric& q, double phi, double z) {
    const double c = std::cos(phi), s = std::sin(phi);
    switch (q.kind) {
        case QuadricKind::Sphere: {
            const double rho = std::sqrt(std::max(0.0, q.r * q.r - z * z));
            return {rho * c, rho * s, z};
        }
        case QuadricKind::Ellipsoid: {
            const double k = std::sqrt(std::max(0.0, 1 - z * z / (q.c * q.c)));
            return {q.a * k * c, q.b * k * s, z};
        }
        case QuadricKind::Paraboloid: {
            const double k = std::sqrt(std::max(0.0, z));
            return {q.p * k * c, q.q * k * s, z};
        }
        case QuadricKind::Hyperboloid: {
            const double k = std::sqrt(1 + z * z / (q.c * q.c));
            return {q.a * k * c, q.b * k * s, z};
        }
        case QuadricKind::Cone: {
            const double k = std::fabs(z) / q.r;
            return {q.p * k * c, q.q * k * s, z};
        }
        case QuadricKind::Cylinder:
            return {q.p * c, q.q * s, z};
    }
    return {0, 0, 0};
}

dvec3 to_world(const Quadric& q, dvec3 m) {
    return dvec3(q.world_from_model * glm::dvec4(m, 1.0));
}

}  // namespace

void add_quadric_mesh(const Quadric& q, double z_lo, double z_hi, Style style, float alpha,
                      int around, int along, std::vector<Face3>& faces) {
    if (!(z_lo < z_hi)) return;
    const double two_pi = 6.283185307179586;
    auto z_at = [&](int j) {
        const double u = double(j) / along;
        if (q.kind == QuadricKind::Paraboloid) {  // even steps in √z: even rings
            const double a = std::sqrt(std::max(0.0, z_lo)), b = std::sqrt(z_hi);
            return (a + u * (b - a)) * (a + u * (b - a));
        }
        if (q.kind == QuadricKind::Sphere || q.kind == QuadricKind::Ellipsoid) {
            const double c = q.kind == QuadricKind::Sphere ? q.r : q.c;  // even in angle
            const double a = std::acos(std::clamp(z_hi / c, -1.0, 1.0)),
                         b = std::acos(std::clamp(z_lo / c, -1.0, 1.0));
            return c * std::cos(a + u * (b - a));
        }
        return z_lo + u * (z_hi - z_lo);
    };
    faces.reserve(faces.size() + static_cast<std::size_t>(around) * along);
    for (int j = 0; j < along; ++j) {
        const double z0 = z_at(j), z1 = z_at(j + 1);
        for (int i = 0; i < around; ++i) {
            const double p0 = two_pi * i / around, p1 = two_pi * (i + 1) / around;
            faces.push_back(
                {{to_world(q, surface_point(q, p0, z0)), to_world(q, surface_point(q, p1, z0)),
                  to_world(q, surface_point(q, p1, z1)), to_world(q, surface_point(q, p0, z1))},
                 style,
                 alpha,
                 true,
                 true});
        }
    }
}

}  // namespace cg
