// A CSG tree in JSON, shared by csg-ray's input and the ray tracer's scene objects:
//
//   NODE  {"op": "union" | "intersection" | "difference", "left": NODE, "right": NODE,
//          "transform": 4×4 rows (optional, parent_from_node: applies to the whole subtree),
//          "name" (optional)}
//       | {"primitive": PRIMITIVE, "transform" (optional), "name" (optional)}
//   PRIMITIVE  a quadric exactly as ray-quadric's "quadric" ({"type", "params", "transform",
//              "zmin", "zmax"}; zmin/zmax cap it: the solid is F < 0 within the slab)
//            | {"type": "box", "min": [x, y, z], "max": [x, y, z]}
//
// Read strictly; errors name the path: `tree.left.right.op: unknown op "xor" (union,
// intersection, difference)`, `tree.left: is missing`, a tree deeper than kMaxCsgDepth.
#pragma once

#include <string>

#include "io/json.hpp"
#include "rays/csg.hpp"

namespace cg::csg_json {

// The tree at `j`, whose path in the input is `path` ("tree", "objects[2].tree"); the values
// are checked by validate_csg.
CsgTree tree(const json& j, const std::string& path);
json tree_json(const CsgTree& t);

}  // namespace cg::csg_json
