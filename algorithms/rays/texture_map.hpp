// Texture mapping, step by step: a point on a surface → texture coordinates (u, v) → a colour
// (the course: "associate texture with polygon; map pixel onto polygon then into texture map;
// use weighted average of covered texture to compute colour").
//
// Steps: the parametrisation (rays/uv_map.hpp: plane, sphere by longitude and latitude, the
// axial quadrics by angle and height, triangle by barycentric interpolation); the wrap of (u, v)
// into [0, 1] (repeat or clamp); then the filter (rays/texture.hpp): the nearest texel, or the
// four bilinear texels and their weights, or — mipmapping, the "weighted average of the covered
// texture" — the pyramid built level by level (each level the 2 × 2 box average of the one
// before), the level of detail λ = log₂(footprint · max(W, H)) from the pixel's footprint, the
// bilinear lookups at levels ⌊λ⌋ and ⌊λ⌋ + 1, and their blend.
// The point must lie on the surface (within round-off); the footprint is the side of the pixel's
// preimage in (u, v) units (a tracer gets it from ray differentials, rays/rt_texture.hpp).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "rays/texture.hpp"
#include "rays/uv_map.hpp"

namespace cg {

struct TextureMap {
    struct Input {
        UvSurface surface;
        glm::dvec3 point{0.0};  // on the surface, world space
        Texture texture;
        double footprint = 0;  // mipmap: the pixel's preimage side in (u, v) units, ≥ 0
        bool operator==(const Input&) const = default;
    };
    struct Result {
        UvFrame frame;         // (u, v), and the partials
        TextureLookup lookup;  // the wrapped (s, t), the texels, their weights, the colour
        int levels = 1;        // mipmap levels
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        Map,
        Wrap,
        MipLevel,
        LevelOfDetail,
        Sample,
        SampleCoarse,
        Blend,
        Done
    };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Map;
        Phase last = Phase::Map;
        PreparedUv prepared;
        Result r;
        std::vector<Shared<TextureImage>> levels;  // mipmap levels 1, 2, … as they are built
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s);

    // Exam practice (texture_map_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The plain function, with the same arithmetic.
    static Result solve(const Input& in);

    // Mipmap level k of a state's texture (0: the image itself); k < levels built.
    static const TextureImage& level(const State& s, int k);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
