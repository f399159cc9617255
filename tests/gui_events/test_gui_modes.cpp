// The study modes in the real viewer (issue 20), driven by real SDL events: switching mode by
// clicking, Predict (choose the event, type the numbers, reveal), Find the bug (name the first
// wrong step) and Compare (two canvases side by side). Run under xvfb-run like the others.
//
// With CG_SHOTS=DIR set, each test also saves the frames a person would look at as PNGs.
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <string>

#include "core/format.hpp"
#include "gui_events/driver.hpp"
#include "study/bug.hpp"
#include "study/predict.hpp"
#include "viewer/gl.hpp"

using cg::test::Driver;
using cg::test::gui_registry;
using cg::viewer::Mode;

namespace {

const cg::Algorithm& algorithm(const std::string& id) {
    const cg::Algorithm* a = gui_registry().find(id);
    REQUIRE(a);
    return *a;
}

// Starts `id` on its example input, as picking it in the list does.
void choose(Driver& d, const std::string& id) {
    d.session().choose(algorithm(id));
    d.frames(3);
}

void shot(Driver& d, const std::string& name) {
    const char* dir = std::getenv("CG_SHOTS");
    if (!dir) return;
    d.move({2, d.size().y - 2.0});  // no tooltip over what is looked at
    d.frames(3);
    const glm::ivec2 size = d.size();
    cg::viewer::write_png(std::string(dir) + "/" + name + ".png", size.x, size.y,
                          d.viewer().last_frame());
}

// Pixels of the box that are coloured (not white, not the grid's greys): the scene's.
int coloured_pixels(Driver& d, const cg::viewer::Box& box) {
    int n = 0;
    for (int y = static_cast<int>(box.min.y) + 1; y < static_cast<int>(box.max.y) - 1; y += 2)
        for (int x = static_cast<int>(box.min.x) + 1; x < static_cast<int>(box.max.x) - 1; x += 2) {
            const std::uint32_t p = d.pixel(x, y);
            const int r = p >> 24 & 255, g = p >> 16 & 255, b = p >> 8 & 255;
            n += std::max({r, g, b}) - std::min({r, g, b}) > 40;
        }
    return n;
}

// The mean time of a frame over `n` frames, in milliseconds, as the student's loop draws them
// (not read back for the test). Printed, not checked: llvmpipe's budget is 16 ms, and a
// machine busy with other work would fail any fixed bound.
double frame_ms(Driver& d, int n = 30) {
    d.viewer().keep_frames(false);
    const auto t0 = std::chrono::steady_clock::now();
    d.frames(n);
    const std::chrono::duration<double, std::milli> t = std::chrono::steady_clock::now() - t0;
    d.viewer().keep_frames(true);
    d.frames(1);  // the frame on screen is read back again
    return t.count() / n;
}

}  // namespace

TEST_CASE("gui modes: the mode switch, by click and by the M key", "[modes][gui-events]") {
    Driver d;
    choose(d, "liang-barsky");
    REQUIRE(d.session().study.mode == Mode::Watch);
    WARN("frame time, Watch (for comparison): " << frame_ms(d) << " ms");
    d.click("mode:Predict");
    CHECK(d.session().study.mode == Mode::Predict);
    d.click("mode:Find the bug");
    CHECK(d.session().study.mode == Mode::Bug);
    CHECK(d.drawn("Bug answer"));
    d.click("mode:Watch");
    CHECK(d.session().study.mode == Mode::Watch);
    CHECK_FALSE(d.drawn("Bug answer"));
    d.key(SDLK_m);
    CHECK(d.session().study.mode == Mode::Predict);
    d.key(SDLK_m);
    CHECK(d.session().study.mode == Mode::Bug);
    d.key(SDLK_m);
    CHECK(d.session().study.mode == Mode::Watch);
}

