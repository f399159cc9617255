// Window to viewport: the state machine run to completion vs the straight-line function, on
// 10^5 random maps of four points each; and the cost of one narrated step plus its picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"

#include "core/rng.hpp"
#include "io/registry.hpp"
#include "viewing/window_viewport.hpp"

namespace {

const std::vector<cg::WindowViewport::Input>& maps() {
    static const std::vector<cg::WindowViewport::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::WindowViewport::Input> v(100'000);
        for (auto& in : v) {
            const double x = rng.uniform(-100, 100), y = rng.uniform(-100, 100);
            in.window = {x, y, x + rng.uniform(1, 50), y + rng.uniform(1, 50)};
            in.viewport = {0, 0, rng.uniform(100, 2000), rng.uniform(100, 2000)};
            for (int k = 0; k < 4; ++k)
                in.points.push_back({rng.uniform(-150, 150), rng.uniform(-150, 150)});
        }
        return v;
    }();
    return inputs;
}

void BM_WindowViewport_Plain(benchmark::State& state) {
    const auto& inputs = maps();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::WindowViewport::map(in).device.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_WindowViewport_Plain)->Unit(benchmark::kMillisecond);

void BM_WindowViewport_StateMachine(benchmark::State& state) {
    const auto inputs = cg::bench::shared_inputs<cg::WindowViewport>(maps());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::WindowViewport>(cg::WindowViewport::begin(in)).device.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_WindowViewport_StateMachine)->Unit(benchmark::kMillisecond);

// What the viewer pays per step: a narrated step through the registry plus the scene.
void BM_WindowViewport_StepAndPicture(benchmark::State& state) { cg::bench::step_and_picture(state, "window-viewport"); }
BENCHMARK(BM_WindowViewport_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
