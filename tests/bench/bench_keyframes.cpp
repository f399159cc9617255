// Keyframes: the state machine run to completion vs the straight-line compute on 60 random
// channels (a third each linear, Catmull–Rom, Kochanek–Bartels; 4 to 24 keys; scalar, 2D and 3D;
// every 2D/3D one also at constant speed with a 128-sample arc-length table; about 600 frames
// each). Both start from the JSON-free input and include the preparation (validation,
// tangents, table). And the cost of one narrated step plus its picture on the example and on
// the constant-speed path.
#include <benchmark/benchmark.h>

#include "animation/keyframes.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using cg::Keyframes;

const std::vector<Keyframes::Input>& inputs() {
    static const std::vector<Keyframes::Input> v = [] {
        cg::Rng rng(33);
        std::vector<Keyframes::Input> out;
        for (int k = 0; k < 60; ++k) {
            Keyframes::Input in;
            in.dim = 1 + k % 3;
            const int n = int(rng.integer(4, 24));
            double t = 0;
            for (int i = 0; i < n; ++i) {
                Keyframes::Key key;
                key.t = t;
                t += rng.uniform(0.2, 1.5);
                for (int d = 0; d < in.dim; ++d) key.value[d] = rng.uniform(-5, 5);
                key.tension = rng.uniform(-0.5, 0.5);
                key.continuity = rng.uniform(-0.5, 0.5);
                key.bias = rng.uniform(-0.5, 0.5);
                in.keys.push_back(key);
            }
            in.interpolation = Keyframes::Interpolation((k / 3) % 3);
            in.dt = (t - in.keys.front().t) / 600;
            in.constant_speed = in.dim > 1;
            in.samples = 128;
            out.push_back(in);
        }
        return out;
    }();
    return v;
}

void BM_Keyframes_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += Keyframes::compute(in).speed_max;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_Keyframes_Plain)->Unit(benchmark::kMillisecond);

void BM_Keyframes_StateMachine(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += cg::run_to_end<Keyframes>(Keyframes::start(in)).speed_max;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_Keyframes_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Keyframes_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "keyframes");
}
BENCHMARK(BM_Keyframes_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_Keyframes_StepAndPicturePath(benchmark::State& state) {
    cg::bench::step_and_picture(state, "keyframes", [](cg::json& in) {
        in = cg::parse_json(R"({"keys": [{"t": 0, "value": [0, 0]}, {"t": 1, "value": [1, 0]},
                                {"t": 2, "value": [6, 2]}, {"t": 3, "value": [7, 5]},
                                {"t": 4, "value": [3, 6]}],
                                "dt": 0.05, "constant_speed": true})");
    });
}
BENCHMARK(BM_Keyframes_StepAndPicturePath)->Unit(benchmark::kMicrosecond);

}  // namespace
