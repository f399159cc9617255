// The projection pipeline's off-axis form, "frustum": {left, right, bottom, top, near, far}
// (glFrustum): a stereo eye's frustum worked by hand in both conventions; 5,000 random frustums
// against glm::frustum (= frustumRH_NO, OpenGL) and, for the course's convention, against it
// with the view's z negated; the corners of the near and far rectangles land on the NDC cube's
// corners (an independent check of every entry); the symmetric frustum equals the fov form;
// both conventions give the same clip coordinates; errors name the field; determinism; picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"
#include "transforms/perspective.hpp"

using cg::Perspective;
using glm::dmat4;
using glm::dvec3;
using glm::dvec4;
using Convention = Perspective::Convention;

namespace {

constexpr double kPi = 3.14159265358979323846;

double max_rel(const dmat4& a, const dmat4& b) {
    double scale = 1, e = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) scale = std::max(scale, std::fabs(b[c][r]));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) e = std::max(e, std::fabs(a[c][r] - b[c][r]));
    return e / scale;
}

Perspective::Input frustum(Convention c, double l, double r, double b, double t, double n, double f,
                           std::vector<dvec3> points = {}) {
    Perspective::Input in;
    in.convention = c;
    in.has_frustum = true;
    in.left = l, in.right = r, in.bottom = b, in.top = t, in.near = n, in.far = f;
    in.points = std::move(points);
    return in;
}

// The course's view looks down +z: a view point (x, y, depth); OpenGL's down −z.
dvec3 at(Convention c, double x, double y, double depth) {
    return {x, y, c == Convention::Course ? depth : -depth};
}

}  // namespace

TEST_CASE("perspective frustum: a stereo eye's off-axis frustum, worked by hand",
          "[transforms][perspective][frustum]") {
    // l = −1, r = 3, b = −1, t = 1, n = 1, f = 3: 2n/(r−l) = 0.5, (r+l)/(r−l) = 0.5,
    // 2n/(t−b) = 1, (t+b)/(t−b) = 0, (f+n)/(f−n) = 2, 2fn/(f−n) = 3.
    for (Convention c : {Convention::OpenGL, Convention::Course}) {
        const bool gl = c == Convention::OpenGL;
        CAPTURE(gl);
        const double s = gl ? -1 : 1;  // the sign of the third column
        const auto in = frustum(c, -1, 3, -1, 1, 1, 3,
                                {at(c, 3, 1, 1), at(c, -1, -1, 1), at(c, 9, 3, 3), at(c, 2, 0, 2)});
        const auto t = cg::test::run_traced<Perspective>(in);
        const dmat4& p = t.result.projection;
        CHECK(p == dmat4(dvec4(0.5, 0, 0, 0), dvec4(0, 1, 0, 0), dvec4(-0.5 * s, 0, 2 * s, s),
                         dvec4(0, 0, -3, 0)));
        // The near rectangle's corners go to (±1, ±1, −1), the far one's to (±1, ±1, +1).
        CHECK(*t.result.ndc[0] == dvec3(1, 1, -1));
        CHECK(*t.result.ndc[1] == dvec3(-1, -1, -1));
        CHECK(*t.result.ndc[2] == dvec3(1, 1, 1));
        // The window's centre (1, 0) scaled to depth 2 is the centre of NDC x and y.
        CHECK(t.result.ndc[3]->x == 0);
        CHECK(t.result.ndc[3]->y == 0);
        REQUIRE(t.steps[2].event == "projection-matrix");
        const std::string& say = t.steps[2].narration;
        CHECK_THAT(say, Catch::Contains("near rectangle x ∈ [−1, 3], y ∈ [−1, 1] at depth n = 1"));
        CHECK_THAT(say, Catch::Contains("2n/(r−l) = 0.5, 2n/(t−b) = 1"));
        CHECK_THAT(say, Catch::Contains(gl ? "(r+l)/(r−l) = 0.5" : "−(r+l)/(r−l) = −0.5"));
        CHECK_THAT(say, Catch::Contains("off-axis"));
        CHECK_THAT(t.steps[2].math, Catch::Contains("\\frac{2n}{r-l}"));
        REQUIRE(t.steps[0].vars.size() >= 6);
        CHECK(t.steps[0].vars[0].name == "left");
        CHECK(t.steps[0].vars[3].name == "top");
    }
}

