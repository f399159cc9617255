// Ray-quadric intersection, step by step: the course's "direct implicit form" — substitute the
// ray E + t d into the surface's equation F = 0 and solve the quadratic in t.
//
// Steps (one each): carry the ray into model space by the inverse transform ("instead of
// solving generally, solve the simple version and transform"); substitute and collect the
// quadratic's coefficients a, b, c; the discriminant Δ = b² − 4ac (or the linear case a = 0,
// or no equation at all); the roots, without cancellation; the nearest root t > ε inside the
// optional z slab; the hit point E + t d; the normal ∇F carried back by the inverse transpose.
// The surfaces, their equations, the tolerances and the conventions (t in units of the given
// direction, normal along ∇F, i.e. out of the solid) are those of rays/quadric.hpp, whose
// plain intersect() computes the same numbers in one call.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "rays/quadric.hpp"

namespace cg {

struct RayQuadric {
    struct Input {
        Quadric quadric;
        glm::dvec3 origin{0.0};     // E, world space
        glm::dvec3 direction{0.0};  // d, world space, ≠ 0, not necessarily unit
        bool operator==(const Input&) const = default;
    };
    using Result = QuadricHit;

    enum class Phase : std::uint8_t {
        ToModel,
        Coefficients,
        Discriminant,
        Roots,
        Nearest,
        HitPoint,
        Normal,
        Done
    };

    // Why a root is not the hit.
    enum class Verdict : std::uint8_t { Pending, Behind, OutsideSlab, Chosen, Farther };

    struct State {
        Shared<Input> in;  // never changes during a run: copies of the state share it
        Phase phase = Phase::ToModel;  // the step to take next
        Phase last = Phase::ToModel;   // the step taken last (what narrate tells)
        PreparedQuadric prepared;
        RayQuadratic quad;     // model-space ray and a, b, c
        QuadraticRoots roots;  // the case, Δ and the roots
        std::array<Verdict, 2> verdict{Verdict::Pending, Verdict::Pending};
        glm::dvec3 model_point{0.0};  // the hit in model space
        QuadricHit hit;               // filled as the steps go
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // start() for an input already validated
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.hit; }
    static void draw(const State& s, Scene& scene);

    // Exam practice (ray_quadric_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The plain function, for the benchmark and for tracers.
    static Result solve(const Input& in) { return intersect(in.quadric, in.origin, in.direction); }

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

// "x^2 + y^2 = z", "\frac{x^2}{4} + \frac{y^2}{9} = 1": the equation with its numbers, as text
// (LaTeX when `latex`) — shared by the narration and the exam's question.
std::string quadric_equation(const Quadric& s, bool latex);

}  // namespace cg
