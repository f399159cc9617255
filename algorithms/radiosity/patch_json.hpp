// Patches in JSON, shared by the radiosity algorithms (form-factor, radiosity):
//   {"type": "rectangle", "corner": [x, y, z], "edge_u": [..], "edge_v": [..]}  (normal u × v)
// | {"type": "disc", "center": [..], "normal": [..], "radius": r}
// | {"type": "triangle", "points": [[..], [..], [..]]}   (normal (p1 − p0) × (p2 − p0))
// | {"type": "point", "center": [..], "normal": [..]}     (a differential area dA)
#pragma once

#include "io/json.hpp"
#include "radiosity/patch.hpp"

namespace cg {

// Reads one patch, throwing InputError naming the field ("patches[2].corner") and the reason.
// `extra` lists further keys the caller reads from the same object (emission, reflectance).
Patch read_patch(const Reader& r, std::initializer_list<const char*> extra = {});
json patch_json(const Patch& p);

}  // namespace cg
