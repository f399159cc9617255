// JSON for the ray tracer's meshes: a mesh object's "generate" (rays/mesh_gen.hpp) and "obj"
// (a Wavefront OBJ file, read with tinyobjloader).
//
//   "generate": {"shape": "sphere", "center": [x, y, z] (default 0), "radius": r (default 1),
//                "segments": n (default 16)}
//             | {"shape": "terrain", "center" (default 0), "size": [w, d] (default [10, 10]),
//                "resolution": n (cells a side, default 64), "height": h (default 1),
//                "roughness": ρ in [0, 1] (default 0.5), "seed": integer (default 1)}
//             | {"shape": "patch", "control_points": 4 rows of 4 [x, y, z],
//                "segments": n (default 8)}
//   "obj": "path/to/file.obj"
//
// OBJ files: a relative path is taken relative to the folder of the scene or input file that
// names it (the CLI rebases it as it does texture images: rebase_image_paths). The file is
// checked line by line before tinyobjloader reads it, so that a broken file is refused with
// its line: a number that is not decimal (no hexadecimal, inf or nan) or is beyond ±1e12, a
// face with fewer than 3 vertices (or more than 255), a face index 0 or referring to a vertex,
// texture coordinate or normal not yet defined, a zero normal, free-form geometry (curv, surf,
// …) or any statement that is not OBJ; a missing or unreadable file; a file without faces.
// Lines end at "\n", "\r\n" or a lone "\r" and fields are separated by spaces and tabs, as
// tinyobjloader reads them. Lines ("l") and points ("p") are ignored, as are groups, smoothing
// groups and materials. Polygons are triangulated (tinyobjloader's fan); the file's normals and
// texture coordinates are used when every face gives them; triangles of zero area are left out.
// Errors:
//   objects[2].obj: "cube.obj" line 12: face index 9 refers to vertex 9, but only 8 are defined
#pragma once

#include <string>

#include "io/json.hpp"
#include "rays/mesh_gen.hpp"

namespace cg::mesh_json {

// The "generate" object (its path names the errors); validated.
mesh::Mesh generate(const Reader& g);
// The triangle count `generate` would make, checked before generating (validated too).
std::size_t generate_count(const Reader& g);

// Reads an OBJ file; throws InputError(field, "\"file\" line N: reason").
mesh::Mesh read_obj(const std::string& path, const std::string& field);

}  // namespace cg::mesh_json
