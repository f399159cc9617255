// Euler angles: exam cases worked by hand (the lock at ±90°, the order mattering); 10,000
// random orders and angles — a fifth of them locked — against glm::eulerAngle* and against
// products of glm::rotate; the lock's lost degree of freedom (θ1 and θ3 trade off exactly,
// and the derivatives with respect to them are parallel); errors; determinism; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "support/traced.hpp"
#include "support/replay.hpp"

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/euler_angles.hpp>

#include "io/registry.hpp"
#include "transforms/euler_angles.hpp"

using cg::EulerAngles;
using glm::dmat3;
using glm::dvec3;

namespace {

using Traced = cg::test::Traced<EulerAngles>;

Traced run_traced(const EulerAngles::Input& in) { return cg::test::run_traced<EulerAngles>(in); }

dmat3 from_rows(std::initializer_list<std::initializer_list<double>> rows) {
    dmat3 m(0.0);
    int r = 0;
    for (const auto& row : rows) {
        int c = 0;
        for (double v : row) m[c++][r] = v;
        ++r;
    }
    return m;
}

double diff(const dmat3& a, const dmat3& b) {
    return cg::rot::max_diff(a, b);
}

// GLM's matrix for order "abc" with angles (θ1, θ2, θ3): eulerAngleCBA(θ3, θ2, θ1).
dmat3 glm_euler(const std::string& order, dvec3 deg) {
    const double t1 = glm::radians(deg[0]), t2 = glm::radians(deg[1]), t3 = glm::radians(deg[2]);
    if (order == "xyz") return dmat3(glm::eulerAngleZYX(t3, t2, t1));
    if (order == "xzy") return dmat3(glm::eulerAngleYZX(t3, t2, t1));
    if (order == "yxz") return dmat3(glm::eulerAngleZXY(t3, t2, t1));
    if (order == "yzx") return dmat3(glm::eulerAngleXZY(t3, t2, t1));
    if (order == "zxy") return dmat3(glm::eulerAngleYXZ(t3, t2, t1));
    return dmat3(glm::eulerAngleXYZ(t3, t2, t1));  // "zyx"
}

// The same from glm::rotate: the first roll applied first (rightmost).
dmat3 glm_rotates(const std::string& order, dvec3 deg) {
    glm::dmat4 m(1.0);
    for (int n = 0; n < 3; ++n) {
        dvec3 axis(0);
        axis[order[n] - 'x'] = 1;
        m = glm::rotate(glm::dmat4(1.0), glm::radians(deg[n]), axis) * m;
    }
    return dmat3(m);
}

}  // namespace

