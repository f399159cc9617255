// L-systems: the string's lengths against the growth matrix counted independently (symbol
// counts times the production matrix, in long double); the string itself against a direct
// rewrite written apart (a map from symbol to replacement, as a Python dict would be); the end
// position and heading against an independent long-double turtle (heading in radians,
// position summed in long double, its own stack); the Koch curves' closed forms (end (3ⁿ, 0),
// length 4ⁿ or 5ⁿ); bracket balance and depth; 3,000 seeded random rule sets, with erasing
// productions, unknown symbols, odd angles and headings; the state machine against compute;
// degenerate inputs (empty axiom, empty production, n = 0, NaN and infinite angles, huge n
// refused at once); errors naming the field; the steps, the batching, the picture; replay on
// the example and the presets; the exam problems.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <map>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "modelling/l_system.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::LSystem;
using Input = LSystem::Input;
using LD = long double;

namespace {

Input make(std::string axiom, std::vector<LSystem::Rule> rules, int n, double angle,
           double heading = 90, double step = 1, std::string draw = "F") {
    Input in;
    in.axiom = std::move(axiom);
    in.rules = std::move(rules);
    in.generations = n;
    in.angle = angle;
    in.heading = heading;
    in.step = step;
    in.draw = std::move(draw);
    return in;
}

// ---- the references ----

std::map<char, std::string> rule_map(const Input& in) {
    std::map<char, std::string> m;
    for (const auto& r : in.rules) m[r.symbol] = r.replacement;
    return m;
}

// "".join(rules.get(c, c) for c in s), n times.
std::vector<std::string> direct_strings(const Input& in) {
    const auto m = rule_map(in);
    std::vector<std::string> out{in.axiom};
    for (int g = 0; g < in.generations; ++g) {
        std::string next;
        for (char c : out.back()) {
            auto it = m.find(c);
            next += it == m.end() ? std::string(1, c) : it->second;
        }
        out.push_back(next);
    }
    return out;
}

// The growth matrix: M[s][t] = occurrences of t in the production of s (the identity row for a
// symbol without one); the count vector after g generations is v₀ Mᵍ, the length its sum.
std::vector<LD> growth_lengths(const Input& in) {
    std::map<char, std::map<char, LD>> M;
    std::map<char, LD> v;
    const auto m = rule_map(in);
    std::string alphabet = in.axiom;
    for (const auto& r : in.rules) alphabet += std::string(1, r.symbol) + r.replacement;
    for (char s : alphabet) {
        auto it = m.find(s);
        M[s].clear();
        if (it == m.end())
            M[s][s] = 1;
        else
            for (char t : it->second) M[s][t] += 1;
    }
    for (char c : in.axiom) v[c] += 1;
    std::vector<LD> lengths;
    for (int g = 0; g <= in.generations; ++g) {
        LD total = 0;
        for (auto& [c, k] : v) total += k;
        lengths.push_back(total);
        std::map<char, LD> next;
        for (auto& [s, k] : v)
            for (auto& [t, o] : M[s]) next[t] += k * o;
        v = next;
    }
    return lengths;
}

struct RefTurtle {
    LD x = 0, y = 0;
    long long k = 0;  // net left turns
};

struct RefEnd {
    LD x = 0, y = 0, heading = 0;  // heading in degrees, [0, 360)
    long long segments = 0, moves = 0, ignored = 0, pushes = 0;
    int depth = 0, max_depth = 0;
    bool balanced = true;
};

RefEnd ref_turtle(const Input& in, const std::string& w) {
    const LD pi = 3.14159265358979323846264338327950288L;
    RefTurtle t;
    std::vector<RefTurtle> stack;
    RefEnd e;
    for (char c : w) {
        if (c == '+') {
            ++t.k;
        } else if (c == '-') {
            --t.k;
        } else if (c == '[') {
            stack.push_back(t);
            ++e.pushes;
            e.max_depth = std::max(e.max_depth, int(stack.size()));
        } else if (c == ']') {
            if (stack.empty()) {
                e.balanced = false;
                continue;
            }
            t = stack.back();
            stack.pop_back();
        } else if (in.draw.find(c) != std::string::npos || c == 'f') {
            const LD h = (LD(in.heading) + LD(t.k) * LD(in.angle)) * pi / 180;
            t.x += LD(in.step) * std::cos(h);
            t.y += LD(in.step) * std::sin(h);
            ++(c == 'f' ? e.moves : e.segments);
        } else {
            ++e.ignored;
        }
    }
    e.x = t.x;
    e.y = t.y;
    e.heading = std::fmod(LD(in.heading) + LD(t.k) * LD(in.angle), 360.0L);
    if (e.heading < 0) e.heading += 360;
    e.depth = int(stack.size());
    e.balanced = e.balanced && stack.empty();
    return e;
}

// The heading difference on the circle, in degrees.
double heading_gap(double a, LD b) {
    LD d = std::fmod(std::fabs(LD(a) - b), 360.0L);
    return double(std::min(d, 360 - d));
}

void check_against_references(const Input& in, const LSystem::Result& r) {
    const auto strings = direct_strings(in);
    const auto lengths = growth_lengths(in);
    REQUIRE(r.lengths.size() == lengths.size());
    for (std::size_t g = 0; g < lengths.size(); ++g) {
        CHECK(LD(r.lengths[g]) == lengths[g]);
        CHECK(r.lengths[g] == (long long)strings[g].size());
    }
    CHECK(r.word == strings.back());
    const RefEnd e = ref_turtle(in, strings.back());
    CHECK(e.balanced);
    CHECK(r.tally.segments == e.segments);
    CHECK(r.tally.moves == e.moves);
    CHECK(r.tally.ignored == e.ignored);
    CHECK(r.tally.pushes == e.pushes);
    CHECK(r.tally.max_depth == e.max_depth);
    // The position: n steps of length s, each with rounding ~1e-16 relative.
    const double tol = 1e-12 * in.step * double(std::max<long long>(1, e.segments + e.moves));
    CHECK(std::fabs(double(LD(r.end.x) - e.x)) <= tol);
    CHECK(std::fabs(double(LD(r.end.y) - e.y)) <= tol);
    CHECK(heading_gap(r.end_heading, e.heading) <= 1e-9);
    CHECK(r.end_heading >= 0);
    CHECK(r.end_heading < 360);
    CHECK(r.path_length == Approx(double(e.segments) * in.step));
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("l-system");
    if (!l) throw std::runtime_error("no lesson for l-system");
    return *l;
}

std::string random_word(cg::Rng& rng, int max_len, bool brackets) {
    static const std::string alphabet = "FFFf+-XYA";
    std::string w;
    const int n = int(rng.integer(0, max_len));
    for (int i = 0; i < n; ++i) {
        if (brackets && rng.chance(0.12)) {
            // A balanced branch: [ … ] around a short word.
            w += "[" + random_word(rng, 3, false) + "]";
            continue;
        }
        w += alphabet[std::size_t(rng.integer(0, int(alphabet.size()) - 1))];
    }
    return w;
}

}  // namespace

