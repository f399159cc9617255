// The viewer's LaTeX → Unicode converter, on the notation the lessons and steps use.
#include <catch2/catch.hpp>

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
