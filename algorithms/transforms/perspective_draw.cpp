// The projection pipeline, the picture. 3D, in world coordinates: the view frustum (translucent
// faces between the near and far planes), the eye with its look-at frame as three short arrows
// r, u, f̂ (the narration's names; f̂ the view direction, whatever the convention's sign of z;
// without a look-at the view frame is the world's, and the world's axes say it),
// the points with their rays to the eye and where the rays cross the near plane, and the
// segments with the part the near plane cuts off. 2D beside it: the NDC square with the
// projected points and the kept parts of the segments.
//
// The camera looks at the frustum from its side, a little from behind the eye and above
// (orthographic), so the frustum opens to the right with the eye at its apex on the left and a
// ray's crossing of the near plane shows as similar triangles; it frames the eye, the points and
// the frustum as deep as they reach. From the default camera the frustum opened toward the
// viewer and the eye's labels sat on each other.
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "transforms/perspective.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using Convention = Perspective::Convention;
using Phase = Perspective::Phase;
using Status = Perspective::SegmentStatus;

constexpr double kPi = 3.14159265358979323846;
// The world axes' colours (as the viewer draws a frame), for the camera's own r, u, f̂.
constexpr std::uint32_t kAxisColour[3] = {0xd62728ff, 0x2ca02cff, 0x1f77b4ff};

struct Frame {
    dvec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, 1}, eye{0, 0, 0};
};

// The view frame from the view matrix (rows r, u, ±f̂, each with the translation −row · eye).
Frame frame_of(const Perspective::Input& in) {
    const dmat4 v = Perspective::view_matrix(in);
    auto row = [&](int i) { return dvec3(v[0][i], v[1][i], v[2][i]); };
    Frame f;
    f.right = row(0), f.up = row(1);
    f.forward = (in.convention == Convention::Course ? 1.0 : -1.0) * row(2);
    f.eye = -(v[3][0] * row(0) + v[3][1] * row(1) + v[3][2] * row(2));
    return f;
}

dvec3 apply_affine(const dmat4& m, dvec3 p) {
    return dvec3(m * dvec4(p, 1.0));
}

std::string point_name(int k) {
    return "P" + std::to_string(k);
}

}  // namespace