TEST_CASE("l-system: the classic systems by hand, symbol for symbol", "[modelling][l-system]") {
    SECTION("Lindenmayer's algae: lengths are Fibonacci numbers") {
        const auto r = LSystem::compute(make("A", {{'A', "AB"}, {'B', "A"}}, 5, 90));
        CHECK(r.lengths == std::vector<long long>{1, 2, 3, 5, 8, 13});
        CHECK(r.word == "ABAABABAABAAB");
        CHECK(r.tally.ignored == 13);  // the turtle has nothing to draw
        CHECK(r.end == glm::dvec2(0, 0));
    }
    SECTION("the Koch curve, two generations") {
        const auto r = LSystem::compute(make("F", {{'F', "F+F--F+F"}}, 2, 60, 0));
        CHECK(r.word == "F+F--F+F+F+F--F+F--F+F--F+F+F+F--F+F");
        CHECK(r.lengths == std::vector<long long>{1, 8, 36});
        CHECK(r.end.x == Approx(9).margin(1e-12));
        CHECK(r.end.y == Approx(0).margin(1e-12));
        CHECK(r.end_heading == 0);
        CHECK(r.path_length == 16);
    }
    SECTION("the fractal plant, one generation: pushes and pops return to the saved state") {
        const auto in = make("X", {{'X', "F+[[X]-X]-F[-FX]+X"}, {'F', "FF"}}, 1, 25);
        const auto r = LSystem::compute(in);
        CHECK(r.word == "F+[[X]-X]-F[-FX]+X");
        CHECK(r.tally.max_depth == 2);
        CHECK(r.tally.pushes == 3);
        CHECK(r.tally.segments == 3);
        // F up to (0, 1); + then the branches return; − − … net turns: + − + = +1, so the final
        // heading is 90 + 25 − 25 + 25 = 115 after "F+[...]-F[...]+": F at 90, then F at 90.
        CHECK(r.end.x == Approx(0).margin(1e-12));
        CHECK(r.end.y == Approx(2));
        CHECK(r.end_heading == Approx(115));
    }
    SECTION("the dragon curve: right angles are exact") {
        const auto in = make("FX", {{'X', "X+YF+"}, {'Y', "-FX-Y"}}, 10, 90, 0);
        const auto r = LSystem::compute(in);
        CHECK(r.tally.segments == 1024);
        CHECK(r.end.x == std::round(r.end.x));  // exact: cos and sin of multiples of 90°
        CHECK(r.end.y == std::round(r.end.y));
        check_against_references(in, r);
    }
}

