// Spring-mass: one undamped spring against the closed form x(t) = L + A cos ωt (RK4's error falls
// ~16× when dt halves; symplectic Euler's energy error stays bounded over 10⁴ steps; explicit
// Euler's energy grows by exactly 1 + ω²dt² a step); a damped spring against its closed form;
// internal forces summing to zero and momentum kept without gravity or pins; an independent
// long-double implementation of all three integrators on 3,000 seeded random small systems
// (pinned masses, gravity, drag, damping, coincident ends), equal to 1e-9 relative; the state
// machine equals the plain function, through the registry too; blow-up stops cleanly with no
// NaN; degenerate inputs refused naming the field; replay on the presets; the exam problems
// against a hand computation; the narration of the first step; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/vector_relational.hpp>

#include "animation/spring_mass.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::SpringMass;
using Input = SpringMass::Input;
using Integrator = SpringMass::Integrator;
using LD = long double;

namespace {

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("spring-mass");
    if (!l) throw std::runtime_error("no lesson for spring-mass");
    return *l;
}

// One mass m on a spring (k, L, c) from a pinned anchor at the origin, along x, no gravity.
Input oscillator(double k, double m, double L, double x0, double dt, int steps, Integrator integ,
                 double c = 0) {
    Input in;
    SpringMass::Mass anchor;
    anchor.pinned = true;
    SpringMass::Mass mass;
    mass.mass = m;
    mass.position = {x0, 0, 0};
    in.masses = {anchor, mass};
    SpringMass::Spring s;
    s.i = 0;
    s.j = 1;
    s.stiffness = k;
    s.rest = L;
    s.has_rest = true;
    s.damping = c;
    in.springs = {s};
    in.gravity = {0, 0, 0};
    in.dt = dt;
    in.steps = steps;
    in.integrator = integ;
    return in;
}

// ---- the reference: the same equations in long double, written separately ----

