// Ray against an axis-aligned box, the picture. The 3D view: the box (translucent blue), the
// current axis's two planes (orange), the ray from E with the line behind E dashed, each worked
// slab's entry and exit on it (teal "near", magenta "far"), the running [t_min, t_max] (orange;
// green and thick in the box once it is a hit), framed on the box, E and the ray across it.
// Beside it, a chart on the t axis: one row per slab worked with its interval [t_near, t_far]
// and its numbers, and the running overlap [t_min, t_max] below them (t = 0 dashed), the rows
// named on the y axis and the one in hand on a pale orange band, so an empty overlap — a miss —
// is seen as two bars that do not meet.
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "accel/ray_aabb.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Case = RayAabb::Case;
using Phase = RayAabb::Phase;
using Verdict = RayAabb::Verdict;

const char* const kAxis[3] = {"x", "y", "z"};

bool finite(dvec3 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}
bool finite(dvec2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

// The t range worth drawing: t = 0 and every plane's t of the whole input (not only the axes
// worked so far, so the view does not jump between steps), padded.
struct Range {
    double lo = 0, hi = 1;
};
Range t_range(const RayAabb::Input& in) {
    Range r{0, 0};
    for (int i = 0; i < 3; ++i) {
        const RayAabb::Slab sl = RayAabb::slab(in.min[i], in.max[i], in.origin[i], in.direction[i]);
        for (double t : {sl.t_near, sl.t_far})
            if (std::isfinite(t)) r.lo = std::min(r.lo, t), r.hi = std::max(r.hi, t);
    }
    if (!(r.hi - r.lo > 0) || !std::isfinite(r.hi - r.lo)) {
        // Only t = 0 (the origin on a corner of a point box): one box diagonal either side.
        const double size = glm::length(in.max - in.min) / glm::length(in.direction);
        const double w = std::isfinite(size) && size > 0 ? size : 1.0;
        r.lo = -w, r.hi = w;
    }
    const double pad = 0.15 * (r.hi - r.lo);
    if (std::isfinite(pad)) r.lo -= pad, r.hi += pad;
    return r;
}

void push(Scene& scene, const Segment3& s) {
    if (finite(s.a) && finite(s.b)) scene.segments3.push_back(s);
}
void push(Scene& scene, const Point3& p) {
    if (finite(p.p)) scene.points3.push_back(p);
}
void push(Scene& scene, const Face3& f) {
    for (const dvec3& p : f.points)
        if (!finite(p)) return;
    scene.faces3.push_back(f);
}
void push2(Layer2& layer, const Segment2& s) {
    if (finite(s.a) && finite(s.b)) layer.segments.push_back(s);
}
void push2(Layer2& layer, const Label2& l) {
    if (finite(l.p)) layer.labels.push_back(l);
}

// The two planes of slab i as quads, a margin beyond the box on the other two axes.
void slab_planes(const RayAabb::Input& in, int i, Style style, float alpha, Scene& scene) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const dvec3 size = in.max - in.min;
    const double m = 0.35 * std::max({size.x, size.y, size.z, 1e-300});
    for (double c : {in.min[i], in.max[i]}) {
        dvec3 q[4];
        for (int n = 0; n < 4; ++n) {
            q[n][i] = c;
            q[n][j] = (n == 1 || n == 2) ? in.max[j] + m : in.min[j] - m;
            q[n][k] = (n >= 2) ? in.max[k] + m : in.min[k] - m;
        }
        push(scene, Face3{{q[0], q[1], q[2], q[3]}, style, alpha, true, true});
    }
}

}  // namespace

