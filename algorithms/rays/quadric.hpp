// Quadric surfaces for ray tracing, and the plain ray-quadric intersection a tracer calls.
//
// The course's surfaces, in their canonical model-space form F(x, y, z) = 0:
//
//   sphere                      x² + y² + z² − r² = 0
//   ellipsoid                   x²/a² + y²/b² + z²/c² − 1 = 0
//   elliptic paraboloid         x²/p² + y²/q² − z = 0
//   hyperboloid of one sheet    x²/a² + y²/b² − z²/c² − 1 = 0
//   elliptic cone               x²/p² + y²/q² − z²/r² = 0
//   elliptic cylinder           x²/p² + y²/q² − 1 = 0
//
// all of the one shape F = A x² + B y² + C z² + D z + E with the coefficients of `coefficients`
// below. F < 0 inside the solid, so the gradient ∇F = (2Ax, 2By, 2Cz + D) points out of it: the
// normal we report is ∇F's direction (not turned toward the ray). A surface is unbounded unless
// an optional model-space slab zmin ≤ z ≤ zmax cuts it (a cut surface is open: no caps).
//
// Placing a quadric: an optional affine `world_from_model` (column vectors, p_world = M p_model).
// Rays are carried into model space by its inverse, E_m = M⁻¹E, d_m = M⁻¹d (d as a direction,
// no translation); the ray parameter t is the same in both spaces, so t found in model space
// is t in the world. Normals go back by the inverse transpose: n_world = (M⁻¹)ᵀ ∇F.
//
// Substituting E + t d into F gives a t² + b t + c = 0 with
//   a = A dx² + B dy² + C dz²,
//   b = 2(A Ex dx + B Ey dy + C Ez dz) + D dz,
//   c = F(E) = A Ex² + B Ey² + C Ez² + D Ez + E.
// t is in units of the given direction (it is not normalised). The roots are computed without
// cancellation: with q = −(b + sign(b)√Δ)/2 they are q/a and c/q (Δ = b² − 4ac).
// Degenerate cases, decided with relative tolerances on the computed numbers (a value below
// kRelZero times the size of the terms that made it is round-off, treated as 0):
//   a = 0, b ≠ 0   linear: one root −c/b (a ray parallel to a paraboloid's axis, to a cone's
//                  generator, to a cylinder's axis...);
//   a = b = 0      no equation in t: c ≠ 0 never meets the surface; c = 0 lies in it (every t
//                  solves — the ray runs along a ruling) and counts as no intersection;
//   Δ = 0          tangent: one double root −b/(2a), listed once;
//   Δ < 0          no real root: a miss.
// The hit is the nearest root t > t_min (kEpsilon by default, in t's units) whose model point
// lies in the z slab.
#pragma once

#include "core/vec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <string>