struct V {
    LD x = 0, y = 0, z = 0;
};
V operator+(V a, V b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V operator-(V a, V b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V operator*(LD s, V a) {
    return {s * a.x, s * a.y, s * a.z};
}
LD dot(V a, V b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
V from(glm::dvec3 p) {
    return {p.x, p.y, p.z};
}

using Sys = std::vector<V>;

// d(x, v)/dt = (v, F/m), with pinned masses held.
void derivative(const Input& in, const Sys& x, const Sys& v, Sys& dx, Sys& dv) {
    const std::size_t n = x.size();
    std::vector<V> f(n);
    const V g = from(in.gravity);
    for (std::size_t i = 0; i < n; ++i) f[i] = LD(in.masses[i].mass) * g - LD(in.drag) * v[i];
    for (const auto& s : in.springs) {
        const V d = x[std::size_t(s.i)] - x[std::size_t(s.j)];
        const LD len = std::sqrt(dot(d, d));
        if (len == 0) continue;
        const V u = (1 / len) * d;
        const V rel = v[std::size_t(s.i)] - v[std::size_t(s.j)];
        const V fi =
            (-LD(s.stiffness) * (len - LD(s.rest))) * u + (-LD(s.damping) * dot(rel, u)) * u;
        f[std::size_t(s.i)] = f[std::size_t(s.i)] + fi;
        f[std::size_t(s.j)] = f[std::size_t(s.j)] - fi;
    }
    dx.assign(n, V{});
    dv.assign(n, V{});
    for (std::size_t i = 0; i < n; ++i) {
        if (in.masses[i].pinned) continue;
        dx[i] = v[i];
        dv[i] = (1 / LD(in.masses[i].mass)) * f[i];
    }
}

void reference(const Input& resolved, Sys& x, Sys& v) {
    x.clear();
    v.clear();
    for (const auto& m : resolved.masses)
        x.push_back(from(m.position)), v.push_back(from(m.velocity));
    const LD dt = resolved.dt;
    const std::size_t n = x.size();
    for (int k = 0; k < resolved.steps; ++k) {
        Sys dx, dv;
        derivative(resolved, x, v, dx, dv);
        if (resolved.integrator == Integrator::ExplicitEuler) {
            for (std::size_t i = 0; i < n; ++i) x[i] = x[i] + dt * dx[i], v[i] = v[i] + dt * dv[i];
        } else if (resolved.integrator == Integrator::SymplecticEuler) {
            for (std::size_t i = 0; i < n; ++i) {
                if (resolved.masses[i].pinned) continue;
                v[i] = v[i] + dt * dv[i];
                x[i] = x[i] + dt * v[i];
            }
        } else {
            Sys kx[4], kv[4], xs(n), vs(n);
            kx[0] = dx;
            kv[0] = dv;
            const LD h[4] = {0, dt / 2, dt / 2, dt};
            for (int q = 1; q < 4; ++q) {
                for (std::size_t i = 0; i < n; ++i)
                    xs[i] = x[i] + h[q] * kx[q - 1][i], vs[i] = v[i] + h[q] * kv[q - 1][i];
                derivative(resolved, xs, vs, kx[q], kv[q]);
            }
            for (std::size_t i = 0; i < n; ++i) {
                x[i] =
                    x[i] + (dt / 6) * (kx[0][i] + LD(2) * kx[1][i] + LD(2) * kx[2][i] + kx[3][i]);
                v[i] =
                    v[i] + (dt / 6) * (kv[0][i] + LD(2) * kv[1][i] + LD(2) * kv[2][i] + kv[3][i]);
            }
        }
    }
}

Input random_system(cg::Rng& rng) {
    Input in;
    const int n = int(rng.integer(1, 5));
    for (int i = 0; i < n; ++i) {
        SpringMass::Mass m;
        m.position = {rng.uniform(-1, 1), rng.uniform(-1, 1),
                      rng.chance(0.5) ? 0.0 : rng.uniform(-1, 1)};
        m.mass = rng.uniform(0.5, 2);
        m.pinned = rng.chance(0.2);
        if (!m.pinned && rng.chance(0.7))
            m.velocity = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        in.masses.push_back(m);
    }
    if (n >= 2) {
        const int springs = int(rng.integer(0, 2 * n));
        for (int k = 0; k < springs; ++k) {
            SpringMass::Spring s;
            s.i = int(rng.integer(0, n - 1));
            do s.j = int(rng.integer(0, n - 1));
            while (s.j == s.i);
            s.stiffness = rng.uniform(0, 40);
            s.damping = rng.chance(0.5) ? rng.uniform(0, 0.5) : 0;
            if (rng.chance(0.5)) {
                s.rest = rng.uniform(0, 1.5);
                s.has_rest = true;
            }
            in.springs.push_back(s);
        }
        // Sometimes two masses start on the same point (a coincident spring, no direction).
        if (rng.chance(0.05)) in.masses[1].position = in.masses[0].position;
    }
    in.gravity = rng.chance(0.5) ? glm::dvec3(0, -9.81, 0) : glm::dvec3(0);
    in.drag = rng.chance(0.3) ? rng.uniform(0, 0.3) : 0;
    in.dt = rng.uniform(0.001, 0.02);
    in.steps = int(rng.integer(1, 30));
    in.integrator = Integrator(rng.integer(0, 2));
    if (rng.chance(0.3)) in.watch = int(rng.integer(0, n - 1));
    return in;
}

std::string err(const std::string& text) {
    return cg::test::error_of("spring-mass", text);
}

bool all_finite(const cg::json& j) {
    if (j.is_number()) return std::isfinite(j.get<double>());
    if (j.is_array() || j.is_object())
        for (const auto& e : j)
            if (!all_finite(e)) return false;
    return true;
}

}  // namespace

TEST_CASE("spring-mass: one undamped spring against x(t) = L + A cos ωt",
          "[animation][spring-mass]") {
    const double k = 4, m = 1, L = 1, A = 0.5, w = std::sqrt(k / m);
    auto error_at = [&](Integrator integ, double dt, double T) {
        const int steps = int(std::lround(T / dt));
        const auto r = SpringMass::compute(oscillator(k, m, L, L + A, dt, steps, integ));
        const double t = steps * dt;
        return std::hypot(r.x.x - (L + A * std::cos(w * t)), r.v.x + A * w * std::sin(w * t));
    };
    SECTION("RK4: error O(dt⁴), halving dt cuts it about 16 times") {
        const double e1 = error_at(Integrator::RK4, 0.04, 4),
                     e2 = error_at(Integrator::RK4, 0.02, 4),
                     e3 = error_at(Integrator::RK4, 0.01, 4);
        CAPTURE(e1, e2, e3);
        CHECK(e1 < 1e-5);
        CHECK(e1 / e2 == Approx(16).epsilon(0.1));
        CHECK(e2 / e3 == Approx(16).epsilon(0.1));
    }
    SECTION("the Euler methods are first order: halving dt about halves the error") {
        for (Integrator integ : {Integrator::ExplicitEuler, Integrator::SymplecticEuler}) {
            const double e1 = error_at(integ, 0.002, 2), e2 = error_at(integ, 0.001, 2);
            CAPTURE(int(integ), e1, e2);
            CHECK(e1 / e2 == Approx(2).epsilon(0.1));
        }
    }
    SECTION("symplectic Euler: the energy error stays bounded over 10⁴ steps") {
        const double dt = 0.05;  // ω dt = 0.1
        const auto r =
            SpringMass::compute(oscillator(k, m, L, L + A, dt, 10000, Integrator::SymplecticEuler));
        const double E0 = r.energy.front();
        CHECK(E0 == Approx(0.5 * k * A * A));
        double first = 0, last = 0;
        for (std::size_t q = 0; q < r.energy.size(); ++q) {
            const double e = std::fabs(r.energy[q] - E0) / E0;
            (q < 1000 ? first : last) = std::max(q < 1000 ? first : last, e);
        }
        CAPTURE(first, last);
        CHECK(last < 0.06);          // about ω dt / 2
        CHECK(last < 1.05 * first);  // no growth after the first period
        CHECK(r.max_drift < 0.06);
        CHECK_FALSE(r.blew_up);
    }
    SECTION("explicit Euler: the energy grows by exactly 1 + ω²dt² every step") {
        const double dt = 0.05;
        const auto r =
            SpringMass::compute(oscillator(k, m, L, L + A, dt, 40, Integrator::ExplicitEuler));
        REQUIRE(r.energy.size() == 41);
        for (std::size_t q = 1; q < r.energy.size(); ++q) {
            CAPTURE(q);
            CHECK(r.energy[q] > r.energy[q - 1]);
            CHECK(r.energy[q] / r.energy[q - 1] == Approx(1 + w * w * dt * dt).epsilon(1e-12));
        }
    }
}

TEST_CASE("spring-mass: a damped spring against its closed form", "[animation][spring-mass]") {
    const double k = 4, m = 1, c = 0.4, L = 1, A = 0.5;
    const double w = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m)),
                 wd = w * std::sqrt(1 - zeta * zeta);
    const double dt = 0.001;
    const int steps = 3000;
    const auto r = SpringMass::compute(oscillator(k, m, L, L + A, dt, steps, Integrator::RK4, c));
    const double t = steps * dt;
    const double x =
        L + A * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
    CHECK(r.x.x == Approx(x).margin(1e-10));
    // The energy only ever falls.
    for (std::size_t q = 1; q < r.energy.size(); ++q) CHECK(r.energy[q] <= r.energy[q - 1] + 1e-15);
}

