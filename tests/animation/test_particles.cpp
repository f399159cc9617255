// Particle systems: the count emitted by t equals ⌊rate·t⌋ on 4,000 seeded random (rate, dt,
// frames) against a long-double reference, and exactly on decimal rates and steps (10 per second
// at dt = 0.1 is one a frame); under gravity alone every particle (given and emitted) equals the
// discrete semi-implicit Euler sum x0 + n dt v0 + dt² g n(n+1)/2 in long double, which differs
// from the parabola x0 + v0 t + ½ g t² by exactly ½ g dt t; drag alone gives (1 − c dt)ⁿ v0 and
// converges to e^{−ct} at first order; on 2,000 random systems with a tilted plane no particle is
// ever below it after a frame and the focus particle's bounces never speed it up; the bounce on
// 100,000 random velocities never gains energy; 3,000 random systems (rate 0, lifetime 0,
// emitters on the plane) keep alive = given + emitted − killed and equal compute; same seed
// gives the same trace byte for byte; bad input names the field; exam problems by hand.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <set>

#include "animation/particles.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Particles;
using Input = Particles::Input;
using LD = long double;

namespace {

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("particles");
    if (!l) throw std::runtime_error("no lesson for particles");
    return *l;
}

std::string err(const std::string& text) {
    return cg::test::error_of("particles", text);
}

// ⌊rate · dt · k⌋ in long double, and whether that is trustworthy (the product not within
// 1e-12 of an integer, where the 64-bit rounding could fall on the wrong side).
long long floor_ld(double rate, double dt, int k, bool& sure) {
    const LD p = LD(rate) * LD(dt) * LD(k);
    const LD f = std::floor(p);
    sure = p - f > 1e-12L && f + 1 - p > 1e-12L;
    return (long long)f;
}

Input random_system(cg::Rng& rng) {
    Input in;
    Particles::Emitter& e = in.emitter;
    e.shape = Particles::Shape(rng.integer(0, 2));
    e.position = {rng.uniform(-1, 1), rng.uniform(0, 2), rng.uniform(-1, 1)};
    e.end = e.position + glm::dvec3(rng.uniform(-1, 1), rng.uniform(0, 1), rng.uniform(-1, 1));
    e.radius = rng.uniform(0, 0.5);
    e.velocity = {rng.uniform(-3, 3), rng.uniform(-3, 6), rng.uniform(-3, 3)};
    e.spread = rng.chance(0.2) ? 0 : rng.uniform(0, 180);
    e.jitter = rng.chance(0.5) ? 0 : rng.uniform(0, 1);
    e.life_min = rng.chance(0.1) ? 0 : rng.uniform(0, 1.5);
    e.life_max = rng.chance(0.3) ? e.life_min : e.life_min + rng.uniform(0, 1);
    e.rate = rng.chance(0.1)   ? 0
             : rng.chance(0.3) ? double(rng.integer(1, 60))
                               : rng.uniform(0, 60);
    const int starts = rng.chance(0.5) ? 0 : int(rng.integer(1, 4));
    for (int i = 0; i < starts; ++i) {
        Particles::Start s;
        s.position = {rng.uniform(-1, 1), rng.uniform(0, 2), rng.uniform(-1, 1)};
        s.velocity = {rng.uniform(-2, 2), rng.uniform(-2, 4), rng.uniform(-2, 2)};
        if (rng.chance(0.5)) s.lifetime = rng.uniform(0.01, 2);
        in.start.push_back(s);
    }
    in.gravity = rng.chance(0.8) ? glm::dvec3(0, -9.81, 0)
                                 : glm::dvec3(rng.uniform(-5, 5), rng.uniform(-10, 0), 0);
    const double dts[] = {0.1, 0.05, 0.02, 0.04, 0.025};
    in.dt = rng.chance(0.5) ? dts[rng.integer(0, 4)] : rng.uniform(0.005, 0.1);
    in.drag = rng.chance(0.5) ? 0 : rng.uniform(0, std::min(3.0, 1 / in.dt));
    if (rng.chance(0.7)) {
        in.plane.on = true;
        in.plane.normal = rng.chance(0.5)
                              ? glm::dvec3(0, 1, 0)
                              : glm::dvec3(rng.uniform(-0.5, 0.5), 1, rng.uniform(-0.5, 0.5));
        in.plane.restitution = rng.chance(0.2) ? double(rng.integer(0, 1)) : rng.uniform(0, 1);
        in.plane.friction = rng.chance(0.3) ? 0 : rng.uniform(0, 1);
        const glm::dvec3 n = glm::normalize(in.plane.normal);
        // The plane through the emitter's lowest point or a little under it (sometimes exactly
        // on it: particles emitted on the plane).
        double low = glm::dot(n, e.position);
        if (e.shape == Particles::Shape::Line) low = std::min(low, glm::dot(n, e.end));
        if (e.shape == Particles::Shape::Disc) low -= e.radius;
        for (const auto& s : in.start) low = std::min(low, glm::dot(n, s.position));
        if (rng.chance(0.3) && e.shape == Particles::Shape::Point && in.start.empty())
            in.plane.point = e.position;  // exactly on the plane
        else
            in.plane.point = (low - rng.uniform(0, 0.5)) * n;
    }
    in.frames = int(rng.integer(1, 60));
    in.seed = rng.next() >> 12;
    in.focus = int(rng.integer(0, 6));
    return in;
}

}  // namespace

