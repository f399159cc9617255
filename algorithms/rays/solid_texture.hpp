// Solid textures, step by step: a 3D procedural texture evaluated at the point itself (the
// textures, Perlin's noise and its conventions are rays/noise.hpp's).
//
// For each point one step gives its colour. For the point chosen by `detail` (default the
// first) of a noisy texture (wood, marble) the noise is worked in full first: the lattice cell
// ⌊f p⌋ and the point's place in it; the eight corners' gradients and their ramps g·(p − c);
// the fade curve's weights; the seven interpolations (four in z, two in y, one in x); then, for
// marble, the turbulence's octaves; then the colour.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "rays/noise.hpp"

namespace cg {

struct SolidTextureAlgo {
    struct Input {
        SolidTexture texture;
        std::vector<glm::dvec3> points;
        int detail = 0;  // the point whose noise is worked step by step
        bool operator==(const Input&) const = default;
    };
    static constexpr std::size_t kMaxPoints = 100000;

    struct Result {
        std::vector<SolidSample> samples;  // per point
        bool noisy = false;                // wood, marble
        bool has_detail = false;           // a noisy texture: the detail point's noise
        NoiseDetail detail;
        std::vector<double> octaves;  // marble: |noise(2^k f p)| / 2^k of the detail point
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        Point,
        Lattice,
        Gradients,
        Fade,
        Interpolate,
        Turbulence,
        Colour,
        Done
    };

    struct State {
        Shared<Input> in;
        Perlin perlin;
        Phase phase = Phase::Point;
        Phase last = Phase::Point;
        std::size_t next = 0;  // the next point
        Result r;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static Result result(State&& s) { return std::move(s.r); }
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return s.r.samples.capacity() * sizeof(SolidSample) +
               s.in->points.capacity() * sizeof(glm::dvec3);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    static Result solve(const Input& in);

    // The point at which the noise is evaluated: f p.
    static glm::dvec3 noise_point(const SolidTexture& t, glm::dvec3 p) { return t.frequency * p; }

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
