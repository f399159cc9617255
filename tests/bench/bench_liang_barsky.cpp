// Liang-Barsky: the state machine run to completion vs the straight-line function, on 10^6
// random segments; and the cost of one narrated step plus its picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"

#include <random>

#include "clipping/liang_barsky.hpp"
#include "io/registry.hpp"

namespace {

const std::vector<cg::LiangBarsky::Input>& segments() {
    static const std::vector<cg::LiangBarsky::Input> inputs = [] {
        std::mt19937_64 rng(42);
        std::uniform_real_distribution<double> u(-10, 10);
        std::vector<cg::LiangBarsky::Input> v(1'000'000);
        for (auto& in : v) in = {{-4, -3, 5, 4}, {u(rng), u(rng)}, {u(rng), u(rng)}};
        return v;
    }();
    return inputs;
}

void BM_LiangBarsky_Plain(benchmark::State& state) {
    const auto& inputs = segments();
    for (auto _ : state) {
        int visible = 0;
        for (const auto& in : inputs) visible += cg::LiangBarsky::clip(in).visible;
        benchmark::DoNotOptimize(visible);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_LiangBarsky_Plain)->Unit(benchmark::kMillisecond);

void BM_LiangBarsky_StateMachine(benchmark::State& state) {
    const auto& inputs = segments();
    for (auto _ : state) {
        int visible = 0;
        for (const auto& in : inputs) {
            cg::LiangBarsky::State s;  // start() without re-validating: inputs are known good
            s.in = in;
            visible += cg::run_to_end<cg::LiangBarsky>(s).visible;
        }
        benchmark::DoNotOptimize(visible);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_LiangBarsky_StateMachine)->Unit(benchmark::kMillisecond);

// What the viewer pays per step: a narrated step through the registry plus the scene.
void BM_LiangBarsky_StepAndPicture(benchmark::State& state) { cg::bench::step_and_picture(state, "liang-barsky"); }
BENCHMARK(BM_LiangBarsky_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
