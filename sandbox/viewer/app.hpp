// The viewer: an SDL2 + Dear ImGui window on any registered algorithm, and the same picture
// drawn offscreen to a PNG for `cgsandbox render`.
#pragma once

#include <SDL.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checkpoint.hpp"
#include "io/lesson.hpp"
#include "viewer/input.hpp"

namespace cg::viewer {

class GridTextures;
class GuiHost;
struct Session;

// Opens the viewer window and runs until closed; returns the process exit code. When no display is
// available, prints ONE line to stderr saying so and how to work headless (`cgsandbox render ...`,
// or `xvfb-run -a build/bin/cgsandbox`) and returns 1 — never crashes.
int run_viewer(const Registry& registry, const std::optional<Checkpoint>& initial);

// The interactive viewer: its window, its session and its event loop, one turn at a time, so
// that the GUI tests drive exactly the loop a student does — SDL events in (SDL_PushEvent),
// pixels out — and can look at the session in between.
class Viewer {
  public:
    // The window opens at most 1400×900 and never larger than the display's usable area.
    // Throws NoDisplay (viewer/host.hpp) when there is no display.
    Viewer(const Registry& registry, const std::optional<Checkpoint>& initial);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // One turn of the loop: when nothing is going on, sleep until an event comes (at most
    // `idle_ms`); take the events this frame may take (viewer/input.hpp); draw and show one
    // frame. Returns false once the window has been asked to close.
    bool turn(int idle_ms = 1000);

    Session& session() { return *session_; }
    SDL_Window* window() const;
    // The last frame shown, as RGBA rows, top row first (read back before the swap).
    const std::vector<std::uint8_t>& last_frame() const { return last_frame_; }
    void keep_frames(bool keep) { keep_frames_ = keep; }  // read each frame back (tests)
    int frames() const { return frames_; }                // frames drawn so far

  private:
    bool handle(const SDL_Event& e);  // false: the window should close
    void draw_frame(double seconds);

    std::unique_ptr<Session> session_;
    std::unique_ptr<GuiHost> host_;
    std::unique_ptr<GridTextures> textures_;  // before host_ goes: it needs the GL context
    std::unique_ptr<GridTextures> compare_textures_;  // Compare's side B's
    EventFeed feed_;
    int busy_frames_ = 3;  // redraw a few frames after any event, so hover effects settle
    std::uint64_t last_ = 0;
    bool running_ = true;
    bool keep_frames_ = false;
    int frames_ = 0;
    std::vector<std::uint8_t> last_frame_;
};

// Draws a checkpoint as the viewer shows it and writes a PNG of width x height. full_ui=false: the
// 2D canvas alone fills the image (grid, axes, the scene, a small caption with the algorithm title
// and step "k / n"); full_ui=true: the whole viewer window, with the checkpoint's lesson (from
// default_lessons_dir()) or exam problem open in the left panel. Throws std::runtime_error with
// a clear one-line message on failure (no display, an unknown lesson; bad input: let
// cg::InputError propagate unchanged). With `layout_path`, also writes there what the canvas
// placed where (layout.hpp); with an empty `out_path`, only that, drawn without a GPU or a
// window (layout_pass.hpp).
void render_png(const Registry& registry, const Checkpoint& checkpoint, int width, int height,
                const std::string& out_path, bool full_ui, const std::string& layout_path = {});

// A lesson's contact sheet: every preset a row, its first, middle and last step the columns,
// each the canvas as a window of width x height shows it with the lesson open.
void contact_sheet(const Registry& registry, const LessonLibrary& lessons, const Lesson& lesson,
                   int width, int height, const std::string& out_path);

}  // namespace cg::viewer
