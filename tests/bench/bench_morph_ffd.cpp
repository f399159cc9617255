// Free-form deformation: the state machine run to completion vs the straight-line compute on
// 12 random lattices (degrees 1 to 6 per axis, a few moved control points, 2,000 shape points
// each, a tenth of them outside the box); and the cost of one narrated step plus its picture on
// the example (a bilinear lattice, 6 points) and on the lesson's 3 × 3 lattice round a circle.
// In space the same pair on 8 random 3D lattices (degrees 1 to 4 per axis, 1,000 points each),
// and one step plus its picture on a 3 × 1 × 1 twist of a 16-point wireframe bar.
#include <benchmark/benchmark.h>

#include "animation/morph_ffd.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using cg::MorphFfd;

const std::vector<MorphFfd::Input>& inputs() {
    static const std::vector<MorphFfd::Input> v = [] {
        cg::Rng rng(41);
        std::vector<MorphFfd::Input> out;
        for (int k = 0; k < 12; ++k) {
            MorphFfd::Input in;
            in.box_min = {-2, -1};
            in.box_max = {2, 1};
            in.l = int(rng.integer(1, 6));
            in.m = int(rng.integer(1, 6));
            for (int q = 0; q < 4; ++q)
                in.moves.push_back({int(rng.integer(0, in.l)), int(rng.integer(0, in.m)),
                                    {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)}, false});
            for (int q = 0; q < 2000; ++q)
                in.shape.push_back({rng.uniform(-2.2, 2.2), rng.uniform(-1, 1)});
            out.push_back(in);
        }
        return out;
    }();
    return v;
}

void BM_MorphFfd_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += MorphFfd::compute(in).deformed.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_MorphFfd_Plain)->Unit(benchmark::kMicrosecond);

void BM_MorphFfd_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<MorphFfd>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<MorphFfd>(MorphFfd::begin(in)).deformed.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_MorphFfd_StateMachine)->Unit(benchmark::kMicrosecond);

void BM_MorphFfd_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "morph-ffd");
}
BENCHMARK(BM_MorphFfd_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_MorphFfd_StepAndPictureCircle(benchmark::State& state) {
    cg::bench::step_and_picture(state, "morph-ffd", [](cg::json& in) {
        in = cg::parse_json(R"({"box": {"min": [-2, -2], "max": [2, 2]}, "degree": [3, 3],
                                "moves": [{"point": [1, 1], "by": [0.8, -0.8]},
                                          {"point": [2, 2], "by": [-0.8, 0.8]}],
                                "shape": [[1.5, 0], [1.3, 0.75], [0.75, 1.3], [0, 1.5],
                                          [-0.75, 1.3], [-1.3, 0.75], [-1.5, 0], [-1.3, -0.75],
                                          [-0.75, -1.3], [0, -1.5], [0.75, -1.3], [1.3, -0.75]],
                                "closed": true})");
    });
}
BENCHMARK(BM_MorphFfd_StepAndPictureCircle)->Unit(benchmark::kMicrosecond);

const std::vector<MorphFfd::Input>& inputs3() {
    static const std::vector<MorphFfd::Input> v = [] {
        cg::Rng rng(42);
        std::vector<MorphFfd::Input> out;
        for (int k = 0; k < 8; ++k) {
            MorphFfd::Input in;
            in.box3_min = {-2, -1, -1};
            in.box3_max = {2, 1, 1};
            in.l = int(rng.integer(1, 4));
            in.m = int(rng.integer(1, 4));
            in.n = int(rng.integer(1, 4));
            for (int q = 0; q < 4; ++q)
                in.moves3.push_back({int(rng.integer(0, in.l)), int(rng.integer(0, in.m)),
                                     int(rng.integer(0, in.n)),
                                     {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)},
                                     false});
            for (int q = 0; q < 1000; ++q)
                in.shape3.push_back({rng.uniform(-2.2, 2.2), rng.uniform(-1, 1), rng.uniform(-1, 1)});
            out.push_back(in);
        }
        return out;
    }();
    return v;
}

void BM_MorphFfdSpace_Plain(benchmark::State& state) {
    const auto& v = inputs3();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += MorphFfd::compute(in).deformed3.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_MorphFfdSpace_Plain)->Unit(benchmark::kMicrosecond);

void BM_MorphFfdSpace_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<MorphFfd>(inputs3());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<MorphFfd>(MorphFfd::begin(in)).deformed3.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_MorphFfdSpace_StateMachine)->Unit(benchmark::kMicrosecond);

void BM_MorphFfdSpace_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "morph-ffd", [](cg::json& in) {
        in = cg::parse_json(R"({"box": {"min": [0, -1, -1], "max": [6, 1, 1]}, "degree": [3, 1, 1],
                                "moves": [{"point": [3, 0, 0], "to": [6, 1, -1]},
                                          {"point": [3, 1, 0], "to": [6, 1, 1]},
                                          {"point": [3, 0, 1], "to": [6, -1, -1]},
                                          {"point": [3, 1, 1], "to": [6, -1, 1]}],
                                "shape": [[0, -0.7, -0.7], [0, 0.7, -0.7], [0, 0.7, 0.7], [0, -0.7, 0.7],
                                          [2, -0.7, -0.7], [2, 0.7, -0.7], [2, 0.7, 0.7], [2, -0.7, 0.7],
                                          [4, -0.7, -0.7], [4, 0.7, -0.7], [4, 0.7, 0.7], [4, -0.7, 0.7],
                                          [6, -0.7, -0.7], [6, 0.7, -0.7], [6, 0.7, 0.7], [6, -0.7, 0.7]],
                                "edges": [[0, 1], [1, 2], [2, 3], [3, 0], [0, 4], [1, 5], [2, 6], [3, 7],
                                          [4, 5], [5, 6], [6, 7], [7, 4], [4, 8], [5, 9], [6, 10], [7, 11],
                                          [8, 9], [9, 10], [10, 11], [11, 8], [8, 12], [9, 13], [10, 14],
                                          [11, 15], [12, 13], [13, 14], [14, 15], [15, 12]]})");
    });
}
BENCHMARK(BM_MorphFfdSpace_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
