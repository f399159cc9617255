// Parametrisations: a point on a surface to texture coordinates (u, v), and the surface's
// partial derivatives P_u = ∂P/∂u, P_v = ∂P/∂v there (what bump mapping needs).
//
//   plane     a point O on it, a unit u axis â in the plane and a scale s; the v axis is
//             b̂ = n̂ × â, so (â, b̂, n̂) is right-handed:  u = (P − O)·â / s,  v = (P − O)·b̂ / s;
//             P_u = s â, P_v = s b̂.
//   triangle  vertices p0, p1, p2 with texture coordinates uv0, uv1, uv2 (default (0, 0),
//             (1, 0), (0, 1)): the point's barycentric weights (α, β, γ), P = α p0 + β p1 + γ p2,
//             interpolate uv = α uv0 + β uv1 + γ uv2. With J = [uv1 − uv0, uv2 − uv0] (2×2),
//             [P_u P_v] = [p1 − p0, p2 − p0] J⁻¹.
//   quadrics  in model space (so a transform carries the texture with the surface), the
//             longitude φ = atan2(y/s_y, x/s_x) around the z axis gives u = ½ + φ/(2π):
//     sphere, ellipsoid   latitude: θ = acos(z/c) from the +z pole (the point scaled to the unit
//                         sphere first), v = 1 − θ/π;
//                         P(u, v) = (a sin θ cos φ, b sin θ sin φ, c cos θ);
//     cylinder, cone,     height: v = (z − zmin)/(zmax − zmin) when the slab is finite, else
//     paraboloid,         v = z; P(u, v) = (s_x ρ(z) cos φ, s_y ρ(z) sin φ, z) with the ring's
//     hyperboloid         size ρ = 1 (cylinder), |z|/r (cone), √z (paraboloid), √(1 + z²/c²)
//                         (hyperboloid).
//             World partials are M's linear part times the model ones.
// At a sphere's poles and a cone's apex P_u = 0 (the parametrisation is singular there): the
// frame says so, and bump mapping leaves the normal alone.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "rays/quadric.hpp"

namespace cg {

enum class UvKind : std::uint8_t { Quadric, Plane, Triangle };

struct UvSurface {
    UvKind kind = UvKind::Plane;
    Quadric quadric;  // Quadric
    // Plane: a point, the normal (any length) and the u axis (any length, not parallel to the
    // normal; its part along the normal is removed), and the scale s > 0.
    glm::dvec3 origin{0.0}, normal{0, 0, 1}, u_axis{1, 0, 0};
    double scale = 1;
    // Triangle: the corners and their texture coordinates.
    std::array<glm::dvec3, 3> p{glm::dvec3(0.0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)};
    std::array<glm::dvec2, 3> uv{glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1)};
    bool operator==(const UvSurface&) const = default;
};

// The default u axis of a plane with normal n: the world x axis projected into the plane, or
// the z axis when n is along x (so a floor y = 0 gets u along x, v along −z... see b̂ = n̂ × â).
glm::dvec3 default_u_axis(glm::dvec3 normal);

// What the mapping needs, computed once per surface.
struct PreparedUv {
    UvKind kind = UvKind::Plane;
    QuadricKind quadric_kind = QuadricKind::Sphere;
    PreparedQuadric quadric;
    glm::dmat3 linear{1.0};  // M's linear part (model → world directions)
    glm::dvec3 sxyz{1.0};    // the quadric's semi-axes along x, y (and c along z)
    double cone_r = 1, hyper_c = 1;
    double zmin = 0, height = 1;  // v = (z − zmin)/height (height 1, zmin 0 when not cut)
    glm::dvec3 origin{0.0}, a{1, 0, 0}, b{0, 1, 0}, n{0, 0, 1};  // plane: unit axes and normal
    double scale = 1;
    glm::dvec3 p0{0.0}, e1{1, 0, 0}, e2{0, 1, 0};  // triangle
    glm::dvec2 uv0{0.0}, j1{1, 0}, j2{0, 1};       // uv0 and J's columns
    glm::dvec3 P_u{0.0}, P_v{0.0};                 // triangle and plane: constant partials
    bool operator==(const PreparedUv&) const = default;
};
// Precondition: the surface is valid (validate_uv_surface does not throw).
PreparedUv prepare_uv(const UvSurface& s);
// Throws InputError naming `field`'s parts (a quadric's params, "u_axis", "uv", "scale").
void validate_uv_surface(const UvSurface& s, const std::string& field);

struct UvFrame {
    glm::dvec2 uv{0.0};
    glm::dvec3 P_u{0.0}, P_v{0.0};  // world space
    glm::dvec3 model_point{0.0};    // quadrics: the point in model space
    glm::dvec3 barycentric{0.0};    // triangles: (α, β, γ)
    double phi = 0, theta = 0;      // quadrics: longitude (and latitude for spheres), radians
    bool singular = false;          // P_u × P_v = 0: a pole or an apex
    bool operator==(const UvFrame&) const = default;
};
// The texture coordinates and partials at a point on (or near: it is projected) the surface.
UvFrame uv_frame(const PreparedUv& s, glm::dvec3 world_point);
// Throws InputError(field, …) unless P lies on the surface (within round-off; inside the
// triangle, inside the quadric's slab): a texture lookup means nothing elsewhere. A plane is
// the exception: a point off it is projected onto it along the normal (u and v ignore the
// normal component), so a plane whose normal is edited keeps its points.
void check_on_surface(const UvSurface& s, const PreparedUv& p, glm::dvec3 P,
                      const std::string& field);
// The other way: the surface point P(u, v), world space (for pictures and tests).
glm::dvec3 uv_point(const PreparedUv& s, glm::dvec2 uv);

}  // namespace cg
