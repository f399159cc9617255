// Change of basis: the coordinates of a point relative to one frame, rewritten relative to
// another. Points do not move; only their representation changes.
//
// A frame F = (a₁, a₂, a₃, O) is three independent axes and an origin, all given in world
// coordinates. The coordinates (p₁, p₂, p₃) of P relative to F mean P = p₁a₁ + p₂a₂ + p₃a₃ + O,
// i.e. P = world_from_F p with world_from_F = [a₁ a₂ a₃ O; 0 0 0 1] (columns, homogeneous, p
// with w = 1). For F1 = (v₁, v₂, v₃, O_v) and F2 = (w₁, w₂, w₃, O_w):
//   M₁,₂ = F2_from_world · world_from_F1 = (world_from_F2)⁻¹ · world_from_F1,   p' = M₁,₂ p,
// the course's "solve F1 = F2 M₁,₂". When F2 is orthonormal its inverse needs no elimination:
// the rows of F2_from_world are w_iᵀ with translation −w_i · O_w, and the entries of M₁,₂ are
//   f_ij = w_i · v_j,   f_i4 = (O_v − O_w) · w_i.
// (The review notes write this with the frames' letters swapped — F_1 = (w₁, w₂, O_w), dotted
// with v_i — which is the same formula; with F1 = (v…) as here it reads as above.) A vector
// (w = 0) has no position, so it transforms by the upper 3×3 only.
//
// Steps: world-from-f1 (with every point's world position), world-from-f2, inverse (or
// inverse-orthonormal: the shortcut), compose, then map-point per point and map-vector per
// vector, each checked against the world position. 3D only: a 2D frame is z = 0 with third
// axis (0, 0, 1). Conventions: right-handed world, column vectors, matrices as rows in JSON;
// frames themselves may be left-handed.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct ChangeOfBasis {
    // |det| / (|a₁| |a₂| |a₃|) at or below which a frame's axes count as linearly dependent
    // (1 for orthogonal axes, 0 for coplanar ones; the same test as normal-transform's).
    static constexpr double kSingularTolerance = 1e-12;
    // |w_i · w_j − δ_ij| at or below which F2 counts as orthonormal (the shortcut applies).
    static constexpr double kOrthonormalTolerance = 1e-9;
    // Every input number must be within ±kMaxMagnitude and every axis at least kMinAxis long,
    // so that products of three of them (a determinant, a coordinate) cannot overflow.
    static constexpr double kMaxMagnitude = 1e100;
    static constexpr double kMinAxis = 1e-100;

    struct Frame {
        glm::dvec3 origin{0, 0, 0};  // O, world coordinates
        std::array<glm::dvec3, 3> axes{glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0),
                                       glm::dvec3(0, 0, 1)};  // a₁, a₂, a₃, world, independent
        bool operator==(const Frame&) const = default;
    };

    struct Input {
        Frame from;                       // F1 = (v₁, v₂, v₃, O_v)
        Frame to;                         // F2 = (w₁, w₂, w₃, O_w)
        std::vector<glm::dvec3> points;   // coordinates relative to F1 (w = 1); may be empty
        std::vector<glm::dvec3> vectors;  // coordinates relative to F1 (w = 0); may be empty
        bool operator==(const Input&) const = default;
    };

    struct Result {
        glm::dmat4 world_from_f1{1.0};    // [v₁ v₂ v₃ O_v]
        glm::dmat4 world_from_f2{1.0};    // [w₁ w₂ w₃ O_w]
        glm::dmat4 f2_from_world{1.0};    // its inverse
        glm::dmat4 matrix{1.0};           // M₁,₂: F1 coordinates → F2 coordinates
        bool orthonormal_to = false;      // F2 orthonormal: the shortcut was used
        std::vector<glm::dvec3> points;   // M₁,₂ p: relative to F2
        std::vector<glm::dvec3> vectors;  // M₁,₂ u (w = 0): relative to F2
        std::vector<glm::dvec3> world;    // world_from_F1 p: the points in world coordinates
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        WorldFromF1,
        WorldFromF2,
        Inverse,
        Compose,
        Points,
        Vectors,
        Done
    };

    struct State {
        Shared<Input> in;  // never changes during a run: copies of the state share it
        Phase phase = Phase::WorldFromF1;
        Phase last = Phase::WorldFromF1;
        Result r;  // filled step by step; the point (vector) mapped last is r.points.back()
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // start() for an input already validated
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static Result result(State&& s) { return std::move(s.r); }
    static void draw(const State& s, Scene& scene);

    // Exam practice (change_of_basis_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same computation straight through, for the benchmark (the tests check it equals the
    // steps exactly).
    static Result transform(const Input& in);

    // The pieces, shared by the steps, the straight-line version and the tests:
    static glm::dmat4 world_from(const Frame& f);  // [a₁ a₂ a₃ O; 0 0 0 1]
    static bool orthonormal(const Frame& f);       // within kOrthonormalTolerance
    static glm::dmat4 inverse_general(const Frame& f);  // [L⁻¹ | −L⁻¹ O], L⁻¹ by cross products
    static glm::dmat4 inverse_orthonormal(const Frame& f);  // rows a_iᵀ, translation −a_i · O

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
