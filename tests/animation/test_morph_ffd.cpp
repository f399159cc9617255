// Free-form deformation: the exam-style example worked by hand (local coordinates, the one
// weight on the moved corner, X' = X + w ΔP, the point outside left alone); every point of
// 3,000 seeded random lattices (degrees 1 to 8, boxes of any size and place, "by" and "to"
// moves, points inside, on the edges and corners, and outside) against an independent
// long-double de Casteljau evaluation, column by column then across, to 1e-12 of the lattice's
// size; linear precision (the undeformed lattice leaves 1,000 random points in place to 1e-12)
// and affine invariance (a lattice moved by a random affine map moves 1,000 points by that map);
// points outside kept bit for bit; the Bernstein weights; the state machine equals compute;
// replay; the presets; bad input; exam problems against a hand computation; the picture.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "animation/morph_ffd.hpp"
#include "core/format.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::MorphFfd;
using Input = MorphFfd::Input;
using Move = MorphFfd::Move;
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

// ---- the reference: de Casteljau in long double, written apart from the code ----

struct P {
    LD x = 0, y = 0;
};
P lerp(P a, P b, LD u) {
    return {(1 - u) * a.x + u * b.x, (1 - u) * a.y + u * b.y};
}

// The point of a Bézier curve with control points c at u, by repeated linear interpolation.
P casteljau(std::vector<P> c, LD u) {
    for (std::size_t r = c.size() - 1; r > 0; --r)
        for (std::size_t q = 0; q < r; ++q) c[q] = lerp(c[q], c[q + 1], u);
    return c[0];
}

// The lattice built again: rest places X_0 + (i/l) S + (j/m) T in long double, then the moves.
std::vector<P> ref_lattice(const Input& in) {
    std::vector<P> p;
    for (int i = 0; i <= in.l; ++i)
        for (int j = 0; j <= in.m; ++j)
            p.push_back({LD(in.box_min.x) + (LD(in.box_max.x) - in.box_min.x) * i / in.l,
                         LD(in.box_min.y) + (LD(in.box_max.y) - in.box_min.y) * j / in.m});
    for (const Move& mv : in.moves) {
        P& q = p[std::size_t(mv.i * (in.m + 1) + mv.j)];
        q = mv.absolute ? P{mv.value.x, mv.value.y} : P{q.x + mv.value.x, q.y + mv.value.y};
    }
    return p;
}

struct Ref {
    LD s = 0, t = 0;
    bool inside = false;
    P x;
};

Ref reference(const Input& in, glm::dvec2 x) {
    const std::vector<P> p = ref_lattice(in);
    Ref r;
    r.s = (LD(x.x) - in.box_min.x) / (LD(in.box_max.x) - in.box_min.x);
    r.t = (LD(x.y) - in.box_min.y) / (LD(in.box_max.y) - in.box_min.y);
    r.inside = r.s >= 0 && r.s <= 1 && r.t >= 0 && r.t <= 1;
    if (!r.inside) {
        r.x = {x.x, x.y};
        return r;
    }
    // Each column i at t, then the columns at s: the tensor-product surface.
    std::vector<P> columns;
    for (int i = 0; i <= in.l; ++i)
        columns.push_back(casteljau({p.begin() + i * (in.m + 1), p.begin() + (i + 1) * (in.m + 1)}, r.t));
    r.x = casteljau(columns, r.s);
    return r;
}

LD size_of(const Input& in) {
    LD big = std::max(std::fabs(in.box_min.x), std::fabs(in.box_min.y));
    big = std::max({big, LD(std::fabs(in.box_max.x)), LD(std::fabs(in.box_max.y))});
    for (const P& q : ref_lattice(in)) big = std::max({big, std::fabs(q.x), std::fabs(q.y)});
    return big;
}

double pick(cg::Rng& rng, double lo, double hi) {
    return rng.uniform(lo, hi);
}

