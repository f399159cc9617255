// Acceleration: the bounding volume hierarchy (bvh) — the plain build-and-trace function vs
// the state machine run to the end on the same 200 random scenes of 64 primitives (spheres,
// boxes, triangles; both splits; one ray each), and one narrated step plus its picture through
// the registry (the example, and a 64-sphere scene).
#include <benchmark/benchmark.h>

#include "accel/bvh.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"

namespace {

const std::vector<cg::Bvh::Input>& scenes() {
    static const std::vector<cg::Bvh::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::Bvh::Input> v(200);
        for (std::size_t k = 0; k < v.size(); ++k) {
            cg::Bvh::Input& in = v[k];
            in.split = k % 2 ? cg::Bvh::Split::Sah : cg::Bvh::Split::Median;
            in.max_leaf = 1 + static_cast<int>(k % 3);
            auto point = [&](double s) {
                return glm::dvec3(rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s));
            };
            for (int i = 0; i < 64; ++i) {
                cg::Primitive p;
                const double what = rng.uniform(0, 1);
                if (what < 0.4) {
                    p.kind = cg::PrimitiveKind::Sphere, p.a = point(10),
                    p.radius = rng.uniform(0.2, 1.5);
                } else if (what < 0.7) {
                    p.kind = cg::PrimitiveKind::Box, p.a = point(10),
                    p.b = p.a + glm::dvec3(rng.uniform(0.2, 2));
                } else {
                    p.kind = cg::PrimitiveKind::Triangle, p.a = point(10);
                    p.b = p.a + glm::dvec3(1.5, 0.2, 0.1), p.c = p.a + glm::dvec3(0.1, 1.5, 0.3);
                }
                in.primitives.push_back(p);
            }
            in.origin = point(15);
            in.direction = point(10) - in.origin;
        }
        return v;
    }();
    return inputs;
}

void BM_Bvh_Plain(benchmark::State& state) {
    const auto& inputs = scenes();
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : inputs) sum += cg::Bvh::build_and_trace(in).primitive_tests;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_Bvh_Plain)->Unit(benchmark::kMillisecond);

void BM_Bvh_StateMachine(benchmark::State& state) {
    // begin() without re-validating (the inputs are known good), each input shared once as
    // the viewer shares it.
    static const std::vector<cg::Shared<cg::Bvh::Input>> inputs = [] {
        std::vector<cg::Shared<cg::Bvh::Input>> v;
        for (const auto& in : scenes()) v.emplace_back(in);
        return v;
    }();
    for (auto _ : state) {
        long long sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::Bvh>(cg::Bvh::begin(in)).primitive_tests;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_Bvh_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Bvh_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "bvh");
}
BENCHMARK(BM_Bvh_StepAndPicture)->Unit(benchmark::kMicrosecond);

// 64 spheres in a 4 × 4 × 4 lattice: the biggest lesson-size picture.
void BM_Bvh_StepAndPicture64(benchmark::State& state) {
    cg::bench::step_and_picture(state, "bvh", [](cg::json& in) {
        cg::json ps = cg::json::array();
        for (int i = 0; i < 64; ++i)
            ps.push_back({{"type", "sphere"},
                          {"center", {3 * (i % 4), 3 * (i / 4 % 4), 3 * (i / 16)}},
                          {"radius", 1}});
        in["primitives"] = ps;
    });
}
BENCHMARK(BM_Bvh_StepAndPicture64)->Unit(benchmark::kMicrosecond);

}  // namespace
