// The recursive ray tracer, step by step (the course's "recursive ray tracing"; the scene, the
// tracer and its conventions are those of rays/rt_scene.hpp).
//
// The student picks the granularity:
//   pixels    one step per pixel: the image fills in row by row from the bottom, each step
//             tracing a pixel's whole ray tree with the plain tracer;
//   rows      one step per row of pixels;
//   ray-tree  one chosen pixel (or one given ray), one step per event of its ray tree: the
//             primary ray; the nearest hit (or a miss: the background); one step per light, the
//             shadow ray blocked or not and the light's diffuse and specular terms; the mirror
//             ray; the refracted ray (Snell's law, or total internal reflection); each ray's
//             colour summed back into its parent's, k_r and k_t weighting; the pixel's colour.
// The ray tree is traced with an explicit stack of the rays in progress, so stepping can stop
// anywhere; its arithmetic is the plain tracer's, in the same order, so the colour it finds is
// bit for bit the plain tracer's (the tests check this on random scenes).
//
// Ray casting is the degenerate setting: settings.max_depth = 0 and no shadows.
//
// Distribution ray tracing (rt_scene.hpp): the ray tree of a distributed pixel holds one primary
// ray per pixel sample, each stepped through its own tree in turn (its position in the pixel,
// lens point and time told at its `primary` step); an area light is one `area-light` step that
// casts all its shadow rays over the light's area; a glossy material casts its reflected rays one
// `glossy` step each, drawn from the Phong lobe about the mirror direction. The pixel's colour is
// the filtered average of the primary rays' colours. The random numbers come from the pixel's
// generator in the plain tracer's order, so the colour is still the plain tracer's bit for bit.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "rays/rt_scene.hpp"

namespace cg {

struct RayTracer {
    enum class Granularity : std::uint8_t { Pixels, Rows, RayTree };
    // A ray-tree run of an image of at most this many pixels also renders the whole image at
    // its start, for the picture (the pixel shown inside it).
    static constexpr long long kPreviewPixels = 96 * 72;
    static constexpr double kPreviewWork = 3e7;  // ... and, distributed, this many ray tests

    struct Input {
        rt::Scene scene;
        Granularity granularity = Granularity::Pixels;
        glm::dvec2 pixel{0.0};      // ray-tree: the pixel containing this point (pixel units, y up)
        bool explicit_ray = false;  // ray-tree: trace this ray instead of a pixel's
        glm::dvec3 ray_origin{0.0}, ray_direction{0.0};
        bool operator==(const Input&) const = default;
    };

    enum class RayKind : std::uint8_t { Primary, Shadow, Reflected, Refracted };
    static const char* kind_id(RayKind k);  // "primary", "shadow", "reflected", "refracted"

    // One ray of the ray tree: what the picture, the narration and the result show.
    struct RayNode {
        RayKind kind = RayKind::Primary;
        int parent = -1;  // the ray that cast it
        int depth = 0;    // reflections/refractions that led to it
        glm::dvec3 origin{0.0}, direction{0.0};
        rt::Hit hit;            // a primary, mirror or refracted ray's nearest hit
        rt::Surface surface;    // ... its k_a, k_d and shading normal (textured, bumped)
        int detail = -1;        // ... and its texture lookup in State::details (-1: none)
        bool traced = false;    // its hit (or its blocker) is known
        int light = -1;         // a shadow ray's light
        int blocker = -1;       // ... and the object blocking it (-1: the light is seen)
        double t_max = 0;       // ... and the distance to its light
        rt::Color color{0.0};   // what this ray carries back (a shadow ray: the light's terms)
        rt::Color weight{1.0};  // the share of it its parent adds (k_r, k_t)
        bool total_internal = false;  // a mirror ray cast by total internal reflection
        bool returned = false;        // its colour has been summed into its parent's
        // Distribution ray tracing: a primary ray's pixel sample (-1: not distributed), its
        // point of the light's area (a shadow ray's, -1: a point light), whether a reflected
        // ray was drawn from the glossy lobe; every ray's time.
        int sample = -1;
        int light_sample = -1;
        bool glossy = false;
        double time = 0;
        glm::dvec3 light_point{0.0};  // a shadow ray's end on an area light
        bool operator==(const RayNode&) const = default;
    };
    // The ray's name in the tree: R0 for the primary ray, then S/M/T with its index.
    static std::string ray_label(const std::vector<RayNode>& tree, int k);

