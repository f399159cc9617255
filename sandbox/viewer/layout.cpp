#include "viewer/layout.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "viewer/canvas_draw.hpp"

namespace cg::viewer {

const char* view_kind_name(ViewKind kind) {
    switch (kind) {
        case ViewKind::World2d:
            return "world2d";
        case ViewKind::View3d:
            return "view3d";
        case ViewKind::Chart:
            return "chart";
        case ViewKind::Image:
            return "image";
        case ViewKind::Diagram:
            return "diagram";
    }
    return "?";
}

ViewKind view_kind(const Panel& panel) {
    switch (panel.kind) {
        case PanelKind::Image:
            return ViewKind::Image;
        case PanelKind::Diagram:
            return ViewKind::Diagram;
        case PanelKind::Chart:
            break;
    }
    return ViewKind::Chart;
}

namespace {

// `area` cut into parts along x (or y) in proportion to `weights`, `gap` apart; whole pixels.
std::vector<Box> split(const Box& area, const std::vector<double>& weights, bool along_x,
                       double gap) {
    std::vector<Box> out;
    const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
    const double length = (along_x ? area.max.x - area.min.x : area.max.y - area.min.y) -
                          gap * static_cast<double>(weights.size() - 1);
    double at = along_x ? area.min.x : area.min.y, sum = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        sum += weights[i];
        const double end = i + 1 == weights.size()
                               ? (along_x ? area.max.x : area.max.y)
                               : std::round((along_x ? area.min.x : area.min.y) +
                                            length * sum / total + gap * static_cast<double>(i));
        Box b = area;
        if (along_x)
            b.min.x = at, b.max.x = end;
        else
            b.min.y = at, b.max.y = end;
        out.push_back(b);
        at = end + gap;
    }
    return out;
}

double width(const Box& b) {
    return b.max.x - b.min.x;
}
double height(const Box& b) {
    return b.max.y - b.min.y;
}

// Room an image panel keeps for its title (when its header's height is not measured) and its
// margins, pixels (as draw_panel and draw_image leave them).
constexpr double kImageTitle = 30, kImageMarginX = 16, kImageMarginY = 12;

// What a panel of fixed shape holds: its width and height in its own units, whether it is
// drawn at whole screen pixels a unit, and the room its drawing keeps round it (pixels).
struct Shape {
    double w = 0, h = 0;
    bool whole_pixels = false;
    double margin_x = 0, margin_y = 0;
};

// An image's raster (cells, drawn pixel-exact: draw_image), a diagram's drawing (its bounds,
// fitted with 16 px round it: draw_diagram); none for a chart, or an empty diagram.
std::optional<Shape> shape_of(const Panel& p) {
    if (p.kind == PanelKind::Image && !p.grids.empty() && p.grids.front().width > 0 &&
        p.grids.front().height > 0)
        return Shape{double(p.grids.front().width), double(p.grids.front().height), true,
                     kImageMarginX, kImageMarginY};
    if (p.kind == PanelKind::Diagram) {
        const Box b = bounds_of(p);
        if (!(b.max.x - b.min.x > 0) || !(b.max.y - b.min.y > 0)) return std::nullopt;
        return Shape{b.max.x - b.min.x, b.max.y - b.min.y, false, 8 + 32, 4 + 32};
    }
    return std::nullopt;
}

// The width over the height of what a fixed-shape panel holds.
double aspect_of(const Shape& s) {
    return s.w / s.h;
}

// A fixed-shape panel's box shrunk to its contents' shape (title above, margins round),
// centred across and at the top: the panel is the picture, not the picture and a strip of
// nothing.
Box tight_box(const Box& box, const Shape& s, double header) {
    const double room_w = std::max(width(box) - s.margin_x, 1.0);
    const double room_h = std::max(height(box) - header - s.margin_y, 1.0);
    const double zoom = s.whole_pixels ? image_zoom(room_w / s.w, room_h / s.h)
                                       : std::min(room_w / s.w, room_h / s.h);
    const double bw = std::ceil(s.w * zoom + s.margin_x);
    const double bh = std::ceil(s.h * zoom + header + s.margin_y);
    const double x0 = std::round(box.min.x + (width(box) - bw) / 2);
    return {{x0, box.min.y}, {x0 + bw, box.min.y + bh}};
}

}  // namespace

bool shows_world(const Scene& scene) {
    return scene.has_2d() || !scene.handles.empty() || (!scene.has_3d() && scene.panels.empty());
}

