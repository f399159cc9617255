// What one teachable step reports, and how bad input is refused.
//
// Every algorithm in the sandbox is a resumable state machine. Advancing it by one step
// returns a StepInfo: which kind of event happened (an id such as "entering" that lessons
// attach their text to), which pseudocode line is now active, one sentence with the actual
// numbers, the step's formula (LaTeX), and the named variables. The viewer, the CLI trace, the worked examples and the
// tests all read this one record, so nothing is computed twice.
#pragma once

#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace cg {

// A variable's value as the inspector shows it. Vectors are points or directions; a matrix
// is a list of rows.
using Value = std::variant<bool, long long, double, std::string, std::vector<double>,
                           std::vector<std::vector<double>>>;

struct Var {
    std::string name;  // as the course writes it: "t_enter", "p_k", "discriminant"
    Value value;
    bool operator==(const Var&) const = default;
};

struct StepInfo {
    std::string event;      // event kind id, one of the algorithm's Spec::events
    int line = 0;           // active pseudocode line, 1-based (0: none)
    std::string narration;  // one sentence, with the numbers of this step
    std::string math;       // the step's formula in LaTeX, with its numbers (may be empty)
    std::vector<Var> vars;  // the variables after this step, in display order
    bool operator==(const StepInfo&) const = default;
};

// The static description of an algorithm: what the registry lists and lessons refer to.
struct EventKind {
    std::string id;       // "entering"
    std::string meaning;  // one line, shown as a legend and checked by the lesson tests
};

// A number in the input worth scrubbing live (the curve parameter t): the viewer shows it as
// a slider over the canvas, and every change re-runs the algorithm at the same step.
struct Slider {
    std::string field;  // JSON pointer of a number in the input: "/t"
    std::string label;  // "t"
    double min = 0, max = 1;
};

// What the study modes (docs/study-modes.md) may ask of an algorithm, declared beside its
// events so that a new algorithm gets every mode by filling this in.

// Predict, then reveal: before a step is shown the student names its event and, for the events
// listed here, one or two of its numbers. An event not listed is predicted by its kind alone.
struct Predictable {
    std::string event;              // an id of Spec::events
    std::vector<std::string> vars;  // names of that step's variables: "t_enter", "r_k"
};

// Find the bug: one plausible student mistake, planted into the trace of a real run at a step
// with this event. `kind` says how the reported working changes (study/bug.hpp):
//   "negate"        a sign flip of `var` (a number or a vector)
//   "swap:<other>"  `var` and `other` exchanged (t_near and t_far not swapped back)
//   "copy:<other>"  `var` takes the value of `other` (n left as grad_F: not normalised)
//   "keep"          `var` keeps its value from the step before (an update forgotten)
//   "other:<cand>"  `var` takes the candidate not chosen: max(t_enter, r_k) read as min
//   "transpose"     a matrix transposed (the inverse instead of the inverse transpose)
//   "reverse"       a list in reverse order (the wrong vertex order)
//   "off-by-one"    an integer one too high
//   "not"           a yes/no answer flipped (inside read as outside)
//   "event:<id>"    the step classified as another event (entering read as leaving)
// The wrong value is carried into the later steps for as long as the right one stays the same,
// as it would be in a student's working.
struct Mistake {
    std::string event;
    std::string var;          // "" for "event:<id>"
    std::string kind;
    std::string description;  // what the student did, one line: "took p_k = dx for the left edge"
};

// A named setting of one input field, for comparing an algorithm with itself: Phong against
// Blinn-Phong is phong-lighting with "/model" set to "phong" and to "blinn-phong".
struct Variant {
    std::string name;   // "phong"
    std::string field;  // JSON pointer into the input: "/model"
    std::string value;  // the field's value as JSON text: "\"phong\""
};

struct Study {
    std::vector<Predictable> predict;  // every algorithm lists at least one event
    std::vector<Mistake> mistakes;     // at least one
    // Compare side by side: algorithms that declare the same kind read the same input
    // ("hsr-scene": painters, z-buffer and Warnock), and their results agree on `compare`
    // ("ids": the visible polygon of every pixel); `costs` are the result fields counting work.
    std::string input_kind = {};
    std::vector<std::string> compare = {};
    std::vector<std::string> costs = {};
    std::vector<Variant> variants = {};
};

struct Spec {
    std::string id;     // CLI and registry id: "liang-barsky"
    std::string title;  // "Liang-Barsky line clipping"
    std::string topic;  // course topic: "Line Clipping"
    std::vector<std::string> pseudocode;
    std::vector<EventKind> events;
    std::vector<Slider> sliders = {};  // none for most algorithms
    Study study = {};
    // For an animation, whose steps are frames: the step variable holding the simulated time in
    // seconds ("t"). The viewer's Play then runs at real time (or slowed down, or sped up):
    // it takes every step whose time has come. Empty for everything else.
    std::string clock = {};
};

// Bad input, refused at the start of a run. `field` is a path into the input as the user
// wrote it ("window.xmin", "p0[1]"); the JSON layer prefixes the file name.
class InputError : public std::runtime_error {
public:
    InputError(std::string field, std::string reason)
        : std::runtime_error(field.empty() ? reason : field + ": " + reason),
          field_(std::move(field)),
          reason_(std::move(reason)) {}
    const std::string& field() const { return field_; }
    const std::string& reason() const { return reason_; }

private:
    std::string field_;
    std::string reason_;
};

}  // namespace cg
