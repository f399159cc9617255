// Sections: [prepare and validate] [the frame]
#include "rays/uv_map.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>

#include "core/format.hpp"
#include "core/step.hpp"

namespace cg {

using glm::dvec2;
using glm::dvec3;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * std::numbers::pi;

bool sphere_like(QuadricKind k) {
    return k == QuadricKind::Sphere || k == QuadricKind::Ellipsoid;
}
}  // namespace

// ---- [prepare and validate] -----------------------------------------------------------------

dvec3 default_u_axis(dvec3 normal) {
    const dvec3 n = unit(normal);
    const dvec3 x{1, 0, 0};
    return std::fabs(n.x) < 0.9 ? unit(x - glm::dot(x, n) * n)
                                : unit(glm::cross(n, dvec3(0, 1, 0)));
}

void validate_uv_surface(const UvSurface& s, const std::string& field) {
    switch (s.kind) {
        case UvKind::Quadric:
            validate_quadric(s.quadric, field);
            return;
        case UvKind::Plane: {
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(s.origin[c]) || std::fabs(s.origin[c]) > 1e12)
                    throw InputError(field + ".point[" + std::to_string(c) + "]",
                                     "must be a finite number of magnitude at most 1e12");
            const dvec3 n = unit(s.normal);
            if (n == dvec3(0.0)) throw InputError(field + ".normal", "must not be the zero vector");
            const dvec3 a = unit(s.u_axis);
            if (a == dvec3(0.0)) throw InputError(field + ".u_axis", "must not be the zero vector");
            if (glm::length(a - glm::dot(a, n) * n) < 1e-6)
                throw InputError(field + ".u_axis",
                                 "must not be parallel to the plane's normal " + given(s.normal, 4) +
                                     ": it has to give a direction in the plane");
            if (!(s.scale > 1e-9 && s.scale < 1e12))
                throw InputError(field + ".uv_scale",
                                 "must be a length between 1e-9 and 1e12: the size of one texture "
                                 "repeat (got " +
                                     given(s.scale) + ")");
            return;
        }
        case UvKind::Triangle: {
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 3; ++c)
                    if (!std::isfinite(s.p[k][c]) || std::fabs(s.p[k][c]) > 1e12)
                        throw InputError(field + ".vertices[" + std::to_string(k) + "][" +
                                             std::to_string(c) + "]",
                                         "must be a finite number of magnitude at most 1e12");
            const dvec3 e1 = s.p[1] - s.p[0], e2 = s.p[2] - s.p[0];
            const double area2 = glm::length(glm::cross(e1, e2));
            if (!(area2 > 1e-12 * glm::length(e1) * glm::length(e2)) || !(area2 > 0))
                throw InputError(field + ".vertices", "is degenerate: the corners " +
                                                          given(s.p[0], 4) + ", " + given(s.p[1], 4) +
                                                          ", " + given(s.p[2], 4) +
                                                          " are collinear or coincide (zero area)");
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 2; ++c)
                    if (!std::isfinite(s.uv[k][c]) || std::fabs(s.uv[k][c]) > 1e9)
                        throw InputError(
                            field + ".uv[" + std::to_string(k) + "][" + std::to_string(c) + "]",
                            "must be a finite number of magnitude at most 1e9");
            const dvec2 j1 = s.uv[1] - s.uv[0], j2 = s.uv[2] - s.uv[0];
            const double det = j1.x * j2.y - j1.y * j2.x;
            if (!(std::fabs(det) > 1e-12 * glm::length(j1) * glm::length(j2)) || det == 0)
                throw InputError(field + ".uv",
                                 "must not put the three corners on one line in (u, v): the "
                                 "texture would have no area on the triangle");
            return;
        }
    }
}

