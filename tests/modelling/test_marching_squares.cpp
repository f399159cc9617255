// Marching squares: hand-worked cells (an ordinary case, both saddles either way, a corner
// exactly at iso); the 16-case table against the rule it comes from (a segment runs from an
// edge where the counter-clockwise walk round the cell leaves the inside to one where it
// enters it; saddles paired by the centre average); 4,000 seeded random grids (integer values,
// so corners equal to iso and saddles with the centre exactly at iso are common, and real
// values) against an independent long-double reference: every segment endpoint on an edge of
// its cell whose corners differ, the interpolated value there equal to iso within 1e-12, every
// such edge used once, the orientation and the saddle decision, the case grid, the crossings;
// the circle closes into one loop whose length tends to 2πr at second order; two blobs merge
// as their radius grows; the state machine against compute; steps, batching, errors, replay,
// the exam problems and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "modelling/marching_squares.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::MarchingSquares;
using MS = MarchingSquares;
using Input = MS::Input;
using LD = long double;

namespace {

Input grid(std::vector<std::vector<double>> values, double iso = 0) {
    Input in;
    in.field = MS::Field::Grid;
    in.values = std::move(values);
    in.iso = iso;
    return in;
}

Input named(MS::Field f, int cells, double radius, double iso = 0, std::uint64_t seed = 1) {
    Input in;
    in.field = f;
    in.cells = cells;
    in.radius = radius;
    in.iso = iso;
    in.seed = seed;
    return in;
}

// ---- the reference, in long double, written apart from the code ----

struct RefEdge {
    LD ax, ay, bx, by;  // the edge's ends, lower coordinate first
    LD fa, fb;
    bool changes;
    LD px, py;  // the crossing
};

// The cell's four edges in the order bottom, right, top, left, as plain geometry.
std::array<RefEdge, 4> ref_edges(const MS::Grid& g, int i, int j, LD iso) {
    // The grid points as the input defines them (origin + h·(i, j), in double), then widened.
    auto P = [&](int a, int b) {
        const glm::dvec2 q = g.origin + g.h * glm::dvec2(a, b);
        return std::pair<LD, LD>{LD(q.x), LD(q.y)};
    };
    const int ends[4][4] = {{i, j, i + 1, j}, {i + 1, j, i + 1, j + 1}, {i, j + 1, i + 1, j + 1},
                            {i, j, i, j + 1}};
    std::array<RefEdge, 4> out{};
    for (int e = 0; e < 4; ++e) {
        RefEdge& r = out[std::size_t(e)];
        auto [ax, ay] = P(ends[e][0], ends[e][1]);
        auto [bx, by] = P(ends[e][2], ends[e][3]);
        r = {ax, ay, bx, by, LD(g.at(ends[e][0], ends[e][1])), LD(g.at(ends[e][2], ends[e][3])),
             false, 0, 0};
        r.changes = (r.fa < iso) != (r.fb < iso);
        if (r.changes) {
            const LD t = (iso - r.fa) / (r.fb - r.fa);
            r.px = ax + t * (bx - ax);
            r.py = ay + t * (by - ay);
        }
    }
    return out;
}

// Which edge of the cell a point lies on, among those whose corners differ: the one whose
// reference crossing it matches (an endpoint at a corner may match two; take the unused one).
struct Check {
    long long endpoints = 0, saddles = 0, joined = 0, at_corner = 0, cells = 0, near = 0;
};

// `exact`: small integers, whose sums are exact in double too, so even a centre exactly at iso
// has one right answer (separated).
void check_against_reference(const Input& in, const MS::Result& r, Check& tally,
                             bool exact = false) {
    const MS::Grid g = MS::sample(in);
    const LD iso = in.iso;
    REQUIRE(r.nx == g.nx);
    REQUIRE(r.ny == g.ny);
    REQUIRE(r.cases.size() == std::size_t(g.nx * g.ny));
    std::size_t next = 0;       // the next segment of r, in scan order
    std::size_t crossings = 0;  // sign changes on grid edges, each counted once
    const LD scale = std::max<LD>(1, std::fabs(LD(g.h)) * std::max(g.nx, g.ny) + 2);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const LD f[4] = {LD(g.at(i, j)), LD(g.at(i + 1, j)), LD(g.at(i + 1, j + 1)),
                             LD(g.at(i, j + 1))};
            int bits = 0;
            for (int k = 0; k < 4; ++k) bits += (f[k] < iso ? 1 : 0) * (1 << k);
            CHECK(int(r.cases[std::size_t(j * g.nx + i)]) == bits);
            const auto edges = ref_edges(g, i, j, iso);
            int changes = 0;
            for (int e = 0; e < 4; ++e) changes += edges[std::size_t(e)].changes;
            crossings += std::size_t(edges[1].changes) + edges[2].changes +
                         (j == 0 ? edges[0].changes : 0) + (i == 0 ? edges[3].changes : 0);
            REQUIRE(changes % 2 == 0);
            const int n = changes / 2;
            if (n == 0) continue;
            ++tally.cells;
            REQUIRE(next + std::size_t(n) <= r.segments.size());
            // Leaving / entering edges on the counter-clockwise walk 0 → 1 → 2 → 3 → 0.
            auto leaving = [&](int e) {
                const bool in_from = f[e] < iso, in_to = f[(e + 1) % 4] < iso;
                return in_from && !in_to;
            };
            std::array<bool, 4> used{};
            std::vector<std::array<int, 2>> pairs;
            for (int k = 0; k < n; ++k) {
                const MS::Segment& s = r.segments[next + std::size_t(k)];
                int found[2] = {-1, -1};
                const glm::dvec2 ends[2] = {s.a, s.b};
                for (int end = 0; end < 2; ++end) {
                    for (int e = 0; e < 4 && found[end] < 0; ++e) {
                        const RefEdge& re = edges[std::size_t(e)];
                        if (!re.changes || used[std::size_t(e)]) continue;
                        // On the edge's line exactly, and between its ends.
                        const LD x = ends[end].x, y = ends[end].y;
                        const bool vertical = re.ax == re.bx;
                        if (vertical ? x != re.ax : y != re.ay) continue;
                        const LD u = vertical ? (y - re.ay) / (re.by - re.ay)
                                              : (x - re.ax) / (re.bx - re.ax);
                        if (u < 0 || u > 1) continue;
                        // The interpolated value there is iso.
                        const LD value = re.fa + u * (re.fb - re.fa);
                        const LD fs = std::max<LD>({1, std::fabs(re.fa), std::fabs(re.fb)});
                        if (std::fabs(value - iso) > 1e-12L * fs) continue;
                        if (std::fabs(x - re.px) + std::fabs(y - re.py) > 1e-12L * scale)
                            continue;
                        // The start of a segment on a leaving edge, its end on an entering one.
                        if ((end == 0) != leaving(e)) continue;
                        found[end] = e;
                        used[std::size_t(e)] = true;
                        tally.at_corner += (u == 0 || u == 1);
                    }
                    INFO("cell " << i << "," << j << " case " << bits << " segment " << k
                                 << " end " << end);
                    REQUIRE(found[end] >= 0);
                    ++tally.endpoints;
                }
                CHECK(s.ea == MS::edge_id(g, i, j, found[0]));
                CHECK(s.eb == MS::edge_id(g, i, j, found[1]));
                pairs.push_back({found[0], found[1]});
            }
            for (int e = 0; e < 4; ++e) CHECK(used[std::size_t(e)] == edges[std::size_t(e)].changes);
            if (n == 2) {
                // A saddle: the centre average decides; joined pairs a leaving edge with the
                // next edge counter-clockwise (around an outside corner), separated with the
                // one before (around an inside corner).
                ++tally.saddles;
                const LD m = (f[0] + f[1] + f[2] + f[3]) / 4;
                // Within rounding of iso (integer multiples of 1e-7, say, whose exact average is
                // iso) either decision is right, as long as both segments follow it.
                const LD fs = std::fabs(f[0]) + std::fabs(f[1]) + std::fabs(f[2]) + std::fabs(f[3]);
                const bool near = !exact && std::fabs(m - iso) <= 1e-15L * fs;
                tally.near += near;
                const bool joined = near ? pairs[0][1] == (pairs[0][0] + 1) % 4 : m < iso;
                tally.joined += joined;
                for (const auto& p : pairs) CHECK(p[1] == (joined ? (p[0] + 1) % 4 : (p[0] + 3) % 4));
            }
            next += std::size_t(n);
        }
    CHECK(next == r.segments.size());
    CHECK(r.crossings.size() == crossings);
    LD length = 0;
    for (const auto& s : r.segments) length += std::hypot(LD(s.b.x - s.a.x), LD(s.b.y - s.a.y));
    CHECK(std::fabs(double(length) - r.length) <= 1e-12 * std::max(1.0, r.length));
    long long inside = 0;
    for (double v : g.f) inside += LD(v) < iso;
    CHECK(r.inside == inside);
}