TEST_CASE("l-system: Koch curves against their closed forms", "[modelling][l-system]") {
    for (int n = 0; n <= 6; ++n) {
        CAPTURE(n);
        const double step = n % 2 ? 0.5 : 2.0;
        // The Koch curve: 4ⁿ segments of the step, from (0, 0) to (3ⁿ·step, 0).
        const auto koch = LSystem::compute(make("F", {{'F', "F+F--F+F"}}, n, 60, 0, step));
        CHECK(koch.tally.segments == (long long)std::pow(4, n));
        CHECK(koch.path_length == Approx(std::pow(4, n) * step));
        CHECK(koch.end.x == Approx(std::pow(3, n) * step).epsilon(1e-12));
        CHECK(std::fabs(koch.end.y) <= 1e-9 * std::pow(3, n));
        CHECK(koch.end_heading == 0);
        CHECK(koch.lengths.back() ==
              ((long long)std::pow(4, n) * 7 - 4) / 3);  // 4ⁿ F, the rest turns
        // The quadratic Koch curve: 5ⁿ segments, also from (0, 0) to (3ⁿ·step, 0), exactly.
        const auto quad = LSystem::compute(make("F", {{'F', "F+F-F-F+F"}}, n, 90, 0, step));
        CHECK(quad.tally.segments == (long long)std::pow(5, n));
        CHECK(quad.end == glm::dvec2(std::pow(3, n) * step, 0));
        // The snowflake: three Koch curves, the turtle back where it started, heading along the
        // third side (two right turns of 120° between the sides: −240° = 120°).
        const auto flake = LSystem::compute(make("F--F--F", {{'F', "F+F--F+F"}}, n, 60, 0));
        CHECK(std::fabs(flake.end.x) <= 1e-9 * std::pow(3, n));
        CHECK(std::fabs(flake.end.y) <= 1e-9 * std::pow(3, n));
        CHECK(flake.end_heading == 120);
    }
}

