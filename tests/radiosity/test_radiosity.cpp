// Radiosity: the solved B against a direct solve of (I − diag(ρ) F) B = E by Gaussian elimination
// with partial pivoting in long double (written here), per channel, to 1e-9 for Jacobi,
// Gauss-Seidel and progressive refinement run to convergence — on the Cornell box and on 2,000
// seeded random scenes (boxes and open sets of walls, every form-factor method, subdivided);
// Jacobi and Gauss-Seidel agree; progressive refinement's energy accounting at every shot; the
// unit cube's analytic form factors; the exam's 3-patch shot by hand; degenerate input (ρ = 0,
// no emitters, coincident patches, zero area, ρ = 1); replay; the exam; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "radiosity/radiosity.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Patch;
using cg::Radiosity;
using glm::dvec3;
using Input = Radiosity::Input;
using Method = Radiosity::Method;
using FF = Radiosity::FormFactors;

namespace {

using LD = long double;

// ---- the independent reference: Gaussian elimination in long double ----

// Solves (I − diag(ρ_c) K) B = E_c for channel c: K = F for gathering; for shooting K_ji =
// A_i F_ij / A_j, the F_ji that reciprocity gives (the same as F when F is reciprocal, which a
// hemicube from the patch centre is not).
std::vector<LD> direct_solve(const Radiosity::Result& r, int c, bool shooting) {
    const auto& sc = *r.scene;
    const std::size_t n = sc.patches.size();
    std::vector<std::vector<LD>> M(n, std::vector<LD>(n + 1));
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j)
            M[i][j] = (i == j ? 1.0L : 0.0L) -
                      LD(sc.reflectance[i][c]) *
                          (shooting ? LD(sc.area[j]) * LD(r.form_factors[j * n + i]) / LD(sc.area[i])
                                    : LD(r.form_factors[i * n + j]));
        M[i][n] = sc.emission[i][c];
    }
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t p = k;
        for (std::size_t i = k + 1; i < n; ++i)
            if (std::fabs(M[i][k]) > std::fabs(M[p][k])) p = i;
        std::swap(M[k], M[p]);
        for (std::size_t i = k + 1; i < n; ++i) {
            const LD f = M[i][k] / M[k][k];
            for (std::size_t j = k; j <= n; ++j) M[i][j] -= f * M[k][j];
        }
    }
    std::vector<LD> B(n);
    for (std::size_t i = n; i-- > 0;) {
        LD s = M[i][n];
        for (std::size_t j = i + 1; j < n; ++j) s -= M[i][j] * B[j];
        B[i] = s / M[i][i];
    }
    return B;
}

// The largest |B − B_direct| over patches and channels, relative to max(1, |B_direct|).
double error_against_direct(const Radiosity::Result& r, Method m) {
    double worst = 0;
    for (int c = 0; c < 3; ++c) {
        const auto ref = direct_solve(r, c, m == Method::Progressive);
        LD scale = 1;
        for (LD v : ref) scale = std::max(scale, std::fabs(v));
        for (std::size_t k = 0; k < ref.size(); ++k)
            worst = std::max(worst, double(std::fabs(LD(r.radiosity[k][c]) - ref[k]) / scale));
    }
    return worst;
}

Radiosity::Surface rect(dvec3 corner, dvec3 u, dvec3 v, dvec3 rho, dvec3 e = {0, 0, 0}) {
    return {Patch::rectangle(corner, u, v), e, rho};
}

// A w × h × d box with inward normals (floor, ceiling, back, front, left, right).
std::vector<Radiosity::Surface> box(double w, double h, double d, const dvec3 rho[6],
                                    const dvec3 e[6]) {
    return {
        rect({0, 0, 0}, {0, 0, d}, {w, 0, 0}, rho[0], e[0]),
        rect({0, h, 0}, {w, 0, 0}, {0, 0, d}, rho[1], e[1]),
        rect({0, 0, 0}, {w, 0, 0}, {0, h, 0}, rho[2], e[2]),
        rect({0, 0, d}, {0, h, 0}, {w, 0, 0}, rho[3], e[3]),
        rect({0, 0, 0}, {0, h, 0}, {0, 0, d}, rho[4], e[4]),
        rect({w, 0, 0}, {0, 0, d}, {0, h, 0}, rho[5], e[5]),
    };
}

