// Rotation about an arbitrary axis: exam cases worked by hand (each canonical axis, an axis
// already on a coordinate axis or in a coordinate plane, a negative axis, ties); 10,000 random
// axes and angles — a quarter of them degenerate — against glm::rotate and Rodrigues' formula
// in long double; the construction's own promises (R_k(−γ) R_j(−φ) a = |a| e_i, R a = a);
// errors; determinism and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "support/traced.hpp"
#include "io/registry.hpp"
#include "support/replay.hpp"
#include "transforms/arbitrary_axis.hpp"

using cg::ArbitraryAxis;
using glm::dmat3;
using glm::dvec3;

namespace {

using Traced = cg::test::Traced<ArbitraryAxis>;

Traced run_traced(const ArbitraryAxis::Input& in) { return cg::test::run_traced<ArbitraryAxis>(in); }

using cg::test::events;

// A matrix given by rows, as glm (column-major).
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

bool near(const dmat3& a, const dmat3& b, double tol = 1e-12) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::fabs(a[c][r] - b[c][r]) > tol) return false;
    return true;
}

// Rodrigues' formula in long double: R = cos θ I + sin θ [k]× + (1 − cos θ) k kᵀ.
using ld = long double;
void rodrigues(dvec3 axis, double angle_deg, ld out[3][3]) {
    const ld n = std::sqrt(ld(axis.x) * axis.x + ld(axis.y) * axis.y + ld(axis.z) * axis.z);
    const ld k[3] = {axis.x / n, axis.y / n, axis.z / n};
    const ld t = ld(angle_deg) * 3.14159265358979323846264338327950288L / 180;
    const ld c = std::cos(t), s = std::sin(t);
    const ld cross[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
    for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col)
            out[r][col] = (r == col ? c : 0) + s * cross[r][col] + (1 - c) * k[r] * k[col];
}

}  // namespace

