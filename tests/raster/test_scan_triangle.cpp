// Triangle scan conversion: exam cases worked by hand; 10,000 random triangles against a
// brute-force edge-function test at every pixel centre in exact integer arithmetic (a
// different method: no sorting, no split, no spans); random meshes of triangles sharing edges
// covering every pixel exactly once; Gouraud colours against barycentric interpolation; the
// exact orientation test against 128-bit integers; determinism and the picture.
//
// Sections: [reference] [hand cases] [random triangles] [meshes] [colours] [orient2d]
//           [errors] [determinism] [picture]
#include <algorithm>
#include <catch2/catch.hpp>

#include "support/replay.hpp"
#include <cmath>
#include <limits>
#include <map>

#include "core/timeline.hpp"
#include "io/registry.hpp"
#include "raster/orient2d.hpp"
#include "raster/scan_triangle.hpp"
#include "support/traced.hpp"

using cg::ScanTriangle;
using glm::dvec2;
using glm::ivec2;

namespace {

// ---- [reference] ----------------------------------------------------------------------------
// Vertices on a grid of 1/2^kBits pixel are integers after scaling, and so are pixel centres
// ((2i + 1)/2 = (2i + 1)·2^(kBits − 1) units), so the edge functions below are exact.

__extension__ typedef __int128 i128;
constexpr int kBits = 10;
constexpr double kUnit = 1.0 / (1 << kBits);

struct Fix {
    long long x, y;
};

Fix fix(dvec2 p) {
    const double sx = p.x * (1 << kBits), sy = p.y * (1 << kBits);
    REQUIRE(sx == std::floor(sx));  // the test only builds inputs on the grid
    REQUIRE(sy == std::floor(sy));
    return {static_cast<long long>(sx), static_cast<long long>(sy)};
}

i128 edge(Fix a, Fix b, Fix p) {
    return i128(b.x - a.x) * (p.y - a.y) - i128(b.y - a.y) * (p.x - a.x);
}

// With the triangle counter-clockwise (inside to the left of each edge), y up: a left edge
// goes down (inside on its +x side), a top edge is horizontal going −x (inside below it).
bool top_or_left(Fix a, Fix b) {
    return b.y < a.y || (b.y == a.y && b.x < a.x);
}

// Every pixel (i, j) of the grid whose centre is inside or on an edge the top-left rule keeps,
// sorted by j then i: the brute-force definition of the fill rule.
std::vector<ivec2> brute_force(const std::vector<dvec2>& t, int w, int h) {
    Fix a = fix(t[0]), b = fix(t[1]), c = fix(t[2]);
    const i128 area2 = edge(a, b, c);
    if (area2 == 0) return {};
    if (area2 < 0) std::swap(b, c);
    std::vector<ivec2> out;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const long long half = 1LL << (kBits - 1);
            const Fix p{(2LL * i + 1) * half, (2LL * j + 1) * half};
            bool in = true;
            for (auto [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
                const i128 e = edge(u, v, p);
                in = in && (e > 0 || (e == 0 && top_or_left(u, v)));
            }
            if (in) out.push_back({i, j});
        }
    return out;
}

std::vector<ivec2> pixels_of(const ScanTriangle::Input& in) {
    const auto r = cg::run_to_end<ScanTriangle>(ScanTriangle::start(in));
    return r.pixels;
}

struct Traced {
    ScanTriangle::Result result;
    std::vector<cg::StepInfo> steps;
};

Traced run_traced(const ScanTriangle::Input& in) {
    Traced t;
    auto s = ScanTriangle::start(in);
    while (!ScanTriangle::done(s)) {
        cg::StepInfo info;
        ScanTriangle::step(s, &info);
        t.steps.push_back(info);
    }
    t.result = ScanTriangle::result(s);
    return t;
}

using cg::test::events;

using Spans = std::vector<std::array<int, 3>>;

}  // namespace

// ---- [hand cases] -----------------------------------------------------------------------------

