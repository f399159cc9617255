// The viewer's panels around the canvas. Each draws into the current ImGui window; ui.cpp
// decides where the windows go.
#pragma once

#include "viewer/session.hpp"

namespace cg::viewer {

// Left, one tab each: the algorithm picker and the input editor (panel_algorithm.cpp); the
// lesson browser and the open lesson (panel_lesson.cpp); exam practice (panel_exam.cpp).
void draw_algorithm_panel(Session& s);
void draw_lessons_panel(Session& s);
void draw_exam_panel(Session& s);
// Under the Algorithm tab for the hidden-surface algorithms: their costs plotted against the
// course's growth laws (panel_costs.cpp).
void draw_costs_panel(Session& s);

// Right: pseudocode with the active line and breakpoints, the variables, the event legend
// (panel_code.cpp).
void draw_pseudocode_panel(Session& s);
// The height the pseudocode panel needs when `panel_width` wide, its long lines wrapped.
float pseudocode_height(Session& s, float panel_width);
void draw_variables_panel(Session& s);
void draw_events_panel(Session& s);

// Bottom: stepping controls, the narration with its formula and the lesson's note, the log,
// screenshot, checkpoints and the worked-example export (panel_controls.cpp).
void draw_controls_panel(Session& s);
void draw_files_row(Session& s);  // its last row (panel_files.cpp)

// The study modes (panel_modes.cpp): the mode switch and Compare at the top of the Step panel;
// the mode's own controls in place of the narration (false: Watch, nothing drawn); the two
// canvases side by side while comparing; the editor of side B's input.
void draw_modes_row(Session& s);
bool draw_mode_now(Session& s);
void draw_compare_canvases(Session& s, bool interactive);
void draw_compare_editor(Session& s);

}  // namespace cg::viewer
