// The interactive viewer: window, event loop, keyboard shortcuts, screenshots.
#include "viewer/app.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <algorithm>
#include <iostream>

#include "viewer/deliver.hpp"
#include "viewer/grid_texture.hpp"
#include "viewer/host.hpp"
#include "viewer/palette.hpp"
#include "viewer/session.hpp"
#include "viewer/ui.hpp"

namespace cg::viewer {

namespace {

constexpr int kMaxWidth = 1400, kMaxHeight = 900;  // what the layout was drawn for

// The stepping keys, F1 or ? for the list of keys, Tab / Shift-Tab from panel to panel, and
// Escape back out of one. They come from SDL's key events (a press and release inside one
// frame still counts; ImGui 1.86 would see the key only as it is when the frame starts).
// Returns true when the key was the viewer's, so ImGui should not see it too.
bool on_key(Session& s, const SDL_KeyboardEvent& key) {
    const ImGuiIO& io = ImGui::GetIO();
    if (key.keysym.sym == SDLK_F1) {
        if (!key.repeat) s.show_help = !s.show_help;
        return true;
    }
    if (io.WantTextInput) return false;  // typing a number is not stepping
    const bool shift = (key.keysym.mod & KMOD_SHIFT) != 0;
    // While the keyboard is moving through a panel's controls (after Tab), the arrows and Space
    // are ImGui's: they move to the next control and press it.
    const bool navigating = io.NavVisible;
    switch (key.keysym.sym) {
        case SDLK_TAB:
            s.panel_step = shift ? -1 : 1;
            return true;
        case SDLK_ESCAPE:
            if (s.show_help) {
                s.show_help = false;
                return true;
            }
            s.leave_panels = true;
            return false;  // ImGui cancels what it was doing too
        case SDLK_HOME:
            s.reset();
            return true;
        case SDLK_END:
            s.run_to_end();
            return true;
        case SDLK_p:
            if (!key.repeat) s.toggle_play();
            return true;
        case SDLK_f:  // frame: fit the views to what the step is about
            s.canvas.fit_pending = true;
            return true;
        case SDLK_LEFTBRACKET:  // fold or unfold the side panels
            s.fold_left = !s.fold_left;
            return true;
        case SDLK_RIGHTBRACKET:
            s.fold_right = !s.fold_right;
            return true;
        case SDLK_LEFT:
            if (navigating) return false;
            s.step_back();
            return true;
        case SDLK_RIGHT:
        case SDLK_SPACE:
            if (navigating) return false;
            s.step_forward();
            return true;
        // The study modes (panel_modes.cpp).
        case SDLK_m:
            if (!key.repeat) s.cycle_mode();
            return true;
        case SDLK_c:
            if (key.repeat) return true;
            if (s.study.compare.open)
                s.close_compare();
            else
                s.open_compare(s.study.compare.choice);
            return true;
        case SDLK_b:
            if (s.study.mode != Mode::Bug) return false;
            if (!key.repeat) s.answer_bug(s.index());
            return true;
        case SDLK_RETURN:
        case SDLK_KP_ENTER:
            if (navigating || s.study.mode != Mode::Predict) return false;
            if (!key.repeat) s.reveal_prediction();
            return true;
        default:
            // 1 … 9: Predict's choice of the next step's event.
            if (s.study.mode == Mode::Predict && s.algorithm && key.keysym.sym >= SDLK_1 &&
                key.keysym.sym <= SDLK_9) {
                const std::size_t i = static_cast<std::size_t>(key.keysym.sym - SDLK_1);
                if (i < s.algorithm->spec->events.size())
                    s.choose_prediction(s.algorithm->spec->events[i].id);
                return true;
            }
            return false;
    }
}

// Reads the frame just drawn from the back buffer, before it is swapped away.
std::vector<std::uint8_t> read_back(const GuiHost& host, int& width, int& height) {
    SDL_GL_GetDrawableSize(host.window(), &width, &height);
    host.gl().ReadBuffer(GL_BACK);
    return read_pixels(host.gl(), width, height);
}

void take_screenshot(Session& s, const GuiHost& host) {
    const std::string id = s.algorithm ? s.algorithm->spec->id : "viewer";
    const std::string path = "cgsandbox-" + id + "-step" + std::to_string(s.index()) + ".png";
    try {
        int width = 0, height = 0;
        const std::vector<std::uint8_t> pixels = read_back(host, width, height);
        write_png(path, width, height, pixels);
        if (!deliver(path, "image/png")) throw std::runtime_error("cannot download " + path);
        s.set_status(delivered("Saved", path), false);
    } catch (const std::exception& e) {
        s.set_status(e.what(), true);
    }
}

// GuiHost opened the window within the display's usable area; a window manager's frame (known
// only once the window is up) may still push it over the edge: then it shrinks to fit.
void fit_frame_to_display(SDL_Window* window) {
    SDL_Rect usable;
    int top = 0, left = 0, bottom = 0, right = 0;
    if (SDL_GetDisplayUsableBounds(std::max(SDL_GetWindowDisplayIndex(window), 0), &usable) != 0 ||
        SDL_GetWindowBordersSize(window, &top, &left, &bottom, &right) != 0)
        return;
    int w = 0, h = 0;
    SDL_GetWindowSize(window, &w, &h);
    const int width = std::min(w, usable.w - left - right);
    const int height = std::min(h, usable.h - top - bottom);
    if (width == w && height == h) return;
    SDL_SetWindowSize(window, std::max(width, 320), std::max(height, 240));
    SDL_SetWindowPosition(window, usable.x + left, usable.y + top);
}

}  // namespace

Viewer::Viewer(const Registry& registry, const std::optional<Checkpoint>& initial)
    : session_(std::make_unique<Session>(registry)) {
    Session& s = *session_;
    // The run first, then the window (see GuiHost: the sanitizer build checks what is
    // allocated before it for leaks).
    // Broken files are listed in the UI; a preset's input is checked when it is loaded.
    s.lessons = load_lessons(default_lessons_dir(), registry, PresetCheck::WhenLoaded);
    if (initial) {
        s.load(*initial);
    } else if (!registry.all().empty()) {
        s.choose(registry.all().front());
        // A student starts from the course: the lesson list, the first algorithm beside it.
        if (!s.lessons.lessons.empty() || !s.lessons.errors.empty()) s.show_tab(Tab::Lessons);
    }
    host_ = std::make_unique<GuiHost>("CG Sandbox", kMaxWidth, kMaxHeight, GuiHost::Mode::Window);
    fit_frame_to_display(host_->window());
    s.fonts = host_->fonts();
    textures_ = std::make_unique<GridTextures>(host_->gl());
    s.textures = textures_.get();
    compare_textures_ = std::make_unique<GridTextures>(host_->gl());
    s.compare_textures = compare_textures_.get();
    ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
    last_ = SDL_GetPerformanceCounter();
}

Viewer::~Viewer() {
    session_->close_compare();  // side B draws with compare_textures_
    session_->textures = nullptr;
    session_->compare_textures = nullptr;
    textures_.reset();  // while the GL context is still there
    compare_textures_.reset();
}

SDL_Window* Viewer::window() const { return host_->window(); }

bool Viewer::handle(const SDL_Event& e) {
    // Keys the viewer takes for itself are kept from ImGui (Tab would also jump to a text
    // field of the panel it lands in).
    if (e.type == SDL_KEYDOWN && on_key(*session_, e.key)) return true;
    ImGui_ImplSDL2_ProcessEvent(&e);
    if (e.type == SDL_KEYDOWN || e.type == SDL_KEYUP) {
        // The modifiers as the event says, not as SDL's keyboard state is now (the backend
        // polls that, and a pushed event does not change it).
        ImGuiIO& io = ImGui::GetIO();
        const Uint16 mod = e.key.keysym.mod;
        io.KeyShift = (mod & KMOD_SHIFT) != 0;
        io.KeyCtrl = (mod & KMOD_CTRL) != 0;
        io.KeyAlt = (mod & KMOD_ALT) != 0;
        io.KeySuper = (mod & KMOD_GUI) != 0;
    }
    // "?" is a character, whatever key the layout puts it on.
    if (e.type == SDL_TEXTINPUT && !ImGui::GetIO().WantTextInput &&
        std::string(e.text.text) == "?")
        session_->show_help = !session_->show_help;
    if (e.type == SDL_QUIT) return false;
    if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE &&
        e.window.windowID == SDL_GetWindowID(host_->window()))
        return false;
    return true;
}

