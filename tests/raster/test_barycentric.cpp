// Barycentric coordinates: hand-worked cases (2D both orientations, edge, vertex, outside; 3D in
// and off the plane); 10,000 random cases against an independent solve of the linear system in
// long double (2D: Cramer's rule on the 2×2 system [A − C, B − C] (α, β) = P − C; 3D: Gaussian
// elimination on [A − C, B − C, n] (α, β, t) = P − C) with P rebuilt from the weights to 1e-12;
// the exact inside / on-edge test against 128-bit integer edge functions, with points exactly
// on edges and one ulp off them; errors naming the field; determinism on the example and the
// lesson's presets; exam problems; the picture.
//
// Sections: [helpers] [hand cases] [random] [exact edges] [3D tolerance] [errors]
//           [determinism] [exam] [picture]
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>

#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "io/registry.hpp"
#include "raster/barycentric.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Barycentric;
using glm::dvec3;
using ld = long double;

namespace {

// ---- [helpers] ------------------------------------------------------------------------------

using Traced = cg::test::Traced<Barycentric>;

Barycentric::Input in2(std::array<glm::dvec2, 3> t, std::vector<glm::dvec2> points) {
    Barycentric::Input in;
    in.dim = 2;
    for (int i = 0; i < 3; ++i) in.triangle[i] = {t[i], 0};
    for (auto p : points) in.points.push_back({p, 0});
    return in;
}

Barycentric::Input in3(std::array<dvec3, 3> t, std::vector<dvec3> points) {
    Barycentric::Input in;
    in.dim = 3;
    in.triangle = t;
    in.points = std::move(points);
    return in;
}

double max_abs(const dvec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// The reference: the weights from a direct solve of the linear system, in long double.
struct Solve {
    ld w[3];
    ld distance = 0;  // 3D: t |n|
};

Solve solve2(const Barycentric::Input& in, const dvec3& p) {
    const auto& v = in.triangle;
    // [ax − cx, bx − cx; ay − cy, by − cy] (α, β) = (px − cx, py − cy), by Cramer's rule.
    const ld a = ld(v[0].x) - v[2].x, b = ld(v[1].x) - v[2].x;
    const ld c = ld(v[0].y) - v[2].y, d = ld(v[1].y) - v[2].y;
    const ld e = ld(p.x) - v[2].x, f = ld(p.y) - v[2].y;
    const ld det = a * d - b * c;
    Solve s;
    s.w[0] = (e * d - b * f) / det;
    s.w[1] = (a * f - e * c) / det;
    s.w[2] = 1 - s.w[0] - s.w[1];
    return s;
}

Solve solve3(const Barycentric::Input& in, const dvec3& p) {
    const auto& v = in.triangle;
    ld n[3], ac[3], bc[3], rhs[3];
    for (int i = 0; i < 3; ++i) ac[i] = ld(v[0][i]) - v[2][i], bc[i] = ld(v[1][i]) - v[2][i];
    const ld ab[3] = {ld(v[1][0]) - v[0][0], ld(v[1][1]) - v[0][1], ld(v[1][2]) - v[0][2]};
    const ld acA[3] = {ld(v[2][0]) - v[0][0], ld(v[2][1]) - v[0][1], ld(v[2][2]) - v[0][2]};
    n[0] = ab[1] * acA[2] - ab[2] * acA[1];
    n[1] = ab[2] * acA[0] - ab[0] * acA[2];
    n[2] = ab[0] * acA[1] - ab[1] * acA[0];
    const ld len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; ++i) n[i] /= len, rhs[i] = ld(p[i]) - v[2][i];
    // Rows i: ac[i] α + bc[i] β + n[i] t = rhs[i]; Gaussian elimination with partial pivoting.
    ld m[3][4];
    for (int i = 0; i < 3; ++i) m[i][0] = ac[i], m[i][1] = bc[i], m[i][2] = n[i], m[i][3] = rhs[i];
    for (int col = 0; col < 3; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 3; ++r)
            if (std::fabs(m[r][col]) > std::fabs(m[pivot][col])) pivot = r;
        for (int c = 0; c < 4; ++c) std::swap(m[col][c], m[pivot][c]);
        for (int r = col + 1; r < 3; ++r) {
            const ld f = m[r][col] / m[col][col];
            for (int c = col; c < 4; ++c) m[r][c] -= f * m[col][c];
        }
    }
    ld x[3];
    for (int r = 2; r >= 0; --r) {
        ld sum = m[r][3];
        for (int c = r + 1; c < 3; ++c) sum -= m[r][c] * x[c];
        x[r] = sum / m[r][r];
    }
    Solve s;
    s.w[0] = x[0];
    s.w[1] = x[1];
    s.w[2] = 1 - x[0] - x[1];
    s.distance = x[2];
    return s;
}

