// Bézier patches: a bilinear patch worked by hand, 2,000 random patches of degree 1 to 6 in
// each direction against the double-sum Bernstein form in long double (point, the columns' Q_j,
// both partial derivatives against the closed-form derivative patches, the normal, every
// tessellation vertex), corners, triangle orientation, degenerate normals, bad input, replay,
// exam problems and the picture.
#include <catch2/catch.hpp>
#include <limits>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <random>

#include "support/traced.hpp"
#include "curve_reference.hpp"
#include "curves/bezier_patch.hpp"
#include "io/exam.hpp"
#include "io/registry.hpp"
#include "support/replay.hpp"

using cg::BezierPatch;
using cg::test::Point3L;
using glm::dvec3;

namespace {

using Grid = std::vector<std::vector<dvec3>>;

using Traced = cg::test::Traced<BezierPatch>;

Traced run_traced(const BezierPatch::Input& in) { return cg::test::run_traced<BezierPatch>(in); }

// --- the reference: the double sum, written from the formula, in long double ---------------

Point3L add(Point3L a, long double w, dvec3 p) {
    a.x += w * p.x, a.y += w * p.y, a.z += w * p.z;
    return a;
}

// Σ_i Σ_j P_ij B_i^m(s) B_j^n(t).
Point3L patch_l(const Grid& g, long double s, long double t) {
    const int m = int(g.size()) - 1, n = int(g[0].size()) - 1;
    Point3L r;
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j)
            r = add(r, cg::test::bernstein_l(m, i, s) * cg::test::bernstein_l(n, j, t),
                    g[size_t(i)][size_t(j)]);
    return r;
}

// m Σ_i Σ_j (P_{i+1,j} − P_ij) B_i^{m−1}(s) B_j^n(t).
Point3L ds_l(const Grid& g, long double s, long double t) {
    const int m = int(g.size()) - 1, n = int(g[0].size()) - 1;
    Point3L r;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j <= n; ++j) {
            const long double w = m * cg::test::bernstein_l(m - 1, i, s) * cg::test::bernstein_l(n, j, t);
            r = add(r, w, g[size_t(i) + 1][size_t(j)]);
            r = add(r, -w, g[size_t(i)][size_t(j)]);
        }
    return r;
}

// n Σ_i Σ_j (P_{i,j+1} − P_ij) B_i^m(s) B_j^{n−1}(t).
Point3L dt_l(const Grid& g, long double s, long double t) {
    const int m = int(g.size()) - 1, n = int(g[0].size()) - 1;
    Point3L r;
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j < n; ++j) {
            const long double w = n * cg::test::bernstein_l(m, i, s) * cg::test::bernstein_l(n - 1, j, t);
            r = add(r, w, g[size_t(i)][size_t(j) + 1]);
            r = add(r, -w, g[size_t(i)][size_t(j)]);
        }
    return r;
}

Point3L cross_l(Point3L a, Point3L b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
long double norm_l(Point3L a) {
    return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}

Grid random_grid(std::mt19937_64& rng, int m, int n, double size = 10) {
    Grid g;
    for (int i = 0; i <= m; ++i) g.push_back(cg::test::random_points(rng, n + 1, 3, size));
    return g;
}

double grid_scale(const Grid& g) {
    double s = 1e-300;
    for (const auto& row : g) s = std::max(s, cg::test::scale_of(row));
    return s;
}

BezierPatch::Input bilinear(double s, double t) {
    BezierPatch::Input in;
    in.control_points = {{{0, 0, 0}, {0, 4, 0}}, {{4, 0, 0}, {4, 4, 4}}};
    in.s = s, in.t = t;
    return in;
}

using cg::test::events;

}  // namespace

