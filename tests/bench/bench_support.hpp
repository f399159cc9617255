// Shared by the benchmarks: what the viewer pays per step.
#pragma once

#include <benchmark/benchmark.h>

#include <vector>

#include "core/shared.hpp"
#include "io/registry.hpp"

namespace cg::bench {

// One narrated step through the registry plus the scene it draws, on the algorithm's
// example; the run restarts (untimed) whenever it finishes.
// `edit` may change the example first (another granularity, a bigger input).
inline void step_and_picture(benchmark::State& state, const char* id,
                             void (*edit)(json&) = nullptr) {
    const Registry registry = builtin_registry();
    const Algorithm& a = *registry.find(id);
    json input = a.example();
    if (edit) edit(input);
    const auto start = a.create(input);
    auto run = start->clone();
    Scene scene;
    for (auto _ : state) {
        if (run->done()) {
            state.PauseTiming();
            run = start->clone();
            state.ResumeTiming();
        }
        StepInfo info;
        run->step(&info);
        scene.clear();
        run->draw(scene);
        benchmark::DoNotOptimize(scene.polygons.data());
        benchmark::DoNotOptimize(info.narration.data());
    }
}

// The inputs of a state-machine benchmark, each made shareable once, as reading a file makes it:
// the states share their immutable input (core/shared.hpp), so the timed loop starts each run
// from a shared input with the algorithm's begin() (start() without re-validating), as the
// plain function starts from a const reference.
template <class A>
std::vector<Shared<typename A::Input>> shared_inputs(const std::vector<typename A::Input>& v) {
    return {v.begin(), v.end()};
}

}  // namespace cg::bench
