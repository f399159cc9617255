// Marching squares: the state machine run to completion vs the straight-line compute on lesson
// and picture sizes (the circle on 64 × 64 and 256 × 256 cells, two blobs on 128 × 128, noise
// on 64 × 64: many saddles); and one narrated step plus its picture on the example (a 3 × 3
// grid) and on the 128 × 128 circle.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "io/registry.hpp"
#include "modelling/marching_squares.hpp"

namespace {

using cg::MarchingSquares;

MarchingSquares::Input make(MarchingSquares::Field f, int cells, double radius) {
    MarchingSquares::Input in;
    in.field = f;
    in.cells = cells;
    in.radius = radius;
    in.seed = 7;
    MarchingSquares::validate(in);
    return in;
}

const std::vector<MarchingSquares::Input>& inputs() {
    using F = MarchingSquares::Field;
    static const std::vector<MarchingSquares::Input> v = {
        make(F::Circle, 64, 0.7),
        make(F::Circle, 256, 0.7),
        make(F::Blobs, 128, 0.4),
        make(F::Noise, 64, 0.7),
    };
    return v;
}

void BM_MarchingSquares_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += MarchingSquares::compute(in).length;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_MarchingSquares_Plain)->Unit(benchmark::kMillisecond);

void BM_MarchingSquares_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<MarchingSquares>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<MarchingSquares>(MarchingSquares::begin(in)).length;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_MarchingSquares_StateMachine)->Unit(benchmark::kMillisecond);

void BM_MarchingSquares_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "marching-squares");
}
BENCHMARK(BM_MarchingSquares_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_MarchingSquares_StepAndPictureCircle(benchmark::State& state) {
    cg::bench::step_and_picture(state, "marching-squares", [](cg::json& in) {
        in = cg::parse_json(R"({"field": "circle", "cells": 128, "radius": 0.7, "iso": 0})");
    });
}
BENCHMARK(BM_MarchingSquares_StepAndPictureCircle)->Unit(benchmark::kMicrosecond);

}  // namespace
