// Sample patterns and reconstruction filters for anti-aliasing: shared by supersampling, the
// 2D part of sampling and the distribution ray tracer.
//
// Patterns place `count` points in the unit square [0, 1)² (a pixel's footprint, measured from
// its bottom-left corner), seeded only from core/rng.hpp so that a seed names one pattern on
// every machine:
//   regular   n × n points at the cell centres ((a + ½)/n, (b + ½)/n); count = n²
//   random    count independent uniform points
//   jittered  stratified: one uniform point in each of the n × n cells, ((a + ξx)/n, (b + ξy)/n);
//             count = n²
//   poisson   dart throwing: uniform candidates, each kept only if it is at least `radius` from
//             every point kept so far; at most kMaxDartsPerSample × count darts, so a radius too
//             large for the count gives fewer points (never a hang)
// Grid patterns list their cells row by row from the bottom (b outer, a inner); each uniform
// point takes x before y from the generator.
//
// Filters weight a sample by its offset (dx, dy) from the pixel's centre, in pixel units:
//   box       1
//   tent      (1 − |dx|)(1 − |dy|)               (the bilinear tent, 1 pixel in radius)
//   gaussian  exp(−(dx² + dy²) / (2σ²)), σ = ½   (0.37 at a pixel's corner)
// A pixel's estimate is Σ w_k v_k / Σ w_k; every weight is > 0 inside the pixel.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"

namespace cg::sampling {

enum class Pattern : std::uint8_t { Regular, Random, Jittered, Poisson };
enum class Filter : std::uint8_t { Box, Tent, Gaussian };

constexpr int kMaxDartsPerSample = 100;  // poisson: darts thrown per wanted point, at most
constexpr double kGaussianSigma = 0.5;   // pixel units

const char* pattern_id(Pattern p);  // "regular", "random", "jittered", "poisson"
const char* filter_id(Filter f);    // "box", "tent", "gaussian"
bool parse_pattern(const std::string& s, Pattern& out);
bool parse_filter(const std::string& s, Filter& out);
bool is_grid(Pattern p);  // regular and jittered need count = n²

// n with n² = count, or 0 when count is no perfect square.
int grid_side(long long count);
// A poisson radius that dart throwing reaches comfortably: 0.7/√count.
double default_radius(int count);

// One generated point and how it was made.
struct PatternPoint {
    glm::dvec2 p{0.0};   // in [0, 1)²
    glm::dvec2 xi{0.5};  // the uniform numbers used (random, jittered, poisson's last dart)
    int cell_a = -1;     // grid patterns: the cell (a, b) it sits in
    int cell_b = -1;
    int darts = 1;  // poisson: darts thrown for this point (rejected ones + 1)
    bool operator==(const PatternPoint&) const = default;
};

// The points of a pattern for `seed` (regular ignores it). Grid patterns need count = n²
// (checked by the caller). `radius` is used by poisson only.
std::vector<PatternPoint> generate(Pattern pattern, int count, std::uint64_t seed,
                                   double radius = 0);

// A seed for one pixel (or any pair of indices) derived from a scene's seed, so that every
// pixel has its own stream and the image does not depend on the order pixels are done in.
std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0);

// The weight at offset d from the pixel's centre (pixel units).
double weight(Filter f, glm::dvec2 d);
// ∫∫ over the pixel [−½, ½]² of the weight.
double pixel_weight_integral(Filter f);

}  // namespace cg::sampling
