// Sampling and aliasing, the picture.
// A signal: two charts in their own units. Above, s(t) against t (grey), its samples (stems and
// dots, the one just taken orange and named), the reconstruction r(t) (green) and, at a fold,
// the component in hand (orange) and its alias (dashed, red when aliased) through the same
// samples. Below, the spectrum: each frequency a bar of height |A| (the one in hand orange), the
// band [0, f_s/2] shaded blue with f_s/2, f_s, 3f_s/2 … dashed, and an aliased frequency's
// alias in red with the fold as an arrow.
// An image: two image panels, the image point-sampled at the pixel centres and supersampled,
// filling row by row (the row in hand outlined, rows not sampled yet pale blue, not white),
// with the true edge (its point a handle to drag in the first), the horizon or the zone plate's
// Nyquist circle drawn in their cells.
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "sampling/sampling.hpp"

namespace cg {

namespace {

using glm::dvec2;
using Phase = Sampling::Phase;
using Mode = Sampling::Mode;

constexpr double kPi = 3.14159265358979323846;

double rad(double deg) {
    return deg * kPi / 180;
}

void draw_signal(const Sampling::State& s, Scene& scene) {
    const Sampling::Input& in = *s.in;
    double amp = 0;
    for (const auto& c : in.signal) amp += std::fabs(c.amplitude);
    if (!(amp > 0)) amp = 1;

    // ---- s(t), its samples and the reconstruction ----
    Panel& time = add_chart(scene, "s(t) and its samples, f_s = " + num(in.rate, 6),
                            Axis{"t", 0, in.duration}, Axis{"s(t)", -1.1 * amp, 1.1 * amp});
    const int m = 300;
    auto curve = [&](auto&& f) {
        std::vector<dvec2> pts;
        pts.reserve(m + 1);
        for (int q = 0; q <= m; ++q) {
            const double t = in.duration * q / m;
            pts.push_back({t, f(t)});
        }
        return pts;
    };
    add_line(time, curve([&](double t) { return Sampling::signal(in.signal, t); }),
             {Role::Subject, 1.5f}, "s(t)");
    if (s.last == Phase::Fold && !s.aliases.empty()) {  // the component and its alias
        const std::size_t k = s.aliases.size() - 1;
        const auto c = in.signal[k];
        const auto a = s.aliases[k];
        if (in.signal.size() > 1)
            add_line(time, curve([&](double t) {
                         return c.amplitude * std::sin(2 * kPi * c.frequency * t + rad(c.phase));
                     }),
                     {Role::Active, 1.5f}, num(c.frequency, 4) + " alone");
        add_line(time, curve([&](double t) {
                     return c.amplitude * std::sin(2 * kPi * a.alias * t + rad(a.alias_phase));
                 }),
                 {a.aliased ? Role::Discarded : Role::Kept, 2.0f, true},
                 "its alias " + num(a.alias, 4));
        for (const auto& x : s.samples) {  // the component's own samples, on both curves
            const double v = c.amplitude * std::sin(2 * kPi * c.frequency * x.x + rad(c.phase));
            time.points.push_back({{x.x, v}, "", {Role::Active}, 3.5f});
        }
    }
    if (!s.curve.empty()) add_line(time, s.curve, {Role::Kept, 2.5f}, "r(t)");
    const bool many = s.samples.size() > 200;
    for (std::size_t n = 0; n < s.samples.size(); ++n) {
        const dvec2 p = s.samples[n];
        const bool last = n + 1 == s.samples.size() && s.last == Phase::Sample;
        if (!many) time.segments.push_back({{p.x, 0}, p, "", {Role::Construction, 1.0f}, false});
        time.points.push_back({p,
                               last ? "x" + std::to_string(n) : "",
                               {last ? Role::Active : Role::Window},
                               many ? 2.0f : 4.0f,
                               last ? 3 : 0});
    }

    // ---- the spectrum ----
    double fmax = in.rate;
    for (const auto& c : in.signal) fmax = std::max(fmax, c.frequency);
    const double f_hi = 1.08 * fmax;
    Panel& spectrum = add_chart(scene, "spectrum: folded into [0, f_s/2]", Axis{"f", 0, f_hi},
                                Axis{"|A|", 0, 1.3 * amp});
    const double top = 1.25 * amp;
    spectrum.polygons.push_back({{{0, 0}, {in.rate / 2, 0}, {in.rate / 2, top}, {0, top}},
                                 {Role::Window, 1.0f},
                                 true,
                                 true});
    for (int k = 1; k * in.rate / 2 <= f_hi && k <= 40; ++k) {
        const double x = k * in.rate / 2;
        const bool nyquist = k == 1;
        const char* name = k == 1   ? "f_s/2"
                           : k == 2 ? "f_s"
                           : k == 3 ? "3f_s/2"
                           : k == 4 ? "2f_s"
                                    : "";
        spectrum.segments.push_back({{x, 0},
                                     {x, top},
                                     "",
                                     {nyquist ? Role::Window : Role::Construction, 1.0f, true},
                                     false});
        if (*name)
            spectrum.labels.push_back(
                {{x, top}, name, {nyquist ? Role::Window : Role::Neutral}, nyquist ? 2 : 0});
    }
    for (std::size_t k = 0; k < in.signal.size(); ++k) {
        const auto& c = in.signal[k];
        const double h = std::fabs(c.amplitude);
        const bool current = s.last == Phase::Fold && k + 1 == s.aliases.size();
        spectrum.segments.push_back({{c.frequency, 0},
                                     {c.frequency, h},
                                     num(c.frequency, 4),
                                     {current ? Role::Active : Role::Subject, 4.0f},
                                     false,
                                     current ? 3 : 1});
        if (k < s.aliases.size() && s.aliases[k].aliased && s.aliases[k].alias != c.frequency) {
            const double xa = s.aliases[k].alias;
            spectrum.segments.push_back(
                {{xa, 0}, {xa, h}, num(xa, 4), {Role::Discarded, 4.0f}, false, current ? 3 : 1});
            spectrum.segments.push_back({{c.frequency, h + 0.06 * amp},
                                         {xa, h + 0.06 * amp},
                                         "",
                                         {Role::Discarded, 1.5f, true},
                                         true});
        }
    }
}

std::uint32_t grey(double v) {
    const auto c = static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
    return c << 24 | c << 16 | c << 8 | 0xffu;
}

// The part of the line through p at `deg` degrees inside [0, w] × [0, h] (Liang–Barsky), if any.
bool clip_line(dvec2 p, double deg, double w, double h, dvec2& a, dvec2& b) {
    const dvec2 d(std::cos(rad(deg)), std::sin(rad(deg)));
    double t0 = -1e300, t1 = 1e300;
    const double lo[2] = {0, 0}, hi[2] = {w, h};
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] == 0) {
            if (p[axis] < lo[axis] || p[axis] > hi[axis]) return false;
            continue;
        }
        double ta = (lo[axis] - p[axis]) / d[axis], tb = (hi[axis] - p[axis]) / d[axis];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    }
    if (!(t0 < t1)) return false;
    a = p + t0 * d, b = p + t1 * d;
    return true;
}