TEST_CASE("particles: N(t) = ⌊rate · t⌋ exactly, with the fraction carried",
          "[animation][particles]") {
    SECTION("decimal rates and steps: 10 a second at dt = 0.1 is one a frame") {
        const struct {
            double rate, dt;
            long long num, den;  // N(k dt) = ⌊k num / den⌋ for the decimal values
        } cases[] = {{10, 0.1, 1, 1},  {20, 0.05, 1, 1}, {5, 0.1, 1, 2},    {30, 0.02, 3, 5},
                     {2.5, 0.1, 1, 4}, {50, 0.02, 1, 1}, {100, 0.01, 1, 1}, {7, 0.1, 7, 10}};
        for (const auto& c : cases) {
            CAPTURE(c.rate, c.dt);
            for (int k = 0; k <= 5000; ++k) {
                CAPTURE(k);
                REQUIRE(Particles::emitted_by(c.rate, c.dt, k) == k * c.num / c.den);
            }
        }
    }
    SECTION("the carried fraction rate · t − N: 2.5 a second at dt = 0.1") {
        CHECK(Particles::carry(2.5, 0.1, 3) == Approx(0.75).epsilon(1e-12));
        CHECK(Particles::carry(2.5, 0.1, 4) == 0);  // 1.0000000000000000555: shown as 0
        CHECK(Particles::carry(2.5, 0.1, 5) == Approx(0.25).epsilon(1e-12));
        CHECK(Particles::carry(0, 0.1, 5) == 0);
        cg::Rng rng(3);
        for (int trial = 0; trial < 1000; ++trial) {
            const double rate = rng.uniform(0, 100), dt = rng.uniform(0.001, 0.1);
            const int k = int(rng.integer(1, 10000));
            const LD exact = LD(rate) * LD(dt) * LD(k) - LD(Particles::emitted_by(rate, dt, k));
            CAPTURE(rate, dt, k);
            CHECK(std::fabs(double(exact) - Particles::carry(rate, dt, k)) <= 1e-9);
        }
    }
    SECTION("4,000 random rates, steps and frame counts against long double") {
        cg::Rng rng(41);
        int sure = 0, unsure = 0;
        for (int trial = 0; trial < 4000; ++trial) {
            const double rate = rng.chance(0.3) ? double(rng.integer(0, 200)) : rng.uniform(0, 200);
            const double dt =
                rng.chance(0.3) ? 1.0 / double(rng.integer(10, 120)) : rng.uniform(0.001, 0.2);
            const int k = int(rng.integer(0, 100000));
            CAPTURE(trial, rate, dt, k);
            bool ok = false;
            const long long ref = floor_ld(rate, dt, k, ok);
            if (!ok) {
                ++unsure;
                CHECK(std::llabs(Particles::emitted_by(rate, dt, k) - ref) <= 1);
                continue;
            }
            ++sure;
            CHECK(Particles::emitted_by(rate, dt, k) == ref);
        }
        CHECK(sure > 3000);
    }
    SECTION("through a run: the per-frame counts add up to ⌊rate · t⌋ at every frame") {
        cg::Rng rng(7);
        for (int trial = 0; trial < 300; ++trial) {
            Input in;
            in.emitter.rate = rng.chance(0.5) ? double(rng.integer(0, 100)) : rng.uniform(0, 100);
            in.emitter.life_min = in.emitter.life_max = rng.uniform(0, 0.3);
            in.dt = rng.uniform(0.005, 0.1);
            in.frames = int(rng.integer(1, 200));
            in.seed = std::uint64_t(trial);
            CAPTURE(trial, in.emitter.rate, in.dt);
            const auto r = Particles::compute(in);
            long long sum = 0;
            for (int k = 1; k <= in.frames; ++k) {
                sum += r.emitted_per_frame[std::size_t(k - 1)];
                bool ok = false;
                const long long ref = floor_ld(in.emitter.rate, in.dt, k, ok);
                if (ok) CHECK(sum == ref);
            }
            CHECK(sum == r.emitted);
        }
    }
}

