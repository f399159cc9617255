// The viewer's session while studying: lessons, presets, exam practice, checkpoints. No window:
// these are the rules the panels rely on.
#include <catch2/catch.hpp>

#include <algorithm>

#include "checkpoint.hpp"
#include "io/lesson.hpp"
#include "viewer/session.hpp"

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

cg::viewer::Session session() {
    cg::viewer::Session s(registry());
    s.lessons = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    return s;
}

}  // namespace

TEST_CASE("session: opening a lesson loads its first preset at step 0", "[gui][session]") {
    cg::viewer::Session s = session();
    const cg::Lesson* lesson = s.lessons.find("liang-barsky");
    REQUIRE(lesson);
    s.open_lesson(*lesson);
    CHECK(s.lesson() == lesson);
    CHECK(s.tab == cg::viewer::Tab::Lessons);
    REQUIRE(s.loaded_preset() == &lesson->presets.front());
    CHECK(s.index() == 0);
    s.jump(3);
    s.load_preset(lesson->presets[2]);  // a preset restarts at step 0
    CHECK(s.loaded_preset() == &lesson->presets[2]);
    CHECK(s.index() == 0);
    // The lesson is shown only beside its own algorithm.
    s.choose(*registry().find("sutherland-hodgman"));
    CHECK(s.lesson() == nullptr);
}

TEST_CASE("session: a lesson preset the algorithm refuses opens with its error, naming the file",
          "[gui][session][errors]") {
    // The viewer loads lessons with PresetCheck::WhenLoaded: a preset is checked as it loads.
    cg::json j = cg::parse_json(R"({"id": "broken", "title": "Broken", "topic": "clipping",
        "order": 1, "algorithm": "liang-barsky", "exam": {"weight": "low"},
        "presets": [{"name": "a bad one", "input": {"window": {"xmin": 0, "ymin": 0, "xmax": 4, "ymax": 4},
                                           "p0": [0, "two"], "p1": [5, 5]}}],
        "sections": [{"title": "Idea", "text": "Clip."}]})");
    cg::Lesson lesson = cg::parse_lesson(j, registry(), cg::PresetCheck::WhenLoaded);
    lesson.file = "lessons/broken.json";
    CHECK_THROWS_WITH(cg::parse_lesson(j, registry()), Catch::Contains("presets[0].input"));
    cg::viewer::Session s(registry());
    s.lessons.lessons.push_back(lesson);
    s.open_lesson(s.lessons.lessons.front());
    CHECK(s.status_is_error);
    CHECK_THAT(s.status, Catch::Contains("lessons/broken.json: the preset \"a bad one\" is refused: "));
    CHECK_THAT(s.input_error, Catch::Contains("p0[1]: must be a number"));
    CHECK(s.input == j["presets"][0]["input"]);  // in the editor, to be mended
    CHECK(s.loaded_preset() == nullptr);
}

TEST_CASE("session: an exam's solution stays hidden until revealed", "[gui][session][exam]") {
    cg::viewer::Session s = session();
    const cg::Algorithm& a = *registry().find("liang-barsky");
    s.start_exam(a, 7);
    REQUIRE(s.exam.active);
    CHECK(s.input == cg::make_exam(a, 7).input);
    CHECK(s.solution_hidden());
    s.step_forward();
    s.run_to_end();
    s.jump(3);
    s.toggle_play();
    CHECK(s.index() == 0);
    CHECK_FALSE(s.playing);
    CHECK_FALSE(s.edit(s.input));  // the problem's input is fixed

    SECTION("Check grades each field; an empty box is no answer") {
        const cg::ExamProblem& p = s.exam.problem;
        for (std::size_t i = 0; i < p.answers.size(); ++i)
            s.exam.typed[i] = p.expected.at(p.answers[i]).dump();
        s.exam.typed[0].clear();
        s.check_exam();
        REQUIRE(s.exam.grades.size() == p.answers.size());
        CHECK_FALSE(s.exam.grades[0].correct);
        CHECK_THAT(s.exam.grades[0].why, Catch::Contains("no answer"));
        for (std::size_t i = 1; i < p.answers.size(); ++i) CHECK(s.exam.grades[i].correct);
    }
    SECTION("points and lists of points may be typed with parentheses") {
        const cg::Algorithm& sh = *registry().find("sutherland-hodgman");
        s.start_exam(sh, 1);
        const cg::ExamProblem& p = s.exam.problem;
        for (std::size_t i = 0; i < p.answers.size(); ++i) {
            std::string typed = p.expected.at(p.answers[i]).dump();
            std::replace(typed.begin(), typed.end(), '[', '(');
            std::replace(typed.begin(), typed.end(), ']', ')');
            s.exam.typed[i] = "[" + typed.substr(1, typed.size() - 2) + "]";
        }
        s.check_exam();
        for (const cg::FieldGrade& g : s.exam.grades) {
            CAPTURE(g.field, g.why);
            CHECK(g.correct);
        }
    }
    SECTION("revealing steps through the solution") {
        s.reveal_next_step();
        CHECK(s.index() == 1);
        s.step_forward();
        CHECK(s.index() == 2);
        s.run_to_end();
        CHECK(s.at_end());
    }
    SECTION("leaving frees the input; a new algorithm leaves too") {
        s.leave_exam();
        CHECK(s.edit(s.input));
        s.start_exam(a, 8);
        s.choose(*registry().find("sutherland-hodgman"));
        CHECK_FALSE(s.exam.active);
    }
}

