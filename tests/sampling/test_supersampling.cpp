// Supersampling one pixel: the patterns (positions in their cells, Poisson distances, seeds),
// the filters' weights, hand-worked exam cases (regular grids on an edge, points on the edge,
// a small object lost between samples, weighted filters); the exact coverage against an
// independent reference (vertical slices in long double) on 4,000 random edges and polygons,
// degenerate ones included; run-to-end == the plain function; the estimate recomputed from the
// samples; the convergence study (the error of each pattern as the number of samples grows, over
// many edges and seeds) against its own recomputation with the long-double reference, and the
// course's claims about its slopes; errors naming the field; determinism and the pictures.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "io/registry.hpp"
#include "sampling/sampling_reference.hpp"
#include "sampling/supersampling.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Supersampling;
using cg::sampling::Filter;
using cg::sampling::Pattern;
using cg::sampling::Region;
using cg::sampling::RegionKind;
using glm::dvec2;

namespace {

Region edge(dvec2 p, double angle) {
    Region r;
    r.kind = RegionKind::Edge;
    r.point = p;
    r.angle_deg = angle;
    return r;
}

Region polygon(std::vector<dvec2> pts) {
    Region r;
    r.kind = RegionKind::Polygon;
    r.points = std::move(pts);
    return r;
}

Supersampling::Input input(Pattern p, int n, Filter f, int i, int j, Region scene,
                           std::uint64_t seed = 1) {
    Supersampling::Input in;
    in.pattern = p;
    in.samples = n;
    in.filter = f;
    in.i = i, in.j = j;
    in.scene = std::move(scene);
    in.seed = seed;
    return in;
}

using Traced = cg::test::Traced<Supersampling>;
Traced run_traced(const Supersampling::Input& in) {
    return cg::test::run_traced<Supersampling>(in);
}

// The filters written out again, from the lesson's formulas.
double weight_of(Filter f, dvec2 d) {
    if (f == Filter::Box) return 1;
    if (f == Filter::Tent) return (1 - std::fabs(d.x)) * (1 - std::fabs(d.y));
    return std::exp(-(d.x * d.x + d.y * d.y) / 0.5);
}

}  // namespace

TEST_CASE("supersampling: patterns put their points where they promise",
          "[sampling][supersampling]") {
    using cg::sampling::generate;
    SECTION("regular: the cell centres, row by row from the bottom") {
        const auto pts = generate(Pattern::Regular, 9, 123);
        REQUIRE(pts.size() == 9);
        for (int b = 0; b < 3; ++b)
            for (int a = 0; a < 3; ++a) {
                CHECK(pts[b * 3 + a].p == dvec2((a + 0.5) / 3, (b + 0.5) / 3));
                CHECK(pts[b * 3 + a].cell_a == a);
                CHECK(pts[b * 3 + a].cell_b == b);
            }
        CHECK(generate(Pattern::Regular, 9, 1) == generate(Pattern::Regular, 9, 2));
    }
    SECTION("jittered: one uniform point in each cell, x = (a + ξx)/n") {
        for (std::uint64_t seed = 0; seed < 200; ++seed) {
            for (int n : {1, 2, 3, 4, 8}) {
                const auto pts = generate(Pattern::Jittered, n * n, seed);
                REQUIRE(int(pts.size()) == n * n);
                for (const auto& q : pts) {
                    REQUIRE(q.p.x >= double(q.cell_a) / n);
                    REQUIRE(q.p.x < double(q.cell_a + 1) / n);
                    REQUIRE(q.p.y >= double(q.cell_b) / n);
                    REQUIRE(q.p.y < double(q.cell_b + 1) / n);
                    REQUIRE(q.p.x == Approx((q.cell_a + q.xi.x) / n).epsilon(1e-15));
                }
            }
        }
        // The uniform numbers come from core/rng.hpp, x before y, cell by cell.
        cg::Rng rng(7);
        const auto pts = generate(Pattern::Jittered, 4, 7);
        for (const auto& q : pts) {
            const double x = rng.uniform(0, 1);
            const double y = rng.uniform(0, 1);
            CHECK(q.xi == dvec2(x, y));
        }
        CHECK(generate(Pattern::Jittered, 16, 7) == generate(Pattern::Jittered, 16, 7));
        CHECK_FALSE(generate(Pattern::Jittered, 16, 7) == generate(Pattern::Jittered, 16, 8));
    }
    SECTION("random: uniform points in the square") {
        const auto pts = generate(Pattern::Random, 1000, 5);
        double mx = 0, my = 0;
        for (const auto& q : pts) {
            REQUIRE((q.p.x >= 0 && q.p.x < 1 && q.p.y >= 0 && q.p.y < 1));
            mx += q.p.x / 1000, my += q.p.y / 1000;
        }
        CHECK(std::fabs(mx - 0.5) < 0.05);
        CHECK(std::fabs(my - 0.5) < 0.05);
    }
    SECTION("poisson: every pair at least r apart; too large a radius gives fewer points") {
        for (std::uint64_t seed = 0; seed < 100; ++seed) {
            for (int n : {2, 9, 16, 64}) {
                const double r = cg::sampling::default_radius(n);
                const auto pts = generate(Pattern::Poisson, n, seed, r);
                REQUIRE(int(pts.size()) == n);  // 0.7/√N is always reached
                for (std::size_t a = 0; a < pts.size(); ++a)
                    for (std::size_t b = a + 1; b < pts.size(); ++b)
                        REQUIRE(glm::length(pts[a].p - pts[b].p) >= r);
            }
        }
        const auto few = generate(Pattern::Poisson, 16, 3, 0.9);
        CHECK(few.size() < 4);
        CHECK_FALSE(few.empty());
    }
    SECTION("per-pixel seeds differ from pixel to pixel and from seed to seed") {
        using cg::sampling::mix_seed;
        CHECK(mix_seed(1, 0, 0) != mix_seed(1, 1, 0));
        CHECK(mix_seed(1, 1, 0) != mix_seed(1, 0, 1));
        CHECK(mix_seed(1, 3, 4) != mix_seed(2, 3, 4));
        CHECK(mix_seed(1, 3, 4) == mix_seed(1, 3, 4));
    }
    SECTION("grid sides") {
        CHECK(cg::sampling::grid_side(1) == 1);
        CHECK(cg::sampling::grid_side(16) == 4);
        CHECK(cg::sampling::grid_side(1024) == 32);
        CHECK(cg::sampling::grid_side(15) == 0);
        CHECK(cg::sampling::grid_side(0) == 0);
    }
}