TEST_CASE("l-system: 3,000 random rule sets against the direct count and the long-double turtle",
          "[modelling][l-system]") {
    cg::Rng rng(2026);
    int erasing = 0, bracketed = 0, empty = 0, zero = 0;
    for (int k = 0; k < 3000; ++k) {
        CAPTURE(k);
        Input in;
        in.axiom = random_word(rng, 4, true);
        static const std::string heads = "FXYAf+";
        for (char c : heads)
            if (rng.chance(0.45)) {
                std::string rep = rng.chance(0.08) ? "" : random_word(rng, 6, true);
                erasing += rep.empty();
                in.rules.push_back({c, rep});
            }
        in.generations = int(rng.integer(0, 5));
        in.angle = rng.chance(0.3) ? double(rng.integer(-4, 4) * 30) : rng.uniform(-360, 360);
        in.heading = rng.chance(0.5) ? 90 : rng.uniform(-360, 360);
        in.step = rng.chance(0.5) ? 1 : rng.uniform(1e-3, 10);
        in.draw = rng.chance(0.8) ? "F" : "FA";
        empty += in.axiom.empty();
        zero += in.generations == 0;
        // Keep the run small enough for 3,000 of them.
        const auto lengths = growth_lengths(in);
        if (lengths.back() > 20000) in.generations = 1;
        bracketed += in.axiom.find('[') != std::string::npos;
        INFO(in.axiom << " n=" << in.generations << " angle=" << in.angle);
        const auto r = LSystem::compute(in);
        check_against_references(in, r);
        // The growth counts the limit is checked with, before any rewriting.
        const auto counted = LSystem::growth(in);
        REQUIRE(counted.size() == r.lengths.size());
        CHECK(counted == r.lengths);
        if (k % 10 == 0) CHECK(cg::run_to_end<LSystem>(LSystem::start(in)) == r);
    }
    CHECK(erasing > 50);
    CHECK(bracketed > 300);
    CHECK(empty > 100);
    CHECK(zero > 300);
}

TEST_CASE("l-system: the state machine gives what compute gives, through the registry too",
          "[modelling][l-system]") {
    cg::Rng rng(5);
    for (int k = 0; k < 200; ++k) {
        Input in = make(random_word(rng, 3, true),
                        {{'F', random_word(rng, 5, true)}, {'X', random_word(rng, 5, true)}},
                        int(rng.integer(0, 4)), 25);
        CAPTURE(in.axiom);
        const auto traced = cg::test::run_traced<LSystem>(in);
        CHECK(traced.result == LSystem::compute(in));
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const Input in = cg::test::input_of<LSystem>("l-system", p.input);
        const auto j = cg::test::result_of("l-system", p.input);
        const auto r = LSystem::compute(in);
        CHECK(j["lengths"] == cg::json(r.lengths));
        CHECK(j["string"] == r.word);
        check_against_references(in, r);
    }
}

TEST_CASE(
    "l-system: the steps — one generation each, the first symbols one at a time, then batches",
    "[modelling][l-system]") {
    SECTION("Koch, two generations: 2 rewrites, 32 single symbols, batches, a summary") {
        const auto t = cg::test::run_traced<LSystem>(make("F", {{'F', "F+F--F+F"}}, 2, 60, 0));
        const auto ev = cg::test::events(t);
        REQUIRE(ev.size() == 2 + 32 + 4 + 1);  // 36 symbols: 32 stepped, 4 batches of 1
        CHECK(ev[0] == "rewrite");
        CHECK(ev[1] == "rewrite");
        CHECK(ev[2] == "draw");
        CHECK(ev[3] == "turn");
        CHECK(ev.back() == "summary");
        CHECK(t.steps[1].narration.find("F → F+F--F+F") != std::string::npos);
        CHECK(std::get<long long>(t.steps[1].vars[1].value) == 36);
    }
    SECTION("a long string: at most kStepped + kBatches turtle steps, and the narration says so") {
        const auto in = make("X", {{'X', "F+[[X]-X]-F[-FX]+X"}, {'F', "FF"}}, 5, 25);
        const auto t = cg::test::run_traced<LSystem>(in);
        int batches = 0;
        for (const auto& s : t.steps) batches += s.event == "batch";
        CHECK(batches >= 30);
        CHECK(batches <= LSystem::kBatches);
        CHECK(t.steps.size() == std::size_t(5 + LSystem::kStepped + batches + 1));
        const auto& b = t.steps[5 + LSystem::kStepped];
        CHECK(b.event == "batch");
        CHECK(b.narration.find("one at a time") != std::string::npos);
        CHECK(t.steps[4].narration.find("6,263 symbols") != std::string::npos);
    }
    SECTION("push and pop report the stack; the pop restores the position") {
        const auto t = cg::test::run_traced<LSystem>(make("F[+F]F", {}, 0, 90));
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"draw", "push", "turn", "draw", "pop", "draw", "summary"});
        auto var = [](const cg::StepInfo& s, const std::string& name) {
            for (const auto& v : s.vars)
                if (v.name == name) return v.value;
            throw std::runtime_error("no variable " + name);
        };
        CHECK(std::get<long long>(var(t.steps[1], "depth")) == 1);
        CHECK(std::get<double>(var(t.steps[3], "x")) == -1);  // the branch goes left
        CHECK(std::get<double>(var(t.steps[4], "x")) == 0);
        CHECK(std::get<double>(var(t.steps[4], "y")) == 1);
        CHECK(std::get<double>(var(t.steps[2], "turn")) == 90);
        CHECK(t.result.end == glm::dvec2(0, 2));
    }
    SECTION("an unknown symbol is skipped, f moves without drawing") {
        const auto t = cg::test::run_traced<LSystem>(make("XfF", {}, 0, 90, 0));
        CHECK(cg::test::events(t) == std::vector<std::string>{"skip", "move", "draw", "summary"});
        CHECK(t.result.end == glm::dvec2(2, 0));
        CHECK(t.result.tally.segments == 1);
        CHECK(t.result.tally.moves == 1);
    }
}

