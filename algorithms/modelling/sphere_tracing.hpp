// Sphere tracing: a ray marched through a signed distance field (Hart 1996).
//
// The course ("Rendering Implicit Surfaces": ray tracing, sphere tracing, marching cubes): a
// surface given as the zero set of f, with f(p) a signed distance bound — below 0 inside, above
// 0 outside, and never more than the distance from p to the surface (|f(p) − f(q)| ≤ |p − q|,
// f is 1-Lipschitz). Then the open ball of radius f(p) around p holds no surface, and a ray at
// p may step forward by f(p) without passing through it (the "unbounding sphere"):
//   t₀ = 0;  p_k = o + t_k·d̂;  d_k = f(p_k);  hit if d_k < ε;  else t_k+1 = t_k + d_k;
//   a miss once t_k+1 > max_distance (the ray escaped) or after max_steps samples.
// The scene: spheres, axis-aligned boxes and tori (axis parallel to y, the tube around a circle
// in the plane y = centre.y), each an exact signed distance, combined by
//   union         min(a, b)             exact outside, an under-estimate inside
//   intersection  max(a, b)             an under-estimate (still a safe bound)
//   difference    max(a, −b), the first shape minus all the others (an under-estimate)
//   smooth-union  smin_k(a, b) = lerp(b, a, h) − k·h·(1−h), h = clamp(½ + (b−a)/(2k), 0, 1)
//                 (polynomial smooth minimum; its gradient is h∇a + (1−h)∇b, so it stays
//                 1-Lipschitz: not the exact distance to its blended surface but never more,
//                 so the march stays safe, only slower)
// folded left over the shapes in the order given. A ray starting inside (d₀ < 0 < ε) hits at
// t = 0. Coordinates right-handed, y up; the picture is the slice plane holding the ray (the
// plane z = o.z when the ray is horizontal, so the lesson's scenes read in world x and y).
//
// Steps: one sample per step (p_k, d_k, and the step across the unbounding sphere), then the
// verdict — hit, escaped past max_distance, or out of steps.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "core/vec.hpp"

namespace cg {

struct SphereTracing {
    static constexpr int kMaxShapes = 16;
    static constexpr int kMaxSteps = 10000;
    static constexpr double kMaxCoordinate = 1e6;  // centres, origin, sizes, distances

    enum class Kind : std::uint8_t { Sphere, Box, Torus };
    enum class Combine : std::uint8_t { Union, Intersection, Difference, SmoothUnion };
    enum class Outcome : std::uint8_t { Hit, Escaped, OutOfSteps };

    struct Shape {
        Kind kind = Kind::Sphere;
        glm::dvec3 centre{0, 0, 0};
        // sphere: (radius, –, –); box: half extents; torus: (major R, minor r, –)
        glm::dvec3 size{1, 1, 1};
        bool operator==(const Shape&) const = default;
    };

    struct Input {
        std::vector<Shape> shapes;
        Combine combine = Combine::Union;
        double k = 0.5;  // the smooth union's blending radius
        glm::dvec3 origin{0, 0, 0};
        glm::dvec3 direction{1, 0, 0};  // any nonzero length; normalised
        double epsilon = 1e-3;          // ε: a hit once d < ε
        double max_distance = 100;      // a miss once t exceeds it
        int max_steps = 100;            // a miss after this many samples
        bool operator==(const Input&) const = default;
    };

    struct Result {
        Outcome outcome = Outcome::OutOfSteps;
        double t = 0;                // the last t (the hit's, or the one past max_distance)
        glm::dvec3 point{0, 0, 0};   // o + t·d̂
        int samples = 0;             // distance evaluations
        std::vector<double> ts, ds;  // t_k and d_k of every sample
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { March, Verdict, Done };

    struct State {
        Shared<Input> in;
        glm::dvec3 unit{1, 0, 0};  // d̂
        Phase phase = Phase::March;
        Phase last = Phase::March;
        Outcome outcome = Outcome::OutOfSteps;
        int k = 0;          // samples taken
        double t = 0;       // t_k: the next sample's distance along the ray
        double t_prev = 0;  // the last sample's t
        double d = 0;       // the last sample's distance
        std::vector<double> ts, ds;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);   // validates, then begin()
    static State begin(Shared<Input> in);  // a fresh state for a valid input
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) { return heap_bytes(s.ts) + heap_bytes(s.ds); }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use.
    static double shape_distance(const Shape& s, glm::dvec3 p);  // exact signed distance
    static double smooth_min(double a, double b, double k);
    static double distance(const Input& in, glm::dvec3 p);  // the scene's bound f(p)
    static const char* kind_name(Kind k);
    static const char* combine_name(Combine c);
    static const char* outcome_name(Outcome o);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