TEST_CASE("bezier-patch: a bilinear patch at (1/2, 1/2) worked by hand", "[curves][bezier-patch]") {
    BezierPatch::Input in = bilinear(0.5, 0.5);
    in.tessellation = 2;
    const Traced t = run_traced(in);
    CHECK(events(t) == std::vector<std::string>{"column", "column", "point", "derivatives",
                                                 "normal", "tessellate"});
    const auto& r = t.result;
    CHECK(r.column_points == std::vector<dvec3>{{2, 0, 0}, {2, 4, 2}});
    CHECK(r.point == dvec3(2, 2, 1));
    CHECK(r.ds == dvec3(4, 0, 2));
    CHECK(r.dt == dvec3(0, 4, 2));
    // (4, 0, 2) × (0, 4, 2) = (−8, −8, 16), length √384.
    CHECK(r.normal_defined);
    const double len = std::sqrt(384.0);
    CHECK(glm::length(r.normal - dvec3(-8 / len, -8 / len, 16 / len)) < 1e-15);
    CHECK(r.triangle_count() == 8);
    REQUIRE(r.vertices.size() == 9);
    CHECK(r.vertices[4] == dvec3(2, 2, 1));
    CHECK(r.vertices[8] == dvec3(4, 4, 4));
    CHECK(r.triangle(0) == std::array<int, 3>{0, 3, 4});
    CHECK(r.triangle(1) == std::array<int, 3>{0, 4, 1});
    CHECK(r.triangle(7) == std::array<int, 3>{4, 8, 5});

    CHECK(t.steps[0].line == 2);
    CHECK(t.steps[0].narration ==
          "Column 0, P₀₀ … P₁₀, is a Bézier curve in s; de Casteljau at s = 0.5: its last level "
          "is Q₀ = (2, 0, 0), and 1 times its last segment is the column's s-derivative R₀ = "
          "(4, 0, 0).");
    CHECK(t.steps[2].line == 4);
    CHECK_THAT(t.steps[2].narration, Catch::EndsWith("P(0.5, 0.5) = (2, 2, 1)."));
    CHECK(t.steps[3].line == 5);
    CHECK_THAT(t.steps[3].narration, Catch::Contains("∂P/∂t = 1·((2, 4, 2) − (2, 0, 0)) = (0, 4, 2)"));
    CHECK_THAT(t.steps[3].narration, Catch::Contains("∂P/∂s = (4, 0, 2)"));
    CHECK(t.steps[4].line == 6);
    CHECK_THAT(t.steps[4].narration, Catch::Contains("∂P/∂s × ∂P/∂t = (−8, −8, 16)"));
    CHECK(t.steps[5].line == 7);
    CHECK_THAT(t.steps[5].narration, Catch::Contains("9 vertices"));
    CHECK_THAT(t.steps[5].narration, Catch::Contains("8 in all"));

    // The JSON result.
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-patch");
    auto run = a.create(cg::json::parse(
        R"({"control_points": [[[0, 0, 0], [0, 4, 0]], [[4, 0, 0], [4, 4, 4]]], "s": 0.5, "t": 0.5,
            "tessellation": 2})"));
    while (!run->done()) run->step(nullptr);
    const cg::json j = a.result(*run);
    CHECK(j["point"] == cg::json::parse("[2.0, 2.0, 1.0]"));
    CHECK(j["column_points"] == cg::json::parse("[[2.0, 0.0, 0.0], [2.0, 4.0, 2.0]]"));
    CHECK(j["triangles"] == 8);
    CHECK(j["vertices"].size() == 9);
    CHECK(j["normal_defined"] == true);
}

TEST_CASE("bezier-patch: a biquadratic step by step shows each column's levels",
          "[curves][bezier-patch]") {
    BezierPatch::Input in;
    in.control_points = {{{0, 0, 0}, {0, 2, 2}, {0, 4, 0}},
                         {{2, 0, 2}, {2, 2, 4}, {2, 4, 2}},
                         {{4, 0, 0}, {4, 2, 2}, {4, 4, 0}}};
    const Traced t = run_traced(in);
    CHECK(events(t) == std::vector<std::string>{"column", "column", "column", "point",
                                                "derivatives", "normal", "tessellate"});
    CHECK_THAT(t.steps[1].narration,
               Catch::Contains("level 1: P₀¹ = (1, 2, 3), P₁¹ = (3, 2, 3); its last level is "
                               "Q₁ = (2, 2, 3)"));
    CHECK(t.result.column_points == std::vector<dvec3>{{2, 0, 1}, {2, 2, 3}, {2, 4, 1}});
    CHECK(t.result.point == dvec3(2, 2, 2));
    // At the top of this symmetric hill both derivatives are horizontal: the normal is +z.
    CHECK(t.result.ds == dvec3(4, 0, 0));
    CHECK(t.result.dt == dvec3(0, 4, 0));
    CHECK(t.result.normal == dvec3(0, 0, 1));
}