TEST_CASE("particles: under gravity alone, the discrete Euler sum and the parabola",
          "[animation][particles]") {
    cg::Rng rng(2026);
    int checked = 0;
    for (int trial = 0; trial < 500; ++trial) {
        Input in;
        in.emitter.position = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
        in.emitter.velocity = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
        in.emitter.spread = 0;  // every emitted particle starts with v̄ exactly
        in.emitter.rate = rng.uniform(0, 30);
        in.emitter.life_min = in.emitter.life_max = 100;
        for (int i = 0, n = int(rng.integer(0, 3)); i < n; ++i) {
            Particles::Start s;
            s.position = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
            s.velocity = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
            in.start.push_back(s);
        }
        in.gravity = {rng.uniform(-3, 3), rng.uniform(-12, 0), rng.uniform(-3, 3)};
        in.dt = rng.uniform(0.001, 0.05);
        in.frames = int(rng.integer(1, 150));
        CAPTURE(trial, in.dt, in.frames);
        const auto r = Particles::compute(in);
        // The frame each emitted particle was born in, from the counts.
        std::vector<int> born;
        for (int k = 1; k <= in.frames; ++k)
            for (int q = 0; q < r.emitted_per_frame[std::size_t(k - 1)]; ++q) born.push_back(k);
        REQUIRE(r.alive == int(in.start.size() + born.size()));
        const int m = int(in.start.size());
        for (std::size_t i = 0; i < r.ids.size(); ++i) {
            const int id = r.ids[i];
            const bool given = id < m;
            const glm::dvec3 x0 = given ? in.start[std::size_t(id)].position : in.emitter.position;
            const glm::dvec3 v0 = given ? in.start[std::size_t(id)].velocity : in.emitter.velocity;
            const int b = given ? 0 : born[std::size_t(id - m)];
            const LD n = LD(in.frames - b), dt = in.dt, t = n * dt;
            for (int c = 0; c < 3; ++c) {
                const LD g = in.gravity[c];
                // v_n = v0 + n dt g;  x_n = x0 + dt Σ_{i=1..n} v_i = x0 + n dt v0 + dt² g n(n+1)/2
                const LD vn = LD(v0[c]) + n * dt * g;
                const LD xn = LD(x0[c]) + n * dt * LD(v0[c]) + dt * dt * g * n * (n + 1) / 2;
                const LD parabola = LD(x0[c]) + LD(v0[c]) * t + g * t * t / 2;
                CHECK(std::fabs(double(r.velocities[i][c] - vn)) <= 1e-11);
                CHECK(std::fabs(double(r.positions[i][c] - xn)) <= 1e-11);
                // The integrator's known error: exactly ½ g dt t, first order in dt.
                CHECK(std::fabs(double(xn - parabola - g * dt * t / 2)) <= 1e-12);
                CHECK(std::fabs(double(r.positions[i][c] - parabola)) <=
                      std::fabs(double(g * dt * t / 2)) + 1e-11);
            }
            CHECK(r.ages[i] == Approx(double(n * dt)).margin(1e-12));
            ++checked;
        }
    }
    CHECK(checked > 3000);
}

