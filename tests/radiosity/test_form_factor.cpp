// Form factors: the exam cases by hand (unit squares facing at distance 1: 0.19982; at a right
// angle sharing an edge: 0.20004; coaxial discs; a point under a disc); every analytic formula
// against an independent brute-force double integral of the kernel in long double (the exam
// cases and random sizes); thousands of random configurations — rotated, translated, every
// analytic case — with the hemicube within its discretisation error and converging as its
// resolution and points grow, and Monte Carlo within 4 standard errors and converging like
// 1/sqrt(N); reciprocity; the closed unit cube's row sum; degenerate and bad input; replay on the
// example and presets; the exam; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "radiosity/form_factor.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::FormFactor;
using cg::Patch;
using glm::dvec3;
using Input = FormFactor::Input;
namespace ff = cg::ff;

namespace {

using LD = long double;
constexpr LD kPiL = 3.141592653589793238462643383279502884L;

// ---- the independent reference: the kernel integrated by the midpoint rule in long double ----

struct LPoint {
    LD x, y, z;
};
// n × n equal-area cells of a rectangle or a disc (the test's own parametrisation), each cell's
// centre; the cells' common area is A / n².
std::vector<LPoint> cells_of(const Patch& p, int n) {
    std::vector<LPoint> out;
    if (p.type == Patch::Type::Rectangle) {
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                const LD s = (a + 0.5L) / n, t = (b + 0.5L) / n;
                out.push_back({p.a.x + s * p.b.x + t * p.c.x, p.a.y + s * p.b.y + t * p.c.y,
                               p.a.z + s * p.b.z + t * p.c.z});
            }
    } else if (p.type == Patch::Type::Disc) {
        // Rings of equal area: ring k between radii R sqrt(k/n) and R sqrt((k+1)/n), n sectors.
        const dvec3 nn = glm::normalize(p.b);
        const dvec3 h = std::fabs(nn.x) < 0.5 ? dvec3(1, 0, 0) : dvec3(0, 0, 1);
        const dvec3 e1 = glm::normalize(glm::cross(h, nn)), e2 = glm::cross(nn, e1);
        for (int k = 0; k < n; ++k) {
            const LD r = p.radius * std::sqrt((k + 0.5L) / n);
            for (int q = 0; q < n; ++q) {
                const LD phi = 2 * kPiL * (q + 0.5L) / n;
                const LD c = std::cos(phi) * r, s = std::sin(phi) * r;
                out.push_back({p.a.x + c * e1.x + s * e2.x, p.a.y + c * e1.y + s * e2.y,
                               p.a.z + c * e1.z + s * e2.z});
            }
        }
    } else {
        out.push_back({p.a.x, p.a.y, p.a.z});
    }
    return out;
}

// F_ij = 1/A_i ∫∫ max(0, cos θ_i) max(0, cos θ_j) / (π r²) dA_j dA_i, by the midpoint rule.
LD brute(const Patch& from, const Patch& to, int n) {
    const dvec3 ni = cg::normal(from), nj = cg::normal(to);
    const auto pi = cells_of(from, n), pj = cells_of(to, n);
    const LD dAj = LD(cg::area(to)) / pj.size();
    LD sum = 0;
    for (const LPoint& x : pi)
        for (const LPoint& y : pj) {
            const LD dx = y.x - x.x, dy = y.y - x.y, dz = y.z - x.z;
            const LD r2 = dx * dx + dy * dy + dz * dz;
            const LD ci = (ni.x * dx + ni.y * dy + ni.z * dz);
            const LD cj = -(nj.x * dx + nj.y * dy + nj.z * dz);
            if (ci <= 0 || cj <= 0) continue;
            sum += ci * cj / (kPiL * r2 * r2) * dAj;
        }
    return sum / pi.size();
}

// ---- random configurations: a case with a formula, rotated and moved -------------------------

