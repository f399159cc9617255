// The primitives the acceleration structures (bvh, uniform-grid) hold: spheres, triangles and
// axis-aligned boxes — each with its bounding box and its ray intersection.
//
// The ray is the half-line P(t) = E + t d, t ≥ 0, t in units of d (not normalised), as in the
// slab test (ray_aabb.hpp). A primitive's hit is its nearest surface point with t ≥ 0:
//   sphere   |P − C|² = r²: the smaller root, or the larger when E is inside (t0 < 0 ≤ t1);
//   triangle Möller–Trumbore: E + t d = A + β (B − A) + γ (C − A) solved by Cramer's rule,
//            a hit when β ≥ 0, γ ≥ 0, β + γ ≤ 1 (edges and corners included) and t ≥ 0; a ray
//            in the triangle's plane (det = 0) misses it (it would meet only its edge);
//            (β, γ) are returned: the barycentric weights of B and C, for interpolation;
//   box      the slab test: t_min, or t_max when E is in the box.
// Bounds: a sphere's is C ± r, a triangle's the min/max of its corners, a box's itself.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <string>

namespace cg {

// An axis-aligned bounding box; the default is the empty box (min = +∞, max = −∞), which
// grow() turns into the box of what it is given.
struct Bounds {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    glm::dvec3 min{kInf}, max{-kInf};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void grow(glm::dvec3 p);
    void grow(const Bounds& b);
    glm::dvec3 centre() const { return (min + max) * 0.5; }
    glm::dvec3 extent() const { return max - min; }
    // 2(ab + bc + ca): the SAH's measure of how likely a random ray is to hit the box; 0 for
    // the empty box.
    double surface_area() const;
    bool operator==(const Bounds&) const = default;
};

enum class PrimitiveKind : std::uint8_t { Sphere, Triangle, Box };

struct Primitive {
    PrimitiveKind kind = PrimitiveKind::Sphere;
    // sphere: a = centre, radius; triangle: a, b, c (counter-clockwise seen from the front);
    // box: a = min, b = max.
    glm::dvec3 a{0.0}, b{0.0}, c{0.0};
    double radius = 0;
    bool operator==(const Primitive&) const = default;
};

// Making them: prim::sphere(C, r), prim::triangle(A, B, C), prim::box(min, max).
namespace prim {
inline Primitive sphere(glm::dvec3 centre, double radius) {
    Primitive p;
    p.kind = PrimitiveKind::Sphere, p.a = centre, p.radius = radius;
    return p;
}
inline Primitive triangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    Primitive p;
    p.kind = PrimitiveKind::Triangle, p.a = a, p.b = b, p.c = c;
    return p;
}
inline Primitive box(glm::dvec3 min, glm::dvec3 max) {
    Primitive p;
    p.kind = PrimitiveKind::Box, p.a = min, p.b = max;
    return p;
}
}  // namespace prim

Bounds bounds(const Primitive& p);
// The point a build sorts and splits by: the centre of the primitive's bounds.
glm::dvec3 centroid(const Primitive& p);

struct PrimitiveHit {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    double t = kInf;             // kInf: no hit with t ≥ 0
    double beta = 0, gamma = 0;  // a triangle's barycentric weights of b and c at the hit
    bool hit() const { return t < kInf; }
};

// The nearest hit with t ≥ 0 of the ray E + t d (d ≠ 0) on p.
PrimitiveHit intersect(const Primitive& p, glm::dvec3 origin, glm::dvec3 direction);

// Whether p meets the closed box b (touching counts), exactly up to rounding: a sphere by the
// squared distance from its centre to the box (Arvo: Σ over axes of the gap outside [min, max],
// squared, ≤ r²); a box by its bounds (every axis's intervals overlap); a triangle by the
// separating-axis test (Akenine-Möller: the box's 3 axes, the triangle's normal and the 9
// cross products of its edges with the axes — no separating axis means they meet).
bool overlaps(const Primitive& p, const Bounds& b);

// "sphere C (0, 0, 0) r 1", "triangle (0, 0, 0) (1, 0, 0) (0, 1, 0)", "box (0, 0, 0)–(1, 1, 1)":
// for narrations.
std::string describe(const Primitive& p);
const char* kind_name(PrimitiveKind k);  // "sphere", "triangle", "box"

}  // namespace cg