TEST_CASE("supersampling: filter weights and their integrals", "[sampling][supersampling]") {
    using cg::sampling::weight;
    CHECK(weight(Filter::Box, {0.3, -0.2}) == 1);
    CHECK(weight(Filter::Tent, {0, 0}) == 1);
    CHECK(weight(Filter::Tent, {0.5, 0.5}) == 0.25);
    CHECK(weight(Filter::Tent, {0.25, -0.25}) == 0.5625);
    CHECK(weight(Filter::Gaussian, {0.5, 0.5}) == Approx(std::exp(-1.0)).epsilon(1e-15));
    // ∫∫ w over the pixel, against a fine midpoint rule.
    for (Filter f : {Filter::Box, Filter::Tent, Filter::Gaussian}) {
        long double sum = 0;
        const int m = 400;
        for (int a = 0; a < m; ++a)
            for (int b = 0; b < m; ++b)
                sum += weight(f, {(a + 0.5) / m - 0.5, (b + 0.5) / m - 0.5});
        CHECK(double(sum / (m * m)) ==
              Approx(cg::sampling::pixel_weight_integral(f)).epsilon(1e-5));
    }
}

TEST_CASE("supersampling: exam cases worked by hand", "[sampling][supersampling]") {
    SECTION("a vertical edge at x = 2.3 with a regular 2 × 2 grid: 0.5 against 0.3") {
        // Going up (90°), the inside is on the left: x ≤ 2.3, 30% of pixel (2, 1).
        const Traced t =
            run_traced(input(Pattern::Regular, 4, Filter::Box, 2, 1, edge({2.3, 0}, 90)));
        CHECK(cg::test::events(t) == std::vector<std::string>{"pattern", "inside", "outside",
                                                              "inside", "outside", "estimate",
                                                              "exact"});
        CHECK(t.result.samples[0].p == dvec2(2.25, 1.25));
        CHECK(t.result.samples[3].p == dvec2(2.75, 1.75));
        CHECK(t.result.estimate == 0.5);
        CHECK(t.result.exact == Approx(0.3).epsilon(1e-14));
        CHECK(t.result.error == Approx(0.2).epsilon(1e-13));
        CHECK_THAT(t.steps[5].narration, Catch::Contains("Σ w v / Σ w = 2 / 4 = 0.5"));
        CHECK_THAT(t.steps[6].narration, Catch::Contains("with area 0.3"));
    }
    SECTION("the diagonal through the pixel's corner: samples on the edge count as inside") {
        // y = x going up-right; inside y ≥ x: half the pixel. 3 × 3 grid: 3 on the line, 3 above.
        const Traced t =
            run_traced(input(Pattern::Regular, 9, Filter::Box, 0, 0, edge({0, 0}, 45)));
        CHECK(t.result.exact == Approx(0.5).epsilon(1e-15));
        int on_line = 0;
        for (const auto& s : t.result.samples) on_line += s.p.x == s.p.y && s.value == 1;
        CHECK(on_line == 3);
        CHECK(t.result.estimate == Approx(6.0 / 9).epsilon(1e-15));
    }
    SECTION("a small object lost between the samples") {
        // A triangle of area 0.02 in the middle of a 2 × 2 grid's cell: no sample sees it.
        const Region tri = polygon({{0.4, 0.4}, {0.6, 0.4}, {0.5, 0.6}});
        const Traced t = run_traced(input(Pattern::Regular, 4, Filter::Box, 0, 0, tri));
        CHECK(t.result.estimate == 0);
        CHECK(t.result.exact == Approx(0.02).epsilon(1e-13));
        CHECK(t.steps.back().event == "exact");
    }
    SECTION("tent and Gaussian weights of a regular 2 × 2 grid") {
        const Region e = edge({0.5, 0}, 90);  // x ≤ 0.5: the left half
        const Traced tent = run_traced(input(Pattern::Regular, 4, Filter::Tent, 0, 0, e));
        for (const auto& s : tent.result.samples) CHECK(s.weight == 0.5625);
        CHECK(tent.result.estimate == 0.5);
        CHECK(tent.result.exact == Approx(0.5).epsilon(1e-14));
        const Traced g = run_traced(input(Pattern::Regular, 4, Filter::Gaussian, 0, 0, e));
        for (const auto& s : g.result.samples) CHECK(s.weight == Approx(std::exp(-0.25)));
        CHECK(g.result.exact == Approx(0.5).epsilon(1e-14));
    }
    SECTION("a triangle over half the pixel: 0.5 for every filter (the weights are symmetric)") {
        for (Filter f : {Filter::Box, Filter::Tent, Filter::Gaussian}) {
            const auto r = Supersampling::supersample(
                input(Pattern::Jittered, 16, f, 0, 0, polygon({{0, 0}, {1, 0}, {0, 1}})));
            CHECK(r.exact == Approx(0.5).epsilon(1e-13));
        }
    }
    SECTION("jittered samples: the narration shows the cell and ξ") {
        const Traced t =
            run_traced(input(Pattern::Jittered, 4, Filter::Box, 3, 5, edge({3.5, 5.5}, 30), 11));
        const auto pts = cg::sampling::generate(Pattern::Jittered, 4, 11);
        CHECK(t.result.samples[1].p == dvec2(3, 5) + pts[1].p);
        CHECK_THAT(t.steps[2].narration, Catch::Contains("cell (1, 0), ξ = "));
        CHECK_THAT(t.steps[2].narration, Catch::Contains("x = 3 + (1 + "));
    }
    SECTION("poisson: the narration counts the darts") {
        Supersampling::Input in =
            input(Pattern::Poisson, 16, Filter::Box, 0, 0, edge({0.2, 0}, 80), 3);
        const Traced t = run_traced(in);
        CHECK_THAT(t.steps[0].narration, Catch::Contains("dart throwing"));
        CHECK(t.result.radius == Approx(0.7 / 4));
        in.radius = 0.8;
        const Traced few = run_traced(in);
        CHECK(few.result.samples.size() < 16);
        CHECK_THAT(few.steps[0].narration, Catch::Contains("r is too large for so many"));
    }
}

