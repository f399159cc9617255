// Change of basis: exam cases worked by hand (the 2D frame turned by 90° and moved, identity
// frames, a scaled and a sheared F2, the course's dot-product formula); 10,000 random pairs of
// frames — orthonormal, general, sheared, and near-singular ones that must be refused —
// against glm::inverse of the frame matrices and Cramer's rule in long double; both
// coordinate tuples naming the same world point; the orthonormal shortcut equal to the
// inverse; bad input through the CLI; determinism, the picture and exam problems.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "support/process.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"
#include "transforms/change_of_basis.hpp"

using cg::ChangeOfBasis;
using glm::dmat4;
using glm::dvec3;
using Frame = ChangeOfBasis::Frame;

namespace {

using Traced = cg::test::Traced<ChangeOfBasis>;

Traced run_traced(const ChangeOfBasis::Input& in) {
    return cg::test::run_traced<ChangeOfBasis>(in);
}

using cg::test::events;

dmat4 from_rows(std::initializer_list<std::initializer_list<double>> rows) {
    dmat4 m(0.0);
    int r = 0;
    for (const auto& row : rows) {
        int c = 0;
        for (double v : row) m[c++][r] = v;
        ++r;
    }
    return m;
}

double max_diff(const dmat4& a, const dmat4& b) {
    double d = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, std::fabs(a[c][r] - b[c][r]));
    return d;
}

double max_abs(const dmat4& a) {
    return max_diff(a, dmat4(0.0));
}

const Frame kWorld{};

// ---- the long-double reference: Cramer's rule ----
using ld = long double;
struct V3 {
    ld x, y, z;
};
V3 ldv(dvec3 v) {
    return {v.x, v.y, v.z};
}
ld det3(V3 a, V3 b, V3 c) {  // det of the columns a, b, c
    return a.x * (b.y * c.z - b.z * c.y) - b.x * (a.y * c.z - a.z * c.y) +
           c.x * (a.y * b.z - a.z * b.y);
}
// x with x₁a₁ + x₂a₂ + x₃a₃ = b.
V3 cramer(const Frame& f, V3 b) {
    const V3 a0 = ldv(f.axes[0]), a1 = ldv(f.axes[1]), a2 = ldv(f.axes[2]);
    const ld d = det3(a0, a1, a2);
    return {det3(b, a1, a2) / d, det3(a0, b, a2) / d, det3(a0, a1, b) / d};
}
// The world position of F1 coordinates p (w = 1) or u (w = 0), in long double.
V3 world_ld(const Frame& f, dvec3 p, bool point) {
    V3 r{0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        r.x += ld(p[i]) * f.axes[i].x, r.y += ld(p[i]) * f.axes[i].y, r.z += ld(p[i]) * f.axes[i].z;
    }
    if (point) r.x += f.origin.x, r.y += f.origin.y, r.z += f.origin.z;
    return r;
}
V3 minus(V3 a, dvec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
ld dist(dvec3 a, V3 b) {
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                     (a.z - b.z) * (a.z - b.z));
}
ld norm(V3 a) {
    return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}

// ---- random frames ----
dvec3 random_vec(cg::Rng& rng, double r) {
    return {rng.uniform(-r, r), rng.uniform(-r, r), rng.uniform(-r, r)};
}

