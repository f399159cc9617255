// Virtual sphere and arcball, the picture. Two views.
//
// 2D, in the viewport's pixels: the ball's disc, its centre, the mouse path (the pairs done
// green, those to come dashed grey, each leg an arrow in the direction the mouse went), the
// current pair S → T (for the virtual sphere T − S is the motion v) and, at the end, the
// straight stroke from the first sample to the last. A drag is often small beside the ball (a
// 30 px loop in a 300 px ball), so the view is a window onto the viewport round the path and
// the ball's centre — the disc, its rim and the viewport's edges clipped to it, the grid still
// in pixels — unless the path covers most of the viewport anyway.
//
// 3D, in ball units: the sphere (its rim as the viewer sees it, two meridians), s and t on it,
// the pair's axis, the object turned by the drag's rotation so far, and the trail of the ball's
// front point R·(0, 0, 1). The camera frames the ball.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "clipping/liang_barsky.hpp"
#include "core/format.hpp"
#include "transforms/trackball_drag.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dquat;
using glm::dvec2;
using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kSameDeg = 1e-6;  // below this a rotation is no rotation

dquat canonical(dquat q) {
    if (q.w < 0) q = -q;
    return q;
}

std::string sample_name(int k) {
    return "S" + std::to_string(k);
}

// A circle of radius r in the plane spanned by unit vectors u, v about the origin, as segments.
void circle3(Scene& scene, dvec3 u, dvec3 v, double r, Style style, int n = 48) {
    for (int i = 0; i < n; ++i) {
        const double a = 2 * kPi * i / n, b = 2 * kPi * (i + 1) / n;
        scene.segments3.push_back({r * (std::cos(a) * u + std::sin(a) * v),
                                   r * (std::cos(b) * u + std::sin(b) * v), "", style, false});
    }
}

// The great-circle arc from unit a to unit b (the shorter one), as segments.
void arc3(Scene& scene, dvec3 a, dvec3 b, Style style, int n = 24) {
    const double angle = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
    if (angle < 1e-9) return;
    dvec3 prev = a;
    for (int i = 1; i <= n; ++i) {
        const double f = static_cast<double>(i) / n;
        const dvec3 p = (std::sin((1 - f) * angle) * a + std::sin(f * angle) * b) / std::sin(angle);
        scene.segments3.push_back({prev, p, "", style, false});
        prev = p;
    }
}

struct Window {
    dvec2 lo, hi;
    bool inside(dvec2 p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
};

// The convex polygon `poly` clipped to the window (Sutherland–Hodgman, one edge at a time).
std::vector<dvec2> clip_to(std::vector<dvec2> poly, const Window& w) {
    for (int edge = 0; edge < 4; ++edge) {
        const int axis = edge % 2;
        const double bound = edge < 2 ? w.lo[axis] : w.hi[axis];
        const auto in = [&](dvec2 p) { return edge < 2 ? p[axis] >= bound : p[axis] <= bound; };
        std::vector<dvec2> out;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
            if (in(a)) out.push_back(a);
            if (in(a) != in(b))
                out.push_back(a + (b - a) * ((bound - a[axis]) / (b[axis] - a[axis])));
        }
        poly = std::move(out);
        if (poly.empty()) break;
    }
    return poly;
}

}  // namespace