TEST_CASE("euler-angles: exam cases worked by hand", "[transforms][euler-angles]") {
    SECTION("xyz (30°, 90°, 45°): locked, R = R_z(θ3 − θ1) R_y(90°)") {
        const Traced t = run_traced({"xyz", {30, 90, 45}});
        CHECK(t.steps.size() == 5);
        CHECK(t.steps[4].event == "gimbal-lock");
        CHECK(t.result.gimbal_lock);
        CHECK(t.result.lock_sign == -1);
        CHECK(t.result.lock_angle_deg == Approx(15));
        const double c = std::cos(M_PI / 12), s = std::sin(M_PI / 12);
        CHECK(diff(t.result.matrix, from_rows({{0, -s, c}, {0, c, s}, {-1, 0, 0}})) < 1e-15);
        CHECK_THAT(t.steps[4].narration,
                   Catch::Contains("R = R_z(θ3 − θ1) R_y(θ2), and only θ3 − θ1 = 15° matters"));
        CHECK_THAT(t.steps[4].narration, Catch::Contains("the angles (60°, 90°, 75°)"));
    }
    SECTION("a quarter turn each: x, then y, then z") {
        const Traced t = run_traced({"xyz", {90, 0, 90}});
        // R_z(90) R_x(90): x → y, y → z, z → x.
        CHECK(t.result.matrix == from_rows({{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}));
        CHECK_FALSE(t.result.gimbal_lock);
        CHECK(t.steps[4].event == "no-lock");
    }
    SECTION("the order matters: the same angles, reversed order, another matrix") {
        const auto a = EulerAngles::compose({"xyz", {90, 0, 90}}).matrix;
        const auto b = EulerAngles::compose({"zyx", {90, 0, 90}}).matrix;
        CHECK(b == from_rows({{0, -1, 0}, {0, 0, -1}, {1, 0, 0}}));  // R_x(90) R_z(90)
        CHECK(diff(a, b) > 0.5);
    }
    SECTION("zxy with θ2 = −90°: locked with the sum") {
        const Traced t = run_traced({"zxy", {20, -90, 50}});
        CHECK(t.result.gimbal_lock);
        // R_x(−90°) takes z to y: R = R_y(θ3 + θ1) R_x(−90°).
        CHECK(t.result.lock_sign == 1);
        CHECK(t.result.lock_angle_deg == Approx(70));
        CHECK(diff(t.result.matrix, cg::rot::rotation(1, cg::rot::cos_sin_deg(70)) *
                                        cg::rot::rotation(0, cg::rot::cos_sin_deg(-90))) < 1e-15);
    }
    SECTION("270° is −90°: locked too") {
        CHECK(EulerAngles::compose({"yzx", {10, 270, 10}}).gimbal_lock);
        CHECK_FALSE(EulerAngles::compose({"yzx", {10, 89.999, 10}}).gimbal_lock);
    }
}

TEST_CASE("euler-angles: 10,000 random orders and angles agree with GLM",
          "[transforms][euler-angles]") {
    static const char* kOrders[] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx"};
    int locked = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        cg::Rng rng(trial);
        EulerAngles::Input in{
            kOrders[trial % 6],
            {rng.uniform(-360, 360), rng.uniform(-360, 360), rng.uniform(-360, 360)}};
        if (trial % 5 == 0) in.angles_deg[1] = 90.0 * (2 * rng.integer(-3, 2) + 1);  // ±90, ±270…
        if (trial % 7 == 0) in.angles_deg[0] = 30.0 * rng.integer(-12, 12);
        CAPTURE(trial, in.order, in.angles_deg.x, in.angles_deg.y, in.angles_deg.z);
        const auto r = cg::run_to_end<EulerAngles>(EulerAngles::start(in));
        REQUIRE(EulerAngles::compose(in) == r);
        REQUIRE(diff(r.matrix, glm_euler(in.order, in.angles_deg)) <= 1e-9);
        REQUIRE(diff(r.matrix, glm_rotates(in.order, in.angles_deg)) <= 1e-9);
        const bool lock = std::fabs(std::cos(glm::radians(in.angles_deg[1]))) < 1e-9;
        REQUIRE(r.gimbal_lock == lock);
        locked += lock;
        // Partial derivatives of R with respect to θ1 and θ3 (central differences).
        const double h = 1e-4;
        auto R = [&](dvec3 d) { return cg::rot::euler_matrix(in.order, in.angles_deg + d); };
        const dmat3 d1 = (R({h, 0, 0}) - R({-h, 0, 0})) / (2 * h);
        const dmat3 d3 = (R({0, 0, h}) - R({0, 0, -h})) / (2 * h);
        if (lock) {
            // The lost degree of freedom: θ1 + δ and θ3 − sδ give the same matrix, for any δ...
            for (double delta : {30.0, -75.0, 123.0})
                REQUIRE(diff(R({delta, 0, -r.lock_sign * delta}), r.matrix) <= 1e-12);
            // ... and the matrix depends on θ3 + sθ1 only: dR/dθ1 = s dR/dθ3.
            REQUIRE(diff(d1, double(r.lock_sign) * d3) <= 1e-6);
            REQUIRE(diff(r.matrix, cg::rot::euler_matrix(
                                       in.order, {0, in.angles_deg[1], r.lock_angle_deg})) <= 1e-9);
        } else {
            REQUIRE(r.lock_sign == 0);
            REQUIRE(diff(d1, d3) > 1e-6);
            REQUIRE(diff(d1, -1.0 * d3) > 1e-6);
        }
    }
    CHECK(locked >= 2000);
}