TEST_CASE("spring-mass: internal forces sum to zero and momentum is kept",
          "[animation][spring-mass]") {
    cg::Rng rng(5);
    for (int trial = 0; trial < 500; ++trial) {
        CAPTURE(trial);
        Input in = random_system(rng);
        in.gravity = {0, 0, 0};
        in.drag = 0;
        for (auto& m : in.masses) m.pinned = false;
        in.watch = -1;
        const Input res = SpringMass::resolve(in);
        std::vector<glm::dvec3> x, v, f;
        glm::dvec3 p0{0, 0, 0};
        for (const auto& m : res.masses)
            x.push_back(m.position), v.push_back(m.velocity), p0 += m.mass * m.velocity;
        SpringMass::forces(res, x, v, f);
        glm::dvec3 sum{0, 0, 0};
        double size = 0;
        for (const auto& fi : f) sum += fi, size += glm::length(fi);
        CHECK(glm::length(sum) <= 1e-12 * std::max(1.0, size));
        const auto r = SpringMass::compute(in);
        glm::dvec3 p1{0, 0, 0};
        for (std::size_t i = 0; i < res.masses.size(); ++i)
            p1 += res.masses[i].mass * r.velocities[i];
        CHECK(glm::length(p1 - p0) <= 1e-12 * std::max(1.0, glm::length(p0)) * r.steps);
    }
}

