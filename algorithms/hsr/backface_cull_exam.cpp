// Back-face culling exam problems: a tetrahedron with small integer vertices, faces oriented
// counter-clockwise from outside, seen from an integer eye (about one problem in four: a parallel
// view along an integer direction). Now and then the eye lies in a face's plane (edge-on: kept).
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "hsr/backface_cull.hpp"

namespace cg {

namespace {

glm::dvec3 random_point(Rng& rng, int r) {
    return {static_cast<double>(rng.integer(-r, r)), static_cast<double>(rng.integer(-r, r)),
            static_cast<double>(rng.integer(-r, r))};
}

}  // namespace

BackfaceCull::Input BackfaceCull::exam_input(Rng& rng) {
    Input in;
    for (;;) {  // four points, not coplanar
        in.vertices = {random_point(rng, 3), random_point(rng, 3), random_point(rng, 3),
                       random_point(rng, 3)};
        const double vol =
            glm::dot(in.vertices[1] - in.vertices[0],
                     glm::cross(in.vertices[2] - in.vertices[0], in.vertices[3] - in.vertices[0]));
        if (vol == 0) continue;
        // With (P1 − P0)·((P2 − P0) × (P3 − P0)) > 0, these faces are counter-clockwise from
        // outside.
        if (vol > 0)
            in.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
        else
            in.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
        break;
    }
    in.perspective = !rng.chance(0.25);
    if (in.perspective) {
        if (rng.chance(0.2)) {  // in the plane of face 0: P0 + a (P1 − P0) + b (P2 − P0)
            const glm::dvec3 p0 = in.vertices[0];
            do
                in.eye = p0 + static_cast<double>(rng.integer(-2, 3)) * (in.vertices[1] - p0) +
                         static_cast<double>(rng.integer(-2, 3)) * (in.vertices[2] - p0);
            while (in.eye == in.vertices[0] || in.eye == in.vertices[1] ||
                   in.eye == in.vertices[2]);
        } else {
            in.eye = random_point(rng, 8);
        }
    } else {
        do in.view_dir = random_point(rng, 2);
        while (in.view_dir == glm::dvec3(0, 0, 0));
    }
    return in;
}

std::string BackfaceCull::question(const Input& in) {
    const bool tetra = in.vertices.size() == 4 && in.faces.size() == 4;
    std::string q = tetra ? "A tetrahedron has vertices" : "A closed mesh has vertices";
    for (std::size_t i = 0; i < in.vertices.size(); ++i)
        q += " P" + std::to_string(i) + " = " + num(in.vertices[i]) +
             (i + 1 < in.vertices.size() ? "," : ";");
    q += " its faces, counter-clockwise seen from outside, are";
    for (std::size_t k = 0; k < in.faces.size(); ++k) {
        q += " F" + std::to_string(k) + " = (";
        for (std::size_t i = 0; i < in.faces[k].size(); ++i)
            q += (i ? ", P" : "P") + std::to_string(in.faces[k][i]);
        q += k + 1 < in.faces.size() ? ")," : ").";
    }
    if (in.perspective)
        q += " The eye is at " + num(in.eye) + "; take V from the eye to each face's first vertex.";
    else
        q += " The view is parallel, looking along V = " + num(in.view_dir) + ".";
    q += " Which faces are back-facing (cull when N·V > 0, N the outward normal; N·V = 0 is kept)? "
         "Give culled: one true/false per face.";
    return q;
}

std::vector<std::string> BackfaceCull::answer_fields() {
    return {"culled"};
}

}  // namespace cg
