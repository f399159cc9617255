// The slab test: a ray against an axis-aligned bounding box (AABB), axis by axis.
//
// The ray is the half-line P(t) = E + t d, t ≥ 0 (t in units of the given direction, which is
// not normalised); t < 0 is the line behind the origin. The box is closed: min_i ≤ x_i ≤ max_i
// for i = x, y, z, min ≤ max on every axis (a flat box, min_i = max_i, is allowed: the bounding
// box of a flat polygon). It is the intersection of three slabs, each the space between two
// parallel planes, so the ray is in the box for the t that are in all three slabs at once.
//
// Per axis (the course's steps; one step each):
//   d_i ≠ 0:  t_near = (min_i − E_i)/d_i,  t_far = (max_i − E_i)/d_i, swapped when d_i < 0
//             (the ray then meets the max plane first);
//   d_i = 0:  the ray is parallel to the slab. It is in the slab for every t when
//             min_i ≤ E_i ≤ max_i — the slab is (t_near, t_far) = (−∞, +∞) — and for none
//             otherwise — the empty slab, written (t_near, t_far) = (+∞, −∞) so that the max/min
//             below need no special case. The division (min_i − E_i)/0 is never made: with E_i on
//             a face it would be 0/0 = NaN, and 0·∞ appears nowhere.
//   then the running  t_min = max(t_min, t_near),  t_max = min(t_max, t_far)  (from −∞, +∞),
//   and the early-out: t_min > t_max means the slabs do not overlap — a miss, the remaining
//   axes are not worked.
// The verdict: a miss when t_min > t_max (the slabs are disjoint, or a parallel ray is outside
// a slab) or t_max < 0 (the box is behind the origin); otherwise a hit, the ray being in the box
// for t in [max(t_min, 0), t_max] (t_min = t_max: it touches an edge or a corner). t_min ≤ 0
// means the origin is in the box (inside, or on a face): then t_min < 0 is behind the origin,
// and the surface point the ray meets is the exit t_max ("t_hit"); otherwise t_hit = t_min.
//
// In JSON an infinite t_near, t_far, t_min or t_max is the string "inf" or "-inf" (JSON has
// no infinities); every other t is a number. A t beyond the double range (a tiny direction
// component against a huge distance) is refused naming the field rather than rounded to ±∞.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"

namespace cg {

struct RayAabb {
    static constexpr double kInf = std::numeric_limits<double>::infinity();

    struct Input {
        glm::dvec3 min{-1.0}, max{1.0};  // the box's corners, min ≤ max on every axis
        glm::dvec3 origin{-3, 0, 0};     // E
        glm::dvec3 direction{1, 0, 0};   // d, not the zero vector; any length
        bool operator==(const Input&) const = default;
    };

    // How one axis went.
    enum class Case : std::uint8_t {
        Crossing,         // d_i > 0: the ray crosses the min plane, then the max plane
        Swapped,          // d_i < 0: it meets the max plane first, so the two t's are swapped
        ParallelInside,   // d_i = 0, min_i ≤ E_i ≤ max_i: in the slab for all t, (−∞, +∞)
        ParallelOutside,  // d_i = 0, E_i outside [min_i, max_i]: never in it, (+∞, −∞)
    };
    struct Slab {
        double t_near = -kInf, t_far = kInf;  // the ray is in the slab for t_near ≤ t ≤ t_far
        Case kind = Case::ParallelInside;
        bool operator==(const Slab&) const = default;
    };

    enum class Verdict : std::uint8_t {
        None,      // not decided yet
        Hit,       // enters the box at t_min ≥ 0
        Inside,    // the origin is in the box (t_min ≤ 0 ≤ t_max): a hit, leaving at t_max
        Disjoint,  // t_min > t_max: the slabs do not overlap (the early-out)
        Behind,    // t_max < 0: the line meets the box, behind the origin
    };

    struct Result {
        bool hit = false;
        double t_min = -kInf, t_max = kInf;  // max of the t_near, min of the t_far worked
        double t_hit = 0;                    // the surface point met: t_min, or t_max when inside
        Verdict verdict = Verdict::None;
        std::array<Slab, 3> axes{};  // x, y, z; only the first `count` were worked
        int count = 0;               // 3, or fewer after an early-out
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Axis, Verdict, Done };

    struct State {
        Input in;
        Phase phase = Phase::Axis;
        Phase last = Phase::Axis;  // the phase of the step just taken (for the narration)
        int axis = 0;              // the next axis to work (0 = x)
        Result r;                  // built as it goes
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The whole test as one straight-line function (same numbers, no narration), for the
    // benchmark; `in` must be valid (validate).
    static Result intersect(const Input& in);

    // One axis's slab (the step's arithmetic, shared by the state machine and intersect).
    static Slab slab(double min, double max, double origin, double direction);

  private:
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
