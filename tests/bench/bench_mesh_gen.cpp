// Generated meshes for the ray tracer's big scenes (rays/mesh_gen.hpp), each generated whole:
// a 10⁶-triangle diamond-square terrain (resolution 708: 1,002,528 triangles), a 512-segment UV
// sphere (261,120 triangles) and a 512 × 512 Bézier patch (524,288 triangles); the counters give
// the triangles per second. No per-triangle allocation: a mesh is five vectors.
#include <benchmark/benchmark.h>

#include "rays/mesh_gen.hpp"

namespace {

void report(benchmark::State& state, const cg::mesh::Mesh& m) {
    state.counters["triangles"] = static_cast<double>(m.triangles.size());
    state.counters["triangles/s"] = benchmark::Counter(
        static_cast<double>(m.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_MeshTerrain1M(benchmark::State& state) {
    cg::mesh::TerrainParams p;
    p.size = {100, 100};
    p.resolution = 708;
    p.height = 8;
    p.seed = 3;
    cg::mesh::Mesh m;
    for (auto _ : state) {
        m = cg::mesh::terrain(p);
        benchmark::DoNotOptimize(m.triangles.data());
    }
    report(state, m);
}
BENCHMARK(BM_MeshTerrain1M)->Unit(benchmark::kMillisecond);

void BM_MeshSphere512(benchmark::State& state) {
    cg::mesh::SphereParams p;
    p.segments = 512;
    cg::mesh::Mesh m;
    for (auto _ : state) {
        m = cg::mesh::sphere(p);
        benchmark::DoNotOptimize(m.triangles.data());
    }
    report(state, m);
}
BENCHMARK(BM_MeshSphere512)->Unit(benchmark::kMillisecond);

void BM_MeshPatch512(benchmark::State& state) {
    cg::mesh::PatchParams p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            p.control_points[i][j] = glm::dvec3(i, j, (i == 1 || i == 2) && (j == 1 || j == 2));
    p.segments = 512;
    cg::mesh::Mesh m;
    for (auto _ : state) {
        m = cg::mesh::patch(p);
        benchmark::DoNotOptimize(m.triangles.data());
    }
    report(state, m);
}
BENCHMARK(BM_MeshPatch512)->Unit(benchmark::kMillisecond);

}  // namespace
