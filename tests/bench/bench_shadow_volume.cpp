// Shadow volumes: the state machine run to completion (start, which validates, then every step)
// vs the straight-line solve (which validates too) on 2,000 random boxes under random lights,
// six eye rays each; and the cost of one narrated step plus its 3D picture.
#include <benchmark/benchmark.h>

#include <glm/mat3x3.hpp>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "shadows/shadow_volume.hpp"

namespace {

const std::vector<cg::ShadowVolume::Input>& scenes() {
    static const std::vector<cg::ShadowVolume::Input> inputs = [] {
        const cg::Registry registry = cg::builtin_registry();
        const cg::json example = registry.find("shadow-volume")->example();
        cg::Rng rng(42);
        std::vector<cg::ShadowVolume::Input> v;
        while (v.size() < 2'000) {
            cg::ShadowVolume::Input in;
            in.has_floor = true;
            in.floor = 0;
            glm::dmat3 m(1.0);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) m[i][j] += rng.uniform(-0.3, 0.3);
            for (const auto& p : example["occluder"]["vertices"])
                in.vertices.push_back(m * (glm::dvec3(p[0], p[1], p[2]) - glm::dvec3(0, 2, 0)) +
                                      glm::dvec3(0, 3, 0));
            for (const auto& f : example["occluder"]["faces"])
                in.faces.push_back({int(f[0]), int(f[1]), int(f[2])});
            in.light = {rng.uniform(-3, 3), rng.uniform(7, 9), rng.uniform(-3, 3)};
            in.eye = {rng.uniform(-8, 8), rng.uniform(1, 6), rng.uniform(5, 9)};
            for (int k = 0; k < 6; ++k)
                in.targets.push_back({rng.uniform(-4, 4), 0, rng.uniform(-4, 4)});
            try {
                cg::ShadowVolume::validate(in);
            } catch (const cg::InputError&) {
                continue;
            }
            v.push_back(std::move(in));
        }
        return v;
    }();
    return inputs;
}

void BM_ShadowVolume_Plain(benchmark::State& state) {
    const auto& inputs = scenes();
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : inputs) sum += cg::ShadowVolume::solve(in).rays.back().count;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ShadowVolume_Plain)->Unit(benchmark::kMillisecond);

void BM_ShadowVolume_StateMachine(benchmark::State& state) {
    const auto& inputs = scenes();
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::ShadowVolume>(cg::ShadowVolume::start(in)).rays.back().count;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ShadowVolume_StateMachine)->Unit(benchmark::kMillisecond);

void BM_ShadowVolume_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "shadow-volume");
}
BENCHMARK(BM_ShadowVolume_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
