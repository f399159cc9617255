// Flat, Gouraud and Phong shading: the state machine run to completion vs the straight-line
// function, per model, on 50 random height-field meshes (8 × 8 vertices, 98 triangles) over a
// 128 × 96 image (about 12,000 pixels each); and the cost of one narrated step plus its picture
// at the lesson's sizes (the example, 16 × 12, and the lesson's first preset, 32 × 24).
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "shading/shading.hpp"

namespace {

using cg::Shading;

const std::vector<Shading::Input>& meshes(Shading::Model model) {
    static std::array<std::vector<Shading::Input>, 3> all;
    auto& v = all[static_cast<int>(model)];
    if (v.empty()) {
        cg::Rng rng(42);
        v.resize(50);
        for (auto& in : v) {
            in.width = 128, in.height = 96;
            in.model = model;
            const int n = 8;
            for (int b = 0; b < n; ++b)
                for (int a = 0; a < n; ++a)
                    in.mesh.vertices.push_back(
                        {-1 + 130.0 * a / (n - 1) + rng.uniform(-3, 3) * (a % (n - 1) != 0),
                         -1 + 98.0 * b / (n - 1) + rng.uniform(-3, 3) * (b % (n - 1) != 0),
                         rng.uniform(0, 20)});
            for (int b = 0; b + 1 < n; ++b)
                for (int a = 0; a + 1 < n; ++a) {
                    const long long v00 = b * n + a;
                    in.mesh.triangles.push_back({v00, v00 + 1, v00 + n + 1});
                    in.mesh.triangles.push_back({v00, v00 + n + 1, v00 + n});
                }
            in.lighting.model = cg::PhongLighting::Model::BlinnPhong;
            in.lighting.eye = {64, 48, -100};
            in.lighting.ambient = glm::dvec3(0.2);
            in.lighting.material.ka = glm::dvec3(0.5);
            in.lighting.material.kd = glm::dvec3(0.6);
            in.lighting.material.ks = glm::dvec3(0.4);
            in.lighting.material.shininess = 20;
            cg::PhongLighting::Light light;
            light.position = {20, 80, -60};
            in.lighting.lights.push_back(light);
        }
    }
    return v;
}

// Each loop keeps every mesh's result until the next pass replaces it (as the viewer keeps a
// run): when each result was freed at once, glibc returned the emptied heap to the system and
// the next run page-faulted it back, in one loop or the other by the luck of the heap's layout
// (10^5 page faults a second; the ratio swung from 0.5 to 2 between builds).
void plain(benchmark::State& state, Shading::Model model) {
    const auto& inputs = meshes(model);
    std::vector<Shading::Result> results(inputs.size());
    for (auto _ : state) {
        long long evaluations = 0;
        for (std::size_t k = 0; k < inputs.size(); ++k) {
            results[k] = Shading::render(inputs[k]);
            evaluations += results[k].evaluations;
        }
        benchmark::DoNotOptimize(evaluations);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void machine(benchmark::State& state, Shading::Model model) {
    const auto& inputs = meshes(model);
    std::vector<Shading::Result> results(inputs.size());
    for (auto _ : state) {
        long long evaluations = 0;
        for (std::size_t k = 0; k < inputs.size(); ++k) {
            results[k] = cg::run_to_end<Shading>(Shading::start(inputs[k]));
            evaluations += results[k].evaluations;
        }
        benchmark::DoNotOptimize(evaluations);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void BM_Shading_Flat_Plain(benchmark::State& s) {
    plain(s, Shading::Model::Flat);
}
void BM_Shading_Flat_StateMachine(benchmark::State& s) {
    machine(s, Shading::Model::Flat);
}
void BM_Shading_Gouraud_Plain(benchmark::State& s) {
    plain(s, Shading::Model::Gouraud);
}
void BM_Shading_Gouraud_StateMachine(benchmark::State& s) {
    machine(s, Shading::Model::Gouraud);
}
void BM_Shading_Phong_Plain(benchmark::State& s) {
    plain(s, Shading::Model::Phong);
}
void BM_Shading_Phong_StateMachine(benchmark::State& s) {
    machine(s, Shading::Model::Phong);
}
BENCHMARK(BM_Shading_Flat_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Shading_Flat_StateMachine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Shading_Gouraud_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Shading_Gouraud_StateMachine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Shading_Phong_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Shading_Phong_StateMachine)->Unit(benchmark::kMillisecond);

// What the viewer pays per step: a narrated step through the registry plus the scene (the
// example, 16 × 12; the other two models' images are made on the first draw and shared).
void BM_Shading_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "shading");
}
BENCHMARK(BM_Shading_StepAndPicture)->Unit(benchmark::kMicrosecond);

// The same on the lesson's largest pictures: a 32 × 24 image (a faceted cylinder, Gouraud).
void BM_Shading_StepAndPicture_Lesson(benchmark::State& state) {
    cg::bench::step_and_picture(state, "shading", [](cg::json& in) {
        in["width"] = 32, in["height"] = 24;
        for (auto& v : in["mesh"]["vertices"])
            v[0] = v[0].get<double>() * 2, v[1] = v[1].get<double>() * 2;
        in["model"] = "gouraud";
        in["pixel"] = {16, 12};
    });
}
BENCHMARK(BM_Shading_StepAndPicture_Lesson)->Unit(benchmark::kMicrosecond);

}  // namespace
