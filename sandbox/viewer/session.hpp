// The viewer's whole state in one object, passed explicitly to every panel (no globals):
// which algorithm runs on which input, where in its timeline the student is, how the canvas
// looks at it, and the little UI memory the panels need from one frame to the next.
//
// A refused input never loses the picture: the editor keeps the bad input and shows why it
// was refused, while the canvas keeps showing the last run that did start.
//
// Studying adds two things on top of a run: an open lesson (its text beside the canvas, its
// presets as inputs, its notes on the current event), and exam practice, which runs a
// generated problem with the solution hidden: stepping stays locked until it is revealed.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "accel/complexity.hpp"
#include "checkpoint.hpp"
#include "core/timeline.hpp"
#include "hsr/complexity.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "study/bug.hpp"
#include "study/compare.hpp"
#include "study/predict.hpp"
#include "viewer/fonts.hpp"
#include "viewer/geometry.hpp"
#include "viewer/view3.hpp"

namespace cg::viewer {

// The narration log (the steps up to the current one), rebuilt only when the run or the
// step changes, because going back past the timeline's window replays steps.
struct NarrationLog {
    static constexpr std::size_t kMaxEntries = 500;
    std::uint64_t run = std::numeric_limits<std::uint64_t>::max();  // Session::run_id
    std::size_t index = 0;                                          // the step it was built for
    std::size_t first = 1;                                          // the step number of steps[0]
    std::vector<StepInfo> steps;
    // The entries as the log panel drew them: wrapped for `wrapped_width` at `wrapped_font`
    // pixels, and their heights; rebuilt when the log, the width or the font changes.
    mutable std::vector<std::string> wrapped;
    mutable std::vector<float> heights;
    mutable float wrapped_width = -1, wrapped_font = -1;
};

struct LayoutRecord;

struct CanvasState {
    View2 view;
    bool fit_pending = true;       // fit the view to the scene when next drawn (size known then)
    // The sizes the world and the 3D view were last fitted at: a resize fits them again.
    glm::dvec2 fitted_world{0, 0}, fitted_3d{0, 0};
    int dragged_handle = -1;       // index into Scene::handles while one is dragged
    glm::dvec2 grab_offset{0, 0};  // handle minus mouse, in world units: no jump on grab
    bool panning = false;
    // A panel's handles (Panel::handles): the panel (index into Scene::panels) whose handle is
    // dragged, or hovered, and which one; -1 when none.
    int panel_dragged = -1, panel_hot = -1, panel_hot_handle = -1;
    Camera3 camera3;  // the 3D canvas's, fitted together with the 2D view
};

// The left panel's tabs.
enum class Tab { Algorithm, Lessons, Exam };

struct ExamState {
    bool active = false;
    std::uint64_t seed = 1;          // the seed field; the problem's own is problem.seed
    ExamProblem problem;             // the problem practised while active
    std::vector<std::string> typed;  // the student's answers, one per problem.answers
    std::vector<FieldGrade> grades;  // the last Check's verdicts; empty before any
    bool revealed = false;           // the solution may be stepped through
    bool answers_shown = false;      // the expected values are shown beside the answers
};

class GridTextures;
struct Session;

// The study modes (docs/study-modes.md) on top of a run: Watch (free stepping), Predict (each
// step predicted before it is shown) and Find the bug (the run's working with one planted
// mistake); beside any of them, Compare opens a second run next to the first. The logic is in
// session_modes.cpp, the drawing in panel_modes.cpp.
enum class Mode { Watch, Predict, Bug };

struct PredictState {
    std::string event;               // the event chosen for the next step ("" before a choice)
    std::vector<std::string> typed;  // the numbers typed, one per predictable_vars(event)
    std::size_t reached = 0;         // steps revealed so far: forward is free up to here
    std::vector<study::PredictGrade> grades;  // one per step predicted, in step order
    std::size_t right = 0;
};

struct BugState {
    std::uint64_t seed = 1;                // the seed field
    std::optional<study::PlantedBug> bug;  // the bug planted in this run
    std::optional<study::BugGrade> grade;  // the last answer's verdict
    std::size_t answered_step = 0;         // the step that answer named
    bool over = false;  // answered right, or given up: the explanation stays until leaving
};

// One choice for Compare's side B.
struct CompareOption {
    enum class Kind { Variant, Algorithm, Edited } kind = Kind::Variant;
    std::string label;                     // what the list shows
    const Algorithm* algorithm = nullptr;  // side B's algorithm
    const Variant* variant = nullptr;      // Kind::Variant: the variant applied to B's input
};

struct CompareState {
    bool open = false;
    int choice = 0;              // index into Session::compare_options()
    std::string edited_text;     // Kind::Edited: side B's input as JSON text
    bool editing = false;        // the editor window for edited_text is shown
    std::string error;           // why side B did not start
    std::shared_ptr<Session> b;  // side B: a session of its own, stepped with this one
    study::Side side_a, side_b;
    std::optional<study::Comparison> result;  // of the two recorded runs, made once per pair
    std::uint64_t run_a = std::numeric_limits<std::uint64_t>::max();  // the runs it is for
    std::uint64_t run_b = std::numeric_limits<std::uint64_t>::max();
    std::size_t synced = std::numeric_limits<std::size_t>::max();  // A's step B was moved to
};

struct StudyState {
    Mode mode = Mode::Watch;
    std::shared_ptr<const study::Trace> trace;  // the run's, recorded once when needed
    std::uint64_t trace_run = std::numeric_limits<std::uint64_t>::max();  // ... for this run
    std::uint64_t generation = 0;  // counts changes to the steps shown (a bug planted or left)
    PredictState predict;
    BugState bug;
    CompareState compare;
};

struct Session {
    explicit Session(const Registry& r) : registry(r) {}

