#include "viewer/session.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <chrono>

#include "viewer/export.hpp"

namespace cg::viewer {

namespace {

// Steps a copy of a fresh run to its end without narration (cheap), so the step counter can
// say "k / n" from the start; gives up on long or slow runs, which then show "k / ?".
std::optional<std::size_t> probe_length(const Run& fresh, double max_seconds) {
    constexpr std::size_t kMaxSteps = 1'000'000;
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(max_seconds));
    std::unique_ptr<Run> run = fresh.clone();
    for (std::size_t n = 0; n <= kMaxSteps; ++n) {
        if (run->done()) return n;
        if (n % 256 == 0 && std::chrono::steady_clock::now() > deadline) break;
        run->step(nullptr);
    }
    return std::nullopt;
}

}  // namespace

// --- starting runs ---------------------------------------------------------------------------

void Session::start(const Algorithm& a, json in, std::size_t step) {
    std::unique_ptr<Run> run = a.create(in);  // may throw: nothing has changed yet
    std::optional<std::size_t> length = probe_length(*run, probe_seconds);
    if (&a != algorithm) {
        breakpoints.clear();
        playing = false;
        canvas.fit_pending = true;
        canvas.dragged_handle = -1;
        followed_line = 0;
        followed_event.clear();
        // A path the student typed stays; the default follows the algorithm.
        if (export_path.empty() || (algorithm && export_path == default_export_path(*algorithm)))
            export_path = default_export_path(a);
    }
    algorithm = &a;
    input = std::move(in);
    input_error.clear();
    timeline = std::make_unique<Timeline>(std::move(run));
    timeline->jump(step);
    probed_length = length;
    ++run_id;
    if (timeline->at_end()) playing = false;
}

bool Session::try_start(const Algorithm& a, json in, std::size_t step) {
    std::string error;
    try {
        start(a, in, step);
        return true;
    } catch (const InputError& e) {
        error = e.what();
    } catch (const std::exception& e) {  // a JSON type error slipping past the reader
        error = e.what();
    }
    if (&a != algorithm) {  // a refused input of another algorithm: nothing to show
        algorithm = &a;
        timeline.reset();
        probed_length.reset();
        breakpoints.clear();
        playing = false;
        canvas.fit_pending = true;
        canvas.dragged_handle = -1;
        ++run_id;
    }
    input = std::move(in);
    input_error = std::move(error);
    return false;
}

void Session::choose(const Algorithm& a) {
    leave_exam();
    try_start(a, a.example(), 0);
    canvas.fit_pending = true;
}

void Session::load(const Checkpoint& c) {
    const Algorithm* a = registry.find(c.algorithm);
    if (!a) {
        set_status("unknown algorithm \"" + c.algorithm + "\"", true);
        return;
    }
    leave_exam();
    if (c.exam_seed) {
        if (try_start_exam(*a, *c.exam_seed) && c.step > 0) {
            exam.revealed = true;  // a later step means the solution was being stepped
            timeline->jump(c.step);
        }
    } else {
        try_start(*a, c.input, c.step);
    }
    lesson_id.clear();
    preset = c.preset;
    browsing = false;
    if (!c.lesson.empty()) {
        if (lessons.find(c.lesson))
            lesson_id = c.lesson;
        else
            set_status("no lesson \"" + c.lesson + "\" (lessons: " + default_lessons_dir() + ")",
                       true);
    }
    if (c.exam_seed)
        show_tab(Tab::Exam);
    else if (!lesson_id.empty())
        show_tab(Tab::Lessons);
    canvas.fit_pending = !c.view;
    if (c.view) canvas.view = *c.view;
}

bool Session::edit(json edited) {
    if (!algorithm) return false;
    if (exam.active) {  // the editor is disabled; this catches a dragged handle
        set_status("The exam problem's input is fixed: leave exam practice to edit it.", true);
        return false;
    }
    return try_start(*algorithm, std::move(edited), index());
}

Checkpoint Session::checkpoint() const {
    Checkpoint c;
    c.algorithm = algorithm ? algorithm->spec->id : "";
    c.input = input;
    c.step = index();
    if (!canvas.fit_pending) c.view = canvas.view;
    if (const Lesson* l = lesson()) c.lesson = l->id;
    if (const LessonPreset* p = loaded_preset()) c.preset = p->name;
    if (exam.active) c.exam_seed = exam.problem.seed;
    return c;
}

// --- where we are ----------------------------------------------------------------------------

std::optional<std::size_t> Session::length() const {
    if (!timeline) return std::nullopt;
    if (timeline->length()) return timeline->length();
    return probed_length;
}

const Scene& Session::scene() const {
    if (scene_run_ != run_id || scene_index_ != index() || !timeline) {
        scene_ = Scene{};
        if (timeline) timeline->current().draw(scene_);
        scene_run_ = timeline ? run_id : std::numeric_limits<std::uint64_t>::max();
        scene_index_ = index();
    }
    return scene_;
}

