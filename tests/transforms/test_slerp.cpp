// Quaternions and slerp: exam cases worked by hand (flip, opposite and nearly equal keys);
// the course's product, conjugate and matrix against GLM's; 10,000 random pairs — some equal,
// opposite or nearly so — against glm::slerp and the closed form in long double, with the
// constant-speed property; the Euler-angle extraction used for the comparison paths; errors;
// determinism and the picture (slerp on the sphere, the matrix blend inside it).
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <map>

#include "support/traced.hpp"
#include "io/registry.hpp"
#include "support/replay.hpp"
#include "transforms/slerp.hpp"

using cg::Slerp;
using glm::dmat3;
using glm::dquat;
using glm::dvec3;

namespace {

using Traced = cg::test::Traced<Slerp>;

Traced run_traced(const Slerp::Input& in) { return cg::test::run_traced<Slerp>(in); }

std::vector<std::string> events(const Traced& t) {
    std::vector<std::string> e;
    for (std::size_t i = 0; i < 6; ++i) e.push_back(t.steps[i].event);
    return e;
}

double qdiff(const dquat& a, const dquat& b) {
    return std::max(
        {std::fabs(a.w - b.w), std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

double mdiff(const dmat3& a, const dmat3& b) {
    return cg::rot::max_diff(a, b);
}

dquat random_quat(cg::Rng& rng) {
    dquat q;
    do {
        q = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    } while (glm::length(q) < 0.1);
    return q;
}

}  // namespace

TEST_CASE("slerp: exam cases worked by hand", "[transforms][slerp]") {
    SECTION("a quarter turn about z to a quarter turn about x at u = 1/3") {
        const Traced t = run_traced({{1, 0, 0, 1}, {1, 1, 0, 0}, 1.0 / 3});
        CHECK(events(t) == std::vector<std::string>{"normalise", "dot", "angle", "blend",
                                                    "rotate-point", "matrix"});
        CHECK(t.steps.size() == 6 + Slerp::kSamples);
        CHECK(t.result.omega_deg == Approx(60));
        CHECK_FALSE(t.result.flipped);
        const double h = std::sqrt(0.5);
        const double w0 = std::sin(M_PI / 180 * 40) / std::sin(M_PI / 3),
                     w1 = std::sin(M_PI / 180 * 20) / std::sin(M_PI / 3);
        CHECK(qdiff(t.result.q, dquat(h * (w0 + w1), h * w1, 0, h * w0)) < 1e-15);
        CHECK_THAT(t.steps[2].narration,
                   Catch::Contains("w0 = sin((1−u)ω)/sin ω = 0.7422, w1 = sin(uω)/sin ω = 0.3949"));
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("q1 q̄0 = [0.5, 0.5, 0.5, −0.5] is a turn by 120°"));
    }
    SECTION("identity to a half turn about y, half way: a quarter turn about y") {
        const Traced t = run_traced({{1, 0, 0, 0}, {0, 0, 1, 0}, 0.5});
        CHECK(t.result.omega_deg == Approx(90));
        CHECK(qdiff(t.result.q, dquat(std::sqrt(0.5), 0, std::sqrt(0.5), 0)) < 1e-15);
        CHECK(mdiff(t.result.matrix, dmat3(dvec3(0, 0, -1), dvec3(0, 1, 0), dvec3(1, 0, 0))) <
              1e-15);
    }
    SECTION("a negative dot product: q1 is flipped and the turn is the short one") {
        const Traced t = run_traced({{1, 0, 0, 0}, {-1, 0, 0, -1}, 0.5});
        CHECK(t.steps[1].event == "flip");
        CHECK(t.result.flipped);
        CHECK(t.result.omega_deg == Approx(45));
        const double a = M_PI / 8;  // 45° about z: half of the quarter turn
        CHECK(qdiff(t.result.q, dquat(std::cos(a), 0, 0, std::sin(a))) < 1e-15);
    }
    SECTION("opposite quaternions are the same orientation: the fallback keeps it") {
        const Traced t = run_traced({{1, 1, 1, 1}, {-1, -1, -1, -1}, 0.25});
        CHECK(t.steps[1].event == "flip");
        CHECK(t.steps[2].event == "nearly-equal");
        CHECK(t.result.fallback);
        CHECK(t.result.omega_deg == 0);
        CHECK(qdiff(t.result.q, dquat(0.5, 0.5, 0.5, 0.5)) < 1e-15);
    }
    SECTION("nearly equal keys: no division by ≈ 0") {
        const Traced t = run_traced({{1, 0, 0, 0}, {1, 1e-9, 0, 0}, 0.5});
        CHECK(t.steps[2].event == "nearly-equal");
        CHECK(t.result.q.x == Approx(0.5e-9).epsilon(1e-6));
        CHECK(glm::length(t.result.q) == Approx(1).epsilon(1e-15));
    }
    SECTION("the ends: u = 0 gives q0, u = 1 gives q1") {
        const dquat q0 = glm::normalize(dquat(1, 2, 3, 4)), q1 = glm::normalize(dquat(4, -3, 2, 1));
        CHECK(qdiff(Slerp::interpolate({q0, q1, 0}).q, q0) < 1e-15);
        CHECK(qdiff(Slerp::interpolate({q0, q1, 1}).q, q1) < 1e-15);
    }
}

TEST_CASE("slerp: the course's quaternion algebra agrees with GLM's", "[transforms][slerp]") {
    for (int trial = 0; trial < 2000; ++trial) {
        cg::Rng rng(trial);
        const dquat a = random_quat(rng), b = random_quat(rng);
        CAPTURE(trial);
        REQUIRE(qdiff(Slerp::product(a, b), a * b) < 1e-15);
        REQUIRE(qdiff(Slerp::conjugate(a), glm::conjugate(a)) == 0);
        // A rotation built from an angle and an axis: (cos θ/2, sin θ/2 v̂) and q (0, P) q̄.
        const double angle = rng.uniform(-M_PI, M_PI);
        const dvec3 axis =
            glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        const dquat q = glm::angleAxis(angle, axis);
        REQUIRE(std::fabs(q.w - std::cos(angle / 2)) < 1e-15);
        REQUIRE(mdiff(Slerp::to_matrix(q), glm::mat3_cast(q)) < 1e-15);
        const dvec3 p(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3));
        const dquat r =
            Slerp::product(Slerp::product(q, dquat(0, p.x, p.y, p.z)), Slerp::conjugate(q));
        REQUIRE(std::fabs(r.w) < 1e-14);
        REQUIRE(glm::length(dvec3(r.x, r.y, r.z) - q * p) < 1e-14);
        REQUIRE(glm::length(Slerp::to_matrix(q) * p - q * p) < 1e-14);
    }
}

TEST_CASE("slerp: 10,000 random pairs agree with glm::slerp and the closed form",
          "[transforms][slerp]") {
    using ld = long double;
    int flips = 0, fallbacks = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        cg::Rng rng(trial);
        Slerp::Input in{random_quat(rng), random_quat(rng), rng.uniform(0, 1)};
        switch (trial % 10) {  // degenerate pairs and the ends
            case 0:
                in.q1 = in.q0 * 3.0;
                break;
            case 1:
                in.q1 = -in.q0;
                break;
            case 2:
                in.q1 = in.q0 + dquat(0, 1e-10, 0, 0);
                break;
            case 3:
                in.q1 = -in.q0 + dquat(1e-7, 0, -1e-7, 0);
                break;
            case 4:
                in.u = trial % 20 == 4 ? 0 : 1;
                break;
            default:
                break;
        }
        CAPTURE(trial, in.u);
        const auto r = cg::run_to_end<Slerp>(Slerp::start(in));
        REQUIRE(Slerp::interpolate(in) == r);
        flips += r.flipped;
        fallbacks += r.fallback;

        const dquat q0 = glm::normalize(in.q0), q1 = glm::normalize(in.q1);
        const dquat g = glm::slerp(q0, q1, in.u);
        REQUIRE(qdiff(r.q, g) <= 1e-9);
        REQUIRE(mdiff(r.matrix, glm::mat3_cast(g)) <= 1e-9);

        // The closed form in long double, with the flip.
        ld a[4] = {q0.w, q0.x, q0.y, q0.z}, b[4] = {q1.w, q1.x, q1.y, q1.z}, d = 0;
        for (int i = 0; i < 4; ++i) d += a[i] * b[i];
        REQUIRE(r.flipped == (d < 0));
        if (d < 0)
            for (int i = 0; i < 4; ++i) b[i] = -b[i], d = std::fabs(d);
        // ω = arccos(d); near d = 1 arccos is ill-conditioned (arccos(1 − 4e-16) = 2.8e-8), so
        // the reference takes the same angle as 2 atan2(|a − b|, |a + b|), in long double.
        ld minus = 0, plus = 0;
        for (int i = 0; i < 4; ++i)
            minus += (a[i] - b[i]) * (a[i] - b[i]), plus += (a[i] + b[i]) * (a[i] + b[i]);
        const ld omega = 2 * std::atan2(std::sqrt(minus), std::sqrt(plus));
        REQUIRE(std::fabs(std::cos(omega) - d) <= 1e-15L);
        ld ref[4];
        if (std::sin(omega) < 1e-6L) {
            ld n = 0;
            for (int i = 0; i < 4; ++i)
                ref[i] = (1 - in.u) * a[i] + in.u * b[i], n += ref[i] * ref[i];
            for (int i = 0; i < 4; ++i) ref[i] /= std::sqrt(n);
        } else {
            for (int i = 0; i < 4; ++i)
                ref[i] = (std::sin((1 - in.u) * omega) * a[i] + std::sin(in.u * omega) * b[i]) /
                         std::sin(omega);
        }
        REQUIRE(std::fabs(r.q.w - ref[0]) <= 1e-9L);
        REQUIRE(std::fabs(r.q.x - ref[1]) <= 1e-9L);
        REQUIRE(std::fabs(r.q.y - ref[2]) <= 1e-9L);
        REQUIRE(std::fabs(r.q.z - ref[3]) <= 1e-9L);
        REQUIRE(std::fabs(r.omega_deg - ld(omega) * 180 / M_PI) <= 1e-6);
        // Unit length, and constant speed: the angle from q0 to q(u) is u ω.
        REQUIRE(std::fabs(glm::length(r.q) - 1) <= 1e-14);
        const double travelled = 2 * std::atan2(glm::length(r.q - q0), glm::length(r.q + q0));
        REQUIRE(std::fabs(travelled - in.u * r.omega_deg * M_PI / 180) <= 1e-9);
    }
    CHECK(flips > 4000);
    CHECK(fallbacks >= 3000);
}

