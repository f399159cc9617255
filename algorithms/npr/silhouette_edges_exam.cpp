// Silhouette exam problems: a small convex solid with integer corners (a tetrahedron, a cube
// or a square pyramid), faces counter-clockwise from outside, and an integer eye outside it.
// Everything is exact in integers, so the signs of (P_0 − E)·N are the student's too; now and
// then the eye lies in a face's plane (edge-on: counted as back-facing).
#include <algorithm>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "npr/silhouette_edges.hpp"

namespace cg {

namespace {

glm::dvec3 random_point(Rng& rng, int r) {
    return {static_cast<double>(rng.integer(-r, r)), static_cast<double>(rng.integer(-r, r)),
            static_cast<double>(rng.integer(-r, r))};
}

// Turns each face of a convex solid to be counter-clockwise from outside.
void orient(npr::Mesh& m) {
    glm::dvec3 c{0, 0, 0};
    for (const auto& p : m.vertices) c += p;
    c /= static_cast<double>(m.vertices.size());
    for (auto& f : m.faces)
        if (glm::dot(npr::newell(m.vertices, f), m.vertices[static_cast<std::size_t>(f[0])] - c) < 0)
            std::reverse(f.begin(), f.end());
}

}  // namespace

SilhouetteEdges::Input SilhouetteEdges::exam_input(Rng& rng) {
    Input in;
    const int kind = static_cast<int>(rng.integer(0, 2));
    if (kind == 0) {
        for (;;) {
            in.mesh.vertices = {random_point(rng, 2), random_point(rng, 2), random_point(rng, 2),
                                random_point(rng, 2)};
            const auto& v = in.mesh.vertices;
            if (glm::dot(v[1] - v[0], glm::cross(v[2] - v[0], v[3] - v[0])) != 0) break;
        }
        in.mesh.faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    } else if (kind == 1) {
        in.mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                            {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}};
        in.mesh.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    } else {
        in.mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}, {1, 2, 1}};
        in.mesh.faces = {{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    }
    orient(in.mesh);
    for (;;) {  // an eye outside: some face is front-facing
        in.eye = random_point(rng, 6);
        bool outside = false;
        for (const auto& f : in.mesh.faces) outside = outside || side_of(in, f) < 0;
        if (outside) return in;
    }
}

std::string SilhouetteEdges::question(const Input& in) {
    const auto& m = in.mesh;
    std::string q = "A closed mesh has vertices";
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
        q += " P" + std::to_string(i) + " = " + num(m.vertices[i]) + (i + 1 < m.vertices.size() ? "," : ";");
    q += " its faces, counter-clockwise seen from outside, are";
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        q += " F" + std::to_string(k) + " = (";
        for (std::size_t i = 0; i < m.faces[k].size(); ++i) q += (i ? ", P" : "P") + std::to_string(m.faces[k][i]);
        q += k + 1 < m.faces.size() ? ")," : ").";
    }
    q += " The eye is at E = " + num(in.eye) +
         ". A face is front-facing when (P_0 − E)·N < 0 (P_0 its first vertex, N its outward normal; "
         "0 counts as back-facing). Give silhouette: the edges between a front and a back face, each "
         "as [i, j] with i < j, in increasing order.";
    return q;
}

std::vector<std::string> SilhouetteEdges::answer_fields() {
    return {"silhouette"};
}

}  // namespace cg
