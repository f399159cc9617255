// The picture in the real viewer (issue 45), driven by real SDL events: the canvas re-fitted
// after the window is resized, F framing the 3D view on the step's subject again after the
// student zoomed away, the side panels folded for room, Predict's question, fields, Reveal
// and verdict all in sight without scrolling at the window's size (run at 1920×1080, and at
// 1280×720 with the other [fit] tests), and the grid's lines drawn whole.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "gui_events/driver.hpp"
#include "study/predict.hpp"
#include "viewer/gl.hpp"
#include "viewer/layout.hpp"
#include "viewer/palette.hpp"

using cg::test::Driver;
using cg::test::gui_registry;
using cg::viewer::Box;
using cg::viewer::LayoutRecord;
using cg::viewer::ViewKind;

namespace {

void choose(Driver& d, const std::string& id) {
    const cg::Algorithm* a = gui_registry().find(id);
    REQUIRE(a);
    d.session().choose(*a);
    d.frames(3);
}

// What the canvas placed where in the next frame.
LayoutRecord layout(Driver& d) {
    LayoutRecord r;
    d.session().layout_record = &r;
    d.frames(1);
    REQUIRE(d.session().layout_record == nullptr);  // taken by that frame
    return r;
}

const LayoutRecord::Panel& view_of(const LayoutRecord& r, ViewKind kind) {
    const auto it = std::find_if(r.panels.begin(), r.panels.end(),
                                 [&](const LayoutRecord::Panel& p) { return p.kind == kind; });
    REQUIRE(it != r.panels.end());
    return *it;
}

// With CG_SHOTS=DIR, the frame on screen as DIR/NAME-WxH.png, to look at.
void shot(Driver& d, const std::string& name) {
    const char* dir = std::getenv("CG_SHOTS");
    if (!dir) return;
    d.move({2, d.size().y - 2.0});  // no tooltip over what is looked at
    d.frames(3);
    const glm::ivec2 size = d.size();
    cg::viewer::write_png(std::string(dir) + "/" + name + "-" + std::to_string(size.x) + "x" +
                              std::to_string(size.y) + ".png",
                          size.x, size.y, d.viewer().last_frame());
}

double width(const Box& b) { return b.max.x - b.min.x; }
double height(const Box& b) { return b.max.y - b.min.y; }

// How much of the view its content fills, the larger of the two directions (a wide figure in
// a tall view fills its width).
double filled(const LayoutRecord::Panel& p) {
    return std::max(width(p.content) / width(p.box), height(p.content) / height(p.box));
}

void wheel(Driver& d, glm::dvec2 at, int clicks) {
    d.move(at);
    d.frames(1);
    for (int i = 0; i < std::abs(clicks); ++i) {
        SDL_Event e{};
        e.type = SDL_MOUSEWHEEL;
        e.wheel.windowID = SDL_GetWindowID(d.viewer().window());
        e.wheel.y = clicks > 0 ? 1 : -1;
        SDL_PushEvent(&e);
        d.frames(1);
    }
}

}  // namespace

TEST_CASE("gui picture: a resized window fits the picture to its new canvas", "[gui-events][picture]") {
    Driver d;
    choose(d, "liang-barsky");
    const LayoutRecord before = layout(d);
    const LayoutRecord::Panel world = view_of(before, ViewKind::World2d);
    CHECK(filled(world) > 0.7);
    const double zoom = d.session().canvas.view.zoom;

    // Smaller: a real resize of the window, as a window manager does it.
    const glm::ivec2 size = d.size();
    SDL_SetWindowSize(d.viewer().window(), size.x * 3 / 4, size.y * 3 / 4);
    d.frames(4);
    REQUIRE(d.size().x < size.x);
    const LayoutRecord after = layout(d);
    const LayoutRecord::Panel small = view_of(after, ViewKind::World2d);
    CAPTURE(width(world.box), width(small.box), zoom, d.session().canvas.view.zoom);
    CHECK(width(small.box) < width(world.box));
    CHECK(d.session().canvas.view.zoom < zoom);  // fitted again, not cut off
    CHECK(filled(small) > 0.7);
    const Box inside = small.box.grown(1);
    CHECK(inside.contains(small.content.min));
    CHECK(inside.contains(small.content.max));

    SDL_SetWindowSize(d.viewer().window(), size.x, size.y);
    d.frames(4);
    CHECK(d.session().canvas.view.zoom == Approx(zoom));
}

TEST_CASE("gui picture: F frames the 3D view on the step's subject again", "[gui-events][picture]") {
    Driver d;
    choose(d, "arbitrary-axis");
    d.key(SDLK_RIGHT);
    d.key(SDLK_RIGHT);
    const double fitted = d.session().canvas.camera3.view.distance;
    const LayoutRecord r = layout(d);
    const LayoutRecord::Panel view = view_of(r, ViewKind::View3d);
    // The student zooms far out with the wheel over the 3D view: the subject shrinks.
    wheel(d, Driver::centre(view.box), -12);
    CHECK(d.session().canvas.camera3.view.distance > 3 * fitted);
    d.key(SDLK_f);
    CHECK(d.session().canvas.camera3.view.distance == Approx(fitted));
    const LayoutRecord again = layout(d);
    CHECK(filled(view_of(again, ViewKind::View3d)) > 0.5);
}

