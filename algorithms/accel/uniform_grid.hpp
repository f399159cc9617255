// Spatial subdivision with a uniform grid: build it over the scene's primitives, then walk one
// ray through it cell by cell with the 3D-DDA of Amanatides and Woo, testing only the
// primitives listed in the cells the ray passes through.
//
// The grid: the box B = the union of the primitives' bounds (or the bounds given, which must
// contain them all), cut into nx × ny × nz equal cells of size s_i = (max_i − min_i)/n_i. Cell
// (i, j, k) is the closed box [min + (i, j, k)·s, min + (i+1, j+1, k+1)·s] (its far planes are
// max on the last cell). An axis along which the scene is flat (all primitives in one plane)
// is padded to ± half the largest side (± 0.5 when every side is 0), so every cell has a size.
//
// Build: each primitive is listed in every cell it meets. Its bounding box gives the candidate
// cells (the index range of its min and max corners), and the exact closed overlap test
// (accel/primitive.hpp overlaps: sphere by distance, triangle by separating axes, box by
// bounds) keeps those it really meets. The test is made on the cell grown by 1e-9 of its size
// on every side, so a primitive that only touches a cell, or meets it by less than a rounding,
// is listed too: a cell may list a primitive it touches, never miss one it contains.
//
// Walk (Amanatides–Woo): the ray P(t) = E + t d, t ≥ 0, enters B by the slab test
// (RayAabb::intersect) at t_start = max(t_min, 0); the start cell is the one containing
// P(t_start) — on a cell boundary, the cell the ray goes into (the lower one when d_i < 0).
// Per axis:  step_i = sign(d_i);  t_max_i = the t of the next cell plane the ray crosses on
// axis i;  t_delta_i = s_i/|d_i|, the t between two planes (d_i = 0: t_max_i = t_delta_i = ∞,
// the ray never steps on that axis). Each step visits the current cell: it tests the
// primitives listed there and keeps the nearest hit so far; the cell's exit is
// t_exit = min(t_max_x, t_max_y, t_max_z). A hit with t ≤ t_exit is final — it lies in this
// cell, and every cell the ray met before has been tested. A hit beyond t_exit is not final:
// the primitive reaches into this cell but the ray meets it further on, in a later cell, and
// a nearer primitive may sit in the next cell, between the exit and that hit. So the walk goes
// on: the axis with the smallest t_max steps (ties: x before y before z), the cell index moves
// by step_i and t_max_i += t_delta_i; leaving the grid ends the walk (a miss).
//
// A primitive listed in several cells is tested once per ray: a mailbox (one flag per
// primitive) remembers it was tested, and its hit, if beyond the exit, waits as the nearest
// so far. The counts: cells visited, primitive tests made, mailbox skips; brute force's
// primitive_tests is n, the number of primitives.
//
// The hit equals brute force's (every primitive, nearest t ≥ 0; ties to the lower index)
// except at exact ties, where a primitive with the same t listed only in a later cell is not
// tested. Sizes are kept lesson-small: at most kMaxPrimitives primitives, kMaxAxisCells per
// axis and kMaxCells cells.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