PreparedUv prepare_uv(const UvSurface& s) {
    PreparedUv p;
    p.kind = s.kind;
    switch (s.kind) {
        case UvKind::Quadric: {
            const Quadric& q = s.quadric;
            p.quadric_kind = q.kind;
            p.quadric = prepare(q);
            p.linear = glm::dmat3(q.world_from_model);
            switch (q.kind) {
                case QuadricKind::Sphere:
                    p.sxyz = dvec3(q.r);
                    break;
                case QuadricKind::Ellipsoid:
                case QuadricKind::Hyperboloid:
                    p.sxyz = {q.a, q.b, q.c};
                    p.hyper_c = q.c;
                    break;
                case QuadricKind::Cone:
                    p.sxyz = {q.p, q.q, 1};
                    p.cone_r = q.r;
                    break;
                case QuadricKind::Paraboloid:
                case QuadricKind::Cylinder:
                    p.sxyz = {q.p, q.q, 1};
                    break;
            }
            if (std::isfinite(q.zmin) && std::isfinite(q.zmax)) {
                p.zmin = q.zmin;
                p.height = q.zmax - q.zmin;
            }
            return p;
        }
        case UvKind::Plane: {
            p.origin = s.origin;
            p.n = unit(s.normal);
            const dvec3 a = unit(s.u_axis);
            p.a = unit(a - glm::dot(a, p.n) * p.n);
            p.b = glm::cross(p.n, p.a);
            p.scale = s.scale;
            p.P_u = p.scale * p.a;
            p.P_v = p.scale * p.b;
            return p;
        }
        case UvKind::Triangle: {
            p.p0 = s.p[0];
            p.e1 = s.p[1] - s.p[0];
            p.e2 = s.p[2] - s.p[0];
            p.uv0 = s.uv[0];
            p.j1 = s.uv[1] - s.uv[0];
            p.j2 = s.uv[2] - s.uv[0];
            const double det = p.j1.x * p.j2.y - p.j1.y * p.j2.x;
            // [P_u P_v] = [e1 e2] J⁻¹, J⁻¹ = [j2.y −j2.x; −j1.y j1.x] / det J.
            p.P_u = (p.j2.y * p.e1 - p.j1.y * p.e2) / det;
            p.P_v = (-p.j2.x * p.e1 + p.j1.x * p.e2) / det;
            return p;
        }
    }
    return p;
}

// ---- [the frame] ----------------------------------------------------------------------------

namespace {

void quadric_frame(const PreparedUv& s, dvec3 P, UvFrame& f) {
    const dvec3 m = s.quadric.transformed ? s.quadric.linear_inv * (P - s.quadric.translation) : P;
    f.model_point = m;
    dvec3 Pu, Pv;
    if (sphere_like(s.quadric_kind)) {
        // Latitude and longitude of the point scaled onto the unit sphere.
        const double a = s.sxyz.x, b = s.sxyz.y, c = s.sxyz.z;
        dvec3 q = unit(dvec3(m.x / a, m.y / b, m.z / c));
        if (q == dvec3(0.0)) q = {0, 0, 1};  // the centre: no direction, call it the pole
        f.theta = std::acos(std::clamp(q.z, -1.0, 1.0));
        f.phi = std::atan2(q.y, q.x);
        f.uv = {0.5 + f.phi / kTwoPi, 1 - f.theta / kPi};
        const double st = std::sin(f.theta), ct = std::cos(f.theta);
        const double sp = std::sin(f.phi), cp = std::cos(f.phi);
        // ∂P/∂u = ∂P/∂φ · 2π, ∂P/∂v = ∂P/∂θ · (−π).
        Pu = kTwoPi * dvec3(-a * st * sp, b * st * cp, 0);
        Pv = -kPi * dvec3(a * ct * cp, b * ct * sp, -c * st);
        f.singular = !(st > 1e-12);
    } else {
        const double sx = s.sxyz.x, sy = s.sxyz.y, z = m.z;
        f.phi = std::atan2(m.y / sy, m.x / sx);
        f.uv = {0.5 + f.phi / kTwoPi, (z - s.zmin) / s.height};
        double rho = 1, drho = 0;  // the ring's size ρ(z) and dρ/dz
        switch (s.quadric_kind) {
            case QuadricKind::Cone:
                rho = std::fabs(z) / s.cone_r;
                drho = (z > 0 ? 1 : z < 0 ? -1 : 0) / s.cone_r;
                break;
            case QuadricKind::Paraboloid:
                rho = std::sqrt(std::max(z, 0.0));
                drho = rho > 0 ? 0.5 / rho : 0;
                break;
            case QuadricKind::Hyperboloid:
                rho = std::sqrt(1 + z * z / (s.hyper_c * s.hyper_c));
                drho = z / (s.hyper_c * s.hyper_c * rho);
                break;
            default:
                break;
        }
        const double sp = std::sin(f.phi), cp = std::cos(f.phi);
        Pu = kTwoPi * dvec3(-sx * rho * sp, sy * rho * cp, 0);
        Pv = s.height * dvec3(sx * drho * cp, sy * drho * sp, 1);
        f.singular = !(rho > 1e-12);
    }
    f.P_u = s.linear * Pu;
    f.P_v = s.linear * Pv;
}

}  // namespace

