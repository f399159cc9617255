// Shadow maps: render the scene's depth from the light into a small N × N image, then, for each
// point the eye sees, move it into the light's frame, find its texel and compare depths.
//
// The course: "render the scene from the light's view and store the z-map; render from the eye;
// for a point P the eye sees, convert it to the light's frame and look up the distance to the
// light in the shadow map: equal, P is lit; farther, P is in shadow."
//
// Conventions. The light's frame is the look-at frame (right r, up u, forward f, f pointing from
// the light's position toward its target; r = normalise(f × up), u = r × f), and
//   light_from_world = [r, −r · o; u, −u · o; −f, f · o; 0 0 0 1]   (rows; o the light's position)
// so a point's light-space coordinates are (x_L, y_L, z_L) with z_L = −(distance along f). The
// depth stored and compared is light-space LINEAR depth d = −z_L = (P − o) · f, the distance
// along the light's view axis (not NDC z), in world units. The map's texel (i, j) covers
// s ∈ [i/N, (i+1)/N), t ∈ [j/N, (j+1)/N), j = 0 the bottom row, with
//   directional (orthographic):  s = (x_L / extent + 1) / 2,            t = (y_L / extent + 1) / 2
//   spot (perspective):          s = (x_L / (d tan(fov/2)) + 1) / 2,    t likewise with y_L
// A point is outside the light's frustum when s or t is outside [0, 1) or d outside
// [near, far]: the map knows nothing there, and the point counts as lit (said in its step).
//
// Phase 1 (one step per triangle): the triangle is rasterised into the map: every texel whose
// centre's light ray meets it at a depth in [near, far] keeps the nearer of that depth and what
// it holds (the map is cleared to far). Phase 2 (one step per eye pixel, bottom row first): the
// eye ray through the pixel's centre finds its nearest triangle, the visible point P; P goes
// into the light's frame, its texel (i, j) and the stored depth d_map are read, and
//   d_P − bias > d_map  → shadow,  else lit.
// Each verdict is compared with the exact one — a shadow ray from P to the light against every
// triangle — so the lookup's mistakes are counted: acne (the map says shadow, but the texel's
// surface is P's own triangle: self-shadowing that the bias is there to prevent), a false shadow
// from another surface (the map's resolution: the texel is shared with an occluder's edge), and
// false-lit (light leaking: a bias too large, "peter panning", or again the resolution).
// Refused: no triangles or more than 64, a zero-area triangle, coincident position and target,
// an up vector along the view direction, fov outside (0, 170], extent ≤ 0, near/far out of
// order, map_size outside 1..64, an eye image outside 1..64 pixels a side, and coordinates above
// 1e15 in size.
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

struct ShadowMap {
    static constexpr std::size_t kMaxTriangles = 64;
    static constexpr int kMaxMap = 64;         // map_size ≤ 64 texels a side
    static constexpr int kMaxEye = 64;         // the eye image ≤ 64 pixels a side
    static constexpr double kMaxCoord = 1e15;  // coordinates, extent, near, far

    enum class LightType : std::uint8_t { Directional, Spot };

    struct Camera {
        glm::dvec3 position{0, 5, 0}, target{0, 0, 0}, up{0, 0, -1};
        bool operator==(const Camera&) const = default;
    };
    struct Light : Camera {
        LightType type = LightType::Directional;
        double extent = 2;   // directional: the orthographic box's half-width (world units)
        double fov_deg = 0;  // spot: the full field of view, degrees
        double near = 0.1, far = 10;
        bool operator==(const Light&) const = default;
    };
    struct Eye : Camera {
        double fov_deg = 60;  // vertical field of view, degrees
        int width = 12, height = 9;
        bool operator==(const Eye&) const = default;
    };
    using Triangle = std::array<glm::dvec3, 3>;

    struct Input {
        std::vector<Triangle> triangles;
        Light light;
        int map_size = 8;
        double bias = 0.05;
        Eye eye;
        bool operator==(const Input&) const = default;
    };