TEST_CASE("gui modes: Predict — choose the event, type the numbers, reveal",
          "[modes][gui-events]") {
    Driver d;
    const cg::Algorithm& a = algorithm("liang-barsky");
    choose(d, "liang-barsky");
    const cg::study::Trace t = cg::study::record(a, d.session().input);
    REQUIRE(t.steps.size() >= 3);
    d.click("mode:Predict");
    REQUIRE(d.session().study.mode == Mode::Predict);

    // Forward is locked until the step is predicted, by key and by button.
    d.key(SDLK_RIGHT);
    CHECK(d.session().index() == 0);
    d.click("Step");
    CHECK(d.session().index() == 0);

    // Step 1, predicted right: its event clicked, its numbers typed, Reveal clicked.
    const cg::StepInfo& first = t.steps[0];
    d.click("predict event:" + first.event);
    REQUIRE(d.session().study.predict.event == first.event);
    for (const std::string& name : cg::study::predictable_vars(*a.spec, first.event)) {
        const cg::Var* v = cg::study::find_var(first, name);
        REQUIRE(v);
        d.click("predict var:" + name);
        d.type(cg::to_text(v->value));
    }
    shot(d, "predict-typed");
    d.click("Reveal");
    const cg::viewer::PredictState& p = d.session().study.predict;
    CHECK(d.session().index() == 1);
    REQUIRE(p.grades.size() == 1);
    CHECK(p.grades[0].correct);
    CHECK(p.right == 1);
    CHECK(d.drawn("predict verdict"));

    // Step 2, predicted wrong: another event chosen with its number key, Enter reveals.
    const cg::Spec& spec = *a.spec;
    std::size_t wrong = 0;
    while (spec.events[wrong].id == t.steps[1].event) ++wrong;
    REQUIRE(wrong < 9);
    d.key(static_cast<SDL_Keycode>(SDLK_1 + wrong));
    CHECK(p.event == spec.events[wrong].id);
    d.key(SDLK_RETURN);
    CHECK(d.session().index() == 2);
    REQUIRE(p.grades.size() == 2);
    CHECK_FALSE(p.grades[1].correct);
    CHECK(p.grades[1].expected_event == t.steps[1].event);
    CHECK(p.right == 1);
    shot(d, "predict-wrong");

    // Back is free, and forward again up to what has been revealed.
    d.key(SDLK_LEFT);
    CHECK(d.session().index() == 1);
    d.key(SDLK_RIGHT);
    CHECK(d.session().index() == 2);
    d.key(SDLK_RIGHT);
    CHECK(d.session().index() == 2);

    // To the end (the true event each time), then the wrongly predicted step is a click away.
    while (d.session().can_predict()) {
        d.session().choose_prediction(t.steps[p.reached].event);
        d.session().study.predict.typed.clear();
        REQUIRE(d.session().reveal_prediction());
    }
    d.frames(3);
    CHECK(p.reached == t.steps.size());
    CHECK(d.drawn("predict summary"));
    shot(d, "predict-summary");
    WARN("frame time, Predict: " << frame_ms(d) << " ms");
    d.click("wrong step 2");
    CHECK(d.session().index() == 2);
}

TEST_CASE("gui modes: Find the bug — the shown working is the tampered one, then name the step",
          "[modes][gui-events]") {
    Driver d;
    const cg::Algorithm& a = algorithm("liang-barsky");
    choose(d, "liang-barsky");
    const cg::study::PlantedBug bug =
        cg::study::plant_bug(*a.spec, cg::study::record(a, d.session().input), 1);
    d.click("mode:Find the bug");
    REQUIRE(d.session().study.mode == Mode::Bug);
    REQUIRE(d.session().study.bug.bug);
    CHECK(d.session().study.bug.bug->step == bug.step);
    CHECK(d.session().index() == 0);

    // A wrong answer first (step 1, or the step after the bug), by the B key.
    const std::size_t other = bug.step > 1 ? 1 : 2;
    for (std::size_t i = 0; i < other; ++i) d.key(SDLK_RIGHT);
    REQUIRE(d.session().index() == other);
    d.key(SDLK_b);
    REQUIRE(d.session().study.bug.grade);
    CHECK_FALSE(d.session().study.bug.grade->correct);
    CHECK(d.drawn("bug verdict wrong"));
    CHECK(d.drawn("Bug answer"));  // not over: try again

    // To the planted step: the panels show its tampered working, not the real step.
    while (d.session().index() < bug.step) d.key(SDLK_RIGHT);
    while (d.session().index() > bug.step) d.key(SDLK_LEFT);
    const cg::StepInfo* shown = d.session().shown_step();
    REQUIRE(shown);
    CHECK(shown->event == bug.steps[bug.step - 1].event);
    CHECK(shown->narration.empty());
    CHECK(shown->vars == bug.steps[bug.step - 1].vars);
    CHECK(d.session().log().steps.back().narration.empty());
    shot(d, "bug-at-step");

    d.click("Bug answer");
    REQUIRE(d.session().study.bug.grade);
    CHECK(d.session().study.bug.grade->correct);
    CHECK(d.session().study.bug.over);
    CHECK(d.drawn("bug verdict right"));
    CHECK_FALSE(d.drawn("Bug answer"));  // the explanation stays until the mode is left
    shot(d, "bug-right");
    WARN("frame time, Find the bug: " << frame_ms(d) << " ms");

    d.click("mode:Watch");
    CHECK(d.session().study.mode == Mode::Watch);
    REQUIRE(d.session().last_step());
    CHECK_FALSE(d.session().shown_step()->narration.empty());  // the real step again
}

