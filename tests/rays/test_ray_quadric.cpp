// Ray-quadric intersection: the course's exam case and hand cases for every branch (tangent,
// eye inside, linear, misses, unnormalised directions, the cone's apex, a ray lying in the
// surface, slabs, transforms); 10,000 random rays per quadric (half of them through random
// transforms with non-uniform scale, shear and rotation, a quarter cut by a slab) against the
// independent long-double solver of quadric_reference.hpp; the state machine against the plain
// function; errors; exam problems; determinism and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <set>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "rays/quadric_reference.hpp"
#include "rays/ray_quadric.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"

using cg::Quadric;
using cg::QuadricKind;
using cg::RayQuadric;
using glm::dvec3;

namespace {

using cg::test::events;
using cg::test::registry;
using Traced = cg::test::JsonTraced;

cg::test::JsonTraced run_json(const std::string& text) {
    return cg::test::run_json("ray-quadric", text);
}

std::string error_of(const std::string& text) {
    return cg::test::error_of("ray-quadric", text);
}

using Events = std::vector<std::string>;

bool near(const cg::json& j, std::vector<double> want, double tol = 1e-12) {
    if (!j.is_array() || j.size() != want.size()) return false;
    for (std::size_t i = 0; i < want.size(); ++i)
        if (std::fabs(j[i].get<double>() - want[i]) > tol) return false;
    return true;
}

}  // namespace

TEST_CASE("ray-quadric: the course's paraboloid question, the linear case", "[rays][ray-quadric]") {
    // x² + y² = z, ray (1, 1, 5) + t(0, 0, −1): a = 0, b = 1, c = −3 → t = 3, P = (1, 1, 2),
    // ∇F = (2x, 2y, −1) = (2, 2, −1), n = (2, 2, −1)/3.
    const Traced t = run_json(
        R"({"quadric": {"type": "paraboloid", "params": {"p": 1, "q": 1}}, "origin": [1, 1, 5], "direction": [0, 0, -1]})");
    CHECK(events(t) == Events{"no-transform", "coefficients", "linear", "roots", "nearest",
                              "hit-point", "normal"});
    CHECK(t.result["hit"] == true);
    CHECK(t.result["roots"] == cg::json::parse("[3]"));
    CHECK(t.result["t"] == 3);
    CHECK(t.result["point"] == cg::json::parse("[1, 1, 2]"));
    CHECK(near(t.result["normal"], {2.0 / 3, 2.0 / 3, -1.0 / 3}));
    // The coefficients are shown symbolically and with their numbers.
    CHECK(t.steps[1].math.find("a = \\frac{d_x^2}{p^2} + \\frac{d_y^2}{q^2} = 0") !=
          std::string::npos);
    CHECK(t.steps[1].math.find("- E_z = -3") != std::string::npos);
    CHECK(t.steps[1].narration.find("a = 0") != std::string::npos);
}