TEST_CASE(
    "supersampling: the exact coverage agrees with vertical slices in long double on 4,000 random "
    "scenes",
    "[sampling][supersampling]") {
    double worst = 0;
    int partial = 0, full = 0, none = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(trial);
        const int i = static_cast<int>(rng.integer(-3, 3)),
                  j = static_cast<int>(rng.integer(-3, 3));
        const Filter f = static_cast<Filter>(trial % 3);
        Region r;
        switch (trial % 8) {
            case 0:  // an edge along the pixel's border or through its corner, axis angles
                r = edge({double(i + rng.integer(0, 1)), double(j + rng.integer(0, 1))},
                         90.0 * rng.integer(0, 3) + (rng.chance(0.5) ? 45 : 0));
                break;
            case 1:
            case 2:
            case 3:  // an edge anywhere near the pixel
                r = edge({i + rng.uniform(-1, 2), j + rng.uniform(-1, 2)}, rng.uniform(-360, 360));
                break;
            case 4: {  // a triangle, often smaller than the pixel
                const double s = rng.chance(0.5) ? 0.3 : 2;
                std::vector<dvec2> p(3);
                for (auto& q : p) q = {i + rng.uniform(-s, 1 + s), j + rng.uniform(-s, 1 + s)};
                if (cg::sampling::signed_area(p) == 0) continue;
                r = polygon(p);
                break;
            }
            case 5: {  // a star-shaped (mostly concave) polygon about the pixel
                const dvec2 c(i + rng.uniform(0, 1), j + rng.uniform(0, 1));
                std::vector<double> a(rng.integer(3, 12));
                for (double& x : a) x = rng.uniform(0, 2 * M_PI);
                std::sort(a.begin(), a.end());
                a.erase(std::unique(a.begin(), a.end()), a.end());
                std::vector<dvec2> p;
                for (double x : a) {
                    const double rad = rng.uniform(0.1, 1.5);
                    p.push_back(c + rad * dvec2(std::cos(x), std::sin(x)));
                }
                if (p.size() < 3) continue;
                r = polygon(p);
                break;
            }
            case 6:  // a polygon with vertices on the pixel's corners and borders
                r = polygon({{double(i), double(j)},
                             {i + 1.0, double(j)},
                             {i + 0.5, j + rng.uniform(0, 1)}});
                break;
            default:  // a big polygon holding the whole pixel, or one far away
                if (rng.chance(0.5))
                    r = polygon({{i - 3.0, j - 2.0}, {i + 4.0, j - 1.0}, {i + 1.0, j + 5.0}});
                else
                    r = polygon({{i + 3.0, j + 3.0}, {i + 4.0, j + 3.0}, {i + 4.0, j + 4.0}});
                break;
        }
        try {
            Supersampling::validate(input(Pattern::Random, 1, f, i, j, r));
        } catch (const cg::InputError&) {
            continue;  // a random star that is not simple
        }
        const double got = cg::sampling::exact_coverage(r, f, i, j);
        const double ref = double(sampling_reference::exact(r, f, i, j));
        CAPTURE(got, ref, int(f));
        REQUIRE(std::fabs(got - ref) <= 1e-12);
        worst = std::max(worst, std::fabs(got - ref));
        if (ref == 0)
            ++none;
        else if (ref == 1)
            ++full;
        else
            ++partial;
        // The box filter's value is the clipped polygon's area, also by the shoelace formula.
        if (f == Filter::Box)
            REQUIRE(std::fabs(cg::sampling::signed_area(cg::sampling::covered_polygon(r, i, j)) -
                              got) <= 1e-12);
    }
    CHECK(partial > 2000);
    CHECK(full > 50);
    CHECK(none > 50);
    WARN("exact coverage, worst difference from the slices: " << worst);
}

