// The viewer as a person uses it: the real window and event loop, driven by real SDL events
// (tests/gui_events/driver.hpp), checked by the pixels on screen and the session's state.
// Run under xvfb-run (tests/CMakeLists.txt), once on a 1920×1080 screen and once on 1280×720.
#include <catch2/catch.hpp>

#include <imgui.h>
#include <imgui_internal.h>

#include <chrono>
#include <filesystem>

#include "gui_events/driver.hpp"
#include "io/lesson.hpp"
#include "support/process.hpp"
#include "viewer/gl.hpp"

using cg::test::Driver;
using cg::test::Hold;
using cg::viewer::Tab;

namespace {

const char* hold_name(Hold h) {
    switch (h) {
        case Hold::SameFrame: return "pressed and released in one frame";
        case Hold::OneFrame: return "released a frame later";
        case Hold::Finger: return "held 300 ms";
    }
    return "";
}

// The colour ImGui gives a tab that is (or is not) selected, as the pixels show it.
std::uint32_t rgba(ImGuiCol c) {
    const ImU32 u = ImGui::GetColorU32(c);  // ABGR
    return (u & 0xff) << 24 | (u >> 8 & 0xff) << 16 | (u >> 16 & 0xff) << 8 | 0xff;
}

bool near(std::uint32_t a, std::uint32_t b, int tolerance = 8) {
    for (int shift : {24, 16, 8})
        if (std::abs(int(a >> shift & 255) - int(b >> shift & 255)) > tolerance) return false;
    return true;
}

// A pixel of the tab's own background: inside its frame, left of its label.
std::uint32_t tab_pixel(Driver& d, const std::string& label) {
    const cg::viewer::Box b = d.widget("tab:" + label);
    return d.pixel(static_cast<int>(b.min.x) + 3, static_cast<int>((b.min.y + b.max.y) / 2));
}

}  // namespace

TEST_CASE("gui events: the first click on a tab switches to it, and it stays", "[gui-events]") {
    for (Hold hold : {Hold::SameFrame, Hold::OneFrame, Hold::Finger}) {
        for (const auto& [label, tab, content] :
             {std::tuple{"Exam", Tab::Exam, "exam seed"},
              std::tuple{"Algorithm", Tab::Algorithm, "algorithms"}}) {
            CAPTURE(hold_name(hold), label);
            Driver d;  // a fresh start: the viewer opens on the Lessons tab
            REQUIRE(d.session().tab == Tab::Lessons);
            REQUIRE(d.drawn("lesson:liang-barsky"));
            d.click(std::string("tab:") + label, hold);
            CHECK(d.session().tab == tab);
            CHECK(d.drawn(content));
            CHECK_FALSE(d.drawn("lesson:liang-barsky"));
            // ... and it stays when the pointer moves away and time passes.
            d.move({d.size().x / 2.0, d.size().y / 2.0});
            d.frames(10);
            CHECK(d.session().tab == tab);
            CHECK(d.drawn(content));
            // The pixels agree: the tab is drawn selected, Lessons is not.
            CHECK(near(tab_pixel(d, label), rgba(ImGuiCol_TabActive)));
            CHECK_FALSE(near(tab_pixel(d, "Lessons"), rgba(ImGuiCol_TabActive)));
        }
    }
    SECTION("and back: every tab, clicked in turn") {
        Driver d;
        for (const auto& [label, tab] : {std::pair{"Algorithm", Tab::Algorithm},
                                         std::pair{"Exam", Tab::Exam},
                                         std::pair{"Lessons", Tab::Lessons}}) {
            d.click(std::string("tab:") + label);
            CHECK(d.session().tab == tab);
        }
    }
}

TEST_CASE("gui events: opening a lesson from code still selects the Lessons tab",
          "[gui-events]") {
    Driver d;
    d.click("tab:Algorithm");
    REQUIRE(d.session().tab == Tab::Algorithm);
    d.click("Read the lesson");  // the Algorithm tab's button opens the lesson of the algorithm
    CHECK(d.session().tab == Tab::Lessons);
    CHECK(d.drawn("presets"));
    CHECK(near(tab_pixel(d, "Lessons"), rgba(ImGuiCol_TabActive)));
}

