// Orientation interpolation: exam cases worked by hand (slerp at u = 1/4, the flip to the short
// way, the matrix blend's det of 1/2, the Euler midpoint against the slerp midpoint); on 3,000
// seeded random inputs (Euler, axis-angle and quaternion keys in all six orders; identical,
// antipodal ±q and nearly identical keys) every frame against an independent long-double
// implementation (slerp in closed form, squad with its own log/exp, the matrix blend's det and
// orthogonality error, the angular speeds) and against GLM (glm::slerp and glm::mat3_cast,
// glm::squad with glm::intermediate, the Euler composition by glm::rotate); slerp's constant
// speed; squad through the keys with a continuous angular velocity; the Euler extraction in
// every order; the state machine equals compute, through the registry too; bad input naming
// the field; replay; the exam problems against a hand computation; the narration; the picture.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include "animation/orientation_interpolation.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"
#include "transforms/slerp.hpp"

using cg::OrientationInterpolation;
using OI = OrientationInterpolation;
using Input = OI::Input;
using Key = OI::Key;
using glm::dmat3;
using glm::dquat;
using glm::dvec3;
using LD = long double;

namespace {

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("orientation-interpolation");
    if (!l) throw std::runtime_error("no lesson for orientation-interpolation");
    return *l;
}

std::string err(const std::string& text) {
    return cg::test::error_of("orientation-interpolation", text);
}

Key euler_key(dvec3 e) {
    Key k;
    k.form = OI::Form::Euler;
    k.euler_deg = e;
    return k;
}
Key axis_key(dvec3 axis, double deg) {
    Key k;
    k.form = OI::Form::AxisAngle;
    k.axis = axis;
    k.angle_deg = deg;
    return k;
}
Key quat_key(dquat q) {
    Key k;
    k.form = OI::Form::Quaternion;
    k.q = q;
    return k;
}

// ---- the reference: quaternions in long double, written separately ----

