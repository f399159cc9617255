// Boids: the state machine run to completion vs the straight-line compute on 12 random flocks
// (20 to 120 boids, wrapped and steered worlds, some with obstacles or a limited field of view,
// 200 frames each); and the cost of one narrated step plus its picture on the example (6 boids)
// and on the lesson's 60-boid flock (its second preset).
#include <benchmark/benchmark.h>

#include "animation/boids.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using cg::Boids;

const std::vector<Boids::Input>& inputs() {
    static const std::vector<Boids::Input> v = [] {
        cg::Rng rng(41);
        std::vector<Boids::Input> out;
        for (int k = 0; k < 12; ++k) {
            Boids::Input in;
            in.random = {int(rng.integer(20, 120)), std::uint64_t(k)};
            in.world_min = {-20, -20};
            in.world_max = {20, 20};
            in.edges = k % 2 ? Boids::Edges::Steer : Boids::Edges::Wrap;
            in.radius = 4;
            in.separation_radius = 1.5;
            if (k % 3 == 0) in.obstacles = {{{-6, 2}, 3}, {{7, -5}, 2}};
            if (k % 4 == 1) in.fov = 240;
            in.max_speed = 4;
            in.min_speed = 2;
            in.dt = 0.05;
            in.steps = 200;
            out.push_back(Boids::resolve(in));
        }
        return out;
    }();
    return v;
}

void BM_Boids_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += Boids::compute(in).polarisation.back();
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_Boids_Plain)->Unit(benchmark::kMillisecond);

void BM_Boids_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<Boids>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<Boids>(Boids::begin(in)).polarisation.back();
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_Boids_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Boids_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "boids");
}
BENCHMARK(BM_Boids_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_Boids_StepAndPictureFlock(benchmark::State& state) {
    cg::bench::step_and_picture(state, "boids", [](cg::json& in) {
        in = cg::parse_json(R"({"random": {"count": 60, "seed": 7},
                                "world": {"min": [-20, -20], "max": [20, 20]}, "radius": 4,
                                "separation_radius": 1.5, "weights": {"separation": 1.5,
                                "alignment": 1, "cohesion": 0.5}, "max_speed": 4,
                                "min_speed": 2, "max_force": 4, "dt": 0.05, "steps": 600})");
    });
}
BENCHMARK(BM_Boids_StepAndPictureFlock)->Unit(benchmark::kMicrosecond);

}  // namespace
