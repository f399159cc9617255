// Subdivision surfaces: the state machine run to completion vs the straight-line compute at
// picture sizes (the cube, Catmull–Clark, 4 levels: 1,536 quads; the octahedron, Loop, 4 levels:
// 2,048 triangles; a pyramid of triangles and a quad, Catmull–Clark, 4 levels: 1,024 quads; a
// 6 × 6 triangulated grid with a boundary, Loop, 3 levels: 4,608 triangles); and one narrated
// step plus its picture on the example (the cube, one level) and on the octahedron's fourth level.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "io/registry.hpp"
#include "modelling/subdivision_surface.hpp"

namespace {

using cg::SubdivisionSurface;
using S = SubdivisionSurface;

S::Input make(S::Mesh m, S::Scheme scheme, int levels) {
    S::Input in;
    in.mesh = std::move(m);
    in.scheme = scheme;
    in.levels = levels;
    S::validate(in);
    return in;
}

S::Mesh tri_grid(int n) {
    S::Mesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.vertices.push_back({double(i), double(j), double((i * j) % 3)});
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            m.faces.push_back({a, b, c});
            m.faces.push_back({a, c, d});
        }
    return m;
}

const std::vector<S::Input>& inputs() {
    static const std::vector<S::Input> v = {
        make({{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
              {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}}},
             S::Scheme::CatmullClark, 4),
        make({{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
              {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}},
             S::Scheme::Loop, 4),
        make({{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1.5}},
              {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2, 1}}},
             S::Scheme::CatmullClark, 4),
        make(tri_grid(6), S::Scheme::Loop, 3),
    };
    return v;
}

void BM_SubdivisionSurface_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += S::compute(in).mesh.vertices.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_SubdivisionSurface_Plain)->Unit(benchmark::kMillisecond);

void BM_SubdivisionSurface_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<S>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared) sum += cg::run_to_end<S>(S::begin(in)).mesh.vertices.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_SubdivisionSurface_StateMachine)->Unit(benchmark::kMillisecond);

void BM_SubdivisionSurface_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "subdivision-surface");
}
BENCHMARK(BM_SubdivisionSurface_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_SubdivisionSurface_StepAndPictureOctahedron(benchmark::State& state) {
    cg::bench::step_and_picture(state, "subdivision-surface", [](cg::json& in) {
        in = cg::parse_json(R"({"vertices": [[1,0,0],[-1,0,0],[0,1,0],[0,-1,0],[0,0,1],[0,0,-1]],
            "faces": [[0,2,4],[2,1,4],[1,3,4],[3,0,4],[2,0,5],[1,2,5],[3,1,5],[0,3,5]],
            "scheme": "loop", "levels": 4})");
    });
}
BENCHMARK(BM_SubdivisionSurface_StepAndPictureOctahedron)->Unit(benchmark::kMicrosecond);

}  // namespace