struct Q {
    LD w = 1, x = 0, y = 0, z = 0;
};
Q from(const dquat& q) {
    return {q.w, q.x, q.y, q.z};
}
Q operator+(Q a, Q b) {
    return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
}
Q operator*(LD s, Q a) {
    return {s * a.w, s * a.x, s * a.y, s * a.z};
}
Q mul(Q a, Q b) {  // Hamilton product
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
Q conj(Q a) {
    return {a.w, -a.x, -a.y, -a.z};
}
LD dot(Q a, Q b) {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
Q normalised(Q a) {
    return (1 / std::sqrt(dot(a, a))) * a;
}
// slerp in the closed form ω = acos(q0 · q1), the shorter way, normalised lerp when sin ω = 0.
Q slerp(Q a, Q b, LD u, bool short_way = true) {
    LD d = dot(a, b);
    if (d < 0 && short_way) b = LD(-1) * b, d = -d;
    const LD w = std::acos(std::clamp<LD>(d, -1, 1));
    if (std::sin(w) < 1e-15L) return normalised(LD(1 - u) * a + u * b);
    return (std::sin((1 - u) * w) / std::sin(w)) * a + (std::sin(u * w) / std::sin(w)) * b;
}
Q qlog(Q q) {  // unit q: (0, θ v̂)
    const LD s = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (s == 0) return {0, 0, 0, 0};
    const LD t = std::atan2(s, q.w) / s;
    return {0, t * q.x, t * q.y, t * q.z};
}
Q qexp(Q v) {
    const LD t = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (t == 0) return {1, 0, 0, 0};
    const LD s = std::sin(t) / t;
    return {std::cos(t), s * v.x, s * v.y, s * v.z};
}
// The turn between two orientations, degrees in [0, 180].
LD turn(Q a, Q b) {
    const Q r = mul(b, conj(a));
    return 2 * std::atan2(std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z), std::fabs(r.w)) * 180 /
           3.14159265358979323846264338327950288L;
}

struct M3 {
    LD a[3][3];  // rows
};
M3 matrix(Q q) {
    const LD w = q.w, x = q.x, y = q.y, z = q.z;
    return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
             {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
             {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}
LD det(const M3& m) {
    const auto& a = m.a;
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}
LD orth_error(const M3& m) {
    LD e = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            LD s = 0;
            for (int k = 0; k < 3; ++k) s += m.a[k][i] * m.a[k][j];
            e = std::max(e, std::fabs(s - (i == j ? 1 : 0)));
        }
    return e;
}

double qdiff(const dquat& a, const dquat& b) {
    return std::max({std::fabs(a.w - b.w), std::fabs(a.x - b.x), std::fabs(a.y - b.y),
                     std::fabs(a.z - b.z)});
}
double qdiff(const dquat& a, Q b) {
    return qdiff(a, dquat(double(b.w), double(b.x), double(b.y), double(b.z)));
}

// R = R_c(θ3) R_b(θ2) R_a(θ1) composed by glm::rotate, for the order "abc".
dmat3 composed(const std::string& order, dvec3 e) {
    glm::dmat4 r(1.0);
    for (int n = 0; n < 3; ++n) {
        dvec3 axis(0);
        axis[order[std::size_t(n)] - 'x'] = 1;
        r = glm::rotate(glm::dmat4(1.0), glm::radians(e[n]), axis) * r;
    }
    return dmat3(r);
}

const char* const kOrders[] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx"};

dquat random_unit(cg::Rng& rng) {
    dquat q;
    do q = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    while (glm::length(q) < 0.1);
    return glm::normalize(q);
}

// Degenerate pairs on purpose: an identical key, an antipodal −q, a nearly identical one.
Input random_input(cg::Rng& rng) {
    Input in;
    in.order = kOrders[rng.integer(0, 5)];
    const int n = int(rng.integer(2, 5));
    for (int i = 0; i < n; ++i) {
        const double kind = rng.uniform(0, 1);
        if (i > 0 && kind < 0.2) {
            // A copy of the one before as a quaternion: the same, −q, or off by 1e-9 / 1e-14.
            glm::dmat3 m;
            dvec3 e;
            dquat q;
            OI::key_forms(in.keys.back(), in.order, q, m, e);
            const int how = int(rng.integer(0, 3));
            const double eps = how == 2 ? 1e-9 : 1e-14;
            if (how == 1) q = -q;
            if (how >= 2)
                q = glm::normalize(q + dquat(eps * rng.uniform(-1, 1), eps * rng.uniform(-1, 1),
                                             eps * rng.uniform(-1, 1), eps * rng.uniform(-1, 1)));
            in.keys.push_back(quat_key(q));
        } else if (kind < 0.5) {
            dvec3 e{rng.uniform(-180, 180), rng.uniform(-90, 90), rng.uniform(-180, 180)};
            if (rng.chance(0.1)) e.y = rng.chance(0.5) ? 90 : -90;  // at the lock
            if (rng.chance(0.1)) e.x += 360;                         // a whole extra turn
            in.keys.push_back(euler_key(e));
        } else if (kind < 0.75) {
            in.keys.push_back(axis_key({rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)},
                                       rng.uniform(-360, 360)));
        } else {
            in.keys.push_back(quat_key(rng.uniform(0.5, 2) * random_unit(rng)));
        }
    }
    in.frames = int(rng.integer(1, 12));
    in.segment_time = rng.uniform(0.1, 3);
    return in;
}

}  // namespace

