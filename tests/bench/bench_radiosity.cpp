// Form factors: the state machine run to completion vs the straight-line function on 2,000
// random pairs of patches (every analytic case, rotated and moved; hemicube resolution 8 on
// 3 × 3 points, 1,000 Monte Carlo rays, reciprocity both ways), reported as form factors per
// second; and the cost of one narrated step plus its 3D picture.
#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "radiosity/form_factor.hpp"

namespace {

using cg::Patch;
using glm::dvec3;

const std::vector<cg::FormFactor::Input>& pairs() {
    static const std::vector<cg::FormFactor::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::FormFactor::Input> v;
        v.reserve(2000);
        for (int k = 0; k < 2000; ++k) {
            const dvec3 x = glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 1));
            const dvec3 y = glm::normalize(glm::cross(x, dvec3(0, 1, 0)));
            const dvec3 z = glm::cross(x, y);
            const dvec3 o(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3));
            const double a = rng.uniform(0.3, 2), b = rng.uniform(0.3, 2), c = rng.uniform(0.3, 2);
            cg::FormFactor::Input in;
            switch (k % 3) {
                case 0:
                    in.from = Patch::rectangle(o, a * x, b * y);
                    in.to = Patch::rectangle(o + c * z, b * y, a * x);
                    break;
                case 1:
                    in.from = Patch::rectangle(o, a * x, b * y);
                    in.to = Patch::rectangle(o, c * z, a * x);
                    break;
                default:
                    in.from = Patch::disc(o, z, a);
                    in.to = Patch::disc(o + c * z, -z, b);
                    break;
            }
            in.seed = std::uint64_t(k) + 1;
            cg::FormFactor::validate(in);
            v.push_back(std::move(in));
        }
        return v;
    }();
    return inputs;
}

void BM_FormFactor_Plain(benchmark::State& state) {
    const auto& inputs = pairs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::FormFactor::compute(in).monte_carlo;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());  // form factors (both ways)
}
BENCHMARK(BM_FormFactor_Plain)->Unit(benchmark::kMillisecond);

const std::vector<cg::Shared<cg::FormFactor::Input>>& shared_pairs() {
    static const auto shared = [] {
        std::vector<cg::Shared<cg::FormFactor::Input>> v;
        for (const auto& in : pairs()) v.emplace_back(in);
        return v;
    }();
    return shared;
}

void BM_FormFactor_StateMachine(benchmark::State& state) {
    const auto& inputs = shared_pairs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            cg::FormFactor::State s;  // start() without re-validating: inputs are known good
            s.in = in;
            s.rng = cg::Rng(in->seed);
            s.batch_rng = s.rng;
            sum += cg::run_to_end<cg::FormFactor>(std::move(s)).monte_carlo;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_FormFactor_StateMachine)->Unit(benchmark::kMillisecond);

void BM_FormFactor_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "form-factor");
}
BENCHMARK(BM_FormFactor_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
