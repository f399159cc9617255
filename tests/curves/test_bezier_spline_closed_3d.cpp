// Bézier splines, closed Catmull-Rom loops and 3D points: a square loop worked by hand; 1,000
// random loops (2D and 3D) whose tangents are (P_{i+1} − P_{i−1})/2 taken cyclically, whose
// segments' end derivatives — from the Bernstein form in long double — are those tangents, and
// whose seam (segment N into segment 0) is C1; 3D Hermite, Catmull-Rom and constructed joints
// (C2 from a 3D B-spline, G1, a corner out of the plane) against the same reference; errors for
// mixed dimensions and a misplaced "closed"; replay on the lesson's presets; the pictures.
#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <random>

#include "curves/bezier_spline.hpp"
#include "curves/curve_reference.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::BezierSpline;
using glm::dvec3;
using Segment = BezierSpline::Segment;
using Mode = BezierSpline::Mode;

namespace {

BezierSpline::Input catmull_rom(std::vector<dvec3> points, bool closed, int dim) {
    BezierSpline::Input in;
    in.mode = Mode::CatmullRom;
    in.dim = dim;
    in.points = std::move(points);
    in.closed = closed;
    return in;
}

// The derivative of a segment at t, from the Bernstein form in long double.
cg::test::Point3L derivative(const Segment& seg, long double t) {
    return cg::test::bezier_derivative_l({seg.begin(), seg.end()}, t);
}

std::vector<dvec3> random_points(std::mt19937_64& rng, int n, int dim, double size) {
    std::uniform_real_distribution<double> u(-size, size);
    std::vector<dvec3> p;
    for (int i = 0; i < n; ++i) {
        const double x = u(rng), y = u(rng);
        p.push_back({x, y, dim == 3 ? u(rng) : 0.0});
    }
    return p;
}

}  // namespace

TEST_CASE("bezier-spline closed: a square loop worked by hand", "[curves][bezier-spline]") {
    const auto t = cg::test::run_traced<BezierSpline>(
        catmull_rom({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, true, 2));
    CHECK(cg::test::events(t) ==
          std::vector<std::string>{"tangent", "tangent", "tangent", "tangent", "segment", "segment",
                                   "segment", "segment", "joint-c1", "joint-c1", "joint-c1",
                                   "joint-c1", "summary"});
    // v_i = (P_{i+1} − P_{i−1})/2 with P_{−1} = P_3 and P_4 = P_0.
    CHECK(*t.result.tangents == std::vector<dvec3>{{1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}});
    REQUIRE(t.result.segments.size() == 4);
    const Segment& last = t.result.segments[3];  // P3 back to P0
    CHECK(last[0] == dvec3(0, 2, 0));
    CHECK(glm::length(last[1] - dvec3(-1.0 / 3, 5.0 / 3, 0)) < 1e-15);
    CHECK(glm::length(last[2] - dvec3(-1.0 / 3, 1.0 / 3, 0)) < 1e-15);
    CHECK(last[3] == dvec3(0, 0, 0));
    REQUIRE(t.result.joints.size() == 4);
    for (const auto& j : t.result.joints) {
        CHECK(j.c1);
        CHECK_FALSE(j.c2);
    }
    CHECK_THAT(t.steps[0].narration,
               Catch::Contains("v₀ = (P₁ − P₃)/2 = ((2, 0) − (0, 2))/2 = (1, −1)") &&
                   Catch::Contains("the neighbours wrap around"));
    CHECK_THAT(t.steps[7].narration,
               Catch::Contains("Segment 3, from P₃ to P₀") && Catch::Contains("closes the loop"));
    CHECK_THAT(t.steps[11].narration,
               Catch::Contains("Joint 4 (segment 3 into segment 0, where the loop closes)"));
    CHECK_THAT(t.steps[12].narration, Catch::Contains("4 segments in a closed loop, 4 joints"));
    const cg::json r = cg::test::result_of(
        "bezier-spline", std::string(R"({"catmull_rom": {"points": [[0, 0], [2, 0],
                            [2, 2], [0, 2]], "closed": true}})"));
    CHECK(r["segments"].size() == 4);
    CHECK(r["segments"][3][3] == cg::json::array({0.0, 0.0}));
    CHECK(r["joints"].size() == 4);
    // "closed": false is the open spline.
    CHECK(cg::test::result_of(
              "bezier-spline",
              std::string(R"({"catmull_rom": {"points": [[0, 0], [2, 0], [2, 2], [0, 2]],
                                  "closed": false}})"))["segments"]
              .size() == 3);
}

