// Subdivision exam problems on small meshes with integer corners, one level: one Catmull–Clark
// face point, edge point or moved vertex, or one Loop edge point or moved vertex, plus the
// numbers of vertices, edges and faces after the level (by the count formulas). Meshes: a cube
// [0, 2]³ (an interior vertex of valence 3), a square pyramid (triangles and a quad: valence 3
// and 4), a 2 × 1 grid of quads with a boundary (the boundary rules); for Loop an octahedron
// (valence 4), a tetrahedron (valence 3) and a flat fan of four triangles (a boundary).
#include "core/format.hpp"
#include "modelling/subdivision_surface.hpp"

namespace cg {

SubdivisionSurface::Input SubdivisionSurface::exam_input(Rng& rng) {
    Input in;
    in.levels = 1;
    in.scheme = rng.chance(0.55) ? Scheme::CatmullClark : Scheme::Loop;
    const double a = double(rng.integer(1, 2)) * 2;  // 2 or 4: face points land on integers
    const int mesh = int(rng.integer(0, 2));
    Mesh& m = in.mesh;
    if (in.scheme == Scheme::CatmullClark) {
        if (mesh == 0) {  // the cube [0, a]³, outward faces
            m.vertices = {{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0},
                          {0, 0, a}, {a, 0, a}, {a, a, a}, {0, a, a}};
            m.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                       {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
        } else if (mesh == 1) {  // a square pyramid: four triangles on a quad
            m.vertices = {{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}, {a / 2, a / 2, a}};
            m.faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2, 1}};
        } else {  // two quads side by side, a fold along the middle: every edge but one on the border
            m.vertices = {{0, 0, 0}, {a, 0, a / 2}, {2 * a, 0, 0},
                          {0, a, 0}, {a, a, a / 2}, {2 * a, a, 0}};
            m.faces = {{0, 1, 4, 3}, {1, 2, 5, 4}};
        }
        const int kind = int(rng.integer(0, 2));
        in.focus = kind == 0 ? FocusKind::Face : kind == 1 ? FocusKind::Edge : FocusKind::Vertex;
    } else {
        if (mesh == 0) {  // the octahedron ±a/2 on the axes
            const double h = a / 2;
            m.vertices = {{h, 0, 0}, {-h, 0, 0}, {0, h, 0}, {0, -h, 0}, {0, 0, h}, {0, 0, -h}};
            m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                       {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
        } else if (mesh == 1) {  // a tetrahedron on alternate corners of the cube [0, a]³
            m.vertices = {{0, 0, 0}, {a, a, 0}, {a, 0, a}, {0, a, a}};
            m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
        } else {  // a flat fan of four triangles around a raised centre: a boundary
            m.vertices = {{0, 0, a / 2}, {a, 0, 0}, {0, a, 0}, {-a, 0, 0}, {0, -a, 0}};
            m.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
        }
        in.focus = rng.chance(0.5) ? FocusKind::Edge : FocusKind::Vertex;
    }
    const auto& f0 = m.faces[std::size_t(rng.integer(0, (long long)m.faces.size() - 1))];
    if (in.focus == FocusKind::Face) {
        in.focus_a = rng.integer(0, (long long)m.faces.size() - 1);
    } else if (in.focus == FocusKind::Edge) {
        const std::size_t i = std::size_t(rng.integer(0, (long long)f0.size() - 1));
        in.focus_a = f0[i];
        in.focus_b = f0[(i + 1) % f0.size()];
    } else {
        in.focus_a = rng.integer(0, (long long)m.vertices.size() - 1);
    }
    return in;
}

std::string SubdivisionSurface::question(const Input& in) {
    std::string vertices, faces;
    for (std::size_t v = 0; v < in.mesh.vertices.size(); ++v)
        vertices += (v ? ", " : "") + std::string("V") + std::to_string(v) + " = " +
                    num(in.mesh.vertices[v]);
    for (std::size_t k = 0; k < in.mesh.faces.size(); ++k) {
        faces += (k ? ", " : "") + std::string("F") + std::to_string(k) + " = (";
        for (std::size_t i = 0; i < in.mesh.faces[k].size(); ++i)
            faces += (i ? " " : "") + std::string("V") + std::to_string(in.mesh.faces[k][i]);
        faces += ")";
    }
    const bool loop = in.scheme == Scheme::Loop;
    std::string ask;
    switch (in.focus) {
        case FocusKind::Face:
            ask = "the face point of F" + std::to_string(in.focus_a);
            break;
        case FocusKind::Edge:
            ask = "the edge point of the edge V" + std::to_string(in.focus_a) + "–V" +
                  std::to_string(in.focus_b);
            break;
        default:
            ask = "the new position of V" + std::to_string(in.focus_a);
            break;
    }
    return "A mesh has vertices " + vertices + " and faces " + faces + ". Apply one level of " +
           (loop ? "Loop subdivision (edge point 3/8(a + b) + 1/8(c + d); vertex (1 − nβ)v + βΣw "
                   "with β = (1/n)(5/8 − (3/8 + 1/4 cos(2π/n))²))"
                 : "Catmull–Clark subdivision (face point the centroid; edge point (a + b + f₁ + "
                   "f₂)/4; vertex (Q + 2R + (n − 3)v)/n)") +
           "; on the boundary an edge point is the midpoint and a vertex 1/8 u + 3/4 v + 1/8 w. "
           "Give " + ask + " (focus_point), and the numbers of vertices, edges and faces after "
           "the level, [V, E, F] (counts/1).";
}

std::vector<std::string> SubdivisionSurface::answer_fields() {
    return {"focus_point", "counts/1"};
}

}  // namespace cg