Input cornell(Method m, int subdivision = 2) {
    Input in = cg::test::input_of<Radiosity>("radiosity", cg::test::algorithm("radiosity").example());
    in.method = m;
    in.subdivision = subdivision;
    in.tolerance = 1e-13;
    in.max_steps = Radiosity::kMaxSteps;
    return in;
}

double total_power(const Radiosity::Scene3& sc, const std::vector<dvec3>& B, int c) {
    double s = 0;
    for (std::size_t k = 0; k < B.size(); ++k) s += sc.area[k] * B[k][c];
    return s;
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lib =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lib.for_algorithm("radiosity");
    REQUIRE(l);
    return *l;
}

}  // namespace

TEST_CASE("radiosity: the exam's 3-patch shot by hand", "[radiosity]") {
    // Unit squares: floor (emits 1), a wall on its edge at a right angle, a ceiling at height 1.
    // Howell: F_floor→wall = 0.20004 (C-14, l = w = h = 1), F_floor→ceiling = 0.19982 (C-11).
    Input in;
    in.method = Method::Progressive;
    in.form_factors = FF::Analytic;
    in.max_steps = 1;
    in.surfaces = {
        rect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0.5}, {1, 1, 1}),
        rect({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0.5, 0.25, 0.75}),
        rect({0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0.25, 0.5, 1.0 / 3}),
    };
    const auto r = Radiosity::compute(in);
    CHECK(r.form_factors[1] == Approx(0.20004).margin(1e-5));
    CHECK(r.form_factors[2] == Approx(0.19982).margin(1e-5));
    REQUIRE(r.first_shot.shooter == 0);
    CHECK(r.steps == 1);
    // Equal areas: F_j0 = F_0j. ΔB_1 = ρ_1 × 0.20004 × 1, ΔB_2 = ρ_2 × 0.19982 × 1.
    CHECK(r.first_shot.f_ji[0] == 0);
    CHECK(r.first_shot.f_ji[1] == Approx(0.20004).margin(1e-5));
    CHECK(r.first_shot.delta_b[1][0] == Approx(0.5 * 0.20004).margin(1e-5));
    CHECK(r.first_shot.delta_b[1][1] == Approx(0.25 * 0.20004).margin(1e-5));
    CHECK(r.first_shot.delta_b[2][2] == Approx(0.19982 / 3).margin(1e-5));
    CHECK(r.radiosity[0] == dvec3(1, 1, 1));  // the shooter keeps its B; its ΔB is shot
    // A floor twice as long (2 × 1, area 2): F_j0 = A_0 F_0j / A_j doubles.
    in.surfaces[0] = rect({0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0.5, 0.5, 0.5}, {1, 1, 1});
    in.surfaces[2] = rect({0, 0, 1}, {0, 2, 0}, {1, 0, 0}, {0.25, 0.5, 0.5});
    const auto r2 = Radiosity::compute(in);
    CHECK(r2.first_shot.f_ji[1] == Approx(2 * r2.form_factors[1]).epsilon(1e-14));
    CHECK(r2.first_shot.f_ji[2] == Approx(r2.form_factors[2]).epsilon(1e-14));  // equal areas
    CHECK(r2.reciprocity_error < 1e-12);  // every pair analytic
}