TEST_CASE(
    "bezier-spline closed: 1,000 random loops — cyclic tangents, C1 at the seam, "
    "derivatives against the Bernstein form in long double",
    "[curves][bezier-spline]") {
    for (int trial = 0; trial < 1000; ++trial) {
        std::mt19937_64 rng(trial);
        const int dim = trial % 2 ? 3 : 2, n = 3 + trial % 9;
        const double size = trial % 5 == 0 ? 1e6 : 10;
        const auto in = catmull_rom(random_points(rng, n, dim, size), true, dim);
        CAPTURE(trial, dim, n);
        const auto t = cg::test::run_traced<BezierSpline>(in);
        const auto& p = in.points;
        const auto& v = *t.result.tangents;
        REQUIRE(t.result.segments.size() == std::size_t(n));
        REQUIRE(t.result.joints.size() == std::size_t(n));
        REQUIRE(t.steps.size() == std::size_t(3 * n + 1));
        const long double tol = 1e-12L * size;
        for (int i = 0; i < n; ++i) {
            const std::size_t k = std::size_t(i), next = std::size_t((i + 1) % n),
                              prev = std::size_t((i + n - 1) % n);
            // The tangent from the two cyclic neighbours, with Catmull-Rom's ½.
            REQUIRE(v[k] == (p[next] - p[prev]) / 2.0);
            const Segment& seg = t.result.segments[k];
            REQUIRE(seg[0] == p[k]);
            REQUIRE(seg[3] == p[next]);  // the last segment returns to P_0
            // P'(0) = v_i and P'(1) = v_{i+1} (cyclically), in long double.
            REQUIRE(cg::test::distance(derivative(seg, 0), v[k]) <= tol);
            REQUIRE(cg::test::distance(derivative(seg, 1), v[next]) <= tol);
            // Every joint is C1, the seam included: segment i's end derivative is segment
            // i + 1's start derivative (the seam: N's and 0's).
            const Segment& after = t.result.segments[next];
            REQUIRE(cg::test::distance(derivative(seg, 1), derivative(after, 0)) <= 2 * tol);
            REQUIRE(t.result.joints[k].c1);
            REQUIRE(t.result.joints[k].c0);
        }
        REQUIRE(t.steps[std::size_t(3 * n - 1)].narration.find("where the loop closes") !=
                std::string::npos);
        // Run to the end without narration: the same result.
        REQUIRE(cg::run_to_end<BezierSpline>(BezierSpline::start(in)) == t.result);
    }
}

