// Fractal terrain: the state machine run to completion vs the straight loops (fractal::refine)
// on 40 random inputs (20 triangles and 20 grids of 6 levels: 2,145 and 4,225 vertices); and
// the cost of one narrated step plus its picture on the example (a triangle refined twice) and
// on a 4-level diamond-square grid.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "modelling/fractal_terrain.hpp"

namespace {

using cg::FractalTerrain;

const std::vector<FractalTerrain::Input>& inputs() {
    static const std::vector<FractalTerrain::Input> v = [] {
        cg::Rng rng(28);
        std::vector<FractalTerrain::Input> out;
        for (int k = 0; k < 40; ++k) {
            FractalTerrain::Input in;
            in.method = k < 20 ? FractalTerrain::Method::Triangle : FractalTerrain::Method::Grid;
            in.levels = 6;
            in.amplitude = rng.uniform(0.5, 2);
            in.roughness = rng.uniform(0.5, 1.5);
            in.seed = std::uint64_t(k);
            in.triangle = {glm::dvec3(-3, rng.uniform(-1, 1), 2), glm::dvec3(3, rng.uniform(-1, 1), 2),
                           glm::dvec3(0, rng.uniform(-1, 1), -3)};
            in.size = 6;
            for (double& c : in.corners) c = rng.uniform(-1, 1);
            FractalTerrain::validate(in);
            out.push_back(in);
        }
        return out;
    }();
    return v;
}

void BM_FractalTerrain_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += FractalTerrain::compute(in).max_height;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_FractalTerrain_Plain)->Unit(benchmark::kMillisecond);

void BM_FractalTerrain_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<FractalTerrain>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<FractalTerrain>(FractalTerrain::begin(in)).max_height;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_FractalTerrain_StateMachine)->Unit(benchmark::kMillisecond);

void BM_FractalTerrain_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "fractal-terrain");
}
BENCHMARK(BM_FractalTerrain_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_FractalTerrain_StepAndPictureGrid(benchmark::State& state) {
    cg::bench::step_and_picture(state, "fractal-terrain", [](cg::json& in) {
        in = cg::parse_json(R"({"method": "diamond-square", "levels": 4, "amplitude": 1,
                                "roughness": 1, "seed": 5, "size": 4, "corners": [0, 0.5, 0.5, 1]})");
    });
}
BENCHMARK(BM_FractalTerrain_StepAndPictureGrid)->Unit(benchmark::kMicrosecond);

}  // namespace
