// Arc length: the table is increasing and its length converges to the integral like 1/N²;
// the integral matches the closed form for quadratics; inverting is exact on uniformly
// parameterised lines and within the table's own error bound on curves; equal fractions give
// (nearly) equal spacing along the curve.
#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <random>

#include "curve_reference.hpp"
#include "curves/arc_length.hpp"
#include "curves/bezier.hpp"
#include "io/exam.hpp"
#include "io/registry.hpp"
#include "support/sweep.hpp"

using cg::ArcLength;
using glm::dvec3;

namespace {

ArcLength::Result run(const ArcLength::Input& in, std::vector<std::string>* events = nullptr) {
    auto s = ArcLength::start(in);
    while (!ArcLength::done(s)) {
        cg::StepInfo info;
        ArcLength::step(s, &info);
        if (events) events->push_back(info.event);
    }
    return ArcLength::result(s);
}

// The arc length of a quadratic from 0 to u in closed form: |P'(v)| = sqrt(A v² + B v + C).
long double quadratic_length(const std::vector<dvec3>& p, long double u) {
    const long double ax = 2.0L * (p[0].x - 2.0L * p[1].x + p[2].x),
                      ay = 2.0L * (p[0].y - 2.0L * p[1].y + p[2].y);
    const long double bx = 2.0L * (p[1].x - p[0].x),
                      by = 2.0L * (p[1].y - p[0].y);  // P'(v) = a v + b
    const long double A = ax * ax + ay * ay, B = 2 * (ax * bx + ay * by), C = bx * bx + by * by;
    auto F = [&](long double v) {
        const long double q = std::sqrt(A * v * v + B * v + C);
        return (2 * A * v + B) * q / (4 * A) + (4 * A * C - B * B) / (8 * A * std::sqrt(A)) *
                                                   std::log(2 * std::sqrt(A) * q + 2 * A * v + B);
    };
    return F(u) - F(0);
}

// ∫_0^u |P'(v)| dv by composite Simpson on 20,000 panels in long double (the test's reference).
long double arc_length_l(const std::vector<dvec3>& p, long double u) {
    const int panels = 20000;
    const long double h = u / panels;
    auto f = [&](long double v) {
        const auto d = cg::test::bezier_derivative_l(p, v);
        return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    };
    long double sum = f(0) + f(u);
    for (int k = 1; k < panels; ++k) sum += (k % 2 ? 4 : 2) * f(k * h);
    return sum * h / 3;
}

}  // namespace

TEST_CASE("arc-length: the exam-sized quadratic worked by hand", "[curves][arc-length]") {
    std::vector<std::string> events;
    const auto r = run({{{0, 0, 0}, {2, 4, 0}, {4, 0, 0}}, 2, 4, {3}, {}}, &events);
    CHECK(events == std::vector<std::string>{"sample", "sample", "sample", "sample", "sample",
                                             "length", "query"});
    // Samples (0, 0), (1, 1.5), (2, 2), (3, 1.5), (4, 0): chords √3.25, √1.25, √1.25, √3.25.
    const double a = std::sqrt(3.25), b = std::sqrt(1.25);
    CHECK(r.u == std::vector<double>{0, 0.25, 0.5, 0.75, 1});
    CHECK(r.s[1] == Approx(a).epsilon(1e-15));
    CHECK(r.s[2] == Approx(a + b).epsilon(1e-15));
    CHECK(r.s[4] == Approx(2 * (a + b)).epsilon(1e-15));
    CHECK(r.length == r.s[4]);
    // s = 3 lies in [s_2, s_3]: u = 0.5 + (3 − s_2)/(s_3 − s_2)·0.25.
    REQUIRE(r.queries.size() == 1);
    CHECK(r.queries[0].bracket == 2);
    CHECK(r.queries[0].u == Approx(0.5 + (3 - (a + b)) / b * 0.25).epsilon(1e-14));
    CHECK(r.length_exact ==
          Approx(double(quadratic_length({{0, 0, 0}, {2, 4, 0}, {4, 0, 0}}, 1))).epsilon(1e-12));
    CHECK(r.length_error < 0);
}

TEST_CASE("arc-length: the integral agrees with the closed form for 500 quadratics",
          "[curves][arc-length]") {
    for (int trial = 0; trial < 500; ++trial) {
        std::mt19937_64 rng(trial);
        const auto p = cg::test::random_points(rng, 3, 2);
        CAPTURE(trial);
        const double exact = double(quadratic_length(p, 1));
        CHECK(std::fabs(ArcLength::exact_length(p) - exact) <= 1e-11 * exact);
    }
}