TEST_CASE("slerp: the naive methods' in-between matrices agree with GLM's, slerp's q unchanged",
          "[transforms][slerp]") {
    double smallest_det = 1;
    for (int trial = 0; trial < 2000; ++trial) {
        cg::Rng rng(1000 + trial);
        Slerp::Input in{random_quat(rng), random_quat(rng), rng.uniform(0, 1)};
        const dquat q0 = glm::normalize(in.q0), q1 = glm::normalize(in.q1);
        const dmat3 m0 = glm::mat3_cast(q0), m1 = glm::mat3_cast(q1);
        const auto slerped = Slerp::interpolate(in);

        in.method = Slerp::Method::MatrixLerp;
        auto r = cg::run_to_end<Slerp>(Slerp::start(in));
        REQUIRE(Slerp::interpolate(in) == r);
        REQUIRE(mdiff(r.matrix, (1 - in.u) * m0 + in.u * m1) <= 1e-12);
        REQUIRE(r.q == slerped.q);
        smallest_det = std::min(smallest_det, glm::determinant(r.matrix));

        in.method = Slerp::Method::EulerLerp;
        r = cg::run_to_end<Slerp>(Slerp::start(in));
        REQUIRE(Slerp::interpolate(in) == r);
        // R = R_z(θ3) R_y(θ2) R_x(θ1) of the lerped angles, composed by GLM.
        const dvec3 e = (1 - in.u) * cg::rot::euler_xyz_of(m0) + in.u * cg::rot::euler_xyz_of(m1);
        const glm::dmat4 R = glm::rotate(glm::dmat4(1), glm::radians(e.z), dvec3(0, 0, 1)) *
                             glm::rotate(glm::dmat4(1), glm::radians(e.y), dvec3(0, 1, 0)) *
                             glm::rotate(glm::dmat4(1), glm::radians(e.x), dvec3(1, 0, 0));
        REQUIRE(mdiff(r.matrix, dmat3(R)) <= 1e-12);
        REQUIRE(std::fabs(glm::determinant(r.matrix) - 1) <= 1e-12);
    }
    CHECK(smallest_det < 0.5);  // the matrix blend shrinks: no rotation in between
    // The method is read, and named on error.
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("slerp");
    cg::json in = a.example();
    in["method"] = "nlerp";
    CHECK_THROWS_WITH(a.create(in), Catch::Contains("method") && Catch::Contains("euler-lerp"));
    in["method"] = "euler-lerp";
    auto run = a.create(in);
    while (!run->done()) run->step(nullptr);
    CHECK(a.result(*run)["matrix"] != a.result(*[&] {
        auto plain = a.create(a.example());
        while (!plain->done()) plain->step(nullptr);
        return plain;
    }())["matrix"]);
}

