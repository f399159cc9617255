// De Casteljau: a cubic worked by hand, 2,000 random curves of degree 1 to 10 (2D and 3D)
// against the Bernstein form in long double (point, derivative, both halves of the split),
// the plain function against the state machine, bad input, and the picture.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "support/traced.hpp"
#include "curve_reference.hpp"
#include "curves/de_casteljau.hpp"
#include "io/exam.hpp"
#include "io/registry.hpp"

using cg::DeCasteljau;
using glm::dvec3;

namespace {

using Traced = cg::test::Traced<DeCasteljau>;

Traced run_traced(const DeCasteljau::Input& in) { return cg::test::run_traced<DeCasteljau>(in); }

DeCasteljau::Input cubic(double t) {
    return {{{0, 0, 0}, {1, 3, 0}, {4, 4, 0}, {6, 1, 0}}, 2, t, false};
}

}  // namespace

TEST_CASE("de-casteljau: a cubic at t = 1/2 worked by hand", "[curves][de-casteljau]") {
    const Traced t = run_traced(cubic(0.5));
    std::vector<std::string> events;
    for (const auto& s : t.steps) events.push_back(s.event);
    CHECK(events == std::vector<std::string>{"level", "level", "point", "tangent", "subdivide"});
    const auto& r = t.result;
    CHECK(r.level(1) == std::vector<dvec3>{{0.5, 1.5, 0}, {2.5, 3.5, 0}, {5, 2.5, 0}});
    CHECK(r.level(2) == std::vector<dvec3>{{1.5, 2.5, 0}, {3.75, 3, 0}});
    CHECK(r.point == dvec3(2.625, 2.75, 0));
    CHECK(r.tangent == dvec3(6.75, 1.5, 0));
    CHECK(r.left() ==
          std::vector<dvec3>{{0, 0, 0}, {0.5, 1.5, 0}, {1.5, 2.5, 0}, {2.625, 2.75, 0}});
    CHECK(r.right() == std::vector<dvec3>{{2.625, 2.75, 0}, {3.75, 3, 0}, {5, 2.5, 0}, {6, 1, 0}});

    CHECK(t.steps[0].line == 4);
    CHECK(t.steps[0].narration ==
          "Level 1: each point lies 0.5 of the way from one point of level 0 to the next: "
          "P₀¹ = (0.5, 1.5), P₁¹ = (2.5, 3.5), P₂¹ = (5, 2.5).");
    CHECK(t.steps[2].line == 5);
    CHECK(t.steps[2].narration ==
          "The last level has one point, P₀³ = 0.5·(1.5, 2.5) + 0.5·(3.75, 3) = (2.625, 2.75): the "
          "curve point P(0.5).");
    CHECK(t.steps[3].line == 6);
    CHECK(t.steps[3].math ==
          "P'(0.5) = 3\\left(P_{1}^{2} - P_{0}^{2}\\right) = 3\\left((3.75, 3) - (1.5, "
          "2.5)\\right) = (6.75, 1.5)");
    CHECK(t.steps[4].line == 7);
    for (const auto& s : t.steps) {
        CHECK(s.line >= 1);
        CHECK(s.line <= int(DeCasteljau::spec().pseudocode.size()));
    }
    // The JSON result lists the levels, level 0 first.
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("de-casteljau");
    REQUIRE(a);
    auto run = a->create(a->example());
    while (!run->done()) run->step(nullptr);
    const cg::json j = a->result(*run);
    CHECK(j["levels"].size() == 4);
    CHECK(j["levels"][0] == cg::json::parse("[[0.0,0.0],[1.0,3.0],[4.0,4.0],[6.0,1.0]]"));
    CHECK(j["point"] == cg::json::parse("[2.625,2.75]"));
    CHECK(j["right"][3] == cg::json::parse("[6.0,1.0]"));
}