TEST_CASE("radiosity: the unit cube's analytic form factors sum to 1", "[radiosity]") {
    const dvec3 rho[6] = {dvec3(0.5), dvec3(0.5), dvec3(0.5), dvec3(0.5), dvec3(0.5), dvec3(0.5)};
    const dvec3 e[6] = {dvec3(1), dvec3(0), dvec3(0), dvec3(0), dvec3(0), dvec3(0)};
    Input in;
    in.surfaces = box(1, 1, 1, rho, e);
    in.form_factors = FF::Analytic;
    in.tolerance = 1e-14;
    const auto r = Radiosity::compute(in);
    for (std::size_t i = 0; i < 6; ++i) CHECK(r.row_sum[i] == Approx(4 * 0.200044 + 0.199825).margin(2e-6));
    CHECK(r.reciprocity_error < 1e-12);
    CHECK(error_against_direct(r, in.method) < 1e-9);
    // By symmetry the four walls agree, and the sum over the cube is the closed-form geometric
    // series: Σ A B = A_0 E_0 / (1 − ρ) when every row sums to 1 (here 0.99998).
    for (std::size_t k = 3; k < 6; ++k) CHECK(r.radiosity[k].x == Approx(r.radiosity[2].x).epsilon(1e-10));
    CHECK(total_power(*r.scene, r.radiosity, 0) == Approx(2.0).epsilon(1e-4));
}

TEST_CASE("radiosity: all three methods converge to the direct solve on the Cornell box",
          "[radiosity]") {
    for (int sub : {1, 2, 3}) {
        CAPTURE(sub);
        const auto jac = Radiosity::compute(cornell(Method::Jacobi, sub));
        const auto gs = Radiosity::compute(cornell(Method::GaussSeidel, sub));
        const auto pr = Radiosity::compute(cornell(Method::Progressive, sub));
        for (const auto* r : {&jac, &gs}) {
            CHECK(r->converged);
            CHECK(error_against_direct(*r, Method::Jacobi) < 1e-9);
        }
        CHECK(pr.converged);
        CHECK(error_against_direct(pr, Method::Progressive) < 1e-9);
        CHECK(gs.steps < jac.steps);  // Gauss-Seidel uses the newer values: fewer sweeps
        for (std::size_t k = 0; k < jac.radiosity.size(); ++k)
            for (int c = 0; c < 3; ++c)
                CHECK(jac.radiosity[k][c] == Approx(gs.radiosity[k][c]).margin(1e-10));
    }
    // With exactly reciprocal form factors (the analytic cube) gathering and shooting solve the
    // same system and agree; with the single hemicube's they need not (the lesson says why).
    const dvec3 rho[6] = {{.5, .6, .7}, {.8, .8, .8}, {.3, .3, .3}, {.9, .1, .5}, {.2, .7, .4}, {.6, .6, .1}};
    const dvec3 e[6] = {dvec3(0), dvec3(2, 1, 1), dvec3(0), dvec3(0), dvec3(0), dvec3(0)};
    Input cube;
    cube.surfaces = box(1, 1, 1, rho, e);
    cube.form_factors = FF::Analytic;
    cube.tolerance = 1e-14;
    cube.max_steps = Radiosity::kMaxSteps;
    cube.method = Method::Jacobi;
    const auto gather = Radiosity::compute(cube);
    cube.method = Method::Progressive;
    const auto shoot = Radiosity::compute(cube);
    CHECK(shoot.converged);
    for (std::size_t k = 0; k < 6; ++k)
        for (int c = 0; c < 3; ++c)
            CHECK(gather.radiosity[k][c] == Approx(shoot.radiosity[k][c]).margin(1e-10));
}