// Loops by a walk written apart: follow b → the segment starting at the same point.
long long ref_loops(const MS::Result& r) {
    std::map<std::pair<double, double>, std::vector<std::size_t>> starts;
    for (std::size_t k = 0; k < r.segments.size(); ++k)
        starts[{r.segments[k].a.x, r.segments[k].a.y}].push_back(k);
    std::vector<bool> seen(r.segments.size());
    long long loops = 0;
    for (std::size_t k0 = 0; k0 < r.segments.size(); ++k0) {
        if (seen[k0]) continue;
        std::size_t k = k0;
        bool closed = false;
        for (std::size_t guard = 0; guard <= r.segments.size(); ++guard) {
            seen[k] = true;
            auto it = starts.find({r.segments[k].b.x, r.segments[k].b.y});
            if (it == starts.end()) break;
            k = it->second.front();
            if (k == k0) {
                closed = true;
                break;
            }
            if (seen[k]) break;
        }
        loops += closed;
    }
    return loops;
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("marching-squares");
    if (!l) throw std::runtime_error("no lesson for marching-squares");
    return *l;
}

}  // namespace

TEST_CASE("marching-squares: cells worked by hand", "[modelling][marching-squares]") {
    SECTION("case 9: corners 0 and 3 inside, one segment bottom → top") {
        // f0 = −1, f1 = 3, f2 = 1, f3 = −2 (rows from the bottom).
        const auto r = MS::compute(grid({{-1, 3}, {-2, 1}}));
        CHECK(r.cases == std::vector<std::uint8_t>{9});
        REQUIRE(r.segments.size() == 1);
        CHECK(r.segments[0].a == glm::dvec2(0.25, 0));  // t = (0 − (−1))/(3 − (−1))
        CHECK(r.segments[0].b.x == Approx(2.0 / 3));   // top, from corner 3: t = 2/3
        CHECK(r.segments[0].b.y == 1);
        REQUIRE(r.crossings.size() == 2);
        CHECK(r.crossings[0] == glm::dvec2(0.25, 0));  // bottom, then top
        CHECK(r.crossings[1].y == 1);
        CHECK(r.chains == 1);
        CHECK(r.loops == 0);
    }
    SECTION("saddle 5: centre average 0 is not below iso 0, so separated") {
        const auto r = MS::compute(grid({{-1, 1}, {1, -1}}));
        CHECK(r.cases == std::vector<std::uint8_t>{5});
        REQUIRE(r.segments.size() == 2);
        CHECK(r.saddles == 1);
        CHECK(r.joined == 0);
        // Around corner 0: bottom (0.5, 0) → left (0, 0.5); around corner 2: top → right.
        CHECK(r.segments[0].a == glm::dvec2(0.5, 0));
        CHECK(r.segments[0].b == glm::dvec2(0, 0.5));
        CHECK(r.segments[1].a == glm::dvec2(0.5, 1));
        CHECK(r.segments[1].b == glm::dvec2(1, 0.5));
    }
    SECTION("saddle 5 joined: centre average −0.25 < 0 cuts off the outside corners") {
        const auto r = MS::compute(grid({{-2, 1}, {1, -1}}));
        CHECK(r.joined == 1);
        REQUIRE(r.segments.size() == 2);
        CHECK(r.segments[0].a == glm::dvec2(2.0 / 3, 0));  // bottom → right, around corner 1
        CHECK(r.segments[0].b == glm::dvec2(1, 0.5));
        CHECK(r.segments[1].b == glm::dvec2(0, 2.0 / 3));  // top → left, around corner 3
    }
    SECTION("saddle 10 both ways") {
        CHECK(MS::compute(grid({{1, -1}, {-1, 1}})).joined == 0);
        const auto j = MS::compute(grid({{1, -1}, {-1, 1}}, 0.5));
        CHECK(j.cases == std::vector<std::uint8_t>{10});
        CHECK(j.joined == 1);
    }
    SECTION("a corner exactly at iso is outside; the crossing lands on it") {
        // f0 = 0 = iso (outside), f3 = −1 inside: case 8, left crossing at t = 0, corner 0.
        const auto r = MS::compute(grid({{0, 1}, {-1, 1}}));
        CHECK(r.cases == std::vector<std::uint8_t>{8});
        REQUIRE(r.segments.size() == 1);
        CHECK(r.segments[0].a == glm::dvec2(0, 0));
        CHECK(r.segments[0].b == glm::dvec2(0.5, 1));
        CHECK(r.inside == 1);
    }
    SECTION("the example: a saddle in the middle, joined") {
        const auto j = cg::test::result_of("marching-squares",
                                           cg::test::algorithm("marching-squares").example());
        CHECK(j["cases"][1][1] == 5);
        CHECK(j["saddles"] == 1);
        CHECK(j["joined"] == 1);
        CHECK(j["loops"] == 1);
        CHECK(j["chains"] == 0);
    }
}

