#include "viewer/host.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <cstdint>
#include <cstring>

// In the sanitizer build, LeakSanitizer does not count what is allocated while the window and
// its GL context exist: SDL, the X libraries and Mesa keep some of it until exit (reported
// without usable stacks, so a suppressions file cannot name them). The run, the session and the
// timeline are made before the host, so their allocations are still checked.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CG_LSAN_SCOPE 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define CG_LSAN_SCOPE 1
#endif
#ifdef CG_LSAN_SCOPE
#include <sanitizer/lsan_interface.h>
#endif

namespace cg::viewer {

namespace {

void third_party_allocations_begin() {
#ifdef CG_LSAN_SCOPE
    __lsan_disable();
#endif
}

void third_party_allocations_end() {
#ifdef CG_LSAN_SCOPE
    __lsan_enable();
#endif
}

bool has_env(const char* name) {
    const char* v = std::getenv(name);
    return v && *v;
}

// Where SDL should draw. Without any display SDL 2.26 quietly falls back to its "offscreen"
// driver: right for `render` (it draws through EGL, no X server needed), but a viewer window
// there would be invisible, so the viewer reports that there is no display instead. An
// explicit SDL_VIDEODRIVER is always respected.
void choose_video_driver(GuiHost::Mode mode) {
#ifdef __EMSCRIPTEN__
    return;  // in a browser the one driver is the page's canvas
#endif
    if (has_env("SDL_VIDEODRIVER") || has_env("WAYLAND_DISPLAY")) return;
    if (has_env("DISPLAY")) {
        SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");  // an unreachable X server is then an error
        return;
    }
    if (mode == GuiHost::Mode::Window)
        throw NoDisplay("neither DISPLAY nor WAYLAND_DISPLAY is set");
    SDL_SetHint(SDL_HINT_VIDEODRIVER, "offscreen");  // also skips noisy probes of the others
}

bool invisible_driver() {
    const char* driver = SDL_GetCurrentVideoDriver();
    return driver && (std::strcmp(driver, "offscreen") == 0 || std::strcmp(driver, "dummy") == 0);
}

}  // namespace

GuiHost::GuiHost(const char* title, int width, int height, Mode mode) {
    third_party_allocations_begin();
    try {
        // `render` is a command-line tool: Ctrl-C should end it, not become an SDL event.
        if (mode == Mode::Offscreen) SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
        choose_video_driver(mode);
        // A click that arrives with the focus (within 10 ms of it, as SDL measures when it
        // handles the events, so a slow frame squeezes them together) is dropped by SDL's X11
        // driver unless this is set: the first click on a freshly shown viewer was lost under
        // load. A student's click always means what it says.
        SDL_SetHint(SDL_HINT_MOUSE_FOCUS_CLICKTHROUGH, "1");
        if (SDL_Init(SDL_INIT_VIDEO) != 0) throw NoDisplay(SDL_GetError());
        sdl_ = true;
        if (mode == Mode::Window && !has_env("SDL_VIDEODRIVER") && invisible_driver())
            throw NoDisplay(
                "cannot open the display" +
                std::string(has_env("DISPLAY") ? std::string(" ") + std::getenv("DISPLAY") : ""));

#ifdef __EMSCRIPTEN__
        // WebGL 2, which is OpenGL ES 3.0 (docs/web.md); the viewer uses nothing more.
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
        constexpr const char* kGlslVersion = "#version 300 es";
#else
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
        constexpr const char* kGlslVersion = "#version 330 core";
#endif
        SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
        Uint32 flags = SDL_WINDOW_OPENGL |
                       (mode == Mode::Window ? SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI
                                             : SDL_WINDOW_HIDDEN);
        // A window never opens bigger than the display's usable area (without task bars): a
        // 1366×768 or 1280×800 laptop gets a window that fits, not one cut off at the bottom.
        SDL_Rect usable;
        if (mode == Mode::Window && SDL_GetDisplayUsableBounds(0, &usable) == 0 && usable.w > 0 &&
            usable.h > 0) {
            width = std::min(width, usable.w);
            height = std::min(height, usable.h);
        }
        window_ = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width,
                                   height, flags);
        if (!window_) throw NoDisplay(SDL_GetError());
        context_ = SDL_GL_CreateContext(window_);
        if (!context_) throw NoDisplay(SDL_GetError());
        SDL_GL_MakeCurrent(window_, context_);
#ifndef __EMSCRIPTEN__  // the browser paces frames itself (emscripten_set_main_loop)
        if (mode == Mode::Window) SDL_GL_SetSwapInterval(1);  // vsync: 60 fps, no busy loop
#endif
        gl_ = Gl::load();

        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        imgui_ = true;
        ImGui::GetIO().IniFilename = nullptr;  // the layout is computed, nothing to remember
        ImGui::GetIO().LogFilename = nullptr;
        fonts_ = setup_fonts_and_style();
        if (mode == Mode::Window) {
            if (!ImGui_ImplSDL2_InitForOpenGL(window_, context_))
                throw std::runtime_error("cannot start ImGui's SDL backend");
            sdl_backend_ = true;
        }
        if (!ImGui_ImplOpenGL3_Init(kGlslVersion))
            throw std::runtime_error("cannot start ImGui's OpenGL backend");
        gl_backend_ = true;
        // The font atlas sampled at its nearest texel: the glyphs are drawn at whole pixels,
        // 1:1, so they look the same, and a software rasteriser samples it for every pixel of
        // every fill (solid fills read its white texel) — nearest costs it less than linear.
        if (!ImGui_ImplOpenGL3_CreateDeviceObjects())
            throw std::runtime_error("cannot create ImGui's OpenGL objects");
        const auto atlas = static_cast<GLuint>(reinterpret_cast<std::intptr_t>(ImGui::GetIO().Fonts->TexID));
        gl_.BindTexture(GL_TEXTURE_2D, atlas);
        gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    } catch (...) {
        teardown();
        third_party_allocations_end();
        throw;
    }
}

GuiHost::~GuiHost() {
    teardown();
    third_party_allocations_end();
}

void GuiHost::teardown() {
    if (gl_backend_) ImGui_ImplOpenGL3_Shutdown();
    if (sdl_backend_) ImGui_ImplSDL2_Shutdown();
    if (imgui_) ImGui::DestroyContext();
    if (context_) SDL_GL_DeleteContext(context_);
    if (window_) SDL_DestroyWindow(window_);
    if (sdl_) SDL_Quit();
    gl_backend_ = sdl_backend_ = imgui_ = sdl_ = false;
    context_ = nullptr;
    window_ = nullptr;
}

}  // namespace cg::viewer