TEST_CASE("l-system: degenerate inputs", "[modelling][l-system]") {
    SECTION("an empty axiom: nothing to rewrite or draw, one summary step") {
        const auto t = cg::test::run_traced<LSystem>(make("", {{'F', "FF"}}, 3, 90));
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"rewrite", "rewrite", "rewrite", "summary"});
        CHECK(t.result.lengths == std::vector<long long>{0, 0, 0, 0});
        CHECK(t.result.end == glm::dvec2(0, 0));
    }
    SECTION("an empty production erases its symbol; the string can vanish") {
        const auto r = LSystem::compute(make("FXF", {{'F', ""}}, 1, 90));
        CHECK(r.word == "X");
        CHECK(r.lengths == std::vector<long long>{3, 1});
        const auto gone = cg::test::run_traced<LSystem>(make("FF", {{'F', ""}}, 2, 90));
        CHECK(cg::test::events(gone) == std::vector<std::string>{"rewrite", "rewrite", "summary"});
        CHECK(gone.result.word.empty());
    }
    SECTION("n = 0: the axiom is read as it is") {
        const auto r = LSystem::compute(make("F+F", {{'F', "FFF"}}, 0, 90, 0));
        CHECK(r.lengths == std::vector<long long>{3});
        CHECK(r.end == glm::dvec2(1, 1));
    }
    SECTION("angle and heading NaN or infinite are refused by name") {
        for (double bad : {std::nan(""), double(INFINITY), -double(INFINITY), 361.0}) {
            CHECK_THROWS_WITH(LSystem::start(make("F", {}, 1, bad)),
                              Catch::StartsWith("angle: must be a finite angle in degrees"));
            CHECK_THROWS_WITH(LSystem::start(make("F", {}, 1, 90, bad)),
                              Catch::StartsWith("heading: must be a finite angle"));
        }
        CHECK_THROWS_WITH(LSystem::start(make("F", {}, 1, 90, 90, std::nan(""))),
                          Catch::StartsWith("step: must be a length above 0"));
        CHECK_THROWS_WITH(LSystem::start(make("F", {}, 1, 90, 90, 0)),
                          Catch::StartsWith("step: must be a length above 0"));
    }
    SECTION("a huge request is refused at once, from the growth counts") {
        const auto t0 = std::chrono::steady_clock::now();
        // F → FF for 40 generations: 2^40 symbols.
        CHECK_THROWS_WITH(LSystem::start(make("F", {{'F', "FF"}}, 40, 90)),
                          "generations: the string would have 262,144 symbols after generation "
                          "18; at most 250,000 are rewritten and drawn (at most 17 generations "
                          "for this system)");
        // Through JSON, 60 generations are out of range before any counting.
        CHECK(cg::test::error_of("l-system", R"({"axiom": "F", "rules": {"F": "FF"},
                                 "generations": 60, "angle": 90})") ==
              "generations: must be 0 to 40 (got 60)");
        // A production of 1,000 symbols, squared: refused after one generation.
        CHECK_THROWS_WITH(
            LSystem::start(make(std::string(1000, 'F'), {{'F', std::string(1000, 'F')}}, 2, 90)),
            Catch::StartsWith("generations: the string would have 1,000,000 symbols after "
                              "generation 1"));
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        CHECK(ms < 200);
        // The limit exactly: symbols without a production count too.
        const std::string xs(LSystem::kMaxLength - 2, 'X');
        CHECK_NOTHROW(LSystem::start(make(xs + "F", {{'F', "FF"}}, 1, 90)));
        CHECK_THROWS_WITH(LSystem::start(make(xs + "XF", {{'F', "FF"}}, 1, 90)),
                          Catch::StartsWith("generations: the string would have 250,001 symbols "
                                            "after generation 1"));
        CHECK_THROWS_WITH(LSystem::start(make(xs + "XXX", {}, 0, 90)),
                          "axiom: has 250,001 symbols; at most 250,000 are rewritten and drawn");
        // An erasing production keeps a long run legal: X → X with F erased.
        CHECK_NOTHROW(LSystem::start(make("XF", {{'F', ""}}, 40, 90)));
    }
}

