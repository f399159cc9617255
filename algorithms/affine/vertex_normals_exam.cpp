// Vertex normals exam problems: a square pyramid with small integer coordinates — the base
// (±a, ±a, 0), the apex (c_x, c_y, h), sometimes off-centre — with or without its base (a quad,
// wound to face down). The question asks for one vertex's normal under one weighting; the
// worked answer is the run's vertex step for that vertex.
#include <string>

#include "affine/vertex_normals.hpp"
#include "core/format.hpp"

namespace cg {

VertexNormals::Input VertexNormals::exam_input(Rng& rng) {
    Input in;
    const double a = double(rng.integer(1, 2));
    const double h = double(rng.integer(1, 3));
    const double cx = a == 2 ? double(rng.integer(-1, 1)) : 0.0;
    const double cy = a == 2 ? double(rng.integer(-1, 1)) : 0.0;
    in.vertices = {{-a, -a, 0}, {a, -a, 0}, {a, a, 0}, {-a, a, 0}, {cx, cy, h}};
    // The sides counter-clockwise seen from outside; the base seen from below.
    in.faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    if (rng.chance(0.5)) in.faces.push_back({0, 3, 2, 1});
    in.has_focus = true;
    in.focus_vertex = rng.chance(0.2) ? 4 : rng.integer(0, 3);
    in.focus_weighting = Weighting(rng.integer(0, 2));
    return in;
}

std::string VertexNormals::question(const Input& in) {
    std::string vertices, faces;
    for (std::size_t v = 0; v < in.vertices.size(); ++v)
        vertices +=
            (v ? ", " : "") + std::string("V") + std::to_string(v) + " = " + num(in.vertices[v]);
    for (std::size_t k = 0; k < in.faces.size(); ++k) {
        faces += (k ? ", " : "") + std::string("F") + std::to_string(k) + " = (";
        for (std::size_t i = 0; i < in.faces[k].size(); ++i)
            faces += (i ? " " : "") + std::string("V") + std::to_string(in.faces[k][i]);
        faces += ")";
    }
    const std::string w = weighting_id(in.focus_weighting);
    const std::string how =
        in.focus_weighting == Weighting::Unweighted
            ? "the plain average of the unit face normals n_f"
        : in.focus_weighting == Weighting::Area
            ? "the area-weighted average Σ A_f n_f (A_f the face's area)"
            : "the angle-weighted average Σ θ_f n_f (θ_f the face's interior angle at the vertex)";
    return "A pyramid has vertices " + vertices + " and faces " + faces +
           ", each counter-clockwise seen from outside (a triangle's normal is (P1 − P0) × (P2 − "
           "P0), the quad's by Newell's method). Give the unit normal of V" +
           std::to_string(in.focus_vertex) + " as " + how +
           " over the faces around it, normalised " + "(vertex_normals/" + w + "/" +
           std::to_string(in.focus_vertex) + ").";
}

std::vector<std::string> VertexNormals::answer_fields(const Input& in) {
    return {"vertex_normals/" + std::string(weighting_id(in.focus_weighting)) + "/" +
            std::to_string(in.focus_vertex)};
}

}  // namespace cg
