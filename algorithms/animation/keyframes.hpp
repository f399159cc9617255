// Keyframe interpolation: functional animation of keyed channels, one frame per step
//
// The course: the animator gives keyframes, an interpolation algorithm replaces the human
// inbetweener. Functional animation: every keyframed parameter is its own scalar function of
// time, so a 2D or 3D position is two or three scalar channels interpolated independently.
//
// Keys (t_i, p_i), i = 0..n−1, t strictly increasing. In the segment [t_i, t_{i+1}], with
// Δ_i = t_{i+1} − t_i and the local parameter u = (t − t_i)/Δ_i:
//
//   linear     p(t) = (1 − u) p_i + u p_{i+1}              (velocity constant in the segment,
//                                                           so it jumps at every key)
//   Hermite    p(t) = h00 p_i + h10 Δ_i m⁺_i + h01 p_{i+1} + h11 Δ_i m⁻_{i+1}
//              h00 = 2u³ − 3u² + 1,  h10 = u³ − 2u² + u,  h01 = −2u³ + 3u²,  h11 = u³ − u²
//              velocity p'(t) = (h00' p_i + h10' Δ m⁺_i + h01' p_{i+1} + h11' Δ m⁻_{i+1}) / Δ
//
// The tangents m are in value per second. With the slopes on either side of key i,
// s⁻ = (p_i − p_{i−1})/Δ_{i−1} and s⁺ = (p_{i+1} − p_i)/Δ_i,
//
//   Catmull–Rom        m⁻_i = m⁺_i = (s⁻ + s⁺)/2      (uniform keys, Δ = 1: (p_{i+1} − p_{i−1})/2)
//   Kochanek–Bartels   m⁻_i (arriving)  = (1−T)[(1−C)(1+B)/2 s⁻ + (1+C)(1−B)/2 s⁺]
//                      m⁺_i (leaving)   = (1−T)[(1+C)(1+B)/2 s⁻ + (1−C)(1−B)/2 s⁺]
//                      with tension T, continuity C, bias B of key i; T = C = B = 0 is
//                      Catmull–Rom, C ≠ 0 makes m⁻ ≠ m⁺: a corner in the velocity.
//
// At the first and last key the missing slope is taken equal to the one there is (a phantom key
// continuing the first or last segment in a straight line), so two keys give a straight line.
// Every interpolation passes through the keys exactly: u = 0 and u = 1 give h00, h01 = 1, 0 / 0, 1.
//
// Frames: t_k = t_0 + k dt for k = 0..K−1 and t_K = t_n−1 (the last frame lands on the last key).
// A step is one frame; the clock variable is "t".
//
// Motion along a path (dim ≥ 2, constant_speed): moving with the parameter equal to time gives
// an uneven speed. The arc-length table of the curves chapter (ArcLength::invert) makes it even:
// sample the path at N + 1 equally spaced times u_j, add up the chords s_j, and for the distance
// s = L (t − t_0)/(t_n−1 − t_0) find u by linear interpolation in the table; the point is P(u).
// The table's length is compared with the true length (ArcLength::exact_length on each segment
// written as a cubic Bézier: p_i, p_i + Δ m⁺_i/3, p_{i+1} − Δ m⁻_{i+1}/3, p_{i+1}).
//
// Refused: fewer than 2 or more than kMaxKeys keys, times not strictly increasing (a repeated
// time names both keys) or closer than kMinGap, non-finite or over-large numbers, T, C, B outside
// [−1, 1], dt ≤ 0, more than kMaxFrames frames, samples outside 1..kMaxSamples, constant_speed with
// dim 1, a query time outside the keys.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct Keyframes {
    static constexpr int kMaxKeys = 1000;
    static constexpr int kMaxFrames = 100000;
    static constexpr int kMaxSamples = 10000;
    static constexpr double kMaxMagnitude = 1e6;  // times and values
    static constexpr double kMinGap = 1e-6;       // seconds between keys: slopes ≤ 2e12

    enum class Interpolation : std::uint8_t { Linear, CatmullRom, KochanekBartels };

    struct Key {
        double t = 0;                                  // seconds
        glm::dvec3 value{0, 0, 0};                     // the first dim components are used
        double tension = 0, continuity = 0, bias = 0;  // Kochanek–Bartels, each in [−1, 1]
        bool operator==(const Key&) const = default;
    };

    struct Input {
        std::vector<Key> keys;
        int dim = 1;  // 1: a scalar channel; 2 or 3: a position, one channel per coordinate
        Interpolation interpolation = Interpolation::CatmullRom;
        double dt = 1.0 / 30;         // seconds per frame
        bool constant_speed = false;  // dim ≥ 2: also move along the path at constant speed
        int samples = 64;             // N of the arc-length table
        bool has_query = false;       // the exam's question: the values at one time
        double query = 0;
        bool operator==(const Input&) const = default;
    };

    // A channel ready to evaluate: keys and the tangents of one interpolation.
    struct Curve {
        Interpolation kind = Interpolation::CatmullRom;
        std::vector<Key> keys;
        std::vector<glm::dvec3> m_in, m_out;  // m⁻_i, m⁺_i, value per second
        bool operator==(const Curve&) const = default;
    };

    // The Hermite basis at u and its derivative d/du.
    struct Basis {
        double h00 = 1, h10 = 0, h01 = 0, h11 = 0;
        double d00 = 0, d10 = 0, d01 = 0, d11 = 0;
        bool operator==(const Basis&) const = default;
    };

    // What one time gives on a curve.
    struct Eval {
        int segment = 0;  // i: t_i ≤ t ≤ t_{i+1}
        double u = 0;
        glm::dvec3 value{0}, velocity{0};
        bool operator==(const Eval&) const = default;
    };

    // Everything derived once at the start, shared by every copy of the state.
    struct Prepared {
        Input in;
        Curve curve;
        int frames = 1;               // K + 1
        std::vector<double> table_u;  // the arc-length table (constant_speed only)
        std::vector<double> table_s;
        double length = 0, length_exact = 0;
        bool operator==(const Prepared&) const = default;
    };

    struct At {  // the values at the query time (the exam's answers), per interpolation
        glm::dvec3 linear{0}, catmull_rom{0}, kochanek_bartels{0};
        glm::dvec3 linear_velocity{0}, catmull_rom_velocity{0}, kochanek_bartels_velocity{0};
        bool operator==(const At&) const = default;
    };

    struct Result {
        int dim = 1;
        std::vector<double> times;            // every frame
        std::vector<glm::dvec3> values;       // p(t_k)
        std::vector<glm::dvec3> velocities;   // p'(t_k)
        std::vector<glm::dvec3> m_in, m_out;  // the tangents at every key
        std::vector<glm::dvec3> jumps;  // p'(t_i⁺) − p'(t_i⁻) at every key (0 at the ends)
        double max_jump = 0;            // the largest |jump|
        bool c1 = true;                 // max_jump ≤ 1e-9 × the velocity scale
        bool c1_linear = true, c1_catmull_rom = true, c1_kochanek_bartels = true;
        // constant_speed:
        double length = 0, length_exact = 0;
        std::vector<glm::dvec3> even;         // the point at constant speed at every frame
        double speed_min = 0, speed_max = 0;  // of the naive motion, |p'| over the frames
        bool has_query = false;
        At at;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Tangents, Table, Frame, Summary, Done };

    struct State {
        Shared<Prepared> p;
        Phase phase = Phase::Tangents;
        Phase last = Phase::Tangents;
        int k = -1;  // the frame shown (−1: none yet)
        double t = 0;
        Eval e;
        glm::dvec3 even{0};  // constant_speed: the point at constant speed
        double even_u = 0;   // its parameter, from the table
        double even_s = 0;   // its distance along the path
        int bracket = 0;     // the table's interval used
        double speed_min = 0, speed_max = 0;
        std::vector<double> times;  // every frame shown so far
        std::vector<glm::dvec3> values, velocities, evens;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static Prepared prepare(const Input& in);  // validates, then the tangents and the table
    static State start(const Input& in) { return begin(Shared<Prepared>(prepare(in))); }
    static State begin(Shared<Prepared> p);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.times) + heap_bytes(s.values) + heap_bytes(s.velocities) +
               heap_bytes(s.evens);
    }
    static Result result(const State& s);
    static Result result(State&& s);  // moves the frame lists out
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use.
    static Curve make_curve(const Input& in, Interpolation kind);
    static Basis basis(double u);
    static int segment_of(const std::vector<Key>& keys, double t);
    static Eval evaluate(const Curve& c, double t);
    static Eval evaluate_in(const Curve& c, int segment, double u);  // at u of a segment
    static double frame_time(const Prepared& p, int k);
    static int frame_count(const Input& in);  // K + 1
    static const char* interpolation_name(Interpolation i);

  private:
    static void take_step(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
