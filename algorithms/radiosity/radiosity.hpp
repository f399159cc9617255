// Radiosity: the diffuse light of a closed scene of patches, from the radiosity equation
//
//   B_i = E_i + ρ_i Σ_j F_ij B_j        (per colour channel: E, ρ and B are RGB)
//
// B_i the radiosity leaving patch i (power per area), E_i its emission, ρ_i its reflectance and
// F_ij the form factor from i to j (form_factor_math.hpp, reused: hemicube, Monte Carlo, or the
// analytic formulas where a pair has one).
//
// The input's surfaces (rectangles or triangles, each with E and ρ) are first subdivided into
// n × n patches (a rectangle into n × n rectangles, a triangle into n² triangles). Then:
//   Phase 1 — the form-factor matrix, one row per step: F_i· with visibility (the nearest patch
//     along each hemicube cell or ray wins), F_ii = 0 (a flat patch cannot see itself); the
//     step shows the row sum Σ_j F_ij (1 in a closed enclosure) and reciprocity
//     A_i F_ij = A_j F_ji against the rows already computed. "analytic" uses a pair's formula
//     where one exists (the pair then counts as unoccluded) and Monte Carlo for the rest.
//   Phase 2 — the solve, one step each, from B = E:
//     jacobi        one gathering sweep, every B_i from the previous sweep's B;
//     gauss-seidel  one gathering sweep, each B_i from the newest B (updated in place);
//     progressive   shooting: the patch with the most unshot power A_i ΔB_i (summed over the
//                   channels; the lowest index on a tie) sends ρ_j F_ji ΔB_i to every j, with
//                   F_ji = A_i F_ij / A_j (reciprocity), and its ΔB_i becomes 0.
//   The residual of a gathering sweep is max |B_new − B_old| over patches and channels; of a
//   shot, the largest unshot radiosity max ΔB_j left. The solve stops when it is below the
//   tolerance (converged) or after max_steps steps.
//
// Convergence. Gathering and shooting converge when the spectral radius of diag(ρ) F is below 1.
// With ρ < 1 in every channel and row sums ≤ 1 it is (the rows of ρF sum to less than 1). The
// rule enforced: ρ must lie in [0, 1]; ρ = 1 (a perfect reflector) is accepted unless, in that
// channel, some patch cannot reach — following non-zero form factors — a patch that loses energy
// (ρ_i Σ_j F_ij < 1), or some row has ρ_i Σ_j F_ij > 1: then light would bounce forever (spectral
// radius ≥ 1) and B diverges. That check needs the form factors, so start computes them first
// when, and only when, some ρ is 1.
//
// The picture (radiosity_draw.cpp): the patches shaded by the current B (3D); while phase 1
// runs, the matrix F filling in row by row (an image panel); while solving, the image from the
// camera (each pixel the tone-mapped B of the patch its centre ray meets first; the id buffer
// is computed once at the start) and the residual per step on a log axis. Tone mapping: B is divided by the largest channel of any
// non-emitting patch (of any patch when all emit), clamped to 1 and raised to 1/2.2.
//
// Refused: no surfaces or more than kMaxPatches after subdivision, a disc or point patch, a
// zero-area or malformed patch (validate_patch), E or ρ not finite, E < 0 or above 1e100, ρ
// outside [0, 1] or a divergent ρ = 1 (above), subdivision outside 1..32, tolerance not positive, max_steps
// outside 1..100000, form-factor settings outside form-factor's limits, a camera whose position
// equals its target or whose up is along the view, fov outside (0, 170), an image outside
// 1..64 pixels a side.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "radiosity/form_factor_math.hpp"
#include "radiosity/patch.hpp"

namespace cg {

struct Radiosity {
    static constexpr std::size_t kMaxPatches = 2048;
    static constexpr int kMaxSubdivision = 32;
    static constexpr int kMaxImage = 64;
    static constexpr int kMaxSteps = 100000;
    static constexpr int kMaxResolution = 128;
    static constexpr int kMaxSamples = 8;
    static constexpr long long kMaxRays = 100000;

    enum class Method : std::uint8_t { Jacobi, GaussSeidel, Progressive };
    enum class FormFactors : std::uint8_t { Analytic, Hemicube, MonteCarlo };

    struct Surface {
        Patch patch = Patch::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        glm::dvec3 emission{0, 0, 0};
        glm::dvec3 reflectance{0.5, 0.5, 0.5};
        bool operator==(const Surface&) const = default;
    };
    struct Camera {
        glm::dvec3 position{0, 0, 3}, target{0, 0, 0}, up{0, 1, 0};
        double fov_deg = 60;  // vertical
        int width = 24, height = 24;
        bool operator==(const Camera&) const = default;
    };

