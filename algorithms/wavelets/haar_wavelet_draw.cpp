// The Haar wavelet transform, the picture.
// 1D: two bar charts over the index i, on one value scale — first, the vector before this step
// (the signal at first), this step's pairs bracketed in orange; second, the vector after it,
// averages green and details teal (the x axes say where pair k went). Zeroed details are dashed
// red outlines at their old height; at the end the input is drawn as grey ticks over the
// reconstruction.
// 2D: image panels — the image, the coefficient image (averages in grey over their range,
// details as mid grey ± √(|d| / max |d|) so that small ones show; zeroed ones reddish grey) with
// the band boundaries in blue and this step's lines outlined in orange (the step's focus); during
// the reconstruction the same panel shows the array being rebuilt from the kept coefficients.
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "wavelets/haar_wavelet.hpp"

namespace cg {

namespace {

using Input = HaarWavelet::Input;
using Mode = HaarWavelet::Mode;
using Pass = HaarWavelet::Pass;
using Phase = HaarWavelet::Phase;
using State = HaarWavelet::State;

std::uint32_t grey(double g) {
    const auto v = std::uint32_t(std::clamp(g, 0.0, 255.0));
    return (v << 24) | (v << 16) | (v << 8) | 0xffu;
}

// How far each line's averages reach after the passes so far: a forward pass leaves len / 2^levels
// averages on its lines, an inverse pass len.
void averages_extent(const State& s, std::vector<int>& row_low, std::vector<int>& col_low) {
    const int n = s.in->n;
    row_low.assign(std::size_t(n), n);
    col_low.assign(std::size_t(n), n);
    for (int q = 0; q < s.next; ++q) {
        const Pass& p = (*s.passes)[q];
        auto& low = p.rows ? row_low : col_low;
        for (int l = p.first; l < p.first + p.count; ++l)
            low[l] = p.inverse ? p.len : p.len >> p.levels;
    }
}

// ---- 1D: bar charts ----

// A bar chart of v over i = 0..n−1: the first `averages` bars green, the rest teal, each valued
// when there are few; zeroed details (v = 0 where `dropped_from` was not) as dashed red outlines.
Panel& bars(Scene& scene, const std::string& title, const std::string& x_label,
            const std::vector<double>& v, int averages, double lo, double hi,
            const std::vector<double>* dropped_from) {
    const int n = int(v.size());
    Panel& chart = add_chart(scene, title, Axis{x_label, -0.5, n - 0.5}, Axis{"value", lo, hi});
    for (int i = 0; i < n; ++i) {
        const Role role = i < averages ? Role::Kept : Role::Entering;
        if (v[i] != 0) add_bars(chart, {{double(i), v[i]}}, 0.8, {role, 1.0f});
        if (dropped_from && (*dropped_from)[i] != 0 && v[i] == 0) {
            const double x0 = i - 0.4, x1 = i + 0.4, yd = (*dropped_from)[i];
            chart.polygons.push_back({{{x0, 0}, {x1, 0}, {x1, yd}, {x0, yd}},
                                      {Role::Discarded, 1.5f, true},
                                      true,
                                      false});
        }
        if (n <= 16) chart.labels.push_back({{double(i), v[i]}, num(v[i], 3), {role}});
    }
    return chart;
}

void draw_1d(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const int n = in.n;
    std::vector<int> row_low, col_low;
    averages_extent(s, row_low, col_low);
    const bool started = s.next > 0 || s.last != Phase::Forward || !s.coefficients.empty();
    const bool threshold_now = s.last == Phase::Threshold && !s.compressed.empty();
    const bool pass_now = s.next > 0 && (s.last == Phase::Forward || s.last == Phase::Inverse);
    std::vector<double> before;
    int before_avg = n;
    if (threshold_now) {
        before = s.coefficients;
        before_avg = 1;
    } else if (pass_now) {
        before = HaarWavelet::before_pass(s, s.next - 1);
        const Pass& p = (*s.passes)[s.next - 1];
        before_avg = p.inverse ? p.len / 2 : p.len;
    } else {
        before = in.data;
    }
    // One value scale for both charts (from 0), with room for the values over the bars.
    double lo = 0, hi = 0;
    for (const std::vector<double>* v : {&in.data, &s.c, static_cast<const std::vector<double>*>(&before)})
        for (double x : *v) lo = std::min(lo, x), hi = std::max(hi, x);
    if (!(hi > lo)) hi = lo + 1;
    const double pad = 0.14 * (hi - lo);
    lo = lo < 0 ? lo - pad : 0;
    hi = hi > 0 ? hi + pad : 0;
    const bool dropped = !s.compressed.empty() && in.compress != HaarWavelet::Compress::None &&
                         s.last == Phase::Threshold;
    std::string title_before = "x, the signal", title_after = "c, the array worked on";
    std::string axis_before = "i", axis_after = "i";
    if (pass_now) {
        const Pass& p = (*s.passes)[s.next - 1];
        const std::string h = std::to_string(p.len / 2);
        const std::string split = "i: s_k at k, d_k at " + h + " + k";
        const std::string pairs = "i: pair k at 2k, 2k + 1";
        title_before = p.inverse ? "before undoing the level of length " + std::to_string(p.len)
                                 : "before level " + std::to_string(s.next);
        title_after = p.inverse ? "rebuilt: pairs s + d, s − d"
                                : "after: averages s (green), then details d (teal)";
        axis_before = p.inverse ? split : pairs;
        axis_after = p.inverse ? pairs : split;
    } else if (threshold_now) {
        title_before = "coefficients";
        title_after = "kept (dashed red: zeroed)";
    } else if (s.last == Phase::Summary) {
        title_after = "reconstruction (grey ticks: the signal)";
    }
    bars(scene, title_before, axis_before, before, started ? before_avg : n, lo, hi, nullptr);
    bars(scene, title_after, axis_after, s.c, row_low[0], lo, hi,
         dropped ? &s.coefficients : nullptr);
    Panel &top = scene.panels[0], &bottom = scene.panels[1];  // (after both are in)
    if (s.last == Phase::Summary)  // the input as ticks over the reconstruction
        for (int i = 0; i < n; ++i)
            bottom.segments.push_back(
                {{i - 0.4, in.data[i]}, {i + 0.4, in.data[i]}, "", {Role::Subject, 2.0f}, false});
    // The pairs of this step, bracketed in orange just above (or below) their taller bar.
    if (pass_now && n <= 64) {
        const Pass& p = (*s.passes)[s.next - 1];
        const int half = p.len / 2;
        for (int k = 0; k < half; ++k) {
            const int a0 = p.inverse ? k : 2 * k, a1 = p.inverse ? half + k : 2 * k + 1;
            if (p.inverse) {  // s_k and d_k are apart: outline both
                for (int a : {a0, a1}) {
                    const double y = before[a];
                    top.polygons.push_back({{{a - 0.45, 0}, {a + 0.45, 0}, {a + 0.45, y}, {a - 0.45, y}},
                                            {Role::Active, 2.0f},
                                            true,
                                            false});
                }
                continue;
            }
            const double y = std::max({before[a0], before[a1], 0.0}) + 0.04 * (hi - lo);
            top.segments.push_back({{a0 - 0.4, y}, {a1 + 0.4, y}, "", {Role::Active, 2.5f}, false});
        }
    }
}

// ---- 2D: image panels ----

Panel& image(Scene& scene, std::string title, const Input& in, const std::vector<double>& v,
             const std::vector<int>* row_low, const std::vector<int>* col_low,
             const std::vector<double>* coefficients) {
    const int n = in.n;
    double lo = 1e300, hi = -1e300;
    for (double x : in.data) lo = std::min(lo, x), hi = std::max(hi, x);
    // A cell holds an average when both its row's and its column's averages reach it (every
    // cell of a plain image).
    auto average = [&](int r, int c) {
        return !row_low || (c < (*row_low)[r] && r < (*col_low)[c]);
    };
    double alo = lo, ahi = hi, dmax = 0;
    if (row_low) {
        alo = 1e300, ahi = -1e300;
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) {
                const double x = v[std::size_t(r) * n + c];
                if (average(r, c))
                    alo = std::min(alo, x), ahi = std::max(ahi, x);
                else
                    dmax = std::max(dmax, std::fabs(x));
            }
        if (!in.normalised) alo = std::min(alo, lo), ahi = std::max(ahi, hi);
    }
    const double a_scale = ahi > alo ? 255 / (ahi - alo) : 0;
    const double d_scale = dmax > 0 ? 1 / dmax : 0;
    PixelGrid2 g;
    g.width = g.height = n;
    g.grid_lines = n <= 16;
    g.rgba.resize(v.size());
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const std::size_t at = std::size_t(r) * n + c;
            const std::size_t cell = std::size_t(n - 1 - r) * n + c;  // row 0 at the top
            std::uint32_t colour;
            if (average(r, c)) {
                colour = grey(a_scale > 0 ? (v[at] - alo) * a_scale : 128);
            } else if (coefficients && (*coefficients)[at] != 0 && v[at] == 0) {
                colour = 0xa08080ffu;  // zeroed: a reddish mid grey (0 is mid grey)
            } else {  // details: mid grey ± √(|d| / max), to make small ones visible
                const double t = std::sqrt(std::fabs(v[at]) * d_scale);
                colour = grey(128 + (v[at] < 0 ? -127 : 127) * t);
            }
            g.rgba[cell] = colour;
        }
    return add_image(scene, std::move(title), std::move(g));
}