template <TrackballKind K>
void TrackballDrag<K>::draw(const State& st, Scene& scene) {
    const dvec2 vp = st.in.viewport, c = vp * 0.5;
    const double d = std::min(vp.x, vp.y);
    const int n = static_cast<int>(st.in.samples.size());
    // After S is mapped the next phase is MapT, after T Rotate, after the pair's rotation
    // Accumulate: the phase to come says how far the current pair has got.
    const bool mapped_s =
        st.phase == Phase::MapT || st.phase == Phase::Rotate || st.phase == Phase::Accumulate;
    const bool mapped_t = st.phase == Phase::Rotate || st.phase == Phase::Accumulate;

    // ---- 2D: the viewport, or a window onto it round the path ----
    Window win{c, c};
    for (const dvec2& p : st.in.samples) win.lo = glm::min(win.lo, p), win.hi = glm::max(win.hi, p);
    const dvec2 span = win.hi - win.lo;
    const double margin = std::max({15.0, 0.25 * std::max(span.x, span.y), 0.08 * d});
    win.lo = glm::max(win.lo - margin, dvec2(-10)), win.hi = glm::min(win.hi + margin, vp + 10.0);
    const dvec2 size = win.hi - win.lo;
    const bool whole = size.x * size.y >= 0.6 * vp.x * vp.y;
    if (whole) win = {dvec2(-10), vp + 10.0};

    std::vector<dvec2> disc;
    for (int i = 0; i < 96; ++i)
        disc.push_back(c + 0.5 * d * dvec2(std::cos(2 * kPi * i / 96), std::sin(2 * kPi * i / 96)));
    if (whole) {
        scene.polygons.push_back(
            {{{0, 0}, {vp.x, 0}, vp, {0, vp.y}}, {Role::Window, 2.0f}, true, false});
        scene.polygons.push_back({disc, {Role::Neutral, 1.5f}, true, true});
        scene.labels.push_back(
            {{c.x, c.y + 0.5 * d}, "the ball (diameter " + num(d) + " px)", {Role::Neutral}});
    } else {
        // The disc's part in the window, filled without an outline of its own; the rim where it
        // passes through; the viewport's edges where they do.
        const std::vector<dvec2> part = clip_to(disc, win);
        if (part.size() >= 3)
            scene.polygons.push_back({part, {Role::Neutral, 0.5f, false, 0x7f7f7f40}, true, true});
        std::vector<dvec2> run;
        for (int i = 0; i <= 96; ++i) {
            const dvec2 p = disc[static_cast<std::size_t>(i % 96)];
            if (win.inside(p)) {
                run.push_back(p);
                continue;
            }
            if (run.size() >= 2)
                scene.polygons.push_back({run, {Role::Neutral, 1.5f}, false, false});
            run.clear();
        }
        if (run.size() >= 2) scene.polygons.push_back({run, {Role::Neutral, 1.5f}, false, false});
        const dvec2 corner[4] = {{0, 0}, {vp.x, 0}, vp, {0, vp.y}};
        for (int i = 0; i < 4; ++i) {
            dvec2 a = corner[i], b = corner[(i + 1) % 4];
            if (LiangBarsky::clip_segment({win.lo.x, win.lo.y, win.hi.x, win.hi.y}, a, b) &&
                glm::length(b - a) > 0)
                scene.segments.push_back({a, b, "", {Role::Window, 2.0f}});
        }
        scene.labels.push_back({{(win.lo.x + win.hi.x) / 2, win.hi.y},
                                "near the path (ball: diameter " + num(d) + " px)",
                                {Role::Neutral},
                                -1});
    }
    scene.points.push_back({c, "centre", {Role::Construction}, 3.0f, -1});

    // The mouse path: each leg an arrow, the ones done green, the ones to come dashed.
    const int done_upto = std::min(st.k, n - 1);  // samples [0, done_upto] are behind us
    for (int k = 0; k + 1 < n; ++k) {
        const dvec2 a = st.in.samples[k], b = st.in.samples[k + 1];
        if (a == b) continue;
        const bool behind = k < done_upto;
        scene.segments.push_back(
            {a, b, "", {behind ? Role::Kept : Role::Subject, behind ? 3.0f : 1.5f, !behind}, true});
    }
    for (int k = 0; k < n; ++k) {
        const dvec2 p = st.in.samples[k];
        const bool outside = glm::dot(2.0 * (p - c) / d, 2.0 * (p - c) / d) > 1.0;
        const bool first_or_last = k == 0 || k == n - 1;
        scene.points.push_back({p,
                                first_or_last ? sample_name(k) : "",
                                {outside ? Role::Discarded : Role::Subject},
                                4.0f});
        const std::string K2 = std::to_string(k);
        scene.handles.push_back(
            {p, sample_name(k), "/samples/" + K2 + "/0", "/samples/" + K2 + "/1"});
    }
    if (mapped_s) {
        const dvec2 S = st.in.samples[st.k], T = st.in.samples[std::min(st.k + 1, n - 1)];
        scene.points.push_back({S, "S = " + sample_name(st.k), {Role::Active}, 6.0f, 1});
        if (mapped_t) {
            scene.points.push_back({T, "T = " + sample_name(st.k + 1), {Role::Active}, 6.0f, 1});
            scene.segments.push_back({S, T, kArcball ? "" : "v", {Role::Active, 3.5f}, !kArcball});
        }
    }
    if (st.phase == Phase::Done && n >= 2)
        scene.segments.push_back(
            {st.in.samples.front(),
             st.in.samples.back(),
             kArcball ? "straight: same rotation" : "straight: another rotation",
             {Role::Construction, 1.0f, true},
             true});

    // ---- 3D: the ball ----
    add_focus(scene, dvec3(-1.1), dvec3(1.1));
    const Style sphere{Role::Construction, 1.0f, true};
    circle3(scene, {1, 0, 0}, {0, 1, 0}, 1.0, {Role::Window, 1.5f});  // the rim seen from +z
    circle3(scene, {1, 0, 0}, {0, 0, 1}, 1.0, sphere);
    circle3(scene, {0, 1, 0}, {0, 0, 1}, 1.0, sphere);
    scene.labels3.push_back({{0, -1.08, 0}, "rim (silhouette)", {Role::Window}, -1});
    scene.segments3.push_back(
        {{0, 0, 0}, {0, 0, 1.4}, "to the viewer (z)", {Role::Construction, 1.0f}, true, 0, -1});

    // The object turned by the rotation so far: the given points joined in order, or a cube.
    const Style object_style{Role::Kept, 2.0f};
    if (st.in.object.empty()) {
        const double h = 0.45;
        auto corner = [&](int i) {
            return st.q_total * dvec3(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
        };
        for (int i = 0; i < 8; ++i)
            for (int bit : {1, 2, 4})
                if (!(i & bit))
                    scene.segments3.push_back(
                        {corner(i), corner(i | bit), "", object_style, false});
        // The face the viewer saw first (+z), filled, to follow the cube's turn.
        scene.faces3.push_back(
            {{corner(4), corner(5), corner(7), corner(6)}, {Role::Kept}, 0.35f, true, true});
    } else {
        for (std::size_t i = 0; i < st.in.object.size(); ++i) {
            const dvec3 p = st.q_total * st.in.object[i];
            scene.points3.push_back({p, "P" + std::to_string(i), {Role::Kept}, 4.0f, -1});
            if (i > 0)
                scene.segments3.push_back(
                    {st.q_total * st.in.object[i - 1], p, "", object_style, false});
        }
    }

    // The trail of the front point, pair by pair.
    for (std::size_t i = 1; i < st.front.size(); ++i)
        scene.segments3.push_back({st.front[i - 1], st.front[i], "", {Role::Leaving, 1.5f}, false});
    scene.points3.push_back({st.front.back(), "R·(0, 0, 1)", {Role::Leaving}, 4.0f});

    if (st.phase != Phase::Summary && st.phase != Phase::Done) {
        if (mapped_s) {
            scene.points3.push_back({st.s.p, "s", {Role::Active}, 6.0f, 1});
            scene.segments3.push_back({{0, 0, 0}, st.s.p, "", {Role::Active, 1.0f, true}, false});
        }
        if (mapped_t) {
            if constexpr (kArcball) {
                scene.points3.push_back({st.t.p, "t", {Role::Active}, 6.0f, 1});
                scene.segments3.push_back(
                    {{0, 0, 0}, st.t.p, "", {Role::Active, 1.0f, true}, false});
                arc3(scene, st.s.p, st.t.p, {Role::Active, 2.5f});
            } else {
                Segment3 v{st.s.p, st.s.p + st.velocity, "v", {Role::Active, 2.5f}, true};
                v.min_pixels = 30;
                scene.segments3.push_back(v);
            }
        }
        if (st.phase == Phase::Accumulate && !st.pairs.empty() && st.pairs.back().angle_deg > 0) {
            const auto& p = st.pairs.back();
            scene.segments3.push_back({{0, 0, 0},
                                       1.35 * p.axis,
                                       "axis, " + num(p.angle_deg, 4) + "°",
                                       {Role::Entering, 2.5f},
                                       true,
                                       0,
                                       1});
        }
    } else if (st.phase == Phase::Done) {
        const AxisAngle total = axis_angle(canonical(st.q_total));
        if (total.angle_deg > kSameDeg)
            scene.segments3.push_back({{0, 0, 0},
                                       1.35 * total.axis,
                                       "drag: " + num(total.angle_deg, 4) + "°",
                                       {Role::Entering, 2.5f},
                                       true,
                                       0,
                                       1});
        const AxisAngle direct = axis_angle(canonical(st.direct));
        if (!kArcball && direct.angle_deg > kSameDeg && st.path_gap_deg > kSameDeg)
            scene.segments3.push_back({{0, 0, 0},
                                       1.35 * direct.axis,
                                       "straight: " + num(direct.angle_deg, 4) + "°",
                                       {Role::Construction, 2.0f, true},
                                       true});
    }
}

template void TrackballDrag<TrackballKind::VirtualSphere>::draw(const State&, Scene&);
template void TrackballDrag<TrackballKind::Arcball>::draw(const State&, Scene&);

}  // namespace cg