TEST_CASE("scan-triangle: exam cases worked by hand", "[raster][scan-triangle]") {
    struct Case {
        const char* name;
        int w, h;
        std::vector<dvec2> triangle;
        Spans spans;
        std::optional<dvec2> split;
        std::array<std::optional<double>, 3> slopes;
        std::vector<std::string> events;
    };
    const std::vector<Case> cases = {
        // x + y = 4 passes through four centres; it is a right edge (inside to its left): out.
        {"right triangle, hypotenuse through centres",
         8,
         8,
         {{0, 0}, {4, 0}, {0, 4}},
         {{0, 0, 2}, {1, 0, 1}, {2, 0, 0}},
         dvec2(0, 0),
         {0.0, std::nullopt, -1.0},
         {"sort", "flat-edge", "slopes", "span", "span", "span", "empty-span", "done"}},
        // The diagonal y = x is a left edge of this triangle: its centres are in.
        {"lower-right half of a square",
         8,
         8,
         {{0, 0}, {4, 0}, {4, 4}},
         {{0, 0, 3}, {1, 1, 3}, {2, 2, 3}, {3, 3, 3}},
         dvec2(0, 0),
         {1.0, std::nullopt, 0.0},
         {"sort", "flat-edge", "slopes", "span", "span", "span", "span", "done"}},
        // ... and a right edge of this one: out. Together the halves cover the square once.
        {"upper-left half of a square",
         8,
         8,
         {{0, 0}, {4, 4}, {0, 4}},
         {{1, 0, 0}, {2, 0, 1}, {3, 0, 2}},
         dvec2(4, 4),
         {1.0, 0.0, std::nullopt},
         {"sort", "flat-edge", "slopes", "empty-span", "span", "span", "span", "done"}},
        // Bottom edge y = ½ through three centres: a horizontal bottom edge, out.
        {"flat bottom on centres",
         6,
         4,
         {{0.5, 0.5}, {4.5, 0.5}, {2.5, 2.5}},
         {{1, 1, 2}},
         dvec2(0.5, 0.5),
         {1.0, std::nullopt, -1.0},
         {"sort", "flat-edge", "slopes", "span", "empty-span", "done"}},
        // Top edge y = 2.5 through five centres: a horizontal top edge, in — but not its right
        // end (4.5, 2.5), which is also on a right edge.
        {"flat top on centres",
         6,
         4,
         {{0.5, 2.5}, {4.5, 2.5}, {2.5, 0.5}},
         {{1, 1, 2}, {2, 0, 3}},
         dvec2(4.5, 2.5),
         {1.0, -1.0, std::nullopt},
         {"sort", "flat-edge", "slopes", "span", "span", "done"}},
        // Split at y1 = 2.5, where the middle vertex (0.5, 2.5) is itself a centre on two left
        // edges: in. The right side is the vertical x = 2.
        {"general, middle vertex on a centre",
         4,
         6,
         {{2, 0}, {0.5, 2.5}, {2, 5}},
         {{1, 1, 1}, {2, 0, 1}, {3, 1, 1}},
         dvec2(2, 2.5),
         {0.0, -0.6, 0.6},
         {"sort", "split", "slopes", "empty-span", "span", "span", "span", "empty-span", "done"}},
        // x_left = 1.5 + (y − 0.5)·1.5/7, x_right from (8, 3): the example of the lesson.
        {"the lesson's example",
         10,
         8,
         {{1.5, 0.5}, {8, 3}, {3, 7.5}},
         {{1, 2, 3}, {2, 2, 6}, {3, 2, 6}, {4, 2, 5}, {5, 3, 4}, {6, 3, 3}},
         dvec2(1.5 + 2.5 * 1.5 / 7, 3),
         {1.5 / 7, 2.6, -5 / 4.5},
         {"sort", "split", "slopes", "span", "span", "span", "span", "span", "span", "empty-span",
          "done"}},
        // Clipped: x_right = 6 − 2y runs past the 3-pixel-wide grid on the two lower rows.
        {"clipped to a 3 × 3 grid",
         3,
         3,
         {{-2, 0}, {6, 0}, {-2, 4}},
         {{0, 0, 2}, {1, 0, 2}, {2, 0, 0}},
         dvec2(-2, 0),
         {0.0, std::nullopt, -2.0},
         {"sort", "flat-edge", "slopes", "span", "span", "span", "done"}},
        {"collinear",
         8,
         8,
         {{0, 0}, {2, 2}, {4, 4}},
         {},
         std::nullopt,
         {std::nullopt, std::nullopt, std::nullopt},
         {"sort", "collinear", "done"}},
        {"two equal vertices",
         8,
         8,
         {{1, 1}, {1, 1}, {5, 3}},
         {},
         std::nullopt,
         {std::nullopt, std::nullopt, std::nullopt},
         {"sort", "collinear", "done"}},
        // Thin: no centre y = j + ½ lies in (0.625, 1.375].
        {"between two rows of centres",
         8,
         8,
         {{0, 0.625}, {7, 1}, {1, 1.375}},
         {},
         dvec2(0.5, 1),
         {1 / 0.75, 7 / 0.375, -16.0},
         {"sort", "split", "slopes", "done"}},
        {"entirely outside the grid",
         4,
         4,
         {{5, 5}, {8, 5}, {5, 8}},
         {},
         dvec2(5, 5),
         {0.0, std::nullopt, -1.0},
         {"sort", "flat-edge", "slopes", "done"}},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.name) {
            const ScanTriangle::Input in{c.w, c.h, c.triangle, {}};
            const Traced t = run_traced(in);
            CHECK(events(t) == c.events);
            CHECK(t.result.spans == c.spans);
            std::vector<ivec2> pixels;
            for (const auto& s : c.spans)
                for (int i = s[1]; i <= s[2]; ++i) pixels.push_back({i, s[0]});
            CHECK(t.result.pixels == pixels);
            CHECK(t.result.pixels == brute_force(c.triangle, c.w, c.h));
            REQUIRE(t.result.split.has_value() == c.split.has_value());
            if (c.split) {
                CHECK(t.result.split->x == Approx(c.split->x));
                CHECK(t.result.split->y == c.split->y);
            }
            for (int e = 0; e < 3; ++e) {
                REQUIRE(t.result.inverse_slopes[e].has_value() == c.slopes[e].has_value());
                if (c.slopes[e]) CHECK(*t.result.inverse_slopes[e] == Approx(*c.slopes[e]));
            }
            CHECK(ScanTriangle::scan(in) == t.result);  // the straight-line version agrees
        }
    }
}