    // A ray being traced, and what comes next for it.
    enum class Next : std::uint8_t { Cast, Texture, Light, Secondary, Refract, Return };
    struct Frame {
        int node = 0;
        Next next = Next::Cast;
        int light = 0;     // the next light to test
        rt::Color c{0.0};  // the colour so far
        int gloss = 0;     // glossy rays drawn so far
        bool operator==(const Frame&) const = default;
    };

    // The image, a row per shared block: copying a state (a checkpoint, a snapshot) shares the
    // rows, and a step copies only the row it writes when that row is shared.
    class Rows {
      public:
        void reset(int width, int height);
        std::uint32_t get(int i, int j) const { return (*rows_[j])[i]; }
        void set(int i, int j, std::uint32_t v);
        int width() const { return width_; }
        int height() const { return static_cast<int>(rows_.size()); }
        std::vector<std::uint32_t> pixels() const;  // row 0 first (the bottom)
        bool operator==(const Rows& o) const;
        std::size_t bytes() const { return rows_.capacity() * sizeof(rows_[0]) + width_ * 4u; }

      private:
        int width_ = 0;
        std::vector<std::shared_ptr<std::vector<std::uint32_t>>> rows_;
    };

    enum class Phase : std::uint8_t { Start, Pixels, Tree, Done };
    // What a step did (Spec::events, in this order).
    enum class Event : std::uint8_t {
        None,
        Pixel,
        Row,
        Primary,
        Hit,
        Miss,
        Lit,
        Shadowed,
        LightBehind,
        Reflect,
        Refract,
        TotalInternal,
        DepthLimit,
        Return,
        Colour,
        Texture,
        AreaLight,
        Glossy,
        Build
    };

    struct State {
        Shared<Input> in;
        Shared<rt::Prepared> prepared;  // the camera frame and prepared objects, computed once
        Phase phase = Phase::Start;
        // pixels and rows
        long long next_pixel = 0;  // row-major from the bottom-left
        Rows image;
        int last_i = -1, last_j = -1;  // the pixel (or row, last_i = -1) just computed
        rt::Color last_color{0.0};
        rt::RayCounts rays;
        std::vector<rt::RayCounts> row_rays;  // pixels/rows: the rays each row cost (height)
        // ray-tree
        int pixel_i = 0, pixel_j = 0;
        std::vector<RayNode> tree;
        std::vector<rt::SurfaceDetail> details;  // the texture lookups of textured hits
        std::vector<Frame> stack;
        int active = -1;             // the ray the last step worked on
        rt::LightTerm last_term;     // the last light step's terms
        rt::Color pixel_color{0.0};  // the primary ray's colour, once returned
        // distribution: the pixel's generator and samples, the next sample, the running sums,
        // and the last area light step's count of shadow rays that reached the light
        Rng rng{0};
        std::vector<rt::PixelSample> samples;
        int next_sample = 0;
        rt::Color sum{0.0};
        double sum_w = 0;
        int area_lit = 0, area_rays = 0;
        int gloss_skipped = 0;  // glossy rays drawn below the surface before the last one
        Shared<std::vector<std::uint32_t>>
            preview;                     // a cheap picture around the pixel (may be empty)
        Event last_event = Event::None;  // what the last step did
        bool operator==(const State&) const = default;
    };

    struct Result {
        Granularity granularity = Granularity::Pixels;
        int width = 0, height = 0;
        rt::RayCounts rays;
        std::vector<std::uint32_t> image;  // pixels/rows: row 0 at the bottom
        // ray-tree
        bool explicit_ray = false;  // the tree of a given ray, not of a pixel's
        int pixel_i = 0, pixel_j = 0;
        rt::Color color{0.0};
        std::vector<RayNode> tree;
        std::vector<rt::SurfaceDetail> details;
        bool distributed = false;
        rt::Distribution distribution;         // what the scene spreads its rays over
        std::vector<rt::PixelSample> samples;  // the pixel's samples (distributed)
        bool operator==(const Result&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    // Refuses what start refuses, without building the hierarchy or rendering the preview
    // (what loading a lesson's presets needs; see make_algorithm).
    static void check(const Input& in) { validate(in); }
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return s.image.bytes() + s.tree.capacity() * sizeof(RayNode) +
               s.details.capacity() * sizeof(rt::SurfaceDetail) +
               s.stack.capacity() * sizeof(Frame) + s.samples.capacity() * sizeof(rt::PixelSample) +
               s.row_rays.capacity() * sizeof(rt::RayCounts);
    }

    // Exam practice (ray_tracer_exam.cpp): one ray into a small scene, traced by hand; or, for
    // a distributed scene, what each effect spreads its rays over.
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields(const Input& in);

  private:
    static void advance(State& s);
    static void advance_tree(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