TEST_CASE("orientation-interpolation: exam cases worked by hand", "[animation][orientation-interpolation]") {
    const double h = std::sqrt(0.5);
    SECTION("identity to a quarter turn about z: ω = 45°, slerp at u = 1/4 turns 22.5°") {
        Input in;
        in.keys = {quat_key({1, 0, 0, 0}), quat_key({h, 0, 0, h})};
        in.frames = 4;
        const auto t = cg::test::run_traced<OI>(in);
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"key", "key", "align", "frame", "frame", "frame", "frame",
                                       "frame", "summary"});
        CHECK(t.result.keys.omega_deg[0] == Approx(45).epsilon(1e-14));
        const double a = M_PI / 16;  // half of 22.5°
        CHECK(qdiff(t.result.frames[1].slerp, dquat(std::cos(a), 0, 0, std::sin(a))) < 1e-15);
        // Slerp: 90° in one second, exactly; the Euler lerp of (0, 0, 0) → (0, 0, 90) agrees.
        for (int k = 1; k <= 4; ++k) {
            CHECK(t.result.frames[std::size_t(k)].speed_slerp == Approx(90).epsilon(1e-12));
            CHECK(t.result.frames[std::size_t(k)].speed_euler == Approx(90).epsilon(1e-12));
        }
        // Half way the matrix blend is (I + R_z(90°))/2: det 1/2, columns of length √2/2.
        const auto& mid = t.result.frames[2];
        CHECK(mid.det == Approx(0.5).epsilon(1e-15));
        CHECK(mid.orth_error == Approx(0.5).epsilon(1e-15));
        CHECK(cg::rot::max_diff(mid.matrix, dmat3(dvec3(0.5, 0.5, 0), dvec3(-0.5, 0.5, 0),
                                                  dvec3(0, 0, 1))) < 1e-15);
        CHECK(t.result.min_det == Approx(0.5));
        CHECK_THAT(t.steps[2].narration, Catch::Contains("ω = acos(0.707107) = 45°"));
        CHECK_THAT(t.steps[4].narration,
                   Catch::Contains("w0 = sin((1−u)ω)/sin ω = 0.7857, w1 = sin(uω)/sin ω = 0.2759"));
    }
    SECTION("the second key given as −q: flipped, the short 45° and not 135°") {
        Input in;
        in.keys = {quat_key({1, 0, 0, 0}), quat_key({-h, 0, 0, -h})};
        in.frames = 2;
        const auto t = cg::test::run_traced<OI>(in);
        CHECK(t.steps[2].event == "flip");
        CHECK(t.result.keys.flipped[0]);
        CHECK(t.result.keys.omega_deg[0] == Approx(45));
        CHECK(qdiff(t.result.keys.q[1], dquat(h, 0, 0, h)) < 1e-15);
        CHECK(qdiff(t.result.frames[1].slerp,
                    dquat(std::cos(M_PI / 8), 0, 0, std::sin(M_PI / 8))) < 1e-15);
        CHECK_THAT(t.steps[2].narration, Catch::Contains("instead of 135°"));
    }
    SECTION("Euler (0, 0, 0) → (90, 90, 0): the lerped midpoint is not the slerp midpoint") {
        Input in;
        in.keys = {euler_key({0, 0, 0}), euler_key({90, 90, 0})};
        in.frames = 2;
        const auto r = OI::compute(in);
        CHECK(r.frames[1].euler_deg == dvec3(45, 45, 0));
        // q1 = q_y(90) q_x(90) = (1/2, 1/2, 1/2, −1/2); slerp half way = (q0 + q1)/|q0 + q1|.
        CHECK(qdiff(r.keys.q[1], dquat(0.5, 0.5, 0.5, -0.5)) < 1e-15);
        const double n = std::sqrt(1.5 * 1.5 + 3 * 0.25);
        CHECK(qdiff(r.frames[1].slerp, dquat(1.5 / n, 0.5 / n, 0.5 / n, -0.5 / n)) < 1e-15);
        // The two midpoints differ by a visible turn.
        CHECK(OI::turn_deg(r.frames[1].slerp, r.frames[1].euler_q) > 10);
    }
    SECTION("a half turn about x: the matrix blend flattens the object (det 0)") {
        Input in;
        in.keys = {axis_key({1, 0, 0}, 0), axis_key({1, 0, 0}, 180)};
        in.frames = 2;
        const auto r = OI::compute(in);
        CHECK(r.frames[1].det == 0);
        CHECK(cg::rot::max_diff(r.frames[1].matrix, dmat3(dvec3(1, 0, 0), dvec3(0), dvec3(0))) ==
              0);
        CHECK(r.keys.omega_deg[0] == Approx(90));
    }
}