Input random_lattice(cg::Rng& rng) {
    Input in;
    const double scale = std::pow(10.0, double(rng.integer(-3, 5)));
    in.box_min = {pick(rng, -1, 1) * scale, pick(rng, -1, 1) * scale};
    in.box_max = in.box_min + glm::dvec2(pick(rng, 0.01, 2) * scale, pick(rng, 0.01, 2) * scale);
    in.l = int(rng.integer(1, MorphFfd::kMaxDegree));
    in.m = int(rng.integer(1, MorphFfd::kMaxDegree));
    const int moves = int(rng.integer(0, 6));
    for (int q = 0; q < moves; ++q) {
        Move mv;
        mv.i = int(rng.integer(0, in.l));
        mv.j = int(rng.integer(0, in.m));
        mv.absolute = rng.chance(0.3);
        const glm::dvec2 d{pick(rng, -1, 1) * scale, pick(rng, -1, 1) * scale};
        mv.value = mv.absolute ? in.box_min + d : d;
        in.moves.push_back(mv);
    }
    const int n = int(rng.integer(1, 5));
    const glm::dvec2 lo = in.box_min, hi = in.box_max;
    for (int q = 0; q < n; ++q) {
        const int kind = int(rng.integer(0, 5));
        glm::dvec2 x{pick(rng, lo.x, hi.x), pick(rng, lo.y, hi.y)};
        if (kind == 1) x.x = rng.chance(0.5) ? lo.x : hi.x;          // on an edge
        if (kind == 2) x = {rng.chance(0.5) ? lo.x : hi.x, rng.chance(0.5) ? lo.y : hi.y};  // corner
        if (kind == 3) x.y = hi.y + pick(rng, 0.001, 1) * (hi.y - lo.y);  // outside
        if (kind == 4) x.x = lo.x - pick(rng, 0.001, 1) * (hi.x - lo.x);  // outside
        in.shape.push_back(x);
    }
    return in;
}

// The exam-style example: bilinear over [0, 4]², P11 by (2, 1).
Input worked() {
    Input in;
    in.box_min = {0, 0};
    in.box_max = {4, 4};
    in.l = in.m = 1;
    in.moves = {{1, 1, {2, 1}, false}};
    in.shape = {{1, 1}, {3, 1}, {3, 3}, {1, 3}, {2, 2}, {5, 2}};
    return in;
}

}  // namespace

TEST_CASE("morph-ffd: the exam-style example worked by hand", "[animation][morph-ffd]") {
    // Only P11 moved, so X' = X + s t (2, 1): the weight on P11 is B_1^1(s) B_1^1(t) = s t.
    const auto t = cg::test::run_traced<MorphFfd>(worked());
    const auto& r = t.result;
    const glm::dvec2 want[] = {{1.125, 1.0625}, {3.375, 1.1875}, {4.125, 3.5625},
                               {1.375, 3.1875}, {2.5, 2.25},     {5, 2}};
    REQUIRE(r.deformed.size() == 6);
    for (std::size_t q = 0; q < 6; ++q) {
        CAPTURE(q);
        CHECK(r.deformed[q] == want[q]);  // quarters: exact in binary
    }
    CHECK(r.local[1] == glm::dvec2(0.75, 0.25));
    CHECK(r.inside == std::vector<char>{1, 1, 1, 1, 1, 0});
    CHECK(r.inside_count == 5);
    CHECK(r.lattice == std::vector<glm::dvec2>{{0, 0}, {0, 4}, {4, 0}, {6, 5}});
    REQUIRE(t.steps.size() == 8);
    CHECK(t.steps[0].event == "lattice");
    CHECK(has(t.steps[0].narration, "Moved: P_11 by (2, 1)"));
    const std::string& n = t.steps[2].narration;
    CAPTURE(n);
    CHECK(t.steps[2].event == "point");
    CHECK(has(n, "s = (3 − 0) / 4 = 0.75, t = (1 − 0) / 4 = 0.25"));
    CHECK(has(n, "B^1(s) = [0.25, 0.75], B^1(t) = [0.75, 0.25]"));
    CHECK(has(n, "= X + 0.1875 · (2, 1) (P_11) = (3.375, 1.1875)"));
    CHECK(t.steps[6].event == "outside");
    CHECK(has(t.steps[6].narration, "s is outside [0, 1]"));
    CHECK(t.steps[7].event == "summary");
    CHECK(has(t.steps[7].narration, "5 of 6 points"));
    // The same corner moved "to" (6, 5) instead gives the same.
    Input to = worked();
    to.moves = {{1, 1, {6, 5}, true}};
    CHECK(MorphFfd::compute(to) == r);
    // Two moves of one point add up.
    Input twice = worked();
    twice.moves = {{1, 1, {1, 0}, false}, {1, 1, {1, 1}, false}};
    CHECK(MorphFfd::compute(twice).deformed == r.deformed);
}

