// The 3D canvas: a scene's 3D primitives (faces, segments and arrows, points, frames, labels)
// seen through an orbiting perspective camera, painted back to front with ImGui draw lists.
// Nothing here knows about any algorithm; canvas.cpp decides where the 3D canvas goes.
#pragma once

#include <imgui.h>

#include <vector>

#include "core/scene.hpp"
#include "viewer/canvas_draw.hpp"
#include "viewer/fonts.hpp"
#include "viewer/view3.hpp"

namespace cg::viewer {

// A view showing the scene's 3D subject (see below) in a canvas of `size` pixels.
View3 fit_view3(const Scene& scene, glm::dvec2 size);

// Mouse handling over `canvas`: left-drag orbits (arcball), right- or middle-drag pans, the
// wheel zooms, a double-click returns to the fitted view (returns true then).
bool interact3(Camera3& camera, const Box& canvas);

// A view fitted to the scene's focus elements (focus3) when it has some, else to the sphere of
// radius extent3 round the origin when it gives one, else to all of its 3D content; seen as
// its view hint asks (view3: along a direction, orthographically) or from the default
// direction.
//
// Everything, back to front: a faint floor grid (y = 0) and world axes, then the scene's
// faces, segments and points sorted by depth, then its labels, placed (labels.hpp) to avoid
// each other and the `keep_clear` boxes.
void draw_scene3(ImDrawList* dl, const Projector& proj, const Scene& scene, const Fonts& fonts,
                 const std::vector<Box>& keep_clear, Recording recording = {});

// The screen box round a focus element's corners (those in front of the camera).
Box screen_bounds(const Projector& proj, const Focus3& focus);

}  // namespace cg::viewer
