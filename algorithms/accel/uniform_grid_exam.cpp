// Uniform-grid exam problems: "which cells does the ray visit in this 4 × 4 grid?" A 4 × 4 × 1
// grid of unit cells over [0, 4] × [0, 4] × [0, 1], two to four spheres of radius 0.3 to 0.5
// centred in cells (and sometimes a box over two cells), all at mid-depth z = 0.5, and a ray in
// the plane z = 0.5 (d_z = 0) whose direction components are 0, ±0.5, ±1 or ±2 and whose
// origin has quarter coordinates — outside the grid, inside it, or missing it. A ray through an
// exact lattice corner, along a cell plane or from a cell plane inside the grid is drawn again:
// which cell comes next there is a tie rule, not a skill.
#include <cmath>

#include "accel/uniform_grid.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

double grid_exam_component(Rng& rng) {
    static constexpr double kSteps[] = {0.5, 1, 2, 1, 0.5};
    const double d = kSteps[rng.integer(0, 4)];
    return rng.chance(0.5) ? d : -d;
}

// Whether the ray meets an x plane and a y plane of the lattice at the same t inside the grid
// (a corner), for t ≥ 0.
// Also a convention rather than a skill: a ray running along a cell plane (d_i = 0, E_i whole),
// or starting on one inside the grid.
bool grid_exam_tie(const UniformGrid::Input& in) {
    const glm::dvec3 E = in.origin, d = in.direction;
    const bool inside = E.x >= 0 && E.x <= 4 && E.y >= 0 && E.y <= 4;
    for (int a = 0; a < 2; ++a)
        if ((d[a] == 0 || inside) && E[a] == std::floor(E[a])) return true;
    if (d.x == 0 || d.y == 0) return false;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) {
            const double tx = (i - E.x) / d.x, ty = (j - E.y) / d.y;
            if (tx == ty && tx >= 0) return true;
        }
    return false;
}

}  // namespace

UniformGrid::Input UniformGrid::exam_input(Rng& rng) {
    for (int attempt = 0;; ++attempt) {
        Input in;
        in.cells = {4, 4, 1};
        in.has_bounds = true;
        in.bounds.min = {0, 0, 0};
        in.bounds.max = {4, 4, 1};
        const int count = static_cast<int>(rng.integer(2, 4));
        for (int k = 0; k < count; ++k) {
            Primitive p;
            const double cx = static_cast<double>(rng.integer(0, 3)) + 0.5;
            const double cy = static_cast<double>(rng.integer(0, 3)) + 0.5;
            if (k == count - 1 && rng.chance(0.3)) {  // a box over two cells
                p.kind = PrimitiveKind::Box;
                const bool wide = rng.chance(0.5) && cx < 3;
                p.a = {cx - 0.25, cy - 0.25, 0.25};
                p.b = {cx + (wide ? 1.25 : 0.25), cy + (wide ? 0.25 : 0.25), 0.75};
            } else {
                p.kind = PrimitiveKind::Sphere;
                p.a = {cx, cy, 0.5};
                p.radius = 0.3 + 0.1 * static_cast<double>(rng.integer(0, 2));
            }
            in.primitives.push_back(p);
        }
        in.direction = {grid_exam_component(rng), grid_exam_component(rng), 0};
        if (rng.chance(0.15)) in.direction[rng.integer(0, 1)] = 0;  // along a row or a column
        auto quarter = [&](long long lo, long long hi) {
            return 0.25 * static_cast<double>(rng.integer(4 * lo, 4 * hi));
        };
        if (rng.chance(0.08)) {  // above the grid, moving away from it: a miss
            in.origin = {-1, 0.25 * static_cast<double>(rng.integer(17, 20)), 0.5};
            in.direction = {std::fabs(in.direction.x) + 0.5, std::fabs(in.direction.y), 0};
        } else if (rng.chance(0.25)) {  // from inside the grid
            in.origin = {quarter(0, 4), quarter(0, 4), 0.5};
        } else {  // from outside: two to three steps back from a point of the grid
            const glm::dvec3 target{quarter(0, 4), quarter(0, 4), 0.5};
            in.origin = target - static_cast<double>(rng.integer(2, 3)) * in.direction;
            if (in.origin.x >= 0 && in.origin.x <= 4 && in.origin.y >= 0 && in.origin.y <= 4)
                in.origin -= in.direction;
        }
        if (!grid_exam_tie(in) || attempt > 50) return in;
    }
}

std::string UniformGrid::question(const Input& in) {
    std::string prims;
    for (std::size_t i = 0; i < in.primitives.size(); ++i)
        prims += (i ? "; " : "") + std::to_string(i) + ": " + describe(in.primitives[i]);
    return "A uniform grid of " + std::to_string(in.cells[0]) + " × " +
           std::to_string(in.cells[1]) + " × " + std::to_string(in.cells[2]) +
           " cells covers the box " + num(in.bounds.min) + "–" + num(in.bounds.max) +
           " (cell [i, j, k] is [i, i+1] × [j, j+1] × [k, k+1] here). It holds " + prims +
           ". Walk the ray P(t) = E + t d, t ≥ 0, with E = " + num(in.origin) +
           " and d = " + num(in.direction) +
           " through it with the 3D-DDA: which cells does it visit, in order (cells_visited: a "
           "list of [i, j, k]; an empty list when the ray misses the grid)? The walk stops in "
           "the first cell where the nearest hit so far has t ≤ that cell's exit; a hit beyond "
           "the exit is not final. Give also the hit primitive's index (primitive; null for a "
           "miss) and its t (null for a miss).";
}

std::vector<std::string> UniformGrid::answer_fields() {
    return {"cells_visited", "primitive", "t"};
}

}  // namespace cg
