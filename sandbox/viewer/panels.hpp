// The viewer's panels around the canvas. Each draws into the current ImGui window; ui.cpp
// decides where the windows go.
#pragma once

#include "viewer/session.hpp"

namespace cg::viewer {

// Left: the algorithm picker and the input editor (panel_algorithm.cpp).
void draw_algorithm_panel(Session& s);

// Right: pseudocode with the active line and breakpoints, the variables, the event legend
// (panel_code.cpp).
void draw_pseudocode_panel(Session& s);
void draw_variables_panel(Session& s);
void draw_events_panel(Session& s);

// Bottom: stepping controls, the narration and its log, screenshot and checkpoints
// (panel_controls.cpp).
void draw_controls_panel(Session& s);

}  // namespace cg::viewer