TEST_CASE("gui modes: Compare — a variant side by side, stepped together", "[modes][gui-events]") {
    Driver d;
    choose(d, "phong-lighting");
    // Side B: the other variant (Phong for Blinn-Phong, or back), picked from the list.
    const std::vector<cg::viewer::CompareOption> options = d.session().compare_options();
    REQUIRE_FALSE(options.empty());
    REQUIRE(options.front().kind == cg::viewer::CompareOption::Kind::Variant);
    d.click("compare with");
    d.click("compare option:" + options.front().label);
    d.click("Compare");
    REQUIRE(d.session().comparing());
    const cg::viewer::CompareState& c = d.session().study.compare;
    REQUIRE(c.result);
    d.frames(3);
    // Two canvases, each with its scene drawn.
    CHECK(coloured_pixels(d, d.widget("compare canvas A")) > 50);
    CHECK(coloured_pixels(d, d.widget("compare canvas B")) > 50);
    CHECK(d.widget("compare canvas A").max.x <= d.widget("compare canvas B").min.x + 1);
    shot(d, "compare-variant");

    // Stepping moves both.
    d.key(SDLK_RIGHT);
    CHECK(d.session().index() == 1);
    CHECK(c.b->index() == 1);
    // Phong and Blinn-Phong part at the specular step: marked, and a click away.
    CHECK_FALSE(c.result->agree);
    REQUIRE(c.result->first_step);
    CHECK(d.drawn("first difference"));
    CHECK(d.drawn("compare verdict"));
    d.click("Go to first difference");
    CHECK(d.session().index() == *c.result->first_step);
    CHECK(c.b->index() == std::min(*c.result->first_step, c.result->steps_b));
    CHECK(c.b->last_step()->event != d.session().last_step()->event);
    shot(d, "compare-first-difference");
    WARN("frame time, phong-lighting side by side: " << frame_ms(d) << " ms");

    // Closing returns to one canvas.
    d.click("Compare");
    CHECK_FALSE(d.session().comparing());
    CHECK_FALSE(d.drawn("compare canvas B"));
}

TEST_CASE("gui modes: Compare — another algorithm on the same input, by the C key",
          "[modes][gui-events]") {
    Driver d;
    choose(d, "z-buffer");
    REQUIRE_FALSE(d.session().compare_options().empty());
    CHECK(d.session().compare_options().front().kind == cg::viewer::CompareOption::Kind::Algorithm);
    d.key(SDLK_c);
    REQUIRE(d.session().comparing());
    d.key(SDLK_END);
    d.frames(3);
    CHECK(coloured_pixels(d, d.widget("compare canvas A")) > 50);
    CHECK(coloured_pixels(d, d.widget("compare canvas B")) > 50);
    CHECK(d.drawn("compare verdict"));
    CHECK(d.drawn("compare costs"));
    shot(d, "compare-algorithms");
    WARN("frame time, z-buffer beside painters: " << frame_ms(d) << " ms");
    d.key(SDLK_c);
    CHECK_FALSE(d.session().comparing());
}

TEST_CASE("gui modes: Compare — an edited copy of this input", "[modes][gui-events]") {
    Driver d;
    choose(d, "liang-barsky");
    const std::vector<cg::viewer::CompareOption> options = d.session().compare_options();
    REQUIRE(options.back().kind == cg::viewer::CompareOption::Kind::Edited);
    d.session().study.compare.choice = static_cast<int>(options.size()) - 1;
    d.click("Compare");
    REQUIRE(d.session().comparing());
    CHECK(d.session().study.compare.result->agree);  // a copy, as yet unedited
    d.click("Edit B");
    REQUIRE(d.drawn("side B input"));
    // An edit: the first endpoint's x moved (the text is A's input, pretty-printed).
    cg::json edited = d.session().input;
    edited["p0"][0] = edited["p0"][0].get<double>() - 1.5;
    d.session().study.compare.edited_text = edited.dump(2);
    d.click("Apply B");
    REQUIRE(d.session().comparing());
    CHECK(d.session().study.compare.b->input == edited);
    CHECK_FALSE(d.session().study.compare.result->agree);
    shot(d, "compare-edited");
}