TEST_CASE("slerp: Euler angles read back from a matrix rebuild it, also at gimbal lock",
          "[transforms][slerp]") {
    for (int trial = 0; trial < 3000; ++trial) {
        cg::Rng rng(trial);
        dvec3 e(rng.uniform(-180, 180), rng.uniform(-90, 90), rng.uniform(-180, 180));
        if (trial % 5 == 0) e.y = trial % 10 == 0 ? 90 : -90;
        CAPTURE(trial, e.x, e.y, e.z);
        const dmat3 m = cg::rot::euler_matrix("xyz", e);
        const dvec3 back = cg::rot::euler_xyz_of(m);
        REQUIRE(mdiff(cg::rot::euler_matrix("xyz", back), m) < 1e-9);
    }
}

TEST_CASE("slerp: bad input names the field", "[transforms][slerp]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(Slerp::start({{0, 0, 0, 0}, {1, 0, 0, 0}, 0.5}),
                      "q0: must not be the zero quaternion [0, 0, 0, 0]: it is no rotation and "
                      "cannot be normalised");
    CHECK_THROWS_WITH(Slerp::start({{1, 0, 0, 0}, {1, 0, nan, 0}, 0.5}),
                      "q1[2]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Slerp::start({{1, 0, 0, 0}, {1, 0, 0, 0}, 1.5}),
                      "u: must be in [0, 1] (got 1.5): slerp interpolates between the two "
                      "orientations; extrapolating past them is not supported");
    CHECK_THROWS_WITH(Slerp::start({{1, 0, 0, 0}, {1, 0, 0, 0}, -0.25}),
                      Catch::StartsWith("u: must be in [0, 1]"));
    CHECK_THROWS_WITH(Slerp::start({{1, 0, 0, 0}, {1, 0, 0, 0}, nan}),
                      "u: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Slerp::start({{1.5e308, 1.5e308, 0, 0}, {1, 0, 0, 0}, 0.5}),
                      Catch::StartsWith("q0: is too large"));
    CHECK_NOTHROW(Slerp::start({{1e-300, 0, 0, 1e-300}, {1, 0, 0, 0}, 0.5}));

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("slerp");
    auto error = [&](const std::string& text) {
        try {
            a.create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(error(R"({"q0": [1, 0, 0, 0], "q1": [0, 0, 0, 1], "u": 0.5})") == "(accepted)");
    CHECK(error(R"({"q0": [1, 0, 0], "q1": [0, 0, 0, 1], "u": 0.5})") ==
          "q0: must be a quaternion [w, x, y, z], got an array ([1,0,0])");
    CHECK_THAT(error(R"({"q0": [1, 0, 0, "a"], "q1": [0, 0, 0, 1], "u": 0.5})"),
               Catch::StartsWith("q0[3]: "));
    CHECK_THAT(error(R"({"q0": [1, 0, 0, 0], "q1": [0, 0, 0, 1]})"),
               Catch::StartsWith("u: is missing"));
    CHECK(error(R"({"q0": [0, 0, 0, 0], "q1": [0, 0, 0, 1], "u": 0.5})") ==
          "q0: must not be the zero quaternion [0, 0, 0, 0]: it is no rotation and cannot be "
          "normalised");
}

TEST_CASE("slerp: traces are deterministic and stepping back reproduces them",
          "[transforms][slerp]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("slerp");
    REQUIRE(a);
    cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);
    auto run = a->create(a->example());
    while (!run->done()) run->step(nullptr);
    const cg::json r = a->result(*run);
    CHECK(r["q"].size() == 4);
    CHECK(r["omega_deg"].get<double>() == Approx(60));
    CHECK(r["matrix"].size() == 3);
    CHECK(r["flipped"] == false);
}

