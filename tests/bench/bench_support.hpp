// Shared by the benchmarks: what the viewer pays per step.
#pragma once

#include <benchmark/benchmark.h>

#include "io/registry.hpp"

namespace cg::bench {

// One narrated step through the registry plus the scene it draws, on the algorithm's
// example; the run restarts (untimed) whenever it finishes.
inline void step_and_picture(benchmark::State& state, const char* id) {
    const Registry registry = builtin_registry();
    const Algorithm& a = *registry.find(id);
    const auto start = a.create(a.example());
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
