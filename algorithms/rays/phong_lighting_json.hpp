// The lighting fields of phong-lighting's JSON, read and written by one pair of functions so
// that every algorithm that lights points (phong-lighting, the shading of a mesh) reads them
// alike, with the same errors:
//   "model": "phong" | "blinn-phong", "eye": [x, y, z], "ambient": colour,
//   "material": {"ka", "kd", "ks": colours, "shininess": p},
//   "lights": [{"position": [x, y, z] | "direction": [x, y, z] (the way the light travels),
//               "intensity": colour, "attenuation": [c1, c2, c3] (optional, point lights only)}, …]
// (a colour is a number or [r, g, b]). Errors name the field under the reader's path:
// "lights[0].intensity", or "lighting.lights[0].intensity" for a reader at "lighting".
#pragma once

#include "io/json.hpp"
#include "rays/phong_lighting.hpp"

namespace cg::rays_json {

// The "model" field alone (read_lighting reads it too).
PhongLighting::Model read_lighting_model(const Reader& r);

// Reads those five fields of `r` into `in` (its point and normal are left alone); the caller
// checks which other fields the object may have.
void read_lighting(const Reader& r, PhongLighting::Input& in);

// The five fields, in that order, as read_lighting reads them.
json lighting_json(const PhongLighting::Input& in);

}  // namespace cg::rays_json
