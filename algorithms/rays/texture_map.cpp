// Sections: [spec] [validate] [advance] [narrate]; the picture is in texture_map_draw.cpp.
#include "rays/texture_map.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

using glm::dvec2;
using glm::dvec3;
using Phase = TextureMap::Phase;

// ---- [spec] ---------------------------------------------------------------------------------

namespace {
enum Line {
    kLineMap = 1,
    kLineWrap,
    kLineNearest,
    kLineBilinear,
    kLineMipLevel,
    kLineLod,
    kLineLevelSample,
    kLineBlend
};
}  // namespace

const Spec& TextureMap::spec() {
    static const Spec spec{
        "texture-map",
        "Texture mapping: (u, v), the texel lookup and its filter",
        "Ray Tracing",
        {
            "(u, v) ← the surface's parametrisation at P",
            "(s, t) ← wrap(u, v)    ▷ repeat: the fractional part; clamp: to [0, 1]",
            "nearest: the texel (⌊s W⌋, ⌊t H⌋)",
            "bilinear: x = s W − ½, i₀ = ⌊x⌋, f = x − i₀ (and y, j₀, g);  c = Σ w_k T_k",
            "mipmap: level k ← the 2 × 2 box average of level k − 1, k = 1 … log₂ max(W, H)",
            "    λ ← log₂(footprint · max(W, H)), clamped to [0, levels − 1]",
            "    c₀, c₁ ← bilinear at levels ⌊λ⌋ and ⌊λ⌋ + 1",
            "    c ← (1 − (λ − ⌊λ⌋)) c₀ + (λ − ⌊λ⌋) c₁",
        },
        {
            {"plane-uv",
             "a plane: u, v are the point's coordinates along the two axes, over the scale"},
            {"sphere-uv", "a sphere or ellipsoid: u from the longitude, v from the latitude"},
            {"axial-uv",
             "a cylinder, cone, paraboloid or hyperboloid: u from the angle, v from the height"},
            {"triangle-uv",
             "a triangle: the corners' (u, v) interpolated with barycentric weights"},
            {"wrap", "(u, v) wrapped into the texture's [0, 1] square"},
            {"nearest", "the texel containing (s, t) gives the colour"},
            {"bilinear", "the four texels around (s, t), weighted by how near their centres are"},
            {"mip-level", "one more level of the pyramid: each texel the average of a 2 × 2 block"},
            {"level-of-detail", "the footprint picks the level λ whose texels are about its size"},
            {"level-sample", "a bilinear lookup at one of the two levels around λ"},
            {"blend", "the two levels' colours blended by the fraction of λ (trilinear)"},
        },
        {},  // no sliders
        {
            .predict =
                {
                    {"sphere-uv", {"uv"}},
                    {"plane-uv", {"uv"}},
                    {"wrap", {"st"}},
                    {"nearest", {"texel"}},
                    {"bilinear", {"texel", "color"}},
                },
            .mistakes =
                {
                    {"sphere-uv", "uv", "reverse", "swapped u and v"},
                    {"bilinear", "weights", "reverse", "paired the weights with the wrong texels"},
                },
            .variants =
                {
                    {"nearest", "/texture/filter", "\"nearest\""},
                    {"bilinear", "/texture/filter", "\"bilinear\""},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

void check_point(dvec3 v, const std::string& field) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]) || std::fabs(v[i]) > 1e12)
            throw InputError(
                field + "[" + std::to_string(i) + "]",
                "must be a finite number of magnitude at most 1e12 (got " + given(v[i]) + ")");
}

}  // namespace

void TextureMap::validate(const Input& in) {
    validate_uv_surface(in.surface, "surface");
    check_point(in.point, "point");
    validate_texture(in.texture, "texture");
    if (!(in.footprint >= 0 && in.footprint <= 1e6))
        throw InputError("footprint", "must be a size in (u, v) units between 0 and 1e6 (got " +
                                          given(in.footprint) + ")");
    check_on_surface(in.surface, prepare_uv(in.surface), in.point, "point");
}

TextureMap::State TextureMap::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.prepared = prepare_uv(in.surface);
    return s;
}

std::size_t TextureMap::bytes(const State& s) {
    std::size_t n = s.in->texture.image.texels.capacity() * sizeof(TexColor);
    for (const auto& l : s.levels) n += l->texels.capacity() * sizeof(TexColor);
    return n;
}

const TextureImage& TextureMap::level(const State& s, int k) {
    return k == 0 ? s.in->texture.image : *s.levels[k - 1];
}

