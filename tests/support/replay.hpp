// Determinism and resumability checks shared by the per-algorithm tests.
#pragma once

#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

#include "core/timeline.hpp"
#include "io/registry.hpp"

namespace cg::test {

// The trace `cgsandbox run --trace` prints for this input, then the result.
inline std::string trace(const Algorithm& a, const json& input) {
    std::string out;
    auto run = a.create(input);
    for (std::size_t i = 1; !run->done(); ++i) {
        StepInfo info;
        run->step(&info);
        out += step_to_json(i, info).dump() + "\n";
    }
    return out + a.result(*run).dump();
}

constexpr std::size_t kEveryStep = std::numeric_limits<std::size_t>::max();

// The same input gives the same trace, byte for byte; a timeline walked to the end, back to
// the start and forward again shows the same states and steps; and a copy taken after step
// `copy_at` (or after every step) finishes in the same state as the timeline.
inline void check_replay(const Algorithm& a, const json& input, std::size_t copy_at) {
    const std::string first = trace(a, input);
    CHECK(trace(a, input) == first);

    Timeline t(a.create(input));
    std::vector<std::unique_ptr<Run>> forward_states;
    std::vector<StepInfo> forward_steps;
    forward_states.push_back(t.current().clone());
    while (t.forward()) {
        forward_states.push_back(t.current().clone());
        forward_steps.push_back(*t.last_step());
    }
    while (t.back()) REQUIRE(t.current().same_state(*forward_states[t.index()]));
    for (std::size_t i = 1; t.forward(); ++i) {
        REQUIRE(t.current().same_state(*forward_states[i]));
        REQUIRE(*t.last_step() == forward_steps[i - 1]);
    }

    const std::size_t n = forward_steps.size();
    const std::size_t from = copy_at == kEveryStep ? 0 : copy_at;
    const std::size_t to = copy_at == kEveryStep ? n : copy_at;
    for (std::size_t k = from; k <= to; ++k) {
        t.jump(k);
        auto copy = t.current().clone();
        while (!copy->done()) copy->step(nullptr);
        t.to_end();
        CHECK(copy->same_state(t.current()));
    }
}

}  // namespace cg::test
