// Projective shadows: the shadow matrix and the shadow points worked by hand (a point light over
// the floor, the sun, a tilted plane, every degenerate vertex); 6,000 random inputs — point and
// directional lights, any plane, with vertices on the plane, level with the light, above it,
// behind the plane and nearly parallel — against the ray–plane intersection in long double; M p
// on the plane and M M = h_L M; errors naming the field; replay on the example and the presets;
// the exam problems; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "shadows/projective_shadow.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::ProjectiveShadow;
using glm::dmat4;
using glm::dvec3;
using glm::dvec4;
using Input = ProjectiveShadow::Input;

namespace {

using LD = long double;

Input make(dvec3 n, double d, dvec4 light, std::vector<dvec3> poly) {
    Input in;
    in.normal = n;
    in.d = d;
    in.light = light;
    in.polygon = std::move(poly);
    return in;
}

const Input kFloor = make({0, 1, 0}, 0, {0, 4, 0, 1}, {{1, 2, 0}, {2, 2, 1}, {1, 1, 2}});

double row(const dmat4& m, int i, int j) {
    return m[j][i];
}

bool near3(const dvec3& a, const dvec3& b, double tol = 1e-12) {
    return std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol &&
           std::fabs(a.z - b.z) <= tol;
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("projective-shadow");
    if (!l) throw std::runtime_error("no lesson for projective-shadow");
    return *l;
}

Input input_of(const cg::json& j) {
    return cg::test::input_of<ProjectiveShadow>("projective-shadow", j);
}

}  // namespace

TEST_CASE("projective-shadow: a triangle under a point light onto the floor, by hand",
          "[shadows][projective-shadow]") {
    const auto t = cg::test::run_traced<ProjectiveShadow>(kFloor);
    CHECK(cg::test::events(t) ==
          std::vector<std::string>{"setup", "matrix", "vertex", "vertex", "vertex", "polygon"});
    // P = [0, 1, 0, 0], L = [0, 4, 0, 1], h_L = 4: M = 4I − L Pᵀ.
    const double want[4][4] = {{4, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 4, 0}, {0, -1, 0, 4}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) CHECK(row(t.result.matrix, i, j) == want[i][j]);
    CHECK(t.result.shadow[0] == dvec3(2, 0, 0));  // [4, 0, 0, 2] / 2
    CHECK(t.result.shadow[1] == dvec3(4, 0, 2));  // [8, 0, 4, 2] / 2
    CHECK(near3(t.result.shadow[2], {4.0 / 3, 0, 8.0 / 3}));
    CHECK(t.result.valid == std::vector<bool>{true, true, true});
    CHECK_FALSE(t.result.flipped);
    CHECK_THAT(t.steps[0].narration, Catch::Contains("h_L = P · L = n · L + d = 4 > 0"));
    CHECK_THAT(t.steps[2].narration,
               Catch::Contains("w′ = 2 > 0; divide by w′: s0 = (4, 0, 0) / 2 = (2, 0, 0)"));
    CHECK_THAT(t.steps[1].narration,
               Catch::Contains("M = [4, 0, 0, 0; 0, 0, 0, 0; 0, 0, 4, 0; 0, −1, 0, 4]"));
}

