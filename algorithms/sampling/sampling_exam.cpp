// Sampling exam problems: one or two sines with whole frequencies in kHz (1 … 25), sampled at a
// rate of 4 … 20 kHz for one millisecond (a handful of samples to step through), phase 0 or
// 90°. About half the frequencies lie above f_s/2: the question is the course's "7 kHz
// sampled at 10 kHz" — the alias of each, whether it is aliased, and the Nyquist rate.
#include "core/format.hpp"
#include "sampling/sampling.hpp"

namespace cg {

Sampling::Input Sampling::exam_input(Rng& rng) {
    static constexpr double kRates[] = {4, 5, 6, 8, 10, 12, 16, 20};
    Input in;
    in.mode = Mode::Signal;
    in.rate = kRates[rng.integer(0, std::size(kRates) - 1)];
    in.duration = 1;
    in.reconstruction = Reconstruction::Linear;
    const long long n = rng.chance(0.7) ? 1 : 2;
    for (long long k = 0; k < n; ++k) {
        Component c;
        c.frequency = static_cast<double>(rng.integer(1, 25));
        c.amplitude = k == 0 ? 1 : 0.5;
        c.phase = rng.chance(0.8) ? 0 : 90;
        in.signal.push_back(c);
    }
    return in;
}

std::string Sampling::question(const Input& in) {
    std::string sines;
    for (std::size_t k = 0; k < in.signal.size(); ++k) {
        const auto& c = in.signal[k];
        sines += (k ? " plus " : "") + (c.amplitude == 1 ? "" : num(c.amplitude) + " ") +
                 "sin(2π · " + num(c.frequency) + " kHz · t" +
                 (c.phase != 0 ? " + " + num(c.phase) + "°" : "") + ")";
    }
    return "The signal " + sines + " is sampled at f_s = " + num(in.rate) + " kHz for " +
           num(in.duration) +
           " ms. For each frequency give, in order, its alias |f − k f_s| with k = round(f / f_s) "
           "(in kHz, in [0, f_s/2]), the alias's phase in degrees (the same φ, or 180° − φ when "
           "f − k f_s < 0, in (−180°, 180°]), k, and whether it is aliased (f_s ≤ 2f): aliases as "
           "[{frequency, alias, alias_phase, k, aliased}, …]. Give also the Nyquist rate 2 f_max "
           "in kHz (nyquist_rate).";
}

std::vector<std::string> Sampling::answer_fields() {
    return {"aliases", "nyquist_rate"};
}

}  // namespace cg
