// Boids: the exam-style example worked by hand (s, a, c, F, v', x'); every rule of every boid
// against an independent brute-force long-double recomputation on 3,000 seeded random flocks
// (coincident boids, still boids, lonely boids, r = 0, limited fields of view, obstacles, both
// edge kinds, truncated steering), to 1e-9 relative; coincident boids pushed apart along their
// relative velocity with 1/ε and never NaN; the update independent of the boids' order (a
// permuted input gives the permuted result, where an in-place update would not); the speed never
// above max_speed; the state machine equals compute; replay and byte-identical traces; the flock
// order measures against hand values; the presets behave as the lesson says; bad input names
// the field; exam problems against a hand computation; the narration and the picture.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>

#include "animation/boids.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Boids;
using Input = Boids::Input;
using Edges = Boids::Edges;
using LD = long double;

namespace {

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("boids");
    if (!l) throw std::runtime_error("no lesson for boids");
    return *l;
}

const cg::LessonPreset& preset(const std::string& part) {
    for (const auto& p : lesson().presets)
        if (p.name.find(part) != std::string::npos) return p;
    throw std::runtime_error("no boids preset named like " + part);
}

std::string err(const std::string& text) {
    return cg::test::error_of("boids", text);
}

double len(glm::dvec2 p) {
    return std::hypot(p.x, p.y);
}

// ---- the reference: the rules in long double, written separately from the code ----

struct P {
    LD x = 0, y = 0;
};
P operator+(P a, P b) {
    return {a.x + b.x, a.y + b.y};
}
P operator-(P a, P b) {
    return {a.x - b.x, a.y - b.y};
}
P operator*(LD s, P a) {
    return {s * a.x, s * a.y};
}
LD norm(P a) {
    return std::sqrt(a.x * a.x + a.y * a.y);
}
P from(glm::dvec2 p) {
    return {p.x, p.y};
}

struct RefRules {
    P s, a, c, o, b, sum, F;
    int neighbours = 0;
    bool ambiguous = false;  // a distance or an angle within rounding of a threshold
};

// The displacement a → b on a torus of size W (the nearest copy of b), by rounding d/W.
P shortest(const Input& in, P a, P b) {
    P d = b - a;
    if (in.edges == Edges::Wrap) {
        const LD W = LD(in.world_max.x) - LD(in.world_min.x),
                 H = LD(in.world_max.y) - LD(in.world_min.y);
        d.x -= W * std::nearbyint(d.x / W);
        d.y -= H * std::nearbyint(d.y / H);
    }
    return d;
}

// a within rounding of the threshold b (a threshold of 0 is never crossed by a distance: < 0).
bool near(LD a, LD b) {
    return b > 0 && std::fabs(a - b) <= 1e-9L * std::max<LD>(1, std::fabs(b));
}

RefRules reference(const Input& in, const std::vector<glm::dvec2>& xs,
                   const std::vector<glm::dvec2>& vs, std::size_t i) {
    RefRules R;
    const LD r = in.radius, rs = in.separation_radius;
    const LD eps = std::max<LD>(1e-3L * r, 1e-6L);
    const P xi = from(xs[i]), vi = from(vs[i]);
    const LD half = LD(in.fov) / 2 * 3.14159265358979323846264338327950288L / 180;
    P sv, sd;
    for (std::size_t j = 0; j < xs.size(); ++j) {
        if (j == i) continue;
        const P d = shortest(in, xi, from(xs[j]));
        const LD dist = norm(d);
        if (near(dist, r) || near(dist, rs)) R.ambiguous = true;
        if (!(dist < r)) continue;
        if (in.fov < 360 && norm(vi) > 0 && dist > 0) {
            LD cosang = (vi.x * d.x + vi.y * d.y) / (norm(vi) * dist);
            cosang = std::clamp<LD>(cosang, -1, 1);
            const LD ang = std::acos(cosang);
            if (std::fabs(ang - half) < 1e-9L) R.ambiguous = true;
            if (ang > half) continue;
        }
        ++R.neighbours;
        sv = sv + from(vs[j]);
        sd = sd + d;
        if (dist < rs) {
            P away;
            if (dist > 0) {
                away = (-1 / dist) * d;
            } else {
                const P rel = vi - from(vs[j]);
                if (norm(rel) > 0) away = (1 / norm(rel)) * rel;
            }
            R.s = R.s + (1 / std::max(dist, eps)) * away;
        }
    }
    if (R.neighbours) {
        R.a = (LD(1) / R.neighbours) * sv - vi;
        R.c = (LD(1) / R.neighbours) * sd;
    }
    for (const auto& ob : in.obstacles) {
        const P e = shortest(in, from(ob.center), xi);
        const LD dist = norm(e), gap = dist - LD(ob.radius);
        if (near(gap, r)) R.ambiguous = true;
        if (!(gap < r)) continue;
        P nh{1, 0};
        if (dist > 0)
            nh = (1 / dist) * e;
        else if (norm(vi) > 0)
            nh = (-1 / norm(vi)) * vi;
        R.o = R.o + (1 / std::max(gap, eps)) * nh;
    }
    if (in.edges == Edges::Steer) {
        const LD m = in.margin;
        const LD lo[2] = {LD(in.world_min.x) + m, LD(in.world_min.y) + m};
        const LD hi[2] = {LD(in.world_max.x) - m, LD(in.world_max.y) - m};
        const LD p[2] = {xi.x, xi.y};
        LD b[2] = {0, 0};
        for (int c = 0; c < 2; ++c) {
            if (p[c] < lo[c]) b[c] += (lo[c] - p[c]) / m;
            if (p[c] > hi[c]) b[c] -= (p[c] - hi[c]) / m;
        }
        R.b = {b[0], b[1]};
    }
    const auto& w = in.weights;
    R.sum = LD(w.separation) * R.s + LD(w.alignment) * R.a + LD(w.cohesion) * R.c +
            LD(w.avoidance) * R.o + LD(w.bounds) * R.b;
    const LD f = norm(R.sum);
    if (near(f, in.max_force)) R.ambiguous = true;
    R.F = f > LD(in.max_force) ? (LD(in.max_force) / f) * R.sum : R.sum;
    return R;
}