TEST_CASE("ray-quadric: hand cases for every branch", "[rays][ray-quadric]") {
    SECTION("sphere, two roots") {
        const Traced t = run_json(
            R"({"quadric": {"type": "sphere", "params": {"r": 1}}, "origin": [0, 0, 5], "direction": [0, 0, -1]})");
        CHECK(events(t) == Events{"no-transform", "coefficients", "two-roots", "roots", "nearest",
                                  "hit-point", "normal"});
        CHECK(t.result["roots"] == cg::json::parse("[4, 6]"));
        CHECK(t.result["t"] == 4);
        CHECK(t.result["point"] == cg::json::parse("[0, 0, 1]"));
        CHECK(t.result["normal"] == cg::json::parse("[0, 0, 1]"));
    }
    SECTION("tangent: one double root") {
        const Traced t = run_json(
            R"({"quadric": {"type": "sphere", "params": {"r": 1}}, "origin": [0, 1, 5], "direction": [0, 0, -1]})");
        CHECK(events(t)[2] == "tangent");
        CHECK(t.result["roots"] == cg::json::parse("[5]"));
        CHECK(t.result["point"] == cg::json::parse("[0, 1, 0]"));
        CHECK(t.result["normal"] == cg::json::parse("[0, 1, 0]"));
    }
    SECTION("tangent through a transform (an ellipsoid scaled and moved)") {
        // Ellipsoid 2, 1, 1 scaled by 2 in y and moved by (1, 0, 0): in the world it is
        // (x − 1)²/4 + y²/4 + z² = 1, touched by the line x = 3, y = 0.
        const Traced t = run_json(
            R"({"quadric": {"type": "ellipsoid", "params": {"a": 2, "b": 1, "c": 1}, "transform": [[1, 0, 0, 1], [0, 2, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}, "origin": [3, 0, -4], "direction": [0, 0, 2]})");
        CHECK(events(t) == Events{"to-model", "coefficients", "tangent", "roots", "nearest",
                                  "hit-point", "normal"});
        CHECK(t.result["roots"] == cg::json::parse("[2]"));
        CHECK(t.result["point"] == cg::json::parse("[3, 0, 0]"));
        CHECK(t.result["normal"] == cg::json::parse("[1, 0, 0]"));
    }
    SECTION("the eye inside: the root behind is skipped") {
        const Traced t = run_json(
            R"({"quadric": {"type": "sphere", "params": {"r": 2}}, "origin": [0, 0, 0], "direction": [1, 0, 0]})");
        CHECK(t.result["roots"] == cg::json::parse("[-2, 2]"));
        CHECK(t.result["t"] == 2);
        CHECK(t.result["normal"] == cg::json::parse("[1, 0, 0]"));  // outward, not toward the eye
        CHECK(t.steps[1].narration.find("inside") != std::string::npos);
        CHECK(t.steps[4].narration.find("not > ε") != std::string::npos);
    }
    SECTION("a direction that is not unit: t in its units") {
        const Traced t = run_json(
            R"({"quadric": {"type": "sphere", "params": {"r": 1}}, "origin": [0, 0, 5], "direction": [0, 0, -2]})");
        CHECK(t.result["roots"] == cg::json::parse("[2, 3]"));
        CHECK(t.result["t"] == 2);
        CHECK(t.result["point"] == cg::json::parse("[0, 0, 1]"));
    }
    SECTION("a miss: no real root") {
        const Traced t = run_json(
            R"({"quadric": {"type": "sphere", "params": {"r": 1}}, "origin": [2, 0, 5], "direction": [0, 0, -1]})");
        CHECK(events(t) == Events{"no-transform", "coefficients", "no-roots"});
        CHECK(t.result["hit"] == false);
        CHECK(t.result["roots"] == cg::json::array());
        CHECK(t.result["t"].is_null());
        CHECK(t.result["point"].is_null());
        CHECK(t.result["normal"].is_null());
    }
    SECTION("a miss: both roots behind the eye") {
        const Traced t = run_json(
            R"({"quadric": {"type": "sphere", "params": {"r": 1}}, "origin": [0, 0, 5], "direction": [0, 0, 1]})");
        CHECK(events(t).back() == "miss");
        CHECK(t.result["roots"] == cg::json::parse("[-6, -4]"));
        CHECK(t.result["hit"] == false);
    }
    SECTION("cone: a ray parallel to the axis crosses both nappes (still quadratic)") {
        // x² + y² = z², ray (1, 0, 5) − t z: z² = 1 at t = 4 and t = 6.
        const Traced t = run_json(
            R"({"quadric": {"type": "cone", "params": {"p": 1, "q": 1, "r": 1}}, "origin": [1, 0, 5], "direction": [0, 0, -1]})");
        CHECK(events(t)[2] == "two-roots");
        CHECK(t.result["roots"] == cg::json::parse("[4, 6]"));
        CHECK(near(t.result["normal"], {std::sqrt(0.5), 0, -std::sqrt(0.5)}));
    }
    SECTION("cone: a ray parallel to a generator is the linear case") {
        // Direction (1, 0, 1) lies on the cone x² = z²: a = 0. From (0, 1, 0): b = 0 too? No:
        // b = 2(x dx − z dz) = 0 and c = 1 − 0 = 1: never meets. From (−2, 0, 0): b = −4,
        // c = 4, t = 1 at the apex-side point (−1, 0, 1).
        const Traced miss = run_json(
            R"({"quadric": {"type": "cone", "params": {"p": 1, "q": 1, "r": 1}}, "origin": [0, 1, 0], "direction": [1, 0, 1]})");
        CHECK(events(miss).back() == "no-solution");
        CHECK(miss.result["hit"] == false);
        const Traced t = run_json(
            R"({"quadric": {"type": "cone", "params": {"p": 1, "q": 1, "r": 1}}, "origin": [-2, 0, 0], "direction": [1, 0, 1]})");
        CHECK(events(t)[2] == "linear");
        CHECK(t.result["roots"] == cg::json::parse("[1]"));
        CHECK(t.result["point"] == cg::json::parse("[-1, 0, 1]"));
    }
    SECTION("cone: through the apex, the normal is undefined") {
        const Traced t = run_json(
            R"({"quadric": {"type": "cone", "params": {"p": 1, "q": 2, "r": 1}}, "origin": [0, 0, 5], "direction": [0, 0, -1]})");
        CHECK(events(t) == Events{"no-transform", "coefficients", "tangent", "roots", "nearest",
                                  "hit-point", "apex"});
        CHECK(t.result["hit"] == true);
        CHECK(t.result["point"] == cg::json::parse("[0, 0, 0]"));
        CHECK(t.result["normal"].is_null());
    }
    SECTION("cone: a ray along a ruling lies in the surface") {
        const Traced t = run_json(
            R"({"quadric": {"type": "cone", "params": {"p": 1, "q": 1, "r": 1}}, "origin": [1, 0, 1], "direction": [1, 0, 1]})");
        CHECK(events(t).back() == "in-surface");
        CHECK(t.result["hit"] == false);
    }
    SECTION("cylinder: a ray parallel to the axis never meets it") {
        const Traced t = run_json(
            R"({"quadric": {"type": "cylinder", "params": {"p": 2, "q": 1}}, "origin": [0, 0, 5], "direction": [0, 0, -1]})");
        CHECK(events(t).back() == "no-solution");
    }
    SECTION("paraboloid: the axis-parallel ray from below, inside") {
        const Traced t = run_json(
            R"({"quadric": {"type": "paraboloid", "params": {"p": 2, "q": 1}}, "origin": [2, 0, -3], "direction": [0, 0, 4]})");
        // z = x²/4 = 1 at the wall: t = (1 + 3)/4 = 1.
        CHECK(events(t)[2] == "linear");
        CHECK(t.result["t"] == 1);
        CHECK(near(t.result["normal"], {1 / std::sqrt(2.0), 0, -1 / std::sqrt(2.0)}));
    }
    SECTION("hyperboloid of one sheet from outside") {
        const Traced t = run_json(
            R"({"quadric": {"type": "hyperboloid", "params": {"a": 1, "b": 1, "c": 1}}, "origin": [5, 0, 0], "direction": [-1, 0, 0]})");
        CHECK(t.result["roots"] == cg::json::parse("[4, 6]"));
        CHECK(t.result["normal"] == cg::json::parse("[1, 0, 0]"));
    }
    SECTION("a slab cuts the first root away: the ray sees the inside of the open cylinder") {
        // x = −3 + t, z = −3 + t meets x² = 1 at t = 2 (z = −1, cut by zmin = 0) and t = 4.
        const Traced t = run_json(
            R"({"quadric": {"type": "cylinder", "params": {"p": 1, "q": 1}, "zmin": 0, "zmax": 5}, "origin": [-3, 0, -3], "direction": [1, 0, 1]})");
        CHECK(t.result["roots"] == cg::json::parse("[2, 4]"));
        CHECK(t.result["t"] == 4);
        CHECK(t.result["normal"] == cg::json::parse("[1, 0, 0]"));
        CHECK(t.steps[4].narration.find("outside the slab") != std::string::npos);
        const Traced both = run_json(
            R"({"quadric": {"type": "cylinder", "params": {"p": 1, "q": 1}, "zmin": -0.5, "zmax": 0.5}, "origin": [-3, 0, -3], "direction": [1, 0, 1]})");
        CHECK(events(both).back() == "miss");
    }
    SECTION("a transformed sphere: solve in model space, scale back") {
        // Unit sphere scaled by 2 in x and moved by (1, 0, 0); ray from (10, 0, 0) along −x:
        // E_m = (4.5, 0, 0), d_m = (−0.5, 0, 0), roots 7 and 11, P = (3, 0, 0).
        const Traced t = run_json(
            R"({"quadric": {"type": "sphere", "params": {"r": 1}, "transform": [[2, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}, "origin": [10, 0, 0], "direction": [-1, 0, 0]})");
        CHECK(t.result["roots"] == cg::json::parse("[7, 11]"));
        CHECK(t.result["point"] == cg::json::parse("[3, 0, 0]"));
        CHECK(t.result["normal"] == cg::json::parse("[1, 0, 0]"));
        CHECK(t.steps[0].narration.find("(4.5, 0, 0)") != std::string::npos);
    }
    SECTION("the normal under non-uniform scale needs the inverse transpose") {
        // The unit sphere scaled by (2, 1, 1): the ellipse x²/4 + y² = 1 in the plane z = 0.
        // At P = (√2, √0.5, 0) the true normal is ∝ (x/4, y) = (√2/4, √0.5), not M n_m.
        const double x = std::sqrt(2.0), y = std::sqrt(0.5);
        Quadric q;
        q.world_from_model = glm::scale(glm::dmat4(1.0), dvec3(2, 1, 1));
        const dvec3 P{x, y, 0};
        const cg::QuadricHit h = cg::intersect(q, P + dvec3(0, 3, 0), {0, -1, 0});
        REQUIRE(h.hit);
        CHECK(h.point.x == Approx(x));
        CHECK(h.point.y == Approx(y));
        const dvec3 want = glm::normalize(dvec3(x / 4, y, 0));
        CHECK(glm::length(h.normal - want) < 1e-12);
    }
}