void draw_image(const Sampling::State& s, Scene& scene) {
    const Sampling::Input& in = *s.in;
    const int w = in.width, h = in.height;
    for (int side = 0; side < 2; ++side) {
        PixelGrid2 g;
        g.width = w, g.height = h;
        g.rgba.assign(std::size_t(w) * h, 0xdde8f5ffu);  // pale blue: rows not sampled yet
        const auto& v = side == 0 ? s.point_sampled : s.supersampled;
        for (std::size_t k = 0; k < v.size(); ++k) g.rgba[k] = grey(v[k]);
        g.grid_lines = w <= 32;
        Panel& panel = add_image(scene,
                                 side == 0 ? "1 sample per pixel (the centre)"
                                           : std::to_string(in.samples) + " " +
                                                 sampling::pattern_id(in.pattern) + " samples, " +
                                                 sampling::filter_id(in.filter) + " filter",
                                 std::move(g));
        if (s.row >= 0 && s.phase != Phase::Done)
            panel.polygons.push_back({{{0, double(s.row)},
                                       {double(w), double(s.row)},
                                       {double(w), s.row + 1.0},
                                       {0, s.row + 1.0}},
                                      {Role::Active, 2.0f},
                                      true,
                                      false});
        if (in.image.kind == Sampling::ImageKind::ZonePlate) {  // the Nyquist circle r = ρ
            const double r = in.image.nyquist_radius;
            const dvec2 c(w / 2.0, h / 2.0);
            Polygon2 p;
            p.style = {Role::Window, 1.5f, true};
            for (int a = 0; a < 64; ++a)
                p.points.push_back(c + r * dvec2(std::cos(a * kPi / 32), std::sin(a * kPi / 32)));
            panel.polygons.push_back(std::move(p));
        } else if (in.image.kind == Sampling::ImageKind::Edge) {  // the true edge
            dvec2 a, b;
            if (clip_line(in.image.point, in.image.angle, w, h, a, b))
                panel.segments.push_back({a, b, "", {Role::Window, 1.5f, true}, false});
            if (side == 0)  // drag the edge's point to move it
                panel.handles.push_back(
                    {in.image.point, "edge", "/image/point/0", "/image/point/1"});
        } else if (in.image.horizon > 0 && in.image.horizon < h) {
            panel.segments.push_back({{0, in.image.horizon},
                                      {double(w), in.image.horizon},
                                      side == 0 ? "horizon" : "",
                                      {Role::Window, 1.0f, true},
                                      false});
        }
    }
}

}  // namespace

void Sampling::draw(const State& s, Scene& scene) {
    if (s.in->mode == Mode::Signal)
        draw_signal(s, scene);
    else
        draw_image(s, scene);
}

}  // namespace cg
