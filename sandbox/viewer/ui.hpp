// One frame of the viewer's user interface, laid out from the display size (no docking, no
// saved layout): the same function serves the window, a full-UI PNG, and a canvas-only PNG.
#pragma once

#include <imgui.h>

#include "viewer/session.hpp"

namespace cg::viewer {

// full_ui=false: the canvas alone fills the display. interactive=false: no hover, drag or
// hints (offscreen rendering has no mouse).
void draw_ui(Session& s, ImVec2 display, bool full_ui, bool interactive);

// Before the frame's draw lists are rendered: the panels' background colour everywhere and the
// canvas's where draw_ui put the canvas. The panels and the canvas draw no background of their
// own: on a software rasteriser (Mesa's llvmpipe, a student without a GPU) a clear costs next
// to nothing and a filled window costs about 12 ns a pixel — a third of a 1280×800 frame.
struct Gl;
void clear_frame(const Gl& gl, int fb_width, int fb_height, const Session& s);

}  // namespace cg::viewer
