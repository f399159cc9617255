// Acceleration: the slab test (ray-aabb) — the plain function vs the state machine run to the
// end on the same 10^5 random rays (a fifth with a component 0, a tenth from inside the box),
// and one narrated step plus its picture through the registry.
#include <benchmark/benchmark.h>

#include "accel/ray_aabb.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"

namespace {

const std::vector<cg::RayAabb::Input>& rays() {
    static const std::vector<cg::RayAabb::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::RayAabb::Input> v(100'000);
        for (auto& in : v) {
            for (int i = 0; i < 3; ++i) {
                in.min[i] = rng.uniform(-4, 0);
                in.max[i] = in.min[i] + rng.uniform(0.5, 4);
                in.origin[i] = rng.uniform(-8, 8);
                in.direction[i] = rng.chance(0.07) ? 0.0 : rng.uniform(-1, 1);
            }
            if (rng.chance(0.1)) in.origin = 0.5 * (in.min + in.max);
            if (in.direction == glm::dvec3(0.0)) in.direction.x = 1;
        }
        return v;
    }();
    return inputs;
}

void BM_RayAabb_Plain(benchmark::State& state) {
    const auto& inputs = rays();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::RayAabb::intersect(in).hit;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_RayAabb_Plain)->Unit(benchmark::kMillisecond);

void BM_RayAabb_StateMachine(benchmark::State& state) {
    const auto& inputs = rays();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            cg::RayAabb::State s;  // start() without re-validating: the inputs are known good
            s.in = in;
            sum += cg::run_to_end<cg::RayAabb>(std::move(s)).hit;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_RayAabb_StateMachine)->Unit(benchmark::kMillisecond);

void BM_RayAabb_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "ray-aabb");
}
BENCHMARK(BM_RayAabb_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