bool Viewer::turn(int idle_ms) {
    Session& s = *session_;
    SDL_Event e;
    // Idle: sleep until something happens. Nothing changes on screen without an event, except
    // a text field's blinking cursor, which gets a redraw every 100 ms.
    const bool animating =
        s.playing || busy_frames_ > 0 || feed_.pending() || ImGui::IsAnyMouseDown();
    if (!animating) {
        const bool typing = ImGui::GetIO().WantTextInput;
        if (SDL_WaitEventTimeout(&e, typing ? std::min(idle_ms, 100) : idle_ms))
            feed_.push(e);
        else if (!typing)
            return running_;
        last_ = SDL_GetPerformanceCounter();  // time spent asleep is not Play's time
    }
    while (SDL_PollEvent(&e)) feed_.push(e);
    if (feed_.pending()) busy_frames_ = 3;
    feed_.take_frame([&](const SDL_Event& ev) { running_ = handle(ev) && running_; });

    const std::uint64_t now = SDL_GetPerformanceCounter();
    const double seconds =
        static_cast<double>(now - last_) / static_cast<double>(SDL_GetPerformanceFrequency());
    last_ = now;
    draw_frame(std::min(seconds, 0.25));
    busy_frames_ = std::max(busy_frames_ - 1, 0);
    return running_;
}