TEST_CASE("de-casteljau: the line and the quadratic of the course's notes",
          "[curves][de-casteljau]") {
    SECTION("degree 1 is linear interpolation: no level steps") {
        const Traced t = run_traced({{{0, 0, 0}, {4, 2, 0}}, 2, 0.25, false});
        REQUIRE(t.steps.size() == 3);
        CHECK(t.steps[0].event == "point");
        CHECK(t.result.point == dvec3(1, 0.5, 0));
        CHECK(t.result.tangent == dvec3(4, 2, 0));
        CHECK(t.result.left() == std::vector<dvec3>{{0, 0, 0}, {1, 0.5, 0}});
    }
    SECTION("a quadratic: P_0^2 = (1 − t) P_0^1 + t P_1^1") {
        const Traced t = run_traced({{{0, 0, 0}, {2, 4, 0}, {4, 0, 0}}, 2, 0.25, false});
        REQUIRE(t.steps.size() == 4);
        CHECK(t.result.level(1) == std::vector<dvec3>{{0.5, 1, 0}, {2.5, 3, 0}});
        CHECK(t.result.point == dvec3(1, 1.5, 0));
        CHECK(t.result.tangent == dvec3(4, 4, 0));  // 2 (P_1^1 − P_0^1)
    }
    SECTION("the ends interpolate: P(0) = P_0, P(1) = P_n, P'(0) = n (P_1 − P_0)") {
        auto in = cubic(0);
        CHECK(run_traced(in).result.point == dvec3(0, 0, 0));
        CHECK(run_traced(in).result.tangent == dvec3(3, 9, 0));
        in.t = 1;
        CHECK(run_traced(in).result.point == dvec3(6, 1, 0));
        CHECK(run_traced(in).result.tangent == dvec3(6, -9, 0));
    }
}

TEST_CASE("de-casteljau: 2,000 random curves of degree 1 to 10 agree with the Bernstein form",
          "[curves][de-casteljau]") {
    for (int trial = 0; trial < 2000; ++trial) {
        std::mt19937_64 rng(trial);
        const int n = 1 + trial % 10, dim = trial % 3 == 0 ? 3 : 2;
        const double size = trial % 7 == 0 ? 1e6 : trial % 7 == 1 ? 1e-3 : 10;
        DeCasteljau::Input in{cg::test::random_points(rng, n + 1, dim, size), dim,
                              std::uniform_real_distribution<double>(0, 1)(rng), false};
        if (trial % 50 == 0) in.t = 0;
        if (trial % 50 == 1) in.t = 1;
        CAPTURE(trial, n, dim, in.t);
        const auto r = cg::run_to_end<DeCasteljau>(DeCasteljau::start(in));
        const double scale = cg::test::scale_of(in.control_points);

        // The point: Σ P_i B_i^n(t) in long double.
        CHECK(double(cg::test::distance(cg::test::bezier_l(in.control_points, in.t), r.point)) <=
              1e-12 * scale);
        // The derivative: n Σ (P_{i+1} − P_i) B_i^{n−1}(t), and a long-double central difference.
        const auto d = cg::test::bezier_derivative_l(in.control_points, in.t);
        CHECK(double(cg::test::distance(d, r.tangent)) <= 1e-12 * n * scale);
        const long double h = 1e-6L;
        const auto ahead = cg::test::bezier_l(in.control_points, in.t + h);
        const auto behind = cg::test::bezier_l(in.control_points, in.t - h);
        const cg::test::Point3L fd{(ahead.x - behind.x) / (2 * h), (ahead.y - behind.y) / (2 * h),
                                   (ahead.z - behind.z) / (2 * h)};
        CHECK(double(cg::test::distance(fd, r.tangent)) <= 1e-6 * n * n * n * scale);
        // The halves: left(s) = P(s t), right(s) = P(t + s (1 − t)).
        const auto left = r.left(), right = r.right();
        REQUIRE(left.size() == std::size_t(n + 1));
        REQUIRE(right.size() == std::size_t(n + 1));
        for (double s : {0.0, 0.2, 0.5, 0.7, 1.0}) {
            const auto want_l = cg::test::bezier_l(in.control_points, s * in.t);
            const auto want_r = cg::test::bezier_l(in.control_points, in.t + s * (1 - in.t));
            CHECK(double(cg::test::distance(cg::test::bezier_l(left, s), want_l)) <= 1e-12 * scale);
            CHECK(double(cg::test::distance(cg::test::bezier_l(right, s), want_r)) <=
                  1e-12 * scale);
        }
        // The plain function is the same computation.
        CHECK(DeCasteljau::evaluate(in) == r);
    }
}

