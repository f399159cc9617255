// Bézier splines: the continuity classification on constructed joints (C2 from a B-spline,
// C1 not C2, G1 with β ≠ 1, C0, broken, zero vectors); Hermite and Catmull-Rom segments
// interpolate their points with the given derivatives; random Catmull-Rom splines are C1.
#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <random>

#include "curves/bezier_spline.hpp"
#include "io/exam.hpp"
#include "io/registry.hpp"

using cg::BezierSpline;
using glm::dvec2;
using glm::dvec3;
using Segment = BezierSpline::Segment;

// A 2D point as the spline stores it: z = 0.
inline dvec3 P(double x, double y) {
    return {x, y, 0};
}

namespace {

BezierSpline::Result run(const BezierSpline::Input& in,
                         std::vector<std::string>* events = nullptr) {
    auto s = BezierSpline::start(in);
    while (!BezierSpline::done(s)) {
        cg::StepInfo info;
        BezierSpline::step(s, &info);
        if (events) events->push_back(info.event);
    }
    return BezierSpline::result(s);
}

BezierSpline::Input segments(std::vector<Segment> s) {
    BezierSpline::Input in;
    in.segments = std::move(s);
    return in;
}

// The uniform cubic B-spline segment over D_i .. D_{i+3} in Bézier form.
Segment from_bspline(dvec3 d0, dvec3 d1, dvec3 d2, dvec3 d3) {
    return {(d0 + 4.0 * d1 + d2) / 6.0, (2.0 * d1 + d2) / 3.0, (d1 + 2.0 * d2) / 3.0,
            (d1 + 4.0 * d2 + d3) / 6.0};
}

bool near(dvec3 a, dvec3 b, double tol) {
    return glm::length(a - b) <= tol;
}

}  // namespace

TEST_CASE("bezier-spline: the example has a C2 and a G1 joint", "[curves][bezier-spline]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-spline");
    auto r = a.create(a.example());
    std::vector<std::string> events;
    while (!r->done()) {
        cg::StepInfo info;
        r->step(&info);
        events.push_back(info.event);
    }
    CHECK(events == std::vector<std::string>{"joint-c2", "joint-g1", "summary"});
    const cg::json j = a.result(*r);
    CHECK(j["joints"][0] ==
          cg::json::parse(R"({"c0": true, "c1": true, "g1": true, "beta": 1.0, "c2": true})"));
    CHECK(j["joints"][1] ==
          cg::json::parse(R"({"c0": true, "c1": false, "g1": true, "beta": 2.0, "c2": false})"));
    CHECK(j["tangents"].is_null());
}

