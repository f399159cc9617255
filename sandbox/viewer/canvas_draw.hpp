// Drawing a cg::Scene into an ImGui draw list: the world-to-screen mapping, the grid with its
// axes, and the scene's primitives. Nothing here knows about any algorithm or handles input;
// canvas.cpp does the interaction and calls these.
#pragma once

#include <imgui.h>

#include <glm/vec2.hpp>
#include <vector>

#include "checkpoint.hpp"
#include "core/scene.hpp"
#include "viewer/fonts.hpp"
#include "viewer/geometry.hpp"

namespace cg::viewer {

// World coordinates are y up; the screen's are y down. The view's centre is at the canvas's
// centre, and `zoom` is pixels per world unit along x; along y it is zoom × y_scale (1 in the
// world and in an image; a chart's axes are scaled apart).
struct ScreenMap {
    Box canvas;  // in screen pixels
    View2 view;
    double y_scale = 1;

    glm::dvec2 centre() const { return (canvas.min + canvas.max) * 0.5; }
    glm::dvec2 to_screen(glm::dvec2 w) const {
        const glm::dvec2 c = centre();
        return {c.x + (w.x - view.center.x) * view.zoom,
                c.y - (w.y - view.center.y) * view.zoom * y_scale};
    }
    glm::dvec2 to_world(glm::dvec2 s) const {
        const glm::dvec2 c = centre();
        return {view.center.x + (s.x - c.x) / view.zoom,
                view.center.y - (s.y - c.y) / (view.zoom * y_scale)};
    }
};

inline ImVec2 im(glm::dvec2 p) {
    return ImVec2(static_cast<float>(p.x), static_cast<float>(p.y));
}
inline glm::dvec2 dv(ImVec2 p) {
    return {p.x, p.y};
}

// The smallest of 1, 2, 5 × 10^k that is at least `at_least` (> 0): grid spacings and
// drag snapping read as round numbers.
double nice_step(double at_least);

// The bounds of the layer's bounded geometry (half-planes are infinite and don't count);
// lo > hi when there is none.
Box bounds_of(const Layer2& layer);

// A view showing all of the layer's bounded geometry in a canvas of `size` pixels, with room
// (`margin` pixels a side) for labels; fit_box, the box `bounds` (the world's focus elements).
View2 fit_view(const Layer2& layer, glm::dvec2 size, double margin = 40);
View2 fit_box(const Box& bounds, glm::dvec2 size, double margin = 40);

// Grid lines every round step (at least ~70 px apart, with lighter subdivisions), the axes,
// and tick labels kept inside the canvas when an axis is out of view.
void draw_grid(ImDrawList* dl, const ScreenMap& map, const Fonts& fonts);

// What a drawing pass reports about itself, when asked: the layout record (layout.hpp) and the
// index its current view has there.
struct LayoutRecord;
struct Recording {
    LayoutRecord* record = nullptr;
    int panel = 0;
};

// The layer, bottom to top: pixel grids, half-planes, polygons, segments, points, handles,
// then all labels, placed to avoid each other, the geometry and the `keep_clear` boxes (the
// sliders, a legend). `hot_handle` is the handle hovered or dragged, or -1. `textures`, if
// given, draws big pixel grids as textures (viewer/grid_texture.hpp). Returns the screen bounds
// of what was drawn (clipped to the canvas).
class GridTextures;
Box draw_scene(ImDrawList* dl, const ScreenMap& map, const Layer2& layer, const Fonts& fonts,
               int hot_handle, const std::vector<Box>& keep_clear, GridTextures* textures = nullptr,
               Recording recording = {}, std::size_t first_texture_slot = 0);

// A chart or an image panel of the scene in `box`: its title above, then a chart's axes and
// ticks in its own units, its series and legend; or an image filling the rest, pixel-exact.
// Returns the map from the panel's coordinates to the screen (for its focus elements and
// handles); `hot_handle` is the panel's handle hovered or dragged, or -1.
// panel_header_height: how tall its title and legend are in a panel `width` pixels wide.
double panel_header_height(const Panel& panel, double width, const Fonts& fonts);
ScreenMap draw_panel(ImDrawList* dl, const Box& box, const Panel& panel, const Fonts& fonts,
                     GridTextures* textures, std::size_t texture_slot, Recording recording,
                     int hot_handle = -1);

}  // namespace cg::viewer