TEST_CASE("supersampling: run to the end equals the plain function, and the estimate is Σwv/Σw",
          "[sampling][supersampling]") {
    for (int trial = 0; trial < 1500; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(1000 + trial);
        const Pattern p = static_cast<Pattern>(trial % 4);
        const Filter f = static_cast<Filter>((trial / 4) % 3);
        int n = static_cast<int>(rng.integer(1, 8));
        n = cg::sampling::is_grid(p) ? n * n : n * n + static_cast<int>(rng.integer(0, 5));
        Supersampling::Input in = input(p, n, f, static_cast<int>(rng.integer(-5, 5)),
                                        static_cast<int>(rng.integer(-5, 5)), Region{},
                                        static_cast<std::uint64_t>(trial));
        in.scene = edge({in.i + rng.uniform(0, 1), in.j + rng.uniform(0, 1)}, rng.uniform(0, 360));
        Supersampling::validate(in);
        const auto r = cg::run_to_end<Supersampling>(Supersampling::start(in));
        REQUIRE(Supersampling::supersample(in) == r);
        long double sw = 0, swv = 0;
        const dvec2 d = cg::sampling::edge_direction(in.scene.angle_deg);
        for (const auto& s : r.samples) {
            REQUIRE(s.p.x >= in.i);
            REQUIRE(s.p.x < in.i + 1);
            REQUIRE(s.p.y >= in.j);
            REQUIRE(s.p.y < in.j + 1);
            const dvec2 q = s.p - in.scene.point;
            REQUIRE(s.value == (d.x * q.y - d.y * q.x >= 0 ? 1 : 0));
            REQUIRE(s.weight ==
                    Approx(weight_of(f, s.p - dvec2(in.i + 0.5, in.j + 0.5))).epsilon(1e-14));
            sw += s.weight, swv += s.weight * s.value;
        }
        REQUIRE(r.estimate == Approx(double(swv / sw)).epsilon(1e-14));
        REQUIRE(r.error == r.estimate - r.exact);
    }
}

