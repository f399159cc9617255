// Silhouette edges: the state machine run to completion vs the straight-line compute on a sphere
// of 64 segments (2,048 faces, 4,032 edges) and a torus of 64 (2,048 faces, 4,096 edges); and
// one narrated step plus its picture on the example (the cube) and on the 24-segment sphere.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "io/registry.hpp"
#include "npr/silhouette_edges.hpp"

namespace {

using cg::SilhouetteEdges;

const std::vector<SilhouetteEdges::Input>& inputs() {
    static const std::vector<SilhouetteEdges::Input> v = [] {
        std::vector<SilhouetteEdges::Input> v;
        for (const char* shape : {"sphere", "torus"}) {
            SilhouetteEdges::Input in;
            in.mesh = cg::npr::generate(shape, 64);
            in.eye = {2, 1.5, 3};
            SilhouetteEdges::validate(in);
            v.push_back(std::move(in));
        }
        return v;
    }();
    return v;
}

void BM_SilhouetteEdges_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        std::size_t sum = 0;
        for (const auto& in : v) sum += SilhouetteEdges::compute(in).silhouette.size();
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_SilhouetteEdges_Plain)->Unit(benchmark::kMicrosecond);

void BM_SilhouetteEdges_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<SilhouetteEdges>(inputs());
    for (auto _ : state) {
        std::size_t sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<SilhouetteEdges>(SilhouetteEdges::begin(in)).silhouette.size();
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_SilhouetteEdges_StateMachine)->Unit(benchmark::kMicrosecond);

void BM_SilhouetteEdges_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "silhouette-edges");
}
BENCHMARK(BM_SilhouetteEdges_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_SilhouetteEdges_StepAndPictureSphere(benchmark::State& state) {
    cg::bench::step_and_picture(state, "silhouette-edges", [](cg::json& in) {
        in = cg::parse_json(R"({"shape": "sphere", "segments": 24, "eye": [2, 1.5, 3]})");
    });
}
BENCHMARK(BM_SilhouetteEdges_StepAndPictureSphere)->Unit(benchmark::kMicrosecond);

}  // namespace
