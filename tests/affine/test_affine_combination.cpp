// Affine combinations: the course's expressions decided by hand (a table of them); thousands of
// random expression trees — integer and fractional coefficients, nested sums, differences,
// scalings and divisions, products of points, dots and crosses — against an independent
// evaluator that builds each tree and its coefficient vector together in long double; identities
// in t (Bernstein sums of every degree to 12, sin² + cos², blends); parse errors with their
// positions; bad input naming the field; replay on the example and the presets; exam problems;
// the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "affine/affine_combination.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"

using cg::AffineCombination;
using Input = AffineCombination::Input;

namespace {

Input make(std::vector<std::string> points, std::vector<std::string> vectors,
           std::vector<std::string> exprs) {
    Input in;
    in.points = std::move(points);
    in.vectors = std::move(vectors);
    in.expressions = std::move(exprs);
    return in;
}

std::vector<AffineCombination::Row> rows(const Input& in) {
    return AffineCombination::classify(in).rows;
}

std::string kind(const std::string& expr, std::vector<std::string> points = {"P", "Q", "R"},
                 std::vector<std::string> vectors = {"v", "w"}) {
    const auto r = rows(make(std::move(points), std::move(vectors), {expr}));
    return cg::affine::kind_name(r[0].kind);
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("affine-combination");
    if (!l) throw std::runtime_error("no lesson for affine-combination");
    return *l;
}

}  // namespace

TEST_CASE("affine-combination: the course's expressions, decided by hand",
          "[affine][affine-combination]") {
    struct Case {
        const char* expr;
        const char* kind;
    };
    const Case cases[] = {
        {"(A + B + C)/3", "point"},
        {"3A − 2B", "point"},
        {"A − B + 2v", "vector"},
        {"A + B", "invalid"},
        {"(1 − s)A + s B", "point"},
        // Products written as the course writes them, without a space: tQ is t times Q.
        {"(1 − s)A + sB", "point"},
        {"(1 − t)A + tB", "point"},
        {"tv", "vector"},
        {"sA − sB", "vector"},
        {"(1 − t)A_0 + tA_1", "point"},
        {"A · B", "invalid"},
        {"(A − B) × v", "vector"},
        {"A + v", "point"},
        {"A − B", "vector"},
        {"2A", "invalid"},
        {"A/2", "invalid"},
        {"A/2 + B/2", "point"},
        {"(A − B) · v", "scalar"},
        {"(A − B) · (C − B)", "scalar"},
        {"A × v", "invalid"},
        {"A B", "invalid"},
        {"A * B", "invalid"},
        {"1/A", "invalid"},
        {"v/(A − B)", "invalid"},
        {"2v − 3w", "vector"},
        {"v × w", "vector"},
        {"v · w", "scalar"},
        {"A^2", "invalid"},
        {"sin(A)", "invalid"},
        {"A + 1", "invalid"},
        {"v + 1", "invalid"},
        {"3", "scalar"},
        {"t", "scalar"},
        {"sin(t)^2 + cos(t)^2", "scalar"},
        {"sin(t)^2 A + cos(t)^2 B", "point"},
        {"sin(t) A + cos(t) B", "invalid"},
        {"t A + t B", "invalid"},
        {"A + t(B − A)", "point"},
        {"(1 − t)A + t B + v", "point"},
        {"sum_{i=0}^{3} B(3,i,t) P_i", "point"},
        {"Σ_{i=0}^{3} B_i^3(t) P_i", "point"},
        {"sum_{i=0}^{3} B(3,i,t) P_i − P_0", "vector"},
        {"sum_{i=1}^{3} B(3,i,t) P_i", "invalid"},
        {"(1 − t)^2 P_0 + 2t(1 − t) P_1 + t^2 P_2", "point"},
        {"2((A + B)/2) − B", "point"},
        {"(A + B)/2 − A", "vector"},
        {"0 A", "vector"},
        {"A − A", "vector"},
        {"(v · w) A", "invalid"},
        {"((A − B) · v) (A − B)", "vector"},
        {"A/(1 − 1)", "invalid"},
        {"dot(A − B, v)", "scalar"},
        {"(A − B) cross v", "vector"},
        {"A dot B", "invalid"},
        {"sum_{i=0}^{2} P_i / 3", "point"},
        {"sum_{i=0}^{2} (P_{i+1} − P_i)", "vector"},
        {"B(A − C)", "invalid"},
        {"B (3, 1, t)", "scalar"},
        {"Σ_{i=0}^{3} B_i^3(s) A_i", "point"},
    };
    for (const auto& c : cases) {
        CAPTURE(c.expr);
        CHECK(kind(c.expr, {"A", "B", "C", "P"}, {"v", "w"}) == c.kind);
    }
    // The numbers a student checks.
    const auto r = rows(make({"A", "B", "C"}, {"v"},
                             {"(A + B + C)/3", "3A − 2B", "A + B", "(1 − s)A + s B", "A · B"}));
    CHECK(r[0].sum == 1);
    CHECK(r[0].sum_constant);
    REQUIRE(r[0].coefficients.size() == 3);
    CHECK(r[0].coefficients[0].value == Approx(1.0 / 3));
    CHECK(r[1].sum == 1);
    CHECK(r[1].coefficients[1].value == -2);
    CHECK(r[2].sum == 2);
    CHECK_THAT(r[2].reason, Catch::Contains("neither 1"));
    CHECK_FALSE(r[3].sum_constant);
    CHECK(r[3].sum_formula == "(1 − s) + s");
    CHECK_THAT(r[3].reason, Catch::Contains("cancel"));
    CHECK_FALSE(r[4].has_sum);
    CHECK_THAT(r[4].reason, Catch::Contains("A is a point"));
    // Identities named.
    const auto id = rows(
        make({"P"}, {}, {"sum_{i=0}^{5} B(5,i,t) P_i", "sin(a)^2 P_0 + cos(a)^2 P_1", "2t P"}));
    CHECK_THAT(id[0].reason, Catch::Contains("Bernstein"));
    CHECK_THAT(id[1].reason, Catch::Contains("sin² + cos² = 1"));
    CHECK(id[2].depends);
    CHECK(id[2].sum_formula == "2 t");
}

