// Keyframes, the picture (2D, in a fixed frame so the layout stays put while frames play).
// A scalar channel: above, the value p(t) against time (the chosen interpolation in orange,
// linear dashed for comparison, Catmull–Rom in grey beside Kochanek–Bartels), the keys, and
// the frame's time as a blue line; below, the velocity p'(t), each segment drawn on its own so
// that a jump at a key shows as a break (marked red).
// A path: above, the path in its plane ((x, y); a 3D path is shown from the front), the keys,
// and the frames so far as dots — orange at parameter = time, green at constant speed — so the
// uneven spacing shows; below, the speed |p'(t)| against time, and L/(t_n − t_0) in green.
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>

#include "animation/keyframes.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

constexpr double kW = 12;                // plot width
constexpr double kTop0 = 4, kTop1 = 10;  // the value or path box
constexpr double kBot0 = 0, kBot1 = 3;   // the velocity box
constexpr int kMaxCurvePoints = 1500;
constexpr std::size_t kMaxDots = 60;

struct Range {
    double lo = 1e300, hi = -1e300;
    void add(double x) {
        if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    }
    void pad() {
        if (!(hi >= lo)) lo = 0, hi = 1;
        const double d = hi - lo, p = d > 0 ? 0.08 * d : std::max(1.0, std::fabs(lo)) * 0.1;
        lo -= p;
        hi += p;
    }
    double map(double x, double y0, double y1) const {
        return y0 + (y1 - y0) * (x - lo) / (hi - lo);
    }
};

void box(Scene& scene, double y0, double y1) {
    scene.polygons.push_back({{{0, y0}, {kW, y0}, {kW, y1}, {0, y1}}, {Role::Construction, 1.0f}});
}

}  // namespace