TEST_CASE("particles: drag alone decays the velocity as (1 − c dt)ⁿ → e^{−ct}",
          "[animation][particles]") {
    auto run = [](double c, double dt, int frames) {
        Input in;
        in.emitter.rate = 0;
        in.start = {{{0, 0, 0}, {3, -2, 1}, Particles::kForever}};
        in.gravity = {0, 0, 0};
        in.drag = c;
        in.dt = dt;
        in.frames = frames;
        return Particles::compute(in);
    };
    const glm::dvec3 v0{3, -2, 1};
    for (double c : {0.5, 2.0, 10.0}) {
        for (double dt : {0.01, 0.05}) {
            const int frames = int(std::lround(1 / dt));
            const auto r = run(c, dt, frames);
            const LD f = 1 - LD(c) * LD(dt);
            LD sum = 0;  // Σ_{i=1..n} f^i
            for (int i = 1; i <= frames; ++i) sum += std::pow(f, LD(i));
            for (int q = 0; q < 3; ++q) {
                CAPTURE(c, dt, q);
                CHECK(r.v[q] == Approx(double(std::pow(f, LD(frames)) * LD(v0[q]))).epsilon(1e-12));
                CHECK(r.x[q] == Approx(double(LD(dt) * LD(v0[q]) * sum)).epsilon(1e-12));
            }
        }
        // First order: halving dt halves the gap to e^{−ct} at t = 1 (the exact position is
        // v0 (1 − e^{−ct}) / c).
        const double e1 = std::fabs(run(c, 0.01, 100).v.x - 3 * std::exp(-c));
        const double e2 = std::fabs(run(c, 0.005, 200).v.x - 3 * std::exp(-c));
        const double p2 = std::fabs(run(c, 0.005, 200).x.x - 3 * (1 - std::exp(-c)) / c);
        CAPTURE(c, e1, e2, p2);
        CHECK(e1 / e2 == Approx(2).epsilon(0.1));
        CHECK(p2 < 0.05 * 3 / c);
    }
    // c dt = 1 stops a particle in one frame; more is refused.
    CHECK(run(10, 0.1, 3).v == glm::dvec3(0));
    CHECK(err(R"({"start": [{"position": [0, 0], "velocity": [1, 0]}], "drag": 11, "dt": 0.1})")
              .find("drag: times dt must be at most 1") == 0);
}