TEST_CASE("gui events: Step and Back, by button and by key", "[gui-events]") {
    Driver d;
    d.click("tab:Algorithm");
    for (Hold hold : {Hold::SameFrame, Hold::OneFrame, Hold::Finger}) {
        CAPTURE(hold_name(hold));
        const std::size_t before = d.session().index();
        const auto frame = d.viewer().last_frame();
        d.click("Step", hold);
        CHECK(d.session().index() == before + 1);
        // The picture changed with it (the canvas, the pseudocode line, the narration).
        CHECK(Driver::changed(frame, d.viewer().last_frame(), d.size(),
                              {{0, 0}, {double(d.size().x), double(d.size().y)}}) > 100);
        d.click("Back", hold);
        CHECK(d.session().index() == before);
        d.key(SDLK_RIGHT, KMOD_NONE, hold);
        CHECK(d.session().index() == before + 1);
        d.key(SDLK_SPACE, KMOD_NONE, hold);
        CHECK(d.session().index() == before + 2);
        d.key(SDLK_LEFT, KMOD_NONE, hold);
        CHECK(d.session().index() == before + 1);
        d.key(SDLK_HOME, KMOD_NONE, hold);
        CHECK(d.session().index() == 0);
    }
    d.key(SDLK_END);
    CHECK(d.session().at_end());
    d.click("Reset");
    CHECK(d.session().index() == 0);
    d.click("Run to end");
    CHECK(d.session().at_end());
}

TEST_CASE("gui events: Play runs an animation at real time, then P pauses it", "[gui-events]") {
    Driver d;
    d.click("tab:Algorithm");
    d.session().choose(*cg::test::gui_registry().find("spring-mass"));
    d.frames(2);
    REQUIRE(d.session().clock_now() == 0.0);
    const auto frame = d.viewer().last_frame();
    const auto start = std::chrono::steady_clock::now();
    d.click("Play");
    CHECK(d.session().playing);
    d.wait_ms(600);
    d.key(SDLK_p);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK_FALSE(d.session().playing);
    // Simulated seconds passed as seconds: the example's 0.02 s steps came dozens at a time,
    // where steps-a-second would have taken two or three; never ahead of the wall clock (one
    // step at most), and behind it only by frames the loaded machine stalled.
    const double t = d.session().clock_now().value();
    CAPTURE(t, wall, d.session().index());
    CHECK(t >= 0.3);
    CHECK(t <= wall + 0.02 + 1e-9);
    CHECK(Driver::changed(frame, d.viewer().last_frame(), d.size(),
                          {{0, 0}, {double(d.size().x), double(d.size().y)}}) > 100);
    // Paused: time stands still.
    const double paused = t;
    d.wait_ms(100);
    CHECK(d.session().clock_now().value() == paused);
}

TEST_CASE("gui events: typing a number into a field restarts the run on it", "[gui-events]") {
    Driver d;
    d.click("tab:Algorithm");
    d.session().choose(*cg::test::gui_registry().find("liang-barsky"));
    d.frames(2);
    d.click("Step");
    d.click("Step");
    REQUIRE(d.session().index() == 2);
    REQUIRE(d.session().input["window"]["xmin"] != 2.5);
    d.click("field:/window/xmin");
    CHECK(ImGui::GetIO().WantTextInput);
    d.key(SDLK_a, KMOD_LCTRL);  // select what is there
    d.type("2.5");
    d.key(SDLK_RETURN);
    CHECK(d.session().input["window"]["xmin"] == 2.5);
    CHECK(d.session().input_error.empty());
    CHECK(d.session().index() == 2);  // the same step of the new run
    // The arrows were the text field's while typing: no steps were taken by them.
    CHECK_FALSE(ImGui::GetIO().WantTextInput);
}

TEST_CASE("gui events: dragging a handle edits the input", "[gui-events]") {
    Driver d;
    d.click("tab:Algorithm");
    d.session().choose(*cg::test::gui_registry().find("liang-barsky"));
    d.frames(2);
    const cg::json before = d.session().input["p0"];
    const glm::dvec2 at = Driver::centre(d.widget("handle:P0"));
    d.drag(at, at + glm::dvec2(60, -40));
    const cg::json after = d.session().input["p0"];
    CHECK(after != before);
    CHECK(after[0].get<double>() > before[0].get<double>());  // right on screen: x grows
    CHECK(after[1].get<double>() > before[1].get<double>());  // up on screen: y grows
    // The handle is drawn where it was dropped.
    CHECK(glm::distance(Driver::centre(d.widget("handle:P0")), at + glm::dvec2(60, -40)) < 12);
}

