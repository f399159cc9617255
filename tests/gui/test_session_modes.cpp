// The viewer's study modes as rules of the session (no window): Predict locks forward stepping
// until a step is predicted, Find the bug shows the planted working, Compare keeps a second
// run on the same step, and every mode lets go when the run under it changes.
#include <catch2/catch.hpp>

#include "study/bug.hpp"
#include "viewer/session.hpp"

using cg::viewer::Mode;

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

const cg::Algorithm& algorithm(const std::string& id) {
    const cg::Algorithm* a = registry().find(id);
    REQUIRE(a);
    return *a;
}

}  // namespace

TEST_CASE("session modes: Predict locks forward until the step is revealed", "[gui][modes]") {
    cg::viewer::Session s(registry());
    s.choose(algorithm("liang-barsky"));
    s.jump(3);
    REQUIRE(s.set_mode(Mode::Predict));
    CHECK(s.index() == 0);  // predicted from the first step
    const cg::study::Trace& t = *s.study.trace;
    s.step_forward();
    s.run_to_end();
    s.jump(4);
    s.toggle_play();
    s.advance(10.0);
    CHECK(s.index() == 0);
    CHECK_FALSE(s.reveal_prediction());  // no event chosen
    s.choose_prediction(t.steps[0].event);
    REQUIRE(s.reveal_prediction());
    CHECK(s.index() == 1);
    CHECK(s.study.predict.right == 1);
    s.choose_prediction(t.steps[1].event);
    const bool asks_numbers = !s.predict_vars().empty();
    for (std::string& typed : s.study.predict.typed) typed = "12345";  // wrong numbers
    REQUIRE(s.reveal_prediction());
    CHECK(s.index() == 2);
    CHECK(s.study.predict.grades.size() == 2);
    CHECK(s.study.predict.right == (asks_numbers ? 1u : 2u));
    // Back is free, and forward again as far as has been revealed.
    s.reset();
    CHECK(s.index() == 0);
    s.run_to_end();
    CHECK(s.index() == 2);
    s.step_forward();
    CHECK(s.index() == 2);
    // Words where a number is asked: graded wrong (some numbers are names: the edge "left").
    s.choose_prediction(t.steps[2].event);
    if (!s.study.predict.typed.empty()) {
        s.study.predict.typed[0] = "not a number";
        REQUIRE(s.reveal_prediction());
        CHECK_FALSE(s.study.predict.grades.back().correct);
        CHECK(s.index() == 3);
    }
}

TEST_CASE("session modes: Find the bug shows the planted working, and grades the answer",
          "[gui][modes]") {
    cg::viewer::Session s(registry());
    const cg::Algorithm& a = algorithm("change-of-basis");
    s.choose(a);
    const cg::study::PlantedBug bug =
        cg::study::plant_bug(*a.spec, cg::study::record(a, s.input), 1);
    REQUIRE(s.set_mode(Mode::Bug));
    REQUIRE(s.study.bug.bug);
    CHECK(s.study.bug.bug->step == bug.step);
    s.jump(bug.step);
    REQUIRE(s.shown_step());
    CHECK(s.shown_step()->vars == bug.steps[bug.step - 1].vars);
    CHECK(s.log().steps.back().vars == bug.steps[bug.step - 1].vars);
    // The canvas's run is the real one.
    CHECK((s.last_step()->vars != bug.steps[bug.step - 1].vars ||
           s.last_step()->event != bug.steps[bug.step - 1].event));
    s.answer_bug(bug.step == 1 ? 2 : 1);
    REQUIRE(s.study.bug.grade);
    CHECK_FALSE(s.study.bug.grade->correct);
    CHECK_FALSE(s.study.bug.over);
    s.answer_bug(bug.step);
    CHECK(s.study.bug.grade->correct);
    CHECK(s.study.bug.over);
    // A new seed plants another bug from step 0; leaving shows the real steps again.
    s.study.bug.seed = 2;
    REQUIRE(s.plant_bug());
    CHECK(s.index() == 0);
    CHECK_FALSE(s.study.bug.over);
    s.set_mode(Mode::Watch);
    s.jump(bug.step);
    CHECK(s.shown_step()->vars == s.last_step()->vars);
}