TEST_CASE("affine-combination: Bernstein sums of every degree are points",
          "[affine][affine-combination]") {
    for (int n = 0; n <= 12; ++n) {
        CAPTURE(n);
        const std::string n_text = std::to_string(n);
        CHECK(kind("sum_{i=0}^{" + n_text + "} B(" + n_text + ",i,t) P_i", {"P"}, {}) == "point");
        // Dropping any one term leaves a sum that is 1 only for some t.
        for (int drop = 0; drop <= n && n > 0; ++drop) {
            std::string e;
            for (int i = 0; i <= n; ++i)
                if (i != drop)
                    e += std::string(e.empty() ? "" : " + ") + "B(" + n_text + "," +
                         std::to_string(i) + ",t) P_" + std::to_string(i);
            const auto r = rows(make({"P"}, {}, {e}));
            CHECK(r[0].kind == cg::affine::Kind::Invalid);
            CHECK(r[0].depends);
        }
    }
}

// ---- an independent reference: random trees built with their coefficients -------------------
namespace {

using LD = long double;

struct Ref {
    std::string text;
    int prec = 9;         // 1 sum, 2 product, 9 atom
    bool scalar = false;  // a number
    bool bad = false;     // an operation points do not have
    LD value = 0;         // the number, when scalar
    LD a[3] = {0, 0, 0};  // coefficients of P, Q, R
    LD b = 0;             // coefficient of v
    LD sum() const { return a[0] + a[1] + a[2]; }
    bool vector() const { return !scalar && !bad && std::fabs(double(sum())) < 1e-12; }
};

std::string paren(const Ref& r, int need) {
    return r.prec < need ? "(" + r.text + ")" : r.text;
}

Ref random_ref(cg::Rng& rng, int depth) {
    const long long pick = rng.integer(0, depth <= 0 ? 1 : 6);
    Ref r;
    if (pick == 0) {  // a number
        const long long n = rng.integer(-4, 4);
        r.scalar = true;
        r.value = LD(n);
        r.text = n < 0 ? "(" + std::to_string(n) + ")" : std::to_string(n);
        return r;
    }
    if (pick == 1) {  // a name
        const long long k = rng.integer(0, 3);
        r.text = k == 3 ? "v" : std::string(1, "PQR"[k]);
        if (k == 3)
            r.b = 1;
        else
            r.a[k] = 1;
        return r;
    }
    const Ref x = random_ref(rng, depth - 1);
    const Ref y = random_ref(rng, depth - 1);
    if (x.bad || y.bad) {
        r = x.bad ? x : y;
        r.text = paren(x, 9) + " + " + paren(y, 9);
        r.bad = true;
        return r;
    }
    switch (pick) {
        case 2:
        case 3: {  // + or −
            const bool minus = pick == 3;
            r.text = x.text + (minus ? " − " : " + ") + paren(y, 2);
            r.prec = 1;
            if (x.scalar != y.scalar) {
                r.bad = true;
                return r;
            }
            r.scalar = x.scalar;
            const LD s = minus ? -1 : 1;
            r.value = x.value + s * y.value;
            for (int i = 0; i < 3; ++i) r.a[i] = x.a[i] + s * y.a[i];
            r.b = x.b + s * y.b;
            return r;
        }
        case 4:
        case 5: {  // a product
            r.text = paren(x, 2) + " * " + paren(y, 9);
            r.prec = 2;
            if (!x.scalar && !y.scalar) {
                r.bad = true;
                return r;
            }
            const Ref& c = x.scalar ? x : y;
            const Ref& l = x.scalar ? y : x;
            r.scalar = l.scalar;
            r.value = c.value * l.value;
            for (int i = 0; i < 3; ++i) r.a[i] = c.value * l.a[i];
            r.b = c.value * l.b;
            return r;
        }
        case 6: {  // a quotient by a nonzero whole number
            const long long d = rng.integer(1, 5) * (rng.chance(0.5) ? 1 : -1);
            r = x;
            r.text =
                paren(x, 2) + "/" + (d < 0 ? "(" + std::to_string(d) + ")" : std::to_string(d));
            r.prec = 2;
            r.value = x.value / LD(d);
            for (int i = 0; i < 3; ++i) r.a[i] = x.a[i] / LD(d);
            r.b = x.b / LD(d);
            return r;
        }
        default:
            break;
    }
    return r;
}

std::string expected_kind(const Ref& r) {
    if (r.bad) return "invalid";
    if (r.scalar) return "scalar";
    const double sum = double(r.sum());
    if (std::fabs(sum - 1) < 1e-12) return "point";
    if (std::fabs(sum) < 1e-12) return "vector";
    return "invalid";
}

}  // namespace

