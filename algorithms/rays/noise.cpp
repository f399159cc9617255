// Sections: [perlin noise] [solid textures]
#include "rays/noise.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>

#include "core/format.hpp"
#include "core/rng.hpp"
#include "core/step.hpp"
#include "rays/quadric.hpp"

namespace cg {

using glm::dvec3;

// ---- [perlin noise] -------------------------------------------------------------------------

Perlin make_perlin(std::uint64_t seed) {
    Perlin n;
    n.seed = seed;
    for (int i = 0; i < 256; ++i) n.perm[i] = static_cast<std::uint8_t>(i);
    Rng rng(seed);
    for (int i = 255; i > 0; --i) {  // Fisher-Yates: swap i with a uniform j ≤ i
        const int j = static_cast<int>(rng.integer(0, i));
        std::swap(n.perm[i], n.perm[j]);
    }
    return n;
}

const std::array<dvec3, 12>& perlin_gradients() {
    static const std::array<dvec3, 12> g{{{1, 1, 0},
                                          {-1, 1, 0},
                                          {1, -1, 0},
                                          {-1, -1, 0},
                                          {1, 0, 1},
                                          {-1, 0, 1},
                                          {1, 0, -1},
                                          {-1, 0, -1},
                                          {0, 1, 1},
                                          {0, -1, 1},
                                          {0, 1, -1},
                                          {0, -1, -1}}};
    return g;
}

int gradient_index(const Perlin& n, long long X, long long Y, long long Z) {
    const int h = n.perm[(n.perm[(n.perm[X & 255] + (Y & 255)) & 255] + (Z & 255)) & 255];
    return h % 12;
}

double fade(double t) {
    return t * t * t * (t * (t * 6 - 15) + 10);
}

namespace {

inline double lerp(double a, double b, double t) {
    return a + t * (b - a);
}

// One evaluation; `d` (optional) keeps every intermediate. The plain and the detailed noise
// are this one function, so they agree to the last bit.
template <bool kDetail>
inline double noise_impl(const Perlin& n, dvec3 p, NoiseDetail* d) {
    const dvec3 cell = glm::floor(p);
    const long long X = static_cast<long long>(cell.x), Y = static_cast<long long>(cell.y),
                    Z = static_cast<long long>(cell.z);
    const dvec3 f = p - cell;
    const double u = fade(f.x), v = fade(f.y), w = fade(f.z);
    const auto& G = perlin_gradients();
    double dots[8];
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c) {
                const int gi = gradient_index(n, X + a, Y + b, Z + c);
                const dvec3& g = G[gi];
                dots[4 * a + 2 * b + c] = g.x * (f.x - a) + g.y * (f.y - b) + g.z * (f.z - c);
                if constexpr (kDetail) d->gradient[4 * a + 2 * b + c] = gi;
            }
    const double z00 = lerp(dots[0], dots[1], w), z01 = lerp(dots[2], dots[3], w),
                 z10 = lerp(dots[4], dots[5], w), z11 = lerp(dots[6], dots[7], w);
    const double y0 = lerp(z00, z01, v), y1 = lerp(z10, z11, v);
    const double value = lerp(y0, y1, u);
    if constexpr (kDetail) {
        d->p = p;
        d->cell = {X, Y, Z};
        d->frac = f;
        d->fade = {u, v, w};
        for (int k = 0; k < 8; ++k) d->dot[k] = dots[k];
        d->along_z = {z00, z01, z10, z11};
        d->along_y = {y0, y1};
        d->value = value;
    }
    return value;
}

}  // namespace

double perlin_noise(const Perlin& n, dvec3 p) {
    return noise_impl<false>(n, p, nullptr);
}

NoiseDetail perlin_detail(const Perlin& n, dvec3 p) {
    NoiseDetail d;
    noise_impl<true>(n, p, &d);
    return d;
}

double turbulence(const Perlin& n, dvec3 p, int octaves) {
    double sum = 0;
    for (int k = 0; k < octaves; ++k)
        sum +=
            std::fabs(noise_impl<false>(n, std::ldexp(1.0, k) * p, nullptr)) / std::ldexp(1.0, k);
    return sum;
}

// ---- [solid textures] -----------------------------------------------------------------------

