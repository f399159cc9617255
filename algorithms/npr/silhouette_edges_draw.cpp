// Silhouette edges, the picture. Front faces filled in their toon band's colour, back faces
// faint grey (not yet classified: fainter still); silhouette edges thick magenta, boundary
// edges dashed blue; the eye. While classifying faces: the face outlined orange, its normal N̂
// (at least 30 px) and the vector P₀ − E from the eye, whose dot product decides; while
// testing edges: the edge orange and its two faces outlined. The view is from the side of the
// eye's line of sight (from the eye itself the eye would sit on the mesh and the loop would be
// only an outline), and the camera is framed on the face and the eye, or on the edge's faces.
// The finished silhouette is seen from the eye: the outline a cartoon renderer draws.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "core/vec.hpp"
#include "npr/silhouette_edges.hpp"
#include "npr/toon_shading.hpp"

namespace cg {

namespace {

std::string edge_label(int a, int b) {
    return "P" + std::to_string(std::min(a, b)) + "P" + std::to_string(std::max(a, b));
}

}  // namespace

void SilhouetteEdges::draw(const State& s, Scene& scene) {
    const auto& in = *s.in;
    const auto& m = in.mesh;
    const auto colours = ToonShading::default_colours(static_cast<int>(in.thresholds.size()) + 1);
    const glm::dvec3 l = unit(in.light);
    const int classified = static_cast<int>(s.r.front.size());
    const bool small = m.faces.size() <= 24;
    // (Not a structured binding: clang, which builds the browser's copy, will not let the
    // lambdas below capture one.)
    const std::pair<glm::dvec3, double> extent = npr::bounds(m);
    const glm::dvec3 mid = extent.first;
    const double size = extent.second;
    auto P = [&](int i) { return m.vertices[static_cast<std::size_t>(i)]; };
    auto face_points = [&](int k) {
        std::vector<glm::dvec3> out;
        for (int i : m.faces[static_cast<std::size_t>(k)]) out.push_back(P(i));
        return out;
    };
    auto outline = [&](int k, Role role, float width) {
        Face3 o;
        o.points = face_points(k);
        o.style = {role, width};
        o.alpha = 0.0f;
        scene.faces3.push_back(std::move(o));
    };
    // The points, and at least 0.6 of the mesh's size around them: a small face of a fine mesh
    // is seen with the surface it sits in.
    auto focus_on = [&](const std::vector<glm::dvec3>& points) {
        glm::dvec3 lo = points.front(), hi = points.front();
        for (const glm::dvec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const glm::dvec3 c = (lo + hi) / 2.0, half = glm::max((hi - lo) / 2.0, glm::dvec3(0.3 * size));
        add_focus(scene, c - half, c + half);
    };

    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        const auto& f = m.faces[k];
        Face3 face;
        face.points = face_points(static_cast<int>(k));
        face.outline = small;
        if (static_cast<int>(k) >= classified) {
            face.style = {Role::Neutral, 1.0f};
            face.alpha = 0.06f;
        } else if (s.r.front[k]) {
            const double d = std::max(0.0, glm::dot(unit(npr::newell(m.vertices, f)), l));
            const int b = ToonShading::band_of(d, in.thresholds);
            face.style = {Role::Subject, 1.0f, false,
                          pack_rgba(colours[static_cast<std::size_t>(b)])};
            face.alpha = 1.0f;
        } else {
            face.style = {Role::Subject, 1.0f};
            face.alpha = 0.15f;
        }
        scene.faces3.push_back(std::move(face));
    }
    // Magenta rather than a cartoon's black: it must stand out against the darkest band too.
    for (const auto& e : s.r.silhouette)
        scene.segments3.push_back({P(e[0]), P(e[1]), "", {Role::Leaving, 5.0f}});
    for (const auto& e : s.r.boundary)
        scene.segments3.push_back({P(e[0]), P(e[1]), "", {Role::Window, 2.0f, true}});
    if (s.last == Phase::Edge && s.phase != Phase::Done) {
        const int k = s.phase == Phase::Edge ? s.k - 1 : static_cast<int>(s.edges->size()) - 1;
        const Edge& e = (*s.edges)[static_cast<std::size_t>(k)];
        Segment3 edge{P(e.a), P(e.b), small ? edge_label(e.a, e.b) : "", {Role::Active, 6.0f}};
        edge.priority = 20;
        scene.segments3.push_back(edge);
        std::vector<glm::dvec3> around = face_points(e.f);
        outline(e.f, Role::Active, 2.0f);
        if (e.g >= 0) {
            outline(e.g, Role::Active, 2.0f);
            for (const glm::dvec3& p : face_points(e.g)) around.push_back(p);
        }
        focus_on(around);
    }
    if (s.last == Phase::Face && s.phase != Phase::Done && classified > 0) {
        const int k = classified - 1;
        const auto& f = m.faces[static_cast<std::size_t>(k)];
        const glm::dvec3 p0 = P(f[0]);
        Segment3 sight{in.eye, p0, "P₀ − E", {Role::Window, 1.5f, true}, true};
        scene.segments3.push_back(sight);
        outline(k, Role::Active, 3.0f);
        std::vector<glm::dvec3> pts = face_points(k);
        glm::dvec3 c{0};
        for (const glm::dvec3& p : pts) c += p;
        c /= double(pts.size());
        Segment3 n{c, c + 0.25 * size * unit(npr::newell(m.vertices, f)), "N̂",
                   {Role::Active, 3.0f}, true};
        n.min_pixels = 30;
        n.priority = 20;
        scene.segments3.push_back(n);
        pts.push_back(in.eye);
        pts.push_back(n.b);
        focus_on(pts);
    }
    if (m.vertices.size() <= 12)
        for (std::size_t i = 0; i < m.vertices.size(); ++i)
            scene.points3.push_back(
                {m.vertices[i], "P" + std::to_string(i), {Role::Neutral}, 3.0f, -10});
    const glm::dvec3 up{0, 1, 0};
    glm::dvec3 e = unit(in.eye - mid);
    if (glm::length(e) == 0) e = {0, 0, 1};
    if (s.phase == Phase::Done) {
        // The result as the eye sees it: the silhouette is the outline.
        scene.view3 = {-e, glm::length(glm::cross(up, e)) < 1e-6 ? glm::dvec3(0, 0, -1) : up,
                       false};
        return;
    }
    scene.points3.push_back({in.eye, "eye", {Role::Window}, 6.0f});
    // While classifying, seen from the side of the line of sight, a little from above.
    glm::dvec3 side = glm::cross(up, e);
    side = glm::length(side) < 1e-6 ? glm::dvec3(1, 0, 0) : unit(side);
    const glm::dvec3 from = unit(0.75 * e + 0.6 * side + 0.3 * up);
    scene.view3 = {-from, up, false};
}

}  // namespace cg