TEST_CASE("particles: a bounce never gains energy and never leaves a particle below",
          "[animation][particles]") {
    cg::Rng rng(99);
    for (int trial = 0; trial < 100000; ++trial) {
        Particles::Plane p;
        p.on = true;
        p.normal =
            glm::normalize(glm::dvec3(rng.uniform(-1, 1), rng.uniform(0.1, 1), rng.uniform(-1, 1)));
        p.point = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
        p.h = glm::dot(p.normal, p.point);
        p.restitution = rng.chance(0.2) ? double(rng.integer(0, 1)) : rng.uniform(0, 1);
        p.friction = rng.chance(0.2) ? double(rng.integer(0, 1)) : rng.uniform(0, 1);
        glm::dvec3 v{rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
        if (glm::dot(v, p.normal) > 0) v = -v;
        // A point a little below the plane.
        glm::dvec3 x = p.point + glm::dvec3(rng.uniform(-3, 3), 0, rng.uniform(-3, 3));
        x -= (glm::dot(p.normal, x) - p.h + rng.uniform(0, 0.3)) * p.normal;
        const double d = Particles::distance(p, x);
        if (!(d < 0)) continue;
        const glm::dvec3 v_before = v;
        Particles::bounce(p, d, x, v);
        CAPTURE(trial);
        CHECK(Particles::distance(p, x) >= 0);
        const LD dl =
            LD(p.normal.x) * x.x + LD(p.normal.y) * x.y + LD(p.normal.z) * x.z -
            (LD(p.normal.x) * p.point.x + LD(p.normal.y) * p.point.y + LD(p.normal.z) * p.point.z);
        CHECK(dl >= -1e-13L);
        // Kinetic energy ½|v|² never grows; the normal speed is −e times the old one.
        CHECK(glm::dot(v, v) <= glm::dot(v_before, v_before) * (1 + 1e-12));
        CHECK(glm::dot(v, p.normal) ==
              Approx(-p.restitution * glm::dot(v_before, p.normal)).margin(1e-9));
    }
    // e = 1, μ = 0: elastic, the speed is kept; e = 0, μ = 1: stopped dead.
    Particles::Plane ground;
    ground.on = true;
    ground.restitution = 1;
    glm::dvec3 x{0, -0.1, 0}, v{2, -3, 0};
    Particles::bounce(ground, -0.1, x, v);
    CHECK(v == glm::dvec3(2, 3, 0));
    CHECK(x.y == Approx(0.1));
    ground.restitution = 0;
    ground.friction = 1;
    x = {0, -0.1, 0}, v = {2, -3, 0};
    Particles::bounce(ground, -0.1, x, v);
    CHECK(v == glm::dvec3(0, 0, 0));
    CHECK(x.y == 0);
}

TEST_CASE("particles: 2,000 random systems with a plane — never below it after a frame",
          "[animation][particles]") {
    cg::Rng rng(5);
    long long bounces = 0, on_plane = 0, focus_bounces = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        Input in = random_system(rng);
        if (!in.plane.on) continue;
        CAPTURE(trial);
        auto s = Particles::start(in);
        const auto& pl = s.in->plane;
        on_plane += pl.point == in.emitter.position;
        while (!Particles::done(s)) {
            Particles::step(s, nullptr);
            for (const auto& p : s.alive) {
                REQUIRE(Particles::distance(pl, p.x) >= 0);
                const LD dl = LD(pl.normal.x) * p.x.x + LD(pl.normal.y) * p.x.y +
                              LD(pl.normal.z) * p.x.z - LD(pl.h);
                REQUIRE(dl >= -1e-12L);
            }
            const auto& f = s.focus;
            if (f.fate == Particles::Fate::Moved && f.hit) {
                ++focus_bounces;
                CHECK(glm::dot(f.v, f.v) <= glm::dot(f.v1, f.v1) * (1 + 1e-12));
            }
        }
        bounces += s.bounces;
    }
    CHECK(bounces > 10000);
    CHECK(focus_bounces > 100);
    CHECK(on_plane > 50);
}

TEST_CASE("particles: 3,000 random systems keep their counts and equal compute",
          "[animation][particles]") {
    cg::Rng rng(17);
    int zero_rate = 0, zero_life = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Input in = random_system(rng);
        CAPTURE(trial);
        const auto plain = Particles::compute(in);
        const auto machine = cg::run_to_end<Particles>(Particles::start(in));
        REQUIRE(machine == plain);
        long long emitted = 0, killed = 0;
        for (int k = 0; k < plain.frames; ++k) {
            emitted += plain.emitted_per_frame[std::size_t(k)];
            killed += plain.killed_per_frame[std::size_t(k)];
            CHECK(plain.alive_per_frame[std::size_t(k)] == int(in.start.size()) + emitted - killed);
        }
        CHECK(emitted == plain.emitted);
        CHECK(killed == plain.killed);
        CHECK(plain.alive == int(in.start.size() + emitted - killed));
        CHECK(plain.ids.size() == std::size_t(plain.alive));
        CHECK(std::is_sorted(plain.ids.begin(), plain.ids.end()));
        for (std::size_t i = 0; i < plain.ids.size(); ++i) {
            const int id = plain.ids[i];
            // Alive means younger than its lifetime.
            const double L = id < int(in.start.size()) ? in.start[std::size_t(id)].lifetime
                                                       : in.emitter.life_max;
            CHECK(plain.ages[i] < L + 1e-9);
        }
        if (in.emitter.rate == 0) {
            ++zero_rate;
            CHECK(plain.emitted == 0);
        }
        if (in.emitter.life_max == 0) {  // lifetime 0: born and killed in the same frame
            ++zero_life;
            for (int id : plain.ids) CHECK(id < int(in.start.size()));
        }
    }
    CHECK(zero_rate > 100);
    CHECK(zero_life > 50);
}