TEST_CASE("slerp: the paths — slerp on the sphere, the matrix blend inside it",
          "[transforms][slerp]") {
    auto s = Slerp::start({{1, 0, 0, 1}, {1, 1, 0, 0}, 0.5});
    while (!Slerp::done(s)) Slerp::step(s, nullptr);
    REQUIRE(s.tip_slerp.size() == Slerp::kSamples);
    for (int k = 0; k < Slerp::kSamples; ++k) {
        CAPTURE(k);
        CHECK(glm::length(s.tip_slerp[k]) == Approx(1).epsilon(1e-14));
        CHECK(glm::length(s.tip_euler[k]) == Approx(1).epsilon(1e-14));
        if (k > 0 && k + 1 < Slerp::kSamples) CHECK(glm::length(s.tip_matrix[k]) < 0.95);
    }
    // Constant speed on the sphere (for the tip, the steps along slerp's path are equal here
    // because the rotation axis of q1 q̄0 is fixed and the tip's circle about it is uniform).
    const double first = glm::length(s.tip_slerp[1] - s.tip_slerp[0]);
    for (int k = 1; k < Slerp::kSamples; ++k)
        CHECK(glm::length(s.tip_slerp[k] - s.tip_slerp[k - 1]) == Approx(first).epsilon(1e-9));
    // The ends agree for all three.
    CHECK(glm::length(s.tip_euler.back() - s.tip_slerp.back()) < 1e-12);
    CHECK(glm::length(s.tip_matrix.front() - s.tip_slerp.front()) < 1e-12);
    cg::Scene scene;
    Slerp::draw(s, scene);
    CHECK(scene.has_3d());
    CHECK(scene.faces3.size() >= 8);  // the house
    std::map<std::string, int> names;  // each key and each path named once
    for (const auto& l : scene.labels3) ++names[l.text];
    for (const char* name : {"q0 x̂", "q1 x̂", "slerp", "lerp of matrices", "lerp of Euler angles"})
        CHECK(names[name] == 1);
    CHECK(scene.view3.orthographic);  // face-on to the arc's plane: the arc bows off the chord
    int red = 0, green = 0;
    for (const auto& seg : scene.segments3) {
        red += seg.style.role == cg::Role::Discarded;
        green += seg.style.role == cg::Role::Kept;
    }
    CHECK(red == Slerp::kSamples - 1);
    CHECK(green == Slerp::kSamples - 1);
}