struct Frame {
    dvec3 o, x, y, z;
    dvec3 at(dvec3 p) const { return o + p.x * x + p.y * y + p.z * z; }
    dvec3 dir(dvec3 v) const { return v.x * x + v.y * y + v.z * z; }
};
Frame random_frame(cg::Rng& rng) {
    dvec3 a;
    do a = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    while (glm::length(a) < 0.2);
    dvec3 b;
    do b = glm::cross(a, dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    while (glm::length(b) < 0.2);
    const dvec3 x = glm::normalize(a), y = glm::normalize(b), z = glm::cross(x, y);
    return {{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)}, x, y, z};
}

struct Config {
    Patch from, to;
    ff::Case kase;
};
// kind 0 parallel rectangles, 1 perpendicular, 2 discs, 3 point to disc.
Config random_config(cg::Rng& rng, int kind) {
    const Frame f = random_frame(rng);
    const double a = rng.uniform(0.2, 3), b = rng.uniform(0.2, 3), c = rng.uniform(0.2, 3);
    switch (kind) {
        case 0:
            return {Patch::rectangle(f.at({0, 0, 0}), f.dir({a, 0, 0}), f.dir({0, b, 0})),
                    Patch::rectangle(f.at({0, 0, c}), f.dir({0, b, 0}), f.dir({a, 0, 0})),
                    ff::Case::ParallelRectangles};
        case 1:
            return {Patch::rectangle(f.at({0, 0, 0}), f.dir({a, 0, 0}), f.dir({0, b, 0})),
                    Patch::rectangle(f.at({0, 0, 0}), f.dir({0, 0, c}), f.dir({a, 0, 0})),
                    ff::Case::PerpendicularRectangles};
        case 2:
            return {Patch::disc(f.at({0, 0, 0}), f.dir({0, 0, 1}), a),
                    Patch::disc(f.at({0, 0, c}), f.dir({0, 0, -1}), b), ff::Case::CoaxialDiscs};
        default:
            return {Patch::point(f.at({0, 0, 0}), f.dir({0, 0, 1})),
                    Patch::disc(f.at({0, 0, c}), f.dir({0, 0, -1}), b), ff::Case::PointToDisc};
    }
}

Input make(Patch from, Patch to, int res = 8, int m = 3, long long rays = 1000) {
    Input in;
    in.from = from;
    in.to = to;
    in.resolution = res;
    in.samples = m;
    in.rays = rays;
    return in;
}

const Patch kBottom = Patch::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
const Patch kTop = Patch::rectangle({0, 0, 1}, {0, 1, 0}, {1, 0, 0});
const Patch kSide = Patch::rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0});  // y = 0, facing +y
const std::vector<Patch> kWalls = {Patch::rectangle({0, 0, 0}, {0, 1, 0}, {0, 0, 1}),
                                   Patch::rectangle({1, 0, 0}, {0, 0, 1}, {0, 1, 0}), kSide,
                                   Patch::rectangle({0, 1, 0}, {1, 0, 0}, {0, 0, 1})};

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("form-factor");
    if (!l) throw std::runtime_error("no lesson for form-factor");
    return *l;
}

}  // namespace