TEST_CASE("orientation-interpolation: 3,000 random inputs against long double and GLM",
          "[animation][orientation-interpolation]") {
    cg::Rng rng(2026);
    int pairs = 0, identical = 0, antipodal = 0, near = 0, flips = 0, glm_squads = 0, locked = 0,
        glm_opposite = 0, glm_compared = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Input in = random_input(rng);
        CAPTURE(trial, in.order, in.frames, in.keys.size());
        const auto r = OI::compute(in);
        const std::size_t n = in.keys.size();
        REQUIRE(r.frames.size() == std::size_t(in.frames) * (n - 1) + 1);
        // The keys: each the rotation it was given as, signs chained the short way.
        for (std::size_t i = 0; i < n; ++i) {
            const Key& k = in.keys[i];
            const dmat3 m = cg::Slerp::to_matrix(r.keys.q[i]);
            dmat3 want;
            if (k.form == OI::Form::Euler)
                want = composed(in.order, k.euler_deg);
            else if (k.form == OI::Form::AxisAngle)
                want = glm::mat3_cast(glm::angleAxis(glm::radians(k.angle_deg), glm::normalize(k.axis)));
            else
                want = glm::mat3_cast(glm::normalize(k.q));
            REQUIRE(cg::rot::max_diff(m, want) < 1e-12);
            // The Euler angles used rebuild the key (rot::euler_xyz_of keeps about 8 digits
            // within 1e-8 of the lock, where it divides by cos θ2).
            REQUIRE(cg::rot::max_diff(composed(in.order, r.keys.e[i]), want) < 1e-6);
            locked += k.form == OI::Form::Euler && std::fabs(k.euler_deg.y) == 90;
            if (i + 1 < n) {
                REQUIRE(glm::dot(r.keys.q[i], r.keys.q[i + 1]) >= 0);
                ++pairs;
                flips += r.keys.flipped[i] != 0;
                const double d = OI::turn_deg(r.keys.q[i], r.keys.q[i + 1]);
                identical += d < 1e-10;
                near += d >= 1e-10 && d < 1e-5;
                antipodal += r.keys.flipped[i] && d < 1e-5;
            }
        }
        // Squad's control points by the world-frame formula, in long double.
        std::vector<Q> q, s;
        for (const auto& k : r.keys.q) q.push_back(from(k));
        s = q;
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const Q inv = conj(q[i]);
            const Q l = qlog(mul(q[i + 1], inv)) + qlog(mul(q[i - 1], inv));
            s[i] = mul(qexp(LD(-0.25) * l), q[i]);
        }
        // GLM's squad and control points.
        const bool glm_ok = n >= 3;
        std::vector<dquat> gs(r.keys.q.begin(), r.keys.q.end());
        for (std::size_t i = 1; i + 1 < n; ++i)
            gs[i] = glm::intermediate(r.keys.q[i - 1], r.keys.q[i], r.keys.q[i + 1]);
        glm_squads += glm_ok;
        const LD dt = LD(in.segment_time) / in.frames;
        for (std::size_t k = 0; k < r.frames.size(); ++k) {
            const auto& f = r.frames[k];
            const std::size_t i = std::size_t(f.segment);
            const LD u = LD(k - i * std::size_t(in.frames)) / in.frames;
            CAPTURE(k, i, double(u));
            REQUIRE(f.u == Approx(double(u)).margin(1e-15));
            REQUIRE(double(f.t) == Approx(double(k * dt)).epsilon(1e-14));
            // Slerp: the closed form, and glm::slerp.
            const Q sl = slerp(q[i], q[i + 1], u);
            REQUIRE(qdiff(f.slerp, sl) < 1e-12);
            const dquat g = glm::slerp(r.keys.q[i], r.keys.q[i + 1], double(u));
            REQUIRE(cg::rot::max_diff(cg::Slerp::to_matrix(f.slerp), glm::mat3_cast(g)) < 1e-9);
            // Squad.
            // Squad's slerps take the arc as given (no sign choice).
            const Q sq =
                n >= 3 ? slerp(sl, slerp(s[i], s[i + 1], u, false), 2 * u * (1 - u), false) : sl;
            REQUIRE(turn(from(f.squad), sq) < 1e-9);
            // glm::mix divides by sin(acos(cos θ)), which loses all its digits where two of its
            // quaternions are nearly opposite (a turn of almost 360°): those frames are skipped.
            const double outer = glm::dot(glm::mix(r.keys.q[i], r.keys.q[i + 1], double(u)),
                                          glm::mix(gs[i], gs[i + 1], double(u)));
            // And glm::exp of a zero vector returns glm's default quaternion, which is not the
            // identity, so glm::intermediate fails for a key equal to both its neighbours.
            const bool opposite = outer < -0.999 || glm::dot(gs[i], gs[i + 1]) < -0.999 ||
                                  std::fabs(glm::length(gs[i]) - 1) > 1e-9 ||
                                  std::fabs(glm::length(gs[i + 1]) - 1) > 1e-9;
            glm_opposite += glm_ok && opposite;
            glm_compared += glm_ok && !opposite;
            if (glm_ok && !opposite) {
                const dquat gq = glm::squad(r.keys.q[i], r.keys.q[i + 1], gs[i], gs[i + 1], double(u));
                REQUIRE(cg::rot::max_diff(cg::Slerp::to_matrix(f.squad),
                                          glm::mat3_cast(glm::normalize(gq))) < 1e-9);
            }
            // Matrix blend: det and orthogonality error.
            const M3 a = matrix(q[i]), b = matrix(q[i + 1]);
            M3 m;
            for (int x = 0; x < 3; ++x)
                for (int y = 0; y < 3; ++y) m.a[x][y] = (1 - u) * a.a[x][y] + u * b.a[x][y];
            for (int x = 0; x < 3; ++x)
                for (int y = 0; y < 3; ++y)
                    REQUIRE(std::fabs(f.matrix[y][x] - double(m.a[x][y])) < 1e-15);
            REQUIRE(std::fabs(f.det - double(det(m))) < 1e-13);
            REQUIRE(std::fabs(f.orth_error - double(orth_error(m))) < 1e-13);
            // Euler: the angles lerped, then composed directly.
            const dvec3 e = double(1 - u) * r.keys.e[i] + double(u) * r.keys.e[i + 1];
            REQUIRE(glm::length(f.euler_deg - e) < 1e-12);
            REQUIRE(cg::rot::max_diff(cg::Slerp::to_matrix(f.euler_q), composed(in.order, e)) < 1e-12);
            // The angular speeds from the frame before.
            if (k > 0) {
                const auto& p = r.frames[k - 1];
                REQUIRE(f.speed_slerp == Approx(double(turn(from(p.slerp), sl) / dt)).margin(1e-7));
                REQUIRE(f.speed_euler ==
                        Approx(double(turn(from(p.euler_q), from(f.euler_q)) / dt)).margin(1e-7));
            } else {
                REQUIRE(f.speed_slerp == 0);
            }
        }
    }
    CAPTURE(pairs, identical, antipodal, near, flips, glm_squads, locked, glm_opposite, glm_compared);
    CHECK(pairs > 7000);
    CHECK(identical > 150);
    CHECK(antipodal > 100);
    CHECK(near > 150);
    CHECK(flips > 1000);
    CHECK(glm_squads > 300);
    CHECK(locked > 50);
    CHECK(glm_compared > 10 * glm_opposite);
    CHECK(glm_compared > 20000);
}