Frame orthonormal_frame(cg::Rng& rng) {
    const glm::dquat q = glm::normalize(
        glm::dquat(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    const glm::dmat3 m = glm::mat3_cast(q);
    Frame f{random_vec(rng, 10), {m[0], m[1], m[2]}};
    if (rng.chance(0.25)) f.axes[2] = -f.axes[2];  // left-handed: still orthonormal
    return f;
}

Frame general_frame(cg::Rng& rng) {
    return {random_vec(rng, 10), {random_vec(rng, 3), random_vec(rng, 3), random_vec(rng, 3)}};
}

Frame shear_frame(cg::Rng& rng) {  // the unit axes with large multiples of earlier axes added
    Frame f{random_vec(rng, 10), {dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)}};
    f.axes[1] += rng.uniform(-5, 5) * f.axes[0];
    f.axes[2] += rng.uniform(-5, 5) * f.axes[0] + rng.uniform(-5, 5) * f.axes[1];
    return f;
}

// The third axis in the plane of the first two, off it by a relative 1e-14 or less.
Frame near_singular_frame(cg::Rng& rng) {
    Frame f = general_frame(rng);
    const dvec3 n = glm::normalize(glm::cross(f.axes[0], f.axes[1]));
    f.axes[2] = rng.uniform(-2, 2) * f.axes[0] + rng.uniform(-2, 2) * f.axes[1] +
                rng.uniform(-1e-14, 1e-14) * glm::length(f.axes[0]) * n;
    return f;
}

std::string error_of(const ChangeOfBasis::Input& in) {
    try {
        ChangeOfBasis::validate(in);
    } catch (const cg::InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

TEST_CASE("change-of-basis: exam cases worked by hand", "[transforms][change-of-basis]") {
    SECTION("2D: F2 turned by 90° and moved to (2, 1); F1 the world frame") {
        // w₁ = y, w₂ = −x: P = (3, 2) = O_w + 1·w₁ + (−1)·w₂, so P is (1, −1) relative to F2.
        const Frame f2{{2, 1, 0}, {dvec3(0, 1, 0), dvec3(-1, 0, 0), dvec3(0, 0, 1)}};
        const Traced t = run_traced({kWorld, f2, {{3, 2, 0}, {2, 1, 0}}, {{1, 0, 0}}});
        CHECK(events(t) == std::vector<std::string>{"world-from-f1", "world-from-f2",
                                                    "inverse-orthonormal", "compose", "map-point",
                                                    "map-point", "map-vector"});
        CHECK(t.result.orthonormal_to);
        CHECK(t.result.matrix ==
              from_rows({{0, 1, 0, -1}, {-1, 0, 0, 2}, {0, 0, 1, 0}, {0, 0, 0, 1}}));
        CHECK(t.result.points[0] == dvec3(1, -1, 0));
        CHECK(t.result.points[1] == dvec3(0, 0, 0));    // O_w itself
        CHECK(t.result.vectors[0] == dvec3(0, -1, 0));  // x = −w₂, no translation
        CHECK(t.result.world[0] == dvec3(3, 2, 0));
    }
    SECTION("identity frames give the identity") {
        const Traced t = run_traced({kWorld, kWorld, {{1, 2, 3}}, {{-4, 5, 6}}});
        CHECK(t.result.matrix == dmat4(1.0));
        CHECK(t.result.points[0] == dvec3(1, 2, 3));
        CHECK(t.result.vectors[0] == dvec3(-4, 5, 6));
        CHECK(t.result.orthonormal_to);
        // The same frame twice, whatever it is, also gives the identity.
        const Frame f{{1, -2, 3}, {dvec3(2, 0, 1), dvec3(1, 1, 0), dvec3(0, 1, 3)}};
        const auto r = ChangeOfBasis::transform({f, f, {{1, 2, 3}}, {}});
        CHECK(max_diff(r.matrix, dmat4(1.0)) < 1e-15);
        CHECK(glm::length(r.points[0] - dvec3(1, 2, 3)) < 1e-14);
    }
    SECTION("F2 scaled by 2: the general inverse halves the coordinates") {
        const Frame f2{{1, 1, 0}, {dvec3(2, 0, 0), dvec3(0, 2, 0), dvec3(0, 0, 1)}};
        const Traced t = run_traced({kWorld, f2, {{3, 5, 0}}, {}});
        CHECK(events(t)[2] == "inverse");
        CHECK_FALSE(t.result.orthonormal_to);
        CHECK(t.result.f2_from_world ==
              from_rows({{0.5, 0, 0, -0.5}, {0, 0.5, 0, -0.5}, {0, 0, 1, 0}, {0, 0, 0, 1}}));
        CHECK(t.result.points[0] == dvec3(1, 2, 0));
    }
    SECTION("F2 sheared") {
        // w₁ = x, w₂ = x + y: (3, 2) = 1·w₁ + 2·w₂.
        const Frame f2{{0, 0, 0}, {dvec3(1, 0, 0), dvec3(1, 1, 0), dvec3(0, 0, 1)}};
        const auto r = ChangeOfBasis::transform({kWorld, f2, {{3, 2, 0}}, {}});
        CHECK(r.f2_from_world ==
              from_rows({{1, -1, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}));
        CHECK(r.points[0] == dvec3(1, 2, 0));
    }
    SECTION("orthonormal F2: the entries are the course's dot products") {
        // F1 scaled and moved, F2 an axis permutation at (1, 2, 3):
        // f_ij = w_i · v_j, f_i4 = (O_v − O_w) · w_i.
        const Frame f1{{4, 0, -1}, {dvec3(2, 0, 0), dvec3(0, 1, 1), dvec3(0, 0, 3)}};
        const Frame f2{{1, 2, 3}, {dvec3(0, 1, 0), dvec3(0, 0, 1), dvec3(1, 0, 0)}};
        const auto r = ChangeOfBasis::transform({f1, f2, {{1, 1, 1}}, {}});
        REQUIRE(r.orthonormal_to);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) CHECK(r.matrix[j][i] == glm::dot(f2.axes[i], f1.axes[j]));
            CHECK(r.matrix[3][i] == glm::dot(f1.origin - f2.origin, f2.axes[i]));
        }
        // P = O_v + v₁ + v₂ + v₃ = (6, 1, 3); relative to F2: (P − O_w) · w_i = (−1, 0, 5).
        CHECK(r.world[0] == dvec3(6, 1, 3));
        CHECK(r.points[0] == dvec3(-1, 0, 5));
    }
    SECTION("no points: the matrices alone") {
        const Traced t = run_traced({kWorld, kWorld, {}, {}});
        CHECK(events(t) == std::vector<std::string>{"world-from-f1", "world-from-f2",
                                                    "inverse-orthonormal", "compose"});
        CHECK(t.result.points.empty());
    }
}

TEST_CASE(
    "change-of-basis: 10,000 random frames agree with glm::inverse and Cramer's rule in long "
    "double",
    "[transforms][change-of-basis]") {
    int accepted = 0, refused = 0, orthonormal = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        cg::Rng rng(trial);
        CAPTURE(trial);
        const int kind =
            trial % 5;  // 0 orthonormal, 1 general, 2 sheared, 3 mixed, 4 near-singular
        ChangeOfBasis::Input in;
        in.from = kind == 0   ? orthonormal_frame(rng)
                  : kind == 2 ? shear_frame(rng)
                              : general_frame(rng);
        in.to = kind == 0   ? orthonormal_frame(rng)
                : kind == 1 ? general_frame(rng)
                : kind == 2 ? shear_frame(rng)
                : kind == 3 ? (rng.chance(0.5) ? orthonormal_frame(rng) : shear_frame(rng))
                            : near_singular_frame(rng);
        if (kind == 4 && rng.chance(0.5)) std::swap(in.from, in.to);
        for (int k = 0; k < 3; ++k) in.points.push_back(random_vec(rng, 5));
        in.vectors.push_back(random_vec(rng, 5));
        if (kind == 4) {
            CHECK_THAT(error_of(in), Catch::Contains("axes: are linearly dependent") ||
                                         Catch::Contains("axes[1]: is parallel to") ||
                                         Catch::Contains("axes[2]: is parallel to"));
            ++refused;
            continue;
        }
        REQUIRE(error_of(in) == "(accepted)");
        ++accepted;
        const auto r = cg::run_to_end<ChangeOfBasis>(ChangeOfBasis::start(in));
        REQUIRE(ChangeOfBasis::transform(in) == r);

        // glm: the inverse of the 4×4 frame matrix, times F1's.
        const dmat4 w1 = ChangeOfBasis::world_from(in.from), w2 = ChangeOfBasis::world_from(in.to);
        const dmat4 ref = glm::inverse(w2) * w1;
        REQUIRE(max_diff(r.matrix, ref) <= 1e-9 * (1 + max_abs(ref)));
        REQUIRE(max_diff(r.f2_from_world, glm::inverse(w2)) <=
                1e-9 * (1 + max_abs(glm::inverse(w2))));

        // Cramer's rule in long double on the world position.
        for (std::size_t k = 0; k < in.points.size(); ++k) {
            CAPTURE(k);
            const V3 world = world_ld(in.from, in.points[k], true);
            const V3 expected = cramer(in.to, minus(world, in.to.origin));
            REQUIRE(dist(r.points[k], expected) <= 1e-9L * (1 + norm(expected)));
            REQUIRE(dist(r.world[k], world) <= 1e-12L * (1 + norm(world)));
            // The two tuples name the same world point: world_from_F2 p' = world_from_F1 p.
            const dvec3 back = dvec3(w2 * glm::dvec4(r.points[k], 1));
            REQUIRE(dist(back, world) <= 1e-9L * (1 + norm(world)));
        }
        const V3 u = world_ld(in.from, in.vectors[0], false);
        REQUIRE(dist(r.vectors[0], cramer(in.to, u)) <= 1e-9L * (1 + norm(cramer(in.to, u))));

        // The shortcut: for orthonormal F2 the transpose is the inverse.
        REQUIRE(r.orthonormal_to == (kind == 0 || ChangeOfBasis::orthonormal(in.to)));
        if (r.orthonormal_to) {
            ++orthonormal;
            REQUIRE(max_diff(ChangeOfBasis::inverse_orthonormal(in.to),
                             ChangeOfBasis::inverse_general(in.to)) <=
                    1e-12 * (1 + glm::length(in.to.origin)));
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j)
                    REQUIRE(std::fabs(r.matrix[j][i] - glm::dot(in.to.axes[i], in.from.axes[j])) <=
                            1e-12);
                REQUIRE(std::fabs(r.matrix[3][i] - glm::dot(in.from.origin - in.to.origin,
                                                            in.to.axes[i])) <= 1e-12 * 40);
            }
        }
    }
    CHECK(accepted == 8000);
    CHECK(refused == 2000);
    CHECK(orthonormal >= 2000);
}