TEST_CASE("form-factor: the exam cases by hand", "[radiosity][form-factor]") {
    CHECK(ff::parallel_rectangles(1, 1, 1) == Approx(0.199825).margin(1e-6));
    CHECK(ff::perpendicular_rectangles(1, 1, 1) == Approx(0.200044).margin(1e-6));
    // Coaxial unit discs at distance 1: X = 3, F = (3 − √5) / 2.
    CHECK(ff::coaxial_discs(1, 1, 1) == Approx((3 - std::sqrt(5.0)) / 2).epsilon(1e-14));
    CHECK(ff::coaxial_discs(1, 2, 1) == Approx(0.763932).margin(1e-6));
    CHECK(ff::coaxial_discs(2, 1, 1) == Approx(0.190983).margin(1e-6));
    CHECK(ff::point_to_disc(1, 1) == 0.5);
    CHECK(ff::perpendicular_rectangles(1, 2, 1) == Approx(0.116426).margin(1e-6));
    // The unit cube: opposite face + 4 sides = 1.
    CHECK(ff::parallel_rectangles(1, 1, 1) + 4 * ff::perpendicular_rectangles(1, 1, 1) ==
          Approx(1).margin(1e-5));

    const auto r = FormFactor::compute(make(kBottom, kTop));
    CHECK(r.analytic_case == "parallel-rectangles");
    REQUIRE(r.analytic);
    CHECK(*r.analytic == Approx(0.199825).margin(1e-6));
    CHECK(r.area_from == 1);
    CHECK(r.area_to == 1);
    CHECK(r.monte_carlo_std_error == Approx(std::sqrt(r.monte_carlo * (1 - r.monte_carlo) / 1000)));
    CHECK(*r.error_monte_carlo <= 4 * r.monte_carlo_std_error);
    const auto p = FormFactor::compute(make(kBottom, kSide));
    CHECK(p.analytic_case == "perpendicular-rectangles");
    CHECK(*p.analytic == Approx(0.200044).margin(1e-6));
    const auto d = FormFactor::compute(
        make(Patch::point({0, 0, 0}, {0, 0, 1}), Patch::disc({0, 0, 1}, {0, 0, -1}, 1), 16, 1));
    CHECK(d.analytic_case == "point-to-disc");
    CHECK(*d.analytic == 0.5);
    CHECK(*d.error_hemicube < 0.02);
    CHECK_FALSE(d.reciprocity);
    // The single hemicube at the centre of the squares gives the point factor, about 0.2395.
    CHECK(FormFactor::compute(make(kBottom, kTop, 128, 1)).hemicube == Approx(0.2395).margin(1e-3));
    // The triangle over half the square: no formula; symmetry says half of 0.19982.
    const auto t = FormFactor::compute(
        make(kBottom, Patch::triangle({0, 0, 1}, {0, 1, 1}, {1, 0, 1}), 64, 8, 20000));
    CHECK(t.analytic_case == "none");
    CHECK_FALSE(t.analytic);
    // (Cells centred exactly on the diagonal's image count as covered: a bias of a few 1e-3.)
    CHECK(t.hemicube == Approx(0.199825 / 2).margin(5e-3));
    CHECK(std::fabs(t.monte_carlo - 0.199825 / 2) <= 4 * t.monte_carlo_std_error);
}

TEST_CASE("form-factor: the analytic formulas against a brute-force double integral",
          "[radiosity][form-factor]") {
    // The exam cases, finely.
    CHECK(double(brute(kBottom, kTop, 40)) ==
          Approx(ff::parallel_rectangles(1, 1, 1)).margin(2e-4));
    CHECK(double(brute(kBottom, kSide, 48)) ==
          Approx(ff::perpendicular_rectangles(1, 1, 1)).margin(3e-3));
    CHECK(double(brute(Patch::disc({0, 0, 0}, {0, 0, 1}, 1), Patch::disc({0, 0, 1}, {0, 0, -1}, 2),
                       40)) == Approx(ff::coaxial_discs(1, 2, 1)).margin(2e-3));
    CHECK(double(brute(Patch::point({0, 0, 0}, {0, 0, 1}), Patch::disc({0, 0, 2}, {0, 0, -1}, 1),
                       200)) == Approx(ff::point_to_disc(1, 2)).margin(1e-4));
    // Random sizes, rotated and moved: the formula the code detects against the integral.
    cg::Rng rng(7);
    int checked = 0;
    for (int k = 0; k < 48; ++k) {
        const int kind = k % 4;
        const Config c = random_config(rng, kind);
        const ff::Analytic an = ff::analytic(c.from, c.to);
        REQUIRE(an.kase == c.kase);
        // Coarser where the kernel is steep (close or small patches): the tolerance follows.
        const int n = kind == 3 ? 120 : 24;
        const LD b = brute(c.from, c.to, n);
        const LD b2 = brute(c.from, c.to, 2 * n);
        CAPTURE(kind, an.value, double(b), double(b2));
        // The midpoint rule's own error, estimated by halving the cells, bounds the comparison.
        const double tol = 3 * std::fabs(double(b2 - b)) + 2e-4;
        CHECK(std::fabs(an.value - double(b2)) <= tol);
        ++checked;
    }
    CHECK(checked == 48);
}