TEST_CASE("ray-quadric: 10,000 random rays per quadric agree with a long-double solver",
          "[rays][ray-quadric][reference]") {
    std::size_t near_degenerate = 0, total = 0, hits = 0, machine_checked = 0;
    for (int kind = 0; kind < 6; ++kind) {
        cg::Rng rng(1000 + kind);
        for (int trial = 0; trial < 10'000; ++trial) {
            Quadric q;
            q.kind = static_cast<QuadricKind>(kind);
            q.r = rng.uniform(0.3, 3), q.a = rng.uniform(0.3, 3), q.b = rng.uniform(0.3, 3);
            q.c = rng.uniform(0.3, 3), q.p = rng.uniform(0.3, 3), q.q = rng.uniform(0.3, 3);
            const double L = 3;
            if (rng.chance(0.5)) {  // rotation · shear · non-uniform scale, then a translation
                glm::dmat4 m = glm::translate(
                    glm::dmat4(1.0), {rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3)});
                m = glm::rotate(m, rng.uniform(0, 6.283),
                                glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1),
                                                     rng.uniform(0.1, 1))));
                glm::dmat4 shear(1.0);
                shear[1][0] = rng.uniform(-1, 1), shear[2][0] = rng.uniform(-1, 1),
                shear[2][1] = rng.uniform(-1, 1);
                m = m * shear *
                    glm::scale(glm::dmat4(1.0),
                               {rng.uniform(0.3, 3), rng.uniform(0.3, 3), rng.uniform(0.3, 3)});
                q.world_from_model = m;
            }
            if (rng.chance(0.25)) {
                q.zmin = rng.uniform(-2 * L, L);
                q.zmax = q.zmin + rng.uniform(0.5, 3 * L);
            }
            const dvec3 target_m{rng.uniform(-L, L), rng.uniform(-L, L), rng.uniform(-L, L)};
            const dvec3 target = dvec3(q.world_from_model * glm::dvec4(target_m, 1.0));
            const dvec3 o{rng.uniform(-8, 8), rng.uniform(-8, 8), rng.uniform(-8, 8)};
            dvec3 d = (target - o) * rng.uniform(0.1, 10);
            if (rng.chance(0.2)) d = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
            CAPTURE(kind, trial, o.x, o.y, o.z, d.x, d.y, d.z);
            ++total;

            const cg::QuadricHit h = cg::intersect(q, o, d);
            const cg::test::LongHit ref = cg::test::reference_intersect(q, o, d);
            if (ref.count > 0 && std::fabs(ref.disc_rel) < 1e-9) {  // within round-off of tangent
                ++near_degenerate;
                continue;
            }
            REQUIRE(h.root_count == ref.count);
            for (int i = 0; i < ref.count; ++i) {
                const long double want = ref.roots[i];
                CHECK(std::fabs(h.roots[i] - want) <=
                      1e-9L * std::max<long double>(1, std::fabs(want)));
            }
            // The chosen root: skip the rare rays whose hit sits within round-off of ε or of
            // a slab face, where either answer is right.
            bool borderline = false;
            for (int i = 0; i < ref.count; ++i) {
                const long double t = ref.roots[i];
                const dvec3 pm =
                    cg::prepare(q).linear_inv * (o + double(t) * d - dvec3(q.world_from_model[3]));
                borderline = borderline || std::fabs(t) < 1e-7 || std::fabs(pm.z - q.zmin) < 1e-7 ||
                             std::fabs(pm.z - q.zmax) < 1e-7;
            }
            if (borderline) {
                ++near_degenerate;
                continue;
            }
            REQUIRE(h.hit == ref.hit);
            if (h.hit) {
                ++hits;
                CHECK(std::fabs(h.t - ref.t) <= 1e-9L * std::max<long double>(1, std::fabs(ref.t)));
                const long double size = glm::length(o) + std::fabs(h.t) * glm::length(d) + 1;
                for (int k = 0; k < 3; ++k)
                    CHECK(std::fabs(h.point[k] - ref.point[k]) <= 1e-9L * size);
                CHECK(cg::test::relative_residual(q, h.point) < 1e-9L);
                REQUIRE(h.has_normal);
                long double err = 0;
                for (int k = 0; k < 3; ++k) err += std::fabs(h.normal[k] - ref.normal[k]);
                CHECK(err < 1e-9L);
                CHECK(glm::length(h.normal) == Approx(1).epsilon(1e-14));
            }
            // Every 20th ray also through the state machine, quiet and narrated.
            if (trial % 20 == 0) {
                ++machine_checked;
                const RayQuadric::Input in{q, o, d};
                auto s = RayQuadric::start(in);
                auto narrated = s;
                CHECK(cg::run_to_end<RayQuadric>(s) == h);
                while (!RayQuadric::done(narrated)) {
                    cg::StepInfo info;
                    RayQuadric::step(narrated, &info);
                    CHECK(info.narration.find("nan") == std::string::npos);
                    CHECK(info.narration.find("inf") == std::string::npos);
                }
                CHECK(RayQuadric::result(narrated) == h);
            }
        }
    }
    CAPTURE(near_degenerate, total, hits);
    CHECK(hits > total / 4);                // the rays do hit, mostly
    CHECK(near_degenerate < total / 1000);  // and the skipped ones are rare
    CHECK(machine_checked == 3000);
}

