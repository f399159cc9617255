// The polygon meshes the non-photorealistic rendering lessons shade and outline, shared by
// toon-shading and silhouette-edges.
//
// A mesh is a list of points and a list of planar faces, each face its vertex indices listed
// counter-clockwise as seen from outside, so that Newell's normal
//   N = Σ_i ((y_i − y_{i+1})(z_i + z_{i+1}), (z_i − z_{i+1})(x_i + x_{i+1}), (x_i − x_{i+1})(y_i + y_{i+1}))
// points out of the solid (for a triangle it is (P_1 − P_0) × (P_2 − P_0)). Instead of listing
// the points, an input may name a generated shape: a UV sphere of radius 1 about the origin (one
// vertex at each pole, `segments` columns and segments/2 rings: quads, triangles at the poles)
// or a torus about the y axis (tube centre radius 1, tube radius 0.4, `segments` around the
// ring and segments/2 around the tube: quads). Both are closed, every edge shared by two faces.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace cg::npr {

struct Mesh {
    std::vector<glm::dvec3> vertices;     // model points
    std::vector<std::vector<int>> faces;  // vertex indices, counter-clockwise from outside
    std::string shape;                    // "" (listed), "sphere" or "torus": how it was made
    int segments = 0;                     // the generated shape's resolution (0 when listed)
    bool operator==(const Mesh&) const = default;
};

constexpr std::size_t kMaxVertices = 100'000;
constexpr std::size_t kMaxFaces = 100'000;
constexpr int kMinSegments = 4, kMaxSegments = 128;

// The generated shapes ("sphere", "torus"); `segments` 4 to 128, even.
Mesh generate(const std::string& shape, int segments);

// Newell's normal of face f (unnormalised; its length is twice the face's area).
glm::dvec3 newell(const std::vector<glm::dvec3>& v, const std::vector<int>& f);

// Throws InputError naming "vertices", "faces[k]" or "faces[k][i]": at least one face of at
// least three distinct in-range indices, finite coordinates within ±1e50, no face without area,
// every face planar to 1e-6 of its size.
void validate(const Mesh& m);

// The box around the mesh: its centre and the length of its diagonal (at least 1e-9).
std::pair<glm::dvec3, double> bounds(const Mesh& m);

}  // namespace cg::npr
