// The 2D canvas: the current step's scene on a grid, with a caption; in the interactive
// viewer also panning, zooming and dragging handles (which edits the input and restarts).
#pragma once

#include "viewer/session.hpp"

namespace cg::viewer {

// Fills the rest of the current ImGui window.
void draw_canvas(Session& session, bool interactive);

}  // namespace cg::viewer
