// Sections: [spec] [validate] [advance] [narrate] [plain] [draw]
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

// ---- [draw] ---------------------------------------------------------------------------------

void ToonShading::draw(const State& s, Scene& scene) {
    // Shaded faces filled in their band's colour; faces still to come faint; the current face
    // outlined in orange with N̂ and L̂ drawn from its centre; the light's direction from the
    // mesh; and, as a legend, the 1D texture: n cells along a strip under the mesh.
    const auto& in = *s.in;
    const auto& m = in.mesh;
    const std::vector<glm::dvec3> colours =
        in.colours.empty() ? default_colours(static_cast<int>(in.thresholds.size()) + 1) : in.colours;
    const auto [mid, size] = npr::bounds(m);
    const int shaded = static_cast<int>(s.r.band.size());
    const int current = s.last == Phase::Face && s.k > 0 && s.phase != Phase::Done ? s.k - 1 : -1;
    const bool small = m.faces.size() <= 24;
    auto centroid = [&](const std::vector<int>& f) {
        glm::dvec3 c{0, 0, 0};
        for (int i : f) c += m.vertices[static_cast<std::size_t>(i)];
        return c / static_cast<double>(f.size());
    };
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        Face3 face;
        for (int i : m.faces[k]) face.points.push_back(m.vertices[static_cast<std::size_t>(i)]);
        face.two_sided = false;
        if (static_cast<int>(k) < shaded) {
            const int b = s.r.band[k];
            face.style = {Role::Subject, 1.0f, false, pack_rgba(colours[static_cast<std::size_t>(b)])};
            face.alpha = 1.0f;
            face.outline = small;
        } else {
            face.style = {Role::Neutral, 1.0f};
            face.alpha = 0.08f;
        }
        if (static_cast<int>(k) == current) face.style.width = 3.0f, face.outline = true;
        scene.faces3.push_back(std::move(face));
        if (small && static_cast<int>(k) < shaded)
            scene.labels3.push_back({centroid(m.faces[k]) , std::to_string(s.r.band[k]), {Role::Neutral}});
    }
    if (current >= 0) {
        const glm::dvec3 c = centroid(m.faces[static_cast<std::size_t>(current)]);
        scene.segments3.push_back({c, c + 0.3 * size * s.n, "N", {Role::Active, 3.0f}, true});
        scene.segments3.push_back({c, c + 0.3 * size * s.l, "L", {Role::Window, 2.5f}, true});
        // Outline the current face on top.
        Face3 f;
        for (int i : m.faces[static_cast<std::size_t>(current)])
            f.points.push_back(m.vertices[static_cast<std::size_t>(i)]);
        f.style = {Role::Active, 3.0f};
        f.alpha = 0.0f;
        scene.faces3.push_back(std::move(f));
    }
    // The light: an arrow pointing along L̂ towards the light, outside the mesh.
    const glm::dvec3 l = s.l;
    scene.segments3.push_back({mid + 0.6 * size * l, mid + 0.95 * size * l, "towards the light",
                               {Role::Window, 2.5f}, true});
    // The 1D texture: cell b spans [t_b, t_{b+1}) of a strip below the mesh, u running along x.
    const double y = mid.y - 0.75 * size, x0 = mid.x - 0.5 * size, w = size, h = 0.07 * size;
    const auto& t = in.thresholds;
    for (std::size_t b = 0; b <= t.size(); ++b) {
        const double u0 = b == 0 ? 0 : t[b - 1], u1 = b == t.size() ? 1 : t[b];
        Face3 cellf;
        cellf.points = {{x0 + u0 * w, y, mid.z}, {x0 + u1 * w, y, mid.z},
                        {x0 + u1 * w, y + h, mid.z}, {x0 + u0 * w, y + h, mid.z}};
        cellf.style = {Role::Subject, 1.0f, false, pack_rgba(colours[b])};
        cellf.alpha = 1.0f;
        scene.faces3.push_back(std::move(cellf));
        if (b > 0)
            scene.labels3.push_back({{x0 + u0 * w, y - 0.6 * h, mid.z}, num(u0, 3), {Role::Neutral}});
    }
    scene.labels3.push_back({{x0 - 0.05 * w, y + 0.5 * h, mid.z}, "u = 0", {Role::Neutral}});
    scene.labels3.push_back({{x0 + 1.05 * w, y + 0.5 * h, mid.z}, "1", {Role::Neutral}});
    if (current >= 0) {
        const double d = std::max(0.0, s.ndotl);
        scene.segments3.push_back({{x0 + d * w, y + 2.2 * h, mid.z}, {x0 + d * w, y + h, mid.z},
                                   "u = d = " + num(d, 3), {Role::Active, 2.5f}, true});
    }
}

}  // namespace cg
