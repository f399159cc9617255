// Bump mapping (Blinn, 1978): perturb the normal, not the geometry, so the lighting shows bumps
// that the silhouette does not (the course: "textures will still appear smooth — we perturb the
// normal, use for lighting calculation").
//
// The surface P(u, v) with partials P_u, P_v and normal n = P_u × P_v (not normalised) is
// displaced, in thought only, along its unit normal by a height B(u, v): P' = P + B n/|n|.
// Differentiating and dropping the terms with B itself (small bumps), P'_u ≈ P_u + B_u n/|n|,
// P'_v ≈ P_v + B_v n/|n|, and
//
//     n' = P'_u × P'_v ≈ n + D,   D = (B_u (n × P_v) − B_v (n × P_u)) / |n|
//
// (n × n = 0 removes the last term). n' is normalised for shading. n is oriented to agree with
// the surface's outward normal (a mirrored uv or a transform with negative determinant would
// flip P_u × P_v; both n and D are then negated). A constant B leaves n unchanged (B_u = B_v = 0).
//
// Heights (amplitude A; frequencies f_u, f_v in cycles per unit of u and v):
//   sines   B = A sin(2π f_u u) sin(2π f_v v)
//   noise   B = A · noise(f_u u, f_v v, 0)        (the Perlin noise of rays/noise.hpp, seeded)
//   image   B = A · grey(bilinear lookup at (u, v)), grey = (r + g + b)/3 (rays/texture.hpp)
// B_u and B_v are central differences with the step h: B_u = (B(u + h, v) − B(u − h, v))/(2h).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "rays/noise.hpp"
#include "rays/texture.hpp"
#include "rays/uv_map.hpp"

namespace cg {

enum class HeightKind : std::uint8_t { Sines, Noise, Image };
const char* height_kind_id(HeightKind k);  // "sines", "noise", "image"

struct HeightField {
    HeightKind kind = HeightKind::Sines;
    double amplitude = 0.02;
    glm::dvec2 frequency{4, 4};  // sines, noise
    std::uint64_t seed = 0;      // noise
    Texture image;               // image: grey-scale heights (looked up bilinearly)
    double step = 1e-4;          // h of the central differences, in (u, v) units
    bool operator==(const HeightField&) const = default;
};
// Throws InputError naming `field`'s parts ("height.step", …).
void validate_height(const HeightField& h, const std::string& field);

// B(u, v). `perlin` must be make_perlin(h.seed) for noise heights.
double height_at(const HeightField& h, const Perlin& perlin, glm::dvec2 uv);

struct BumpResult {
    double B = 0;                     // B(u, v)
    std::array<double, 4> samples{};  // B(u + h, v), B(u − h, v), B(u, v + h), B(u, v − h)
    double B_u = 0, B_v = 0;
    glm::dvec3 n{0.0};     // P_u × P_v, oriented outward
    bool flipped = false;  // P_u × P_v pointed inward and was negated
    glm::dvec3 n_cross_pv{0.0}, n_cross_pu{0.0};
    glm::dvec3 D{0.0};          // the perturbation
    glm::dvec3 normal{0.0};     // n/|n|, or `outward` where n = 0
    glm::dvec3 perturbed{0.0};  // (n + D)/|n + D|, unit
    bool singular = false;      // n = 0: nothing to perturb, n' = the outward normal
    bool operator==(const BumpResult&) const = default;
};
// Blinn's perturbation at a frame; `outward` is the surface's outward unit normal there (the
// orientation, and the answer where the parametrisation is singular). It is the two halves
// below, one after the other.
BumpResult blinn_bump(const UvFrame& frame, glm::dvec3 outward, const HeightField& h,
                      const Perlin& perlin);
// B, the four samples and the central differences B_u, B_v.
void bump_heights(const HeightField& h, const Perlin& perlin, glm::dvec2 uv, BumpResult& r);
// n = P_u × P_v oriented outward, D and the perturbed normal (needs B_u, B_v in r).
void bump_normal(const UvFrame& frame, glm::dvec3 outward, BumpResult& r);
// The surface's outward unit normal at P (a quadric's ∇F direction, a plane's or triangle's).
glm::dvec3 outward_normal(const PreparedUv& p, glm::dvec3 P);

}  // namespace cg
