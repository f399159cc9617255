// Acceleration: the uniform grid (uniform-grid) — the plain function (build and walk) vs the
// state machine run to the end on the same 1,000 random scenes of 40 small primitives in a
// 6 × 6 × 6 grid, one ray each (a fifth from inside, some with a component 0); the walk alone
// against brute force; and one narrated step plus its picture through the registry.
#include <benchmark/benchmark.h>

#include "accel/uniform_grid.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"

namespace {

using cg::UniformGrid;

const std::vector<cg::Shared<UniformGrid::Input>>& grid_inputs() {
    static const std::vector<cg::Shared<UniformGrid::Input>> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::Shared<UniformGrid::Input>> v;
        for (int s = 0; s < 1000; ++s) {
            UniformGrid::Input in;
            for (int i = 0; i < 40; ++i) {
                const glm::dvec3 c(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4));
                cg::Primitive p;
                const double k = rng.uniform(0, 1);
                if (k < 0.4) {
                    p.kind = cg::PrimitiveKind::Sphere, p.a = c, p.radius = rng.uniform(0.1, 0.6);
                } else if (k < 0.7) {
                    p.kind = cg::PrimitiveKind::Box, p.a = c,
                    p.b = c + glm::dvec3(rng.uniform(0.1, 1));
                } else {
                    p.kind = cg::PrimitiveKind::Triangle, p.a = c;
                    p.b = c + glm::dvec3(rng.uniform(0.2, 1), 0, rng.uniform(-0.5, 0.5));
                    p.c = c + glm::dvec3(0, rng.uniform(0.2, 1), rng.uniform(-0.5, 0.5));
                }
                in.primitives.push_back(p);
            }
            in.cells = {6, 6, 6};
            in.origin = rng.chance(0.2) ? glm::dvec3(rng.uniform(-3, 3), rng.uniform(-3, 3), 0)
                                        : glm::dvec3(-9, rng.uniform(-4, 4), rng.uniform(-4, 4));
            in.direction = glm::dvec3(1, rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5));
            if (rng.chance(0.2)) in.direction.y = 0;
            UniformGrid::validate(in);
            v.emplace_back(std::move(in));
        }
        return v;
    }();
    return inputs;
}

void BM_UniformGrid_Plain(benchmark::State& state) {
    const auto& inputs = grid_inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += UniformGrid::trace(*in).primitive_tests;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(inputs.size()));
}
BENCHMARK(BM_UniformGrid_Plain)->Unit(benchmark::kMillisecond);

void BM_UniformGrid_StateMachine(benchmark::State& state) {
    const auto& inputs = grid_inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            UniformGrid::State s;  // start() without re-validating: the inputs are known good
            s.in = in;
            s.grid = cg::Shared<UniformGrid::Grid>(UniformGrid::build(*in));
            sum += cg::run_to_end<UniformGrid>(std::move(s)).primitive_tests;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(inputs.size()));
}
BENCHMARK(BM_UniformGrid_StateMachine)->Unit(benchmark::kMillisecond);

// The walk alone through grids built once, against brute force on the same rays: what the
// grid saves per ray once it is built.
void BM_UniformGrid_WalkOnly(benchmark::State& state) {
    const auto& inputs = grid_inputs();
    static const std::vector<cg::Shared<UniformGrid::Grid>> grids = [&] {
        std::vector<cg::Shared<UniformGrid::Grid>> g;
        for (const auto& in : inputs) g.emplace_back(UniformGrid::build(*in));
        return g;
    }();
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < inputs.size(); ++i)
            sum += UniformGrid::trace(*inputs[i], grids[i]).t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(inputs.size()));
}
BENCHMARK(BM_UniformGrid_WalkOnly)->Unit(benchmark::kMillisecond);

void BM_UniformGrid_BruteForce(benchmark::State& state) {
    const auto& inputs = grid_inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            double t = 0;
            sum += UniformGrid::brute_force(*in, t);
            sum += t < UniformGrid::kInf ? t : 0;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(inputs.size()));
}
BENCHMARK(BM_UniformGrid_BruteForce)->Unit(benchmark::kMillisecond);

void BM_UniformGrid_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "uniform-grid");
}
BENCHMARK(BM_UniformGrid_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
