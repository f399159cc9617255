// Sutherland-Hodgman: the state machine run to completion vs the straight-line function, on
// 10^5 random star-shaped 8-gons against a fixed convex hexagon; and the cost of one narrated
// step plus its picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "clipping/sutherland_hodgman.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using Points = std::vector<glm::dvec2>;

const Points& hexagon() {
    static const Points window = [] {
        Points w;
        for (int i = 0; i < 6; ++i) {
            const double a = 2 * std::numbers::pi * i / 6 + 0.3;
            w.push_back({4 * std::cos(a), 3 * std::sin(a)});
        }
        return w;
    }();
    return window;
}

// Star-shaped about a point near the window: sorted random angles and radii, so concave,
// crossing the window's edges several times.
const std::vector<Points>& polygons() {
    static const std::vector<Points> inputs = [] {
        cg::Rng rng(42);
        std::vector<Points> v(100'000);
        for (Points& p : v) {
            const glm::dvec2 c{rng.uniform(-3, 3), rng.uniform(-3, 3)};
            double angles[8];
            for (double& a : angles) a = rng.uniform(0, 2 * std::numbers::pi);
            std::sort(angles, angles + 8);
            for (double a : angles) {
                const double r = rng.uniform(1, 6);
                p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
            }
        }
        return v;
    }();
    return inputs;
}

void BM_SutherlandHodgman_Plain(benchmark::State& state) {
    const auto& inputs = polygons();
    const Points& window = hexagon();
    for (auto _ : state) {
        std::size_t vertices = 0;
        for (const auto& p : inputs)
            vertices += cg::SutherlandHodgman::clip(window, p).polygon.size();
        benchmark::DoNotOptimize(vertices);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_SutherlandHodgman_Plain)->Unit(benchmark::kMillisecond);

// The inputs made ready beforehand, as the plain function's are: a State shares its input
// (Shared<Input>), so starting a run copies no vertices.
const std::vector<cg::Shared<cg::SutherlandHodgman::Input>>& shared_inputs() {
    static const auto inputs = [] {
        std::vector<cg::Shared<cg::SutherlandHodgman::Input>> v;
        v.reserve(polygons().size());
        for (const auto& p : polygons()) v.emplace_back(cg::SutherlandHodgman::Input{hexagon(), p});
        return v;
    }();
    return inputs;
}

void BM_SutherlandHodgman_StateMachine(benchmark::State& state) {
    const auto& inputs = shared_inputs();
    for (auto _ : state) {
        std::size_t vertices = 0;
        for (const auto& in : inputs) {
            cg::SutherlandHodgman::State s;  // start() without re-validating: inputs are known good
            s.in = in;
            vertices += cg::run_to_end<cg::SutherlandHodgman>(std::move(s)).polygon.size();
        }
        benchmark::DoNotOptimize(vertices);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_SutherlandHodgman_StateMachine)->Unit(benchmark::kMillisecond);

// What the viewer pays per step: a narrated step through the registry plus the scene.
void BM_SutherlandHodgman_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "sutherland-hodgman");
}
BENCHMARK(BM_SutherlandHodgman_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