TEST_CASE("bezier-patch: 2,000 random patches of degree 1 to 6 agree with the double sum",
          "[curves][bezier-patch]") {
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> u(0, 1);
    std::uniform_int_distribution<int> degree(1, 6), tess(1, 6);
    int normals_checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        BezierPatch::Input in;
        const int m = degree(rng), n = degree(rng);
        in.control_points = random_grid(rng, m, n);
        // Degenerate ones too: coincident points, a collapsed row, a collapsed column.
        if (trial % 10 == 1) in.control_points[1][0] = in.control_points[0][0];
        if (trial % 10 == 2)
            for (auto& p : in.control_points[0]) p = in.control_points[0][1];
        if (trial % 10 == 3)
            for (auto& row : in.control_points) row[size_t(n)] = in.control_points[0][size_t(n)];
        in.s = trial % 7 == 0 ? 0.0 : trial % 7 == 1 ? 1.0 : u(rng);
        in.t = trial % 5 == 0 ? 1.0 : trial % 5 == 1 ? 0.0 : u(rng);
        in.tessellation = tess(rng);
        CAPTURE(trial, m, n, in.s, in.t);
        const double scale = grid_scale(in.control_points);
        const auto s = BezierPatch::start(in);
        const BezierPatch::Result r = cg::run_to_end<BezierPatch>(s);

        CHECK(double(cg::test::distance(patch_l(in.control_points, in.s, in.t), r.point)) <
              1e-12 * scale);
        const Point3L ds = ds_l(in.control_points, in.s, in.t), dt = dt_l(in.control_points, in.s, in.t);
        CHECK(double(cg::test::distance(ds, r.ds)) < 1e-9 * scale);
        CHECK(double(cg::test::distance(dt, r.dt)) < 1e-9 * scale);
        // Q_j = Σ_i P_ij B_i^m(s): column j as a curve in s.
        REQUIRE(r.column_points.size() == size_t(n) + 1);
        for (int j = 0; j <= n; ++j) {
            std::vector<dvec3> column;
            for (const auto& row : in.control_points) column.push_back(row[size_t(j)]);
            CHECK(double(cg::test::distance(cg::test::bezier_l(column, in.s),
                                            r.column_points[size_t(j)])) < 1e-12 * scale);
        }
        // The normal: where the reference cross product is clearly non-zero, the same
        // direction; where it is zero, declared undefined; never NaN.
        CHECK(std::isfinite(r.normal.x));
        const Point3L c = cross_l(ds, dt);
        const long double sine = norm_l(c) / (norm_l(ds) * norm_l(dt));
        if (norm_l(ds) > 1e-6 && norm_l(dt) > 1e-6 && sine > 1e-6) {
            ++normals_checked;
            REQUIRE(r.normal_defined);
            CHECK(double(cg::test::distance({c.x / norm_l(c), c.y / norm_l(c), c.z / norm_l(c)},
                                            r.normal)) < 1e-6);
        }
        if (norm_l(ds) == 0 || norm_l(dt) == 0) {
            CHECK_FALSE(r.normal_defined);
            CHECK(r.normal == dvec3(0));
        }
        if (r.normal_defined) CHECK(std::fabs(glm::length(r.normal) - 1) < 1e-15);
        // The tessellation: (N + 1)² vertices, each P(a/N, b/N) — against the reference and,
        // exactly, against the algorithm's own evaluation of that (s, t).
        const int N = in.tessellation;
        REQUIRE(r.vertices.size() == size_t((N + 1) * (N + 1)));
        CHECK(r.triangle_count() == 2 * N * N);
        for (int a = 0; a <= N; ++a)
            for (int b = 0; b <= N; ++b) {
                const dvec3 v = r.vertices[size_t(a * (N + 1) + b)];
                CHECK(double(cg::test::distance(
                          patch_l(in.control_points, (long double)a / N, (long double)b / N), v)) <
                      1e-12 * scale);
                CHECK(v == BezierPatch::point_at(in, double(a) / N, double(b) / N));
            }
        // Corners interpolate the corner control points, exactly.
        CHECK(r.vertices.front() == in.control_points[0][0]);
        CHECK(r.vertices[size_t(N)] == in.control_points[0][size_t(n)]);
        CHECK(r.vertices[size_t(N * (N + 1))] == in.control_points[size_t(m)][0]);
        CHECK(r.vertices.back() == in.control_points[size_t(m)][size_t(n)]);
        // The plain function computes the same thing, bit for bit.
        CHECK(BezierPatch::evaluate(in) == r);
    }
    CHECK(normals_checked > 1500);
}

