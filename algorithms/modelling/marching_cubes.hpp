// Marching cubes: the surface f(x, y, z) = iso of a sampled scalar field, one grid cube at a time.
//
// The course ("Rendering Implicit Surfaces": sample the function on a uniform grid and decide
// from adjacent samples), in 3D; marching squares is the same thing in 2D and keeps the same
// conventions here:
//   inside     a corner is inside when f < iso (f ≥ iso is outside, so f = iso is outside)
//   bits       corners 0 = (i, j, k), 1 = (i+1, j, k), 2 = (i+1, j+1, k), 3 = (i, j+1, k) (the
//              bottom square counter-clockwise, as in 2D), then 4 … 7 the same one layer up;
//              case = Σ b_k 2^k, from 0 to 255
//   edges      0 … 3 the bottom square's (0→1, 1→2, 3→2, 0→3), 4 … 7 the top square's,
//              8 … 11 the vertical ones (0→4, 1→5, 2→6, 3→7), each from its lower-coordinate end
//   crossing   on an edge a → b whose corners differ, t = (iso − f_a)/(f_b − f_a),
//              p = a + t·(b − a); two cubes sharing an edge compute the same point bit for bit
//   table      GENERATED, not typed in: on each of the six faces the crossings are joined as
//              marching squares joins them (seen from outside the cube, the inside on the left);
//              every crossed edge then starts one face segment and ends another, so the
//              segments close into cycles, and each cycle is fanned into triangles
//   ambiguity  a face whose inside corners are diagonal (a 2D saddle) is decided by the
//              face-centre average m = (sum of its four corners)/4: m < iso joins the inside
//              corners. Two cubes sharing the face see the same four values (summed in the same
//              order), decide alike, and the surface has no holes
//   triangles  counter-clockwise seen from outside (f ≥ iso): the normals point out of the
//              inside region, so a sphere's mesh encloses a positive volume
// Fields: a grid of values given layer by layer (values[k][j][i] at the point (i, j, k), unit
// spacing), or a named field sampled on [−1, 1]³ with `cells` cells a side: sphere
// x² + y² + z² − r², torus (√(x² + y²) − 0.6)² + z² − r², two blobs ½ − Σ exp(−|p − c|²/r²)
// with c = (∓0.4, 0, 0), and a gyroid-like sin 2πx cos 2πy + sin 2πy cos 2πz + sin 2πz cos 2πx.
//
// Steps: the sampling; then the cubes in scan order (i fastest, then j, then k): a cube the
// surface crosses is one step, a run it does not cross is one step; after kStepped steps the
// rest go in at most kBatches batches; a summary (triangles, area, volume, closed or not).
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

struct MarchingCubes {
    static constexpr int kMaxCells = 64;  // cells a side, either way of giving the field
    static constexpr double kMaxValue = 1e100;
    static constexpr int kStepped = 48;  // steps before batching
    static constexpr int kBatches = 32;

    enum class Field : std::uint8_t { Grid, Sphere, Torus, Blobs, Gyroid };

    struct Input {
        Field field = Field::Grid;
        std::vector<std::vector<std::vector<double>>> values;  // Grid: values[k][j][i]
        int cells = 16;      // named fields: cells a side on [−1, 1]³
        double radius = 0.7; // sphere radius; torus tube radius; blob radius
        double iso = 0;
        bool operator==(const Input&) const = default;
    };

    // The sampled field: nx × ny × nz cubes, point (i, j, k) at origin + h·(i, j, k).
    struct Grid {
        int nx = 0, ny = 0, nz = 0;
        glm::dvec3 origin{0, 0, 0};
        double h = 1;
        std::vector<double> f;  // f[(k·(ny+1) + j)·(nx+1) + i]
        std::size_t index(int i, int j, int k) const {
            return (std::size_t(k) * std::size_t(ny + 1) + std::size_t(j)) * std::size_t(nx + 1) +
                   std::size_t(i);
        }
        double at(int i, int j, int k) const { return f[index(i, j, k)]; }
        glm::dvec3 point(int i, int j, int k) const { return origin + h * glm::dvec3(i, j, k); }
        bool operator==(const Grid&) const = default;
    };

