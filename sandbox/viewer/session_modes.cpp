// The study modes on top of a run (see session.hpp): Predict, Find the bug and Compare.
// Everything here goes through algorithms/study: the viewer adds no algorithm-specific code.
#include <algorithm>

#include "viewer/session.hpp"

namespace cg::viewer {

json read_answer(std::string text);  // session_study.cpp: "(1, 2)" read as [1, 2]

// --- the run's trace -------------------------------------------------------------------------

const study::Trace* Session::trace() {
    if (!algorithm || !timeline || !input_error.empty()) return nullptr;
    if (study.trace_run != run_id) {  // once per run, refused or not
        study.trace.reset();
        study.trace_run = run_id;
        try {
            study.trace = std::make_shared<const study::Trace>(study::record(*algorithm, input));
        } catch (const std::exception& e) {  // InputError: too long to keep, say
            set_status(algorithm->spec->id + ": " + e.what(), true);
        }
    }
    return study.trace.get();
}

// --- modes -----------------------------------------------------------------------------------

bool Session::set_mode(Mode m) {
    const Mode before = study.mode;
    study.mode = Mode::Watch;
    study.predict = PredictState{};
    const std::uint64_t seed = study.bug.seed;
    study.bug = BugState{};
    study.bug.seed = seed;
    ++study.generation;
    if (m == Mode::Watch) return true;
    if (solution_hidden()) {
        set_status("An exam's solution is hidden: leave exam practice (or reveal it) first.", true);
        return false;
    }
    if (comparing()) close_compare();
    if (!trace()) {
        if (input_error.empty() && timeline) return false;  // the status line says why
        set_status("No run to study: the input was refused.", true);
        return false;
    }
    playing = false;
    study.mode = m;
    if (m == Mode::Predict) {
        timeline->reset();  // every step predicted, from the first
        study.predict.reached = 0;
        if (before != Mode::Predict)
            set_status(
                "Predict: choose the next step's event (keys 1–9), type its numbers, "
                "then Reveal (Enter).",
                false);
        return true;
    }
    if (!plant_bug()) {
        study.mode = Mode::Watch;
        return false;
    }
    return true;
}

void Session::cycle_mode() {
    switch (study.mode) {
        case Mode::Watch:
            set_mode(Mode::Predict);
            break;
        case Mode::Predict:
            set_mode(Mode::Bug);
            break;
        case Mode::Bug:
            set_mode(Mode::Watch);
            break;
    }
}

void Session::sync_study() {
    if (study.mode != Mode::Watch && (exam.active || study.trace_run != run_id)) {
        // The run changed under the mode (an edit, another algorithm, an exam): start it
        // again on the new run, or leave it when it cannot be studied.
        if (exam.active || !set_mode(study.mode)) set_mode(Mode::Watch);
    }
    CompareState& c = study.compare;
    if (!c.open) return;
    if (exam.active || !timeline || c.side_a.algorithm != algorithm) {
        close_compare();  // an exam, a refused input or another algorithm: one canvas again
        return;
    }
    if (c.run_a != run_id) {  // A restarted: B follows (an edited copy keeps its own input)
        if (!open_compare(c.choice)) return;
    }
    if (comparing() && c.synced != index()) {
        c.b->timeline->jump(index());  // clamps at B's end
        c.synced = index();
    }
}

const StepInfo* Session::shown_step(std::size_t k) {
    if (k == 0 || !timeline) return nullptr;
    if (study.mode == Mode::Bug && study.bug.bug && k <= study.bug.bug->steps.size())
        return &study.bug.bug->steps[k - 1];
    if (k == index()) return last_step();
    const NarrationLog& l = log();
    if (k >= l.first && k < l.first + l.steps.size()) return &l.steps[k - l.first];
    return nullptr;
}

// --- predict ---------------------------------------------------------------------------------

const std::vector<std::string>& Session::predict_vars() const {
    static const std::vector<std::string> none;
    if (!algorithm || study.predict.event.empty()) return none;
    return study::predictable_vars(*algorithm->spec, study.predict.event);
}

void Session::choose_prediction(const std::string& event) {
    PredictState& p = study.predict;
    if (p.event == event) return;
    p.event = event;
    p.typed.assign(predict_vars().size(), "");
}

bool Session::can_predict() const {
    return study.mode == Mode::Predict && study.trace && timeline &&
           index() == study.predict.reached && study.predict.reached < study.trace->steps.size();
}

bool Session::forward_locked(std::size_t to) const {
    return study.mode == Mode::Predict && to > study.predict.reached;
}

bool Session::reveal_prediction() {
    if (!can_predict()) return false;
    PredictState& p = study.predict;
    if (p.event.empty()) {
        set_status("Choose the event you expect first (keys 1–9, or click one).", true);
        return false;
    }
    study::Prediction prediction;
    prediction.step = p.reached + 1;
    prediction.event = p.event;
    const std::vector<std::string>& names = predict_vars();
    for (std::size_t i = 0; i < names.size() && i < p.typed.size(); ++i) {
        if (p.typed[i].find_first_not_of(" \t") == std::string::npos) continue;  // not given
        try {
            prediction.variables[names[i]] = read_answer(p.typed[i]);
        } catch (const std::exception&) {
            set_status("\"" + p.typed[i] + "\" is not a number for " + names[i] +
                           " (decimals like 0.25, a point as (x, y))",
                       true);
            return false;
        }
    }
    const StepInfo& truth = study.trace->steps[p.reached];
    study::PredictGrade g = study::grade_prediction(*algorithm->spec, truth, prediction);
    g.step = prediction.step;
    if (g.correct) ++p.right;
    p.grades.push_back(std::move(g));
    ++p.reached;
    timeline->forward();
    // The next prediction starts afresh: no event chosen, no numbers.
    p.event.clear();
    p.typed.clear();
    set_status("", false);
    return true;
}

// --- find the bug ----------------------------------------------------------------------------

bool Session::plant_bug() {
    const study::Trace* t = trace();
    if (!t) return false;
    BugState& b = study.bug;
    try {
        b.bug = study::plant_bug(*algorithm->spec, *t, b.seed);
    } catch (const std::exception& e) {
        b.bug.reset();
        set_status(algorithm->spec->id + ": no bug to plant: " + e.what(), true);
        return false;
    }
    b.grade.reset();
    b.answered_step = 0;
    b.over = false;
    ++study.generation;
    timeline->reset();  // the working is read from the start
    set_status("Find the bug: step through and press B (or the button) at the first wrong step.",
               false);
    return true;
}

void Session::answer_bug(std::size_t step) {
    BugState& b = study.bug;
    if (study.mode != Mode::Bug || !b.bug || b.over) return;
    if (step == 0) {
        set_status("Step 0 has no working: step on to the step you think is wrong.", true);
        return;
    }
    b.grade = study::grade_bug_answer(*algorithm->spec, *b.bug, step);
    b.answered_step = step;
    b.over = b.grade->correct;
    set_status(b.over ? "Found it. New bug for another, or Watch to leave." : "Look again.", false);
}

void Session::give_up_bug() {
    BugState& b = study.bug;
    if (study.mode != Mode::Bug || !b.bug || b.over) return;
    b.grade = study::grade_bug_answer(*algorithm->spec, *b.bug, b.bug->step);
    b.grade->correct = false;
    b.answered_step = 0;
    b.over = true;
    set_status("", false);
    jump(b.bug->step);
}

// --- compare ---------------------------------------------------------------------------------

const Variant* Session::input_variant() const {
    if (!algorithm) return nullptr;
    for (const Variant& v : algorithm->spec->study.variants) {
        const json::json_pointer at(v.field);
        try {
            if (input.contains(at) && input.at(at) == json::parse(v.value)) return &v;
        } catch (const std::exception&) {  // a malformed declaration: no variant
        }
    }
    return nullptr;
}

std::vector<CompareOption> Session::compare_options() const {
    std::vector<CompareOption> out;
    if (!algorithm) return out;
    const Spec& spec = *algorithm->spec;
    // The variants this input is not already in (Blinn-Phong's input compares with Phong).
    const Variant* current = input_variant();
    for (const Variant& v : spec.study.variants)
        if (&v != current)
            out.push_back({CompareOption::Kind::Variant, spec.id + "@" + v.name, algorithm, &v});
    if (!spec.study.input_kind.empty())
        for (const Algorithm& a : registry.all())
            if (&a != algorithm && a.spec->study.input_kind == spec.study.input_kind)
                out.push_back({CompareOption::Kind::Algorithm, a.spec->id, &a, nullptr});
    out.push_back(
        {CompareOption::Kind::Edited, "an edited copy of this input", algorithm, nullptr});
    return out;
}

bool Session::open_compare(int choice) {
    CompareState& c = study.compare;
    const std::vector<CompareOption> options = compare_options();
    auto fail = [&](std::string why) {
        c.error = std::move(why);
        set_status("Compare: " + c.error, true);
        if (c.open && c.editing && c.b) return false;  // a bad edit: the last pair stays
        close_compare();
        return false;
    };
    if (choice < 0 || choice >= static_cast<int>(options.size()))
        return fail("nothing to compare with");
    if (solution_hidden()) return fail("an exam's solution is hidden");
    if (study.mode != Mode::Watch) set_mode(Mode::Watch);
    const study::Trace* ta = trace();
    if (!ta) return fail("this run cannot be recorded");
    const CompareOption& o = options[choice];
    const bool same_choice = c.choice == choice && c.b;
    c.choice = choice;
    const Variant* va = o.kind == CompareOption::Kind::Variant ? input_variant() : nullptr;
    c.side_a = study::Side{algorithm, va, algorithm->spec->id + (va ? "@" + va->name : "")};
    c.side_b = study::Side{o.algorithm, o.variant, o.label};
    json input_b = study::side_input(c.side_b, input);
    if (o.kind == CompareOption::Kind::Edited) {
        c.side_b.label = algorithm->spec->id + " (edited)";
        if (c.edited_text.empty() || !same_choice) c.edited_text = input.dump(2);
        try {
            input_b = json::parse(c.edited_text);
        } catch (const std::exception& e) {
            return fail(std::string("side B's input is not JSON: ") + e.what());
        }
    }
    auto b = std::make_shared<Session>(registry);
    b->fonts = fonts;
    b->textures = compare_textures;
    b->probe_seconds = probe_seconds;
    study::Trace tb;
    try {
        study::check_comparable(c.side_a, c.side_b);
        b->start(*o.algorithm, input_b, index());
        tb = study::record(*o.algorithm, input_b);
        c.result = study::compare(c.side_a, *ta, c.side_b, tb);
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    b->canvas.fit_pending = true;
    c.b = std::move(b);
    if (!c.open) canvas.fit_pending = true;  // half the width now
    c.open = true;
    c.error.clear();
    c.run_a = run_id;
    c.run_b = c.b->run_id;
    c.synced = index();
    playing = false;
    return true;
}

void Session::close_compare() {
    CompareState& c = study.compare;
    if (c.open) canvas.fit_pending = true;  // the whole width again
    c.open = false;
    c.editing = false;
    c.b.reset();
    c.result.reset();
    c.run_a = c.run_b = std::numeric_limits<std::uint64_t>::max();
}

}  // namespace cg::viewer
