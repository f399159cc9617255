// Sections: [spec] [validate] [advance] [narrate]; the picture is in bump_map_draw.cpp.
#include "rays/bump_map.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

using glm::dvec3;
using Phase = BumpMap::Phase;

namespace {
enum Line { kLineFrame = 1, kLineHeight, kLineDifferences, kLineNormal, kLinePerturb, kLineUnit };

double tilt_of(const BumpResult& b) {
    return std::acos(std::clamp(glm::dot(b.normal, b.perturbed), -1.0, 1.0)) * 180 /
           3.14159265358979323846;
}
}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& BumpMap::spec() {
    static const Spec spec{
        "bump-map",
        "Bump mapping: Blinn's perturbed normal",
        "Ray Tracing",
        {
            "(u, v), P_u = ∂P/∂u, P_v = ∂P/∂v at P",
            "B ← B(u, v);  B(u ± h, v), B(u, v ± h)",
            "B_u ← (B(u + h, v) − B(u − h, v)) / 2h;  B_v likewise",
            "n ← P_u × P_v (outward)",
            "D ← (B_u (n × P_v) − B_v (n × P_u)) / |n|;  n' ← n + D",
            "n' ← n' / |n'|    ▷ used for the lighting; the geometry does not move",
        },
        {
            {"partials", "the point's (u, v) and the surface's partial derivatives there"},
            {"height", "the height function at (u, v) and at its four neighbours ±h"},
            {"differences", "B_u and B_v by central differences"},
            {"normal", "n = P_u × P_v, and Blinn's perturbation D"},
            {"singular", "P_u × P_v = 0 (a pole, an apex): there is no normal to perturb"},
            {"perturbed", "the perturbed normal, normalised: what the lighting uses"},
        },
        {},  // no sliders
        {
            .predict =
                {
                    {"height", {"B"}},
                    {"differences", {"B_u", "B_v"}},
                    {"normal", {"D"}},
                    {"perturbed", {"n'"}},
                },
            .mistakes =
                {
                    {"normal", "D", "negate", "added the height gradient where it is subtracted"},
                    {"partials", "P_u", "swap:P_v", "mixed up P_u and P_v"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void BumpMap::validate(const Input& in) {
    validate_uv_surface(in.surface, "surface");
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(in.point[i]) || std::fabs(in.point[i]) > 1e12)
            throw InputError("point[" + std::to_string(i) + "]",
                             "must be a finite number of magnitude at most 1e12 (got " +
                                 given(in.point[i]) + ")");
    validate_height(in.height, "height");
    if (in.has_light) {
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(in.light[i]) || std::fabs(in.light[i]) > 1e12)
                throw InputError("light[" + std::to_string(i) + "]",
                                 "must be a finite number of magnitude at most 1e12");
        if (unit(in.light) == dvec3(0.0))
            throw InputError("light",
                             "must not be the zero vector: it is the direction toward "
                             "the light");
    }
    check_on_surface(in.surface, prepare_uv(in.surface), in.point, "point");
}

BumpMap::State BumpMap::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.prepared = prepare_uv(in.surface);
    if (in.height.kind == HeightKind::Noise) s.perlin = make_perlin(in.height.seed);
    s.outward = outward_normal(s.prepared, in.point);
    return s;
}

BumpMap::Result BumpMap::solve(const Input& in) {
    Result r;
    const PreparedUv p = prepare_uv(in.surface);
    const Perlin perlin =
        in.height.kind == HeightKind::Noise ? make_perlin(in.height.seed) : Perlin{};
    r.frame = uv_frame(p, in.point);
    r.bump = blinn_bump(r.frame, outward_normal(p, in.point), in.height, perlin);
    r.tilt_deg = tilt_of(r.bump);
    return r;
}

// ---- [advance] ------------------------------------------------------------------------------

void BumpMap::advance(State& s) {
    const Input& in = *s.in;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Frame:  // The parametrisation and its partials
            s.r.frame = uv_frame(s.prepared, in.point);
            s.phase = Phase::Height;
            return;
        case Phase::Height:  // The heights (and, with them, the differences: bump_heights)
            bump_heights(in.height, s.perlin, s.r.frame.uv, s.r.bump);
            s.phase = Phase::Differences;
            return;
        case Phase::Differences:  // B_u, B_v (computed with the heights; shown here)
            s.phase = Phase::Normal;
            return;
        case Phase::Normal:  // n and D
            bump_normal(s.r.frame, s.outward, s.r.bump);
            s.phase = s.r.bump.singular ? Phase::Done : Phase::Normalise;
            s.r.tilt_deg = tilt_of(s.r.bump);
            return;
        case Phase::Normalise:  // n' (computed with D; shown here)
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void BumpMap::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

void BumpMap::narrate(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const UvFrame& f = s.r.frame;
    const BumpResult& b = s.r.bump;
    const HeightField& h = in.height;
    info.math.clear();
    switch (s.last) {
        case Phase::Frame:
            info.event = "partials";
            info.line = kLineFrame;
            info.narration = "At P = " + num(in.point, 4) + ": (u, v) = " + num(f.uv, 6) +
                             ", P_u = " + num(f.P_u, 5) + ", P_v = " + num(f.P_v, 5) + ".";
            info.math = "P_u = " + tex(f.P_u, 5) + ",\\quad P_v = " + tex(f.P_v, 5);
            break;
        case Phase::Height: {
            info.event = "height";
            info.line = kLineHeight;
            std::string formula;
            switch (h.kind) {
                case HeightKind::Sines:
                    formula = "B = " + num(h.amplitude) + "·sin(2π·" + num(h.frequency.x) +
                              "u)·sin(2π·" + num(h.frequency.y) + "v)";
                    break;
                case HeightKind::Noise:
                    formula = "B = " + num(h.amplitude) + "·noise(" + num(h.frequency.x) + "u, " +
                              num(h.frequency.y) + "v, 0)";
                    break;
                case HeightKind::Image:
                    formula = "B = " + num(h.amplitude) + "·grey(bilinear lookup in the " +
                              std::to_string(h.image.image.width) + "×" +
                              std::to_string(h.image.image.height) + " height image)";
                    break;
            }
            info.narration = formula + ": B(u, v) = " + num(b.B, 6) + "; with h = " + num(h.step) +
                             ", B(u ± h, v) = " + num(b.samples[0], 6) + ", " +
                             num(b.samples[1], 6) + " and B(u, v ± h) = " + num(b.samples[2], 6) +
                             ", " + num(b.samples[3], 6) + ".";
            info.math = "B(u, v) = " + tex(b.B, 6);
            break;
        }
        case Phase::Differences:
            info.event = "differences";
            info.line = kLineDifferences;
            info.narration =
                "B_u = (" + num(b.samples[0], 6) + " − " + num(b.samples[1], 6) + ")/(2·" +
                num(h.step) + ") = " + num(b.B_u, 6) + ", B_v = (" + num(b.samples[2], 6) + " − " +
                num(b.samples[3], 6) + ")/(2·" + num(h.step) + ") = " + num(b.B_v, 6) +
                (b.B_u == 0 && b.B_v == 0 ? ": the surface is flat here, n stays." : ".");
            info.math = "B_u = \\frac{B(u+h, v) - B(u-h, v)}{2h} = " + tex(b.B_u, 6) +
                        ",\\quad B_v = " + tex(b.B_v, 6);
            break;
        case Phase::Normal:
            if (b.singular) {
                info.event = "singular";
                info.line = kLineNormal;
                info.narration = "P_u × P_v = " + num(b.n, 4) +
                                 ": the parametrisation is singular at P (a pole or an apex), "
                                 "there is no frame to tilt; the normal stays " +
                                 num(b.perturbed, 4) + ".";
                info.math = "P_u \\times P_v = 0";
                break;
            }
            info.event = "normal";
            info.line = kLinePerturb;
            info.narration =
                "n = P_u × P_v = " + num(b.n, 5) + (b.flipped ? " (turned outward)" : "") +
                ", |n| = " + num(glm::length(b.n), 5) + "; n × P_v = " + num(b.n_cross_pv, 5) +
                ", n × P_u = " + num(b.n_cross_pu, 5) +
                "; D = (B_u (n × P_v) − B_v (n × P_u))/|n| = " + num(b.D, 5) + ".";
            info.math =
                "D = \\frac{B_u (n \\times P_v) - B_v (n \\times P_u)}{|n|} = " + tex(b.D, 5);
            break;
        case Phase::Normalise:
        case Phase::Done:
            info.event = "perturbed";
            info.line = kLineUnit;
            info.narration = "n' = (n + D)/|n + D| = " + num(b.perturbed, 5) + ", tilted " +
                             num(s.r.tilt_deg, 4) + "° from n̂ = " + num(b.normal, 5) +
                             ": the lighting sees a bump, the silhouette does not.";
            info.math = "n' = \\frac{n + D}{|n + D|} = " + tex(b.perturbed, 5);
            break;
    }
    info.vars = {{"P", vec(in.point)}, {"uv", vec(f.uv)}, {"P_u", vec(f.P_u)}, {"P_v", vec(f.P_v)}};
    if (s.last >= Phase::Height) info.vars.push_back({"B", b.B});
    if (s.last >= Phase::Differences) {
        info.vars.push_back({"B_u", b.B_u});
        info.vars.push_back({"B_v", b.B_v});
    }
    if (s.last >= Phase::Normal) {
        info.vars.push_back({"n", vec(b.n)});
        info.vars.push_back({"D", vec(b.D)});
    }
    if (s.phase == Phase::Done) info.vars.push_back({"n'", vec(b.perturbed)});
}

}  // namespace cg