TEST_CASE("orientation-interpolation: slerp's speed is constant, squad's continuous at the keys",
          "[animation][orientation-interpolation]") {
    cg::Rng rng(7);
    int jumps = 0;
    double worst_squad = 0;
    for (int trial = 0; trial < 200; ++trial) {
        CAPTURE(trial);
        Input in;
        for (int i = 0; i < 4; ++i) in.keys.push_back(quat_key(random_unit(rng)));
        in.frames = 100;
        in.segment_time = 0.5;
        const auto r = OI::compute(in);
        for (std::size_t k = 1; k < r.frames.size(); ++k) {
            const auto& f = r.frames[k];
            // Within a segment, 2ω per segment_time exactly.
            const std::size_t i = std::size_t(std::min<std::size_t>((k - 1) / 100, 2));
            REQUIRE(f.speed_slerp ==
                    Approx(2 * r.keys.omega_deg[i] / in.segment_time).epsilon(1e-9));
        }
        // Squad passes through every key; its speed just before and after an inner key agree
        // (to the frame's O(dt) difference), where slerp's jumps from one ω to the next.
        for (int key = 0; key < 4; ++key) {
            const auto& f = r.frames[std::size_t(key * 100)];
            CHECK(OI::turn_deg(f.squad, r.keys.q[std::size_t(key)]) < 1e-9);
            CHECK(OI::turn_deg(f.slerp, r.keys.q[std::size_t(key)]) < 1e-9);
        }
        for (int key = 1; key < 3; ++key) {
            const std::size_t k = std::size_t(key * 100);
            const double before = r.frames[k].speed_squad, after = r.frames[k + 1].speed_squad;
            const double scale = std::max(1.0, r.speed_max[2]);
            worst_squad = std::max(worst_squad, std::fabs(before - after) / scale);
            jumps += std::fabs(r.frames[k].speed_slerp - r.frames[k + 1].speed_slerp) > 0.05 * scale;
        }
    }
    CAPTURE(worst_squad, jumps);
    CHECK(worst_squad < 0.05);
    CHECK(jumps > 200);  // slerp's speed jumps at most of the 400 inner keys
}

TEST_CASE("orientation-interpolation: Euler angles read back in every order, log and exp",
          "[animation][orientation-interpolation]") {
    cg::Rng rng(11);
    for (const char* order : kOrders) {
        for (int trial = 0; trial < 500; ++trial) {
            dvec3 e{rng.uniform(-180, 180), rng.uniform(-90, 90), rng.uniform(-180, 180)};
            if (trial % 50 == 0) e.y = trial % 100 == 0 ? 90 : -90;
            CAPTURE(order, e.x, e.y, e.z);
            const dmat3 m = composed(order, e);
            const dvec3 back = OI::euler_of(order, m);
            REQUIRE(cg::rot::max_diff(composed(order, back), m) < 1e-12);
            REQUIRE(std::fabs(back.y) <= 90);
            if (std::fabs(e.y) < 89) REQUIRE(glm::length(back - e) < 1e-9);
        }
    }
    for (int trial = 0; trial < 1000; ++trial) {
        dquat q = random_unit(rng);
        if (q.w < 0) q = -q;
        const dvec3 l = OI::log_unit(q);
        const dquat g = glm::log(q);
        REQUIRE(glm::length(l - dvec3(g.x, g.y, g.z)) < 1e-12);
        REQUIRE(qdiff(OI::exp_pure(l), q) < 1e-14);
    }
    CHECK(OI::log_unit({1, 0, 0, 0}) == dvec3(0));
    CHECK(OI::exp_pure(dvec3(0)) == dquat(1, 0, 0, 0));
}