void Viewer::draw_frame(double seconds) {
    Session& s = *session_;
    s.advance(seconds);

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplSDL2_NewFrame();
#ifdef __EMSCRIPTEN__
    // Two animation frames may read the same time in a browser (its clock is coarsened), and
    // ImGui 1.86 wants time to pass between frames.
    ImGui::GetIO().DeltaTime = std::max(ImGui::GetIO().DeltaTime, 1e-4f);
#endif
    feed_.apply(ImGui::GetIO());
    ImGui::NewFrame();
    draw_ui(s, ImGui::GetIO().DisplaySize, true, true);
    ImGui::Render();

    int width = 0, height = 0;
    SDL_GL_GetDrawableSize(host_->window(), &width, &height);
    clear_frame(host_->gl(), width, height, s);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (s.screenshot_requested) {
        s.screenshot_requested = false;
        take_screenshot(s, *host_);
    }
    if (keep_frames_) last_frame_ = read_back(*host_, width, height);
    SDL_GL_SwapWindow(host_->window());
    ++frames_;
}

int run_viewer(const Registry& registry, const std::optional<Checkpoint>& initial) {
    std::unique_ptr<Viewer> viewer;
    try {
        viewer = std::make_unique<Viewer>(registry, initial);
    } catch (const NoDisplay& e) {
        std::cerr << "cgsandbox: no display available (" << e.sdl_error()
                  << "); work headless with `cgsandbox render ID --out FILE.png`, or run the "
                     "viewer under `xvfb-run -a build/bin/cgsandbox`\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "cgsandbox: cannot open the viewer: " << e.what() << "\n";
        return 1;
    }
    while (viewer->turn()) {
    }
    return 0;
}

}  // namespace cg::viewer
