// The viewer's LaTeX → Unicode converter, on the notation the lessons and steps use.
#include <catch2/catch.hpp>

#include <cctype>
#include <fstream>
#include <functional>
#include <map>

#include "io/lesson.hpp"
#include "io/registry.hpp"
#include "viewer/math_text.hpp"

using cg::viewer::math_to_unicode;
using cg::viewer::text_to_unicode;

TEST_CASE("math text: LaTeX becomes readable Unicode", "[gui][math]") {
    auto [latex, unicode] = GENERATE(table<std::string, std::string>({
        // fractions: parentheses only around compound parts
        {R"(\frac{a}{b})", "a/b"},
        {R"(\frac{q_1}{p_1})", "q₁/p₁"},
        {R"(\frac{-1}{-4})", "−1/−4"},
        {R"(\frac{a + b}{2})", "(a + b)/2"},
        {R"(\frac{-8}{-8 - 12})", "−8/(−8 − 12)"},
        {R"(\tfrac12)", "1/2"},
        {R"(\frac{\mathrm{side}(S)}{\mathrm{side}(S) - \mathrm{side}(P)})",
         "side(S)/(side(S) − side(P))"},
        // subscripts: digits and index letters as Unicode, words with an underscore
        {"x_0", "x₀"},
        {"P_{i+1}", "Pᵢ₊₁"},
        {"p_k", "pₖ"},
        {"x_{min}", "x_min"},
        {"t_{enter}", "t_enter"},
        {"L_v", "L_v"},
        {"x_{v,max}", "x_v,max"},
        // superscripts
        {"t^2", "t²"},
        {"x^{-12}", "x⁻¹²"},
        {"(1-t)^{n-i}", "(1−t)ⁿ⁻ⁱ"},
        {"M^T", "Mᵀ"},
        {"L^*", "L*"},
        {R"(23.08^\circ)", "23.08°"},  // degrees, never "^∘"
        {R"(\cos\frac{23.08^\circ}{2})", "cos 23.08°/2"},
        {"P_{1}^{2}", "P₁²"},
        {"e^{max}", "e^(max)"},
        // relations, operators, arrows
        {R"(a \le b \ge c \ne d \neq e)", "a ≤ b ≥ c ≠ d ≠ e"},
        {R"(a \cdot b \times c)", "a · b × c"},
        {R"(t \in [0, 1] \to \infty)", "t ∈ [0, 1] → ∞"},
        {R"(x \approx 3 \pm 0.1)", "x ≈ 3 ± 0.1"},
        {R"(\text{input} \leftarrow \text{output})", "input ← output"},
        // Greek
        {R"(\alpha + \beta = \gamma)", "α + β = γ"},
        {R"(\Delta \Sigma \Omega \theta \omega)", "Δ Σ Ω θ ω"},
        // functions, roots, spacing
        {R"(\max(t_{enter}, r_k))", "max(t_enter, rₖ)"},
        {R"(\min(1, 1.25))", "min(1, 1.25)"},
        {R"(\cos\theta + \sin\theta)", "cos θ + sin θ"},
        {R"(\tan x \cot y)", "tan x cot y"},
        {R"(\sqrt{x})", "√(x)"},
        {R"(\sqrt{b^2 - 4ac})", "√(b² − 4ac)"},
        {R"(a = 1,\quad b = 2)", "a = 1,\u2003b = 2"},
        {R"(t\,(P - S))", "t\u2009(P − S)"},
        {R"(a\;b\!c)", "a bc"},
        // delimiters, styles
        {R"(\left( a \right))", "( a )"},
        {R"(\left. x \right|)", "x |"},
        {R"(\lvert v \rvert + |w|)", "| v | + |w|"},
        {R"(\lceil x - \tfrac12 \rceil)", "⌈ x − 1/2 ⌉"},
        {R"(\mathbf{v} + \mathrm{d}x + \text{if } y)", "v + dx + if y"},
        {R"(\text{x-ray})", "x-ray"},
        // matrices and environments
        {R"(\begin{bmatrix} a & b \\ c & d \end{bmatrix})", "[a b; c d]"},
        {R"(\begin{bmatrix} 2 \\ 1 \\ 1 \end{bmatrix})", "[2; 1; 1]"},
        {R"(\begin{pmatrix} 1 & 0 \\ 0 & 1 \\ \end{pmatrix})", "(1 0; 0 1)"},
        {R"(\begin{bmatrix} \frac{L_v}{2} & 0 \\ 0 & 1 \end{bmatrix})", "[L_v/2 0; 0 1]"},
        // big operators, binomials
        {R"(\sum_{i=0}^{3} B_i^3(t))", "∑ᵢ₌₀³ Bᵢ³(t)"},
        {R"(\int_0^1 |P'(u)|\,du)", "∫₀¹ |P′(u)|\u2009du"},
        {R"(\binom{n}{i})", "C(n, i)"},
        // unknown commands keep their name
        {R"(\foo + \norm{v} + \bar{y})", "foo + norm(v) + y"},
        {R"(\mathbb{R}^2)", "ℝ²"},
    }));
    CAPTURE(latex);
    CHECK(math_to_unicode(latex) == unicode);
}