TEST_CASE("scan-triangle: each step reports its line, numbers and variables",
          "[raster][scan-triangle]") {
    const Traced t = run_traced({10, 8, {{1.5, 0.5}, {8, 3}, {3, 7.5}}, {}});
    REQUIRE(t.steps.size() == 11);
    CHECK(t.steps[0].line == 1);
    CHECK(t.steps[0].narration ==
          "Sorted by y: v0 = (1.5, 0.5) (P0), v1 = (8, 3) (P1), v2 = (3, 7.5) (P2). The long edge "
          "v0→v2 spans the whole height, y = 0.5 to 7.5.");
    CHECK(t.steps[1].line == 2);
    CHECK_THAT(t.steps[1].narration, Catch::StartsWith("The line y = y1 = 3 meets the long edge at "
                                                       "x_split = 1.5 + (2.5/7)·1.5 = 2.036"));
    CHECK(t.steps[2].narration ==
          "Inverse slopes dx/dy: v0→v2 m = 1.5/7 = 0.2143; v0→v1 m = 6.5/2.5 = 2.6; v1→v2 m = "
          "−5/4.5 = −1.111. Scanlines j = 1 to 7 have their centre y = j + ½ in (0.5, 7.5].");
    CHECK(t.steps[5].line == 8);
    CHECK(t.steps[5].narration ==
          "Scanline j = 3, y = 3.5 (upper part): x_left = 1.5 + (3.5 − 0.5)·0.2143 = 2.143 on "
          "v0→v2, x_right = 8 + (3.5 − 3)·(−1.111) = 7.444 on v1→v2. Fill i = 2 to 6 (⌈2.143 − ½⌉ "
          "= 2 to ⌈7.444 − ½⌉ − 1 = 6): 5 pixels.");
    CHECK(t.steps[10].narration == "Every scanline is done: 19 pixels filled.");
    auto find = [&](const cg::StepInfo& s, const std::string& name) {
        for (const auto& v : s.vars)
            if (v.name == name) return v.value;
        FAIL("no variable " << name);
        return cg::Value{};
    };
    CHECK(std::get<long long>(find(t.steps[5], "j")) == 3);
    CHECK(std::get<double>(find(t.steps[5], "y")) == 3.5);
    CHECK(std::get<std::string>(find(t.steps[5], "part")) == "upper");
    CHECK(std::get<long long>(find(t.steps[5], "i_first")) == 2);
    CHECK(std::get<long long>(find(t.steps[5], "i_last")) == 6);
    CHECK(std::get<long long>(find(t.steps[5], "filled")) == 12);
    for (const auto& s : t.steps) {
        bool declared = false;
        for (const auto& e : ScanTriangle::spec().events) declared = declared || e.id == s.event;
        CHECK(declared);
        CHECK(s.line >= 1);
        CHECK(s.line <= int(ScanTriangle::spec().pseudocode.size()));
    }
}

