// Curves: 10^6 de Casteljau evaluations of random cubics through the state machine vs the
// straight-line function, and the cost of one narrated step plus its picture for each curve
// algorithm.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"

#include <random>

#include "curves/de_casteljau.hpp"
#include "io/registry.hpp"

namespace {

constexpr std::size_t kEvaluations = 1'000'000;

// 4,096 random cubics, each evaluated at its own t; the loops cycle through them.
const std::vector<cg::DeCasteljau::Input>& cubics() {
    static const std::vector<cg::DeCasteljau::Input> inputs = [] {
        std::mt19937_64 rng(42);
        std::uniform_real_distribution<double> u(-10, 10), t(0, 1);
        std::vector<cg::DeCasteljau::Input> v(4096);
        for (auto& in : v) {
            for (int i = 0; i < 4; ++i) in.control_points.push_back({u(rng), u(rng), 0});
            in.t = t(rng);
        }
        return v;
    }();
    return inputs;
}

void BM_Curve_DeCasteljau_Plain(benchmark::State& state) {
    const auto& inputs = cubics();
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < kEvaluations; ++i) {
            const auto r = cg::DeCasteljau::evaluate(inputs[i & 4095]);
            sum += r.point.x + r.tangent.y + r.at(1, 2).x;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kEvaluations));
}
BENCHMARK(BM_Curve_DeCasteljau_Plain)->Unit(benchmark::kMillisecond);

void BM_Curve_DeCasteljau_StateMachine(benchmark::State& state) {
    const auto& inputs = cubics();
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < kEvaluations; ++i) {
            // begin() is start() without re-validating: the inputs are known good.
            const auto r =
                cg::run_to_end<cg::DeCasteljau>(cg::DeCasteljau::begin(inputs[i & 4095]));
            sum += r.point.x + r.tangent.y + r.at(1, 2).x;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kEvaluations));
}
BENCHMARK(BM_Curve_DeCasteljau_StateMachine)->Unit(benchmark::kMillisecond);

using cg::bench::step_and_picture;

void BM_Curve_DeCasteljau_StepAndPicture(benchmark::State& state) {
    step_and_picture(state, "de-casteljau");
}
BENCHMARK(BM_Curve_DeCasteljau_StepAndPicture)->Unit(benchmark::kMicrosecond);
void BM_Curve_Bernstein_StepAndPicture(benchmark::State& state) {
    step_and_picture(state, "bernstein");
}
BENCHMARK(BM_Curve_Bernstein_StepAndPicture)->Unit(benchmark::kMicrosecond);
void BM_Curve_BezierSpline_StepAndPicture(benchmark::State& state) {
    step_and_picture(state, "bezier-spline");
}
BENCHMARK(BM_Curve_BezierSpline_StepAndPicture)->Unit(benchmark::kMicrosecond);
void BM_Curve_ArcLength_StepAndPicture(benchmark::State& state) {
    step_and_picture(state, "arc-length");
}
BENCHMARK(BM_Curve_ArcLength_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