    // A camera's orthonormal frame; `half` is the light's extent, or tan(fov/2) for a
    // perspective camera (the eye, a spot light).
    struct Frame {
        glm::dvec3 origin{0}, right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, -1};
        double half = 1;
        bool perspective = false;
        bool operator==(const Frame&) const = default;
    };

    enum class Verdict : std::uint8_t {
        Pending,
        Background,   // the eye ray meets nothing
        Outside,      // P is outside the light's frustum: lit
        Lit,          // map and shadow ray agree: lit
        Shadow,       // ... agree: in shadow
        Acne,         // the map says shadow, its texel holds P's own triangle: self-shadowing
        FalseShadow,  // the map says shadow, the shadow ray reaches the light (another surface)
        FalseLit      // the map says lit, the shadow ray is blocked (light leaking)
    };
    static const char* verdict_id(Verdict v);  // "lit", "shadow", "acne", ...
    static char verdict_char(Verdict v);       // '.', 'o', 'L', 'S', 'A', 'F', 'K'

    // One lookup: an eye pixel's visible point and its test against the map.
    struct Lookup {
        int i = 0, j = 0;  // the eye pixel
        int tri = -1;      // the triangle P lies on (-1: background)
        glm::dvec3 p{0};
        glm::dvec4 p_light{0};  // light_from_world [P, 1]
        double s = 0, t = 0;    // map coordinates in [0, 1)
        int ti = -1, tj = -1;   // the texel (-1: outside)
        double d_p = 0, d_map = 0;
        int map_tri = -1;  // the triangle the texel's depth came from (-1: cleared)
        bool map_shadow = false;
        bool exact_shadow = false;  // the shadow ray from P is blocked
        int blocker = -1;
        Verdict verdict = Verdict::Pending;
        bool operator==(const Lookup&) const = default;
    };

    struct Counts {
        int lit = 0, shadow = 0, background = 0, outside = 0, acne = 0, false_shadow = 0,
            false_lit = 0;
        bool operator==(const Counts&) const = default;
    };

    struct Result {
        int map_size = 0;
        std::vector<double> depth;  // N × N, texel (i, j) at [j N + i]; far where nothing
        std::vector<int> owner;     // the triangle each texel holds (-1: none)
        int width = 0, height = 0;
        std::vector<Verdict> image;  // width × height, pixel (i, j) at [j width + i]
        Counts counts;
        Lookup last;  // the last pixel's lookup (the exam's question)
        glm::dmat4 light_from_world{1.0};
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Setup, Rasterise, Lookup, Summary, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Setup;
        Phase last = Phase::Setup;
        Frame light, eye;
        glm::dmat4 light_from_world{1.0};
        std::vector<double> depth;  // the map being rendered
        std::vector<int> owner;
        int k = -1;                    // the triangle rasterised last
        int covered = 0, written = 0;  // ... texels it covered, and where it was nearer
        std::vector<Verdict> image;    // the eye image (Pending until looked up)
        long long next_pixel = 0;      // row-major from the bottom-left
        Lookup look;                   // the last lookup
        Counts counts;
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
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.depth) + heap_bytes(s.owner) + heap_bytes(s.image);
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

    // The whole render in straight loops, for the benchmark.
    static Result render(const Input& in);

    // The pieces both paths share.
    static Frame light_frame(const Light& l);
    static Frame eye_frame(const Eye& e);
    static glm::dmat4 view_matrix(const Frame& f);  // light_from_world
    // The light ray through texel (i, j)'s centre, o + t d with d · f = 1 (t is the depth).
    static void texel_ray(const Frame& f, int n, int i, int j, glm::dvec3& o, glm::dvec3& d);
    // Rasterise triangle k into depth/owner; returns texels covered, sets `written`.
    static int rasterise(const Input& in, const Frame& light, int k, std::vector<double>& depth,
                         std::vector<int>& owner, int& written);
    // Nearest hit of a ray o + t d (t > 0) against the triangles; -1 for none.
    static int nearest(const Input& in, const glm::dvec3& o, const glm::dvec3& d, double& t);
    static Lookup lookup(const Input& in, const Frame& light, const Frame& eye,
                         const glm::dmat4& light_from_world, const std::vector<double>& depth,
                         const std::vector<int>& owner, int i, int j);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
