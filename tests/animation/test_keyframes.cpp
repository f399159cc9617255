// Keyframes: hand-worked exam cases (Catmull–Rom at u = ½, tangents, C1 or not); an independent
// long-double implementation of linear, Catmull–Rom and Kochanek–Bartels (tangents from the
// phantom-key rule, the cubic in power form a u³ + b u² + c u + d rather than the Hermite basis)
// on 4,000 seeded random key sets (1 to 3 channels, 2 to 9 keys, uneven times, equal values,
// extreme T, C, B of ±1), equal to 1e-10 relative; C0 at every key, C1 for Catmull–Rom, the
// linear jump equal to the slope difference and the KB jump equal to (1−T) C [(1+B) s⁻ − (1−B)
// s⁺]; the keys hit exactly; repeated times refused naming both keys; the constant-speed motion
// against a long-double chord table; the state machine equals compute, through the registry
// too; replay; the clock; the exam problems against a hand computation; the picture.
#include <catch2/catch.hpp>
#include <cmath>

#include "animation/keyframes.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Keyframes;
using Input = Keyframes::Input;
using Interp = Keyframes::Interpolation;
using LD = long double;

namespace {

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("keyframes");
    if (!l) throw std::runtime_error("no lesson for keyframes");
    return *l;
}

Input scalar(std::vector<std::pair<double, double>> keys, Interp kind, double dt = 0.25) {
    Input in;
    for (auto [t, v] : keys) {
        Keyframes::Key k;
        k.t = t;
        k.value.x = v;
        in.keys.push_back(k);
    }
    in.interpolation = kind;
    in.dt = dt;
    return in;
}

Input input_of(const cg::json& j) {
    auto run = cg::test::algorithm("keyframes").create(j);
    return static_cast<cg::RunOf<Keyframes>&>(*run).state.p->in;
}

std::string err(const std::string& text) {
    return cg::test::error_of("keyframes", text);
}

bool all_finite(const cg::json& j) {
    if (j.is_number()) return std::isfinite(j.get<double>());
    if (j.is_array() || j.is_object())
        for (const auto& e : j)
            if (!all_finite(e)) return false;
    return true;
}

// ---- the reference, written apart: long double, power form, phantom end keys ----

struct Ref {
    std::vector<LD> t;
    std::vector<std::vector<LD>> p;  // p[i][d]
    std::vector<std::vector<LD>> m_in, m_out;
    int dim = 1;
    Interp kind;
};

Ref reference(const Input& in) {
    Ref r;
    r.dim = in.dim;
    r.kind = in.interpolation;
    const std::size_t n = in.keys.size();
    for (const auto& k : in.keys) {
        r.t.push_back(k.t);
        r.p.push_back({k.value.x, k.value.y, k.value.z});
    }
    r.m_in.assign(n, std::vector<LD>(3, 0));
    r.m_out.assign(n, std::vector<LD>(3, 0));
    for (std::size_t i = 0; i < n; ++i) {
        // Phantom keys extend the ends in a straight line: p_{−1} = 2p_0 − p_1 at 2t_0 − t_1.
        for (int d = 0; d < r.dim; ++d) {
            const LD tp = i == 0 ? 2 * r.t[0] - r.t[1] : r.t[i - 1];
            const LD pp = i == 0 ? 2 * r.p[0][d] - r.p[1][d] : r.p[i - 1][d];
            const LD tn = i + 1 == n ? 2 * r.t[n - 1] - r.t[n - 2] : r.t[i + 1];
            const LD pn = i + 1 == n ? 2 * r.p[n - 1][d] - r.p[n - 2][d] : r.p[i + 1][d];
            const LD sm = (r.p[i][d] - pp) / (r.t[i] - tp), sp = (pn - r.p[i][d]) / (tn - r.t[i]);
            const LD T = in.keys[i].tension, C = in.keys[i].continuity, B = in.keys[i].bias;
            switch (r.kind) {
                case Interp::Linear:
                    r.m_in[i][d] = sm;
                    r.m_out[i][d] = sp;
                    break;
                case Interp::CatmullRom:
                    r.m_in[i][d] = r.m_out[i][d] = (sm + sp) / 2;
                    break;
                case Interp::KochanekBartels:
                    r.m_in[i][d] = (1 - T) * ((1 - C) * (1 + B) * sm + (1 + C) * (1 - B) * sp) / 2;
                    r.m_out[i][d] = (1 - T) * ((1 + C) * (1 + B) * sm + (1 - C) * (1 - B) * sp) / 2;
                    break;
            }
        }
    }
    return r;
}

