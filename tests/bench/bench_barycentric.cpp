// Barycentric coordinates: the state machine run to completion vs the straight-line function
// on 20,000 random triangles with 8 points each (2D and 3D apart); and the cost of one narrated
// step plus its picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "raster/barycentric.hpp"

namespace {

const std::vector<cg::Barycentric::State>& starts(int dim) {
    auto make = [](int d) {
        cg::Rng rng(42 + d);
        std::vector<cg::Barycentric::State> v;
        v.reserve(20'000);
        while (v.size() < 20'000) {
            cg::Barycentric::Input in;
            in.dim = d;
            auto c = [&] { return rng.uniform(-10, 10); };
            for (auto& p : in.triangle) p = {c(), c(), d == 3 ? c() : 0};
            for (int k = 0; k < 8; ++k) in.points.push_back({c(), c(), d == 3 ? c() : 0});
            try {
                v.push_back(cg::Barycentric::start(in));  // shares the input; validated once
            } catch (const cg::InputError&) {
            }
        }
        return v;
    };
    static const std::vector<cg::Barycentric::State> two = make(2), three = make(3);
    return dim == 2 ? two : three;
}

void plain(benchmark::State& state, int dim) {
    const auto& inputs = starts(dim);
    for (auto _ : state) {
        double sum = 0;
        for (const auto& s : inputs)
            sum += cg::Barycentric::compute(*s.in).results.back().weights.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void machine(benchmark::State& state, int dim) {
    const auto& inputs = starts(dim);
    for (auto _ : state) {
        double sum = 0;
        for (const auto& s : inputs)
            sum += cg::run_to_end<cg::Barycentric>(s).results.back().weights.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void BM_Barycentric2_Plain(benchmark::State& state) {
    plain(state, 2);
}
void BM_Barycentric2_StateMachine(benchmark::State& state) {
    machine(state, 2);
}
void BM_Barycentric3_Plain(benchmark::State& state) {
    plain(state, 3);
}
void BM_Barycentric3_StateMachine(benchmark::State& state) {
    machine(state, 3);
}
BENCHMARK(BM_Barycentric2_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Barycentric2_StateMachine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Barycentric3_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Barycentric3_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Barycentric_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "barycentric");
}
BENCHMARK(BM_Barycentric_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_Barycentric3_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "barycentric", [](cg::json& in) {
        in = cg::json{{"triangle", {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}},
                      {"points", {{0.25, 0.5, 1.5}, {1, 1, 1}}}};
    });
}
BENCHMARK(BM_Barycentric3_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
