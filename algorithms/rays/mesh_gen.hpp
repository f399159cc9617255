// Generated triangle meshes for the ray tracer's scenes, so that a big scene needs no download:
// a UV-tessellated sphere, a fractal terrain (diamond-square) and a tessellated bicubic Bézier
// patch, each with smooth per-vertex normals and (u, v).
//
// A mesh is indexed: flat arrays of vertices (and, one per vertex, unit normals and (u, v)) and
// triangles as three vertex indices, counter-clockwise seen from the side the normals point
// to. No allocation per triangle: a 10⁶-triangle terrain is five vectors.
//
// Sphere (centre c, radius r, `segments` n ≥ 3): n columns around the y axis and
// rings = max(2, n/2) rows from the south pole (v = 0) to the north pole (v = 1); vertex (i, k)
// (ring i = 0 .. rings, column k = 0 .. n) is at polar angle θ = π (1 − i/rings) from +y and
// azimuth φ = 2π k/n, so the seam (k = 0 and k = n) and the poles are repeated for their
// (u, v) = (k/n, i/rings). Its normal is (p − c)/r exactly; the triangles touching a pole are
// one per column (the other half of the quad would have zero area). Vertices (rings + 1)(n + 1),
// triangles 2 n (rings − 1).
//
// Terrain (`size` [w, d], `resolution` n cells a side, `height` h, `roughness` ρ, `seed`):
// diamond-square on a (2^k + 1)² grid, 2^k the smallest power of two ≥ n, of which the first
// (n + 1)² samples are kept. The four corners start at uniform(−1, 1); then, level by level with
// the amplitude a = ρ, ρ², ρ³, …, each square's centre becomes the average of its four corners
// plus uniform(−a, a) (the diamond step), and each edge midpoint the average of its (three or
// four) diamond neighbours plus uniform(−a, a) (the square step), in a fixed order from one
// generator (core/rng.hpp) seeded by `seed`: the same seed, the same terrain (the levels are
// modelling/fractal_terrain's fractal::diamond_square, the stepped lesson's code). The heights are
// then scaled so that the largest |height| kept is h (all zero stays zero). Vertex (i, j) (row
// j along z, column i along x) is at (x, y, z) = center + (w (i/n − ½), height, d (j/n − ½));
// its normal is the unit (−∂y/∂x, 1, −∂y/∂z) by central differences (one-sided on the border),
// its (u, v) = (i/n, j/n). Vertices (n + 1)², triangles 2 n².
//
// Patch (4 × 4 `control_points`, rows i along s and columns j along t, `segments` n): the
// surface sampled at s = a/n, t = b/n by curves/bezier_patch's point_at (vertex a (n + 1) + b),
// triangles as BezierPatch's tessellation; the normal is the unit ∂P/∂s × ∂P/∂t, the
// derivatives being point_at on the difference nets (∂P/∂s = 3 Σ (P_{i+1,j} − P_ij) B_i²(s)
// B_j³(t), likewise in t). Where the normal is undefined (a collapsed corner or edge) it is taken
// a little inside, at (½ + (s − ½)(1 − 10⁻⁴), ½ + (t − ½)(1 − 10⁻⁴)); if it is undefined there
// too, the mesh gets no normals (flat). Triangles of zero area (a collapsed edge: degenerate()
// or |e1 × e2| ≤ 10⁻²⁰ of the net's extent squared, rounding noise) are left out.
// (u, v) = (s, t).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace cg::mesh {

struct Mesh {
    std::vector<glm::dvec3> vertices;
    std::vector<glm::dvec3> normals;  // empty, or one unit normal per vertex
    std::vector<glm::dvec2> uv;       // empty, or one (u, v) per vertex
    std::vector<std::array<std::uint32_t, 3>> triangles;
    bool operator==(const Mesh&) const = default;
};

constexpr int kMaxSphereSegments = 2048;     // 4.2 million triangles
constexpr int kMaxTerrainResolution = 2048;  // 8.4 million triangles
constexpr int kMaxPatchSegments = 1024;      // 2.1 million triangles

struct SphereParams {
    glm::dvec3 center{0.0};
    double radius = 1;
    int segments = 16;
    bool operator==(const SphereParams&) const = default;
};
struct TerrainParams {
    glm::dvec3 center{0.0};
    glm::dvec2 size{10, 10};  // w along x, d along z
    int resolution = 64;      // cells a side
    double height = 1;
    double roughness = 0.5;  // the amplitude's factor per level, in [0, 1]
    std::uint64_t seed = 1;
    bool operator==(const TerrainParams&) const = default;
};
struct PatchParams {
    std::array<std::array<glm::dvec3, 4>, 4> control_points{};  // [i][j]
    int segments = 8;
    bool operator==(const PatchParams&) const = default;
};

// Throw InputError naming `field` + ".radius" etc. (`field` is the "generate" object's path).
void validate(const SphereParams& p, const std::string& field);
void validate(const TerrainParams& p, const std::string& field);
void validate(const PatchParams& p, const std::string& field);

// Counts without generating (to check a scene's limits first).
std::size_t sphere_triangles(int segments);
std::size_t terrain_triangles(int resolution);
std::size_t patch_triangles(int segments);

// Preconditions: validate does not throw.
Mesh sphere(const SphereParams& p);
Mesh terrain(const TerrainParams& p);
Mesh patch(const PatchParams& p);

// Whether a triangle has zero area as the tracer's validation sees it (rt::validate):
// |e1 × e2| ≤ 1e-12 |e1| |e2| or 0.
bool degenerate(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2);

}  // namespace cg::mesh
