// Sphere tracing: the state machine run to completion vs the straight-line compute on the
// lesson's kinds of rays (a sphere hit off-centre, a grazing ray out of steps, a union of a
// sphere and a box, a smooth union, a box minus a sphere, a torus skimmed), 100 to 500 steps
// each; and one narrated step plus its picture (the outline by marching squares on a 56-cell
// grid of the field, the march re-run for the view) on the example and on the smooth union.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "io/registry.hpp"
#include "modelling/sphere_tracing.hpp"

namespace {

using cg::SphereTracing;
using Shape = SphereTracing::Shape;
using Kind = SphereTracing::Kind;
using Combine = SphereTracing::Combine;

SphereTracing::Input make(std::vector<Shape> shapes, Combine combine, glm::dvec3 o, glm::dvec3 d,
                          double eps, int steps) {
    SphereTracing::Input in;
    in.shapes = std::move(shapes);
    in.combine = combine;
    in.k = 1.5;
    in.origin = o;
    in.direction = d;
    in.epsilon = eps;
    in.max_distance = 100;
    in.max_steps = steps;
    SphereTracing::validate(in);
    return in;
}

const std::vector<SphereTracing::Input>& inputs() {
    const Shape s1{Kind::Sphere, {12, 3, 0}, {5, 0, 0}};
    const Shape s2{Kind::Sphere, {8, 2, 0}, {2.5, 0, 0}};
    const Shape s3{Kind::Sphere, {12, -1, 0}, {2.5, 0, 0}};
    const Shape b1{Kind::Box, {13, -1, 0}, {2, 2, 2}};
    const Shape b2{Kind::Box, {10, 0, 0}, {3, 3, 3}};
    const Shape t1{Kind::Torus, {10, 0, 0}, {3, 1, 0}};
    static const std::vector<SphereTracing::Input> v = {
        make({s1}, Combine::Union, {0, 0, 0}, {1, 0, 0}, 1e-9, 100),
        make({{Kind::Sphere, {10, 2.02, 0}, {2, 0, 0}}}, Combine::Union, {0, 0, 0}, {1, 0, 0}, 1e-6,
             500),
        make({s2, b1}, Combine::Union, {0, 0, 0}, {1, 0.05, 0}, 1e-6, 200),
        make({s2, s3}, Combine::SmoothUnion, {0, -1.2, 0}, {1, 0.12, 0}, 1e-6, 200),
        make({b2, {Kind::Sphere, {7, 0, 0}, {2.5, 0, 0}}}, Combine::Difference, {0, 0.5, 0},
             {1, 0, 0}, 1e-6, 200),
        make({t1}, Combine::Union, {0, 1.3, 0}, {1, 0, 0}, 1e-6, 200),
    };
    return v;
}

void BM_SphereTracing_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += SphereTracing::compute(in).t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_SphereTracing_Plain)->Unit(benchmark::kMicrosecond);

void BM_SphereTracing_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<SphereTracing>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<SphereTracing>(SphereTracing::begin(in)).t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_SphereTracing_StateMachine)->Unit(benchmark::kMicrosecond);

void BM_SphereTracing_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "sphere-tracing");
}
BENCHMARK(BM_SphereTracing_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_SphereTracing_StepAndPictureSmooth(benchmark::State& state) {
    cg::bench::step_and_picture(state, "sphere-tracing", [](cg::json& in) {
        in = cg::parse_json(R"({"shapes": [{"type": "sphere", "centre": [8, 2, 0], "radius": 2.5},
                                           {"type": "sphere", "centre": [12, -1, 0], "radius": 2.5}],
                                "combine": "smooth-union", "k": 1.5, "origin": [0, -1.2, 0],
                                "direction": [1, 0.12, 0], "epsilon": 0.01, "max_distance": 40,
                                "max_steps": 60})");
    });
}
BENCHMARK(BM_SphereTracing_StepAndPictureSmooth)->Unit(benchmark::kMicrosecond);

}  // namespace