TEST_CASE("projective-shadow: the sun, a tilted plane, a turned-round plane, by hand",
          "[shadows][projective-shadow]") {
    SECTION("the sun: l = (1, 2, 1), n · l = 2, s = p − h_p l / 2") {
        const auto r = ProjectiveShadow::flatten(
            make({0, 1, 0}, 0, {1, 2, 1, 0}, {{0, 2, 0}, {2, 2, 0}, {1, 3, 2}}));
        CHECK(r.shadow[0] == dvec3(-1, 0, -1));
        CHECK(r.shadow[1] == dvec3(1, 0, -1));
        CHECK(r.shadow[2] == dvec3(-0.5, 0, 0.5));
        // M = 2I − [l, 0] [0, 1, 0, 0]: the bottom row is [0, 0, 0, 2] (w′ = n · l for all).
        CHECK(row(r.matrix, 3, 3) == 2);
        CHECK(row(r.matrix, 3, 1) == 0);
        CHECK(row(r.matrix, 0, 1) == -1);
        CHECK(row(r.matrix, 1, 1) == 0);
    }
    SECTION("a tilted plane x + 2y = 0, light (0, 6, 0): h_L = 12") {
        const Input in = make({1, 2, 0}, 0, {0, 6, 0, 1}, {{1, 2, 0}, {2, 2, 1}, {0, 3, 2}});
        const auto r = ProjectiveShadow::flatten(in);
        // p0: h_p = 5, s = (12 (1, 2, 0) − 5 (0, 6, 0)) / 7 = (12, −6, 0) / 7.
        CHECK(near3(r.shadow[0], {12.0 / 7, -6.0 / 7, 0}));
        for (const dvec3& s : r.shadow) CHECK(std::fabs(s.x + 2 * s.y) < 1e-12);
    }
    SECTION("normal (0, −1, 0) with the light above: turned round, the same M as the floor's") {
        const Input in = make({0, -1, 0}, 0, {0, 4, 0, 1}, kFloor.polygon);
        const auto t = cg::test::run_traced<ProjectiveShadow>(in);
        CHECK(t.steps[0].event == "flip-plane");
        CHECK(t.result.flipped);
        CHECK(t.result.matrix == ProjectiveShadow::flatten(kFloor).matrix);
        CHECK(t.result.shadow == ProjectiveShadow::flatten(kFloor).shadow);
    }
}

TEST_CASE("projective-shadow: degenerate vertices are their own events",
          "[shadows][projective-shadow]") {
    // Light (0, 3, 0) over the floor. p1 on the floor, p2 level with the light, p3 above it,
    // p4 under the floor.
    const Input in =
        make({0, 1, 0}, 0, {0, 3, 0, 1}, {{1, 1, 0}, {2, 0, 1}, {2, 3, 1}, {1, 4, 2}, {1, -1, 0}});
    const auto t = cg::test::run_traced<ProjectiveShadow>(in);
    CHECK(cg::test::events(t) == std::vector<std::string>{"setup", "matrix", "vertex", "on-plane",
                                                          "level-with-light", "above-light",
                                                          "behind-plane", "polygon"});
    CHECK(t.result.valid == std::vector<bool>{true, true, false, false, false});
    CHECK(t.result.shadow[1] == dvec3(2, 0, 1));  // its own shadow
    // Above the light: M p = 3p − 4L = [3, 0, 6, −1]; the anti-shadow (−3, 0, −6) is named.
    CHECK_THAT(t.steps[5].narration, Catch::Contains("(−3, 0, −6)"));
    CHECK_THAT(t.steps[5].narration, Catch::Contains("anti-shadow"));
    // Under the floor: M p = 3p + L = [3, 0, 0, 4]: the false shadow (0.75, 0, 0).
    CHECK_THAT(t.steps[6].narration, Catch::Contains("(0.75, 0, 0)"));
    CHECK_THAT(t.steps[7].narration, Catch::Contains("3 of 5 vertices cast none"));
}

