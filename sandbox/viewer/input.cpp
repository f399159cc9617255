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
        return b >= 0 && button_changed_[b];  // its press (or release) is this frame's
    }
    if (e.type == SDL_MOUSEMOTION) return any_button_changed_;  // a click happens where it was
    if (is_key(e) && !(e.type == SDL_KEYDOWN && e.key.repeat))
        return std::find(keys_changed_.begin(), keys_changed_.end(), e.key.keysym.scancode) !=
               keys_changed_.end();
    return false;
}

void EventFeed::note(const SDL_Event& e) {
    switch (e.type) {
        case SDL_MOUSEMOTION:
            pos_ = ImVec2(static_cast<float>(e.motion.x), static_cast<float>(e.motion.y));
            break;
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
    keys_changed_.clear();
    while (!queue_.empty() && !must_wait(queue_.front())) {
        const SDL_Event e = queue_.front();
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
