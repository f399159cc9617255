// Projective (planar) shadows: the 4×4 matrix that flattens a polygon onto a plane from a point
// or directional light, applied vertex by vertex.
//
// Conventions: column vectors p' = M p, homogeneous points p = [x, y, z, 1]. The plane is
// n · x + d = 0, written as the row P = [n_x, n_y, n_z, d] so that P · p = n · p + d is the
// (scaled) signed height of p above the plane. The light is L = [L_x, L_y, L_z, 1] for a point
// light, or L = [l_x, l_y, l_z, 0] for a directional light, l pointing TOWARD the light (where
// the sun is, as the lighting vector L), so its rays travel along −l.
//
// The shadow matrix:  M = (P · L) I − L P   (L a column, P a row: the outer product L Pᵀ), i.e.
//   M_ij = (P · L) δ_ij − L_i P_j,   with P · L = n · L + d w_L =: h_L.
// For any p:  M p = h_L p − (P · p) L, a combination of p and L, so on the line through p and
// the light; and P · (M p) = h_L (P · p) − (P · p) h_L = 0, so on the plane. It is therefore
// the ray–plane intersection, a perspective projection whose centre is the light. For a point
// light w' = h_L − h_p (h_p = n · p + d), and after the divide
//   s = (h_L p − h_p L) / (h_L − h_p);
// for a directional light w' = n · l for every vertex and s = p − h_p l / (n · l).
// M M = h_L M: applying it twice flattens nothing more (a projection, up to the scale h_L).
//
// The plane is oriented so that the light is on its positive side: when h_L < 0, (n, d) is
// replaced by (−n, −d) (the same plane; M changes sign, the same projective map). Then a vertex
// casts a shadow exactly when it is on the light's side (h_p ≥ 0) and, for a point light,
// below the light (w' = h_L − h_p > 0). The per-vertex cases:
//   vertex            0 < h_p < h_L (point) / h_p > 0 (directional): the shadow point s;
//   on-plane          h_p = 0: p maps to itself (w' = h_L);
//   level-with-light  w' = 0 (or the divide overflows): the ray is parallel to the plane, the
//                     "shadow" is a point at infinity: no shadow;
//   above-light       w' < 0: the vertex is higher than the light; the line from the light
//                     through it meets the plane behind the light (the anti-shadow), no shadow;
//   behind-plane      h_p < 0: the vertex is on the far side of the plane; M gives the crossing
//                     between the light and the vertex (a false shadow), no shadow.
// Refused: the zero normal, a point light on the plane (h_L = 0: M has rank 1 and sends
// everything to L), a directional light parallel to the plane (n · l = 0), a light with w other
// than 0 or 1, fewer than 3 or more than kMaxVertices vertices, and inputs whose matrix or
// products overflow.
//
// Steps: setup (P, L, h_L; or flip-plane when the plane had to be turned round), matrix (M, each
// entry's formula), then one step per vertex (p' = M p, the divide by w', the shadow point, or
// one of the cases above), then polygon (the shadow polygon).
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct ProjectiveShadow {
    static constexpr std::size_t kMaxVertices = 64;

    struct Input {
        glm::dvec3 normal{0, 1, 0};  // the plane n · x + d = 0 (n need not be unit)
        double d = 0;
        glm::dvec4 light{0, 4, 0,
                         1};  // [x, y, z, 1] a point light, [l_x, l_y, l_z, 0] toward the sun
        std::vector<glm::dvec3> polygon;
        bool operator==(const Input&) const = default;
    };

    // What happened to one vertex.
    enum class Case : std::uint8_t {
        Pending,
        Shadow,
        OnPlane,
        LevelWithLight,
        AboveLight,
        BehindPlane
    };

    struct Result {
        glm::dmat4 matrix{1.0};          // M (of the oriented plane)
        std::vector<glm::dvec3> shadow;  // the shadow points (meaningful where valid)
        std::vector<bool> valid;         // the vertex casts a shadow
        bool flipped = false;            // the plane was turned round (h_L < 0 as given)
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Setup, Matrix, Vertex, Polygon, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Setup;
        Phase last = Phase::Setup;
        glm::dvec4 plane{0, 1, 0, 0};  // P = [n, d], oriented toward the light
        double h_light = 0;            // P · L
        bool flipped = false;
        glm::dmat4 m{1.0};
        int k = -1;                              // the vertex done last
        std::vector<glm::dvec3> shadow;          // s = p'/w' (or p, or the matrix's point)
        std::array<Case, kMaxVertices> cases{};  // per vertex done (a fixed array: no allocation)
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);  // moves the shadow points out (run_to_end)
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);  // matrix, shadow/<highest>

    // The whole shadow in one straight-line function, for the benchmark.
    static Result flatten(const Input& in);

    // M for an oriented plane P = [n, d] and a light L (the formula above).
    static glm::dmat4 shadow_matrix(const glm::dvec4& plane, const glm::dvec4& light);
    // One vertex through M: its image p', its case and its shadow point.
    static Case classify(const glm::dvec4& plane, const glm::dmat4& m, const glm::dvec3& p,
                         glm::dvec4& image, glm::dvec3& shadow);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