bool close(glm::dvec2 got, P want, LD tol = 1e-9L) {
    const LD scale = std::max<LD>(1, norm(want));
    return std::fabs(got.x - want.x) <= tol * scale && std::fabs(got.y - want.y) <= tol * scale;
}

// A random flock: sometimes coincident boids, still boids, a lonely boid, r = 0, a limited field
// of view, obstacles (one sometimes centred on a boid), a steered world, a small max_force.
Input random_flock(cg::Rng& rng) {
    Input in;
    const double W = rng.uniform(4, 30), H = rng.uniform(4, 30);
    in.world_min = {rng.uniform(-20, 0), rng.uniform(-20, 0)};
    in.world_max = in.world_min + glm::dvec2(W, H);
    in.edges = rng.chance(0.5) ? Edges::Wrap : Edges::Steer;
    const double side = std::min(W, H);
    in.radius = rng.chance(0.05) ? 0 : rng.uniform(0.5, 0.5 * side);
    in.separation_radius = rng.chance(0.3) ? in.radius : rng.uniform(0, in.radius * 1.2);
    in.fov = rng.chance(0.6) ? 360 : rng.uniform(0, 360);
    in.max_speed = rng.uniform(0.5, 4);
    in.min_speed = rng.chance(0.3) ? rng.uniform(0, in.max_speed) : 0;
    in.max_force = rng.chance(0.3) ? rng.uniform(0, 1) : rng.uniform(1, 20);
    in.weights = {rng.uniform(0, 3), rng.uniform(0, 3), rng.uniform(0, 3), rng.uniform(0, 3),
                  rng.uniform(0, 3)};
    in.margin = rng.uniform(0.05, 0.5) * side;
    in.dt = rng.uniform(0.01, 0.5);
    in.steps = int(rng.integer(1, 4));
    // Clustered so that most boids have neighbours: a few groups of radius ~r.
    const int n = int(rng.integer(1, 14));
    const glm::dvec2 centre{rng.uniform(in.world_min.x, in.world_max.x),
                            rng.uniform(in.world_min.y, in.world_max.y)};
    const double spread = std::max(in.radius, 1.0);
    for (int b = 0; b < n; ++b) {
        Boids::Boid boid;
        boid.position = centre + glm::dvec2(rng.uniform(-spread, spread), rng.uniform(-spread, spread));
        if (rng.chance(0.2))  // anywhere: a lonely one
            boid.position = {rng.uniform(in.world_min.x, in.world_max.x),
                             rng.uniform(in.world_min.y, in.world_max.y)};
        if (in.edges == Edges::Steer)
            boid.position = glm::clamp(boid.position, in.world_min, in.world_max);
        const double sp = rng.chance(0.15) ? 0 : rng.uniform(0, in.max_speed);
        const double h = rng.uniform(0, 6.283185307179586);
        boid.velocity = sp * glm::dvec2(std::cos(h), std::sin(h));
        in.boids.push_back(boid);
    }
    if (n >= 2 && rng.chance(0.15)) in.boids[1].position = in.boids[0].position;  // coincident
    if (n >= 3 && rng.chance(0.05)) in.boids[2] = in.boids[0];                     // identical
    const int obstacles = rng.chance(0.4) ? int(rng.integer(1, 2)) : 0;
    for (int k = 0; k < obstacles; ++k)
        in.obstacles.push_back({centre + glm::dvec2(rng.uniform(-spread, spread), rng.uniform(-spread, spread)),
                                rng.uniform(0.1, 2)});
    if (!in.obstacles.empty() && rng.chance(0.1)) in.obstacles[0].center = in.boids[0].position;
    in.focus = int(rng.integer(0, n - 1));
    return in;
}

std::vector<glm::dvec2> positions(const Input& in) {
    std::vector<glm::dvec2> x;
    for (const auto& b : in.boids) x.push_back(b.position);
    return x;
}
std::vector<glm::dvec2> velocities(const Input& in) {
    std::vector<glm::dvec2> v;
    for (const auto& b : in.boids) v.push_back(b.velocity);
    return v;
}

bool all_finite(const cg::json& j) {
    if (j.is_number()) return std::isfinite(j.get<double>());
    if (j.is_array() || j.is_object())
        for (const auto& e : j)
            if (!all_finite(e)) return false;
    return true;
}

// The exam-style example: boid 0 at the origin flying right, three neighbours, one beyond r.
Input worked() {
    Input in;
    in.boids = {{{0, 0}, {1, 0}}, {{1, 0}, {0, 1}}, {{0, -2}, {1, 1}}, {{-3, 4}, {1, -1}},
                {{7, 0}, {-1, 0}}};
    in.radius = 6;
    in.separation_radius = 2.5;
    in.weights = {1, 1, 1, 1, 1};
    in.max_force = 10;
    in.max_speed = 5;
    in.dt = 1;
    in.steps = 1;
    return in;
}

}  // namespace