// The value and velocity in segment i at time t: a u³ + b u² + c u + d.
void ref_eval(const Ref& r, std::size_t i, LD t, LD* value, LD* velocity) {
    const LD D = r.t[i + 1] - r.t[i], u = (t - r.t[i]) / D;
    for (int d = 0; d < r.dim; ++d) {
        const LD p0 = r.p[i][d], p1 = r.p[i + 1][d];
        if (r.kind == Interp::Linear) {
            value[d] = p0 + u * (p1 - p0);
            velocity[d] = (p1 - p0) / D;
            continue;
        }
        const LD m0 = D * r.m_out[i][d], m1 = D * r.m_in[i + 1][d];
        const LD a = 2 * p0 - 2 * p1 + m0 + m1, b = -3 * p0 + 3 * p1 - 2 * m0 - m1, c = m0;
        value[d] = ((a * u + b) * u + c) * u + p0;
        velocity[d] = ((3 * a * u + 2 * b) * u + c) / D;
    }
}

std::size_t ref_segment(const Ref& r, LD t) {
    std::size_t i = 0;
    while (i + 2 < r.t.size() && t >= r.t[i + 1]) ++i;
    return i;
}

Input random_keys(cg::Rng& rng) {
    Input in;
    in.dim = int(rng.integer(1, 3));
    const int n = int(rng.integer(2, 9));
    const bool equal = rng.chance(0.1);
    const bool extreme = rng.chance(0.2);
    const bool uneven = rng.chance(0.5);
    double t = rng.uniform(-5, 5);
    for (int i = 0; i < n; ++i) {
        Keyframes::Key k;
        k.t = t;
        t += uneven ? rng.uniform(0.01, 3) : 1;
        for (int d = 0; d < in.dim; ++d) k.value[d] = equal ? 2.5 : rng.uniform(-10, 10);
        auto tcb = [&] { return extreme ? double(rng.integer(-1, 1)) : rng.uniform(-1, 1); };
        k.tension = tcb();
        k.continuity = tcb();
        k.bias = tcb();
        in.keys.push_back(k);
    }
    in.interpolation = Interp(rng.integer(0, 2));
    in.dt = (t - in.keys.front().t) / double(rng.integer(5, 60));
    return in;
}

}  // namespace

