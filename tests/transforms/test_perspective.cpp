// The projection pipeline: exam cases worked by hand (the course's matrix with cot 45° = 1);
// 5,000 random cameras against GLM (glm::perspectiveLH_NO for the course's matrix,
// glm::perspectiveRH_NO = glm::perspective for OpenGL's, glm::lookAtRH for the view) to 1e-9;
// the two conventions give the same clip coordinates; near and far go to −1 and +1; near-plane
// clipping against the cut computed in view space in long double; errors; determinism; the
// picture; exam problems.
#include <catch2/catch.hpp>

#include "support/traced.hpp"
#include "support/replay.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "transforms/perspective.hpp"

using cg::Perspective;
using glm::dmat4;
using glm::dvec3;
using glm::dvec4;
using Convention = Perspective::Convention;

namespace {

constexpr double kPi = 3.14159265358979323846;

using Traced = cg::test::Traced<Perspective>;

Traced run_traced(const Perspective::Input& in) { return cg::test::run_traced<Perspective>(in); }

using cg::test::events;

std::array<double, 4> row(const dmat4& m, int r) { return {m[0][r], m[1][r], m[2][r], m[3][r]}; }

double max_rel(const dmat4& a, const dmat4& b) {
    double scale = 1, e = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) scale = std::max(scale, std::fabs(b[c][r]));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) e = std::max(e, std::fabs(a[c][r] - b[c][r]));
    return e / scale;
}

Perspective::Input basic(Convention c, std::vector<dvec3> points) {
    Perspective::Input in;
    in.convention = c;
    in.fov_y_deg = 90;
    in.aspect = 1;
    in.near = 1;
    in.far = 3;
    in.points = std::move(points);
    return in;
}

}  // namespace