TEST_CASE("checkpoint: the open lesson, its preset and the exam survive saving and opening",
          "[gui][session][checkpoint]") {
    cg::viewer::Session s = session();
    const cg::Lesson* lesson = s.lessons.find("liang-barsky");
    REQUIRE(lesson);
    s.open_lesson(*lesson);
    s.load_preset(lesson->presets[1]);
    s.jump(2);
    const cg::json saved = cg::checkpoint_to_json(s.checkpoint());
    CHECK(saved["lesson"] == "liang-barsky");
    CHECK(saved["preset"] == lesson->presets[1].name);

    cg::viewer::Session t = session();
    t.load(cg::checkpoint_from_json(saved, registry()));
    CHECK(t.lesson() == t.lessons.find("liang-barsky"));
    REQUIRE(t.loaded_preset());
    CHECK(t.loaded_preset()->name == lesson->presets[1].name);
    CHECK(t.index() == 2);

    s.start_exam(*registry().find("liang-barsky"), 12);
    const cg::json exam = cg::checkpoint_to_json(s.checkpoint());
    CHECK(exam["exam_seed"] == 12);
    t.load(cg::checkpoint_from_json(exam, registry()));
    CHECK(t.exam.active);
    CHECK(t.solution_hidden());
    CHECK(t.exam.problem.question == s.exam.problem.question);

    cg::json wrong = saved;
    wrong["exam_seed"] = "seven";
    CHECK_THROWS_WITH(cg::checkpoint_from_json(wrong, registry()), Catch::Contains("exam_seed"));
}

TEST_CASE("session: an animation plays at real time or at the speed slider's pace",
          "[gui][session][animation]") {
    int animations = 0;
    for (const cg::Algorithm& a : registry().all()) {
        if (a.spec->clock.empty()) continue;
        ++animations;
        CAPTURE(a.spec->id);
        cg::viewer::Session s = session();
        s.choose(a);
        REQUIRE(s.clock_now() == 0.0);
        // One time step: the first step that moves the clock.
        double dt = 0;
        while (dt == 0 && !s.at_end()) {
            s.step_forward();
            dt = s.clock_now().value_or(0);
        }
        REQUIRE(dt > 0);
        // Wall-clock frames of 20 ms: Play takes every step whose time has come (the first at
        // once), no more.
        for (float scale : {1.0f, 0.25f, 2.0f}) {
            CAPTURE(scale);
            s.reset();
            s.time_scale = scale;
            s.toggle_play();
            REQUIRE(s.playing);
            double wall = 0;
            for (int frame = 0; frame < 10 && s.playing; ++frame) {
                s.advance(0.02);
                wall += 0.02;
            }
            // The frame shown is the one whose interval holds the time played: P ≤ t < P + dt.
            const double t = s.clock_now().value(), played = wall * scale;
            CHECK(t < played + dt - 1e-9);
            if (s.playing) CHECK(t >= played - 1e-9);
        }
        // A stalled frame is not made up in a burst: at most a quarter of a second more.
        s.reset();
        s.time_scale = 1;
        s.toggle_play();
        s.advance(5.0);
        CHECK(s.clock_now().value() < 0.25 + dt - 1e-9);
        // Everything else keeps its steps a second.
        s.choose(*registry().find("liang-barsky"));
        CHECK_FALSE(s.clock_now().has_value());
    }
    CHECK(animations >= 1);
}