TEST_CASE("marching-squares: the 16-case table follows from the leaving/entering rule",
          "[modelling][marching-squares]") {
    for (int index = 0; index < 16; ++index)
        for (bool joined : {false, true}) {
            CAPTURE(index, joined);
            std::array<std::array<int, 2>, 2> seg{};
            const int n = MS::table(index, joined, seg);
            auto in = [&](int k) { return (index >> (k % 4) & 1) != 0; };
            std::vector<int> leave, enter;
            for (int e = 0; e < 4; ++e) {
                if (in(e) && !in(e + 1)) leave.push_back(e);
                if (!in(e) && in(e + 1)) enter.push_back(e);
            }
            REQUIRE(leave.size() == enter.size());
            REQUIRE(n == int(leave.size()));
            for (int k = 0; k < n; ++k) {
                const int from = seg[std::size_t(k)][0], to = seg[std::size_t(k)][1];
                CHECK(std::find(leave.begin(), leave.end(), from) != leave.end());
                CHECK(std::find(enter.begin(), enter.end(), to) != enter.end());
                if (n == 2) CHECK(to == (joined ? (from + 1) % 4 : (from + 3) % 4));
            }
        }
}

TEST_CASE("marching-squares: 4,000 random grids against the long-double reference",
          "[modelling][marching-squares]") {
    cg::Rng rng(2026);
    Check tally;
    long long ties = 0, untied = 0;
    for (int k = 0; k < 4000; ++k) {
        CAPTURE(k);
        const int nx = int(rng.integer(1, 12)), ny = int(rng.integer(1, 12));
        const bool integers = rng.chance(0.5);
        const double scale = rng.chance(0.2) ? std::pow(10.0, double(rng.integer(-8, 8))) : 1;
        Input in;
        in.field = MS::Field::Grid;
        in.iso = integers ? double(rng.integer(-1, 1)) * scale : rng.uniform(-1, 1) * scale;
        for (int j = 0; j <= ny; ++j) {
            std::vector<double> row;
            for (int i = 0; i <= nx; ++i) {
                double v = integers ? double(rng.integer(-3, 3)) * scale
                                    : rng.uniform(-2, 2) * scale;
                if (rng.chance(0.05)) v = in.iso;
                ties += v == in.iso;
                row.push_back(v);
            }
            in.values.push_back(row);
        }
        const auto r = MS::compute(in);
        check_against_reference(in, r, tally, integers && scale == 1);
        // Following end points is unambiguous only when no sample sits at iso (otherwise
        // several crossings can share a corner).
        bool tie = false;
        for (const auto& row : in.values)
            for (double v : row) tie = tie || v == in.iso;
        if (!tie) {
            CHECK(r.loops == ref_loops(r));
            ++untied;
        }
        if (k % 20 == 0) CHECK(cg::run_to_end<MS>(MS::start(in)) == r);
    }
    // The named noise field too.
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        const Input in = named(MS::Field::Noise, int(seed % 40) + 1, 0.7, 0.1, seed);
        check_against_reference(in, MS::compute(in), tally);
    }
    CHECK(tally.endpoints > 100000);
    CHECK(tally.saddles > 3000);
    CHECK(tally.joined > 1000);
    CHECK(tally.saddles - tally.joined > 1000);
    CHECK(tally.at_corner > 500);
    CHECK(ties > 5000);
    CHECK(untied > 300);
    WARN("random grids: " << tally.endpoints << " endpoints, " << tally.saddles << " saddles ("
                          << tally.joined << " joined, " << tally.near
                          << " with the centre within rounding of iso), " << tally.at_corner
                          << " crossings on a corner, " << untied << " grids without ties");
    CHECK(tally.near < tally.saddles / 10);  // the centre within rounding of iso: rare
}

