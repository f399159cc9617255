// Radiosity of a 1,014-patch box (the unit Cornell box's six walls, each cut into 13 × 13, the
// whole ceiling emitting): the state machine run to completion vs the straight-line function,
// Gauss-Seidel with hemicube form factors (R = 4 on the patch centre); and the cost of one
// narrated step plus its picture on the lesson's example. (bench_radiosity.cpp is form-factor's.)
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "io/registry.hpp"
#include "radiosity/radiosity.hpp"

namespace {

using cg::Patch;
using cg::Radiosity;
using glm::dvec3;

const Radiosity::Input& box() {
    static const Radiosity::Input in = [] {
        Radiosity::Input b;
        const dvec3 white(0.75), red(0.75, 0.2, 0.2), green(0.2, 0.75, 0.2);
        b.surfaces = {
            {Patch::rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}), dvec3(0), white},
            {Patch::rectangle({0, 1, 0}, {1, 0, 0}, {0, 0, 1}), dvec3(1), white},
            {Patch::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), dvec3(0), white},
            {Patch::rectangle({0, 0, 1}, {0, 1, 0}, {1, 0, 0}), dvec3(0), white},
            {Patch::rectangle({0, 0, 0}, {0, 1, 0}, {0, 0, 1}), dvec3(0), red},
            {Patch::rectangle({1, 0, 0}, {0, 0, 1}, {0, 1, 0}), dvec3(0), green},
        };
        b.subdivision = 13;  // 6 × 169 = 1,014 patches
        b.method = Radiosity::Method::GaussSeidel;
        b.form_factors = Radiosity::FormFactors::Hemicube;
        b.resolution = 4;
        b.samples = 1;
        b.tolerance = 1e-6;
        b.max_steps = 1000;
        b.camera = {{0.5, 0.5, 0.95}, {0.5, 0.5, 0}, {0, 1, 0}, 60, 32, 32};
        return b;
    }();
    return in;
}

void BM_Radiosity_Plain(benchmark::State& state) {
    for (auto _ : state) {
        const auto r = Radiosity::compute(box());
        benchmark::DoNotOptimize(r.radiosity.data());
    }
    state.SetItemsProcessed(state.iterations() * 1014);
}
BENCHMARK(BM_Radiosity_Plain)->Unit(benchmark::kMillisecond);

void BM_Radiosity_StateMachine(benchmark::State& state) {
    for (auto _ : state) {
        const auto r = cg::run_to_end<Radiosity>(Radiosity::start(box()));
        benchmark::DoNotOptimize(r.radiosity.data());
    }
    state.SetItemsProcessed(state.iterations() * 1014);
}
BENCHMARK(BM_Radiosity_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Radiosity_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "radiosity");
}
BENCHMARK(BM_Radiosity_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