// ---- [random triangles] -----------------------------------------------------------------------

namespace {

// A coordinate in [lo, hi] on the test grid, of the kind the trial asks for.
double coordinate(cg::Rng& rng, double lo, double hi, int kind) {
    switch (kind) {
        case 0:
            return std::round(rng.uniform(lo, hi) / kUnit) * kUnit;  // 1/1024 pixel
        case 1:
            return std::round(rng.uniform(lo, hi));  // whole
        case 2:
            return std::floor(rng.uniform(lo, hi)) + 0.5;  // on centres
        case 3:
            return std::round(rng.uniform(lo, hi) * 2) / 2;  // whole or half
        default:
            return std::round(rng.uniform(lo, hi) * 4) / 4;  // quarters
    }
}

}  // namespace

TEST_CASE("scan-triangle: 10,000 random triangles agree with the brute-force edge functions",
          "[raster][scan-triangle]") {
    int filled = 0, degenerate = 0, on_edge_centres = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        cg::Rng rng(trial);
        const int w = static_cast<int>(rng.integer(1, 40)),
                  h = static_cast<int>(rng.integer(1, 40));
        const int kind = static_cast<int>(rng.integer(0, 4));
        auto point = [&] {
            return dvec2(coordinate(rng, -5, w + 5, kind), coordinate(rng, -5, h + 5, kind));
        };
        std::vector<dvec2> t{point(), point(), point()};
        switch (trial % 10) {
            case 1:
                t[1].y = t[0].y;
                break;  // a horizontal edge
            case 2:
                t[2].y = t[1].y;
                break;
            case 3: {  // collinear (on the grid: t = k/8)
                const double s = static_cast<double>(rng.integer(-16, 16)) / 8;
                t[2] = t[0] + s * (t[1] - t[0]);
                t[2] = {std::round(t[2].x / kUnit) * kUnit, std::round(t[2].y / kUnit) * kUnit};
                break;
            }
            case 4:
                t[1] = t[0];
                break;  // two vertices equal: zero area
            case 5:
                t[0] = {std::floor(t[0].x) + 0.5, std::floor(t[0].y) + 0.5};
                break;  // on a centre
            default:
                break;
        }
        CAPTURE(trial, w, h, t[0].x, t[0].y, t[1].x, t[1].y, t[2].x, t[2].y);
        const ScanTriangle::Input in{w, h, t, {}};
        const auto r = cg::run_to_end<ScanTriangle>(ScanTriangle::start(in));
        const auto expected = brute_force(t, w, h);
        REQUIRE(r.pixels == expected);
        REQUIRE(ScanTriangle::scan(in) == r);
        // The spans describe the same pixels.
        std::size_t count = 0;
        for (const auto& s : r.spans) count += static_cast<std::size_t>(s[2] - s[1] + 1);
        REQUIRE(count == r.pixels.size());
        filled += !r.pixels.empty();
        degenerate += !r.split;
        // How often a centre sat exactly on an edge (the cases the rule decides).
        Fix a = fix(t[0]), b = fix(t[1]), c = fix(t[2]);
        if (edge(a, b, c) != 0)
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    const long long half = 1LL << (kBits - 1);
                    const Fix p{(2LL * i + 1) * half, (2LL * j + 1) * half};
                    on_edge_centres +=
                        edge(a, b, p) == 0 || edge(b, c, p) == 0 || edge(c, a, p) == 0;
                }
    }
    CHECK(filled > 6000);
    CHECK(degenerate > 1200);
    CHECK(on_edge_centres > 10000);  // ties are exercised, not just generic positions
}