TEST_CASE("perspective: exam cases worked by hand", "[transforms][perspective]") {
    SECTION("the course's matrix, fov 90°, near 1, far 3") {
        // c = cot 45° = 1; (f+n)/(f−n) = 2, −2fn/(f−n) = −3. P0 = (1, 0.5, 2): clip (1, 0.5, 1, 2),
        // NDC (0.5, 0.25, 0.5). P1 = (−1, 1, 4): clip (−1, 1, 5, 4): z > w, beyond far.
        // P2 = (0.2, 0, 0.5): clip (0.2, 0, −2, 0.5): nearer than near. P3 = (1, 1, −1): w = −1.
        auto in = basic(Convention::Course, {{1, 0.5, 2}, {-1, 1, 4}, {0.2, 0, 0.5}, {1, 1, -1}});
        const Traced t = run_traced(in);
        CHECK(row(t.result.projection, 0) == std::array<double, 4>{1, 0, 0, 0});
        CHECK(row(t.result.projection, 1) == std::array<double, 4>{0, 1, 0, 0});
        CHECK(row(t.result.projection, 2) == std::array<double, 4>{0, 0, 2, -3});
        CHECK(row(t.result.projection, 3) == std::array<double, 4>{0, 0, 1, 0});
        CHECK(t.result.clip[0] == dvec4(1, 0.5, 1, 2));
        CHECK(t.result.ndc[0] == dvec3(0.5, 0.25, 0.5));
        CHECK(t.result.clip[1] == dvec4(-1, 1, 5, 4));
        CHECK(t.result.ndc[1] == dvec3(-0.25, 0.25, 1.25));
        CHECK(t.result.clip[2] == dvec4(0.2, 0, -2, 0.5));
        CHECK(t.result.clip[3] == dvec4(1, 1, -5, -1));
        CHECK_FALSE(t.result.ndc[3].has_value());
        CHECK(t.result.inside == std::vector<bool>{true, false, false, false});
        CHECK(events(t) == std::vector<std::string>{
                               "model-matrix", "view-identity", "projection-matrix",
                               "point-to-view", "inside-volume", "divide",
                               "point-to-view", "outside-volume", "divide",
                               "point-to-view", "outside-volume", "divide",
                               "point-to-view", "behind-eye", "no-divide"});
        CHECK(t.steps[2].narration ==
              "fov_y = 90°: c = cot(45°) = 1, c/a = 1 for aspect 1; near 1, far 3: (f+n)/(f−n) = 2, "
              "−2fn/(f−n) = −3, and w = z. P = [1 0 0 0; 0 1 0 0; 0 0 2 −3; 0 0 1 0]: depth n goes "
              "to z_ndc = −1, depth f to +1.");
        CHECK(t.steps[7].narration ==
              "P1_clip = P p_view = (−1, 1, 5, 4): w = 4 > 0 but z > w (beyond the far plane): "
              "outside the view volume (it would be clipped).");
        CHECK_THAT(t.steps[14].narration, Catch::Contains("mirrored through the centre"));
    }
    SECTION("OpenGL's convention: the same picture with z negated") {
        auto in = basic(Convention::OpenGL, {{1, 0.5, -2}, {0, 0, -1}, {0, 0, -3}});
        const Traced t = run_traced(in);
        CHECK(row(t.result.projection, 2) == std::array<double, 4>{0, 0, -2, -3});
        CHECK(row(t.result.projection, 3) == std::array<double, 4>{0, 0, -1, 0});
        CHECK(t.result.clip[0] == dvec4(1, 0.5, 1, 2));
        CHECK(t.result.ndc[1] == dvec3(0, 0, -1));  // near → −1
        CHECK(t.result.ndc[2] == dvec3(0, 0, 1));   // far → +1
        CHECK(t.steps[1].event == "view-identity");
    }
    SECTION("a look-at, a model matrix and a viewport") {
        // OpenGL, eye (0, 0, 5) looking at the origin: V = translate(0, 0, −5). The model moves
        // the point by (1, 0, 0).
        auto in = basic(Convention::OpenGL, {{0, 1, 0}});
        in.look_at = true;
        in.eye = {0, 0, 5};
        in.center = {0, 0, 0};
        in.far = 9;
        in.has_model = true;
        in.model = glm::translate(dmat4(1.0), dvec3(1, 0, 0));
        in.has_viewport = true;
        in.viewport = {800, 600};
        in.aspect = 800.0 / 600;
        const Traced t = run_traced(in);
        CHECK(row(t.result.view, 2) == std::array<double, 4>{0, 0, 1, -5});
        CHECK(t.result.world[0] == dvec3(1, 1, 0));
        CHECK(t.result.eye_coords[0] == dvec3(1, 1, -5));
        CHECK(t.result.clip[0].w == 5);
        CHECK(t.result.ndc[0]->x == Approx(0.75 / 5));
        CHECK(t.result.ndc[0]->y == Approx(0.2));
        CHECK(t.result.device[0]->x == Approx((0.15 + 1) * 400));
        CHECK(t.result.device[0]->y == Approx(1.2 * 300));
        CHECK(events(t)[1] == "view-frame");
        CHECK(events(t).back() == "to-viewport");
        CHECK(max_rel(t.result.mvp, t.result.projection * t.result.view * t.result.model) == 0);
    }
    SECTION("a segment from behind the eye across the near plane") {
        // Course, n = 1, f = 3: A = (0.5, 0.5, −1): clip (0.5, 0.5, −5, −1), d_A = −6; B = (0.5,
        // −0.5, 2): clip (0.5, −0.5, 1, 2), d_B = 3. t = 6/9 = 2/3: the cut (0.5, −1/6, −1, 1).
        auto in = basic(Convention::Course, {});
        in.segments = {{dvec3(0.5, 0.5, -1), dvec3(0.5, -0.5, 2)},
                       {dvec3(0, 0, 0.5), dvec3(1, 0, -2)},
                       {dvec3(0, 0, 1.5), dvec3(1, 1, 2.5)}};
        const Traced t = run_traced(in);
        CHECK(events(t) == std::vector<std::string>{"model-matrix", "view-identity",
                                                    "projection-matrix", "segment-clipped",
                                                    "segment-divide", "segment-rejected",
                                                    "segment-kept", "segment-divide"});
        const auto& g = t.result.segments[0];
        CHECK(g.status == Perspective::SegmentStatus::Clipped);
        CHECK(g.t0 == Approx(2.0 / 3));
        CHECK(g.t1 == 1);
        CHECK(g.kept[0].w == Approx(1));
        CHECK(g.kept[0].y == Approx(-1.0 / 6));
        CHECK(g.ndc[0].z == -1);
        CHECK(g.ndc[1] == dvec3(0.25, -0.25, 0.5));
        CHECK_THAT(t.steps[4].narration, Catch::Contains("on the wrong side of the screen"));
        CHECK(t.result.segments[1].status == Perspective::SegmentStatus::Rejected);
        CHECK(t.result.segments[2].status == Perspective::SegmentStatus::Inside);
    }
}