TEST_CASE("perspective frustum: 5,000 random frustums against glm::frustum, and the corners",
          "[transforms][perspective][frustum]") {
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        double l = rng.uniform(-3, 3), r = rng.uniform(-3, 3);
        double b = rng.uniform(-3, 3), t = rng.uniform(-3, 3);
        if (l > r) std::swap(l, r);
        if (b > t) std::swap(b, t);
        if (r - l < 1e-3 || t - b < 1e-3) continue;
        const double n = rng.uniform(0.05, 5), f = n * rng.uniform(1.01, 1000);
        CAPTURE(trial, l, r, b, t, n, f);
        auto gl = frustum(Convention::OpenGL, l, r, b, t, n, f);
        auto course = frustum(Convention::Course, l, r, b, t, n, f);
        const dmat4 pg = Perspective::projection_matrix(gl),
                    pc = Perspective::projection_matrix(course);
        REQUIRE(max_rel(pg, glm::frustum(l, r, b, t, n, f)) < 1e-14);
        REQUIRE(max_rel(pg, glm::frustumRH_NO(l, r, b, t, n, f)) < 1e-14);
        // The course's view z is OpenGL's −z: P_course = P_gl · diag(1, 1, −1, 1).
        dmat4 flip(1.0);
        flip[2][2] = -1;
        REQUIRE(max_rel(pc, glm::frustumRH_NO(l, r, b, t, n, f) * flip) < 1e-14);
        // Independent of GLM: the eight corners go to the NDC cube's corners.
        for (Convention c : {Convention::OpenGL, Convention::Course}) {
            const dmat4& p = c == Convention::OpenGL ? pg : pc;
            for (double depth : {n, f})
                for (int corner = 0; corner < 4; ++corner) {
                    const double x = (corner & 1) ? r : l, y = (corner & 2) ? t : b;
                    const dvec4 clip = p * dvec4(at(c, x * depth / n, y * depth / n, depth), 1);
                    REQUIRE(std::fabs(clip.w - depth) < 1e-12 * depth);
                    const dvec3 ndc = dvec3(clip) / clip.w;
                    REQUIRE(std::fabs(ndc.x - ((corner & 1) ? 1 : -1)) < 1e-9);
                    REQUIRE(std::fabs(ndc.y - ((corner & 2) ? 1 : -1)) < 1e-9);
                    REQUIRE(std::fabs(ndc.z - (depth == n ? -1 : 1)) < 1e-9);
                }
        }
        // The same world point, a look-at camera: the same clip coordinates in both conventions,
        // the state machine equal to the plain function.
        gl.look_at = course.look_at = true;
        gl.eye = course.eye = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
        gl.center = course.center = gl.eye + dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 2);
        gl.points = course.points = {{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4)}};
        const auto rg = cg::run_to_end<Perspective>(Perspective::start(gl));
        const auto rc = cg::run_to_end<Perspective>(Perspective::start(course));
        REQUIRE(rg == Perspective::project(gl));
        REQUIRE(rc == Perspective::project(course));
        const dvec4 a = rg.clip[0], c = rc.clip[0];
        REQUIRE(glm::length(a - c) <= 1e-12 * std::max(1.0, glm::length(a)));
        const dmat4 ref =
            glm::frustumRH_NO(l, r, b, t, n, f) * glm::lookAtRH(gl.eye, gl.center, dvec3(0, 1, 0));
        const dvec4 expect = ref * dvec4(gl.points[0], 1);
        REQUIRE(glm::length(a - expect) <= 1e-9 * std::max(1.0, glm::length(expect)));
    }
}

TEST_CASE("perspective frustum: the symmetric frustum is the fov form",
          "[transforms][perspective][frustum]") {
    for (int trial = 0; trial < 2000; ++trial) {
        cg::Rng rng(trial);
        Perspective::Input fov;
        fov.convention = trial % 2 ? Convention::OpenGL : Convention::Course;
        fov.fov_y_deg = trial % 10 == 0 ? 90 : rng.uniform(5, 170);
        fov.aspect = rng.uniform(0.25, 4);
        fov.near = rng.uniform(0.1, 3);
        fov.far = fov.near * rng.uniform(1.5, 100);
        for (int k = 0; k < 4; ++k)
            fov.points.push_back(
                at(fov.convention, rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-1, 30)));
        const double t = fov.near * std::tan(fov.fov_y_deg * kPi / 360), r = fov.aspect * t;
        Perspective::Input fr = fov;
        fr.has_frustum = true;
        fr.left = -r, fr.right = r, fr.bottom = -t, fr.top = t;
        CAPTURE(trial, fov.fov_y_deg, fov.aspect);
        REQUIRE(max_rel(Perspective::projection_matrix(fr), Perspective::projection_matrix(fov)) <
                1e-14);
        const auto a = Perspective::project(fov), b = Perspective::project(fr);
        for (std::size_t k = 0; k < a.clip.size(); ++k) {
            REQUIRE(glm::length(a.clip[k] - b.clip[k]) <= 1e-13 * glm::length(a.clip[k]));
            REQUIRE(a.ndc[k].has_value() == b.ndc[k].has_value());
        }
    }
    // With 90° and aspect 1 both give the course's exam matrix exactly.
    auto sym = frustum(Convention::Course, -1, 1, -1, 1, 1, 3);
    Perspective::Input fov;
    fov.near = 1, fov.far = 3;
    CHECK(Perspective::projection_matrix(sym) == Perspective::projection_matrix(fov));
    const auto t = cg::test::run_traced<Perspective>(sym);
    CHECK_THAT(t.steps[2].narration, Catch::Contains("(symmetric: the same as the fov form)"));
}