TEST_CASE("marching-squares: the circle closes into one loop of length → 2πr",
          "[modelling][marching-squares]") {
    const double r = 0.7, exact = 2 * M_PI * r;
    double previous = 0;
    for (int n : {8, 16, 32, 64, 128, 256}) {
        CAPTURE(n);
        const auto res = MS::compute(named(MS::Field::Circle, n, r));
        CHECK(res.loops == 1);
        CHECK(res.chains == 0);
        CHECK(ref_loops(res) == 1);
        // Every crossing on the circle to second order in h (f = x² + y² − r² is quadratic).
        const double h = 2.0 / n;
        for (const auto& p : res.crossings) CHECK(std::fabs(std::hypot(p.x, p.y) - r) <= h * h);
        const double err = std::fabs(res.length - exact);
        if (previous > 0 && n <= 128) CHECK(err < previous / 2.5);  // about 4× per halving
        previous = err;
        if (n == 256) CHECK(err / exact < 3e-5);  // measured 1.6e-5
    }
    // Inside on the left: the loop runs counter-clockwise, its signed area is +πr².
    const auto res = MS::compute(named(MS::Field::Circle, 64, r));
    double area = 0;
    for (const auto& s : res.segments) area += 0.5 * (s.a.x * s.b.y - s.b.x * s.a.y);
    CHECK(area == Approx(M_PI * r * r).epsilon(2e-3));
}