TEST_CASE("keyframes: the exam's channel by hand", "[animation][keyframes]") {
    // Keys (0, 0), (1, 2), (2, 6), (3, 4). Catmull–Rom: m_0 = 2 (the first slope), m_1 = 3,
    // m_2 = 1, m_3 = −2. At t = 1.5 (u = ½): (2 + 6)/2 + (3 − 1)/8 = 4.25; linear 4; the velocity
    // (h00' p1 + h10' m1 + h01' p2 + h11' m2) = −1.5·2 − 0.25·3 + 1.5·6 − 0.25·1 = 5.
    Input in = scalar({{0, 0}, {1, 2}, {2, 6}, {3, 4}}, Interp::CatmullRom);
    in.has_query = true;
    in.query = 1.5;
    const auto r = Keyframes::compute(in);
    CHECK(r.m_out[0].x == 2);
    CHECK(r.m_out[1].x == 3);
    CHECK(r.m_out[2].x == 1);
    CHECK(r.m_in[3].x == -2);
    CHECK(r.at.catmull_rom.x == Approx(4.25).epsilon(1e-15));
    CHECK(r.at.linear.x == 4);
    CHECK(r.at.catmull_rom_velocity.x == Approx(5).epsilon(1e-15));
    CHECK(r.at.linear_velocity.x == 4);
    CHECK(r.c1);
    CHECK_FALSE(r.c1_linear);
    CHECK(r.c1_catmull_rom);
    CHECK(r.c1_kochanek_bartels);  // T = C = B = 0 is Catmull–Rom
    // Frames every 0.25 s: 13 of them, the last on the last key.
    REQUIRE(r.times.size() == 13);
    CHECK(r.times.back() == 3);
    CHECK(r.values[6].x == Approx(4.25).epsilon(1e-15));
    // Linear: the velocity jumps at key 1 from 2 to 4 and at key 2 from 4 to −2.
    in.interpolation = Interp::Linear;
    const auto l = Keyframes::compute(in);
    CHECK(l.jumps[1].x == 2);
    CHECK(l.jumps[2].x == -6);
    CHECK(l.max_jump == 6);
    CHECK_FALSE(l.c1);
    // Kochanek–Bartels with C = 0.5 at key 1: m⁻ = [(0.5)(2) + (1.5)(4)]/2 = 3.5,
    // m⁺ = [(1.5)(2) + (0.5)(4)]/2 = 2.5 — a jump of −1.
    in.interpolation = Interp::KochanekBartels;
    for (auto& k : in.keys) k.continuity = 0.5;
    const auto kb = Keyframes::compute(in);
    CHECK(kb.m_in[1].x == Approx(3.5));
    CHECK(kb.m_out[1].x == Approx(2.5));
    CHECK(kb.jumps[1].x == Approx(-1));
    CHECK_FALSE(kb.c1);
    // Tension 1 flattens every tangent: the channel eases in and out of every key.
    for (auto& k : in.keys) k.continuity = 0, k.tension = 1;
    const auto flat = Keyframes::compute(in);
    for (const auto& m : flat.m_out) CHECK(m.x == 0);
    CHECK(flat.c1);
}

