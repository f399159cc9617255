// The z-buffer (depth buffer) algorithm for hidden-surface removal.
//
// Beside the colour buffer keep a depth buffer, one depth per pixel, cleared to ∞ (farther
// than anything). Scan-convert the polygons one after another in index order; at every pixel
// centre a polygon covers, its depth on its plane, z = −(a·x + b·y + d)/c, is compared with the
// buffer: when nearer (z < depth[i, j]) the polygon's depth and colour are written, otherwise
// the pixel keeps what it has. Each pixel ends with the nearest polygon.
//
// Conventions (hsr/screen_scene.hpp): smaller z is nearer; a polygon covers a pixel centre by
// the triangle scan conversion's top-left rule (a convex polygon is scanned as a fan of
// triangles with raster/triangle_spans.hpp); at equal z the polygon drawn first — the lower
// index — stays, because only a strictly nearer z replaces it. That is the project's one
// tie-break rule, so the result equals hsr::visible_ids at every pixel.
//
// Cost: one depth compare per scan-converted pixel, p_c in all, plus the set-up of each of the
// n polygons: O(p_c + n), online (each polygon is handled once and forgotten).
//
// Steps: clear; then per polygon one step (granularity "polygon": its pixels' compares
// summarised) or a set-up step and one step per covered pixel (granularity "pixel"); done.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "hsr/screen_scene.hpp"

namespace cg {

struct ZBuffer {
    enum class Granularity : std::uint8_t { Polygon, Pixel };

    struct Input {
        hsr::ScreenScene scene;
        Granularity granularity = Granularity::Polygon;  // one step per polygon, or per pixel
        bool operator==(const Input&) const = default;
    };
    struct Result {
        long long width = 0, height = 0;  // of the buffers, in pixels
        std::vector<int> ids;       // width × height, row 0 at the bottom; −1 background
        std::vector<double> depth;  // the depth buffer; +∞ where nothing was drawn
        long long compares = 0;     // depth compares = pixels scan-converted (p_c)
        long long writes = 0;       // compares the polygon won (depth and colour written)
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Clear, Polygon, Setup, Pixel, Finish, Done };

    struct State {
        Input in;
        Phase phase = Phase::Clear;  // the step to take next
        Phase last = Phase::Clear;   // the step taken last (what narrate tells)
        std::vector<hsr::Plane> planes;  // one per polygon
        std::vector<int> ids;            // the colour buffer, as polygon indices (−1 background)
        std::vector<double> depth;       // the depth buffer (+∞ = cleared)
        int k = -1;                      // the polygon being drawn (or just drawn)
        std::vector<hsr::PixelSpan> spans;  // pixel granularity: polygon k's spans
        std::size_t span = 0;            // pixel granularity: the next pixel is spans[span], i
        int i = 0;
        // The step just taken: a polygon's totals, or one pixel's compare.
        long long step_pixels = 0, step_wins = 0;
        int pi = 0, pj = 0;              // the pixel compared (pixel granularity)
        double z = 0, z_old = 0;         // its depth on the plane, and the buffer's before
        int id_old = -1;                 // the buffer's polygon before
        bool won = false;
        long long compares = 0, writes = 0;
        bool operator==(const State&) const = default;
    };
    // The state's heap memory, for the timeline's memory budget (see Run::bytes).
    static std::size_t bytes(const State& s) {
        return hsr::heap_bytes(s.in.scene) + heap_bytes(s.planes) + heap_bytes(s.ids) + heap_bytes(s.depth) +
               heap_bytes(s.spans);
    }

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (z_buffer_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same algorithm as one straight-line function, for the benchmark's comparison.
    static Result render(const Input& in);

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