TEST_CASE("scan-triangle: random doubles agree with edge functions in long double",
          "[raster][scan-triangle]") {
    // Arbitrary doubles: a centre within rounding of an edge is then vanishingly rare, so long
    // double is a fair reference here (the exact cases are covered above).
    for (int trial = 0; trial < 2000; ++trial) {
        cg::Rng rng(1'000'000 + trial);
        const int w = static_cast<int>(rng.integer(1, 30)),
                  h = static_cast<int>(rng.integer(1, 30));
        std::vector<dvec2> t;
        for (int k = 0; k < 3; ++k) t.push_back({rng.uniform(-3, w + 3), rng.uniform(-3, h + 3)});
        CAPTURE(trial, t[0].x, t[0].y, t[1].x, t[1].y, t[2].x, t[2].y);
        using ld = long double;
        auto e = [](dvec2 a, dvec2 b, ld px, ld py) {
            return (ld(b.x) - a.x) * (py - a.y) - (ld(b.y) - a.y) * (px - a.x);
        };
        dvec2 a = t[0], b = t[1], c = t[2];
        const ld area2 = e(a, b, c.x, c.y);
        if (area2 < 0) std::swap(b, c);
        std::vector<ivec2> expected;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const ld px = i + 0.5L, py = j + 0.5L;
                if (e(a, b, px, py) > 0 && e(b, c, px, py) > 0 && e(c, a, px, py) > 0)
                    expected.push_back({i, j});
            }
        REQUIRE(pixels_of({w, h, t, {}}) == expected);
    }
}

// ---- [meshes] ----------------------------------------------------------------------------------

