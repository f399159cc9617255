// Affine combinations: the state machine run to completion vs classify() on 2,000 exam-style
// lists of five expressions (parsing included in both: start() parses, as classify() does); and
// the cost of one narrated step plus its picture (the parse tree and the verdict list).
#include <benchmark/benchmark.h>

#include "affine/affine_combination.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"

namespace {

const std::vector<cg::AffineCombination::Input>& lists() {
    static const std::vector<cg::AffineCombination::Input> inputs = [] {
        std::vector<cg::AffineCombination::Input> v;
        for (std::uint64_t seed = 0; seed < 2000; ++seed) {
            cg::Rng rng(seed);
            v.push_back(cg::AffineCombination::exam_input(rng));
        }
        return v;
    }();
    return inputs;
}

void BM_AffineCombination_Plain(benchmark::State& state) {
    const auto& inputs = lists();
    for (auto _ : state) {
        std::size_t points = 0;
        for (const auto& in : inputs)
            for (const auto& r : cg::AffineCombination::classify(in).rows) points += r.kind == cg::affine::Kind::Point;
        benchmark::DoNotOptimize(points);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_AffineCombination_Plain)->Unit(benchmark::kMillisecond);

void BM_AffineCombination_StateMachine(benchmark::State& state) {
    const auto& inputs = lists();
    for (auto _ : state) {
        std::size_t points = 0;
        for (const auto& in : inputs)
            for (const auto& r : cg::run_to_end<cg::AffineCombination>(cg::AffineCombination::start(in)).rows)
                points += r.kind == cg::affine::Kind::Point;
        benchmark::DoNotOptimize(points);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_AffineCombination_StateMachine)->Unit(benchmark::kMillisecond);

void BM_AffineCombination_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "affine-combination");
}
BENCHMARK(BM_AffineCombination_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
