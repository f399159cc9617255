// A scene's panels: charts (axes, ticks and numbers in their own units, series, a legend),
// images (a raster filling its panel, pixel-exact) and diagrams (a drawing fitted at one
// scale). Sections: [ranges and ticks] [title and legend] [chart] [image] [diagram]
// [draw_panel].
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "core/format.hpp"
#include "viewer/canvas_draw.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/layout.hpp"
#include "viewer/palette.hpp"
#include "viewer/text_wrap.hpp"

namespace cg::viewer {

namespace {

constexpr std::uint32_t kPanelFrame = 0xd0d0d0ff;
constexpr std::uint32_t kPlotFrame = 0x9a9a9aff;
constexpr std::uint32_t kZeroLine = 0xb0b0b0ff;

// --- [ranges and ticks] ----------------------------------------------------------------------

struct Range {
    double lo = DBL_MAX, hi = -DBL_MAX;
    void add(double v) {
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    bool empty() const { return lo > hi; }
};

// x or y of every bounded primitive (labels are placed, they do not set the range).
void data_range(const Layer2& l, Range& x, Range& y) {
    auto add = [&](glm::dvec2 p) { x.add(p.x), y.add(p.y); };
    for (const PixelGrid2& g : l.grids)
        add(g.origin), add(g.origin + glm::dvec2(g.width, g.height));
    for (const Polygon2& poly : l.polygons)
        for (glm::dvec2 p : poly.points) add(p);
    for (const Segment2& s : l.segments) add(s.a), add(s.b);
    for (const Point2& p : l.points) add(p.p);
}

// The range an axis shows: as given, or the data's padded by 5% (a flat series gets ±1, or
// ±10% of its value), reaching 0 when asked; log axes in decades of log10.
Range axis_range(const Axis& axis, Range data) {
    if (axis.lo < axis.hi) {
        Range r;
        r.lo = axis.log ? std::log10(std::max(axis.lo, 1e-300)) : axis.lo;
        r.hi = axis.log ? std::log10(std::max(axis.hi, 1e-300)) : axis.hi;
        return r;
    }
    if (!axis.names.empty()) {  // every category in view, half a step round each
        data.add(-0.5);
        data.add(static_cast<double>(axis.names.size()) - 0.5);
        return data;
    }
    if (data.empty()) data.lo = 0, data.hi = 1;
    if (axis.include_zero && !axis.log) data.add(0);
    if (data.hi - data.lo <= 1e-12 * std::max(1.0, std::fabs(data.hi))) {
        const double d = data.lo == 0 ? 1 : 0.1 * std::fabs(data.lo);
        return {data.lo - d, data.hi + d};
    }
    const double pad = 0.05 * (data.hi - data.lo);
    Range r{data.lo - pad, data.hi + pad};
    // Padding must not push a range that starts at 0 below it (a count, an energy).
    if (data.lo >= 0 && r.lo < 0 && !axis.log) r.lo = 0;
    return r;
}

// Tick positions (in the axis's plotted units) at least `min_pixels` apart: at multiples of the
// axis's own step when it has one (a whole number of bands), else of a round number.
std::vector<double> ticks(const Range& r, double pixels, double min_pixels, const Axis& axis) {
    std::vector<double> out;
    const double per_pixel = (r.hi - r.lo) / std::max(pixels, 1.0);
    if (!axis.names.empty()) {  // the categories, every k-th one when they are crowded
        const std::size_t stride =
            std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(min_pixels * per_pixel)));
        for (std::size_t k = 0; k < axis.names.size(); k += stride) out.push_back(double(k));
        return out;
    }
    double step = nice_step(min_pixels * per_pixel);
    if (axis.step > 0 && !axis.log)
        step = axis.step * std::max(1.0, nice_step(min_pixels * per_pixel / axis.step));
    if (axis.log) step = std::max(1.0, std::round(step));  // whole decades
    for (double v = std::ceil(r.lo / step - 1e-9) * step; v <= r.hi + 1e-9 * step; v += step)
        out.push_back(std::fabs(v) < step * 1e-9 ? 0 : v);
    return out;
}

std::string tick_text(double v, bool log) {
    if (!log) return num(v, 4);
    const double p = std::pow(10.0, v);
    return p >= 1e-3 && p <= 1e4 ? num(p, 4) : num(p, 2);
}

// A tick's text: its category's name, or its number in the axis's shared power of ten.
std::string tick_label(const Axis& axis, double v, double unit) {
    if (!axis.names.empty()) {
        const long k = std::lround(v);
        return k >= 0 && k < static_cast<long>(axis.names.size()) ? text_minus(axis.names[k]) : "";
    }
    return tick_text(v / unit, axis.log);
}

// A linear axis whose ticks are huge or tiny is read in a power of ten shared by all of them,
// written once with the axis's label ("E (J), × 10¹³" over ticks 0, 1, 2, 3.5): the ticks stay
// short and the plot keeps its width. Returns the exponent (0: none needed).
int shared_power(const std::vector<double>& ticks, const Axis& axis) {
    if (axis.log || !axis.names.empty()) return 0;
    double largest = 0;
    for (double v : ticks) largest = std::max(largest, std::fabs(v));
    if (largest == 0 || (largest < 1e5 && largest >= 1e-3)) return 0;
    return static_cast<int>(std::floor(std::log10(largest)));
}

std::string with_power(const std::string& label, int power) {
    if (power == 0) return label;
    const std::string ten = num(std::pow(10.0, power));  // "10¹³", "10⁻⁵"
    return label.empty() ? "× " + ten : label + ",  × " + ten;
}

// The layer with log10 applied to the coordinates of the log axes; points at or below 0 on a
// log axis are left out (a polyline is broken there).
Layer2 logged(const Layer2& l, bool lx, bool ly) {
    if (!lx && !ly) return l;
    auto ok = [&](glm::dvec2 p) { return (!lx || p.x > 0) && (!ly || p.y > 0); };
    auto f = [&](glm::dvec2 p) {
        return glm::dvec2(lx ? std::log10(p.x) : p.x, ly ? std::log10(p.y) : p.y);
    };
    Layer2 out;
    out.labels = l.labels;
    for (Label2& x : out.labels) x.p = ok(x.p) ? f(x.p) : glm::dvec2(NAN, NAN);
    for (const Polygon2& poly : l.polygons) {
        Polygon2 piece{{}, poly.style, poly.closed, poly.filled};
        for (glm::dvec2 p : poly.points) {
            if (ok(p)) {
                piece.points.push_back(f(p));
                continue;
            }
            if (piece.points.size() > 1) out.polygons.push_back(piece);
            piece.points.clear();
            piece.closed = false;
        }
        if (piece.points.size() > 1) out.polygons.push_back(std::move(piece));
    }
    for (const Segment2& s : l.segments)
        if (ok(s.a) && ok(s.b)) {
            Segment2 c = s;
            c.a = f(s.a), c.b = f(s.b);
            out.segments.push_back(std::move(c));
        }
    for (const Point2& p : l.points)
        if (ok(p.p)) {
            Point2 c = p;
            c.p = f(p.p);
            out.points.push_back(std::move(c));
        }
    return out;
}

// --- [title and legend] ----------------------------------------------------------------------

double text_width(ImFont* font, const std::string& t) {
    return font->CalcTextSizeA(font->FontSize, FLT_MAX, 0, t.c_str()).x;
}

// The title, wrapped to the panel's width; returns the height it took (`dl` null: measures).
double draw_title(ImDrawList* dl, const Box& box, const std::string& title, const Fonts& f) {
    if (title.empty()) return 4;
    const float wrap = static_cast<float>(std::max(box.max.x - box.min.x - 12, 20.0));
    // Broken at spaces only (ImGui's wrapping would split "t = 1.15" after its point).
    const std::string t = wrap_at_spaces(f.ui, f.ui->FontSize, text_minus(title), wrap);
    const ImVec2 size = f.ui->CalcTextSizeA(f.ui->FontSize, FLT_MAX, 0, t.c_str());
    if (dl)
        dl->AddText(f.ui, f.ui->FontSize, im(box.min + glm::dvec2(6, 4)), im_colour(kCaptionText),
                    t.c_str());
    return size.y + 8;
}

// The legend's entries in rows across the panel's width; returns the height it took (`dl`
// null: measures).
double draw_legend(ImDrawList* dl, const Box& box, const std::vector<LegendEntry>& legend,
                   const Fonts& f) {
    if (legend.empty()) return 0;
    const double row = f.small->FontSize + 4, swatch = 18;
    double x = box.min.x + 6, y = box.min.y;
    for (const LegendEntry& e : legend) {
        const std::string t = text_minus(e.text);
        const double w = swatch + 4 + text_width(f.small, t) + 14;
        if (x + w > box.max.x && x > box.min.x + 6) x = box.min.x + 6, y += row;
        if (!dl) {
            x += w;
            continue;
        }
        const ImU32 c = im_colour(style_rgba(e.style));
        const float mid = static_cast<float>(y + row / 2);
        if (e.marker) {
            dl->AddCircleFilled(ImVec2(static_cast<float>(x + swatch / 2), mid), 4, c);
        } else if (e.style.dashed) {
            for (double d = 0; d < swatch; d += 6)
                dl->AddLine(ImVec2(static_cast<float>(x + d), mid),
                            ImVec2(static_cast<float>(x + std::min(d + 3.5, swatch)), mid), c,
                            std::clamp(e.style.width, 1.0f, 4.0f));
        } else {
            dl->AddLine(ImVec2(static_cast<float>(x), mid),
                        ImVec2(static_cast<float>(x + swatch), mid), c,
                        std::clamp(e.style.width, 1.0f, 4.0f));
        }
        dl->AddText(f.small, f.small->FontSize,
                    ImVec2(static_cast<float>(x + swatch + 4), static_cast<float>(y + 2)),
                    im_colour(kCaptionText), t.c_str());
        x += w;
    }
    return y + row - box.min.y + 2;
}

// --- [chart] ---------------------------------------------------------------------------------

ScreenMap draw_chart(ImDrawList* dl, const Box& body, const Panel& panel, const Fonts& f,
                     GridTextures* textures, std::size_t slot, Recording rec, int hot) {
    const Layer2 layer = logged(panel, panel.x.log, panel.y.log);
    Range dx, dy;
    data_range(layer, dx, dy);

    const double small = f.small->FontSize;
    // (A shared power of ten is written with the axis's label: room for it either way.)
    const double y_label = small + 4, x_label = small + 4;
    // Room for the y ticks' numbers: the widest of them.
    Box plot{{body.min.x, body.min.y + y_label + 4},
             {body.max.x - 12, body.max.y - small - 8 - x_label}};
    Range rx = axis_range(panel.x, dx), ry = axis_range(panel.y, dy);
    std::vector<double> yt = ticks(ry, plot.max.y - plot.min.y, 34, panel.y);
    int y_power = shared_power(yt, panel.y);
    double widest = 0;
    for (double v : yt)
        widest =
            std::max(widest, text_width(f.small, tick_label(panel.y, v, std::pow(10.0, y_power))));
    plot.min.x = body.min.x + widest + 12;
    if (plot.max.x - plot.min.x < 20 || plot.max.y - plot.min.y < 20) return ScreenMap{plot, {}};
    if (panel.equal_aspect) {
        // One length for a unit of x and of y: the range with room to spare is widened about
        // its middle until both fill the plot at the same scale.
        const double sx = (plot.max.x - plot.min.x) / (rx.hi - rx.lo);
        const double sy = (plot.max.y - plot.min.y) / (ry.hi - ry.lo);
        Range& wider = sx < sy ? ry : rx;
        const double scale = std::min(sx, sy);
        const double half =
            (sx < sy ? plot.max.y - plot.min.y : plot.max.x - plot.min.x) / scale / 2;
        const double mid = (wider.lo + wider.hi) / 2;
        wider.lo = mid - half, wider.hi = mid + half;
        yt = ticks(ry, plot.max.y - plot.min.y, 34, panel.y);
    }
    y_power = shared_power(yt, panel.y);
    const double y_unit = std::pow(10.0, y_power);
    const std::vector<double> xt = ticks(rx, plot.max.x - plot.min.x, 70, panel.x);
    const int x_power = shared_power(xt, panel.x);
    const double x_unit = std::pow(10.0, x_power);

    ScreenMap map{plot, {}};
    map.view.center = {(rx.lo + rx.hi) / 2, (ry.lo + ry.hi) / 2};
    map.view.zoom = (plot.max.x - plot.min.x) / (rx.hi - rx.lo);
    map.y_scale = (plot.max.y - plot.min.y) / (ry.hi - ry.lo) / map.view.zoom;
    if (panel.y.reversed) map.y_scale = -map.y_scale;  // a screen's rows: y grows downward

    // Grid lines at the ticks, the zero lines, the frame; the numbers outside it.
    const ImU32 grid = im_colour(kGridMajor), text = im_colour(kTickLabel);
    for (double v : xt) {
        const float x = static_cast<float>(std::floor(map.to_screen({v, 0}).x) + 0.5);
        dl->AddLine(ImVec2(x, float(plot.min.y)), ImVec2(x, float(plot.max.y)),
                    v == 0 && !panel.x.log ? im_colour(kZeroLine) : grid);
        const std::string t = tick_label(panel.x, v, x_unit);
        const double w = text_width(f.small, t);
        const double tx = std::clamp(x - w / 2, body.min.x, body.max.x - w);
        dl->AddText(f.small, f.small->FontSize, ImVec2(float(tx), float(plot.max.y + 3)), text,
                    t.c_str());
    }
    for (double v : yt) {
        const float y = static_cast<float>(std::floor(map.to_screen({0, v}).y) + 0.5);
        dl->AddLine(ImVec2(float(plot.min.x), y), ImVec2(float(plot.max.x), y),
                    v == 0 && !panel.y.log ? im_colour(kZeroLine) : grid);
        const std::string t = tick_label(panel.y, v, y_unit);
        dl->AddText(f.small, f.small->FontSize,
                    ImVec2(float(plot.min.x - 6 - text_width(f.small, t)), float(y - small / 2)),
                    text, t.c_str());
    }
    dl->AddRect(im(plot.min), im(plot.max), im_colour(kPlotFrame));
    if (const std::string t = with_power(text_minus(panel.y.label), y_power); !t.empty())
        dl->AddText(f.small, f.small->FontSize, ImVec2(float(body.min.x + 4), float(body.min.y)),
                    im_colour(kCaptionText), t.c_str());
    if (const std::string t = with_power(text_minus(panel.x.label), x_power); !t.empty()) {
        dl->AddText(
            f.small, f.small->FontSize,
            ImVec2(float(plot.max.x - text_width(f.small, t)), float(body.max.y - small - 2)),
            im_colour(kCaptionText), t.c_str());
    }

    dl->PushClipRect(im(plot.min), im(plot.max), true);
    draw_scene(dl, map, layer, f, hot, {}, textures, rec, slot);
    dl->PopClipRect();
    // What the chart draws: the plot and its ticks' numbers (the axes' names and the title are
    // the panel's own rows).
    if (rec.record)
        rec.record->panels[rec.panel].content = {{plot.min.x - widest - 8, plot.min.y},
                                                 {plot.max.x, plot.max.y + small + 4}};
    return map;
}

// --- [image] ---------------------------------------------------------------------------------

ScreenMap draw_image(ImDrawList* dl, const Box& body, const Panel& panel, const Fonts& f,
                     GridTextures* textures, std::size_t slot, Recording rec, int hot) {
    ScreenMap map{body.grown(-4), {}};
    if (panel.grids.empty()) return map;
    const PixelGrid2& g = panel.grids.front();
    const double w = std::max(g.width, 1), h = std::max(g.height, 1);
    const glm::dvec2 room = map.canvas.max - map.canvas.min;
    const double zoom = image_zoom(room.x / w, room.y / h);  // as the layout sized the panel
    map.view = {glm::dvec2(w / 2, h / 2), std::max(zoom, 1e-6)};
    const Box image{map.to_screen({0, h}), map.to_screen({w, 0})};
    draw_scene(dl, map, panel, f, hot, {}, textures, rec, slot);
    dl->AddRect(im(image.min - glm::dvec2(1)), im(image.max + glm::dvec2(1)),
                im_colour(kPlotFrame));
    if (rec.record) rec.record->panels[rec.panel].content = image;
    return map;
}

// --- [diagram] -------------------------------------------------------------------------------

// A drawing in units of its own, fitted at one scale with room for its labels, no axes.
ScreenMap draw_diagram(ImDrawList* dl, const Box& body, const Panel& panel, const Fonts& f,
                       GridTextures* textures, std::size_t slot, Recording rec, int hot) {
    ScreenMap map{body, fit_view(panel, body.max - body.min, 16)};
    const Box drawn = draw_scene(dl, map, panel, f, hot, {}, textures, rec, slot);
    // (An empty diagram draws nothing: its content is a point, which the layout check flags.)
    const glm::dvec2 middle = (body.min + body.max) / 2.0;
    if (rec.record)
        rec.record->panels[rec.panel].content =
            drawn.min.x <= drawn.max.x ? drawn : Box{middle, middle};
    return map;
}

}  // namespace

