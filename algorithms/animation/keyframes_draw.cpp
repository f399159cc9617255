// Keyframes, the picture. Every curve is sampled whole, so the panels stay put while frames play.
// A scalar channel: two charts against t (s). Left, the value p(t) (the chosen interpolation in
// orange, linear dashed for comparison, Catmull–Rom in grey beside Kochanek–Bartels), the keys
// p0, p1, …, the frame's time as a blue line and the frame's value as an orange dot. Right, the
// velocity p'(t), each segment drawn on its own so that a jump at a key shows as a break (marked
// red, "jump").
// A path: the path in its plane in the world ((x, y); a 3D path is seen from the front), the
// keys, and the frames so far as dots — orange at parameter = time, green at constant speed — so
// the uneven spacing shows; beside it a chart of the speed |p'(t)| against t (from 0), with the
// constant speed L/T in green.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "animation/keyframes.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

constexpr int kMaxCurvePoints = 1500;
constexpr std::size_t kMaxDots = 60;

const char* pretty_name(Keyframes::Interpolation i) {
    return i == Keyframes::Interpolation::Linear       ? "linear"
           : i == Keyframes::Interpolation::CatmullRom ? "Catmull–Rom"
                                                       : "Kochanek–Bartels";
}

}  // namespace

void Keyframes::draw(const State& s, Scene& scene) {
    const Prepared& p = *s.p;
    const Curve& c = p.curve;
    const int dim = p.in.dim;
    const std::size_t n = c.keys.size();
    const double t0 = c.keys.front().t, t1 = c.keys.back().t;
    const int per = std::clamp(kMaxCurvePoints / int(n - 1), 2, 48);
    const bool shown = s.k >= 0;  // a frame has been computed

    // The curves to draw: the chosen one and the comparison ones.
    std::vector<std::pair<Curve, Style>> curves;
    curves.push_back({c, {Role::Active, 2.5f}});
    if (c.kind != Interpolation::Linear)
        curves.push_back(
            {make_curve(p.in, Interpolation::Linear), {Role::Construction, 1.0f, true}});
    if (c.kind == Interpolation::KochanekBartels)
        curves.push_back({make_curve(p.in, Interpolation::CatmullRom), {Role::Subject, 1.5f}});

    // Dense samples, segment by segment (the value and the velocity at both ends of each).
    std::vector<std::vector<std::vector<Eval>>> dense(curves.size());
    double v_lo = 1e300, v_hi = -1e300;  // the value's range, for the time line
    for (std::size_t q = 0; q < curves.size(); ++q) {
        dense[q].resize(n - 1);
        for (std::size_t i = 0; i + 1 < n; ++i)
            for (int j = 0; j <= per; ++j) {
                const Eval e = evaluate_in(curves[q].first, int(i), double(j) / per);
                dense[q][i].push_back(e);
                if (std::isfinite(e.value.x))
                    v_lo = std::min(v_lo, e.value.x), v_hi = std::max(v_hi, e.value.x);
            }
    }
    auto time_of = [&](std::size_t i, const Eval& e) {
        return c.keys[i].t + e.u * (c.keys[i + 1].t - c.keys[i].t);
    };
    auto rate = [&](const Eval& e) { return dim == 1 ? e.velocity.x : glm::length(e.velocity); };
    const Style now_style{Role::Window, 1.0f, true};

    // ---- the value against time (scalar) or the path in the world ----
    if (dim == 1) {
        Panel& value = add_chart(
            scene,
            shown ? "value p(" + num(s.t, 4) + ") = " + num(s.e.value.x, 4) : "value p(t)",
            Axis{"t (s)"}, Axis{"p"});
        for (std::size_t q = curves.size(); q-- > 0;) {  // the chosen curve last, on top
            std::vector<glm::dvec2> line;
            for (std::size_t i = 0; i + 1 < n; ++i)
                for (std::size_t j = i == 0 ? 0 : 1; j < dense[q][i].size(); ++j)
                    line.push_back({time_of(i, dense[q][i][j]), dense[q][i][j].value.x});
            add_line(value, std::move(line), curves[q].second, pretty_name(curves[q].first.kind));
        }
        for (std::size_t i = 0; i < n; ++i)
            value.points.push_back({{c.keys[i].t, c.keys[i].value.x},
                                    n <= 12 ? "p" + std::to_string(i) : "",
                                    {Role::Neutral},
                                    4.5f});
        value.segments.push_back({{s.t, v_lo}, {s.t, v_hi}, "", now_style, false});
        if (shown) value.points.push_back({{s.t, s.e.value.x}, "", {Role::Active}, 6.5f});
        std::reverse(value.legend.begin(), value.legend.end());  // the chosen curve first
    } else {
        // The frames so far, thinned to kMaxDots: parameter = time orange, constant speed green.
        auto xy = [](glm::dvec3 v) { return glm::dvec2(v.x, v.y); };
        for (std::size_t q = curves.size(); q-- > 0;) {
            Polygon2 line{{}, curves[q].second, false, false};
            for (std::size_t i = 0; i + 1 < n; ++i)
                for (std::size_t j = i == 0 ? 0 : 1; j < dense[q][i].size(); ++j)
                    line.points.push_back(xy(dense[q][i][j].value));
            scene.polygons.push_back(std::move(line));
        }
        for (std::size_t i = 0; i < n; ++i)
            scene.points.push_back({xy(c.keys[i].value),
                                    n <= 12 ? "p" + std::to_string(i) : "",
                                    {Role::Neutral},
                                    4.5f});
        const std::size_t frames = s.values.size();
        const std::size_t stride = std::max<std::size_t>(1, (frames + kMaxDots - 1) / kMaxDots);
        for (std::size_t f = 0; f < frames; f += stride) {
            scene.points.push_back({xy(s.values[f]), "", {Role::Active}, 2.5f});
            if (p.in.constant_speed)
                scene.points.push_back({xy(s.evens[f]), "", {Role::Kept}, 2.5f});
        }
        if (shown) {
            scene.points.push_back({xy(s.e.value), "P(t)", {Role::Active}, 6.5f});
            if (p.in.constant_speed)
                scene.points.push_back({xy(s.even), "P(u(s))", {Role::Kept}, 6.5f});
        }
    }

    // ---- the velocity (scalar) or the speed (path) against time ----
    Panel& rate_chart =
        dim == 1 ? add_chart(scene,
                             shown ? "velocity p'(" + num(s.t, 4) +
                                         ") = " + num(s.e.velocity.x, 4)
                                   : "velocity p'(t)",
                             Axis{"t (s)"}, Axis{"p' (per s)"})
                 : add_chart(scene,
                             std::string("speed |p'(t)|, ") + pretty_name(c.kind) +
                                 (dim == 3 ? " (path seen from the front)" : ""),
                             Axis{"t (s)"}, Axis{"|p'| (per s)", 0, 0, false, true});
    const std::size_t drawn = dim == 1 ? curves.size() : 1;
    double r_lo = dim == 1 ? 1e300 : 0, r_hi = -1e300;
    for (std::size_t q = drawn; q-- > 0;)
        for (std::size_t i = 0; i + 1 < n; ++i) {
            std::vector<glm::dvec2> line;
            for (const Eval& e : dense[q][i]) {
                line.push_back({time_of(i, e), rate(e)});
                if (std::isfinite(rate(e))) r_lo = std::min(r_lo, rate(e)), r_hi = std::max(r_hi, rate(e));
            }
            add_line(rate_chart, std::move(line), curves[q].second,
                     i > 0        ? ""
                     : dim == 1 ? pretty_name(curves[q].first.kind)
                                : "parameter = time");
        }
    std::reverse(rate_chart.legend.begin(), rate_chart.legend.end());  // the chosen curve first
    // The jumps of the chosen curve at its inner keys.
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double l = rate(dense[0][i - 1].back()), r = rate(dense[0][i].front());
        if (std::fabs(r - l) <= 1e-9 * std::max(1.0, std::fabs(r_hi - r_lo))) continue;
        rate_chart.segments.push_back({{c.keys[i].t, l},
                                       {c.keys[i].t, r},
                                       n <= 8 ? "jump" : "",
                                       {Role::Discarded, 1.5f, true},
                                       false});
    }
    if (p.in.constant_speed) {
        const double v = p.length / (t1 - t0);
        add_line(rate_chart, {{t0, v}, {t1, v}}, {Role::Kept, 2.0f}, "L/T: constant speed");
        r_hi = std::max(r_hi, v);
    }
    rate_chart.segments.push_back({{s.t, r_lo}, {s.t, r_hi}, "", now_style, false});
    if (shown) rate_chart.points.push_back({{s.t, rate(s.e)}, "", {Role::Active}, 5.0f});
}

}  // namespace cg