TEST_CASE("boids: the exam-style example worked by hand", "[animation][boids]") {
    // Neighbours 1, 2, 3 (|d| = 1, 2, 5); boid 4 is 7 away. Close (|d| < 2.5): 1 and 2.
    // s = −(1, 0)/1 − (0, −2)/4 = (−1, 0.5); a = mean v − v = (2/3, 1/3) − (1, 0);
    // c = mean d = ((1, 0) + (0, −2) + (−3, 4))/3 = (−2/3, 2/3); F = (−2, 1.5), |F| = 2.5 < 10;
    // v' = (1, 0) + (−2, 1.5) = (−1, 1.5) (speed 1.80 < 5); x' = (−1, 1.5).
    const auto t = cg::test::run_traced<Boids>(worked());
    const auto& r = t.result.rules;
    CHECK(r.neighbours == 3);
    CHECK(r.close == 2);
    CHECK(r.separation.x == Approx(-1));
    CHECK(r.separation.y == Approx(0.5));
    CHECK(r.alignment.x == Approx(-1.0 / 3));
    CHECK(r.alignment.y == Approx(1.0 / 3));
    CHECK(r.cohesion.x == Approx(-2.0 / 3));
    CHECK(r.cohesion.y == Approx(2.0 / 3));
    CHECK(r.steering.x == Approx(-2));
    CHECK(r.steering.y == Approx(1.5));
    CHECK(t.result.v.x == Approx(-1));
    CHECK(t.result.v.y == Approx(1.5));
    CHECK(t.result.x.x == Approx(-1));
    CHECK(t.result.x.y == Approx(1.5));
    // The narration gives the numbers.
    const std::string& n = t.steps[0].narration;
    CAPTURE(n);
    CHECK(n.find("saw 3 neighbours within r = 6 (1, 2, 3)") != std::string::npos);
    CHECK(n.find("1: d = (1, 0), |d| = 1 → (−1, 0)") != std::string::npos);
    CHECK(n.find("2: d = (0, −2), |d| = 2 → (0, 0.5)") != std::string::npos);
    CHECK(n.find("s = (−1, 0.5)") != std::string::npos);
    CHECK(n.find("= (−0.333333, 0.333333)") != std::string::npos);
    CHECK(n.find("= (−0.666667, 0.666667)") != std::string::npos);
    CHECK(n.find("= (−2, 1.5)") != std::string::npos);
    CHECK(n.find("v ← v + dt F = (1, 0) + 1 · (−2, 1.5) = (−1, 1.5)") != std::string::npos);
    CHECK(t.steps[1].event == "summary");
    // Truncation: max_force 2 scales F = (−2, 1.5) to length 2: (−1.6, 1.2), v' = (−0.6, 1.2).
    Input forced = worked();
    forced.max_force = 2;
    const auto tf = cg::test::run_traced<Boids>(forced);
    CHECK(tf.result.rules.steering.x == Approx(-1.6));
    CHECK(tf.result.rules.steering.y == Approx(1.2));
    CHECK(tf.result.v.x == Approx(-0.6));
    CHECK(tf.result.v.y == Approx(1.2));
    CHECK(tf.steps[0].narration.find("longer than max_force = 2 (|F| = 2.5), so scaled to (−1.6, 1.2)") !=
          std::string::npos);
    // max_speed 1.5 (every start is slower): v' = (−1, 1.5), speed 1.803, scaled to 1.5.
    Input slow = worked();
    slow.max_speed = 1.5;
    const auto ts = cg::test::run_traced<Boids>(slow);
    CHECK(ts.result.rules.steering.x == Approx(-2));
    CHECK(len(ts.result.v) <= 1.5);
    CHECK(ts.result.v.x == Approx(-1.5 / std::hypot(1.0, 1.5)));
    CHECK(ts.result.v.y == Approx(2.25 / std::hypot(1.0, 1.5)));
    CHECK(ts.steps[0].narration.find("speed 1.80278 clamped to [0, 1.5]") != std::string::npos);
}

TEST_CASE("boids: 3,000 random flocks, every rule against a long-double brute force",
          "[animation][boids]") {
    cg::Rng rng(2026);
    int checked = 0, ambiguous = 0, coincident = 0, still = 0, lonely = 0, zero_r = 0, fov = 0,
        truncated = 0, avoided = 0, bounded = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Input given = random_flock(rng);
        CAPTURE(trial);
        const Input in = Boids::resolve(given);
        const auto x = positions(in), v = velocities(in);
        std::vector<glm::dvec2> x1, v1;
        Boids::Rules fr;
        Boids::Seen seen;
        Boids::advance(in, x, v, x1, v1, fr, seen);
        zero_r += in.radius == 0;
        fov += in.fov < 360;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const auto got = Boids::rules(in, x, v, i);
            const RefRules want = reference(in, x, v, i);
            if (want.ambiguous) {
                ++ambiguous;
                continue;
            }
            CAPTURE(i, in.radius, in.separation_radius, in.fov);
            REQUIRE(got.neighbours == want.neighbours);
            CHECK(close(got.separation, want.s));
            CHECK(close(got.alignment, want.a));
            CHECK(close(got.cohesion, want.c));
            CHECK(close(got.avoidance, want.o));
            CHECK(close(got.bounds, want.b));
            CHECK(close(got.sum, want.sum));
            CHECK(close(got.steering, want.F));
            // The new velocity: v + dt F, speed clamped to [min_speed, max_speed].
            P nv = from(v[i]) + LD(in.dt) * want.F;
            const LD sp = norm(nv);
            if (sp > 0 && sp < LD(in.min_speed)) nv = (LD(in.min_speed) / sp) * nv;
            if (norm(nv) > LD(in.max_speed)) nv = (LD(in.max_speed) / norm(nv)) * nv;
            CHECK(close(v1[i], nv));
            CHECK(std::isfinite(x1[i].x));
            CHECK(std::isfinite(x1[i].y));
            ++checked;
            still += v[i] == glm::dvec2(0);
            lonely += want.neighbours == 0;
            truncated += norm(want.sum) > LD(in.max_force);
            avoided += norm(want.o) > 0;
            bounded += norm(want.b) > 0;
            for (std::size_t j = 0; j < x.size(); ++j)
                coincident += j != i && x[j] == x[i] && got.neighbours > 0;
        }
    }
    WARN("rules checked for " << checked << " boids (" << ambiguous << " ambiguous skipped); coincident "
         << coincident << ", still " << still << ", lonely " << lonely << ", r = 0 flocks " << zero_r
         << ", limited view flocks " << fov << ", truncated " << truncated << ", avoiding "
         << avoided << ", bounded " << bounded);
    CHECK(checked > 15000);
    CHECK(ambiguous < checked / 1000);
    CHECK(coincident > 200);
    CHECK(still > 1000);
    CHECK(lonely > 1000);
    CHECK(zero_r > 100);
    CHECK(fov > 1000);
    CHECK(truncated > 1000);
    CHECK(avoided > 1000);
    CHECK(bounded > 300);
}

