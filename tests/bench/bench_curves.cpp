// Curves: 10^6 de Casteljau evaluations of random cubics and 10^4 bicubic patch runs through
// the state machine vs the straight-line functions, and the cost of one narrated step plus its
// picture for each curve algorithm.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"

#include <random>

#include "curves/bezier_patch.hpp"
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

// 1,024 random bicubic patches, each evaluated at its own (s, t) with the point, both partial
// derivatives, the normal and an 8 × 8 tessellation (81 vertices): the whole run.
constexpr std::size_t kPatches = 10'000;

const std::vector<cg::BezierPatch::Input>& bicubics() {
    static const std::vector<cg::BezierPatch::Input> inputs = [] {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> u(-10, 10), t(0, 1);
        std::vector<cg::BezierPatch::Input> v(1024);
        for (auto& in : v) {
            in.control_points.assign(4, {});
            for (auto& row : in.control_points)
                for (int j = 0; j < 4; ++j) row.push_back({u(rng), u(rng), u(rng)});
            in.s = t(rng), in.t = t(rng);
        }
        return v;
    }();
    return inputs;
}

void BM_Curve_BezierPatch_Plain(benchmark::State& state) {
    const auto& inputs = bicubics();
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < kPatches; ++i) {
            const auto r = cg::BezierPatch::evaluate(inputs[i & 1023]);
            sum += r.point.x + r.normal.y + r.vertices[40].z;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kPatches));
}
BENCHMARK(BM_Curve_BezierPatch_Plain)->Unit(benchmark::kMillisecond);

void BM_Curve_BezierPatch_StateMachine(benchmark::State& state) {
    const auto& inputs = bicubics();
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < kPatches; ++i) {
            const auto r =
                cg::run_to_end<cg::BezierPatch>(cg::BezierPatch::begin(inputs[i & 1023]));
            sum += r.point.x + r.normal.y + r.vertices[40].z;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kPatches));
}
BENCHMARK(BM_Curve_BezierPatch_StateMachine)->Unit(benchmark::kMillisecond);

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
void BM_Curve_BezierPatch_StepAndPicture(benchmark::State& state) {
    step_and_picture(state, "bezier-patch");
}
BENCHMARK(BM_Curve_BezierPatch_StepAndPicture)->Unit(benchmark::kMicrosecond);
void BM_Curve_ArcLength_StepAndPicture(benchmark::State& state) {
    step_and_picture(state, "arc-length");
}
BENCHMARK(BM_Curve_ArcLength_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
