// Supersampling one pixel, the pictures.
// A pixel (the world, in pixel units): the pixel (blue) among its eight neighbours, the scene
// (the edge's half-plane with the outside shaded, or the polygon, both draggable), the
// pattern's cells, and the samples: grey before they are taken, then green inside and red
// outside, sized by weight; the current one orange with, for Poisson, its exclusion circle.
// From the exact step on, the covered polygon (green).
// A study: a chart with logarithmic axes, RMS error against samples per pixel N, each
// pattern's points joined in its colour and named in the legend (the newest larger, with its
// value), and guides of
// slope −½ and −¾ from error 1 at the first N, so a pattern running parallel to one has its
// slope.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "sampling/supersampling.hpp"

namespace cg {

namespace {

using glm::dvec2;
using Phase = Supersampling::Phase;
using sampling::Pattern;
using sampling::RegionKind;

Role pattern_role(Pattern p) {
    switch (p) {
        case Pattern::Regular:
            return Role::Discarded;
        case Pattern::Random:
            return Role::Leaving;
        case Pattern::Jittered:
            return Role::Kept;
        case Pattern::Poisson:
            return Role::Window;
    }
    return Role::Neutral;
}

}  // namespace

void Supersampling::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    if (in.is_study) return draw_study(s, scene);
    const double x0 = in.i, y0 = in.j;
    const Style grid{Role::Construction, 1.0f, false};
    for (int k = -1; k <= 2; ++k) {
        scene.segments.push_back({{x0 + k, y0 - 1}, {x0 + k, y0 + 2}, "", grid, false});
        scene.segments.push_back({{x0 - 1, y0 + k}, {x0 + 2, y0 + k}, "", grid, false});
    }
    scene.polygons.push_back({{{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}},
                              {Role::Window, 2.5f},
                              true,
                              false});
    scene.points.push_back({{x0 + 0.5, y0 + 0.5}, "", {Role::Window}, 2.5f});
    scene.labels.push_back({{x0 + 0.02, y0 - 0.12},
                            "pixel (" + std::to_string(in.i) + ", " + std::to_string(in.j) + ")",
                            {Role::Window}});
    add_focus(scene, dvec2(x0, y0), dvec2(x0 + 1, y0 + 1));

    const sampling::Region& r = in.scene;
    if (r.kind == RegionKind::Edge) {
        const dvec2 d = sampling::edge_direction(r.angle_deg);
        // The line's point nearest the pixel's centre: where the handle sits.
        const dvec2 c(x0 + 0.5, y0 + 0.5);
        const dvec2 foot = r.point + d * glm::dot(c - r.point, d);
        scene.half_planes.push_back({foot, {-d.y, d.x}, "edge", {Role::Subject, 2.0f}});
        scene.handles.push_back({foot, "edge", "/scene/point/0", "/scene/point/1"});
    } else {
        scene.polygons.push_back({r.points, {Role::Subject, 2.0f}, true, true});
        for (std::size_t k = 0; k < r.points.size(); ++k) {
            const std::string p = "/scene/points/" + std::to_string(k);
            scene.handles.push_back({r.points[k], "P" + std::to_string(k), p + "/0", p + "/1"});
        }
    }

    if (sampling::is_grid(in.pattern)) {
        const int n = sampling::grid_side(in.samples);
        if (n > 1 && n <= 16)
            for (int k = 1; k < n; ++k) {
                const double t = double(k) / n;
                const Style cells{Role::Construction, 1.0f, true};
                scene.segments.push_back({{x0 + t, y0}, {x0 + t, y0 + 1}, "", cells, false});
                scene.segments.push_back({{x0, y0 + t}, {x0 + 1, y0 + t}, "", cells, false});
            }
    }

    if (s.phase >= Phase::Done && !s.covered.empty())
        scene.polygons.push_back({s.covered, {Role::Kept, 2.0f}, true, true});