TEST_CASE("morph-ffd: 3,000 random lattices against a long-double de Casteljau",
          "[animation][morph-ffd]") {
    cg::Rng rng(2026);
    int points = 0, outside = 0, edges = 0, high = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Input in = random_lattice(rng);
        CAPTURE(trial, in.l, in.m);
        const auto r = MorphFfd::compute(in);
        const LD tol = 1e-12L * size_of(in);
        high += in.l >= 6 && in.m >= 6;
        for (std::size_t q = 0; q < in.shape.size(); ++q) {
            CAPTURE(q, in.shape[q].x, in.shape[q].y);
            const Ref ref = reference(in, in.shape[q]);
            ++points;
            CHECK(std::fabs(r.local[q].x - ref.s) <= 1e-12L * (1 + std::fabs(ref.s)));
            CHECK(std::fabs(r.local[q].y - ref.t) <= 1e-12L * (1 + std::fabs(ref.t)));
            // Exactly on the edge both say inside; no random point lies within rounding of it.
            REQUIRE(bool(r.inside[q]) == ref.inside);
            if (!ref.inside) {
                ++outside;
                CHECK(r.deformed[q] == in.shape[q]);  // bit for bit
                continue;
            }
            edges += r.local[q].x == 0 || r.local[q].x == 1;
            CHECK(std::fabs(r.deformed[q].x - ref.x.x) <= tol);
            CHECK(std::fabs(r.deformed[q].y - ref.x.y) <= tol);
        }
    }
    CHECK(points > 7000);
    CHECK(outside > 2000);
    CHECK(edges > 1500);
    CHECK(high > 50);
}

TEST_CASE("morph-ffd: linear precision and affine invariance", "[animation][morph-ffd]") {
    cg::Rng rng(7);
    for (int trial = 0; trial < 1000; ++trial) {
        CAPTURE(trial);
        Input in = random_lattice(rng);
        in.moves.clear();
        in.shape.clear();
        for (int q = 0; q < 4; ++q)
            in.shape.push_back({pick(rng, in.box_min.x, in.box_max.x), pick(rng, in.box_min.y, in.box_max.y)});
        const double tol = 1e-12 * double(size_of(in));
        // The undeformed lattice leaves every point where it is.
        const auto same = MorphFfd::compute(in);
        for (std::size_t q = 0; q < in.shape.size(); ++q) {
            CHECK(std::fabs(same.deformed[q].x - in.shape[q].x) <= tol);
            CHECK(std::fabs(same.deformed[q].y - in.shape[q].y) <= tol);
        }
        // Every control point taken "to" A P + b: every point goes to A X + b.
        const double a = pick(rng, -1, 1), b = pick(rng, -1, 1), c = pick(rng, -1, 1),
                     d = pick(rng, -1, 1);
        const glm::dvec2 shift{pick(rng, -1, 1), pick(rng, -1, 1)};
        auto map = [&](glm::dvec2 x) {
            return glm::dvec2(a * x.x + b * x.y, c * x.x + d * x.y) + shift * (in.box_max.x - in.box_min.x);
        };
        for (int i = 0; i <= in.l; ++i)
            for (int j = 0; j <= in.m; ++j) in.moves.push_back({i, j, map(MorphFfd::rest(in, i, j)), true});
        const auto moved = MorphFfd::compute(in);
        const double tol2 = 1e-12 * double(size_of(in));
        for (std::size_t q = 0; q < in.shape.size(); ++q) {
            const glm::dvec2 want = map(in.shape[q]);
            CHECK(std::fabs(moved.deformed[q].x - want.x) <= tol2);
            CHECK(std::fabs(moved.deformed[q].y - want.y) <= tol2);
        }
    }
}

