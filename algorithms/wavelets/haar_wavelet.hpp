// The Haar wavelet transform: averaging and differencing, level by level, and lossy compression.
//
// The course: "given an array, represent it in a different form by taking the average of
// adjacent elements and storing both the average and the difference between the average and the
// actual values; truncating (small) values to 0 gives a lossy compression technique", and in 2D
// "apply 1-D Haar to every row, then apply 1-D Haar to every column".
//
// One level on the first m entries of a line x (m even), k = 0 … m/2 − 1:
//   unnormalised  s_k = (x_2k + x_2k+1) / 2,    d_k = x_2k − s_k = (x_2k − x_2k+1) / 2
//   normalised    s_k = (x_2k + x_2k+1) / √2,   d_k = (x_2k − x_2k+1) / √2   (orthonormal)
// and the line becomes [s_0 … s_m/2−1, d_0 … d_m/2−1, (the details of earlier levels)]. The next
// level works on the m/2 averages. Undoing a level: x_2k = s_k + d_k, x_2k+1 = s_k − d_k
// (normalised: both divided by √2). A normalised coefficient is the unnormalised one times
// √(support), the number of samples its basis function spans; so the normalised transform keeps
// the L2 norm (Parseval), and dropping coefficients costs exactly the norm of what is dropped.
// Computed as x/2 ± y/2 (x/√2 ± y/√2), so that values near 1e300 do not overflow.
//
// Modes: "1d" — a signal of length n = 2^L, one level per step (m = n, n/2, …, 2).
//   "standard" — an n × n image: every row fully transformed (all L levels), then every column;
//   "nonstandard" — one level of every row of the m × m averages block, then one level of its
//   columns, m = n, n/2, …, 2 (the quadrants: averages, row details, column details, diagonal).
// In 2D a step is one row (or column) for n ≤ 16, and a group of n/16 of them above that.
// Compression (optional): "threshold" t zeroes every detail with |c| < t; "keep" f keeps the
// overall average and the ⌈f N⌉ − 1 largest details by size (ties: the lower index) and zeroes
// the rest. The overall average is never dropped. The step predicts the L2 error from the
// dropped coefficients (√Σ w c², w = 1 normalised, the support size unnormalised), and the
// reconstruction, undone level by level in reverse order, reports the actual one.
// Refused: an empty signal or image, a length or side that is not a power of two, a ragged or
// non-square image, more than 1024 samples (1D) or 256 × 256 (2D), values above 1e300 in size,
// "1d" with an image or a 2D mode with a signal, both threshold and keep, threshold < 0, keep
// outside (0, 1], an unknown pattern.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct HaarWavelet {
    static constexpr int kMaxSignal = 1024;
    static constexpr int kMaxImage = 256;
    static constexpr double kMaxValue = 1e300;
    static constexpr int kMaxGroups = 16;  // steps per 2D pass (rows grouped above 16 × 16)

    enum class Mode : std::uint8_t { OneD, Standard, NonStandard };
    enum class Compress : std::uint8_t { None, Threshold, Keep };

    struct Input {
        Mode mode = Mode::OneD;
        int n = 0;                 // the signal's length, or the image's side
        std::vector<double> data;  // 1D: n values; 2D: n × n, row-major, row 0 the first given
        std::string pattern;       // 2D: the generated image's name ("" when given as rows)
        std::uint64_t seed = 1;    // for the "noise" pattern
        bool normalised = false;
        Compress compress = Compress::None;
        double threshold = 0;
        double keep = 1;
        bool operator==(const Input&) const = default;
    };

    // One step of the decomposition or its reconstruction: `levels` levels on the first `len`
    // entries of lines first … first + count − 1 (rows, or columns).
    struct Pass {
        bool inverse = false;
        bool rows = true;
        int first = 0, count = 1;
        int len = 0, levels = 1;
        bool operator==(const Pass&) const = default;
    };

    struct Result {
        Mode mode = Mode::OneD;
        int n = 0;
        std::vector<std::vector<double>> levels;  // 1D: the vector after each level
        std::vector<double> coefficients;         // the full transform
        std::vector<double> compressed;           // after zeroing (= coefficients without it)
        std::vector<double> reconstruction;
        long long zeroed = 0;        // non-zero coefficients set to 0
        long long kept = 0;          // non-zero coefficients left
        double predicted_error = 0;  // √Σ w c² over the dropped coefficients
        double l2_error = 0;         // ‖x − x̃‖₂
        double max_error = 0;        // max |x − x̃|
        double relative_error = 0;   // l2_error / ‖x‖₂ (0 for a zero signal)
        double signal_norm = 0, coefficient_norm = 0;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Forward, Threshold, Inverse, Summary, Done };

    struct State {
        Shared<Input> in;
        Shared<std::vector<Pass>> passes;  // forward then inverse, fixed at the start
        Phase phase = Phase::Forward;
        Phase last = Phase::Forward;
        int next = 0;           // the next pass
        std::vector<double> c;  // the working array
        std::vector<std::vector<double>> levels;
        std::vector<double> coefficients, compressed;
        long long zeroed = 0, kept = 0;
        // cut: the threshold in force (keep: the smallest detail kept)
        double predicted_error = 0, cut = 0;
        double l2_error = 0, max_error = 0, signal_norm = 0, coefficient_norm = 0;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);   // validates, then begin()
    static State begin(Shared<Input> in);  // a fresh state for a valid input
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.c) + heap_bytes(s.levels) + heap_bytes(s.coefficients) +
               heap_bytes(s.compressed);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Everything in straight loops, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use.
    static std::vector<Pass> plan(const Input& in);
    static void apply(const Input& in, const Pass& p, std::vector<double>& c);
    // The array before pass p of s (the pass undone, or redone, on a copy of s.c), for the
    // narration and the picture only (the round trip's rounding is far below what they print).
    static std::vector<double> before_pass(const State& s, int p);
    // Zeroes the small coefficients of c in place; returns the predicted L2 error and sets the
    // counts and the cut.
    static double compress(const Input& in, std::vector<double>& c, long long& zeroed,
                           long long& kept, double& cut);
    // The weight w of coefficient `at` in ‖x‖² = Σ w c² (1 when normalised).
    static double weight(const Input& in, std::size_t at);
    // √Σ v², scaled so that values near 1e300 do not overflow.
    static double norm(const std::vector<double>& v);
    // A generated n × n image: "gradient", "disc", "checker", "rings", "blocks" or "noise".
    static std::vector<double> pattern_image(const std::string& name, int n, std::uint64_t seed);
    static const std::vector<std::string>& pattern_names();

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