TEST_CASE("bezier-patch: the triangles turn counter-clockwise around the surface normal",
          "[curves][bezier-patch]") {
    // Gentle height fields over a regular grid with jittered positions: the surface is a graph
    // with little curvature, so ∂P/∂s × ∂P/∂t is defined everywhere and even a one-cell mesh's
    // triangles must turn the same way around it. (A wildly bent patch can legitimately fold a
    // coarse triangle over; that is tessellation error, not orientation.)
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1), height(-0.3, 0.3);
    std::uniform_int_distribution<int> degree(1, 5), tess(1, 10);
    for (int trial = 0; trial < 300; ++trial) {
        BezierPatch::Input in;
        const int m = degree(rng), n = degree(rng);
        for (int i = 0; i <= m; ++i) {
            std::vector<dvec3> row;
            for (int j = 0; j <= n; ++j)
                row.push_back({i + jitter(rng), j + jitter(rng), height(rng)});
            in.control_points.push_back(row);
        }
        // Half of them mirrored (x ↔ y): the normal then points down, and the triangles follow.
        if (trial % 2)
            for (auto& row : in.control_points)
                for (auto& p : row) std::swap(p.x, p.y);
        in.tessellation = tess(rng);
        CAPTURE(trial, m, n, in.tessellation);
        const auto r = cg::run_to_end<BezierPatch>(BezierPatch::start(in));
        const int N = in.tessellation;
        for (int k = 0; k < r.triangle_count(); ++k) {
            const auto tri = r.triangle(k);
            const dvec3 a = r.vertices[size_t(tri[0])], b = r.vertices[size_t(tri[1])],
                        c = r.vertices[size_t(tri[2])];
            const int cell = k / 2, ca = cell / N, cb = cell % N;
            const long double s = (ca + 0.5L) / N, t = (cb + 0.5L) / N;
            const Point3L want = cross_l(ds_l(in.control_points, s, t), dt_l(in.control_points, s, t));
            const dvec3 got = glm::cross(b - a, c - a);
            CHECK(got.x * double(want.x) + got.y * double(want.y) + got.z * double(want.z) > 0);
        }
    }
}