TEST_CASE("arbitrary-axis: exam cases worked by hand", "[transforms][arbitrary-axis]") {
    SECTION("90° about (1, 1, 0): the tie goes to x, φ = 0, γ = 45°") {
        const Traced t = run_traced({{1, 1, 0}, 90, {{1, 0, 0}, {0, 0, 1}}});
        CHECK(events(t) == std::vector<std::string>{"choose-axis", "already-in-plane", "to-axis",
                                                    "rotate", "undo-axis", "undo-plane", "compose",
                                                    "rotate-point", "rotate-point"});
        CHECK(t.result.canonical == 0);
        CHECK(t.result.phi_deg == 0);
        CHECK(t.result.gamma_deg == Approx(45));
        const double h = std::sqrt(0.5);
        CHECK(near(t.result.matrix, from_rows({{0.5, 0.5, h}, {0.5, 0.5, -h}, {-h, h, 0}})));
        CHECK(glm::length(t.result.points[0] - dvec3(0.5, 0.5, -h)) < 1e-12);
        CHECK(glm::length(t.result.points[1] - dvec3(h, -h, 0)) < 1e-12);
    }
    SECTION("120° about (1, 1, 1) permutes the axes: x → y → z → x") {
        const Traced t = run_traced({{1, 1, 1}, 120, {}});
        CHECK(events(t) == std::vector<std::string>{"choose-axis", "to-plane", "to-axis", "rotate",
                                                    "undo-axis", "undo-plane", "compose"});
        CHECK(t.result.canonical == 0);
        CHECK(t.result.phi_deg == Approx(-45));  // atan2(−a_z, a_x)
        CHECK(t.result.gamma_deg == Approx(std::atan(1 / std::sqrt(2.0)) * 180 / M_PI));  // 35.26°
        CHECK(near(t.result.matrix, from_rows({{0, 0, 1}, {1, 0, 0}, {0, 1, 0}})));
    }
    SECTION("closest to y: R = R_z(φ) R_x(γ) R_y(θ) R_x(−γ) R_z(−φ)") {
        const Traced t = run_traced({{1, 3, 2}, 45, {}});
        CHECK(t.result.canonical == 1);
        CHECK(t.result.phi_deg == Approx(std::atan2(-1.0, 3.0) * 180 / M_PI));
        CHECK(t.result.gamma_deg == Approx(std::atan2(2.0, std::sqrt(10.0)) * 180 / M_PI));
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("R = R_z(φ) R_x(γ) R_y(θ) R_x(−γ) R_z(−φ)"));
        CHECK(t.steps[1].narration.find("turns a about z into the yz plane") != std::string::npos);
    }
    SECTION("closest to z: R = R_x(φ) R_y(γ) R_z(θ) R_y(−γ) R_x(−φ)") {
        const Traced t = run_traced({{1, -2, 5}, 30, {}});
        CHECK(t.result.canonical == 2);
        CHECK(t.result.phi_deg == Approx(std::atan2(2.0, 5.0) * 180 / M_PI));
        CHECK(t.result.gamma_deg == Approx(std::atan2(1.0, std::sqrt(29.0)) * 180 / M_PI));
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("R = R_x(φ) R_y(γ) R_z(θ) R_y(−γ) R_x(−φ)"));
    }
    SECTION("the z axis itself, not unit length: both turns are the identity, R = R_z(θ)") {
        const Traced t = run_traced({{0, 0, 2}, 90, {{1, 0, 0}}});
        CHECK(events(t) == std::vector<std::string>{"choose-axis", "already-in-plane",
                                                    "already-on-axis", "rotate", "undo-axis",
                                                    "undo-plane", "compose", "rotate-point"});
        CHECK(t.result.matrix == from_rows({{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}));  // exactly
        CHECK(t.result.points[0] == dvec3(0, 1, 0));
        CHECK_THAT(t.steps[0].narration, Catch::Contains("not unit length"));
        CHECK_THAT(t.steps[0].narration, Catch::Contains("already lies on the z axis"));
    }
    SECTION("the negative x axis: φ = 180°, and 90° about −x is −90° about x") {
        const Traced t = run_traced({{-1, 0, 0}, 90, {{0, 1, 0}}});
        CHECK(t.result.phi_deg == 180);
        CHECK(t.result.gamma_deg == 0);
        CHECK(t.steps[1].event == "to-plane");
        CHECK(t.steps[2].event == "already-on-axis");
        CHECK(near(t.result.matrix, from_rows({{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}), 1e-15));
    }
    SECTION("in the yz plane, closest to z: γ = 0 after the first turn") {
        const Traced t = run_traced({{0, 3, 4}, 90, {}});
        CHECK(t.result.canonical == 2);
        CHECK(t.steps[1].event == "to-plane");  // about x, removing the y component
        CHECK(t.steps[2].event == "already-on-axis");
        CHECK(t.result.phi_deg == Approx(std::atan2(-3.0, 4.0) * 180 / M_PI));
    }
}

TEST_CASE("arbitrary-axis: the steps show their matrices as numbers",
          "[transforms][arbitrary-axis]") {
    const Traced t = run_traced({{1, 1, 0}, 90, {{1, 0, 0}}});
    CHECK(t.steps[2].narration ==
          "In the xy plane c = (1, 1, 0) makes the angle γ with the x axis: cos γ = r/|a| = "
          "0.7071, sin γ = a_y/|a| = 0.7071, γ = 45°. R_z(−γ) = [0.7071 0.7071 0; −0.7071 0.7071 "
          "0; 0 0 1] turns c about z onto the x axis: R_z(−γ) c = (1.414, 0, 0) = |a| e_x.");
    CHECK(t.steps[3].narration ==
          "The axis now is the x axis: rotate by θ = 90° about it (cos θ = 0, sin θ = 1): R_x(θ) = "
          "[1 0 0; 0 0 −1; 0 1 0].");
    CHECK_THAT(t.steps[3].math, Catch::EndsWith("\\begin{bmatrix} 1 & 0 & 0 & 0 \\\\ 0 & 0 & -1 "
                                                "& 0 \\\\ 0 & 1 & 0 & 0 \\\\ 0 & 0 & 0 & 1 "
                                                "\\end{bmatrix}"));
    // Every matrix of the construction is a variable, as a 4×4 homogeneous matrix.
    const auto& vars = t.steps[6].vars;
    std::vector<std::string> names;
    for (const auto& v : vars) names.push_back(v.name);
    for (const char* want :
         {"R_y(-phi)", "R_z(-gamma)", "R_x(theta)", "R_z(gamma)", "R_y(phi)", "R"}) {
        CAPTURE(want);
        const auto it = std::find(names.begin(), names.end(), want);
        REQUIRE(it != names.end());
        const auto& m = std::get<std::vector<std::vector<double>>>(vars[it - names.begin()].value);
        CHECK(m.size() == 4);
        CHECK(m[3] == std::vector<double>{0, 0, 0, 1});
    }
    for (const auto& s : t.steps) {
        bool declared = false;
        for (const auto& e : ArbitraryAxis::spec().events) declared = declared || e.id == s.event;
        CHECK(declared);
    }
}

TEST_CASE("arbitrary-axis: 10,000 random axes and angles agree with glm::rotate and Rodrigues",
          "[transforms][arbitrary-axis]") {
    int degenerate = 0, per_axis[3] = {0, 0, 0};
    for (int trial = 0; trial < 10000; ++trial) {
        cg::Rng rng(trial);
        ArbitraryAxis::Input in;
        in.axis = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        switch (trial % 8) {  // a quarter degenerate, some far from unit length
            case 0:
                in.axis[rng.integer(0, 2)] = 0;
                ++degenerate;
                break;  // in a coordinate plane
            case 1: {   // on a coordinate axis, either way
                const int i = static_cast<int>(rng.integer(0, 2));
                in.axis = dvec3(0);
                in.axis[i] = rng.chance(0.5) ? 1 : -1;
                ++degenerate;
                break;
            }
            case 2:
                in.axis *= 1e-150;
                break;
            case 3:
                in.axis *= 1e150;
                break;
            case 4:
                in.axis.y = in.axis.x;
                break;  // a tie
            default:
                break;
        }
        if (in.axis == dvec3(0)) in.axis.z = 1;
        in.angle_deg = trial % 16 == 5 ? 90.0 * rng.integer(-8, 8) : rng.uniform(-720, 720);
        for (int p = 0; p < 2; ++p)
            in.points.push_back({rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)});
        CAPTURE(trial, in.axis.x, in.axis.y, in.axis.z, in.angle_deg);

        const auto r = cg::run_to_end<ArbitraryAxis>(ArbitraryAxis::start(in));
        REQUIRE(ArbitraryAxis::rotate(in) == r);
        ++per_axis[r.canonical];

        // GLM's own rotation matrix (the axis normalised by GLM).
        const dvec3 unit =
            in.axis / std::max({std::fabs(in.axis.x), std::fabs(in.axis.y), std::fabs(in.axis.z)});
        const glm::dmat4 g = glm::rotate(glm::dmat4(1.0), in.angle_deg * M_PI / 180, unit);
        ld ref[3][3];
        rodrigues(unit, in.angle_deg, ref);
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) {
                CAPTURE(row, col);
                REQUIRE(std::fabs(r.matrix[col][row] - g[col][row]) <= 1e-9);
                REQUIRE(std::fabs(r.matrix[col][row] - ref[row][col]) <= 1e-9L);
            }
        // The construction's promises: the closest axis; the two turns take a onto it; R a = a.
        const dvec3 m = glm::abs(in.axis);
        REQUIRE(m[r.canonical] == std::max({m.x, m.y, m.z}));
        const int i = r.canonical, j = (i + 1) % 3, k = (i + 2) % 3;
        const dvec3 n = glm::normalize(unit);
        const dvec3 on = cg::rot::rotation(k, cg::rot::cos_sin_deg(-r.gamma_deg)) *
                         (cg::rot::rotation(j, cg::rot::cos_sin_deg(-r.phi_deg)) * n);
        REQUIRE(std::fabs(on[i] - 1) <= 1e-12);
        REQUIRE(std::fabs(on[j]) <= 1e-12);
        REQUIRE(std::fabs(on[k]) <= 1e-12);
        REQUIRE(glm::length(r.matrix * n - n) <= 1e-12);
        REQUIRE(r.phi_deg > -180);
        REQUIRE(r.phi_deg <= 180);
        REQUIRE(std::fabs(r.gamma_deg) <= 90);
        for (std::size_t p = 0; p < in.points.size(); ++p)
            REQUIRE(glm::length(r.points[p] - r.matrix * in.points[p]) == 0);
    }
    CHECK(degenerate == 2500);
    CHECK(per_axis[0] > 2500);
    CHECK(per_axis[1] > 2000);
    CHECK(per_axis[2] > 2000);
}