TEST_CASE("boids: coincident boids are pushed apart along their relative velocity, never NaN",
          "[animation][boids]") {
    Input in;
    in.boids = {{{1, 1}, {1, 0}}, {{1, 1}, {0, 1}}, {{1, 1}, {0, 1}}};
    in.radius = 2;
    in.weights = {1, 0, 0, 0, 0};
    in.max_force = 1e6;
    const Input res = Boids::resolve(in);
    const auto x = positions(res), v = velocities(res);
    const double eps = Boids::epsilon(res);  // 2e-3
    CHECK(eps == Approx(2e-3));
    // Boid 0 against 1 and 2: v_0 − v_j = (1, −1), both: 2 · (1, −1)/√2 / ε.
    const auto r0 = Boids::rules(res, x, v, 0);
    CHECK(r0.separation.x == Approx(2 / std::sqrt(2.0) / eps));
    CHECK(r0.separation.y == Approx(-2 / std::sqrt(2.0) / eps));
    // Boids 1 and 2 are the same boid to each other: only boid 0 pushes them, the other way.
    const auto r1 = Boids::rules(res, x, v, 1), r2 = Boids::rules(res, x, v, 2);
    CHECK(r1.separation.x == Approx(-1 / std::sqrt(2.0) / eps));
    CHECK(r1.separation.y == Approx(1 / std::sqrt(2.0) / eps));
    CHECK(r1 == r2);
    // Every boid on one point, all still: nothing can tell them apart; nothing moves, no NaN.
    Input pile;
    pile.boids.assign(5, {{2, -3}, {0, 0}});
    pile.steps = 50;
    const auto r = Boids::compute(pile);
    for (const auto& p : r.positions) CHECK(p == glm::dvec2(2, -3));
    for (const auto& u : r.velocities) CHECK(u == glm::dvec2(0));
    CHECK(r.nearest.back() == 0);
    CHECK(r.polarisation.back() == 0);
    // The same pile with different velocities flies apart, finite throughout.
    for (std::size_t i = 0; i < pile.boids.size(); ++i)
        pile.boids[i].velocity = {std::cos(double(i)), std::sin(double(i))};
    const auto j = cg::test::result_of("boids", cg::json::parse(R"({
        "boids": [{"position": [2, -3], "velocity": [1, 0]}, {"position": [2, -3], "velocity": [0, 1]},
                  {"position": [2, -3], "velocity": [-1, 0]}, {"position": [2, -3]}],
        "steps": 50})"));
    CHECK(all_finite(j));
    CHECK(j["final_nearest"].get<double>() > 0.1);
}

TEST_CASE("boids: still boids, lonely boids, r = 0 and obstacles met head on",
          "[animation][boids]") {
    SECTION("a still boid sees all round even with a narrow field of view") {
        Input in;
        in.boids = {{{0, 0}, {0, 0}}, {{-1, 0}, {0, 0}}};
        in.fov = 10;
        const Input res = Boids::resolve(in);
        CHECK(Boids::rules(res, positions(res), velocities(res), 0).neighbours == 1);
        // Moving right, boid 1 is behind it: out of a 10° view.
        Input moving = in;
        moving.boids[0].velocity = {1, 0};
        const Input rm = Boids::resolve(moving);
        CHECK(Boids::rules(rm, positions(rm), velocities(rm), 0).neighbours == 0);
        moving.fov = 360;
        const Input ra = Boids::resolve(moving);
        CHECK(Boids::rules(ra, positions(ra), velocities(ra), 0).neighbours == 1);
    }
    SECTION("with r = 0 nobody sees anybody: every boid flies straight on") {
        Input in;
        in.boids = {{{0, 0}, {1, 0}}, {{0, 0}, {0, 1}}, {{0.5, 0.5}, {-1, 0.5}}};
        in.radius = 0;
        in.edges = Edges::Wrap;
        in.dt = 0.1;
        in.steps = 30;
        const auto r = Boids::compute(in);
        CHECK(r.rules.neighbours == 0);
        CHECK(r.rules.steering == glm::dvec2(0));
        CHECK(r.velocities[0] == glm::dvec2(1, 0));
        CHECK(r.positions[0].x == Approx(3));
        CHECK(r.positions[1].y == Approx(3));
    }
    SECTION("a lonely boid keeps its velocity") {
        Input in;
        in.boids = {{{0, 0}, {1, 1}}, {{9, 9}, {0, 1}}};
        in.radius = 2;
        in.steps = 10;
        const auto r = Boids::compute(in);
        CHECK(r.rules.neighbours == 0);
        CHECK(r.velocities[0] == glm::dvec2(1, 1));
    }
    SECTION("a boid on an obstacle's centre is pushed against its velocity, or +x when still") {
        Input in;
        in.boids = {{{0, 0}, {0, 1}}, {{5, 5}, {0, 0}}};
        in.obstacles = {{{0, 0}, 1}, {{5, 5}, 1}};
        in.radius = 1;
        const Input res = Boids::resolve(in);
        const double eps = Boids::epsilon(res);
        const auto r0 = Boids::rules(res, positions(res), velocities(res), 0);
        CHECK(r0.avoidance.x == 0);
        CHECK(r0.avoidance.y == Approx(-1 / eps));
        const auto r1 = Boids::rules(res, positions(res), velocities(res), 1);
        CHECK(r1.avoidance.x == Approx(1 / eps));
        CHECK(r1.avoidance.y == 0);
    }
}

