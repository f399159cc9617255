// Independent references for the texture algorithms, in long double and from the definitions:
// the parametrisations' (u, v) from atan2/acos of the model point, texel lookups computed from
// the texel centres, mip levels as brute-force box averages of level 0, Perlin noise from its
// definition (the permutation is the input; hash, gradients, fade and interpolation redone),
// and the normal of a displaced surface P + B n̂ by finite differences.
#pragma once

#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "rays/noise.hpp"
#include "rays/texture.hpp"
#include "rays/uv_map.hpp"

namespace cg::test {

using LD = long double;
constexpr LD kPiL = 3.141592653589793238462643383279502884L;

struct LVec {
    LD x = 0, y = 0, z = 0;
};
inline LVec lv(glm::dvec3 v) {
    return {v.x, v.y, v.z};
}
inline LVec operator+(LVec a, LVec b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline LVec operator-(LVec a, LVec b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline LVec operator*(LD s, LVec a) {
    return {s * a.x, s * a.y, s * a.z};
}
inline LD dot(LVec a, LVec b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline LVec cross(LVec a, LVec b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline LD len(LVec a) {
    return std::sqrt(dot(a, a));
}
inline LVec normalized(LVec a) {
    return (1 / len(a)) * a;
}

// ---- texel lookups ----------------------------------------------------------------------------

inline LD wrap_ref(LD u, TexWrap w) {
    if (w == TexWrap::Clamp) return u < 0 ? 0 : (u > 1 ? 1 : u);
    return u - std::floor(u);
}

inline long long index_ref(long long i, int n, TexWrap w) {
    if (w == TexWrap::Clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
    return ((i % n) + n) % n;
}

struct LColor {
    LD r = 0, g = 0, b = 0;
};

inline LColor texel_ref(const TextureImage& im, long long i, long long j) {
    const glm::dvec3 c = im.at(static_cast<int>(i), static_cast<int>(j));
    return {c.x, c.y, c.z};
}

// Bilinear from the definition: the four texels whose centres (i + ½)/W surround (s, t).
inline LColor bilinear_ref(const TextureImage& im, LD s, LD t, TexWrap w) {
    const LD x = s * im.width - 0.5L, y = t * im.height - 0.5L;
    const LD i0 = std::floor(x), j0 = std::floor(y);
    const LD f = x - i0, g = y - j0;
    LColor out;
    for (int b = 0; b < 2; ++b)
        for (int a = 0; a < 2; ++a) {
            const LD wt = (a ? f : 1 - f) * (b ? g : 1 - g);
            const LColor c = texel_ref(im, index_ref(static_cast<long long>(i0) + a, im.width, w),
                                       index_ref(static_cast<long long>(j0) + b, im.height, w));
            out.r += wt * c.r, out.g += wt * c.g, out.b += wt * c.b;
        }
    return out;
}

// Mip level k, texel (i, j): the plain average of level 0 over its block.
inline LColor box_average_ref(const TextureImage& im, int k, int i, int j) {
    const int bw = std::min(im.width, 1 << k), bh = std::min(im.height, 1 << k);
    LColor s;
    for (int y = j * bh; y < (j + 1) * bh; ++y)
        for (int x = i * bw; x < (i + 1) * bw; ++x) {
            const LColor c = texel_ref(im, x, y);
            s.r += c.r, s.g += c.g, s.b += c.b;
        }
    const LD n = LD(bw) * bh;
    return {s.r / n, s.g / n, s.b / n};
}

// ---- parametrisations ---------------------------------------------------------------------

// (u, v) of a model-space point of a quadric, from atan2/acos (spheres, ellipsoids) or the
// height (the others), in long double.
inline void quadric_uv_ref(const Quadric& q, LVec m, LD& u, LD& v) {
    LD sx = 1, sy = 1, sz = 1;
    switch (q.kind) {
        case QuadricKind::Sphere:
            sx = sy = sz = q.r;
            break;
        case QuadricKind::Ellipsoid:
        case QuadricKind::Hyperboloid:
            sx = q.a, sy = q.b, sz = q.c;
            break;
        default:
            sx = q.p, sy = q.q;
            break;
    }
    u = 0.5L + std::atan2(m.y / sy, m.x / sx) / (2 * kPiL);
    if (q.kind == QuadricKind::Sphere || q.kind == QuadricKind::Ellipsoid) {
        const LVec s{m.x / sx, m.y / sy, m.z / sz};
        v = 1 - std::acos(std::max<LD>(-1, std::min<LD>(1, s.z / len(s)))) / kPiL;
    } else if (std::isfinite(q.zmin) && std::isfinite(q.zmax)) {
        v = (m.z - q.zmin) / (LD(q.zmax) - q.zmin);
    } else {
        v = m.z;
    }
}

// ---- Perlin noise -------------------------------------------------------------------------

inline LD fade_ref(LD t) {
    return 6 * std::pow(t, 5) - 15 * std::pow(t, 4) + 10 * std::pow(t, 3);
}

inline LD noise_ref(const Perlin& n, LVec p) {
    static const int G[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                 {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                 {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};
    const LD X = std::floor(p.x), Y = std::floor(p.y), Z = std::floor(p.z);
    const LD x = p.x - X, y = p.y - Y, z = p.z - Z;
    auto wrap = [](LD c) {
        return static_cast<int>(((static_cast<long long>(c) % 256) + 256) % 256);
    };
    LD total = 0;
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c) {
                const int h =
                    n.perm[(n.perm[(n.perm[wrap(X + a)] + wrap(Y + b)) % 256] + wrap(Z + c)) % 256];
                const int* g = G[h % 12];
                const LD ramp = g[0] * (x - a) + g[1] * (y - b) + g[2] * (z - c);
                // The trilinear weight of corner (a, b, c): a product of fades.
                const LD w = (a ? fade_ref(x) : 1 - fade_ref(x)) *
                             (b ? fade_ref(y) : 1 - fade_ref(y)) *
                             (c ? fade_ref(z) : 1 - fade_ref(z));
                total += w * ramp;
            }
    return total;
}

// ---- displaced surfaces -------------------------------------------------------------------

// The unit normal of P(u, v) + B(u, v) n̂(u, v) by central differences of step d (long double
// arithmetic around double surface points), oriented like `outward`.
inline LVec displaced_normal_ref(const std::function<LVec(LD, LD)>& point,
                                 const std::function<LVec(LD, LD)>& unit_normal,
                                 const std::function<LD(LD, LD)>& height, LD u, LD v, LD d,
                                 LVec outward) {
    auto Pd = [&](LD a, LD b) { return point(a, b) + height(a, b) * unit_normal(a, b); };
    const LVec Pu = (1 / (2 * d)) * (Pd(u + d, v) - Pd(u - d, v));
    const LVec Pv = (1 / (2 * d)) * (Pd(u, v + d) - Pd(u, v - d));
    LVec n = normalized(cross(Pu, Pv));
    if (dot(n, outward) < 0) n = -1 * n;
    return n;
}

}  // namespace cg::test
