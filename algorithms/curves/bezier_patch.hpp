// Tensor-product Bézier patches: a surface point by de Casteljau along s, then along t.
//
// A grid of (m + 1) × (n + 1) control points P_ij (row i, column j) spans the surface
//
//     P(s, t) = Σ_i Σ_j P_ij B_i^m(s) B_j^n(t),     s, t ∈ [0, 1],
//
// whose blending functions are products of the curves' Bernstein polynomials. Summing over i
// first, each column j (P_0j .. P_mj) is a Bézier curve in s; evaluated by de Casteljau it gives
//
//     Q_j = Σ_i P_ij B_i^m(s),
//
// and Q_0 .. Q_n are the control points of the curve t ↦ P(s, t) on the surface, so one more
// de Casteljau run, in t, gives P(s, t). The partial derivatives come the same way:
// ∂P/∂t is the derivative of the Q curve, n (Q_1^{n−1} − Q_0^{n−1}); ∂P/∂s blends the columns'
// s-derivatives R_j = m Σ_i (P_{i+1,j} − P_ij) B_i^{m−1}(s) in t. Their cross product, scaled to
// length 1, is the surface normal. Where the two derivatives are parallel or one of them
// vanishes (a collapsed corner or edge: several control points on top of each other) the
// cross product is zero and the normal is undefined there: the result says so
// (normal_defined = false, normal = 0) instead of dividing by zero.
//
// Steps: one per column j (its de Casteljau triangle in s, giving Q_j and R_j), then the point
// (de Casteljau in t on the Q_j), the two derivatives, the normal, and the tessellation: the
// surface sampled at s = a/N, t = b/N (a, b = 0 .. N), stored row-major (vertex a (N + 1) + b),
// each grid cell split along its diagonal into two triangles
//     (a, b) (a+1, b) (a+1, b+1)   and   (a, b) (a+1, b+1) (a, b+1),
// counter-clockwise seen from the side ∂P/∂s × ∂P/∂t points to, so their normals agree with the
// surface normal.
//
// Conventions: degrees m, n in 1 .. 10; points [x, y, z]; s and t in [0, 1] unless
// `extrapolate` is set (then within ±1000; the tessellation always covers [0, 1]²);
// tessellation N in 1 .. 64.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "curves/bezier.hpp"

namespace cg {

struct BezierPatch {
    static constexpr int kMaxDegree = 10;        // per direction
    static constexpr int kMaxTessellation = 64;  // (N + 1)² = 4,225 vertices at most
    using Row = std::array<glm::dvec3, kMaxDegree + 1>;

    struct Input {
        std::vector<std::vector<glm::dvec3>> control_points;  // rows i = 0 .. m, columns j = 0 .. n
        double s = 0.5, t = 0.5;
        int tessellation = 8;      // N: the grid of the triangle mesh
        bool extrapolate = false;  // allow s, t outside [0, 1]
        bool operator==(const Input&) const = default;
    };

    struct Result {
        int m = 0, n = 0;  // the degrees in s and t
        double s = 0, t = 0;
        glm::dvec3 point{0};             // P(s, t)
        glm::dvec3 ds{0}, dt{0};         // ∂P/∂s, ∂P/∂t
        glm::dvec3 normal{0};            // unit ∂P/∂s × ∂P/∂t; 0 when undefined
        bool normal_defined = false;     // false where the derivatives are parallel or zero
        std::vector<glm::dvec3> column_points;  // Q_0 .. Q_n
        int tessellation = 0;                   // N
        std::vector<glm::dvec3> vertices;       // (N + 1)², row-major
        int triangle_count() const { return 2 * tessellation * tessellation; }
        std::array<int, 3> triangle(int k) const;  // vertex indices of triangle k (see above)
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Column, Point, Derivatives, Normal, Tessellate, Done };

    struct State {
        Shared<Input> in;
        int m = 0, n = 0;
        Phase phase = Phase::Column;
        int j = 0;  // columns done
        Row q{}, r{};  // Q_j and R_j of the columns done
        glm::dvec3 point{0}, ds{0}, dt{0}, normal{0};
        bool normal_defined = false;
        double scale = 0;                  // the largest |coordinate| of the control points
        std::vector<glm::dvec3> vertices;  // filled by the last step
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);       // throws InputError naming the field
    static State start(const Input& in);         // validate, then begin
    static State begin(const Input& in);         // the initial state of a known-good input
    static void step(State& s, StepInfo* info);  // advance, then narrate if info is given
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (bezier_patch_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same evaluation as one straight-line function, for the benchmark's comparison.
    static Result evaluate(const Input& in);

    // Shared by the steps, evaluate() and the picture: P(s, t) via the columns, the unit normal
    // of two derivatives (false when undefined), and the (N + 1)² tessellation vertices.
    static glm::dvec3 point_at(const Input& in, double s, double t);
    // A derivative no longer than 1e-12 · scale (the largest |coordinate| of the control points)
    // counts as zero.
    static bool unit_normal(glm::dvec3 ds, glm::dvec3 dt, double scale, glm::dvec3& normal);
    static std::vector<glm::dvec3> tessellate(const Input& in, int N);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