TEST_CASE("ray-quadric: bad input is refused with the field named", "[rays][ray-quadric][errors]") {
    const std::string sphere = R"("quadric": {"type": "sphere", "params": {"r": 1}})";
    CHECK(error_of("{" + sphere + R"(, "origin": [0, 0, 5], "direction": [0, 0, 0]})") ==
          "direction: must not be the zero vector: a ray needs a direction");
    CHECK(
        error_of(
            R"({"quadric": {"type": "sphere", "params": {"r": 1}, "transform": [[1, 0, 0, 0], [0, 1, 0, 0], [1, 1, 0, 0], [0, 0, 0, 1]]}, "origin": [0, 0, 5], "direction": [0, 0, -1]})") ==
        "quadric.transform: is singular (determinant 0): it flattens space, so rays cannot be "
        "carried into model space");
    CHECK_THAT(
        error_of(
            R"({"quadric": {"type": "sphere", "params": {"r": 1}, "transform": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]}, "origin": [0, 0, 5], "direction": [0, 0, -1]})"),
        Catch::StartsWith("quadric.transform[3]: must be [0, 0, 0, 1]"));
    CHECK(
        error_of(
            R"({"quadric": {"type": "sphere", "params": {"r": -1}}, "origin": [0, 0, 5], "direction": [0, 0, -1]})") ==
        "quadric.params.r: must be positive: it is a semi-axis length (got −1)");
    CHECK(
        error_of(
            R"({"quadric": {"type": "cone", "params": {"p": 1, "q": 0, "r": 1}}, "origin": [0, 0, 5], "direction": [0, 0, -1]})") ==
        "quadric.params.q: must be positive: it is a semi-axis length (got 0)");
    CHECK_THAT(
        error_of(
            R"({"quadric": {"type": "cone", "params": {"p": 1, "q": 1}}, "origin": [0, 0, 5], "direction": [0, 0, -1]})"),
        Catch::StartsWith("quadric.params.r: is missing"));
    CHECK_THAT(
        error_of(
            R"({"quadric": {"type": "sphere", "params": {"r": 1, "a": 2}}, "origin": [0, 0, 5], "direction": [0, 0, -1]})"),
        Catch::StartsWith("quadric.params.a: is not a known field"));
    CHECK_THAT(
        error_of(
            R"({"quadric": {"type": "torus", "params": {"r": 1}}, "origin": [0, 0, 5], "direction": [0, 0, -1]})"),
        Catch::StartsWith("quadric.type: must be one of sphere, ellipsoid"));
    CHECK(
        error_of(
            R"({"quadric": {"type": "cylinder", "params": {"p": 1, "q": 1}, "zmin": 2, "zmax": 1}, "origin": [0, 0, 5], "direction": [0, 0, -1]})") ==
        "quadric.zmax: must be greater than zmin (1 ≤ 2): the slab is empty");
    CHECK_THAT(error_of("{" + sphere + R"(, "origin": [0, 0], "direction": [0, 0, -1]})"),
               Catch::StartsWith("origin: must be a point [x, y, z]"));
    CHECK_THAT(error_of("{" + sphere + R"(, "origin": [0, 0, 1e999], "direction": [0, 0, -1]})"),
               Catch::StartsWith("origin[2]: not valid JSON: number overflow"));
    CHECK_THAT(error_of("{" + sphere + R"(, "origin": [0, 0, 1e300], "direction": [0, 0, -1]})"),
               Catch::StartsWith("origin: is too far away"));
    CHECK_THAT(error_of("{" + sphere + R"(, "origin": [0, 0, 5], "direction": [0, 0, 1e-200]})"),
               Catch::StartsWith("direction: is too small or too large"));

    // NaN anywhere, from C++ (JSON cannot spell NaN): the field is named.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    RayQuadric::Input in;
    in.origin = {0, 0, 5};
    in.direction = {0, 0, -1};
    auto with = [&](auto change) {
        RayQuadric::Input copy = in;
        change(copy);
        try {
            RayQuadric::start(copy);
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(with([](auto&) {}) == "(accepted)");
    CHECK(with([&](auto& i) { i.origin.y = nan; }) ==
          "origin[1]: must be a finite number (got NaN)");
    CHECK(with([&](auto& i) { i.direction.z = nan; }) ==
          "direction[2]: must be a finite number (got NaN)");
    CHECK(with([&](auto& i) { i.quadric.r = nan; }) ==
          "quadric.params.r: must be a finite number (got NaN)");
    CHECK(with([&](auto& i) { i.quadric.world_from_model[3][1] = nan; }) ==
          "quadric.transform[1][3]: must be a finite number (got NaN)");
    CHECK(with([&](auto& i) { i.quadric.zmin = nan; }) ==
          "quadric.zmin: must be a finite number (got NaN)");
    CHECK(with([&](auto& i) {
              i.quadric.kind = QuadricKind::Ellipsoid;
              i.quadric.c = nan;
          }) == "quadric.params.c: must be a finite number (got NaN)");
    // Parameters of other kinds are not looked at.
    CHECK(with([&](auto& i) { i.quadric.p = nan; }) == "(accepted)");
}

TEST_CASE("ray-quadric: exam problems are nice and answered right", "[rays][ray-quadric][exam]") {
    const cg::Algorithm& a = *registry().find("ray-quadric");
    std::set<std::string> events;
    int hits = 0, transformed = 0, tangents = 0;
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const RayQuadric::Input in = [&] {
            cg::Rng rng(seed);
            return RayQuadric::exam_input(rng);
        }();
        const cg::test::LongHit ref =
            cg::test::reference_intersect(in.quadric, in.origin, in.direction);
        const cg::json& e = p.expected;
        const Traced traced = run_json(p.input.dump());
        for (const std::string& e : cg::test::events(traced)) events.insert(e);
        if (ref.a != 0 && std::fabs(ref.disc_rel) < 1e-12L) {
            // Tangent as posed ((−3, −2.4) on the ellipse x²/25 + y²/9 = 1), a hair off it
            // for the doubles nearest −2.4: the algorithm calls it tangent, as the exam means.
            const cg::Algorithm& alg = *registry().find("ray-quadric");
            auto run = alg.create(p.input);
            while (!run->done()) run->step(nullptr);
            const cg::json r = alg.result(*run);
            REQUIRE(r["roots"].size() == 1);
            CHECK(r["roots"][0].get<double>() == Approx(double(-ref.b / (2 * ref.a))));
            ++tangents;
            continue;
        }
        REQUIRE(e["hit"] == ref.hit);
        for (int i = 0; i < ref.count; ++i)  // every root a multiple of 1/8
            CHECK(std::fabs(ref.roots[i] * 8 - std::round(ref.roots[i] * 8)) < 1e-9L);
        if (ref.hit) {
            ++hits;
            CHECK(e["t"].get<double>() == Approx(double(ref.t)));
            for (int k = 0; k < 3; ++k)
                CHECK(e["point"][k].get<double>() == Approx(double(ref.point[k])).margin(1e-12));
        } else {
            CHECK(e["t"].is_null());
        }
        transformed += in.quadric.world_from_model != glm::dmat4(1.0);
        CHECK(p.question.find(cg::quadric_equation(in.quadric, false)) != std::string::npos);
        // Grading: the expected answer is right, a wrong t is not.
        CHECK(cg::grade(p, e)[1].correct);
        if (ref.hit) {
            cg::json wrong = e;
            wrong["t"] = e["t"].get<double>() + 0.5;
            CHECK_FALSE(cg::grade(p, wrong)[1].correct);
        }
    }
    CHECK(hits > 250);
    CHECK(tangents > 0);
    CHECK(transformed > 40);
    for (const char* ev :
         {"linear", "two-roots", "tangent", "miss", "apex", "to-model", "normal"}) {
        CAPTURE(ev);
        CHECK(events.count(ev) == 1);
    }
    RayQuadric::Input course;
    course.quadric.kind = QuadricKind::Paraboloid;
    course.origin = {1, 1, 5};
    course.direction = {0, 0, -1};
    CHECK(RayQuadric::question(course).rfind(
              "Intersect the ray (1, 1, 5) + t·(0, 0, −1) with the elliptic paraboloid x² + y² = "
              "z. Is there a hit",
              0) == 0);
}

TEST_CASE("ray-quadric: traces are deterministic and stepping back reproduces them",
          "[rays][ray-quadric]") {
    const cg::Algorithm& a = *registry().find("ray-quadric");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    cg::test::check_replay(
        a,
        cg::parse_json(
            R"({"quadric": {"type": "hyperboloid", "params": {"a": 1, "b": 2, "c": 1}, "transform": [[1, 0.5, 0, 1], [0, 2, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1]], "zmin": -1, "zmax": 2}, "origin": [6, 1, 0.5], "direction": [-1, 0, 0.25]})"),
        cg::test::kEveryStep);
    // The input written back reads the same.
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const cg::json j = a.exam_input(seed);
        CHECK(registry().find("ray-quadric")->create(j) != nullptr);
        CHECK(cg::exam_for_input(a, j).expected == cg::make_exam(a, seed).expected);
    }
}

