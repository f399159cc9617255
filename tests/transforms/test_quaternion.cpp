// Quaternion algebra: exam cases worked by hand (i j = k but j i = −k, parallel vector parts
// commute, the inverse of [1, 2, 3, 4], a 120° turn about (1, 1, 1), 180° matrices); every op
// against GLM (operator*, conjugate, inverse, quaternion × vector, angleAxis, mat3_cast,
// quat_cast) and against closed forms in long double (Hamilton's product by components,
// Rodrigues' formula) on thousands of random inputs — non-unit, tiny and huge quaternions,
// points on the axis, 180° and near-180° matrices, slightly-off typed matrices; run-to-end ==
// the plain function; errors naming the field; determinism, presets and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <set>

#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"
#include "transforms/quaternion.hpp"
#include "transforms/rotation_common.hpp"
#include "transforms/slerp.hpp"

using cg::Quaternion;
using cg::Slerp;
using glm::dmat3;
using glm::dquat;
using glm::dvec3;
using Op = Quaternion::Op;
using ld = long double;

namespace {

using Traced = cg::test::Traced<Quaternion>;

Traced run_traced(const Quaternion::Input& in) {
    return cg::test::run_traced<Quaternion>(in);
}

Quaternion::Input multiply(dquat a, dquat b) {
    Quaternion::Input in;
    in.op = Op::Multiply;
    in.q1 = a;
    in.q2 = b;
    return in;
}
Quaternion::Input single(Op op, dquat q) {
    Quaternion::Input in;
    in.op = op;
    in.q = q;
    return in;
}
Quaternion::Input rotate(dquat q, dvec3 p) {
    Quaternion::Input in = single(Op::Rotate, q);
    in.point = p;
    return in;
}
Quaternion::Input axis_angle(dvec3 axis, double angle_deg) {
    Quaternion::Input in;
    in.op = Op::FromAxisAngle;
    in.axis = axis;
    in.angle_deg = angle_deg;
    return in;
}
Quaternion::Input from_matrix(const dmat3& m) {
    Quaternion::Input in;
    in.op = Op::FromMatrix;
    in.matrix = m;
    return in;
}
// Rows → glm's column storage.
dmat3 rows(dvec3 r0, dvec3 r1, dvec3 r2) {
    return glm::transpose(dmat3(r0, r1, r2));
}

double qdiff(const dquat& a, const dquat& b) {
    return std::max(
        {std::fabs(a.w - b.w), std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}
double qdiff_sign(const dquat& a, const dquat& b) {  // q and −q: the same rotation
    return std::min(qdiff(a, b), qdiff(a, -b));
}
double vdiff(const dvec3& a, const dvec3& b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}
double mdiff(const dmat3& a, const dmat3& b) {
    return cg::rot::max_diff(a, b);
}

dquat random_quat(cg::Rng& rng) {
    return {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
}
dvec3 random_vec(cg::Rng& rng, double m) {
    return {rng.uniform(-m, m), rng.uniform(-m, m), rng.uniform(-m, m)};
}
dquat random_unit(cg::Rng& rng) {
    dquat q;
    do q = random_quat(rng);
    while (glm::length(q) < 0.1);
    return glm::normalize(q);
}

// Hamilton's product component by component, in long double: independent of the course's
// (s, v) form that the code uses.
struct LQ {
    ld w, x, y, z;
};
LQ lq(const dquat& q) {
    return {q.w, q.x, q.y, q.z};
}
LQ hamilton(const LQ& a, const LQ& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
ld ldiff(const LQ& a, const dquat& b) {
    return std::max(
        {std::fabs(a.w - b.w), std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

// Rodrigues' formula in long double: P cos θ + (k × P) sin θ + k (k · P)(1 − cos θ), for the
// turn of the unit quaternion q (θ = 2 atan2(|v|, w), k = v / |v|).
void rodrigues(const dquat& q, const dvec3& p, ld out[3]) {
    const ld n = std::sqrt(ld(q.x) * q.x + ld(q.y) * q.y + ld(q.z) * q.z);
    if (n == 0) {
        out[0] = p.x, out[1] = p.y, out[2] = p.z;
        return;
    }
    const ld k[3] = {q.x / n, q.y / n, q.z / n}, P[3] = {p.x, p.y, p.z};
    const ld th = 2 * std::atan2(n, ld(q.w)), c = std::cos(th), s = std::sin(th);
    const ld kp = k[0] * P[0] + k[1] * P[1] + k[2] * P[2];
    const ld kxp[3] = {k[1] * P[2] - k[2] * P[1], k[2] * P[0] - k[0] * P[2],
                       k[0] * P[1] - k[1] * P[0]};
    for (int i = 0; i < 3; ++i) out[i] = P[i] * c + kxp[i] * s + k[i] * kp * (1 - c);
}

std::vector<cg::json> presets() {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lib.for_algorithm("quaternion");
    std::vector<cg::json> v;
    if (l)
        for (const auto& p : l->presets) v.push_back(p.input);
    return v;
}

}  // namespace

TEST_CASE("quaternion: exam cases worked by hand", "[transforms][quaternion]") {
    const double h = std::sqrt(0.5);
    SECTION("quarter turns about x and y: q1 q2 and q2 q1 differ in v1 × v2") {
        const Traced t = run_traced(multiply({1, 1, 0, 0}, {1, 0, 1, 0}));
        CHECK(cg::test::events(t) == std::vector<std::string>{"scalar-part", "vector-part",
                                                              "product", "reverse", "differ"});
        CHECK(t.result.q == dquat(1, 1, 1, 1));
        CHECK(*t.result.q2q1 == dquat(1, 1, 1, -1));
        CHECK_FALSE(*t.result.commute);
        CHECK(*t.result.norm == Approx(2));
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("s1 s2 = 1 · 1 = 1, v1 · v2 = (1, 0, 0) · (0, 1, 0) = 0, so s = "
                                   "s1 s2 − v1 · v2 = 1"));
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("s1 v2 = (0, 1, 0), s2 v1 = (1, 0, 0), v1 × v2 = (1, 0, 0) × "
                                   "(0, 1, 0) = (0, 0, 1)"));
        CHECK_THAT(t.steps[4].narration, Catch::Contains("(0, 2 v1 × v2) = [0, 0, 0, 2]"));
        CHECK(t.result.angle_deg == std::nullopt);
        CHECK(t.result.point == std::nullopt);
        CHECK(t.result.matrix == std::nullopt);
    }
    SECTION("i j = k, j i = −k") {
        const auto r = Quaternion::compute(multiply({0, 1, 0, 0}, {0, 0, 1, 0}));
        CHECK(r.q == dquat(0, 0, 0, 1));
        CHECK(*r.q2q1 == dquat(0, 0, 0, -1));
        CHECK(Quaternion::compute(multiply({0, 1, 0, 0}, {0, 1, 0, 0})).q == dquat(-1, 0, 0, 0));
    }
    SECTION("parallel vector parts commute") {
        const Traced t = run_traced(multiply({1, 2, 0, -1}, {3, -4, 0, 2}));
        CHECK(t.steps.back().event == "commute");
        CHECK(*t.result.commute);
        CHECK(t.result.q == *t.result.q2q1);
        CHECK(t.result.q == dquat(3 + 10, -4 + 6, 0, 2 - 3));
        CHECK(*Quaternion::compute(multiply({0, 0, 0, 0}, {1, 2, 3, 4})).commute);
    }
    SECTION("conjugate and inverse of [1, 2, 3, 4]") {
        const Traced c = run_traced(single(Op::Conjugate, {1, 2, 3, 4}));
        CHECK(cg::test::events(c) == std::vector<std::string>{"conjugate", "norm"});
        CHECK(c.result.q == dquat(1, -2, -3, -4));
        CHECK(*c.result.norm == Approx(std::sqrt(30.0)));
        CHECK_THAT(c.steps[1].narration, Catch::Contains("q q̄ = [30, 0, 0, 0]"));
        const Traced i = run_traced(single(Op::Inverse, {1, 2, 3, 4}));
        CHECK(cg::test::events(i) ==
              std::vector<std::string>{"conjugate", "norm", "inverse", "check-inverse"});
        CHECK(qdiff(i.result.q, dquat(1, -2, -3, -4) / 30.0) < 1e-16);
        CHECK_THAT(i.steps[3].narration, Catch::Contains("q q⁻¹ = [1, 0, 0, 0]"));
    }
    SECTION("rotate (1, 0, 0) by [1, 0, 0, 1]: normalised, a quarter turn about z") {
        const Traced t = run_traced(rotate({1, 0, 0, 1}, {1, 0, 0}));
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"normalise", "q-times-p", "times-conjugate", "image"});
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("has length 1.41421, so it is normalised first"));
        CHECK(qdiff(t.result.q, dquat(h, 0, 0, h)) < 1e-15);
        CHECK(vdiff(*t.result.point, {0, 1, 0}) < 1e-15);
        CHECK(*t.result.angle_deg == Approx(90));
        CHECK(vdiff(*t.result.axis, {0, 0, 1}) == 0);
    }
    SECTION("rotate (1, 2, 3) by 120° about (1, 1, 1): the coordinates cycle") {
        const auto r = Quaternion::compute(rotate({1, 1, 1, 1}, {1, 2, 3}));
        CHECK(vdiff(*r.point, {3, 1, 2}) < 1e-15);
        CHECK(*r.angle_deg == Approx(120));
        const Traced t = run_traced(rotate({0.5, 0.5, 0.5, 0.5}, {1, 2, 3}));
        CHECK_THAT(t.steps[0].narration, Catch::Contains("is already unit length"));
    }
    SECTION("the quaternion of a 90° turn about (0, 0, 1), exactly") {
        const Traced t = run_traced(axis_angle({0, 0, 1}, 90));
        CHECK(cg::test::events(t) == std::vector<std::string>{"unit-axis", "half-angle", "build"});
        CHECK(t.result.q == dquat(h, 0, 0, h));
        CHECK(Quaternion::compute(axis_angle({0, 0, 2}, 180)).q == dquat(0, 0, 0, 1));
        CHECK(Quaternion::compute(axis_angle({0, 0, 1}, -90)).q == dquat(h, 0, 0, -h));
        const auto full = Quaternion::compute(axis_angle({1, 0, 0}, 360));
        CHECK(full.q == dquat(-1, 0, 0, 0));
        CHECK(full.axis == std::nullopt);
        CHECK(*full.angle_deg == Approx(360));
    }
    SECTION("the matrix of [1, 0, 0, 1]") {
        const Traced t = run_traced(single(Op::ToMatrix, {1, 0, 0, 1}));
        CHECK(cg::test::events(t) == std::vector<std::string>{"normalise", "terms", "matrix"});
        CHECK(mdiff(*t.result.matrix, rows({0, -1, 0}, {1, 0, 0}, {0, 0, 1})) < 1e-15);
        CHECK_THAT(t.steps[2].narration, Catch::Contains("= [0 −1 0; 1 0 0; 0 0 1]"));
    }
    SECTION("from_matrix: a quarter turn, and 180° turns where w = 0") {
        const Traced t = run_traced(from_matrix(rows({0, -1, 0}, {1, 0, 0}, {0, 0, 1})));
        CHECK(cg::test::events(t) == std::vector<std::string>{"is-rotation", "candidates",
                                                              "extract", "sign", "check-back"});
        CHECK(qdiff(t.result.q, dquat(h, 0, 0, h)) < 1e-15);
        CHECK_THAT(t.steps[1].narration, Catch::Contains("The largest is 4w²"));
        // 180° about x: the largest is 4x², and w = 0.
        const Traced x = run_traced(from_matrix(rows({1, 0, 0}, {0, -1, 0}, {0, 0, -1})));
        CHECK(x.result.q == dquat(0, 1, 0, 0));
        CHECK_THAT(x.steps[1].narration, Catch::Contains("The largest is 4x²"));
        // 180° about (1, 1, 0)/√2: R = 2nnᵀ − I.
        const auto d = Quaternion::compute(from_matrix(rows({0, 1, 0}, {1, 0, 0}, {0, 0, -1})));
        CHECK(qdiff(d.q, dquat(0, h, h, 0)) < 1e-15);
        CHECK(*d.angle_deg == Approx(180));
        // 180° about (0, 1, −1)/√2: the sign rule makes the first non-zero (y) positive.
        const auto e = Quaternion::compute(from_matrix(rows({-1, 0, 0}, {0, 0, -1}, {0, -1, 0})));
        CHECK(qdiff(e.q, dquat(0, 0, h, -h)) < 1e-15);
        // The identity.
        CHECK(Quaternion::compute(from_matrix(dmat3(1.0))).q == dquat(1, 0, 0, 0));
    }
}

TEST_CASE("quaternion: 5,000 random products against GLM and Hamilton's product in long double",
          "[transforms][quaternion]") {
    int commuting = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        dquat a = random_quat(rng), b = random_quat(rng);
        switch (trial % 10) {
            case 0:  // parallel vector parts
                b = {b.w, 3 * a.x, 3 * a.y, 3 * a.z};
                break;
            case 1:  // a zero
                a = {0, 0, 0, 0};
                break;
            case 2:  // scalars only
                a = {a.w, 0, 0, 0};
                break;
            case 3:  // large and small
                a = a * 1e150;
                b = b * 1e-150;
                break;
            default:
                break;
        }
        CAPTURE(trial);
        const auto in = multiply(a, b);
        const auto r = cg::run_to_end<Quaternion>(Quaternion::start(in));
        REQUIRE(Quaternion::compute(in) == r);
        REQUIRE(qdiff(r.q, a * b) <= 2e-15 * glm::length(a) * glm::length(b));
        REQUIRE(qdiff(*r.q2q1, b * a) <= 2e-15 * glm::length(a) * glm::length(b));
        const ld scale = ld(glm::length(a)) * glm::length(b);
        REQUIRE(ldiff(hamilton(lq(a), lq(b)), r.q) <= 1e-15L * scale);
        REQUIRE(ldiff(hamilton(lq(b), lq(a)), *r.q2q1) <= 1e-15L * scale);
        REQUIRE(std::fabs(*r.norm - glm::length(a) * glm::length(b)) <= 1e-14 * scale);
        REQUIRE(*r.commute == (glm::cross(dvec3(a.x, a.y, a.z), dvec3(b.x, b.y, b.z)) == dvec3(0)));
        if (*r.commute) REQUIRE(r.q == *r.q2q1);
        commuting += *r.commute;
    }
    CHECK(commuting >= 1000);
}

TEST_CASE("quaternion: 5,000 random conjugates and inverses against GLM and long double",
          "[transforms][quaternion]") {
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        dquat q = random_quat(rng);
        if (trial % 7 == 0) q = q * 1e-150;
        if (trial % 7 == 1) q = q * 1e150;
        if (trial % 7 == 2) q = glm::normalize(q);
        if (glm::length(q) == 0) continue;
        CAPTURE(trial);
        const auto c = cg::run_to_end<Quaternion>(Quaternion::start(single(Op::Conjugate, q)));
        REQUIRE(c == Quaternion::compute(single(Op::Conjugate, q)));
        REQUIRE(c.q == glm::conjugate(q));
        const auto in = single(Op::Inverse, q);
        const auto i = cg::run_to_end<Quaternion>(Quaternion::start(in));
        REQUIRE(i == Quaternion::compute(in));
        const dquat g = glm::inverse(q);
        REQUIRE(qdiff(i.q, g) <= 1e-15 * glm::length(g));
        // q⁻¹ = q̄ / |q|² in long double, and q q⁻¹ = 1.
        const ld n2 = ld(q.w) * q.w + ld(q.x) * q.x + ld(q.y) * q.y + ld(q.z) * q.z;
        REQUIRE(ldiff({q.w / n2, -q.x / n2, -q.y / n2, -q.z / n2}, i.q) <= 1e-15L / std::sqrt(n2));
        REQUIRE(qdiff(Quaternion::compute(multiply(q, i.q)).q, dquat(1, 0, 0, 0)) < 1e-15);
    }
}

