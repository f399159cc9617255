// Solid textures (the course: "hard to texture map onto curved surfaces — use a 3D texture
// instead, usually procedural"): a colour computed from the point itself, and Perlin's
// gradient noise that makes the procedural ones look natural.
//
// Perlin noise (Perlin's improved noise, 2002). The integer lattice cell holding p is
// (X, Y, Z) = ⌊p⌋ and the point's place in it (x, y, z) = p − ⌊p⌋. Each lattice corner c gets a
// pseudo-random gradient g_c, one of the 12 edge directions of a cube ((±1, ±1, 0), (±1, 0, ±1),
// (0, ±1, ±1)), picked by hashing the corner with a permutation π of 0…255:
// g = G[π[π[π[X] + Y] + Z] mod 12] (indices mod 256). Each corner contributes the linear ramp
// g_c·(p − c); the eight are blended by trilinear interpolation with the fade curve
// f(t) = 6t⁵ − 15t⁴ + 10t³ in each axis. At lattice points every ramp is 0 there, so the noise
// is 0; between them it wanders in about [−1, 1]. The fade is the quintic, not the classic
// 3t² − 2t³: both have f' = 0 at the cell faces (so the noise is C¹), but only the quintic also
// has f'' = 0 there, so a normal or a lighting derived from the noise has no visible creases
// along the lattice. π is a Fisher-Yates shuffle driven by the seeded SplitMix64 generator
// (core/rng.hpp): a seed names one noise, bit for bit, on every machine.
//
// Turbulence: Σ_{k < octaves} |noise(2^k p)| / 2^k.
//
// The textures (two colours c0, c1; â is a unit axis; "mix" is (1 − t) c0 + t c1):
//   checker  c0 where ⌊x/s⌋ + ⌊y/s⌋ + ⌊z/s⌋ is even, else c1 (s: the cube size);
//   stripes  t = ½ (1 + sin(2π (p·â)/period));
//   wood     rings around the axis through the origin: r = |p − (p·â) â|,
//            t = frac(r/period + amplitude · noise(frequency · p));
//   marble   t = ½ (1 + sin(2π (p·â)/period + amplitude · turbulence(frequency · p, octaves))).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>

namespace cg {

struct Perlin {
    std::uint64_t seed = 0;
    std::array<std::uint8_t, 256> perm{};  // π
    bool operator==(const Perlin&) const = default;
};
Perlin make_perlin(std::uint64_t seed);

// The 12 gradient directions, and the one a lattice corner gets.
const std::array<glm::dvec3, 12>& perlin_gradients();
int gradient_index(const Perlin& n, long long X, long long Y, long long Z);

double fade(double t);  // 6t⁵ − 15t⁴ + 10t³

// Everything one noise evaluation computes, for the steps and the picture.
struct NoiseDetail {
    glm::dvec3 p{0.0};
    std::array<long long, 3> cell{0, 0, 0};  // ⌊p⌋
    glm::dvec3 frac{0.0};                    // p − ⌊p⌋
    glm::dvec3 fade{0.0};                    // f of each fraction
    std::array<int, 8> gradient{};           // corner (a, b, c) at index 4a + 2b + c
    std::array<double, 8> dot{};             // g_c · (p − c)
    std::array<double, 4> along_z{};         // lerps in z: (00, 01, 10, 11) by (a, b)
    std::array<double, 2> along_y{};         // then in y
    double value = 0;                        // then in x
    bool operator==(const NoiseDetail&) const = default;
};
// The same arithmetic either way: perlin_noise(n, p) == perlin_detail(n, p).value bit for bit.
double perlin_noise(const Perlin& n, glm::dvec3 p);
NoiseDetail perlin_detail(const Perlin& n, glm::dvec3 p);
double turbulence(const Perlin& n, glm::dvec3 p, int octaves);

// Points must stay where ⌊p⌋ and the fractions are exact enough: |coordinate × frequency| ≤ this.
constexpr double kMaxNoiseCoordinate = 1e9;
constexpr int kMaxOctaves = 16;

enum class SolidKind : std::uint8_t { Checker, Stripes, Wood, Marble };
const char* solid_kind_id(SolidKind k);  // "checker", "stripes", "wood", "marble"

struct SolidTexture {
    SolidKind kind = SolidKind::Marble;
    std::array<glm::dvec3, 2> colors{glm::dvec3(0.9, 0.9, 0.88), glm::dvec3(0.25, 0.22, 0.3)};
    double size = 1;           // checker: the cube's side
    glm::dvec3 axis{0, 0, 1};  // stripes, wood, marble (any length > 0)
    double period = 1;         // stripes, wood, marble
    double amplitude = 4;      // wood, marble: how much the noise bends the pattern
    double frequency = 1;      // wood, marble: the noise's scale, lattice cells per unit
    int octaves = 4;           // marble: turbulence octaves
    std::uint64_t seed = 0;    // wood, marble: which noise
    bool operator==(const SolidTexture&) const = default;
};
bool uses_noise(SolidKind k);  // wood, marble
// Throws InputError naming `field`'s parts ("texture.period", …).
void validate_solid(const SolidTexture& t, const std::string& field);

struct SolidSample {
    glm::dvec3 color{0.0};
    double t = 0;             // the mix between c0 and c1 (checker: 0 or 1)
    double noise = 0;         // wood: the noise; marble: the turbulence (0 for the others)
    glm::dvec3 axis{0.0};     // unit axis
    bool cell_known = false;  // wood, marble: the noise cell ⌊f p⌋; checker ⌊p/s⌋
    std::array<long long, 3> cell{0, 0, 0};
    bool operator==(const SolidSample&) const = default;
};
// `perlin` must be make_perlin(t.seed) when the texture uses noise.
SolidSample solid_sample(const SolidTexture& t, const Perlin& perlin, glm::dvec3 p);

}  // namespace cg
