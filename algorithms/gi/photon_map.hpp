// Photon mapping (Jensen): light carried forward from the lights as photons, stored where it
// lands on diffuse surfaces, then read back as a density estimate.
//
//   Pass 1 — emission and tracing. Each light emits its share of the photons (the count split
//     evenly between the lights, the first lights taking one more when it does not divide), each
//     carrying Φ_p = Φ_L / n_L: the light's power split evenly. A point light emits uniformly over
//     all directions, a spot (cone_deg < 180) uniformly over the cone about its direction. A
//     photon follows the ray tracer's geometry (rays/rt_scene.hpp: nearest_hit, mirror_ray,
//     transmitted_ray): a mirror reflects it, glass refracts it by Snell's law (η = 1/ior
//     entering, ior leaving; reflected at total internal reflection; no Fresnel split — glass here
//     is perfectly clear). At a diffuse surface the photon is stored (position, direction of
//     travel, power), then Russian roulette: with ξ uniform in [0, 1), ξ < ρ (the albedo) it
//     survives and leaves in a cosine-distributed direction with its power unchanged (Φ ρ / P
//     with P = ρ), else it is absorbed. A photon that meets nothing leaves the scene; one still
//     bouncing after max_bounces stops. A stored photon whose path met a mirror or glass and no
//     diffuse surface before is a caustic photon (L S+ D).
//   Pass 2 — the kd-tree over the stored photons: each node is the median, on its bounding box's
//     widest axis (x before y before z on a tie), of its range of photons, ordered by (coordinate,
//     index); the photons below go left, above go right (an implicit balanced tree on the index
//     array, node of range [lo, hi) at m = ⌊(lo + hi)/2⌋). Built depth first, one node per step.
//   Pass 3 — the k nearest photons to the query point x: a depth-first search keeping the k
//     nearest seen so far in a max-heap ordered by (d², index); r² is its top once full. A subtree
//     on the far side of a node's plane is skipped when the plane's distance² exceeds r² (it can
//     hold nothing nearer). Ties are broken by the photon's index, so the set equals brute force's.
//   Estimate: E(x) ≈ Σ_p Φ_p / (π r²), r the distance to the k-th nearest photon (k is reduced to
//     the photons stored when fewer). With no photon stored, or r = 0, E is reported as 0 with
//     `degenerate` set.
//
// The reference: the direct irradiance at x, ray traced — Σ_L I_L |cos θ| / d² over the lights
// that see x unblocked (a shadow ray; any object blocks, glass too) and have x inside their cone,
// with I_L = Φ_L / Ω_L (Ω = 2π (1 − cos α) = 4π sin²(α/2), 4π for a point light) and θ the angle between the
// light's direction and the normal of the surface nearest x. On a lit plane with nothing to
// reflect (albedo 0), E converges to it as photons and k grow.
//
// Steps: the first kOneByOne photons one step each (every bounce narrated, ξ and P shown), then
// the rest in at most kBatches batches; one kd-tree node per step; one visited or skipped subtree
// per step; the estimate.
//
// Refused: no objects or more than kMaxObjects, no lights or more than kMaxLights, a sphere
// radius outside [1e-6, 1e6], a zero plane normal, coordinates beyond ±kMaxCoordinate, albedo
// outside [0, 1], ior outside [1, 3], power not in (0, 1e12], cone_deg outside [1e-4, 180], a zero
// spot direction, photons outside 1..kMaxPhotons, max_bounces outside 1..kMaxBounces, k outside
// 1..kMaxK.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "rays/rt_scene.hpp"

namespace cg {

struct PhotonMap {
    static constexpr std::size_t kMaxObjects = 32;
    static constexpr std::size_t kMaxLights = 8;
    static constexpr int kMaxPhotons = 1000000;
    static constexpr int kMaxBounces = 64;
    static constexpr int kMaxK = 10000;
    static constexpr double kMaxCoordinate = 1e6;
    static constexpr int kOneByOne = 20;  // photons narrated one by one
    static constexpr int kBatches = 40;   // ... then the rest in at most this many steps

    enum class Material : std::uint8_t { Diffuse, Mirror, Glass };
    enum class Shape : std::uint8_t { Sphere, Plane };

    struct Object {
        Shape shape = Shape::Sphere;
        glm::dvec3 center{0, 0, 0};  // sphere centre, or a point of the plane
        double radius = 1;           // sphere
        glm::dvec3 normal{0, 1, 0};  // plane
        Material material = Material::Diffuse;
        double albedo = 0.5;  // diffuse: the survival probability of Russian roulette
        double ior = 1.5;     // glass
        bool operator==(const Object&) const = default;
    };
    struct Light {
        glm::dvec3 position{0, 1, 0};
        double power = 1;               // Φ_L
        glm::dvec3 direction{0, -1, 0};  // a spot's axis
        double cone_deg = 180;           // half-angle; 180: every direction (a point light)
        bool operator==(const Light&) const = default;
    };
    struct Input {
        std::vector<Object> objects;
        std::vector<Light> lights;
        int photons = 500;  // emitted in all
        int max_bounces = 8;
        std::uint64_t seed = 1;
        glm::dvec3 query{0, 0, 0};
        int k = 20;
        bool operator==(const Input&) const = default;
    };

    struct Photon {
        glm::dvec3 position{0.0};
        glm::dvec3 direction{0.0};  // of travel, unit
        double power = 0;
        int light = 0;
        bool caustic = false;
        bool operator==(const Photon&) const = default;
    };