UvFrame uv_frame(const PreparedUv& s, dvec3 P) {
    UvFrame f;
    switch (s.kind) {
        case UvKind::Quadric:
            quadric_frame(s, P, f);
            return f;
        case UvKind::Plane: {
            const dvec3 d = P - s.origin;
            f.uv = {glm::dot(d, s.a) / s.scale, glm::dot(d, s.b) / s.scale};
            f.P_u = s.P_u;
            f.P_v = s.P_v;
            return f;
        }
        case UvKind::Triangle: {
            // Barycentric weights of the point (projected onto the triangle's plane).
            const dvec3 d = P - s.p0;
            const double e11 = glm::dot(s.e1, s.e1), e12 = glm::dot(s.e1, s.e2),
                         e22 = glm::dot(s.e2, s.e2);
            const double d1 = glm::dot(d, s.e1), d2 = glm::dot(d, s.e2);
            const double det = e11 * e22 - e12 * e12;
            const double beta = (e22 * d1 - e12 * d2) / det, gamma = (e11 * d2 - e12 * d1) / det;
            f.barycentric = {1 - beta - gamma, beta, gamma};
            f.uv = s.uv0 + beta * s.j1 + gamma * s.j2;
            f.P_u = s.P_u;
            f.P_v = s.P_v;
            return f;
        }
    }
    return f;
}

dvec3 uv_point(const PreparedUv& s, dvec2 uv) {
    switch (s.kind) {
        case UvKind::Plane:
            return s.origin + s.scale * (uv.x * s.a + uv.y * s.b);
        case UvKind::Triangle: {
            const dvec2 w = uv - s.uv0;
            const double det = s.j1.x * s.j2.y - s.j1.y * s.j2.x;
            const double beta = (s.j2.y * w.x - s.j2.x * w.y) / det;
            const double gamma = (-s.j1.y * w.x + s.j1.x * w.y) / det;
            return s.p0 + beta * s.e1 + gamma * s.e2;
        }
        case UvKind::Quadric: {
            const double phi = kTwoPi * (uv.x - 0.5);
            dvec3 m;
            if (sphere_like(s.quadric_kind)) {
                const double theta = kPi * (1 - uv.y);
                m = {s.sxyz.x * std::sin(theta) * std::cos(phi),
                     s.sxyz.y * std::sin(theta) * std::sin(phi), s.sxyz.z * std::cos(theta)};
            } else {
                const double z = s.zmin + uv.y * s.height;
                double rho = 1;
                if (s.quadric_kind == QuadricKind::Cone) rho = std::fabs(z) / s.cone_r;
                if (s.quadric_kind == QuadricKind::Paraboloid) rho = std::sqrt(std::max(z, 0.0));
                if (s.quadric_kind == QuadricKind::Hyperboloid)
                    rho = std::sqrt(1 + z * z / (s.hyper_c * s.hyper_c));
                m = {s.sxyz.x * rho * std::cos(phi), s.sxyz.y * rho * std::sin(phi), z};
            }
            return s.linear * m + s.quadric.translation;
        }
    }
    return s.origin;
}

// The point must lie on the surface: the map is only meaningful there.
void check_on_surface(const UvSurface& s, const PreparedUv& p, dvec3 P, const std::string& field) {
    switch (s.kind) {
        case UvKind::Plane:  // a point off the plane is projected onto it: u, v ignore n
            return;
        case UvKind::Triangle: {
            const dvec3 n = unit(glm::cross(p.e1, p.e2));
            const double d = glm::dot(P - p.p0, n);
            const double size = 1 + glm::length(p.e1) + glm::length(p.e2) + glm::length(P);
            if (std::fabs(d) > 1e-9 * size)
                throw InputError(
                    field, "must lie in the triangle's plane (it is " + given(d, 4) + " off it)");
            const dvec3 b = uv_frame(p, P).barycentric;
            if (b.x < -1e-9 || b.y < -1e-9 || b.z < -1e-9)
                throw InputError(
                    field,
                    "must lie inside the triangle (its barycentric weights are " + given(b, 4) + ")");
            return;
        }
        case UvKind::Quadric: {
            const PreparedQuadric& q = p.quadric;
            const dvec3 m = q.transformed ? q.linear_inv * (P - q.translation) : P;
            const QuadricCoefficients& f = q.f;
            const double size = std::fabs(f.A) * m.x * m.x + std::fabs(f.B) * m.y * m.y +
                                std::fabs(f.C) * m.z * m.z + std::fabs(f.D * m.z) + std::fabs(f.E);
            const double F = eval_F(f, m);
            if (!(std::fabs(F) <= 1e-9 * size))  // size 0: the cone's apex, on the surface
                throw InputError(field, std::string("must lie on the ") +
                                            quadric_kind_name(s.quadric.kind) +
                                            " (F = " + given(F, 4) + " there, not 0)");
            if (m.z < q.zmin - 1e-9 * (1 + std::fabs(q.zmin)) ||
                m.z > q.zmax + 1e-9 * (1 + std::fabs(q.zmax)))
                throw InputError(
                    field, "must lie inside the slab zmin ≤ z ≤ zmax (model z = " + given(m.z) + ")");
            return;
        }
    }
}

}  // namespace cg