TEST_CASE("de-casteljau: extrapolation is refused unless asked for, and then said",
          "[curves][de-casteljau]") {
    auto in = cubic(1.5);
    CHECK_THROWS_WITH(DeCasteljau::start(in),
                      "t: must lie in [0, 1] (got 1.5); give \"extrapolate\": true to evaluate "
                      "outside the segment");
    in.extrapolate = true;
    const Traced t = run_traced(in);
    CHECK_THAT(t.steps[0].narration,
               Catch::StartsWith("t = 1.5 lies outside [0, 1], so this extrapolates"));
    CHECK(double(cg::test::distance(cg::test::bezier_l(in.control_points, 1.5L), t.result.point)) <
          1e-12);
    in.t = -1001;
    CHECK_THROWS_WITH(DeCasteljau::start(in),
                      "t: must be within ±1000 even when extrapolating (got −1001)");
}

TEST_CASE("de-casteljau: bad input names the field", "[curves][de-casteljau]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto in = cubic(0.5);
    in.control_points[2].y = nan;
    CHECK_THROWS_WITH(DeCasteljau::start(in),
                      "control_points[2][1]: must be a finite number (got NaN)");
    in = cubic(nan);
    CHECK_THROWS_WITH(DeCasteljau::start(in), "t: must be a finite number (got NaN)");
    in = cubic(0.5);
    in.control_points.resize(1);
    CHECK_THROWS_WITH(DeCasteljau::start(in), "control_points: needs at least 2 points (got 1)");
    in.control_points.assign(52, dvec3(0));
    CHECK_THROWS_WITH(DeCasteljau::start(in), "control_points: takes at most 51 points (got 52)");
    in = cubic(0.5);
    in.control_points[1].z = 2;
    CHECK_THROWS_WITH(DeCasteljau::start(in),
                      "control_points[1][2]: must be 0 for a 2D point (got 2)");

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("de-casteljau");
    auto create = [&](const char* text) { return a.create(cg::parse_json(text)); };
    CHECK_THROWS_WITH(create(R"({"control_points": [], "t": 0.5})"),
                      "control_points: needs at least 2 points (got 0)");
    CHECK_THROWS_WITH(
        create(R"({"control_points": [[0, 0], [1, 2, 3]], "t": 0.5})"),
        "control_points[1]: must be a point [x, y] like control_points[0], got an array ([1,2,3])");
    CHECK_THROWS_WITH(create(R"({"control_points": [[0, 0], [1, "a"]], "t": 0.5})"),
                      "control_points[1][1]: must be a number, got a string (\"a\")");
    CHECK_THROWS_WITH(create(R"({"control_points": [[0, 0], [1, 2]]})"), "t: is missing");
    CHECK_THROWS_WITH(create(R"({"control_points": [[0, 0], [1, 2]], "t": 0.5, "T": 1})"),
                      Catch::StartsWith("T: is not a known field"));
    // 3D points are read as such and written back with three coordinates.
    auto run = create(R"({"control_points": [[0, 0, 0], [1, 2, 3]], "t": 0.5})");
    while (!run->done()) run->step(nullptr);
    CHECK(a.result(*run)["point"] == cg::json::parse("[0.5, 1.0, 1.5]"));
}

TEST_CASE("de-casteljau: the state is cheap, and a copy mid-run finishes identically",
          "[curves][de-casteljau]") {
    SECTION("the triangle of a cubic stays inline; larger ones move to the heap and back") {
        cg::curves::InlinePoints<4> p{{1, 2, 3}, {4, 5, 6}};
        p.push_back({7, 8, 9});
        p.resize(6);  // to the heap, keeping the points
        CHECK(p[2] == dvec3(7, 8, 9));
        CHECK(p[5] == dvec3(0));
        auto q = p;
        CHECK(q == p);
        q.resize(2);  // back inline
        CHECK(q == cg::curves::InlinePoints<4>{{1, 2, 3}, {4, 5, 6}});
        CHECK_FALSE(q == p);
    }
    std::mt19937_64 rng(7);
    DeCasteljau::Input in{cg::test::random_points(rng, 7, 3), 3, 0.3, false};
    auto s = DeCasteljau::start(in);
    for (int i = 0; i < 3; ++i) DeCasteljau::step(s, nullptr);
    auto copy = s;
    CHECK(copy == s);
    CHECK(cg::run_to_end<DeCasteljau>(copy) == cg::run_to_end<DeCasteljau>(s));
}