TEST_CASE("morph-ffd: the Bernstein weights", "[animation][morph-ffd]") {
    MorphFfd::Weights b{};
    MorphFfd::bernstein(2, 0.5, b);
    CHECK(b[0] == 0.25);
    CHECK(b[1] == 0.5);
    CHECK(b[2] == 0.25);
    MorphFfd::bernstein(3, 0.25, b);
    CHECK(b[0] == Approx(27.0 / 64));
    CHECK(b[1] == Approx(27.0 / 64));
    CHECK(b[2] == Approx(9.0 / 64));
    CHECK(b[3] == Approx(1.0 / 64));
    // At the ends only the end weight is left: the box's edges go to the lattice's edges.
    for (int d = 1; d <= MorphFfd::kMaxDegree; ++d) {
        MorphFfd::bernstein(d, 0, b);
        CHECK(b[0] == 1);
        for (int i = 1; i <= d; ++i) CHECK(b[std::size_t(i)] == 0);
        MorphFfd::bernstein(d, 1, b);
        CHECK(b[std::size_t(d)] == 1);
        for (int i = 0; i < d; ++i) CHECK(b[std::size_t(i)] == 0);
        cg::Rng rng{std::uint64_t(d)};
        for (int k = 0; k < 50; ++k) {
            MorphFfd::bernstein(d, rng.uniform(0, 1), b);
            double sum = 0;
            for (int i = 0; i <= d; ++i) {
                sum += b[std::size_t(i)];
                CHECK(b[std::size_t(i)] >= 0);
            }
            CHECK(sum == Approx(1).epsilon(1e-14));
        }
    }
}

TEST_CASE("morph-ffd: the state machine gives what compute gives, through the registry too",
          "[animation][morph-ffd]") {
    cg::Rng rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        CAPTURE(trial);
        const Input in = random_lattice(rng);
        const auto traced = cg::test::run_traced<MorphFfd>(in);
        const auto plain = MorphFfd::compute(in);
        CHECK(traced.result == plain);
        CHECK(cg::run_to_end<MorphFfd>(MorphFfd::start(in)) == plain);
        const auto ev = cg::test::events(traced);
        REQUIRE(ev.size() == in.shape.size() + 2);
        CHECK(ev.front() == "lattice");
        CHECK(ev.back() == "summary");
        for (std::size_t q = 0; q < in.shape.size(); ++q)
            CHECK(ev[q + 1] == (plain.inside[q] ? "point" : "outside"));
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const auto j = cg::test::result_of("morph-ffd", p.input);
        CHECK(j["deformed"].size() == p.input["shape"].size());
    }
}

TEST_CASE("morph-ffd: determinism and replay", "[animation][morph-ffd]") {
    const auto& a = cg::test::algorithm("morph-ffd");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 5);
        CHECK(cg::test::trace(a, p.input) == cg::test::trace(a, p.input));
    }
}

TEST_CASE("morph-ffd: the lesson's presets do what the lesson says", "[animation][morph-ffd]") {
    auto run = [](const cg::LessonPreset& p) {
        const Input in = cg::test::input_of<MorphFfd>("morph-ffd", p.input);
        return std::make_pair(in, MorphFfd::compute(in));
    };
    SECTION("the undeformed lattice: every point stays put") {
        const auto [in, r] = run(preset("undeformed"));
        for (std::size_t q = 0; q < in.shape.size(); ++q) {
            CHECK(std::fabs(r.deformed[q].x - in.shape[q].x) < 1e-12);
            CHECK(std::fabs(r.deformed[q].y - in.shape[q].y) < 1e-12);
        }
    }
    SECTION("the affine lattice shears: x' = x + 0.375 (y + 2), y' = y") {
        const auto [in, r] = run(preset("affine"));
        for (std::size_t q = 0; q < in.shape.size(); ++q) {
            CHECK(r.deformed[q].x == Approx(in.shape[q].x + 0.375 * (in.shape[q].y + 2)));
            CHECK(r.deformed[q].y == Approx(in.shape[q].y).margin(1e-12));
        }
    }
    SECTION("bending a bar: the middle lifts more than the ends") {
        const auto [in, r] = run(preset("bar"));
        double middle = 0, end = 1e9;
        for (std::size_t q = 0; q < in.shape.size(); ++q) {
            const double lift = r.deformed[q].y - in.shape[q].y;
            if (std::fabs(in.shape[q].x - 4) < 0.3) middle = std::max(middle, lift);
            if (in.shape[q].x < 0.6) end = std::min(end, lift);
        }
        CHECK(middle == Approx(1.5));  // (3/4)·2 at s = 1/2
        CHECK(end < 0.5);
    }
    SECTION("the zigzag: the points outside the box stay where they are") {
        const auto [in, r] = run(preset("zigzag"));
        int outside = 0, moved = 0;
        for (std::size_t q = 0; q < in.shape.size(); ++q) {
            if (!r.inside[q]) {
                ++outside;
                CHECK(r.deformed[q] == in.shape[q]);
            } else {
                moved += r.deformed[q] != in.shape[q];
            }
        }
        CHECK(outside >= 3);
        CHECK(moved >= 5);
    }
}

