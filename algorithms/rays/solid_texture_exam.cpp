// Solid-texture exam problems: "which colour does the 3D checker give at P?", or "work Perlin's
// noise at P by hand: the lattice cell, the fade weights, the ramps of the eight corner
// gradients listed, the interpolations; then the wood (or one-octave marble) colour". The points
// have coordinates in quarters (checker: halves of the cube size), so the fractions are 0, ¼, ½
// or ¾ and the fade weights are 0, 0.103515625, 0.5, 0.896484375. About one time in four a
// degenerate case: a point on a lattice corner (the noise is exactly 0 there), on a checker
// cube's face (⌊·⌋ takes the cube above), or negative coordinates (⌊−0.25⌋ = −1).
#include <array>
#include <cmath>
#include <glm/common.hpp>

#include "core/format.hpp"
#include "rays/solid_texture.hpp"

namespace cg {

namespace {

template <class T, std::size_t N>
const T& pick(Rng& rng, const std::array<T, N>& values) {
    return values[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(N) - 1))];
}

double quarter(Rng& rng, int lo, int hi) {
    return 0.25 * static_cast<double>(rng.integer(lo, hi));
}

}  // namespace

SolidTextureAlgo::Input SolidTextureAlgo::exam_input(Rng& rng) {
    Input in;
    SolidTexture& t = in.texture;
    const bool degenerate = rng.chance(0.25);
    const int kind = static_cast<int>(rng.integer(0, 2));
    glm::dvec3 p{quarter(rng, 0, 11), quarter(rng, 0, 11), quarter(rng, 0, 11)};
    if (kind == 0) {
        t.kind = SolidKind::Checker;
        t.colors = {glm::dvec3(1), glm::dvec3(0)};
        t.size = pick(rng, std::array<double, 2>{1, 2});
        p = {0.5 * t.size * static_cast<double>(rng.integer(-4, 5)) + 0.25 * t.size,
             0.5 * t.size * static_cast<double>(rng.integer(-4, 5)) + 0.25 * t.size,
             0.5 * t.size * static_cast<double>(rng.integer(-4, 5)) + 0.25 * t.size};
        if (degenerate) p.x = std::floor(p.x / t.size) * t.size;  // on a face
    } else {
        t.kind = kind == 1 ? SolidKind::Wood : SolidKind::Marble;
        t.colors = {glm::dvec3(1), glm::dvec3(0)};
        t.frequency = 1;
        t.seed = static_cast<std::uint64_t>(rng.integer(0, 999));
        t.axis = {0, 0, 1};
        t.period = 1;
        t.amplitude = 1;
        t.octaves = 1;
        if (degenerate) {
            if (rng.chance(0.5))
                p = glm::floor(p);  // a lattice corner
            else
                p = -p - glm::dvec3(0.25);  // negative coordinates
        }
    }
    in.points = {p};
    return in;
}

std::string SolidTextureAlgo::question(const Input& in) {
    const SolidTexture& t = in.texture;
    const glm::dvec3 p = in.points[0];
    if (t.kind == SolidKind::Checker)
        return "A 3D checker of cube size " + num(t.size) + " is c₀ = " + num(t.colors[0]) +
               " where ⌊x/s⌋ + ⌊y/s⌋ + ⌊z/s⌋ is even and c₁ = " + num(t.colors[1]) +
               " where it is odd. Give the cube (cells) and the colour "
               "(colors) at P = " +
               num(p) + " (noise: none, null).";
    const Perlin perlin = make_perlin(t.seed);
    const glm::dvec3 q = t.frequency * p;
    const glm::dvec3 c = glm::floor(q);
    std::string grads;
    for (int k = 0; k < 8; ++k) {
        const long long X = static_cast<long long>(c.x) + ((k >> 2) & 1),
                        Y = static_cast<long long>(c.y) + ((k >> 1) & 1),
                        Z = static_cast<long long>(c.z) + (k & 1);
        grads += (k ? ", " : "") + std::string("(") + std::to_string(X) + ", " + std::to_string(Y) +
                 ", " + std::to_string(Z) +
                 "): " + num(perlin_gradients()[gradient_index(perlin, X, Y, Z)]);
    }
    const std::string at = t.frequency == 1
                               ? "q = P = " + num(p)
                               : "q = f·P = " + num(t.frequency) + "·" + num(p) + " = " + num(q);
    std::string s = "Perlin noise at " + at +
                    " with the fade 6t⁵ − 15t⁴ + 10t³ and the corner gradients " + grads +
                    ". Give the lattice cell (cells), noise(q) = the trilinear blend of the "
                    "ramps g·(q − corner) (noise), and the colour (colors) of ";
    if (t.kind == SolidKind::Wood)
        s += "wood: t = frac(r/" + num(t.period) + " + " + num(t.amplitude) +
             "·noise(q)), r = the distance of P from the axis " + num(t.axis) +
             ", colour = (1 − t)·c₀ + t·c₁ with c₀ = " + num(t.colors[0]) +
             ", c₁ = " + num(t.colors[1]) + ".";
    else
        s += "marble (" + std::to_string(t.octaves) + " octave" + (t.octaves == 1 ? "" : "s") +
             "): t = ½(1 + sin(2π P·â/" + num(t.period) + " + " + num(t.amplitude) +
             "·turbulence(q))), â = " + num(t.axis) +
             ", colour = (1 − t)·c₀ + t·c₁ with c₀ = " + num(t.colors[0]) +
             ", c₁ = " + num(t.colors[1]) + " (noise: give the turbulence Σ |noise(2^k q)|/2^k).";
    return s;
}

std::vector<std::string> SolidTextureAlgo::answer_fields() {
    return {"cells", "noise", "colors"};
}

}  // namespace cg
