// Free-form deformation in space (the trivariate Sederberg–Parry lattice, a 3D box): a trilinear
// case worked by hand; every point of 2,000 seeded random 3D lattices (degrees 1 to 4 per axis,
// boxes of any size and place, "by" and "to" moves, points inside, on faces and corners, and
// outside through each pair of faces) against an independent long-double nested de Casteljau
// (along k, then j, then i) to 1e-12 of the lattice's size; linear precision (the undeformed
// lattice leaves random points in place to 1e-12) and affine invariance (a lattice moved by a
// random 3D affine map moves every point by that map); points outside kept bit for bit; the
// state machine equals compute; the JSON form (the box's dimension decides); the spatial
// presets; bad input; the picture on the 3D canvas.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "animation/morph_ffd.hpp"
#include "core/rng.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::MorphFfd;
using Input = MorphFfd::Input;
using Move3 = MorphFfd::Move3;
using LD = long double;

namespace {

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("morph-ffd");
    if (!l) throw std::runtime_error("no lesson for morph-ffd");
    return *l;
}

const cg::LessonPreset& preset(const std::string& part) {
    for (const auto& p : lesson().presets)
        if (p.name.find(part) != std::string::npos) return p;
    throw std::runtime_error("no morph-ffd preset named like " + part);
}