TEST_CASE("orientation-interpolation: the state machine gives what compute gives, through the "
          "registry too",
          "[animation][orientation-interpolation]") {
    cg::Rng rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        CAPTURE(trial);
        const Input in = random_input(rng);
        const auto traced = cg::test::run_traced<OI>(in);
        CHECK(traced.result == OI::compute(in));
        CHECK(cg::run_to_end<OI>(OI::start(in)) == OI::compute(in));
        const auto ev = cg::test::events(traced);
        const std::size_t n = in.keys.size();
        REQUIRE(ev.size() == n + (n - 1) + (n >= 3) + OI::frame_count(in) + 1);
        CHECK(ev.back() == "summary");
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const auto j = cg::test::result_of("orientation-interpolation", p.input);
        const Input in = cg::test::input_of<OI>("orientation-interpolation", p.input);
        CHECK(j == cg::test::result_of("orientation-interpolation", p.input));
        CHECK(j["t"].size() == std::size_t(OI::frame_count(in)));
    }
}

TEST_CASE("orientation-interpolation: the lesson's presets show what they say",
          "[animation][orientation-interpolation]") {
    const auto& presets = lesson().presets;
    REQUIRE(presets.size() >= 4);
    auto run = [&](const std::string& part) {
        for (const auto& p : presets)
            if (p.name.find(part) != std::string::npos)
                return OI::compute(cg::test::input_of<OI>("orientation-interpolation", p.input));
        FAIL("no preset with " << part);
        return OI::Result{};
    };
    // Euler's speed is uneven where slerp's is flat, also near the lock, where a small turn
    // needs large changes of all three angles.
    const auto cmp = run("Euler angles against slerp");
    CHECK(cmp.speed_max[1] / cmp.speed_min[1] == Approx(1).epsilon(1e-9));
    CHECK(cmp.speed_max[0] / cmp.speed_min[0] > 1.5);
    const auto lock = run("gimbal lock");
    CHECK(lock.speed_max[1] / lock.speed_min[1] == Approx(1).epsilon(1e-9));
    CHECK(lock.speed_max[0] / lock.speed_min[0] > 1.5);
    CHECK(lock.speed_max[1] == Approx(60).epsilon(1e-5));  // a 60° turn in one second
    CHECK(glm::length(lock.keys.e[1] - dvec3(89.4, 30, 88.8)) < 0.5);
    const auto flip = run("q or −q");
    CHECK(flip.keys.flipped[0]);
    const auto sq = run("squad");
    CHECK(sq.keys.q.size() >= 4);
    CHECK(sq.min_det < 0.9);
}