// Exact edge functions on integer coordinates (inputs built on a grid of integers).
__extension__ typedef __int128 i128;
int exact_sign(const dvec3& a, const dvec3& b, const dvec3& p) {
    const auto i = [](double x) { return static_cast<long long>(x); };
    const i128 v =
        i128(i(b.x) - i(a.x)) * (i(p.y) - i(a.y)) - i128(i(b.y) - i(a.y)) * (i(p.x) - i(a.x));
    return (v > 0) - (v < 0);
}

}  // namespace

// ---- [hand cases] ---------------------------------------------------------------------------

TEST_CASE("barycentric: exam cases worked by hand", "[raster][barycentric]") {
    SECTION("A = (0, 0), B = (4, 0), C = (1, 3): inside, on BC, beyond BC") {
        const Traced t = cg::test::run_traced<Barycentric>(
            in2({{{0, 0}, {4, 0}, {1, 3}}}, {{1, 1}, {2.5, 1.5}, {4, 2}}));
        CHECK(cg::test::events(t) == std::vector<std::string>{"area", "areas", "ratios", "inside",
                                                              "areas", "ratios", "on-edge", "areas",
                                                              "ratios", "outside"});
        CHECK(t.result.area == 6);  // ½ ((4)(3) − (0)(1))
        const auto& r = t.result.results;
        REQUIRE(r.size() == 3);
        // P0 = (1, 1): A_a = area(P, B, C) = ½ ((−3)(1) − (3)(−3)) = 3, A_b = 1, A_c = 2.
        CHECK(r[0].areas == dvec3(3, 1, 2));
        CHECK(r[0].weights == dvec3(0.5, 1.0 / 6, 1.0 / 3));
        CHECK((r[0].inside && !r[0].on_edge));
        // P1 = (2.5, 1.5) on BC: α = 0 exactly, β = γ = ½.
        CHECK(r[1].weights == dvec3(0, 0.5, 0.5));
        CHECK((r[1].inside && r[1].on_edge));
        // P2 = (4, 2): A_a = ½ ((−3)(2) − (3)(0)) = −3, so α = −½: beyond BC.
        CHECK(r[2].areas == dvec3(-3, 5, 4));
        CHECK(r[2].weights.x == -0.5);
        CHECK(r[2].weights.y == Approx(5.0 / 6).epsilon(1e-15));
        CHECK(r[2].weights.z == Approx(2.0 / 3).epsilon(1e-15));
        CHECK((!r[2].inside && !r[2].on_edge));
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("area = ½ (B − A) × (C − A) = ½ ((4)(3) − (0)(1)) = 6 > 0: "
                                   "A, B, C turn counter-clockwise"));
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("A_a = area(P, B, C) = 3, A_b = area(A, P, C) = 1, A_c = "
                                   "area(A, B, P) = 2 (sum 6"));
        CHECK_THAT(t.steps[2].narration,
                   Catch::Contains("α = A_a / area = 3 / 6 = 0.5, β = A_b / area = 1 / 6 = "
                                   "0.166667, γ = A_c / area = 2 / 6 = 0.333333"));
        CHECK_THAT(t.steps[2].narration, Catch::Contains("αA + βB + γC = (1, 1) = P"));
        CHECK_THAT(t.steps[6].narration, Catch::Contains("α = 0 and the others ≥ 0: P1 lies on "
                                                         "the edge BC"));
        CHECK_THAT(t.steps[7].narration, Catch::Contains("P is beyond the edge BC"));
        CHECK_THAT(t.steps[9].narration,
                   Catch::Contains("α < 0 (on the far side of BC from A): P2 is outside"));
        CHECK(t.steps[3].line == 6);
    }
    SECTION("clockwise: the signed areas change sign together, the weights do not") {
        // B and C swapped: the weights of P swap with them.
        const auto r = Barycentric::compute(in2({{{0, 0}, {1, 3}, {4, 0}}}, {{1, 1}}));
        CHECK(r.area == -6);
        CHECK(r.results[0].areas == dvec3(-3, -2, -1));
        CHECK(r.results[0].weights == dvec3(0.5, 1.0 / 3, 1.0 / 6));
        CHECK(r.results[0].inside);
        const Traced t =
            cg::test::run_traced<Barycentric>(in2({{{0, 0}, {1, 3}, {4, 0}}}, {{1, 1}}));
        CHECK_THAT(t.steps[0].narration, Catch::Contains("= −6 < 0: A, B, C turn clockwise"));
    }
    SECTION("a vertex: weights (0, 1, 0), on two edges") {
        const Traced t =
            cg::test::run_traced<Barycentric>(in2({{{0, 0}, {4, 0}, {1, 3}}}, {{4, 0}}));
        CHECK(t.result.results[0].weights == dvec3(0, 1, 0));
        CHECK(t.result.results[0].on_edge);
        CHECK_THAT(t.steps.back().narration, Catch::Contains("P0 is the vertex B, on two edges"));
    }
    SECTION("on the line through B and C but beyond B: not on the edge") {
        const auto r = Barycentric::compute(in2({{{0, 0}, {4, 0}, {1, 3}}}, {{6, -2}}));
        const dvec3 w = r.results[0].weights;  // A_a = ½ ((−3)(−2) − (3)(2)) = 0
        CHECK(w.x == 0);
        CHECK(w.y == Approx(10.0 / 6).epsilon(1e-15));
        CHECK(w.z == Approx(-2.0 / 3).epsilon(1e-15));
        CHECK_FALSE(r.results[0].inside);
        CHECK_FALSE(r.results[0].on_edge);  // on the line of BC but not on the edge
    }
    SECTION("3D: the plane z = 1, a point 2 above it") {
        const Traced t = cg::test::run_traced<Barycentric>(
            in3({{{0, 0, 1}, {4, 0, 1}, {0, 4, 1}}}, {{1, 1, 3}, {2, 2, 1}}));
        CHECK(cg::test::events(t) == std::vector<std::string>{"area", "project", "areas", "ratios",
                                                              "inside", "project", "areas",
                                                              "ratios", "on-edge"});
        CHECK(t.result.area == 8);
        CHECK(t.result.normal == dvec3(0, 0, 16));
        const auto& r = t.result.results;
        CHECK(r[0].distance == 2);
        CHECK(r[0].projected == dvec3(1, 1, 1));
        CHECK(r[0].weights == dvec3(0.5, 0.25, 0.25));
        CHECK((r[0].inside && !r[0].on_edge));
        CHECK(r[1].distance == 0);
        CHECK(r[1].weights == dvec3(0, 0.5, 0.5));
        CHECK(r[1].on_edge);
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("d = (P − A) · N = 2, so it is 2 off the plane (on the side n "
                                   "points to). Its projection P′ = P − d N = (1, 1, 1)"));
        CHECK_THAT(t.steps[5].narration, Catch::Contains("it lies in the triangle's plane"));
    }
    SECTION("3D: a tilted triangle, n = (6, 3, 2), |n| = 7") {
        const auto r = Barycentric::compute(in3({{{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}}, {{1, 1, 1}}));
        CHECK(r.normal == dvec3(6, 3, 2));
        CHECK(r.area == 3.5);
        // d = (P − A) · n̂ = (0, 1, 1) · (6, 3, 2) / 7 = 5/7.
        CHECK(r.results[0].distance == Approx(5.0 / 7).epsilon(1e-15));
        const dvec3 pp = r.results[0].projected;
        CHECK(glm::length(pp - (dvec3(1, 1, 1) - 5.0 / 49 * dvec3(6, 3, 2))) < 1e-15);
        const dvec3 w = r.results[0].weights;
        CHECK(glm::length(w.x * dvec3(1, 0, 0) + w.y * dvec3(0, 2, 0) + w.z * dvec3(0, 0, 3) - pp) <
              1e-15);
    }
}

