// The course's two 3D rotation interfaces as step-by-step drags: the virtual sphere and the
// arcball, run over a recorded mouse path.
//
// The math of one sample pair lives in transforms/trackball.hpp (shared with the viewer's 3D
// canvas camera): to_ball maps a mouse position in a viewport onto the unit sphere (or, outside
// the ball, onto its rim), arcball and virtual_sphere give one pair's rotation. This file walks
// a whole drag, samples S0, S1, …, Sn (pixels, origin bottom-left, y up), pair by pair:
//
//   map S onto the sphere            s = (m, √(1 − |m|²)), or (m/|m|, 0) on the rim
//   arcball: map T onto the sphere   t likewise
//   virtual sphere: T − S            a tangential velocity at s
//   the pair's axis and angle        arcball: s × t and 2∠(s, t)  (q = (s · t, s × t))
//                                    virtual sphere: s × (T − S) and |T − S| (ball radii, in
//                                    radians); S outside the ball: about z by ∠(S, T) seen
//                                    from the ball's centre
//   accumulate                       q_total ← q_pair · q_total  (column vectors: the newest
//                                    rotation acts last, so it multiplies on the left)
//
// and ends with the comparison the course draws: the drag's rotation against one pair taken
// straight from the first sample to the last. For the arcball the two agree (the pair
// quaternions telescope: (u t*)(t s*) = u s*), so the rotation does not depend on the path and
// a closed mouse loop returns the ball to where it started; for the virtual sphere they differ,
// and a closed loop leaves the ball turned.
//
// One template serves both interfaces; only the second mapping and the summary's wording
// differ. Rotations are unit quaternions [w, x, y, z] in view coordinates (x right, y up, z
// toward the viewer), right-handed, acting on column vectors. Reported rotations are
// canonicalised to w ≥ 0 (q and −q are the same rotation); pair angles are in degrees,
// 2·atan2(|v|, w) ∈ [0°, 360°] for the pair quaternion (w, v).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "transforms/trackball.hpp"

namespace cg {

enum class TrackballKind : std::uint8_t { VirtualSphere, Arcball };

template <TrackballKind K>
struct TrackballDrag {
    static constexpr bool kArcball = K == TrackballKind::Arcball;

    struct Input {
        glm::dvec2 viewport{0, 0};           // width, height in pixels, both > 0
        std::vector<glm::dvec2> samples;     // the mouse path, ≥ 2 samples, pixels
        std::vector<glm::dvec3> object;      // optional points (ball units) that turn with the ball
        bool operator==(const Input&) const = default;
    };

    struct Pair {
        glm::dvec3 axis{0, 0, 0};  // unit; (0, 0, 0) when the pair does not rotate
        double angle_deg = 0;      // in [0, 360]
        bool rim = false;          // S (or, for the arcball, S or T) lies outside the ball
        bool operator==(const Pair&) const = default;
    };

    struct Result {
        glm::dquat rotation{1, 0, 0, 0};  // the whole drag, w ≥ 0
        glm::dmat3 matrix{1.0};           // the same as a 3×3 matrix
        std::vector<Pair> pairs;
        glm::dquat direct{1, 0, 0, 0};    // one pair straight from the first sample to the last
        double path_gap_deg = 0;          // the angle of rotation · direct⁻¹
        bool closed = false;              // the last sample is the first
        double net_angle_deg = 0;         // the angle of the whole drag's rotation
        std::vector<glm::dvec3> object;   // the object's points turned by the rotation
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { MapS, MapT, Rotate, Accumulate, Summary, Done };

    struct State {
        Input in;
        Phase phase = Phase::MapS;  // the step to take next
        Phase last = Phase::MapS;   // the step taken last
        int k = 0;                  // the pair S_k → S_{k+1} being worked
        trackball::BallPoint s{}, t{};
        glm::dvec3 velocity{0, 0, 0};       // virtual sphere: (T − S, 0) in ball units
        glm::dquat q_pair{1, 0, 0, 0};
        glm::dquat q_total{1, 0, 0, 0};
        std::vector<Pair> pairs;            // finished pairs
        std::vector<glm::dvec3> front;      // R·(0, 0, 1) after each pair, from the start
        glm::dquat direct{1, 0, 0, 0};      // set by the summary
        double path_gap_deg = 0, net_angle_deg = 0;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (trackball_drag_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same drag as one straight-line function, for the benchmark's comparison.
    static Result drag(const Input& in);

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

using VirtualSphere = TrackballDrag<TrackballKind::VirtualSphere>;
using Arcball = TrackballDrag<TrackballKind::Arcball>;

extern template struct TrackballDrag<TrackballKind::VirtualSphere>;
extern template struct TrackballDrag<TrackballKind::Arcball>;

// Axis and angle of a unit quaternion (w, v): v/|v| and 2·atan2(|v|, w) in degrees, in
// [0°, 360°]; the axis is (0, 0, 0) for the identity.
struct AxisAngle {
    glm::dvec3 axis{0, 0, 0};
    double angle_deg = 0;
};
AxisAngle axis_angle(const glm::dquat& q);

// The smallest angle (degrees, [0°, 180°]) of the rotation q: 2·atan2(|v|, |w|).
double rotation_angle_deg(const glm::dquat& q);

}  // namespace cg
