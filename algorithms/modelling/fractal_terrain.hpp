// Fractal terrain: midpoint displacement on a triangle, and diamond–square on a grid.
//
// The course: "Start with triangle, refine and adjust vertices. At every step of refinement,
// adjust height of vertices. Use scaled random numbers to adjust height."
//
// "midpoint-triangle": a triangle A B C (points [x, y, z], y the height) is refined `levels`
// times. One level splits every triangle into four through its edge midpoints; a midpoint's
// height is the average of its edge's two endpoints plus a random offset in [−a, a):
//     h_m = (h_p + h_q)/2 + r,   r = uniform(−a, a)
// An edge shared by two triangles is split once, so both see the same midpoint (no cracks).
// After n levels the vertices form the lattice (i, j), i + j ≤ N = 2^n, at
// A + (i/N)(B − A) + (j/N)(C − A) in x and z: (N + 1)(N + 2)/2 vertices and 4^n triangles.
//
// "diamond-square": a square of side `size` centred on the origin in the x–z plane, its four
// corner heights given, on a (N + 1)² grid. A level with cells of s = N/2^(L−1):
//   diamond  each cell's centre = the average of the cell's four corners + r
//   square   each edge midpoint = the average of its three or four diamond neighbours + r
//            (three on the border: the fourth would lie outside).
// (N + 1)² vertices and 2 N² triangles (each cell split along the same diagonal).
//
// The amplitude: a = `amplitude` at level 1, times 2^(−H) at each level after (H the
// `roughness`, 0 … 4: 0 keeps a, the roughest; 1 halves it, the classic "fractal" terrain).
// The random numbers come from one seeded generator (core/rng.hpp), drawn in the fixed order
// of the walk below (level by level; the triangle's new points row by row; the grid's diamonds,
// then its squares, row by row), so the same input gives the same terrain bit for bit.
// With amplitude 0 a triangle stays exactly the plane through A, B, C (up to the rounding of
// the averages, none for small dyadic heights); the grid stays flat only for equal corners
// (exactly when 3 h rounds to nothing, as for dyadic h), because a border point averages three
// neighbours, one of them inside — a tilted plane is not kept.
//
// rays/mesh_gen's terrain is `diamond_square` below with corners drawn from its generator, the
// first amplitude and the factor both its roughness ρ.
//
// Stepped: each level starts with a "level" step (its amplitude). Up to level 2 every new point
// is a step ("midpoint"; "diamond" and "square"); from level 3 a whole level (triangle) or
// phase (grid) is one "batch" step. Then a "summary".
// Refused: levels outside 0 … 8, NaN or infinite numbers, coordinates or heights above 1e12 in
// size, an amplitude below 0 or above 1e12, a roughness outside [0, 4], a triangle with no
// area seen from above (collinear in x and z), a size ≤ 0, fields of the other method.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

namespace fractal {

enum class Method : std::uint8_t { Triangle, Grid };

// Where the walk over the new points is: level L (1-based), the grid's phase (0 diamond,
// 1 square; always 0 for the triangle) and the point (i, j) of the lattice of side N.
struct Visit {
    int level = 1;
    int phase = 0;
    int i = 0, j = 0;
    bool operator==(const Visit&) const = default;
};

// The first new point of level 1 (levels ≥ 1), and the next one: false after the last.
Visit first(Method m, int N);
Visit first_at(Method m, int N, int level);
bool advance(Method m, int N, Visit& v);
// The points whose average the new one takes (2 for the triangle, 3 or 4 for the grid), as
// lattice indices, in the order they are summed; returns how many.
int neighbours(Method m, int N, const Visit& v, std::array<int, 4>& out);
// The same points as (i, j).
int neighbour_points(Method m, int N, const Visit& v, std::array<std::array<int, 2>, 4>& ij);
// The lattice index of (i, j): the triangle's rows j = 0 … N hold N + 1 − j points.
int index(Method m, int N, int i, int j);
int vertex_count(Method m, int N);
// The average of the neighbours, summed in their order and divided by their count
// (the diamond: 0.25 × the sum, as mesh_gen always did).
double average(const std::vector<double>& h, const std::array<int, 4>& nb, int count, int phase);

// Every level at once on h (the corners set, the rest anything); h then holds the terrain.
// The amplitude is a0 at level 1, then multiplied by `factor` per level; `amplitudes` and
// `largest` (if given) get each level's amplitude and largest |offset|.
void refine(Method m, int levels, double a0, double factor, Rng& rng, std::vector<double>& h,
            std::vector<double>* amplitudes = nullptr, std::vector<double>* largest = nullptr);
// Diamond–square on a (N + 1)² grid, N = 2^levels, its corners already in h.
inline void diamond_square(std::vector<double>& h, int levels, double a0, double factor,
                           Rng& rng) {
    refine(Method::Grid, levels, a0, factor, rng, h);
}

}  // namespace fractal

struct FractalTerrain {
    static constexpr int kMaxLevels = 8;  // 65 536 triangles, 66 049 grid points
    static constexpr int kSingleLevels = 2;  // levels stepped point by point
    static constexpr double kMaxValue = 1e12;
    static constexpr double kMaxRoughness = 4;

    using Method = fractal::Method;

    struct Input {
        Method method = Method::Triangle;
        int levels = 2;
        double amplitude = 1;
        double roughness = 1;  // H: the amplitude's factor per level is 2^(−H)
        std::uint64_t seed = 1;
        std::array<glm::dvec3, 3> triangle{};  // A, B, C
        double size = 1;                       // the grid's side
        std::array<double, 4> corners{};       // heights at (0,0), (N,0), (0,N), (N,N)
        bool operator==(const Input&) const = default;
    };

    struct Result {
        std::vector<glm::dvec3> vertices;  // lattice order
        std::vector<std::array<int, 3>> triangles;
        std::vector<double> amplitudes;       // a per level
        std::vector<double> largest_offsets;  // max |r| per level
        long long vertex_count = 0, triangle_count = 0;
        double min_height = 0, max_height = 0;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Level, Points, Summary, Done };
    enum class Last : std::uint8_t { None, Level, Point, Batch, Summary };

    struct State {
        Shared<Input> in;
        int N = 1;
        Phase phase = Phase::Level;
        Last last = Last::None;
        fractal::Visit at;        // the next point
        fractal::Visit done_at;   // the point (or the batch's first point) just done
        int batch = 0;            // points in the batch just done
        double a = 0;             // the amplitude of the current level
        double avg = 0, offset = 0;  // the last point's average and random offset
        std::vector<double> h;    // heights, lattice order; set up to the walk's position
        std::vector<double> amplitudes, largest;
        Rng rng{1};
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.h) + heap_bytes(s.amplitudes) + heap_bytes(s.largest);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Straight loops (fractal::refine), for the benchmark, the tests and the fuzz oracle.
    static Result compute(const Input& in);

    // The pieces both use.
    static double factor(const Input& in);  // 2^(−H)
    static std::vector<double> start_heights(const Input& in);  // the corners set, the rest 0
    static glm::dvec3 position(const Input& in, int N, int i, int j, double height);
    static std::vector<std::array<int, 3>> triangles(Method m, int N, int spacing);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
