// Shadow volumes: the silhouette edges of a closed occluder seen from a point light, the shadow
// quads they sweep away from the light, and for each eye ray the stencil's count — +1 at every
// front-facing shadow face passed before the visible surface, −1 at every back-facing one.
//
// Conventions: the occluder is a closed, consistently oriented triangle mesh, each face's
// vertices counter-clockwise seen from outside, so n_f = (b − a) × (c − a) points out. A face is
// lit (faces the light) when n_f · (L − a) > 0; a face edge-on to the light (n_f · (L − a) = 0)
// counts as facing away (its cone of shadow is flat). An edge is a silhouette edge when its two
// faces disagree. It is oriented (a, b) as it runs in its lit face; its shadow quad is
// a, b, b∞, a∞, extruded away from the light to infinity (the points L + u (a − L), u ≥ 1: the
// homogeneous points [a − L, 0] at u = ∞), lying in the plane through L, a and b, with the
// outward normal n_q = (a − L) × (b − L). The picture draws each quad to a finite length (down to
// the floor when there is one).
//
// The shadow volume is the union of the cones V_f = {L + u (p − L) : p ∈ f, u ≥ 1} behind the
// lit faces; their shared sides cancel, leaving the silhouette quads and the lit faces (the light
// cap). A point X is in V_f exactly when the segment from L to X crosses f, so a point is in
// shadow (its shadow ray is blocked) exactly when it lies in at least one cone. Walking along an
// eye ray E + t d, the number of cones containing the point changes by +1 where the ray crosses a
// quad from its outside (n_q · d < 0: a front-facing shadow face) and by −1 where it leaves one
// (n_q · d > 0: back-facing). The walk never crosses the light cap before the visible surface
// point P (the cap is part of the occluder, and P is the first surface hit), so
//   count(P) = count(E) + Σ_{quads crossed at 0 < t < t_P} (±1),
// the stencil's arithmetic (z-pass: the depth test passes for the shadow faces in front of the
// surface). count(E) is the number of cones that contain the eye: 0 when the eye is lit — the
// stencil's clear value — and otherwise the number of lit faces the segment from the eye to the
// light crosses. Starting at 0 then is the z-pass failure when the eye is in shadow (renderers
// use z-fail, counting the faces behind the surface, with capped volumes). Verdict: in shadow
// ⟺ count(P) > 0. It is compared with a shadow ray from P to L tested exactly against every face
// (except the face P lies on). Crossings at t > t_P (behind the surface: the depth test fails)
// are not counted; the verdict step says how many there were.
//
// Refused (InputError naming the field): non-finite or too large coordinates (|x| > 1e9), fewer
// than 4 or more than kMaxVertices vertices, fewer than 4 or more than kMaxFaces faces, face
// indices out of range or repeated, a zero-area face, an open mesh (an edge with no neighbour,
// named), an edge used twice in one direction (inconsistent orientation or non-manifold, named),
// a mesh wound clockwise (negative volume), the light inside the occluder or on its surface, the
// eye inside the occluder or on its surface, a target equal to the eye, more than kMaxRays
// targets. A ray that meets no surface (no floor below it, passing the occluder) is a "miss".
//
// Steps: one per face (lit or unlit, with n_f · (L − a)), one per edge (silhouette, with its quad
// and normal, or inner-edge), then for each eye ray: ray (its first surface point P and the count
// it starts from; eye-in-shadow when that is not 0) or miss, one step per quad crossed before P
// (enter +1 / leave −1, the running count), and verdict (count > 0, the shadow ray's answer).
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

struct ShadowVolume {
    static constexpr std::size_t kMaxVertices = 64;
    static constexpr std::size_t kMaxFaces = 128;
    static constexpr std::size_t kMaxRays = 16;
    static constexpr double kMaxCoordinate = 1e9;

    struct Input {
        std::vector<glm::dvec3> vertices;
        std::vector<std::array<int, 3>> faces;  // counter-clockwise seen from outside
        glm::dvec3 light{0, 5, 0};              // a point light
        glm::dvec3 eye{0, 3, 6};
        std::vector<glm::dvec3> targets;  // each eye ray runs from the eye through a target
        bool has_floor = true;            // the receiver: the floor plane y = floor
        double floor = 0;
        bool operator==(const Input&) const = default;
    };

    // An undirected edge: (a, b) as it runs in face f; face g runs it as (b, a).
    struct Edge {
        int a = 0, b = 0, f = 0, g = 0;
        bool operator==(const Edge&) const = default;
    };
    struct Mesh {
        std::vector<Edge> edges;          // in the order the faces first use them
        std::vector<glm::dvec3> normals;  // n_f = (b − a) × (c − a)
        bool operator==(const Mesh&) const = default;
    };

    static constexpr int kFloor = -1;  // surface: the floor
    static constexpr int kNone = -2;   // surface: nothing (a miss)

    struct Crossing {
        double t = 0;  // along E + t d (t = 1 at the target)
        int quad = 0;  // index into the silhouette list
        int sign = 0;  // +1 front-facing (entering), −1 back-facing (leaving)
        bool operator==(const Crossing&) const = default;
    };

    struct Ray {
        int surface = kNone;  // kFloor, kNone or the face index
        glm::dvec3 hit{0};    // P (meaningful unless a miss)
        double t_hit = 0;
        int start = 0;               // count(E): the cones containing the eye
        std::vector<int> crossings;  // the signs passed before P, in order
        int behind = 0;              // quads crossed behind P (not counted)
        int count = 0;               // count(P)
        bool in_shadow = false;      // count > 0
        bool shadow_ray = false;     // the shadow ray from P to L is blocked
        bool operator==(const Ray&) const = default;
    };

    struct Result {
        std::vector<bool> lit;
        std::vector<std::array<int, 2>> silhouette;  // (a, b) as in the lit face
        std::vector<Ray> rays;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Face, Edge, RayStart, Crossing, Verdict, Done };

    struct State {
        Shared<Input> in;
        Shared<Mesh> mesh;
        Phase phase = Phase::Face;
        Phase last = Phase::Face;
        int face = -1;   // the face done last
        int edge = -1;   // the edge done last
        int ray = -1;    // the ray being walked
        int cross = -1;  // its crossing done last
        std::vector<std::uint8_t> lit;
        std::vector<std::array<int, 2>> silhouette;
        std::vector<Crossing> crossings;  // the current ray's, before P, sorted by t
        int behind = 0;
        int count = 0;
        Ray current;
        std::vector<Ray> rays;  // finished
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // The whole computation in one straight-line function (validates first), for the benchmark.
    static Result solve(const Input& in);

    // The pieces, shared by the state machine and solve.
    static Mesh build_mesh(const Input& in);  // assumes a valid input
    // Where the segment E + t d (0 < t) first meets the floor or a face.
    static Ray first_hit(const Input& in, const Mesh& mesh, const glm::dvec3& target);
    // The number of lit faces the segment from p to the light crosses (skipping face `skip`).
    static int cones_containing(const Input& in, const std::vector<std::uint8_t>& lit,
                                const glm::dvec3& p, int skip, bool any_face);
    // The quads crossed by E + t d, t > 0, sorted by t (all of them; the caller splits at t_P).
    static std::vector<Crossing> crossings(const Input& in,
                                           const std::vector<std::array<int, 2>>& silhouette,
                                           const glm::dvec3& target);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
