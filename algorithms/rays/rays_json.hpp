// JSON helpers shared by the ray-tracing algorithms' *_json.cpp files: colours, 4×4 matrices
// and quadric surfaces, read strictly (errors name the field) and written back nicely.
//
//   colour    a number (grey: the same on r, g, b) or [r, g, b]
//   matrix    4×4 as a list of 4 rows (column vectors: p' = M p)
//   quadric   {"type": "sphere" | "ellipsoid" | "paraboloid" | "hyperboloid" | "cone" | "cylinder",
//              "params": {"r"} | {"a", "b", "c"} | {"p", "q"} | {"a", "b", "c"} | {"p", "q", "r"} |
//                        {"p", "q"}  (in that order of types),
//              "transform": world_from_model (optional), "zmin", "zmax" (optional)}
#pragma once

#include <glm/mat4x4.hpp>
#include <string>

#include "io/json.hpp"
#include "rays/quadric.hpp"

namespace cg::rays_json {

// A colour field; sets `rgb` when it was given as [r, g, b].
glm::dvec3 color(const Reader& r, const char* key, bool& rgb);
json color_json(const glm::dvec3& c, bool rgb, bool nice);

// A point, or null when there is none (a miss).
json point_or_null(bool has, glm::dvec3 p);

glm::dmat4 matrix4(const Reader& r, const char* key);
json matrix4_json(const glm::dmat4& m);

// The quadric's fields of object `r` ("type", "params", "transform", "zmin", "zmax"); the
// caller checks which other fields the object may have.
Quadric quadric(const Reader& r);
json quadric_json(const Quadric& q);
inline constexpr const char* kQuadricTypes =
    "sphere, ellipsoid, paraboloid, hyperboloid, cone, cylinder";

}  // namespace cg::rays_json