TEST_CASE("l-system: bad input names the field and the reason", "[modelling][l-system]") {
    auto err = [](const std::string& text) { return cg::test::error_of("l-system", text); };
    CHECK(err(R"({"axiom": "F[", "generations": 1, "angle": 90})") ==
          "axiom: unbalanced brackets: 1 [ is never closed");
    CHECK(err(R"({"axiom": "F]F", "generations": 1, "angle": 90})") ==
          "axiom: unbalanced brackets: the ] at symbol 1 closes no [");
    CHECK(err(R"({"axiom": "F", "rules": {"F": "F]["}, "generations": 1, "angle": 90})") ==
          "rules.F: unbalanced brackets: the ] at symbol 1 closes no [");
    CHECK(err(R"({"axiom": "F", "rules": {"FF": "F"}, "generations": 1, "angle": 90})") ==
          "rules.FF: a production rewrites one symbol; \"FF\" is 2 symbols");
    CHECK(err(R"({"axiom": "F", "rules": {"[": "F"}, "generations": 1, "angle": 90})")
              .rfind("rules.[: brackets have no productions", 0) == 0);
    CHECK(err(R"({"axiom": "F", "rules": {"F": 3}, "generations": 1, "angle": 90})")
              .rfind("rules.F: must be a string", 0) == 0);
    CHECK(err(R"({"axiom": "F", "rules": ["F"], "generations": 1, "angle": 90})")
              .rfind("rules: must be an object", 0) == 0);
    CHECK(err(R"({"axiom": "Fé", "generations": 1, "angle": 90})")
              .rfind("axiom: symbol 1 is not a printable ASCII character", 0) == 0);
    CHECK(err(R"({"axiom": "F", "generations": 1, "angle": 90, "draw": "F+"})")
              .rfind("draw: '+' already means something", 0) == 0);
    CHECK(err(R"({"axiom": "F", "generations": 1})").rfind("angle: is missing", 0) == 0);
    CHECK(err(R"({"axiom": "F", "generations": 1, "angle": "90"})")
              .rfind("angle: must be a number", 0) == 0);
    CHECK(err(R"({"axiom": "F", "generations": 1.5, "angle": 90})")
              .rfind("generations: must be", 0) == 0);
    CHECK(err(R"({"axiom": "F", "generations": -1, "angle": 90})") ==
          "generations: must be 0 to 40 (got -1)");
    CHECK(err(R"({"axiom": "F", "generations": 1, "angle": 90, "angel": 3})")
              .rfind("angel: is not a known field", 0) == 0);
    // The Unicode minus reads as '-', spaces are dropped; a key may be a Unicode minus too.
    const auto j = cg::test::result_of(
        "l-system",
        std::string(R"({"axiom": "F − F", "rules": {"F": "F+F"}, "generations": 1, "angle": 90})"));
    CHECK(j["string"] == "F+F-F+F");
    CHECK(err(R"({"axiom": "F", "rules": {"−": "+"}, "generations": 1, "angle": 90})") ==
          "(accepted)");
}

TEST_CASE("l-system: replay on the example and the presets", "[modelling][l-system]") {
    const auto& a = cg::test::algorithm("l-system");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
    CHECK(lesson().presets.size() >= 4);
}

TEST_CASE(
    "l-system: exam problems — the string after 2 generations, answered by the direct "
    "rewrite",
    "[modelling][l-system][exam]") {
    const auto& a = cg::test::algorithm("l-system");
    int erasing = 0, branching = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = cg::test::input_of<LSystem>("l-system", p.input);
        CAPTURE(seed, p.question);
        CHECK(in.generations == 2);
        const auto strings = direct_strings(in);
        CHECK(p.expected["string"] == strings[2]);
        CHECK(strings[2].size() < 60);
        CHECK(p.expected["lengths"] ==
              cg::json(std::vector<long long>{(long long)strings[0].size(),
                                              (long long)strings[1].size(),
                                              (long long)strings[2].size()}));
        CHECK(p.question.find("ω = " + in.axiom) != std::string::npos);
        for (const auto& r : in.rules) erasing += r.replacement.empty();
        branching += strings[2].find('[') != std::string::npos;
        CHECK(p.answers == std::vector<std::string>{"string", "lengths"});
    }
    CHECK(erasing > 10);
    CHECK(branching > 60);
}