TEST_CASE("session modes: Compare steps side B with A, and closes with another algorithm",
          "[gui][modes]") {
    cg::viewer::Session s(registry());
    s.choose(algorithm("z-buffer"));
    const std::vector<cg::viewer::CompareOption> options = s.compare_options();
    REQUIRE(options.size() >= 3);  // painters, warnock, an edited copy
    CHECK(options.back().kind == cg::viewer::CompareOption::Kind::Edited);
    REQUIRE(s.open_compare(0));
    REQUIRE(s.comparing());
    REQUIRE(s.study.compare.result);
    CHECK(s.study.compare.result->agree);  // z-buffer and painters see the same polygons
    s.step_forward();
    s.sync_study();
    CHECK(s.study.compare.b->index() == 1);
    s.run_to_end();
    s.sync_study();
    CHECK(s.study.compare.b->index() == std::min(s.index(), s.study.compare.result->steps_b));
    // The same result object while nothing changes: computed once per pair of runs.
    const cg::study::Comparison* before = &*s.study.compare.result;
    s.sync_study();
    CHECK(&*s.study.compare.result == before);
    // A mode closes Compare; so does another algorithm.
    s.set_mode(Mode::Predict);
    CHECK_FALSE(s.comparing());
    s.set_mode(Mode::Watch);
    REQUIRE(s.open_compare(0));
    s.choose(algorithm("liang-barsky"));
    s.sync_study();
    CHECK_FALSE(s.comparing());
    // Variants: the option list leaves out the one the input already is.
    s.choose(algorithm("phong-lighting"));
    const cg::Variant* own = s.input_variant();
    for (const cg::viewer::CompareOption& o : s.compare_options())
        if (o.kind == cg::viewer::CompareOption::Kind::Variant) CHECK(o.variant != own);
}

TEST_CASE("session modes: a mode follows the run it studies", "[gui][modes]") {
    cg::viewer::Session s(registry());
    s.choose(algorithm("liang-barsky"));
    REQUIRE(s.set_mode(Mode::Predict));
    s.choose_prediction(s.study.trace->steps[0].event);
    REQUIRE(s.reveal_prediction());
    // An edit restarts the run: Predict starts again on it.
    cg::json edited = s.input;
    edited["p1"][0] = 3;
    REQUIRE(s.edit(edited));
    s.sync_study();
    CHECK(s.study.mode == Mode::Predict);
    CHECK(s.study.predict.grades.empty());
    CHECK(s.index() == 0);
    // An exam: back to Watch (its solution is hidden).
    REQUIRE(s.try_start_exam(algorithm("liang-barsky"), 1));
    s.sync_study();
    CHECK(s.study.mode == Mode::Watch);
    CHECK_FALSE(s.set_mode(Mode::Bug));
    CHECK(s.study.mode == Mode::Watch);
}

TEST_CASE("session modes: every registered algorithm can be predicted, bugged and compared",
          "[gui][modes]") {
    cg::viewer::Session s(registry());
    for (const cg::Algorithm& a : registry().all()) {
        INFO(a.spec->id);
        s.choose(a);
        REQUIRE(s.input_error.empty());
        CHECK(s.set_mode(Mode::Predict));
        CHECK(s.set_mode(Mode::Bug));
        CHECK(s.set_mode(Mode::Watch));
        const std::vector<cg::viewer::CompareOption> options = s.compare_options();
        for (int i = 0; i < static_cast<int>(options.size()); ++i) {
            INFO("side B: " << options[i].label << " (" << s.study.compare.error << ")");
            CHECK(s.open_compare(i));
            CHECK(s.comparing());
            s.close_compare();
        }
    }
}