TEST_CASE("marching-squares: two blobs, apart and merged", "[modelling][marching-squares]") {
    const auto apart = MS::compute(named(MS::Field::Blobs, 48, 0.3));
    CHECK(apart.loops == 2);
    CHECK(apart.chains == 0);
    const auto merged = MS::compute(named(MS::Field::Blobs, 48, 0.45));
    CHECK(merged.loops == 1);
    Check tally;
    check_against_reference(named(MS::Field::Blobs, 48, 0.3), apart, tally);
}

TEST_CASE("marching-squares: the state machine gives what compute gives",
          "[modelling][marching-squares]") {
    cg::Rng rng(9);
    for (int k = 0; k < 100; ++k) {
        const Input in = named(k % 3 == 0 ? MS::Field::Noise : k % 3 == 1 ? MS::Field::Circle
                                                                          : MS::Field::Blobs,
                               int(rng.integer(1, 40)), rng.uniform(0.2, 1), rng.uniform(-0.2, 0.2),
                               std::uint64_t(k));
        const auto t = cg::test::run_traced<MS>(in);
        CHECK(t.result == MS::compute(in));
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const Input in = cg::test::input_of<MS>("marching-squares", p.input);
        const auto r = MS::compute(in);
        const auto j = cg::test::result_of("marching-squares", p.input);
        CHECK(j["segment_count"] == r.segments.size());
        Check tally;
        check_against_reference(in, r, tally);
    }
}