TEST_CASE("euler-angles: bad input names the field", "[transforms][euler-angles]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const char* bad : {"xxy", "xy", "xyzx", "XYZ", "abc", "", "xzx"}) {
        CAPTURE(bad);
        CHECK_THROWS_WITH(EulerAngles::start({bad, {0, 0, 0}}),
                          Catch::StartsWith("order: must name the three axes once each"));
    }
    CHECK_THROWS_WITH(EulerAngles::start({"xyz", {0, nan, 0}}),
                      "angles_deg[1]: must be a finite number (got NaN)");
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("euler-angles");
    auto error = [&](const std::string& text) {
        try {
            a.create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(error(R"({"order": "zyx", "angles_deg": [1, 2, 3]})") == "(accepted)");
    CHECK_THAT(error(R"({"order": "yxy", "angles_deg": [1, 2, 3]})"),
               Catch::StartsWith("order: must name the three axes once each"));
    CHECK_THAT(error(R"({"order": 3, "angles_deg": [1, 2, 3]})"),
               Catch::StartsWith("order: must be a string"));
    CHECK_THAT(error(R"({"order": "xyz", "angles_deg": [1, 2]})"),
               Catch::StartsWith("angles_deg: "));
    CHECK_THAT(error(R"({"order": "xyz"})"), Catch::StartsWith("angles_deg: is missing"));
    CHECK_THAT(error(R"({"order": "xyz", "angles": [1, 2, 3]})"),
               Catch::StartsWith("angles: is not a known field"));
}

TEST_CASE("euler-angles: traces are deterministic and stepping back reproduces them",
          "[transforms][euler-angles]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("euler-angles");
    REQUIRE(a);
    cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);
    cg::test::check_replay(*a, cg::json::parse(R"({"order": "zyx", "angles_deg": [30, 20, 10]})"),
                           2);
    auto run = a->create(a->example());
    while (!run->done()) run->step(nullptr);
    const cg::json r = a->result(*run);
    CHECK(r["gimbal_lock"] == true);
    CHECK(r["lock_sign"] == -1);
    CHECK(r["matrix"].size() == 3);
}

TEST_CASE("euler-angles: the picture shows the rolls and, at the lock, two axes in one",
          "[transforms][euler-angles]") {
    auto axes_of = [](const cg::Scene& scene, cg::Role role) {
        std::vector<dvec3> out;
        for (const auto& seg : scene.segments3)
            if (seg.arrow && seg.style.role == role && seg.label.empty())
                out.push_back(glm::normalize(seg.b));
        return out;
    };
    for (const bool lock : {true, false}) {
        CAPTURE(lock);
        auto s = EulerAngles::start({"xyz", {30, lock ? 90.0 : 60.0, 45}});
        EulerAngles::step(s, nullptr);
        cg::Scene first;
        EulerAngles::draw(s, first);
        bool roll_axis = false;
        for (const auto& seg : first.segments3)
            roll_axis = roll_axis || seg.label == "roll about x";
        CHECK(roll_axis);
        CHECK(first.faces3.size() == 16);  // the house and its ghost
        while (!EulerAngles::done(s)) EulerAngles::step(s, nullptr);
        cg::Scene scene;
        EulerAngles::draw(s, scene);
        const auto red = axes_of(scene, cg::Role::Discarded);
        if (lock) {
            REQUIRE(red.size() == 2);  // inner and outer axes, parallel
            CHECK(glm::length(glm::cross(red[0], red[1])) < 1e-12);
        } else {
            CHECK(red.empty());
            const auto inner = axes_of(scene, cg::Role::Leaving),
                       outer = axes_of(scene, cg::Role::Window);
            REQUIRE(inner.size() == 1);
            REQUIRE(outer.size() == 1);
            CHECK(glm::length(glm::cross(inner[0], outer[0])) > 0.3);
        }
        // The house's frame is R's columns.
        REQUIRE(scene.frames3.size() == 2);
        CHECK(scene.frames3[1].x == s.R[0]);
        CHECK(scene.frames3[1].z == s.R[2]);
    }
}

TEST_CASE("rotations: every step's 3D picture is finite, on examples, presets and exam problems",
          "[transforms][euler-angles][slerp][arbitrary-axis]") {
    const cg::Registry registry = cg::builtin_registry();
    auto finite = [](dvec3 p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    for (const char* id : {"arbitrary-axis", "slerp", "euler-angles"}) {
        const cg::Algorithm& a = *registry.find(id);
        std::vector<cg::json> inputs{a.example()};
        for (std::uint64_t seed = 0; seed < 40; ++seed) inputs.push_back(a.exam_input(seed));
        for (const cg::json& input : inputs) {
            CAPTURE(id, input.dump());
            auto run = a.create(input);
            while (!run->done()) {
                run->step(nullptr);
                cg::Scene scene;
                run->draw(scene);
                REQUIRE(scene.has_3d());
                for (const auto& f : scene.faces3)
                    for (const auto& p : f.points) REQUIRE(finite(p));
                for (const auto& s : scene.segments3) REQUIRE((finite(s.a) && finite(s.b)));
                for (const auto& p : scene.points3) REQUIRE(finite(p.p));
                for (const auto& l : scene.labels3) REQUIRE(finite(l.p));
                for (const auto& fr : scene.frames3)
                    REQUIRE((finite(fr.x) && finite(fr.y) && finite(fr.z)));
                REQUIRE(std::isfinite(scene.extent3));
            }
        }
    }
}