TEST_CASE("boids: the update does not depend on the boids' order (double buffering)",
          "[animation][boids]") {
    cg::Rng rng(99);
    int differs_in_place = 0, trials = 0;
    for (int trial = 0; trial < 500; ++trial) {
        CAPTURE(trial);
        // One frame: from the same start every offset is computed alike in either order, only
        // the order of the sums changes. (Over more frames those last bits can tip a boid over
        // r, and the runs part: chaos, not order dependence.)
        Input in = random_flock(rng);
        in.steps = 1;
        const std::size_t n = in.boids.size();
        std::vector<std::size_t> perm(n);
        std::iota(perm.begin(), perm.end(), 0);
        for (std::size_t k = n; k > 1; --k)
            std::swap(perm[k - 1], perm[std::size_t(rng.integer(0, (long long)k - 1))]);
        // Boid k of the permuted flock is boid perm[k] of the original.
        Input p = in;
        for (std::size_t k = 0; k < n; ++k) p.boids[k] = in.boids[perm[k]];
        for (std::size_t k = 0; k < n; ++k)
            if (perm[k] == std::size_t(in.focus)) p.focus = int(k);
        const auto a = Boids::compute(in), b = Boids::compute(p);
        for (std::size_t k = 0; k < n; ++k) {
            CAPTURE(k, perm[k]);
            // Only the order of the sums changes: equal to rounding.
            CHECK(len(b.positions[k] - a.positions[perm[k]]) <= 1e-9 * (1 + len(a.positions[perm[k]])));
            CHECK(len(b.velocities[k] - a.velocities[perm[k]]) <= 1e-9 * (1 + len(a.velocities[perm[k]])));
        }
        CHECK(b.rules.neighbours == a.rules.neighbours);
        CHECK(b.polarisation.back() == Approx(a.polarisation.back()).margin(1e-9));
        CHECK(b.nearest.back() == Approx(a.nearest.back()).margin(1e-9));
        // Updating in place (boid k reading boids < k already moved) depends on the order.
        if (n >= 3 && in.radius > 0) {
            ++trials;
            auto in_place = [](const Input& given) {
                const Input res = Boids::resolve(given);
                auto x = positions(res), v = velocities(res);
                for (std::size_t i = 0; i < x.size(); ++i) {
                    const auto r = Boids::rules(res, x, v, i);
                    v[i] = Boids::truncate(v[i] + res.dt * r.steering, res.max_speed);
                    x[i] += res.dt * v[i];
                }
                return x;
            };
            const auto xa = in_place(in), xb = in_place(p);
            bool differs = false;
            for (std::size_t k = 0; k < n; ++k) differs = differs || len(xb[k] - xa[perm[k]]) > 1e-6;
            differs_in_place += differs;
        }
    }
    CAPTURE(trials, differs_in_place);
    CHECK(differs_in_place > trials / 10);  // the buffered update is what makes the order not matter
}

TEST_CASE("boids: the speed never exceeds max_speed, nor falls below min_speed",
          "[animation][boids]") {
    cg::Rng rng(7);
    long long checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Input in = random_flock(rng);
        in.steps = 40;
        CAPTURE(trial, in.max_speed, in.min_speed);
        auto s = Boids::start(in);
        // Initial velocities above max_speed are scaled down at the start.
        for (const auto& u : s.v) CHECK(len(u) <= in.max_speed);
        while (!Boids::done(s)) {
            Boids::step(s, nullptr);
            for (const auto& u : s.v) {
                const double sp = len(u);
                CHECK(sp <= in.max_speed);  // exactly: no rounding above it
                if (sp > 0) CHECK(sp >= in.min_speed * (1 - 1e-15));
                ++checked;
            }
        }
    }
    CHECK(checked > 20000);
    // A start far too fast is scaled to max_speed.
    const auto j = cg::test::result_of("boids", cg::json::parse(R"({
        "boids": [{"position": [0, 0], "velocity": [300, 400]}], "max_speed": 2, "steps": 1})"));
    CHECK(j["velocities"][0][0].get<double>() == Approx(1.2));
    CHECK(j["velocities"][0][1].get<double>() == Approx(1.6));
}