TEST_CASE("affine-combination: 6,000 random expressions against an independent evaluator",
          "[affine][affine-combination]") {
    cg::Rng rng(20261204);
    int seen[4] = {0, 0, 0, 0};
    for (int n = 0; n < 6000; ++n) {
        const Ref x = random_ref(rng, 4);
        std::string text = x.text;
        std::string expected = expected_kind(x);
        if (rng.chance(0.15)) {  // a dot product of it with another: a number when both are vectors
            const Ref y = random_ref(rng, 2);
            text = "(" + x.text + ") · (" + y.text + ")";
            const bool both = x.vector() && y.vector();
            expected = (x.bad || y.bad || !both) ? "invalid" : "scalar";
        }
        CAPTURE(n, text);
        const auto r = rows(make({"P", "Q", "R"}, {"v"}, {text}));
        REQUIRE(r.size() == 1);
        CHECK(cg::affine::kind_name(r[0].kind) == expected);
        if (expected == "point" || expected == "vector" ||
            (r[0].has_sum && !x.bad && text == x.text)) {
            REQUIRE(r[0].has_sum);
            REQUIRE(r[0].sum_constant);
            CHECK(r[0].sum == Approx(double(x.sum())).margin(1e-12));
            for (const auto& t : r[0].coefficients) {
                const long double want = t.name == "v" ? x.b
                                                       : x.a[t.name[0] == 'P'   ? 0
                                                             : t.name[0] == 'Q' ? 1
                                                                                : 2];
                CHECK(t.value == Approx(double(want)).margin(1e-12));
            }
        }
        seen[static_cast<int>(r[0].kind)]++;
    }
    // Every kind comes up often enough for the comparison to mean something.
    for (int k = 0; k < 4; ++k) {
        CAPTURE(k);
        CHECK(seen[k] > 200);
    }
}