TEST_CASE("projective-shadow: bad input names the field", "[shadows][projective-shadow]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(
        ProjectiveShadow::start(make({0, 1, 0}, 0, {1, 0, 2, 1}, kFloor.polygon)),
        Catch::StartsWith("light: the point light lies on the plane (n · L + d = 0)"));
    CHECK_THROWS_WITH(
        ProjectiveShadow::start(make({0, 1, 0}, 0, {1, 0, 2, 0}, kFloor.polygon)),
        Catch::StartsWith("light: the directional light is parallel to the plane (n · l = 0)"));
    CHECK_THROWS_WITH(ProjectiveShadow::start(make({0, 0, 0}, 1, {0, 4, 0, 1}, kFloor.polygon)),
                      Catch::StartsWith("plane.normal: must not be the zero vector"));
    CHECK_THROWS_WITH(ProjectiveShadow::start(make({0, 1, 0}, 0, {0, 4, 0, 2}, kFloor.polygon)),
                      Catch::StartsWith("light[3]: must be 1 (a point light"));
    CHECK_THROWS_WITH(
        ProjectiveShadow::start(make({0, 1, 0}, 0, {0, 0, 0, 0}, kFloor.polygon)),
        Catch::StartsWith(
            "light: a directional light [l_x, l_y, l_z, 0] needs a non-zero direction"));
    CHECK_THROWS_WITH(ProjectiveShadow::start(make({0, 1, 0}, nan, {0, 4, 0, 1}, kFloor.polygon)),
                      "plane.d: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(
        ProjectiveShadow::start(make({0, 1, 0}, 0, {0, 4, 0, 1}, {{1, 1, 1}, {2, 2, 2}})),
        "polygon: must have at least 3 vertices (got 2)");
    CHECK_THROWS_WITH(
        ProjectiveShadow::start(make({0, 1, 0}, 0, {0, 4, 0, 1}, std::vector<dvec3>(65, dvec3(1)))),
        Catch::StartsWith("polygon: has 65 vertices; at most 64"));
    CHECK_THROWS_WITH(
        ProjectiveShadow::start(make({0, 1e300, 0}, 0, {0, 1e300, 0, 1}, kFloor.polygon)),
        Catch::StartsWith("light: is too large: n · L + d w overflows"));
    CHECK_THROWS_WITH(
        ProjectiveShadow::start(make({0, 1e200, 0}, 0, {1e200, 1e100, 0, 1}, kFloor.polygon)),
        Catch::StartsWith("light: is too large: the shadow matrix's entries overflow"));
    CHECK_THROWS_WITH(ProjectiveShadow::start(
                          make({0, 1, 0}, 0, {0, 4, 0, 1}, {{1, 1, 1}, {2, 2, 1e308}, {1, 2, 3}})),
                      Catch::StartsWith("polygon[1]: is too large"));
    auto error = [](const std::string& text) {
        return cg::test::error_of("projective-shadow", text);
    };
    CHECK_THAT(
        error(
            R"({"plane": {"normal": [0, 1, 0], "d": 0}, "light": [0, 4, 0], "polygon": [[1, 1, 1], [2, 1, 1], [1, 2, 1]]})"),
        Catch::StartsWith("light: must be [x, y, z, 1] (a point light) or [l_x, l_y, l_z, 0]"));
    CHECK_THAT(
        error(
            R"({"plane": {"point": [0, 0, 0], "normal": [0, 1, 0]}, "light": [0, 4, 0, 1], "polygon": [[1, 1, 1], [2, 1, 1], [1, 2, 1]]})"),
        Catch::StartsWith("plane.point"));
    CHECK_THAT(
        error(
            R"({"plane": {"normal": [0, 1, 0], "d": 0}, "light": [0, 4, 0, "a"], "polygon": [[1, 1, 1], [2, 1, 1], [1, 2, 1]]})"),
        Catch::StartsWith("light[3]: must be a number"));
}