    const Registry& registry;
    Fonts fonts;

    // --- what runs ---
    const Algorithm* algorithm = nullptr;
    json input;                                // as the editor shows it, possibly refused
    std::string input_error;                   // why `input` was refused; empty when it runs
    std::unique_ptr<Timeline> timeline;        // the last run that started; null if none has
    std::optional<std::size_t> probed_length;  // its length, if a quick dry run finished
    std::uint64_t run_id = 0;     // counts restarts, so caches know when they are stale
    double probe_seconds = 0.05;  // time a dry run may take to find the length

    // --- stepping ---
    std::set<int> breakpoints;  // pseudocode lines, 1-based
    bool playing = false;
    static constexpr int kMaxPlayStepsPerFrame = 2000;  // an animation's steps in one frame, at most
    float steps_per_second = 2.0f;
    double play_clock = 0;  // steps owed to Play; one is taken whenever it reaches 1
    // Animations (Spec::clock): Play keeps the simulated time `time_scale` times the wall
    // clock's; play_time is the simulated time Play has reached.
    float time_scale = 1.0f;
    double play_time = 0;
    // The current state's simulated time (the clock variable of the step that led to it; 0 at
    // the start); none when the algorithm is not an animation or the step does not say.
    std::optional<double> clock_now() const;
    // One step of Play: false, and Play stopped, at a locked step, the end or a breakpoint.
    bool play_step();

    CanvasState canvas;
    Box canvas_rect{{0, 0}, {0, 0}};  // where the last frame put the canvas (display pixels)
    // When set, the next frame's canvas writes there what it placed where (layout.hpp).
    LayoutRecord* layout_record = nullptr;

    // --- studying ---
    LessonLibrary lessons;  // loaded at start-up; broken files are listed in lessons.errors
    std::string lesson_id;  // the open lesson, shown while its algorithm is the one running
    std::string preset;     // the lesson preset last loaded (it counts while the input equals it)
    bool browsing = false;  // the Lessons tab lists the lessons although one is open
    ExamState exam;
    StudyState study;
    std::vector<hsr::ComplexityRow> hsr_costs;  // the costs plot's table, made when first opened
    std::vector<accel::ComplexityRow> accel_costs;  // the same for the acceleration structures
    Tab tab = Tab::Algorithm;    // the tab shown (what the tab bar shows, or is about to)
    bool tab_requested = false;  // `tab` is to be selected in the tab bar when next drawn

    // --- panels ---
    std::string checkpoint_path = "checkpoint.json";
    std::string export_path;  // "Export worked example…"; worked-<id>.md until edited
    float files_height = 0;   // the files row's height last frame, so the log leaves room
    std::string status;       // the last save / open / screenshot message
    bool status_is_error = false;
    bool screenshot_requested = false;  // taken by the main loop after the frame is drawn
    int followed_line = 0;              // the pseudocode line last scrolled into view
    std::string followed_event;         // ... and the event in the legend

    // --- the window ---
    // The side panels folded to a strip, giving their width to the canvas: the lesson panel
    // on the left ([ or its ◀ button) and the code column on the right (] or its ▶ button).
    bool fold_left = false, fold_right = false;

    // --- the keyboard ---
    bool show_help = false;    // the list of keys (F1 or ?)
    int panel_step = 0;        // Tab (+1) or Shift-Tab (−1): focus the next or previous panel
    bool leave_panels = false;  // Escape: give the keys back to stepping
    std::string focused_panel;  // the panel with the keyboard focus, "" if none

    // Where the controls were drawn in the last frame, by name ("Step", "tab:Exam"), so the
    // GUI tests can click them as a person would (record_widgets turns it on).
    struct Widget {
        Box box;          // where it is on screen (scrolled out of sight, maybe)
        Box window;       // the visible part of the window that holds it
        bool visible = true;  // not scrolled out of sight, not clipped
    };
    bool record_widgets = false;
    std::map<std::string, Widget> widgets;
    void note_widget(const std::string& name);  // the last ImGui item, when recording