TEST_CASE("bezier-patch: a collapsed corner or edge gives no normal, and says why",
          "[curves][bezier-patch]") {
    SECTION("a collapsed edge: the whole first row is one point") {
        BezierPatch::Input in;
        in.control_points = {{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}},
                             {{1, -1, 1}, {1, 0, 2}, {1, 1, 1}},
                             {{2, -2, 0}, {2, 0, 1}, {2, 2, 0}}};
        in.s = 0, in.t = 0.3;
        const Traced t = run_traced(in);
        CHECK(t.result.point == dvec3(0));
        CHECK(t.result.dt == dvec3(0));
        CHECK(t.result.ds != dvec3(0));
        CHECK_FALSE(t.result.normal_defined);
        CHECK(t.result.normal == dvec3(0));
        CHECK_THAT(t.steps[5].narration,
                   Catch::StartsWith("No normal here: ∂P/∂t is zero (control points collapsed "
                                     "along t)"));
        // Elsewhere on the same patch the normal is fine.
        in.s = 0.5;
        CHECK(cg::run_to_end<BezierPatch>(BezierPatch::start(in)).normal_defined);
    }
    SECTION("a collapsed corner: P00 = P01 = P10, evaluated there") {
        BezierPatch::Input in;
        in.control_points = {{{0, 0, 0}, {0, 0, 0}, {0, 2, 1}},
                             {{0, 0, 0}, {1, 1, 2}, {1, 2, 1}},
                             {{2, 0, 1}, {2, 1, 1}, {2, 2, 0}}};
        in.s = 0, in.t = 0;
        const Traced t = run_traced(in);
        CHECK_FALSE(t.result.normal_defined);
        CHECK_THAT(t.steps.back().narration, Catch::Contains("vertices"));
        CHECK_THAT(t.steps[t.steps.size() - 2].narration,
                   Catch::StartsWith("No normal here: both ∂P/∂s and ∂P/∂t are zero"));
        const cg::Registry registry = cg::builtin_registry();
        const cg::Algorithm& a = *registry.find("bezier-patch");
        auto run = a.create(cg::json{{"control_points",
                                      {{{0, 0, 0}, {0, 0, 0}, {0, 2, 1}},
                                       {{0, 0, 0}, {1, 1, 2}, {1, 2, 1}},
                                       {{2, 0, 1}, {2, 1, 1}, {2, 2, 0}}}},
                                     {"s", 0},
                                     {"t", 0}});
        while (!run->done()) run->step(nullptr);
        const std::string text = a.result(*run).dump();
        CHECK(text.find("null") == std::string::npos);
        CHECK(text.find("nan") == std::string::npos);
        CHECK(a.result(*run)["normal"] == cg::json::parse("[0.0, 0.0, 0.0]"));
        cg::Scene scene;
        run->draw(scene);
        bool said = false, zero = false;
        for (const auto& l : scene.labels3) {
            said = said || l.text == "normal undefined here";
            zero = zero || l.text == "∂P/∂t = 0";
        }
        CHECK(said);
        CHECK(zero);
        for (const auto& seg : scene.segments3)
            if (seg.arrow) CHECK(seg.a != seg.b);
    }
    SECTION("a patch folded onto a line: the derivatives are parallel") {
        BezierPatch::Input in;
        in.control_points = {{{0, 0, 0}, {1, 1, 1}}, {{1, 1, 1}, {2, 2, 2}}};
        const Traced t = run_traced(in);
        CHECK_FALSE(t.result.normal_defined);
        CHECK_THAT(t.steps[4].narration,
                   Catch::StartsWith("No normal here: ∂P/∂s and ∂P/∂t are parallel"));
    }
    SECTION("tiny and huge coordinates neither underflow nor overflow the normal") {
        for (double size : {1e-95, 1e95}) {  // coordinates below 1e-100 are refused (bezier.hpp)
            BezierPatch::Input in = bilinear(0.5, 0.5);
            for (auto& row : in.control_points)
                for (auto& p : row) p *= size;
            const auto r = cg::run_to_end<BezierPatch>(BezierPatch::start(in));
            CHECK(r.normal_defined);
            const double len = std::sqrt(384.0);
            CHECK(glm::length(r.normal - dvec3(-8 / len, -8 / len, 16 / len)) < 1e-15);
        }
    }
}

TEST_CASE("bezier-patch: s and t outside [0, 1] are refused unless extrapolating",
          "[curves][bezier-patch]") {
    BezierPatch::Input in = bilinear(1.5, 0.5);
    CHECK_THROWS_WITH(BezierPatch::start(in),
                      "s: must lie in [0, 1] (got 1.5); give \"extrapolate\": true to evaluate "
                      "outside the segment");
    in = bilinear(0.5, -0.25);
    CHECK_THROWS_WITH(BezierPatch::start(in), Catch::StartsWith("t: must lie in [0, 1] (got −0.25)"));
    in.extrapolate = true;
    in.s = 1.5;
    const Traced t = run_traced(in);
    CHECK_THAT(t.steps[0].narration, Catch::StartsWith("(s, t) lies outside [0, 1]²"));
    CHECK(double(cg::test::distance(patch_l(in.control_points, 1.5L, -0.25L), t.result.point)) <
          1e-12);
    // The tessellation still covers the patch itself.
    CHECK(t.result.vertices.back() == dvec3(4, 4, 4));
    in.s = 1001;
    CHECK_THROWS_WITH(BezierPatch::start(in),
                      "s: must be within ±1000 even when extrapolating (got 1001)");
}