TEST_CASE("quaternion: 5,000 random rotations of points against GLM and Rodrigues' formula",
          "[transforms][quaternion]") {
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        dquat q = random_quat(rng);
        dvec3 p = random_vec(rng, 5);
        switch (trial % 8) {
            case 0:  // a point on the axis stays
                p = 2.5 * dvec3(q.x, q.y, q.z);
                break;
            case 1:
                p = {0, 0, 0};
                break;
            case 2:  // a half turn
                q.w = 0;
                break;
            case 3:  // tiny, huge and negated quaternions are the same rotation
                q = q * 1e-300;
                break;
            case 4:
                q = q * -1e300;
                break;
            case 5:  // the identity
                q = {3, 0, 0, 0};
                break;
            default:
                break;
        }
        if (q == dquat(0, 0, 0, 0)) continue;
        CAPTURE(trial);
        const auto in = rotate(q, p);
        const auto r = cg::run_to_end<Quaternion>(Quaternion::start(in));
        REQUIRE(Quaternion::compute(in) == r);
        const dquat u = glm::normalize(
            q / std::max({std::fabs(q.w), std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)}));
        REQUIRE(qdiff(r.q, u) <= 1e-15);
        const double tol = 1e-14 * std::max(1.0, glm::length(p));
        REQUIRE(vdiff(*r.point, u * p) <= tol);  // GLM's quaternion × vector
        REQUIRE(vdiff(*r.point, glm::mat3_cast(u) * p) <= tol);
        ld ref[3];
        rodrigues(u, p, ref);
        for (int k = 0; k < 3; ++k) REQUIRE(std::fabs(ref[k] - (*r.point)[k]) <= tol);
        REQUIRE(std::fabs(glm::length(*r.point) - glm::length(p)) <= tol);
        if (trial % 8 == 0) REQUIRE(vdiff(*r.point, p) <= tol);
    }
}