TEST_CASE("gui picture: the side panels fold for room and unfold again", "[gui-events][picture][fit]") {
    Driver d;
    choose(d, "liang-barsky");
    d.session().open_lesson(*d.session().lessons.find("liang-barsky"));
    d.frames(3);
    const Box open = d.session().canvas_rect;
    const glm::ivec2 size = d.size();
    CAPTURE(size.x, size.y, width(open));
    CHECK(width(open) >= 0.5 * size.x);  // half the width with both panels open
    d.click("fold left");
    CHECK(d.session().fold_left);
    d.key(SDLK_RIGHTBRACKET);
    CHECK(d.session().fold_right);
    const Box folded = d.session().canvas_rect;
    shot(d, "folded");
    CHECK(width(folded) >= 0.9 * size.x);
    CHECK(width(folded) * height(folded) >= 0.5 * size.x * size.y);  // half the window
    const LayoutRecord r = layout(d);
    CHECK(filled(view_of(r, ViewKind::World2d)) > 0.7);  // and the picture fills it
    d.click("unfold left");
    d.click("unfold right");
    CHECK_FALSE(d.session().fold_left);
    CHECK_FALSE(d.session().fold_right);
    CHECK(d.session().canvas_rect.max.x == Approx(open.max.x));
}

TEST_CASE("gui picture: Predict shows its question, fields, Reveal and verdict without scrolling",
          "[gui-events][picture][fit]") {
    Driver d;
    CAPTURE(d.size().x, d.size().y);
    for (const char* id : {"liang-barsky", "ray-quadric", "phong-lighting"}) {
        CAPTURE(id);
        choose(d, id);
        d.session().open_lesson(*d.session().lessons.for_algorithm(id));
        d.frames(2);
        d.click("mode:Predict");
        REQUIRE(d.session().study.mode == cg::viewer::Mode::Predict);
        const cg::study::Trace* t = d.session().trace();
        REQUIRE(t);
        // Two steps predicted: the first with its numbers, so every kind of field shows.
        for (int k = 0; k < 2 && d.session().can_predict(); ++k) {
            const cg::StepInfo& next = t->steps[d.session().study.predict.reached];
            d.click("predict event:" + next.event);
            for (const std::string& name : d.session().predict_vars()) {
                CAPTURE(name);
                CHECK(d.spot("predict var:" + name).visible);
            }
            CHECK(d.spot("predict event:" + next.event).visible);
            CHECK(d.spot("Reveal").visible);
            d.click("Reveal");
            CHECK(d.spot("predict verdict").visible);
            CHECK(d.spot("predict score").visible);
        }
        shot(d, std::string("predict-") + id);
        d.click("mode:Watch");
    }
}

TEST_CASE("gui picture: the grid's lines are drawn whole", "[gui-events][picture]") {
    Driver d;
    choose(d, "liang-barsky");
    const LayoutRecord r = layout(d);
    const LayoutRecord::Panel& world = view_of(r, ViewKind::World2d);
    // The band over the picture's content holds only the grid: each column of it with the
    // minor lines' grey is such a line, and must run through the whole band (broken lines
    // stopped at random heights).
    const int y0 = static_cast<int>(world.box.min.y) + 2, y1 = static_cast<int>(world.content.min.y) - 2;
    REQUIRE(y1 - y0 >= 10);
    auto grid_grey = [&](int x, int y) {
        const std::uint32_t p = d.pixel(x, y);
        const int r = p >> 24 & 255, g = p >> 16 & 255, b = p >> 8 & 255;
        return r == g && g == b && r >= 0xc8 && r <= 0xf4;  // the minor and major lines
    };
    int lines = 0;
    for (int x = static_cast<int>(world.box.min.x) + 2; x < static_cast<int>(world.box.max.x) - 2; ++x) {
        int grey = 0;
        for (int y = y0; y < y1; ++y) grey += grid_grey(x, y);
        if (grey < (y1 - y0) / 5) continue;  // not a line (a crossing horizontal one, text)
        ++lines;
        CAPTURE(x, grey, y1 - y0);
        CHECK(grey >= (y1 - y0) * 3 / 4);
    }
    CHECK(lines >= 5);
}

TEST_CASE("gui picture: a handle in an image panel is dragged from pixel to pixel",
          "[gui-events][picture]") {
    Driver d;
    choose(d, "ray-tracer");
    const cg::Lesson* lesson = d.session().lessons.for_algorithm("ray-tracer");
    REQUIRE(lesson);
    // A preset that traces one pixel's ray tree.
    const auto preset = std::find_if(lesson->presets.begin(), lesson->presets.end(), [](auto& p) {
        const cg::json& st = p.input.value("stepping", cg::json::object());
        return st.value("granularity", "") == "ray-tree" && st.contains("pixel");
    });
    REQUIRE(preset != lesson->presets.end());
    d.session().load_preset(*preset);
    d.frames(3);
    const cg::json before = d.session().input["stepping"]["pixel"];
    const LayoutRecord r = layout(d);
    const LayoutRecord::Panel& image = view_of(r, ViewKind::Image);
    const int width = d.session().input["camera"]["size"][0].get<int>();
    const double cell = (image.content.max.x - image.content.min.x) / width;
    CAPTURE(before.dump(), cell);
    REQUIRE(cell >= 4);
    const glm::dvec2 at = Driver::centre(d.widget("handle:pixel"));
    CHECK(image.content.contains(at));
    // Three pixels right and two up, the mouse a little off the centres.
    d.drag(at, at + glm::dvec2(3.3 * cell, -2.2 * cell));
    const cg::json after = d.session().input["stepping"]["pixel"];
    CAPTURE(after.dump());
    CHECK(after[0].get<double>() == before[0].get<double>() + 3);
    CHECK(after[1].get<double>() == before[1].get<double>() + 2);
    CHECK(d.session().input_error.empty());
    // The tree now is that pixel's, and the handle is drawn on it.
    CHECK(glm::distance(Driver::centre(d.widget("handle:pixel")),
                        at + glm::dvec2(3 * cell, -2 * cell)) < 2);
}