TEST_CASE("arbitrary-axis: bad input names the field", "[transforms][arbitrary-axis]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(ArbitraryAxis::start({{0, 0, 0}, 90, {}}),
                      "axis: must not be the zero vector (0, 0, 0): a rotation axis needs a "
                      "direction");
    CHECK_THROWS_WITH(ArbitraryAxis::start({{1, nan, 0}, 90, {}}),
                      "axis[1]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(ArbitraryAxis::start({{1, 0, inf}, 90, {}}),
                      "axis[2]: must be a finite number (got inf)");
    CHECK_THROWS_WITH(ArbitraryAxis::start({{1, 0, 0}, nan, {}}),
                      "angle_deg: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(ArbitraryAxis::start({{1, 0, 0}, 90, {{0, 0, 0}, {1, 2, nan}}}),
                      "points[1][2]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(ArbitraryAxis::start({{1.7e308, 1.7e308, 1.7e308}, 90, {}}),
                      Catch::StartsWith("axis: is too long"));
    // A tiny axis is still an axis.
    CHECK_NOTHROW(ArbitraryAxis::start({{1e-310, 0, 1e-310}, 90, {}}));

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("arbitrary-axis");
    auto error = [&](const std::string& text) {
        try {
            a.create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(error(R"({"axis": [1, 1, 0], "angle_deg": 90})") == "(accepted)");
    CHECK(error(R"({"axis": [0, 0, 0], "angle_deg": 90})") ==
          "axis: must not be the zero vector (0, 0, 0): a rotation axis needs a direction");
    CHECK_THAT(error(R"({"axis": [1, 1], "angle_deg": 90})"), Catch::StartsWith("axis: "));
    CHECK_THAT(error(R"({"axis": [1, 1, 0]})"), Catch::StartsWith("angle_deg: is missing"));
    CHECK_THAT(error(R"({"axis": [1, 1, 0], "angle": 90})"),
               Catch::StartsWith("angle: is not a known field"));
    CHECK_THAT(error(R"({"axis": [1, 1, 0], "angle_deg": 90, "points": [[1, 2]]})"),
               Catch::StartsWith("points[0]: "));
}

TEST_CASE("arbitrary-axis: traces are deterministic and stepping back reproduces them",
          "[transforms][arbitrary-axis]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("arbitrary-axis");
    REQUIRE(a);
    cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);
    cg::test::check_replay(*a, cg::json::parse(R"({"axis": [2, 1, -2], "angle_deg": 60,
                                                  "points": [[1, 1, 1]]})"),
                           3);
    auto run = a->create(a->example());
    while (!run->done()) run->step(nullptr);
    const cg::json r = a->result(*run);
    CHECK(r["canonical_axis"] == "x");
    CHECK(r["phi_deg"] == 0);
    CHECK(r["matrix"].size() == 4);
    CHECK(r["matrix"][3] == cg::json::parse("[0, 0, 0, 1]"));
    CHECK(r["points"].size() == 2);
}