TEST_CASE("form-factor: thousands of random configurations, the hemicube and Monte Carlo",
          "[radiosity][form-factor]") {
    cg::Rng rng(2026);
    int n = 0, within = 0;
    double worst_sigmas = 0;
    for (int k = 0; k < 2000; ++k) {
        const int kind = k % 4;
        const Config c = random_config(rng, kind);
        const ff::Analytic an = ff::analytic(c.from, c.to);
        REQUIRE(an.kase == c.kase);
        CAPTURE(k, kind, an.value);
        // Monte Carlo: within 4 standard errors of the truth.
        const long long rays = 2000;
        const double mc = ff::monte_carlo(c.from, c.to, rays, std::uint64_t(k) + 1);
        const double sigma = std::sqrt(an.value * (1 - an.value) / rays);
        worst_sigmas = std::max(worst_sigmas, std::fabs(mc - an.value) / sigma);
        CHECK(std::fabs(mc - an.value) <= 4 * sigma + 1e-12);
        within += std::fabs(mc - an.value) <= sigma;
        // The hemicube (8 × 8 points, resolution 32): within its discretisation error.
        if (k % 16 < 4) {  // 500 of them, every kind
            const double h = ff::hemicube(c.from, c.to, 32, kind == 3 ? 1 : 8);
            CHECK(std::fabs(h - an.value) <= 0.03);
        }
        ++n;
    }
    CHECK(n == 2000);
    // About 68% of the estimates within one standard error (a normal distribution).
    CHECK(within > 0.6 * n);
    CHECK(within < 0.76 * n);
    CHECK(worst_sigmas > 2.5);  // the spread is real, not a degenerate estimator
}

TEST_CASE(
    "form-factor: the hemicube converges as its cells and points grow, Monte Carlo like "
    "1/sqrt(N)",
    "[radiosity][form-factor]") {
    cg::Rng rng(99);
    std::vector<Config> cs;
    for (int k = 0; k < 120; ++k) cs.push_back(random_config(rng, k % 3));
    auto mean_error = [&](int res, int m) {
        double e = 0;
        for (const auto& c : cs)
            e += std::fabs(ff::hemicube(c.from, c.to, res, m) - ff::analytic(c.from, c.to).value);
        return e / cs.size();
    };
    const double e1 = mean_error(8, 2), e2 = mean_error(16, 4), e3 = mean_error(64, 8);
    CAPTURE(e1, e2, e3);
    CHECK(e2 < e1);
    CHECK(e3 < e2);
    CHECK(e3 < 0.01);
    // The single hemicube at the centre does not converge to F_ij: its limit is F_dA→j.
    const double single = mean_error(64, 1);
    CHECK(single > 2 * e3);
    // Monte Carlo: 16 times the rays, a quarter of the RMS error.
    auto rms = [&](long long rays) {
        double s = 0;
        int k = 0;
        for (const auto& c : cs) {
            const double d = ff::monte_carlo(c.from, c.to, rays, std::uint64_t(++k)) -
                             ff::analytic(c.from, c.to).value;
            s += d * d;
        }
        return std::sqrt(s / cs.size());
    };
    const double r1 = rms(500), r2 = rms(8000);
    CAPTURE(r1, r2);
    CHECK(r1 / r2 > 2.8);
    CHECK(r1 / r2 < 5.7);
}

