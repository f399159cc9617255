// The interactive viewer: window, event loop, keyboard shortcuts, screenshots.
#include "viewer/app.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "viewer/host.hpp"
#include "viewer/palette.hpp"
#include "viewer/session.hpp"
#include "viewer/ui.hpp"

namespace cg::viewer {

namespace {

// ImGui 1.86 samples key state once per frame, so a press and release within one frame would
// be lost: the stepping shortcuts come from SDL's key events instead.
void on_key(Session& s, const SDL_KeyboardEvent& key) {
    if (ImGui::GetIO().WantTextInput) return;  // typing a number is not stepping
    switch (key.keysym.sym) {
        case SDLK_HOME:
            s.reset();
            break;
        case SDLK_LEFT:
            s.step_back();
            break;
        case SDLK_RIGHT:
        case SDLK_SPACE:
            s.step_forward();
            break;
        case SDLK_END:
            s.run_to_end();
            break;
        case SDLK_p:
            if (!key.repeat) s.toggle_play();
            break;
        default:
            break;
    }
}

// Reads the frame just drawn from the back buffer, before it is swapped away.
void take_screenshot(Session& s, const GuiHost& host) {
    int width = 0, height = 0;
    SDL_GL_GetDrawableSize(host.window(), &width, &height);
    const std::string id = s.algorithm ? s.algorithm->spec->id : "viewer";
    const std::string path = "cgsandbox-" + id + "-step" + std::to_string(s.index()) + ".png";
    try {
        host.gl().ReadBuffer(GL_BACK);
        write_png(path, width, height, read_pixels(host.gl(), width, height));
        s.set_status("Saved " + path, false);
    } catch (const std::exception& e) {
        s.set_status(e.what(), true);
    }
}

// Returns false when the window should close.
bool handle_event(Session& s, const GuiHost& host, const SDL_Event& e) {
    ImGui_ImplSDL2_ProcessEvent(&e);
    if (e.type == SDL_QUIT) return false;
    if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE &&
        e.window.windowID == SDL_GetWindowID(host.window()))
        return false;
    if (e.type == SDL_KEYDOWN) on_key(s, e.key);
    return true;
}

}  // namespace

int run_viewer(const Registry& registry, const std::optional<Checkpoint>& initial) {
    std::unique_ptr<GuiHost> host;
    try {
        host = std::make_unique<GuiHost>("CG Sandbox", 1400, 900, GuiHost::Mode::Window);
    } catch (const NoDisplay& e) {
        std::cerr << "cgsandbox: no display available (" << e.sdl_error()
                  << "); work headless with `cgsandbox render ID --out FILE.png`, or run the "
                     "viewer under `xvfb-run -a build/bin/cgsandbox`\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "cgsandbox: cannot open the viewer: " << e.what() << "\n";
        return 1;
    }

    Session s(registry);
    s.fonts = host->fonts();
    s.lessons = load_lessons(default_lessons_dir(), registry);  // broken files: listed in the UI
    if (initial) {
        s.load(*initial);
    } else if (!registry.all().empty()) {
        s.choose(registry.all().front());
        // A student starts from the course: the lesson list, the first algorithm beside it.
        if (!s.lessons.lessons.empty() || !s.lessons.errors.empty()) s.show_tab(Tab::Lessons);
    }

    bool running = true;
    int busy_frames = 3;  // redraw a few frames after any event so hover effects settle
    Uint64 last = SDL_GetPerformanceCounter();
    while (running) {
        SDL_Event e;
        // Idle: sleep until something happens. Nothing changes on screen without an event,
        // except a text field's blinking cursor, which gets a redraw every 100 ms.
        const bool animating = s.playing || busy_frames > 0 || ImGui::IsAnyMouseDown();
        if (!animating) {
            const bool typing = ImGui::GetIO().WantTextInput;
            if (SDL_WaitEventTimeout(&e, typing ? 100 : 1000)) {
                running = handle_event(s, *host, e);
                busy_frames = 3;
            } else if (!typing) {
                continue;
            }
            last = SDL_GetPerformanceCounter();  // time spent asleep is not Play's time
        }
        while (SDL_PollEvent(&e)) {
            running = handle_event(s, *host, e) && running;
            busy_frames = 3;
        }

        const Uint64 now = SDL_GetPerformanceCounter();
        const double seconds =
            static_cast<double>(now - last) / static_cast<double>(SDL_GetPerformanceFrequency());
        last = now;
        s.advance(std::min(seconds, 0.25));

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplSDL2_NewFrame();
        ImGui::NewFrame();
        draw_ui(s, ImGui::GetIO().DisplaySize, true, true);
        ImGui::Render();

        int width = 0, height = 0;
        SDL_GL_GetDrawableSize(host->window(), &width, &height);
        host->gl().clear(width, height, kCanvasBackground);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        if (s.screenshot_requested) {
            s.screenshot_requested = false;
            take_screenshot(s, *host);
        }
        SDL_GL_SwapWindow(host->window());
        busy_frames = std::max(busy_frames - 1, 0);
    }
    return 0;
}

}  // namespace cg::viewer
