// Warnock's area-subdivision algorithm for hidden-surface removal.
//
// Look at an area of the screen (at first the whole screen) with the polygons that may show in
// it, and classify each against the area rectangle:
//   surrounding   the polygon contains the whole area
//   intersecting  it overlaps the area and crosses its border
//   contained     it lies entirely inside the area
//   disjoint      it does not overlap the area's interior (dropped for this area and inside it)
// (exact tests on the convex outline: a separating axis — the area's own x and y, or one of the
// polygon's edges with all four corners on its outer side — means disjoint.) The area is
// simple, and is drawn at once, when
//   - no polygon is left: background;
//   - one polygon is left: its pixels (by the coverage rule), background elsewhere;
//   - a surrounding polygon is in front of every other polygon left over the whole area: the
//     planes are compared at the area's four corners, where the surrounding polygon must be
//     strictly nearer (by a small margin for rounding) than each other one — depth is linear,
//     so then it is nearer everywhere in between;
//   - the area is one pixel: the nearest polygon covering the pixel centre (the tie rule).
// Otherwise the area is split at x + ⌊w/2⌋ and y + ⌊h/2⌋ into four (two when it is one pixel
// wide or high): bottom-left, bottom-right, top-left, top-right, pushed on a stack in reverse so
// they are examined in that order, each with the parent's non-disjoint polygons.
//
// Conventions (hsr/screen_scene.hpp): smaller z nearer, equal z → lower index; coverage by the
// top-left rule at pixel centres. Areas are whole pixels: [x, x + w) × [y, y + h).
//
// Cost: each area costs one classification per polygon passed down; in the worst case every
// pixel becomes an area with every polygon, O(p·n).
//
// Steps: one per area examined (empty, single, surrounder, pixel, or split); done.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "hsr/screen_scene.hpp"

namespace cg {

struct Warnock {
    struct Input {
        hsr::ScreenScene scene;
        bool operator==(const Input&) const = default;
    };
    struct Result {
        long long width = 0, height = 0;
        std::vector<int> ids;          // width × height, row 0 at the bottom; −1 background
        long long areas = 0;           // areas examined
        long long classifications = 0; // polygon-area classifications
        bool operator==(const Result&) const = default;
    };

    enum class Class : std::uint8_t { Surrounding, Intersecting, Contained, Disjoint };
    enum class Outcome : std::uint8_t { None, Empty, Single, Surrounder, Pixel, Split };
    enum class Phase : std::uint8_t { Area, Finish, Done };

    struct Area {
        int x = 0, y = 0, w = 0, h = 0;      // pixels [x, x + w) × [y, y + h)
        std::uint32_t list = 0, count = 0;   // its polygons: lists[list .. list + count)
        int depth = 0;                       // 0 for the screen, +1 per split
        bool operator==(const Area&) const = default;
    };

    struct State {
        Input in;
        Phase phase = Phase::Area;
        std::vector<hsr::Plane> planes;           // one per polygon
        std::vector<std::vector<glm::dvec2>> outlines;  // counter-clockwise, one per polygon
        std::vector<Area> stack;                  // areas still to examine, the next on top
        std::vector<int> lists;                   // polygon lists of the areas, stacked
        std::vector<int> ids;                     // decided pixels; −2 = not yet, −1 background
        std::vector<Area> visited;                // every area examined, in order (the quadtree)
        // The area examined last, and what it found.
        Area area;
        std::vector<int> polys;                   // the polygons it classified
        std::vector<Class> classes;               // ... and their classes
        Outcome outcome = Outcome::None;
        int drawn = -1;                           // the polygon drawn (single, surrounder, pixel)
        long long areas = 0, classifications = 0;
        bool operator==(const State&) const = default;
    };
    // The state's heap memory, for the timeline's memory budget (see Run::bytes).
    static std::size_t bytes(const State& s) {
        return hsr::heap_bytes(s.in.scene) + heap_bytes(s.planes) + heap_bytes(s.outlines) +
               heap_bytes(s.stack) + heap_bytes(s.lists) + heap_bytes(s.ids) + heap_bytes(s.visited) +
               heap_bytes(s.polys) + heap_bytes(s.classes);
    }

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (warnock_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same algorithm as one straight-line (recursive) function, for the benchmark.
    static Result render(const Input& in);

    // The class of a convex counter-clockwise outline against the area [x0, x1] × [y0, y1].
    static Class classify(const std::vector<glm::dvec2>& ccw, double x0, double y0, double x1, double y1);

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
