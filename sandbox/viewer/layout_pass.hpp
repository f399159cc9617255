// The viewer's drawing pass without a GPU or a window, kept only for its layout record.
//
// An ImGui context of its own with the viewer's fonts (their atlas built on the CPU), drawing
// the same UI the window and `render` draw; the draw lists are built and thrown away. What the
// canvas placed where (layout.hpp) comes from that same pass, so `cgsandbox render --layout`
// and the layout tests see exactly what a student would, at any window size, cheaply.
#pragma once

#include <string>

#include "checkpoint.hpp"
#include "io/lesson.hpp"
#include "viewer/fonts.hpp"
#include "viewer/layout.hpp"

struct ImGuiContext;

namespace cg::viewer {

struct Session;

// Opens a session on a checkpoint as the viewer does: the run at its step, then its lesson,
// exam and view. Throws InputError for refused input and std::runtime_error when the
// checkpoint's lesson cannot be opened.
void open_checkpoint(Session& s, const Checkpoint& checkpoint, const LessonLibrary& lessons);

class LayoutPass {
  public:
    LayoutPass();  // makes its context current while it works, and restores the one before
    ~LayoutPass();
    LayoutPass(const LayoutPass&) = delete;
    LayoutPass& operator=(const LayoutPass&) = delete;

    const Fonts& fonts() const { return fonts_; }

    // Draws the session's window (full_ui) or canvas alone at width x height and returns what
    // its canvas placed where. The session's fonts are set to this pass's.
    LayoutRecord record(Session& s, int width, int height, bool full_ui);

  private:
    ImGuiContext* context_ = nullptr;
    Fonts fonts_;
};

}  // namespace cg::viewer