const char* solid_kind_id(SolidKind k) {
    switch (k) {
        case SolidKind::Checker:
            return "checker";
        case SolidKind::Stripes:
            return "stripes";
        case SolidKind::Wood:
            return "wood";
        case SolidKind::Marble:
            return "marble";
    }
    return "";
}

bool uses_noise(SolidKind k) {
    return k == SolidKind::Wood || k == SolidKind::Marble;
}

void validate_solid(const SolidTexture& t, const std::string& field) {
    for (int k = 0; k < 2; ++k)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(t.colors[k][c]) || t.colors[k][c] < 0 || t.colors[k][c] > 1e6)
                throw InputError(field + ".colors[" + std::to_string(k) + "]",
                                 "must be a colour with components in [0, 1e6] (got " +
                                     given(t.colors[k], 6) + ")");
    auto length = [&](double v, const char* key, const char* what) {
        if (!(v >= 1e-9 && v <= 1e12))
            throw InputError(field + "." + key, std::string("must be a length between 1e-9 and "
                                                            "1e12: ") +
                                                    what + " (got " + given(v) + ")");
    };
    switch (t.kind) {
        case SolidKind::Checker:
            length(t.size, "size", "the side of one cube");
            return;
        case SolidKind::Stripes:
        case SolidKind::Wood:
        case SolidKind::Marble:
            break;
    }
    length(t.period, "period", "the distance from one stripe or ring to the next");
    const double m = std::max({std::fabs(t.axis.x), std::fabs(t.axis.y), std::fabs(t.axis.z)});
    if (!(m >= 1e-150) || !std::isfinite(m))
        throw InputError(field + ".axis",
                         "must be a nonzero finite direction (got " + given(t.axis) + ")");
    if (!uses_noise(t.kind)) return;
    if (!(std::fabs(t.amplitude) <= 1e6))
        throw InputError(field + ".amplitude", "must be a number of magnitude at most 1e6 (got " +
                                                   given(t.amplitude) + ")");
    if (!(t.frequency > 1e-9 && t.frequency <= 1e6))
        throw InputError(field + ".frequency",
                         "must be between 1e-9 and 1e6 lattice cells per "
                         "unit (got " +
                             given(t.frequency) + ")");
    if (t.kind == SolidKind::Marble && (t.octaves < 1 || t.octaves > kMaxOctaves))
        throw InputError(field + ".octaves", "must be between 1 and " +
                                                 std::to_string(kMaxOctaves) + " (got " +
                                                 std::to_string(t.octaves) + ")");
}

SolidSample solid_sample(const SolidTexture& t, const Perlin& perlin, dvec3 p) {
    constexpr double kTwoPi = 2 * std::numbers::pi;
    SolidSample s;
    s.axis = unit(t.axis);
    switch (t.kind) {
        case SolidKind::Checker: {
            const dvec3 c = glm::floor(p / t.size);
            const double k = c.x + c.y + c.z;
            s.t = std::fmod(std::fabs(k), 2.0) == 1 ? 1 : 0;
            s.cell_known = true;
            s.cell = {static_cast<long long>(c.x), static_cast<long long>(c.y),
                      static_cast<long long>(c.z)};
            break;
        }
        case SolidKind::Stripes:
            s.t = 0.5 * (1 + std::sin(kTwoPi * glm::dot(p, s.axis) / t.period));
            break;
        case SolidKind::Wood: {
            const double r = glm::length(p - glm::dot(p, s.axis) * s.axis);
            s.noise = perlin_noise(perlin, t.frequency * p);
            const double rings = r / t.period + t.amplitude * s.noise;
            s.t = rings - std::floor(rings);
            break;
        }
        case SolidKind::Marble:
            s.noise = turbulence(perlin, t.frequency * p, t.octaves);
            s.t = 0.5 *
                  (1 + std::sin(kTwoPi * glm::dot(p, s.axis) / t.period + t.amplitude * s.noise));
            break;
    }
    if (uses_noise(t.kind)) {
        const dvec3 c = glm::floor(t.frequency * p);
        s.cell_known = true;
        s.cell = {static_cast<long long>(c.x), static_cast<long long>(c.y),
                  static_cast<long long>(c.z)};
    }
    s.color = (1 - s.t) * t.colors[0] + s.t * t.colors[1];
    return s;
}

}  // namespace cg