TEST_CASE("bezier-spline: continuity of constructed joints", "[curves][bezier-spline]") {
    // 500 random first segments per kind; the second is built to have the wanted joint.
    struct Trial {
        std::mt19937_64 rng;
        Segment a;
        dvec3 out, c2_q2;  // P3 − P2, and the Q2 that closes the A-frame
        dvec3 pt() {
            return {std::uniform_real_distribution<double>(-10, 10)(rng),
                    std::uniform_real_distribution<double>(-10, 10)(rng), 0};
        }
    };
    auto trials = [](auto&& check) {
        for (int trial = 0; trial < 500; ++trial) {
            Trial t{std::mt19937_64(trial), {}, {}, {}};
            t.a = {t.pt(), t.pt(), t.pt(), t.pt()};
            t.out = t.a[3] - t.a[2];
            t.c2_q2 = 2.0 * (t.a[3] + t.out) - 2.0 * t.a[2] + t.a[1];
            CAPTURE(trial);
            check(t);
        }
    };
    SECTION("C2: consecutive segments of a B-spline") {
        trials([](Trial& t) {
            dvec3 d[6];
            for (dvec3& p : d) p = t.pt();
            const auto r = run(segments({from_bspline(d[0], d[1], d[2], d[3]),
                                         from_bspline(d[1], d[2], d[3], d[4]),
                                         from_bspline(d[2], d[3], d[4], d[5])}));
            REQUIRE(r.joints.size() == 2);
            for (const auto& j : r.joints) {
                CHECK(j.c2);
                CHECK(j.c1);
                CHECK(j.g1);
                CHECK(j.beta == 1.0);
            }
        });
    }
    SECTION("C2: the A-frame closed by hand") {
        trials([](Trial& t) {
            const auto r = run(segments({t.a, {t.a[3], t.a[3] + t.out, t.c2_q2, t.pt()}}));
            CHECK(BezierSpline::level(r.joints[0]) == "C2");
        });
    }
    SECTION("C1 but not C2") {
        trials([](Trial& t) {
            const auto r =
                run(segments({t.a, {t.a[3], t.a[3] + t.out, t.c2_q2 + P(1, 0), t.pt()}}));
            CHECK(BezierSpline::level(r.joints[0]) == "C1");
            CHECK_FALSE(r.joints[0].c2);
        });
    }
    SECTION("G1 but not C1, with the β of P3 − P2 = β (Q1 − Q0)") {
        trials([](Trial& t) {
            double beta = std::uniform_real_distribution<double>(0.2, 5)(t.rng);
            if (std::fabs(beta - 1) < 1e-3) beta = 2;
            const auto r = run(segments({t.a, {t.a[3], t.a[3] + t.out / beta, t.pt(), t.pt()}}));
            CHECK(BezierSpline::level(r.joints[0]) == "G1");
            REQUIRE(r.joints[0].beta.has_value());
            CHECK(*r.joints[0].beta == Approx(beta).epsilon(1e-12));
        });
    }
    SECTION("C0 only: the opposite direction, or sideways") {
        trials([](Trial& t) {
            const auto back = run(segments({t.a, {t.a[3], t.a[3] - t.out, t.pt(), t.pt()}}));
            CHECK(BezierSpline::level(back.joints[0]) == "C0");
            CHECK_FALSE(back.joints[0].beta.has_value());
            const auto side =
                run(segments({t.a, {t.a[3], t.a[3] + P(-t.out.y, t.out.x), t.pt(), t.pt()}}));
            CHECK(BezierSpline::level(side.joints[0]) == "C0");
        });
    }
    SECTION("broken: the next piece starts elsewhere, even if smooth otherwise") {
        trials([](Trial& t) {
            const dvec3 q0 = t.a[3] + P(0.01, 0);
            const auto r = run(segments({t.a, {q0, q0 + t.out, t.pt(), t.pt()}}));
            CHECK(BezierSpline::level(r.joints[0]) == "broken");
            CHECK_FALSE(r.joints[0].g1);
        });
    }
    SECTION("zero end vectors on both sides: C1 without a direction (no β)") {
        const auto r = run(
            segments({{P(0, 0), P(1, 1), P(2, 0), P(2, 0)}, {P(2, 0), P(2, 0), P(3, 1), P(4, 0)}}));
        CHECK(r.joints[0].c1);
        CHECK(r.joints[0].g1);
        CHECK_FALSE(r.joints[0].beta.has_value());
        // ... and the curve turns a corner there all the same (the lesson says so): the
        // tangent comes from the points further in, (2, 0) − (1, 1) against (3, 1) − (2, 0).
        const dvec3 left = P(2, 0) - P(1, 1), right = P(3, 1) - P(2, 0);
        CHECK(glm::length(glm::cross(left, right)) > 0.5);
    }
    SECTION("a zero end vector beside one that is not: no common direction, C0 only") {
        const auto r = run(
            segments({{P(0, 0), P(1, 1), P(2, 0), P(2, 0)}, {P(2, 0), P(3, 0), P(3, 1), P(4, 0)}}));
        CHECK(BezierSpline::level(r.joints[0]) == "C0");
        CHECK_FALSE(r.joints[0].g1);
    }
}