TEST_CASE("arc-length: tables increase and converge to the integral like 1/N²",
          "[curves][arc-length]") {
    for (int trial = 0; trial < int(cg::test::sweep(200)); ++trial) {
        std::mt19937_64 rng(trial);
        const int n = 2 + trial % 4, dim = trial % 2 ? 3 : 2;
        const auto p = cg::test::random_points(rng, n + 1, dim);
        CAPTURE(trial, n, dim);
        const double exact = ArcLength::exact_length(p);
        CHECK(std::fabs(exact - double(arc_length_l(p, 1))) <= 1e-6 * exact);
        // Near a cusp (the speed |P'| almost 0) the error is erratic, not yet asymptotic.
        double slowest = 1e300;
        for (int k = 0; k <= 1000; ++k) {
            const auto d = cg::test::bezier_derivative_l(p, k / 1000.0L);
            slowest = std::min(slowest, double(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z)));
        }
        const bool smooth = slowest > 0.1 * exact;
        double previous_error = 0, first_error = 0;
        for (int samples : {50, 100, 200, 400}) {
            const auto r = run({p, dim, samples, {}, {}});
            REQUIRE(r.s.size() == std::size_t(samples + 1));
            for (std::size_t j = 1; j < r.s.size(); ++j) CHECK(r.s[j] >= r.s[j - 1]);
            const double error = exact - r.length;
            CHECK(error >= -1e-12 * exact);  // chords are never longer than the arc
            CHECK(r.length_error == Approx(-error).margin(1e-15 * exact));
            // Doubling N quarters the error (asymptotically; allow 3.2 .. 4.8).
            if (samples == 50) first_error = error;
            if (samples == 400) CHECK(error < first_error / 8);
            if (smooth && previous_error > 1e-9 * exact) {
                CHECK(previous_error / error > 3.2);
                CHECK(previous_error / error < 4.8);
            }
            previous_error = error;
        }
    }
}

TEST_CASE("arc-length: inversion is exact on uniformly parameterised lines",
          "[curves][arc-length]") {
    for (int trial = 0; trial < 200; ++trial) {
        std::mt19937_64 rng(trial);
        const auto ends = cg::test::random_points(rng, 2, 3);
        const int n = 1 + trial % 4;  // the same line written with evenly spaced control points
        std::vector<dvec3> p;
        for (int i = 0; i <= n; ++i) p.push_back(ends[0] + (ends[1] - ends[0]) * (double(i) / n));
        const double length = glm::length(ends[1] - ends[0]);
        CAPTURE(trial, n);
        const auto r = run({p, 3, 7, {}, {0, 0.1, 0.33, 0.5, 0.9, 1}});
        CHECK(r.length == Approx(length).epsilon(1e-14));
        for (const auto& q : r.queries) {
            CHECK(q.u == Approx(q.s / length).margin(1e-14));
            CHECK(glm::length(q.point - ends[0]) == Approx(q.s).margin(1e-12 * length));
        }
    }
}

TEST_CASE("arc-length: on curves the inverse is within the table's error bound",
          "[curves][arc-length]") {
    for (int trial = 0; trial < int(cg::test::sweep(100)); ++trial) {
        std::mt19937_64 rng(1000 + trial);
        const int n = 2 + trial % 3, samples = 10 + 10 * (trial % 4);
        const auto p = cg::test::random_points(rng, n + 1, 2);
        CAPTURE(trial, n, samples);
        const auto r = run({p, 2, samples, {}, {0.1, 0.3, 0.5, 0.7, 0.95}});
        // Bound: the table's deficit at its end, plus linear interpolation's error inside one
        // interval, h²/8 · max |d|P'|/du| ≤ h²/8 · n (n − 1) max |P_{i+2} − 2 P_{i+1} + P_i|.
        double second = 0;
        for (int i = 0; i + 2 <= n; ++i)
            second = std::max(second, glm::length(p[std::size_t(i) + 2] -
                                                  2.0 * p[std::size_t(i) + 1] + p[std::size_t(i)]));
        const double h = 1.0 / samples;
        const double bound = -r.length_error + h * h / 8 * n * (n - 1) * second + 1e-9 * r.length;
        for (const auto& q : r.queries) {
            const double travelled = double(arc_length_l(p, q.u));
            CHECK(std::fabs(travelled - q.s) <= bound);
            CHECK(glm::length(q.point - cg::curves::bezier_point(p, q.u)) <= 1e-12 * r.length);
        }
    }
}