TextureMap::Result TextureMap::solve(const Input& in) {
    Result r;
    const PreparedUv p = prepare_uv(in.surface);
    r.frame = uv_frame(p, in.point);
    if (in.texture.filter == TexFilter::Mipmap) {
        const MipMap mip = build_mipmap(in.texture.image);
        r.levels = static_cast<int>(mip.levels.size());
        r.lookup = lookup(in.texture, &mip, r.frame.uv, in.footprint);
    } else {
        r.lookup = lookup(in.texture, nullptr, r.frame.uv, in.footprint);
    }
    return r;
}

// ---- [advance] ------------------------------------------------------------------------------

// The same calls, in the same order, as lookup() in rays/texture.cpp: the colour is solve()'s
// to the last bit.
void TextureMap::advance(State& s) {
    const Input& in = *s.in;
    const Texture& t = in.texture;
    TextureLookup& l = s.r.lookup;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Map:  // The parametrisation
            s.r.frame = uv_frame(s.prepared, in.point);
            s.phase = Phase::Wrap;
            return;
        case Phase::Wrap:  // Wrap into the unit square
            l.uv = s.r.frame.uv;
            l.st = wrap_uv(l.uv, t.wrap);
            if (t.filter == TexFilter::Mipmap) {
                s.r.levels = mip_level_count(t.image.width, t.image.height);
                s.phase = s.r.levels > 1 ? Phase::MipLevel : Phase::LevelOfDetail;
            } else {
                s.phase = Phase::Sample;
            }
            return;
        case Phase::MipLevel: {  // One level of the pyramid
            const int k = static_cast<int>(s.levels.size());
            s.levels.push_back(Shared<TextureImage>(next_mip_level(level(s, k))));
            if (static_cast<int>(s.levels.size()) + 1 >= s.r.levels) s.phase = Phase::LevelOfDetail;
            return;
        }
        case Phase::LevelOfDetail:  // The footprint picks the level
            l.lambda = mip_lambda(t.image.width, t.image.height, in.footprint, s.r.levels);
            l.level0 = static_cast<int>(std::floor(l.lambda));
            l.level1 = std::min(l.level0 + 1, s.r.levels - 1);
            l.blend = l.lambda - l.level0;
            s.phase = Phase::Sample;
            return;
        case Phase::Sample:  // The texel lookup
            switch (t.filter) {
                case TexFilter::Nearest:
                    l.taps = sample_nearest(t.image, l.st, t.wrap);
                    l.color = l.taps.color;
                    s.phase = Phase::Done;
                    return;
                case TexFilter::Bilinear:
                    l.taps = sample_bilinear(t.image, l.st, t.wrap);
                    l.color = l.taps.color;
                    s.phase = Phase::Done;
                    return;
                case TexFilter::Mipmap:
                    l.taps = sample_bilinear(level(s, l.level0), l.st, t.wrap);
                    if (l.level1 == l.level0) {
                        l.coarse = l.taps;
                        s.phase = Phase::Blend;
                    } else {
                        s.phase = Phase::SampleCoarse;
                    }
                    return;
            }
            return;
        case Phase::SampleCoarse:
            l.coarse = sample_bilinear(level(s, l.level1), l.st, t.wrap);
            s.phase = Phase::Blend;
            return;
        case Phase::Blend:  // Trilinear: blend the two levels
            l.color = (1 - l.blend) * l.taps.color + l.blend * l.coarse.color;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void TextureMap::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string texel_text(glm::ivec2 t) {
    return "(" + std::to_string(t.x) + ", " + std::to_string(t.y) + ")";
}

std::string taps_text(const TexelTaps& t, const TextureImage& im) {
    std::string s;
    for (int k = 0; k < t.count; ++k)
        s += (k ? " + " : "") + num(t.weight[k], 4) + "·" +
             num(im.at(t.texel[k].x, t.texel[k].y), 3);
    return s;
}

void narrate_map(const TextureMap::State& s, StepInfo& info) {
    const UvSurface& sf = s.in->surface;
    const UvFrame& f = s.r.frame;
    const dvec3 P = s.in->point;
    info.line = kLineMap;
    switch (sf.kind) {
        case UvKind::Plane: {
            info.event = "plane-uv";
            const dvec3 d = P - s.prepared.origin;
            info.narration =
                "On the plane: P − O = " + num(d, 4) + "; u = (P − O)·a/s = " + num(f.uv.x, 6) +
                ", v = (P − O)·b/s = " + num(f.uv.y, 6) + " with a = " + num(s.prepared.a, 4) +
                ", b = n × a = " + num(s.prepared.b, 4) + ", s = " + num(s.prepared.scale) + ".";
            info.math = "u = \\frac{(P - O) \\cdot a}{s} = " + tex(f.uv.x) +
                        ",\\quad v = \\frac{(P - O) \\cdot b}{s} = " + tex(f.uv.y);
            return;
        }
        case UvKind::Triangle: {
            info.event = "triangle-uv";
            const dvec3 b = f.barycentric;
            info.narration = "Barycentric weights of P: (α, β, γ) = " + num(b, 4) +
                             "; (u, v) = α·" + num(sf.uv[0], 4) + " + β·" + num(sf.uv[1], 4) +
                             " + γ·" + num(sf.uv[2], 4) + " = " + num(f.uv, 6) + ".";
            info.math = "(u, v) = \\alpha\\,uv_0 + \\beta\\,uv_1 + \\gamma\\,uv_2 = " + tex(f.uv);
            return;
        }
        case UvKind::Quadric:
            break;
    }
    const dvec3 m = f.model_point;
    const std::string model =
        s.prepared.quadric.transformed ? " (in model space " + num(m, 4) + ")" : "";
    const double phi_deg = f.phi * 180 / 3.14159265358979323846;
    if (sf.quadric.kind == QuadricKind::Sphere || sf.quadric.kind == QuadricKind::Ellipsoid) {
        info.event = "sphere-uv";
        const double theta_deg = f.theta * 180 / 3.14159265358979323846;
        info.narration =
            "Longitude φ = atan2(y, x) = " + num(phi_deg, 5) +
            "°, polar angle θ = " + "acos(z/r) = " + num(theta_deg, 5) + "°" + model +
            ": u = ½ + φ/(2π) = " + num(f.uv.x, 6) + ", v = 1 − θ/π = " + num(f.uv.y, 6) + "." +
            (f.singular ? " P is a pole: every u names it (u is undefined there)." : "");
        info.math =
            "u = \\frac{1}{2} + \\frac{\\operatorname{atan2}(y, x)}{2\\pi} = " + tex(f.uv.x) +
            ",\\quad v = 1 - \\frac{\\arccos(z/r)}{\\pi} = " + tex(f.uv.y);
        return;
    }
    info.event = "axial-uv";
    const bool cut = std::isfinite(sf.quadric.zmin) && std::isfinite(sf.quadric.zmax);
    info.narration = "Angle around the axis φ = atan2(y, x) = " + num(phi_deg, 5) + "°" + model +
                     ": u = ½ + φ/(2π) = " + num(f.uv.x, 6) + "; height " +
                     (cut ? "v = (z − zmin)/(zmax − zmin) = " : "v = z = ") + num(f.uv.y, 6) + "." +
                     (f.singular ? " P is the apex: every u names it." : "");
    info.math =
        "u = \\frac{1}{2} + \\frac{\\operatorname{atan2}(y, x)}{2\\pi} = " + tex(f.uv.x) +
        (cut ? ",\\quad v = \\frac{z - z_{min}}{z_{max} - z_{min}} = " : ",\\quad v = z = ") +
        tex(f.uv.y);
}

}  // namespace