TEST_CASE("keyframes: 4,000 random key sets against a long-double power-form reference",
          "[animation][keyframes]") {
    cg::Rng rng(2026);
    int equal = 0, two = 0, extreme = 0, kinds[3] = {0, 0, 0};
    for (int trial = 0; trial < 4000; ++trial) {
        const Input in = random_keys(rng);
        CAPTURE(trial, int(in.interpolation), in.dim, in.keys.size());
        const Ref ref = reference(in);
        const auto r = Keyframes::compute(in);
        const auto curve = Keyframes::make_curve(in, in.interpolation);
        // The scale of the numbers: values up to 10, slopes up to 20/0.01.
        LD vscale = 1, sscale = 1;
        for (std::size_t i = 0; i < ref.t.size(); ++i)
            for (int d = 0; d < in.dim; ++d) {
                vscale = std::max(vscale, std::fabs(ref.p[i][d]));
                sscale = std::max({sscale, std::fabs(ref.m_in[i][d]), std::fabs(ref.m_out[i][d])});
            }
        // Tangents.
        for (std::size_t i = 0; i < ref.t.size(); ++i)
            for (int d = 0; d < in.dim; ++d) {
                CHECK(std::fabs(LD(r.m_in[i][d]) - ref.m_in[i][d]) <= 1e-12L * sscale);
                CHECK(std::fabs(LD(r.m_out[i][d]) - ref.m_out[i][d]) <= 1e-12L * sscale);
            }
        // Every frame, and random times.
        REQUIRE(r.times.size() == r.values.size());
        std::vector<LD> times(r.times.begin(), r.times.end());
        for (int q = 0; q < 20; ++q)
            times.push_back(rng.uniform(in.keys.front().t, in.keys.back().t));
        for (std::size_t f = 0; f < times.size(); ++f) {
            const double t = double(times[f]);
            const auto e = Keyframes::evaluate(curve, t);
            LD v[3], dv[3];
            ref_eval(ref, ref_segment(ref, t), t, v, dv);
            for (int d = 0; d < in.dim; ++d) {
                CHECK(std::fabs(LD(e.value[d]) - v[d]) <= 1e-10L * (vscale + sscale));
                CHECK(std::fabs(LD(e.velocity[d]) - dv[d]) <= 1e-10L * sscale * 10);
                if (f < r.times.size()) CHECK(r.values[f][d] == e.value[d]);
            }
        }
        // The keys exactly, from either side: C0.
        for (std::size_t i = 0; i < in.keys.size(); ++i) {
            CHECK(Keyframes::evaluate(curve, in.keys[i].t).value == curve.keys[i].value);
            if (i > 0)
                CHECK(Keyframes::evaluate_in(curve, int(i) - 1, 1.0).value == curve.keys[i].value);
            if (i + 1 < in.keys.size())
                CHECK(Keyframes::evaluate_in(curve, int(i), 0.0).value == curve.keys[i].value);
        }
        // The jumps at the inner keys: the slope difference (linear), 0 (Catmull–Rom),
        // (1−T) C [(1+B) s⁻ − (1−B) s⁺] (Kochanek–Bartels).
        for (std::size_t i = 1; i + 1 < in.keys.size(); ++i)
            for (int d = 0; d < in.dim; ++d) {
                const LD sm = (ref.p[i][d] - ref.p[i - 1][d]) / (ref.t[i] - ref.t[i - 1]);
                const LD sp = (ref.p[i + 1][d] - ref.p[i][d]) / (ref.t[i + 1] - ref.t[i]);
                const LD T = in.keys[i].tension, C = in.keys[i].continuity, B = in.keys[i].bias;
                const LD expect = in.interpolation == Interp::Linear ? sp - sm
                                  : in.interpolation == Interp::CatmullRom
                                      ? 0
                                      : (1 - T) * C * ((1 + B) * sm - (1 - B) * sp);
                CHECK(std::fabs(LD(r.jumps[i][d]) - expect) <= 1e-9L * sscale);
            }
        CHECK(r.c1_catmull_rom);
        if (in.interpolation == Interp::CatmullRom) CHECK(r.max_jump <= 1e-9 * double(sscale));
        equal += in.keys[0].value == in.keys[1].value;
        two += in.keys.size() == 2;
        extreme += std::fabs(in.keys[0].tension) == 1 || std::fabs(in.keys[0].continuity) == 1;
        ++kinds[int(in.interpolation)];
    }
    CHECK(equal > 200);
    CHECK(two > 300);
    CHECK(extreme > 300);
    CHECK(kinds[0] > 1000);
    CHECK(kinds[1] > 1000);
    CHECK(kinds[2] > 1000);
}

