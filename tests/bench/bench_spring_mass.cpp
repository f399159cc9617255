// Spring-mass: the state machine run to completion vs the straight-line compute on 60 random
// systems (20 per integrator: chains of 8 to 32 masses and 6 × 6 cloths, 200 steps each); and
// the cost of one narrated step plus its picture on the example (one spring) and on the 8 × 8
// cloth patch of the lesson.
#include <benchmark/benchmark.h>

#include "animation/spring_mass.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using cg::SpringMass;

const std::vector<SpringMass::Input>& inputs() {
    static const std::vector<SpringMass::Input> v = [] {
        cg::Rng rng(33);
        std::vector<SpringMass::Input> out;
        for (int k = 0; k < 60; ++k) {
            SpringMass::Input in;
            if (k % 2 == 0) {  // a chain hanging from its first mass
                const int n = int(rng.integer(8, 32));
                for (int i = 0; i < n; ++i) {
                    SpringMass::Mass m;
                    m.position = {0.1 * i, rng.uniform(-0.01, 0.01), 0};
                    m.mass = 0.05;
                    m.pinned = i == 0;
                    in.masses.push_back(m);
                    if (i > 0) {
                        SpringMass::Spring s;
                        s.i = i - 1;
                        s.j = i;
                        s.stiffness = 100;
                        s.damping = 0.05;
                        in.springs.push_back(s);
                    }
                }
            } else {  // a 6 × 6 cloth pinned at two corners, with shear springs
                const int n = 6;
                for (int r = 0; r < n; ++r)
                    for (int c = 0; c < n; ++c) {
                        SpringMass::Mass m;
                        m.position = {0.1 * c, 0, 0.1 * r};
                        m.mass = 0.01;
                        m.pinned = r == 0 && (c == 0 || c == n - 1);
                        in.masses.push_back(m);
                    }
                auto add = [&](int a, int b) {
                    SpringMass::Spring s;
                    s.i = a;
                    s.j = b;
                    s.stiffness = 50;
                    s.damping = 0.02;
                    in.springs.push_back(s);
                };
                for (int r = 0; r < n; ++r)
                    for (int c = 0; c < n; ++c) {
                        const int id = r * n + c;
                        if (c + 1 < n) add(id, id + 1);
                        if (r + 1 < n) add(id, id + n);
                        if (c + 1 < n && r + 1 < n) add(id, id + n + 1), add(id + 1, id + n);
                    }
            }
            in.dt = 0.002;
            in.steps = 200;
            in.integrator = SpringMass::Integrator((k / 2) % 3);
            out.push_back(SpringMass::resolve(in));
        }
        return out;
    }();
    return v;
}

void BM_SpringMass_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += SpringMass::compute(in).max_drift;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_SpringMass_Plain)->Unit(benchmark::kMillisecond);

void BM_SpringMass_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<SpringMass>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<SpringMass>(SpringMass::begin(in)).max_drift;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_SpringMass_StateMachine)->Unit(benchmark::kMillisecond);

void BM_SpringMass_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "spring-mass");
}
BENCHMARK(BM_SpringMass_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_SpringMass_StepAndPictureCloth(benchmark::State& state) {
    cg::bench::step_and_picture(state, "spring-mass", [](cg::json& in) {
        in = cg::parse_json(R"({"cloth": {"rows": 8, "cols": 8, "spacing": 0.1, "mass": 0.01,
                                "stiffness": 50, "damping": 0.02}, "dt": 0.002, "steps": 750,
                                "watch": 63})");
    });
}
BENCHMARK(BM_SpringMass_StepAndPictureCloth)->Unit(benchmark::kMicrosecond);

}  // namespace
