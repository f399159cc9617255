// Aliasing and anti-aliasing: supersampling one pixel (the state machine run to the end vs the
// plain function, on 2,000 random pixels with 16 jittered samples, and on Poisson dart
// throwing); one narrated step plus its picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "sampling/supersampling.hpp"

namespace {

std::vector<cg::Supersampling::Input> pixels(cg::sampling::Pattern pattern, int samples,
                                             cg::sampling::Filter filter) {
    cg::Rng rng(42);
    std::vector<cg::Supersampling::Input> v(2000);
    for (std::size_t k = 0; k < v.size(); ++k) {
        auto& in = v[k];
        in.pattern = pattern;
        in.samples = samples;
        in.filter = filter;
        in.i = static_cast<int>(rng.integer(0, 99));
        in.j = static_cast<int>(rng.integer(0, 99));
        in.scene.kind = cg::sampling::RegionKind::Edge;
        const double x = in.i + rng.uniform(0, 1);
        const double y = in.j + rng.uniform(0, 1);
        in.scene.point = {x, y};
        in.scene.angle_deg = rng.uniform(0, 360);
        in.seed = k;
    }
    return v;
}

const std::vector<cg::Supersampling::Input>& jittered16() {
    static const auto v = pixels(cg::sampling::Pattern::Jittered, 16, cg::sampling::Filter::Tent);
    return v;
}
const std::vector<cg::Supersampling::Input>& poisson16() {
    static const auto v = pixels(cg::sampling::Pattern::Poisson, 16, cg::sampling::Filter::Box);
    return v;
}

void plain(benchmark::State& state, const std::vector<cg::Supersampling::Input>& inputs) {
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::Supersampling::supersample(in).error;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void machine(benchmark::State& state, const std::vector<cg::Supersampling::Input>& inputs) {
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            cg::Supersampling::State s;  // start() without re-validating: inputs are known good
            s.in = cg::Shared<cg::Supersampling::Input>(in);
            s.radius = cg::Supersampling::radius_of(in);
            sum += cg::run_to_end<cg::Supersampling>(std::move(s)).error;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void BM_Supersampling_Plain(benchmark::State& state) {
    plain(state, jittered16());
}
BENCHMARK(BM_Supersampling_Plain)->Unit(benchmark::kMillisecond);
void BM_Supersampling_StateMachine(benchmark::State& state) {
    machine(state, jittered16());
}
BENCHMARK(BM_Supersampling_StateMachine)->Unit(benchmark::kMillisecond);
void BM_Supersampling_Poisson_Plain(benchmark::State& state) {
    plain(state, poisson16());
}
BENCHMARK(BM_Supersampling_Poisson_Plain)->Unit(benchmark::kMillisecond);
void BM_Supersampling_Poisson_StateMachine(benchmark::State& state) {
    machine(state, poisson16());
}
BENCHMARK(BM_Supersampling_Poisson_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Supersampling_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "supersampling");
}
BENCHMARK(BM_Supersampling_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
