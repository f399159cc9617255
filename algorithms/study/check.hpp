// Check your own implementation: a student's trace against the sandbox's, step by step.
//
// A student writes the algorithm in any language and prints one JSON object per step, in the
// format of `cgsandbox run --trace`: {"index": k, "event": "...", "variables": {...}} ("step"
// may stand for "index"; "line", "narration" and "math" are ignored), and may end with the
// result object. The checker walks both traces together and stops at the first step that
// differs, saying what was expected there: the event, the numbers, the pseudocode line and the
// sandbox's narration. A variable the student leaves out is not checked; one the sandbox does
// not report at that step is a difference (a renamed variable is named as such).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "study/trace.hpp"

namespace cg::study {

// The lines of a JSON Lines text (blank lines skipped), each parsed. A line that is not JSON,
// or not an object, is an InputError naming it: "line 3: ...".
std::vector<json> read_json_lines(const std::string& text);

struct Mismatch {
    std::string what;  // "event", a variable's name, "steps", "result/t_enter"
    json expected;
    json given;
    std::string note;  // why it differs, one sentence
};

struct CheckReport {
    bool agree = true;
    std::size_t steps_expected = 0, steps_given = 0, steps_agreeing = 0;
    std::size_t step = 0;  // the first step that differs (0: none, or only the result differs)
    std::vector<Mismatch> mismatches;  // at that step (or in the result)
    // What should have happened at that step:
    std::string event, meaning, pseudocode, narration;
    int line = 0;
    json expected_variables;  // the step's variables as `run --trace` prints them
};

// Compares the given trace lines (the last one may be the result) with the sandbox's trace.
// A line that is not a step (no "event") anywhere but last is an InputError: the file is
// unreadable as a trace, not merely different.
CheckReport check_trace(const Spec& spec, const Trace& truth, const std::vector<json>& given,
                        double tolerance = 1e-3);

json check_json(const CheckReport& r);
std::string check_text(const Spec& spec, const CheckReport& r);

}  // namespace cg::study
