// Numbers as a student reads them: short, exact where the value is a simple decimal, and
// identical on every machine (printf's %g is deterministic for a given double).
#pragma once

#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/step.hpp"

namespace cg {

// `x` with up to `digits` significant digits, trailing zeros removed, and -0 printed as 0.
std::string num(double x, int digits = 6);
std::string num(glm::dvec2 p, int digits = 6);  // "(1, 2.5)"
std::string num(glm::dvec3 p, int digits = 6);  // "(1, 2.5, -3)"

// The same numbers for LaTeX: "-4", "0.25", "2.5 \\times 10^{-12}", points "(1, 2.5)".
std::string tex(double x, int digits = 6);
std::string tex(glm::dvec2 p, int digits = 6);
std::string tex(glm::dvec3 p, int digits = 6);

// A Value as the variables inspector shows it.
std::string to_text(const Value& v, int digits = 6);

inline std::vector<double> vec(glm::dvec2 p) { return {p.x, p.y}; }
inline std::vector<double> vec(glm::dvec3 p) { return {p.x, p.y, p.z}; }

}  // namespace cg
