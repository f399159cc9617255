// Silhouette edges of a polygon mesh: the edges between a front-facing and a back-facing face.
//
// A smooth surface's silhouette is where the line of sight from the eye just grazes it. A mesh
// of flat faces has no such points, so the course approximates the silhouette by the mesh edges
// that separate a face turned towards the eye from one turned away. With a perspective eye E
// and a face's first vertex P_0 and outward Newell normal N (faces counter-clockwise from
// outside):
//   front(F) ⇔ (P_0 − E)·N < 0      (strictly; an edge-on face, = 0, counts as back-facing)
// and an edge shared by faces F and G is a silhouette edge ⇔ front(F) ≠ front(G). An edge of
// only one face is a BOUNDARY edge (an open mesh's rim): it is listed apart in `boundary` and is
// never a silhouette edge, having no second face to compare. A mesh whose edge has three faces,
// or whose two faces run along an edge the same way (inconsistent orientation), is refused.
//
// Which parts of each silhouette edge are visible is a separate question (the course: depth
// buffering); this finds the candidate edges. On a closed mesh every vertex meets an even number
// of silhouette edges, so the silhouette is a set of closed loops.
//
// The picture shades the front faces with toon shading (npr/toon_shading.hpp; `light` and
// `thresholds` serve the picture only) and draws the silhouette edges thick over them.
//
// Steps: one per face (front or back); one per edge (silhouette, interior or boundary); done
// (the silhouette sorted: each edge [i, j] with i < j, in increasing order).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "npr/npr_mesh.hpp"

namespace cg {

struct SilhouetteEdges {
    struct Input {
        npr::Mesh mesh;                      // closed or open, consistently oriented
        glm::dvec3 eye{0, 0, 5};             // the perspective eye point E
        glm::dvec3 light{1, 2, 3};           // picture only: the toon shading's light direction
        std::vector<double> thresholds{0.35, 0.7};  // picture only: its thresholds
        bool operator==(const Input&) const = default;
    };
    using EdgeId = std::array<int, 2>;  // vertex indices, smaller first
    struct Result {
        std::vector<bool> front;          // per face
        std::vector<EdgeId> silhouette;   // sorted
        std::vector<EdgeId> boundary;     // sorted
        int edges = 0;                    // distinct edges of the mesh
        bool operator==(const Result&) const = default;
    };
    // An edge as the mesh lists it: from a to b in face f (counter-clockwise), and in face g
    // (from b to a) or g = −1 for a boundary edge.
    struct Edge {
        int a = 0, b = 0, f = 0, g = -1;
        bool operator==(const Edge&) const = default;
    };

    enum class Phase : std::uint8_t { Face, Edge, Finish, Done };

    struct State {
        Shared<Input> in;                // never changes during a run
        Shared<std::vector<Edge>> edges; // the mesh's edges, first appearance order
        Phase phase = Phase::Face;
        Phase last = Phase::Face;
        int k = 0;                       // the next face, then the next edge
        double side = 0;                 // the face just classified: (P_0 − E)·N
        Result r;
        bool operator==(const State&) const = default;
    };
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.r.front) / 8 + heap_bytes(s.r.silhouette) + heap_bytes(s.r.boundary);
    }

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State begin(Shared<Input> in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static Result result(State&& s) { return std::move(s.r); }
    static void draw(const State& s, Scene& scene);

    // Exam practice (silhouette_edges_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The straight-line function, for a valid input (validate() first; start() does).
    static Result compute(const Input& in);

    // The mesh's edges (throws InputError "faces[k]" for an edge with a third face or two
    // faces running the same way).
    static std::vector<Edge> edge_list(const npr::Mesh& m);
    // (P_0 − E)·N for face f.
    static double side_of(const Input& in, const std::vector<int>& f);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
