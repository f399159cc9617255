// Shadow maps: the state machine run to completion vs the straight-line render on 200 random
// scenes (a floor and up to five triangles; directional and spot lights; 16 × 16 maps, a
// 16 × 12 eye image); and the cost of one narrated step plus its picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "shadows/shadow_map.hpp"

namespace {

using cg::ShadowMap;

const std::vector<ShadowMap::Input>& scenes() {
    static const std::vector<ShadowMap::Input> inputs = [] {
        cg::Rng rng(21);
        std::vector<ShadowMap::Input> v;
        while (v.size() < 200) {
            ShadowMap::Input in;
            in.triangles = {{{{-3, 0, -3}, {3, 0, -3}, {3, 0, 3}}},
                            {{{-3, 0, -3}, {3, 0, 3}, {-3, 0, 3}}}};
            const int extra = int(rng.integer(1, 5));
            for (int k = 0; k < extra; ++k) {
                const glm::dvec3 c{rng.uniform(-1.5, 1.5), rng.uniform(0.3, 2),
                                   rng.uniform(-1.5, 1.5)};
                ShadowMap::Triangle t;
                for (auto& p : t)
                    p = c + glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
                in.triangles.push_back(t);
            }
            const bool spot = rng.chance(0.5);
            in.light.type = spot ? ShadowMap::LightType::Spot : ShadowMap::LightType::Directional;
            in.light.position = {rng.uniform(-3, 3), rng.uniform(4, 6), rng.uniform(-3, 3)};
            in.light.target = {0, 0, 0};
            in.light.up = {0, 0, -1};
            in.light.fov_deg = 70;
            in.light.extent = 3.5;
            in.light.near = 0.5;
            in.light.far = 12;
            in.map_size = 16;
            in.bias = 0.1;
            in.eye.position = {0, 5, 6};
            in.eye.target = {0, 0, 0};
            in.eye.up = {0, 1, 0};
            in.eye.fov_deg = 45;
            in.eye.width = 16;
            in.eye.height = 12;
            try {
                ShadowMap::validate(in);
            } catch (const cg::InputError&) {
                continue;
            }
            v.push_back(std::move(in));
        }
        return v;
    }();
    return inputs;
}

void BM_ShadowMap_Plain(benchmark::State& state) {
    const auto& inputs = scenes();
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : inputs) sum += ShadowMap::render(in).counts.shadow;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ShadowMap_Plain)->Unit(benchmark::kMillisecond);

const std::vector<cg::Shared<ShadowMap::Input>>& shared_scenes() {
    static const auto shared = [] {
        std::vector<cg::Shared<ShadowMap::Input>> v;
        for (const auto& in : scenes()) v.emplace_back(in);
        return v;
    }();
    return shared;
}

void BM_ShadowMap_StateMachine(benchmark::State& state) {
    const auto& inputs = shared_scenes();
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : inputs) {
            ShadowMap::State s;  // start() without re-validating: inputs are known good
            s.in = in;
            sum += cg::run_to_end<ShadowMap>(std::move(s)).counts.shadow;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ShadowMap_StateMachine)->Unit(benchmark::kMillisecond);

void BM_ShadowMap_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "shadow-map");
}
BENCHMARK(BM_ShadowMap_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