TEST_CASE("orientation-interpolation: bad input names the field and the reason",
          "[animation][orientation-interpolation]") {
    const std::string two = R"("keys": [{"euler": [0, 0, 0]}, {"euler": [0, 0, 90]}])";
    CHECK(err(R"({})").find("keys") == 0);
    CHECK(err(R"({"keys": []})").find("keys: must have at least 2 key orientations") == 0);
    CHECK(err(R"({"keys": [{"euler": [0, 0, 0]}]})").find("keys: must have at least 2") == 0);
    CHECK(err(R"({"keys": [{}, {"euler": [0, 0, 0]}]})").find("keys[0]: must give") == 0);
    CHECK(err(R"({"keys": [{"euler": [0, 0, 0], "quaternion": [1, 0, 0, 0]}, {"euler": [0, 0, 0]}]})")
              .find("keys[0]: must give one form only") == 0);
    CHECK(err(R"({"keys": [{"axis": [0, 0, 1]}, {"euler": [0, 0, 0]}]})")
              .find("keys[0].angle: is missing") == 0);
    CHECK(err(R"({"keys": [{"axis": [0, 0, 0], "angle": 30}, {"euler": [0, 0, 0]}]})")
              .find("keys[0].axis: must not be the zero vector") == 0);
    CHECK(err(R"({"keys": [{"quaternion": [0, 0, 0, 0]}, {"euler": [0, 0, 0]}]})")
              .find("keys[0].quaternion: must not be [0, 0, 0, 0]") == 0);
    CHECK(err(R"({"keys": [{"quaternion": [1, 0, 0]}, {"euler": [0, 0, 0]}]})")
              .find("keys[0].quaternion: must be a quaternion") == 0);
    CHECK(err(R"({"keys": [{"euler": [0, 1e5, 0]}, {"euler": [0, 0, 0]}]})")
              .find("keys[0].euler[1]: is too large") == 0);
    CHECK(err(R"({"keys": [{"euler": [0, 0, 0]}, {"euler": [0, "a", 0]}]})")
              .find("keys[1].euler[1]: must be a number") == 0);
    CHECK(err(R"({"keys": [{"euler": [0, 0, 0]}, {"spin": 3}]})").find("keys[1]") == 0);
    CHECK(err("{" + two + R"(, "order": "xyx"})").find("order: must be one of") == 0);
    CHECK(err("{" + two + R"(, "frames": 0})").find("frames: must be 1 to 240") == 0);
    CHECK(err("{" + two + R"(, "frames": 241})").find("frames: must be 1 to 240") == 0);
    CHECK(err("{" + two + R"(, "segment_time": 0})").find("segment_time: must be a time > 0") == 0);
    CHECK(err("{" + two + R"(, "segment_time": -1})").find("segment_time: must be a time > 0") == 0);
    CHECK(err("{" + two + R"(, "extra": 1})").find("extra") != std::string::npos);
    std::string many = R"({"keys": [)";
    for (int i = 0; i < 33; ++i) many += std::string(i ? "," : "") + R"({"euler": [0, 0, 0]})";
    CHECK(err(many + "]}").find("keys: has 33 keys; at most 32") == 0);
    std::string lots = R"({"keys": [)";
    for (int i = 0; i < 32; ++i) lots += std::string(i ? "," : "") + R"({"euler": [0, 0, 0]})";
    CHECK(err(lots + R"(], "frames": 200})").find("frames: 200 frames for each of 31 segments") == 0);
    // Accepted: identical keys (nothing moves), q and −q (the same orientation: slerp stands
    // still), 360° apart in Euler angles (slerp stands still, the Euler lerp spins once).
    const auto same = cg::test::result_of("orientation-interpolation",
                                          std::string(R"({"keys": [{"quaternion": [0, 1, 0, 0]},
                                                       {"quaternion": [0, -1, 0, 0]}]})"));
    CHECK(same["flipped"][0] == true);
    CHECK(same["omega_deg"][0] == 0);
    CHECK(same["speed_range"]["slerp"][1] == 0);
    const auto spin = cg::test::result_of("orientation-interpolation",
                                          std::string(R"({"keys": [{"euler": [0, 0, 0]}, {"euler": [360, 0, 0]}],
                                              "frames": 8})"));
    CHECK(spin["speed_range"]["slerp"][1] == 0);
    CHECK(spin["speed_range"]["euler"][0].get<double>() == Approx(360));
}

TEST_CASE("orientation-interpolation: replay on the example and the presets",
          "[animation][orientation-interpolation]") {
    const auto& a = cg::test::algorithm("orientation-interpolation");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
}

