// Driving the real viewer as a person does: its own window (under Xvfb) and its own event loop
// (Viewer::turn), fed real SDL events — pointer motion, a button down and, a frame or more
// later (or in the same frame), up; keys down and up; typed text — through SDL_PushEvent.
// Afterwards the tests read the pixels of the frame on screen and the session's state.
//
// Controls are found where the viewer last drew them (Session::widgets, by name), so a click
// lands where a person would click, on whatever the layout is at this window size.
#pragma once

#include <catch2/catch.hpp>

#include <SDL.h>

#include <chrono>
#include <optional>
#include <string>
#include <thread>

#include "io/registry.hpp"
#include "viewer/app.hpp"
#include "viewer/session.hpp"

namespace cg::test {

inline const Registry& gui_registry() {
    static const Registry r = builtin_registry();
    return r;
}

// How long a button or key stays down: released in the same frame it was pressed (a fast
// tap: both events arrive before the frame), a frame later, or after 300 ms (a finger).
enum class Hold { SameFrame, OneFrame, Finger };

class Driver {
  public:
    explicit Driver(const std::optional<Checkpoint>& initial = std::nullopt)
        : viewer_(gui_registry(), initial) {
        session().record_widgets = true;
        viewer_.keep_frames(true);
        frames(4);  // the window comes up and the layout settles
    }

    viewer::Session& session() { return viewer_.session(); }
    viewer::Viewer& viewer() { return viewer_; }

    // The window's size, as the viewer lays it out.
    glm::ivec2 size() const {
        int w = 0, h = 0;
        SDL_GetWindowSize(viewer_.window(), &w, &h);
        return {w, h};
    }

    // n turns of the loop, each drawing a frame (an idle loop would sleep instead: the tick
    // event stands for the student's hand resting on the mouse).
    void frames(int n = 1) {
        for (int i = 0; i < n; ++i) {
            SDL_Event tick{};
            tick.type = tick_type();
            SDL_PushEvent(&tick);
            REQUIRE(viewer_.turn(0));
        }
    }

    // Frames for `ms` milliseconds of wall time, at about 60 per second.
    void wait_ms(int ms) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
        while (std::chrono::steady_clock::now() < until) {
            frames(1);
            std::this_thread::sleep_for(std::chrono::milliseconds(16));
        }
    }

    // Where the viewer drew the control `name` in the last frame (fails if it did not).
    viewer::Box widget(const std::string& name) { return spot(name).box; }
    const viewer::Session::Widget& spot(const std::string& name) {
        const auto it = session().widgets.find(name);
        INFO("the control \"" << name << "\" was not drawn in the last frame");
        REQUIRE(it != session().widgets.end());
        return it->second;
    }

    // Scrolls the control's panel with the mouse wheel until the control is in sight, as a
    // person would before clicking it.
    void scroll_to(const std::string& name) {
        for (int i = 0; i < 60 && !spot(name).visible; ++i) {
            const viewer::Session::Widget w = spot(name);
            move(centre(w.window));
            SDL_Event e{};
            e.type = SDL_MOUSEWHEEL;
            e.wheel.windowID = SDL_GetWindowID(viewer_.window());
            // Below, even in part (cut by the window's bottom edge): down.
            e.wheel.y = w.box.max.y > w.window.max.y + 1 ? -1 : 1;
            SDL_PushEvent(&e);
            frames(2);
        }
        const viewer::Session::Widget& w = spot(name);
        INFO("the control \"" << name << "\" cannot be scrolled into sight (at y "
                               << w.box.min.y << " to " << w.box.max.y << ", its window's visible "
                               << "part y " << w.window.min.y << " to " << w.window.max.y << ")");
        REQUIRE(spot(name).visible);
    }
    bool drawn(const std::string& name) { return session().widgets.count(name) > 0; }
    static glm::dvec2 centre(const viewer::Box& b) { return (b.min + b.max) / 2.0; }

    void move(glm::dvec2 to) {
        SDL_Event e{};
        e.type = SDL_MOUSEMOTION;
        e.motion.windowID = SDL_GetWindowID(viewer_.window());
        e.motion.x = static_cast<Sint32>(to.x);
        e.motion.y = static_cast<Sint32>(to.y);
        e.motion.xrel = e.motion.x - static_cast<Sint32>(pointer_.x);
        e.motion.yrel = e.motion.y - static_cast<Sint32>(pointer_.y);
        e.motion.state = down_ ? SDL_BUTTON_LMASK : 0;
        pointer_ = to;
        SDL_PushEvent(&e);
    }