namespace cg {

enum class QuadricKind : std::uint8_t {
    Sphere,
    Ellipsoid,
    Paraboloid,
    Hyperboloid,
    Cone,
    Cylinder
};

const char* quadric_kind_id(QuadricKind k);    // "sphere", "paraboloid", ... (the JSON "type")
const char* quadric_kind_name(QuadricKind k);  // "elliptic paraboloid", ...

// The surface as the user describes it. Only the parameters of its kind are used (the others
// keep their defaults): sphere r; ellipsoid and hyperboloid a, b, c; paraboloid and cylinder
// p, q; cone p, q, r. All are lengths, > 0.
struct Quadric {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    QuadricKind kind = QuadricKind::Sphere;
    double r = 1, a = 1, b = 1, c = 1, p = 1, q = 1;
    glm::dmat4 world_from_model{1.0};  // affine (last row 0 0 0 1), invertible
    double zmin = -kInf, zmax = kInf;  // the model-space slab kept; ±inf: not cut
    bool operator==(const Quadric&) const = default;
};

// F's coefficients: F(x, y, z) = A x² + B y² + C z² + D z + E.
struct QuadricCoefficients {
    double A = 0, B = 0, C = 0, D = 0, E = 0;
    bool operator==(const QuadricCoefficients&) const = default;
};
QuadricCoefficients coefficients(const Quadric& s);

// What the intersection needs, computed once per surface: a tracer keeps one per object.
struct PreparedQuadric {
    QuadricCoefficients f;
    bool transformed = false;     // world_from_model is not the identity
    glm::dmat3 linear_inv{1.0};   // M⁻¹'s 3×3 part (model_from_world for directions)
    glm::dvec3 translation{0.0};  // M's translation column
    // Normals go back by (M⁻¹)ᵀ: in glm that is the row vector ∇F times M⁻¹, ∇F * linear_inv.
    double zmin = -Quadric::kInf, zmax = Quadric::kInf;
    bool operator==(const PreparedQuadric&) const = default;
};
// Precondition: the quadric is valid (validate_quadric does not throw).
PreparedQuadric prepare(const Quadric& s);

// Throws InputError naming the field ("quadric.params.r", "quadric.transform[3]",
// "quadric.zmax") for a non-positive or non-finite parameter, a non-affine or singular
// transform, or an empty slab. `prefix` is the quadric's path in the input ("quadric").
void validate_quadric(const Quadric& s, const std::string& prefix);

// The ray in model space and the quadratic's coefficients (t² first).
struct RayQuadratic {
    glm::dvec3 origin{0.0}, direction{0.0};  // model space
    double a = 0, b = 0, c = 0;
    double a_size = 0;  // |A| dx² + |B| dy² + |C| dz²: the size of the terms that made a
    double b_size = 0;  // ... and b
    bool operator==(const RayQuadratic&) const = default;
};
RayQuadratic ray_quadratic(const PreparedQuadric& s, glm::dvec3 origin, glm::dvec3 direction);

enum class QuadraticCase : std::uint8_t {
    TwoRoots,    // Δ > 0
    Tangent,     // Δ = 0: a double root
    NoRoots,     // Δ < 0
    Linear,      // a = 0, b ≠ 0
    NoSolution,  // a = b = 0, c ≠ 0
    InSurface,   // a = b = c = 0
};

struct QuadraticRoots {
    QuadraticCase kind = QuadraticCase::NoRoots;
    double discriminant = 0;  // b² − 4ac (0 when forced by the tolerance; unused if linear)
    std::array<double, 2> t{0, 0};  // ascending
    int count = 0;                  // 0, 1 or 2
    bool operator==(const QuadraticRoots&) const = default;
};
QuadraticRoots solve_quadratic(const RayQuadratic& q);

struct QuadricHit {
    bool hit = false;
    std::array<double, 2> roots{0, 0};  // every real root, ascending (a double root once)
    int root_count = 0;
    double t = 0;             // the nearest root > t_min inside the slab (if hit)
    glm::dvec3 point{0.0};    // E + t d, world space (if hit)
    glm::dvec3 normal{0.0};   // unit, ∇F's direction, world space (if has_normal)
    bool has_normal = false;  // false at a miss and where ∇F = 0 (a cone's apex)
    bool operator==(const QuadricHit&) const = default;
};

constexpr double kRayEpsilon = 1e-9;  // default t_min, in units of the direction
constexpr double kRelZero = 1e-13;    // below this × the terms' size a computed value is 0

// The whole intersection as one plain function. The first form does prepare() per call; a
// tracer intersecting many rays with one surface prepares once and calls the second.
QuadricHit intersect(const Quadric& s, glm::dvec3 origin, glm::dvec3 direction,
                     double t_min = kRayEpsilon);
QuadricHit intersect(const PreparedQuadric& s, glm::dvec3 origin, glm::dvec3 direction,
                     double t_min = kRayEpsilon);
// Only the hit's t (+inf at a miss): what a tracer's nearest-hit search needs of each object.
double intersect_t(const PreparedQuadric& s, glm::dvec3 origin, glm::dvec3 direction,
                   double t_min = kRayEpsilon);
// The unit normal (∇F's direction, world space) at a world point on the surface; 0 where ∇F = 0.
glm::dvec3 normal_at(const PreparedQuadric& s, glm::dvec3 world_point);

// Helpers shared with the state machine.
inline double eval_F(const QuadricCoefficients& f, glm::dvec3 p) {
    return f.A * p.x * p.x + f.B * p.y * p.y + f.C * p.z * p.z + f.D * p.z + f.E;
}
inline glm::dvec3 gradient(const QuadricCoefficients& f, glm::dvec3 p) {
    return {2 * f.A * p.x, 2 * f.B * p.y, 2 * f.C * p.z + f.D};
}
}  // namespace cg
