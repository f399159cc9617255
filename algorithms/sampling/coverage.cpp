#include "sampling/coverage.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cg::sampling {

namespace {

using glm::dvec2;

double cross(dvec2 a, dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

// One Sutherland-Hodgman pass: keep the side where side(p) ≥ 0 (side is affine in p).
template <class Side>
std::vector<dvec2> clip_pass(const std::vector<dvec2>& in, Side side) {
    std::vector<dvec2> out;
    if (in.empty()) return out;
    out.reserve(in.size() + 4);
    dvec2 s = in.back();
    double ss = side(s);
    for (const dvec2& p : in) {
        const double sp = side(p);
        if (sp >= 0) {
            if (ss < 0) out.push_back(s + (p - s) * (ss / (ss - sp)));
            out.push_back(p);
        } else if (ss >= 0) {
            out.push_back(s + (p - s) * (ss / (ss - sp)));
        }
        s = p, ss = sp;
    }
    return out;
}

// Gauss-Legendre nodes and weights on [0, 1], 16 points, by Newton's method on P_16.
struct Legendre16 {
    std::array<double, 16> x{}, w{};
    Legendre16() {
        constexpr int n = 16;
        for (int k = 0; k < n; ++k) {
            double t = std::cos(M_PI * (k + 0.75) / (n + 0.5));
            double dp = 1;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = t;
                for (int m = 2; m <= n; ++m) {
                    const double p2 = ((2 * m - 1) * t * p1 - (m - 1) * p0) / m;
                    p0 = p1, p1 = p2;
                }
                dp = n * (t * p1 - p0) / (t * t - 1);
                const double dt = p1 / dp;
                t -= dt;
                if (std::fabs(dt) < 1e-17) break;
            }
            x[k] = 0.5 * (1 - t);
            w[k] = 1 / ((1 - t * t) * dp * dp);  // 2/((1−t²)P'²) halved for [0, 1]
        }
    }
};

const Legendre16& legendre() {
    static const Legendre16 g;
    return g;
}

// W(x) = ∫_0^x w(s) ds and w(y) for the separable filters.
double antiderivative(Filter f, double x) {
    switch (f) {
        case Filter::Box:
            return x;
        case Filter::Tent: {
            const double a = std::min(std::fabs(x), 1.0);
            return std::copysign(a - a * a / 2, x);
        }
        case Filter::Gaussian:
            return kGaussianSigma * std::sqrt(M_PI / 2) *
                   std::erf(x / (kGaussianSigma * std::sqrt(2.0)));
    }
    return x;
}

double profile(Filter f, double y) {
    switch (f) {
        case Filter::Box:
            return 1;
        case Filter::Tent:
            return std::max(0.0, 1 - std::fabs(y));
        case Filter::Gaussian:
            return std::exp(-y * y / (2 * kGaussianSigma * kGaussianSigma));
    }
    return 1;
}

}  // namespace

dvec2 edge_direction(double angle_deg) {
    double a = std::fmod(angle_deg, 360.0);
    if (a < 0) a += 360;
    if (a == 0) return {1, 0};
    if (a == 90) return {0, 1};
    if (a == 180) return {-1, 0};
    if (a == 270) return {0, -1};
    const double h = std::sqrt(0.5);  // the diagonals exactly: cos 45° = sin 45°
    if (a == 45) return {h, h};
    if (a == 135) return {-h, h};
    if (a == 225) return {-h, -h};
    if (a == 315) return {h, -h};
    const double r = a * M_PI / 180;
    return {std::cos(r), std::sin(r)};
}

double region_value(const Region& r, dvec2 p) {
    if (r.kind == RegionKind::Edge) return edge_value(r.point, edge_direction(r.angle_deg), p);
    bool in = false;
    const std::size_t n = r.points.size();
    for (std::size_t k = 0, prev = n - 1; k < n; prev = k++) {
        const dvec2 a = r.points[prev], b = r.points[k];
        if ((a.y > p.y) != (b.y > p.y)) {
            const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (p.x < x) in = !in;
        }
    }
    return in ? 1.0 : 0.0;
}

double signed_area(const std::vector<dvec2>& poly) {
    double a = 0;
    for (std::size_t k = 0, prev = poly.size() - 1; k < poly.size(); prev = k++)
        a += cross(poly[prev], poly[k]);
    return poly.empty() ? 0 : a / 2;
}

std::vector<dvec2> covered_polygon(const Region& r, int i, int j) {
    const double x0 = i, y0 = j, x1 = x0 + 1, y1 = y0 + 1;
    std::vector<dvec2> square = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    if (r.kind == RegionKind::Edge) {
        const dvec2 d = edge_direction(r.angle_deg), p0 = r.point;
        std::vector<dvec2> cut = clip_pass(square, [&](dvec2 p) { return cross(d, p - p0); });
        if (signed_area(cut) == 0) cut.clear();  // the edge along a side, facing away
        return cut;
    }
    std::vector<dvec2> poly = r.points;
    if (signed_area(poly) < 0) std::reverse(poly.begin(), poly.end());
    poly = clip_pass(poly, [&](dvec2 p) { return p.x - x0; });
    poly = clip_pass(poly, [&](dvec2 p) { return x1 - p.x; });
    poly = clip_pass(poly, [&](dvec2 p) { return p.y - y0; });
    poly = clip_pass(poly, [&](dvec2 p) { return y1 - p.y; });
    if (std::fabs(signed_area(poly)) == 0) poly.clear();
    return poly;
}

double weighted_area(Filter f, const std::vector<dvec2>& poly, dvec2 centre) {
    if (poly.size() < 3) return 0;
    if (f == Filter::Box) return signed_area(poly);
    const Legendre16& g = legendre();
    double sum = 0;
    for (std::size_t k = 0, prev = poly.size() - 1; k < poly.size(); prev = k++) {
        const dvec2 a = poly[prev] - centre, b = poly[k] - centre;
        const double dy = b.y - a.y;
        if (dy == 0) continue;
        // Cut the edge where it crosses x = 0 or y = 0 (the tent's kinks).
        std::array<double, 4> cuts = {0, 1, 1, 1};
        int m = 1;
        if ((a.x < 0) != (b.x < 0) && a.x != b.x) cuts[m++] = a.x / (a.x - b.x);
        if ((a.y < 0) != (b.y < 0)) cuts[m++] = a.y / (a.y - b.y);
        cuts[m++] = 1;
        std::sort(cuts.begin(), cuts.begin() + m);
        for (int c = 0; c + 1 < m; ++c) {
            const double s0 = cuts[c], s1 = cuts[c + 1];
            if (s1 <= s0) continue;
            double piece = 0;
            for (int q = 0; q < 16; ++q) {
                const double s = s0 + (s1 - s0) * g.x[q];
                const dvec2 p = a + (b - a) * s;
                piece += g.w[q] * antiderivative(f, p.x) * profile(f, p.y);
            }
            sum += piece * (s1 - s0) * dy;
        }
    }
    return sum;
}

double exact_coverage(const Region& r, Filter f, int i, int j) {
    const std::vector<dvec2> covered = covered_polygon(r, i, j);
    const double v = weighted_area(f, covered, {i + 0.5, j + 0.5}) / pixel_weight_integral(f);
    return std::clamp(v, 0.0, 1.0);
}

}  // namespace cg::sampling
