// Triangle scan conversion: the state machine run to completion vs the straight-line function,
// on 10^4 random triangles in a 512 × 512 grid (about 2·10^8 pixels per pass); and the cost of
// one narrated step plus its picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"

#include "core/rng.hpp"
#include "io/registry.hpp"
#include "raster/scan_triangle.hpp"

namespace {

const std::vector<cg::ScanTriangle::Input>& triangles() {
    static const std::vector<cg::ScanTriangle::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::ScanTriangle::Input> v(10'000);
        for (auto& in : v) {
            in.width = in.height = 512;
            for (int k = 0; k < 3; ++k)
                in.triangle.push_back({rng.uniform(0, 512), rng.uniform(0, 512)});
        }
        return v;
    }();
    return inputs;
}

void BM_ScanTriangle_Plain(benchmark::State& state) {
    const auto& inputs = triangles();
    for (auto _ : state) {
        std::size_t pixels = 0;
        for (const auto& in : inputs) pixels += cg::ScanTriangle::scan(in).pixels.size();
        benchmark::DoNotOptimize(pixels);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ScanTriangle_Plain)->Unit(benchmark::kMillisecond);

void BM_ScanTriangle_StateMachine(benchmark::State& state) {
    const auto& inputs = triangles();
    for (auto _ : state) {
        std::size_t pixels = 0;
        for (const auto& in : inputs) {
            cg::ScanTriangle::State s;  // start() without re-validating: inputs are known good
            s.in = in;
            pixels += cg::run_to_end<cg::ScanTriangle>(std::move(s)).pixels.size();
        }
        benchmark::DoNotOptimize(pixels);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ScanTriangle_StateMachine)->Unit(benchmark::kMillisecond);

// What the viewer pays per step: a narrated step through the registry plus the scene (the
// example: a 10 × 8 grid).
void BM_ScanTriangle_StepAndPicture(benchmark::State& state) { cg::bench::step_and_picture(state, "scan-triangle"); }
BENCHMARK(BM_ScanTriangle_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