TEST_CASE("keyframes: two keys, equal values, repeated times", "[animation][keyframes]") {
    // Two keys: Catmull–Rom takes the one slope at both ends, so it is the straight line.
    const Input two = scalar({{1, 3}, {3, 7}}, Interp::CatmullRom, 0.1);
    const auto c = Keyframes::compute(two);
    Input lin = two;
    lin.interpolation = Interp::Linear;
    const auto l = Keyframes::compute(lin);
    REQUIRE(c.values.size() == l.values.size());
    for (std::size_t f = 0; f < c.values.size(); ++f) {
        CHECK(c.values[f].x == Approx(l.values[f].x).epsilon(1e-14));
        CHECK(c.velocities[f].x == Approx(2).epsilon(1e-14));
    }
    CHECK(c.c1);
    CHECK(l.c1);  // no inner key: nothing to jump
    // Equal values: flat, velocity exactly 0, whatever the interpolation and T, C, B.
    for (Interp k : {Interp::Linear, Interp::CatmullRom, Interp::KochanekBartels}) {
        Input flat = scalar({{0, 5}, {1, 5}, {1.5, 5}, {4, 5}}, k, 0.1);
        for (auto& key : flat.keys) key.tension = -1, key.continuity = 1, key.bias = -1;
        const auto r = Keyframes::compute(flat);
        for (std::size_t f = 0; f < r.values.size(); ++f) {
            CHECK(r.values[f].x == Approx(5).epsilon(1e-15));
            CHECK(r.velocities[f].x == 0);
        }
        CHECK(r.c1);
    }
    // A repeated time names both keys; a time going back says the keys must be in order.
    CHECK(err(R"({"keys": [{"t": 0, "value": 1}, {"t": 1, "value": 2}, {"t": 1, "value": 3}]})") ==
          "keys[2].t: repeats the time of keys[1] (1): two values at one time are no function of "
          "time");
    CHECK(err(R"({"keys": [{"t": 0, "value": 1}, {"t": 2, "value": 2}, {"t": 1, "value": 3}]})")
              .find("keys[2].t: must be later than keys[1].t = 2") == 0);
    CHECK(err(R"({"keys": [{"t": 0, "value": 1}]})").find("keys: must have at least 2 keys") == 0);
}

TEST_CASE("keyframes: bad input names the field and the reason", "[animation][keyframes]") {
    const std::string k2 = R"("keys": [{"t": 0, "value": 1}, {"t": 1, "value": 2}])";
    CHECK(err(R"({})").find("keys: is missing") == 0);
    CHECK(err(R"({"keys": 3})").find("keys: must be a list of keys") == 0);
    CHECK(err(R"({"keys": [{"t": 0, "value": 1}, {"t": 1, "value": [1, 2]}]})")
              .find("keys[1].value: must be a number like keys[0].value") == 0);
    CHECK(err(R"({"keys": [{"t": 0, "value": "a"}, {"t": 1, "value": 2}]})")
              .find("keys[0].value: must be a number or a point") == 0);
    CHECK(err(R"({"keys": [{"t": 0, "value": 1, "tension": 1.5}, {"t": 1, "value": 2}]})")
              .find("keys[0].tension: must lie in [−1, 1]") == 0);
    CHECK(err("{" + k2 + R"(, "bias": -2})").find("keys[0].bias: must lie in [−1, 1]") == 0);
    CHECK(err("{" + k2 + R"(, "dt": 0})").find("dt: must be a time step > 0") == 0);
    CHECK(err("{" + k2 + R"(, "dt": 1e-9})").find("dt: gives more than 100000 frames") == 0);
    CHECK(err("{" + k2 + R"(, "interpolation": "bezier"})").find("interpolation: must be") == 0);
    CHECK(err("{" + k2 + R"(, "constant_speed": true})").find("constant_speed: needs a path") == 0);
    CHECK(err("{" + k2 + R"(, "query": 2})").find("query: must lie between") == 0);
    CHECK(err("{" + k2 + R"(, "samples": 0})").find("samples: must be 1 to 10000") == 0);
    CHECK(err(R"({"keys": [{"t": 0, "value": 1}, {"t": 1e7, "value": 2}]})")
              .find("keys[1].t: is too large") == 0);
    CHECK(err("{" + k2 + R"(, "speed": 1})").find("speed") != std::string::npos);
    CHECK(err("{" + k2 + "}") == "(accepted)");
}

