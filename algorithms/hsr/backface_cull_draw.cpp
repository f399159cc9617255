// Back-face culling, the picture (3D). Each face is filled by its verdict: kept green, culled
// faint grey, undecided fainter still, the face being decided orange. A decided face carries its
// outward unit normal with one short label at the arrow's tip ("F3 kept", "F0 culled"), so the
// labels spread out with the normals instead of piling up on the cube; the face being decided
// shows its N (thick, at least 30 px) and its view vector V from the eye to its first corner P₀
// (in a parallel view, V is the viewing direction, drawn into P₀). The viewer is the eye's dot,
// or the viewing direction as an arrow beside the mesh.
//
// The camera frames the mesh, the eye and the current N together and looks at them from 60°
// round the vertical from the eye's side (a view hint, orthographic so the mesh is not shrunk by
// the depth the eye adds): from the default camera the eye sat almost where the camera is and
// its dot landed on the mesh.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "hsr/backface_cull.hpp"

namespace cg {

namespace {

// A camera direction that sees the mesh and the viewer `toward` (unit, from the mesh to the
// viewer) apart: 60° round the vertical from the viewer's side (toward the front, +z), 25° above
// the floor, so the faces that look at the viewer still show their fronts and the eye's dot
// lands well beside the mesh, not on it. Never along a cube's diagonal, where a cube turns into
// an ambiguous hexagon.
glm::dvec3 side_look(glm::dvec3 toward) {
    constexpr double kPi = 3.14159265358979323846;
    const double az = std::hypot(toward.x, toward.z) > 1e-6 ? std::atan2(toward.x, toward.z) : 0;
    const double cam = az > 0 ? az - kPi / 3 : az + kPi / 3, el = 25 * kPi / 180;
    return -glm::dvec3(std::cos(el) * std::sin(cam), std::sin(el), std::cos(el) * std::cos(cam));
}

}  // namespace

void BackfaceCull::draw(const State& s, Scene& scene) {
    const auto& in = *s.in;
    const int decided = static_cast<int>(s.r.culled.size());
    const int current = s.last == Phase::Face && s.k > 0 ? s.k - 1 : -1;  // the face just decided
    const bool finished = s.phase == Phase::Done;
    const bool first = decided == 0;

    glm::dvec3 lo = in.vertices[0], hi = in.vertices[0], mid{0, 0, 0};
    for (const auto& p : in.vertices) lo = glm::min(lo, p), hi = glm::max(hi, p), mid += p;
    mid /= static_cast<double>(in.vertices.size());
    const double size = std::max(glm::length(hi - lo), 1e-9);

    auto centroid = [&](const std::vector<int>& f) {
        glm::dvec3 c{0, 0, 0};
        for (int i : f) c += in.vertices[static_cast<std::size_t>(i)];
        return c / static_cast<double>(f.size());
    };
    // What the camera frames: the mesh, the viewer, the normals' tips (one focus element, so
    // the mesh is the element measured, not a lone point).
    glm::dvec3 focus_lo = lo, focus_hi = hi;
    auto frame = [&](glm::dvec3 p) {
        focus_lo = glm::min(focus_lo, p), focus_hi = glm::max(focus_hi, p);
    };
    // Labels and normals only while they stay readable.
    const bool small = in.faces.size() <= 40;

    for (std::size_t k = 0; k < in.faces.size(); ++k) {
        const auto& f = in.faces[k];
        Face3 face;
        for (int i : f) face.points.push_back(in.vertices[static_cast<std::size_t>(i)]);
        const bool is_decided = static_cast<int>(k) < decided;
        const bool culled = is_decided && s.r.culled[k];
        const bool is_current = static_cast<int>(k) == current;
        Role role = Role::Neutral;
        face.alpha = 0.08f;
        if (is_decided)
            role = culled ? Role::Subject : Role::Kept, face.alpha = culled ? 0.12f : 0.45f;
        if (is_current) role = Role::Active, face.alpha = 0.6f;
        face.style = {role, 1.5f};
        scene.faces3.push_back(std::move(face));
        if (!small) continue;
        const glm::dvec3 c = centroid(f);
        const std::string name = "F" + std::to_string(k);
        if (is_current) {  // named at its centre; its N is drawn below
            scene.labels3.push_back({c, name + (culled ? " culled" : " kept"), {role}, 2});
        } else if (is_decided) {  // its normal, named at the tip
            const glm::dvec3 n = s.r.normals[k];
            scene.segments3.push_back({c, c + 0.22 * size * n, "", {role, 1.5f}, true});
            scene.labels3.push_back(
                {c + 0.27 * size * n, name + (culled ? " culled" : " kept"), {role}});
            frame(c + 0.27 * size * n);
        } else {
            scene.labels3.push_back({c, name, {Role::Neutral}, -1});
        }
    }

    // The corners: all numbered at the start (the faces are lists of them), then the numbers
    // of the face being decided only, whose first corner P₀ is where V ends.
    if (in.vertices.size() <= 60) {
        std::vector<bool> named(in.vertices.size(), first && small);
        if (current >= 0 && !finished)
            for (int i : in.faces[static_cast<std::size_t>(current)])
                named[static_cast<std::size_t>(i)] = true;
        for (std::size_t i = 0; i < in.vertices.size(); ++i)
            scene.points3.push_back(
                {in.vertices[i], named[i] ? std::to_string(i) : "", {Role::Neutral}, 3.0f, -1});
    }

    // The face being decided: its normal from its centroid, and its view vector into P₀.
    if (current >= 0 && !finished) {
        const auto& f = in.faces[static_cast<std::size_t>(current)];
        const glm::dvec3 c = centroid(f);
        const glm::dvec3 u = s.r.normals[static_cast<std::size_t>(current)];
        Segment3 n{c, c + 0.45 * size * u, "N", {Role::Active, 3.0f}, true};
        n.min_pixels = 30;
        n.priority = 2;
        scene.segments3.push_back(n);
        frame(n.b);
        const glm::dvec3 p0 = in.vertices[static_cast<std::size_t>(f[0])];
        const glm::dvec3 from =
            in.perspective ? in.eye : p0 - 0.45 * size * glm::normalize(in.view_dir);
        scene.segments3.push_back({from, p0, "V", {Role::Window, 1.5f, true}, true, 0, 1});
    }

    // The viewer, framed with the mesh, seen from the side of the line between them.
    if (in.perspective) {
        scene.points3.push_back({in.eye, "eye " + num(in.eye, 4), {Role::Window}, 6.0f, 1});
        frame(in.eye);
        const glm::dvec3 toward = in.eye - mid;
        if (glm::length(toward) > 1e-9)
            scene.view3 = {side_look(glm::normalize(toward)), {0, 1, 0}, true};
    } else {
        const glm::dvec3 d = glm::normalize(in.view_dir);
        const glm::dvec3 tail = mid - 0.9 * size * d;
        scene.segments3.push_back({tail,
                                   mid - 0.45 * size * d,
                                   "view direction " + num(in.view_dir, 4),
                                   {Role::Window, 2.5f},
                                   true,
                                   0,
                                   1});
        frame(tail);
        scene.view3 = {side_look(-d), {0, 1, 0}, true};
    }
    add_focus(scene, focus_lo, focus_hi);
}

}  // namespace cg
