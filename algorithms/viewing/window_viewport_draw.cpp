// Window to viewport through NDC, the picture. Three views, each in its own coordinates:
//   - the world: the window (blue) at its world coordinates with the points and their handles,
//     on the world's grid;
//   - a chart of NDC (x_ndc, y_ndc): the square [−1, 1]² and the points' images there;
//   - a chart of the device (x_d, y_d): the viewport (blue) and the points' images, its y axis
//     running downward for a device whose rows are counted from the top ("y down").
// Both charts keep one scale for x and y (equal_aspect), so the NDC square is square and a
// viewport whose aspect differs from the window's shows the points' shape stretched. The point
// mapped this step is orange where it comes from and where it lands; the others are named in
// every view (P0 in the world and NDC, P0' on the device) instead of lines joining them.
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "viewing/window_viewport.hpp"

namespace cg {

namespace {

using glm::dvec2;
using Rect = WindowViewport::Rect;
using Phase = WindowViewport::Phase;

bool flipped_x(const Rect& v) {
    return v.xmax < v.xmin;
}
bool flipped_y(const Rect& v) {
    return v.ymax < v.ymin;
}
std::string point_name(int k) {
    return "P" + std::to_string(k);
}

std::vector<dvec2> rect(dvec2 a, dvec2 b) {
    return {a, {b.x, a.y}, b, {a.x, b.y}};
}

std::string range(const Rect& r) {
    return "[" + num(r.xmin) + ", " + num(r.xmax) + "] × [" + num(r.ymin) + ", " + num(r.ymax) +
           "]";
}

// The range a chart shows along one axis: the rectangle's and every image's (of all points,
// mapped or not, so the chart stays put over the run), with room round them for the labels.
struct Span {
    double lo = 0, hi = 0;
};
// `below` adds room under it (in the fraction of its length) for a note.
Span span_of(double a, double b, const std::vector<double>& images, double below = 0) {
    Span s{std::min(a, b), std::max(a, b)};
    for (double v : images)
        if (std::isfinite(v)) s.lo = std::min(s.lo, v), s.hi = std::max(s.hi, v);
    const double pad = 0.18 * (s.hi - s.lo);
    return {s.lo - pad - below * (s.hi - s.lo), s.hi + pad};
}

}  // namespace

void WindowViewport::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Rect &w = in.window, &v = in.viewport;
    const Result all = map(in);  // every point's images: the charts' ranges
    const int n = static_cast<int>(in.points.size());
    const int active = s.phase == Phase::Done ? -1 : s.k;
    const bool to_ndc = s.last == Phase::ToNdc, to_device = s.last == Phase::ToDevice;

    // ---- the world: the window and the points ----
    scene.polygons.push_back(
        {rect({w.xmin, w.ymin}, {w.xmax, w.ymax}), {Role::Window, 2.0f}, true, true});
    scene.labels.push_back(
        {{(w.xmin + w.xmax) / 2, w.ymax}, "window (world) " + range(w), {Role::Window}});
    if (n >= 3)  // the points in order, so that a shape's distortion shows
        scene.polygons.push_back({in.points, {Role::Subject, 1.5f}, true, false});
    for (int k = 0; k < n; ++k) {
        const bool now = to_ndc && k == active;
        scene.points.push_back({in.points[k],
                                point_name(k),
                                {now ? Role::Active : Role::Subject},
                                5.0f,
                                now ? 30 : 0});
        const std::string K = std::to_string(k);
        scene.handles.push_back(
            {in.points[k], point_name(k), "/points/" + K + "/0", "/points/" + K + "/1"});
    }
    scene.handles.push_back(
        {{w.xmin, w.ymin}, "window (xmin, ymin)", "/window/xmin", "/window/ymin"});
    scene.handles.push_back(
        {{w.xmax, w.ymax}, "window (xmax, ymax)", "/window/xmax", "/window/ymax"});