TEST_CASE("bezier-patch: bad input names the field", "[curves][bezier-patch]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    BezierPatch::Input in;
    in.control_points = {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}},
                         {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}},
                         {{0, 2, 0}, {1, 2, 0}, {2, 2, 0}}};
    auto bad = in;
    bad.control_points[1][2].x = nan;
    CHECK_THROWS_WITH(BezierPatch::start(bad),
                      "control_points[1][2][0]: must be a finite number (got NaN)");
    bad = in;
    bad.control_points[2][0].z = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(BezierPatch::start(bad),
                      "control_points[2][0][2]: must be a finite number (got inf)");
    bad = in;
    bad.control_points[1].pop_back();
    CHECK_THROWS_WITH(BezierPatch::start(bad),
                      "control_points[1]: has 2 points but control_points[0] has 3: every row of "
                      "the grid needs the same number");
    bad = in;
    bad.control_points.resize(1);
    CHECK_THROWS_WITH(BezierPatch::start(bad),
                      "control_points: needs at least 2 rows (degree 1 in s), got 1");
    bad = in;
    for (auto& row : bad.control_points) row.resize(1);
    CHECK_THROWS_WITH(BezierPatch::start(bad), "control_points[0]: needs at least 2 points (got 1)");
    bad = in;
    bad.control_points.assign(12, in.control_points[0]);
    CHECK_THROWS_WITH(BezierPatch::start(bad),
                      "control_points: takes at most 11 rows (degree 10 in s), got 12");
    bad = in;
    for (auto& row : bad.control_points) row.assign(12, dvec3(0));
    CHECK_THROWS_WITH(BezierPatch::start(bad), "control_points[0]: takes at most 11 points (got 12)");
    bad = in;
    bad.s = nan;
    CHECK_THROWS_WITH(BezierPatch::start(bad), "s: must be a finite number (got NaN)");
    bad = in;
    bad.tessellation = 0;
    CHECK_THROWS_WITH(BezierPatch::start(bad), "tessellation: must be an integer from 1 to 64 (got 0)");

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-patch");
    auto create = [&](const char* text) { return a.create(cg::parse_json(text)); };
    CHECK_THROWS_WITH(create(R"({"control_points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0]]], "s": 0.5, "t": 0.5})"),
                      Catch::StartsWith("control_points[1]: has 1 points but control_points[0] has 2"));
    CHECK_THROWS_WITH(create(R"({"control_points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1]]], "s": 0.5, "t": 0.5})"),
                      "control_points[1][1]: must be a point [x, y, z], got an array ([1,1])");
    CHECK_THROWS_WITH(create(R"({"control_points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, "z"]]], "s": 0.5, "t": 0.5})"),
                      "control_points[1][1][2]: must be a number, got a string (\"z\")");
    CHECK_THROWS_WITH(create(R"({"control_points": [[[0, 0, 0], [1, 0, 0]], 3], "s": 0.5, "t": 0.5})"),
                      "control_points[1]: must be a row: a list of points [x, y, z], got 3");
    CHECK_THROWS_WITH(create(R"({"control_points": [[0, 0, 0], [1, 0, 0]], "s": 0.5, "t": 0.5})"),
                      Catch::StartsWith("control_points[0][0]: must be a point [x, y, z]"));
    CHECK_THROWS_WITH(create(R"({"control_points": 1, "s": 0.5, "t": 0.5})"),
                      Catch::StartsWith("control_points: must be a list of rows"));
    CHECK_THROWS_WITH(create(R"({"control_points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 0]]], "t": 0.5})"),
                      "s: is missing");
    CHECK_THROWS_WITH(create(R"({"control_points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 0]]], "s": 0.5, "t": 0.5, "tessellation": 2.5})"),
                      Catch::StartsWith("tessellation: must be an integer"));
    CHECK_THROWS_WITH(create(R"({"control_points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 0]]], "s": 0.5, "t": 0.5, "tessellation": 65})"),
                      "tessellation: must be an integer from 1 to 64 (got 65)");
    CHECK_THROWS_WITH(create(R"({"control_points": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 0]]], "s": 0.5, "t": 0.5, "u": 1})"),
                      Catch::StartsWith("u: is not a known field"));
}