TEST_CASE("l-system: the picture — the growing string in grey, then the turtle's lines",
          "[modelling][l-system]") {
    const auto in = make("F[+F]F", {}, 0, 90);
    auto s = LSystem::start(in);
    {
        cg::Scene scene;
        LSystem::draw(s, scene);              // before the walk: the whole string in grey
        REQUIRE(scene.polygons.size() == 3);  // the stem broken at [ and ], and the branch
        CHECK(scene.polygons[0].style.role == cg::Role::Subject);
        CHECK(scene.labels.size() == 1);
    }
    LSystem::step(s, nullptr);  // F
    LSystem::step(s, nullptr);  // [
    LSystem::step(s, nullptr);  // +
    LSystem::step(s, nullptr);  // F: the branch
    cg::Scene scene;
    LSystem::draw(s, scene);
    int done = 0, recent = 0, saved = 0;
    for (const auto& p : scene.polygons) {
        done += p.style.role == cg::Role::Kept;
        recent += p.style.role == cg::Role::Active;
    }
    for (const auto& p : scene.points) saved += p.style.role == cg::Role::Window;
    CHECK(done == 1);
    CHECK(recent == 1);
    CHECK(saved == 1);  // the state saved at [, at (0, 1)
    bool turtle = false;
    for (const auto& p : scene.points)
        turtle = turtle || (p.label == "turtle" && p.p == glm::dvec2(-1, 1));
    CHECK(turtle);
    // Everything finite on a big preset.
    const auto big = make("X", {{'X', "F+[[X]-X]-F[-FX]+X"}, {'F', "FF"}}, 5, 25);
    auto b = LSystem::start(big);
    while (!LSystem::done(b)) LSystem::step(b, nullptr);
    cg::Scene all;
    LSystem::draw(b, all);
    std::size_t points = 0;
    for (const auto& p : all.polygons)
        for (const auto& q : p.points) {
            CHECK(std::isfinite(q.x));
            CHECK(std::isfinite(q.y));
            ++points;
        }
    CHECK(points > 2000);
}
