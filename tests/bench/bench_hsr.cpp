// Hidden-surface removal: back-face culling, Warnock, the z-buffer and the painter's algorithm as state machines run to completion vs their
// straight-line functions, on 200 random 64 × 64 screens with 20 polygons each.
#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include "hsr/backface_cull.hpp"
#include "hsr/painters.hpp"
#include "hsr/random_scene.hpp"
#include "hsr/warnock.hpp"
#include "hsr/z_buffer.hpp"

namespace {

const std::vector<cg::hsr::ScreenScene>& scenes() {
    static const std::vector<cg::hsr::ScreenScene> v = [] {
        std::vector<cg::hsr::ScreenScene> out;
        for (std::uint64_t t = 0; t < 200; ++t) {
            cg::Rng rng(1000 + t);
            out.push_back(cg::hsr::random_scene(rng, 64, 64, 20));
        }
        return out;
    }();
    return v;
}

void BM_ZBuffer_Plain(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& s : scenes()) benchmark::DoNotOptimize(cg::ZBuffer::render({s}).writes);
}
BENCHMARK(BM_ZBuffer_Plain)->Unit(benchmark::kMillisecond);

void BM_ZBuffer_StateMachine(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& s : scenes()) {
            cg::ZBuffer::State st;
            st.in = {s};
            benchmark::DoNotOptimize(cg::run_to_end<cg::ZBuffer>(std::move(st)).writes);
        }
}
BENCHMARK(BM_ZBuffer_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Warnock_Plain(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& s : scenes()) benchmark::DoNotOptimize(cg::Warnock::render({s}).areas);
}
BENCHMARK(BM_Warnock_Plain)->Unit(benchmark::kMillisecond);

void BM_Warnock_StateMachine(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& s : scenes())
            benchmark::DoNotOptimize(cg::run_to_end<cg::Warnock>(cg::Warnock::start({s})).areas);
}
BENCHMARK(BM_Warnock_StateMachine)->Unit(benchmark::kMillisecond);

// The painter's algorithm: 200 random 64 × 64 screens with 20 polygons that do not intersect
// (about half with three strips woven in a cycle).
const std::vector<cg::hsr::ScreenScene>& layered_scenes() {
    static const std::vector<cg::hsr::ScreenScene> v = [] {
        std::vector<cg::hsr::ScreenScene> out;
        for (std::uint64_t t = 0; t < 200; ++t) {
            cg::Rng rng(3000 + t);
            out.push_back(cg::hsr::random_layered_scene(rng, 64, 64, 20));
        }
        return out;
    }();
    return v;
}

void BM_Painters_Plain(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& s : layered_scenes()) benchmark::DoNotOptimize(cg::Painters::render({s}).pair_tests);
}
BENCHMARK(BM_Painters_Plain)->Unit(benchmark::kMillisecond);

void BM_Painters_StateMachine(benchmark::State& state) {
    for (auto _ : state)
        for (const auto& s : layered_scenes()) {
            cg::Painters::State st;
            st.in = {s};
            benchmark::DoNotOptimize(cg::run_to_end<cg::Painters>(std::move(st)).pair_tests);
        }
}
BENCHMARK(BM_Painters_StateMachine)->Unit(benchmark::kMillisecond);

// Back-face culling: a 64 × 64 grid sphere (4,032 quads and 128 pole triangles) seen from 200 eyes.
const cg::BackfaceCull::Input& sphere() {
    static const cg::BackfaceCull::Input m = [] {
        cg::BackfaceCull::Input in;
        const int rings = 64, segs = 64;
        in.vertices.push_back({0, 0, -1});
        for (int i = 1; i < rings; ++i)
            for (int j = 0; j < segs; ++j) {
                const double t = 3.141592653589793 * i / rings, p = 6.283185307179586 * j / segs;
                in.vertices.push_back({std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), -std::cos(t)});
            }
        in.vertices.push_back({0, 0, 1});
        auto at = [&](int i, int j) { return 1 + (i - 1) * segs + (j % segs); };
        const int top = static_cast<int>(in.vertices.size()) - 1;
        for (int j = 0; j < segs; ++j) in.faces.push_back({0, at(1, j + 1), at(1, j)});
        for (int i = 1; i + 1 < rings; ++i)
            for (int j = 0; j < segs; ++j) in.faces.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
        for (int j = 0; j < segs; ++j) in.faces.push_back({at(rings - 1, j), at(rings - 1, j + 1), top});
        return in;
    }();
    return m;
}

std::vector<cg::BackfaceCull::Input> sphere_views() {
    std::vector<cg::BackfaceCull::Input> v;
    cg::Rng rng(7);
    for (int t = 0; t < 200; ++t) {
        cg::BackfaceCull::Input in = sphere();
        in.eye = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
        v.push_back(std::move(in));
    }
    return v;
}

void BM_BackfaceCull_Plain(benchmark::State& state) {
    static const auto views = sphere_views();
    for (auto _ : state)
        for (const auto& in : views) benchmark::DoNotOptimize(cg::BackfaceCull::cull(in).dots.back());
}
BENCHMARK(BM_BackfaceCull_Plain)->Unit(benchmark::kMillisecond);

void BM_BackfaceCull_StateMachine(benchmark::State& state) {
    // The inputs made ready beforehand, as the plain function's are: a State shares its input.
    static const auto views = [] {
        std::vector<cg::Shared<cg::BackfaceCull::Input>> v;
        for (auto& in : sphere_views()) v.emplace_back(std::move(in));
        return v;
    }();
    for (auto _ : state)
        for (const auto& in : views)
            benchmark::DoNotOptimize(cg::run_to_end<cg::BackfaceCull>(cg::BackfaceCull::start(in)).dots.back());
}
BENCHMARK(BM_BackfaceCull_StateMachine)->Unit(benchmark::kMillisecond);

}  // namespace
