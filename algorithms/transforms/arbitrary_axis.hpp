// Rotation about an arbitrary axis through the origin, built the course's way: turn the axis
// onto the closest coordinate axis, rotate there, turn it back.
//
// Given the axis a = (a_x, a_y, a_z) ≠ 0 and the angle θ:
//   1. i ← the coordinate axis closest to a, i.e. with the largest |a_i| (ties: x, then y, then
//      z); j, k ← the next two in cyclic order (i = x: j = y, k = z; i = y: z, x; i = z: x, y).
//   2. φ = atan2(−a_k, a_i): R_j(−φ) turns a about axis j into the i–j plane (its k component
//      becomes 0): c = R_j(−φ) a = (a_i, a_j, a_k) → (r, a_j, 0) in (i, j, k) components, with
//      r = √(a_i² + a_k²) > 0 (never 0: |a_i| is the largest component).
//   3. γ = atan2(a_j, r): R_k(−γ) turns c about axis k onto axis i: R_k(−γ) c = |a| e_i.
//   4. R_i(θ), then undo 3 and 2:
//        R = R_j(φ) R_k(γ) R_i(θ) R_k(−γ) R_j(−φ),
//      i.e. for i = x:  R = R_y(φ) R_z(γ) R_x(θ) R_z(−γ) R_y(−φ)   (the course's formula),
//           for i = y:  R = R_z(φ) R_x(γ) R_y(θ) R_x(−γ) R_z(−φ),
//           for i = z:  R = R_x(φ) R_y(γ) R_z(θ) R_y(−γ) R_x(−φ).
// The course's note writes sin φ = z / √(x² + z²) for the x case, measuring φ from x toward z;
// with the right-handed R_y (which turns z toward x) that direction is a negative angle, so
// here sin φ = −a_k / r — the same construction, the sign that makes R_j(−φ) do what it says.
// The cosines and sines are taken from the axis's components (cos φ = a_i / r, sin γ = a_j/|a|),
// not from the angles, so no round-off enters through atan2 and back. The axis need not be unit
// length: only ratios are used (|a| is reported). θ > 0 turns counter-clockwise seen from the
// tip of a looking toward the origin; any finite θ is accepted (reduced modulo 360 exactly).
//
// Steps: choose-axis, to-plane (or already-in-plane when φ = 0), to-axis (or already-on-axis
// when γ = 0), rotate, undo-axis, undo-plane, compose, rotate-point per input point.
#pragma once

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "transforms/rotation_common.hpp"

namespace cg {

struct ArbitraryAxis {
    struct Input {
        glm::dvec3 axis{1, 1, 0};        // direction of the axis through the origin, ≠ 0
        double angle_deg = 90;           // θ, degrees
        std::vector<glm::dvec3> points;  // points to rotate; may be empty
        bool operator==(const Input&) const = default;
    };
    struct Result {
        glm::dmat3 matrix{1.0};          // R (the JSON shows its 4×4 homogeneous form)
        double phi_deg = 0;              // φ, (−180, 180]
        double gamma_deg = 0;            // γ, [−90, 90]
        int canonical = 0;               // i: 0 = x, 1 = y, 2 = z
        std::vector<glm::dvec3> points;  // R P for each input point
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        Choose,
        ToPlane,
        ToAxis,
        Rotate,
        UndoAxis,
        UndoPlane,
        Compose,
        Points,
        Done
    };

    struct State {
        Shared<Input> in;  // never changes during a run: copies of the state share it
        Phase phase = Phase::Choose;
        Phase last = Phase::Choose;
        int i = 0, j = 1, k = 2;  // the canonical axis and the two after it
        double scale = 1;         // max |a_i|
        glm::dvec3 as{1, 0, 0};   // a / scale (what the angles are computed from)
        double phi_deg = 0, gamma_deg = 0;
        rot::CosSin phi, gamma, theta;  // cos and sin of φ, γ, θ
        glm::dmat3 to_plane{1.0}, to_axis{1.0}, spin{1.0}, undo_axis{1.0}, undo_plane{1.0};
        glm::dmat3 R{1.0};
        int p = -1;                       // the point rotated last (−1: none yet)
        std::vector<glm::dvec3> rotated;  // R P so far
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // start() for an input already validated
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);  // moves the rotated points out (run_to_end)
    static void draw(const State& s, Scene& scene);

    // Exam practice (arbitrary_axis_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same construction as one straight-line function, for the benchmark.
    static Result rotate(const Input& in);

    // For the narration and the picture (computed there, not while stepping):
    static double length(const State& s);       // |a|
    static glm::dvec3 unit(const State& s);     // a / |a|
    static glm::dmat3 applied(const State& s);  // the product of the matrices applied so far

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