const NarrationLog& Session::log() {
    if (log_.run == run_id && log_.index == index() && log_generation_ == study.generation)
        return log_;
    log_.run = run_id;
    log_generation_ = study.generation;
    log_.index = index();
    log_.first =
        log_.index > NarrationLog::kMaxEntries ? log_.index - NarrationLog::kMaxEntries + 1 : 1;
    log_.steps.clear();
    log_.wrapped.clear(), log_.heights.clear();
    if (timeline && log_.index > 0) log_.steps = timeline->steps(log_.first, log_.index);
    // Find the bug: the planted working in place of the real one.
    if (study.mode == Mode::Bug && study.bug.bug)
        for (std::size_t i = 0; i < log_.steps.size(); ++i)
            if (const StepInfo* shown = shown_step(log_.first + i)) log_.steps[i] = *shown;
    return log_;
}

// --- moving ----------------------------------------------------------------------------------

bool Session::on_breakpoint() {
    const StepInfo* info = last_step();
    if (!info || !breakpoints.count(info->line)) return false;
    set_status("Paused at the breakpoint on line " + std::to_string(info->line) + ".", false);
    return true;
}

void Session::step_forward() {
    playing = false;
    if (!can_step()) return;
    if (forward_locked(index() + 1) && !timeline->at_end()) {
        set_status("Predict the next step first: choose its event, then Reveal (Enter).", false);
        return;
    }
    timeline->forward();
}

void Session::step_back() {
    playing = false;
    if (can_step()) timeline->back();
}

void Session::reset() {
    playing = false;
    if (can_step()) timeline->reset();
}

void Session::jump(std::size_t step) {
    playing = false;
    if (!can_step()) return;
    if (study.mode == Mode::Predict)
        step = std::min(step, std::max(index(), study.predict.reached));
    timeline->jump(step);
}

void Session::run_to_end() {
    playing = false;
    if (!can_step()) return;
    if (study.mode == Mode::Predict) {  // only as far as has been revealed
        jump(study.predict.reached);
        return;
    }
    if (breakpoints.empty()) {
        timeline->to_end();
        return;
    }
    // One step at a time only to look at each line; still instant, not one step per frame.
    while (timeline->forward())
        if (on_breakpoint()) return;
}

void Session::toggle_play() {
    if (playing || !can_step()) {
        playing = false;
        return;
    }
    if (timeline->at_end()) timeline->reset();
    playing = true;
    play_clock = 1;  // the first step comes at once, so Play visibly responds
    play_time = clock_now().value_or(0);
}

std::optional<double> Session::clock_now() const {
    if (!timeline || !algorithm || algorithm->spec->clock.empty()) return std::nullopt;
    const StepInfo* last = timeline->last_step();
    if (!last) return 0.0;
    for (const Var& v : last->vars) {
        if (v.name != algorithm->spec->clock) continue;
        if (const double* d = std::get_if<double>(&v.value)) return *d;
        if (const long long* i = std::get_if<long long>(&v.value)) return static_cast<double>(*i);
    }
    return std::nullopt;
}

bool Session::play_step() {
    if (forward_locked(index() + 1) || !timeline->forward() || on_breakpoint()) {
        playing = false;
        return false;
    }
    return true;
}

void Session::advance(double seconds) {
    if (!playing || !timeline) return;
    if (std::optional<double> now = clock_now()) {
        // An animation: every step whose simulated time has come, so that it plays at
        // time_scale × real time. Behind by more than a quarter of a second of simulated time
        // (a stalled frame, or steps too small to keep up with), it lets the debt go rather
        // than race: the animation slows down instead of skipping.
        play_time = std::min(play_time + seconds * time_scale, *now + 0.25 * time_scale);
        for (int taken = 0; now && *now < play_time && taken < kMaxPlayStepsPerFrame; ++taken) {
            if (!play_step()) break;
            now = clock_now();
        }
    } else {
        // A stalled frame must not turn into a burst of steps.
        play_clock = std::min(play_clock + seconds * steps_per_second, 3.0);
        while (play_clock >= 1) {
            play_clock -= 1;
            if (!play_step()) break;
        }
    }
    if (timeline->at_end()) playing = false;
}

void Session::set_status(std::string text, bool error) {
    status = std::move(text);
    status_is_error = error;
}

void Session::note_widget(const std::string& name) {
    if (!record_widgets) return;
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    const ImRect clip = ImGui::GetCurrentWindow()->InnerClipRect;  // what of the window shows
    const Box box{{lo.x, lo.y}, {hi.x, hi.y}}, window{{clip.Min.x, clip.Min.y}, {clip.Max.x, clip.Max.y}};
    // In sight: all of its height, and its middle, inside the window's visible part.
    const bool visible = ImGui::IsItemVisible() && window.contains((box.min + box.max) / 2.0) &&
                         box.min.y >= window.min.y - 1 && box.max.y <= window.max.y + 1;
    widgets[name] = Widget{box, window, visible};
}

}  // namespace cg::viewer
