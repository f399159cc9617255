// Scan conversion of a triangle, as the course does it: sort, split, slopes, scanlines.
//
//   1. Sort the vertices by y: v0 lowest, v1 middle, v2 highest (ties by x).
//   2. Split with the horizontal line y = y1 through the middle vertex. It meets the long edge
//      v0→v2 at x_split = x0 + (y1 − y0)·(x2 − x0)/(y2 − y0). Below the line is the lower part,
//      whose top edge is horizontal (flat-top); above it the upper part, whose bottom edge is
//      horizontal (flat-bottom). Each part is bounded left and right by two edges: the long
//      edge and a short one (v0→v1 below, v1→v2 above). When two vertices share a y one part
//      has no height and there is nothing to split; when all three are collinear nothing is
//      filled.
//   3. Inverse slopes m = dx/dy of the three edges, so that along an edge x = x_a + (y − y_a)·m.
//   4. Walk the scanlines bottom to top; on each, the span [x_left, x_right) between the part's
//      two edges at the scanline's centre y holds the pixels to fill. One step per scanline.
//
// Conventions (the project's): pixel (i, j) covers [i, i+1) × [j, j+1), origin bottom-left,
// y up, and is sampled at its centre (i + ½, j + ½). A pixel is filled when its centre is
// inside the triangle. A centre exactly on an edge is decided by the top-left rule, read with
// y up:
//   - a LEFT edge is one with the triangle's inside to its right (+x side): it belongs to the
//     triangle; a RIGHT edge (inside to its left) does not;
//   - a TOP edge is a horizontal edge with the inside below it (smaller y, the edge at the top
//     of the picture): it belongs to the triangle; a horizontal BOTTOM edge does not.
// A vertex belongs when both its edges do. Two triangles sharing an edge see it as a left edge
// on one side and a right edge on the other (or top and bottom), so every centre on it is
// filled by exactly one of them, and a mesh covers each pixel exactly once.
//
// The rule as scanline arithmetic (exactly this, nothing rounded): scanline j is visited when
// y0 < j + ½ ≤ y2, i.e. ⌊y0 + ½⌋ ≤ j < ⌊y2 + ½⌋ (a centre on a horizontal bottom edge is out,
// on a horizontal top edge in); the lower part takes the centres with y ≤ y1, the upper part
// those above; on the scanline pixel i is filled when x_left ≤ i + ½ < x_right, i.e.
// ⌈x_left − ½⌉ ≤ i < ⌈x_right − ½⌉ (left edges in, right edges out). The x_left and x_right
// shown are doubles, but which side of an edge a centre lies on is decided by the exact
// orientation test (orient2d.hpp), so integer and half-integer inputs — centres exactly on
// edges and vertices — come out right every time.
//
// Pixels outside the width × height grid are not filled: scanlines and spans are clipped to it
// (only scanlines that meet the grid are visited). With per-vertex colours (RGB in [0, 1]) the
// pixels are Gouraud shaded: colours are interpolated linearly along both edges to the
// scanline, then along the span to each pixel centre.
//
// Steps: sort; split (or flat-edge, or collinear → done); slopes; one per scanline (span or
// empty-span); done.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "raster/triangle_spans.hpp"

namespace cg {

struct ScanTriangle {
    static constexpr long long kMaxSize = 4096;  // pixels, per side of the grid
    static constexpr double kMaxCoordinate = 1e9;  // |vertex coordinate|, in pixels

    struct Input {
        long long width = 0, height = 0;    // the grid, in pixels: 1 … kMaxSize each
        std::vector<glm::dvec2> triangle;   // 3 vertices, any order, in pixel units
        std::vector<glm::dvec3> colors;     // none, or 3 (one per vertex): RGB in [0, 1]
        bool operator==(const Input&) const = default;
    };
    struct Result {
        std::vector<glm::ivec2> pixels;      // (i, j) filled, sorted by j then i
        std::vector<glm::dvec3> colors;      // parallel to pixels when colours were given
        std::vector<std::array<int, 3>> spans;  // (j, i_first, i_last) per scanline with pixels
        std::optional<glm::dvec2> split;     // (x_split, y1); none when collinear
        // m = dx/dy of v0→v2 (long), v0→v1 (lower), v1→v2 (upper); none when horizontal, and
        // all none when collinear.
        std::array<std::optional<double>, 3> inverse_slopes;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Sort, Split, Slopes, Scanline, Finish, Done };
    using Edge = raster::TriangleEdge;  // Long v0→v2, Lower v0→v1, Upper v1→v2

    struct Span {
        int j = 0, i_first = 0, i_end = 0;  // scanline j fills i_first ≤ i < i_end
        double x_left = 0, x_right = 0;     // the span at y = j + ½
        bool operator==(const Span&) const = default;
    };

    struct State {
        Input in;
        Phase phase = Phase::Sort;       // the step to take next
        Phase last = Phase::Sort;        // the step taken last (what narrate tells)
        std::array<glm::dvec2, 3> v{};   // the vertices sorted by y (then x)
        std::array<glm::dvec3, 3> c{};   // their colours (when shaded)
        std::array<int, 3> order{};      // v[k] is in.triangle[order[k]]
        int orient = 0;  // +1: v1 left of the long edge v0→v2, −1 right, 0 collinear
        double x_split = 0;              // where the long edge crosses y = y1
        std::array<double, 3> m{};       // dx/dy per Edge; 0 for a horizontal edge (never used)
        int j_begin = 0, j_end = 0;      // the scanlines visited: j_begin ≤ j < j_end (clipped)
        int j = 0;                       // the scanline done last (during Phase::Scanline)
        bool upper = false;              // scanline j lies in the upper part
        double x_left = 0, x_right = 0;  // scanline j's span at y = j + ½
        int i_first = 0, i_end = 0;      // its pixels: i_first ≤ i < i_end (clipped to the grid)
        // The scanlines filled so far, as spans: the pixels (and their colours) follow from
        // them, so a snapshot of the state stays small however large the triangle.
        std::vector<Span> spans;
        long long filled = 0;            // pixels in those spans
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);  // advance, then narrate if info is given
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);  // the pixels so far; all of them once done
    static void draw(const State& s, Scene& scene);

    // Exam practice (scan_triangle_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same scan conversion as one straight-line function, for the benchmark's comparison.
    static Result scan(const Input& in);

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