namespace {

// The study, from its input.
Supersampling::Input study_input(std::vector<Pattern> patterns, bool near_axis,
                                 std::uint64_t seed = 1, int edges = 400,
                                 std::vector<int> samples = {1, 4, 16, 64, 256}) {
    Supersampling::Input in;
    in.is_study = true;
    in.study.patterns = std::move(patterns);
    in.study.samples = std::move(samples);
    in.study.edges = edges;
    in.study.near_axis = near_axis;
    in.seed = seed;
    return in;
}

const int kCounts[] = {1, 4, 16, 64, 256};
const std::vector<Pattern> kAllPatterns = {Pattern::Regular, Pattern::Random, Pattern::Jittered,
                                           Pattern::Poisson};

// The study's RMS errors again, box filter: the trials' edges and seeds from study_trial (the
// one definition of the experiment), but the samples' values by the half-plane test written
// out, the estimate as the fraction inside, and the exact value from the long-double slices.
std::vector<double> recompute_study(const Supersampling::Input& in) {
    std::vector<long double> exact(in.study.edges);
    for (int t = 0; t < in.study.edges; ++t)
        exact[t] = sampling_reference::exact(
            Supersampling::study_trial(in, Pattern::Random, 1, t).scene, Filter::Box, 0, 0);
    std::vector<double> out;
    for (Pattern p : in.study.patterns)
        for (int n : in.study.samples) {
            long double sum = 0;
            for (int t = 0; t < in.study.edges; ++t) {
                const Supersampling::Input trial = Supersampling::study_trial(in, p, n, t);
                const double r = p == Pattern::Poisson ? cg::sampling::default_radius(n) : 0;
                const auto pts = cg::sampling::generate(p, n, trial.seed, r);
                const dvec2 d = cg::sampling::edge_direction(trial.scene.angle_deg);
                long double inside = 0;
                for (const auto& q : pts) {
                    const dvec2 v = q.p - trial.scene.point;
                    inside += d.x * v.y - d.y * v.x >= 0 ? 1 : 0;
                }
                const long double e = inside / pts.size() - exact[t];
                sum += e * e;
            }
            out.push_back(double(std::sqrt(sum / in.study.edges)));
        }
    return out;
}

}  // namespace

TEST_CASE("supersampling: the study's trials are the edges it documents",
          "[sampling][supersampling][convergence]") {
    for (bool near : {false, true})
        for (int t : {0, 1, 17, 399}) {
            const Supersampling::Input in = study_input(kAllPatterns, near, 3, 400, {4, 16});
            const auto trial = Supersampling::study_trial(in, Pattern::Jittered, 16, t);
            cg::Rng rng(50000 + t);
            const double angle = near ? rng.uniform(-1, 1) : rng.uniform(0, 360);
            CHECK(trial.scene.kind == RegionKind::Edge);
            CHECK(trial.scene.angle_deg == angle);
            CHECK(trial.scene.point.x == rng.uniform(0, 1));
            CHECK(trial.scene.point.y == rng.uniform(0, 1));
            CHECK((trial.i == 0 && trial.j == 0));
            CHECK(trial.pattern == Pattern::Jittered);
            CHECK(trial.samples == 16);
            CHECK(trial.seed == 3u * Supersampling::kMaxStudyEdges + t);
            CHECK_FALSE(trial.is_study);
            Supersampling::validate(trial);
        }
}

// The course's claims, measured by the study: over many edges and seeds, the RMS error of each
// pattern against the exact coverage as the number of samples grows.
TEST_CASE("supersampling: error against the number of samples, per pattern",
          "[sampling][supersampling][convergence]") {
    const auto any = Supersampling::run_study(study_input(kAllPatterns, false));
    const auto near = Supersampling::run_study(study_input(kAllPatterns, true));
    // The study's numbers are the RMS errors recomputed independently.
    for (const auto* r : {&any, &near}) {
        const auto ref = recompute_study(study_input(kAllPatterns, r == &near));
        REQUIRE(r->study.size() == 20);
        for (std::size_t k = 0; k < 20; ++k) {
            CAPTURE(k, r->study[k].rms_error, ref[k]);
            CHECK(r->study[k].pattern == kAllPatterns[k / 5]);
            CHECK(r->study[k].samples == kCounts[k % 5]);
            REQUIRE(std::fabs(r->study[k].rms_error - ref[k]) <= 1e-12);
        }
    }
    double table[2][4][5];
    for (int c = 0; c < 20; ++c) {
        table[0][c / 5][c % 5] = any.study[c].rms_error;
        table[1][c / 5][c % 5] = near.study[c].rms_error;
    }
    auto slope = [&](int axis, int a) {
        const auto& r = axis ? near : any;
        REQUIRE(r.slopes[a].pattern == kAllPatterns[a]);
        return r.slopes[a].slope;
    };
    for (int axis = 0; axis < 2; ++axis) {
        std::string line = axis ? "edges within 1° of the x axis:" : "edges at any angle:";
        for (int a = 0; a < 4; ++a) {
            line += std::string("\n  ") + cg::sampling::pattern_id(kAllPatterns[a]);
            for (int c = 0; c < 5; ++c) line += " " + std::to_string(table[axis][a][c]);
            line += "  slope " + std::to_string(slope(axis, a));
        }
        WARN(line);
    }
    // The slopes are the least-squares fit over N ≥ 4, recomputed here.
    for (int a = 0; a < 4; ++a) {
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (int c = 1; c < 5; ++c) {
            const double x = std::log10(kCounts[c]), y = std::log10(table[0][a][c]);
            sx += x, sy += y, sxx += x * x, sxy += x * y;
        }
        CHECK(slope(0, a) == Approx((4 * sxy - sx * sy) / (4 * sxx - sx * sx)).epsilon(1e-12));
    }
    // Random: the error of a mean of N coin flips, ∝ N^−½.
    CHECK(slope(0, 1) == Approx(-0.5).margin(0.08));
    // Jittered: only the cells the edge crosses (∝ √N of them) are random, error ∝ N^−¾.
    CHECK(slope(0, 2) == Approx(-0.75).margin(0.1));
    CHECK(slope(0, 2) < -0.65);
    CHECK(slope(0, 2) < slope(0, 1) - 0.15);
    for (int c = 2; c < 5; ++c) CHECK(table[0][2][c] < 0.6 * table[0][1][c]);
    // Poisson disc is about as good as jittered, far better than random.
    for (int c = 2; c < 5; ++c) CHECK(table[0][3][c] < 0.7 * table[0][1][c]);
    // Regular, on edges nearly along a grid row: a whole row of samples flips at once, so the
    // error stays structured, ∝ 1/n = N^−½, flatter than jittered's, and at 64 samples and more
    // it is well above jittered's.
    CHECK(slope(1, 0) == Approx(-0.5).margin(0.1));
    CHECK(slope(1, 0) > slope(1, 2) + 0.15);
    for (int c = 3; c < 5; ++c) CHECK(table[1][0][c] > 1.5 * table[1][2][c]);
    // ... while on edges at any angle the regular grid is as good as jittered.
    CHECK(table[1][0][4] > 2 * table[0][0][4]);
    CHECK(slope(0, 0) < -0.65);
    // One sample: every pattern is a single point, error about √(c(1 − c)) on average.
    for (int a = 0; a < 4; ++a) CHECK(table[0][a][0] > 0.25);
    // Structured, not noise: another seed leaves the regular grid's errors exactly as they were
    // (the same edges, no randomness in the grid) and moves jittered's and random's.
    const auto other = Supersampling::run_study(
        study_input({Pattern::Regular, Pattern::Random, Pattern::Jittered}, true, 2));
    for (int c = 0; c < 5; ++c) {
        CHECK(other.study[c].rms_error == table[1][0][c]);
        CHECK(other.study[5 + c].rms_error != table[1][1][c]);
        CHECK(other.study[10 + c].rms_error != table[1][2][c]);
    }
    CHECK(other.slopes[0].slope == slope(1, 0));
    CHECK(other.slopes[2].slope < -0.65);
}

