// Subdivision surfaces: Loop subdivision of triangle meshes, Catmull–Clark of quad (and mixed
// triangle/quad) meshes, one level after another.
//
// The course ("Subdivision Surfaces"): start from a polyhedron; the topological split puts a new
// vertex on every edge (and, for quads, one in every face) and joins them, then every vertex is
// moved to a weighted average of its neighbours. Each level has the same steps:
//   split         number the edges (in the order the faces meet them), find each edge's faces
//   face points   (Catmull–Clark) f = the centroid of the face's corners
//   edge points   Loop: 3/8 (a + b) + 1/8 (c + d), c and d the corners opposite the edge ab
//                 Catmull–Clark: (a + b + f₁ + f₂)/4, f₁ and f₂ the face points on either side
//   vertex points Loop (Loop 1987): (1 − nβ) v + β Σ neighbours,
//                   β = (1/n)(5/8 − (3/8 + 1/4 cos(2π/n))²)  (n = 3: 3/16; n = 6: 1/16)
//                 Catmull–Clark (1978): (Q + 2R + (n − 3) v)/n, Q the average of the face points
//                   around v, R the average of the midpoints of the edges at v, n its valence
//   connect       Loop: triangle abc → a,ab,ca / b,bc,ab / c,ca,bc / ab,bc,ca;
//                 Catmull–Clark: an n-gon → n quads (corner, edge point, face point, edge point)
// Boundaries (an edge in one face only), the same rule in both schemes — the mesh's border is
// subdivided as a cubic B-spline curve, on its own: a boundary edge point is the midpoint
// (a + b)/2; a boundary vertex goes to 1/8 u + 3/4 v + 1/8 w, u and w its two boundary
// neighbours. A vertex with more than two boundary edges (two fans meeting at a point) and a
// vertex in no face stay where they are. Sharp creases are not modelled.
// Numbering of the new mesh: the old vertices keep their indices, then (Catmull–Clark) the face
// points in face order, then the edge points in edge order — so a vertex index names the same
// vertex at every level. Counts: Loop V' = V + E, E' = 2E + 3F, F' = 4F; Catmull–Clark
// V' = V + F + E, E' = 2E + Σ n_f, F' = Σ n_f; either way V − E + F is unchanged.
// Faces are lists of 3 (Loop) or 3 and 4 (Catmull–Clark) vertex indices; an edge in more than
// two faces, a vertex listed twice in one face and an index out of range are errors. Limits:
// at most kMaxLevels levels and kMaxFaces faces after the last one (from the count formulas,
// before anything is built).
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

struct SubdivisionSurface {
    static constexpr int kMaxLevels = 5;
    static constexpr long long kMaxFaces = 50'000;     // after the last level
    static constexpr long long kMaxVertices = 50'000;  // in the input
    static constexpr double kMaxCoordinate = 1e100;

    enum class Scheme : std::uint8_t { Loop, CatmullClark };
    static const char* scheme_id(Scheme s);  // "loop", "catmull-clark"

    // What the narration works out in full and the picture labels; the exam asks for it.
    enum class FocusKind : std::uint8_t { None, Vertex, Face, Edge };

    struct Mesh {
        std::vector<glm::dvec3> vertices;
        std::vector<std::vector<int>> faces;  // 3 or 4 indices each
        bool operator==(const Mesh&) const = default;
    };

    struct Input {
        Mesh mesh;
        Scheme scheme = Scheme::CatmullClark;
        int levels = 1;
        FocusKind focus = FocusKind::None;
        long long focus_a = 0, focus_b = 0;  // the vertex, the face, or the edge's two ends
        bool operator==(const Input&) const = default;
    };

    // The mesh's edges: each once, numbered in the order the faces (corner by corner) meet them.
    struct Topology {
        std::vector<std::array<int, 2>> edges;       // its two ends, as first met
        std::vector<std::array<int, 2>> edge_faces;  // the faces on either side (−1: boundary)
        std::vector<std::vector<int>> face_edges;    // per face: edge i joins corner i and i+1
        bool operator==(const Topology&) const = default;
    };

    // The number of vertices, edges and faces.
    struct Counts {
        long long V = 0, E = 0, F = 0;
        long long euler() const { return V - E + F; }
        bool operator==(const Counts&) const = default;
    };

    // One level's new points, before they are joined.
    struct Points {
        std::vector<glm::dvec3> face, edge, vertex;  // face points empty for Loop
        bool operator==(const Points&) const = default;
    };

    // A vertex's rule with its weights: new position = Σ weight · point.
    struct Stencil {
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        std::vector<std::string> names;  // "V3", "F2" (a face point), "E5"
        std::string rule;                // "interior, n = 4" / "boundary" / "kept"
        bool operator==(const Stencil&) const = default;
    };

    struct Result {
        Mesh mesh;                  // after the last level
        std::vector<Counts> counts;  // before level 1, after level 1, …
        Topology first_topology;     // the input's edges
        Points first;                // level 1's new points
        bool has_focus = false;
        glm::dvec3 focus_point{0.0};  // level 1's point for the focus
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Split, FacePoints, EdgePoints, VertexPoints, Connect, Summary, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Split;
        Phase last = Phase::Split;
        int level = 0;  // levels finished
        Mesh mesh;      // the mesh being subdivided (the result once done)
        Topology topo;  // its edges (after the split)
        Points points;  // its new points so far
        std::vector<Counts> counts;
        Topology first_topology;
        Points first;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);  // moves the mesh out (run_to_end)
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // Every level in straight loops, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use.
    static Topology topology(const Mesh& m);
    static Counts counts_of(const Mesh& m, const Topology& t);
    static Counts counts_after(Scheme scheme, const Mesh& m, const Counts& c);  // the formulas
    static std::vector<glm::dvec3> face_points(const Mesh& m);
    static std::vector<glm::dvec3> edge_points(Scheme scheme, const Mesh& m, const Topology& t,
                                               const std::vector<glm::dvec3>& face_points);
    static std::vector<glm::dvec3> vertex_points(Scheme scheme, const Mesh& m, const Topology& t,
                                                 const std::vector<glm::dvec3>& face_points);
    static Mesh connect(Scheme scheme, const Mesh& m, const Topology& t, Points&& p);
    // The rules as weights, for the narration and the picture (and checked against the above).
    static Stencil vertex_stencil(Scheme scheme, const Mesh& m, const Topology& t,
                                  const std::vector<glm::dvec3>& face_points, int v);
    static Stencil edge_stencil(Scheme scheme, const Mesh& m, const Topology& t,
                                const std::vector<glm::dvec3>& face_points, int e);
    static double loop_beta(int n);
    static int find_edge(const Topology& t, int a, int b);  // −1: no such edge

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

// Shared by the narration and the picture: a weight as a small fraction ("3/8") when it is one;
// the vertex whose rule is worked out (the focus, else V0), and the face and edge shown with it.
std::string subdivision_weight(double w);
int subdivision_shown_vertex(const SubdivisionSurface::Input& in);
int subdivision_shown_face(const SubdivisionSurface::State& s);
int subdivision_shown_edge(const SubdivisionSurface::State& s);

}  // namespace cg