void Perspective::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Frame fr = frame_of(in);
    // The frustum's x and y range per unit depth: symmetric for the fov form, the near
    // rectangle over n for the frustum form (glFrustum's l, r, b, t).
    const double ty = std::tan(in.fov_y_deg * kPi / 360), tx = ty * in.aspect;
    const double x_lo = in.has_frustum ? in.left / in.near : -tx;
    const double x_hi = in.has_frustum ? in.right / in.near : tx;
    const double y_lo = in.has_frustum ? in.bottom / in.near : -ty;
    const double y_hi = in.has_frustum ? in.top / in.near : ty;
    auto at_depth = [&](double x, double y, double depth) {  // corner (±1, ±1) to world
        const double u = x < 0 ? x_lo : x_hi, v = y < 0 ? y_lo : y_hi;
        return fr.eye + depth * (u * fr.right + v * fr.up + fr.forward);
    };
    // The far plane can be far away; draw the frustum to the farthest point shown, if nearer.
    double depth_shown = in.far;
    double reach = in.near;
    for (const dvec3 p : in.points) {
        const dvec3 w = apply_affine(in.model, p);
        reach = std::max(reach, glm::dot(w - fr.eye, fr.forward));
    }
    for (const auto& seg : in.segments)
        for (const dvec3 p : seg)
            reach = std::max(reach, glm::dot(apply_affine(in.model, p) - fr.eye, fr.forward));
    const bool cut_far = in.far > 4 * reach;
    if (cut_far) depth_shown = 1.25 * reach;

    // What the camera frames: the eye, the frustum as deep as the farthest point (a far plane
    // far beyond the points would shrink them), the points and the segments.
    dvec3 lo = fr.eye, hi = fr.eye;
    auto frame = [&](dvec3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); };

    const std::array<dvec2, 4> corners = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
    std::vector<dvec3> near_quad, far_quad;
    for (const dvec2 c : corners) {
        near_quad.push_back(at_depth(c.x, c.y, in.near));
        far_quad.push_back(at_depth(c.x, c.y, depth_shown));
        frame(near_quad.back());
        frame(at_depth(c.x, c.y, std::min(depth_shown, 1.15 * reach)));
    }
    scene.faces3.push_back({near_quad, {Role::Window, 1.5f}, 0.25f, true, true});
    scene.faces3.push_back({far_quad, {Role::Window, 1.0f, cut_far}, 0.08f, true, true});
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        scene.faces3.push_back({{near_quad[i], near_quad[j], far_quad[j], far_quad[i]},
                                {Role::Window, 1.0f},
                                0.08f,
                                true,
                                true});
    }
    scene.labels3.push_back({near_quad[2], "near " + num(in.near), {Role::Window}});
    scene.labels3.push_back({far_quad[2],
                             cut_far ? "far " + num(in.far) + " (cut short)" : "far " + num(in.far),
                             {Role::Window}});
    // The eye and its look-at frame: r, u, f̂, short, in the axes' colours. Without a look-at
    // the view frame is the world's, whose axes the viewer draws at the eye already.
    const double axis_len = std::max(0.5 * in.near, 0.15 * depth_shown);
    const dvec3 axes[3] = {fr.right, fr.up, fr.forward};
    static const char* const kAxisName[3] = {"r", "u", "f̂"};
    for (int i = 0; i < 3 && in.look_at; ++i) {
        Segment3 a{fr.eye, fr.eye + axis_len * axes[i], kAxisName[i], {Role::Neutral, 2.5f}, true};
        a.style.rgba = kAxisColour[i];
        a.min_pixels = 30;
        a.priority = -1;
        scene.segments3.push_back(a);
    }
    scene.points3.push_back({fr.eye, "eye", {Role::Neutral}, 5.0f, 1});

    // The points.
    const int n = static_cast<int>(in.points.size());
    const bool points_phase =
        s.last >= Phase::PointView && s.last <= Phase::PointDevice && s.phase != Phase::Model;
    const int shown = static_cast<int>(s.r.world.size());
    for (int k = 0; k < n; ++k) {
        const bool active = points_phase && k == s.k && s.phase != Phase::Done;
        const dvec3 w = k < shown ? s.r.world[k] : apply_affine(in.model, in.points[k]);
        frame(w);
        const bool known = k < static_cast<int>(s.r.clip.size());
        const Role role = active          ? Role::Active
                          : !known        ? Role::Subject
                          : s.r.inside[k] ? Role::Kept
                                          : Role::Discarded;
        scene.points3.push_back({w, point_name(k), {role}, active ? 6.0f : 5.0f, active ? 2 : 0});
        scene.segments3.push_back(
            {w, fr.eye, "", {active ? Role::Active : Role::Construction, 1.0f, true}, false});
        const double depth = glm::dot(w - fr.eye, fr.forward);
        if (depth >= in.near)  // the ray to the eye crosses the near plane
            scene.points3.push_back({fr.eye + (w - fr.eye) * (in.near / depth), "", {role}, 3.0f});
    }

    // The segments: the kept part green, the dropped part red, once clipped.
    const int clipped = static_cast<int>(s.r.segments.size());
    for (int k = 0; k < static_cast<int>(in.segments.size()); ++k) {
        const dvec3 a = apply_affine(in.model, in.segments[k][0]);
        const dvec3 b = apply_affine(in.model, in.segments[k][1]);
        frame(a), frame(b);
        const bool active = (s.last == Phase::SegmentClip || s.last == Phase::SegmentDivide) &&
                            k == s.j && s.phase != Phase::Done;
        if (k >= clipped) {
            scene.segments3.push_back({a, b, "", {Role::Subject, 2.0f}, false});
            continue;
        }
        const Segment& g = s.r.segments[k];
        const float width = active ? 3.0f : 2.0f;
        if (g.status == Status::Rejected) {
            scene.segments3.push_back({a, b, "", {Role::Discarded, width}, false});
            continue;
        }
        const dvec3 p0 = a + g.t0 * (b - a), p1 = a + g.t1 * (b - a);
        scene.segments3.push_back({p0, p1, "", {active ? Role::Active : Role::Kept, width}, false});
        if (g.t0 > 0) scene.segments3.push_back({a, p0, "", {Role::Discarded, width, true}, false});
        if (g.t1 < 1) scene.segments3.push_back({p1, b, "", {Role::Discarded, width, true}, false});
        if (g.status == Status::Clipped)
            scene.points3.push_back({g.t0 > 0 ? p0 : p1, "cut", {Role::Entering}, 5.0f});
    }
    add_focus(scene, lo, hi);
    // Seen from the frustum's side (f̂ × y: the frustum then opens to the right on screen), a
    // little from behind the eye and from above.
    const dvec3 world_up(0, 1, 0);
    dvec3 side = glm::cross(fr.forward, world_up);
    side = glm::length(side) > 1e-6 ? glm::normalize(side) : fr.right;
    scene.view3 = {-glm::normalize(side + 0.45 * world_up - 0.7 * fr.forward), world_up, true};

    // 2D: the NDC square and the images.
    scene.polygons.push_back(
        {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, {Role::Window, 2.0f}, true, false});
    scene.segments.push_back({{-1, 0}, {1, 0}, "", {Role::Construction, 1.0f, true}, false});
    scene.segments.push_back({{0, -1}, {0, 1}, "", {Role::Construction, 1.0f, true}, false});
    scene.labels.push_back({{0, 1}, "NDC [−1, 1]² (x, y)", {Role::Window}});
    for (int k = 0; k < static_cast<int>(s.r.ndc.size()); ++k) {
        if (!s.r.ndc[k]) continue;
        const dvec3 q = *s.r.ndc[k];
        if (std::fabs(q.x) > 5 || std::fabs(q.y) > 5) continue;  // far off the square
        const bool active = points_phase && k == s.k && s.phase != Phase::Done;
        scene.points.push_back({dvec2(q),
                                point_name(k) + (active ? " " + num(q, 3) : ""),
                                {active          ? Role::Active
                                 : s.r.inside[k] ? Role::Kept
                                                 : Role::Discarded},
                                active ? 6.0f : 5.0f});
    }
    for (int k = 0; k < clipped; ++k) {
        const Segment& g = s.r.segments[k];
        const bool divided =
            k < s.j || (k == s.j && (s.last == Phase::SegmentDivide || s.phase == Phase::Done));
        if (g.status == Status::Rejected || !divided) continue;
        scene.segments.push_back(
            {dvec2(g.ndc[0]),
             dvec2(g.ndc[1]),
             "segment " + std::to_string(k),
             {k == s.j && s.phase != Phase::Done ? Role::Active : Role::Kept, 2.0f},
             false});
    }
}

}  // namespace cg
