// Numbers as a student reads them, and as a person writes them: short, exact where the value is
// a simple decimal, identical on every machine (printf's %g is deterministic for a given
// double). One formatter for everything the student reads — narration, variables, labels,
// exam text, the formulas' numbers — so the rules hold everywhere:
//   - a value within kZeroSnap of zero is rounding noise of a zero and prints "0" (5.55e-17,
//     -1.22e-16 and -0 all print 0); an integer to rounding prints as that integer (%g with
//     `digits` significant figures already rounds 2.9999999999999996 to 3);
//   - otherwise `digits` significant figures, trailing zeros dropped;
//   - big numbers whole (1234567; 1310 for 1.31e+03 at three figures); scientific notation only
//     below 10⁻⁴ and from 10¹⁵, written short as a person writes it: "2.5 × 10⁻⁵", not "2.5e-05";
//   - one minus sign, U+2212 "−", in text; tex() keeps LaTeX's "-" (its renderer draws "−").
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>

#include "core/step.hpp"

namespace cg {

// Below this, a value shown to a student is a zero that rounding disturbed.
inline constexpr double kZeroSnap = 1e-12;

// The minus sign text uses (U+2212), as UTF-8.
inline constexpr const char* kMinus = "\u2212";

// `x` with up to `digits` significant digits, as the rules above say.
std::string num(double x, int digits = 6);
std::string num(glm::dvec2 p, int digits = 6);  // "(1, 2.5)"
std::string num(glm::dvec3 p, int digits = 6);  // "(1, 2.5, −3)"

// A value the user gave, in an error about it: as num() writes it but never snapped to 0 (a
// refused 1e-300 is "10⁻³⁰⁰", not "0", which the error's own rule may allow).
std::string given(double x, int digits = 6);
std::string given(glm::dvec2 p, int digits = 6);
std::string given(glm::dvec3 p, int digits = 6);

// The same numbers for LaTeX: "-4", "0.25", "2.5 \\times 10^{-12}", points "(1, 2.5)".
std::string tex(double x, int digits = 6);
std::string tex(glm::dvec2 p, int digits = 6);
std::string tex(glm::dvec3 p, int digits = 6);

// A Value as the variables inspector shows it.
std::string to_text(const Value& v, int digits = 6);

// Text with every hyphen-minus that is a minus sign (before a digit, a decimal point or ∞,
// where no letter or digit stands before it; or spaced on both sides) written as "−"; hyphens
// inside words ("Liang-Barsky", "x-axis") stay.
std::string text_minus(std::string_view text);

inline std::vector<double> vec(glm::dvec2 p) {
    return {p.x, p.y};
}
inline std::vector<double> vec(glm::dvec3 p) {
    return {p.x, p.y, p.z};
}

}  // namespace cg