TEST_CASE(
    "bezier-spline 3D: Hermite, Catmull-Rom and joints in space, against the Bernstein "
    "form in long double",
    "[curves][bezier-spline]") {
    for (int trial = 0; trial < 500; ++trial) {
        std::mt19937_64 rng(trial);
        const int n = 2 + trial % 7;
        CAPTURE(trial, n);
        // Hermite: P'(0) = v_i, P'(1) = v_{i+1}.
        BezierSpline::Input h;
        h.mode = Mode::Hermite;
        h.dim = 3;
        h.points = random_points(rng, n, 3, 10);
        h.tangents = random_points(rng, n, 3, 10);
        const auto rh = cg::run_to_end<BezierSpline>(BezierSpline::start(h));
        for (int i = 0; i + 1 < n; ++i) {
            const Segment& seg = rh.segments[std::size_t(i)];
            REQUIRE(cg::test::distance(derivative(seg, 0), h.tangents[std::size_t(i)]) <= 1e-12L);
            REQUIRE(cg::test::distance(derivative(seg, 1), h.tangents[std::size_t(i) + 1]) <=
                    1e-12L);
            REQUIRE(cg::test::distance(cg::test::bezier_l({seg.begin(), seg.end()}, 1),
                                       h.points[std::size_t(i) + 1]) <= 1e-12L);
        }
        for (const auto& j : rh.joints) REQUIRE(j.c1);
        // Open Catmull-Rom in 3D: the one-sided ends, the central differences inside.
        const auto c = catmull_rom(random_points(rng, n + 1, 3, 10), false, 3);
        const auto rc = cg::run_to_end<BezierSpline>(BezierSpline::start(c));
        const auto& p = c.points;
        for (std::size_t i = 0; i + 1 < p.size(); ++i) {
            const dvec3 vi = i == 0 ? p[1] - p[0] : (p[i + 1] - p[i - 1]) / 2.0;
            REQUIRE(cg::test::distance(derivative(rc.segments[i], 0), vi) <= 1e-12L);
        }
        REQUIRE(rc.segments.back()[3] == p.back());
    }
    // Constructed 3D joints: a B-spline is C2; a stretched leg G1 with β = 2; a leg bent out of
    // the plane C0.
    auto bspline = [](dvec3 d0, dvec3 d1, dvec3 d2, dvec3 d3) -> Segment {
        return {(d0 + 4.0 * d1 + d2) / 6.0, (2.0 * d1 + d2) / 3.0, (d1 + 2.0 * d2) / 3.0,
                (d1 + 4.0 * d2 + d3) / 6.0};
    };
    const dvec3 d[5] = {{0, 0, 0}, {1, 2, 3}, {3, 3, -1}, {4, 0, 2}, {6, 1, 1}};
    BezierSpline::Input s;
    s.dim = 3;
    s.segments = {bspline(d[0], d[1], d[2], d[3]), bspline(d[1], d[2], d[3], d[4])};
    CHECK(BezierSpline::level(cg::run_to_end<BezierSpline>(BezierSpline::start(s)).joints[0]) ==
          "C2");
    const Segment a{dvec3(0, 0, 0), dvec3(1, 1, 1), dvec3(2, 1, 2), dvec3(3, 2, 2)};
    const dvec3 out = a[3] - a[2];
    s.segments = {a, {a[3], a[3] + 0.5 * out, dvec3(5, 5, 5), dvec3(6, 4, 3)}};
    auto j = cg::run_to_end<BezierSpline>(BezierSpline::start(s)).joints[0];
    CHECK(BezierSpline::level(j) == "G1");
    CHECK(*j.beta == Approx(2));
    s.segments = {a, {a[3], a[3] + dvec3(out.x, out.y, out.z + 1), dvec3(5, 5, 5), dvec3(6, 4, 3)}};
    CHECK(BezierSpline::level(cg::run_to_end<BezierSpline>(BezierSpline::start(s)).joints[0]) ==
          "C0");
    // The JSON result keeps the third coordinate.
    const cg::json r = cg::test::result_of(
        "bezier-spline",
        std::string(R"({"catmull_rom": {"points": [[0, 0, 0], [1, 2, 3], [4, 0, 1]]}})"));
    CHECK(r["tangents"][0] == cg::json::array({1.0, 2.0, 3.0}));
    CHECK(r["segments"][1][3] == cg::json::array({4.0, 0.0, 1.0}));
    const auto t = cg::test::run_json(
        "bezier-spline",
        std::string(R"({"catmull_rom": {"points": [[0, 0, 0], [1, 2, 3], [4, 0, 1]]}})"));
    CHECK_THAT(t.steps[0].narration, Catch::Contains("= (1, 2, 3) − (0, 0, 0) = (1, 2, 3)"));
}