// --- [draw_panel] ----------------------------------------------------------------------------

double panel_header_height(const Panel& panel, double width, const Fonts& fonts) {
    const Box box{{0, 0}, {width, 1e6}};
    const double title = draw_title(nullptr, box, panel.title, fonts);
    return title + draw_legend(nullptr, {{0, title}, {width, 1e6}}, panel.legend, fonts);
}

ScreenMap draw_panel(ImDrawList* dl, const Box& box, const Panel& panel, const Fonts& fonts,
                     GridTextures* textures, std::size_t texture_slot, Recording rec,
                     int hot_handle) {
    dl->PushClipRect(im(box.min), im(box.max), true);
    dl->AddRect(im(box.min), im(box.max), im_colour(kPanelFrame));
    double top = draw_title(dl, box, panel.title, fonts);
    top += draw_legend(dl, {{box.min.x, box.min.y + top}, box.max}, panel.legend, fonts);
    const Box body{{box.min.x + 4, box.min.y + top}, {box.max.x - 4, box.max.y - 4}};
    const ScreenMap map = panel.kind == PanelKind::Image
                              ? draw_image(dl, body, panel, fonts, textures, texture_slot, rec, hot_handle)
                          : panel.kind == PanelKind::Diagram
                              ? draw_diagram(dl, body, panel, fonts, textures, texture_slot, rec,
                                             hot_handle)
                              : draw_chart(dl, body, panel, fonts, textures, texture_slot, rec, hot_handle);
    dl->PopClipRect();
    return map;
}

}  // namespace cg::viewer