// ---- [random] -------------------------------------------------------------------------------

TEST_CASE("barycentric: 10,000 random cases agree with a long-double solve of the system",
          "[raster][barycentric]") {
    int inside = 0, outside = 0, edges = 0, three_d = 0;
    double worst_rebuild = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        cg::Rng rng(trial);
        CAPTURE(trial);
        const bool is3 = trial % 2 == 1;
        // Scales from 1e-50 to 1e50, and now and then a thin (but valid) triangle.
        const double scale = std::pow(10.0, double(rng.integer(-50, 50)) * (trial % 7 == 0));
        Barycentric::Input in;
        in.dim = is3 ? 3 : 2;
        auto coord = [&] { return scale * rng.uniform(-10, 10); };
        for (auto& v : in.triangle) v = {coord(), coord(), is3 ? coord() : 0};
        if (trial % 11 == 3) {  // thin: C near the line AB (height ~1e-4 of the edge)
            in.triangle[2] = in.triangle[0] + 0.7 * (in.triangle[1] - in.triangle[0]) +
                             1e-4 * dvec3(in.triangle[1].y - in.triangle[0].y,
                                          in.triangle[0].x - in.triangle[1].x, 0);
        }
        const int n = static_cast<int>(rng.integer(1, 4));
        for (int k = 0; k < n; ++k) {
            dvec3 p{coord() * 1.5, coord() * 1.5, is3 ? coord() : 0};
            switch (rng.integer(0, 5)) {
                case 0:  // a vertex
                    p = in.triangle[rng.integer(0, 2)];
                    break;
                case 1:  // an affine combination with weights in eighths (sometimes outside)
                {
                    const double a = rng.integer(-4, 12) / 8.0, b = rng.integer(-4, 12) / 8.0;
                    p = a * in.triangle[0] + b * in.triangle[1] + (1 - a - b) * in.triangle[2];
                    if (is3 && rng.chance(0.5)) p += coord() * dvec3(0.1, -0.2, 0.3);
                    break;
                }
                case 2:  // far away
                    p *= 1e3;
                    break;
                default:
                    break;
            }
            in.points.push_back(p);
        }
        try {
            Barycentric::validate(in);
        } catch (const cg::InputError& e) {
            FAIL("refused: " << e.what());
        }
        const auto r = cg::run_to_end<Barycentric>(Barycentric::start(in));
        REQUIRE(Barycentric::compute(in) == r);
        REQUIRE(r.results.size() == in.points.size());
        three_d += is3;

        double size = 0;  // the triangle's size, for relative tolerances
        for (const auto& v : in.triangle) size = std::max(size, max_abs(v));
        // The weights' condition: how thin the triangle is (longest edge² / 2|area|).
        double longest = 0;
        for (int i = 0; i < 3; ++i)
            longest = std::max(longest, glm::length(in.triangle[(i + 1) % 3] - in.triangle[i]));
        const double cond = longest * longest / (2 * std::fabs(r.area));
        for (std::size_t k = 0; k < in.points.size(); ++k) {
            CAPTURE(k);
            const auto& pr = r.results[k];
            const dvec3 w = pr.weights;
            const double wmax = std::max(1.0, max_abs(w));
            // α + β + γ = 1 and P (or P′) rebuilt from the weights.
            REQUIRE(std::fabs(w.x + w.y + w.z - 1) <= 1e-12 * wmax * cond);
            const dvec3 back = w.x * in.triangle[0] + w.y * in.triangle[1] + w.z * in.triangle[2];
            const dvec3 target = is3 ? pr.projected : in.points[k];
            const double scale_k = std::max(size, max_abs(in.points[k]));
            const double err = max_abs(back - target) / scale_k;
            worst_rebuild = std::max(worst_rebuild, cond < 100 ? err : 0);
            REQUIRE(err <= 1e-12 * (cond < 100 ? 1 : cond));
            // The independent solve.
            const Solve ref = is3 ? solve3(in, in.points[k]) : solve2(in, in.points[k]);
            for (int i = 0; i < 3; ++i) {
                CAPTURE(i, w[i], double(ref.w[i]));
                REQUIRE(std::fabs(w[i] - ref.w[i]) <= 1e-12L * wmax * cond);
            }
            if (is3) {
                REQUIRE(std::fabs(pr.distance - ref.distance) <= 1e-12L * scale_k * cond);
                // P′ lies in the plane: A + (P′ − A) has no component along the normal.
                REQUIRE(std::fabs(glm::dot(pr.projected - in.triangle[0], r.normal) /
                                  glm::length(r.normal)) <= 1e-12 * scale_k);
            }
            // Classification agrees with the reference's signs where they are clear.
            const ld margin = 1e-9L;
            const bool clear = std::fabs(ref.w[0]) > margin && std::fabs(ref.w[1]) > margin &&
                               std::fabs(ref.w[2]) > margin;
            if (clear) {
                const bool ref_inside = ref.w[0] > 0 && ref.w[1] > 0 && ref.w[2] > 0;
                REQUIRE(pr.inside == ref_inside);
                REQUIRE_FALSE(pr.on_edge);
            }
            inside += pr.inside && !pr.on_edge;
            outside += !pr.inside;
            edges += pr.on_edge;
        }
    }
    CHECK(three_d == 5000);
    CHECK(inside > 800);
    CHECK(outside > 5000);
    CHECK(edges > 2000);  // every vertex, and combinations with a weight 0
    INFO("worst rebuild " << std::scientific << worst_rebuild);
    CHECK(worst_rebuild <= 1e-13);  // 1.7e-14 seen
}