TEST_CASE("keyframes: constant speed along a path by the arc-length table",
          "[animation][keyframes]") {
    // A path whose keys are unevenly far apart in equal times: the naive speed varies a lot.
    const auto j = cg::json::parse(R"({
        "keys": [{"t": 0, "value": [0, 0]}, {"t": 1, "value": [1, 0]}, {"t": 2, "value": [6, 2]},
                 {"t": 3, "value": [7, 5]}],
        "interpolation": "catmull-rom", "dt": 0.05, "constant_speed": true, "samples": 200})");
    const Input in = input_of(j);
    const auto r = Keyframes::compute(in);
    REQUIRE(r.even.size() == r.times.size());
    CHECK(r.speed_max > 3 * r.speed_min);
    // The table's length below the true one, and close for N = 200.
    CHECK(r.length <= r.length_exact + 1e-12);
    CHECK(r.length == Approx(r.length_exact).epsilon(1e-4));
    // A long-double chord table of the same path, inverted by hand: the even points agree, and
    // consecutive even points are (nearly) equally far apart.
    const auto curve = Keyframes::make_curve(in, in.interpolation);
    const int N = in.samples;
    std::vector<LD> us, ss;
    glm::dvec3 prev{0};
    for (int q = 0; q <= N; ++q) {
        const LD u = LD(3) * q / N;
        const glm::dvec3 pt = Keyframes::evaluate(curve, double(u)).value;
        us.push_back(u);
        ss.push_back(q == 0 ? 0 : ss.back() + LD(glm::length(pt - prev)));
        prev = pt;
    }
    const LD L = ss.back();
    CHECK(std::fabs(LD(r.length) - L) <= 1e-12L * L);
    // The arc length between two parameters, by 64 fine chords.
    auto arc = [&](LD ua, LD ub) {
        LD sum = 0;
        glm::dvec3 a = Keyframes::evaluate(curve, double(ua)).value;
        for (int q = 1; q <= 64; ++q) {
            const glm::dvec3 b = Keyframes::evaluate(curve, double(ua + (ub - ua) * q / 64)).value;
            sum += glm::length(b - a);
            a = b;
        }
        return sum;
    };
    LD lo = 1e9, hi = 0, naive_lo = 1e9, naive_hi = 0, u_prev = 0;
    for (std::size_t f = 0; f < r.times.size(); ++f) {
        const LD s = L * r.times[f] / 3;
        std::size_t q = 0;
        while (q + 1 < ss.size() - 1 && ss[q + 1] < s) ++q;
        const LD u = us[q] + (s - ss[q]) / (ss[q + 1] - ss[q]) * (us[q + 1] - us[q]);
        const glm::dvec3 pt = Keyframes::evaluate(curve, double(u)).value;
        CHECK(glm::length(pt - r.even[f]) <= 1e-9);
        if (f > 0) {
            const LD step = arc(u_prev, u), naive = arc(r.times[f - 1], r.times[f]);
            lo = std::min(lo, step), hi = std::max(hi, step);
            naive_lo = std::min(naive_lo, naive), naive_hi = std::max(naive_hi, naive);
        }
        u_prev = u;
    }
    // Equal arcs per frame, up to the table's linear interpolation (the last frame is whole:
    // dt divides the span); the naive motion's arcs differ more than threefold.
    CAPTURE(double(lo), double(hi), double(naive_lo), double(naive_hi));
    CHECK(hi <= 1.005L * lo);
    CHECK(naive_hi > 3 * naive_lo);
    CHECK(glm::length(r.even.back() - glm::dvec3(7, 5, 0)) <= 1e-9);  // u_{N−1} + 1·Δu ≈ u_N
    CHECK(r.even.front() == glm::dvec3(0, 0, 0));
}

TEST_CASE("keyframes: the state machine gives what compute gives, frame by frame",
          "[animation][keyframes]") {
    cg::Rng rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        CAPTURE(trial);
        Input in = random_keys(rng);
        if (in.dim > 1 && trial % 2 == 0) in.constant_speed = true;
        const auto traced = cg::test::run_traced<Keyframes>(in);
        const auto r = Keyframes::compute(in);
        CHECK(traced.result == r);
        CHECK(cg::run_to_end<Keyframes>(Keyframes::start(in)) == r);
        const auto ev = cg::test::events(traced);
        REQUIRE(ev.size() == r.times.size() + 2 + (in.constant_speed ? 1 : 0));
        CHECK(ev.front() == "tangents");
        CHECK(ev.back() == "summary");
        // Each frame's narrated variables are the frame's numbers; the clock never goes back.
        double clock = -1e300;
        std::size_t f = 0;
        for (const auto& st : traced.steps) {
            REQUIRE(!st.vars.empty());
            CHECK(st.vars[0].name == "t");
            const double t = std::get<double>(st.vars[0].value);
            CHECK(t >= clock);
            clock = t;
            if (st.event != "frame" && st.event != "key") continue;
            CHECK(t == r.times[f]);
            for (const auto& v : st.vars)
                if (v.name == "p" && in.dim == 1) CHECK(std::get<double>(v.value) == r.values[f].x);
            ++f;
        }
        CHECK(f == r.times.size());
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const auto j = cg::test::result_of("keyframes", p.input);
        CHECK(all_finite(j));
    }
}

