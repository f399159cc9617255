// Particle systems: the state machine run to completion vs the straight-line compute on 24
// random systems (fountains, sprays on a tilted plane and drag-only clouds; 20 to 120 particles a
// second for 150 frames, about 100 to 400 alive at once); and the cost of one narrated frame plus
// its picture on the example (a 40-frame fountain) and on the lesson's fountain (about 90 alive).
#include <benchmark/benchmark.h>

#include "animation/particles.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using cg::Particles;

const std::vector<Particles::Input>& inputs() {
    static const std::vector<Particles::Input> v = [] {
        cg::Rng rng(23);
        std::vector<Particles::Input> out;
        for (int k = 0; k < 24; ++k) {
            Particles::Input in;
            Particles::Emitter& e = in.emitter;
            e.shape = Particles::Shape(k % 3);
            e.position = {0, 0.5, 0};
            e.end = {1, 0.5, 0};
            e.radius = 0.3;
            e.velocity = {rng.uniform(-2, 2), rng.uniform(4, 8), 0};
            e.spread = rng.uniform(5, 40);
            e.jitter = 0.1;
            e.life_min = 1.5;
            e.life_max = 3;
            e.rate = rng.uniform(20, 120);
            if (k % 4 != 3) {
                in.plane.on = true;
                in.plane.normal = k % 2 ? glm::dvec3(0, 1, 0) : glm::dvec3(0.2, 1, 0);
                in.plane.restitution = 0.6;
                in.plane.friction = 0.2;
            } else {
                in.drag = 1;
            }
            in.dt = 0.02;
            in.frames = 150;
            in.seed = std::uint64_t(k);
            out.push_back(Particles::resolve(in));
        }
        return out;
    }();
    return v;
}

void BM_Particles_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : v) sum += Particles::compute(in).bounces;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_Particles_Plain)->Unit(benchmark::kMillisecond);

void BM_Particles_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<Particles>(inputs());
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<Particles>(Particles::begin(in)).bounces;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_Particles_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Particles_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "particles");
}
BENCHMARK(BM_Particles_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_Particles_StepAndPictureFountain(benchmark::State& state) {
    cg::bench::step_and_picture(state, "particles", [](cg::json& in) {
        in = cg::parse_json(R"({"emitter": {"position": [0, 0.1, 0], "velocity": [0, 7, 0],
            "spread": 12, "jitter": 0.1, "lifetime": [1.2, 1.6], "rate": 60},
            "plane": {"restitution": 0.3, "friction": 0.3}, "dt": 0.04, "frames": 125,
            "seed": 3, "focus": 40})");
    });
}
BENCHMARK(BM_Particles_StepAndPictureFountain)->Unit(benchmark::kMicrosecond);

}  // namespace