TEST_CASE("particles: the same seed gives the same trace, byte for byte, with replay and copies",
          "[animation][particles]") {
    const auto& a = cg::test::algorithm("particles");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 17);
        const auto j = cg::test::result_of("particles", p.input);
        CHECK(j == cg::test::result_of("particles", p.input));
        CHECK(j["frames"].get<int>() == p.input["frames"].get<int>());
    }
    // Another seed, other particles; the counts stay the same (they depend on the rate only).
    cg::json in = a.example();
    const auto r1 = cg::test::result_of("particles", in);
    in["seed"] = 8;
    const auto r2 = cg::test::result_of("particles", in);
    CHECK(r1["positions"] != r2["positions"]);
    CHECK(r1["emitted_per_frame"] == r2["emitted_per_frame"]);
    // The state machine equals the plain function through the registry on every preset.
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        CHECK(a.plain(p.input) == cg::test::result_of("particles", p.input));
    }
}

TEST_CASE("particles: bad input names the field and the reason", "[animation][particles]") {
    const std::string one = R"("start": [{"position": [0, 1]}])";
    CHECK(err("{" + one + R"(, "dt": 0})").find("dt: must be a time step > 0") == 0);
    CHECK(err("{" + one + R"(, "dt": -0.1})").find("dt: must be a time step > 0") == 0);
    CHECK(err("{" + one + R"(, "dt": 1e-9})").find("dt: must be from 1e-6") == 0);
    CHECK(err("{" + one + R"(, "frames": 0})").find("frames: must be 1 to 100000") == 0);
    CHECK(err(R"({"emitter": {"rate": -1}})").find("emitter.rate: must be 0 to 1e6") == 0);
    CHECK(err(R"({"emitter": {"rate": 1000000}, "frames": 1000})")
              .find("emitter.rate: 1000000 per second") == 0);
    CHECK(
        err(R"({"emitter": {"lifetime": [2, 1]}})").find("emitter.lifetime: must be [min, max]") ==
        0);
    CHECK(err(R"({"emitter": {"lifetime": -1}})").find("emitter.lifetime: must be 0 to 1e6") == 0);
    CHECK(err(R"({"emitter": {"spread": 200}})").find("emitter.spread: must be an angle") == 0);
    CHECK(err(R"({"emitter": {"shape": "cube"}})").find("emitter.shape: must be \"point\"") == 0);
    CHECK(err(R"({"emitter": {"shape": "line"}})").find("emitter.end: is missing") == 0);
    CHECK(err(R"({"emitter": {"jitter": 2}})").find("emitter.jitter: must be 0 to 1") == 0);
    CHECK(err(R"({"emitter": {"position": [0, -1]}, "plane": {}})")
              .find("emitter.position: is below the plane") == 0);
    CHECK(err(R"({"start": [{"position": [0, -1]}], "plane": {}})")
              .find("start[0].position: is below the plane") == 0);
    CHECK(err(R"({"plane": {"normal": [0, 0, 0]}})").find("plane.normal: must not be zero") == 0);
    CHECK(err(R"({"plane": {"restitution": 1.5}})").find("plane.restitution: must be 0 to 1") == 0);
    CHECK(err(R"({"plane": {"friction": -0.5}})").find("plane.friction: must be 0 to 1") == 0);
    CHECK(err(R"({"start": [{"position": [0, 1], "lifetime": 0}]})")
              .find("start[0].lifetime: must be > 0") == 0);
    CHECK(err(R"({"start": [{"position": [1e7, 1]}]})").find("start[0].position: is too large") ==
          0);
    CHECK(err(R"({"start": [{"position": [0, 1, 2, 3]}]})")
              .find("start[0].position: must be a point") == 0);
    CHECK(err(R"({"seed": -1})").find("seed: must be an integer ≥ 0") == 0);
    CHECK(err(R"({"seed": 0.5})").find("seed: must be") == 0);
    CHECK(err(R"({"gravity": "down"})").find("gravity: must be a point") == 0);
    CHECK(err(R"({"wind": [1, 0]})").find("wind") != std::string::npos);
    CHECK(err(R"({"emitter": {"rate": 10000, "lifetime": 1000}, "frames": 100000, "dt": 0.0001})")
              .find("frames: 100000 frames with up to") == 0);
    // Accepted: no emitter and nothing given (an empty run), rate 0, lifetime 0.
    CHECK(err(R"({})") == "(accepted)");
    const auto empty = cg::test::result_of("particles", std::string(R"({"frames": 5})"));
    CHECK(empty["alive"] == 0);
    CHECK(empty["focus_born"] == false);
    const auto flash = cg::test::result_of(
        "particles",
        std::string(R"({"emitter": {"rate": 10, "lifetime": 0}, "dt": 0.1, "frames": 10})"));
    CHECK(flash["emitted"] == 10);
    CHECK(flash["killed"] == 10);
    CHECK(flash["alive"] == 0);
}

