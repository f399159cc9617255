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

struct Spec {
    std::string id;     // CLI and registry id: "liang-barsky"
    std::string title;  // "Liang-Barsky line clipping"
    std::string topic;  // course topic: "Line Clipping"
    std::vector<std::string> pseudocode;
    std::vector<EventKind> events;
    std::vector<Slider> sliders = {};  // none for most algorithms
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
