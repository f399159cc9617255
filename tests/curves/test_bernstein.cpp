// Bernstein: binomials exact, a cubic at t = 1/3 worked by hand, and on 2,000 random curves:
// the weights sum to 1, the point equals de Casteljau's, the hull (checked from its
// definition) contains every curve sample, and affine maps commute with the sum.
#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <random>

#include "curve_reference.hpp"
#include "curves/bernstein.hpp"
#include "curves/bezier.hpp"
#include "curves/de_casteljau.hpp"
#include "io/registry.hpp"

using cg::Bernstein;
using glm::dvec2;

namespace {

Bernstein::Result run(const Bernstein::Input& in, std::vector<std::string>* events = nullptr) {
    auto s = Bernstein::start(in);
    while (!Bernstein::done(s)) {
        cg::StepInfo info;
        Bernstein::step(s, &info);
        if (events) events->push_back(info.event);
    }
    return Bernstein::result(s);
}

std::vector<glm::dvec3> as3(const std::vector<dvec2>& p) {
    std::vector<glm::dvec3> out;
    for (dvec2 q : p) out.push_back({q.x, q.y, 0});
    return out;
}

double cross(dvec2 a, dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

}  // namespace

TEST_CASE("bernstein: binomial coefficients are exact up to degree 50", "[curves][bernstein]") {
    std::vector<std::uint64_t> row{1};
    for (int n = 1; n <= cg::curves::kMaxDegree; ++n) {
        std::vector<std::uint64_t> next(static_cast<std::size_t>(n) + 1, 1);
        for (int i = 1; i < n; ++i)
            next[static_cast<std::size_t>(i)] =
                row[static_cast<std::size_t>(i) - 1] + row[static_cast<std::size_t>(i)];
        row = next;
        for (int i = 0; i <= n; ++i) {
            CAPTURE(n, i);
            REQUIRE(cg::curves::binomial(n, i) ==
                    static_cast<double>(row[static_cast<std::size_t>(i)]));
        }
    }
    CHECK(cg::curves::binomial(50, 25) == 126410606437752.0);
}

TEST_CASE("bernstein: a cubic at t = 1/3 worked by hand", "[curves][bernstein]") {
    std::vector<std::string> events;
    const auto r = run({{{0, 0}, {1, 3}, {4, 4}, {6, 1}}, 1.0 / 3, false, std::nullopt}, &events);
    CHECK(events == std::vector<std::string>{"basis", "basis", "basis", "basis", "sum",
                                             "non-negative", "point", "hull"});
    const double want[] = {8.0 / 27, 12.0 / 27, 6.0 / 27, 1.0 / 27};
    for (int i = 0; i < 4; ++i)
        CHECK(r.basis[static_cast<std::size_t>(i)] == Approx(want[i]).epsilon(1e-15));
    CHECK(std::fabs(r.sum - 1) <= 1e-15);
    CHECK(r.non_negative);
    // P = (12·(1, 3) + 6·(4, 4) + 1·(6, 1)) / 27 = (42, 61) / 27
    CHECK(r.point.x == Approx(42.0 / 27).epsilon(1e-15));
    CHECK(r.point.y == Approx(61.0 / 27).epsilon(1e-15));
    CHECK(r.hull == std::vector<dvec2>{{0, 0}, {6, 1}, {4, 4}, {1, 3}});
    CHECK(r.inside_hull);
    CHECK_FALSE(r.affine_invariant.has_value());
    CHECK_FALSE(r.transformed_point.has_value());
}

TEST_CASE("bernstein: each step reports its line and numbers", "[curves][bernstein]") {
    auto s = Bernstein::start({{{0, 0}, {2, 4}, {4, 0}}, 0.25, false, std::nullopt});
    cg::StepInfo info;
    Bernstein::step(s, &info);
    Bernstein::step(s, &info);
    CHECK(info.event == "basis");
    CHECK(info.line == 2);
    CHECK(info.narration == "B₁²(0.25) = C(2, 1)·(1 − t)¹·t¹ = 2 · 0.75¹ · 0.25¹ = 0.375.");
    Bernstein::step(s, &info);
    Bernstein::step(s, &info);
    CHECK(info.event == "sum");
    CHECK(info.line == 3);
    Bernstein::step(s, &info);
    Bernstein::step(s, &info);
    CHECK(info.event == "point");
    CHECK(info.narration == "P(0.25) = 0.5625·(0, 0) + 0.375·(2, 4) + 0.0625·(4, 0) = (1, 1.5).");
}

TEST_CASE("bernstein: 2,000 random curves: unity, de Casteljau, the hull, affine invariance",
          "[curves][bernstein]") {
    for (int trial = 0; trial < 2000; ++trial) {
        std::mt19937_64 rng(trial);
        std::uniform_real_distribution<double> u(-10, 10), unit(0, 1);
        const int n = 1 + trial % 10;
        Bernstein::Input in;
        for (int i = 0; i <= n; ++i) in.control_points.push_back({u(rng), u(rng)});
        in.t = trial % 100 == 0 ? 0 : trial % 100 == 1 ? 1 : unit(rng);
        if (trial % 13 == 0)  // collinear control points
            for (auto& p : in.control_points) p = {p.x, 0.5 * p.x + 1};
        Bernstein::Rows m{glm::dvec3{u(rng), u(rng), u(rng)}, glm::dvec3{u(rng), u(rng), u(rng)},
                          glm::dvec3{0, 0, 1}};
        in.transform = m;
        CAPTURE(trial, n, in.t);
        const auto r = run(in);
        double scale = 0;
        for (dvec2 p : in.control_points) scale = std::max({scale, std::fabs(p.x), std::fabs(p.y)});

        CHECK(std::fabs(r.sum - 1) <= 1e-15);
        CHECK(r.non_negative);
        for (int i = 0; i <= n; ++i)
            CHECK(std::fabs(r.basis[static_cast<std::size_t>(i)] -
                            double(cg::test::bernstein_l(n, i, in.t))) <= 1e-15);
        const auto dc = cg::DeCasteljau::evaluate({as3(in.control_points), 2, in.t, false});
        CHECK(std::fabs(r.point.x - dc.point.x) <= 1e-12 * scale);
        CHECK(std::fabs(r.point.y - dc.point.y) <= 1e-12 * scale);

        // The hull from its definition: its corners are control points, it turns left at every
        // corner, and every control point and every curve sample is on its inner side.
        REQUIRE(r.hull.size() >= 2);
        for (dvec2 h : r.hull)
            CHECK(std::find(in.control_points.begin(), in.control_points.end(), h) !=
                  in.control_points.end());
        if (trial % 13 == 0) CHECK(r.hull.size() == 2);
        std::vector<dvec2> inside = in.control_points;
        for (int j = 0; j <= 50; ++j) {
            const auto p = cg::curves::bezier_point(as3(in.control_points), j / 50.0);
            inside.push_back({p.x, p.y});
        }
        if (r.hull.size() >= 3) {
            for (std::size_t i = 0; i < r.hull.size(); ++i) {
                const dvec2 a = r.hull[i], b = r.hull[(i + 1) % r.hull.size()],
                            c = r.hull[(i + 2) % r.hull.size()];
                CHECK(cross(b - a, c - b) > 0);
                for (dvec2 p : inside)
                    CHECK(cross(b - a, p - a) >= -1e-9 * scale * glm::length(b - a));
            }
        }
        for (dvec2 p : inside) CHECK(Bernstein::in_hull(r.hull, p, 1e-9 * scale));
        CHECK(r.inside_hull);

        // Affine invariance: Σ B_i T(P_i) = T(P(t)) to 1e-12 of the mapped points' size.
        REQUIRE(r.transformed_point.has_value());
        REQUIRE(r.affine_invariant.has_value());
        CHECK(*r.affine_invariant);
        double mapped_scale = 0;
        for (dvec2 p : in.control_points) {
            const dvec2 q = Bernstein::apply(m, p);
            mapped_scale = std::max({mapped_scale, std::fabs(q.x), std::fabs(q.y)});
        }
        CHECK(glm::length(*r.transformed_point - *r.image_of_point) <= 1e-12 * mapped_scale);
    }
}

TEST_CASE("bernstein: outside [0, 1] some weights are negative and the point can leave the hull",
          "[curves][bernstein]") {
    Bernstein::Input in{{{0, 0}, {1, 3}, {4, 4}, {6, 1}}, 1.3, false, std::nullopt};
    CHECK_THROWS_WITH(Bernstein::start(in), Catch::StartsWith("t: must lie in [0, 1] (got 1.3)"));
    in.extrapolate = true;
    std::vector<std::string> events;
    const auto r = run(in, &events);
    CHECK(events[5] == "negative-weight");
    CHECK_FALSE(r.non_negative);
    CHECK(std::fabs(r.sum - 1) <= 1e-14);
    CHECK_FALSE(r.inside_hull);
}

TEST_CASE("bernstein: bad input names the field", "[curves][bernstein]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(Bernstein::start({{{0, 0}, {1, nan}}, 0.5, false, std::nullopt}),
                      "control_points[1][1]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Bernstein::start({{{0, 0}}, 0.5, false, std::nullopt}),
                      "control_points: needs at least 2 points (got 1)");
    Bernstein::Rows projective{glm::dvec3{1, 0, 0}, glm::dvec3{0, 1, 0}, glm::dvec3{0.5, 0, 1}};
    CHECK_THROWS_WITH(Bernstein::start({{{0, 0}, {1, 1}}, 0.5, false, projective}),
                      "transform[2]: must be [0, 0, 1]: only an affine map keeps a Bézier curve "
                      "(got (0.5, 0, 1))");

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("bernstein");
    auto create = [&](const char* text) { return a.create(cg::parse_json(text)); };
    CHECK_THROWS_WITH(create(R"({"control_points": [[0, 0], [1, 1, 1]], "t": 0.5})"),
                      "control_points[1]: must be a point [x, y], got an array ([1,1,1])");
    CHECK_THROWS_WITH(
        create(
            R"({"control_points": [[0, 0], [1, 1]], "t": 0.5, "transform": [[1, 0, 0], [0, 1]]})"),
        "transform: must be 3 rows of 3 numbers, got an array ([[1,0,0],[0,1]])");
    CHECK_THROWS_WITH(
        create(
            R"({"control_points": [[0, 0], [1, 1]], "t": 0.5, "transform": [[1, 0, 0], [0, 1], [0, 0, 1]]})"),
        "transform[1]: must be a row of 3 numbers, got an array ([0,1])");
    // A null transform is the same as none.
    auto run = create(R"({"control_points": [[0, 0], [1, 1]], "t": 0.5, "transform": null})");
    while (!run->done()) run->step(nullptr);
    CHECK(a.result(*run)["affine_invariant"].is_null());
}

