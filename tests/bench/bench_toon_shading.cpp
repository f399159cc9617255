// Toon shading: the state machine run to completion vs the straight-line compute on a sphere of
// 64 segments (2,048 faces) and a torus of 64 (2,048 quads) in three bands; and one narrated
// step plus its picture on the example (the pyramid) and on the 24-segment sphere.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "io/registry.hpp"
#include "npr/toon_shading.hpp"

namespace {

using cg::ToonShading;

const std::vector<ToonShading::Input>& inputs() {
    static const std::vector<ToonShading::Input> v = [] {
        std::vector<ToonShading::Input> v;
        for (const char* shape : {"sphere", "torus"}) {
            ToonShading::Input in;
            in.mesh = cg::npr::generate(shape, 64);
            in.light = {1, 2, 3};
            in.thresholds = {0.3, 0.75};
            ToonShading::validate(in);
            v.push_back(std::move(in));
        }
        return v;
    }();
    return v;
}

void BM_ToonShading_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : v) sum += ToonShading::compute(in).counts[1];
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_ToonShading_Plain)->Unit(benchmark::kMicrosecond);

void BM_ToonShading_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<ToonShading>(inputs());
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : shared) sum += cg::run_to_end<ToonShading>(ToonShading::begin(in)).counts[1];
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_ToonShading_StateMachine)->Unit(benchmark::kMicrosecond);

void BM_ToonShading_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "toon-shading");
}
BENCHMARK(BM_ToonShading_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_ToonShading_StepAndPictureSphere(benchmark::State& state) {
    cg::bench::step_and_picture(state, "toon-shading", [](cg::json& in) {
        in = cg::parse_json(R"({"shape": "sphere", "segments": 24, "light": [1, 2, 3], "thresholds": [0.3, 0.75]})");
    });
}
BENCHMARK(BM_ToonShading_StepAndPictureSphere)->Unit(benchmark::kMicrosecond);

}  // namespace
