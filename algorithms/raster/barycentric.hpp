// Barycentric coordinates of points in a triangle, as ratios of signed areas.
//
// For a triangle A, B, C and a point P, the weights (α, β, γ) with α + β + γ = 1 and
// P = αA + βB + γC are the ratios of the three sub-triangles' signed areas to the whole one:
//     α = area(P, B, C) / area(A, B, C),  β = area(A, P, C) / area(A, B, C),
//     γ = area(A, B, P) / area(A, B, C),
// the sub-triangle opposite a vertex giving that vertex's weight (P at A makes area(P, B, C)
// the whole triangle: α = 1).
//   - 2D: area(A, B, C) = ½ (B − A) × (C − A) = ½ ((Bx − Ax)(Cy − Ay) − (By − Ay)(Cx − Ax)),
//     signed: positive when A, B, C turn counter-clockwise. The sub-areas are signed the same
//     way, so the ratios do not depend on the triangle's orientation.
//   - 3D: the normal n = (B − A) × (C − A), area = |n|/2. A sub-area is its cross product
//     projected on the unit normal n̂ = n/|n|: area(P, B, C) = ½ ((C − B) × (P − B)) · n̂,
//     negative when P is beyond the edge BC. A point off the plane is first projected onto it,
//     P′ = P − d n̂ with d = (P − A) · n̂ (its signed distance: positive on the side n points to);
//     the weights are those of P′ (the cross products of P and P′ give the same dot with n̂).
//
// Inside and on the edge. `inside` includes the boundary: all three weights ≥ 0. `on_edge`
// says the point is on the boundary: inside, with at least one weight 0 (two at a vertex).
//   - 2D: decided exactly, with the exact orientation test of raster/orient2d.hpp applied to
//     (B, C, P), (C, A, P), (A, B, P): a point exactly on an edge is on it whatever rounding
//     does. The weights agree with it: a sub-area whose exact sign is 0 is exactly 0 (so an
//     edge point's weight is exactly 0), and one whose plain double formula came out with the
//     wrong sign (a point within rounding of an edge's line) is recomputed from an exact
//     expansion of the cross product, correct to about an ulp.
//   - 3D: a point given in a plane that is not a coordinate plane rarely lies in it exactly in
//     floating point, so the rule is a tolerance: a weight with |w| ≤ 1e-12 counts as 0. The
//     weights are ratios, so the tolerance is relative to the triangle's size. inside and
//     on_edge are about P′, the point projected onto the plane; `distance` says how far P is.
//
// Input rules: three vertices and every point have the same dimension, 2 or 3 (the JSON
// reader refuses a mix, naming the first point that differs). At least 1 and at most 1000
// points. Coordinates finite, within ±1e100, and 0 or at least 1e-100 in size (so products of
// coordinate differences neither overflow nor underflow, and the exact test is exact). A
// degenerate triangle is refused: collinear vertices (2D: exactly; 3D: n = 0), or so thin that
// its height is below 1e-9 of its longest edge (2|area| < 1e-9 · longest²), where the weights
// would be ratios of nearly vanishing areas.
//
// Steps: area (the whole triangle's, its orientation or normal); then per point: project (3D
// only: the distance and P′), areas (the three signed sub-areas), ratios (the weights and
// their sum), and the inside test (inside, on-edge or outside).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct Barycentric {
    static constexpr std::size_t kMaxPoints = 1000;
    static constexpr double kMaxCoordinate = 1e100;   // |coordinate| at most this
    static constexpr double kMinCoordinate = 1e-100;  // a non-zero coordinate at least this
    static constexpr double kMinShape = 1e-9;         // 2|area| / longest edge² at least this
    static constexpr double kEdgeTolerance3 = 1e-12;  // 3D: |weight| ≤ this counts as 0

    struct Input {
        int dim = 2;                           // 2 or 3; in 2D every z is 0
        std::array<glm::dvec3, 3> triangle{};  // A, B, C
        std::vector<glm::dvec3> points;        // P, … : 1 … kMaxPoints
        bool operator==(const Input&) const = default;
    };

    struct PointResult {
        glm::dvec3 areas{0};      // signed areas of (P, B, C), (A, P, C), (A, B, P)
        glm::dvec3 weights{0};    // (α, β, γ) = areas / area
        bool inside = false;      // all weights ≥ 0 (the boundary included)
        bool on_edge = false;     // inside, and on an edge or a vertex
        double distance = 0;      // 3D: signed distance of P from the plane (along n̂); 2D: 0
        glm::dvec3 projected{0};  // 3D: P′ = P − distance · n̂; 2D: P
        bool operator==(const PointResult&) const = default;
    };
    struct Result {
        int dim = 2;
        double area = 0;       // 2D: signed (> 0 counter-clockwise); 3D: |n|/2 > 0
        glm::dvec3 normal{0};  // 3D: n = (B − A) × (C − A); 2D: (0, 0, 2·area)
        std::vector<PointResult> results;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Area, Project, Areas, Ratios, Inside, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Area;  // the step to take next
        Phase last = Phase::Area;   // the step taken last
        double area = 0;
        glm::dvec3 normal{0};       // n
        glm::dvec3 unit_normal{0};  // n̂ (3D)
        int orient = 0;             // 2D: the exact sign of area(A, B, C)
        int k = -1;                 // the point being worked (its index)
        PointResult cur;            // its working so far
        glm::ivec3 signs{0};        // the signs of its sub-areas (2D exact; 3D with tolerance)
        std::vector<PointResult> results;  // the points finished
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);  // moves the list out (run_to_end's spent state)
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same computation as one straight-line function, for the benchmark and the tests.
    static Result compute(const Input& in);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
