// Find the bug: a real run's working with one plausible student mistake planted in it.
//
// Each algorithm declares its typical mistakes in Spec::study.mistakes (a sign flip of p_k,
// min for max, the inverse instead of the inverse transpose, …). From a seed the sandbox picks
// one mistake and one step where it shows, rewrites that step's working (its variables, or its
// event for a misclassification) and carries the wrong value on through the later steps for as
// long as the right value would have stayed the same. The student steps through the working
// and names the first wrong step. The tampered trace hides the narration and the formulas of
// every step: they are the sandbox's explanation and would give the step away; the pictures
// (in the viewer) are the right run's.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "study/trace.hpp"

namespace cg::study {

// The step `at` (0-based) of `trace` with `m` planted, or nothing when the mistake does not
// apply there or would not change what the step shows (beyond the grading tolerance).
std::optional<StepInfo> plant(const Mistake& m, const Trace& trace, std::size_t at);

struct BugSite {
    std::size_t mistake = 0;  // index into Spec::study.mistakes
    std::size_t step = 0;     // 1-based
};
// Every (mistake, step) that plants a visible mistake, in step order.
std::vector<BugSite> bug_sites(const Spec& spec, const Trace& trace);

struct PlantedBug {
    std::size_t step = 0;  // the first wrong step, 1-based
    Mistake mistake;
    std::vector<StepInfo> steps;  // the working, with the mistake; narration and math empty
    StepInfo correct;             // the right step
    std::string explanation;      // what went wrong there, with the right and the wrong values
};

// The bug for `seed`: the same seed, the same bug. Throws InputError when no declared mistake
// shows on this input.
PlantedBug plant_bug(const Spec& spec, const Trace& trace, std::uint64_t seed);

struct BugGrade {
    bool correct = false;
    std::string text;  // the verdict, then the explanation beside the right step
};
BugGrade grade_bug_answer(const Spec& spec, const PlantedBug& bug, std::size_t answer);

}  // namespace cg::study