    void button(bool down, Uint8 which = SDL_BUTTON_LEFT) {
        SDL_Event e{};
        e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
        e.button.windowID = SDL_GetWindowID(viewer_.window());
        e.button.button = which;
        e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
        e.button.clicks = 1;
        e.button.x = static_cast<Sint32>(pointer_.x);
        e.button.y = static_cast<Sint32>(pointer_.y);
        down_ = down;
        SDL_PushEvent(&e);
    }

    // Moves to `at`, lets a frame show the hover, presses, holds, releases, and lets the
    // result settle for a few frames.
    void click_at(glm::dvec2 at, Hold hold = Hold::OneFrame) {
        move(at);
        frames(1);
        button(true);
        if (hold == Hold::OneFrame) frames(1);
        if (hold == Hold::Finger) wait_ms(300);
        button(false);
        frames(3);
    }
    void click(const std::string& name, Hold hold = Hold::OneFrame) {
        scroll_to(name);
        click_at(centre(widget(name)), hold);
    }

    // Presses the left button on `from`, moves to `to` in a few steps, releases.
    void drag(glm::dvec2 from, glm::dvec2 to) {
        move(from);
        frames(1);
        button(true);
        frames(1);
        for (int i = 1; i <= 4; ++i) {
            move(from + (to - from) * (i / 4.0));
            frames(1);
        }
        button(false);
        frames(3);
    }

    // A key pressed and released, as a keyboard sends it: with a modifier, the modifier's own
    // key goes down first and comes up last (its release is what clears the modifier).
    void key(SDL_Keycode sym, Uint16 mod = KMOD_NONE, Hold hold = Hold::OneFrame) {
        const SDL_Keycode modifier = mod & KMOD_CTRL    ? SDLK_LCTRL
                                     : mod & KMOD_SHIFT ? SDLK_LSHIFT
                                     : mod & KMOD_ALT   ? SDLK_LALT
                                                        : SDLK_UNKNOWN;
        if (modifier != SDLK_UNKNOWN) push_key(SDL_KEYDOWN, modifier, mod);
        push_key(SDL_KEYDOWN, sym, mod);
        if (hold == Hold::OneFrame) frames(1);
        if (hold == Hold::Finger) wait_ms(300);
        push_key(SDL_KEYUP, sym, mod);
        if (modifier != SDLK_UNKNOWN) push_key(SDL_KEYUP, modifier, KMOD_NONE);
        frames(2);
    }

    // Text as the keyboard types it: one SDL_TEXTINPUT per character (each with its key).
    void type(const std::string& text) {
        for (char c : text) {
            SDL_Event e{};
            e.type = SDL_TEXTINPUT;
            e.text.windowID = SDL_GetWindowID(viewer_.window());
            e.text.text[0] = c;
            SDL_PushEvent(&e);
        }
        frames(2);
    }

    // The frame on screen, RGBA, top row first.
    std::uint32_t pixel(int x, int y) const {
        const auto& f = viewer_.last_frame();
        const glm::ivec2 s = size();
        const std::size_t i = 4 * (static_cast<std::size_t>(y) * s.x + x);
        REQUIRE(i + 3 < f.size());
        return std::uint32_t(f[i]) << 24 | std::uint32_t(f[i + 1]) << 16 |
               std::uint32_t(f[i + 2]) << 8 | f[i + 3];
    }
    // How many pixels of the box differ between two frames.
    static int changed(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                       glm::ivec2 size, const viewer::Box& box) {
        int n = 0;
        for (int y = std::max(0, int(box.min.y)); y < std::min(size.y, int(box.max.y)); ++y)
            for (int x = std::max(0, int(box.min.x)); x < std::min(size.x, int(box.max.x)); ++x) {
                const std::size_t i = 4 * (static_cast<std::size_t>(y) * size.x + x);
                n += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
            }
        return n;
    }

  private:
    void push_key(Uint32 type, SDL_Keycode sym, Uint16 mod) {
        SDL_Event e{};
        e.type = type;
        e.key.windowID = SDL_GetWindowID(viewer_.window());
        e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
        e.key.keysym.sym = sym;
        e.key.keysym.scancode = SDL_GetScancodeFromKey(sym);
        e.key.keysym.mod = mod;
        SDL_PushEvent(&e);
    }

    static Uint32 tick_type() {
        static const Uint32 t = SDL_RegisterEvents(1);
        return t;
    }

    viewer::Viewer viewer_;
    glm::dvec2 pointer_{0, 0};
    bool down_ = false;
};

}  // namespace cg::test