TEST_CASE("ray-quadric: the picture shows the surface, the ray, the roots and f(t)",
          "[rays][ray-quadric]") {
    RayQuadric::Input in;
    in.quadric.kind = QuadricKind::Sphere;
    in.origin = {0, 0, 5};
    in.direction = {0, 0, -1};
    auto s = RayQuadric::start(in);
    cg::Scene before;
    RayQuadric::draw(s, before);
    CHECK(before.faces3.size() == 24 * 12);
    CHECK(before.panels.empty());  // no f(t) before the coefficients
    CHECK(before.focus3.size() == 1);
    while (!RayQuadric::done(s)) RayQuadric::step(s, nullptr);
    cg::Scene scene;
    RayQuadric::draw(s, scene);
    CHECK(scene.has_3d());
    CHECK_FALSE(scene.has_2d());  // f(t) is a chart, not drawn into the world
    int roots3 = 0, kept = 0;
    bool hit = false;
    for (const auto& p : scene.points3) {
        roots3 += p.label.rfind("t", 0) == 0;
        hit = hit || p.label == "P";
        kept += p.style.role == cg::Role::Kept;
    }
    CHECK(roots3 == 1);  // t₂; t₁ is the hit P
    CHECK(hit);
    CHECK(kept == 1);
    bool ray = false, normal = false;
    for (const auto& seg : scene.segments3) {
        ray = ray || (seg.arrow && seg.label == "E + t d");
        normal = normal || (seg.arrow && seg.label == "n" && seg.min_pixels >= 30);
    }
    CHECK(ray);
    CHECK(normal);
    // Every surface vertex lies on the sphere.
    for (const auto& f : scene.faces3)
        for (const auto& p : f.points) CHECK(glm::length(p) == Approx(1).epsilon(1e-12));
    // The camera frames the eye and the surface.
    REQUIRE(scene.focus3.size() == 1);
    CHECK(scene.focus3[0].hi.z >= 5);
    CHECK(scene.focus3[0].lo.z <= -1);
    // f(t) = t² − 10t + 24 in a chart of its own: the curve, and the roots 4 and 6 on f = 0.
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& chart = scene.panels[0];
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.x.label == "t");
    CHECK(chart.y.label == "f(t)");
    REQUIRE(chart.polygons.size() == 1);
    CHECK(chart.polygons[0].closed == false);
    for (const auto& p : chart.polygons[0].points)
        CHECK(p.y == Approx(p.x * p.x - 10 * p.x + 24).margin(1e-9));
    int roots2 = 0;
    for (const auto& p : chart.points)
        if (p.label.rfind("t", 0) == 0) {
            ++roots2;
            CHECK(p.p.y == 0);
            CHECK((p.p.x == Approx(4) || p.p.x == Approx(6)));
        }
    CHECK(roots2 == 2);
}