TEST_CASE("boids: the state machine gives what compute gives, through the registry too",
          "[animation][boids]") {
    cg::Rng rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        CAPTURE(trial);
        Input in = random_flock(rng);
        in.steps = int(rng.integer(1, 30));
        const auto traced = cg::test::run_traced<Boids>(in);
        const auto plain = Boids::compute(in);
        CHECK(traced.result == plain);
        CHECK(cg::run_to_end<Boids>(Boids::start(in)) == plain);
        const auto ev = cg::test::events(traced);
        REQUIRE(ev.size() == std::size_t(in.steps) + 1);
        CHECK(ev.back() == "summary");
        CHECK(plain.polarisation.size() == std::size_t(in.steps) + 1);
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const auto j = cg::test::result_of("boids", p.input);
        CHECK(all_finite(j));
        CHECK(j["polarisation"].size() == j["steps"].get<std::size_t>() + 1);
    }
}

TEST_CASE("boids: determinism, replay, and the seed naming one random start",
          "[animation][boids]") {
    const auto& a = cg::test::algorithm("boids");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 5);
    }
    // The same seed gives byte-identical traces; another seed another flock.
    const cg::json base = cg::json::parse(
        R"({"random": {"count": 30, "seed": 5}, "world": {"min": [-10, -10], "max": [10, 10]},
            "steps": 40})");
    CHECK(cg::test::trace(a, base) == cg::test::trace(a, base));
    cg::json other = base;
    other["random"]["seed"] = 6;
    CHECK(cg::test::result_of("boids", base)["positions"] !=
          cg::test::result_of("boids", other)["positions"]);
    // The random start: inside the world, outside the obstacles, speeds in [max/2, max].
    Input in;
    in.random = {200, 11};
    in.world_min = {-5, 0};
    in.world_max = {15, 8};
    in.radius = 2;
    in.obstacles = {{{0, 4}, 2}};
    in.max_speed = 3;
    const Input res = Boids::resolve(in);
    REQUIRE(res.boids.size() == 200);
    for (const auto& b : res.boids) {
        CHECK(b.position.x >= -5);
        CHECK(b.position.x < 15);
        CHECK(b.position.y >= 0);
        CHECK(b.position.y < 8);
        CHECK(len(b.position - glm::dvec2(0, 4)) >= 2);
        CHECK(len(b.velocity) >= 1.5 * (1 - 1e-12));
        CHECK(len(b.velocity) <= 3);
    }
}

TEST_CASE("boids: polarisation and mean nearest-neighbour distance", "[animation][boids]") {
    Input in;
    in.world_min = {-10, -10};
    in.world_max = {10, 10};
    // All the same way: φ = 1; half each way: φ = 0; a still boid counts as 0.
    CHECK(Boids::polarisation({{1, 0}, {2, 0}, {0.5, 0}}) == Approx(1));
    CHECK(Boids::polarisation({{1, 0}, {-2, 0}}) == 0);
    CHECK(Boids::polarisation({{0, 3}, {0, 0}}) == Approx(0.5));
    CHECK(Boids::polarisation({{1, 0}, {0, 1}}) == Approx(std::sqrt(0.5)));
    // A 3 × 3 grid of spacing 2: every nearest neighbour is 2 away.
    std::vector<glm::dvec2> grid;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) grid.push_back({2.0 * i, 2.0 * j});
    CHECK(Boids::mean_nearest(in, grid) == Approx(2));
    CHECK(Boids::mean_nearest(in, {{0, 0}}) == 0);
    // Wrapped: −9.5 and 9.5 are 1 apart round the edge; steered, 19 apart.
    CHECK(Boids::mean_nearest(in, {{-9.5, 0}, {9.5, 0}}) == Approx(1));
    in.edges = Edges::Steer;
    CHECK(Boids::mean_nearest(in, {{-9.5, 0}, {9.5, 0}}) == Approx(19));
}

TEST_CASE("boids: a wrapped world is a torus", "[animation][boids]") {
    Input in;
    in.boids = {{{9.9, 0}, {1, 0}}, {{-9.8, 0.5}, {0, 0}}};
    in.radius = 1;
    in.weights = {0, 0, 1, 0, 0};
    in.dt = 0.5;
    in.steps = 1;
    const Input res = Boids::resolve(in);
    // Boid 1 is 0.3 to the right of boid 0 round the edge: a neighbour, cohesion toward it.
    const auto r = Boids::rules(res, positions(res), velocities(res), 0);
    CHECK(r.neighbours == 1);
    CHECK(r.cohesion.x == Approx(0.3));
    CHECK(r.cohesion.y == Approx(0.5));
    // Boid 0 leaves on the right and comes back on the left.
    const auto c = Boids::compute(in);
    CHECK(c.positions[0].x < -9);
    CHECK(c.positions[0].x >= -10);
    // A boid given outside a wrapped world is taken round into it.
    Input outside;
    outside.boids = {{{25, -12}, {0, 0}}};
    const Input ro = Boids::resolve(outside);
    CHECK(ro.boids[0].position.x == Approx(5));
    CHECK(ro.boids[0].position.y == Approx(8));
}