TEST_CASE("change-of-basis: degenerate frames are refused, naming the field",
          "[transforms][change-of-basis]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto with_to = [](std::array<dvec3, 3> axes) {
        return ChangeOfBasis::Input{kWorld, {{0, 0, 0}, axes}, {{1, 2, 3}}, {}};
    };
    CHECK(error_of(with_to({dvec3(1, 0, 0), dvec3(0, 0, 0), dvec3(0, 0, 1)})) ==
          "to.axes[1]: must not be the zero vector: the three axes of F2 must span space");
    CHECK_THAT(error_of(with_to({dvec3(1, 0, 0), dvec3(1, 0, 0), dvec3(0, 0, 1)})),
               Catch::StartsWith("to.axes[1]: is the same as to.axes[0]"));
    CHECK_THAT(error_of(with_to({dvec3(1, 2, 0), dvec3(0, 0, 1), dvec3(-2, -4, 0)})),
               Catch::StartsWith("to.axes[2]: is parallel to to.axes[0]"));
    CHECK_THAT(error_of(with_to({dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(1, 1, 0)})),
               Catch::StartsWith("to.axes: are linearly dependent (det = 0"));
    // Relative, not absolute: tiny but independent axes are a frame; a relative 1e-13 is not.
    CHECK(error_of(with_to({dvec3(1e-50, 0, 0), dvec3(0, 1e-50, 0), dvec3(0, 0, 1e-50)})) ==
          "(accepted)");
    CHECK_THAT(error_of(with_to({dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(1, 1, 1e-13)})),
               Catch::StartsWith("to.axes: are linearly dependent"));
    CHECK(error_of(with_to({dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(1, 1, 1e-11)})) == "(accepted)");
    CHECK(error_of(with_to({dvec3(1, 0, 0), dvec3(0, nan, 0), dvec3(0, 0, 1)})) ==
          "to.axes[1][1]: must be a finite number (got NaN)");
    CHECK_THAT(error_of(with_to({dvec3(1e101, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)})),
               Catch::StartsWith("to.axes[0][0]: must be within ±1e100 (got 10¹⁰¹)"));
    CHECK_THAT(error_of(with_to({dvec3(1e-101, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)})),
               Catch::StartsWith("to.axes[0]: is too short"));
    ChangeOfBasis::Input in = with_to({dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)});
    in.from.axes[2] = in.from.axes[0] + in.from.axes[1];
    CHECK_THAT(error_of(in), Catch::StartsWith("from.axes: are linearly dependent") &&
                                 Catch::Contains("F1 is not a frame"));
    // A point far out in long axes, rewritten in short ones, overflows: refused, not inf.
    // (F2's third axis is nearly in the plane of the others, so its inverse has entries 1e111.)
    in = {{{0, 0, 0}, {dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1e100)}},
          {{0, 0, 0}, {dvec3(1e-100, 0, 0), dvec3(0, 1e-100, 0), dvec3(1e-100, 1e-100, 1e-111)}},
          {{0, 0, 1e100}},
          {}};
    CHECK_THAT(error_of(in),
               Catch::StartsWith("points[0]: its coordinates relative to \"to\" overflow"));
}

