// Free-form deformation (Sederberg and Parry), in the plane and in space: the space around a
// shape is bent, and the shape goes with it
//
// The course (animation, deformations): a free-form deformation changes the space around an
// object with a nonlinear transformation, instead of moving the object's vertices one by one.
// A lattice of (l+1)(m+1) control points P_ij is laid over an axis-aligned box [x_min, x_max] ×
// [y_min, y_max]; undeformed they sit evenly on it,
//
//   P_ij = X_0 + (i/l) S + (j/m) T,   X_0 = box min,  S = (x_max − x_min, 0),  T = (0, y_max − y_min)
//
// A point X of the shape is embedded by its local coordinates in the box,
//
//   s = (X − X_0)·S / |S|²,   t = (X − X_0)·T / |T|²     (0 ≤ s, t ≤ 1 inside the box)
//
// and after some control points have moved it goes to the Bernstein blend of the lattice,
//
//   X(s, t) = Σ_{i=0..l} Σ_{j=0..m} B_i^l(s) B_j^m(t) P_ij,   B_i^l(s) = C(l, i) s^i (1 − s)^(l−i)
//
// the n = 0 case of the trivariate Sederberg–Parry formula. In space (a 3D box, n ≥ 1) the
// lattice has (l+1)(m+1)(n+1) points P_ijk = X_0 + (i/l) S + (j/m) T + (k/n) U, U = (0, 0, z
// extent), the third local coordinate is u = (X − X_0)·U / |U|², and
//
//   X(s, t, u) = Σ_i Σ_j Σ_k B_i^l(s) B_j^m(t) B_k^n(u) P_ijk.
//
// The planar case keeps its own 2D fields and code (the *3 fields and functions are the spatial
// one), so a planar lattice computes exactly what it always did.
// Because Σ_i B_i^l(s) (i/l) = s (linear precision), the undeformed lattice maps every point to
// itself, and a lattice moved by an affine map moves every point inside by that same map.
//
// A point outside the box (s or t outside [0, 1]) is left where it is: the lattice deforms only
// the space it covers. (Evaluating the polynomial there would extrapolate it wildly; clamping
// s and t would smear every outside point onto the box's image of its edge.) A point exactly on
// the box's edge is inside, and since the edge's control points alone decide where it goes, a
// shape crossing the edge stays joined there only when that edge's control points did not move.
//
// Control points move by "by" (a displacement) or "to" (a position), applied in the order given
// (two moves of one point add up, or the later "to" wins). Refused: a degree outside 1..kMaxDegree,
// a box with max ≤ min on an axis, coordinates not finite or above 1e6 in size, a move naming a
// control point outside the lattice, no shape points, more than kMaxPoints points or kMaxMoves
// moves; in space also n outside 1..kMaxDegree (at most 9 × 9 × 9 control points), a flat box
// (zero depth), an edge naming a point the shape does not have, more than kMaxEdges edges.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct MorphFfd {
    static constexpr int kMaxDegree = 8;
    static constexpr int kMaxPoints = 5000;
    static constexpr int kMaxMoves = 1000;
    static constexpr double kMaxCoordinate = 1e6;

    struct Move {
        int i = 0, j = 0;          // the control point P_ij
        glm::dvec2 value{0, 0};    // the displacement, or the new position when `absolute`
        bool absolute = false;     // "to" rather than "by"
        bool operator==(const Move&) const = default;
    };

    static constexpr int kMaxEdges = 10000;

    struct Move3 {
        int i = 0, j = 0, k = 0;   // the control point P_ijk
        glm::dvec3 value{0, 0, 0};  // the displacement, or the new position when `absolute`
        bool absolute = false;
        bool operator==(const Move3&) const = default;
    };

    struct Input {
        glm::dvec2 box_min{0, 0}, box_max{1, 1};
        int l = 2, m = 2;  // the lattice's degrees along x (s) and y (t)
        std::vector<Move> moves;
        std::vector<glm::dvec2> shape;  // a polyline (a polygon when closed)
        bool closed = false;
        // In space: n ≥ 1 (the degree along z, u) makes the lattice spatial, and then the box,
        // moves and shape below replace the planar ones above (which are ignored).
        int n = 0;
        glm::dvec3 box3_min{0, 0, 0}, box3_max{1, 1, 1};
        std::vector<Move3> moves3;
        std::vector<glm::dvec3> shape3;  // a polyline (closed: a polygon), or a wireframe:
        std::vector<std::array<int, 2>> edges;  // when given, the shape's edges (index pairs)
        bool spatial() const { return n > 0; }
        bool operator==(const Input&) const = default;
    };

    // Bernstein weights of one parameter, B_0^d … B_d^d (only the first d + 1 used).
    using Weights = std::array<double, kMaxDegree + 1>;

    struct Result {
        std::vector<glm::dvec2> lattice;   // P_ij moved, at i·(m+1) + j
        std::vector<glm::dvec2> local;     // (s, t) of every shape point
        std::vector<char> inside;          // 1 when 0 ≤ s, t ≤ 1
        std::vector<glm::dvec2> deformed;  // X(s, t), or the point itself when outside
        int inside_count = 0;
        // In space, instead of the three above: P_ijk at (i·(m+1) + j)·(n+1) + k, (s, t, u), X'.
        std::vector<glm::dvec3> lattice3, local3, deformed3;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Lattice, Point, Summary, Done };

    struct State {
        Shared<Input> in;
        Shared<std::vector<glm::dvec2>> lattice;  // the moved control points, built once
        Phase phase = Phase::Lattice;
        Phase last = Phase::Lattice;
        int k = 0;  // shape points deformed so far
        std::vector<glm::dvec2> local, deformed;
        std::vector<char> inside;
        int inside_count = 0;
        Shared<std::vector<glm::dvec3>> lattice3;  // in space
        std::vector<glm::dvec3> local3, deformed3;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);  // validate(), then begin()
    static State begin(Shared<Input> validated);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.local) + heap_bytes(s.deformed) + heap_bytes(s.inside) +
               heap_bytes(s.local3) + heap_bytes(s.deformed3);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields() { return {"local/0", "deformed/0"}; }

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use (on a validated input).
    // The undeformed lattice, then the moves applied: P_ij at i·(m+1) + j.
    static std::vector<glm::dvec2> lattice(const Input& in);
    static glm::dvec2 rest(const Input& in, int i, int j);  // X_0 + (i/l) S + (j/m) T
    static glm::dvec2 local(const Input& in, glm::dvec2 x);  // (s, t)
    static bool inside(glm::dvec2 st) { return st.x >= 0 && st.x <= 1 && st.y >= 0 && st.y <= 1; }
    static void bernstein(int degree, double u, Weights& b);
    // X(s, t) = Σ_i Σ_j B_i^l(s) B_j^m(t) P_ij (for any s, t: the caller decides outside).
    static glm::dvec2 blend(const Input& in, const std::vector<glm::dvec2>& lattice,
                            glm::dvec2 st);
    // Where x goes: the blend inside the box, x itself outside.
    static glm::dvec2 deform(const Input& in, const std::vector<glm::dvec2>& lattice,
                             glm::dvec2 x);

    // The same in space (n ≥ 1): P_ijk at (i·(m+1) + j)·(n+1) + k.
    static std::vector<glm::dvec3> lattice3(const Input& in);
    static glm::dvec3 rest3(const Input& in, int i, int j, int k);
    static glm::dvec3 local3(const Input& in, glm::dvec3 x);  // (s, t, u)
    static bool inside3(glm::dvec3 stu) {
        return stu.x >= 0 && stu.x <= 1 && stu.y >= 0 && stu.y <= 1 && stu.z >= 0 && stu.z <= 1;
    }
    static glm::dvec3 blend3(const Input& in, const std::vector<glm::dvec3>& lattice,
                             glm::dvec3 stu);
    static glm::dvec3 deform3(const Input& in, const std::vector<glm::dvec3>& lattice,
                              glm::dvec3 x);
    static void draw3(const State& s, Scene& scene);

  private:
    static void take_step(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
    // The spatial case's own parts (morph_ffd_space.cpp).
    static void validate3(const Input& in);
    static void take_step3(State& s);
    [[gnu::cold]] static void narrate3(const State& s, StepInfo& info);
    static Result compute3(const Input& in);
};

}  // namespace cg