TEST_CASE("boids: the lesson's presets do what the lesson says", "[animation][boids]") {
    auto run = [](const cg::LessonPreset& p) {
        return Boids::compute(cg::test::input_of<Boids>("boids", p.input));
    };
    SECTION("a flock forms: the polarisation climbs from disorder to order") {
        const auto r = run(preset("a flock forming"));
        CAPTURE(r.polarisation.front(), r.polarisation.back());
        CHECK(r.polarisation.front() < 0.3);
        CHECK(r.polarisation.back() > 0.9);
    }
    SECTION("cohesion only: swarms gather (the nearest distance falls) but never align") {
        const auto r = run(preset("cohesion only"));
        CAPTURE(r.nearest.front(), r.nearest.back(), r.polarisation.back());
        CHECK(r.nearest.back() < 0.75 * r.nearest.front());
        CHECK(r.polarisation.back() < 0.4);
    }
    SECTION("alignment only: the headings order, nobody gathers") {
        const auto r = run(preset("alignment only"));
        CAPTURE(r.polarisation.back(), r.nearest.front(), r.nearest.back());
        CHECK(r.polarisation.back() > 0.9);
    }
    SECTION("separation only: no flock, the boids stay as far apart as the full flock's twice") {
        const auto r = run(preset("separation only")), all = run(preset("a flock forming"));
        CAPTURE(r.nearest.front(), r.nearest.back(), all.nearest.back(), r.polarisation.back());
        CHECK(r.nearest.back() > 1.5 * all.nearest.back());
        CHECK(r.polarisation.back() < 0.3);
    }
    SECTION("obstacles: the boids keep out of the rocks") {
        const auto& p = preset("obstacle");
        const Input in = Boids::resolve(cg::test::input_of<Boids>("boids", p.input));
        REQUIRE(!in.obstacles.empty());
        auto s = Boids::start(in);
        long long inside = 0, total = 0;
        while (!Boids::done(s)) {
            Boids::step(s, nullptr);
            for (const auto& x : s.x) {
                for (const auto& o : in.obstacles) inside += len(x - o.center) < o.radius;
                ++total;
            }
        }
        CAPTURE(inside, total);
        CHECK(inside * 1000 < total);  // fewer than one boid-frame in a thousand
    }
}

TEST_CASE("boids: bad input names the field and the reason", "[animation][boids]") {
    const std::string one = R"("boids": [{"position": [0, 0]}, {"position": [1, 0]}])";
    CHECK(err(R"({})").find("boids: is missing") == 0);
    CHECK(err(R"({"boids": []})") == "boids: must have at least 1 boid (got none)");
    CHECK(err(R"({"boids": [{"position": [0, 0, 0]}]})").find("boids[0].position: must be a point [x, y]") == 0);
    CHECK(err(R"({"boids": [{"position": [1e7, 0]}]})").find("boids[0].position: is too large") == 0);
    CHECK(err(R"({"boids": [{"position": [0, 0], "speed": 1}]})").find("boids[0]") == 0);
    CHECK(err(R"({"random": {"count": 0}})").find("random.count: must be 1 to 1000") == 0);
    CHECK(err(R"({"random": {"count": 1001}})").find("random.count: must be 1 to 1000") == 0);
    CHECK(err(R"({"random": {"count": 3, "seed": -1}})").find("random.seed: must be") == 0);
    CHECK(err("{" + one + R"(, "random": {"count": 3}})").find("random: give either") == 0);
    CHECK(err("{" + one + R"(, "world": {"min": [0, 0], "max": [0, 5]}})").find("world: max must be above min in x") == 0);
    CHECK(err("{" + one + R"(, "world": {"min": [0, 0], "max": [4, 5]}})").find("world: is 4 across at its narrowest, less than 2r = 6") == 0);
    CHECK(err("{" + one + R"(, "edges": "bounce"})").find("edges: must be \"wrap\" or \"steer\"") == 0);
    CHECK(err("{" + one + R"(, "edges": "steer", "margin": 0})").find("margin: must be a width") == 0);
    CHECK(err("{" + one + R"(, "margin": -1})").find("margin: must be a width") == 0);
    CHECK(err("{" + one + R"(, "radius": -1})").find("radius: must be ≥ 0") == 0);
    CHECK(err("{" + one + R"(, "separation_radius": -1})").find("separation_radius: must be ≥ 0") == 0);
    CHECK(err("{" + one + R"(, "fov": 400})").find("fov: must be a field of view of 0 to 360") == 0);
    CHECK(err("{" + one + R"(, "weights": {"cohesion": -1}})").find("weights.cohesion: must be ≥ 0") == 0);
    CHECK(err("{" + one + R"(, "weights": {"flocking": 1}})").find("weights") == 0);
    CHECK(err("{" + one + R"(, "max_speed": -2})").find("max_speed: must be ≥ 0") == 0);
    CHECK(err("{" + one + R"(, "min_speed": 3})").find("min_speed: must be at most max_speed = 2") == 0);
    CHECK(err("{" + one + R"(, "max_force": 1e7})").find("max_force: is too large") == 0);
    CHECK(err("{" + one + R"(, "dt": 0})").find("dt: must be a time step > 0") == 0);
    CHECK(err("{" + one + R"(, "dt": 11})").find("dt: is too large") == 0);
    CHECK(err("{" + one + R"(, "steps": 0})").find("steps: must be 1 to 100000") == 0);
    CHECK(err(R"({"random": {"count": 1000}, "steps": 100})").find("steps: 100 steps of 1000 boids is too much work") == 0);
    CHECK(err("{" + one + R"(, "focus": 2})").find("focus: must name a boid 0 to 1 (got 2)") == 0);
    CHECK(err("{" + one + R"(, "obstacles": [{"center": [0, 0], "radius": 0}]})").find("obstacles[0].radius: must be > 0") == 0);
    CHECK(err("{" + one + R"(, "obstacles": [{"center": [0, 0]}]})").find("obstacles[0]") == 0);
    CHECK(err("{" + one + R"(, "dt": NaN})").find("not valid JSON") != std::string::npos);
    // Accepted: one boid, a field of view of 0, r = 0, every weight 0.
    CHECK(err(R"({"boids": [{"position": [0, 0]}]})") == "(accepted)");
    CHECK(err("{" + one + R"(, "fov": 0, "radius": 0, "weights": {"separation": 0,
        "alignment": 0, "cohesion": 0, "avoidance": 0, "bounds": 0}})") == "(accepted)");
}