TEST_CASE("bezier-spline: Hermite segments interpolate with the given derivatives",
          "[curves][bezier-spline]") {
    for (int trial = 0; trial < 500; ++trial) {
        std::mt19937_64 rng(trial);
        std::uniform_real_distribution<double> u(-10, 10);
        BezierSpline::Input in;
        in.mode = BezierSpline::Mode::Hermite;
        const int n = 2 + trial % 6;
        for (int i = 0; i < n; ++i) {
            in.points.push_back({u(rng), u(rng), 0});
            in.tangents.push_back({u(rng), u(rng), 0});
        }
        CAPTURE(trial);
        const auto r = run(in);
        REQUIRE(r.segments.size() == std::size_t(n - 1));
        for (std::size_t i = 0; i + 1 < in.points.size(); ++i) {
            const Segment& s = r.segments[i];
            CHECK(s[0] == in.points[i]);
            CHECK(s[3] == in.points[i + 1]);
            CHECK(near(3.0 * (s[1] - s[0]), in.tangents[i], 1e-12 * 10));
            CHECK(near(3.0 * (s[3] - s[2]), in.tangents[i + 1], 1e-12 * 10));
        }
        for (const auto& j : r.joints) CHECK(j.c1);
        CHECK(*r.tangents == in.tangents);
    }
}

TEST_CASE("bezier-spline: Catmull-Rom makes derivatives from neighbours, and is C1",
          "[curves][bezier-spline]") {
    SECTION("four points worked by hand") {
        BezierSpline::Input in;
        in.mode = BezierSpline::Mode::CatmullRom;
        in.points = {P(0, 0), P(2, 3), P(5, 3), P(7, 0)};
        std::vector<std::string> events;
        const auto r = run(in, &events);
        CHECK(events == std::vector<std::string>{"tangent", "tangent", "tangent", "tangent",
                                                 "segment", "segment", "segment", "joint-c1",
                                                 "joint-c1", "summary"});
        CHECK(*r.tangents == std::vector<dvec3>{P(2, 3), P(2.5, 1.5), P(2.5, -1.5), P(2, -3)});
        // The segment between P1 and P2: [P1, P1 + v1/3, P2 − v2/3, P2].
        CHECK(r.segments[1][0] == P(2, 3));
        CHECK(near(r.segments[1][1], P(2 + 2.5 / 3, 3.5), 1e-15));
        CHECK(near(r.segments[1][2], P(5 - 2.5 / 3, 3.5), 1e-15));
        CHECK(r.segments[1][3] == P(5, 3));
    }
    SECTION("two points: one straight segment") {
        BezierSpline::Input in;
        in.mode = BezierSpline::Mode::CatmullRom;
        in.points = {P(0, 0), P(3, 6)};
        std::vector<std::string> events;
        const auto r = run(in, &events);
        CHECK(events.back() == "summary");
        CHECK(r.segments == std::vector<Segment>{{P(0, 0), P(1, 2), P(2, 4), P(3, 6)}});
        CHECK(r.joints.empty());
    }
    SECTION(
        "1,000 random splines: through every point, v_i = (P_{i+1} − P_{i−1})/2, C1 at every "
        "joint") {
        for (int trial = 0; trial < 1000; ++trial) {
            std::mt19937_64 rng(trial);
            std::uniform_real_distribution<double> u(-100, 100);
            BezierSpline::Input in;
            in.mode = BezierSpline::Mode::CatmullRom;
            for (int i = 0; i < 3 + trial % 8; ++i) in.points.push_back({u(rng), u(rng), 0});
            CAPTURE(trial);
            const auto r = run(in);
            const auto& p = in.points;
            for (std::size_t i = 0; i + 1 < p.size(); ++i) {
                CHECK(r.segments[i][0] == p[i]);
                CHECK(r.segments[i][3] == p[i + 1]);
                const dvec3 v = i == 0 ? p[1] - p[0] : (p[i + 1] - p[i - 1]) / 2.0;
                CHECK(near(3.0 * (r.segments[i][1] - r.segments[i][0]), v, 1e-12 * 100));
            }
            for (const auto& j : r.joints) CHECK(j.c1);
        }
    }
}

