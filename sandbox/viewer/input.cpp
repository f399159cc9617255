#include "viewer/input.hpp"

#include <algorithm>

namespace cg::viewer {

namespace {

// SDL numbers the buttons left 1, middle 2, right 3; ImGui left 0, right 1, middle 2.
int imgui_button(Uint8 sdl_button) {
    switch (sdl_button) {
        case SDL_BUTTON_LEFT: return 0;
        case SDL_BUTTON_RIGHT: return 1;
        case SDL_BUTTON_MIDDLE: return 2;
        default: return -1;
    }
}

bool is_button(const SDL_Event& e) {
    return e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP;
}

bool is_key(const SDL_Event& e) { return e.type == SDL_KEYDOWN || e.type == SDL_KEYUP; }

}  // namespace

bool EventFeed::must_wait(const SDL_Event& e) const {
    if (is_button(e)) {
        const int b = imgui_button(e.button.button);
        if (b >= 0 && button_changed_[b]) return true;  // its press (or release) is this frame's
        // A press where the pointer has only just arrived waits a frame: ImGui decides what is
        // hovered from where the pointer was, and an item that lets others overlap it (a tab)
        // takes a click only once it was the hovered one (HoveredIdPreviousFrame). A move and
        // its click sent together lost the click on a tab that way.
        return e.type == SDL_MOUSEBUTTONDOWN && moved_;
    }
    if (e.type == SDL_MOUSEMOTION) return any_button_changed_;  // a click happens where it was
    if (is_key(e) && !(e.type == SDL_KEYDOWN && e.key.repeat))
        return std::find(keys_changed_.begin(), keys_changed_.end(), e.key.keysym.scancode) !=
               keys_changed_.end();
    return false;
}

void EventFeed::note(const SDL_Event& e) {
    switch (e.type) {
        case SDL_MOUSEMOTION: {
            const ImVec2 to(static_cast<float>(e.motion.x), static_cast<float>(e.motion.y));
            moved_ = moved_ || to.x != pos_.x || to.y != pos_.y;
            pos_ = to;
            break;
        }
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP: {
            pos_ = ImVec2(static_cast<float>(e.button.x), static_cast<float>(e.button.y));
            const int b = imgui_button(e.button.button);
            if (b < 0) break;
            buttons_[b] = e.type == SDL_MOUSEBUTTONDOWN;
            button_changed_[b] = any_button_changed_ = true;
            break;
        }
        case SDL_KEYDOWN:
        case SDL_KEYUP:
            if (!e.key.repeat) keys_changed_.push_back(e.key.keysym.scancode);
            break;
        case SDL_WINDOWEVENT:
            // The pointer left the window: nothing is hovered any more, unless a drag holds it.
            if (e.window.event == SDL_WINDOWEVENT_LEAVE &&
                std::none_of(std::begin(buttons_), std::end(buttons_), [](bool b) { return b; }))
                pos_ = ImVec2(-FLT_MAX, -FLT_MAX);
            break;
        default:
            break;
    }
}

void EventFeed::take_frame(const std::function<void(const SDL_Event&)>& handle) {
    std::fill(std::begin(button_changed_), std::end(button_changed_), false);
    any_button_changed_ = false;
    moved_ = false;
    keys_changed_.clear();
    while (!queue_.empty()) {
        const SDL_Event e = queue_.front();
        if (e.type == SDL_MOUSEBUTTONDOWN &&
            (static_cast<float>(e.button.x) != pos_.x || static_cast<float>(e.button.y) != pos_.y)) {
            // A press somewhere the pointer is not (no motion event took it there): the
            // pointer goes there in this frame, the press comes in the next (see must_wait).
            pos_ = ImVec2(static_cast<float>(e.button.x), static_cast<float>(e.button.y));
            moved_ = true;
            break;
        }
        if (must_wait(e)) break;
        queue_.pop_front();
        note(e);
        handle(e);
    }
}

void EventFeed::apply(ImGuiIO& io) const {
    io.MousePos = pos_;
    for (int b = 0; b < 3; ++b) io.MouseDown[b] = buttons_[b];
}

}  // namespace cg::viewer
