// Sections: [spec] [validate] [advance] [narrate] [plain]; the picture is in toon_shading_draw.cpp
#include "npr/toon_shading.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

enum Line { kLineLoop = 1, kLineNormal, kLineDot, kLineClamp, kLineBand, kLineColour, kLineDone };

std::string cell(int b, const std::vector<double>& t) {
    const std::string lo = b == 0 ? "0" : num(t[static_cast<std::size_t>(b - 1)], 4);
    const std::size_t n = t.size();
    return static_cast<std::size_t>(b) == n ? "[" + lo + ", 1]"
                                            : "[" + lo + ", " + num(t[static_cast<std::size_t>(b)], 4) + ")";
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ToonShading::spec() {
    static const Spec spec{
        "toon-shading",
        "Toon shading",
        "Non-Photorealistic Rendering",
        {
            "for each face F_k (counter-clockwise seen from outside):",
            "    N̂ ← Newell's normal, normalised            ▷ flat: one normal a face",
            "    N̂·L̂                                         ▷ L̂ towards the light",
            "    d ← max(0, N̂·L̂)                             ▷ the diffuse attenuation",
            "    b ← #{ i : t_i ≤ d }                         ▷ = the 1D texture's cell at u = d",
            "    colour F_k with colour[b]                    ▷ a tie d = t_i goes up",
            "done: every face flat in one of n colours",
        },
        {
            {"lit", "N̂·L̂ > 0: the face's diffuse term d falls in one of the bands"},
            {"on-threshold", "d equals a threshold exactly: the tie goes to the brighter band"},
            {"unlit", "N̂·L̂ ≤ 0: the face is turned from the light, d = 0, the darkest band"},
            {"done", "every face has its band and colour"},
        },
        {},  // no sliders
        {
            .predict = {{"lit", {"d", "band"}}, {"unlit", {"band"}}},
            .mistakes = {
                {"lit", "band", "off-by-one", "counted the band from 1, or the tie the wrong way"},
                {"lit", "N̂·L̂", "negate", "took L from the light to the surface"},
                {"unlit", "", "event:lit", "used N·L without clamping at 0 for a face turned away"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

std::vector<glm::dvec3> ToonShading::default_colours(int n) {
    std::vector<glm::dvec3> c;
    for (int b = 0; b < n; ++b) {
        const double s = 0.3 + 0.7 * b / (n - 1);  // brightness of band b
        c.push_back(glm::dvec3{0.98, 0.62, 0.28} * s);
    }
    return c;
}

void ToonShading::validate(const Input& in) {
    npr::validate(in.mesh);
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(in.light[c]) || std::fabs(in.light[c]) > 1e100)
            throw InputError("light[" + std::to_string(c) + "]", "must be a finite number within ±1e100");
    const double q = glm::dot(in.light, in.light);
    if (!(q > 1e-200))
        throw InputError("light", "is the zero vector (or nearly): the light's direction needs a length");
    const std::size_t n = in.thresholds.size() + 1;
    if (n < kMinBands || n > kMaxBands)
        throw InputError("thresholds", "needs 1 to 7 thresholds (2 to 8 bands), got " +
                                           std::to_string(in.thresholds.size()));
    for (std::size_t i = 0; i < in.thresholds.size(); ++i) {
        const double t = in.thresholds[i];
        const std::string at = "thresholds[" + std::to_string(i) + "]";
        if (!(t > 0 && t < 1)) throw InputError(at, "must lie strictly between 0 and 1 (got " + given(t) + ")");
        if (i > 0 && !(t > in.thresholds[i - 1]))
            throw InputError(at, "must be greater than the threshold before it (" +
                                     given(in.thresholds[i - 1]) + "), got " + given(t));
    }
    if (!in.colours.empty() && in.colours.size() != n)
        throw InputError("colours", "needs one colour per band: " + std::to_string(n) + ", got " +
                                        std::to_string(in.colours.size()));
    for (std::size_t b = 0; b < in.colours.size(); ++b)
        for (int c = 0; c < 3; ++c)
            if (!(in.colours[b][c] >= 0 && in.colours[b][c] <= 1))
                throw InputError("colours[" + std::to_string(b) + "][" + std::to_string(c) + "]",
                                 "must be between 0 and 1 (got " + given(in.colours[b][c]) + ")");
}

ToonShading::State ToonShading::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

ToonShading::State ToonShading::begin(Shared<Input> in) {
    State s;
    s.l = unit(in->light);
    const std::size_t faces = in->mesh.faces.size();
    s.r.ndotl.reserve(faces);
    s.r.band.reserve(faces);
    s.r.counts.assign(in->thresholds.size() + 1, 0);
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void ToonShading::advance(State& s) {
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Face: {  // Normal, N̂·L̂, clamp, band
            const auto& in = *s.in;
            s.n = unit(npr::newell(in.mesh.vertices, in.mesh.faces[static_cast<std::size_t>(s.k)]));
            s.ndotl = glm::dot(s.n, s.l);
            s.band = band_of(std::max(0.0, s.ndotl), in.thresholds);
            s.r.ndotl.push_back(s.ndotl);
            s.r.band.push_back(s.band);
            ++s.r.counts[static_cast<std::size_t>(s.band)];
            if (++s.k == static_cast<int>(in.mesh.faces.size())) s.phase = Phase::Finish;
            return;
        }
        case Phase::Finish:
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

void ToonShading::narrate(const State& s, StepInfo& info) {
    info = {};
    const auto& t = s.in->thresholds;
    if (s.last == Phase::Face) {
        const int k = s.k - 1;
        const double d = std::max(0.0, s.ndotl);
        const std::string head = "F" + std::to_string(k) + ": N̂ = " + num(s.n, 4) +
                                 ", N̂·L̂ = " + num(s.ndotl, 4);
        bool tie = false;
        for (double x : t) tie = tie || d == x;
        if (s.ndotl <= 0) {
            info.event = "unlit";
            info.line = kLineClamp;
            info.narration = head + " ≤ 0: the face is turned from the light, d = 0, band 0 (the darkest).";
        } else if (tie) {
            info.event = "on-threshold";
            info.line = kLineBand;
            info.narration = head + " = d lies exactly on a threshold; the tie goes up: band " +
                             std::to_string(s.band) + ", texture cell " + cell(s.band, t) + ".";
        } else {
            info.event = "lit";
            info.line = kLineColour;
            info.narration = head + ", so d = " + num(d, 4) + " falls in texture cell " +
                             cell(s.band, t) + ": band " + std::to_string(s.band) + ".";
        }
        info.math = "d = \\max(0, " + tex(s.ndotl, 4) + ") = " + tex(d, 4) + ",\\quad b = " +
                    std::to_string(s.band);
        info.vars.push_back({"k", static_cast<long long>(k)});
        info.vars.push_back({"N̂", vec(s.n)});
        info.vars.push_back({"L̂", vec(s.l)});
        info.vars.push_back({"N̂·L̂", s.ndotl});
        info.vars.push_back({"d", d});
        info.vars.push_back({"band", static_cast<long long>(s.band)});
    } else {
        info.event = "done";
        info.line = kLineDone;
        std::string counts;
        for (std::size_t b = 0; b < s.r.counts.size(); ++b)
            counts += (b ? ", " : "") + std::to_string(s.r.counts[b]);
        info.narration = "All " + std::to_string(s.r.band.size()) +
                         " faces shaded; faces per band, darkest first: " + counts + ".";
        info.math = "\\text{faces per band} = (" + counts + ")";
        std::vector<double> c(s.r.counts.begin(), s.r.counts.end());
        info.vars.push_back({"counts", c});
    }
}

void ToonShading::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [plain] --------------------------------------------------------------------------------

[[gnu::flatten]] ToonShading::Result ToonShading::compute(const Input& in) {
    const glm::dvec3 l = unit(in.light);
    Result r;
    r.ndotl.reserve(in.mesh.faces.size());
    r.band.reserve(in.mesh.faces.size());
    r.counts.assign(in.thresholds.size() + 1, 0);
    for (const auto& f : in.mesh.faces) {
        const double nl = glm::dot(unit(npr::newell(in.mesh.vertices, f)), l);
        const int b = band_of(std::max(0.0, nl), in.thresholds);
        r.ndotl.push_back(nl);
        r.band.push_back(b);
        ++r.counts[static_cast<std::size_t>(b)];
    }
    return r;
}

}  // namespace cg