    struct Input {
        std::vector<Surface> surfaces;
        int subdivision = 1;  // each surface into n × n patches (n² for a triangle)
        Method method = Method::GaussSeidel;
        FormFactors form_factors = FormFactors::Hemicube;
        int resolution = 16;  // hemicube cells across the top face (even)
        int samples = 1;      // the hemicube on an m × m grid of points of each patch
        long long rays = 2000;  // Monte Carlo rays per patch
        std::uint64_t seed = 1;
        double tolerance = 1e-4;
        int max_steps = 500;
        Camera camera;
        bool operator==(const Input&) const = default;
    };

    // The subdivided scene, fixed at the start and shared by every copy of the state.
    struct Scene3 {
        std::vector<Patch> patches;
        std::vector<int> surface;  // the input surface each patch came from
        std::vector<double> area;
        std::vector<glm::dvec3> emission, reflectance;
        std::vector<int> pixel;  // the camera's id buffer: the patch each pixel sees, or −1
        bool operator==(const Scene3&) const = default;
    };

    struct Shot {  // the first shot of a progressive run (the exam's question)
        int shooter = -1;
        std::vector<double> f_ji;                 // F_ji = A_i F_ij / A_j for every j
        std::vector<std::vector<double>> delta_b;  // ρ_j F_ji ΔB_i, RGB, for every j
        bool operator==(const Shot&) const = default;
    };

    struct Sweep {  // one gathering sweep: its residual and the patch k that changed the most
        double residual = 0;
        int k = -1;
        glm::dvec3 gathered{0, 0, 0};  // Σ_j F_kj B_j
        glm::dvec3 before{0, 0, 0};    // B_k before the sweep
        bool operator==(const Sweep&) const = default;
    };

    struct Result {
        Shared<Scene3> scene;
        std::vector<double> form_factors;  // N × N, row-major
        std::vector<double> row_sum;
        double reciprocity_error = 0;  // max |A_i F_ij − A_j F_ji|
        std::vector<glm::dvec3> radiosity;
        int steps = 0;  // solve steps (sweeps or shots)
        bool converged = false;
        double residual = 0;
        glm::dvec3 shot_power{0, 0, 0};    // progressive: Σ A_i ΔB_i over the shots
        glm::dvec3 unshot_power{0, 0, 0};  // progressive: Σ A_j ΔB_j left
        Shot first_shot;
        std::vector<std::uint32_t> image;  // the camera's picture, RGBA, row 0 at the bottom
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { FormFactors, Solve, Done };

    struct State {
        Shared<Input> in;
        Shared<Scene3> scene;
        Phase phase = Phase::FormFactors;
        Phase last = Phase::FormFactors;
        int row = -1;                 // the form-factor row computed last
        std::vector<double> F;        // N × N, filled row by row
        std::vector<glm::dvec3> B;    // the current radiosities
        std::vector<glm::dvec3> unshot;  // progressive: ΔB
        glm::dvec3 shot_power{0, 0, 0};
        int steps = 0;          // solve steps done
        double residual = 0;    // of the last solve step
        std::vector<double> history;  // the residual after every solve step
        bool converged = false;
        int shooter = -1;       // progressive: the last shooter (−1: nothing left to shoot)
        glm::dvec3 shot{0, 0, 0};  // its ΔB_i when it shot
        Shot first_shot;
        Sweep sweep;  // the last gathering sweep
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, cg::Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Everything in one straight-line function, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use.
    // The subdivided patches with their E, ρ and areas, and the camera's id buffer.
    static Scene3 prepare(const Input& in);
    static void form_factor_row(const Input& in, const Scene3& sc, int i, double* row);
    static double row_sum(const std::vector<double>& F, std::size_t n, int i);
    // The largest |A_i F_ij − A_j F_ji| over j < i (the rows before i are known).
    static double reciprocity_error(const Scene3& sc, const std::vector<double>& F, int i);
    static Sweep jacobi_sweep(const Scene3& sc, const std::vector<double>& F,
                              std::vector<glm::dvec3>& B);
    static Sweep gauss_seidel_sweep(const Scene3& sc, const std::vector<double>& F,
                                     std::vector<glm::dvec3>& B);
    // The shooter (most unshot power), or −1 when nothing is left to shoot.
    static int choose_shooter(const Scene3& sc, const std::vector<glm::dvec3>& unshot);
    // Patch i shoots; returns the residual max ΔB_j left. `shot` (if given) receives the shot.
    static double shoot(const Scene3& sc, const std::vector<double>& F, int i,
                        std::vector<glm::dvec3>& B, std::vector<glm::dvec3>& unshot,
                        glm::dvec3& shot_power, Shot* shot);
    static std::vector<std::uint32_t> image(const Scene3& sc, const std::vector<glm::dvec3>& B);
    // Throws InputError when some ρ = 1 makes the system diverge (the rule above).
    static void check_convergence(const Input& in, const Scene3& sc, const std::vector<double>& F);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