TEST_CASE("scan-triangle: triangles sharing edges cover every pixel exactly once",
          "[raster][scan-triangle]") {
    int meshes = 0;
    for (int trial = 0; trial < 300; ++trial) {
        cg::Rng rng(2'000'000 + trial);
        CAPTURE(trial);
        const int nx = static_cast<int>(rng.integer(2, 6)),
                  ny = static_cast<int>(rng.integer(2, 6));
        const double step = static_cast<double>(rng.integer(3, 7));
        // The hull is a rectangle with whole or half corners; inside points are jittered, and
        // some are snapped to pixel centres or to whole numbers so edges meet centres exactly.
        const double x0 = std::round(rng.uniform(-2, 3) * 2) / 2,
                     y0 = std::round(rng.uniform(-2, 3) * 2) / 2;
        std::vector<dvec2> grid((nx + 1) * (ny + 1));
        auto at = [&](int i, int j) -> dvec2& { return grid[j * (nx + 1) + i]; };
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                dvec2 p{x0 + i * step, y0 + j * step};
                if (i > 0 && i < nx && j > 0 && j < ny) {
                    p += dvec2(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)) * step;
                    const int snap = static_cast<int>(rng.integer(0, 2));
                    if (snap == 0)
                        p = {std::floor(p.x) + 0.5, std::floor(p.y) + 0.5};
                    else if (snap == 1)
                        p = {std::round(p.x), std::round(p.y)};
                    else
                        p = {std::round(p.x / kUnit) * kUnit, std::round(p.y / kUnit) * kUnit};
                }
                at(i, j) = p;
            }
        const int w = static_cast<int>(std::ceil(x0 + nx * step)) + 2;
        const int h = static_cast<int>(std::ceil(y0 + ny * step)) + 2;
        // Each quad cut by one of its diagonals, chosen at random.
        std::vector<std::vector<dvec2>> triangles;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const dvec2 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
                if (rng.chance(0.5))
                    triangles.push_back({a, b, c}), triangles.push_back({a, c, d});
                else
                    triangles.push_back({a, b, d}), triangles.push_back({b, c, d});
            }
        // Snapping can fold a thin triangle over; such a mesh is not a tiling, so skip it.
        if (std::any_of(triangles.begin(), triangles.end(),
                        [](const auto& t) { return cg::orient2d(t[0], t[1], t[2]) <= 0; }))
            continue;
        ++meshes;
        std::vector<int> count(static_cast<std::size_t>(w) * h, 0);
        for (const auto& t : triangles)
            for (const ivec2 p : pixels_of({w, h, t, {}})) ++count[p.y * w + p.x];
        // The union is the rectangle [x0, x1] × [y0, y1]: by the rule its left side and top
        // belong to it, its right side and bottom do not.
        const double x1 = x0 + nx * step, y1 = y0 + ny * step;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const double cx = i + 0.5, cy = j + 0.5;
                const int expected = (x0 <= cx && cx < x1 && y0 < cy && cy <= y1) ? 1 : 0;
                CAPTURE(i, j);
                REQUIRE(count[j * w + i] == expected);
            }
    }
    CHECK(meshes > 250);
}

// ---- [colours] ---------------------------------------------------------------------------------

TEST_CASE("scan-triangle: Gouraud colours equal barycentric interpolation at the centres",
          "[raster][scan-triangle]") {
    for (int trial = 0; trial < 500; ++trial) {
        cg::Rng rng(3'000'000 + trial);
        CAPTURE(trial);
        const int w = 24, h = 20;
        std::vector<dvec2> t;
        std::vector<glm::dvec3> colors;
        for (int k = 0; k < 3; ++k) {
            t.push_back({rng.uniform(-2, w + 2), rng.uniform(-2, h + 2)});
            colors.push_back({rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)});
        }
        const ScanTriangle::Input in{w, h, t, colors};
        const auto r = cg::run_to_end<ScanTriangle>(ScanTriangle::start(in));
        REQUIRE(r.colors.size() == r.pixels.size());
        REQUIRE(r.pixels == pixels_of({w, h, t, {}}));  // colours change nothing else
        REQUIRE(ScanTriangle::scan(in) == r);
        const double area2 =
            (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
        for (std::size_t k = 0; k < r.pixels.size(); ++k) {
            const dvec2 p{r.pixels[k].x + 0.5, r.pixels[k].y + 0.5};
            auto sub = [&](dvec2 a, dvec2 b) {
                return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
            };
            const double l0 = sub(t[1], t[2]) / area2, l1 = sub(t[2], t[0]) / area2,
                         l2 = sub(t[0], t[1]) / area2;
            const glm::dvec3 expected = l0 * colors[0] + l1 * colors[1] + l2 * colors[2];
            for (int c = 0; c < 3; ++c) REQUIRE(std::fabs(r.colors[k][c] - expected[c]) < 1e-9);
        }
    }
}

// ---- [orient2d] --------------------------------------------------------------------------------

