// An SDL window with an OpenGL 3.3 core context and a Dear ImGui context on it: what both the
// interactive viewer and the offscreen `render` stand on.
//
// Constructing one is the single place that can find there is no display. It then throws
// NoDisplay and tears down whatever it had set up, so callers never meet half-initialised
// SDL; the destructor shuts ImGui and SDL down in the reverse order.
#pragma once

#include <SDL.h>

#include <stdexcept>
#include <string>

#include "viewer/fonts.hpp"
#include "viewer/gl.hpp"

namespace cg::viewer {

class NoDisplay : public std::runtime_error {
  public:
    explicit NoDisplay(const std::string& sdl_error)
        : std::runtime_error("no display available (" + sdl_error + "): run under `xvfb-run -a`"),
          sdl_error_(sdl_error) {}
    const std::string& sdl_error() const { return sdl_error_; }

  private:
    std::string sdl_error_;
};

class GuiHost {
  public:
    enum class Mode {
        Window,     // a visible, resizable window fed by SDL's events
        Offscreen,  // a hidden window; the caller sets ImGui's display size and draws offscreen
    };

    GuiHost(const char* title, int width, int height, Mode mode);
    ~GuiHost();
    GuiHost(const GuiHost&) = delete;
    GuiHost& operator=(const GuiHost&) = delete;

    SDL_Window* window() const { return window_; }
    const Gl& gl() const { return gl_; }
    const Fonts& fonts() const { return fonts_; }

  private:
    void teardown();

    bool sdl_ = false, imgui_ = false, sdl_backend_ = false, gl_backend_ = false;
    SDL_Window* window_ = nullptr;
    SDL_GLContext context_ = nullptr;
    Gl gl_;
    Fonts fonts_;
};

}  // namespace cg::viewer