std::vector<ViewSlot> layout_views(const Scene& scene, const Box& area, double gap,
                                   const HeaderHeight& header_of) {
    auto header = [&](const Panel& p, double w) {
        return header_of ? header_of(p, w) : kImageTitle;
    };
    auto tighten = [&](std::vector<ViewSlot>& views) {
        for (ViewSlot& v : views) {
            if (v.panel < 0) continue;
            const Panel& p = scene.panels[v.panel];
            if (const std::optional<Shape> shape = shape_of(p)) {
                // Narrower, the title and legend may take more rows: measured again there.
                const Box room = v.box;
                v.box = tight_box(room, *shape, header(p, width(room)));
                const double h = header(p, width(v.box));
                if (h != header(p, width(room))) v.box = tight_box(room, *shape, h);
            }
        }
    };
    std::vector<ViewSlot> mains, panels;
    const bool three = scene.has_3d();
    const bool world = shows_world(scene);
    if (three) mains.push_back({ViewKind::View3d, -1, area});
    if (world) mains.push_back({ViewKind::World2d, -1, area});
    for (std::size_t i = 0; i < scene.panels.size(); ++i)
        panels.push_back({view_kind(scene.panels[i]), static_cast<int>(i), area});

    const bool wide = width(area) >= height(area) * 1.15;
    auto place = [&](std::vector<ViewSlot>& views, const Box& box, bool along_x,
                     const std::vector<double>& weights) {
        const std::vector<Box> boxes = split(box, weights, along_x, gap);
        for (std::size_t i = 0; i < views.size(); ++i) views[i].box = boxes[i];
    };
    auto weights_of = [&](const std::vector<ViewSlot>& views) {
        std::vector<double> w;
        for (const ViewSlot& v : views)
            w.push_back(v.panel >= 0 ? std::max(scene.panels[v.panel].weight, 0.1) : 1.5);
        return w;
    };
    std::vector<ViewSlot> out;
    if (panels.empty() || mains.empty()) {
        std::vector<ViewSlot>& views = panels.empty() ? mains : panels;
        if (views.size() <= 2 || panels.empty()) {
            place(views, area, wide, weights_of(views));
        } else {
            // Many panels alone: a grid, as square as the canvas allows.
            const std::size_t n = views.size();
            std::size_t cols = std::max<std::size_t>(
                1, static_cast<std::size_t>(
                       std::round(std::sqrt(n * width(area) / height(area) / 1.3))));
            cols = std::min(cols, n);
            const std::size_t rows = (n + cols - 1) / cols;
            const std::vector<Box> row_boxes =
                split(area, std::vector<double>(rows, 1.0), false, gap);
            for (std::size_t r = 0; r < rows; ++r) {
                const std::size_t first = r * cols, count = std::min(cols, n - first);
                const std::vector<Box> cells =
                    split(row_boxes[r], std::vector<double>(count, 1.0), true, gap);
                for (std::size_t c = 0; c < count; ++c) views[first + c].box = cells[c];
            }
        }
        tighten(views);
        return views;
    }
    // The main views on one side, the panels on the other: a main view weighs 1.5, a panel its
    // weight; the panels' side never takes more than half the canvas.
    const std::vector<double> mw = weights_of(mains), pw = weights_of(panels);
    const double m = std::accumulate(mw.begin(), mw.end(), 0.0);
    const double p = std::min(std::accumulate(pw.begin(), pw.end(), 0.0), m);
    const std::vector<Box> sides = split(area, {m, p}, wide, gap);
    place(mains, sides[0], width(sides[0]) >= height(sides[0]) * 1.15, mw);
    // The panels' side: each image asks for the length that shows its raster across the side's
    // whole breadth; when they all fit, the charts share what is left by weight, else every
    // panel is sized by weight alone.
    const bool along_x = !wide;
    const Box& side = sides[1];
    const double breadth = along_x ? height(side) : width(side);
    const double length = (along_x ? width(side) : height(side)) - gap * double(panels.size() - 1);
    std::vector<double> need(panels.size(), 0);
    double images = 0, chart_weight = 0;
    std::size_t charts = 0;
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const Panel& p = scene.panels[panels[i].panel];
        const std::optional<Shape> shape = shape_of(p);
        if (!shape) {
            chart_weight += pw[i], ++charts;
            continue;
        }
        const double a = aspect_of(*shape);
        need[i] = along_x ? (breadth - header(p, breadth) - shape->margin_y) * a + shape->margin_x
                          : (breadth - shape->margin_x) / a + header(p, breadth) + shape->margin_y;
        images += need[i];
    }
    constexpr double kLeastChart = 200;  // a chart smaller than this is mostly its axes
    if (images > 0 && charts > 0 && images + kLeastChart * double(charts) <= length) {
        std::vector<double> lengths(panels.size());
        for (std::size_t i = 0; i < panels.size(); ++i)
            lengths[i] = need[i] > 0 ? need[i] : (length - images) * pw[i] / chart_weight;
        place(panels, side, along_x, lengths);
    } else {
        place(panels, side, along_x, pw);
    }
    out = mains;
    out.insert(out.end(), panels.begin(), panels.end());
    tighten(out);
    return out;
}