TEST_CASE("particles: the focus particle's frame, narrated with its numbers",
          "[animation][particles]") {
    // a = (0, −10) − 0.5 (2, 4) = (−1, −12); v = (2, 4) + 0.1 a = (1.9, 2.8);
    // x = (0, 1) + 0.1 v = (0.19, 1.28).
    const auto t = cg::test::run_json("particles", lesson().presets[0].input);
    const std::string& n = t.steps[0].narration;
    CAPTURE(n);
    CHECK(t.steps[0].event == "frame");
    CHECK(n.find("a = g − c v = (0, −10, 0) − 0.5 · (2, 4, 0) = (−1, −12, 0)") !=
          std::string::npos);
    CHECK(n.find("= (1.9, 2.8, 0)") != std::string::npos);
    CHECK(n.find("= (0.19, 1.28, 0)") != std::string::npos);
    std::vector<std::string> names;
    for (const auto& v : t.steps[0].vars) names.push_back(v.name);
    CHECK(names == std::vector<std::string>{"t", "k", "dt", "N", "carry", "emitted", "killed",
                                            "alive", "x", "v", "a"});
    // A bounce: from (0, 0.1) at (1, −3), no gravity: x1 = (0.1, −0.2), d = −0.2,
    // x = (0.1, −0.2 + 1.5 · 0.2) = (0.1, 0.1), v = −0.5 (0, −3) + 0.8 (1, 0) = (0.8, 1.5).
    const auto b = cg::test::run_json("particles", std::string(R"({
        "start": [{"position": [0, 0.1], "velocity": [1, -3]}], "gravity": [0, 0],
        "plane": {"restitution": 0.5, "friction": 0.2}, "dt": 0.1, "frames": 2})"));
    const std::string& nb = b.steps[0].narration;
    CAPTURE(nb);
    CHECK(b.steps[0].event == "bounce");
    CHECK(nb.find("d = n·x − h = −0.2") != std::string::npos);
    CHECK(nb.find("x ← x − (1 + e) d n = (0.1, 0.1, 0)") != std::string::npos);
    CHECK(nb.find("= (0.8, 1.5, 0)") != std::string::npos);
    CHECK(b.steps[1].event == "frame");
    CHECK(b.steps.back().event == "summary");
    // The emission count in the narration: 2.5 a second at dt = 0.1, frame 3: ⌊0.75⌋ = 0.
    const auto slow = cg::test::run_json("particles", lesson().presets[5].input);
    CHECK(slow.steps[3].narration.find("⌊2.5 · 0.4⌋ = 1, so 1 emitted") != std::string::npos);
    CHECK(slow.steps[0].narration.find("not born yet") != std::string::npos);
}

