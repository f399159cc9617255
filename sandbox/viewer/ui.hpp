// One frame of the viewer's user interface, laid out from the display size (no docking, no
// saved layout): the same function serves the window, a full-UI PNG, and a canvas-only PNG.
#pragma once

#include <imgui.h>

#include "viewer/session.hpp"

namespace cg::viewer {

// full_ui=false: the canvas alone fills the display. interactive=false: no hover, drag or
// hints (offscreen rendering has no mouse).
void draw_ui(Session& s, ImVec2 display, bool full_ui, bool interactive);

}  // namespace cg::viewer