TEST_CASE("bezier-spline closed and 3D: bad input names the field", "[curves][bezier-spline]") {
    using cg::test::error_of;
    CHECK(error_of("bezier-spline", R"({"catmull_rom": {"points": [[0, 0], [1, 1, 1]]}})") ==
          "catmull_rom.points[1]: must be a point [x, y] like catmull_rom.points[0], got an "
          "array ([1,1,1])");
    CHECK(error_of("bezier-spline",
                   R"({"segments": [[[0, 0, 0], [1, 1, 1], [2, 1, 0], [3, 0, 0]],
                                    [[3, 0], [4, 0], [5, 1], [6, 0]]]})") ==
          "segments[1][0]: must be a point [x, y, z] like segments[0][0]: all points of a spline "
          "have the same dimension, got an array ([3,0])");
    CHECK_THAT(
        error_of(
            "bezier-spline",
            R"({"hermite": {"points": [[0, 0, 0], [1, 1, 1]], "tangents": [[1, 0], [1, 0]]}})"),
        Catch::StartsWith("hermite.tangents[0]: must be a vector [x, y, z] like "
                          "hermite.points[0]"));
    CHECK_THAT(error_of("bezier-spline", R"({"catmull_rom": {"points": [[0, 0], [1, 1], [2, 0]]},
                                          "closed": true})"),
               Catch::StartsWith("closed: belongs inside \"catmull_rom\""));
    CHECK(error_of("bezier-spline",
                   R"({"hermite": {"points": [[0, 0], [1, 1]], "tangents": [[1, 0], [1, 0]],
                                   "closed": true}})") ==
          "hermite.closed: applies to catmull_rom only: a Hermite spline joins its points with "
          "the tangents given; to close it, repeat P0 (and v0) at the end");
    CHECK(error_of("bezier-spline",
                   R"({"catmull_rom": {"points": [[0, 0], [1, 1]], "closed": true}})") ==
          "catmull_rom.points: a closed loop needs at least 3 points (got 2)");
    CHECK(error_of(
              "bezier-spline",
              R"({"catmull_rom": {"points": [[0, 0], [1, 1], [2, 0], [0, 0]], "closed": true}})") ==
          "catmull_rom.points[3]: repeats the first point: a closed loop joins the last point back "
          "to the first by itself, so leave the repeat out");
    CHECK_THAT(error_of("bezier-spline",
                        R"({"catmull_rom": {"points": [[0, 0], [1, 1], [2, 0]], "closed": 1}})"),
               Catch::StartsWith("catmull_rom.closed: must be true or false"));
    BezierSpline::Input in;
    in.segments = {{dvec3(0), dvec3(1, 1, 0), dvec3(2, 1, 0), dvec3(3, 0, 0)}};
    in.closed = true;
    CHECK_THROWS_WITH(BezierSpline::start(in),
                      "closed: applies to catmull_rom only: segments and Hermite data are joined "
                      "as given");
    in.closed = false;
    in.segments[0][1].z = 1;  // a 2D input with a z
    CHECK_THROWS_WITH(BezierSpline::start(in),
                      "segments[0][1][2]: must be 0 for a 2D point (got 1)");
}

TEST_CASE("bezier-spline closed and 3D: presets replay, and the pictures", "[curves][bezier-spline]") {
    const cg::Algorithm& a = cg::test::algorithm("bezier-spline");
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* lesson = lib.for_algorithm("bezier-spline");
    REQUIRE(lesson);
    int closed = 0, space = 0;
    for (const auto& p : lesson->presets) {
        const bool is_closed = p.name.find("closed") != std::string::npos;
        const bool is_3d = p.name.find("3D") != std::string::npos;
        if (!is_closed && !is_3d) continue;
        closed += is_closed;
        space += is_3d;
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, cg::test::kEveryStep);
    }
    CHECK(closed >= 1);
    CHECK(space >= 1);

    // 3D: on the 3D canvas only, no handles; every step's picture finite.
    auto run = a.create(cg::parse_json(
        R"({"catmull_rom": {"points": [[0, 0, 0], [2, 1, 1], [3, 3, 0], [1, 4, -1]], "closed": true}})"));
    while (true) {
        cg::Scene scene;
        run->draw(scene);
        CHECK(scene.has_3d());
        CHECK_FALSE(scene.has_2d());
        CHECK(scene.handles.empty());
        for (const auto& s : scene.segments3)
            REQUIRE((std::isfinite(s.a.x + s.a.y + s.a.z) && std::isfinite(s.b.x + s.b.y + s.b.z)));
        if (run->done()) break;
        run->step(nullptr);
    }
    // 2D closed: the polyline through the points is drawn as a loop, with a handle per point.
    auto s =
        BezierSpline::start(catmull_rom({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, true, 2));
    cg::Scene scene;
    BezierSpline::draw(s, scene);
    REQUIRE_FALSE(scene.polygons.empty());
    CHECK(scene.polygons[0].closed);
    CHECK(scene.polygons.size() == 1 + 4);  // the loop, and the four segments to come
    CHECK(scene.handles.size() == 4);
    CHECK_FALSE(scene.has_3d());
}