TEST_CASE("form-factor: reciprocity, and the closed unit cube's row sum",
          "[radiosity][form-factor]") {
    cg::Rng rng(5);
    for (int k = 0; k < 300; ++k) {
        const Config c = random_config(rng, k % 3);
        const ff::Analytic an = ff::analytic(c.from, c.to);
        const double ai = cg::area(c.from), aj = cg::area(c.to);
        CAPTURE(k);
        // The formula both ways: A_i F_ij = A_j F_ji.
        CHECK(ai * an.value == Approx(aj * an.reverse).epsilon(1e-9));
        const ff::Analytic back = ff::analytic(c.to, c.from);
        CHECK(back.value == Approx(an.reverse).epsilon(1e-12));
    }
    // Different areas: a small disc under a big one.
    Input in = make(Patch::disc({0, 0, 0}, {0, 0, 1}, 1), Patch::disc({0, 0, 1}, {0, 0, -1}, 2), 16,
                    4, 20000);
    const auto r = FormFactor::compute(in);
    REQUIRE(r.reciprocity);
    CHECK(r.reciprocity->f_ji_expected == Approx(0.763932 / 4).margin(1e-6));
    CHECK(*r.reciprocity->f_ji_analytic == Approx(0.190983).margin(1e-6));
    CHECK(std::fabs(r.reciprocity->f_ji_monte_carlo - 0.190983) <=
          4 * ff::std_error(0.190983, 20000));
    CHECK(r.reciprocity->f_ji_hemicube == Approx(0.190983).margin(0.01));
    // The cube: bottom → top, and the four walls.
    Input cube = make(kBottom, kTop, 32, 6, 20000);
    cube.enclosure = kWalls;
    const auto rc = FormFactor::compute(cube);
    REQUIRE(rc.row_sum);
    REQUIRE(rc.row_sum->analytic);
    CHECK(*rc.row_sum->analytic == Approx(1).margin(1e-5));
    CHECK(rc.row_sum->monte_carlo == 1);  // every ray lands somewhere in a closed box
    CHECK(rc.row_sum->hemicube == Approx(1).margin(2e-3));  // the ΔF of all cells sum to ≈ 1
    CHECK(rc.row_sum->hemicube_terms.size() == 5);
    for (std::size_t k = 1; k < 5; ++k)
        CHECK(rc.row_sum->monte_carlo_terms[k] ==
              Approx(0.200044).margin(4 * ff::std_error(0.2, 20000)));
    // With one wall missing, the row sum falls short by about that wall's factor.
    cube.enclosure.pop_back();
    const auto open = FormFactor::compute(cube);
    CHECK_FALSE(open.row_sum->analytic == std::nullopt);
    CHECK(open.row_sum->monte_carlo == Approx(0.8).margin(0.02));
}

TEST_CASE("form-factor: the hemicube cells' delta form factors", "[radiosity][form-factor]") {
    // All cells of a hemicube sum to 1 minus a discretisation error that shrinks with R.
    double prev = 1;
    for (int res : {4, 8, 32, 128}) {
        double sum = 0;
        for (int f = 0; f < ff::kFaces; ++f)
            for (int k = 0; k < ff::face_cells(res, f); ++k) {
                double x, y, z, dF;
                ff::cell(res, f, k, x, y, z, dF);
                const double r2 = x * x + y * y + z * z;
                // ΔF = cos θ_i cos θ_cell / (π r²) ΔA, directly.
                const double cos_i = z / std::sqrt(r2);
                const double cos_p =
                    (f == 0 ? z : (f <= 2 ? std::fabs(x) : std::fabs(y))) / std::sqrt(r2);
                CHECK(dF ==
                      Approx(cos_i * cos_p / (M_PI * r2) * (4.0 / (res * res))).epsilon(1e-12));
                sum += dF;
            }
        CHECK(std::fabs(sum - 1) < prev);
        prev = std::fabs(sum - 1);
    }
    CHECK(prev < 1e-4);
}