namespace {

json box_json(const Box& b) {
    auto r = [](double v) { return std::round(v * 10) / 10; };
    return json::array({r(b.min.x), r(b.min.y), r(b.max.x), r(b.max.y)});
}

bool inside(const Box& inner, const Box& outer, double slack = 0.5) {
    return inner.min.x >= outer.min.x - slack && inner.min.y >= outer.min.y - slack &&
           inner.max.x <= outer.max.x + slack && inner.max.y <= outer.max.y + slack;
}

double area_of(const Box& b) {
    return std::max(width(b), 0.0) * std::max(height(b), 0.0);
}

}  // namespace

json layout_json(const LayoutRecord& r) {
    json panels = json::array(), labels = json::array(), focus = json::array(),
         dropped = json::array();
    for (const LayoutRecord::Panel& p : r.panels)
        panels.push_back({{"kind", view_kind_name(p.kind)},
                          {"box", box_json(p.box)},
                          {"content", box_json(p.content)}});
    for (const LayoutRecord::Label& l : r.labels)
        labels.push_back({{"text", l.text}, {"box", box_json(l.box)}, {"panel", l.panel}});
    for (const LayoutRecord::Focus& f : r.focus)
        focus.push_back({{"box", box_json(f.box)}, {"panel", f.panel}});
    for (const LayoutRecord::Label& l : r.dropped)
        dropped.push_back({{"text", l.text}, {"box", box_json(l.box)}, {"panel", l.panel}});
    return {{"canvas", box_json(r.canvas)},
            {"title", {{"box", box_json(r.title)}, {"fits", r.title_fits}}},
            {"panels", panels},
            {"labels", labels},
            {"focus", focus},
            {"dropped", dropped}};
}

std::vector<std::string> layout_problems(const LayoutRecord& r) {
    std::vector<std::string> out;
    auto text = [](const Box& b) {
        return "[" + std::to_string(int(b.min.x)) + ", " + std::to_string(int(b.min.y)) + ", " +
               std::to_string(int(b.max.x)) + ", " + std::to_string(int(b.max.y)) + "]";
    };
    if (!r.title_fits) out.push_back("the title is truncated");
    for (std::size_t i = 0; i < r.labels.size(); ++i) {
        const LayoutRecord::Label& a = r.labels[i];
        for (std::size_t j = i + 1; j < r.labels.size(); ++j)
            if (a.box.grown(-0.5).overlaps(r.labels[j].box.grown(-0.5)))
                out.push_back("labels \"" + a.text + "\" " + text(a.box) + " and \"" +
                              r.labels[j].text + "\" " + text(r.labels[j].box) + " overlap");
        if (a.panel < 0 || a.panel >= static_cast<int>(r.panels.size()) ||
            !inside(a.box, r.panels[a.panel].box))
            out.push_back("label \"" + a.text + "\" " + text(a.box) + " is outside its panel");
        if (a.box.grown(-0.5).overlaps(r.title))
            out.push_back("label \"" + a.text + "\" " + text(a.box) + " is under the title");
    }
    // Active (role rank 6) or given a priority of its own: what the step is about.
    for (const LayoutRecord::Label& l : r.dropped)
        if (l.priority >= 60)
            out.push_back("label \"" + l.text + "\" of the step's subject found no room");
    for (const LayoutRecord::Focus& f : r.focus)
        if (std::max(width(f.box), height(f.box)) < 24)
            out.push_back("a focus element " + text(f.box) + " is under 24 px");
    for (const LayoutRecord::Panel& p : r.panels)
        if ((p.kind == ViewKind::Chart || p.kind == ViewKind::Image ||
             p.kind == ViewKind::Diagram) &&
            area_of(p.content) < 0.5 * area_of(p.box))
            out.push_back(std::string("a ") + view_kind_name(p.kind) + " " + text(p.content) +
                          " uses less than half of its panel " + text(p.box));
    return out;
}

}  // namespace cg::viewer