TEST_CASE("perspective: 5,000 random cameras agree with GLM", "[transforms][perspective]") {
    int inside = 0, behind = 0, clipped = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        Perspective::Input in;
        in.convention = trial % 2 ? Convention::OpenGL : Convention::Course;
        in.fov_y_deg = rng.uniform(1, 179);
        in.aspect = rng.uniform(0.2, 5);
        in.near = rng.uniform(0.01, 10);
        in.far = in.near * rng.uniform(1.01, 1000);
        in.look_at = trial % 5 != 0;
        if (in.look_at) {
            in.eye = {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)};
            in.center = in.eye + dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            in.up = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        }
        const int n = static_cast<int>(rng.integer(0, 6));
        for (int k = 0; k < n; ++k)
            in.points.push_back({rng.uniform(-100, 100), rng.uniform(-100, 100), rng.uniform(-100, 100)});
        for (int k = 0; k < 2; ++k)
            in.segments.push_back({dvec3(rng.uniform(-100, 100), rng.uniform(-100, 100), rng.uniform(-100, 100)),
                                   dvec3(rng.uniform(-100, 100), rng.uniform(-100, 100), rng.uniform(-100, 100))});
        CAPTURE(trial);
        try {
            Perspective::validate(in);
        } catch (const cg::InputError&) {
            continue;  // a random up parallel to the view direction (never happens in practice)
        }
        const auto r = cg::run_to_end<Perspective>(Perspective::start(in));
        REQUIRE(Perspective::project(in) == r);

        const double fovy = in.fov_y_deg * kPi / 180;
        const bool course = in.convention == Convention::Course;
        const dmat4 p_ref = course ? glm::perspectiveLH_NO(fovy, in.aspect, in.near, in.far)
                                   : glm::perspectiveRH_NO(fovy, in.aspect, in.near, in.far);
        REQUIRE(max_rel(r.projection, p_ref) < 1e-9);
        if (!course) REQUIRE(max_rel(r.projection, glm::perspective(fovy, in.aspect, in.near, in.far)) < 1e-9);
        dmat4 v_ref = in.look_at ? glm::lookAtRH(in.eye, in.center, in.up) : dmat4(1.0);
        if (course && in.look_at)  // the course's view frame has z along +f̂: negate row 2
            for (int c = 0; c < 4; ++c) v_ref[c][2] = -v_ref[c][2];
        REQUIRE(max_rel(r.view, v_ref) < 1e-9);
        // Either convention: the same clip matrix P V as OpenGL's for the same camera.
        if (in.look_at) {
            const dmat4 gl = glm::perspectiveRH_NO(fovy, in.aspect, in.near, in.far) *
                             glm::lookAtRH(in.eye, in.center, in.up);
            REQUIRE(max_rel(r.projection * r.view, gl) < 1e-9);
        }
        const dmat4 mvp = p_ref * v_ref;
        for (int k = 0; k < n; ++k) {
            const dvec4 c = mvp * dvec4(in.points[k], 1.0);
            const double scale = 1 + std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z) + std::fabs(c.w);
            for (int i = 0; i < 4; ++i) REQUIRE(std::fabs(r.clip[k][i] - c[i]) < 1e-9 * scale);
            REQUIRE(r.ndc[k].has_value() == (r.clip[k].w > 0));
            if (r.ndc[k]) {
                const dvec3 q = dvec3(c) / c.w;
                const double s2 = scale / std::fabs(c.w);
                for (int i = 0; i < 3; ++i) REQUIRE(std::fabs((*r.ndc[k])[i] - q[i]) < 1e-8 * s2);
                inside += r.inside[k];
            } else {
                ++behind;
            }
        }
        // Near-plane clipping against the cut found in view space, in long double.
        for (std::size_t k = 0; k < in.segments.size(); ++k) {
            using ld = long double;
            const auto& g = r.segments[k];
            auto depth = [&](dvec3 p) {  // distance along the view direction
                const dvec3 v = dvec3(v_ref * dvec4(p, 1.0));
                return course ? ld(v.z) : -ld(v.z);
            };
            const ld da = depth(in.segments[k][0]), db = depth(in.segments[k][1]);
            const ld n0 = in.near;
            if (da >= n0 && db >= n0) {
                REQUIRE(g.status == Perspective::SegmentStatus::Inside);
            } else if (da < n0 && db < n0) {
                REQUIRE(g.status == Perspective::SegmentStatus::Rejected);
            } else {
                REQUIRE(g.status == Perspective::SegmentStatus::Clipped);
                ++clipped;
                const ld t = (n0 - da) / (db - da);
                const double t_cut = da < n0 ? g.t0 : g.t1;
                REQUIRE(std::fabs(ld(t_cut) - t) < 1e-9L);
                REQUIRE((da < n0 ? g.t1 : g.t0) == (da < n0 ? 1.0 : 0.0));
                REQUIRE(g.ndc[da < n0 ? 0 : 1].z == -1);
                for (int e = 0; e < 2; ++e) {
                    REQUIRE(g.kept[e].w > 0);
                    REQUIRE(std::isfinite(g.ndc[e].x));
                }
            }
        }
    }
    CHECK(inside > 200);
    CHECK(behind > 1000);
    CHECK(clipped > 1000);
}

