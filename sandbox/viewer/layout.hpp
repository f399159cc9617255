// The canvas's layout, and the record of what was placed where.
//
// The canvas is a title strip (the algorithm, the step, the event; wrapped, never cut) over
// the views: the 2D world and the 3D view (the main views, when the scene has them) and the
// scene's panels (charts and images). On a wide canvas the main views take the left part and
// the panels are stacked in a column on the right; on a tall one the main views are on top and
// the panels in a row below. Each view is then fitted to its own content by its own drawing.
//
// The same pass that draws records, when asked, what it placed (LayoutRecord): `cgsandbox
// render --layout FILE.json` writes it, and the layout tests check it over every lesson
// preset — labels that overlap, leave their panel or run under the title; a focus element too
// small to see; a chart or an image using less than half of its panel.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "io/json.hpp"
#include "viewer/geometry.hpp"

namespace cg::viewer {

enum class ViewKind { World2d, View3d, Chart, Image, Diagram };
// "world2d", "view3d", "chart", "image", "diagram"
const char* view_kind_name(ViewKind kind);

// The view kind of a panel.
ViewKind view_kind(const Panel& panel);

struct ViewSlot {
    ViewKind kind = ViewKind::World2d;
    int panel = -1;  // Chart, Image and Diagram: the index into Scene::panels
    Box box;
};

// Whether the scene shows the 2D world: when it has 2D content or handles, or when nothing else
// would be shown.
bool shows_world(const Scene& scene);

// How tall a panel's title and legend are when it is `width` pixels wide (the drawing's own
// measure: an image panel is sized to its raster under them).
using HeaderHeight = std::function<double(const Panel&, double width)>;

// Screen pixels per cell for an image that may take `fit_x` × `fit_y` pixels per cell: the
// smaller, in whole pixels (crisp, even cells) when that shrinks it by at most 15%.
inline double image_zoom(double fit_x, double fit_y) {
    const double zoom = std::min(fit_x, fit_y);
    return zoom >= 2 && std::floor(zoom) >= 0.85 * zoom ? std::floor(zoom) : zoom;
}

// The views of `scene` in `area` (the canvas below the title strip), `gap` pixels apart.
std::vector<ViewSlot> layout_views(const Scene& scene, const Box& area, double gap = 6,
                                   const HeaderHeight& header = {});

// What one drawing pass placed, in window pixels (y down). Panels are listed in the order of
// the views; a label's or a focus element's `panel` indexes them.
struct LayoutRecord {
    struct Panel {
        ViewKind kind;
        Box box;      // the view's whole box
        Box content;  // the bounds of what it draws
    };
    struct Label {
        std::string text;
        Box box;
        int panel = 0;
        int priority = 0;  // labels.hpp's label_priority
    };
    struct Focus {
        Box box;
        int panel = 0;
    };
    Box canvas{};
    Box title{};
    bool title_fits = true;
    std::vector<Panel> panels;
    std::vector<Label> labels;
    std::vector<Label> dropped;  // labels that found no free place (box: round the anchor)
    std::vector<Focus> focus;
};

// {"canvas": box, "title": {"box": box, "fits": bool}, "panels": [{"kind", "box", "content"}],
//  "labels": [{"text", "box", "panel"}], "focus": [{"box", "panel"}], "dropped": [{"text",
//  "box", "panel"}]}, boxes [x0, y0, x1, y1].
json layout_json(const LayoutRecord& record);

// The problems the layout tests fail on, one line each (empty: none): two labels overlapping,
// a label outside its panel or under the title, a truncated title, a focus element under 24 px,
// a chart or an image using less than half of its panel, a label of the step's subject (an
// Active one, or one with a priority of its own) dropped for want of room.
std::vector<std::string> layout_problems(const LayoutRecord& record);

}  // namespace cg::viewer
