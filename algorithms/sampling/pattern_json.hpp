// JSON readers shared by the sampling algorithms (supersampling, sampling): pattern and filter
// names, sample counts, pixels, seeds and the 2D scene (an edge or a polygon).
#pragma once

#include <glm/vec2.hpp>

#include "io/json.hpp"
#include "sampling/coverage.hpp"
#include "sampling/patterns.hpp"

namespace cg::sampling_json {

sampling::Pattern pattern(const Reader& r, const char* key);
sampling::Filter filter(const Reader& r, const char* key);
int count(const Reader& r, const char* key, int max);                // an integer in [1, max]
glm::ivec2 pixel(const Reader& r, const char* key, double max_abs);  // [i, j], integers
std::uint64_t seed(const Reader& r, const char* key);                // an integer in [0, 2^53]

// {"type": "edge", "point": [x, y], "angle": degrees} | {"type": "polygon", "points": [...]}
sampling::Region region(const Reader& r);
json region_json(const sampling::Region& region);

}  // namespace cg::sampling_json