TEST_CASE("bezier-spline: bad input names the field", "[curves][bezier-spline]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-spline");
    auto create = [&](const char* text) { return a.create(cg::parse_json(text)); };
    CHECK_THROWS_WITH(create(R"({})"),
                      "the input needs one of \"segments\", \"hermite\" or \"catmull_rom\"");
    CHECK_THROWS_WITH(
        create(R"({"segments": [], "catmull_rom": {"points": []}})"),
        "catmull_rom: give only one of \"segments\", \"hermite\" and \"catmull_rom\"");
    CHECK_THROWS_WITH(create(R"({"segments": []})"), "segments: needs at least 1 segment (got 0)");
    CHECK_THROWS_WITH(
        create(R"({"segments": [[[0, 0], [1, 1], [2, 2]]]})"),
        "segments[0]: must be 4 points [P0, P1, P2, P3], got an array ([[0,0],[1,1],[2,2]])");
    CHECK_THROWS_WITH(create(R"({"hermite": {"points": [[0, 0], [1, 1]], "tangents": [[1, 0]]}})"),
                      "hermite.tangents: needs one vector per point (2), got 1");
    CHECK_THROWS_WITH(create(R"({"catmull_rom": {"points": [[0, 0]]}})"),
                      "catmull_rom.points: needs at least 2 points (got 1)");
    CHECK_THROWS_WITH(create(R"({"catmull_rom": {"points": [[0, 0], [1, 1]], "tension": 0.5}})"),
                      Catch::StartsWith("catmull_rom.tension: is not a known field"));
    BezierSpline::Input in;
    in.segments = {{P(0, 0), P(1, std::numeric_limits<double>::quiet_NaN()), P(2, 0), P(3, 0)}};
    CHECK_THROWS_WITH(BezierSpline::start(in),
                      "segments[0][1][1]: must be a finite number (got NaN)");
}

TEST_CASE("bezier-spline: exam problems reach every kind of joint",
          "[curves][bezier-spline][exam]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-spline");
    std::map<std::string, int> kinds;
    int catmull_rom = 0;
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        cg::Rng rng(seed);
        const auto in = BezierSpline::exam_input(rng);
        const auto r = run(in);
        if (in.mode == BezierSpline::Mode::CatmullRom) {
            ++catmull_rom;
            CHECK(r.segments.size() == 3);
            for (const auto& j : r.joints) CHECK(j.c1);
            continue;
        }
        REQUIRE(r.joints.size() == 1);
        ++kinds[BezierSpline::level(r.joints[0])];
        for (const auto& seg : in.segments)
            for (dvec3 p : seg) CHECK((p.x == std::floor(p.x) && p.y == std::floor(p.y)));
    }
    CHECK(catmull_rom > 120);
    for (const char* k : {"C2", "C1", "G1", "C0", "broken"}) {
        CAPTURE(k);
        CHECK(kinds[k] > 5);
    }
    CHECK_THAT(cg::make_exam(a, 1).question + cg::make_exam(a, 2).question,
               Catch::Contains("continuity"));
}

TEST_CASE("bezier-spline: the picture shows the joint's vectors and the A-frame",
          "[curves][bezier-spline]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bezier-spline");
    auto r = a.create(a.example());
    r->step(nullptr);  // the C2 joint
    cg::Scene scene;
    r->draw(scene);
    int arrows = 0;
    for (const auto& s : scene.segments) arrows += s.arrow;
    CHECK(arrows == 2);
    bool apex = false;
    for (const auto& p : scene.points)
        apex = apex || (p.label == "A-frame apex" && p.p == dvec2(5, 4));
    CHECK(apex);
    CHECK(scene.handles.size() == 12);
    CHECK(scene.handles[5].x_field == "/segments/1/1/0");
}
