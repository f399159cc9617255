// Independent references for the curve tests: the Bernstein form in long double, written from
// the formula (no de Casteljau, no shared code with the algorithms), and a few helpers.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <random>
#include <vector>

namespace cg::test {

struct Point3L {
    long double x = 0, y = 0, z = 0;
};

// C(n, i) by Pascal's triangle, in long double.
inline long double binomial_l(int n, int i) {
    std::vector<long double> row{1};
    for (int m = 1; m <= n; ++m) {
        std::vector<long double> next(static_cast<std::size_t>(m) + 1, 1);
        for (int j = 1; j < m; ++j)
            next[static_cast<std::size_t>(j)] =
                row[static_cast<std::size_t>(j) - 1] + row[static_cast<std::size_t>(j)];
        row = next;
    }
    return i < 0 || i > n ? 0 : row[static_cast<std::size_t>(i)];
}

// B_i^n(t) = C(n, i) (1 − t)^(n − i) t^i.
inline long double bernstein_l(int n, int i, long double t) {
    return binomial_l(n, i) * std::pow(1 - t, static_cast<long double>(n - i)) *
           std::pow(t, static_cast<long double>(i));
}

// Σ P_i B_i^n(t).
inline Point3L bezier_l(const std::vector<glm::dvec3>& p, long double t) {
    const int n = static_cast<int>(p.size()) - 1;
    Point3L r;
    for (int i = 0; i <= n; ++i) {
        const long double b = bernstein_l(n, i, t);
        r.x += b * p[static_cast<std::size_t>(i)].x;
        r.y += b * p[static_cast<std::size_t>(i)].y;
        r.z += b * p[static_cast<std::size_t>(i)].z;
    }
    return r;
}

// P'(t) = n Σ (P_{i+1} − P_i) B_i^{n−1}(t).
inline Point3L bezier_derivative_l(const std::vector<glm::dvec3>& p, long double t) {
    const int n = static_cast<int>(p.size()) - 1;
    Point3L r;
    for (int i = 0; i < n; ++i) {
        const long double b = n * bernstein_l(n - 1, i, t);
        r.x += b * ((long double)p[static_cast<std::size_t>(i) + 1].x -
                    p[static_cast<std::size_t>(i)].x);
        r.y += b * ((long double)p[static_cast<std::size_t>(i) + 1].y -
                    p[static_cast<std::size_t>(i)].y);
        r.z += b * ((long double)p[static_cast<std::size_t>(i) + 1].z -
                    p[static_cast<std::size_t>(i)].z);
    }
    return r;
}

inline long double distance(const Point3L& a, glm::dvec3 b) {
    const long double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}
inline long double distance(const Point3L& a, const Point3L& b) {
    const long double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

inline double scale_of(const std::vector<glm::dvec3>& p) {
    double s = 0;
    for (const auto& q : p) s = std::max({s, std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
    return std::max(s, 1e-300);
}

// Random control points: degree n, 2D (z = 0) or 3D, coordinates of size about `size`.
inline std::vector<glm::dvec3> random_points(std::mt19937_64& rng, int count, int dim,
                                             double size = 10) {
    std::uniform_real_distribution<double> u(-size, size);
    std::vector<glm::dvec3> p;
    for (int i = 0; i < count; ++i) p.push_back({u(rng), u(rng), dim == 3 ? u(rng) : 0.0});
    return p;
}

}  // namespace cg::test