// ---- [exact edges] --------------------------------------------------------------------------

TEST_CASE("barycentric: 2D inside and on_edge are exact, against 128-bit edge functions",
          "[raster][barycentric]") {
    int on = 0, off_in = 0, off_out = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        CAPTURE(trial);
        Barycentric::Input in;
        in.dim = 2;
        // Big integer coordinates: points on the edges with a weight that is no simple fraction.
        const long long big = trial % 2 ? 1'000'000'000'000LL : 1000;
        do {
            for (auto& v : in.triangle)
                v = {double(rng.integer(-big, big)), double(rng.integer(-big, big)), 0};
        } while (exact_sign(in.triangle[0], in.triangle[1], in.triangle[2]) == 0);
        for (int k = 0; k < 6; ++k) {
            // On the edge i → i+1 at an integer point: step along the edge by its direction
            // divided by the gcd, so the point is exactly on it.
            const int i = static_cast<int>(rng.integer(0, 2));
            const dvec3 a = in.triangle[i], b = in.triangle[(i + 1) % 3];
            long long dx = static_cast<long long>(b.x - a.x),
                      dy = static_cast<long long>(b.y - a.y);
            const long long g = std::gcd(std::llabs(dx), std::llabs(dy));
            dx /= g, dy /= g;
            const long long steps = rng.integer(0, g);
            dvec3 p = a + double(steps) * dvec3(dx, dy, 0);
            if (k % 3 == 1) p.x += 1;  // one unit off the edge (an ulp for the big triangles)
            if (k % 3 == 2) p.y -= 1;
            in.points.push_back(p);
        }
        try {
            Barycentric::validate(in);
        } catch (const cg::InputError&) {
            continue;  // too thin for the sandbox: not this test's business
        }
        const auto r = Barycentric::compute(in);
        const int orient = exact_sign(in.triangle[0], in.triangle[1], in.triangle[2]);
        for (std::size_t k = 0; k < in.points.size(); ++k) {
            CAPTURE(k);
            const dvec3 p = in.points[k];
            const int s[3] = {orient * exact_sign(in.triangle[1], in.triangle[2], p),
                              orient * exact_sign(in.triangle[2], in.triangle[0], p),
                              orient * exact_sign(in.triangle[0], in.triangle[1], p)};
            const bool ref_inside = s[0] >= 0 && s[1] >= 0 && s[2] >= 0;
            const bool ref_edge = ref_inside && (s[0] == 0 || s[1] == 0 || s[2] == 0);
            REQUIRE(r.results[k].inside == ref_inside);
            REQUIRE(r.results[k].on_edge == ref_edge);
            for (int i = 0; i < 3; ++i) {  // every weight's sign is the exact one (0 exactly)
                const double w = r.results[k].weights[i];
                REQUIRE((w > 0) - (w < 0) == s[i]);
            }
            on += ref_edge;
            off_in += ref_inside && !ref_edge;
            off_out += !ref_inside;
        }
    }
    CHECK(on > 8000);
    CHECK(off_in > 2000);
    CHECK(off_out > 2000);
}