TEST_CASE("perspective: near goes to −1, far to +1, in both conventions", "[transforms][perspective]") {
    for (int trial = 0; trial < 1000; ++trial) {
        cg::Rng rng(100000 + trial);
        for (Convention c : {Convention::Course, Convention::OpenGL}) {
            Perspective::Input in;
            in.convention = c;
            in.fov_y_deg = rng.uniform(5, 175);
            in.aspect = rng.uniform(0.3, 3);
            in.near = rng.uniform(0.05, 5);
            in.far = in.near + rng.uniform(0.1, 500);
            const double z = c == Convention::Course ? 1 : -1;
            const double x = rng.uniform(-1, 1), y = rng.uniform(-1, 1);
            in.points = {{x, y, z * in.near}, {x, y, z * in.far}};
            CAPTURE(trial);
            const auto r = Perspective::project(in);
            REQUIRE(r.ndc[0]->z == Approx(-1).epsilon(1e-12));
            REQUIRE(r.ndc[1]->z == Approx(1).epsilon(1e-12));
            // Depth is monotonic: a point halfway lands strictly between.
            in.points = {{x, y, z * (in.near + in.far) / 2}};
            const double mid = Perspective::project(in).ndc[0]->z;
            REQUIRE(mid > -1);
            REQUIRE(mid < 1);
        }
    }
}

