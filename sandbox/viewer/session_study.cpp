// Lessons and exam practice on top of a run (see session.hpp).
#include <algorithm>

#include "viewer/session.hpp"

namespace cg::viewer {

// --- lessons ---------------------------------------------------------------------------------

const Lesson* Session::lesson() const {
    if (lesson_id.empty() || !algorithm) return nullptr;
    const Lesson* l = lessons.find(lesson_id);
    return l && l->algorithm == algorithm->spec->id ? l : nullptr;
}

const LessonPreset* Session::loaded_preset() const {
    const Lesson* l = lesson();
    const LessonPreset* p = l ? l->preset(preset) : nullptr;
    return p && !exam.active && input_error.empty() && p->input == input ? p : nullptr;
}

void Session::open_lesson(const Lesson& l) {
    const Algorithm* a = registry.find(l.algorithm);
    if (!a) return;  // parse_lesson has checked that it exists
    leave_exam();
    lesson_id = l.id;
    browsing = false;
    show_tab(Tab::Lessons);
    // Already running one of its presets (say, reopened from a checkpoint): keep the step.
    const auto running = std::find_if(l.presets.begin(), l.presets.end(), [&](const auto& p) {
        return algorithm == a && input_error.empty() && p.input == input;
    });
    if (running != l.presets.end())
        preset = running->name;
    else if (!l.presets.empty())
        load_preset(l.presets.front());
}

void Session::load_preset(const LessonPreset& p) {
    const Lesson* l = lessons.find(lesson_id);
    const Algorithm* a = l ? registry.find(l->algorithm) : nullptr;
    if (!a) return;
    leave_exam();
    if (try_start(*a, p.input, 0))
        preset = p.name;
    else  // the viewer checks a preset only now (PresetCheck::WhenLoaded): say whose it is
        set_status(l->file + ": the preset \"" + p.name + "\" is refused: " + input_error, true);
    canvas.fit_pending = true;
}

void Session::show_tab(Tab t) {
    tab = t;
    tab_requested = true;
}

// --- exam practice ---------------------------------------------------------------------------

void Session::start_exam(const Algorithm& a, std::uint64_t seed) {
    ExamProblem problem = make_exam(a, seed);  // may throw: nothing has changed yet
    start(a, problem.input, 0);
    exam = ExamState{};
    exam.active = true;
    exam.seed = seed;
    exam.typed.assign(problem.answers.size(), "");
    exam.problem = std::move(problem);
    playing = false;
    canvas.fit_pending = true;
}

bool Session::try_start_exam(const Algorithm& a, std::uint64_t seed) {
    try {
        start_exam(a, seed);
        return true;
    } catch (const std::exception& e) {  // InputError, or a generator's bad input
        set_status(a.spec->id + ": exam problem " + std::to_string(seed) + ": " + e.what(), true);
        return false;
    }
}

// parse_answer reads "(1, 3)" as a point, but a list of points only in JSON's brackets; a
// student writes [(1, 0), (0, 3)], so every parenthesis is read as a bracket (no answer is
// text, so nothing else can be meant by them).
json read_answer(std::string text) {
    std::replace(text.begin(), text.end(), '(', '[');
    std::replace(text.begin(), text.end(), ')', ']');
    return parse_answer(text);
}

void Session::check_exam() {
    if (!exam.active) return;
    json given = json::object();
    for (std::size_t i = 0; i < exam.problem.answers.size() && i < exam.typed.size(); ++i) {
        const std::string& text = exam.typed[i];
        // An empty box is "no answer" (graded wrong), not the answer "none".
        if (text.find_first_not_of(" \t") != std::string::npos)
            given[exam.problem.answers[i]] = read_answer(text);
    }
    exam.grades = grade(exam.problem, given);
}

void Session::reveal_next_step() {
    if (!exam.active) return;
    exam.revealed = true;
    step_forward();
}

void Session::leave_exam() {
    if (!exam.active) return;
    const std::uint64_t seed = exam.seed;
    exam = ExamState{};
    exam.seed = seed;  // the seed field keeps its number for next time
}

}  // namespace cg::viewer