TEST_CASE("barycentric: 2D signs stay exact where double arithmetic gets them wrong",
          "[raster][barycentric]") {
    // Kettner et al.'s classroom example: points a few ulps around (0.5, 0.5), near the line
    // y = x, which carries the edge AB from A = (24, 24) to B = (−12, −12); C = (−12, 24) lies
    // above it. (P − A) rounds in double, so the plain cross product gets many signs wrong.
    // Exactly: on the line (x = y) is on the edge, above it inside, below it outside.
    const double u = std::ldexp(1.0, -53);
    int on = 0, in = 0, out = 0;
    for (int block = 0; block < 128; ++block) {
        Barycentric::Input input = in2({{{24, 24}, {-12, -12}, {-12, 24}}}, {});
        for (int i = 0; i < 512; ++i) {
            const int x = (block * 512 + i) % 256, y = (block * 512 + i) / 256;
            input.points.push_back({0.5 + x * u, 0.5 + y * u, 0});
        }
        const auto r = Barycentric::compute(input);
        for (int i = 0; i < 512; ++i) {
            const int x = (block * 512 + i) % 256, y = (block * 512 + i) / 256;
            CAPTURE(x, y);
            const auto& pr = r.results[i];
            REQUIRE(pr.on_edge == (x == y));
            REQUIRE(pr.inside == (y >= x));
            // γ (the sub-area (A, B, P)) has the exact sign: 0 on the line, and its sign
            // agrees with inside off it.
            REQUIRE((pr.weights.z == 0) == (x == y));
            REQUIRE((pr.weights.z > 0) == (y > x));
            on += pr.on_edge;
            in += pr.inside && !pr.on_edge;
            out += !pr.inside;
        }
    }
    CHECK(on == 256);
    CHECK(in == 256 * 255 / 2);
    CHECK(out == 256 * 255 / 2);
}

