// The picture of subdivision: the mesh being subdivided as translucent faces, the new points as
// they are made — face points teal, edge points magenta, moved vertices orange — and the rule of
// this step for one point: dashed lines from each point it averages, each labelled with its
// weight; the camera is framed on that rule. After a level is joined, the finer mesh in green
// with its new vertices marked.
#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "modelling/subdivision_surface.hpp"

namespace cg {

namespace {

using S = SubdivisionSurface;
using glm::dvec3;

constexpr std::size_t kLabelledFaces = 24;  // above this many faces, points go unlabelled

// The rule for one point: dashed lines from each point it averages, labelled with its weight.
// The camera frames the stencil, with at least `context` around it (a small stencil of a fine
// mesh is seen with the surface it sits on).
void stencil(const S::Stencil& st, dvec3 target, const std::string& name, double context,
             Scene& scene) {
    dvec3 lo = target, hi = target;
    for (const dvec3& p : st.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const dvec3 c = (lo + hi) / 2.0, half = glm::max((hi - lo) / 2.0, dvec3(context));
    add_focus(scene, c - half, c + half);
    for (std::size_t i = 0; i < st.points.size(); ++i) {
        if (st.points[i] != target)
            scene.segments3.push_back(
                {st.points[i], target, "", {Role::Construction, 1.5f, true}, false});
        scene.points3.push_back({st.points[i],
                                 st.names[i] + " ×" + subdivision_weight(st.weights[i]),
                                 {Role::Window},
                                 5.f});
    }
    scene.points3.push_back({target, name, {Role::Active}, 8.f, 20});
}

}  // namespace

void SubdivisionSurface::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Mesh& m = s.mesh;
    const auto& P = m.vertices;
    const bool joined = s.last == Phase::Connect || s.last == Phase::Summary ||
                        s.phase == Phase::Done || (s.level > 0 && s.phase == Phase::Split);
    const bool labels = m.faces.size() <= kLabelledFaces;
    const bool working = !joined && s.phase != Phase::Split;  // a level under way
    const int shown_face = working && s.last == Phase::FacePoints ? subdivision_shown_face(s) : -1;

    scene.faces3.reserve(m.faces.size());
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        Face3 f;
        for (int v : m.faces[k]) f.points.push_back(P[std::size_t(v)]);
        const bool current = int(k) == shown_face;
        f.style.role = current ? Role::Active : joined ? Role::Kept : Role::Subject;
        f.alpha = current ? 0.45f : 0.22f;
        scene.faces3.push_back(std::move(f));
    }
    // The vertices: after a join, the new ones (every index past the old count) in teal.
    const long long old_v = joined && s.counts.size() >= 2 ? s.counts[s.counts.size() - 2].V
                                                           : (long long)P.size();
    if (P.size() <= 5000)
        for (std::size_t v = 0; v < P.size(); ++v) {
            const bool added = (long long)v >= old_v;
            scene.points3.push_back({P[v],
                                     labels && !working ? "V" + std::to_string(v) : "",
                                     {added ? Role::Entering : Role::Neutral},
                                     added ? 3.5f : 3.f});
        }
    dvec3 lo = P[0], hi = P[0];
    for (const auto& p : P) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double size = std::max(glm::length(hi - lo), 1e-300);
    const double context = 0.2 * size;
    if (working) {
        for (std::size_t k = 0; k < s.points.face.size(); ++k)
            scene.points3.push_back({s.points.face[k], "", {Role::Entering}, 4.5f});
        for (std::size_t e = 0; e < s.points.edge.size(); ++e)
            scene.points3.push_back({s.points.edge[e], "", {Role::Leaving}, 4.5f});
        for (std::size_t v = 0; v < s.points.vertex.size(); ++v)
            scene.points3.push_back({s.points.vertex[v], "", {Role::Active}, 4.5f});
        // This step's rule for one point, with its weights.
        if (s.last == Phase::FacePoints) {
            const int f = shown_face;
            Stencil st;
            for (int v : m.faces[std::size_t(f)]) {
                st.points.push_back(P[std::size_t(v)]);
                st.weights.push_back(1.0 / double(m.faces[std::size_t(f)].size()));
                st.names.push_back("V" + std::to_string(v));
            }
            stencil(st, s.points.face[std::size_t(f)], "F" + std::to_string(f), context, scene);
        } else if (s.last == Phase::EdgePoints) {
            const int e = subdivision_shown_edge(s);
            stencil(edge_stencil(in.scheme, m, s.topo, s.points.face, e),
                    s.points.edge[std::size_t(e)], "E" + std::to_string(e), context, scene);
        } else if (s.last == Phase::VertexPoints) {
            const int v = subdivision_shown_vertex(in);
            stencil(vertex_stencil(in.scheme, m, s.topo, s.points.face, v),
                    s.points.vertex[std::size_t(v)], "V" + std::to_string(v) + "'", context,
                    scene);
        }
    }
    // The caption under the mesh, centred, so it stays on the canvas.
    const std::string scheme = in.scheme == Scheme::Loop ? "Loop" : "Catmull–Clark";
    const std::string caption =
        working ? scheme + " level " + std::to_string(s.level + 1) + ": " +
                      (in.scheme == Scheme::Loop ? "" : "face points teal, ") +
                      "edge points magenta, vertices moved orange"
                : scheme + ", level " + std::to_string(s.level) + ": " +
                      std::to_string(m.vertices.size()) + " vertices, " +
                      std::to_string(m.faces.size()) + " faces" +
                      (joined && s.level > 0 ? " (new vertices teal)" : "");
    // The colours' key: placed before the stencil's weights, so it is not the one shortened.
    scene.labels3.push_back({dvec3(0.5 * (lo.x + hi.x), lo.y - 0.12 * size, 0.5 * (lo.z + hi.z)),
                             caption,
                             {Role::Neutral},
                             1});
}

}  // namespace cg