TEST_CASE("radiosity: progressive refinement accounts for every bit of power, shot by shot",
          "[radiosity]") {
    // Σ_j A_j B_j = (power shot so far) + (power unshot): what a shot sends out it takes from
    // the shooter's unshot store, and every receiver adds its gain to both B and ΔB.
    Input in = cornell(Method::Progressive, 2);
    in.max_steps = 300;
    auto s = Radiosity::start(in);
    const auto& sc = *s.scene;
    double emitted[3] = {};
    for (int c = 0; c < 3; ++c) emitted[c] = total_power(sc, sc.emission, c);
    int shots = 0;
    double last_unshot = 1e300;
    while (!Radiosity::done(s)) {
        Radiosity::step(s, nullptr);
        if (s.last != Radiosity::Phase::Solve) continue;
        ++shots;
        for (int c = 0; c < 3; ++c) {
            const double unshot = total_power(sc, s.unshot, c);
            CHECK(total_power(sc, s.B, c) == Approx(s.shot_power[c] + unshot).epsilon(1e-12));
            CHECK(s.shot_power[c] >= emitted[c] * (shots >= 4 ? 1 - 1e-12 : 0));
        }
        // Unshot power only falls (the receivers' gain is less than the shot: ρ F row sums < 1).
        const double u = total_power(sc, s.unshot, 0) + total_power(sc, s.unshot, 1) +
                         total_power(sc, s.unshot, 2);
        CHECK(u <= last_unshot * (1 + 1e-12));
        last_unshot = u;
    }
    CHECK(shots == 300);
}

TEST_CASE("radiosity: 2,000 seeded random scenes against the direct solve", "[radiosity]") {
    cg::Rng rng(2027);
    int converged = 0, open = 0, methods[3] = {};
    for (int t = 0; t < 2000; ++t) {
        CAPTURE(t);
        dvec3 rho[6], e[6];
        for (int k = 0; k < 6; ++k) {
            rho[k] = dvec3(rng.uniform(0, 0.9), rng.uniform(0, 0.9), rng.uniform(0, 0.9));
            if (rng.integer(0, 9) == 0) rho[k] = dvec3(0);
            e[k] = rng.integer(0, 2) == 0 ? dvec3(rng.uniform(0, 5), rng.uniform(0, 5), rng.uniform(0, 5))
                                          : dvec3(0);
        }
        Input in;
        in.surfaces = box(rng.uniform(0.3, 3), rng.uniform(0.3, 3), rng.uniform(0.3, 3), rho, e);
        if (rng.integer(0, 3) == 0) {  // an open scene: drop some walls
            const int drop = int(rng.integer(1, 4));
            for (int k = 0; k < drop; ++k)
                in.surfaces.erase(in.surfaces.begin() + rng.integer(0, std::int64_t(in.surfaces.size()) - 1));
            ++open;
        }
        in.subdivision = int(rng.integer(1, 2));
        in.form_factors = FF(rng.integer(0, 2));
        in.resolution = 4;
        in.rays = 64;
        in.seed = std::uint64_t(t);
        in.method = Method(rng.integer(0, 2));
        ++methods[int(in.method)];
        in.tolerance = 1e-13;
        in.max_steps = Radiosity::kMaxSteps;
        const auto r = Radiosity::compute(in);
        converged += r.converged;
        CHECK(r.converged);
        CHECK(error_against_direct(r, in.method) < 1e-9);
        // Ray fractions never sum above 1; the hemicube's cells at R = 4 overshoot a little; the
        // analytic values mixed with 64-ray estimates carry the rays' noise.
        const double most = in.form_factors == FF::MonteCarlo ? 1 + 1e-12
                            : in.form_factors == FF::Hemicube ? 1.06
                                                              : 1.25;
        for (double s : r.row_sum) CHECK(s <= most);
    }
    CHECK(converged == 2000);
    CHECK(open > 300);
    for (int m : methods) CHECK(m > 500);
}