void RayAabb::draw(const State& s, Scene& scene) {
    const Input& in = s.in;
    const Result& r = s.r;
    const dvec3 E = in.origin, d = in.direction;
    const Range range = t_range(in);
    auto P = [&](double t) { return E + t * d; };

    // The box: its six faces.
    auto corner = [&](int c) {
        return dvec3(c & 1 ? in.max.x : in.min.x, c & 2 ? in.max.y : in.min.y,
                     c & 4 ? in.max.z : in.min.z);
    };
    static const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                    {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (const auto& q : quads)
        push(scene, Face3{{corner(q[0]), corner(q[1]), corner(q[2]), corner(q[3])},
                          {Role::Window, 1.5f},
                          0.12f,
                          true,
                          true});
    scene.labels3.push_back({in.max, "max", {Role::Window}});
    scene.labels3.push_back({in.min, "min", {Role::Window}});

    // The planes of the axis in hand (the next one before the first step and at the verdict,
    // none).
    const bool axis_step = s.last == Phase::Axis && s.axis > 0;
    const int focus = s.axis == 0 ? -1 : s.axis - 1;
    if (focus >= 0 && axis_step) slab_planes(in, focus, {Role::Active, 1.5f}, 0.16f, scene);

    // The ray: behind E dashed, ahead with an arrow.
    if (range.lo < 0)
        push(scene, Segment3{P(range.lo), E, "", {Role::Construction, 1.0f, true}, false});
    push(scene, Segment3{E, P(range.hi), "E + t d", {Role::Subject, 1.5f}, true});
    push(scene, Point3{E, "E", {Role::Subject}, 5.0f});

    // Each worked slab's two points on the ray.
    for (int i = 0; i < r.count; ++i) {
        const Slab& sl = r.axes[i];
        const bool now = i == focus && axis_step;
        const float rad = now ? 6.0f : 4.0f;
        // Named only: their t are written in the chart beside.
        if (std::isfinite(sl.t_near))
            push(scene,
                 Point3{P(sl.t_near), std::string(kAxis[i]) + " near", {Role::Entering}, rad});
        if (std::isfinite(sl.t_far))
            push(scene, Point3{P(sl.t_far), std::string(kAxis[i]) + " far", {Role::Leaving}, rad});
    }

    // The running interval, or the final one.
    if (r.count > 0 && r.t_min <= r.t_max) {
        const double a = std::max(r.t_min, range.lo), b = std::min(r.t_max, range.hi);
        if (r.verdict == Verdict::Hit || r.verdict == Verdict::Inside) {
            const double a0 = std::max(r.t_min, 0.0);
            push(scene, Segment3{P(a0), P(r.t_max), "in the box", {Role::Kept, 6.0f}, false});
            if (r.t_min < 0)  // the part of the line in the box behind E
                push(scene,
                     Segment3{
                         P(std::max(r.t_min, range.lo)), E, "", {Role::Kept, 2.0f, true}, false});
            push(scene, Point3{P(r.t_hit), "t_hit = " + num(r.t_hit, 4), {Role::Kept}, 7.0f, 30});
        } else if (a <= b) {
            push(scene,
                 Segment3{P(a),
                          P(b),
                          "",
                          {r.verdict == Verdict::Behind ? Role::Discarded : Role::Active, 4.0f},
                          false});
        }
    }
    scene.extent3 = 0;  // fit to the content

    // The camera frames the box, E and the ray's points worked so far.
    glm::dvec3 flo = glm::min(in.min, E), fhi = glm::max(in.max, E);
    auto frame = [&](double t) {
        if (std::isfinite(t) && t >= range.lo && t <= range.hi)
            flo = glm::min(flo, P(t)), fhi = glm::max(fhi, P(t));
    };
    if (r.count > 0 && r.t_min <= r.t_max) frame(r.t_min), frame(r.t_max);
    for (int i = 0; i < r.count; ++i) frame(r.axes[i].t_near), frame(r.axes[i].t_far);
    if (finite(flo) && finite(fhi)) add_focus(scene, flo, fhi);

    // ---- the chart: the t axis, one row per slab (x, y, z at 3, 2, 1, named on the y axis) and
    // the running interval [t_min, t_max] at 0; infinite ends run to the edge with an arrow ----
    const double lo = range.lo, hi = range.hi, w = hi - lo;
    if (!(w > 0) || !std::isfinite(w)) return;
    Axis rows{""};
    rows.names = {"[t_min, t_max]", "z slab", "y slab", "x slab"};
    for (int i = 0; i < r.count; ++i)
        if (r.axes[i].kind == Case::ParallelOutside) rows.names[3 - i] += " (empty)";
    Panel& chart = add_chart(scene, "slab intervals on the t axis", Axis{"t", lo, hi}, rows);
    chart.weight = 1.1;
    auto row = [&](double y, double a, double b, Role role, bool active) {
        if (active)  // the row in hand: a pale orange band, like the slab's planes in 3D
            chart.polygons.push_back(
                {{{lo, y - 0.38}, {hi, y - 0.38}, {hi, y + 0.38}, {lo, y + 0.38}},
                 {Role::Active, 0.0f},
                 true,
                 true});
        if (!(a <= b)) return;  // empty
        const double ca = std::max(a, lo), cb = std::min(b, hi);
        if (ca > cb) return;
        const Style bar{role, active ? 7.0f : 4.0f};
        push2(chart, Segment2{{ca, y}, {cb, y}, "", bar, std::isinf(b)});
        if (std::isinf(a))  // −∞: an arrowhead at the left edge too
            push2(chart, Segment2{{0.5 * (ca + cb), y}, {ca, y}, "", bar, true});
        if (std::isfinite(a)) push2(chart, Label2{{ca, y - 0.06}, num(a, 4), {Role::Entering}});
        if (std::isfinite(b)) push2(chart, Label2{{cb, y - 0.06}, num(b, 4), {Role::Leaving}});
    };
    for (int i = 0; i < r.count; ++i) {
        const Slab& sl = r.axes[i];
        row(3 - i, sl.t_near, sl.t_far, Role::Window, i == focus && axis_step);
    }
    const bool hit = r.verdict == Verdict::Hit || r.verdict == Verdict::Inside;
    if (r.count > 0) row(0, r.t_min, r.t_max, hit ? Role::Kept : Role::Active, !axis_step);
    push2(chart, Segment2{{0, -0.5}, {0, 3.5}, "", {Role::Construction, 1.0f, true}, false});
}

}  // namespace cg