TEST_CASE("gui events: open a lesson, pick a preset", "[gui-events]") {
    Driver d;
    d.click("lesson:sutherland-hodgman");
    const cg::Lesson* lesson = d.session().lessons.find("sutherland-hodgman");
    REQUIRE(lesson);
    CHECK(d.session().lesson() == lesson);
    CHECK(d.session().algorithm->spec->id == "sutherland-hodgman");
    REQUIRE(lesson->presets.size() >= 2);
    const std::string name = lesson->presets[1].name;
    d.click("presets");
    d.click("preset:" + name);
    REQUIRE(d.session().loaded_preset());
    CHECK(d.session().loaded_preset()->name == name);
    CHECK(d.session().index() == 0);
    d.click("All lessons");
    CHECK(d.drawn("lesson:liang-barsky"));
}

TEST_CASE("gui events: a mistakes section's step link opens that step of its preset",
          "[gui-events]") {
    Driver d;
    d.click("lesson:liang-barsky");
    const cg::Lesson* lesson = d.session().lessons.find("liang-barsky");
    REQUIRE(lesson);
    // Start elsewhere: another preset, stepped on, so that the link must load and jump.
    d.click("presets");
    d.click("preset:" + lesson->presets[1].name);
    d.key(SDLK_RIGHT);
    REQUIRE(d.session().index() == 1);
    d.click("step link:Common mistakes:4");
    REQUIRE(d.session().loaded_preset());
    CHECK(d.session().loaded_preset()->name == lesson->presets[0].name);
    CHECK(d.session().index() == 4);
    d.click("step link:Common mistakes:2");
    CHECK(d.session().loaded_preset()->name == lesson->presets[0].name);
    CHECK(d.session().index() == 2);
}

TEST_CASE("gui events: an exam, answered and checked", "[gui-events]") {
    Driver d;
    d.click("lesson:liang-barsky");
    d.click("tab:Exam");
    d.click("Start exam");
    REQUIRE(d.session().exam.active);
    CHECK(d.session().solution_hidden());
    const cg::ExamProblem& p = d.session().exam.problem;
    REQUIRE_FALSE(p.answers.empty());
    const std::string field = p.answers.front();
    d.click("answer:" + field);
    d.type(p.expected.at(field).dump());
    d.click("Check");
    REQUIRE_FALSE(d.session().exam.grades.empty());
    CHECK(d.session().exam.grades.front().field == field);
    CHECK(d.session().exam.grades.front().correct);
    // Stepping stays locked until the solution is asked for.
    d.key(SDLK_RIGHT);
    CHECK(d.session().index() == 0);
    d.click("Show solution");
    CHECK(d.session().index() == 1);
    d.click("Next solution step");
    CHECK(d.session().index() == 2);
}

TEST_CASE("gui events: save a checkpoint and open it again", "[gui-events]") {
    Driver d;
    d.click("tab:Algorithm");
    d.session().choose(*cg::test::gui_registry().find("liang-barsky"));
    d.frames(2);
    const std::string path = cg::test::output_path("gui-events-checkpoint.json");
    std::filesystem::remove(path);
    d.click("checkpoint path");
    d.key(SDLK_a, KMOD_LCTRL);
    d.type(path);
    d.key(SDLK_RETURN);
    REQUIRE(d.session().checkpoint_path == path);
    d.click("Step");
    d.click("Step");
    d.click("Step");
    d.click("Save");
    CHECK(std::filesystem::exists(path));
    CHECK_THAT(d.session().status, Catch::StartsWith("Saved"));
    d.click("Reset");
    REQUIRE(d.session().index() == 0);
    d.click("Open");
    CHECK(d.session().index() == 3);
    CHECK_THAT(d.session().status, Catch::StartsWith("Opened"));
}