TEST_CASE("perspective: bad input names the field", "[transforms][perspective]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto in = basic(Convention::Course, {{0, 0, 2}});
    auto with = [&](auto change) {
        auto copy = in;
        change(copy);
        return copy;
    };
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.near = 0; })),
                      "near: must be positive: the near plane lies in front of the eye (got 0)");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.near = -1; })),
                      "near: must be positive: the near plane lies in front of the eye (got −1)");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.far = 1; })), "far: must be greater than near (1 ≤ 1)");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.fov_y_deg = 180; })),
                      "fov_y_deg: must be between 0 and 180 degrees, both excluded (got 180)");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.fov_y_deg = 0; })),
                      "fov_y_deg: must be between 0 and 180 degrees, both excluded (got 0)");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.aspect = 0; })),
                      "aspect: must be positive: it is width / height (got 0)");
    CHECK_THROWS_WITH(Perspective::start(with([&](auto& i) { i.aspect = nan; })),
                      "aspect: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Perspective::start(with([&](auto& i) { i.points[0].y = nan; })),
                      "points[0][1]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) {
                          i.look_at = true;
                          i.eye = i.center = {1, 2, 3};
                      })),
                      "center: must differ from eye (1, 2, 3): the view direction center − eye is zero");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) {
                          i.look_at = true;
                          i.eye = {0, 0, 0};
                          i.center = {0, 5, 0};
                          i.up = {0, 2, 0};
                      })),
                      Catch::StartsWith("up: must not be parallel to the view direction center − eye = (0, 5, 0)"));
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) {
                          i.look_at = true;
                          i.up = {0, 0, 0};
                      })),
                      "up: must not be the zero vector");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) {
                          i.has_model = true;
                          i.model[0][3] = 1;
                      })),
                      Catch::StartsWith("model[3]: must be [0, 0, 0, 1]"));
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) {
                          i.has_viewport = true;
                          i.viewport = {640, 0};
                      })),
                      Catch::StartsWith("viewport[1]: must be positive"));
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.points[0] = {1, 1, 1e308}; })),
                      Catch::StartsWith("points[0]: is too large to project"));
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.points[0] = {1e10, 0, 1e-300}; })),
                      Catch::StartsWith("points[0]: lies too close to the eye's plane to divide"));
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) { i.segments = {{dvec3(1), dvec3(1)}}; })),
                      "segments[0]: has both ends at (1, 1, 1): not a segment");
    CHECK_THROWS_WITH(Perspective::start(with([](auto& i) {
                          i.near = 1e-6;
                          i.segments = {{dvec3(0, 0, -1e6), dvec3(0, 0, 1)}};
                      })),
                      Catch::StartsWith("segments[0][0]: lies too far"));

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("perspective");
    auto error = [&](const std::string& fields) {
        try {
            a.create(cg::parse_json(R"({"convention": "course", "fov_y_deg": 90, "aspect": 1, "near": 1, "far": 3, )" + fields + "}"));
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(error(R"("points": [[0, 0, 2]])") == "(accepted)");
    CHECK(error(R"("points": [], "eye": [0, 0, -5], "center": [0, 0, 0], "segments": [[[0, 0, 1], [1, 1, 1]]], "viewport": [4, 3])") == "(accepted)");
    CHECK(error(R"("points": [], "eye": [0, 0, -5])") == "center: is missing: a look-at needs both eye and center");
    CHECK(error(R"("points": [], "up": [0, 1, 0])") == "up: needs eye and center: without a look-at the view matrix is I");
    CHECK_THAT(error(R"("points": [], "model": [[1, 0, 0], [0, 1, 0], [0, 0, 1]])"),
               Catch::StartsWith("model: must be a 4×4 matrix"));
    CHECK_THAT(error(R"("points": [], "segments": [[[0, 0, 1]]])"), Catch::StartsWith("segments[0]: must be a segment"));
    CHECK_THAT(error(R"("points": [], "fov": 60)"), Catch::StartsWith("fov: is not a known field"));
    CHECK_THAT(error(R"("points": [], "viewport": [4])"), Catch::StartsWith("viewport: must be [width, height]"));
    try {
        a.create(cg::parse_json(R"({"convention": "directx", "fov_y_deg": 90, "aspect": 1, "near": 1, "far": 3, "points": []})"));
        FAIL("accepted");
    } catch (const cg::InputError& e) {
        CHECK_THAT(std::string(e.what()), Catch::StartsWith("convention: must be \"course\""));
    }
}

TEST_CASE("perspective: traces are deterministic and stepping back reproduces them", "[transforms][perspective]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("perspective");
    REQUIRE(a);
    cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);
    auto run = a->create(a->example());
    while (!run->done()) run->step(nullptr);
    const cg::json r = a->result(*run);
    CHECK(r["matrix"] == cg::json::parse("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 2, -3], [0, 0, 1, 0]]"));
    CHECK(r["clip"][0] == cg::json::parse("[1, 0.5, 1, 2]"));
    CHECK(r["ndc"][0] == cg::json::parse("[0.5, 0.25, 0.5]"));
    CHECK(r["ndc"][3].is_null());
    CHECK(r["device"][0] == cg::json::parse("[480, 400]"));
    CHECK(r["segments"][0]["status"] == "clipped");
}