TEST_CASE("orient2d: exact on nearly collinear points, against 128-bit integers",
          "[raster][orient2d]") {
    // Coordinates are multiples of 2^-48 below 16, so scaled by 2^48 they are integers below
    // 2^52 and every product fits in 128 bits. p is put within a few units of the line ab,
    // where the plain double formula often gets the sign wrong.
    constexpr double kScale = 0x1p48;
    int zero = 0, wrong_plain = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        cg::Rng rng(4'000'000 + trial);
        auto grid = [&](double v) { return std::round(v * kScale) / kScale; };
        const dvec2 a{grid(rng.uniform(0, 16)), grid(rng.uniform(0, 16))};
        const dvec2 b{grid(rng.uniform(0, 16)), grid(rng.uniform(0, 16))};
        const double t = rng.uniform(-0.5, 1.5);
        dvec2 p = a + t * (b - a);
        p = {grid(p.x) + static_cast<double>(rng.integer(-2, 2)) / kScale,
             grid(p.y) + static_cast<double>(rng.integer(-2, 2)) / kScale};
        if (trial % 4 == 0)
            p = a + static_cast<double>(rng.integer(-3, 3)) * (b - a);  // exactly on it
        CAPTURE(trial, a.x, a.y, b.x, b.y, p.x, p.y);
        auto big = [&](double v) { return static_cast<i128>(static_cast<long long>(v * kScale)); };
        const i128 det = (big(b.x) - big(a.x)) * (big(p.y) - big(a.y)) -
                         (big(b.y) - big(a.y)) * (big(p.x) - big(a.x));
        const int expected = (det > 0) - (det < 0);
        REQUIRE(cg::orient2d(a, b, p) == expected);
        zero += expected == 0;
        const double plain = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        wrong_plain += ((plain > 0) - (plain < 0)) != expected;
    }
    CHECK(zero > 4000);
    CHECK(wrong_plain > 100);  // the cases where exactness matters were really exercised
}

// ---- [errors] ----------------------------------------------------------------------------------