void Keyframes::draw(const State& s, Scene& scene) {
    const Prepared& p = *s.p;
    const Curve& c = p.curve;
    const int dim = p.in.dim;
    const std::size_t n = c.keys.size();
    const double t0 = c.keys.front().t, t1 = c.keys.back().t;
    auto tx = [&](double t) { return kW * (t - t0) / (t1 - t0); };
    const int per = std::clamp(kMaxCurvePoints / int(n - 1), 2, 48);

    // The curves to draw: the chosen one and the comparison ones.
    std::vector<std::pair<Curve, Style>> curves;
    curves.push_back({c, {Role::Active, 2.5f}});
    if (c.kind != Interpolation::Linear) {
        Input lin = p.in;
        curves.push_back(
            {make_curve(lin, Interpolation::Linear), {Role::Construction, 1.0f, true}});
    }
    if (c.kind == Interpolation::KochanekBartels)
        curves.push_back({make_curve(p.in, Interpolation::CatmullRom), {Role::Subject, 1.5f}});

    // Dense samples, segment by segment (the value and the velocity at both ends of each).
    struct Dense {
        std::vector<std::vector<Eval>> segments;
    };
    std::vector<Dense> dense(curves.size());
    Range vr, sr;  // value (or path extent) and velocity (or speed)
    Range px, py;
    for (std::size_t q = 0; q < curves.size(); ++q) {
        dense[q].segments.resize(n - 1);
        for (std::size_t i = 0; i + 1 < n; ++i)
            for (int j = 0; j <= per; ++j) {
                const Eval e = evaluate_in(curves[q].first, int(i), double(j) / per);
                dense[q].segments[i].push_back(e);
                if (dim == 1) {
                    vr.add(e.value.x);
                    sr.add(e.velocity.x);
                } else {
                    px.add(e.value.x);
                    py.add(e.value.y);
                    if (q == 0) sr.add(glm::length(e.velocity));
                }
            }
    }
    if (dim > 1) sr.add(0);
    if (p.in.constant_speed) sr.add(p.length / (t1 - t0));
    sr.pad();
    box(scene, kTop0, kTop1);
    box(scene, kBot0, kBot1);
    const double now_x = tx(s.t);

    // ---- the top box ----
    std::function<glm::dvec2(glm::dvec3)> top;
    if (dim == 1) {
        vr.pad();
        top = [&](glm::dvec3 v) { return glm::dvec2(0, vr.map(v.x, kTop0, kTop1)); };
    } else {
        px.pad();
        py.pad();
        // One scale for both axes (a circle stays round), centred in the box.
        const double sx = kW / (px.hi - px.lo), sy = (kTop1 - kTop0) / (py.hi - py.lo);
        const double k = std::min(sx, sy);
        const double ox = (kW - k * (px.hi - px.lo)) / 2,
                     oy = kTop0 + ((kTop1 - kTop0) - k * (py.hi - py.lo)) / 2;
        top = [=](glm::dvec3 v) {
            return glm::dvec2(ox + k * (v.x - px.lo), oy + k * (v.y - py.lo));
        };
    }
    auto at = [&](double t, glm::dvec3 v) {
        const glm::dvec2 q = top(v);
        return dim == 1 ? glm::dvec2(tx(t), q.y) : q;
    };
    for (std::size_t q = curves.size(); q-- > 0;) {  // the chosen curve last, on top
        Polygon2 line{{}, curves[q].second, false, false};
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double a = c.keys[i].t, b = c.keys[i + 1].t;
            for (std::size_t j = i == 0 ? 0 : 1; j < dense[q].segments[i].size(); ++j) {
                const Eval& e = dense[q].segments[i][j];
                line.points.push_back(at(a + e.u * (b - a), e.value));
            }
        }
        scene.polygons.push_back(std::move(line));
    }
    for (std::size_t i = 0; i < n; ++i)
        scene.points.push_back({at(c.keys[i].t, c.keys[i].value),
                                n <= 12 ? "p" + std::to_string(i) : "",
                                {Role::Neutral},
                                4.5f});
    if (dim == 1) {
        scene.segments.push_back(
            {{now_x, kBot0}, {now_x, kTop1}, "", {Role::Window, 1.0f, true}, false});
        scene.points.push_back({at(s.t, s.e.value), "", {Role::Active}, 6.5f});
        scene.labels.push_back(
            {{0, kTop1 + 0.35},
             "value p(t) = " + (s.k >= 0 ? num(s.e.value.x, 4) : std::string("…")) + "   (" +
                 interpolation_name(c.kind) + ")",
             {Role::Neutral}});
        scene.labels.push_back({{kW + 0.15, kTop1 - 0.3}, num(vr.hi, 3), {Role::Neutral}});
        scene.labels.push_back({{kW + 0.15, kTop0 + 0.1}, num(vr.lo, 3), {Role::Neutral}});
    } else {
        // The frames so far, thinned to kMaxDots: parameter = time orange, constant speed green.
        const std::size_t shown = s.values.size();
        const std::size_t stride = std::max<std::size_t>(1, (shown + kMaxDots - 1) / kMaxDots);
        for (std::size_t f = 0; f < shown; f += stride) {
            scene.points.push_back({top(s.values[f]), "", {Role::Active}, 2.5f});
            if (p.in.constant_speed)
                scene.points.push_back({top(s.evens[f]), "", {Role::Kept}, 2.5f});
        }
        if (s.k >= 0) {
            scene.points.push_back({top(s.e.value), "P(t)", {Role::Active}, 6.5f});
            if (p.in.constant_speed)
                scene.points.push_back({top(s.even), "P(u(s))", {Role::Kept}, 6.5f});
        }
        scene.labels.push_back(
            {{0, kTop1 + 0.35},
             std::string("path (") + interpolation_name(c.kind) +
                 (dim == 3 ? "), seen from the front: (x, y)" : ")") +
                 (p.in.constant_speed ? "   orange: u = t   green: constant speed" : ""),
             {Role::Neutral}});
        scene.segments.push_back(
            {{now_x, kBot0}, {now_x, kBot1}, "", {Role::Window, 1.0f, true}, false});
    }

    // ---- the bottom box: velocity (scalar) or speed (path) against time ----
    auto vy = [&](double v) { return sr.map(v, kBot0, kBot1); };
    if (sr.lo < 0 && sr.hi > 0)
        scene.segments.push_back({{0, vy(0)}, {kW, vy(0)}, "", {Role::Construction, 1.0f}, false});
    const std::size_t drawn = dim == 1 ? curves.size() : 1;
    for (std::size_t q = drawn; q-- > 0;)
        for (std::size_t i = 0; i + 1 < n; ++i) {
            Polygon2 line{{}, curves[q].second, false, false};
            const double a = c.keys[i].t, b = c.keys[i + 1].t;
            for (const Eval& e : dense[q].segments[i])
                line.points.push_back(
                    {tx(a + e.u * (b - a)), vy(dim == 1 ? e.velocity.x : glm::length(e.velocity))});
            scene.polygons.push_back(std::move(line));
        }
    // The jumps of the chosen curve at its inner keys.
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const Eval& left = dense[0].segments[i - 1].back();
        const Eval& right = dense[0].segments[i].front();
        const double l = dim == 1 ? left.velocity.x : glm::length(left.velocity);
        const double r = dim == 1 ? right.velocity.x : glm::length(right.velocity);
        if (std::fabs(r - l) <= 1e-9 * std::max(1.0, std::fabs(sr.hi - sr.lo))) continue;
        const double x = tx(c.keys[i].t);
        scene.segments.push_back(
            {{x, vy(l)}, {x, vy(r)}, n <= 8 ? "jump" : "", {Role::Discarded, 1.5f, true}, false});
    }
    if (p.in.constant_speed) {
        const double v = vy(p.length / (t1 - t0));
        scene.segments.push_back({{0, v}, {kW, v}, "L/T", {Role::Kept, 2.0f}, false});
    }
    if (s.k >= 0)
        scene.points.push_back({{now_x, vy(dim == 1 ? s.e.velocity.x : glm::length(s.e.velocity))},
                                "",
                                {Role::Active},
                                5.0f});
    scene.labels.push_back(
        {{0, kBot1 + 0.35}, dim == 1 ? "velocity p'(t)" : "speed |p'(t)|", {Role::Neutral}});
    scene.labels.push_back({{kW + 0.15, kBot1 - 0.3}, num(sr.hi, 3), {Role::Neutral}});
    scene.labels.push_back({{kW + 0.15, kBot0 + 0.1}, num(sr.lo, 3), {Role::Neutral}});
    scene.labels.push_back({{0, kBot0 - 0.5}, "t = " + num(t0, 4), {Role::Neutral}});
    scene.labels.push_back({{kW - 1.2, kBot0 - 0.5}, "t = " + num(t1, 4), {Role::Neutral}});
    scene.labels.push_back({{std::clamp(now_x - 0.6, 1.6, kW - 3.2), kBot0 - 0.5},
                            "now " + num(s.t, 4),
                            {Role::Window}});
}

}  // namespace cg