    // What happened to a photon at one point of its path.
    enum class Event : std::uint8_t { Reflect, Refract, TotalInternal, Survive, Absorb, Escape, Limit };
    struct Bounce {
        Event event = Event::Escape;
        glm::dvec3 point{0.0};  // where (for Escape: a point far along the ray)
        int object = -1;
        double xi = 0, P = 0;  // Russian roulette's ξ and survival probability
        bool operator==(const Bounce&) const = default;
    };
    struct Path {
        int photon = -1, light = -1;
        glm::dvec3 origin{0.0};
        double power = 0;
        std::vector<Bounce> bounces;
        int stored = 0;  // diffuse hits stored
        bool operator==(const Path&) const = default;
    };

    // The geometry, fixed at the start and shared by every copy of the state.
    struct World {
        rt::Prepared prepared;
        std::vector<int> emitted_by;  // n_L per light
        double extent = 1;            // the scene's radius about the origin, for the picture
        glm::dvec3 query_normal{0, 1, 0};  // of the surface nearest the query point
        bool operator==(const World&) const = default;
    };

    struct Node {  // a kd-tree node as built: its range, the median and the split
        int lo = 0, hi = 0, m = -1, axis = 0;
        double split = 0;
        glm::dvec3 box_lo{0.0}, box_hi{0.0};
        bool operator==(const Node&) const = default;
    };
    struct Range {
        int lo = 0, hi = 0;
        double bound = 0;  // the query: a lower bound on d² of every photon in the range
        bool operator==(const Range&) const = default;
    };
    struct Neighbour {
        double d2 = 0;
        int photon = -1;
        bool operator<(const Neighbour& o) const {
            return d2 < o.d2 || (d2 == o.d2 && photon < o.photon);
        }
        bool operator==(const Neighbour&) const = default;
    };

    struct Result {
        std::vector<double> power_per_photon;  // Φ_L / n_L per light
        std::vector<int> emitted;              // n_L
        std::vector<Photon> photons;           // stored, in the order they landed
        int caustic = 0;                       // caustic photons among them
        int escaped = 0, absorbed = 0, limited = 0;
        std::vector<int> order;  // the kd-tree: photon indices, node of [lo, hi) at ⌊(lo+hi)/2⌋
        std::vector<std::uint8_t> axis;  // the split axis at each position of `order`
        int depth = 0;                   // of the tree (levels)
        std::vector<int> neighbours;     // the k nearest, nearest first (ties: lower index)
        std::vector<double> distances;   // ... their distances to x
        int visited = 0, pruned = 0;
        double radius = 0;
        double sum_power = 0;
        double irradiance = 0;
        double direct_irradiance = 0;
        bool degenerate = false;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Emit, Build, Query, Estimate, Done };

    struct State {
        Shared<Input> in;
        Shared<World> world;
        Phase phase = Phase::Emit;
        Phase last = Phase::Emit;
        Rng rng{1};
        int emitted = 0;  // photons traced so far
        int batch_first = 0;
        std::vector<Photon> photons;
        int escaped = 0, absorbed = 0, limited = 0;
        Path path;  // the last photon's path (one-by-one steps; a batch's last photon)
        std::vector<int> order;
        std::vector<std::uint8_t> axis;
        std::vector<Range> todo;  // the build's ranges still to split, or the query's stack
        Node node;                // the node built last
        int depth = 0;
        std::vector<Neighbour> heap;  // max-heap by (d², index)
        int k = 0;                    // min(k, photons stored)
        int visited = 0, pruned = 0;
        Range range;       // the query's last range popped
        int at = -1;       // ... the photon visited there (−1: skipped)
        double d2 = 0;     // ... its d²
        bool taken = false;
        bool replaced = false;  // ... it replaced the farthest of a full heap
        double r2 = 0;
        double sum_power = 0, irradiance = 0;
        bool degenerate = false;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, cg::Scene& scene);
    static std::size_t bytes(const State& s);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // Everything in one straight-line function, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use.
    static World prepare(const Input& in);
    static int light_of(const World& w, int photon);  // the light emitting photon number `photon`
    // Traces one photon from light L with power Φ_p, appending its diffuse hits to `photons`;
    // `path` (if given) receives every bounce. Returns the path's last event.
    static Event trace_photon(const Input& in, const World& w, int light, double power, Rng& rng,
                              std::vector<Photon>& photons, Path* path);
    // The median split of order[lo, hi): axis and split of the node, partitioning the range.
    static Node split(const std::vector<Photon>& ph, std::vector<int>& order, int lo, int hi);
    // The whole kd-tree at once (the same nodes as the stepped build); returns its depth.
    static int build_tree(const std::vector<Photon>& ph, std::vector<int>& order,
                          std::vector<std::uint8_t>& axis);
    // The k nearest to x by searching the tree (the stepped search's order), nearest first;
    // `visited` and `pruned` (if given) count the nodes.
    static std::vector<Neighbour> nearest(const std::vector<Photon>& ph, const std::vector<int>& order,
                                          const std::vector<std::uint8_t>& axis, glm::dvec3 x, int k,
                                          int* visited = nullptr, int* pruned = nullptr);
    // Offers a photon to the k-nearest max-heap.
    static bool offer(std::vector<Neighbour>& heap, int k, Neighbour n);
    static double distance2(glm::dvec3 a, glm::dvec3 b);
    // The k nearest by testing every photon (the reference).
    static std::vector<int> nearest_brute_force(const std::vector<Photon>& ph, glm::dvec3 x, int k);
    // The ray-traced direct irradiance at x (the reference the estimate converges to).
    static double direct_irradiance(const Input& in, const World& w, glm::dvec3 x);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