TEST_CASE("perspective: the picture shows the frustum in 3D and NDC in 2D", "[transforms][perspective]") {
    auto in = basic(Convention::Course, {{1, 0.5, 2}, {0.2, 0, 0.5}});
    in.look_at = true;
    in.eye = {0, 0, -2};
    in.center = {0, 0, 0};
    in.segments = {{dvec3(0.5, 0.5, -3), dvec3(0.5, -0.5, 1)}};
    auto s = Perspective::start(in);
    cg::Scene scene;
    Perspective::draw(s, scene);
    CHECK(scene.faces3.size() == 6);  // near, far and four sides
    // The eye, with its frame r, u, f̂ as three arrows (f̂ toward the centre).
    int eye = 0;
    for (const auto& p : scene.points3) eye += p.label == "eye" && p.p == dvec3(0, 0, -2);
    CHECK(eye == 1);
    std::vector<std::string> frame;
    for (const auto& g : scene.segments3)
        if (g.arrow && g.a == dvec3(0, 0, -2)) frame.push_back(g.label);
    CHECK(frame == std::vector<std::string>{"r", "u", "f̂"});
    REQUIRE(scene.focus3.size() == 1);  // the frustum, the eye and the points
    CHECK(scene.focus3[0].lo.z <= -2);
    while (!Perspective::done(s)) Perspective::step(s, nullptr);
    scene.clear();
    Perspective::draw(s, scene);
    CHECK(scene.has_2d());
    CHECK(scene.has_3d());
    int rays = 0, cut = 0, ndc_points = 0;
    for (const auto& g : scene.segments3) rays += g.style.dashed && g.b == dvec3(0, 0, -2);
    for (const auto& p : scene.points3) cut += p.label == "cut";
    for (const auto& p : scene.points) ndc_points += !p.label.empty();
    CHECK(rays == 2);
    CHECK(cut == 1);
    CHECK(ndc_points == 2);
    bool kept2d = false;
    for (const auto& g : scene.segments) kept2d = kept2d || g.label == "segment 0";
    CHECK(kept2d);
}

TEST_CASE("perspective: exam problems use short decimals and grade their own answers", "[transforms][perspective]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("perspective");
    int behind = 0, segments = 0, look_at = 0;
    for (std::uint64_t seed = 0; seed < 500; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
        for (const auto& r : p.expected["matrix"])
            for (const auto& v : r) CHECK(std::fabs(v.get<double>() * 40 - std::round(v.get<double>() * 40)) < 1e-12);
        for (const auto& q : p.expected["ndc"]) behind += q.is_null();
        segments += p.input.contains("segments");
        look_at += p.input.contains("eye");
    }
    CHECK(behind > 5);
    CHECK(segments > 50);
    CHECK(look_at > 50);
}