TEST_CASE("math text: only the parts between dollars are math", "[gui][math]") {
    CHECK(text_to_unicode("If $p_k = 0$ the segment is parallel.") ==
          "If pₖ = 0 the segment is parallel.");
    CHECK(text_to_unicode("$$r_k = \\frac{q_k}{p_k}$$ per edge") == "rₖ = qₖ/pₖ per edge");
    CHECK(text_to_unicode("costs \\$5, a - b stays") == "costs $5, a - b stays");
    CHECK(text_to_unicode("an unmatched $x_0 stays") == "an unmatched $x_0 stays");
    CHECK(text_to_unicode("- left: $p_1 = -dx$\n- right") == "- left: p₁ = −dx\n- right");
}

// Every LaTeX command the lessons' math ($…$ in any of their texts) and the steps' formulas
// (every preset run to its end) use must be one the converter knows: an unknown one is shown
// by its bare name ("\ll" as "ll", "\iint" as "iint").
TEST_CASE("math text: every command the lessons and the steps' formulas use is known",
          "[gui][math]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry);
    REQUIRE(lib.errors.empty());
    std::map<std::string, std::string> used;  // command → where first seen
    auto commands = [&](const std::string& latex, const std::string& where) {
        for (std::size_t i = 0; i + 1 < latex.size(); ++i) {
            if (latex[i] != '\\' || !std::isalpha(static_cast<unsigned char>(latex[i + 1]))) {
                if (latex[i] == '\\') ++i;  // \\ and \{ are not commands with names
                continue;
            }
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j]))) ++j;
            used.emplace(latex.substr(i + 1, j - i - 1), where);
            i = j - 1;
        }
    };
    auto math_in = [&](const std::string& text, const std::string& where) {
        for (std::size_t i = 0; (i = text.find('$', i)) != std::string::npos;) {
            if (i > 0 && text[i - 1] == '\\') { ++i; continue; }
            const std::size_t close = text.find('$', i + 1);
            if (close == std::string::npos) break;
            commands(text.substr(i + 1, close - i - 1), where);
            i = close + 1;
        }
    };
    std::size_t formulas = 0;
    for (const cg::Lesson& l : lib.lessons) {
        const std::string file = l.file;
        std::function<void(const cg::json&)> walk = [&](const cg::json& j) {
            if (j.is_string()) math_in(j.get<std::string>(), file);
            if (j.is_array() || j.is_object())
                for (const cg::json& v : j) walk(v);
        };
        std::ifstream in(file);
        walk(cg::json::parse(in));
        const cg::Algorithm* a = registry.find(l.algorithm);
        REQUIRE(a);
        for (const cg::LessonPreset& p : l.presets) {
            auto run = a->create(p.input);
            while (!run->done()) {
                cg::StepInfo info;
                run->step(&info);
                if (!info.math.empty()) ++formulas, commands(info.math, l.id + " \"" + p.name + "\" (" + info.event + ")");
            }
        }
    }
    CHECK(formulas > 1000);
    CHECK(used.size() > 40);
    for (const auto& [name, where] : used) {
        CAPTURE(name, where);
        CHECK(cg::viewer::known_command(name));
    }
    CHECK(math_to_unicode(R"(d \ll D)") == "d ≪ D");
    CHECK(math_to_unicode(R"(\iint_A dA)") == "∬_A dA");
}
