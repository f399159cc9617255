// An independent ray-quadric intersection in long double, written another way: the surface as
// a symmetric 4×4 matrix Q (F(X) = Xᵀ Q X for X = (x, y, z, 1)), carried to the world as
// Q_w = M⁻ᵀ Q M⁻¹ with M⁻¹ from Gauss-Jordan elimination, and the quadratic's coefficients read
// off Q_w directly in world space: a = dᵀQ_w d, b = 2 dᵀQ_w E, c = EᵀQ_w E (d with w = 0).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "rays/quadric.hpp"

namespace cg::test {

using LMat = std::array<std::array<long double, 4>, 4>;  // [row][col]
using LVec = std::array<long double, 4>;

inline LMat lmat(const glm::dmat4& m) {  // glm is m[col][row]
    LMat r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = m[j][i];
    return r;
}

// Gauss-Jordan with partial pivoting.
inline LMat inverse(LMat a) {
    LMat inv{};
    for (int i = 0; i < 4; ++i) inv[i][i] = 1;
    for (int c = 0; c < 4; ++c) {
        int p = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
        std::swap(a[c], a[p]);
        std::swap(inv[c], inv[p]);
        const long double d = a[c][c];
        for (int j = 0; j < 4; ++j) a[c][j] /= d, inv[c][j] /= d;
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            const long double f = a[r][c];
            for (int j = 0; j < 4; ++j) a[r][j] -= f * a[c][j], inv[r][j] -= f * inv[c][j];
        }
    }
    return inv;
}

inline LMat mul(const LMat& a, const LMat& b) {
    LMat r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

inline LMat transpose(const LMat& a) {
    LMat r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = a[j][i];
    return r;
}

inline LVec mul(const LMat& a, const LVec& v) {
    LVec r{};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) r[i] += a[i][k] * v[k];
    return r;
}

inline long double dot(const LVec& a, const LVec& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

// The model-space matrix of F, written from the equations (not from cg::coefficients).
inline LMat model_matrix(const Quadric& q) {
    LMat m{};
    auto i2 = [](long double v) { return 1 / (v * v); };
    switch (q.kind) {
        case QuadricKind::Sphere:
            m[0][0] = m[1][1] = m[2][2] = 1;
            m[3][3] = -static_cast<long double>(q.r) * q.r;
            break;
        case QuadricKind::Ellipsoid:
            m[0][0] = i2(q.a), m[1][1] = i2(q.b), m[2][2] = i2(q.c), m[3][3] = -1;
            break;
        case QuadricKind::Paraboloid:  // x²/p² + y²/q² − z: the −z split over two entries
            m[0][0] = i2(q.p), m[1][1] = i2(q.q), m[2][3] = m[3][2] = -0.5L;
            break;
        case QuadricKind::Hyperboloid:
            m[0][0] = i2(q.a), m[1][1] = i2(q.b), m[2][2] = -i2(q.c), m[3][3] = -1;
            break;
        case QuadricKind::Cone:
            m[0][0] = i2(q.p), m[1][1] = i2(q.q), m[2][2] = -i2(q.r);
            break;
        case QuadricKind::Cylinder:
            m[0][0] = i2(q.p), m[1][1] = i2(q.q), m[3][3] = -1;
            break;
    }
    return m;
}

struct LongHit {
    int count = 0;
    std::array<long double, 2> roots{0, 0};
    long double a = 0, b = 0, c = 0;
    long double disc_rel = 0;  // Δ / (b² + |4ac|): how far from tangent
    bool hit = false;
    long double t = 0;
    std::array<long double, 3> point{0, 0, 0}, normal{0, 0, 0};
    long double residual = 0;  // |F(point)| relative to the size of its terms
};

inline LongHit reference_intersect(const Quadric& q, glm::dvec3 o, glm::dvec3 d,
                                   long double t_min = kRayEpsilon) {
    const LMat M = lmat(q.world_from_model), Minv = inverse(M);
    const LMat Qm = model_matrix(q);
    const LMat Qw = mul(transpose(Minv), mul(Qm, Minv));
    const LVec E{o.x, o.y, o.z, 1}, D{d.x, d.y, d.z, 0};
    const long double a = dot(D, mul(Qw, D)), b = 2 * dot(D, mul(Qw, E)), c = dot(E, mul(Qw, E));
    LongHit h;
    h.a = a, h.b = b, h.c = c;
    if (a == 0) {  // only the exact case: random rays never land here
        if (b != 0) h.count = 1, h.roots[0] = -c / b;
    } else {
        const long double disc = b * b - 4 * a * c;
        h.disc_rel = disc / (b * b + std::fabs(4 * a * c));
        if (disc == 0) {
            h.count = 1, h.roots[0] = -b / (2 * a);
        } else if (disc > 0) {
            const long double s = std::sqrt(disc);
            const long double qq = -0.5L * (b + (b < 0 ? -s : s));
            h.count = 2;
            h.roots = {qq / a, c / qq};
            if (h.roots[0] > h.roots[1]) std::swap(h.roots[0], h.roots[1]);
        }
    }
    for (int i = 0; i < h.count; ++i) {
        const long double t = h.roots[i];
        if (!(t > t_min)) continue;
        const LVec P{o.x + t * d.x, o.y + t * d.y, o.z + t * d.z, 1};
        const LVec Pm = mul(Minv, P);
        if (Pm[2] < q.zmin || Pm[2] > q.zmax) continue;
        h.hit = true;
        h.t = t;
        h.point = {P[0], P[1], P[2]};
        // ∇(XᵀQ_w X) = 2 Q_w X: its first three components are the world gradient.
        const LVec g = mul(Qw, P);
        const long double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (len > 0) h.normal = {g[0] / len, g[1] / len, g[2] / len};
        // F at the point, relative to the size of its terms (in model space).
        long double size = 0;
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) size += std::fabs(Pm[r] * Qm[r][k] * Pm[k]);
        h.residual = std::fabs(dot(Pm, mul(Qm, Pm))) / std::max<long double>(size, 1e-300L);
        break;
    }
    return h;
}

// |F| at a world point, relative to the size of F's terms there (long double, via M⁻¹).
inline long double relative_residual(const Quadric& q, glm::dvec3 p) {
    const LMat Minv = inverse(lmat(q.world_from_model)), Qm = model_matrix(q);
    const LVec Pm = mul(Minv, LVec{p.x, p.y, p.z, 1});
    long double size = 0;
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) size += std::fabs(Pm[r] * Qm[r][k] * Pm[k]);
    return std::fabs(dot(Pm, mul(Qm, Pm))) / std::max<long double>(size, 1e-300L);
}

}  // namespace cg::test