TEST_CASE("affine-combination: integer combinations of three points, every sum from -9 to 9",
          "[affine][affine-combination]") {
    for (int a = -3; a <= 3; ++a)
        for (int b = -3; b <= 3; ++b)
            for (int c = -3; c <= 3; ++c) {
                const std::string e = std::to_string(a) + " P + " + std::to_string(b) + " Q + " +
                                      std::to_string(c) + " R";
                CAPTURE(e);
                const auto r = rows(make({"P", "Q", "R"}, {}, {e}));
                const int sum = a + b + c;
                CHECK(r[0].sum == sum);
                CHECK(cg::affine::kind_name(r[0].kind) == std::string(sum == 1   ? "point"
                                                                      : sum == 0 ? "vector"
                                                                                 : "invalid"));
            }
}

TEST_CASE("affine-combination: parse errors give the character position",
          "[affine][affine-combination]") {
    auto error = [](const std::string& expr) {
        try {
            AffineCombination::start(make({"P", "Q"}, {"v"}, {"P", expr}));
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(error("(P + Q") == "expressions[1]: at character 7: expected ')'");
    CHECK(error("P + ") == "expressions[1]: at character 5: expected a number, a name or '('");
    CHECK(error("P $ Q") == "expressions[1]: at character 3: unexpected character");
    CHECK(error("") == "expressions[1]: at character 1: the expression is empty");
    CHECK(error("P + Q)") ==
          "expressions[1]: at character 6: expected an operator or the end of the expression");
    CHECK(error("sum_{i=0}^{x} P_i") ==
          "expressions[1]: at character 12: expected a whole number for the sum's upper bound");
    CHECK(error("sum_{i=3}^{1} P_i") ==
          "expressions[1]: at character 13: the upper bound is below the lower bound: the sum has "
          "no terms");
    CHECK(error("sum_{i=0}^{99999} sum_{j=0}^{99} P_i") ==
          "expressions[1]: at character 17: the sums expand to more than 4096 terms");
    CHECK(error("B(3, 1") == "expressions[1]: at character 7: expected ',' in B(n, i, t)");
    CHECK(error("− − (P") == "expressions[1]: at character 7: expected ')'");
    CHECK(
        error(std::string(70, '(') + "P" + std::string(70, ')')).find("nested more than 64 deep") !=
        std::string::npos);
    CHECK(error(std::string(2001, 'P')).find("longer than 2000 characters") != std::string::npos);
    CHECK(error("P_") ==
          "expressions[1]: at character 3: expected a subscript after '_': a whole number, a name "
          "or {…}");
    CHECK(error("sin + P").find("reserved word") != std::string::npos);
    // Two declared names run together are refused, naming the product they would be.
    CHECK(error("PQ") ==
          "expressions[1]: at character 1: \"PQ\" is not declared: it reads as P·Q, a product of "
          "two declared names (write the product with · or a space, or declare PQ)");
    CHECK(error("(1 − t)P + tQ") == "no error");
    // Unicode operators count as one character each.
    CHECK(error("P − Q · · v") ==
          "expressions[1]: at character 9: expected a number, a name or '('");
}

TEST_CASE("affine-combination: bad input names the field", "[affine][affine-combination]") {
    auto error = [](const std::string& text) {
        return cg::test::error_of("affine-combination", text);
    };
    CHECK_THAT(error(R"({"points": ["P"], "expressions": []})"),
               Catch::StartsWith("expressions: must list at least one expression"));
    CHECK_THAT(error(R"({"points": ["P"]})"), Catch::Contains("expressions"));
    CHECK_THAT(error(R"({"expressions": ["P"]})"), Catch::StartsWith("points: missing"));
    CHECK_THAT(error(R"({"points": "P", "expressions": ["P"]})"),
               Catch::StartsWith("points: must be a list of names"));
    CHECK_THAT(error(R"({"points": [1], "expressions": ["P"]})"),
               Catch::StartsWith("points[0]: must be a string"));
    CHECK_THAT(error(R"({"points": ["2P"], "expressions": ["P"]})"),
               Catch::StartsWith("points[0]: \"2P\" is not a name"));
    CHECK_THAT(error(R"({"points": ["P", "P"], "expressions": ["P"]})"),
               Catch::StartsWith("points[1]: \"P\" is already declared in points[0]"));
    CHECK_THAT(error(R"({"points": ["P"], "vectors": ["P"], "expressions": ["P"]})"),
               Catch::StartsWith("vectors[0]: \"P\" is already declared"));
    CHECK_THAT(error(R"({"points": ["sin"], "expressions": ["P"]})"),
               Catch::StartsWith("points[0]: \"sin\" is reserved"));
    CHECK_THAT(error(R"({"points": ["P"], "expressions": [null]})"),
               Catch::StartsWith("expressions[0]: must be a string"));
    CHECK_THAT(error(R"({"points": ["P"], "expressions": ["P"], "colour": 1})"),
               Catch::Contains("colour"));
    CHECK_THAT(error(R"j({"points": ["P"], "scalars": ["t"], "expressions": ["P + s(P − P)"]})j"),
               Catch::StartsWith("expressions[0]: at character 5: \"s\" is not declared"));
    CHECK_NOTHROW(cg::test::result_of(
        "affine-combination",
        cg::json::parse(
            R"({"points": ["P"], "scalars": ["t"], "expressions": ["sum_{i=0}^{2} B(2,i,t) P_i"]})")));
}

TEST_CASE("affine-combination: replay on the example and the presets, run-to-end is classify",
          "[affine][affine-combination]") {
    const cg::Algorithm& a = cg::test::algorithm("affine-combination");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    std::set<std::string> seen;
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, cg::test::kEveryStep);
        const Input in = cg::test::input_of<AffineCombination>("affine-combination", p.input);
        CHECK(cg::run_to_end<AffineCombination>(AffineCombination::start(in)) ==
              AffineCombination::classify(in));
        for (const auto& step : cg::test::run_json("affine-combination", p.input).steps)
            seen.insert(step.event);
    }
    for (const auto& e : AffineCombination::spec().events) {
        CAPTURE(e.id);
        CHECK(seen.count(e.id));
    }
    const cg::json r = cg::test::result_of("affine-combination", a.example());
    CHECK(r["kinds"] ==
          cg::json::parse(
              R"(["point", "point", "vector", "invalid", "point", "point", "invalid", "vector"])"));
    CHECK(r["results"][4]["coefficient_sum"] == "(1 − t) + t");
    CHECK(r["results"][0]["coefficient_sum"] == 1.0);
    CHECK(r["results"][6]["coefficient_sum"].is_null());
    CHECK(r["results"][1]["coefficients"]["Q"] == -2.0);
}