void TextureMap::narrate(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Texture& t = in.texture;
    const TextureLookup& l = s.r.lookup;
    info.math.clear();
    const std::string size = std::to_string(t.image.width) + "×" + std::to_string(t.image.height);
    switch (s.last) {
        case Phase::Map:
            narrate_map(s, info);
            break;
        case Phase::Wrap:
            info.event = "wrap";
            info.line = kLineWrap;
            info.narration =
                std::string(t.wrap == TexWrap::Repeat ? "Repeat: the fractional parts, "
                                                      : "Clamp to [0, 1]: ") +
                "(s, t) = " + num(l.st, 6) + " on the " + size + " " + t.source + ".";
            info.math = "(s, t) = " + tex(l.st);
            break;
        case Phase::MipLevel: {
            const int k = static_cast<int>(s.levels.size());
            const TextureImage& im = level(s, k);
            info.event = "mip-level";
            info.line = kLineMipLevel;
            info.narration =
                "Level " + std::to_string(k) + ": " + std::to_string(im.width) + "×" +
                std::to_string(im.height) + ", each texel the average of " +
                (level(s, k - 1).width > 1 && level(s, k - 1).height > 1 ? "2 × 2" : "2") +
                " texels of level " + std::to_string(k - 1) +
                " (texel (0, 0) = " + num(im.at(0, 0), 4) + ").";
            info.math =
                "T_k(i, j) = \\tfrac{1}{4} \\sum_{a, b \\in \\{0, 1\\}} T_{k-1}(2i + a, 2j + b)";
            break;
        }
        case Phase::LevelOfDetail: {
            info.event = "level-of-detail";
            info.line = kLineLod;
            const double rho = in.footprint * std::max(t.image.width, t.image.height);
            info.narration =
                "The footprint " + num(in.footprint, 4) + " covers ρ = " + num(rho, 4) +
                " texels: λ = " + (rho > 1 ? "log₂ ρ" : "0 (magnified)") + " = " +
                num(l.lambda, 4) + ", between levels " + std::to_string(l.level0) + " and " +
                std::to_string(l.level1) + " (share " + num(l.blend, 4) + " of the coarser).";
            info.math = "\\lambda = \\log_2(" + tex(rho, 4) + ") = " + tex(l.lambda, 4);
            break;
        }
        case Phase::Sample:
        case Phase::SampleCoarse: {
            const bool coarse = s.last == Phase::SampleCoarse;
            const TexelTaps& tp = coarse ? l.coarse : l.taps;
            if (t.filter == TexFilter::Nearest) {
                info.event = "nearest";
                info.line = kLineNearest;
                info.narration = "Texel (⌊s·" + std::to_string(t.image.width) + "⌋, ⌊t·" +
                                 std::to_string(t.image.height) +
                                 "⌋) = " + texel_text(tp.texel[0]) + ": colour " +
                                 num(tp.color, 4) + ".";
                info.math = "T" + texel_text(tp.texel[0]) + " = " + tex(tp.color, 4);
                break;
            }
            const int k = t.filter == TexFilter::Mipmap ? (coarse ? l.level1 : l.level0) : 0;
            const TextureImage& im = level(s, k);
            info.event = t.filter == TexFilter::Mipmap ? "level-sample" : "bilinear";
            info.line = t.filter == TexFilter::Mipmap ? kLineLevelSample : kLineBilinear;
            info.narration =
                (t.filter == TexFilter::Mipmap ? "Level " + std::to_string(k) + ": " : "") +
                "texels " + texel_text(tp.texel[0]) + ", " + texel_text(tp.texel[1]) + ", " +
                texel_text(tp.texel[2]) + ", " + texel_text(tp.texel[3]) +
                " with f = " + num(tp.f.x, 4) + ", g = " + num(tp.f.y, 4) + ": weights " +
                num(tp.weight[0], 4) + ", " + num(tp.weight[1], 4) + ", " + num(tp.weight[2], 4) +
                ", " + num(tp.weight[3], 4) + " (sum 1); colour " + taps_text(tp, im) + " = " +
                num(tp.color, 4) + ".";
            info.math =
                "c = (1-f)(1-g)\\,T_{00} + f(1-g)\\,T_{10} + (1-f)g\\,T_{01} + fg\\,T_{11} = " +
                tex(tp.color, 4);
            break;
        }
        case Phase::Blend:
        case Phase::Done:
            info.event = "blend";
            info.line = kLineBlend;
            info.narration = "Blend: (1 − " + num(l.blend, 4) + ")·" + num(l.taps.color, 4) +
                             " + " + num(l.blend, 4) + "·" + num(l.coarse.color, 4) + " = " +
                             num(l.color, 4) + ".";
            info.math = "c = (1 - " + tex(l.blend, 4) + ")\\,c_0 + " + tex(l.blend, 4) +
                        "\\,c_1 = " + tex(l.color, 4);
            break;
    }
    info.vars = {{"P", vec(in.point)}, {"uv", vec(s.r.frame.uv)}};
    if (s.last >= Phase::Wrap) info.vars.push_back({"st", vec(l.st)});
    if (s.last >= Phase::LevelOfDetail && t.filter == TexFilter::Mipmap) {
        info.vars.push_back({"lambda", l.lambda});
        info.vars.push_back({"levels", std::vector<double>{double(l.level0), double(l.level1)}});
    }
    if (s.last >= Phase::Sample) {
        info.vars.push_back(
            {"texel", std::vector<double>{double(l.taps.texel[0].x), double(l.taps.texel[0].y)}});
        info.vars.push_back({"weights", std::vector<double>(l.taps.weight.begin(),
                                                            l.taps.weight.begin() + l.taps.count)});
    }
    if (s.phase == Phase::Done) info.vars.push_back({"color", vec(l.color)});
}

}  // namespace cg
