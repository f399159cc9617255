// The screen scene's JSON, shared by every hidden-surface algorithm:
//   {"width": W, "height": H, "polygons": [{"vertices": [[x, y, z], …], "color": [r, g, b]}, …]}
// and the "ids" every result carries: H rows (row 0 the bottom row) of W polygon indices, −1
// for background.
#pragma once

#include "hsr/screen_scene.hpp"
#include "io/json.hpp"

namespace cg::hsr {

// Reads "width", "height" and "polygons" from r (the caller lists its allowed fields with
// Reader::only). Strict: polygons allow only "vertices" and "color"; "color" is optional (white).
ScreenScene read_screen_scene(const Reader& r);
// The same three fields, with integral numbers written as integers.
void write_screen_scene(const ScreenScene& scene, json& out);
// H rows of W values, row 0 the bottom row.
json ids_json(const std::vector<int>& ids, long long width, long long height);

}  // namespace cg::hsr