TEST_CASE("form-factor: degenerate configurations give 0, bad input names the field",
          "[radiosity][form-factor]") {
    // Coplanar, side by side: nothing leaves i toward j.
    const auto cop =
        FormFactor::compute(make(kBottom, Patch::rectangle({2, 0, 0}, {1, 0, 0}, {0, 1, 0})));
    CHECK(cop.hemicube == 0);
    CHECK(cop.monte_carlo == 0);
    CHECK(cop.analytic_case == "none");
    // j behind i, and j facing away (its back to i).
    CHECK(FormFactor::compute(make(kBottom, Patch::rectangle({0, 0, -2}, {1, 0, 0}, {0, 1, 0})))
              .monte_carlo == 0);
    const auto away =
        FormFactor::compute(make(kBottom, Patch::rectangle({0, 0, 1}, {1, 0, 0}, {0, 1, 0})));
    CHECK(away.monte_carlo == 0);
    CHECK(away.hemicube == 0);
    CHECK(away.analytic_case == "none");

    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(
        FormFactor::start(make(Patch::rectangle({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), kTop)),
        Catch::StartsWith("from: the rectangle has zero area"));
    CHECK_THROWS_WITH(FormFactor::start(make(kBottom, Patch::disc({0, 0, 1}, {0, 0, -1}, 0))),
                      Catch::StartsWith("to.radius: must be positive"));
    CHECK_THROWS_WITH(
        FormFactor::start(make(kBottom, Patch::triangle({0, 0, 1}, {1, 1, 1}, {2, 2, 1}))),
        Catch::StartsWith("to: the triangle has zero area"));
    CHECK_THROWS_WITH(
        FormFactor::start(make(Patch::rectangle({nan, 0, 0}, {1, 0, 0}, {0, 1, 0}), kTop)),
        "from.corner[0]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(
        FormFactor::start(make(kBottom, Patch::rectangle({0, 0, 1}, {0, inf, 0}, {1, 0, 0}))),
        Catch::StartsWith("to.edge_u[1]: must be a finite number"));
    CHECK_THROWS_WITH(
        FormFactor::start(make(kBottom, Patch::rectangle({0, 0, 1}, {0, 1, 0}, {1, 1, 0}))),
        Catch::StartsWith("to.edge_v: must be perpendicular to edge_u"));
    CHECK_THROWS_WITH(FormFactor::start(make(kBottom, Patch::point({0, 0, 1}, {0, 0, -1}))),
                      Catch::StartsWith("to: a point (a differential area dA) can only be"));
    CHECK_THROWS_WITH(FormFactor::start(make(kBottom, kTop, 7)),
                      Catch::StartsWith("hemicube.resolution: must be an even number"));
    CHECK_THROWS_WITH(FormFactor::start(make(kBottom, kTop, 8, 0)),
                      Catch::StartsWith("hemicube.samples: must be from 1 to 8"));
    CHECK_THROWS_WITH(FormFactor::start(make(kBottom, kTop, 8, 3, 0)),
                      Catch::StartsWith("monte_carlo.rays: must be from 1"));
    CHECK_THROWS_WITH(
        FormFactor::start(make(kBottom, Patch::rectangle({0, 0, 1e200}, {0, 1, 0}, {1, 0, 0}))),
        Catch::StartsWith("to.corner[2]: is too large"));
    Input bad = make(kBottom, kTop);
    bad.enclosure = {Patch::disc({0, 0, 0}, {0, 0, 0}, 1)};
    CHECK_THROWS_WITH(FormFactor::start(bad),
                      Catch::StartsWith("enclosure[0].normal: must not be the zero vector"));
    // Through the JSON layer.
    CHECK_THAT(
        cg::test::error_of("form-factor", R"({"from": {"type": "square"}, "to": {}})"),
        Catch::StartsWith("from.type: must be \"rectangle\", \"disc\", \"triangle\" or \"point\""));
    CHECK_THAT(cg::test::error_of("form-factor",
                                  R"({"from": {"type": "triangle", "points": [[0,0,0],[1,0,0]]},
                                      "to": {"type": "disc", "center": [0,0,1], "normal": [0,0,-1], "radius": 1}})"),
               Catch::StartsWith("from.points: a triangle has 3 points (got 2)"));
}

