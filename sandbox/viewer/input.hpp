// SDL's events into Dear ImGui, one frame's worth at a time.
//
// ImGui 1.86 reads its input as state, once per frame: the SDL backend polls the pointer's
// position and buttons when the frame starts (SDL_GetGlobalMouseState, SDL_GetMouseState), and
// a key is down or up when ImGui looks. Two things get lost that way:
//   - a press and its release inside one frame (a quick click, a tap of Tab): ImGui never sees
//     the button or key down;
//   - events that did not come from the operating system: SDL_PushEvent moves no pointer and
//     presses no button in SDL's own state, and that is how the GUI tests drive the viewer.
// So the viewer feeds ImGui from the events themselves. The pointer is where the last mouse
// event put it, its buttons as the last button events left them. And a frame takes the queued
// events in order only up to the first one that would undo or blur what the same frame already
// did — the release of a button or key pressed in it, a second press after a release, a move
// after a click, a press after a move — and leaves the rest for the next frame, so that every
// press is seen for at least one frame, at the place it happened, over what was hovered there. (ImGui 1.87 later built the same in, calling it
// input trickling.)
#pragma once

#include <SDL.h>
#include <imgui.h>

#include <cfloat>
#include <deque>
#include <functional>
#include <vector>

namespace cg::viewer {

class EventFeed {
  public:
    void push(const SDL_Event& e) { queue_.push_back(e); }
    bool pending() const { return !queue_.empty(); }

    // Hands this frame's events to `handle`, in order, keeping what they say about the pointer.
    void take_frame(const std::function<void(const SDL_Event&)>& handle);

    // After the SDL backend's NewFrame, before ImGui::NewFrame: the pointer and its buttons as
    // the events left them, over what the backend polled.
    void apply(ImGuiIO& io) const;

    ImVec2 pointer() const { return pos_; }

  private:
    // Whether `e` must wait for the next frame, given what this frame took already.
    bool must_wait(const SDL_Event& e) const;
    void note(const SDL_Event& e);  // what `e` changes of the pointer and of this frame

    std::deque<SDL_Event> queue_;
    ImVec2 pos_{-FLT_MAX, -FLT_MAX};
    bool buttons_[3] = {false, false, false};  // ImGui's order: left, right, middle

    // This frame so far.
    bool button_changed_[3] = {false, false, false};
    bool any_button_changed_ = false;
    bool moved_ = false;  // the pointer moved in this frame
    std::vector<SDL_Scancode> keys_changed_;
};

}  // namespace cg::viewer