TEST_CASE("arbitrary-axis: the picture carries the axis and a house through the steps",
          "[transforms][arbitrary-axis]") {
    const ArbitraryAxis::Input in{{1, 2, 2}, 90, {{1, 0, 0}}};
    auto s = ArbitraryAxis::start(in);
    const dvec3 unit = glm::normalize(in.axis);
    auto axis_arrow = [](const cg::Scene& scene) {
        for (const auto& seg : scene.segments3)
            if (seg.style.role == cg::Role::Active && seg.arrow) return glm::normalize(seg.b);
        return dvec3(0);
    };
    int step = 0;
    while (!ArbitraryAxis::done(s)) {
        ArbitraryAxis::step(s, nullptr);
        ++step;
        cg::Scene scene;
        ArbitraryAxis::draw(s, scene);
        CAPTURE(step);
        CHECK(scene.has_3d());
        CHECK_FALSE(scene.has_2d());
        CHECK(scene.frames3.size() == 1);
        CHECK(scene.faces3.size() >= 8);  // the house (and its ghost once it has moved)
        // After the two turns the axis lies along the chosen coordinate axis (y here)...
        if (s.last == ArbitraryAxis::Phase::ToAxis || s.last == ArbitraryAxis::Phase::Rotate)
            CHECK(glm::length(axis_arrow(scene) - dvec3(0, 1, 0)) < 1e-12);
        // ... and from the last undo on it is back where it started.
        if (s.last >= ArbitraryAxis::Phase::UndoPlane)
            CHECK(glm::length(axis_arrow(scene) - unit) < 1e-12);
    }
    // The solid house is the ghost moved by R.
    cg::Scene scene;
    ArbitraryAxis::draw(s, scene);
    std::vector<const cg::Face3*> ghost, solid;
    for (const auto& f : scene.faces3)
        (f.style.role == cg::Role::Construction ? ghost : solid).push_back(&f);
    REQUIRE(ghost.size() == solid.size());
    for (std::size_t f = 0; f < ghost.size(); ++f)
        for (std::size_t p = 0; p < ghost[f]->points.size(); ++p)
            CHECK(glm::length(solid[f]->points[p] - s.R * ghost[f]->points[p]) < 1e-12);
    int labels = 0;
    for (const auto& l : scene.labels3) labels += l.text == "P0′";
    for (const auto& p : scene.points3) labels += p.label == "P0′";
    CHECK(labels == 1);
}
