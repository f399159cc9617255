// Boids, the picture (2D). Left: the world (blue; in a steered world the margin band dashed),
// the obstacles (filled grey discs), every boid as a small triangle pointing along its velocity
// (a dot when still): the focus boid orange, the boids it sees now teal, the rest grey. Around
// the focus boid its perception circle (dashed; a wedge when the field of view is limited), its
// separation circle when smaller, a thin line to each neighbour (to the neighbour's nearest
// image in a wrapped world) and the rules it would steer by from this state as arrows from it,
// each already weighted (w_s s, w_a a, w_c c, w_o o, w_b b), and their sum F dashed: the picture
// shows the next step's steering, the narration the last one's numbers. Right, two charts against
// t (s) over the whole run's length: the polarisation φ (0 to 1) and the mean nearest-neighbour
// distance (from 0).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "animation/boids.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

constexpr std::size_t kMaxPlotPoints = 512;
constexpr int kCircleSegments = 72;

// A circle (or the arc from a0 to a1, radians, through the centre's wedge when `wedge`).
Polygon2 arc(glm::dvec2 c, double r, double a0, double a1, bool wedge, Style style) {
    Polygon2 p{{}, style, wedge, false};
    if (wedge) p.points.push_back(c);
    const int n = std::max(8, int(std::ceil(kCircleSegments * (a1 - a0) / (2 * std::numbers::pi))));
    for (int q = 0; q <= n; ++q) {
        const double a = a0 + (a1 - a0) * q / n;
        p.points.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return p;
}

Polygon2 circle(glm::dvec2 c, double r, Style style, bool filled = false) {
    Polygon2 p{{}, style, true, filled};
    for (int q = 0; q < kCircleSegments; ++q) {
        const double a = 2 * std::numbers::pi * q / kCircleSegments;
        p.points.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return p;
}

}  // namespace

void Boids::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const std::size_t n = s.x.size(), f = std::size_t(in.focus);
    const glm::dvec2 lo = in.world_min, hi = in.world_max, size = hi - lo;
    const double big = std::max(size.x, size.y);

    scene.polygons.push_back(
        {{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, {Role::Window, 1.5f}, true, false});
    if (in.edges == Edges::Steer) {
        const double m = std::min({in.margin, 0.5 * size.x, 0.5 * size.y});
        scene.polygons.push_back({{lo + m, {hi.x - m, lo.y + m}, hi - m, {lo.x + m, hi.y - m}},
                                  {Role::Window, 1.0f, true},
                                  true,
                                  false});
    }
    for (const Obstacle& o : in.obstacles)
        scene.polygons.push_back(circle(o.center, o.radius, {Role::Neutral, 1.5f}, true));

    // Who the focus boid sees now, and what it would steer by.
    Seen seen;
    const Rules now = rules(in, s.x, s.v, f, &seen);
    std::vector<char> is_neighbour(n, 0);
    for (int j : seen.ids) is_neighbour[std::size_t(j)] = 1;

    const glm::dvec2 xf = s.x[f], vf = s.v[f];
    const double speed_f = std::hypot(vf.x, vf.y);
    const Style ring{Role::Construction, 1.5f, true};
    if (in.radius > 0) {
        if (in.fov < 360 && speed_f > 0) {
            const double heading = std::atan2(vf.y, vf.x);
            const double half = in.fov * std::numbers::pi / 360;
            scene.polygons.push_back(arc(xf, in.radius, heading - half, heading + half,
                                         in.fov > 0, ring));
        } else {
            scene.polygons.push_back(circle(xf, in.radius, ring));
        }
        if (in.separation_radius < in.radius && in.separation_radius > 0)
            scene.polygons.push_back(circle(xf, in.separation_radius, {Role::Discarded, 1.0f, true}));
    }
    for (const glm::dvec2& d : seen.offsets)
        scene.segments.push_back({xf, xf + d, "", {Role::Entering, 1.0f}, false});

    // The boids: triangles along their velocity, about 2% of the world's larger side (4% for a
    // handful, as in the exam-style example).
    const bool numbered = n <= 12;
    const double L = (numbered ? 0.04 : 0.02) * big;
    for (std::size_t i = 0; i < n; ++i) {
        const Role role = i == f ? Role::Active : is_neighbour[i] ? Role::Entering : Role::Subject;
        const glm::dvec2 p = s.x[i], u = s.v[i];
        const double sp = std::hypot(u.x, u.y);
        if (sp > 0) {
            const glm::dvec2 dir = u / sp, side{-dir.y, dir.x};
            const double k = i == f ? 1.4 : 1.0;
            scene.polygons.push_back({{p + 0.6 * k * L * dir, p - 0.4 * k * L * dir + 0.3 * k * L * side,
                                       p - 0.4 * k * L * dir - 0.3 * k * L * side},
                                      {role, 1.0f},
                                      true,
                                      true});
        } else {
            scene.points.push_back({p, "", {role}, i == f ? 5.0f : 3.5f});
        }
        if (numbered)
            scene.labels.push_back({p + glm::dvec2(0.5 * L, 0.5 * L), std::to_string(i), {role}});
    }

    // The weighted rules and their sum, as arrows from the focus boid, all scaled together so
    // the longest is 0.8 r (or a tenth of the world when r is 0).
    struct Arrow {
        glm::dvec2 w;
        const char* label;
        Role role;
        bool dashed;
    };
    const Weights& wt = in.weights;
    const Arrow arrows[] = {
        {wt.separation * now.separation, "separation", Role::Discarded, false},
        {wt.alignment * now.alignment, "alignment", Role::Leaving, false},
        {wt.cohesion * now.cohesion, "cohesion", Role::Kept, false},
        {wt.avoidance * now.avoidance, "avoidance", Role::Window, false},
        {wt.bounds * now.bounds, "bounds", Role::Neutral, false},
        {now.sum, "F", Role::Active, true},
    };
    double longest = 0;
    for (const Arrow& a : arrows) longest = std::max(longest, std::hypot(a.w.x, a.w.y));
    if (longest > 0 && std::isfinite(longest)) {
        const double scale = (in.radius > 0 ? 0.8 * in.radius : 0.1 * big) / longest;
        for (const Arrow& a : arrows) {
            if (a.w == glm::dvec2(0)) continue;
            // Labelled just past the tip (the tips lie further apart than the midpoints).
            const glm::dvec2 tip = xf + scale * a.w;
            const glm::dvec2 dir = a.w / std::hypot(a.w.x, a.w.y);
            scene.segments.push_back({xf, tip, "", {a.role, 2.5f, a.dashed}, true});
            scene.labels.push_back({tip + 0.06 * big * dir, a.label, {a.role}});
        }
    }

    // Dragging: the obstacles' centres (the boids move; their starts are edited as numbers).
    for (std::size_t k = 0; k < in.obstacles.size(); ++k) {
        const std::string base = "/obstacles/" + std::to_string(k) + "/center/";
        scene.handles.push_back({in.obstacles[k].center, "obstacle " + std::to_string(k),
                                 base + "0", base + "1"});
    }

    // The step's subject: the focus boid with its perception circle.
    const double reach = std::max(in.radius, 0.05 * big);
    add_focus(scene, xf - glm::dvec2(reach), xf + glm::dvec2(reach));

    // The flock's order against t over the whole run, in two charts beside the world (no
    // titles: the y axes say what is plotted, and the room goes to the plots).
    const double t_end = double(in.steps) * in.dt;
    auto plot = [&](const std::vector<double>& ys, Axis y, Role role) {
        Panel& chart = add_chart(scene, "", Axis{"t (s)", 0, t_end}, std::move(y));
        chart.weight = 0.5;  // the two together 1 against the world's 1.5
        std::vector<glm::dvec2> line;
        const std::size_t stride = (ys.size() + kMaxPlotPoints - 1) / kMaxPlotPoints;
        for (std::size_t q = 0; q < ys.size(); q += stride) line.push_back({double(q) * in.dt, ys[q]});
        if ((ys.size() - 1) % stride != 0)
            line.push_back({double(ys.size() - 1) * in.dt, ys.back()});
        add_line(chart, std::move(line), {role, 2.0f});
        chart.points.push_back({{double(ys.size() - 1) * in.dt, ys.back()}, "", {role}, 4.5f});
    };
    plot(s.polarisation,
         Axis{"polarisation φ = " + num(s.polarisation.back(), 3) + "  (1: all aligned)", 0, 1},
         Role::Active);
    plot(s.nearest,
         Axis{"mean nearest distance = " + num(s.nearest.back(), 3), 0, 0, false, true},
         Role::Entering);
}

}  // namespace cg
