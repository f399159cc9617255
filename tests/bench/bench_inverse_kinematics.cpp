// Inverse kinematics: the state machine run to completion vs the straight-line compute on 60
// random reachable problems (20 per iterative solver: planar and 3D chains of 3 to 8 links, at
// most 100 iterations); and the cost of one narrated step plus its picture on the example (a
// three-link CCD arm) and on the lesson's 3D chain by damped least squares.
#include <benchmark/benchmark.h>

#include "animation/inverse_kinematics.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using cg::InverseKinematics;
using IK = InverseKinematics;

const std::vector<IK::Input>& inputs() {
    static const std::vector<IK::Input> v = [] {
        cg::Rng rng(324);
        std::vector<IK::Input> out;
        for (int k = 0; k < 60; ++k) {
            IK::Input in;
            const int n = int(rng.integer(3, 8));
            const bool planar = k % 2 == 0;
            for (int i = 0; i < n; ++i) {
                in.lengths.push_back(rng.uniform(0.5, 1.5));
                in.angles.push_back(rng.uniform(-30, 30));
                if (!planar)
                    in.axes.push_back(
                        {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.2, 1)});
            }
            in.method = IK::Method(2 + (k / 2) % 3);
            in.iterations = 100;
            in.damping = 0.1;
            // A reachable target: the end of the chain at other angles.
            IK::Input goal = in;
            goal.method = IK::Method::Forward;
            for (double& a : goal.angles) a = rng.uniform(-90, 90);
            in.target = IK::compute(goal).end;
            in.has_target = true;
            out.push_back(IK::resolve(in));
        }
        return out;
    }();
    return v;
}

void BM_InverseKinematics_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += IK::compute(in).error;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_InverseKinematics_Plain)->Unit(benchmark::kMillisecond);

void BM_InverseKinematics_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<IK>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared) sum += cg::run_to_end<IK>(IK::begin(in)).error;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_InverseKinematics_StateMachine)->Unit(benchmark::kMillisecond);

void BM_InverseKinematics_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "inverse-kinematics");
}
BENCHMARK(BM_InverseKinematics_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_InverseKinematics_StepAndPicture3D(benchmark::State& state) {
    cg::bench::step_and_picture(state, "inverse-kinematics", [](cg::json& in) {
        in = cg::parse_json(R"({"lengths": [1.2, 1, 1, 0.8],
            "axes": [[0, 1, 0], [0, 0, 1], [0, 0, 1], [1, 0, 0]], "angles": [0, 20, 20, 0],
            "target": [1, 2, 1.5], "method": "dls", "damping": 0.5, "iterations": 100})");
    });
}
BENCHMARK(BM_InverseKinematics_StepAndPicture3D)->Unit(benchmark::kMicrosecond);

}  // namespace