TEST_CASE("supersampling: a study run to the end equals the plain function",
          "[sampling][supersampling][convergence]") {
    for (std::uint64_t seed : {0u, 5u}) {
        const auto in =
            study_input({Pattern::Poisson, Pattern::Jittered}, seed == 5, seed, 37, {1, 4, 9, 36});
        Supersampling::validate(in);
        const auto r = cg::run_to_end<Supersampling>(Supersampling::start(in));
        CHECK(r == Supersampling::run_study(in));
        CHECK(r.is_study);
        REQUIRE(r.study.size() == 8);
        REQUIRE(r.slopes.size() == 2);
        for (std::size_t k = 0; k < 8; ++k)
            CHECK(r.study[k].rms_error ==
                  Supersampling::study_rms(in, r.study[k].pattern, r.study[k].samples));
    }
}

TEST_CASE("supersampling: errors name the field", "[sampling][supersampling][errors]") {
    const cg::Algorithm& a = cg::test::algorithm("supersampling");
    auto error_of = [&](const std::string& text) -> std::string {
        try {
            a.create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return e.what();
        }
        return "(accepted)";
    };
    const std::string scene = R"("scene": {"type": "edge", "point": [0.5, 0.5], "angle": 30})";
    CHECK(error_of(R"({"pattern": "hex", "samples": 4, "pixel": [0, 0], )" + scene + "}") ==
          "pattern: must be \"regular\", \"random\", \"jittered\" or \"poisson\", got a string "
          "(\"hex\")");
    CHECK(
        error_of(R"({"pattern": "jittered", "samples": 5, "pixel": [0, 0], )" + scene + "}") ==
        "samples: must be a square number n × n (1, 4, 9, 16, …) for the jittered pattern (got 5)");
    CHECK(error_of(R"({"pattern": "random", "samples": 0, "pixel": [0, 0], )" + scene + "}") ==
          "samples: must be between 1 and 1024 (got 0)");
    CHECK(error_of(R"({"pattern": "random", "samples": 4, "radius": 0.1, "pixel": [0, 0], )" +
                   scene + "}") ==
          "radius: only the poisson pattern has a radius (the pattern is random)");
    CHECK(error_of(R"({"pattern": "poisson", "samples": 4, "radius": -1, "pixel": [0, 0], )" +
                   scene + "}") == "radius: must be between 0 and 2 pixels (got −1)");
    CHECK(error_of(R"({"pattern": "random", "samples": 4, "pixel": [0.5, 0], )" + scene + "}") ==
          "pixel[0]: must be an integer pixel index, got 0.5");
    CHECK(error_of(R"({"pattern": "random", "samples": 4, "pixel": [0, 0], "filter": "sinc", )" +
                   scene + "}") ==
          "filter: must be \"box\", \"tent\" or \"gaussian\", got a string (\"sinc\")");
    CHECK(error_of(R"({"pattern": "random", "samples": 4, "pixel": [0, 0], "seed": -1, )" + scene +
                   "}") == "seed: must be an integer between 0 and 2^53 (got -1)");
    CHECK(
        error_of(
            R"({"pattern": "random", "samples": 4, "pixel": [0, 0], "scene": {"type": "polygon", "points": [[0, 0], [2, 2], [2, 0], [0, 1]]}})") ==
        "scene.points: must be a simple polygon: edges 0 and 2 cross or touch");
    CHECK(
        error_of(
            R"({"pattern": "random", "samples": 4, "pixel": [0, 0], "scene": {"type": "polygon", "points": [[0, 0], [1, 1], [2, 2]]}})") ==
        "scene.points: has zero area (all vertices on one line): it covers nothing");
    CHECK(
        error_of(
            R"({"pattern": "random", "samples": 4, "pixel": [0, 0], "scene": {"type": "disc"}})") ==
        "scene.type: must be \"edge\" or \"polygon\", got \"disc\"");
    CHECK(
        error_of(
            R"({"pattern": "random", "samples": 4, "pixel": [0, 0], "scene": {"type": "edge", "point": [0, 0], "angle": 0, "width": 1}})") ==
        "scene.width: is not a known field (expected: type, point, angle)");

    // The study.
    CHECK(error_of(R"({"study": {}, "pixel": [0, 0]})") ==
          "pixel: cannot be given beside \"study\": a study draws its own edges and patterns "
          "(its filter and seed go inside it)");
    CHECK(error_of(R"({"pattern": "random", "study": {}})") ==
          "pattern: cannot be given beside \"study\": a study draws its own edges and patterns "
          "(its filter and seed go inside it)");
    CHECK(error_of(R"({"study": {"patterns": []}})") ==
          "study.patterns: must list at least one pattern (got none)");
    CHECK(error_of(R"({"study": {"patterns": ["random", "halton"]}})") ==
          "study.patterns[1]: must be \"regular\", \"random\", \"jittered\" or \"poisson\", "
          "got a string (\"halton\")");
    CHECK(error_of(R"({"study": {"patterns": ["random", "random"]}})") ==
          "study.patterns[1]: repeats \"random\"");
    CHECK(error_of(R"({"study": {"samples": []}})") ==
          "study.samples: must list between 2 and 8 sample counts (got 0)");
    CHECK(error_of(R"({"study": {"samples": [1, 4, 8]}})") ==
          "study.samples[2]: must be a square number n × n (1, 4, 9, 16, …) for the regular "
          "pattern (got 8)");
    CHECK(error_of(R"({"study": {"patterns": ["jittered"], "samples": [4, 10]}})") ==
          "study.samples[1]: must be a square number n × n (1, 4, 9, 16, …) for the jittered "
          "pattern (got 10)");
    CHECK(error_of(R"({"study": {"patterns": ["random"], "samples": [4, 10]}})") == "(accepted)");
    CHECK(error_of(R"({"study": {"samples": [16, 4]}})") ==
          "study.samples[1]: must be larger than the count before it (got 4 after 16)");
    CHECK(error_of(R"({"study": {"samples": [1, 4]}})") ==
          "study.samples: must hold at least two counts of 4 or more, to fit a slope (got 1)");
    CHECK(error_of(R"({"study": {"samples": [4, 1024]}})") ==
          "study.samples[1]: must be between 1 and 256 (got 1024)");
    CHECK(error_of(R"({"study": {"samples": [4, 16.5]}})") ==
          "study.samples[1]: must be an integer, got 16.5");
    CHECK(error_of(R"({"study": {"edges": 5000}})") ==
          "study.edges: must be between 1 and 1000 (got 5000)");
    CHECK(error_of(R"({"study": {"edges": 1000}})") ==
          "study.edges: times the sample counts' sum (341) must be at most 204800, so that a run "
          "stays short (got 1000 × 341 = 341000)");
    CHECK(error_of(R"({"study": {"edges": 600}})") == "(accepted)");
    CHECK(error_of(R"({"study": {"edges": 0}})") ==
          "study.edges: must be between 1 and 1000 (got 0)");
    CHECK(error_of(R"({"study": {"angles": "diagonal"}})") ==
          "study.angles: must be \"any\" or \"near-axis\", got a string (\"diagonal\")");
    CHECK(error_of(R"({"study": {"pixel": [0, 0]}})") ==
          "study.pixel: is not a known field (expected: patterns, samples, edges, angles, filter, "
          "seed)");
    // The C++ input is checked as strictly as the JSON.
    Supersampling::Input in = study_input({Pattern::Random}, false, 1, 1001, {4, 16});
    CHECK_THROWS_WITH(Supersampling::validate(in),
                      "study.edges: must be between 1 and 1000 (got 1001)");
}

