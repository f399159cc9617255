// Orientation interpolation: the state machine run to completion vs the straight-line compute
// on 60 random inputs (2 to 6 keys of every form, 24 frames a segment, Euler, matrix, slerp and
// squad with their speeds); and the cost of one narrated step plus its picture on the example
// (two keys, 4 frames) and on the lesson's four-key squad preset (12 frames a segment).
#include <benchmark/benchmark.h>

#include "animation/orientation_interpolation.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using cg::OrientationInterpolation;
using OI = OrientationInterpolation;

const std::vector<OI::Input>& inputs() {
    static const std::vector<OI::Input> v = [] {
        cg::Rng rng(44);
        const char* orders[] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx"};
        std::vector<OI::Input> out;
        for (int t = 0; t < 60; ++t) {
            OI::Input in;
            in.order = orders[rng.integer(0, 5)];
            const int n = int(rng.integer(2, 6));
            for (int i = 0; i < n; ++i) {
                OI::Key k;
                k.form = OI::Form(rng.integer(0, 2));
                k.euler_deg = {rng.uniform(-180, 180), rng.uniform(-90, 90), rng.uniform(-180, 180)};
                k.axis = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.1, 1)};
                k.angle_deg = rng.uniform(-180, 180);
                k.q = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), 1};
                in.keys.push_back(k);
            }
            in.frames = 24;
            out.push_back(in);
        }
        return out;
    }();
    return v;
}

void BM_OrientationInterpolation_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += OI::compute(in).min_det;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_OrientationInterpolation_Plain)->Unit(benchmark::kMillisecond);

void BM_OrientationInterpolation_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<OI>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared) sum += cg::run_to_end<OI>(OI::begin(in)).min_det;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_OrientationInterpolation_StateMachine)->Unit(benchmark::kMillisecond);

void BM_OrientationInterpolation_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "orientation-interpolation");
}
BENCHMARK(BM_OrientationInterpolation_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_OrientationInterpolation_StepAndPictureSquad(benchmark::State& state) {
    cg::bench::step_and_picture(state, "orientation-interpolation", [](cg::json& in) {
        in = cg::parse_json(R"({"keys": [{"axis": [0, 0, 1], "angle": 0},
                                         {"axis": [1, 0, 0], "angle": 90},
                                         {"axis": [1, 1, 0], "angle": 150},
                                         {"axis": [0, 1, 0], "angle": 60}],
                                "order": "xyz", "frames": 12, "segment_time": 1})");
    });
}
BENCHMARK(BM_OrientationInterpolation_StepAndPictureSquad)->Unit(benchmark::kMicrosecond);

}  // namespace