TEST_CASE("keyframes: replay on the example and the presets", "[animation][keyframes]") {
    const auto& a = cg::test::algorithm("keyframes");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 4);
    }
}

TEST_CASE("keyframes: a frame narrates segment, u, the basis and the tangents",
          "[animation][keyframes]") {
    const Input in = scalar({{0, 0}, {1, 2}, {2, 6}, {3, 4}}, Interp::CatmullRom, 0.5);
    const auto t = cg::test::run_traced<Keyframes>(in);
    // Steps: tangents, frames t = 0, 0.5, 1, 1.5, …, summary.
    REQUIRE(t.steps.size() == 9);
    const auto& mid = t.steps[4];  // t = 1.5
    CAPTURE(mid.narration);
    CHECK(mid.event == "frame");
    CHECK(mid.narration.find("segment 1 [1, 2], u = (1.5 − 1)/1 = 0.5") != std::string::npos);
    CHECK(mid.narration.find("h00 = 0.5, h10 = 0.125, h01 = 0.5, h11 = −0.125") !=
          std::string::npos);
    CHECK(mid.narration.find("Δ m⁺_1 = 3") != std::string::npos);
    CHECK(mid.narration.find("p = 4.25") != std::string::npos);
    const auto& key = t.steps[3];  // t = 1, key 1
    CHECK(key.event == "key");
    CHECK(key.narration.find("no jump, C1 here") != std::string::npos);
    Input lin = in;
    lin.interpolation = Interp::Linear;
    const auto tl = cg::test::run_traced<Keyframes>(lin);
    CHECK(tl.steps[3].narration.find("a jump of 2") != std::string::npos);
    CHECK(tl.steps.back().narration.find("not C1") != std::string::npos);
}

TEST_CASE("keyframes: exam problems, worked by hand", "[animation][keyframes][exam]") {
    const auto& a = cg::test::algorithm("keyframes");
    int value = 0, tangent = 0, c1 = 0, line = 0, flat = 0;
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = input_of(p.input);
        REQUIRE(in.keys.size() == 4);
        std::vector<LD> v;
        for (const auto& k : in.keys) v.push_back(k.value.x);
        // Catmull–Rom tangents for keys 1 s apart; the ends take their one slope.
        const LD m[4] = {v[1] - v[0], (v[2] - v[0]) / 2, (v[3] - v[1]) / 2, v[3] - v[2]};
        if (p.answers[0] == "at/linear") {
            ++value;
            const std::size_t i = std::size_t(in.query);
            CHECK(p.expected["at/linear"].get<double>() == Approx(double((v[i] + v[i + 1]) / 2)));
            CHECK(p.expected["at/catmull_rom"].get<double>() ==
                  Approx(double((v[i] + v[i + 1]) / 2 + (m[i] - m[i + 1]) / 8)).margin(1e-12));
            flat += v[0] == v[1] && v[1] == v[2] && v[2] == v[3];
        } else if (p.answers[0] == "at/catmull_rom_velocity") {
            ++tangent;
            const std::size_t i = std::size_t(in.query);
            const LD T = in.keys[i].tension, C = in.keys[i].continuity, B = in.keys[i].bias;
            const LD out =
                (1 - T) *
                ((1 + C) * (1 + B) * (v[i] - v[i - 1]) + (1 - C) * (1 - B) * (v[i + 1] - v[i])) / 2;
            CHECK(p.expected["at/catmull_rom_velocity"].get<double>() ==
                  Approx(double(m[i])).margin(1e-12));
            CHECK(p.expected["at/kochanek_bartels_velocity"].get<double>() ==
                  Approx(double(out)).margin(1e-12));
        } else {
            ++c1;
            REQUIRE(p.answers.size() == 3);
            const bool collinear = v[1] - v[0] == v[2] - v[1] && v[2] - v[1] == v[3] - v[2];
            line += collinear;
            const LD T = in.keys[0].tension, C = in.keys[0].continuity, B = in.keys[0].bias;
            bool kb = true;
            for (int i = 1; i <= 2; ++i)
                kb = kb &&
                     (1 - T) * C * ((1 + B) * (v[i] - v[i - 1]) - (1 - B) * (v[i + 1] - v[i])) == 0;
            CHECK(p.expected["c1_at_keys/linear"].get<bool>() == collinear);
            CHECK(p.expected["c1_at_keys/catmull_rom"].get<bool>());
            CHECK(p.expected["c1_at_keys/kochanek_bartels"].get<bool>() == kb);
        }
    }
    CHECK(value > 150);
    CHECK(tangent > 60);
    CHECK(c1 > 60);
    CHECK(line > 5);
    CHECK(flat > 5);
}