std::string err(const std::string& text) {
    return cg::test::error_of("morph-ffd", text);
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// ---- the reference: nested de Casteljau in long double, written apart from the code ----

struct P {
    LD x = 0, y = 0, z = 0;
};
P lerp(P a, P b, LD u) {
    return {(1 - u) * a.x + u * b.x, (1 - u) * a.y + u * b.y, (1 - u) * a.z + u * b.z};
}

P casteljau(std::vector<P> c, LD u) {
    for (std::size_t r = c.size() - 1; r > 0; --r)
        for (std::size_t q = 0; q < r; ++q) c[q] = lerp(c[q], c[q + 1], u);
    return c[0];
}

// The lattice built again, as a 3D array [i][j][k], in long double, then the moves.
using Grid = std::vector<std::vector<std::vector<P>>>;
Grid ref_lattice(const Input& in) {
    Grid g(std::size_t(in.l + 1), std::vector<std::vector<P>>(std::size_t(in.m + 1),
                                                              std::vector<P>(std::size_t(in.n + 1))));
    const glm::dvec3 lo = in.box3_min, hi = in.box3_max;
    for (int i = 0; i <= in.l; ++i)
        for (int j = 0; j <= in.m; ++j)
            for (int k = 0; k <= in.n; ++k)
                g[i][j][k] = {LD(lo.x) + (LD(hi.x) - lo.x) * i / in.l,
                              LD(lo.y) + (LD(hi.y) - lo.y) * j / in.m,
                              LD(lo.z) + (LD(hi.z) - lo.z) * k / in.n};
    for (const Move3& mv : in.moves3) {
        P& q = g[mv.i][mv.j][mv.k];
        const P v{mv.value.x, mv.value.y, mv.value.z};
        q = mv.absolute ? v : P{q.x + v.x, q.y + v.y, q.z + v.z};
    }
    return g;
}

struct Ref {
    LD s = 0, t = 0, u = 0;
    bool inside = false;
    P x;
};

Ref reference(const Input& in, glm::dvec3 x) {
    const Grid g = ref_lattice(in);
    const glm::dvec3 lo = in.box3_min, hi = in.box3_max;
    Ref r;
    r.s = (LD(x.x) - lo.x) / (LD(hi.x) - lo.x);
    r.t = (LD(x.y) - lo.y) / (LD(hi.y) - lo.y);
    r.u = (LD(x.z) - lo.z) / (LD(hi.z) - lo.z);
    r.inside = r.s >= 0 && r.s <= 1 && r.t >= 0 && r.t <= 1 && r.u >= 0 && r.u <= 1;
    if (!r.inside) {
        r.x = {x.x, x.y, x.z};
        return r;
    }
    // Each row (i, j) at u, each slab i's rows at t, then the slabs at s: the trivariate volume.
    std::vector<P> slabs;
    for (int i = 0; i <= in.l; ++i) {
        std::vector<P> rows;
        for (int j = 0; j <= in.m; ++j) rows.push_back(casteljau(g[i][j], r.u));
        slabs.push_back(casteljau(rows, r.t));
    }
    r.x = casteljau(slabs, r.s);
    return r;
}

LD size_of(const Input& in) {
    LD big = 0;
    for (int c = 0; c < 3; ++c)
        big = std::max({big, LD(std::fabs(in.box3_min[c])), LD(std::fabs(in.box3_max[c]))});
    for (const auto& slab : ref_lattice(in))
        for (const auto& row : slab)
            for (const P& q : row) big = std::max({big, std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
    return big;
}

double pick(cg::Rng& rng, double lo, double hi) {
    return rng.uniform(lo, hi);
}

Input random_lattice(cg::Rng& rng) {
    Input in;
    const double scale = std::pow(10.0, double(rng.integer(-3, 5)));
    for (int c = 0; c < 3; ++c) {
        in.box3_min[c] = pick(rng, -1, 1) * scale;
        in.box3_max[c] = in.box3_min[c] + pick(rng, 0.01, 2) * scale;
    }
    in.l = int(rng.integer(1, 4));
    in.m = int(rng.integer(1, 4));
    in.n = int(rng.integer(1, 4));
    const int moves = int(rng.integer(0, 6));
    for (int q = 0; q < moves; ++q) {
        Move3 mv;
        mv.i = int(rng.integer(0, in.l));
        mv.j = int(rng.integer(0, in.m));
        mv.k = int(rng.integer(0, in.n));
        mv.absolute = rng.chance(0.3);
        const glm::dvec3 d{pick(rng, -1, 1) * scale, pick(rng, -1, 1) * scale, pick(rng, -1, 1) * scale};
        mv.value = mv.absolute ? in.box3_min + d : d;
        in.moves3.push_back(mv);
    }
    const int n = int(rng.integer(1, 5));
    const glm::dvec3 lo = in.box3_min, hi = in.box3_max;
    for (int q = 0; q < n; ++q) {
        const int kind = int(rng.integer(0, 5));
        const int axis = int(rng.integer(0, 2));
        glm::dvec3 x{pick(rng, lo.x, hi.x), pick(rng, lo.y, hi.y), pick(rng, lo.z, hi.z)};
        if (kind == 1) x[axis] = rng.chance(0.5) ? lo[axis] : hi[axis];  // on a face
        if (kind == 2)
            for (int c = 0; c < 3; ++c) x[c] = rng.chance(0.5) ? lo[c] : hi[c];  // a corner
        if (kind == 3) x[axis] = hi[axis] + pick(rng, 0.001, 1) * (hi[axis] - lo[axis]);  // outside
        if (kind == 4) x[axis] = lo[axis] - pick(rng, 0.001, 1) * (hi[axis] - lo[axis]);  // outside
        in.shape3.push_back(x);
    }
    return in;
}

// The trilinear example: box [0, 4]³, P111 by (2, 1, −1), P100 by (0, 0, 2).
Input worked() {
    Input in;
    in.box3_min = {0, 0, 0};
    in.box3_max = {4, 4, 4};
    in.l = in.m = in.n = 1;
    in.moves3 = {{1, 1, 1, {2, 1, -1}, false}, {1, 0, 0, {0, 0, 2}, false}};
    in.shape3 = {{1, 2, 3}, {3, 3, 3}, {4, 4, 4}, {3, 1, 1}, {2, 2, 5}};
    return in;
}

}  // namespace

TEST_CASE("morph-ffd in space: a trilinear lattice worked by hand", "[animation][morph-ffd]") {
    // Trilinear weights: on P111 s t u, on P100 s (1 − t)(1 − u); X' = X + Σ w ΔP (all eighths
    // and their products: exact in binary).
    const auto t = cg::test::run_traced<MorphFfd>(worked());
    const auto& r = t.result;
    const glm::dvec3 want[] = {{1.1875, 2.09375, 2.96875},
                               {3.84375, 3.421875, 2.671875},
                               {6, 5, 3},
                               {3.09375, 1.046875, 1.796875},
                               {2, 2, 5}};
    // (3, 1, 1): s = 0.75, t = u = 0.25, w111 = 0.046875, w100 = 0.421875:
    // (3, 1, 1) + 0.046875 (2, 1, −1) + 0.421875 (0, 0, 2).
    REQUIRE(r.deformed3.size() == 5);
    for (std::size_t q = 0; q < 5; ++q) {
        CAPTURE(q);
        CHECK(r.deformed3[q] == want[q]);
    }
    CHECK(r.deformed.empty());
    CHECK(r.local3[0] == glm::dvec3(0.25, 0.5, 0.75));
    CHECK(r.inside == std::vector<char>{1, 1, 1, 1, 0});
    CHECK(r.inside_count == 4);
    REQUIRE(r.lattice3.size() == 8);
    CHECK(r.lattice3[7] == glm::dvec3(6, 5, 3));  // P111 at (1·2 + 1)·2 + 1
    CHECK(r.lattice3[4] == glm::dvec3(4, 0, 2));  // P100 at (1·2 + 0)·2 + 0
    REQUIRE(t.steps.size() == 7);
    CHECK(t.steps[0].event == "lattice");
    CHECK(has(t.steps[0].narration, "degree 1 × 1 × 1: 8 control points"));
    CHECK(has(t.steps[0].narration, "Moved: P_111 by (2, 1, −1); P_100 by (0, 0, 2)"));
    const std::string& n = t.steps[1].narration;
    CAPTURE(n);
    CHECK(t.steps[1].event == "point");
    CHECK(has(n, "s = (1 − 0) / 4 = 0.25, t = (2 − 0) / 4 = 0.5, u = (3 − 0) / 4 = 0.75"));
    CHECK(has(n, "B^1(u) = [0.25, 0.75]"));
    CHECK(has(n, "(P_100)"));
    CHECK(has(n, "(P_111)"));
    CHECK(has(n, "= (1.1875, 2.09375, 2.96875)"));
    CHECK(t.steps[5].event == "outside");
    CHECK(has(t.steps[5].narration, "u is outside [0, 1]"));
    CHECK(t.steps[6].event == "summary");
    CHECK(has(t.steps[6].narration, "4 of 5 points"));
    // The same through the registry: the JSON result has 3D points.
    const auto j = cg::test::result_of("morph-ffd", preset("trilinear").input);
    CHECK(j["deformed"][0] == cg::parse_json("[1.1875, 2.09375, 2.96875]"));
    CHECK(j["local"][0].size() == 3);
    CHECK(j["outside_count"] == 1);
    CHECK(cg::test::input_of<MorphFfd>("morph-ffd", preset("trilinear").input) == worked());
}

TEST_CASE("morph-ffd in space: 2,000 random lattices against a nested long-double de Casteljau",
          "[animation][morph-ffd]") {
    cg::Rng rng(2027);
    int points = 0, outside = 0, faces = 0, cubic = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Input in = random_lattice(rng);
        CAPTURE(trial, in.l, in.m, in.n);
        const auto r = MorphFfd::compute(in);
        const LD tol = 1e-12L * size_of(in);
        cubic += in.l >= 3 && in.m >= 3 && in.n >= 3;
        for (std::size_t q = 0; q < in.shape3.size(); ++q) {
            const glm::dvec3 x = in.shape3[q];
            CAPTURE(q, x.x, x.y, x.z);
            const Ref ref = reference(in, x);
            ++points;
            CHECK(std::fabs(r.local3[q].x - ref.s) <= 1e-12L * (1 + std::fabs(ref.s)));
            CHECK(std::fabs(r.local3[q].y - ref.t) <= 1e-12L * (1 + std::fabs(ref.t)));
            CHECK(std::fabs(r.local3[q].z - ref.u) <= 1e-12L * (1 + std::fabs(ref.u)));
            REQUIRE(bool(r.inside[q]) == ref.inside);
            if (!ref.inside) {
                ++outside;
                CHECK(r.deformed3[q] == x);  // bit for bit
                continue;
            }
            const glm::dvec3 st = r.local3[q];
            faces += st.x == 0 || st.x == 1 || st.y == 0 || st.y == 1 || st.z == 0 || st.z == 1;
            CHECK(std::fabs(r.deformed3[q].x - ref.x.x) <= tol);
            CHECK(std::fabs(r.deformed3[q].y - ref.x.y) <= tol);
            CHECK(std::fabs(r.deformed3[q].z - ref.x.z) <= tol);
        }
    }
    CHECK(points > 5000);
    CHECK(outside > 1500);
    CHECK(faces > 1500);
    CHECK(cubic > 100);
}

TEST_CASE("morph-ffd in space: linear precision and affine invariance", "[animation][morph-ffd]") {
    cg::Rng rng(8);
    for (int trial = 0; trial < 500; ++trial) {
        CAPTURE(trial);
        Input in = random_lattice(rng);
        in.moves3.clear();
        in.shape3.clear();
        const glm::dvec3 lo = in.box3_min, hi = in.box3_max;
        for (int q = 0; q < 4; ++q)
            in.shape3.push_back({pick(rng, lo.x, hi.x), pick(rng, lo.y, hi.y), pick(rng, lo.z, hi.z)});
        const double tol = 1e-12 * double(size_of(in));
        const auto same = MorphFfd::compute(in);
        for (std::size_t q = 0; q < in.shape3.size(); ++q)
            for (int c = 0; c < 3; ++c) CHECK(std::fabs(same.deformed3[q][c] - in.shape3[q][c]) <= tol);
        // Every control point taken "to" A P + b: every point goes to A X + b.
        double a[3][3];
        for (auto& row : a)
            for (double& v : row) v = pick(rng, -1, 1);
        const double w = hi.x - lo.x;
        const glm::dvec3 shift{pick(rng, -1, 1) * w, pick(rng, -1, 1) * w, pick(rng, -1, 1) * w};
        auto map = [&](glm::dvec3 x) {
            glm::dvec3 y = shift;
            for (int r = 0; r < 3; ++r) y[r] += a[r][0] * x.x + a[r][1] * x.y + a[r][2] * x.z;
            return y;
        };
        for (int i = 0; i <= in.l; ++i)
            for (int j = 0; j <= in.m; ++j)
                for (int k = 0; k <= in.n; ++k)
                    in.moves3.push_back({i, j, k, map(MorphFfd::rest3(in, i, j, k)), true});
        const auto moved = MorphFfd::compute(in);
        const double tol2 = 1e-12 * double(size_of(in));
        for (std::size_t q = 0; q < in.shape3.size(); ++q) {
            const glm::dvec3 want = map(in.shape3[q]);
            for (int c = 0; c < 3; ++c) CHECK(std::fabs(moved.deformed3[q][c] - want[c]) <= tol2);
        }
    }
}

TEST_CASE("morph-ffd in space: the state machine gives what compute gives",
          "[animation][morph-ffd]") {
    cg::Rng rng(18);
    for (int trial = 0; trial < 300; ++trial) {
        CAPTURE(trial);
        const Input in = random_lattice(rng);
        const auto traced = cg::test::run_traced<MorphFfd>(in);
        const auto plain = MorphFfd::compute(in);
        CHECK(traced.result == plain);
        CHECK(cg::run_to_end<MorphFfd>(MorphFfd::start(in)) == plain);
        const auto ev = cg::test::events(traced);
        REQUIRE(ev.size() == in.shape3.size() + 2);
        CHECK(ev.front() == "lattice");
        CHECK(ev.back() == "summary");
        for (std::size_t q = 0; q < in.shape3.size(); ++q)
            CHECK(ev[q + 1] == (plain.inside[q] ? "point" : "outside"));
    }
    const auto& a = cg::test::algorithm("morph-ffd");
    for (const char* name : {"trilinear", "tapered", "bar twisted"}) {
        INFO(name);
        cg::test::check_replay(a, preset(name).input, 3);
    }
}

TEST_CASE("morph-ffd in space: the presets do what the lesson says", "[animation][morph-ffd]") {
    auto run = [](const char* name) {
        const Input in = cg::test::input_of<MorphFfd>("morph-ffd", preset(name).input);
        REQUIRE(in.spatial());
        return std::make_pair(in, MorphFfd::compute(in));
    };
    SECTION("the column tapers linearly: x' = x (1 − 0.6 t), z' = z (1 − 0.6 t), y' = y") {
        const auto [in, r] = run("tapered");
        CHECK(!in.edges.empty());
        for (std::size_t q = 0; q < in.shape3.size(); ++q) {
            const glm::dvec3 x = in.shape3[q];
            const double f = 1 - 0.6 * (x.y / 4);
            CHECK(r.deformed3[q].x == Approx(x.x * f).margin(1e-12));
            CHECK(r.deformed3[q].y == Approx(x.y).margin(1e-12));
            CHECK(r.deformed3[q].z == Approx(x.z * f).margin(1e-12));
        }
    }
    SECTION("the twisted bar: each cross-section keeps its distance from the axis roughly, and "
            "the far end is turned 90°") {
        const auto [in, r] = run("bar twisted");
        for (std::size_t q = 0; q < in.shape3.size(); ++q) {
            const glm::dvec3 x = in.shape3[q], X = r.deformed3[q];
            CHECK(X.x == Approx(x.x).margin(1e-9));  // the sections stay at their place along x
            if (x.x == 6) {  // the end: (y, z) turned by 90°, (y, z) → (−z, y)
                CHECK(X.y == Approx(-x.z).margin(1e-3));
                CHECK(X.z == Approx(x.y).margin(1e-3));
            }
            if (x.x == 0) {  // the start: not moved (its section is the rest one)
                CHECK(X.y == Approx(x.y).margin(1e-12));
                CHECK(X.z == Approx(x.z).margin(1e-12));
            }
        }
    }
}

TEST_CASE("morph-ffd in space: bad input names the field and the reason", "[animation][morph-ffd]") {
    const std::string box = R"("box": {"min": [0, 0, 0], "max": [1, 1, 1]})";
    const std::string sh = R"("shape": [[0.5, 0.5, 0.5]])";
    const std::string b = "{" + box + ", " + sh;
    CHECK(err(b + "}") == "(accepted)");  // degree [2, 2, 2] by default
    CHECK(err(b + R"(, "degree": [2, 2]})").find("degree: must be [l, m, n] for a 3D box") == 0);
    CHECK(err(b + R"(, "degree": [2, 2, 9]})").find("degree[2]: must be a whole degree 1 to 8") == 0);
    CHECK(err(b + R"(, "degree": [2, 2, 0]})").find("degree[2]: must be a whole degree 1 to 8") == 0);
    CHECK(err(b + R"(, "degree": [8, 8, 8], "moves": [{"point": [8, 8, 8], "by": [1, 1, 1]}]})") == "(accepted)");
    CHECK(err(b + R"(, "moves": [{"point": [0, 3, 0], "by": [1, 1, 1]}]})").find("moves[0].point: must name a control point [i, j, k] with 0 ≤ i ≤ 2, 0 ≤ j ≤ 2 and 0 ≤ k ≤ 2 (got [0, 3, 0])") == 0);
    CHECK(err(b + R"(, "moves": [{"point": [0, 0], "by": [1, 1, 1]}]})").find("moves[0].point: must be a control point [i, j, k]") == 0);
    CHECK(err(b + R"(, "moves": [{"point": [0, 0, 0], "by": [1, 1]}]})").find("moves[0].by") == 0);
    CHECK(err(b + R"(, "moves": [{"point": [0, 0, 0], "to": [1, 1, 2e6]}]})").find("moves[0].to: is too large") == 0);
    CHECK(err(R"({"box": {"min": [0, 0, 0], "max": [1, 1, 0]}, )" + sh + "}").find("box: max must be above min in z") == 0);
    CHECK(err(R"({"box": {"min": [0, 0, 0], "max": [1, 1]}, )" + sh + "}").find("box.max") == 0);
    CHECK(err("{" + box + R"(, "shape": [[0.5, 0.5]]})").find("shape[0]") == 0);
    CHECK(err("{" + box + R"(, "shape": []})") == "shape: must have at least 1 point (got none)");
    CHECK(err(b + R"(, "edges": [[0, 1]]})").find("edges[0]: must join two shape points, indices 0 to 0 (got [0, 1])") == 0);
    CHECK(err(b + R"(, "edges": [[0]]})").find("edges[0]: must be a pair") == 0);
    CHECK(err(b + R"(, "edges": [[0, 0.5]]})").find("edges[0][1]: must be a whole index") == 0);
    CHECK(err(b + R"(, "edges": 2})").find("edges: must be a list") == 0);
    CHECK(err(R"({"shape": [[0, 0]], "edges": [[0, 0]]})").find("edges: is for a 3D shape") == 0);
    std::string many = "{" + box + R"(, "shape": [)";
    for (int q = 0; q <= MorphFfd::kMaxPoints; ++q) many += (q ? ",[0,0,0]" : "[0,0,0]");
    CHECK(err(many + "]}").find("shape: has 5001 points; at most 5000") == 0);
}

TEST_CASE("morph-ffd in space: the picture on the 3D canvas", "[animation][morph-ffd]") {
    auto s = MorphFfd::start(worked());
    cg::Scene before;
    MorphFfd::draw(s, before);
    CHECK(before.has_3d());
    CHECK(!before.has_2d());
    int box = 0, lattice = 0, bent = 0;
    for (const auto& g : before.segments3) {
        box += g.style.role == cg::Role::Window;
        lattice += g.style.role == cg::Role::Leaving;
        bent += g.style.role == cg::Role::Entering;
    }
    CHECK(box == 12);
    CHECK(lattice == 12);  // the 1 × 1 × 1 lattice is a cube too
    CHECK(bent == 0);
    MorphFfd::step(s, nullptr);
    MorphFfd::step(s, nullptr);
    MorphFfd::step(s, nullptr);
    cg::Scene scene;
    MorphFfd::draw(s, scene);
    int arrows = 0, green = 0;
    bent = 0;
    std::vector<std::string> names;
    for (const auto& g : scene.segments3) {
        arrows += g.arrow;
        bent += g.style.role == cg::Role::Entering;
        green += g.style.role == cg::Role::Kept;
    }
    for (const auto& p : scene.points3)
        if (!p.label.empty()) names.push_back(p.label);
    CHECK(bent == 12 * 24);  // the box's edges carried through the deformation
    CHECK(arrows == 3);      // P111 and P100 from their rest places, and the point to X'
    CHECK(green == 8);       // the polyline's first edge, sampled
    for (const char* name : {"P111", "P100", "X", "X'"})
        CHECK(std::find(names.begin(), names.end(), name) != names.end());
    // A wireframe draws its edges, not the polyline.
    const Input taper = cg::test::input_of<MorphFfd>("morph-ffd", preset("tapered").input);
    cg::Scene ts;
    MorphFfd::draw(MorphFfd::start(taper), ts);
    int grey = 0;
    for (const auto& g : ts.segments3) grey += g.style.role == cg::Role::Subject;
    CHECK(grey == int(taper.edges.size()));
}