TEST_CASE("radiosity: degenerate input — no light, no reflection, coincident patches, ρ = 1",
          "[radiosity]") {
    for (Method m : {Method::Jacobi, Method::GaussSeidel, Method::Progressive}) {
        CAPTURE(int(m));
        // ρ = 0 everywhere: B = E exactly.
        Input in = cornell(m, 2);
        for (auto& s : in.surfaces) s.reflectance = dvec3(0);
        const auto r = Radiosity::compute(in);
        CHECK(r.converged);
        for (std::size_t k = 0; k < r.radiosity.size(); ++k) CHECK(r.radiosity[k] == r.scene->emission[k]);
        // No emitters: B = 0, in one step.
        Input dark = cornell(m, 2);
        for (auto& s : dark.surfaces) s.emission = dvec3(0);
        const auto t = cg::test::run_traced<Radiosity>(dark);
        CHECK(t.result.converged);
        CHECK(t.result.steps == 1);
        for (const dvec3& b : t.result.radiosity) CHECK(b == dvec3(0));
        if (m == Method::Progressive) CHECK(t.steps.back().event == "nothing-to-shoot");
        // Coincident patches: a second floor on top of the first (they do not see each other:
        // coplanar) — still the direct solve's answer.
        Input twin = cornell(m, 1);
        twin.surfaces.push_back(twin.surfaces[0]);
        twin.surfaces.back().reflectance = dvec3(0.3);
        const auto rt = Radiosity::compute(twin);
        CHECK(rt.converged);
        CHECK(error_against_direct(rt, m) < 1e-9);
        CHECK(rt.form_factors[0 * 8 + 7] == 0);
    }
    // ρ = 1 on one wall of a box whose other walls absorb: accepted, converges.
    Input one = cornell(Method::GaussSeidel, 1);
    one.surfaces[2].reflectance = dvec3(1, 1, 1);
    // The hemicube's rows sum to 1.0086 here: a perfect reflector would gain light, refused.
    CHECK_THROWS_WITH(Radiosity::start(one),
                      Catch::StartsWith("surfaces[2].reflectance: ρ = 1 in the red channel on a "
                                        "patch whose form factors sum to 1.0085"));
    one.form_factors = FF::MonteCarlo;  // ray fractions: rows sum to at most 1
    const auto r1 = Radiosity::compute(one);
    CHECK(r1.converged);
    CHECK(error_against_direct(r1, Method::GaussSeidel) < 1e-9);
    // ρ = 1 in the red channel on every wall of a closed box: the light never leaves — refused.
    // (Analytic form factors: the cube's rows sum to 0.99998 < 1, so it is a Monte Carlo box,
    // whose rows sum to exactly 1.)
    const dvec3 rho[6] = {{1, .5, .5}, {1, .5, .5}, {1, .5, .5}, {1, .5, .5}, {1, .5, .5}, {1, .5, .5}};
    const dvec3 e[6] = {dvec3(1), dvec3(0), dvec3(0), dvec3(0), dvec3(0), dvec3(0)};
    Input closed;
    closed.surfaces = box(1, 1, 1, rho, e);
    closed.form_factors = FF::MonteCarlo;
    CHECK_THROWS_WITH(Radiosity::start(closed),
                      Catch::Contains(".reflectance: ρ = 1 in the red channel on patches that "
                                      "form a closed set"));
    CHECK_THROWS_WITH(Radiosity::compute(closed), Catch::Contains("bounce forever"));
    closed.surfaces.pop_back();  // an opening: light escapes, so it converges
    CHECK(Radiosity::compute(closed).converged);
}