TEST_CASE("morph-ffd: bad input names the field and the reason", "[animation][morph-ffd]") {
    const std::string sh = R"("shape": [[0.5, 0.5]])";
    CHECK(err(R"({})").find("shape: is missing") == 0);
    CHECK(err(R"({"shape": []})") == "shape: must have at least 1 point (got none)");
    CHECK(err(R"({"shape": [[0, 0, 0]]})").find("shape[0]") == 0);
    CHECK(err(R"({"shape": [[1e7, 0]]})").find("shape[0]: is too large") == 0);
    CHECK(err("{" + sh + R"(, "degree": [0, 2]})").find("degree[0]: must be a whole degree 1 to 8") == 0);
    CHECK(err("{" + sh + R"(, "degree": [2, 9]})").find("degree[1]: must be a whole degree 1 to 8") == 0);
    CHECK(err("{" + sh + R"(, "degree": [1.5, 2]})").find("degree[0]: must be a whole degree") == 0);
    CHECK(err("{" + sh + R"(, "degree": 2})").find("degree: must be [l, m]") == 0);
    CHECK(err("{" + sh + R"(, "box": {"min": [0, 0], "max": [0, 1]}})").find("box: max must be above min in x") == 0);
    CHECK(err("{" + sh + R"(, "box": {"min": [0, 0]}})").find("box.max") == 0);
    CHECK(err("{" + sh + R"(, "moves": [{"point": [3, 0], "by": [1, 1]}]})").find("moves[0].point: must name a control point [i, j] with 0 ≤ i ≤ 2 and 0 ≤ j ≤ 2 (got [3, 0])") == 0);
    CHECK(err("{" + sh + R"(, "moves": [{"point": [0, 0]}]})").find("moves[0]: needs exactly one of") == 0);
    CHECK(err("{" + sh + R"(, "moves": [{"point": [0, 0], "by": [1, 1], "to": [1, 1]}]})").find("moves[0]: needs exactly one of") == 0);
    CHECK(err("{" + sh + R"(, "moves": [{"point": [0, 0], "to": [1, 2e6]}]})").find("moves[0].to: is too large") == 0);
    CHECK(err("{" + sh + R"(, "moves": [{"point": [0.5, 0], "by": [1, 1]}]})").find("moves[0].point[0]: must be a whole index") == 0);
    CHECK(err("{" + sh + R"(, "moves": 3})").find("moves: must be a list") == 0);
    CHECK(err("{" + sh + R"(, "closed": 1})").find("closed") == 0);
    CHECK(err("{" + sh + R"(, "twist": 1})").find("twist: is not a known field") == 0);
    CHECK(err("{" + sh + R"(, "box": {"min": [0, NaN], "max": [1, 1]}})").find("not valid JSON") != std::string::npos);
    std::string many = R"({"shape": [)";
    for (int q = 0; q <= MorphFfd::kMaxPoints; ++q) many += (q ? ",[0,0]" : "[0,0]");
    CHECK(err(many + "]}").find("shape: has 5001 points; at most 5000") == 0);
    // Accepted: one point, degree 8 × 8, a point far outside.
    CHECK(err("{" + sh + "}") == "(accepted)");
    CHECK(err(R"({"shape": [[1e6, -1e6]], "degree": [8, 8]})") == "(accepted)");
}