TEST_CASE("orientation-interpolation: exam problems answered by hand",
          "[animation][orientation-interpolation][exam]") {
    const auto& a = cg::test::algorithm("orientation-interpolation");
    int kinds[3] = {0, 0, 0}, flips = 0, flat = 0, same_keys = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<OI>("orientation-interpolation", p.input);
        REQUIRE(in.keys.size() == 2);
        const Key& k0 = in.keys[0];
        const Key& k1 = in.keys[1];
        ++kinds[int(k0.form)];
        if (k0.form == OI::Form::Quaternion) {
            // ω = acos(q1 · q2) after the sign choice; q(u) at u = 1/frames.
            Q q1 = from(k0.q), q2 = from(k1.q);
            LD d = dot(q1, q2);
            if (d < 0) q2 = LD(-1) * q2, d = -d, ++flips;
            // The same key twice: ω = 0 and q(u) = q1 (acos near 1 keeps only half the digits
            // of a dot product rounded below 1, so the reference says 0 there itself).
            const bool same = qdiff(k0.q, k1.q) == 0 || qdiff(k0.q, -k1.q) == 0;
            same_keys += same;
            const LD w = same ? 0 : std::acos(std::min<LD>(d, 1)), u = LD(1) / in.frames;
            const Q q = same ? q1
                             : (std::sin((1 - u) * w) / std::sin(w)) * q1 +
                                   (std::sin(u * w) / std::sin(w)) * q2;
            CHECK(p.answers == std::vector<std::string>{"omega_deg/0", "slerp/1"});
            CHECK(p.expected["omega_deg/0"].get<double>() == Approx(double(w * 180 / M_PI)).margin(1e-12));
            const auto g = p.expected["slerp/1"].get<std::vector<double>>();
            CHECK(qdiff(dquat(g[0], g[1], g[2], g[3]), q) < 1e-12);
        } else if (k0.form == OI::Form::Euler) {
            CHECK(p.answers == std::vector<std::string>{"euler/1", "slerp/1"});
            const auto e = p.expected["euler/1"].get<std::vector<double>>();
            CHECK(dvec3(e[0], e[1], e[2]) == 0.5 * (k0.euler_deg + k1.euler_deg));
            // Slerp half way is the normalised sum of the two (aligned) quaternions.
            const dquat q0 = glm::quat_cast(composed("xyz", k0.euler_deg));
            dquat q1 = glm::quat_cast(composed("xyz", k1.euler_deg));
            if (glm::dot(q0, q1) < 0) q1 = -q1;
            const dquat mid = glm::normalize(q0 + q1);
            const auto g = p.expected["slerp/1"].get<std::vector<double>>();
            CHECK(cg::rot::max_diff(glm::mat3_cast(dquat(g[0], g[1], g[2], g[3])), glm::mat3_cast(mid)) <
                  1e-12);
        } else {
            // (I + R)/2 about one axis: det = cos²(θ/2).
            CHECK(p.answers == std::vector<std::string>{"matrix/1", "matrix_det/1"});
            const double c = std::cos(glm::radians(k1.angle_deg) / 2);
            CHECK(p.expected["matrix_det/1"].get<double>() == Approx(c * c).margin(1e-15));
            const dmat3 r = glm::mat3_cast(glm::angleAxis(glm::radians(k1.angle_deg), k1.axis));
            const dmat3 m = 0.5 * (dmat3(1.0) + r);
            const auto rows = p.expected["matrix/1"];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) CHECK(rows[i][j].get<double>() == Approx(m[j][i]).margin(1e-15));
            flat += k1.angle_deg == 180;
        }
    }
    CHECK(kinds[int(OI::Form::Quaternion)] > 100);
    CHECK(kinds[int(OI::Form::Euler)] > 50);
    CHECK(kinds[int(OI::Form::AxisAngle)] > 30);
    CHECK(flips > 20);
    CHECK(flat > 5);
    CHECK(same_keys > 5);
}

TEST_CASE("orientation-interpolation: the picture, four fans in 3D, the speed and det charts",
          "[animation][orientation-interpolation]") {
    Input in;
    in.keys = {axis_key({0, 0, 1}, 0), axis_key({1, 0, 0}, 90), axis_key({0, 1, 0}, 120)};
    in.frames = 6;
    auto s = OI::start(in);
    cg::Scene before;
    OI::draw(s, before);
    CHECK(before.has_3d());
    for (int k = 0; k < 3 + 2 + 1 + 5; ++k) OI::step(s, nullptr);
    REQUIRE(s.frames.size() == 5);
    cg::Scene scene;
    OI::draw(s, scene);
    CHECK_FALSE(scene.has_2d());  // nothing on the world's grid
    REQUIRE(scene.panels.size() == 2);
    const cg::Panel& speed = scene.panels[0];
    const cg::Panel& det = scene.panels[1];
    CHECK(speed.kind == cg::PanelKind::Chart);
    CHECK(speed.x.label == "t (s)");
    CHECK(speed.y.lo == 0);
    REQUIRE(speed.legend.size() == 3);  // Euler, slerp, squad
    CHECK(speed.legend[2].text == "squad");
    CHECK(speed.polygons[2].points.size() == 4);  // frames 1..4 have a speed
    CHECK(det.legend.size() == 2);  // det = 1 and det M(t)
    CHECK(det.polygons.back().points.size() == 5);
    CHECK(scene.focus3.size() == 1);
    CHECK(scene.faces3.size() >= 4 * 5);  // a house a fan
    int labels = 0;
    for (const auto& l : scene.labels3) labels += l.text == "squad" || l.text == "slerp";
    CHECK(labels == 2);
    // Two keys: no squad fan.
    Input two;
    two.keys = {axis_key({0, 0, 1}, 0), axis_key({1, 0, 0}, 90)};
    cg::Scene s2;
    OI::draw(OI::start(two), s2);
    for (const auto& l : s2.labels3) CHECK(l.text != "squad");
}