    // ---- NDC: the square [−1, 1]² and the points mapped so far ----
    {
        std::vector<double> xs, ys;
        for (dvec2 q : all.ndc) xs.push_back(q.x), ys.push_back(q.y);
        const Span sx = span_of(-1, 1, xs), sy = span_of(-1, 1, ys);
        Panel& ndc = add_chart(scene, "NDC [−1, 1] × [−1, 1]", Axis{"x_ndc", sx.lo, sx.hi},
                               Axis{"y_ndc", sy.lo, sy.hi});
        ndc.equal_aspect = true;
        ndc.polygons.push_back({rect({-1, -1}, {1, 1}), {Role::Neutral, 2.0f}, true, false});
        const int mapped = static_cast<int>(s.ndc.size());
        if (n >= 3 && mapped == n)
            ndc.polygons.push_back({s.ndc, {Role::Subject, 1.5f}, true, false});
        for (int k = 0; k < mapped; ++k) {
            const bool now = (to_ndc || to_device) && k == active;
            ndc.points.push_back(
                {s.ndc[k],
                 now ? point_name(k) + "_ndc = " + num(s.ndc[k], 4) : point_name(k),
                 {now ? Role::Active : Role::Kept},
                 now ? 6.0f : 5.0f,
                 now ? 30 : 0});
        }
    }

    // ---- the device: the viewport and the points mapped so far ----
    {
        std::vector<double> xs, ys;
        for (dvec2 d : all.device) xs.push_back(d.x), ys.push_back(d.y);
        // Room under the viewport (on screen) for the note that the picture is distorted.
        const double note = all.distorted ? 0.2 : 0;
        const Span sx = span_of(v.xmin, v.xmax, xs);
        Span sy = span_of(v.ymin, v.ymax, ys, flipped_y(v) ? 0 : note);
        if (flipped_y(v)) sy.hi += note * (sy.hi - sy.lo);  // drawn downward: under is up
        const bool flipped = flipped_x(v) || flipped_y(v);
        const std::string title = flipped ? std::string("viewport (device, ") +
                                                (flipped_x(v) && flipped_y(v) ? "x and y flipped"
                                                 : flipped_y(v)               ? "y down"
                                                                              : "x flipped") +
                                                ")"
                                          : "viewport (device) " + range(v);
        Axis y{"y_d", sy.lo, sy.hi};
        y.reversed = flipped_y(v);  // a screen's rows: counted from the top, drawn upright
        Panel& dev = add_chart(scene, title, Axis{"x_d", sx.lo, sx.hi}, y);
        dev.equal_aspect = true;
        dev.polygons.push_back(
            {rect({v.xmin, v.ymin}, {v.xmax, v.ymax}), {Role::Window, 2.0f}, true, true});
        const int mapped = static_cast<int>(s.device.size());
        const bool to_device_now = to_device && active >= 0 && active < mapped;
        // A flipped viewport: the device's own coordinates at the corners the window's corners
        // reach (not where the point just mapped lands: its own label says the same).
        if (flipped)
            for (const dvec2 c : {dvec2(v.xmin, v.ymin), dvec2(v.xmax, v.ymax)}) {
                if (to_device_now && s.device[active] == c) continue;
                dev.labels.push_back({c, num(c), {Role::Neutral}});
            }
        if (s.phase != Phase::Aspect && s.distorted)
            dev.labels.push_back(
                {{(v.xmin + v.xmax) / 2, y.reversed
                                             ? std::max(v.ymin, v.ymax) + 0.06 * (sy.hi - sy.lo)
                                             : std::min(v.ymin, v.ymax) - 0.06 * (sy.hi - sy.lo)},
                 "distorted: aspect " + num(s.aspect_window, 4) + " ≠ " + num(s.aspect_viewport, 4),
                 {Role::Discarded},
                 10});
        if (n >= 3 && mapped == n)
            dev.polygons.push_back({s.device, {Role::Subject, 1.5f}, true, false});
        for (int k = 0; k < mapped; ++k) {
            const bool now = to_device && k == active;
            dev.points.push_back(
                {s.device[k],
                 now ? point_name(k) + "_device = " + num(s.device[k], 4) : point_name(k) + "'",
                 {now ? Role::Active : Role::Kept},
                 now ? 6.0f : 5.0f,
                 now ? 30 : 0});
        }
    }
}

}  // namespace cg