TEST_CASE("bezier-patch: deterministic and resumable", "[curves][bezier-patch]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-patch");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    cg::test::check_replay(
        a,
        cg::json::parse(R"({"control_points": [[[0, 0, 0], [0, 0, 0]], [[1, 0, 1], [1, 1, 0]]],
                            "s": 0, "t": 1, "tessellation": 3})"),
        cg::test::kEveryStep);
}

TEST_CASE("bezier-patch: exam problems are hand-sized and their answers match the reference",
          "[curves][bezier-patch][exam]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-patch");
    int bilinear_count = 0, biquadratic_count = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const BezierPatch::Input in = BezierPatch::exam_input(rng);
        REQUIRE_NOTHROW(BezierPatch::validate(in));
        const int m = int(in.control_points.size()) - 1;
        const int n = int(in.control_points[0].size()) - 1;
        CHECK(m == n);
        bilinear_count += m == 1;
        biquadratic_count += m == 2;
        for (const auto& row : in.control_points)
            for (const auto& p : row) CHECK(p == glm::floor(p));
        if (m == 2) CHECK((in.s == 0.5 && in.t == 0.5));
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const auto want = patch_l(in.control_points, in.s, in.t);
        CHECK(std::fabs(p.expected["point"][0].get<double>() - double(want.x)) < 1e-12);
        CHECK(std::fabs(p.expected["point"][1].get<double>() - double(want.y)) < 1e-12);
        CHECK(std::fabs(p.expected["point"][2].get<double>() - double(want.z)) < 1e-12);
        const auto ds = ds_l(in.control_points, in.s, in.t);
        CHECK(std::fabs(p.expected["ds"][2].get<double>() - double(ds.z)) < 1e-12);
        // Hand-sized: the point is a multiple of 1/64.
        for (int c = 0; c < 3; ++c) {
            const double v = p.expected["point"][c].get<double>() * 64;
            CHECK(v == std::floor(v));
        }
    }
    CHECK(bilinear_count > 100);
    CHECK(biquadratic_count > 100);
    CHECK_THAT(cg::make_exam(a, 3).question, Catch::Contains("by de Casteljau, first along s"));
}

TEST_CASE("bezier-patch: the picture shows the net, the construction, the surface and the normal",
          "[curves][bezier-patch]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-patch");
    auto run = a.create(a.example());
    int step = 0;
    auto has_point = [](const cg::Scene& scene, const std::string& label) {
        for (const auto& p : scene.points3)
            if (p.label == label) return true;
        return false;
    };
    auto has_segment = [](const cg::Scene& scene, const std::string& label) {
        for (const auto& s : scene.segments3)
            if (s.label == label && s.arrow) return true;
        return false;
    };
    while (true) {
        cg::Scene scene;
        run->draw(scene);
        CHECK(scene.has_3d());
        CHECK_FALSE(scene.has_2d());
        CHECK(has_point(scene, "P₀₀"));
        CHECK(has_point(scene, "P₃₃"));
        CHECK(scene.faces3.size() == 128);  // the 8 × 8 mesh (a faint preview until the end)
        if (step >= 1 && step <= 4) CHECK(has_point(scene, "Q" + cg::curves::subscript(step - 1)));
        if (step == 1) CHECK(has_point(scene, "P₀¹"));  // the column's de Casteljau levels
        if (step >= 5) CHECK(has_point(scene, "P(0.4, 0.7)"));
        if (step >= 6) CHECK(has_segment(scene, "∂P/∂s / 3"));
        if (step >= 6) CHECK(has_segment(scene, "∂P/∂t / 3"));
        if (step >= 7) CHECK(has_segment(scene, "N"));
        if (run->done()) {
            for (const auto& f : scene.faces3) CHECK(f.style.role == cg::Role::Kept);
            break;
        }
        run->step(nullptr);
        ++step;
    }
    CHECK(step == 8);
}
