// Haar wavelets: the state machine run to completion vs the straight-line compute on 120 random
// inputs (80 signals of 256 samples, 20 standard and 20 non-standard 64 × 64 images; half
// normalised, half keeping 10% of the coefficients); and the cost of one narrated step plus its
// picture on the example (a 4 × 4 image) and on a 64 × 64 pattern.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "wavelets/haar_wavelet.hpp"

namespace {

using cg::HaarWavelet;

const std::vector<HaarWavelet::Input>& inputs() {
    static const std::vector<HaarWavelet::Input> v = [] {
        cg::Rng rng(22);
        std::vector<HaarWavelet::Input> out;
        for (int k = 0; k < 120; ++k) {
            HaarWavelet::Input in;
            in.mode = k < 80    ? HaarWavelet::Mode::OneD
                      : k < 100 ? HaarWavelet::Mode::Standard
                                : HaarWavelet::Mode::NonStandard;
            in.n = k < 80 ? 256 : 64;
            const std::size_t count = k < 80 ? 256 : 64 * 64;
            for (std::size_t i = 0; i < count; ++i) in.data.push_back(rng.uniform(0, 255));
            in.normalised = k % 2 == 0;
            if (k % 4 < 2) {
                in.compress = HaarWavelet::Compress::Keep;
                in.keep = 0.1;
            }
            HaarWavelet::validate(in);
            out.push_back(std::move(in));
        }
        return out;
    }();
    return v;
}

void BM_HaarWavelet_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += HaarWavelet::compute(in).l2_error;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_HaarWavelet_Plain)->Unit(benchmark::kMillisecond);

void BM_HaarWavelet_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<HaarWavelet>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared)
            sum += cg::run_to_end<HaarWavelet>(HaarWavelet::begin(in)).l2_error;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_HaarWavelet_StateMachine)->Unit(benchmark::kMillisecond);

void BM_HaarWavelet_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "haar-wavelet");
}
BENCHMARK(BM_HaarWavelet_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_HaarWavelet_StepAndPicture64(benchmark::State& state) {
    cg::bench::step_and_picture(state, "haar-wavelet", [](cg::json& in) {
        in = cg::parse_json(R"({"pattern": {"name": "rings", "size": 64}, "mode": "nonstandard",
                                "normalised": true, "keep": 0.05})");
    });
}
BENCHMARK(BM_HaarWavelet_StepAndPicture64)->Unit(benchmark::kMicrosecond);

}  // namespace
