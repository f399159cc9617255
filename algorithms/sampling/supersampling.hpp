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

    struct Input {
        sampling::Pattern pattern = sampling::Pattern::Jittered;
        int samples = 16;  // count; n² for regular and jittered
        sampling::Filter filter = sampling::Filter::Box;
        double radius = 0;  // poisson: the dart-throwing distance, pixel units (0: 0.7/√count)
        int i = 0, j = 0;   // the pixel
        sampling::Region scene;
        std::uint64_t seed = 1;
        bool operator==(const Input&) const = default;
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
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Pattern, Sample, Estimate, Exact, Done };

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
        return heap_bytes(s.points) + heap_bytes(s.samples) + heap_bytes(s.covered);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same numbers in one straight-line function, for the benchmark and the tests.
    static Result supersample(const Input& in);
    // The radius poisson uses for this input (else 0).
    static double radius_of(const Input& in);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
