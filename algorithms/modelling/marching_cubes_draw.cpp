// The picture of marching cubes: the grid's box; on small grids every sample point, green inside
// and grey outside; the triangles found so far in green, lit by a fixed light (diffuse, either
// side: 0.35 + 0.65 |n·l|) so the surface's shape reads, the last step's in orange; the current
// cube's twelve edges in orange with its corners (numbered, with their values) and its crossings
// as teal points, and a caption "case 1 = 00000001₂" under it. The camera frames the cube, or
// the triangles the step made.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "core/vec.hpp"
#include "modelling/marching_cubes.hpp"

namespace cg {

namespace {

using MC = MarchingCubes;
using glm::dvec3;

constexpr std::size_t kOutlinedTriangles = 600;  // above this many, the faces go unoutlined
const dvec3 kGreen{0x2c / 255.0, 0xa0 / 255.0, 0x2c / 255.0};  // Role::Kept's colour, lit
const dvec3 kLight = unit(dvec3(0.35, 0.85, 0.4));          // from above, front and right

std::string bits8(int index) {
    std::string b;
    for (int k = 7; k >= 0; --k) b += (index >> k & 1) ? '1' : '0';
    return b;
}

}  // namespace

void MarchingCubes::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    const dvec3 lo = g.origin, hi = g.point(g.nx, g.ny, g.nz);
    // The box around the grid, dashed.
    const auto& ends = edge_ends();
    const auto& off = corner_offset();
    auto box = [&](int c) {
        return dvec3(off[std::size_t(c)][0] ? hi.x : lo.x, off[std::size_t(c)][1] ? hi.y : lo.y,
                     off[std::size_t(c)][2] ? hi.z : lo.z);
    };
    for (const auto& e : ends)
        scene.segments3.push_back({box(e[0]), box(e[1]), "", {Role::Construction, 1.0f, true}, false});
    // The sample points on small grids (values on a single cube's or a 2 × 2 × 2 grid).
    const bool single = s.last == Phase::Cubes && s.batch == 0 && s.next - s.from == 1 &&
                        s.phase != Phase::Done;
    if (g.f.size() <= 125 && !single) {
        const bool values = g.f.size() <= 27;
        for (int k = 0; k <= g.nz; ++k)
            for (int j = 0; j <= g.ny; ++j)
                for (int i = 0; i <= g.nx; ++i) {
                    const bool inside = g.at(i, j, k) < in.iso;
                    scene.points3.push_back({g.point(i, j, k), values ? num(g.at(i, j, k), 3) : "",
                                             {inside ? Role::Kept : Role::Subject},
                                             inside ? 5.0f : 3.5f});
                }
    }
    const bool outline = s.triangles.size() <= kOutlinedTriangles;
    scene.faces3.reserve(s.triangles.size());
    for (std::size_t n = 0; n < s.triangles.size(); ++n) {
        const auto& t = s.triangles[n];
        const bool recent = n >= s.tri_from && s.last == Phase::Cubes;
        Face3 f;
        f.points = {s.vertices[std::size_t(t[0])], s.vertices[std::size_t(t[1])],
                    s.vertices[std::size_t(t[2])]};
        f.style = {recent ? Role::Active : Role::Kept, 1.0f};
        f.alpha = 0.7f;
        if (!recent) {
            const dvec3 n = unit(glm::cross(f.points[1] - f.points[0], f.points[2] - f.points[0]));
            f.style.rgba = pack_rgba(kGreen * (0.35 + 0.65 * std::fabs(glm::dot(n, kLight))));
            f.alpha = 0.85f;
        }
        f.outline = outline || recent;
        scene.faces3.push_back(std::move(f));
    }
    const dvec3 caption((lo.x + hi.x) / 2, lo.y - 0.12 * (hi.y - lo.y), (lo.z + hi.z) / 2);
    // The camera frames what the step made (or the cube it marched), with a tenth of the grid
    // around it: on a fine grid a cube or a slab of triangles is otherwise a speck.
    const dvec3 context = 0.1 * (hi - lo);
    auto focus_on = [&](dvec3 a, dvec3 b) {
        const dvec3 c = (a + b) / 2.0, half = glm::max((b - a) / 2.0, context);
        add_focus(scene, c - half, c + half);
    };
    if (!single) {
        if (s.last == Phase::Cubes && s.phase != Phase::Done && s.tri_from < s.triangles.size()) {
            dvec3 a = s.vertices[std::size_t(s.triangles[s.tri_from][0])], b = a;
            for (std::size_t n = s.tri_from; n < s.triangles.size(); ++n)
                for (int v : s.triangles[n])
                    a = glm::min(a, s.vertices[std::size_t(v)]),
                    b = glm::max(b, s.vertices[std::size_t(v)]);
            focus_on(a, b);
        }
        std::string text = std::to_string(s.triangles.size()) + " triangles";
        if (s.phase == Phase::Done)
            text += ", area " + num(s.area, 4) + (s.boundary == 0 && s.nonmanifold == 0
                                                      ? ", closed"
                                                      : ", " + std::to_string(s.boundary) + " open edges");
        scene.labels3.push_back({caption, text, {Role::Neutral}});
        return;
    }
    const int n = s.from;
    const Cube c = march(g, n % g.nx, n / g.nx % g.ny, n / (g.nx * g.ny), in.iso);
    auto corner = [&](int q) {
        return g.point(c.i + off[std::size_t(q)][0], c.j + off[std::size_t(q)][1],
                       c.k + off[std::size_t(q)][2]);
    };
    for (const auto& e : ends)
        scene.segments3.push_back({corner(e[0]), corner(e[1]), "", {Role::Active, 2.0f}, false});
    focus_on(corner(0), corner(6));
    const bool values = g.nx * g.ny * g.nz <= 8;
    for (int q = 0; q < 8; ++q) {
        const bool inside = c.index >> q & 1;
        scene.points3.push_back({corner(q),
                                 values ? std::to_string(q) + ": " + num(c.f[std::size_t(q)], 3)
                                        : std::string(),
                                 {inside ? Role::Kept : Role::Subject},
                                 inside ? 6.0f : 4.0f});
    }
    for (int e = 0; e < 12; ++e)
        if (c.crossed >> e & 1)
            scene.points3.push_back({c.p[std::size_t(e)], values ? "e" + std::to_string(e) : "",
                                     {Role::Entering}, 5.0f});
    std::string label = "case " + std::to_string(c.index) + " = " + bits8(c.index) + "₂, " +
                        std::to_string(c.row->triangles) +
                        (c.row->triangles == 1 ? " triangle" : " triangles");
    if (c.ambiguous) {
        int faces = 0, joined = 0;
        for (int F = 0; F < 6; ++F) faces += c.ambiguous >> F & 1, joined += c.joined >> F & 1;
        label += " (" + std::to_string(faces) + (faces == 1 ? " saddle face, " : " saddle faces, ") +
                 std::to_string(joined) + " joined)";
    }
    // Under the cube, which the camera frames, rather than under the whole grid.
    const dvec3 c0 = glm::min(corner(0), corner(6)), c1 = glm::max(corner(0), corner(6));
    scene.labels3.push_back({dvec3((c0.x + c1.x) / 2, c0.y - 0.15 * (c1.y - c0.y), (c0.z + c1.z) / 2),
                             label,
                             {Role::Active}});
}

}  // namespace cg