// ---- [3D tolerance] -------------------------------------------------------------------------

TEST_CASE("barycentric: 3D on_edge uses |weight| <= 1e-12", "[raster][barycentric]") {
    // The plane x + y + z = 1 (no coordinate plane): decimal points on the edges are not exact.
    const std::array<dvec3, 3> t{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    const auto r = Barycentric::compute(in3(t, {{0.3, 0.7, 0},
                                                {0, 0.1, 0.9},
                                                {0.1, 0.2, 0.7},
                                                {0.3, 0.7 + 1e-9, -1e-9},
                                                {4.0 / 3, 4.0 / 3, 4.0 / 3}}));
    CHECK(r.results[0].on_edge);  // γ = 0 (on AB)
    CHECK(r.results[1].on_edge);  // α = 0 (on BC)
    CHECK((r.results[2].inside && !r.results[2].on_edge));
    CHECK_FALSE(r.results[3].on_edge);  // γ ≈ −1e-9: outside, beyond the tolerance
    CHECK_FALSE(r.results[3].inside);
    CHECK(r.results[4].distance == Approx(std::sqrt(3.0)).epsilon(1e-14));  // the centroid + n
    CHECK(r.results[4].inside);
    const auto w = r.results[4].weights;
    CHECK(std::fabs(w.x - 1.0 / 3) < 1e-15);
}

// ---- [errors] -------------------------------------------------------------------------------

TEST_CASE("barycentric: bad input names the field", "[raster][barycentric]") {
    using cg::test::error_of;
    const std::string id = "barycentric";
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4, 0], [1, 3]], "points": [[1, 1]]})") ==
          "(accepted)");
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4, 0]], "points": [[1, 1]]})") ==
          "triangle: must be a list of three points [A, B, C], got an array ([[0,0],[4,0]])");
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4, 0, 0], [1, 3]], "points": [[1, 1]]})") ==
          "triangle[1]: has 3 coordinates but triangle[0] has 2: A, B and C must all be 2D [x, "
          "y] or all 3D [x, y, z]");
    CHECK(
        error_of(id, R"({"triangle": [[0, 0], [4, 0], [1, 3]], "points": [[1, 1], [1, 1, 1]]})") ==
        "points[1]: has 3 coordinates but the triangle has 2: every point must have the "
        "triangle's dimension (2D)");
    CHECK(error_of(id, R"({"triangle": [[0, 0, 0], [4, 0, 0], [1, 3, 0]], "points": [[1, 1]]})") ==
          "points[0]: has 2 coordinates but the triangle has 3: every point must have the "
          "triangle's dimension (3D)");
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4], [1, 3]], "points": [[1, 1]]})") ==
          "triangle[1]: must be a point [x, y] or [x, y, z], got an array ([4])");
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4, 0], [1, 3]], "points": []})") ==
          "points: must list at least one point [x, y] or [x, y, z]");
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4, 0], [1, 3]], "points": [[1, "a"]]})") ==
          "points[0][1]: must be a number, got a string (\"a\")");
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4, 0], [8, 0]], "points": [[1, 1]]})") ==
          "triangle: is degenerate: A, B and C lie on one line (its area is 0), so barycentric "
          "coordinates are not defined");
    CHECK(
        error_of(id, R"({"triangle": [[0, 0, 0], [1, 1, 1], [3, 3, 3]], "points": [[1, 1, 1]]})") ==
        "triangle: is degenerate: A, B and C lie on one line (its area is 0), so barycentric "
        "coordinates are not defined");
    CHECK(error_of(id, R"({"triangle": [[1, 2], [4, 0], [1, 2]], "points": [[1, 1]]})") ==
          "triangle: is degenerate: A and C are the same point, so the triangle has no area and "
          "barycentric coordinates are not defined");
    CHECK_THAT(error_of(id, R"({"triangle": [[0, 0], [1e6, 0], [5e5, 1e-6]], "points": [[1, 1]]})"),
               Catch::StartsWith("triangle: is degenerate: A, B and C lie (nearly) on one line — "
                                 "its height is 10⁻⁶, below 1e-9 of its longest edge (1000000)"));
    CHECK(error_of(id, R"({"triangle": [[0, 0], [1e101, 0], [1, 3]], "points": [[1, 1]]})") ==
          "triangle[1][0]: must lie within ±1e100 (got 10¹⁰¹): products of coordinates must not "
          "overflow");
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4, 0], [1, 3]], "points": [[1e-300, 1]]})") ==
          "points[0][0]: must be 0 or at least 1e-100 in size (got 10⁻³⁰⁰): products of "
          "coordinates must not underflow");
    CHECK(error_of(id, R"({"triangle": [[0, 0], [4, 0], [1, 3]], "points": [[1, 1]], "p": 1})") ==
          "p: is not a known field (expected: triangle, points)");
    std::string many = R"({"triangle": [[0, 0], [4, 0], [1, 3]], "points": [)";
    for (int k = 0; k < 1001; ++k) many += std::string(k ? "," : "") + "[1, 1]";
    CHECK(error_of(id, many + "]}") == "points: must list at most 1000 points (got 1001)");
    // The typed interface checks what JSON cannot express.
    Barycentric::Input bad = in2({{{0, 0}, {4, 0}, {1, 3}}}, {{1, 1}});
    bad.dim = 4;
    CHECK_THROWS_WITH(Barycentric::start(bad),
                      "triangle: must have 2D or 3D vertices (got dimension 4)");
    bad = in2({{{0, 0}, {4, 0}, {1, 3}}}, {{1, std::numeric_limits<double>::quiet_NaN()}});
    CHECK_THROWS_WITH(Barycentric::start(bad), "points[0][1]: must be a finite number (got NaN)");
}