TEST_CASE("change-of-basis: bad input through the CLI names the field",
          "[transforms][change-of-basis][cli]") {
    const auto run = [](const std::string& text) {
        const std::string path = cg::test::write_temp("change-of-basis.json", text);
        auto r = cg::test::cgsandbox({"run", "change-of-basis", "--input", path});
        CHECK(r.exit_code == 2);
        CHECK(r.out.empty());
        const std::string prefix = "cgsandbox: " + path + ": ";
        REQUIRE(r.err.rfind(prefix, 0) == 0);
        return r.err.substr(prefix.size());
    };
    const std::string to =
        R"("to": {"origin": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})";
    CHECK_THAT(
        run(R"({"from": {"origin": [0, 0, 0], "axes": [[1, 0, 0], [2, 0, 0], [0, 0, 1]]}, )" + to +
            R"(, "points": []})"),
        Catch::StartsWith("from.axes[1]: is parallel to from.axes[0]"));
    CHECK_THAT(run(R"({"from": {"origin": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0]]}, )" + to +
                   R"(, "points": []})"),
               Catch::StartsWith("from.axes: must be three axes"));
    CHECK_THAT(run(R"({"from": {"origin": [0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}, )" +
                   to + R"(, "points": []})"),
               Catch::StartsWith("from.origin: must be a point [x, y, z]"));
    CHECK_THAT(
        run(R"({"from": {"origin": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}, )" + to +
            R"(})"),
        Catch::StartsWith("points: is missing"));
    CHECK_THAT(
        run(R"({"from": {"origin": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}, )" + to +
            R"(, "points": [[1, NaN, 0]]})"),
        Catch::StartsWith("points[0][1]: not valid JSON"));
    CHECK_THAT(
        run(R"({"from": {"origin": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}, )" + to +
            R"(, "points": [[1e300, 0, 0]]})"),
        Catch::StartsWith("points[0][0]: must be within ±1e100"));
    CHECK_THAT(
        run(R"({"from": {"origin": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "scale": 2}, )" +
            to + R"(, "points": []})"),
        Catch::StartsWith("from.scale: is not a known field (expected: origin, axes)"));
    // And a good input runs.
    auto ok = cg::test::cgsandbox({"run", "change-of-basis"});
    REQUIRE(ok.exit_code == 0);
    const cg::json r = cg::json::parse(ok.out);
    CHECK(r["points"] == cg::json::parse("[[1.0, -1.0, 0.0]]"));
    CHECK(r["orthonormal_to"] == true);
}

