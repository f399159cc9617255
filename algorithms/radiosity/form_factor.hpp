// The form factor F_ij between two patches, three ways side by side: the analytic formula where
// one exists, the hemicube, and Monte Carlo ray casting; then reciprocity (A_i F_ij = A_j F_ji,
// with F_ji computed by each method in reverse) and, given the rest of a closed enclosure, the
// row sum Σ_k F_ik = 1.
//
// The geometry and the three methods are in radiosity/patch.hpp and form_factor_math.hpp. The
// hemicube stands on an m × m grid of equal-area points of patch i (m = "samples"; m = 1 is the
// classic single hemicube at i's centre, which gives the point-to-patch factor F_dA→j, not F_ij);
// its result is the mean of the points' sums. Visibility: F_ij counts everything that reaches j
// (H = 1: nothing else is tested); the row sum is taken with the nearest patch of {to} ∪
// enclosure along each ray or cell (a z-buffer), as a radiosity solver would.
//
// Steps: setup (areas, normals, which analytic case applies), analytic (the formula and its
// value, or no-analytic), one hemicube-face step per face (top, +x, −x, +y, −y: the covered
// cells and their summed ΔF), Monte Carlo in batches (10 batches of N/10 rays: hits so far,
// N_ij/N_i, the standard error), reciprocity (F_ji by each method against A_i F_ij / A_j; for a
// point, dA F = A_j F_j,dA with F_j,dA → 0), and row-sum when an enclosure is given.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "radiosity/form_factor_math.hpp"
#include "radiosity/patch.hpp"

namespace cg {

struct FormFactor {
    static constexpr int kMaxResolution = 128;
    static constexpr int kMaxSamples = 8;
    static constexpr long long kMaxRays = 1'000'000;
    static constexpr std::size_t kMaxEnclosure = 16;
    static constexpr int kBatches = 10;

    struct Input {
        Patch from = Patch::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        Patch to = Patch::rectangle({0, 0, 1}, {0, 1, 0}, {1, 0, 0});
        int resolution = 8;  // hemicube cells across the top face (even)
        int samples = 3;     // the hemicube on an m × m grid of points of `from`
        long long rays = 1000;
        std::uint64_t seed = 1;
        std::vector<Patch> enclosure;  // the rest of a closed enclosure (optional)
        bool operator==(const Input&) const = default;
    };

    struct Reciprocity {
        double a_i_f_ij = 0;       // A_i F_ij (analytic if known, else Monte Carlo)
        double f_ji_expected = 0;  // A_i F_ij / A_j
        std::optional<double> f_ji_analytic;
        double f_ji_hemicube = 0, f_ji_monte_carlo = 0;
        bool operator==(const Reciprocity&) const = default;
    };
    struct RowSum {
        std::optional<double> analytic;  // when every pair has a formula
        double hemicube = 0, monte_carlo = 0;
        std::vector<double> hemicube_terms, monte_carlo_terms;  // F_ij, then each enclosure patch
        bool operator==(const RowSum&) const = default;
    };

    struct Result {
        double area_from = 0, area_to = 0;
        std::optional<double> analytic;
        std::string analytic_case = "none";
        double hemicube = 0, monte_carlo = 0, monte_carlo_std_error = 0;
        std::optional<double> error_hemicube, error_monte_carlo;  // |method − analytic|
        std::optional<Reciprocity> reciprocity;                   // not for a point (dA)
        std::optional<RowSum> row_sum;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        Setup,
        Analytic,
        Hemicube,
        MonteCarlo,
        Reciprocity,
        RowSum,
        Done
    };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Setup;
        Phase last = Phase::Setup;
        ff::Analytic an;
        int face = -1;                // the hemicube face done last
        double face_sum = 0;          // its ΔF sum (mean over the points)
        int face_covered = 0;         // its cells seen by some point
        double hemicube = 0;          // the running sum
        std::vector<float> coverage;  // the last face's cells: fraction of points that see j
        Rng rng{1};
        Rng batch_rng{1};  // the generator before the last batch (to redraw its rays)
        int batch = 0;     // batches done
        long long rays_done = 0, hits = 0, batch_hits = 0;
        std::optional<Reciprocity> reciprocity;
        std::optional<RowSum> row_sum;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Everything in one straight-line function, for the benchmark.
    static Result compute(const Input& in);

    // The pieces both use.
    static long long batch_size(const Input& in, int batch);  // rays in batch k (0-based)
    static Reciprocity reciprocity(const Input& in, const ff::Analytic& an, double hemicube,
                                   double monte_carlo);
    static RowSum row_sum(const Input& in, const ff::Analytic& an);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