TEST_CASE("radiosity: bad input names the field", "[radiosity]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto err = [](const Input& in) {
        try {
            Radiosity::start(in);
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    const Input good = cornell(Method::Jacobi, 1);
    CHECK(err(good) == "(accepted)");
    Input in = good;
    in.surfaces.clear();
    CHECK_THAT(err(in), Catch::StartsWith("surfaces: needs at least one surface"));
    in = good;
    in.surfaces[1].patch = Patch::rectangle({0, 0, 0}, {1, 0, 0}, {2, 0, 0});
    CHECK_THAT(err(in), Catch::StartsWith("surfaces[1]: the rectangle has zero area"));
    in = good;
    in.surfaces[3].patch = Patch::disc({0, 0, 0}, {0, 0, 1}, 1);
    CHECK_THAT(err(in), Catch::StartsWith("surfaces[3].type: must be \"rectangle\" or \"triangle\""));
    in = good;
    in.surfaces[0].reflectance = {0.5, 1.2, 0.5};
    CHECK_THAT(err(in), Catch::StartsWith("surfaces[0].reflectance: must lie in [0, 1]"));
    in = good;
    in.surfaces[0].emission = {0.5, nan, 0.5};
    CHECK_THAT(err(in), Catch::StartsWith("surfaces[0].emission: must be finite"));
    in = good;
    in.surfaces[0].emission = {-1, 0, 0};
    CHECK_THAT(err(in), Catch::StartsWith("surfaces[0].emission"));
    in = good;
    in.subdivision = 40;
    CHECK_THAT(err(in), Catch::StartsWith("subdivision: must be from 1 to 32"));
    in.subdivision = 20;  // 7 × 400 = 2800 patches
    CHECK_THAT(err(in), Catch::Contains("at most 2048"));
    in = good;
    in.tolerance = 0;
    CHECK_THAT(err(in), Catch::StartsWith("tolerance: must be a positive number"));
    in = good;
    in.camera.target = in.camera.position;
    CHECK_THAT(err(in), Catch::StartsWith("camera.target: equals the position"));
    in = good;
    in.camera.up = in.camera.target - in.camera.position;
    CHECK_THAT(err(in), Catch::StartsWith("camera.up"));
    in = good;
    in.resolution = 7;
    CHECK_THAT(err(in), Catch::StartsWith("form_factors.resolution"));
    CHECK_THAT(cg::test::error_of("radiosity", R"({"surfaces": [], "method": "newton"})"),
               Catch::StartsWith("method: must be \"jacobi\", \"gauss-seidel\" or \"progressive\""));
    CHECK_THAT(cg::test::error_of("radiosity",
                                  R"({"surfaces": [{"type": "rectangle", "corner": [0,0,0],
                                      "edge_u": [1,0,0], "edge_v": [0,1,0], "glow": 1}]})"),
               Catch::StartsWith("surfaces[0].glow: is not a known field"));
    CHECK_THAT(cg::test::error_of("radiosity", R"({"surfaces": [{"type": "rectangle", "corner": [0,0,0],
                                      "edge_u": [1,0,0], "edge_v": [0,1,0], "reflectance": [1, 1]}]})"),
               Catch::StartsWith("surfaces[0].reflectance"));
}

TEST_CASE("radiosity: triangles subdivide into n² triangles of the same total area",
          "[radiosity]") {
    Input in;
    in.surfaces = {{Patch::triangle({0, 0, 0}, {2, 0, 0}, {0, 3, 0}), {1, 1, 1}, {0.5, 0.5, 0.5}},
                   {Patch::rectangle({0, 0, 2}, {0, 3, 0}, {2, 0, 0}), {0, 0, 0}, {0.5, 0.5, 0.5}}};
    for (int n : {1, 2, 3, 5}) {
        in.subdivision = n;
        const auto sc = Radiosity::prepare(in);
        REQUIRE(sc.patches.size() == std::size_t(2 * n * n));
        double tri = 0;
        for (std::size_t k = 0; k < sc.patches.size(); ++k)
            if (sc.surface[k] == 0) {
                tri += sc.area[k];
                CHECK(cg::normal(sc.patches[k]).z == Approx(1));  // same orientation
                CHECK(sc.area[k] == Approx(3.0 / (n * n)));
            }
        CHECK(tri == Approx(3));
        in.tolerance = 1e-13;
        CHECK(error_against_direct(Radiosity::compute(in), in.method) < 1e-9);
    }
}

