// Predict, then reveal: before each step is shown, the student says what it will do.
//
// A prediction names the step's event ("entering") and, for the events an algorithm lists in
// its Spec::study.predict, the numbers that step computes ("t_enter": 0.25). Grading is the
// exam's: the event exactly, each number to three significant figures. The viewer's Predict
// mode and `cgsandbox predict` both go through grade_prediction.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "study/trace.hpp"

namespace cg::study {

// The numbers asked for when a step is predicted to be `event` (none: the event alone).
const std::vector<std::string>& predictable_vars(const Spec& spec, std::string_view event);

struct Prediction {
    std::size_t step = 0;  // 1-based
    std::string event;
    json variables = json::object();  // {name: value}
};

struct VarGrade {
    std::string name;
    bool correct = false;
    json expected;  // the step's value
    json given;     // null when not given
};

struct PredictGrade {
    std::size_t step = 0;
    bool correct = false;  // the event and every asked number right
    bool event_correct = false;
    std::string expected_event;  // the truth
    std::string given_event;
    std::vector<VarGrade> vars;  // the true event's predictable numbers
    std::string why;             // for a wrong prediction: what was expected, one line
};

// Grades one prediction against the step it predicts.
PredictGrade grade_prediction(const Spec& spec, const StepInfo& truth, const Prediction& p,
                              double tolerance = 1e-3);

// The question for step `step`, given the step before it (null for the first step): what has
// happened so far, the events to choose from with their meanings, and the numbers each asks.
std::string predict_question(const Spec& spec, std::size_t step, const StepInfo* before);
json predict_question_json(const Spec& spec, std::size_t step, const StepInfo* before);

// One line of an answers file: {"step": k, "event": "...", "variables": {...}}. Throws
// InputError naming the field ("line 3: variables") for a malformed one.
Prediction prediction_from_json(const json& j, const std::string& where);

struct PredictReport {
    std::vector<PredictGrade> grades;  // one per answered step, in step order
    std::size_t steps = 0;             // steps in the run
    std::size_t right = 0;
    std::vector<std::size_t> wrong;  // the steps predicted wrongly, to revisit
};

// Grades every prediction (a step predicted twice, or past the end, is an InputError).
PredictReport grade_predictions(const Spec& spec, const Trace& trace,
                                const std::vector<Prediction>& predictions,
                                double tolerance = 1e-3);
json report_json(const PredictReport& r);
std::string report_text(const PredictReport& r);

}  // namespace cg::study