TEST_CASE("form-factor: replay on the example and the presets, run-to-end is compute",
          "[radiosity][form-factor]") {
    const cg::Algorithm& a = cg::test::algorithm("form-factor");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    std::set<std::string> seen;
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, 7);
        const Input in = cg::test::input_of<FormFactor>("form-factor", p.input);
        const auto t = cg::test::run_traced<FormFactor>(in);
        CHECK(t.result == FormFactor::compute(in));
        CHECK(cg::run_to_end<FormFactor>(FormFactor::start(in)) == t.result);
        for (const auto& e : cg::test::events(t)) seen.insert(e);
    }
    for (const auto& e : FormFactor::spec().events) {
        CAPTURE(e.id);
        CHECK(seen.count(e.id));
    }
    const cg::json r = cg::test::result_of("form-factor", a.example());
    CHECK(r["analytic"].get<double>() == Approx(0.199825).margin(1e-6));
    CHECK(r["analytic_case"] == "parallel-rectangles");
    CHECK(r["reciprocity"]["F_ji_expected"].get<double>() == Approx(0.199825).margin(1e-6));
    CHECK(r["row_sum"].is_null());
    // Fewer rays than batches: the empty batches are no steps.
    const auto few = cg::test::run_traced<FormFactor>(make(kBottom, kTop, 8, 1, 3));
    int batches = 0;
    for (const auto& e : cg::test::events(few)) batches += e == "mc-batch";
    CHECK(batches == 3);
    CHECK(few.result == FormFactor::compute(make(kBottom, kTop, 8, 1, 3)));
}

TEST_CASE("form-factor: exam problems ask for F_ji by reciprocity", "[radiosity][form-factor]") {
    const cg::Algorithm& a = cg::test::algorithm("form-factor");
    std::set<std::string> cases;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = cg::test::input_of<FormFactor>("form-factor", p.input);
        const ff::Analytic an = ff::analytic(in.from, in.to);
        REQUIRE(an.kase != ff::Case::None);
        cases.insert(ff::case_name(an.kase));
        const double expected = double(cg::area(in.from)) / cg::area(in.to) * an.value;
        CHECK(p.expected["reciprocity/F_ji_expected"].get<double>() ==
              Approx(expected).epsilon(1e-12));
        CHECK(p.expected["reciprocity/F_ji_expected"].get<double>() ==
              Approx(an.reverse).epsilon(1e-9));
    }
    CHECK(cases.size() == 3);
}

TEST_CASE("form-factor: the picture — patches, normals, hemicube cells, rays",
          "[radiosity][form-factor]") {
    auto s = FormFactor::start(make(kBottom, kTop, 8, 3, 600));  // batches of 60 rays
    cg::Scene pic;
    FormFactor::draw(s, pic);
    CHECK(pic.has_3d());
    FormFactor::step(s, nullptr);  // setup
    FormFactor::step(s, nullptr);  // analytic
    FormFactor::step(s, nullptr);  // the top face
    cg::Scene top;
    FormFactor::draw(s, top);
    int cells = 0;
    for (const auto& f : top.faces3) cells += f.style.role == cg::Role::Active;
    CHECK(cells == s.face_covered);
    CHECK(cells > 0);
    while (s.phase != FormFactor::Phase::MonteCarlo) FormFactor::step(s, nullptr);
    FormFactor::step(s, nullptr);  // the first batch
    cg::Scene rays;
    FormFactor::draw(s, rays);
    int hit = 0, miss = 0;
    for (const auto& g : rays.segments3) {
        hit += g.style.role == cg::Role::Kept && !g.arrow;
        miss += g.style.role == cg::Role::Discarded;
    }
    CHECK(hit == s.batch_hits);  // the batch's 60 rays, all drawn
    CHECK(hit + miss == 60);
}