TEST_CASE(
    "quaternion: 5,000 random axis-angle pairs against glm::angleAxis, and matrices "
    "against glm::mat3_cast and Rodrigues",
    "[transforms][quaternion]") {
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        dvec3 axis = random_vec(rng, 3);
        if (glm::length(axis) < 1e-3) continue;
        double angle = rng.uniform(-400, 400);
        if (trial % 5 == 0) angle = 45.0 * rng.integer(-8, 8);  // the exact table
        if (trial % 5 == 1) axis *= 1e-300;
        if (trial % 5 == 2) axis *= 1e300;
        CAPTURE(trial, angle);
        const auto in = axis_angle(axis, angle);
        const auto r = cg::run_to_end<Quaternion>(Quaternion::start(in));
        REQUIRE(Quaternion::compute(in) == r);
        const dvec3 unit = glm::normalize(
            axis / std::max({std::fabs(axis.x), std::fabs(axis.y), std::fabs(axis.z)}));
        const dquat g = glm::angleAxis(glm::radians(angle), unit);
        REQUIRE(qdiff(r.q, g) <= 1e-13);
        // (cos θ/2, sin θ/2 â) in long double.
        const ld half = ld(angle) * 3.14159265358979323846264338327950288L / 360;
        REQUIRE(ldiff({std::cos(half), std::sin(half) * unit.x, std::sin(half) * unit.y,
                       std::sin(half) * unit.z},
                      r.q) <= 1e-13L);
        REQUIRE(std::fabs(glm::length(r.q) - 1) <= 1e-15);

        // Its matrix (to_matrix normalises first; scaled inputs give the same matrix).
        const auto in2 = single(Op::ToMatrix, r.q * (trial % 3 == 0 ? 7.0 : 1.0));
        const auto m = cg::run_to_end<Quaternion>(Quaternion::start(in2));
        REQUIRE(Quaternion::compute(in2) == m);
        REQUIRE(mdiff(*m.matrix, glm::mat3_cast(g)) <= 1e-14);
        for (int c = 0; c < 3; ++c) {
            ld col[3];
            rodrigues(r.q, dvec3(c == 0, c == 1, c == 2), col);
            for (int k = 0; k < 3; ++k) REQUIRE(std::fabs(col[k] - (*m.matrix)[c][k]) <= 1e-14L);
        }
        REQUIRE(std::fabs(glm::determinant(*m.matrix) - 1) <= 1e-14);
    }
}