TEST_CASE("affine-combination: exam problems mix every kind", "[affine][affine-combination]") {
    const cg::Algorithm& a = cg::test::algorithm("affine-combination");
    int count[4] = {0, 0, 0, 0};
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        REQUIRE(p.answers == std::vector<std::string>{"kinds"});
        const Input in = cg::test::input_of<AffineCombination>("affine-combination", p.input);
        CHECK(in.expressions.size() == 5);
        for (const auto& r : AffineCombination::classify(in).rows)
            count[static_cast<int>(r.kind)]++;
        CHECK_THAT(p.question, Catch::Contains(in.expressions[0]));
    }
    for (int k = 0; k < 4; ++k) {
        CAPTURE(k);
        CHECK(count[k] > 100);
    }
}

TEST_CASE("affine-combination: the picture — the parse tree coloured by type, the verdicts beside",
          "[affine][affine-combination]") {
    auto s = AffineCombination::start(make({"P", "Q"}, {"v"}, {"(P + Q)/2", "P · Q"}));
    cg::Scene before;
    AffineCombination::draw(s, before);
    CHECK_FALSE(before.has_3d());
    CHECK_FALSE(before.world_grid);  // a tree: no grid, axes or ticks whose numbers mean nothing
    REQUIRE(before.points.size() == 5);  // P, Q, +, 2, /
    AffineCombination::step(s, nullptr);
    cg::Scene pic;
    AffineCombination::draw(s, pic);
    REQUIRE(pic.points.size() == 5);
    CHECK(pic.segments.size() == 4);
    // The root (the division, drawn last and largest) is a point; P + Q is a partial sum.
    CHECK(pic.points.back().label == "/  point");
    CHECK(pic.points.back().style.role == cg::Role::Kept);
    bool partial = false;
    for (const auto& p : pic.points)
        partial = partial || (p.label == "+  Σ = 2" && p.style.role == cg::Role::Active);
    CHECK(partial);
    bool listed = false;
    for (const auto& l : pic.labels) listed = listed || l.text == "1. (P + Q)/2  →  point";
    CHECK(listed);
    AffineCombination::step(s, nullptr);
    cg::Scene end;
    AffineCombination::draw(s, end);
    CHECK(end.points.back().style.role == cg::Role::Discarded);
}

