// A run kept step by step: the record the study modes (docs/study-modes.md) work on.
//
// Predict, find the bug, check your own code and compare all ask the same thing of an
// algorithm: what did each step report? The registry's type-erased Run answers it; this file
// runs an input to the end once and keeps every StepInfo and the result, so that the modes can
// look back and forth without running the algorithm again.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/registry.hpp"

namespace cg::study {

// A study mode keeps every step; a run longer than this is refused with a clear error (the
// lessons' presets stay far below: the longest, a ray-traced 48 × 36 image, has about 20,000).
constexpr std::size_t kMaxTraceSteps = 200'000;

struct Trace {
    std::vector<StepInfo> steps;  // step k (1-based) is steps[k - 1]
    json result;
};

// Runs `input` to the end. Bad input throws InputError naming the field, as `run` does.
Trace record(const Algorithm& algorithm, const json& input, std::size_t max_steps = kMaxTraceSteps);

// The variable `name` of a step, or null when the step does not report it.
const Var* find_var(const StepInfo& step, std::string_view name);

// The names of a step's variables, "t_enter, t_leave, p_k", for messages.
std::string var_names(const StepInfo& step);

// The ids of an algorithm's events, "entering, leaving, accept", for messages.
std::string event_names(const Spec& spec);
const EventKind* find_event(const Spec& spec, std::string_view id);

// Two values agree: numbers within `tolerance` relative to max(1, |expected|) (1e-3 is the
// exam's three significant figures), lists and matrices element by element, the rest exactly.
bool values_agree(const json& expected, const json& given, double tolerance);

// A value as a reader sees it: 0.25, (1, 2, 3), [[1, 0], [0, 1]], "left", yes/no.
std::string show(const json& value);

}  // namespace cg::study
