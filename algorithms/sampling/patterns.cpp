#include "sampling/patterns.hpp"

#include <algorithm>
#include <cmath>

namespace cg::sampling {

const char* pattern_id(Pattern p) {
    switch (p) {
        case Pattern::Regular:
            return "regular";
        case Pattern::Random:
            return "random";
        case Pattern::Jittered:
            return "jittered";
        case Pattern::Poisson:
            return "poisson";
    }
    return "regular";
}

const char* filter_id(Filter f) {
    switch (f) {
        case Filter::Box:
            return "box";
        case Filter::Tent:
            return "tent";
        case Filter::Gaussian:
            return "gaussian";
    }
    return "box";
}

bool parse_pattern(const std::string& s, Pattern& out) {
    for (Pattern p : {Pattern::Regular, Pattern::Random, Pattern::Jittered, Pattern::Poisson})
        if (s == pattern_id(p)) {
            out = p;
            return true;
        }
    return false;
}

bool parse_filter(const std::string& s, Filter& out) {
    for (Filter f : {Filter::Box, Filter::Tent, Filter::Gaussian})
        if (s == filter_id(f)) {
            out = f;
            return true;
        }
    return false;
}

bool is_grid(Pattern p) {
    return p == Pattern::Regular || p == Pattern::Jittered;
}

int grid_side(long long count) {
    if (count < 1) return 0;
    long long n = std::llround(std::sqrt(double(count)));
    while (n * n > count) --n;
    while ((n + 1) * (n + 1) <= count) ++n;
    return n * n == count ? static_cast<int>(n) : 0;
}

double default_radius(int count) {
    return 0.7 / std::sqrt(double(count < 1 ? 1 : count));
}

std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
    // SplitMix64's finaliser over the three words, each step scrambling the sum so far.
    auto mix = [](std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    };
    std::uint64_t h = mix(seed + 0x9e3779b97f4a7c15ull);
    h = mix(h ^ (a + 0x632be59bd9b4e019ull));
    return mix(h ^ (b + 0x8cb92ba72f3d8dd7ull));
}

std::vector<PatternPoint> generate(Pattern pattern, int count, std::uint64_t seed, double radius) {
    std::vector<PatternPoint> pts;
    if (count < 1) return pts;
    pts.reserve(static_cast<std::size_t>(count));
    Rng rng(seed);
    auto uniform2 = [&rng] {
        const double x = rng.uniform(0, 1);  // x first, then y: one draw per statement
        const double y = rng.uniform(0, 1);
        return glm::dvec2(x, y);
    };
    switch (pattern) {
        case Pattern::Regular:
        case Pattern::Jittered: {
            const int n = grid_side(count);
            for (int b = 0; b < n; ++b)
                for (int a = 0; a < n; ++a) {
                    PatternPoint q;
                    q.cell_a = a, q.cell_b = b;
                    if (pattern == Pattern::Jittered) q.xi = uniform2();
                    q.p = (glm::dvec2(a, b) + q.xi) / double(n);
                    pts.push_back(q);
                }
            break;
        }
        case Pattern::Random:
            for (int k = 0; k < count; ++k) {
                PatternPoint q;
                q.xi = uniform2();
                q.p = q.xi;
                pts.push_back(q);
            }
            break;
        case Pattern::Poisson: {
            const double r2 = radius * radius;
            long long budget = static_cast<long long>(kMaxDartsPerSample) * count;
            int darts = 0;
            while (int(pts.size()) < count && budget-- > 0) {
                const glm::dvec2 c = uniform2();
                ++darts;
                bool far = true;
                for (const PatternPoint& q : pts) {
                    const glm::dvec2 d = q.p - c;
                    if (d.x * d.x + d.y * d.y < r2) {
                        far = false;
                        break;
                    }
                }
                if (!far) continue;
                PatternPoint q;
                q.p = q.xi = c;
                q.darts = darts;
                darts = 0;
                pts.push_back(q);
            }
            break;
        }
    }
    return pts;
}

double weight(Filter f, glm::dvec2 d) {
    switch (f) {
        case Filter::Box:
            return 1;
        case Filter::Tent:
            return std::max(0.0, 1 - std::fabs(d.x)) * std::max(0.0, 1 - std::fabs(d.y));
        case Filter::Gaussian:
            return std::exp(-(d.x * d.x + d.y * d.y) / (2 * kGaussianSigma * kGaussianSigma));
    }
    return 1;
}

double pixel_weight_integral(Filter f) {
    switch (f) {
        case Filter::Box:
            return 1;
        case Filter::Tent:
            return 0.75 * 0.75;  // (∫_{−½}^{½} (1 − |x|) dx)²
        case Filter::Gaussian: {
            const double one = kGaussianSigma * std::sqrt(2 * M_PI) *
                               std::erf(0.5 / (kGaussianSigma * std::sqrt(2.0)));
            return one * one;
        }
    }
    return 1;
}

}  // namespace cg::sampling