TEST_CASE("gui events: the keyboard reaches every panel, and F1 lists the keys",
          "[gui-events]") {
    Driver d;
    d.key(SDLK_F1);
    CHECK(d.session().show_help);
    CHECK(ImGui::FindWindowByName("Keyboard") != nullptr);
    CHECK(ImGui::FindWindowByName("Keyboard")->Active);
    d.key(SDLK_ESCAPE);
    CHECK_FALSE(d.session().show_help);
    d.type("?");
    CHECK(d.session().show_help);
    d.key(SDLK_F1);
    CHECK_FALSE(d.session().show_help);

    // Tab from panel to panel; the arrows then move through the panel's controls, and Space
    // presses one — here, on the Step panel, the first control is Reset, the next is Back,
    // then Step.
    d.click("tab:Algorithm");  // the click gives the Study panel the keyboard ...
    d.key(SDLK_RIGHT);          // ... but the arrows step until Tab moves it through controls
    d.key(SDLK_RIGHT);
    REQUIRE(d.session().index() == 2);
    CHECK(d.session().focused_panel == "Study");
    d.key(SDLK_ESCAPE);  // no panel has the keyboard: Tab starts at the first
    CHECK(d.session().focused_panel.empty());
    d.key(SDLK_TAB);
    CHECK(d.session().focused_panel == "Study");
    d.key(SDLK_TAB);
    CHECK(d.session().focused_panel == "Canvas");
    d.key(SDLK_TAB);
    CHECK(d.session().focused_panel == "Step");
    CHECK(ImGui::GetIO().NavVisible);
    d.key(SDLK_RIGHT);  // Reset → Back: moves the cursor, does not step
    CHECK(d.session().index() == 2);
    d.key(SDLK_SPACE);  // presses Back
    CHECK(d.session().index() == 1);
    d.key(SDLK_TAB, KMOD_LSHIFT);
    CHECK(d.session().focused_panel == "Canvas");
    d.key(SDLK_TAB, KMOD_LSHIFT);
    CHECK(d.session().focused_panel == "Study");
    d.key(SDLK_TAB, KMOD_LSHIFT);
    CHECK(d.session().focused_panel == "Pseudocode");
    d.key(SDLK_ESCAPE);  // back to stepping
    CHECK_FALSE(ImGui::GetIO().NavVisible);
    d.key(SDLK_RIGHT);
    CHECK(d.session().index() == 2);
}

TEST_CASE("gui events: the window fits the screen, and every control is on it",
          "[gui-events][fit]") {
    Driver d;
    const glm::ivec2 size = d.size();
    SDL_Rect usable;
    REQUIRE(SDL_GetDisplayUsableBounds(0, &usable) == 0);
    CAPTURE(size.x, size.y, usable.w, usable.h);
    CHECK(size.x <= std::min(1400, usable.w));
    CHECK(size.y <= std::min(900, usable.h));
    CHECK(size.x == std::min(1400, usable.w));  // as big as it may be

    const cg::viewer::Box screen{{0, 0}, {double(size.x), double(size.y)}};
    auto on_screen = [&](const std::string& name) {
        const cg::viewer::Box b = d.widget(name);
        INFO(name << " at (" << b.min.x << ", " << b.min.y << ") – (" << b.max.x << ", "
                  << b.max.y << ")");
        CHECK(screen.contains(b.min));
        CHECK(screen.contains(b.max));
        CHECK(d.spot(name).visible);  // in sight without scrolling
    };
    for (const char* id : {"liang-barsky", "ray-tracer", "bezier-patch", "painters"}) {
        CAPTURE(id);
        d.session().choose(*cg::test::gui_registry().find(id));
        for (const Tab t : {Tab::Algorithm, Tab::Lessons, Tab::Exam}) {
            d.session().show_tab(t);
            d.frames(3);
            for (const char* c : {"Reset", "Back", "Step", "Run to end", "Play", "Screenshot",
                                  "checkpoint path", "Save", "Open", "export path", "Export",
                                  "tab:Algorithm", "tab:Lessons", "tab:Exam"})
                on_screen(c);
            // No panel hides a control past its edge: the bottom panel's rows all fit, and no
            // pseudocode line needs a sideways scroll.
            ImGuiWindow* step = ImGui::FindWindowByName("Step");
            REQUIRE(step);
            CHECK(step->ScrollMax.y == 0);
            ImGuiWindow* code = ImGui::FindWindowByName("Pseudocode");
            REQUIRE(code);
            CHECK(code->ScrollMax.x == 0);
            const auto& text = d.spot("pseudocode text");
            INFO("pseudocode text reaches x = " << text.box.max.x << ", the panel's edge is "
                                                << text.window.max.x);
            CHECK(text.visible);
            // The sliders show their numbers beside them, not under their grab.
            on_screen("speed");
            on_screen("scrub");
        }
    }
    // A picture of it, to look at.
    const std::string png = cg::test::output_path("gui-events-" + std::to_string(size.x) + "x" +
                                                  std::to_string(size.y) + ".png");
    d.session().choose(*cg::test::gui_registry().find("liang-barsky"));
    d.session().open_lesson(*d.session().lessons.find("liang-barsky"));
    d.frames(3);
    d.click("Step");
    d.click("Step");
    d.click("Step");
    cg::viewer::write_png(png, size.x, size.y, d.viewer().last_frame());
    CHECK(std::filesystem::file_size(png) > 1000);
}