TEST_CASE("boids: exam problems are one frame of one boid, answered by hand",
          "[animation][boids][exam]") {
    const auto& a = cg::test::algorithm("boids");
    int capped = 0, beyond = 0, four = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<Boids>("boids", p.input);
        REQUIRE(in.steps == 1);
        REQUIRE(in.focus == 0);
        const std::size_t n = in.boids.size();
        REQUIRE(n >= 3);
        REQUIRE(n <= 6);
        // By hand, in long double: s = Σ −d/|d|² over |d| < r_sep, a = mean v_j − v, c = mean d.
        const P x = from(in.boids[0].position), v = from(in.boids[0].velocity);
        P s, sv, sd;
        int m = 0;
        for (std::size_t j = 1; j < n; ++j) {
            const P d = from(in.boids[j].position) - x;
            const LD dist = norm(d);
            if (dist >= LD(in.radius)) {
                ++beyond;
                continue;
            }
            ++m;
            sv = sv + from(in.boids[j].velocity);
            sd = sd + d;
            if (dist < LD(in.separation_radius)) s = s + (-1 / (dist * dist)) * d;
        }
        REQUIRE(m >= 2);
        REQUIRE(m <= 4);
        four += m == 4;
        const P al = (LD(1) / m) * sv - v, co = (LD(1) / m) * sd;
        P F = s + al + co;
        if (norm(F) > LD(in.max_force)) F = (LD(in.max_force) / norm(F)) * F;
        P nv = v + LD(in.dt) * F;
        if (norm(nv) > LD(in.max_speed)) {
            nv = (LD(in.max_speed) / norm(nv)) * nv;
            ++capped;
        }
        auto get = [&](const char* f) { return p.expected[f].get<std::vector<double>>(); };
        auto same = [](const std::vector<double>& g, P w) {
            return g.size() == 2 && std::fabs(g[0] - double(w.x)) < 1e-12 &&
                   std::fabs(g[1] - double(w.y)) < 1e-12;
        };
        CHECK(same(get("focus/separation"), s));
        CHECK(same(get("focus/alignment"), al));
        CHECK(same(get("focus/cohesion"), co));
        CHECK(same(get("focus/v"), nv));
        CHECK(p.answers == std::vector<std::string>{"focus/separation", "focus/alignment",
                                                    "focus/cohesion", "focus/v"});
        CHECK(p.question.find("boid " + std::to_string(n - 1)) != std::string::npos);
    }
    CHECK(capped > 8);
    CHECK(beyond > 50);
    CHECK(four > 50);
}

TEST_CASE("boids: the picture, the focus boid's view and the order charts", "[animation][boids]") {
    const Input in = worked();
    const auto s = Boids::start(in);
    cg::Scene scene;
    Boids::draw(s, scene);
    // The world, the perception and separation circles, 5 boids, the two plot lines and frame.
    int teal = 0, orange = 0, arrows = 0;
    for (const auto& p : scene.polygons)
        if (p.filled) {
            teal += p.style.role == cg::Role::Entering;
            orange += p.style.role == cg::Role::Active;
        }
    CHECK(teal == 3);    // boids 1, 2, 3 seen
    CHECK(orange == 1);  // the focus boid
    for (const auto& g : scene.segments) arrows += g.arrow;
    CHECK(arrows == 4);  // separation, alignment, cohesion, F
    std::vector<std::string> labels;
    for (const auto& l : scene.labels) labels.push_back(l.text);
    for (const char* name : {"separation", "alignment", "cohesion", "F", "0", "4"})
        CHECK(std::find(labels.begin(), labels.end(), name) != labels.end());
    // The arrows: weighted rules from the focus boid, scaled together, F their sum.
    glm::dvec2 sum{0, 0}, F{0, 0};
    for (const auto& g : scene.segments)
        if (g.arrow) (g.style.dashed ? F : sum) += g.b - g.a;
    CHECK(len(sum - F) < 1e-9);
    CHECK(len(F) / len(glm::dvec2(-2, 1.5)) > 0);
    CHECK(scene.handles.empty());  // no obstacles: nothing to drag
    // The order against time: two charts over the run, φ from 0 to 1, the distance from 0.
    REQUIRE(scene.panels.size() == 2);
    CHECK(scene.panels[0].kind == cg::PanelKind::Chart);
    CHECK(scene.panels[0].x.label == "t (s)");
    CHECK(scene.panels[0].x.hi == Approx(in.steps * in.dt));
    CHECK(scene.panels[0].y.hi == 1);
    CHECK(scene.panels[1].y.include_zero);
    for (const auto& p : scene.panels) CHECK(p.polygons.size() == 1);
    CHECK(scene.focus2.size() == 1);
    // A limited field of view draws a wedge through the boid.
    Input narrow = in;
    narrow.fov = 90;
    cg::Scene wedge;
    Boids::draw(Boids::start(narrow), wedge);
    bool through = false;
    for (const auto& p : wedge.polygons)
        through = through || (!p.filled && p.closed && !p.points.empty() && p.points[0] == glm::dvec2(0));
    CHECK(through);
    // A steered world draws its margin band; obstacles are filled discs.
    Input steer = in;
    steer.edges = Edges::Steer;
    steer.obstacles = {{{4, 4}, 1}};
    cg::Scene ss;
    Boids::draw(Boids::start(steer), ss);
    int dashed_window = 0;
    for (const auto& p : ss.polygons) dashed_window += p.style.role == cg::Role::Window && p.style.dashed;
    CHECK(dashed_window == 1);
    REQUIRE(ss.handles.size() == 1);
    CHECK(ss.handles[0].x_field == "/obstacles/0/center/0");
}