TEST_CASE("radiosity: the Cornell presets gather and shoot to the same floor: a coarse hemicube "
          "parts them, as the lesson says",
          "[radiosity]") {
    // The floor's red channel, area-weighted over its patches (surface 0, y = 0).
    auto floor = [](const cg::json& input) {
        const Input in = cg::test::input_of<Radiosity>("radiosity", input);
        const auto r = Radiosity::compute(in);
        CHECK(r.converged);
        double b = 0, area = 0;
        for (std::size_t k = 0; k < r.radiosity.size(); ++k)
            if (r.scene->surface[k] == 0) b += r.scene->area[k] * r.radiosity[k].x, area += r.scene->area[k];
        return b / area;
    };
    auto preset = [](const std::string& name) {
        for (const auto& p : lesson().presets)
            if (p.name == name) return p.input;
        FAIL("no preset " << name);
        return cg::json();
    };
    const cg::json gs = preset("Cornell box, Gauss-Seidel");
    const double gathered = floor(gs);
    const double shot = floor(preset("Cornell box, progressive refinement"));
    const double monte_carlo = floor(preset("Cornell box, Monte Carlo form factors"));
    CHECK(floor(preset("Cornell box, Jacobi (compare the sweeps)")) == Approx(gathered).epsilon(0.01));
    // The lesson's numbers: about 0.33, 0.35 and 0.36, within a few percent of each other.
    CHECK(gathered == Approx(0.33).margin(0.005));
    CHECK(shot == Approx(0.35).margin(0.005));
    CHECK(monte_carlo == Approx(0.36).margin(0.005));
    CHECK(std::abs(gathered - shot) / shot < 0.08);
    // Resolution 8 on one point: the floor gathers about 0.79, more than twice what is shot.
    cg::json coarse = gs;
    coarse["form_factors"]["resolution"] = 8;
    coarse["form_factors"]["samples"] = 1;
    const double aliased = floor(coarse);
    CHECK(aliased == Approx(0.79).margin(0.005));
    CHECK(aliased > 2 * shot);
}

TEST_CASE("radiosity: replay on the example and the presets, run-to-end is compute",
          "[radiosity]") {
    const cg::Algorithm& a = cg::test::algorithm("radiosity");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    std::set<std::string> seen;
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        // Replay tests the machine, not the form factors' accuracy: the presets' fine hemicube
        // (32 × 32 cells on 3 × 3 points) made coarse keeps this quick, under the sanitizers too.
        cg::json input = p.input;
        if (input.contains("form_factors") &&
            input["form_factors"].value("method", "hemicube") == "hemicube")
            input["form_factors"]["resolution"] = 8, input["form_factors"]["samples"] = 1;
        cg::test::check_replay(a, input, 7);
        const Input in = cg::test::input_of<Radiosity>("radiosity", input);
        const auto t = cg::test::run_traced<Radiosity>(in);
        CHECK(t.result == Radiosity::compute(in));
        CHECK(cg::run_to_end<Radiosity>(Radiosity::start(in)) == t.result);
        for (const auto& e : cg::test::events(t)) seen.insert(e);
    }
    for (const auto& e : Radiosity::spec().events) {
        CAPTURE(e.id);
        CHECK(seen.count(e.id));
    }
    const cg::json r = cg::test::result_of("radiosity", a.example());
    CHECK(r["patches"] == 28);
    CHECK(r["converged"] == true);
    CHECK(r["table"].size() == 28);
    CHECK(r["first_shot"].is_null());
}

TEST_CASE("radiosity: exam problems — one shot on 3 patches, F_ji by reciprocity",
          "[radiosity]") {
    const cg::Algorithm& a = cg::test::algorithm("radiosity");
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = cg::test::input_of<Radiosity>("radiosity", p.input);
        REQUIRE(in.surfaces.size() == 3);
        CHECK(p.expected["first_shot/shooter"] == 0);
        const double a0 = cg::area(in.surfaces[0].patch);
        for (int j = 1; j < 3; ++j) {
            const auto an = cg::ff::analytic(in.surfaces[0].patch, in.surfaces[std::size_t(j)].patch);
            REQUIRE(an.kase != cg::ff::Case::None);
            const double fji = a0 * an.value / cg::area(in.surfaces[std::size_t(j)].patch);
            CHECK(p.expected["first_shot/F_ji"][j].get<double>() == Approx(fji).epsilon(1e-12));
            CHECK(p.expected["first_shot/F_ji"][j].get<double>() == Approx(an.reverse).epsilon(1e-9));
            for (int c = 0; c < 3; ++c)
                CHECK(p.expected["first_shot/delta_B"][j][c].get<double>() ==
                      Approx(in.surfaces[std::size_t(j)].reflectance[c] * fji *
                             in.surfaces[0].emission[c])
                          .epsilon(1e-12));
        }
    }
}

