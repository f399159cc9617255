// LaTeX math as readable Unicode, for the viewer's panels (ImGui draws plain text only).
//
// The lessons and each step's formula are written in LaTeX so the Markdown export can keep
// them; the viewer shows them as a student would write them on paper:
//     \frac{q_1}{p_1}  → q₁/p₁          \frac{a + b}{2}    → (a + b)/2
//     x_0, P_{i+1}     → x₀, Pᵢ₊₁       x_{min}, t_{enter} → x_min, t_enter
//     t^2, x^{-12}     → t², x⁻¹²       \le \ne \cdot \in  → ≤ ≠ · ∈
//     \sqrt{x}         → √(x)           \begin{bmatrix} a & b \\ c & d \end{bmatrix} → [a b; c d]
// Subscripts become Unicode only for digits and the index letters i j k l m n (so x_{min}
// stays readable and L_v, L_w look alike); superscripts whenever Unicode has every character.
// Unknown commands are kept without their backslash (\norm{v} → norm(v)), so nothing
// silently disappears.
#pragma once

#include <string>
#include <string_view>

namespace cg::viewer {

// Whether the converter knows the command `name` (without its backslash): a symbol, a style,
// a function name, a fraction, a root, an environment… An unknown one is shown by its name,
// which reads wrong ("\\ll" as "ll"): the tests list every command the lessons and the
// formulas use and fail on one not known here.
bool known_command(std::string_view name);

// One formula, without the $ delimiters.
std::string math_to_unicode(std::string_view latex);

// Text with inline math between $ … $ (or $$ … $$): the math converted, the rest unchanged.
// "\$" is a literal dollar; an unmatched $ is kept as it is.
std::string text_to_unicode(std::string_view text);

}  // namespace cg::viewer