    // One generated table row: the cycles traced on the cube's faces (cube edges in order, the
    // inside on the left seen from outside) and the triangles fanned from them (cube edges,
    // counter-clockwise seen from outside). A cycle that cannot be cut into triangles without a
    // chord lying in a face of the cube is fanned round its centre instead: vertex 12 + q
    // stands for cycle q's centre (the average of its crossings), bit q of `centres`.
    struct Row {
        int triangles = 0;
        int centres = 0;
        std::array<std::array<std::uint8_t, 3>, 12> tri{};
        int cycles = 0;
        std::array<std::uint8_t, 6> length{};  // edges per cycle
        std::array<std::uint8_t, 12> cycle{};  // the cycles one after the other
    };

    // What one cube gives.
    struct Cube {
        int i = 0, j = 0, k = 0;
        int index = 0;              // the case, 0 … 255
        std::array<double, 8> f{};  // corner values
        int crossed = 0;            // bit e set when edge e is crossed
        std::array<double, 12> t{};
        std::array<glm::dvec3, 12> p{};
        int ambiguous = 0;             // bit F set when face F is a saddle
        int joined = 0;                // bit F set when that saddle joins its inside corners
        std::array<double, 6> centre{};  // ambiguous faces: the face-centre average
        const Row* row = nullptr;
    };

    struct Result {
        int nx = 0, ny = 0, nz = 0;
        std::vector<std::uint8_t> cases;       // per cube, scan order
        std::vector<glm::dvec3> vertices;      // one per sign-changing grid edge
        std::vector<int> vertex_edge;          // its grid edge: 3·(point index) + axis (−1: a
                                               // cycle's centre, see Row)
        std::vector<std::array<int, 3>> triangles;  // vertex indices, ccw seen from outside
        long long inside = 0;                  // grid points with f < iso
        long long ambiguous = 0, joined = 0;   // saddle faces met (per cube), joined ones
        double area = 0, volume = 0;           // volume: signed, by the divergence theorem
        long long edges = 0, boundary = 0, nonmanifold = 0;  // mesh edges; on 1; on > 2 triangles
        long long euler = 0;                   // V − E + F
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Sample, Cubes, Summary, Done };

    struct State {
        Shared<Input> in;
        Shared<Grid> grid;
        Phase phase = Phase::Sample;
        Phase last = Phase::Sample;
        int next = 0, from = 0, steps = 0, batch = 0;
        std::vector<std::uint8_t> cases;
        std::vector<glm::dvec3> vertices;
        std::vector<int> vertex_edge;
        std::vector<int> edge_vertex;  // per grid edge, its vertex or −1
        std::vector<std::array<int, 3>> triangles;
        std::size_t tri_from = 0;  // the first triangle of the last step
        long long ambiguous = 0, joined = 0;
        double area = 0, volume = 0;
        long long edges = 0, boundary = 0, nonmanifold = 0, euler = 0;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.cases) + heap_bytes(s.vertices) + heap_bytes(s.vertex_edge) +
               heap_bytes(s.edge_vertex) + heap_bytes(s.triangles) +
               s.grid->f.capacity() * sizeof(double);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    static Result compute(const Input& in);

    // The pieces both use (and the tests check).
    static Grid sample(const Input& in);
    static double field_value(const Input& in, glm::dvec3 p);  // named fields
    static int case_index(const Grid& g, int i, int j, int k, double iso);
    static Cube march(const Grid& g, int i, int j, int k, double iso);
    static int edge_id(const Grid& g, int i, int j, int k, int edge);  // cube edge → grid edge

    // The cube's geometry: corner offsets, edges (lower end first), faces (corners
    // counter-clockwise seen from outside; face F's edge m joins its corners m and m + 1).
    static const std::array<std::array<int, 3>, 8>& corner_offset();
    static const std::array<std::array<int, 2>, 12>& edge_ends();
    static const std::array<std::array<int, 4>, 6>& face_corners();
    static const std::array<std::array<int, 4>, 6>& face_edges();
    // The face's saddle decision uses its corners summed in this order (the same for both
    // cubes sharing the face, so they get the same bits).
    static const std::array<std::array<int, 4>, 6>& face_sum_order();
    static int ambiguous_faces(int index);  // bit F: face F is a saddle in this case
    // The segments marching squares draws on face F: (from edge, to edge) cube edges.
    static int face_segments(int index, int face, bool joined, std::array<std::array<int, 2>, 2>& seg);
    // The generated row for a case and the decisions of its ambiguous faces (other bits of
    // `joined` are ignored).
    static const Row& table(int index, int joined);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