// ---- [determinism] --------------------------------------------------------------------------

TEST_CASE("barycentric: traces are deterministic and stepping back reproduces them",
          "[raster][barycentric]") {
    const cg::Algorithm& a = cg::test::algorithm("barycentric");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* lesson = lessons.for_algorithm("barycentric");
    REQUIRE(lesson);
    CHECK(lesson->presets.size() >= 5);
    for (const auto& p : lesson->presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
    const cg::json r = cg::test::result_of("barycentric", a.example());
    CHECK(r["area"] == 6.0);
    CHECK(r["results"][1]["weights"] == cg::json::array({0.0, 0.5, 0.5}));
    CHECK(r["results"][1]["on_edge"] == true);
    CHECK_FALSE(r.contains("normal"));
    const cg::json r3 = cg::test::result_of(
        "barycentric",
        std::string(R"({"triangle": [[0, 0, 1], [4, 0, 1], [0, 4, 1]], "points": [[1, 1, 3]]})"));
    CHECK(r3["normal"] == cg::json::array({0.0, 0.0, 16.0}));
    CHECK(r3["results"][0]["distance"] == 2.0);
    CHECK(r3["results"][0]["projected"] == cg::json::array({1.0, 1.0, 1.0}));
}

// ---- [exam] ---------------------------------------------------------------------------------

TEST_CASE("barycentric: exam problems have hand-computable answers that rebuild the points",
          "[raster][barycentric][exam]") {
    int three_d = 0, edge = 0, out = 0;
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const Barycentric::Input in = Barycentric::exam_input(rng);
        const auto r = Barycentric::compute(in);
        three_d += in.dim == 3;
        for (std::size_t k = 0; k < in.points.size(); ++k) {
            const auto& pr = r.results[k];
            const Solve ref = in.dim == 3 ? solve3(in, in.points[k]) : solve2(in, in.points[k]);
            for (int i = 0; i < 3; ++i) REQUIRE(std::fabs(pr.weights[i] - ref.w[i]) < 1e-13L);
            if (in.dim == 2) {
                // Whole-number vertices and half-integer points: 4·area·w is a whole number.
                for (int i = 0; i < 3; ++i) {
                    const double q = 4 * r.area * pr.weights[i];
                    REQUIRE(std::fabs(q - std::round(q)) < 1e-9);
                }
            } else {
                // Weights in quarters by construction.
                for (int i = 0; i < 3; ++i)
                    REQUIRE(std::fabs(4 * pr.weights[i] - std::round(4 * pr.weights[i])) < 1e-9);
            }
            edge += pr.on_edge;
            out += !pr.inside;
        }
        const std::string q = Barycentric::question(in);
        CHECK_THAT(q, Catch::StartsWith("Give the barycentric coordinates of P0 = ("));
    }
    CHECK(three_d > 100);
    CHECK(edge > 100);
    CHECK(out > 200);
}