TEST_CASE("bernstein: the picture charts the basis beside the curve", "[curves][bernstein]") {
    auto s = Bernstein::start({{{0, 0}, {1, 3}, {4, 4}, {6, 1}}, 0.5, false, std::nullopt});
    while (!Bernstein::done(s)) Bernstein::step(s, nullptr);
    cg::Scene scene;
    Bernstein::draw(s, scene);
    CHECK(scene.handles.size() == 4);
    CHECK(scene.handles[3].x_field == "/control_points/3/0");
    int hull = 0;
    for (const auto& poly : scene.polygons) hull += poly.style.role == cg::Role::Window && poly.filled;
    CHECK(hull == 1);
    // The basis in a chart of its own: t from 0 to 1, B from 0 to 1, four curves, four values.
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& chart = scene.panels[0];
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.x.lo == 0);
    CHECK(chart.x.hi == 1);
    CHECK(chart.y.lo == 0);
    CHECK(chart.y.hi == 1);
    int plotted = 0;
    for (const auto& poly : chart.polygons) plotted += poly.points.size() == 101;
    CHECK(plotted == 4);
    int values = 0;
    for (const auto& p : chart.points) values += p.label.rfind("B", 0) == 0;
    CHECK(values == 4);
    for (const auto& p : scene.points) CHECK(p.label.rfind("B", 0) != 0);  // none in the world
}