TEST_CASE(
    "change-of-basis: traces are deterministic, the picture shows both frames and the construction",
    "[transforms][change-of-basis]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("change-of-basis");
    REQUIRE(a);
    cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);

    auto run = a->create(a->example());
    const auto scene_now = [&] {
        cg::Scene scene;
        run->draw(scene);
        return scene;
    };
    const auto dashed = [](const cg::Scene& s, cg::Role role) {
        int n = 0;
        for (const auto& g : s.segments3) n += g.style.dashed && g.style.role == role;
        return n;
    };
    // F1's axes v₁, v₂ and F2's w₁, w₂ (the example is 2D: no third axes, seen from +z), with
    // the opacity that says which frame the step works on.
    const auto alpha = [](const cg::Scene& s, const std::string& axis) {
        for (const auto& g : s.segments3)
            if (g.arrow && g.label == axis) return static_cast<int>(g.style.rgba & 0xffu);
        return -1;
    };
    cg::Scene s = scene_now();
    REQUIRE(s.frames3.size() == 1);  // the world's
    CHECK(s.frames3[0].name == "");
    for (const char* axis : {"v₁", "v₂", "w₁", "w₂"}) CHECK(alpha(s, axis) > 0);
    CHECK(alpha(s, "v₃") == -1);
    CHECK(s.view3.orthographic);
    CHECK(s.view3.look == dvec3(0, 0, -1));
    CHECK(s.points3.empty());  // nothing computed yet

    run->step(nullptr);  // world_from_F1: P reached along v₁, v₂ from O_v
    s = scene_now();
    CHECK(alpha(s, "v₁") > alpha(s, "w₁"));
    REQUIRE(s.points3.size() == 1);
    CHECK(s.points3[0].p == dvec3(3, 2, 0));
    CHECK(s.points3[0].label == "P0 = (3, 2) in F1");
    CHECK(dashed(s, cg::Role::Construction) == 2);  // 3·v₁ then 2·v₂ (0·v₃ is skipped)

    run->step(nullptr);  // world_from_F2
    run->step(nullptr);  // its inverse
    s = scene_now();
    CHECK(alpha(s, "w₁") > alpha(s, "v₁"));
    CHECK(dashed(s, cg::Role::Construction) == 0);
    run->step(nullptr);  // M₁,₂
    run->step(nullptr);  // P0: from O_w along w₁, w₂
    s = scene_now();
    CHECK(s.points3[0].label == "P0 = (1, −1) in F2");
    CHECK(s.points3[0].style.role == cg::Role::Active);
    CHECK(dashed(s, cg::Role::Active) == 2);
    bool vector_arrow = false;
    for (const auto& g : s.segments3)
        vector_arrow = vector_arrow || (g.arrow && g.label == "u0 = (1, 0) in F1");
    CHECK(vector_arrow);
}

TEST_CASE("change-of-basis: exam problems grade their own answers and have short decimals",
          "[transforms][change-of-basis]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("change-of-basis");
    int orthonormal = 0, general = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
        CHECK_THAT(p.question, Catch::Contains("relative to F2"));
        (p.expected["orthonormal_to"].get<bool>() ? orthonormal : general) += 1;
        const auto tenths = [](double x) { return std::fabs(x * 10 - std::round(x * 10)) < 1e-9; };
        for (const auto& row : p.expected["matrix"])
            for (const auto& v : row) CHECK(tenths(v.get<double>()));
        for (const auto& pt : p.expected["points"])
            for (const auto& v : pt) CHECK(tenths(v.get<double>()));
    }
    CHECK(orthonormal > 180);
    CHECK(general > 30);
}
