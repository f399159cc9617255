// Toon shading: the diffuse term max(0, N·L) quantised to a few flat colours, face by face.
//
// The course gives two ways of saying the same thing. Ray tracing: compute the diffuse
// attenuation d = max(0, N̂·L̂) and quantise it to two or three colours. OpenGL: use d as the
// coordinate u of a one-dimensional texture holding two or three colours. Both are one rule:
// the thresholds 0 < t_1 < … < t_{n−1} < 1 are the edges of the texture's cells, cell b being
// [t_b, t_{b+1}) (t_0 = 0, t_n = 1, the last cell closed at 1), and
//   band(d) = the number of thresholds t_i with t_i ≤ d.
// A tie, d exactly on t_i, therefore goes to the BRIGHTER band, as a texel lookup puts a
// coordinate on a cell's left edge into that cell (the project's [i, i+1) pixel convention). A
// face turned away from the light, N·L < 0, has d = 0: the darkest band, 0.
//
// Conventions: faces counter-clockwise seen from outside, N̂ the unit Newell normal (flat, one
// per face); L̂ the unit direction FROM the surface TOWARDS the light (a directional light), the
// same for every face. The comparison d ≥ t_i is made in double as written; a threshold that
// N̂·L̂ equals only in exact arithmetic is decided by the rounded d.
//
// Steps: one per face (N̂, N̂·L̂, d, the band and its colour); done (the count per band).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "core/vec.hpp"
#include "npr/npr_mesh.hpp"

namespace cg {

struct ToonShading {
    struct Input {
        npr::Mesh mesh;                    // the faces to shade
        glm::dvec3 light{1, 1, 1};         // L, towards the light (any length but zero)
        std::vector<double> thresholds;    // t_1 < … < t_{n−1}, in (0, 1): n = 2 to 8 bands
        std::vector<glm::dvec3> colours;   // one RGB in [0, 1]³ per band, darkest first
        bool operator==(const Input&) const = default;
    };
    struct Result {
        std::vector<double> ndotl;  // N̂·L̂ per face (before clamping)
        std::vector<int> band;      // per face, 0 (darkest) to n − 1
        std::vector<int> counts;    // faces per band
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Face, Finish, Done };

    struct State {
        Shared<Input> in;           // never changes during a run
        glm::dvec3 l{0, 0, 0};      // L̂, the unit light direction
        Phase phase = Phase::Face;  // the step to take next
        Phase last = Phase::Face;   // the step taken last
        int k = 0;                  // the next face
        glm::dvec3 n{0, 0, 0};      // the face just shaded: N̂
        double ndotl = 0;           //   N̂·L̂
        int band = 0;               //   its band
        Result r;
        bool operator==(const State&) const = default;
    };
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.r.ndotl) + heap_bytes(s.r.band) + heap_bytes(s.r.counts);
    }

    static constexpr int kMinBands = 2, kMaxBands = 8;

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // a fresh state for a valid input
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static Result result(State&& s) { return std::move(s.r); }
    static void draw(const State& s, Scene& scene);

    // Exam practice (toon_shading_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The straight-line function, for a valid input (validate() first; start() does).
    static Result compute(const Input& in);

    // The rule itself: the band of diffuse intensity d (the number of thresholds ≤ d).
    static int band_of(double d, const std::vector<double>& thresholds) {
        int b = 0;
        for (double t : thresholds) b += d >= t;
        return b;
    }
    // The default palette for n bands: a warm orange from dark to light.
    static std::vector<glm::dvec3> default_colours(int n);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