TEST_CASE("morph-ffd: exam problems, one point through a small lattice by hand",
          "[animation][morph-ffd][exam]") {
    const auto& a = cg::test::algorithm("morph-ffd");
    int outside = 0, quadratic = 0, two = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<MorphFfd>("morph-ffd", p.input);
        REQUIRE(in.shape.size() == 1);
        REQUIRE(in.m == 1);
        REQUIRE((in.l == 1 || in.l == 2));
        quadratic += in.l == 2;
        two += in.moves.size() == 2;
        // By hand: s, t; X' = X + Σ B_i(s) B_j(t) ΔP_ij (linear precision), in long double.
        const glm::dvec2 x = in.shape[0];
        const LD s = LD(x.x) / 4, t = LD(x.y) / 4;
        LD X = x.x, Y = x.y;
        if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
            for (const Move& mv : in.moves) {
                const LD bs = in.l == 1 ? (mv.i ? s : 1 - s)
                                        : (mv.i == 0 ? (1 - s) * (1 - s) : mv.i == 1 ? 2 * s * (1 - s) : s * s);
                const LD bt = mv.j ? t : 1 - t;
                X += bs * bt * mv.value.x;
                Y += bs * bt * mv.value.y;
            }
        } else {
            ++outside;
        }
        const auto local = p.expected["local/0"].get<std::vector<double>>();
        const auto got = p.expected["deformed/0"].get<std::vector<double>>();
        CHECK(local == std::vector<double>{double(s), double(t)});
        CHECK(got == std::vector<double>{double(X), double(Y)});  // quarters: exact
        CHECK(p.answers == std::vector<std::string>{"local/0", "deformed/0"});
        CHECK(has(p.question, "Where does the point X = " + cg::num(x)));
    }
    CHECK(outside > 20);
    CHECK(quadratic > 100);
    CHECK(two > 100);
}

TEST_CASE("morph-ffd: the picture, the lattice, the bent space and the shape",
          "[animation][morph-ffd]") {
    auto s = MorphFfd::start(worked());
    cg::Scene before;
    MorphFfd::draw(s, before);
    // Before the first step: the box, the undeformed control polygon (4 edges), no curves.
    int magenta = 0;
    for (const auto& g : before.segments) magenta += g.style.role == cg::Role::Leaving;
    CHECK(magenta == 4);
    for (const auto& p : before.polygons) CHECK(p.style.role != cg::Role::Entering);
    MorphFfd::step(s, nullptr);
    MorphFfd::step(s, nullptr);
    MorphFfd::step(s, nullptr);
    cg::Scene scene;
    MorphFfd::draw(s, scene);
    int curves = 0, green = 0, arrows = 0;
    for (const auto& p : scene.polygons) {
        curves += p.style.role == cg::Role::Entering;
        green += p.style.role == cg::Role::Kept;
    }
    CHECK(curves == 18);  // s = const and t = const at every eighth
    CHECK(green == 1);
    for (const auto& g : scene.segments) arrows += g.arrow;
    CHECK(arrows == 2);  // P11 from its rest place, and the point (3, 1) to where it goes
    // The deformed shape's curve passes through the deformed points and the map between them.
    const cg::Polygon2* after = nullptr;
    for (const auto& p : scene.polygons)
        if (p.style.role == cg::Role::Kept) after = &p;
    REQUIRE(after);
    CHECK(after->points.front() == glm::dvec2(1.125, 1.0625));
    CHECK(after->points.back() == glm::dvec2(3.375, 1.1875));
    std::vector<std::string> labels;
    for (const auto& l : scene.labels) labels.push_back(l.text);
    for (const char* name : {"P00", "P01", "P10", "P11"})
        CHECK(std::find(labels.begin(), labels.end(), name) != labels.end());
    CHECK(scene.handles.empty());  // a "by" move is edited as numbers
    Input to = worked();
    to.moves = {{1, 1, {6, 5}, true}};
    cg::Scene ts;
    MorphFfd::draw(MorphFfd::start(to), ts);
    REQUIRE(ts.handles.size() == 1);
    CHECK(ts.handles[0].x_field == "/moves/0/to/0");
}