TEST_CASE("keyframes: the picture shows the jumps and the spacing", "[animation][keyframes]") {
    auto jumps = [](const Input& in) {
        auto s = Keyframes::start(in);
        for (int k = 0; k < 5; ++k) Keyframes::step(s, nullptr);
        cg::Scene scene;
        Keyframes::draw(s, scene);
        // Two charts against t (s): the value with its keys and the frame's dot, the velocity.
        REQUIRE(scene.panels.size() == 2);
        CHECK_FALSE(scene.has_2d());  // nothing on the world's grid
        const cg::Panel& value = scene.panels[0];
        const cg::Panel& velocity = scene.panels[1];
        CHECK(value.kind == cg::PanelKind::Chart);
        CHECK(value.x.label == "t (s)");
        CHECK(velocity.x.label == "t (s)");
        CHECK(value.points.size() >= in.keys.size() + 1);
        CHECK(value.legend.front().style.role == cg::Role::Active);  // the chosen curve first
        CHECK(velocity.legend.size() == value.legend.size());
        int n = 0;
        for (const auto& seg : velocity.segments) n += seg.label == "jump";
        return n;
    };
    const Input cr = scalar({{0, 0}, {1, 2}, {2, 6}, {3, 4}}, Interp::CatmullRom);
    Input lin = cr;
    lin.interpolation = Interp::Linear;
    CHECK(jumps(cr) == 0);
    CHECK(jumps(lin) == 2);
    // A path at constant speed: a dot per frame so far in each colour.
    const Input path = input_of(cg::json::parse(R"({
        "keys": [{"t": 0, "value": [0, 0]}, {"t": 1, "value": [1, 0]}, {"t": 2, "value": [6, 2]}],
        "dt": 0.1, "constant_speed": true})"));
    auto s = Keyframes::start(path);
    for (int k = 0; k < 12; ++k) Keyframes::step(s, nullptr);
    cg::Scene scene;
    Keyframes::draw(s, scene);
    int green = 0;
    for (const auto& pt : scene.points) green += pt.style.role == cg::Role::Kept;
    CHECK(green == 11);  // 10 frames so far plus the current point, in the world
    // The speed against time in a chart from 0, with the constant speed L/T.
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& speed = scene.panels[0];
    CHECK(speed.kind == cg::PanelKind::Chart);
    CHECK(speed.y.include_zero);
    REQUIRE(speed.legend.size() == 2);
    CHECK(speed.legend[1].style.role == cg::Role::Kept);
}
