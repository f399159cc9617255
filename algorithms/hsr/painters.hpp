// The painter's algorithm (depth-sort, Newell's method) for hidden-surface removal.
//
// Sort the polygons on their farthest z (largest z first: smaller z is nearer). Then, with P the
// farthest polygon of the list, resolve the ambiguity with every Q whose z extent overlaps P's:
// P may be drawn before Q when one of the standard tests holds, tried cheapest first:
//   1. their x extents do not overlap;            2. their y extents do not overlap;
//   3. P lies entirely on the far side of Q's plane;
//   4. Q lies entirely on the near side of P's plane;
//   5. their projections on the screen do not overlap (no separating line: they do).
// When every test fails, P may hide part of Q, so Q should be drawn first: if Q may be drawn
// before P (the plane tests with the roles swapped, 3′ and 4′), Q is moved to the far end of
// the list and marked, and the tests restart with Q as P. A marked Q that would move again
// means the overlaps are cyclic; and when neither order is safe (each crosses the other's
// plane), one polygon is split: P by Q's plane if P crosses or touches it, else Q by P's plane,
// else — a cycle of polygons each wholly on one side of the others' planes — P (or Q) is cut in
// two along a pixel-grid line. The pieces replace their polygon and the list is examined again.
// When P obscures nothing it is settled: it goes next in the drawing order. Finally the settled
// polygons are scan-converted back to front, each overwriting what is behind it.
//
// Pixel exactness (hsr/screen_scene.hpp: centres, the top-left rule, ties nearer wins and equal z
// → lower index). A piece covers a pixel centre when its parent does AND the centre lies on the
// piece's side of every cut: a plane cut by Q's plane is decided at the centre by the very
// comparison hsr::visible_ids makes (P's and Q's depths there, the tie rule), a grid cut by the
// centre's column or row. So the pieces of a polygon share its centres out exactly, with no
// re-rasterised rounded vertices, and a piece's side of the plane that cut it is known exactly.
// Tests 1, 2 and 5 on unsplit polygons are exact (touching counts as apart: the top-left rule
// gives a shared edge's centres to one side only). Tests 3 and 4 compare vertex depths with a
// margin of 1e-9 relative to the coordinates' size, and the geometry of pieces (clipped vertex
// lists, used for the tests and the picture) is padded by that margin, so a test that passes is
// right at every centre; a polygon merely touching another's plane fails them and is split by
// it, exactly. Two polygons in one flat plane z = c are ordered by the tie rule (the lower index
// is drawn later). A piece covering at most one pixel centre is tested at that centre directly
// (test 6), which also ends any cycle. The result therefore equals hsr::visible_ids at every
// pixel for every valid scene — intersecting polygons included (they are split along their
// intersection).
//
// Cost: each settled polygon is tested against every polygon whose z extent overlaps, and moves
// restart the tests: Ω(n²) pair tests in general (the course's bound), plus the pixels drawn.
//
// Steps: sort; one per pair test (with the test that decided, or the move or split it forced);
// one per settled polygon; one per polygon drawn; done.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "hsr/screen_scene.hpp"

namespace cg {

struct Painters {
    struct Input {
        hsr::ScreenScene scene;
        bool operator==(const Input&) const = default;
    };

    // What decided a pair (P, Q), P the farthest of the list.
    enum class Test : std::uint8_t {
        None,        // nothing yet
        Depth,       // (not a pair test) Q's z extent lies wholly in front of P's
        Same,        // P and Q are pieces of one polygon: their centres never coincide
        XExtent,     // 1: x extents apart
        YExtent,     // 2: y extents apart
        PBehind,     // 3: P on the far side of Q's plane
        QInFront,    // 4: Q on the near side of P's plane
        Projection,  // 5: projections apart
        Centre,      // 6: a piece with at most one pixel centre, compared there
    };
    enum class Outcome : std::uint8_t { None, Pass, Move, Split };

    // A side of a cut: a plane cut by polygon `other`'s plane (far: `other` is in front at the
    // centre), or a grid cut at the integer column / row `other` (low: the centre is below it).
    struct Cut {
        enum class Kind : std::uint8_t { Plane, Column, Row };
        Kind kind = Kind::Plane;
        int other = 0;      // the cutting polygon's index, or the grid line x = other / y = other
        bool low_or_far = true;
        bool operator==(const Cut&) const = default;
    };

    // A polygon of the list: a whole input polygon, or a piece of one.
    struct Piece {
        int parent = 0;                    // the input polygon it is (part of)
        std::string name;                  // "P2", pieces "P2a", "P2b", "P2ab", …
        std::vector<Cut> cuts;             // empty for a whole polygon
        std::vector<glm::dvec3> vertices;  // its outline (clipped for a piece: for tests and picture)
        glm::dvec3 lo{0}, hi{0};           // extents (padded by the margin for a piece)
        long long centres = 0;             // pixel centres it covers
        int i_lo = 0, i_hi = 0, j_lo = 0, j_hi = 0;  // the columns and rows of those centres
        bool marked = false;               // moved to the far end since the last settle or split
        bool operator==(const Piece&) const = default;
    };

    // One pair test, as the exam asks for it: which test decided, or what it forced.
    struct Decision {
        std::string p, q;
        Test test = Test::None;
        Outcome outcome = Outcome::None;
        bool operator==(const Decision&) const = default;
    };

    struct Result {
        long long width = 0, height = 0;
        std::vector<int> ids;            // width × height, row 0 at the bottom; −1 background
        std::vector<int> order;          // parents of the drawn polygons, back to front
        std::vector<std::string> names;  // the same, by name (pieces "P2a", …)
        std::vector<Decision> decisions;  // every pair test, in order
        long long pair_tests = 0;        // pairs with overlapping z extents tested
        long long moves = 0, splits = 0;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Sort, Pair, Settle, Draw, Finish, Done };

    struct State {
        Input in;
        Phase phase = Phase::Sort;
        Phase last = Phase::Sort;
        std::vector<hsr::Plane> planes;  // one per input polygon
        std::vector<std::vector<hsr::PixelSpan>> spans;  // one per input polygon: its pixels
        double margin = 0;               // the tests' rounding margin (relative 1e-9)
        std::vector<Piece> list;         // still to settle, the farthest first (P = list[0])
        std::vector<Piece> settled;      // the drawing order, back to front
        std::vector<int> ids;            // the colour buffer as polygon indices
        std::size_t q = 0;               // the next Q to test: list[q]
        std::size_t drawn = 0;           // settled pieces drawn so far
        // The step just taken.
        std::string name;                // the polygon settled or drawn
        Decision pair;                   // the pair tested, and what decided
        bool cycle = false;              // a split because Q was marked (cyclic overlaps)
        std::string split_name;          // the polygon split ...
        Cut split_cut;                   // ... by this cut
        std::vector<std::string> made;   // ... into these pieces (those covering a centre)
        long long step_pixels = 0;       // pixels written by the polygon just drawn
        std::vector<Decision> decisions;  // every pair test so far
        long long pair_tests = 0, moves = 0, splits = 0;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (painters_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same algorithm as one straight-line function, for the benchmark's comparison.
    static Result render(const Input& in);

    // Does piece p of a started run cover the point (x, y)? Its parent covers it, and it lies on
    // p's side of every cut (for the tests: the pieces of a polygon share its centres out).
    static bool covers(const State& s, const Piece& p, double x, double y);

    static const char* test_name(Test t);  // "x extents", "P behind Q's plane", …
    static std::string test_code(const Decision& d);  // "1" … "6", "same", "move", "split"
    static std::string cut_text(const Cut& cut);      // "the plane of P1", "the grid line x = 3"

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
