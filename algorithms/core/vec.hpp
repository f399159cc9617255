// Lengths and directions of vectors without overflow or underflow.
//
// Input coordinates may be anything a JSON file can hold (1e300, 1e-300), and a narration shows
// |v| beside v/|v|: both are computed here, so the length shown is the one that made the unit
// vector, and a huge or tiny vector still has a direction.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

namespace cg {

// |v| without overflow or underflow: std::hypot's three-argument form scales as unit() does,
// so the length a narration shows beside v/|v| is the one that made it (|(1e300, 0, 0)| is
// 1e300, not the inf of √(x² + y² + z²)).
inline double length_of(glm::dvec3 v) { return std::hypot(v.x, v.y, v.z); }

// A unit vector along v without overflow or underflow; (0, 0, 0) for v = 0. The usual
// v/|v| when |v|² is a comfortable number (a unit axis stays exact: √(x²) = |x|), else v is
// first scaled by its largest component.
inline glm::dvec3 unit(glm::dvec3 v) {
    const double len2 = v.x * v.x + v.y * v.y + v.z * v.z;
    if (len2 > 1e-290 && len2 < 1e290) return v / std::sqrt(len2);
    const double m = std::max(std::max(std::fabs(v.x), std::fabs(v.y)), std::fabs(v.z));
    if (m == 0) return glm::dvec3(0.0);
    v /= m;
    return v / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

}  // namespace cg
