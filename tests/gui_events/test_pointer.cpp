// The viewer as a separate program, clicked by the X server's own pointer: xdotool moves it and
// presses the button through XTEST, exactly as a mouse would, and the test reads the window's
// pixels back from the X server (XGetImage). Pushed SDL events (test_gui_events.cpp) go round
// SDL's view of the pointer; this goes through it — which is where the first click on a tab was
// lost: ImGui 1.86's SDL backend polls the pointer when a frame starts instead of taking the
// position from the click's own event.
//
// Where to click comes from the same viewer drawn in this process at the same window size
// (the layout is a function of the size alone).
#include <catch2/catch.hpp>

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <thread>

#include "gui_events/driver.hpp"
#include "support/process.hpp"

extern char** environ;

namespace {

using cg::test::Driver;

// `cgsandbox` with no arguments — the viewer as a student starts it — in the background.
class ViewerProcess {
  public:
    ViewerProcess() {
        // Its window mapped and drawn. On a loaded machine the viewer may take seconds to
        // come up, or fail to reach a display that is itself slow to start: it is started
        // again then, up to three times.
        for (int attempt = 0; attempt < 3 && window_ == 0; ++attempt) {
            char* argv[] = {const_cast<char*>(CG_BINARY), nullptr};
            REQUIRE(posix_spawn(&pid_, CG_BINARY, nullptr, nullptr, argv, environ) == 0);
            const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
            while (std::chrono::steady_clock::now() < until) {
                int status = 0;
                if (waitpid(pid_, &status, WNOHANG) == pid_) {  // it gave up: start it again
                    pid_ = 0;
                    break;
                }
                const auto r = cg::test::run_process(
                    {"xdotool", "search", "--onlyvisible", "--name", "CG Sandbox"});
                if (r.exit_code == 0 && !r.out.empty()) {
                    window_ = std::stoul(r.out);
                    break;
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
        }
        REQUIRE(window_ != 0);
    }
    ~ViewerProcess() {
        if (pid_ == 0) return;
        kill(pid_, SIGTERM);
        int status = 0;
        waitpid(pid_, &status, 0);
    }
    unsigned long window() const { return window_; }

  private:
    pid_t pid_ = 0;
    unsigned long window_ = 0;
};

void xdotool(const std::vector<std::string>& args) {
    std::vector<std::string> argv{"xdotool"};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto r = cg::test::run_process(argv);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
}

void pause_ms(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

// Polls `done` every 20 ms until it holds or `seconds` pass; whether it held. A loaded machine
// (the sanitizer build, the other core busy) draws a frame in a second rather than in 10 ms: the
// test waits for what it expects to see instead of for a fixed time.
template <class Done>
bool wait_for(Done done, double seconds = 30) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!done()) {
        if (std::chrono::steady_clock::now() > until) return false;
        pause_ms(20);
    }
    return true;
}

// A pixel of the window as the X server has it, 0xRRGGBBAA.
std::uint32_t window_pixel(unsigned long window, glm::dvec2 at) {
    Display* d = XOpenDisplay(nullptr);
    REQUIRE(d);
    XImage* image = XGetImage(d, window, static_cast<int>(at.x), static_cast<int>(at.y), 1, 1,
                              AllPlanes, ZPixmap);
    REQUIRE(image);
    const unsigned long p = XGetPixel(image, 0, 0);
    XDestroyImage(image);
    XCloseDisplay(d);
    return static_cast<std::uint32_t>(((p >> 16) & 255) << 24 | ((p >> 8) & 255) << 16 |
                                      (p & 255) << 8 | 255);
}

bool near(std::uint32_t a, std::uint32_t b, int tolerance = 10) {
    for (int shift : {24, 16, 8})
        if (std::abs(int(a >> shift & 255) - int(b >> shift & 255)) > tolerance) return false;
    return true;
}

}  // namespace

TEST_CASE("gui pointer: the first click on the Exam tab of a fresh viewer switches to it",
          "[gui-events][pointer]") {
    // Where things are at this window size, and how they look, from a viewer in this process.
    // (and what those pixels look like once Exam is chosen, in this process's frame).
    glm::dvec2 exam_tab, start_button, lessons_tab;
    std::uint32_t button = 0, lessons_unselected = 0, lessons_selected = 0;
    {
        Driver d;
        exam_tab = Driver::centre(d.widget("tab:Exam"));
        const cg::viewer::Box lessons = d.widget("tab:Lessons");
        lessons_tab = glm::dvec2(lessons.min.x + 3, (lessons.min.y + lessons.max.y) / 2);
        lessons_selected = d.pixel(int(lessons_tab.x), int(lessons_tab.y));
        d.click("tab:Exam");
        d.move({700, 400});
        d.frames(3);
        const cg::viewer::Box start = d.widget("Start exam");
        start_button = glm::dvec2(start.min.x + 3, (start.min.y + start.max.y) / 2);
        button = d.pixel(int(start_button.x), int(start_button.y));
        lessons_unselected = d.pixel(int(lessons_tab.x), int(lessons_tab.y));
        REQUIRE_FALSE(near(lessons_selected, lessons_unselected));
    }
    for (const int hold_ms : {0, 300}) {  // a quick tap, and a finger's press
        CAPTURE(hold_ms);
        ViewerProcess viewer;
        const std::string w = std::to_string(viewer.window());
        // Its first frames drawn: the lesson list's tab shows as selected.
        REQUIRE(wait_for([&] { return near(window_pixel(viewer.window(), lessons_tab), lessons_selected); }));
        // The pointer comes in from the canvas, rests on the tab, and presses once.
        xdotool({"mousemove", "--window", w, "700", "400"});
        xdotool({"mousemove", "--window", w, std::to_string(int(exam_tab.x)),
                 std::to_string(int(exam_tab.y))});
        if (hold_ms == 0) {
            xdotool({"click", "1"});
        } else {
            xdotool({"mousedown", "1"});
            pause_ms(hold_ms);
            xdotool({"mouseup", "1"});
        }
        // However slow its frames, the click is taken: Exam's content appears.
        CHECK(wait_for([&] { return near(window_pixel(viewer.window(), start_button), button); }));
        xdotool({"mousemove", "--window", w, "700", "400"});  // away: it must stay switched
        pause_ms(500);
        CHECK(near(window_pixel(viewer.window(), start_button), button));  // Exam's content
        CHECK(near(window_pixel(viewer.window(), lessons_tab), lessons_unselected));
    }
}
