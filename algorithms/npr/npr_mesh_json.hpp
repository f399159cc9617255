// The JSON of an NPR mesh (npr/npr_mesh.hpp), shared by toon-shading and silhouette-edges:
//   either "vertices": [[x, y, z], …] and "faces": [[i, j, k, …], …]
//   or     "shape": "sphere" | "torus" and "segments": n (even, 4 to 128)
#pragma once

#include "io/json.hpp"
#include "npr/npr_mesh.hpp"

namespace cg::npr {

// The fields this reads; the caller's Reader::only lists them with its own.
Mesh read_mesh(const Reader& r);
void write_mesh(json& j, const Mesh& m);

}  // namespace cg::npr