    // --- starting runs ---
    // Starts `a` on `in` and moves to `step` (clamped to the end). Throws InputError and
    // leaves the session unchanged when the input is refused.
    void start(const Algorithm& a, json in, std::size_t step);
    // The same for the viewer: a refusal is kept in input_error and false returned.
    bool try_start(const Algorithm& a, json in, std::size_t step);
    void choose(const Algorithm& a);  // its example input, at step 0, view fitted
    void load(const Checkpoint& c);   // never throws
    bool edit(json edited);           // restarts at the current step
    Checkpoint checkpoint() const;

    // --- where we are ---
    std::size_t index() const { return timeline ? timeline->index() : 0; }
    std::optional<std::size_t> length() const;
    const StepInfo* last_step() const { return timeline ? timeline->last_step() : nullptr; }
    bool at_end() const { return !timeline || timeline->at_end(); }
    // What the current step draws, made once per step (a frame asks for it several times).
    const Scene& scene() const;
    const NarrationLog& log();

    // --- studying (session_study.cpp) ---
    const Lesson* lesson() const;               // the open lesson, if its algorithm runs
    const LessonPreset* loaded_preset() const;  // the preset, while the input is still it
    void open_lesson(const Lesson& l);          // its first preset, unless already running it
    void load_preset(const LessonPreset& p);    // restarts at step 0
    void show_tab(Tab t);
    // Starts exam practice on make_exam(a, seed) at step 0, solution hidden. Throws
    // InputError (no generator, or a refused input) and leaves the session unchanged.
    void start_exam(const Algorithm& a, std::uint64_t seed);
    bool try_start_exam(const Algorithm& a, std::uint64_t seed);  // failures: the status line
    void check_exam();                                            // grades exam.typed
    void reveal_next_step();  // unlocks stepping and takes one step
    void leave_exam();
    bool solution_hidden() const { return exam.active && !exam.revealed; }

    // --- study modes (session_modes.cpp) ---
    // Switches mode; Predict and Find the bug record the run first (a refusal, say a run too
    // long to keep, goes to the status line and the mode stays Watch). Returns false then.
    bool set_mode(Mode m);
    void cycle_mode();            // Watch → Predict → Find the bug → Watch (the M key)
    const study::Trace* trace();  // the current run's, recorded once per run; null if refused
    // Every frame: re-enters the mode when the run changed under it (an edit, a dragged
    // handle), and keeps Compare's side B on this run's step.
    void sync_study();
    // The step the panels show for step k (1-based): the planted bug's working in Find the
    // bug, else the real step. Null for step 0.
    const StepInfo* shown_step(std::size_t k);
    const StepInfo* shown_step() { return shown_step(index()); }
    // Predict: the numbers the chosen event asks for; Reveal grades the prediction against
    // the true next step and takes it. False when there is nothing to predict now.
    const std::vector<std::string>& predict_vars() const;
    void choose_prediction(const std::string& event);
    bool can_predict() const;  // at the furthest step revealed, with a step still to come
    bool reveal_prediction();
    bool forward_locked(std::size_t to) const;  // Predict: `to` is past what has been revealed
    // Find the bug: plants bug.seed's bug (the run from step 0); names `step` as the first
    // wrong one; gives up (the explanation is shown).
    bool plant_bug();
    void answer_bug(std::size_t step);
    void give_up_bug();
    // Compare: the choices for side B, opening it beside this run, closing it.
    std::vector<CompareOption> compare_options() const;
    const Variant* input_variant() const;  // the variant the input is in, if any
    bool open_compare(int choice);
    void close_compare();
    bool comparing() const {
        return study.compare.open && study.compare.b && study.compare.b->timeline;
    }
    GridTextures* compare_textures = nullptr;  // side B's grid textures (its own slots)

    // --- moving (each does nothing without a run, or while an exam's solution is hidden) ---
    void step_forward();
    void step_back();
    void reset();
    void run_to_end();  // stops early on a breakpoint
    void jump(std::size_t step);
    void toggle_play();
    void advance(double seconds);  // Play's clock

    void set_status(std::string text, bool error);

    GridTextures* textures = nullptr;  // big pixel grids as textures, when drawn with OpenGL

  private:
    bool on_breakpoint();  // true (and says so) when the last step's line has a breakpoint
    bool can_step() const { return timeline && !solution_hidden(); }

    NarrationLog log_;
    std::uint64_t log_generation_ = 0;
    mutable Scene scene_;  // scene()'s, for the step it was drawn at
    mutable std::uint64_t scene_run_ = std::numeric_limits<std::uint64_t>::max();
    mutable std::size_t scene_index_ = 0;
};

}  // namespace cg::viewer