TEST_CASE("arc-length: equal fractions give nearly equal spacing, equal u does not",
          "[curves][arc-length]") {
    const std::vector<dvec3> p{{0, 0, 0}, {1, 4, 0}, {2, 4, 0}, {8, 0, 0}};
    std::vector<double> fractions;
    for (int k = 1; k < 10; ++k) fractions.push_back(k / 10.0);
    const auto r = run({p, 2, 200, {}, fractions});
    const double exact = r.length_exact;
    double worst_corrected = 0, worst_naive = 0;
    double previous_corrected = 0, previous_naive = 0;
    for (std::size_t k = 0; k < r.queries.size(); ++k) {
        const double corrected = double(arc_length_l(p, r.queries[k].u));
        const double naive = double(arc_length_l(p, fractions[k]));
        worst_corrected =
            std::max(worst_corrected, std::fabs(corrected - previous_corrected - exact / 10));
        worst_naive = std::max(worst_naive, std::fabs(naive - previous_naive - exact / 10));
        previous_corrected = corrected, previous_naive = naive;
    }
    CAPTURE(worst_corrected, worst_naive);
    CHECK(worst_corrected < 1e-3 * exact / 10);
    CHECK(worst_naive > 0.2 * exact / 10);
}

TEST_CASE("arc-length: degenerate curves and bad input", "[curves][arc-length]") {
    SECTION("a curve that stands still has length 0, and s = 0 is at u = 0") {
        const auto r = run({{{1, 1, 0}, {1, 1, 0}, {1, 1, 0}}, 2, 5, {0}, {}});
        CHECK(r.length == 0);
        CHECK(r.length_exact == 0);
        CHECK(r.queries[0].u == 0);
    }
    SECTION("s at the ends, and fraction 1 exactly at the end") {
        const auto r = run({{{0, 0, 0}, {2, 4, 0}, {4, 0, 0}}, 2, 4, {}, {0, 1}});
        CHECK(r.queries[0].u == 0);
        CHECK(r.queries[1].u == 1);
        CHECK(r.queries[1].point == dvec3(4, 0, 0));
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<dvec3> p{{0, 0, 0}, {2, 4, 0}, {4, 0, 0}};
    CHECK_THROWS_WITH(ArcLength::start({p, 2, 0, {}, {}}),
                      "samples: must be between 1 and 10000 (got 0)");
    CHECK_THROWS_WITH(ArcLength::start({p, 2, 10001, {}, {}}),
                      "samples: must be between 1 and 10000 (got 10001)");
    CHECK_THROWS_WITH(ArcLength::start({p, 2, 4, {1}, {0.5}}),
                      "fractions: give distances or fractions, not both");
    CHECK_THROWS_WITH(ArcLength::start({p, 2, 4, {}, {1.5}}),
                      "fractions[0]: must lie in [0, 1] (got 1.5)");
    CHECK_THROWS_WITH(
        ArcLength::start({p, 2, 4, {1, 7}, {}}),
        "distances[1]: must lie in [0, 5.84162], the length of the table with 4 samples (got 7)");
    CHECK_THROWS_WITH(ArcLength::start({p, 2, 4, {nan}, {}}),
                      "distances[0]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(ArcLength::start({{{0, 0, 0}}, 2, 4, {}, {}}),
                      "control_points: needs at least 2 points (got 1)");

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("arc-length");
    auto create = [&](const char* text) { return a.create(cg::parse_json(text)); };
    CHECK_THROWS_WITH(create(R"({"control_points": [[0, 0], [1, 1]], "samples": 2.5})"),
                      "samples: must be an integer, got 2.5");
    CHECK_THROWS_WITH(create(R"({"control_points": [[0, 0], [1, 1]], "distances": [1, "a"]})"),
                      "distances[1]: must be a number, got a string (\"a\")");
    // The default N is 10, and 3D points come back with three coordinates.
    auto r = create(R"({"control_points": [[0, 0, 0], [3, 4, 12]], "distances": [6.5]})");
    while (!r->done()) r->step(nullptr);
    const cg::json j = a.result(*r);
    CHECK(j["table"].size() == 11);
    CHECK(j["length"].get<double>() == Approx(13).epsilon(1e-15));
    CHECK(j["queries"][0]["point"] == cg::json::parse("[1.5, 2.0, 6.0]"));
}

TEST_CASE("arc-length: exam problems have four chords and a distance inside the curve",
          "[curves][arc-length][exam]") {
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const auto in = ArcLength::exam_input(rng);
        CHECK(in.samples == 4);
        REQUIRE(in.distances.size() == 1);
        const double length = ArcLength::table_length(in.control_points, 4);
        CHECK(in.distances[0] > 0);
        CHECK(in.distances[0] < length);
        CHECK(in.distances[0] * 2 == std::floor(in.distances[0] * 2));
    }
}