TEST_CASE(
    "projective-shadow: 6,000 random inputs against the ray–plane intersection in long double",
    "[shadows][projective-shadow]") {
    cg::Rng rng(2026);
    int shadows = 0, none = 0, on_plane = 0, level = 0, exact_cases = 0;
    for (int trial = 0; trial < 6000; ++trial) {
        CAPTURE(trial);
        Input in;
        const bool exact = trial % 3 == 0;  // integer inputs: the degenerate cases hit exactly
        const bool sun = trial % 4 == 1;
        if (exact) {
            const int axis = int(rng.integer(0, 2));
            in.normal = dvec3(0);
            in.normal[axis] = rng.chance(0.5) ? 1 : -2;
            in.d = double(rng.integer(-3, 3));
            for (int i = 0; i < 3; ++i) in.light[i] = double(rng.integer(-5, 5));
            in.light.w = sun ? 0 : 1;
            const int n = int(rng.integer(3, 6));
            for (int k = 0; k < n; ++k) {
                dvec3 p;
                for (int i = 0; i < 3; ++i) p[i] = double(rng.integer(-5, 5));
                const double pick = rng.uniform(0, 1);
                if (pick < 0.2)
                    p[axis] = -in.d / in.normal[axis];  // on the plane
                else if (pick < 0.35 && !sun)
                    p[axis] = in.light[axis];  // level with the light
                in.polygon.push_back(p);
            }
            ++exact_cases;
        } else {
            in.normal = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
            in.d = rng.uniform(-3, 3);
            in.light = {rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(-6, 6),
                        sun ? 0.0 : 1.0};
            const int n = int(rng.integer(3, 6));
            for (int k = 0; k < n; ++k) {
                dvec3 p{rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(-6, 6)};
                if (!sun && rng.chance(0.15)) {  // nearly parallel: almost level with the light
                    const double nn = glm::dot(in.normal, in.normal);
                    const double gap = glm::dot(in.normal, dvec3(in.light) - p) + 0 * in.d;
                    p += (gap / nn) * in.normal * (1 - std::pow(10.0, -rng.uniform(3, 9)));
                }
                in.polygon.push_back(p);
            }
        }
        try {
            ProjectiveShadow::validate(in);
        } catch (const cg::InputError&) {
            continue;  // a light on the plane or parallel to it: refused (tested above)
        }
        const auto r = ProjectiveShadow::flatten(in);
        CHECK(cg::run_to_end<ProjectiveShadow>(ProjectiveShadow::start(in)) == r);

        // The reference: the ray from the light through p (point), or the line through p along
        // l (sun), met with the plane; a shadow exists when p is on the light's side of the
        // plane (or on it) and, for a point light, strictly below the light.
        const LD nx = in.normal.x, ny = in.normal.y, nz = in.normal.z, d = in.d;
        auto height = [&](LD x, LD y, LD z) { return nx * x + ny * y + nz * z; };
        const LD hL = height(in.light.x, in.light.y, in.light.z) + d * in.light.w;
        const LD nnorm = std::sqrt(nx * nx + ny * ny + nz * nz);
        for (std::size_t k = 0; k < in.polygon.size(); ++k) {
            CAPTURE(k);
            const dvec3 p = in.polygon[k];
            const LD hp = height(p.x, p.y, p.z) + d;
            const LD s = hL > 0 ? 1 : -1;  // orient toward the light
            const LD a = s * hp, b = s * hL;
            bool expect;
            LD X[3];
            LD wref;
            if (sun) {
                expect = a >= 0;
                const LD t = hp / hL;  // p − (h_p / n·l) l
                for (int i = 0; i < 3; ++i) X[i] = LD(p[i]) - t * LD(in.light[i]);
                wref = std::fabs(hL);
            } else {
                expect = a == 0 || (a > 0 && a < b);
                // L + t (p − L) with n·(L + t(p − L)) + d = 0.
                const LD t = hL / (hL - hp);
                for (int i = 0; i < 3; ++i)
                    X[i] = LD(in.light[i]) + t * (LD(p[i]) - LD(in.light[i]));
                wref = std::fabs(hL - hp);
            }
            const LD scale =
                nnorm * (glm::length(p) + glm::length(dvec3(in.light))) + std::fabs(d) + 1;
            const bool clear =
                exact || (std::fabs(a) > 1e-9 * scale && std::fabs(b - a) > 1e-9 * scale);
            if (clear) CHECK(r.valid[k] == expect);
            if (r.valid[k] && expect && wref > 0) {
                const LD size = std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]) +
                                glm::length(p) + glm::length(dvec3(in.light));
                const LD tol = 1e-12L * size * scale / wref + 1e-300L;
                for (int i = 0; i < 3; ++i) CHECK(std::fabs(LD(r.shadow[k][i]) - X[i]) <= tol);
                // The shadow point is on the plane (to its rounding).
                const dvec3 q = r.shadow[k];
                CHECK(std::fabs(height(q.x, q.y, q.z) + d) <=
                      1e-12L * nnorm * size * scale / wref + 1e-300L);
            }
            if (exact && hp == 0) {
                CHECK(r.valid[k]);
                CHECK(r.shadow[k] == p);  // maps to itself
                ++on_plane;
            }
            if (exact && !sun && hp == hL) {
                CHECK_FALSE(r.valid[k]);
                ++level;
            }
            r.valid[k] ? ++shadows : ++none;
        }

        // M p lies on the plane for any p (homogeneous: P · (M p) = 0), and M M = h_L M.
        const dmat4& M = r.matrix;
        const dvec4 P = r.flipped ? -dvec4(in.normal, in.d) : dvec4(in.normal, in.d);
        const LD h = std::fabs(hL);
        LD mmax = 0;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) mmax = std::max(mmax, std::fabs(LD(M[j][i])));
        const dvec4 any{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5), 1};
        const dvec4 image = M * any;
        LD on = 0, pn = 0;
        for (int i = 0; i < 4; ++i) on += LD(P[i]) * LD(image[i]), pn += std::fabs(LD(P[i]));
        CHECK(std::fabs(on) <= 1e-13L * pn * mmax * 20);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                LD mm = 0;
                for (int k = 0; k < 4; ++k) mm += LD(M[k][i]) * LD(M[j][k]);
                CHECK(std::fabs(mm - h * LD(M[j][i])) <= 1e-13L * mmax * mmax * 8);
            }
    }
    INFO(shadows << " shadows, " << none << " without, " << on_plane << " on the plane, " << level
                 << " level");
    CHECK(shadows > 8000);
    CHECK(none > 3000);
    CHECK(on_plane > 500);
    CHECK(level > 300);
    CHECK(exact_cases == 2000);
}

