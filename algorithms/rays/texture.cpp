// Sections: [images] [validate] [mipmap] [lookup]
#include "rays/texture.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "core/format.hpp"
#include "core/step.hpp"

namespace cg {

using glm::dvec2;
using glm::ivec2;

// ---- [images] -------------------------------------------------------------------------------

const char* filter_id(TexFilter f) {
    switch (f) {
        case TexFilter::Nearest:
            return "nearest";
        case TexFilter::Bilinear:
            return "bilinear";
        case TexFilter::Mipmap:
            return "mipmap";
    }
    return "";
}

const char* wrap_id(TexWrap w) {
    return w == TexWrap::Repeat ? "repeat" : "clamp";
}

TextureImage checker_image(int nu, int nv, TexColor c0, TexColor c1) {
    TextureImage im;
    im.width = nu;
    im.height = nv;
    im.texels.resize(static_cast<std::size_t>(nu) * nv);
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
            im.texels[static_cast<std::size_t>(j) * nu + i] = (i + j) % 2 == 0 ? c0 : c1;
    return im;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {
bool power_of_two(int n) {
    return n > 0 && (n & (n - 1)) == 0;
}
}  // namespace

void validate_image(const TextureImage& im, const std::string& field) {
    if (im.width < 1 || im.height < 1)
        throw InputError(field, "must have at least one texel (got " + std::to_string(im.width) +
                                    "×" + std::to_string(im.height) + ")");
    if (im.width > kMaxTextureSide || im.height > kMaxTextureSide ||
        static_cast<long long>(im.width) * im.height > kMaxTexels)
        throw InputError(field, "is " + std::to_string(im.width) + "×" + std::to_string(im.height) +
                                    " texels; the limit is 4096 on a side and 2048 × 2048 in all");
    if (im.texels.size() != static_cast<std::size_t>(im.width) * im.height)
        throw InputError(field, "has " + std::to_string(im.texels.size()) + " texels for " +
                                    std::to_string(im.width) + "×" + std::to_string(im.height));
    for (std::size_t k = 0; k < im.texels.size(); ++k)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(im.texels[k][c]) || im.texels[k][c] < 0 || im.texels[k][c] > 1e6)
                throw InputError(field, "texel (" + std::to_string(k % im.width) + ", " +
                                            std::to_string(k / im.width) +
                                            ") must be a colour with components in [0, 1e6] "
                                            "(got " +
                                            given(im.texels[k], 6) + ")");
}

void validate_texture(const Texture& t, const std::string& field) {
    validate_image(t.image, field);
    if (t.filter == TexFilter::Mipmap &&
        !(power_of_two(t.image.width) && power_of_two(t.image.height)))
        throw InputError(field + ".filter",
                         "\"mipmap\" needs a width and height that are powers of two, so that "
                         "each level halves the one before (the image is " +
                             std::to_string(t.image.width) + "×" + std::to_string(t.image.height) +
                             ")");
}

// ---- [mipmap] -------------------------------------------------------------------------------

TextureImage next_mip_level(const TextureImage& f) {
    TextureImage c;
    const int sx = f.width > 1 ? 2 : 1, sy = f.height > 1 ? 2 : 1;  // the block's size
    c.width = f.width / sx;
    c.height = f.height / sy;
    c.texels.resize(static_cast<std::size_t>(c.width) * c.height);
    const double share = 1.0 / (sx * sy);
    for (int j = 0; j < c.height; ++j)
        for (int i = 0; i < c.width; ++i) {
            TexColor sum(0.0);
            for (int b = 0; b < sy; ++b)
                for (int a = 0; a < sx; ++a) sum += f.at(sx * i + a, sy * j + b);
            c.texels[static_cast<std::size_t>(j) * c.width + i] = sum * share;
        }
    return c;
}

int mip_level_count(int width, int height) {
    int n = 1;
    for (int s = std::max(width, height); s > 1; s /= 2) ++n;
    return n;
}

MipMap build_mipmap(const TextureImage& image) {
    MipMap m;
    const int n = mip_level_count(image.width, image.height);
    m.levels.reserve(n);
    m.levels.push_back(image);
    for (int k = 1; k < n; ++k) m.levels.push_back(next_mip_level(m.levels.back()));
    return m;
}

// ---- [lookup] -------------------------------------------------------------------------------

dvec2 wrap_uv(dvec2 uv, TexWrap wrap) {
    if (wrap == TexWrap::Clamp) return glm::clamp(uv, dvec2(0.0), dvec2(1.0));
    return uv - glm::floor(uv);  // may round to 1 for a tiny negative u: indices are clamped
}

int wrap_index(long long i, int n, TexWrap wrap) {
    if (wrap == TexWrap::Clamp) return static_cast<int>(std::clamp<long long>(i, 0, n - 1));
    const long long m = i % n;
    return static_cast<int>(m < 0 ? m + n : m);
}

TexelTaps sample_nearest(const TextureImage& im, dvec2 st, TexWrap /*wrap*/) {
    TexelTaps t;
    const int i = std::clamp(static_cast<int>(std::floor(st.x * im.width)), 0, im.width - 1);
    const int j = std::clamp(static_cast<int>(std::floor(st.y * im.height)), 0, im.height - 1);
    t.texel[0] = {i, j};
    t.weight[0] = 1;
    t.count = 1;
    t.color = im.at(i, j);
    return t;
}

TexelTaps sample_bilinear(const TextureImage& im, dvec2 st, TexWrap wrap) {
    TexelTaps t;
    // Texel centres sit at (i + ½)/W: the four around (u, v) and the fractions between them.
    const double x = st.x * im.width - 0.5, y = st.y * im.height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double f = x - x0, g = y - y0;
    const long long i0 = static_cast<long long>(x0), j0 = static_cast<long long>(y0);
    const int ia = wrap_index(i0, im.width, wrap), ib = wrap_index(i0 + 1, im.width, wrap);
    const int ja = wrap_index(j0, im.height, wrap), jb = wrap_index(j0 + 1, im.height, wrap);
    t.texel = {ivec2{ia, ja}, ivec2{ib, ja}, ivec2{ia, jb}, ivec2{ib, jb}};
    t.weight = {(1 - f) * (1 - g), f * (1 - g), (1 - f) * g, f * g};
    t.count = 4;
    t.f = {f, g};
    t.color = t.weight[0] * im.at(ia, ja) + t.weight[1] * im.at(ib, ja) +
              t.weight[2] * im.at(ia, jb) + t.weight[3] * im.at(ib, jb);
    return t;
}

double mip_lambda(int width, int height, double footprint, int levels) {
    const double rho = footprint * std::max(width, height);  // texels under the footprint
    if (!(rho > 1)) return 0;                                // magnified: the finest level
    return std::min(std::log2(rho), static_cast<double>(levels - 1));
}

TextureLookup lookup(const Texture& t, const MipMap* mip, dvec2 uv, double footprint) {
    TextureLookup r;
    r.uv = uv;
    r.st = wrap_uv(uv, t.wrap);
    switch (t.filter) {
        case TexFilter::Nearest:
            r.taps = sample_nearest(t.image, r.st, t.wrap);
            r.color = r.taps.color;
            return r;
        case TexFilter::Bilinear:
            r.taps = sample_bilinear(t.image, r.st, t.wrap);
            r.color = r.taps.color;
            return r;
        case TexFilter::Mipmap: {
            const int n = static_cast<int>(mip->levels.size());
            r.lambda = mip_lambda(t.image.width, t.image.height, footprint, n);
            r.level0 = static_cast<int>(std::floor(r.lambda));
            r.level1 = std::min(r.level0 + 1, n - 1);
            r.blend = r.lambda - r.level0;
            r.taps = sample_bilinear(mip->levels[r.level0], r.st, t.wrap);
            r.coarse = sample_bilinear(mip->levels[r.level1], r.st, t.wrap);
            r.color = (1 - r.blend) * r.taps.color + r.blend * r.coarse.color;
            return r;
        }
    }
    return r;
}

TexColor texture_color(const Texture& t, const MipMap* mip, dvec2 uv, double footprint) {
    return lookup(t, mip, uv, footprint).color;
}

}  // namespace cg
