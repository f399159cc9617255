// Worked examples: a whole run written out as a solution a teacher could hand out.
//
// The document holds the question, the input, the pseudocode, every step with the same
// narration the viewer shows and its formula, and the final answer. Markdown keeps the
// formulas as LaTeX ($$ … $$), ready for notes; JSON holds the same for machines.
#pragma once

#include <string>

#include "io/exam.hpp"
#include "io/registry.hpp"

namespace cg {

struct WorkedExample {
    const Algorithm* algorithm = nullptr;
    std::string subtitle;  // e.g. the preset's name, or "exam problem, seed 7"
    ExamProblem problem;   // question, input and the answer fields
    std::vector<StepInfo> steps;
    json result;
};

// Runs the algorithm on the problem's input, recording every step. Throws InputError.
WorkedExample work(const Algorithm& a, ExamProblem problem, std::string subtitle = "");

std::string worked_markdown(const WorkedExample& w);
json worked_json(const WorkedExample& w);

}  // namespace cg
