#include "curves/bezier.hpp"

#include <cmath>

#include "core/format.hpp"
#include "core/step.hpp"

namespace cg::curves {

double binomial(int n, int i) {
    if (i < 0 || i > n) return 0;
    i = std::min(i, n - i);
    // C(n, j) = C(n, j − 1) · (n − j + 1) / j stays an integer at every j; in 64 bits the
    // product cannot overflow for n ≤ kMaxDegree.
    std::uint64_t c = 1;
    for (int j = 1; j <= i; ++j)
        c = c * static_cast<std::uint64_t>(n - j + 1) / static_cast<std::uint64_t>(j);
    return static_cast<double>(c);
}

glm::dvec3 bezier_point(std::span<const glm::dvec3> control_points, double t) {
    std::array<glm::dvec3, kMaxDegree + 1> p;
    const std::size_t count = std::min(control_points.size(), p.size());
    std::copy(control_points.begin(), control_points.begin() + static_cast<std::ptrdiff_t>(count),
              p.begin());
    for (std::size_t k = 1; k < count; ++k)
        for (std::size_t i = 0; i + k < count; ++i) p[i] = (1 - t) * p[i] + t * p[i + 1];
    return count ? p[0] : glm::dvec3(0);
}

glm::dvec3 bezier_derivative(std::span<const glm::dvec3> control_points, double t) {
    const std::size_t count = std::min<std::size_t>(control_points.size(), kMaxDegree + 1);
    if (count < 2) return glm::dvec3(0);
    std::array<glm::dvec3, kMaxDegree> d;
    for (std::size_t i = 0; i + 1 < count; ++i) d[i] = control_points[i + 1] - control_points[i];
    return static_cast<double>(count - 1) * bezier_point({d.data(), count - 1}, t);
}

std::vector<glm::dvec2> bezier_polyline(std::span<const glm::dvec3> control_points, double t0,
                                        double t1, int samples) {
    std::vector<glm::dvec2> out;
    out.reserve(static_cast<std::size_t>(samples) + 1);
    for (int j = 0; j <= samples; ++j) {
        const double t = j == samples ? t1 : t0 + (t1 - t0) * j / samples;
        out.push_back(xy(bezier_point(control_points, t)));
    }
    return out;
}

double coordinate_scale(std::span<const glm::dvec3> points) {
    double scale = 0;
    for (const glm::dvec3& p : points)
        scale = std::max({scale, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    return scale;
}

std::uint32_t shade(int k) {
    // Blue, purple, teal, brown, pink, slate, olive, crimson: far apart in hue and lightness.
    static constexpr std::uint32_t kShades[] = {0x3a6fc4ff, 0x8a4fc0ff, 0x0f8f8aff, 0x9a6a35ff,
                                                0xc9479bff, 0x55677bff, 0x7d8a1eff, 0xb0303eff};
    const int m = static_cast<int>(std::size(kShades));
    return kShades[((k - 1) % m + m) % m];
}

std::string subscript(int n) {
    static constexpr const char* kDigits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
    if (n < 0) return "₋" + subscript(-n);
    std::string s;
    for (char c : std::to_string(n)) s += kDigits[c - '0'];
    return s;
}

std::string superscript(int n) {
    static constexpr const char* kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    if (n < 0) return "⁻" + superscript(-n);
    std::string s;
    for (char c : std::to_string(n)) s += kDigits[c - '0'];
    return s;
}

std::string point_name(int i, int level, const char* letter) {
    return letter + subscript(i) + (level >= 0 ? superscript(level) : "");
}

void validate_points(std::span<const glm::dvec3> points, int dim, const std::string& field,
                     std::size_t min_count, std::size_t max_count) {
    if (dim != 2 && dim != 3)
        throw InputError(field,
                         "points must be 2D or 3D (got dimension " + std::to_string(dim) + ")");
    if (points.size() < min_count)
        throw InputError(field, "needs at least " + std::to_string(min_count) + " points (got " +
                                    std::to_string(points.size()) + ")");
    if (points.size() > max_count)
        throw InputError(field, "takes at most " + std::to_string(max_count) + " points (got " +
                                    std::to_string(points.size()) + ")");
    for (std::size_t i = 0; i < points.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = points[i][c];
            const std::string at = field + "[" + std::to_string(i) + "][" + std::to_string(c) + "]";
            if (c == 2 && dim == 2) {
                if (v != 0) throw InputError(at, "must be 0 for a 2D point (got " + given(v) + ")");
                continue;
            }
            if (!std::isfinite(v))
                throw InputError(at, "must be a finite number (got " + given(v) + ")");
            if (std::fabs(v) > kMaxCoordinate)
                throw InputError(at, "must be within ±1e100 (got " + given(v) + ")");
            // Below that, squared distances (arc lengths) underflow to zero.
            if (v != 0 && std::fabs(v) < 1e-100)
                throw InputError(at, "must be 0 or at least 1e-100 in size (got " + given(v) + ")");
        }
}

void validate_t(double t, bool extrapolate, const std::string& field) {
    if (!std::isfinite(t)) throw InputError(field, "must be a finite number (got " + given(t) + ")");
    if (!extrapolate && (t < 0 || t > 1))
        throw InputError(field,
                         "must lie in [0, 1] (got " + given(t) +
                             "); give \"extrapolate\": true to evaluate outside the segment");
    if (std::fabs(t) > kMaxAbsT)
        throw InputError(field,
                         "must be within ±1000 even when extrapolating (got " + given(t) + ")");
}

}  // namespace cg::curves