TEST_CASE(
    "quaternion: from_matrix (Shepperd) against glm::quat_cast on 5,000 matrices, 180° "
    "turns and slightly-off typed matrices included",
    "[transforms][quaternion]") {
    int largest_seen[4] = {0, 0, 0, 0};
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        dquat q = random_unit(rng);
        switch (trial % 10) {
            case 0:  // a half turn: w = 0
                q = glm::normalize(dquat(0, q.x, q.y, q.z));
                break;
            case 1:  // nearly a half turn
                q = glm::normalize(dquat(1e-9, q.x, q.y, q.z));
                break;
            case 2:  // the identity, or nearly
                q = trial % 20 == 2 ? dquat(1, 0, 0, 0) : glm::normalize(dquat(1, 1e-9, 0, 0));
                break;
            case 3: {  // a quarter or half turn about a coordinate axis
                const int axis = int(rng.integer(0, 2));
                const double angle = 90.0 * double(rng.integer(1, 3));
                dvec3 a(0);
                a[axis] = 1;
                q = glm::angleAxis(glm::radians(angle), a);
                break;
            }
            default:
                break;
        }
        dmat3 m = glm::mat3_cast(q);
        const bool noisy = trial % 10 == 4;
        if (noisy)  // four significant digits, as typed
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k) m[c][k] = std::round(m[c][k] * 1e4) / 1e4;
        CAPTURE(trial);
        const auto in = from_matrix(m);
        auto s = Quaternion::start(in);
        while (!Quaternion::done(s)) Quaternion::step(s, nullptr);
        const auto r = Quaternion::result(s);
        REQUIRE(Quaternion::compute(in) == r);
        ++largest_seen[s.largest];
        REQUIRE(std::fabs(glm::length(r.q) - 1) <= 1e-15);
        // The sign rule: w ≥ 0, or w = 0 and the first non-zero positive.
        REQUIRE(r.q.w >= 0);
        if (r.q.w == 0)
            REQUIRE((r.q.x > 0 || (r.q.x == 0 && (r.q.y > 0 || (r.q.y == 0 && r.q.z > 0)))));
        const double tol = noisy ? 2e-4 : 1e-14;
        REQUIRE(qdiff_sign(r.q, q) <= tol);
        REQUIRE(qdiff_sign(r.q, glm::normalize(glm::quat_cast(m))) <= (noisy ? 1e-12 : 1e-14));
        REQUIRE(mdiff(Slerp::to_matrix(r.q), m) <= (noisy ? 2e-4 : 1e-14));
        REQUIRE(s.residual == mdiff(Slerp::to_matrix(r.q), m));
        // The largest candidate is the largest |component| (4c² = the candidate for exact R).
        if (!noisy) {
            const double c[4] = {std::fabs(r.q.w), std::fabs(r.q.x), std::fabs(r.q.y),
                                 std::fabs(r.q.z)};
            REQUIRE(c[s.largest] >= *std::max_element(c, c + 4) - 1e-15);
        }
    }
    for (int i = 0; i < 4; ++i) CHECK(largest_seen[i] > 200);
}