TEST_CASE("marching-squares: the steps — crossed cells one by one, empty runs, batches",
          "[modelling][marching-squares]") {
    SECTION("the example") {
        const Input in = cg::test::input_of<MS>(
            "marching-squares", cg::test::algorithm("marching-squares").example());
        const auto t = cg::test::run_traced<MS>(in);
        const auto ev = cg::test::events(t);
        CHECK(ev.front() == "sample");
        CHECK(ev.back() == "summary");
        int saddles = 0, cells = 0;
        for (std::size_t k = 0; k < t.steps.size(); ++k) {
            saddles += ev[k] == "saddle";
            cells += ev[k] == "cell";
            if (ev[k] == "saddle") {
                CHECK(t.steps[k].narration.find("case 5") != std::string::npos);
                CHECK(t.steps[k].narration.find("joined") != std::string::npos);
            }
        }
        CHECK(saddles == 1);
        CHECK(cells == 6);  // seven crossed cells around the two low points, one a saddle
    }
    SECTION("a big grid: at most kStepped cell steps, then at most kBatches batches") {
        const auto t = cg::test::run_traced<MS>(named(MS::Field::Circle, 128, 0.7));
        CHECK(t.steps.size() <= std::size_t(2 + MS::kStepped + MS::kBatches));
        int batches = 0;
        for (const auto& s : t.steps) batches += s.event == "batch";
        CHECK(batches >= 20);
        CHECK(t.result == MS::compute(named(MS::Field::Circle, 128, 0.7)));
    }
}

TEST_CASE("marching-squares: bad input names the field", "[modelling][marching-squares]") {
    auto err = [](const std::string& text) { return cg::test::error_of("marching-squares", text); };
    CHECK(err(R"({"values": [[1, 2]], "iso": 0})").rfind("values: needs at least 2 rows", 0) == 0);
    CHECK(err(R"({"values": [[1, 2], [3]], "iso": 0})").rfind("values[1]: has 1 values", 0) == 0);
    CHECK(err(R"({"values": [[1], [3]], "iso": 0})").rfind("values[0]: needs at least 2", 0) == 0);
    CHECK(err(R"({"values": [[1, "a"], [3, 4]], "iso": 0})").rfind("values[0][1]: must be a number", 0) == 0);
    CHECK(err(R"({"values": [[1, 2], [3, 4]]})").rfind("iso: is missing", 0) == 0);
    CHECK(err(R"({"values": [[1, 2], [3, 1e200]], "iso": 0})").rfind("values[1][1]: must be a finite", 0) == 0);
    CHECK(err(R"({"field": "sphere", "iso": 0})").rfind("field: must be", 0) == 0);
    CHECK(err(R"({"field": "circle", "cells": 0, "iso": 0})").rfind("cells: must be 1 to 256", 0) == 0);
    CHECK(err(R"({"field": "circle", "cells": 300, "iso": 0})").rfind("cells: must be 1 to 256", 0) == 0);
    CHECK(err(R"({"field": "circle", "radius": 0, "iso": 0})").rfind("radius: must be above 0", 0) == 0);
    CHECK(err(R"({"field": "circle", "seed": 3, "iso": 0})").rfind("seed: only with", 0) == 0);
    CHECK(err(R"({"field": "circle", "values": [[1, 2], [3, 4]], "iso": 0})").rfind("values: only with", 0) == 0);
    CHECK(err(R"({"values": [[1, 2], [3, 4]], "cells": 4, "iso": 0})").rfind("cells: is for a named field", 0) == 0);
    CHECK(err(R"({"values": [[1, 2], [3, 4]], "iso": 0, "isovalue": 1})").rfind("isovalue: is not a known field", 0) == 0);
    CHECK_THROWS_WITH(MS::start(grid({{1, 2}, {3, std::nan("")}})),
                      Catch::StartsWith("values[1][1]: must be a finite"));
    CHECK_THROWS_WITH(MS::start(grid({{1, 2}, {3, 4}}, INFINITY)), Catch::StartsWith("iso: must be"));
    // A flat field at iso: every corner outside, nothing crossed.
    const auto flat = MS::compute(grid({{0, 0, 0}, {0, 0, 0}}));
    CHECK(flat.segments.empty());
    CHECK(flat.cases == std::vector<std::uint8_t>{0, 0});
}

