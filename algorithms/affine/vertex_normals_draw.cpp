// Vertex normals, the picture (3D). The mesh's faces, translucent. While the faces are worked
// out, the current face is orange with its unit normal n_k (thick, at least 30 px) from its
// centroid; the normals found so far stay, thin. While the vertices are worked out, the current
// vertex is an orange dot, the faces around it blue with their normals (the terms of the sums)
// labelled, and its three normals leave it: unweighted (teal, widest), area (green), angle
// (magenta, narrowest) — drawn one inside the other, so where two or three agree the stripes
// show it, and labelled once per direction at the tip ("angle", "area = angle", "all three").
// The vertices done before keep their three normals, thin and unlabelled, except the one the
// preset asks about (its value at the tip). The camera frames the mesh with its face normals,
// then each vertex with its normals and the near parts of its faces.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "affine/vertex_normals.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec3;
using FaceNormal = VertexNormals::FaceNormal;
using VertexSums = VertexNormals::VertexSums;
using Weighting = VertexNormals::Weighting;

constexpr Role kRole[3] = {Role::Entering, Role::Kept, Role::Leaving};

std::string vname(std::size_t v) {
    return "V" + std::to_string(v);
}

}  // namespace

void VertexNormals::draw(const State& s, Scene& scene) {
    const Prepared& p = *s.in;
    const auto& P = p.vertices;
    // Arrows a fraction of the mesh's mean edge length, so they read at any scale.
    double edges = 0;
    long long n_edges = 0;
    for (const auto& c : p.corners)
        for (std::size_t i = 0; i < c.size() && n_edges < 4096; ++i, ++n_edges)
            edges += glm::length(P[c[(i + 1) % c.size()]] - P[c[i]]);
    dvec3 lo = P[0], hi = P[0];
    for (const auto& q : P) lo = glm::min(lo, q), hi = glm::max(hi, q);
    double len = n_edges ? 0.6 * edges / double(n_edges) : 0.0;
    if (!(len > 0)) len = std::max(0.25 * glm::length(hi - lo), 1.0);
    const bool labels = P.size() <= 40;

    const bool on_faces = s.vertex < 0;
    const bool on_vertex = !on_faces && s.vertex < static_cast<int>(s.vertices.size());
    // What the camera frames: at a face, the whole mesh with its normals; at a vertex, the
    // vertex and its normals with the faces' nearest parts (a long face would shrink them).
    const double inf = 1e300;
    dvec3 focus_lo(inf), focus_hi(-inf);
    auto frame = [&](dvec3 q) {
        focus_lo = glm::min(focus_lo, q), focus_hi = glm::max(focus_hi, q);
    };

    std::vector<bool> around(p.corners.size(), false);
    for (std::size_t k = 0; k < p.corners.size(); ++k) {
        const auto& c = p.corners[k];
        Face3 f;
        for (long long v : c) f.points.push_back(P[v]);
        const bool current = on_faces && int(k) == s.face;
        around[k] = !on_faces && std::find(c.begin(), c.end(), s.vertex) != c.end();
        const bool worked = int(k) < static_cast<int>(s.faces.size());
        const bool degenerate = worked && !s.faces[k].defined;
        f.style.role = current      ? Role::Active
                       : degenerate ? Role::Discarded
                       : around[k]  ? Role::Window
                                    : Role::Subject;
        f.alpha = current || around[k] ? 0.45f : 0.25f;
        if (on_faces)  // a face is seen with the whole mesh
            for (const dvec3& q : f.points) frame(q);
        scene.faces3.push_back(std::move(f));
    }
    // Face normals at the centroids of the faces worked out so far: the current one thick; at
    // a vertex, the normals of its faces (its sums' terms) named, the others faint.
    for (std::size_t k = 0; k < s.faces.size(); ++k) {
        const FaceNormal& f = s.faces[k];
        dvec3 c(0.0);
        for (long long v : f.corners) c += P[v];
        if (!f.corners.empty()) c /= double(f.corners.size());
        const bool current = on_faces && int(k) == s.face;
        if (!f.defined) {
            if (current) scene.labels3.push_back({c, "no normal (area 0)", {Role::Discarded}, 2});
            continue;
        }
        Segment3 n{c, c + len * f.normal, labels ? "n" + std::to_string(k) : "", {}, true};
        if (current) {
            n.style = {Role::Active, 3.f};
            n.min_pixels = 30;
            n.priority = 2;
        } else if (on_faces || around[k]) {
            n.style = {Role::Neutral, 2.f};
            n.priority = on_faces ? -1 : 0;
        } else {
            n.style = {Role::Construction, 1.5f};
            n.label.clear();
        }
        if (on_faces) frame(n.b);
        scene.segments3.push_back(std::move(n));
    }
    // The vertices, and their three normals once worked out.
    constexpr float kWidth[3] = {6.f, 4.f, 2.f};  // nested: where they agree, all three show
    for (std::size_t v = 0; v < P.size(); ++v) {
        const bool current = on_vertex && int(v) == s.vertex;
        const bool focus = p.has_focus && p.focus_vertex == static_cast<long long>(v);
        scene.points3.push_back({P[v],
                                 labels || current ? vname(v) : "",
                                 {current ? Role::Active : Role::Neutral},
                                 current ? 7.f : 4.f,
                                 current ? 2 : -1});
        if (current) {  // the vertex, its normals' reach, and its faces up to a little beyond
            frame(P[v] - dvec3(len)), frame(P[v] + dvec3(len));
            for (std::size_t k = 0; k < p.corners.size(); ++k)
                if (around[k])
                    for (long long q : p.corners[k]) {
                        const double d = glm::length(P[q] - P[v]);
                        frame(d > 1.2 * len ? P[v] + (P[q] - P[v]) * (1.2 * len / d) : P[q]);
                    }
        }
        if (static_cast<int>(v) >= static_cast<int>(s.vertices.size())) continue;
        const VertexSums& vs = s.vertices[v];
        for (int w = 0; w < 3; ++w) {
            if (!vs.normal[w]) continue;
            const dvec3 tip = P[v] + (1.2 * len) * *vs.normal[w];
            Segment3 arrow{P[v], tip, "", {kRole[w], current ? kWidth[w] : kWidth[w] / 2}, true};
            if (current) arrow.min_pixels = 30, frame(tip);
            scene.segments3.push_back(arrow);
        }
        // One label per direction, at the tip of the first weighting that points that way: all
        // of them at the current vertex, and the one the preset asks about (with its value).
        bool labelled[3] = {false, false, false};
        for (int w = 0; w < 3; ++w) {
            if (!vs.normal[w] || labelled[w]) continue;
            bool asked = false;
            int names = 0;
            std::string text;
            for (int o = w; o < 3; ++o)
                if (vs.normal[o] && glm::length(*vs.normal[o] - *vs.normal[w]) < 1e-9) {
                    labelled[o] = true;
                    asked = asked || (focus && int(p.focus_weighting) == o);
                    text += (names++ ? " = " : "") + std::string(weighting_id(Weighting(o)));
                }
            if (!current && !asked) continue;
            if (names == 3) text = "all three";
            if (asked) text += " " + num(*vs.normal[w], 3);
            scene.labels3.push_back(
                {P[v] + (1.2 * len) * *vs.normal[w], text, {kRole[w]}, current ? 2 : 0});
        }
        if (current && vs.faces.empty())
            scene.labels3.push_back({P[v], "no faces: normal undefined", {Role::Discarded}, 2});
    }
    if (focus_lo.x <= focus_hi.x) add_focus(scene, focus_lo, focus_hi);
}

}  // namespace cg
