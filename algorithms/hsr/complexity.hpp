// The cost of the hidden-surface algorithms on growing random scenes, as a table
// (`cgsandbox complexity hsr`): Warnock's areas and polygon-area classifications against p·n,
// the z-buffer's depth compares against p_c + n, the painter's pair tests against n².
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cg::hsr {

struct ComplexityRow {
    int n = 0;                    // polygons
    long long side = 0, p = 0;    // screen side and pixels
    long long p_c = 0;            // pixels scan-converted (with multiplicity)
    long long areas = 0, classifications = 0;  // Warnock
    long long compares = 0, writes = 0;        // z-buffer
    // Painter's algorithm: pairs with overlapping z extents tested (-1: not measured).
    long long painter_pair_tests = -1;
    int trials = 1;               // scenes summed in this row
};

// One row per (side, n), each the sum over `trials` random scenes seeded from `seed`.
std::vector<ComplexityRow> complexity(const std::vector<long long>& sides, const std::vector<int>& counts,
                                      int trials, std::uint64_t seed);
std::string complexity_table(const std::vector<ComplexityRow>& rows);

}  // namespace cg::hsr
