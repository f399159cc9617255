// Ray tracing: ray-quadric intersection and Phong lighting, the state machine run to completion
// vs the plain function, on 10^5 random rays (all six quadrics, half of them transformed) and
// 10^5 random shading points (one to three lights); and one narrated step plus its picture.
#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "rays/phong_lighting.hpp"
#include "rays/ray_quadric.hpp"

namespace {

const std::vector<cg::RayQuadric::Input>& rays() {
    static const std::vector<cg::RayQuadric::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::RayQuadric::Input> v(100'000);
        for (auto& in : v) {
            cg::Quadric& q = in.quadric;
            q.kind = static_cast<cg::QuadricKind>(rng.integer(0, 5));
            q.r = rng.uniform(0.5, 2), q.a = rng.uniform(0.5, 2), q.b = rng.uniform(0.5, 2);
            q.c = rng.uniform(0.5, 2), q.p = rng.uniform(0.5, 2), q.q = rng.uniform(0.5, 2);
            if (rng.chance(0.5)) {
                glm::dmat4 m = glm::translate(glm::dmat4(1.0), {rng.uniform(-1, 1), 0, 0});
                m = glm::rotate(m, rng.uniform(0, 3), glm::dvec3(0.6, 0, 0.8));
                q.world_from_model = glm::scale(m, {rng.uniform(0.5, 2), 1, rng.uniform(0.5, 2)});
            }
            in.origin = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
            in.direction = glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) -
                           0.2 * in.origin;
        }
        return v;
    }();
    return inputs;
}

void BM_RayQuadric_Plain(benchmark::State& state) {
    const auto& inputs = rays();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::RayQuadric::solve(in).t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_RayQuadric_Plain)->Unit(benchmark::kMillisecond);

void BM_RayQuadric_StateMachine(benchmark::State& state) {
    const auto inputs = cg::bench::shared_inputs<cg::RayQuadric>(rays());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::RayQuadric>(cg::RayQuadric::begin(in)).t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_RayQuadric_StateMachine)->Unit(benchmark::kMillisecond);

// What a tracer pays per ray when a scene of 16 surfaces is prepared once (no inverse per
// call): the same 10^5 rays, ray i against surface i mod 16.
void BM_RayQuadric_Prepared(benchmark::State& state) {
    const auto& inputs = rays();
    std::vector<cg::PreparedQuadric> scene;
    for (std::size_t i = 0; i < 16; ++i) scene.push_back(cg::prepare(inputs[i].quadric));
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < inputs.size(); ++i)
            sum += cg::intersect(scene[i % 16], inputs[i].origin, inputs[i].direction).t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_RayQuadric_Prepared)->Unit(benchmark::kMillisecond);

void BM_RayQuadric_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "ray-quadric");
}
BENCHMARK(BM_RayQuadric_StepAndPicture)->Unit(benchmark::kMicrosecond);

const std::vector<cg::PhongLighting::Input>& shading_points() {
    static const std::vector<cg::PhongLighting::Input> inputs = [] {
        cg::Rng rng(7);
        auto rv = [&](double lo, double hi) {
            return glm::dvec3(rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi));
        };
        std::vector<cg::PhongLighting::Input> v(100'000);
        for (auto& in : v) {
            in.model = rng.chance(0.5) ? cg::PhongLighting::Model::Phong
                                       : cg::PhongLighting::Model::BlinnPhong;
            in.rgb = true;
            in.point = rv(-1, 1);
            in.normal = rv(-1, 1);
            in.eye = rv(-10, 10);
            in.ambient = rv(0, 0.3);
            in.material = {rv(0, 1), rv(0, 1), rv(0, 1), rng.uniform(1, 100)};
            const int n = static_cast<int>(rng.integer(1, 3));
            for (int i = 0; i < n; ++i) {
                cg::PhongLighting::Light L;
                L.intensity = rv(0, 1);
                if (rng.chance(0.3)) {
                    L.directional = true;
                    L.direction = rv(-1, 1);
                } else {
                    L.position = rv(-10, 10);
                    L.attenuation = {1, 0.1, 0.01};
                }
                in.lights.push_back(L);
            }
        }
        return v;
    }();
    return inputs;
}

void BM_PhongLighting_Plain(benchmark::State& state) {
    const auto& inputs = shading_points();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::PhongLighting::shade(in).intensity.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_PhongLighting_Plain)->Unit(benchmark::kMillisecond);

void BM_PhongLighting_StateMachine(benchmark::State& state) {
    const auto inputs = cg::bench::shared_inputs<cg::PhongLighting>(shading_points());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::PhongLighting>(cg::PhongLighting::begin(in)).intensity.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_PhongLighting_StateMachine)->Unit(benchmark::kMillisecond);

void BM_PhongLighting_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "phong-lighting");
}
BENCHMARK(BM_PhongLighting_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