    const bool many = s.points.size() > 64;
    double wmax = 0;
    for (const auto& smp : s.samples) wmax = std::max(wmax, smp.weight);
    for (std::size_t k = 0; k < s.points.size(); ++k) {
        const dvec2 p = dvec2(x0, y0) + s.points[k].p;
        if (int(k) > s.k) {
            scene.points.push_back({p, "", {Role::Subject}, many ? 2.0f : 3.0f});
            continue;
        }
        const Sample& smp = s.samples[k];
        const bool current = int(k) == s.k && s.last == Phase::Sample;
        const float radius = (many ? 2.0f : 3.0f) +
                             (many ? 2.0f : 4.0f) * float(smp.weight / std::max(wmax, 1e-300));
        const Role role = current ? Role::Active : smp.value > 0 ? Role::Kept : Role::Discarded;
        scene.points.push_back({p, current ? std::to_string(k + 1) : "", {role}, radius});
    }
    if (s.last == Phase::Sample && in.pattern == Pattern::Poisson) {  // the exclusion circle
        const dvec2 c = s.samples[s.k].p;
        std::vector<dvec2> circle;
        for (int a = 0; a < 48; ++a)
            circle.push_back(c +
                             s.radius * dvec2(std::cos(a * M_PI / 24), std::sin(a * M_PI / 24)));
        scene.polygons.push_back({std::move(circle), {Role::Active, 1.0f, true}, true, false});
    }
    if (s.phase >= Phase::Exact) {
        std::string t = "estimate " + num(s.estimate, 4);
        if (s.phase == Phase::Done)
            t += ", exact " + num(s.exact, 4) + ", error " + num(s.estimate - s.exact, 3);
        scene.labels.push_back({{x0 + 0.02, y0 + 1.06}, t, {Role::Neutral}});
    }
}

void Supersampling::draw_study(const State& s, Scene& scene) {
    const Study& st = s.in->study;
    const double n0 = st.samples.front(), n1 = st.samples.back();
    double e_lo = 1e-3;
    for (const StudyPoint& q : s.study) e_lo = std::min(e_lo, std::max(q.rms_error, 1e-6));
    Panel& chart = add_chart(scene,
                             "RMS error over " + std::to_string(st.edges) + " edges " +
                                 (st.near_axis ? "within 1° of the x axis" : "at any angle"),
                             Axis{"samples per pixel N", n0 / 1.4, n1 * 1.4, true},
                             Axis{"RMS error", e_lo / 2, 1.5, true});
    // Guides: slopes −½ and −¾ from error 1 at the first count, above the data (every pattern
    // starts below 1), so a pattern's line running parallel to a guide has its slope.
    add_line(chart, {{n0, 1.0}, {n1, std::pow(n1 / n0, -0.5)}}, {Role::Construction, 1.5f, true},
             "slope −½");
    add_line(chart, {{n0, 1.0}, {n1, std::pow(n1 / n0, -0.75)}}, {Role::Subject, 1.0f, true},
             "slope −¾");

    const std::size_t m = st.samples.size();
    for (std::size_t a = 0; a * m < s.study.size(); ++a) {
        const std::size_t first = a * m, last = std::min(s.study.size(), first + m);
        const Pattern p = s.study[first].pattern;
        const Style style{pattern_role(p), 2.5f};
        std::vector<dvec2> line;
        for (std::size_t k = first; k < last; ++k) {
            const StudyPoint& q = s.study[k];
            line.push_back({double(q.samples), std::max(q.rms_error, 1e-6)});
            const bool newest = k + 1 == s.study.size() && s.last == Phase::Point;
            chart.points.push_back({line.back(), newest ? num(q.rms_error, 3) : "", style,
                                    newest ? 6.5f : 4.0f, newest ? 3 : 0});
        }
        chart.legend.push_back({sampling::pattern_id(p), style, false});
        if (line.size() > 1) add_line(chart, std::move(line), style);
    }
}

}  // namespace cg
