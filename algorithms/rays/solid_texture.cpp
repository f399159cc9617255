// Sections: [spec] [validate] [advance] [narrate]; the picture is in solid_texture_draw.cpp.
#include "rays/solid_texture.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

using glm::dvec3;
using Phase = SolidTextureAlgo::Phase;

namespace {
enum Line {
    kLinePoint = 1,
    kLineLattice,
    kLineGradients,
    kLineFade,
    kLineInterpolate,
    kLineTurbulence,
    kLineColour
};

bool noisy(const SolidTexture& t) {
    return uses_noise(t.kind);
}

std::string corner_name(int k) {
    return std::string("g") + char('0' + (k >> 2)) + char('0' + ((k >> 1) & 1)) +
           char('0' + (k & 1));
}
}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& SolidTextureAlgo::spec() {
    static const Spec spec{
        "solid-texture",
        "Solid textures and Perlin noise",
        "Ray Tracing",
        {
            "for each point p: colour ← mix(c₀, c₁, t(p))    ▷ checker, stripes, wood, marble",
            "noise(q), q = f p:  cell (X, Y, Z) ← ⌊q⌋;  (x, y, z) ← q − ⌊q⌋",
            "    each corner c: gradient g_c ← G[π[π[π[X] + Y] + Z] mod 12];  ramp g_c · (q − c)",
            "    fade: u, v, w ← 6t⁵ − 15t⁴ + 10t³ of x, y, z",
            "    lerp the 8 ramps by w (z), then v (y), then u (x): noise(q)",
            "    marble: turbulence = Σ_k |noise(2^k q)| / 2^k",
            "    t ← the texture's formula;  colour ← (1 − t) c₀ + t c₁",
        },
        {
            {"point", "a point's colour from the texture's formula"},
            {"lattice",
             "the integer lattice cell holding the noise point, and the point's place in it"},
            {"gradients",
             "the pseudo-random gradients at the cell's 8 corners, and their ramps at the point"},
            {"fade", "the fade curve's weights for the three fractions"},
            {"interpolate", "the 8 ramps blended along z, then y, then x: the noise value"},
            {"turbulence",
             "the octaves of |noise| summed at doubling frequencies and halving weights"},
            {"colour", "the worked point's colour from its noise"},
        },
        {},  // no sliders
        {
            .predict =
                {
                    {"lattice", {"cell"}},
                    {"fade", {"fade"}},
                    {"interpolate", {"noise"}},
                    {"colour", {"colour"}},
                },
            .mistakes =
                {
                    {"lattice", "q", "copy:p", "forgot to scale p by the frequency"},
                    {"turbulence", "", "event:colour",
                     "skipped the turbulence sum and used plain noise"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void SolidTextureAlgo::validate(const Input& in) {
    validate_solid(in.texture, "texture");
    if (in.points.empty()) throw InputError("points", "must list at least one point");
    if (in.points.size() > kMaxPoints)
        throw InputError("points", "has " + std::to_string(in.points.size()) +
                                       " points; the limit is " + std::to_string(kMaxPoints));
    const SolidTexture& t = in.texture;
    // Where ⌊q⌋ and q − ⌊q⌋ stay exact enough: |q| ≤ 1e9 for the noise, |p/s| ≤ 1e15 for cubes.
    const double scale = noisy(t) ? t.frequency * std::ldexp(1.0, t.octaves - 1)
                         : t.kind == SolidKind::Checker ? 1 / t.size
                                                        : 1 / t.period;
    const double limit = noisy(t) ? kMaxNoiseCoordinate : 1e15;
    for (std::size_t i = 0; i < in.points.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = in.points[i][c];
            const std::string f = "points[" + std::to_string(i) + "][" + std::to_string(c) + "]";
            if (!std::isfinite(x)) throw InputError(f, "must be a finite number");
            if (!(std::fabs(x * scale) <= limit))
                throw InputError(f, "is too large for the texture's lattice (" + given(x) + " × " +
                                        given(scale) + " exceeds " + given(limit) + ")");
        }
    if (in.detail < 0 || in.detail >= static_cast<int>(in.points.size()))
        throw InputError("detail", "must be the index of a point, 0 to " +
                                       std::to_string(in.points.size() - 1) + " (got " +
                                       std::to_string(in.detail) + ")");
}

SolidTextureAlgo::State SolidTextureAlgo::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    if (noisy(in.texture)) s.perlin = make_perlin(in.texture.seed);
    s.r.noisy = noisy(in.texture);
    s.r.samples.reserve(in.points.size());
    return s;
}

SolidTextureAlgo::Result SolidTextureAlgo::solve(const Input& in) {
    Result r;
    const Perlin perlin = noisy(in.texture) ? make_perlin(in.texture.seed) : Perlin{};
    r.noisy = noisy(in.texture);
    r.samples.reserve(in.points.size());
    for (const dvec3& p : in.points) r.samples.push_back(solid_sample(in.texture, perlin, p));
    return r;
}

// ---- [advance] ------------------------------------------------------------------------------

void SolidTextureAlgo::advance(State& s) {
    const Input& in = *s.in;
    const SolidTexture& t = in.texture;
    s.last = s.phase;
    auto finish_point = [&] {
        // A copied state's list has lost its capacity: room for every point, once.
        if (s.r.samples.capacity() < in.points.size()) s.r.samples.reserve(in.points.size());
        s.r.samples.push_back(solid_sample(t, s.perlin, in.points[s.next]));
        ++s.next;
        s.phase = s.next < in.points.size() ? Phase::Point : Phase::Done;
    };
    switch (s.phase) {
        case Phase::Point:
            if (noisy(t) && static_cast<int>(s.next) == in.detail) {  // work this one's noise
                s.last = Phase::Lattice;
                s.r.detail = perlin_detail(s.perlin, noise_point(t, in.points[s.next]));
                s.r.has_detail = true;
                s.phase = Phase::Gradients;
                return;
            }
            finish_point();
            return;
        case Phase::Gradients:
            s.phase = Phase::Fade;
            return;
        case Phase::Fade:
            s.phase = Phase::Interpolate;
            return;
        case Phase::Interpolate:
            s.phase = t.kind == SolidKind::Marble ? Phase::Turbulence : Phase::Colour;
            return;
        case Phase::Turbulence: {
            const dvec3 q = noise_point(t, in.points[s.next]);
            for (int k = 0; k < t.octaves; ++k)  // turbulence()'s own terms
                s.r.octaves.push_back(std::fabs(perlin_noise(s.perlin, std::ldexp(1.0, k) * q)) /
                                      std::ldexp(1.0, k));
            s.phase = Phase::Colour;
            return;
        }
        case Phase::Colour:
            finish_point();
            return;
        case Phase::Lattice:
        case Phase::Done:
            return;
    }
}

void SolidTextureAlgo::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string formula_text(const SolidTexture& t) {
    switch (t.kind) {
        case SolidKind::Checker:
            return "checker: c₀ where ⌊x/s⌋ + ⌊y/s⌋ + ⌊z/s⌋ is even (s = " + num(t.size) + ")";
        case SolidKind::Stripes:
            return "stripes: t = ½(1 + sin(2π p·â/" + num(t.period) + "))";
        case SolidKind::Wood:
            return "wood: t = frac(r/" + num(t.period) + " + " + num(t.amplitude) + "·noise(" +
                   num(t.frequency) + " p)), r the distance from the axis";
        case SolidKind::Marble:
            return "marble: t = ½(1 + sin(2π p·â/" + num(t.period) + " + " + num(t.amplitude) +
                   "·turbulence(" + num(t.frequency) + " p)))";
    }
    return "";
}

}  // namespace

void SolidTextureAlgo::narrate(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const SolidTexture& t = in.texture;
    const NoiseDetail& d = s.r.detail;
    info.math.clear();
    const std::size_t i = s.last == Phase::Point || s.last == Phase::Colour ? s.next - 1 : s.next;
    const dvec3 p = in.points[i];
    const auto& G = perlin_gradients();
    switch (s.last) {
        case Phase::Point:
        case Phase::Colour: {
            const SolidSample& ss = s.r.samples[i];
            info.event = s.last == Phase::Point ? "point" : "colour";
            info.line = s.last == Phase::Point ? kLinePoint : kLineColour;
            info.narration = "Point " + std::to_string(i) + " " + num(p, 4) + ", " +
                             formula_text(t) + (noisy(t) ? ": noise " + num(ss.noise, 5) : "") +
                             ": t = " + num(ss.t, 5) + ", colour " + num(ss.color, 4) + ".";
            info.math = "(1 - " + tex(ss.t, 4) + ")\\,c_0 + " + tex(ss.t, 4) +
                        "\\,c_1 = " + tex(ss.color, 4);
            break;
        }
        case Phase::Lattice:
            info.event = "lattice";
            info.line = kLineLattice;
            info.narration = "Point " + std::to_string(i) + ": q = f p = " + num(d.p, 5) +
                             " lies in the lattice cell (" + std::to_string(d.cell[0]) + ", " +
                             std::to_string(d.cell[1]) + ", " + std::to_string(d.cell[2]) +
                             "), at (x, y, z) = " + num(d.frac, 5) + " inside it.";
            info.math = "\\lfloor q \\rfloor = (" + std::to_string(d.cell[0]) + ", " +
                        std::to_string(d.cell[1]) + ", " + std::to_string(d.cell[2]) +
                        "),\\quad q - \\lfloor q \\rfloor = " + tex(d.frac, 5);
            break;
        case Phase::Gradients: {
            info.event = "gradients";
            info.line = kLineGradients;
            std::string list;
            for (int k = 0; k < 8; ++k)
                list += (k ? "; " : "") + corner_name(k) + " = " + num(G[d.gradient[k]], 1) +
                        " → " + num(d.dot[k], 4);
            info.narration = "Corner gradients and ramps g·(q − c): " + list + ".";
            info.math = "g_{000} \\cdot (x, y, z) = " + tex(d.dot[0], 4);
            break;
        }
        case Phase::Fade:
            info.event = "fade";
            info.line = kLineFade;
            info.narration = "Fade weights f(t) = 6t⁵ − 15t⁴ + 10t³: u = f(" + num(d.frac.x, 4) +
                             ") = " + num(d.fade.x, 5) + ", v = f(" + num(d.frac.y, 4) +
                             ") = " + num(d.fade.y, 5) + ", w = f(" + num(d.frac.z, 4) +
                             ") = " + num(d.fade.z, 5) +
                             " (f' and f'' vanish at 0 and 1: no creases at the cell's faces).";
            info.math = "f(t) = 6t^5 - 15t^4 + 10t^3:\\; (u, v, w) = " + tex(d.fade, 5);
            break;
        case Phase::Interpolate:
            info.event = "interpolate";
            info.line = kLineInterpolate;
            info.narration = "Along z by w: " + num(d.along_z[0], 4) + ", " + num(d.along_z[1], 4) +
                             ", " + num(d.along_z[2], 4) + ", " + num(d.along_z[3], 4) +
                             "; along y by v: " + num(d.along_y[0], 4) + ", " +
                             num(d.along_y[1], 4) + "; along x by u: noise = " + num(d.value, 6) +
                             ".";
            info.math = "\\mathrm{noise}(q) = \\mathrm{lerp}(" + tex(d.along_y[0], 4) + ", " +
                        tex(d.along_y[1], 4) + ", " + tex(d.fade.x, 4) + ") = " + tex(d.value, 6);
            break;
        case Phase::Turbulence: {
            info.event = "turbulence";
            info.line = kLineTurbulence;
            std::string list;
            double sum = 0;
            for (std::size_t k = 0; k < s.r.octaves.size(); ++k) {
                list += (k ? " + " : "") + num(s.r.octaves[k], 4);
                sum += s.r.octaves[k];
            }
            info.narration = "Turbulence over " + std::to_string(t.octaves) + " octaves: " + list +
                             " = " + num(sum, 5) + ".";
            info.math = "\\sum_k \\frac{|\\mathrm{noise}(2^k q)|}{2^k} = " + tex(sum, 5);
            break;
        }
        case Phase::Done:
            break;
    }
    info.vars = {{"point", static_cast<long long>(i)}, {"p", vec(p)}};
    if (s.r.has_detail && i == static_cast<std::size_t>(in.detail)) {
        info.vars.push_back({"q", vec(d.p)});
        info.vars.push_back(
            {"cell", std::vector<double>{double(d.cell[0]), double(d.cell[1]), double(d.cell[2])}});
        if (s.last >= Phase::Fade || s.last == Phase::Colour)
            info.vars.push_back({"fade", vec(d.fade)});
        if (s.last >= Phase::Interpolate || s.last == Phase::Colour)
            info.vars.push_back({"noise", d.value});
    }
    if (s.last == Phase::Point || s.last == Phase::Colour)
        info.vars.push_back({"colour", vec(s.r.samples[i].color)});
}

}  // namespace cg
