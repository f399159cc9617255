// Shared by the benchmarks: what the viewer pays per step.
#pragma once

#include <benchmark/benchmark.h>

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

}  // namespace cg::bench
