// Transforming normals: why a normal goes through the inverse transpose.
//
// Points and tangent vectors (differences of points) transform by the linear part L of a
// transformation (the upper 3×3 of an affine 4×4). A normal is not a difference of points: it
// is defined by being perpendicular to every tangent, n · t = 0. Under a non-uniform scale or a
// shear, L n is no longer perpendicular to the transformed tangents L t. The matrix that keeps
// the perpendicularity is N = (L⁻¹)ᵀ: (N n) · (L t) = nᵀ L⁻¹ L t = n · t = 0. For a rotation
// (times a uniform scale) N is L up to that scale, which is why the difference goes unnoticed
// until a model is squashed.
//
// Steps: the linear part and its determinant; two tangents spanning the plane the normal
// stands on (given, or built perpendicular to n); the naive image L n with its dot products
// against L t₁ and L t₂ (naive-works when both vanish, naive-fails otherwise); the inverse
// transpose, as cofactors over the determinant; the correct image N n, its dots (zero up to
// round-off) and its unit vector.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct NormalTransform {
    // |cos| of the angle between a vector and the plane it should lie in, below which the
    // naive normal counts as still perpendicular (and given tangents as perpendicular to n).
    static constexpr double kPerpTolerance = 1e-9;

    struct Input {
        glm::dmat3 linear{1.0};    // the upper 3×3 of the transformation, invertible
        glm::dvec3 normal{0, 0, 1};  // non-zero
        bool has_tangents = false;
        std::array<glm::dvec3, 2> tangents{};  // perpendicular to the normal, independent
        bool operator==(const Input&) const = default;
    };

    struct Result {
        double det = 1;
        std::array<glm::dvec3, 2> tangents{};    // t₁, t₂ as used
        std::array<glm::dvec3, 2> images{};      // L t₁, L t₂
        glm::dvec3 naive{0, 0, 0};               // L n
        std::array<double, 2> naive_cos{};       // cos between L n and L tᵢ
        bool naive_ok = true;                    // both |cos| ≤ kPerpTolerance
        glm::dmat3 inverse_transpose{1.0};       // (L⁻¹)ᵀ
        glm::dvec3 normal{0, 0, 0};              // N n
        glm::dvec3 unit_normal{0, 0, 0};         // N n / |N n|
        std::array<double, 2> cos{};             // cos between N n and L tᵢ: 0 up to round-off
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Linear, Tangents, Naive, InverseTranspose, Correct, Done };

    struct State {
        Shared<Input> in;  // never changes during a run: copies of the state share it
        Phase phase = Phase::Linear;
        Phase last = Phase::Linear;
        Result r;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // start() for an input already validated
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    static Result transform(const Input& in);  // the straight-line version
    // The tangents t₁, t₂ the run uses: the input's, or two built perpendicular to n.
    static std::array<glm::dvec3, 2> tangents_of(const Input& in);

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