TEST_CASE("supersampling: determinism, resumability and the picture", "[sampling][supersampling]") {
    const cg::Algorithm& a = cg::test::algorithm("supersampling");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    const cg::json poly = cg::parse_json(
        R"({"pattern": "poisson", "samples": 9, "filter": "gaussian", "pixel": [0, 0], "seed": 4,
            "scene": {"type": "polygon", "points": [[-0.5, 0.2], [0.8, -0.3], [1.4, 0.9], [0.3, 0.6]]}})");
    cg::test::check_replay(a, poly, 5);

    // The picture after the last step: the pixel, the edge's half-plane, 16 samples (green in,
    // red out) and the covered polygon.
    auto run = a.create(a.example());
    while (!run->done()) run->step(nullptr);
    cg::Scene scene;
    run->draw(scene);
    REQUIRE(scene.half_planes.size() == 1);
    int in = 0, out = 0;
    for (const auto& p : scene.points) {
        in += p.style.role == cg::Role::Kept;
        out += p.style.role == cg::Role::Discarded;
    }
    const auto r = a.result(*run);
    int inside = 0;
    for (const auto& s : r["samples"]) inside += s[2].get<double>() > 0;
    CHECK(in == inside);
    CHECK(in + out == 16);
    bool covered = false;
    for (const auto& p : scene.polygons)
        covered = covered || (p.style.role == cg::Role::Kept && p.filled);
    CHECK(covered);
    REQUIRE(scene.handles.size() == 1);
    CHECK(scene.handles[0].x_field == "/scene/point/0");
}

