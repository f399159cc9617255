// The 3D rotations (arbitrary axis, slerp, Euler angles): each state machine run to completion
// vs its straight-line function on 10^5 random inputs; and the cost of one narrated step plus
// its 3D picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"

#include "core/rng.hpp"
#include "io/registry.hpp"
#include "transforms/arbitrary_axis.hpp"

namespace {

const std::vector<cg::ArbitraryAxis::Input>& axes() {
    static const std::vector<cg::ArbitraryAxis::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::ArbitraryAxis::Input> v(100'000);
        for (auto& in : v) {
            in.axis = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            in.angle_deg = rng.uniform(-180, 180);
            in.points = {{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)}};
        }
        return v;
    }();
    return inputs;
}

void BM_ArbitraryAxis_Plain(benchmark::State& state) {
    const auto& inputs = axes();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::ArbitraryAxis::rotate(in).points.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ArbitraryAxis_Plain)->Unit(benchmark::kMillisecond);

void BM_ArbitraryAxis_StateMachine(benchmark::State& state) {
    const auto& inputs = axes();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            cg::ArbitraryAxis::State s;  // start() without re-validating: inputs are known good
            s.in = in;
            sum += cg::run_to_end<cg::ArbitraryAxis>(std::move(s)).points.back().x;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ArbitraryAxis_StateMachine)->Unit(benchmark::kMillisecond);

void BM_ArbitraryAxis_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "arbitrary-axis");
}
BENCHMARK(BM_ArbitraryAxis_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