TEST_CASE("de-casteljau: the picture shows the construction, the point and the halves",
          "[curves][de-casteljau]") {
    auto s = DeCasteljau::start(cubic(0.5));
    cg::Scene scene;
    DeCasteljau::draw(s, scene);
    REQUIRE(scene.handles.size() == 4);
    CHECK(scene.handles[2].x_field == "/control_points/2/0");
    CHECK(scene.handles[2].y_field == "/control_points/2/1");
    CHECK(scene.polygons[0].style.role == cg::Role::Construction);  // the whole curve, faintly
    CHECK(scene.polygons[0].points.size() == 101);

    DeCasteljau::step(s, nullptr);
    scene.clear();
    DeCasteljau::draw(s, scene);
    bool labelled = false;
    for (const auto& p : scene.points)
        labelled = labelled || (p.label == "P₁¹" && p.p == glm::dvec2(2.5, 3.5));
    CHECK(labelled);

    while (!DeCasteljau::done(s)) DeCasteljau::step(s, nullptr);
    scene.clear();
    DeCasteljau::draw(s, scene);
    int left = 0, right = 0, kept = 0;
    for (const auto& poly : scene.polygons) {
        left += poly.style.role == cg::Role::Entering && poly.points.size() == 4;
        right += poly.style.role == cg::Role::Leaving && poly.points.size() == 4;
    }
    for (const auto& p : scene.points)
        kept += p.style.role == cg::Role::Kept && p.p == glm::dvec2(2.625, 2.75);
    CHECK(left == 1);
    CHECK(right == 1);
    CHECK(kept == 1);
}

TEST_CASE("de-casteljau: exam problems are hand-sized and their answers match the reference",
          "[curves][de-casteljau][exam]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("de-casteljau");
    int cubics = 0;
    for (std::uint64_t seed = 0; seed < 500; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const DeCasteljau::Input in = DeCasteljau::exam_input(rng);
        const int n = int(in.control_points.size()) - 1;
        CHECK(n >= 1);
        CHECK(n <= 4);
        cubics += n == 3;
        for (const auto& p : in.control_points) {
            CHECK(p.x == std::floor(p.x));
            CHECK(p.y == std::floor(p.y));
        }
        bool nice_t = false;
        for (double t : {0.25, 1.0 / 3, 0.5, 2.0 / 3, 0.75}) nice_t = nice_t || in.t == t;
        CHECK(nice_t);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const auto want = cg::test::bezier_l(in.control_points, in.t);
        CHECK(std::fabs(p.expected["point"][0].get<double>() - double(want.x)) < 1e-12);
        CHECK(std::fabs(p.expected["point"][1].get<double>() - double(want.y)) < 1e-12);
    }
    CHECK(cubics > 200);
    CHECK_THAT(cg::make_exam(a, 3).question, Catch::Contains("with de Casteljau's algorithm"));
}

TEST_CASE("de Casteljau: 3D control points are drawn in 3D, 2D ones in 2D", "[de-casteljau][picture]") {
    DeCasteljau::Input in;
    in.control_points = {{0, 0, 0}, {1, 2, 1}, {3, 2, -1}, {4, 0, 2}};
    in.dim = 3;
    in.t = 0.5;
    DeCasteljau::State s = DeCasteljau::start(in);
    while (!DeCasteljau::done(s)) {
        DeCasteljau::step(s, nullptr);
        cg::Scene scene;
        DeCasteljau::draw(s, scene);
        CHECK(scene.has_3d());
        CHECK_FALSE(scene.has_2d());
        CHECK(scene.points3.size() >= 4);
        for (const auto& seg : scene.segments3)  // every point of the picture is finite
            CHECK(std::isfinite(seg.a.x + seg.a.y + seg.a.z + seg.b.x + seg.b.y + seg.b.z));
    }
    // The curve point sits where the Bernstein form puts it, z included.
    cg::Scene end;
    DeCasteljau::draw(s, end);
    const auto p = std::find_if(end.points3.begin(), end.points3.end(),
                                [](const cg::Point3& q) { return q.label.rfind("P(", 0) == 0; });
    REQUIRE(p != end.points3.end());
    CHECK(p->p.z == Approx(0.125 * 0 + 0.375 * 1 + 0.375 * -1 + 0.125 * 2));
    in.dim = 2;
    for (auto& q : in.control_points) q.z = 0;
    cg::Scene flat;
    DeCasteljau::draw(DeCasteljau::start(in), flat);
    CHECK(flat.has_2d());
    CHECK_FALSE(flat.has_3d());
}