TEST_CASE("marching-squares: replay on the example and the presets", "[modelling][marching-squares]") {
    const auto& a = cg::test::algorithm("marching-squares");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
    CHECK(lesson().presets.size() >= 4);
}

TEST_CASE("marching-squares: exam problems — the case index and the crossings of one cell",
          "[modelling][marching-squares][exam]") {
    const auto& a = cg::test::algorithm("marching-squares");
    int saddles = 0, on_iso = 0;
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<MS>("marching-squares", p.input);
        const LD iso = in.iso;
        const LD f[4] = {in.values[0][0], in.values[0][1], in.values[1][1], in.values[1][0]};
        int bits = 0;
        for (int k = 0; k < 4; ++k) {
            bits |= int(f[k] < iso) << k;
            on_iso += f[k] == iso;
        }
        CHECK(bits != 0);
        CHECK(bits != 15);
        saddles += bits == 5 || bits == 10;
        CHECK(p.expected["cases/0/0"] == bits);
        // Crossings bottom (0→1), right (1→2), top (3→2), left (0→3).
        const int ends[4][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}};
        const LD pos[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        std::vector<std::array<LD, 2>> want;
        for (const auto& e : ends) {
            const LD fa = f[e[0]], fb = f[e[1]];
            if ((fa < iso) == (fb < iso)) continue;
            const LD t = (iso - fa) / (fb - fa);
            want.push_back({pos[e[0]][0] + t * (pos[e[1]][0] - pos[e[0]][0]),
                            pos[e[0]][1] + t * (pos[e[1]][1] - pos[e[0]][1])});
        }
        const auto& got = p.expected["crossings"];
        REQUIRE(got.size() == want.size());
        for (std::size_t k = 0; k < want.size(); ++k) {
            CHECK(std::fabs(got[k][0].get<double>() - double(want[k][0])) <= 1e-12);
            CHECK(std::fabs(got[k][1].get<double>() - double(want[k][1])) <= 1e-12);
        }
        CHECK(p.answers == std::vector<std::string>{"cases/0/0", "crossings"});
    }
    CHECK(saddles > 60);
    CHECK(on_iso > 20);
}

TEST_CASE("marching-squares: the picture", "[modelling][marching-squares]") {
    auto s = MS::start(grid({{3, 2, 3}, {1, -2, 1}, {2, 1, 3}}));
    MS::step(s, nullptr);  // sampling
    {
        cg::Scene scene;
        MS::draw(s, scene);
        int inside = 0;
        for (const auto& p : scene.points) inside += p.style.role == cg::Role::Kept;
        CHECK(inside == 1);
        CHECK(scene.points.size() == 9);
    }
    MS::step(s, nullptr);  // cell (0, 0): crossed (corner (1, 1) inside)
    cg::Scene scene;
    MS::draw(s, scene);
    REQUIRE(scene.polygons.size() == 1);
    CHECK(scene.polygons[0].style.role == cg::Role::Active);
    bool label = false;
    for (const auto& l : scene.labels) label = label || l.text.rfind("case 4 = 0100", 0) == 0;
    CHECK(label);
    int recent = 0;
    for (const auto& sg : scene.segments) recent += sg.style.role == cg::Role::Active;
    CHECK(recent == 1);
}
