// JSON for the acceleration structures' primitives (accel/primitive.hpp), read strictly (errors
// name the field and the reason) and written back nicely:
//   {"type": "sphere",   "center": [x, y, z], "radius": r}          r > 0
//   {"type": "triangle", "vertices": [[x, y, z], [x, y, z], [x, y, z]]}   not collinear
//   {"type": "box",      "min": [x, y, z], "max": [x, y, z]}         min ≤ max on every axis
#pragma once

#include <cstddef>
#include <vector>

#include "accel/primitive.hpp"
#include "io/json.hpp"

namespace cg::accel_json {

Primitive primitive(const Reader& o);
json primitive_json(const Primitive& p);

// The list r[key]: at least one primitive and at most max_count.
std::vector<Primitive> primitives(const Reader& r, const char* key, std::size_t max_count);
json primitives_json(const std::vector<Primitive>& ps);

}  // namespace cg::accel_json
