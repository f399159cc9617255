// Vertex normals: the state machine run to completion vs compute() on a UV sphere of 64 × 32
// quads (2,050 vertices, 2,048 faces, polygons by Newell) and on 2,000 exam pyramids; and the
// cost of one narrated step plus its picture at lesson size.
#include <benchmark/benchmark.h>

#include <cmath>

#include "affine/vertex_normals.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"

namespace {

using cg::VertexNormals;

// Latitude rings of quads between two poles, each pole closed by a fan of triangles.
VertexNormals::Input sphere(int slices, int stacks) {
    VertexNormals::Input in;
    const double pi = 3.14159265358979323846;
    in.vertices.push_back({0, 0, -1});
    for (int j = 1; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const double th = 2 * pi * i / slices, ph = pi * j / stacks;
            in.vertices.push_back(
                {std::sin(ph) * std::cos(th), std::sin(ph) * std::sin(th), -std::cos(ph)});
        }
    in.vertices.push_back({0, 0, 1});
    auto at = [&](int j, int i) { return 1 + (j - 1) * slices + (i % slices); };
    for (int i = 0; i < slices; ++i) in.faces.push_back({0, at(1, i + 1), at(1, i)});
    for (int j = 1; j + 1 < stacks; ++j)
        for (int i = 0; i < slices; ++i)
            in.faces.push_back({at(j, i), at(j, i + 1), at(j + 1, i + 1), at(j + 1, i)});
    const long long top = static_cast<long long>(in.vertices.size()) - 1;
    for (int i = 0; i < slices; ++i)
        in.faces.push_back({top, at(stacks - 1, i), at(stacks - 1, i + 1)});
    return in;
}

const VertexNormals::Input& big() {
    static const VertexNormals::Input in = sphere(64, 33);
    return in;
}

const std::vector<VertexNormals::Input>& pyramids() {
    static const std::vector<VertexNormals::Input> inputs = [] {
        std::vector<VertexNormals::Input> v;
        for (std::uint64_t seed = 0; seed < 2000; ++seed) {
            cg::Rng rng(seed);
            v.push_back(VertexNormals::exam_input(rng));
        }
        return v;
    }();
    return inputs;
}

void BM_VertexNormals_Sphere_Plain(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(VertexNormals::compute(big()).vertices.size());
}
BENCHMARK(BM_VertexNormals_Sphere_Plain)->Unit(benchmark::kMicrosecond);

void BM_VertexNormals_Sphere_StateMachine(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(
            cg::run_to_end<VertexNormals>(VertexNormals::start(big())).vertices.size());
}
BENCHMARK(BM_VertexNormals_Sphere_StateMachine)->Unit(benchmark::kMicrosecond);

void BM_VertexNormals_Pyramids_Plain(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& in : pyramids())
            benchmark::DoNotOptimize(VertexNormals::compute(in).vertices.size());
    state.SetItemsProcessed(state.iterations() * pyramids().size());
}
BENCHMARK(BM_VertexNormals_Pyramids_Plain)->Unit(benchmark::kMillisecond);

void BM_VertexNormals_Pyramids_StateMachine(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& in : pyramids())
            benchmark::DoNotOptimize(
                cg::run_to_end<VertexNormals>(VertexNormals::start(in)).vertices.size());
    state.SetItemsProcessed(state.iterations() * pyramids().size());
}
BENCHMARK(BM_VertexNormals_Pyramids_StateMachine)->Unit(benchmark::kMillisecond);

void BM_VertexNormals_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "vertex-normals");
}
BENCHMARK(BM_VertexNormals_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