TEST_CASE("quaternion: bad input names the field", "[transforms][quaternion]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(Quaternion::start(single(Op::Inverse, {0, 0, 0, 0})),
                      "q: must not be the zero quaternion [0, 0, 0, 0]: it has no inverse "
                      "(|q|² = 0)");
    CHECK_THROWS_WITH(Quaternion::start(rotate({0, 0, 0, 0}, {1, 0, 0})),
                      "q: must not be the zero quaternion [0, 0, 0, 0]: it is no rotation and "
                      "cannot be normalised");
    CHECK_THROWS_WITH(Quaternion::start(single(Op::ToMatrix, {0, 0, 0, 0})),
                      Catch::StartsWith("q: must not be the zero quaternion"));
    CHECK_NOTHROW(Quaternion::start(single(Op::Conjugate, {0, 0, 0, 0})));
    CHECK_NOTHROW(Quaternion::start(multiply({0, 0, 0, 0}, {1, 2, 3, 4})));
    CHECK_THROWS_WITH(Quaternion::start(multiply({1, nan, 0, 0}, {1, 0, 0, 0})),
                      "q1[1]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Quaternion::start(multiply({1e200, 0, 0, 0}, {1e200, 0, 0, 0})),
                      Catch::StartsWith("q1: is too large together with q2"));
    CHECK_THROWS_WITH(Quaternion::start(single(Op::Inverse, {1e-170, 0, 0, 0})),
                      Catch::StartsWith("q: is too small"));
    CHECK_THROWS_WITH(Quaternion::start(single(Op::Conjugate, {1e200, 0, 0, 0})),
                      Catch::StartsWith("q: is too large"));
    CHECK_THROWS_WITH(Quaternion::start(rotate({1, 0, 0, 1}, {1.5e308, 1.5e308, 0})),
                      Catch::StartsWith("point: is too large"));
    CHECK_THROWS_WITH(Quaternion::start(axis_angle({0, 0, 0}, 90)),
                      "axis: must not be the zero vector: it has no direction");
    CHECK_THROWS_WITH(Quaternion::start(axis_angle({0, 0, 1}, nan)),
                      "angle_deg: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Quaternion::start(from_matrix(dmat3(2.0))),
                      "matrix: is not a rotation: its columns must be orthonormal (RᵀR = I "
                      "within 0.001), but max |RᵀR − I| = 3");
    CHECK_THROWS_WITH(Quaternion::start(from_matrix(rows({1, 0, 0}, {0, 1, 0}, {0, 0, -1}))),
                      "matrix: is a reflection (det R = −1), not a rotation: a rotation has det "
                      "R = 1");
    CHECK_THROWS_WITH(Quaternion::start(from_matrix(rows({1, 0, 0}, {0, 1, 0.01}, {0, 0, 1}))),
                      Catch::StartsWith("matrix: is not a rotation"));
    CHECK_NOTHROW(
        Quaternion::start(from_matrix(rows({0.7071, -0.7071, 0}, {0.7071, 0.7071, 0}, {0, 0, 1}))));

    using cg::test::error_of;
    CHECK(error_of("quaternion", R"({"op": "multiply", "q1": [1, 0, 0, 0], "q2": [0, 1, 0, 0]})") ==
          "(accepted)");
    CHECK(error_of("quaternion", R"({"op": "divide", "q": [1, 0, 0, 0]})") ==
          "op: must be one of multiply, conjugate, inverse, rotate, from_axis_angle, to_matrix, "
          "from_matrix (got \"divide\")");
    CHECK_THAT(error_of("quaternion", R"({"q": [1, 0, 0, 0]})"),
               Catch::StartsWith("op: is missing"));
    CHECK(error_of("quaternion", R"({"op": "conjugate", "q": [1, 0, 0, 0], "q2": [1, 0, 0, 0]})") ==
          "q2: is not a known field (expected: op, q)");
    CHECK(error_of("quaternion", R"({"op": "rotate", "q": [1, 0, 0]})") ==
          "q: must be a quaternion [w, x, y, z], got an array ([1,0,0])");
    CHECK_THAT(error_of("quaternion", R"({"op": "rotate", "q": [1, 0, 0, 0]})"),
               Catch::StartsWith("point: is missing"));
    CHECK_THAT(error_of("quaternion", R"({"op": "from_matrix", "matrix": [[1, 0, 0], [0, 1, 0]]})"),
               Catch::StartsWith("matrix: must be a 3×3 matrix as three rows"));
    CHECK_THAT(error_of("quaternion",
                        R"({"op": "from_matrix", "matrix": [[1, 0, 0], [0, 1], [0, 0, 1]]})"),
               Catch::StartsWith("matrix[1]: "));
    CHECK_THAT(error_of("quaternion", R"({"op": "from_axis_angle", "axis": [0, 0, 1]})"),
               Catch::StartsWith("angle_deg: is missing"));
}