TEST_CASE("affine-combination: the picture writes expressions as a person writes them",
          "[affine][affine-combination]") {
    CHECK(AffineCombination::display("sum_{i=0}^{3} B(3,i,t) P_i") == "Σᵢ₌₀³ Bᵢ³(t) Pᵢ");
    CHECK(AffineCombination::display("(1 − t)^3 P_0 + 3t(1 - t)^2 P_1") ==
          "(1 − t)³ P₀ + 3t(1 − t)² P₁");
    CHECK(AffineCombination::display("sin(t)^2 P + cos(t)^2 Q") == "sin²(t) P + cos²(t) Q");
    CHECK(AffineCombination::display("B_i^3(t) P_{i+1}") == "Bᵢ³(t) Pᵢ₊₁");
    CHECK(AffineCombination::display("P dot Q cross v") == "P · Q × v");
    CHECK(AffineCombination::display("2e-3 A") == "2e−3 A");
    // What Unicode cannot lower stays as typed.
    CHECK(AffineCombination::display("P_Q + A_{2b}") == "P_Q + A_{2b}");
    // The picture uses it: the tree's leaves and the list of verdicts.
    auto s = AffineCombination::start(make({"P"}, {}, {"sum_{i=0}^{3} B(3,i,t) P_i"}));
    AffineCombination::step(s, nullptr);
    cg::Scene pic;
    AffineCombination::draw(s, pic);
    bool root = false, listed = false;
    for (const auto& p : pic.points) root = root || p.label == "Σᵢ₌₀³  point";
    for (const auto& l : pic.labels) listed = listed || l.text == "1. Σᵢ₌₀³ Bᵢ³(t) Pᵢ  →  point";
    CHECK(root);
    CHECK(listed);
}
