// The 3D rotations (arbitrary axis, slerp, Euler angles): each state machine run to completion
// vs its straight-line function on 10^5 random inputs; and the cost of one narrated step plus
// its 3D picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "transforms/arbitrary_axis.hpp"
#include "transforms/euler_angles.hpp"
#include "transforms/slerp.hpp"

namespace {

const std::vector<cg::ArbitraryAxis::Input>& axes() {
    static const std::vector<cg::ArbitraryAxis::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::ArbitraryAxis::Input> v(100'000);
        for (auto& in : v) {
            in.axis = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            in.angle_deg = rng.uniform(-180, 180);
            in.points = {{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)}};
        }
        return v;
    }();
    return inputs;
}

void BM_ArbitraryAxis_Plain(benchmark::State& state) {
    const auto& inputs = axes();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::ArbitraryAxis::rotate(in).points.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ArbitraryAxis_Plain)->Unit(benchmark::kMillisecond);

void BM_ArbitraryAxis_StateMachine(benchmark::State& state) {
    const auto inputs = cg::bench::shared_inputs<cg::ArbitraryAxis>(axes());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::ArbitraryAxis>(cg::ArbitraryAxis::begin(in)).points.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ArbitraryAxis_StateMachine)->Unit(benchmark::kMillisecond);

void BM_ArbitraryAxis_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "arbitrary-axis");
}
BENCHMARK(BM_ArbitraryAxis_StepAndPicture)->Unit(benchmark::kMicrosecond);

// Slerp: the plain function computes only q(u) and its matrix, so the state machine is run
// to the matrix step (the nine comparison samples are the lesson's extra, measured apart).
const std::vector<cg::Slerp::Input>& pairs() {
    static const std::vector<cg::Slerp::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::Slerp::Input> v(100'000);
        for (auto& in : v) {
            in.q0 = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1),
                     rng.uniform(-1, 1)};
            in.q1 = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1),
                     rng.uniform(-1, 1)};
            in.u = rng.uniform(0, 1);
        }
        return v;
    }();
    return inputs;
}

void BM_Slerp_Plain(benchmark::State& state) {
    const auto& inputs = pairs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::Slerp::interpolate(in).matrix[0][0];
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_Slerp_Plain)->Unit(benchmark::kMillisecond);

[[gnu::flatten]] double slerp_machine(const cg::Slerp::Input& in) {
    cg::Slerp::State s;
    s.in = in;
    while (s.phase != cg::Slerp::Phase::Sample) cg::Slerp::step(s, nullptr);
    return s.matrix[0][0];
}

void BM_Slerp_StateMachine(benchmark::State& state) {
    const auto& inputs = pairs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += slerp_machine(in);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_Slerp_StateMachine)->Unit(benchmark::kMillisecond);

// The whole lesson run, with the nine samples of the three paths.
void BM_Slerp_StateMachineWithPaths(benchmark::State& state) {
    const auto& inputs = pairs();
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < inputs.size(); i += 10) {
            cg::Slerp::State s;
            s.in = inputs[i];
            sum += cg::run_to_end<cg::Slerp>(std::move(s)).matrix[0][0];
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * (inputs.size() / 10));
}
BENCHMARK(BM_Slerp_StateMachineWithPaths)->Unit(benchmark::kMillisecond);

void BM_Slerp_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "slerp");
}
BENCHMARK(BM_Slerp_StepAndPicture)->Unit(benchmark::kMicrosecond);

const std::vector<cg::EulerAngles::Input>& eulers() {
    static const std::vector<cg::EulerAngles::Input> inputs = [] {
        static const char* kOrders[] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx"};
        cg::Rng rng(42);
        std::vector<cg::EulerAngles::Input> v(100'000);
        for (auto& in : v) {
            in.order = kOrders[rng.integer(0, 5)];
            in.angles_deg = {rng.uniform(-180, 180), rng.uniform(-90, 90), rng.uniform(-180, 180)};
        }
        return v;
    }();
    return inputs;
}

void BM_EulerAngles_Plain(benchmark::State& state) {
    const auto& inputs = eulers();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::EulerAngles::compose(in).matrix[0][0];
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_EulerAngles_Plain)->Unit(benchmark::kMillisecond);

void BM_EulerAngles_StateMachine(benchmark::State& state) {
    const auto& inputs = eulers();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            cg::EulerAngles::State s;
            s.in = in;
            sum += cg::run_to_end<cg::EulerAngles>(std::move(s)).matrix[0][0];
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_EulerAngles_StateMachine)->Unit(benchmark::kMillisecond);

void BM_EulerAngles_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "euler-angles");
}
BENCHMARK(BM_EulerAngles_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