// ---- [picture] ------------------------------------------------------------------------------

TEST_CASE("barycentric: the picture shades the three sub-triangles", "[raster][barycentric]") {
    auto s = Barycentric::start(in2({{{0, 0}, {4, 0}, {1, 3}}}, {{1, 1}, {4, 2}}));
    cg::Scene before;
    Barycentric::draw(s, before);
    CHECK(before.handles.size() == 5);  // A, B, C, P0, P1
    CHECK(before.handles[3].x_field == "/points/0/0");
    CHECK(before.polygons.size() == 1);
    Barycentric::step(s, nullptr);  // area
    Barycentric::step(s, nullptr);  // areas of P0
    cg::Scene scene;
    Barycentric::draw(s, scene);
    CHECK(scene.polygons.size() == 4);  // three sub-triangles and the triangle
    int filled = 0;
    for (const auto& p : scene.polygons) filled += p.filled;
    CHECK(filled == 3);
    std::vector<std::string> labels;
    for (const auto& l : scene.labels) labels.push_back(l.text);
    CHECK(labels == std::vector<std::string>{"A_a = 3", "A_b = 1", "A_c = 2"});
    Barycentric::step(s, nullptr);  // ratios
    scene.clear();
    Barycentric::draw(s, scene);
    CHECK(scene.labels[0].text == "A_a = 3, α = 0.5");
    // P1 beyond BC: its sub-triangle (P, B, C) is drawn dashed (negative area).
    Barycentric::step(s, nullptr);
    Barycentric::step(s, nullptr);
    scene.clear();
    Barycentric::draw(s, scene);
    CHECK(scene.polygons[0].style.dashed);
    CHECK_FALSE(scene.polygons[0].filled);
    CHECK_FALSE(scene.polygons[1].style.dashed);
    CHECK(scene.polygons[1].filled);
    CHECK_FALSE(scene.has_3d());

    // 3D: the faces, the projection and the normal on the 3D canvas.
    auto s3 = Barycentric::start(in3({{{0, 0, 1}, {4, 0, 1}, {0, 4, 1}}}, {{1, 1, 3}}));
    Barycentric::step(s3, nullptr);
    Barycentric::step(s3, nullptr);
    Barycentric::step(s3, nullptr);
    cg::Scene scene3;
    Barycentric::draw(s3, scene3);
    CHECK(scene3.has_3d());
    CHECK_FALSE(scene3.has_2d());
    CHECK(scene3.faces3.size() == 4);
    bool projected = false;
    for (const auto& p : scene3.points3) projected = projected || p.label == "P′";
    CHECK(projected);
}
