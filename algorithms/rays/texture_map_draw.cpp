// Texture mapping, the picture.
// 3D: the surface painted with the texture, the point P and the directions of growing u and v
// there (at least 30 px), framed on the surface around P.
// Image panels: the texture itself, one cell a texel, with (s, t) on it and — mip-mapping — the
// pixel's footprint; the texels the step reads outlined with their weights (nearest: the one
// texel). Mip-mapping adds the level in hand: the level just built, or the level a lookup reads,
// with (s, t), the footprint (about one texel at the level λ picks) and its taps.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "rays/texture_draw.hpp"
#include "rays/texture_map.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Phase = TextureMap::Phase;

// The sample point, and (mip-mapping) the footprint, on a panel showing an image of w × h texels
// every `shown`-th.
void mark_sample(const TextureLookup& l, double footprint, int w, int h, int shown, bool with_foot,
                 Panel& panel) {
    const dvec2 at = dvec2(l.st.x * w, l.st.y * h) / double(shown);
    if (with_foot && footprint > 0) {
        const dvec2 half = 0.5 * footprint * dvec2(w, h) / double(shown);
        const dvec2 a = at - half, b = at + half;
        panel.polygons.push_back({{{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}},
                                  {Role::Window, 1.5f, true},
                                  true,
                                  false});
    }
    panel.points.push_back({at, "(s, t)", {Role::Active}, 6.0f, 3});
}

void outline_taps(const TexelTaps& tp, int shown, Panel& panel) {
    for (int q = 0; q < tp.count; ++q)
        texdraw::outline_texel(tp.texel[q], shown,
                               tp.count > 1 ? num(tp.weight[q], 3) : "nearest",
                               q == 0 ? Role::Kept : Role::Entering, panel);
}

}  // namespace

void TextureMap::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Texture& t = in.texture;
    const TextureLookup& l = s.r.lookup;
    const bool mip = t.filter == TexFilter::Mipmap;
    const bool wrapped = s.last >= Phase::Wrap && s.phase != Phase::Map;
    const bool fine = s.last >= Phase::Sample && s.phase > Phase::Sample;  // taps read
    const bool coarse = s.last >= Phase::SampleCoarse && s.phase > Phase::SampleCoarse;
    const bool lod = mip && s.last >= Phase::LevelOfDetail && s.phase > Phase::LevelOfDetail;

    // The level in hand besides level 0: the one just built, or the one a lookup reads.
    int k = 0;
    if (s.last == Phase::MipLevel && s.phase != Phase::Map) k = static_cast<int>(s.levels.size());
    if (mip && fine) k = coarse && l.level1 != l.level0 ? l.level1 : l.level0;

    // ---- level 0: the texture ----
    int shown = 1;
    const TextureImage& im = level(s, 0);
    Panel& base = texdraw::add_image(im, scene, "the texture", shown);
    if (wrapped) mark_sample(l, lod ? in.footprint : 0, im.width, im.height, shown, lod, base);
    if (fine && l.level0 == 0) outline_taps(l.taps, shown, base);
    if (coarse && l.level1 == 0 && l.level1 != l.level0) outline_taps(l.coarse, shown, base);

    // ---- the level in hand ----
    if (k > 0) {
        int kshown = 1;
        const TextureImage& lk = level(s, k);
        Panel& p = texdraw::add_image(lk, scene, "level " + std::to_string(k), kshown);
        if (wrapped) mark_sample(l, in.footprint, lk.width, lk.height, kshown, lod, p);
        if (fine && k == l.level0) outline_taps(l.taps, kshown, p);
        if (coarse && k == l.level1 && l.level1 != l.level0) outline_taps(l.coarse, kshown, p);
    }

    // ---- 3D ----
    const std::size_t first = scene.faces3.size();
    texdraw::add_textured_surface(s.prepared, in.surface, s.r.frame.uv, t, nullptr, scene);
    texdraw::add_point_frame(s.prepared, in.point, s.last >= Phase::Map ? &s.r.frame : nullptr,
                             scene);
    dvec3 lo = in.point, hi = in.point;
    for (std::size_t f = first; f < scene.faces3.size(); ++f)
        for (const dvec3& q : scene.faces3[f].points) lo = glm::min(lo, q), hi = glm::max(hi, q);
    add_focus(scene, lo, hi);
}

}  // namespace cg