TEST_CASE("quaternion: the JSON result, determinism, stepping back, and the presets",
          "[transforms][quaternion]") {
    const cg::Algorithm& a = cg::test::algorithm("quaternion");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    const cg::json r = cg::test::result_of("quaternion", a.example());
    CHECK(r["q"] == cg::json::array({1.0, 1.0, 1.0, 1.0}));
    CHECK(r["q2q1"] == cg::json::array({1.0, 1.0, 1.0, -1.0}));
    CHECK(r["commute"] == false);
    CHECK(r["point"].is_null());
    CHECK(r["matrix"].is_null());
    const cg::json m =
        cg::test::result_of("quaternion", std::string(R"({"op": "to_matrix", "q": [0, 0, 0, 2]})"));
    CHECK(m["matrix"] == cg::json::array({{-1.0, 0.0, 0.0}, {0.0, -1.0, 0.0}, {0.0, 0.0, 1.0}}));
    CHECK(m["angle_deg"] == 180.0);
    CHECK(m["axis"] == cg::json::array({0.0, 0.0, 1.0}));
    CHECK(m["q2q1"].is_null());

    const std::vector<cg::json> ps = presets();
    REQUIRE(ps.size() >= 7);
    std::set<std::string> ops;
    for (const cg::json& p : ps) {
        CAPTURE(p.dump());
        ops.insert(p["op"].get<std::string>());
        cg::test::check_replay(a, p, cg::test::kEveryStep);
    }
    CHECK(ops.size() == 7);  // every op has a preset
}