TEST_CASE("supersampling: a study replays, and its picture is the log-log plot",
          "[sampling][supersampling][convergence]") {
    const cg::Algorithm& a = cg::test::algorithm("supersampling");
    const cg::json small = cg::parse_json(
        R"({"study": {"patterns": ["regular", "jittered"], "samples": [1, 4, 16], "edges": 30,
            "angles": "near-axis", "filter": "tent", "seed": 4}})");
    cg::test::check_replay(a, small, cg::test::kEveryStep);

    const cg::json in = cg::parse_json(R"({"study": {"edges": 20}})");
    auto run = a.create(in);
    // The plot is a chart with logarithmic axes in its own units (N, RMS error), not drawn on the
    // world's grid.
    auto chart_of = [](const cg::Scene& sc) -> const cg::Panel& {
        CHECK_FALSE(sc.has_2d());
        REQUIRE(sc.panels.size() == 1);
        return sc.panels[0];
    };
    auto count = [](const cg::Panel& c, cg::Role role) {
        int n = 0;
        for (const auto& p : c.points) n += p.style.role == role;
        return n;
    };
    auto in_legend = [](const cg::Panel& c, const std::string& text) {
        for (const auto& l : c.legend)
            if (l.text == text) return true;
        return false;
    };
    {  // before any step: the axes and the guides, no data
        cg::Scene sc;
        run->draw(sc);
        const cg::Panel& c = chart_of(sc);
        CHECK(c.kind == cg::PanelKind::Chart);
        CHECK(c.x.log);
        CHECK(c.y.log);
        CHECK(c.x.label == "samples per pixel N");
        CHECK(c.points.empty());
        CHECK(in_legend(c, "slope −½"));
        CHECK(in_legend(c, "slope −¾"));
    }
    // The points appear as the steps reach them: regular (red) first, then random (magenta).
    for (int k = 1; k <= 7; ++k) {
        cg::StepInfo info;
        run->step(&info);
        CHECK(info.event == "point");
        cg::Scene sc;
        run->draw(sc);
        const cg::Panel& c = chart_of(sc);
        CHECK(count(c, cg::Role::Discarded) == std::min(k, 5));
        CHECK(count(c, cg::Role::Leaving) == std::max(0, k - 5));
    }
    while (!run->done()) run->step(nullptr);
    cg::Scene sc;
    run->draw(sc);
    const cg::Panel& c = chart_of(sc);
    CHECK(c.points.size() == 20);
    int lines = 0;
    for (const auto& p : c.polygons) lines += !p.closed && p.points.size() == 5;
    CHECK(lines == 4);
    for (const char* name : {"regular", "random", "jittered", "poisson"}) CHECK(in_legend(c, name));
    // Every point sits at (N, error) in the chart's own units, in order along N.
    const auto r = a.result(*run);
    REQUIRE(r["study"].size() == 20);
    CHECK(r["slopes"].size() == 4);
    for (std::size_t k = 0; k < 20; ++k) {
        CHECK(c.points[k].p.x == r["study"][k]["samples"].get<double>());
        CHECK(c.points[k].p.y == Approx(std::max(r["study"][k]["rms_error"].get<double>(), 1e-6)));
    }
}
