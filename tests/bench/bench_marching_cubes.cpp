// Marching cubes: the state machine run to completion vs the straight-line compute on lesson
// sizes (the sphere on 16³ and 40³ cubes, two blobs on 24³, the gyroid on 16³: many saddle
// faces); and one narrated step plus its picture on the example (one cube) and on the 40³
// sphere.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "io/registry.hpp"
#include "modelling/marching_cubes.hpp"

namespace {

using cg::MarchingCubes;

MarchingCubes::Input make(MarchingCubes::Field f, int cells, double radius) {
    MarchingCubes::Input in;
    in.field = f;
    in.cells = cells;
    in.radius = radius;
    MarchingCubes::validate(in);
    return in;
}

const std::vector<MarchingCubes::Input>& inputs() {
    using F = MarchingCubes::Field;
    static const std::vector<MarchingCubes::Input> v = {
        make(F::Sphere, 16, 0.7),
        make(F::Sphere, 40, 0.7),
        make(F::Blobs, 24, 0.4),
        make(F::Gyroid, 16, 0.7),
    };
    return v;
}

void BM_MarchingCubes_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += MarchingCubes::compute(in).area;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_MarchingCubes_Plain)->Unit(benchmark::kMillisecond);

void BM_MarchingCubes_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<MarchingCubes>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<MarchingCubes>(MarchingCubes::begin(in)).area;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_MarchingCubes_StateMachine)->Unit(benchmark::kMillisecond);

void BM_MarchingCubes_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "marching-cubes");
}
BENCHMARK(BM_MarchingCubes_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_MarchingCubes_StepAndPictureSphere(benchmark::State& state) {
    cg::bench::step_and_picture(state, "marching-cubes", [](cg::json& in) {
        in = cg::parse_json(R"({"field": "sphere", "cells": 40, "radius": 0.7, "iso": 0})");
    });
}
BENCHMARK(BM_MarchingCubes_StepAndPictureSphere)->Unit(benchmark::kMicrosecond);

}  // namespace