TEST_CASE("quaternion: the picture — axes, the rotation axis, the point and its image, frames",
          "[transforms][quaternion]") {
    auto finish = [](const Quaternion::Input& in) {
        auto s = Quaternion::start(in);
        while (!Quaternion::done(s)) Quaternion::step(s, nullptr);
        cg::Scene scene;
        Quaternion::draw(s, scene);
        return scene;
    };
    auto labelled = [](const cg::Scene& scene, const std::string& text) {
        for (const auto& l : scene.labels3)
            if (l.text.find(text) != std::string::npos) return true;
        for (const auto& p : scene.points3)
            if (p.label == text) return true;
        return false;
    };
    {  // rotate: P, P′ on the arc about the axis
        const cg::Scene scene = finish(rotate({1, 0, 0, 1}, {1, 0, 1}));
        REQUIRE(scene.points3.size() == 2);
        CHECK(scene.points3[0].label == "P");
        CHECK(scene.points3[1].label == "P′");
        CHECK(vdiff(scene.points3[1].p, {0, 1, 1}) < 1e-15);
        CHECK(labelled(scene, "rotation axis"));
        int arc = 0;
        for (const auto& seg : scene.segments3) {
            arc += seg.style.role == cg::Role::Leaving;
            if (seg.style.role == cg::Role::Leaving) CHECK(std::fabs(seg.a.z - 1) < 1e-15);
        }
        CHECK(arc >= 10);
    }
    {  // multiply: two frames that differ, and the three vectors
        const cg::Scene scene = finish(multiply({1, 1, 0, 0}, {1, 0, 1, 0}));
        REQUIRE(scene.frames3.size() == 3);  // world, q1q2, q2q1
        CHECK(vdiff(scene.frames3[1].x, scene.frames3[2].x) > 0.1);
        CHECK(labelled(scene, "v1 × v2"));
    }
    {  // from_matrix: R's frame, then the axis read from it
        const cg::Scene scene = finish(from_matrix(rows({0, -1, 0}, {1, 0, 0}, {0, 0, 1})));
        REQUIRE(scene.frames3.size() == 2);
        CHECK(scene.frames3[1].name == "R");
        CHECK(labelled(scene, "axis of q"));
    }
    // Every step of every preset and 200 exam problems draws finite 3D geometry only.
    const cg::Algorithm& a = cg::test::algorithm("quaternion");
    std::vector<cg::json> inputs = presets();
    for (std::uint64_t seed = 0; seed < 200; ++seed) inputs.push_back(a.exam_input(seed));
    auto finite = [](dvec3 p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    for (const cg::json& in : inputs) {
        auto run = a.create(in);
        do {
            cg::Scene scene;
            run->draw(scene);
            CHECK(scene.has_3d());
            for (const auto& s : scene.segments3) REQUIRE((finite(s.a) && finite(s.b)));
            for (const auto& p : scene.points3) REQUIRE(finite(p.p));
            for (const auto& l : scene.labels3) REQUIRE(finite(l.p));
            if (run->done()) break;
            run->step(nullptr);
        } while (true);
    }
}