TEST_CASE("scan-triangle: bad input names the field", "[raster][scan-triangle]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<dvec2> t{{0, 0}, {4, 0}, {0, 4}};
    CHECK_THROWS_WITH(ScanTriangle::start({0, 8, t, {}}),
                      "width: must be a whole number of pixels from 1 to 4096 (got 0)");
    CHECK_THROWS_WITH(ScanTriangle::start({8, 5000, t, {}}),
                      "height: must be a whole number of pixels from 1 to 4096 (got 5000)");
    CHECK_THROWS_WITH(ScanTriangle::start({8, 8, {{0, 0}, {1, 1}}, {}}),
                      "triangle: must have exactly 3 vertices (got 2)");
    CHECK_THROWS_WITH(ScanTriangle::start({8, 8, {{0, 0}, {nan, 1}, {2, 2}}, {}}),
                      "triangle[1][0]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(ScanTriangle::start({8, 8, {{0, 0}, {1, 1}, {2, -inf}}, {}}),
                      "triangle[2][1]: must be a finite number (got -inf)");
    CHECK_THROWS_WITH(ScanTriangle::start({8, 8, {{0, 0}, {1, 1}, {2e9, 0}}, {}}),
                      "triangle[2][0]: must lie within ±1e9 pixels of the origin (got 2000000000)");
    CHECK_THROWS_WITH(ScanTriangle::start({8, 8, t, {{1, 0, 0}, {0, 1, 0}}}),
                      "colors: must give one colour per vertex, 3 in all (got 2)");
    CHECK_THROWS_WITH(ScanTriangle::start({8, 8, t, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1.5}}}),
                      "colors[2][2]: must be from 0 to 1 (got 1.5)");

    // Through JSON: wrong point sizes, non-integer sizes, unknown fields.
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("scan-triangle");
    auto error = [&](const std::string& text) {
        try {
            a.create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(error(R"({"width": 8, "height": 8, "triangle": [[0, 0], [1], [2, 2]]})") ==
          "triangle[1]: must be a point [x, y], got an array ([1])");
    CHECK_THAT(error(R"({"width": 8.5, "height": 8, "triangle": [[0, 0], [1, 0], [2, 2]]})"),
               Catch::StartsWith("width: must be an integer"));
    CHECK_THAT(
        error(R"({"width": 8, "height": 8, "triangle": [[0, 0], [1, 0], [2, 2]], "colours": []})"),
        Catch::StartsWith("colours: is not a known field"));
    CHECK(
        error(
            R"({"width": 8, "height": 8, "triangle": [[0, 0], [1, 0], [2, 2]], "colors": [[1, 0], [0, 1, 0], [0, 0, 1]]})") ==
        "colors[0]: must be a point [x, y, z], got an array ([1,0])");
    // Collinear vertices are not an error: the result is simply empty.
    auto run = a.create(
        cg::parse_json(R"({"width": 8, "height": 8, "triangle": [[0, 0], [1, 1], [2, 2]]})"));
    while (!run->done()) run->step(nullptr);
    const cg::json r = a.result(*run);
    CHECK(r["pixels"] == cg::json::array());
    CHECK(r["split"].is_null());
    CHECK_FALSE(r.contains("colors"));
}

// ---- [determinism] -----------------------------------------------------------------------------

TEST_CASE("scan-triangle: traces are deterministic and stepping back reproduces them",
          "[raster][scan-triangle]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("scan-triangle");
    REQUIRE(a);
    cg::json input = a->example();
    input["colors"] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

    cg::test::check_replay(*a, input, 5);
}

// ---- [picture] ---------------------------------------------------------------------------------

TEST_CASE("scan-triangle: the picture shows the grid, the triangle, the split and the scanline",
          "[raster][scan-triangle]") {
    auto s = ScanTriangle::start({10, 8, {{1.5, 0.5}, {8, 3}, {3, 7.5}}, {}});
    for (int k = 0; k < 6; ++k) ScanTriangle::step(s, nullptr);  // sort, split, slopes, j = 1..3
    cg::Scene scene;
    ScanTriangle::draw(s, scene);
    REQUIRE(scene.grids.size() == 1);
    const cg::PixelGrid2& g = scene.grids[0];
    CHECK(g.width == 10);
    CHECK(g.height == 8);
    int filled = 0;
    for (std::uint32_t v : g.rgba) filled += v != 0;
    CHECK(filled == 12);  // rows 1 to 3
    CHECK(g.rgba[1 * 10 + 2] == cg::PixelGrid2::kRoleColour);
    CHECK(g.rgba[0 * 10 + 1] == 0);  // (1, 0): its centre is the bottom vertex, not filled
    bool scanline = false, dashed_split = false;
    for (const auto& seg : scene.segments) {
        scanline = scanline || (seg.style.role == cg::Role::Active && seg.a.y == 3.5);
        dashed_split = dashed_split || (seg.style.role == cg::Role::Construction &&
                                        seg.style.dashed && seg.a.y == 3);
    }
    CHECK(scanline);
    CHECK(dashed_split);
    int entering = 0, leaving = 0;
    for (const auto& p : scene.points) {
        entering += p.style.role == cg::Role::Entering;
        leaving += p.style.role == cg::Role::Leaving;
    }
    CHECK(entering == 1);
    CHECK(leaving == 1);
    REQUIRE(scene.handles.size() == 3);
    CHECK(scene.handles[1].x_field == "/triangle/1/0");

    // Gouraud colours go into the cells as they are.
    auto c =
        ScanTriangle::start({4, 4, {{0, 0}, {4, 0}, {0, 4}}, {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}});
    while (!ScanTriangle::done(c)) ScanTriangle::step(c, nullptr);
    cg::Scene coloured;
    ScanTriangle::draw(c, coloured);
    CHECK(coloured.grids[0].rgba[0] == 0xff0000ffu);
}
