// Marching squares: the contour f(x, y) = iso of a sampled scalar field, one grid cell at a time.
//
// The course ("Rendering Implicit Surfaces": marching cubes samples the function on a uniform
// grid and decides from adjacent samples); this is its 2D form, worked first. The field is
// sampled at the grid points; each cell looks only at its four corners:
//   inside     a corner is inside when f < iso (f ≥ iso is outside, so f = iso is outside)
//   bits       corners numbered counter-clockwise from the bottom left: 0 = (i, j),
//              1 = (i+1, j), 2 = (i+1, j+1), 3 = (i, j+1); bit k of the case is 1 when corner k
//              is inside, so case = b0 + 2·b1 + 4·b2 + 8·b3, from 0 to 15
//   edges      0 bottom (corner 0 to 1), 1 right (1 to 2), 2 top (3 to 2), 3 left (0 to 3),
//              each from its lower-coordinate end, so two cells sharing an edge compute the
//              same crossing bit for bit
//   crossing   on an edge a → b whose corners differ, t = (iso − f_a) / (f_b − f_a) and
//              p = a + t·(b − a): linear interpolation of f along the edge
//   segments   from the 16-case table, oriented with the inside on the left (a closed contour
//              runs counter-clockwise around an inside region)
//   saddles    cases 5 (corners 0 and 2 inside) and 10 (1 and 3): two segments either way;
//              decided by the cell-centre average m = (f0 + f1 + f2 + f3)/4: m < iso means the
//              centre is inside, so the two inside corners are joined (the segments cut off
//              the outside corners); otherwise they are separated
// Fields: a grid of values given row by row (row 0 at the bottom, value [j][i] at the point
// (i, j), unit spacing), or a named field sampled on [−1, 1]² with `cells` cells a side:
// circle f = x² + y² − r², two blobs f = ½ − Σ exp(−|p − c_k|²/r²) with c = (∓0.4, 0), and
// noise (independent uniform values in [−1, 1) at every grid point, from a seed).
//
// Steps: the sampling; then the cells in scan order (i fastest, rows upward): a cell the
// contour crosses is one step, a run of cells it does not cross is one step; after kStepped
// steps the rest go in at most kBatches batches; a summary (segments, length, closed loops).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct MarchingSquares {
    static constexpr int kMaxCells = 256;  // cells a side, either way of giving the field
    static constexpr double kMaxValue = 1e100;
    static constexpr int kStepped = 64;  // steps before batching
    static constexpr int kBatches = 32;

    enum class Field : std::uint8_t { Grid, Circle, Blobs, Noise };

    struct Input {
        Field field = Field::Grid;
        std::vector<std::vector<double>> values;  // Grid: rows from the bottom, values[j][i]
        int cells = 16;                           // named fields: cells a side on [−1, 1]²
        double radius = 0.7;                      // circle radius; blob radius
        double iso = 0;
        std::uint64_t seed = 1;  // noise
        bool operator==(const Input&) const = default;
    };

    // The sampled field: nx × ny cells, (nx + 1)(ny + 1) values, point (i, j) at origin + h·(i, j).
    struct Grid {
        int nx = 0, ny = 0;
        glm::dvec2 origin{0, 0};
        double h = 1;
        std::vector<double> f;  // row-major from the bottom: f[j·(nx+1) + i]
        double at(int i, int j) const { return f[std::size_t(j) * std::size_t(nx + 1) + std::size_t(i)]; }
        glm::dvec2 point(int i, int j) const { return origin + h * glm::dvec2(i, j); }
        bool operator==(const Grid&) const = default;
    };

    // A contour segment from a to b, the inside on its left; ea, eb the grid edges they lie on
    // (2·(j·(nx+1) + i) for the horizontal edge from point (i, j), +1 for the vertical one).
    struct Segment {
        glm::dvec2 a{0, 0}, b{0, 0};
        int ea = 0, eb = 0;
        bool operator==(const Segment&) const = default;
    };

    // What one cell gives: its case, the crossings on its edges (bottom, right, top, left, only
    // those the contour crosses), the saddle decision.
    struct Cell {
        int i = 0, j = 0;
        int index = 0;                     // the case, 0 … 15
        std::array<double, 4> f{};         // corner values, corners 0 … 3
        std::array<double, 4> t{};         // per edge, the crossing parameter (crossed edges)
        std::array<glm::dvec2, 4> p{};     // per edge, the crossing point
        int crossed = 0;                   // bit e set when edge e is crossed
        double centre = 0;                 // saddles: the average of the corners
        bool joined = false;               // saddles: inside corners joined through the centre
        int segments = 0;
        std::array<std::array<int, 2>, 2> seg{};  // (from edge, to edge), inside on the left
    };

    struct Result {
        int nx = 0, ny = 0;
        std::vector<std::uint8_t> cases;  // per cell, row-major from the bottom
        std::vector<Segment> segments;
        // One point per grid edge where the sign changes, cell by cell in scan order, within a
        // cell bottom, right, top, left (bottom and left only on the grid's border: elsewhere
        // the cell below or to the left has listed them).
        std::vector<glm::dvec2> crossings;
        long long inside = 0;  // grid points with f < iso
        long long saddles = 0, joined = 0;
        double length = 0;
        long long loops = 0, chains = 0;  // closed contours; open ones ending on the border
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Sample, Cells, Summary, Done };

    struct State {
        Shared<Input> in;
        Shared<Grid> grid;
        Phase phase = Phase::Sample;
        Phase last = Phase::Sample;
        int next = 0;   // the next cell, row-major
        int from = 0;   // the first cell of the last step
        int steps = 0;  // cell steps taken
        int batch = 0;  // cells per step once batching (0: not yet)
        std::vector<std::uint8_t> cases;
        std::vector<Segment> segments;
        std::vector<glm::dvec2> crossings;
        std::size_t seg_from = 0;  // the first segment of the last step
        long long saddles = 0, joined = 0;
        double length = 0;
        long long loops = 0, chains = 0;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);  // moves the lists out (run_to_end)
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.cases) + heap_bytes(s.segments) + heap_bytes(s.crossings) + s.grid->f.capacity() * sizeof(double);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    static Result compute(const Input& in);

    // The pieces both use.
    static Grid sample(const Input& in);
    static double field_value(const Input& in, glm::dvec2 p);  // named fields (not noise)
    static int case_index(const Grid& g, int i, int j, double iso);
    // The whole cell: case, crossings, saddle decision, segments.
    static Cell march(const Grid& g, int i, int j, double iso);
    static int edge_id(const Grid& g, int i, int j, int edge);
    // The segment table: the (from, to) edge pairs of a case, inside on the left; a saddle
    // (5, 10) gives the pairs for joined or separated inside corners.
    static int table(int index, bool joined, std::array<std::array<int, 2>, 2>& seg);
    // Closed loops and open chains among the segments (each grid edge starts at most one
    // segment and ends at most one).
    static void count_loops(const Grid& g, const std::vector<Segment>& segs, long long& loops,
                            long long& chains);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