TEST_CASE("spring-mass: 3,000 random systems against a long-double implementation",
          "[animation][spring-mass]") {
    cg::Rng rng(2026);
    int coincident = 0, pinned = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Input in = random_system(rng);
        CAPTURE(trial, int(in.integrator), in.steps, in.masses.size(), in.springs.size());
        const Input res = SpringMass::resolve(in);
        Sys x, v;
        reference(res, x, v);
        const auto r = SpringMass::compute(in);
        REQUIRE_FALSE(r.blew_up);
        REQUIRE(r.steps == in.steps);
        for (std::size_t i = 0; i < x.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                const LD xr = c == 0 ? x[i].x : c == 1 ? x[i].y : x[i].z;
                const LD vr = c == 0 ? v[i].x : c == 1 ? v[i].y : v[i].z;
                CHECK(std::fabs(double(r.positions[i][c] - xr)) <=
                      1e-9 * std::max<double>(1, std::fabs(double(xr))));
                CHECK(std::fabs(double(r.velocities[i][c] - vr)) <=
                      1e-9 * std::max<double>(1, std::fabs(double(vr))));
            }
            pinned += res.masses[i].pinned;
        }
        if (in.masses.size() >= 2 && in.masses[0].position == in.masses[1].position) ++coincident;
    }
    CHECK(coincident > 20);
    CHECK(pinned > 300);
}

TEST_CASE("spring-mass: the state machine gives what compute gives, through the registry too",
          "[animation][spring-mass]") {
    cg::Rng rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        CAPTURE(trial);
        const Input in = random_system(rng);
        const auto traced = cg::test::run_traced<SpringMass>(in);
        CHECK(traced.result == SpringMass::compute(in));
        CHECK(cg::run_to_end<SpringMass>(SpringMass::start(in)) == SpringMass::compute(in));
        const auto ev = cg::test::events(traced);
        REQUIRE(ev.size() == std::size_t(in.steps) + 1);
        CHECK(ev.back() == "summary");
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const auto j = cg::test::result_of("spring-mass", p.input);
        CHECK(all_finite(j));
        CHECK(j["energy"].size() == j["steps"].get<std::size_t>() + 1);
        CHECK(j["dt"].get<double>() == p.input["dt"].get<double>());
    }
}