TEST_CASE("particles: exam problems, worked by hand", "[animation][particles][exam]") {
    const auto& a = cg::test::algorithm("particles");
    int euler = 0, bounce = 0, count = 0, died = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<Particles>("particles", p.input);
        if (in.start.empty()) {
            ++count;
            REQUIRE(p.answers == std::vector<std::string>{"emitted", "alive"});
            // Exact in binary: times are multiples of 0.25. Born at the end of frames j with
            // N(j dt) growing; alive at t if t − t_birth < L.
            const LD t = LD(in.frames) * LD(in.dt), L = in.emitter.life_min;
            const long long N = (long long)std::floor(LD(in.emitter.rate) * t);
            const long long old = t >= L ? (long long)std::floor(LD(in.emitter.rate) * (t - L)) : 0;
            CHECK(p.expected["emitted"].get<long long>() == N);
            CHECK(p.expected["alive"].get<long long>() == N - old);
            died += old > 0;
        } else if (in.plane.on) {
            ++bounce;
            REQUIRE(p.answers == std::vector<std::string>{"v"});
            const glm::dvec3 v = in.start[0].velocity;
            const double e = in.plane.restitution, mu = in.plane.friction;
            const auto gv = p.expected["v"].get<std::vector<double>>();
            CHECK(gv[0] == Approx((1 - mu) * v.x).margin(1e-12));
            CHECK(gv[1] == Approx(-e * v.y).margin(1e-12));
        } else {
            ++euler;
            REQUIRE(p.answers == std::vector<std::string>{"x", "v"});
            const auto& s = in.start[0];
            const LD c = in.drag, dt = in.dt;
            const auto gx = p.expected["x"].get<std::vector<double>>();
            const auto gv = p.expected["v"].get<std::vector<double>>();
            for (int q = 0; q < 2; ++q) {
                const LD a_q = LD(in.gravity[q]) - c * LD(s.velocity[q]);
                const LD v1 = LD(s.velocity[q]) + dt * a_q, x1 = LD(s.position[q]) + dt * v1;
                CHECK(gx[std::size_t(q)] == Approx(double(x1)).margin(1e-12));
                CHECK(gv[std::size_t(q)] == Approx(double(v1)).margin(1e-12));
            }
        }
    }
    CHECK(euler > 80);
    CHECK(bounce > 60);
    CHECK(count > 60);
    CHECK(died > 20);
}

TEST_CASE("particles: the picture — plane, emitter, particles by age, the counts in a chart",
          "[animation][particles]") {
    const auto& fountain = lesson().presets[1];
    REQUIRE(fountain.name.find("fountain") != std::string::npos);
    const Input in = cg::test::input_of<Particles>("particles", fountain.input);
    auto s = Particles::start(in);
    for (int k = 0; k < 50; ++k) Particles::step(s, nullptr);
    cg::Scene scene;
    Particles::draw(s, scene);
    CHECK(scene.points3.size() >= s.alive.size());  // the particles, the emitter, the focus
    CHECK(scene.faces3.size() == 1);                // the plane
    CHECK_FALSE(scene.has_2d());  // nothing on the world's grid
    CHECK(scene.focus3.size() == 1);
    int arrows = 0;
    for (const auto& seg : scene.segments3) arrows += seg.arrow;
    CHECK(arrows >= 5);  // velocity ticks
    // Young particles yellowish, old ones redder: the colours differ.
    std::set<std::uint32_t> colours;
    for (const auto& p : scene.points3) colours.insert(p.style.rgba);
    CHECK(colours.size() > 10);
    // The counts against t: a chart with three series, alive first, named with the counts now.
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& counts = scene.panels[0];
    CHECK(counts.kind == cg::PanelKind::Chart);
    CHECK(counts.x.label == "t (s)");
    CHECK(counts.y.include_zero);
    CHECK(counts.polygons.size() == 3);
    REQUIRE(counts.legend.size() == 3);
    CHECK(counts.legend[0].text == "alive " + std::to_string(s.alive.size()));
    CHECK(counts.polygons[0].points.size() == s.alive_n.size());
}
