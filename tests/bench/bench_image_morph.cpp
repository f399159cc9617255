// Image morphing: the state machine run to completion vs the straight-line compute on 8 random
// morphs (16 to 48 pixels a side, 1 to 8 line pairs, 5 to 10 frames); and the cost of one
// narrated step plus its picture on the example (4 × 4) and on the lesson's 24 × 24 bar.
#include <benchmark/benchmark.h>

#include "animation/image_morph.hpp"
#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"

namespace {

using cg::ImageMorph;

const std::vector<ImageMorph::Input>& inputs() {
    static const std::vector<ImageMorph::Input> v = [] {
        cg::Rng rng(43);
        std::vector<ImageMorph::Input> out;
        const char* names[] = {"disc", "square", "bar", "column", "cross", "ramp"};
        for (int k = 0; k < 8; ++k) {
            ImageMorph::Input in;
            const int n = int(rng.integer(16, 48));
            in.image_a = ImageMorph::pattern_image(names[rng.integer(0, 5)], n);
            in.image_b = ImageMorph::pattern_image(names[rng.integer(0, 5)], n);
            const int m = int(rng.integer(1, 8));
            for (int i = 0; i < m; ++i) {
                auto pt = [&] { return glm::dvec2(rng.uniform(0, n), rng.uniform(0, n)); };
                ImageMorph::Pair pr{{pt(), pt()}, {pt(), pt()}};
                pr.a.q = pr.a.p + glm::dvec2(n / 4.0, 1);
                pr.b.q = pr.b.p + glm::dvec2(1, n / 4.0);
                in.lines.push_back(pr);
            }
            const int frames = int(rng.integer(5, 10));
            for (int f = 0; f < frames; ++f) in.alphas.push_back(double(f) / (frames - 1));
            out.push_back(ImageMorph::resolve(in));
        }
        return out;
    }();
    return v;
}

void BM_ImageMorph_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += ImageMorph::compute(in).difference;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_ImageMorph_Plain)->Unit(benchmark::kMillisecond);

void BM_ImageMorph_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<ImageMorph>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<ImageMorph>(ImageMorph::begin(in)).difference;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_ImageMorph_StateMachine)->Unit(benchmark::kMillisecond);

void BM_ImageMorph_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "image-morph");
}
BENCHMARK(BM_ImageMorph_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_ImageMorph_StepAndPictureBar(benchmark::State& state) {
    cg::bench::step_and_picture(state, "image-morph", [](cg::json& in) {
        in = cg::parse_json(R"({"image_a": {"pattern": "bar", "size": 24},
                                "image_b": {"pattern": "column", "size": 24},
                                "lines": [{"a": [[3, 12], [21, 12]], "b": [[12, 21], [12, 3]]}],
                                "frames": 5, "focus": [12, 12]})");
    });
}
BENCHMARK(BM_ImageMorph_StepAndPictureBar)->Unit(benchmark::kMicrosecond);

}  // namespace