#include "accel/primitive.hpp"
#include "accel/ray_aabb.hpp"
#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct UniformGrid {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    static constexpr std::size_t kMaxPrimitives = 64;
    static constexpr int kMaxAxisCells = 16;
    static constexpr int kMaxCells = 512;
    // The cell grown by this fraction of its size on every side for the overlap test.
    static constexpr double kMargin = 1e-9;

    using Cell = std::array<int, 3>;

    struct Input {
        std::vector<Primitive> primitives;
        Cell cells{4, 4, 1};      // n_x, n_y, n_z, each 1..kMaxAxisCells
        bool has_bounds = false;  // the grid's box given (else the scene's bounds)
        Bounds bounds;            // when given: min < max on every axis, holding every primitive
        glm::dvec3 origin{-1, 0.5, 0.5};  // E
        glm::dvec3 direction{1, 0, 0};    // d, not zero; any length
        bool operator==(const Input&) const = default;
    };

    // Where one primitive went in the build.
    struct Placement {
        Cell lo{}, hi{};     // the index range its bounds span (the candidates)
        int candidates = 0;  // cells in that range
        int kept = 0;        // those the exact test kept
        bool operator==(const Placement&) const = default;
    };

    // The built grid (derived from the input once, immutable).
    struct Grid {
        Bounds box;
        Cell n{1, 1, 1};
        glm::dvec3 size{1.0};
        std::array<bool, 3> padded{};         // an axis where the scene was flat
        std::vector<std::vector<int>> cells;  // index i + n_x (j + n_y k): the primitives
        std::vector<Placement> placed;        // per primitive
        int index(const Cell& c) const { return c[0] + n[0] * (c[1] + n[1] * c[2]); }
        // The plane number k on axis a (k = n_a is max_a exactly).
        double plane(int a, int k) const {
            return k == n[a] ? box.max[a] : box.min[a] + k * size[a];
        }
        Bounds cell_box(const Cell& c) const;
        bool operator==(const Grid&) const = default;
    };

    // One primitive test in a cell.
    struct Test {
        int primitive = 0;
        double t = kInf;       // kInf: missed
        bool skipped = false;  // the mailbox: already tested on this ray
        bool operator==(const Test&) const = default;
    };

    // The 3D-DDA's running values.
    struct Walk {
        bool inside = false;  // the ray is in the grid (a cell to visit)
        Cell cell{}, step{};
        glm::dvec3 t_max{kInf}, t_delta{kInf};
        double t_enter = 0;        // where the ray entered the current cell
        double t_exit = 0;         // the last visited cell's exit
        std::vector<char> tested;  // the mailbox, per primitive
        int best = -1;             // the nearest hit so far: primitive (−1: none) and t
        double best_t = kInf;
        int primitive_tests = 0, mailbox_skips = 0;
        std::vector<Cell> visited;
        bool operator==(const Walk&) const = default;
    };

    struct Result {
        bool entered = false;           // the ray meets the grid's box
        double t_start = 0, t_end = 0;  // where it is in the box (when entered)
        bool hit = false;
        int primitive = -1;
        double t = 0;
        glm::dvec3 point{0.0};
        Cell cell{};  // the cell where the hit was accepted
        std::vector<Cell> cells_visited;
        int primitive_tests = 0, mailbox_skips = 0;
        int brute_force_tests = 0;  // n
        Shared<Grid> grid;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Build, Enter, Cell, Done };
    // How the step just taken ended (for the narration and the picture).
    enum class Outcome : std::uint8_t {
        None,
        Placed,
        Entered,
        StartInside,
        MissGrid,
        Empty,
        NoHit,
        Beyond,
        Hit,
        Exit
    };

    struct State {
        Shared<Input> in;
        Shared<Grid> grid;
        Phase phase = Phase::Build;
        Outcome last = Outcome::None;
        int built = 0;  // primitives placed so far
        RayAabb::Result entry;
        Walk w;
        std::vector<Test> tests;  // the tests of the cell just visited
        Cell visited_cell{};      // the cell just visited
        int stepped_axis = -1;    // the axis the walk stepped after it (−1: none)
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // Build and walk in one straight function (same numbers, no narration), for the
    // benchmark; `in` must be valid (validate).
    static Result trace(const Input& in);
    // The walk alone through a grid built for in's primitives (many rays, one build).
    static Result trace(const Input& in, const Shared<Grid>& grid);

    // The grid alone (`in` valid).
    static Grid build(const Input& in);
    // The brute-force nearest hit: every primitive, nearest t ≥ 0, ties to the lower index;
    // returns the primitive (−1: none) and sets t.
    static int brute_force(const Input& in, double& t);

  private:
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