void rect(Panel& panel, double x0, double y0, double x1, double y1, Style style) {
    panel.polygons.push_back({{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, style, true, false});
}

void draw_2d(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const int n = in.n;
    std::vector<int> row_low, col_low;
    averages_extent(s, row_low, col_low);
    const bool inverse = s.last == Phase::Inverse || s.last == Phase::Summary;
    image(scene, "image x", in, in.data, nullptr, nullptr, nullptr);
    // The working array: the coefficients, then (starting from the kept ones, the zeroed still
    // marked) the reconstruction under way.
    const std::string title = !inverse ? (in.mode == Mode::Standard ? "coefficients (standard)"
                                                                    : "coefficients (non-standard)")
                              : s.last == Phase::Summary ? "reconstruction"
                                                         : "reconstruction under way";
    const bool marked = s.last == Phase::Threshold || (inverse && s.last != Phase::Summary);
    image(scene, title, in, s.c, &row_low, &col_low, marked ? &s.coefficients : nullptr);
    const int at = int(scene.panels.size()) - 1;  // the panel being worked on
    Panel& work = scene.panels.back();
    // The band boundaries of the transform: where averages end and details begin.
    const Style band{Role::Window, 1.0f};
    for (int r = 0; r < n; ++r)
        if (row_low[r] < n) {
            const double x = row_low[r];
            work.segments.push_back({{x, double(n - 1 - r)}, {x, double(n - r)}, "", band, false});
        }
    for (int c = 0; c < n; ++c)
        if (col_low[c] < n) {
            const double y = n - col_low[c];
            work.segments.push_back({{double(c), y}, {c + 1.0, y}, "", band, false});
        }
    // The lines of this step, outlined; the quadrants of a non-standard level named.
    if (s.next > 0 && (s.last == Phase::Forward || s.last == Phase::Inverse)) {
        const Pass& p = (*s.passes)[s.next - 1];
        const double a = p.first, b = p.first + p.count;
        const glm::dvec2 lo = p.rows ? glm::dvec2(0, n - b) : glm::dvec2(a, n - p.len);
        const glm::dvec2 hi = p.rows ? glm::dvec2(p.len, n - a) : glm::dvec2(b, n);
        rect(work, lo.x, lo.y, hi.x, hi.y, {Role::Active, 2.5f});
        add_focus(scene, lo, hi, at);
        if (in.mode == Mode::NonStandard && !p.rows && !p.inverse && p.len >= 4) {
            const double h = p.len / 2.0;
            work.labels.push_back({{0.2, n - h / 2}, "averages", {Role::Kept}});
            work.labels.push_back({{h + 0.2, n - h / 2}, "row details", {Role::Entering}});
            work.labels.push_back({{0.2, n - 1.5 * h}, "column details", {Role::Entering}});
            work.labels.push_back({{h + 0.2, n - 1.5 * h}, "diagonal", {Role::Entering}});
        }
    }
}

}  // namespace

void HaarWavelet::draw(const State& s, Scene& scene) {
    if (s.in->mode == Mode::OneD)
        draw_1d(s, scene);
    else
        draw_2d(s, scene);
}

}  // namespace cg
