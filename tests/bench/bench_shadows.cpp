// Projective shadows: the state machine run to completion vs the straight-line function on 10^5
// random triangles (point and directional lights, random planes); and the cost of one narrated
// step plus its 3D picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "shadows/projective_shadow.hpp"

namespace {

const std::vector<cg::ProjectiveShadow::Input>& triangles() {
    static const std::vector<cg::ProjectiveShadow::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::ProjectiveShadow::Input> v;
        v.reserve(100'000);
        while (v.size() < 100'000) {
            cg::ProjectiveShadow::Input in;
            in.normal = {rng.uniform(-1, 1), rng.uniform(0.2, 1), rng.uniform(-1, 1)};
            in.d = rng.uniform(-1, 1);
            const bool sun = rng.chance(0.25);
            in.light = {rng.uniform(-5, 5), rng.uniform(3, 8), rng.uniform(-5, 5), sun ? 0.0 : 1.0};
            in.polygon = {{rng.uniform(-3, 3), rng.uniform(0, 3), rng.uniform(-3, 3)},
                          {rng.uniform(-3, 3), rng.uniform(0, 3), rng.uniform(-3, 3)},
                          {rng.uniform(-3, 3), rng.uniform(0, 3), rng.uniform(-3, 3)}};
            try {
                cg::ProjectiveShadow::validate(in);
            } catch (const cg::InputError&) {
                continue;
            }
            v.push_back(std::move(in));
        }
        return v;
    }();
    return inputs;
}

void BM_ProjectiveShadow_Plain(benchmark::State& state) {
    const auto& inputs = triangles();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::ProjectiveShadow::flatten(in).shadow.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ProjectiveShadow_Plain)->Unit(benchmark::kMillisecond);

// The inputs as the state machine holds them (shared, made once, as start() makes them).
const std::vector<cg::Shared<cg::ProjectiveShadow::Input>>& shared_triangles() {
    static const auto shared = [] {
        std::vector<cg::Shared<cg::ProjectiveShadow::Input>> v;
        for (const auto& in : triangles()) v.emplace_back(in);
        return v;
    }();
    return shared;
}

void BM_ProjectiveShadow_StateMachine(benchmark::State& state) {
    const auto& inputs = shared_triangles();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            cg::ProjectiveShadow::State s;  // start() without re-validating: inputs are known good
            s.in = in;
            sum += cg::run_to_end<cg::ProjectiveShadow>(std::move(s)).shadow.back().x;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ProjectiveShadow_StateMachine)->Unit(benchmark::kMillisecond);

void BM_ProjectiveShadow_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "projective-shadow");
}
BENCHMARK(BM_ProjectiveShadow_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