TEST_CASE("perspective frustum: bad input names the field", "[transforms][perspective][frustum]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    using C = Convention;
    CHECK_THROWS_WITH(Perspective::start(frustum(C::OpenGL, 1, 1, -1, 1, 1, 3)),
                      "frustum.right: must be greater than left (1 ≤ 1): the near rectangle has "
                      "no width");
    CHECK_THROWS_WITH(Perspective::start(frustum(C::OpenGL, -1, 1, 2, 1, 1, 3)),
                      "frustum.top: must be greater than bottom (1 ≤ 2): the near rectangle has "
                      "no height");
    CHECK_THROWS_WITH(Perspective::start(frustum(C::Course, -1, 1, -1, 1, 0, 3)),
                      "frustum.near: must be positive: the near plane lies in front of the eye "
                      "(got 0)");
    CHECK_THROWS_WITH(Perspective::start(frustum(C::Course, -1, 1, -1, 1, 2, 2)),
                      "frustum.far: must be greater than near (2 ≤ 2)");
    CHECK_THROWS_WITH(Perspective::start(frustum(C::Course, nan, 1, -1, 1, 1, 3)),
                      "frustum.left: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(Perspective::start(frustum(C::Course, -1e308, 1e308, -1, 1, 1, 3)),
                      Catch::StartsWith("frustum.right: left −10³⁰⁸ and right 10³⁰⁸ give a "
                                        "matrix too large or too small"));
    CHECK_THROWS_WITH(Perspective::start(frustum(C::Course, -1, 1, 0, 1e-310, 1, 3)),
                      Catch::StartsWith("frustum.top: bottom 0 and top 10⁻³¹⁰ give a matrix"));

    using cg::test::error_of;
    const std::string good =
        R"({"convention": "opengl", "frustum": {"left": -1, "right": 3, "bottom": -1, "top": 1,
            "near": 1, "far": 3}, "points": [[1, 0, -2]]})";
    CHECK(error_of("perspective", good) == "(accepted)");
    auto with = [&](const std::string& extra) {
        return error_of("perspective", good.substr(0, good.size() - 1) + ", " + extra + "}");
    };
    CHECK(with(R"("near": 1)") ==
          "near: cannot be given with \"frustum\": give either fov_y_deg, aspect, near and far, "
          "or a frustum {left, right, bottom, top, near, far}");
    CHECK_THAT(with(R"("fov_y_deg": 90)"), Catch::StartsWith("fov_y_deg: cannot be given with"));
    CHECK_THAT(with(R"("aspect": 1)"), Catch::StartsWith("aspect: cannot be given with"));
    CHECK_THAT(error_of("perspective", R"({"convention": "opengl", "points": []})"),
               Catch::StartsWith("fov_y_deg: is missing"));
    CHECK_THAT(
        error_of("perspective",
                 R"({"convention": "opengl", "frustum": {"left": -1, "right": 1, "bottom": -1,
                            "top": 1, "near": 1}, "points": []})"),
        Catch::StartsWith("frustum.far: is missing"));
    CHECK_THAT(
        error_of("perspective",
                 R"({"convention": "opengl", "frustum": {"left": -1, "right": 1, "bottom": -1,
                            "top": 1, "near": 1, "far": 3, "depth": 2}, "points": []})"),
        Catch::StartsWith("frustum.depth: is not a known field"));
    CHECK_THAT(
        error_of("perspective", R"({"convention": "opengl", "frustum": [1, 2], "points": []})"),
        Catch::StartsWith("frustum: "));
    CHECK_THAT(
        error_of("perspective",
                 R"({"convention": "opengl", "frustum": {"left": 1, "right": -1, "bottom": -1,
                            "top": 1, "near": 1, "far": 3}, "points": []})"),
        Catch::StartsWith("frustum.right: must be greater than left"));
}

TEST_CASE("perspective frustum: determinism, stepping back, the lesson's preset and its picture",
          "[transforms][perspective][frustum]") {
    const cg::Algorithm& a = cg::test::algorithm("perspective");
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* lesson = lib.for_algorithm("perspective");
    REQUIRE(lesson);
    int off_axis = 0;
    for (const auto& p : lesson->presets) {
        if (!p.input.contains("frustum")) continue;
        ++off_axis;
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, cg::test::kEveryStep);
    }
    CHECK(off_axis >= 1);

    // The picture: the near rectangle's corners are the frustum's, off the view axis.
    auto s = Perspective::start(frustum(Convention::OpenGL, -1, 3, -1, 1, 1, 3, {{1, 0, -2}}));
    while (!Perspective::done(s)) Perspective::step(s, nullptr);
    cg::Scene scene;
    Perspective::draw(s, scene);
    REQUIRE(scene.faces3.size() >= 2);
    const auto& near_quad = scene.faces3[0].points;
    REQUIRE(near_quad.size() == 4);
    CHECK(near_quad[0] == dvec3(-1, -1, -1));
    CHECK(near_quad[2] == dvec3(3, 1, -1));
    const auto& far_quad = scene.faces3[1].points;
    CHECK(far_quad[2] == dvec3(9, 3, -3));
}