TEST_CASE("spring-mass: blow-up stops the run with a clear step and no NaN",
          "[animation][spring-mass]") {
    // k = 1000, m = 1: ω dt = 1.58 at dt = 0.05; explicit Euler multiplies E by 3.5 a step.
    const Input stiff = oscillator(1000, 1, 1, 1.5, 0.05, 100, Integrator::ExplicitEuler);
    const auto t = cg::test::run_traced<SpringMass>(stiff);
    CHECK(t.result.blew_up);
    CHECK(t.result.blow_up_step == t.result.steps + 1);
    CHECK(t.result.steps < 40);
    REQUIRE(t.steps.size() >= 2);
    CHECK(t.steps[t.steps.size() - 2].event == "blow-up");
    CHECK(t.steps[t.steps.size() - 2].narration.find("blew up") != std::string::npos);
    for (double e : t.result.energy) CHECK(std::isfinite(e));
    CHECK(t.result.energy.back() <= SpringMass::kBlowUp * t.result.energy_scale);
    // Symplectic Euler at the same dt stays bounded (ω dt < 2); beyond 2 it blows up too.
    Input sym = stiff;
    sym.integrator = Integrator::SymplecticEuler;
    const auto rs = SpringMass::compute(sym);
    CHECK_FALSE(rs.blew_up);
    CHECK(rs.max_drift < 5);
    sym.dt = 0.1;  // ω dt = 3.16
    sym.steps = 2000;
    CHECK(SpringMass::compute(sym).blew_up);
    // An overflow to infinity is caught as well: a tiny mass on a huge spring.
    Input over = oscillator(1e12, 1e-12, 1, 1e6, 1000, 50, Integrator::ExplicitEuler);
    const auto ro = cg::test::run_traced<SpringMass>(over);
    CHECK(ro.result.blew_up);
    CHECK(all_finite(cg::test::result_of("spring-mass", cg::json::parse(R"({
        "masses": [{"position": [0, 0], "pinned": true}, {"position": [1000000, 0], "mass": 1e-12}],
        "springs": [{"i": 0, "j": 1, "stiffness": 1e12, "rest_length": 1}],
        "gravity": [0, 0], "dt": 1000, "steps": 50, "integrator": "explicit-euler"})"))));
}

TEST_CASE("spring-mass: coincident ends exert no force and give no NaN",
          "[animation][spring-mass]") {
    Input in = oscillator(10, 1, 0.5, 0, 0.01, 50, Integrator::RK4);  // the mass on the anchor
    const auto r = SpringMass::compute(in);
    CHECK(r.x == glm::dvec3(0));
    CHECK(r.v == glm::dvec3(0));
    CHECK(r.energy.back() == Approx(0.5 * 10 * 0.25));
    // With a velocity it leaves the anchor, and the spring takes over.
    in.masses[1].velocity = {1, 0, 0};
    const auto r2 = SpringMass::compute(in);
    CHECK(std::isfinite(r2.x.x));
    CHECK(r2.x.x > 0);
}

TEST_CASE("spring-mass: bad input names the field and the reason", "[animation][spring-mass]") {
    const std::string one = R"("masses": [{"position": [0, 0]}, {"position": [1, 0]}])";
    CHECK(err(R"({})").find("masses: is missing") == 0);
    CHECK(err(R"({"masses": []})") == "masses: must have at least 1 mass (got none)");
    CHECK(err("{" + one + R"(, "springs": [{"i": 0, "j": 0, "stiffness": 1}]})")
              .find("springs[0].j: joins mass 0 to itself") == 0);
    CHECK(err("{" + one + R"(, "springs": [{"i": 0, "j": 2, "stiffness": 1}]})")
              .find("springs[0].j: must name a mass 0 to 1 (got 2)") == 0);
    CHECK(err("{" + one + R"(, "springs": [{"i": -1, "j": 1, "stiffness": 1}]})")
              .find("springs[0].i: must name a mass") == 0);
    CHECK(err(R"({"masses": [{"position": [0, 0], "mass": 0}]})")
              .find("masses[0].mass: must be > 0") == 0);
    CHECK(err(R"({"masses": [{"position": [0, 0], "mass": -2}]})")
              .find("masses[0].mass: must be > 0") == 0);
    CHECK(err("{" + one + R"(, "dt": 0})").find("dt: must be a time step > 0") == 0);
    CHECK(err("{" + one + R"(, "dt": -0.1})").find("dt: must be a time step > 0") == 0);
    CHECK(err("{" + one + R"(, "dt": NaN})").find("not valid JSON") != std::string::npos);
    CHECK(err("{" + one + R"(, "steps": 100001})").find("steps: must be 1 to 100000") == 0);
    CHECK(err("{" + one + R"(, "steps": 0})").find("steps: must be 1 to 100000") == 0);
    CHECK(err(R"({"cloth": {"rows": 32, "cols": 32}, "steps": 100000})")
              .find("steps: 100000 steps of 1024 masses") == 0);
    CHECK(err("{" + one + R"(, "springs": [{"i": 0, "j": 1, "stiffness": -1}]})")
              .find("springs[0].stiffness: must be ≥ 0") == 0);
    CHECK(err("{" + one + R"(, "springs": [{"i": 0, "j": 1, "stiffness": 1, "rest_length": -1}]})")
              .find("springs[0].rest_length: must be ≥ 0") == 0);
    CHECK(err("{" + one + R"(, "integrator": "verlet"})").find("integrator: must be") == 0);
    CHECK(err("{" + one + R"(, "watch": 2})").find("watch: must name a mass 0 to 1 (got 2)") == 0);
    CHECK(err(R"({"masses": [{"position": [0, 0, 0, 0]}]})")
              .find("masses[0].position: must be a point") == 0);
    CHECK(err(R"({"masses": [{"position": [1e7, 0]}]})").find("masses[0].position: is too large") ==
          0);
    CHECK(err(R"({"masses": [{"position": [0, 0], "pinned": true, "velocity": [1, 0]}]})")
              .find("masses[0].velocity: must be 0 for a pinned mass") == 0);
    CHECK(err(R"({"cloth": {"rows": 1, "cols": 4}})").find("cloth.rows: must be 2 to 32") == 0);
    CHECK(err(R"({"cloth": {"rows": 2, "cols": 2}, "masses": []})").find("cloth: give either") ==
          0);
    CHECK(err("{" + one + R"(, "drag": -1})").find("drag: must be ≥ 0") == 0);
    // Accepted: one mass without springs (it falls), every mass pinned (nothing moves).
    CHECK(err(R"({"masses": [{"position": [0, 0]}]})") == "(accepted)");
    const auto all_pinned = cg::test::result_of("spring-mass", cg::json::parse(R"({
        "masses": [{"position": [0, 0], "pinned": true}, {"position": [2, 0], "pinned": true}],
        "springs": [{"i": 0, "j": 1, "stiffness": 3, "rest_length": 1}], "steps": 10})"));
    CHECK(all_pinned["max_drift"].get<double>() == 0);
    CHECK(all_pinned["total"].get<double>() == Approx(1.5));
    CHECK(all_pinned["positions"][1][0].get<double>() == 2);
}

TEST_CASE("spring-mass: replay on the example and the presets", "[animation][spring-mass]") {
    const auto& a = cg::test::algorithm("spring-mass");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
}

TEST_CASE("spring-mass: the first step narrates the force term by term",
          "[animation][spring-mass]") {
    Input in = oscillator(10, 2, 1, 1.5, 0.1, 3, Integrator::ExplicitEuler, 1);
    in.masses[1].velocity = {0.5, 0, 0};
    const auto t = cg::test::run_traced<SpringMass>(in);
    const std::string& n = t.steps[0].narration;
    CAPTURE(n);
    // F = −10 (1.5 − 1) − 1 (0.5) = −5.5; a = −2.75; x = 1.5 + 0.05 = 1.55; v = 0.5 − 0.275.
    CHECK(n.find("Hooke −k (|d| − L) d̂ = −10 · (1.5 − 1) · (1, 0, 0) = (−5, 0, 0)") !=
          std::string::npos);
    CHECK(n.find("Total F = (−5.5, 0, 0)") != std::string::npos);
    CHECK(n.find("= (1.55, 0, 0)") != std::string::npos);
    CHECK(n.find("= (0.225, 0, 0)") != std::string::npos);
    in.integrator = Integrator::RK4;
    const auto r = cg::test::run_traced<SpringMass>(in);
    CHECK(r.steps[0].narration.find("k4 = (") != std::string::npos);
    // Variables: t, the energies and the watched mass.
    const auto& vars = t.steps[0].vars;
    std::vector<std::string> names;
    for (const auto& v : vars) names.push_back(v.name);
    CHECK(names == std::vector<std::string>{"t", "k", "dt", "x", "v", "F", "E_kin", "E_spring",
                                            "E_grav", "E_total"});
}

TEST_CASE("spring-mass: exam problems are one explicit Euler step, answered by hand",
          "[animation][spring-mass][exam]") {
    const auto& a = cg::test::algorithm("spring-mass");
    int hanging = 0, damped = 0, rest = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<SpringMass>("spring-mass", p.input);
        REQUIRE(in.steps == 1);
        REQUIRE(in.integrator == Integrator::ExplicitEuler);
        const auto& m = in.masses[1];
        const auto& s = in.springs[0];
        // By hand, in long double.
        const V x = from(m.position), v = from(m.velocity);
        const LD len = std::sqrt(dot(x, x));
        const V u = (1 / len) * x;
        const V F = (-LD(s.stiffness) * (len - LD(s.rest))) * u + (-LD(s.damping) * dot(v, u)) * u +
                    LD(m.mass) * from(in.gravity);
        const V x1 = x + LD(in.dt) * v, v1 = v + (LD(in.dt) / LD(m.mass)) * F;
        const auto gx = p.expected["x"].get<std::vector<double>>();
        const auto gv = p.expected["v"].get<std::vector<double>>();
        CHECK(gx[0] == Approx(double(x1.x)).margin(1e-12));
        CHECK(gx[1] == Approx(double(x1.y)).margin(1e-12));
        CHECK(gv[0] == Approx(double(v1.x)).margin(1e-12));
        CHECK(gv[1] == Approx(double(v1.y)).margin(1e-12));
        CHECK(p.answers == std::vector<std::string>{"x", "v"});
        hanging += in.gravity.y != 0;
        damped += s.damping != 0;
        rest += m.velocity == glm::dvec3(0) && len == s.rest;
    }
    CHECK(hanging > 40);
    CHECK(damped > 100);
    CHECK(rest > 10);
}

TEST_CASE("spring-mass: the picture, masses and springs in 3D, the energy in a chart",
          "[animation][spring-mass]") {
    const auto& cloth = lesson().presets[5];
    REQUIRE(cloth.name.find("cloth") != std::string::npos);
    const Input in = cg::test::input_of<SpringMass>("spring-mass", cloth.input);
    auto s = SpringMass::start(in);
    for (int k = 0; k < 20; ++k) SpringMass::step(s, nullptr);
    cg::Scene scene;
    SpringMass::draw(s, scene);
    CHECK(scene.points3.size() == 64);
    CHECK(scene.segments3.size() >= in.springs.size() + 3);  // springs, the path, the forces
    // The energy against time: a chart in J and s, with E_0, its range at least E_0 ± E_scale.
    CHECK_FALSE(scene.has_2d());  // nothing on the world's grid
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& energy = scene.panels[0];
    CHECK(energy.kind == cg::PanelKind::Chart);
    CHECK(energy.x.label == "t (s)");
    CHECK(energy.y.label == "E (J)");
    CHECK(energy.y.lo <= s.history.front() - s.energy_scale);
    CHECK(energy.y.hi >= s.history.front() + s.energy_scale);
    REQUIRE(energy.legend.size() == 2);  // E_0 and E(t)
    CHECK(energy.polygons.back().points.size() == s.history.size());
    // The camera frames the masses as they are now.
    REQUIRE(scene.focus3.size() == 1);
    for (const glm::dvec3& x : s.x) {
        CHECK(glm::all(glm::lessThanEqual(scene.focus3[0].lo, x)));
        CHECK(glm::all(glm::lessThanEqual(x, scene.focus3[0].hi)));
    }
    int arrows = 0;
    for (const auto& seg : scene.segments3) arrows += seg.arrow;
    CHECK(arrows >= 3);  // gravity, two springs at the corner and more, the total
    // A stretched spring is drawn reddish, one at rest grey.
    const Input one = oscillator(10, 1, 1, 1.5, 0.01, 1, Integrator::RK4);
    cg::Scene s1;
    SpringMass::draw(SpringMass::start(one), s1);
    REQUIRE(!s1.segments3.empty());
    CHECK(s1.view3.orthographic);  // in the plane z = 0: seen face-on
    CHECK(!scene.view3.orthographic);  // the cloth falls in 3D
    CHECK((s1.segments3[0].style.rgba >> 24) > ((s1.segments3[0].style.rgba >> 8) & 0xFF));
}
