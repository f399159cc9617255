// Vertex normals of a polygon mesh: each face's normal, then each vertex's normal as the
// normalised average of the normals of the faces around it — unweighted, area-weighted and
// angle-weighted, side by side.
//
// Face normals.
//   - A triangle P0 P1 P2: N = (P1 − P0) × (P2 − P0), the cross product of two edges. Its
//     length is twice the triangle's area, so the area comes with the normal.
//   - A polygon P0 … P(n−1) (n > 3): Newell's method, N = Σ_i (P_i − P0) × (P_(i+1) − P0) over
//     the fan from P0, which is Newell's N_x = Σ (y_i − y_(i+1))(z_i + z_(i+1)) (and its
//     cyclic shifts) with P0 moved to the origin so that far-off meshes lose no digits. Each
//     component is the signed area of the polygon's shadow on a coordinate plane, so N uses
//     every edge: a concave corner (whose two edges cross the wrong way) or three collinear
//     corners (whose edges cross to zero) cannot spoil it, and for a non-planar polygon it is
//     the normal of the plane the polygon covers the most area of. |N| is twice the area
//     (the projected area, for a non-planar polygon).
//   - n_f = N/|N|; a face with N = 0 (zero area: collinear or coincident corners) has no
//     normal and contributes to no vertex.
//   - The interior angle at a corner is the angle between the edges to the next and the
//     previous corner, θ = atan2(|a × b|, a · b) (a = P_next − P, b = P_prev − P); at a
//     polygon's corner that turns against n_f (n_f · (a × b) < 0: a reflex corner of a concave
//     polygon) it is 2π − θ, above 180°. A corner with a zero-length edge (two indices at one
//     point) has no angle: 0.
//
// Vertex normals, over the faces with a normal that have the vertex as a corner (a face once):
//   unweighted  Σ n_f
//   area        Σ A_f n_f  = ½ Σ N_f (the unnormalised normals already carry the area)
//   angle       Σ θ_f n_f  (θ_f the face's interior angle at the vertex)
// each then normalised. A vertex with no such face (isolated, or only zero-area faces around
// it), or whose sum cancels (|Σ| ≤ 1e-12 Σ |terms|: two faces wound oppositely), has no normal
// under that weighting: reported as null, never NaN. Shading (shading/shading.cpp) takes its
// vertex normals, when a mesh comes without them, from area_weighted() below.
//
// Faces with a vertex listed twice in a row (cyclically: [0, 1, 1, 2], [0, 1, 0]) lose the
// repeat — a zero-length edge has no direction; a vertex listed twice apart ([0, 1, 0, 2]) is an
// error, as is a face with fewer than 3 vertices, an index out of range or a coordinate that is
// not a finite number within ±kMaxCoordinate.
//
// Steps: one per face (its normal N and n_f, its area, its corners' angles), then one per vertex
// (its faces and the three sums, normalised).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct VertexNormals {
    static constexpr long long kMaxVertices = 100'000;
    static constexpr long long kMaxFaces = 100'000;
    static constexpr long long kMaxCorners = 1'000'000;  // Σ over the faces of their corners
    // |coordinate|: edges' cross products (≤ 8·10²⁰⁰) and their sums stay finite.
    static constexpr double kMaxCoordinate = 1e100;
    static constexpr double kCancel = 1e-12;  // |Σ| ≤ kCancel Σ|terms|: the sum cancels

    enum class Weighting : std::uint8_t { Unweighted, Area, Angle };
    static const char* weighting_id(Weighting w);  // "unweighted", "area", "angle"

    struct Input {
        std::vector<glm::dvec3> vertices;
        std::vector<std::vector<long long>> faces;  // indices into vertices, ≥ 3 each
        // The vertex and weighting the exam asks about, labelled in the picture (optional).
        bool has_focus = false;
        long long focus_vertex = 0;
        Weighting focus_weighting = Weighting::Area;
        bool operator==(const Input&) const = default;
    };

    // One face, worked out.
    struct FaceNormal {
        std::vector<long long> corners;  // its vertices, repeats in a row dropped
        bool newell = false;             // more than 3 corners: Newell's method
        glm::dvec3 N{0.0};               // cross product or Newell sum: |N| = 2 × area
        double area = 0;                 // |N| / 2
        bool defined = false;            // N ≠ 0
        glm::dvec3 normal{0.0};          // n_f = N / |N| (0 when undefined)
        std::vector<double> angles;      // interior angle at each corner, radians
        bool operator==(const FaceNormal&) const = default;
    };

    // One vertex, worked out.
    struct VertexSums {
        std::vector<int> faces;            // the faces with a normal around it, in face order
        std::vector<int> zero_area_faces;  // ... and those without one
        std::array<glm::dvec3, 3> sum{};   // per Weighting: Σ w_f n_f (area: Σ N_f)
        std::array<double, 3> scale{};     // per Weighting: Σ |w_f n_f| (for the cancel test)
        std::array<std::optional<glm::dvec3>, 3> normal{};  // normalised; none: undefined
        bool operator==(const VertexSums&) const = default;
    };

    struct Result {
        std::vector<FaceNormal> faces;
        std::vector<VertexSums> vertices;
        bool operator==(const Result&) const = default;
    };

    // The input with the faces' corner lists cleaned (repeats in a row dropped).
    struct Prepared : Input {
        std::vector<std::vector<long long>> corners;
        std::vector<std::vector<int>> faces_of;  // per vertex: the faces around it, in order
        bool operator==(const Prepared&) const = default;
    };

    struct State {
        Shared<Prepared> in;
        int face = -1;    // the face worked out last (−1: none yet)
        int vertex = -1;  // the vertex worked out last (−1: none yet)
        std::vector<FaceNormal> faces;
        std::vector<VertexSums> vertices;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) {
        return s.vertex + 1 >= static_cast<int>(s.in->vertices.size());
    }
    static Result result(const State& s) { return Result{s.faces, s.vertices}; }
    static Result result(State&& s) { return Result{std::move(s.faces), std::move(s.vertices)}; }
    static void draw(const State& s, Scene& scene);

    // Exam practice (vertex_normals_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Every face and vertex in one go, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The arithmetic, shared by the steps, compute() and shading.
    static FaceNormal face_normal(const std::vector<glm::dvec3>& vertices,
                                  std::vector<long long> corners);
    static VertexSums vertex_sums(const std::vector<FaceNormal>& faces,
                                  const std::vector<int>& around, int vertex);
    // The area-weighted vertex normals of a triangle mesh from its faces' N (each
    // (P1 − P0) × (P2 − P0), or 0 to leave the face out): at each vertex Σ N_f over its
    // triangles in index order, made a unit vector (0 where the sum is 0). Shading's vertex
    // normals for a mesh without them.
    static std::vector<glm::dvec3> area_weighted(
        std::size_t vertex_count, const std::vector<std::array<long long, 3>>& triangles,
        const std::vector<glm::dvec3>& N);

  private:
    static Prepared prepare(const Input& in);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
