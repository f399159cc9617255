// The orientation test, exactly: on which side of the directed line a→b does p lie?
//
//     orient2d(a, b, p) = sign of (b − a) × (p − a) = sign of (bx − ax)(py − ay) − (by − ay)(px −
//     ax)
//
// +1: p is to the left of a→b (counter-clockwise turn), −1: to the right, 0: on the line.
// Rasterisation decides "is this pixel centre inside?" with this test, and a centre exactly on
// an edge is common (integer vertices, centres at halves), so it must never be a rounding
// accident. Shewchuk's scheme: the plain double formula, trusted when it is farther from 0 than
// its rounding error bound (almost always); otherwise the determinant is expanded into six
// products, each split exactly into two doubles with fma, and the sign of their exact sum is
// found by adding them as a non-overlapping expansion.
//
// Exact for all finite inputs whose products neither overflow nor underflow: |coordinate| ≤
// 1e150 and every non-zero coordinate at least 1e-100 in magnitude is ample.
#pragma once

#include <cmath>

#include <glm/vec2.hpp>

namespace cg {

namespace orient2d_detail {

// s + e = a + b exactly (Knuth's Two-Sum).
inline void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double b_virtual = s - a, a_virtual = s - b_virtual;
    e = (a - a_virtual) + (b - b_virtual);
}

// The sign of x[0] + ... + x[N−1], exactly. The running sum is kept as non-overlapping
// components of increasing magnitude (Shewchuk's grow-expansion, zeros dropped), so its sign is
// the sign of the last component.
template <int N>
int sign_of_sum(const double (&x)[N]) {
    double e[N];
    int n = 0;
    for (double q : x) {
        int m = 0;
        for (int i = 0; i < n; ++i) {
            double s, err;
            two_sum(q, e[i], s, err);
            if (err != 0) e[m++] = err;
            q = s;
        }
        if (q != 0) e[m++] = q;
        n = m;
    }
    return n == 0 ? 0 : (e[n - 1] > 0 ? 1 : -1);
}

[[gnu::noinline]] inline int orient2d_exact(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
    // (bx − ax)(py − ay) − (by − ay)(px − ax)
    //   = bx·py − bx·ay − ax·py − by·px + by·ax + ay·px
    const double f[6][2] = {{b.x, p.y}, {-b.x, a.y}, {-a.x, p.y},
                            {-b.y, p.x}, {b.y, a.x},  {a.y, p.x}};
    double terms[12];
    for (int k = 0; k < 6; ++k) {
        const double hi = f[k][0] * f[k][1];
        terms[2 * k] = hi;
        terms[2 * k + 1] = std::fma(f[k][0], f[k][1], -hi);  // the product's rounding error
    }
    return sign_of_sum(terms);
}

}  // namespace orient2d_detail

inline int orient2d(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
    const double left = (b.x - a.x) * (p.y - a.y);
    const double right = (b.y - a.y) * (p.x - a.x);
    const double det = left - right;
    // When the two products have opposite signs (or one is 0) no cancellation can flip the sign.
    if ((left > 0 && right <= 0) || (left < 0 && right >= 0) || left == 0)
        return (det > 0) - (det < 0);
    // Shewchuk's ccwerrboundA = (3 + 16ε)ε, ε = 2^−53.
    constexpr double kErrorBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
    const double bound = kErrorBound * (std::fabs(left) + std::fabs(right));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return orient2d_detail::orient2d_exact(a, b, p);
}

}  // namespace cg