TEST_CASE("projective-shadow: replay on the example and the presets, run-to-end is flatten",
          "[shadows][projective-shadow]") {
    const cg::Algorithm& a = cg::test::algorithm("projective-shadow");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    std::set<std::string> seen;
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, cg::test::kEveryStep);
        const Input in = input_of(p.input);
        CHECK(cg::run_to_end<ProjectiveShadow>(ProjectiveShadow::start(in)) ==
              ProjectiveShadow::flatten(in));
        for (const auto& e : cg::test::events(cg::test::run_traced<ProjectiveShadow>(in)))
            seen.insert(e);
    }
    // Every event kind happens in some preset.
    for (const auto& e : ProjectiveShadow::spec().events) {
        CAPTURE(e.id);
        CHECK(seen.count(e.id));
    }
    const cg::json r = cg::test::result_of("projective-shadow", a.example());
    CHECK(r["shadow"][0] == cg::json::parse("[2.0, 0.0, 0.0]"));
    CHECK(r["valid"] == cg::json::parse("[true, true, true]"));
    CHECK(r["matrix"].size() == 4);
    const cg::json above = cg::test::result_of("projective-shadow", lesson().presets[2].input);
    CHECK(above["shadow"][2].is_null());
}

TEST_CASE("projective-shadow: exam problems have a shadow for every vertex and ask for the highest",
          "[shadows][projective-shadow]") {
    const cg::Algorithm& a = cg::test::algorithm("projective-shadow");
    int suns = 0, on_plane = 0;
    for (std::uint64_t seed = 0; seed < 500; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = input_of(p.input);
        const auto r = ProjectiveShadow::flatten(in);
        CHECK(r.valid == std::vector<bool>{true, true, true});
        CHECK_FALSE(r.flipped);
        REQUIRE(p.answers.size() == 2);
        CHECK(p.answers[0] == "matrix");
        const int k = std::stoi(p.answers[1].substr(7));
        for (const auto& v : in.polygon)
            CHECK(glm::dot(in.normal, v) + in.d <= glm::dot(in.normal, in.polygon[k]) + in.d);
        CHECK_THAT(p.question, Catch::Contains("vertex p" + std::to_string(k)));
        suns += in.light.w == 0;
        for (const auto& v : in.polygon) on_plane += glm::dot(in.normal, v) + in.d == 0;
    }
    CHECK(suns > 60);
    CHECK(on_plane > 20);
}

TEST_CASE("projective-shadow: the picture — plane, light, polygon, rays, shadow",
          "[shadows][projective-shadow]") {
    auto s = ProjectiveShadow::start(kFloor);
    cg::Scene pic;
    ProjectiveShadow::draw(s, pic);
    CHECK(pic.has_3d());
    CHECK(pic.faces3.size() == 2);  // the plane and the polygon
    while (!ProjectiveShadow::done(s)) ProjectiveShadow::step(s, nullptr);
    cg::Scene end;
    ProjectiveShadow::draw(s, end);
    REQUIRE(end.faces3.size() == 3);  // + the shadow polygon
    CHECK(end.faces3[2].points.size() == 3);
    for (const auto& q : end.faces3[2].points) CHECK(q.y == 0);
    int kept = 0;
    for (const auto& seg : end.segments3) kept += seg.style.role == cg::Role::Kept;
    CHECK(kept == 3);  // a ray from each vertex to its shadow
    // The plane's quad covers the shadow points.
    double xmin = 1e9, xmax = -1e9;
    for (const auto& q : end.faces3[0].points)
        xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x);
    CHECK(xmin < 0);
    CHECK(xmax > 4);
    // The sun is an arrow, not a point.
    auto sun = ProjectiveShadow::start(
        make({0, 1, 0}, 0, {1, 2, 1, 0}, {{0, 2, 0}, {2, 2, 0}, {1, 3, 2}}));
    cg::Scene sp;
    ProjectiveShadow::draw(sun, sp);
    bool arrow = false;
    for (const auto& seg : sp.segments3) arrow = arrow || (seg.arrow && seg.label == "sun");
    CHECK(arrow);
}
