// Sampling a signal, and what goes wrong when the samples are too far apart: aliasing.
//
// 1D (the course's Nyquist limit). A sum of sines s(t) = Σ A sin(2π f t + φ) is sampled at rate
// f_s, x_n = s(n / f_s). A sine of frequency f gives at the sample times exactly the values of
// a sine of frequency |f − k f_s| for any integer k, so the samples cannot tell them apart; the
// lowest of these, folded into [0, f_s/2] with k = round(f / f_s), is the alias the
// reconstruction shows. With f − k f_s < 0 the fold mirrors the sine: the alias has phase
// 180° − φ. A frequency is recovered only when f_s > 2 f (its Nyquist rate); here "aliased" means
// f_s ≤ 2 f (at f_s = 2 f exactly the alias is f itself, but its amplitude and phase are lost).
// Reconstruction from the samples: nearest (the sample closest in time), linear (between the
// two neighbours), or sinc windowed by Lanczos, Σ x_n sinc(u − n) sinc((u − n)/a), u = t f_s,
// a = 4 lobes each side. As the sampling theorem assumes, the samples go on for all time: the
// ones just outside [0, duration] are used near its ends. error_rms compares the reconstruction
// with s(t) over [0, duration] at 16 points per sample interval (at most 20,000).
//
// 2D. An image function over a width × height raster of pixels ((i, j) covers
// [i, i+1) × [j, j+1), y up), grey values in [0, 1]: an edge at an angle (1 on its left), a
// checkerboard on a ground plane receding in perspective to a horizon, or a zone plate
// ½ (1 + cos(π r² / (2ρ))), whose rings' local frequency r / (2ρ) cycles per pixel reaches the
// Nyquist limit ½ at r = ρ. Each pixel is sampled once at its centre and, beside it,
// supersampled (sampling/patterns.hpp: pattern, samples, filter, seed; pixel (i, j) uses the
// seed mix_seed(seed, i, j)): stairsteps and moiré on the left, their anti-aliased version on
// the right.
//
// Steps. 1D: one per sample (x_n = s(t_n), each component's share); one per frequency (its
// fold: k, the alias, aliased or not); reconstruct (the curve and error_rms). 2D: one per row of
// pixels (both versions), then compare (the RMS difference between them).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "sampling/patterns.hpp"

namespace cg {

struct Sampling {
    static constexpr int kMaxComponents = 16;
    static constexpr long long kMaxSamples = 4096;  // 1D samples in [0, duration]
    static constexpr int kMaxErrorPoints = 20000;
    static constexpr int kPointsPerInterval = 16;
    static constexpr int kLanczos = 4;             // lobes each side of the windowed sinc
    static constexpr int kMaxSide = 256;           // 2D: pixels a side
    static constexpr int kMaxSupersamples = 256;   // 2D: samples per pixel
    static constexpr double kMaxImageWork = 4e6;   // 2D: width × height × samples
    static constexpr double kMaxPoissonWork = 1e9;  // ... × samples again for Poisson darts
    static constexpr double kMaxFrequency = 1e12;  // |f|, f_s, 1/duration

    enum class Mode : std::uint8_t { Signal, Image };
    enum class Reconstruction : std::uint8_t { Nearest, Linear, Sinc };
    enum class ImageKind : std::uint8_t { Edge, Checkerboard, ZonePlate };

    struct Component {
        double frequency = 1;  // f ≥ 0, in cycles per unit of time (Hz, or kHz with ms)
        double amplitude = 1;  // A
        double phase = 0;      // φ, degrees
        bool operator==(const Component&) const = default;
    };

    struct Image {
        ImageKind kind = ImageKind::ZonePlate;
        double angle = 30;          // edge: degrees, counter-clockwise from +x
        glm::dvec2 point{0.0};      // edge: a point on it (pixel units)
        double horizon = 0;         // checkerboard: the horizon's height y (pixels)
        double square = 0.25;       // checkerboard: a square's side on the ground
        double focal = 0;           // checkerboard: focal length (pixels)
        double nyquist_radius = 0;  // zone plate: ρ, where the rings reach ½ cycle/pixel
        bool operator==(const Image&) const = default;
    };

    struct Input {
        Mode mode = Mode::Signal;
        // 1D
        std::vector<Component> signal;
        double rate = 10;     // f_s, samples per unit of time
        double duration = 1;  // sampled over [0, duration]
        Reconstruction reconstruction = Reconstruction::Linear;
        // 2D
        Image image;
        int width = 32, height = 32;
        sampling::Pattern pattern = sampling::Pattern::Jittered;
        int samples = 16;
        sampling::Filter filter = sampling::Filter::Box;
        std::uint64_t seed = 1;
        bool operator==(const Input&) const = default;
    };

    struct Alias {
        double frequency = 0;    // f
        double alias = 0;        // |f − k f_s| ∈ [0, f_s/2]
        double alias_phase = 0;  // degrees, in (−180, 180]
        long long k = 0;         // round(f / f_s)
        bool aliased = false;    // f_s ≤ 2 f
        bool operator==(const Alias&) const = default;
    };

    struct Result {
        Mode mode = Mode::Signal;
        // 1D
        std::vector<glm::dvec2> samples;  // (t_n, x_n)
        std::vector<Alias> aliases;
        double nyquist_rate = 0;  // 2 f_max
        double error_rms = 0;
        // 2D
        int width = 0, height = 0;
        std::vector<double> point_sampled, supersampled;  // row-major, row 0 at the bottom
        double rms_difference = 0;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Sample, Fold, Reconstruct, Row, Compare, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Sample;
        Phase last = Phase::Sample;
        // 1D
        long long count = 0;              // samples in [0, duration]
        std::vector<glm::dvec2> samples;  // taken so far
        std::vector<Alias> aliases;       // folded so far
        std::vector<glm::dvec2> curve;    // the reconstruction, for the picture
        double error_rms = 0;
        // 2D
        int row = -1;
        std::vector<double> point_sampled, supersampled;
        double rms_difference = 0;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.samples) + heap_bytes(s.aliases) + heap_bytes(s.curve) +
               heap_bytes(s.point_sampled) + heap_bytes(s.supersampled);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The plain functions (the benchmark and the tests use them).
    static Result run(const Input& in);
    static double signal(const std::vector<Component>& c, double t);
    static Alias fold(double frequency, double phase_deg, double rate);
    static long long sample_count(double rate, double duration);
    // The reconstruction at time t from the samples x_n = s(n / f_s), n any integer.
    static double reconstruct(const Input& in, double t);
    // error_rms, and (when `curve` is given) every few of the points it compared, (t, r(t)).
    static double error_rms(const Input& in, std::vector<glm::dvec2>* curve = nullptr);
    // The 2D image function at a point (pixel units).
    static double image_value(const Input& in, glm::dvec2 p);
    static double supersample_pixel(const Input& in, int i, int j);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
