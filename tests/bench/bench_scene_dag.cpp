// Scene DAG: the state machine run to completion vs the straight-line recursive traversal on
// 2,000 random puppets and robot arms (exam inputs: 3-4 nodes) and on the lesson's puppet; and
// the cost of one narrated step plus its 3D picture. The state machine starts from a copy of an
// already started (validated, resolved) state, as the plain function resolves the names and
// builds the local matrices itself but does not validate.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "core/run.hpp"
#include "transforms/scene_dag.hpp"

namespace {

const std::vector<cg::SceneDag::State>& started() {
    static const std::vector<cg::SceneDag::State> states = [] {
        cg::Rng rng(42);
        std::vector<cg::SceneDag::State> v;
        for (int i = 0; i < 2000; ++i) v.push_back(cg::SceneDag::start(cg::SceneDag::exam_input(rng)));
        return v;
    }();
    return states;
}

void BM_SceneDag_Plain(benchmark::State& state) {
    const auto& states = started();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& s : states) sum += cg::SceneDag::traverse(s.in).draws.back().matrix[3][0];
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * states.size());
}
BENCHMARK(BM_SceneDag_Plain)->Unit(benchmark::kMillisecond);

void BM_SceneDag_StateMachine(benchmark::State& state) {
    const auto& states = started();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& s : states)
            sum += cg::run_to_end<cg::SceneDag>(s).draws.back().matrix[3][0];
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * states.size());
}
BENCHMARK(BM_SceneDag_StateMachine)->Unit(benchmark::kMillisecond);

void BM_SceneDag_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "scene-dag");
}
BENCHMARK(BM_SceneDag_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
