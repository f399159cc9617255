// The viewer: an SDL2 + Dear ImGui window on any registered algorithm, and the same picture
// drawn offscreen to a PNG for `cgsandbox render`.
#pragma once

#include <optional>
#include <string>

#include "checkpoint.hpp"

namespace cg::viewer {

// Opens the viewer window and runs until closed; returns the process exit code. When no display is
// available, prints ONE line to stderr saying so and how to work headless (`cgsandbox render ...`,
// or `xvfb-run -a build/bin/cgsandbox`) and returns 1 — never crashes.
int run_viewer(const Registry& registry, const std::optional<Checkpoint>& initial);

// Draws a checkpoint as the viewer shows it and writes a PNG of width x height. full_ui=false: the
// 2D canvas alone fills the image (grid, axes, the scene, a small caption with the algorithm title
// and step "k / n"); full_ui=true: the whole viewer window, with the checkpoint's lesson (from
// default_lessons_dir()) or exam problem open in the left panel. Throws std::runtime_error with
// a clear one-line message on failure (no display, an unknown lesson; bad input: let
// cg::InputError propagate unchanged).
void render_png(const Registry& registry, const Checkpoint& checkpoint, int width, int height,
                const std::string& out_path, bool full_ui);

}  // namespace cg::viewer
