// Texture images and the one texture lookup: the course's "map pixel onto polygon then into
// texture map; use weighted average of covered texture to compute colour".
//
// One in-memory image type serves every texture in the sandbox: a colour texture of
// `texture-map` and of the tracer's materials, and the grey-scale height map of `bump-map`.
// Where the image came from (a PNG file read by the JSON layer, an inline grid, a generated
// checker) does not matter here: this library needs only GLM and std.
//
// Conventions. Texel (i, j) is column i from the left and row j from the BOTTOM (y up, the
// project's pixel convention), so its centre is at ((i + ½)/W, (j + ½)/H) in (u, v). (Images
// are stored top row first; the JSON layer turns them over when it reads them.)
// Wrapping: `repeat` takes the fractional part of u and v (the texture tiles the plane), `clamp`
// clamps them to [0, 1] (the border texels stretch outward).
// Filters:
//   nearest   the texel containing (u, v): i = ⌊u W⌋, j = ⌊v H⌋;
//   bilinear  the four texels around (u, v): with x = u W − ½, i₀ = ⌊x⌋, f = x − i₀ (and the
//             same for v), weights (1 − f)(1 − g), f(1 − g), (1 − f) g, f g. The weights sum to 1
//             and a texture linear in the texel centres is reproduced exactly;
//   mipmap    the pixel's footprint in the texture, box-filtered: level k of the pyramid is
//             the image averaged over 2^k × 2^k blocks (W, H powers of two); a footprint of ρ
//             texels picks λ = log₂ ρ, and the colour is bilinear at levels ⌊λ⌋ and ⌊λ⌋ + 1,
//             blended by λ − ⌊λ⌋ (trilinear filtering).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace cg {

using TexColor = glm::dvec3;

struct TextureImage {
    int width = 0, height = 0;
    std::vector<TexColor> texels;  // width × height, row-major, row 0 at the bottom (v small)
    const TexColor& at(int i, int j) const {
        return texels[static_cast<std::size_t>(j) * width + i];
    }
    bool operator==(const TextureImage&) const = default;
};

// Limits, so an input cannot exhaust the machine: refused with their numbers.
constexpr int kMaxTextureSide = 4096;
constexpr long long kMaxTexels = 2048LL * 2048;

enum class TexFilter : std::uint8_t { Nearest, Bilinear, Mipmap };
enum class TexWrap : std::uint8_t { Repeat, Clamp };
const char* filter_id(TexFilter f);  // "nearest", "bilinear", "mipmap"
const char* wrap_id(TexWrap w);      // "repeat", "clamp"

// A colour texture: the image and how it is looked up. `source` says where the image came
// from, for the narration and for writing the input back ("earth.png", "grid", "checker").
struct Texture {
    TextureImage image;
    TexFilter filter = TexFilter::Bilinear;
    TexWrap wrap = TexWrap::Repeat;
    std::string source = "grid";
    // A generated checker (source "checker"): its size in squares and two colours, kept so the
    // input can be written back as it was given.
    glm::ivec2 checker_size{0, 0};
    std::array<TexColor, 2> checker_colors{TexColor(0.0), TexColor(1.0)};
    bool operator==(const Texture&) const = default;
};

// An n_u × n_v checker of colours c0 (texel (0, 0)) and c1, one texel per square.
TextureImage checker_image(int nu, int nv, TexColor c0, TexColor c1);

// Throws InputError naming `field` (e.g. "texture") for an empty or oversized image, a texel
// count that does not match, non-finite or negative texels, or a mipmap filter on a size that
// is not a power of two.
void validate_texture(const Texture& t, const std::string& field);
void validate_image(const TextureImage& im, const std::string& field);

// ---- the mipmap pyramid -------------------------------------------------------------------

// Level k + 1 from level k: each texel the average of a 2 × 2 block (2 × 1 or 1 × 2 once a
// side is down to one texel). Precondition: sizes are powers of two.
TextureImage next_mip_level(const TextureImage& finer);
int mip_level_count(int width, int height);  // 1 + log₂ max(W, H)
struct MipMap {
    std::vector<TextureImage> levels;  // levels[0] is the image itself
    bool operator==(const MipMap&) const = default;
};
MipMap build_mipmap(const TextureImage& image);

// ---- the lookup ---------------------------------------------------------------------------

// (u, v) wrapped into [0, 1]: repeat keeps the fractional part, clamp clamps.
glm::dvec2 wrap_uv(glm::dvec2 uv, TexWrap wrap);
// A texel index wrapped (repeat: modulo n) or clamped to [0, n − 1].
int wrap_index(long long i, int n, TexWrap wrap);

// The texels a filter reads and their weights (nearest: one, bilinear: four).
struct TexelTaps {
    std::array<glm::ivec2, 4> texel{};
    std::array<double, 4> weight{0, 0, 0, 0};
    int count = 0;
    glm::dvec2 f{0.0};  // bilinear: the fractions (f, g) between the texel centres
    TexColor color{0.0};
    bool operator==(const TexelTaps&) const = default;
};
// `st` is (u, v) already wrapped.
TexelTaps sample_nearest(const TextureImage& im, glm::dvec2 st, TexWrap wrap);
TexelTaps sample_bilinear(const TextureImage& im, glm::dvec2 st, TexWrap wrap);

// The level of detail for a footprint of `footprint` in (u, v) units (the side of the pixel's
// preimage): λ = log₂(footprint · max(W, H)), clamped to [0, levels − 1].
double mip_lambda(int width, int height, double footprint, int levels);

struct TextureLookup {
    glm::dvec2 uv{0.0};  // as given
    glm::dvec2 st{0.0};  // wrapped
    TexelTaps taps;      // nearest / bilinear, or the finer mipmap level's bilinear taps
    // mipmap only:
    double lambda = 0;           // the level of detail
    int level0 = 0, level1 = 0;  // the two levels read (equal when λ is whole or at an end)
    double blend = 0;            // λ − level0: the share of level1
    TexelTaps coarse;            // level1's taps
    TexColor color{0.0};
    bool operator==(const TextureLookup&) const = default;
};
// The whole lookup. `mip` must be build_mipmap(t.image) when t.filter is mipmap (else unused);
// `footprint` in (u, v) units, ≥ 0 (0: the finest level).
TextureLookup lookup(const Texture& t, const MipMap* mip, glm::dvec2 uv, double footprint);
// Only the colour, with the same arithmetic.
TexColor texture_color(const Texture& t, const MipMap* mip, glm::dvec2 uv, double footprint);

}  // namespace cg