TEST_CASE("radiosity: the picture — patches by B, the matrix, the camera image, the residual",
          "[radiosity]") {
    const Input in = cornell(Method::Progressive, 2);
    auto s = Radiosity::start(in);
    Radiosity::step(s, nullptr);
    cg::Scene rows;
    Radiosity::draw(s, rows);
    CHECK(rows.faces3.size() == 28);
    CHECK(rows.faces3[0].style.role == cg::Role::Active);  // patch i = 0, its row computed
    CHECK(!rows.has_2d());  // nothing in the world: the matrix and the row sums are panels
    REQUIRE(rows.panels.size() == 2);
    CHECK(rows.panels[0].kind == cg::PanelKind::Image);  // the matrix F
    REQUIRE(rows.panels[0].grids.size() == 1);
    CHECK(rows.panels[0].grids[0].width == 28);
    CHECK(rows.panels[0].polygons.size() == 1);  // row i outlined
    CHECK(rows.panels[1].kind == cg::PanelKind::Chart);  // the row sums, one bar so far
    CHECK(rows.panels[1].polygons.size() == 2);          // the line at 1 and row 0's bar
    CHECK(rows.focus3.size() == 1);
    while (s.phase == Radiosity::Phase::FormFactors) Radiosity::step(s, nullptr);
    Radiosity::step(s, nullptr);
    cg::Scene solve;
    Radiosity::draw(s, solve);
    REQUIRE(solve.panels.size() == 2);
    CHECK(solve.panels[0].kind == cg::PanelKind::Image);  // the camera's picture
    REQUIRE(solve.panels[0].grids.size() == 1);
    CHECK(solve.panels[0].grids[0].width == in.camera.width);
    CHECK(solve.panels[0].grids[0].rgba == Radiosity::image(*s.scene, s.B));
    const cg::Panel& chart = solve.panels[1];  // the residual per step, on a log axis
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.y.log);
    REQUIRE(chart.polygons.size() == 2);  // the tolerance and the residual so far
    CHECK(chart.polygons[0].points.front().y == in.tolerance);
    REQUIRE(chart.polygons[1].points.size() == s.history.size());
    CHECK(chart.polygons[1].points.back().y == s.residual);
    CHECK(s.shooter >= 24);
    // The shooter is the lamp (patches 24..27): it keeps its colour, outlined and named in orange.
    int outline = 0;
    for (const auto& g : solve.segments3) outline += g.style.role == cg::Role::Active;
    CHECK(outline == int(solve.faces3[std::size_t(s.shooter)].points.size()));
    REQUIRE(solve.labels3.size() == 1);
    CHECK(solve.labels3[0].text == "shooter");
    CHECK(solve.labels3[0].style.role == cg::Role::Active);
    // The red wall looks red and the green one green from the camera.
    const auto img = Radiosity::image(*s.scene, Radiosity::compute(cornell(Method::GaussSeidel, 2)).radiosity);
    const auto px = [&](int i, int j) { return img[std::size_t(j * in.camera.width + i)]; };
    const std::uint32_t left = px(1, 12), right = px(22, 12);
    CHECK((left >> 24) > ((left >> 16) & 0xff));
    CHECK(((right >> 16) & 0xff) > (right >> 24));
}
