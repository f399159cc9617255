// Colour spaces: the state machine run to completion vs the straight-line function on 20,000
// inputs of 8 random colours, for RGB → HSV (the max/min/hue path), HSL → XYZ (sector, then
// the matrix) and YIQ → HSL (the inverse matrix and the gamut check, then the hue); and the
// cost of one narrated step plus its 3D picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "colour/colour_spaces.hpp"
#include "core/rng.hpp"

namespace {

using Space = cg::ColourSpaces::Space;

std::vector<cg::ColourSpaces::State> make(Space from, Space to) {
    cg::Rng rng(42);
    std::vector<cg::ColourSpaces::State> v;
    v.reserve(20'000);
    for (int i = 0; i < 20'000; ++i) {
        cg::ColourSpaces::Input in{from, to, {}};
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 rgb{rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)};
            in.colors.push_back(cg::ColourSpaces::convert({Space::Rgb, from, {rgb}}).colors[0]);
        }
        v.push_back(cg::ColourSpaces::start(in));
    }
    return v;
}

const std::vector<cg::ColourSpaces::State>& inputs(int which) {
    static const std::vector<cg::ColourSpaces::State> a = make(Space::Rgb, Space::Hsv),
                                                      b = make(Space::Hsl, Space::Xyz),
                                                      c = make(Space::Yiq, Space::Hsl);
    return which == 0 ? a : which == 1 ? b : c;
}

void plain(benchmark::State& state, int which) {
    const auto& v = inputs(which);
    for (auto _ : state) {
        double sum = 0;
        for (const auto& s : v) sum += cg::ColourSpaces::convert(*s.in).colors.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}

void machine(benchmark::State& state, int which) {
    const auto& v = inputs(which);
    for (auto _ : state) {
        double sum = 0;
        for (const auto& s : v) sum += cg::run_to_end<cg::ColourSpaces>(s).colors.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}

void BM_ColourRgbHsv_Plain(benchmark::State& state) {
    plain(state, 0);
}
void BM_ColourRgbHsv_StateMachine(benchmark::State& state) {
    machine(state, 0);
}
void BM_ColourHslXyz_Plain(benchmark::State& state) {
    plain(state, 1);
}
void BM_ColourHslXyz_StateMachine(benchmark::State& state) {
    machine(state, 1);
}
void BM_ColourYiqHsl_Plain(benchmark::State& state) {
    plain(state, 2);
}
void BM_ColourYiqHsl_StateMachine(benchmark::State& state) {
    machine(state, 2);
}
BENCHMARK(BM_ColourRgbHsv_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColourRgbHsv_StateMachine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColourHslXyz_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColourHslXyz_StateMachine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColourYiqHsl_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColourYiqHsl_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Colour_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "colour-spaces");
}
BENCHMARK(BM_Colour_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
