#include "hsr/complexity.hpp"

#include <cstdio>

#include "core/rng.hpp"
#include "hsr/painters.hpp"
#include "hsr/random_scene.hpp"
#include "hsr/warnock.hpp"
#include "hsr/z_buffer.hpp"

namespace cg::hsr {

std::vector<ComplexityRow> complexity(const std::vector<long long>& sides, const std::vector<int>& counts,
                                      int trials, std::uint64_t seed) {
    std::vector<ComplexityRow> rows;
    for (long long side : sides)
        for (int n : counts) {
            ComplexityRow row;
            row.n = n, row.side = side, row.p = side * side, row.trials = trials;
            for (int t = 0; t < trials; ++t) {
                Rng rng(seed + 7919 * static_cast<std::uint64_t>(t) + 104729 * static_cast<std::uint64_t>(n) +
                        static_cast<std::uint64_t>(side));
                const ScreenScene scene = random_scene(rng, side, side, n);
                const auto w = Warnock::render({scene});
                const auto z = ZBuffer::render({scene});
                row.areas += w.areas, row.classifications += w.classifications;
                row.compares += z.compares, row.writes += z.writes;
                row.p_c += z.compares;
                if (row.painter_pair_tests < 0) row.painter_pair_tests = 0;
                row.painter_pair_tests += Painters::render({scene}).pair_tests;
            }
            rows.push_back(row);
        }
    return rows;
}

namespace {

// Pair tests per trial over n²: flat when the count grows like n².
std::string per_n2(const ComplexityRow& r) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", double(r.painter_pair_tests) / (double(r.trials) * r.n * r.n));
    return buf;
}

}  // namespace

std::string complexity_table(const std::vector<ComplexityRow>& rows) {
    std::string out =
        "Hidden-surface removal on random scenes (sums over the trials of each row)\n"
        "  Warnock: areas examined, polygon-area classifications; worst case O(p·n)\n"
        "  z-buffer: depth compares = p_c (scan-converted pixels); O(p_c + n)\n"
        "  painter's: pair tests (pairs with overlapping z extents tested); Omega(n^2)\n\n";
    char line[256];
    std::snprintf(line, sizeof line, "%5s %8s %10s %10s %12s %10s %12s %10s %10s %10s\n", "n", "p", "p·n", "areas",
                  "classif.", "cl./(p·n)", "z compares", "cmp/(p_c+n)", "painter", "pt/n^2");
    out += line;
    for (const auto& r : rows) {
        const double pn = double(r.p) * r.n;
        std::snprintf(line, sizeof line, "%5d %8lld %10.0f %10lld %12lld %10.3f %12lld %10.3f %10s %10s\n", r.n, r.p, pn,
                      r.areas, r.classifications, pn > 0 ? r.classifications / pn : 0.0, r.compares,
                      double(r.compares) / double(r.p_c + r.n > 0 ? r.p_c + r.n : 1),
                      r.painter_pair_tests < 0 ? "-" : std::to_string(r.painter_pair_tests).c_str(),
                      r.painter_pair_tests < 0 || r.n == 0 ? "-" : per_n2(r).c_str());
        out += line;
    }
    return out;
}

}  // namespace cg::hsr
