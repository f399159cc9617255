// Anti-aliasing one pixel by supersampling, beside the exact area-sampled value.
//
// The course: a pixel is not a point but a little area; its true value is the integral of the
// image over that area (area sampling), weighted toward its centre if we like (weighted
// sampling). A ray tracer cannot integrate, so it point-samples: more samples per pixel,
// averaged with a filter's weights (supersampling). Samples on a regular grid still alias (an
// edge nearly along the grid crosses all its rows at once); random positions turn the error
// into noise; jittered (stratified) ones — one random point per grid cell — keep the noise
// small as well.
//
// The pixel (i, j) covers [i, i+1) × [j, j+1); the scene is a polygon edge (a half-plane) or a
// simple polygon, of value 1 inside and 0 outside (sampling/coverage.hpp). Patterns and filters
// are sampling/patterns.hpp's: sample k sits at (i, j) + the pattern's k-th point, and weighs
// w_k = filter(x_k − i − ½, y_k − j − ½).
//
// Steps: pattern (the positions, how they were made); one step per sample — inside or outside,
// its value and weight and the running sums; estimate (Σ w_k v_k / Σ w_k); exact (the covered
// part of the pixel, the pixel clipped against the edge or the polygon clipped against the
// pixel, and ∫∫ w over it / ∫∫ w over the pixel), with the error, estimate − exact.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "sampling/coverage.hpp"
#include "sampling/patterns.hpp"

namespace cg {

struct Supersampling {
    static constexpr int kMaxSamples = 1024;
    static constexpr int kMaxPolygon = 256;        // polygon vertices
    static constexpr double kMaxCoordinate = 1e6;  // |coordinates| and |pixel indices|
    static constexpr int kMaxStudyEdges = 1000;    // trials per point
    static constexpr int kMaxStudySamples = 256;   // the largest N in a study
    static constexpr int kMaxStudyCounts = 8;      // how many values of N
    static constexpr int kMaxStudyWork = 204800;   // edges × Σ N, per pattern: a run under ~1 s

    // The convergence study: RMS error against N, per pattern, over random edges.
    struct Study {
        std::vector<sampling::Pattern> patterns;  // distinct, in the order measured
        std::vector<int> samples;                 // increasing; n² for regular and jittered
        int edges = 400;                          // trials per (pattern, N) point
        bool near_axis = false;                   // edges within 1° of the x axis, else any angle
        bool operator==(const Study&) const = default;
    };

    struct Input {
        sampling::Pattern pattern = sampling::Pattern::Jittered;
        int samples = 16;  // count; n² for regular and jittered
        sampling::Filter filter = sampling::Filter::Box;
        double radius = 0;  // poisson: the dart-throwing distance, pixel units (0: 0.7/√count)
        int i = 0, j = 0;   // the pixel
        sampling::Region scene;
        std::uint64_t seed = 1;
        bool is_study = false;  // a convergence study (study, filter, seed) instead of a pixel
        Study study;
        bool operator==(const Input&) const = default;
    };

    struct StudyPoint {
        sampling::Pattern pattern = sampling::Pattern::Regular;
        int samples = 0;
        double rms_error = 0;  // √(mean over the edges of (estimate − exact)²)
        bool operator==(const StudyPoint&) const = default;
    };
    struct Slope {
        sampling::Pattern pattern = sampling::Pattern::Regular;
        double slope = 0;  // least squares of log10 error against log10 N, over N ≥ 4
        bool operator==(const Slope&) const = default;
    };

    struct Sample {
        glm::dvec2 p{0.0};  // in the image, pixel units
        double value = 0;   // f(p): 1 inside, 0 outside
        double weight = 1;  // the filter's weight
        bool operator==(const Sample&) const = default;
    };

    struct Result {
        std::vector<Sample> samples;
        double weight_sum = 0;            // Σ w_k
        double estimate = 0;              // Σ w_k v_k / Σ w_k
        double exact = 0;                 // ∫∫ w f / ∫∫ w over the pixel
        double error = 0;                 // estimate − exact
        double radius = 0;                // poisson: the radius used (else 0)
        std::vector<glm::dvec2> covered;  // the covered part of the pixel (counter-clockwise)
        std::vector<StudyPoint> study;    // a study: the points, pattern by pattern
        std::vector<Slope> slopes;        // a study: one per pattern
        bool is_study = false;            // a study's result (the fields above it are unused)
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Pattern, Sample, Estimate, Exact, Point, Slopes, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Pattern;
        Phase last = Phase::Pattern;
        double radius = 0;
        std::vector<sampling::PatternPoint> points;  // the pattern, in [0, 1)²
        int k = -1;                                  // the sample taken last
        std::vector<Sample> samples;
        double sum_w = 0, sum_wv = 0;
        double estimate = 0;
        std::vector<glm::dvec2> covered;
        double covered_integral = 0;  // ∫∫ w over the covered part
        double exact = 0;
        std::vector<StudyPoint> study;  // a study: the points shown so far
        std::vector<Slope> slopes;      // a study: after the last step
        // A study's points, all measured in start (0.1 s for the lesson's studies): each step
        // then shows one, so that a step stays instant (one point is 400 × N supersamples).
        Shared<std::vector<StudyPoint>> measured;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    // Refuses what start refuses, without measuring a study's error curves (what loading a
    // lesson's presets needs; see make_algorithm).
    static void check(const Input& in) { validate(in); }
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.points) + heap_bytes(s.samples) + heap_bytes(s.covered) +
               heap_bytes(s.study) + heap_bytes(s.slopes);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same numbers in one straight-line function, for the benchmark and the tests.
    static Result supersample(const Input& in);
    // The radius poisson uses for this input (else 0).
    static double radius_of(const Input& in);

    // The study's experiment, one definition for the algorithm and the tests: trial t (0-based)
    // of the point (pattern, N) supersamples pixel (0, 0) with in.filter, against an
    // edge through a uniform point of the pixel at a uniform angle in [0°, 360°) (near-axis:
    // [−1°, 1°)) from Rng(50000 + t) — the same edges for every seed — with the pattern's seed
    // in.seed · kMaxStudyEdges + t.
    static Input study_trial(const Input& in, sampling::Pattern pattern, int samples, int t);
    // The RMS of supersample(study_trial(…)).error over the in.study.edges trials.
    static double study_rms(const Input& in, sampling::Pattern pattern, int samples);
    // The least-squares slope of log10 rms against log10 N over the points with N ≥ 4.
    static double study_slope(const std::vector<StudyPoint>& points, sampling::Pattern pattern);
    // The whole study in one straight-line function.
    static Result run_study(const Input& in);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
    static void validate_study(const Input& in);
    static void advance_study(State& s);
    [[gnu::cold]] static void narrate_study(const State& s, StepInfo& info);
    static void draw_study(const State& s, Scene& scene);
};

}  // namespace cg
