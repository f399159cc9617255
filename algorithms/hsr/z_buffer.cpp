// Sections: [spec] [advance] [narrate] [result and render]; the picture is in z_buffer_draw.cpp
#include "hsr/z_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/format.hpp"

namespace cg {

namespace {

using hsr::PixelSpan;
using hsr::Plane;

constexpr double kFar = std::numeric_limits<double>::infinity();

enum Line {
    kLineClear = 1,
    kLineLoop,
    kLinePlane,
    kLineScan,
    kLineDepth,
    kLineCompare,
    kLineWrite,
    kLineDone,
};

std::size_t at(const ZBuffer::State& s, int i, int j) {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(s.in.scene.width) + static_cast<std::size_t>(i);
}

long long count_pixels(const std::vector<PixelSpan>& spans) {
    long long n = 0;
    for (const auto& sp : spans) n += sp.i_end - sp.i_first;
    return n;
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ZBuffer::spec() {
    static const Spec spec{
        "z-buffer",
        "Z-buffer hidden-surface removal",
        "Hidden Surface Removal",
        {
            "for every pixel: depth ← ∞,  colour ← background",
            "for each polygon P_k, k = 0, 1, …, n − 1:",
            "    its plane: z(x, y) = −(a·x + b·y + d)/c",
            "    scan-convert P_k: each pixel centre (i + ½, j + ½) it covers (top-left rule):",
            "        z ← z(i + ½, j + ½)",
            "        if z < depth[i, j]:               ▷ equal z: the earlier polygon stays",
            "            depth[i, j] ← z,  colour[i, j] ← colour of P_k",
            "done: every pixel shows its nearest polygon",
        },
        {
            {"clear", "depth buffer to ∞ and colour buffer to background"},
            {"polygon", "one polygon scan-converted: its depth compares, and how many it won"},
            {"polygon-start", "a polygon's plane and the pixels it covers, before its compares"},
            {"pixel-write", "the polygon is nearer at this pixel: depth and colour written"},
            {"pixel-keep", "the buffer already holds something as near or nearer: unchanged"},
            {"done", "every polygon drawn: the colour buffer is the visible image"},
        },
        {},  // no sliders
        {
            .predict = {{"polygon", {"writes"}}, {"pixel-write", {"z"}}, {"pixel-keep", {"z"}}},
            .mistakes = {
                {"polygon", "writes", "copy:compares",
                 "wrote every covered pixel without the depth test"},
                {"pixel-keep", "", "event:pixel-write",
                 "compared with > and let the farther polygon overwrite the nearer"},
                {"pixel-write", "", "event:pixel-keep",
                 "kept the old colour though the new z is nearer"},
                {"pixel-write", "z", "keep", "forgot to step z along the span"},
            },
            .input_kind = "hsr-scene",
            .compare = {"ids"},
            .costs = {"compares", "writes"},
        },
    };
    return spec;
}

void ZBuffer::validate(const Input& in) { hsr::validate(in.scene); }

ZBuffer::State ZBuffer::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void ZBuffer::advance(State& s) {
    s.last = s.phase;
    const auto& scene = s.in.scene;
    const int n = static_cast<int>(scene.polygons.size());
    const bool per_pixel = s.in.granularity == Granularity::Pixel;
    switch (s.phase) {
        case Phase::Clear: {  // Clear both buffers
            const std::size_t size = static_cast<std::size_t>(scene.width * scene.height);
            s.ids.assign(size, -1);
            s.depth.assign(size, kFar);
            s.planes.clear();
            s.planes.reserve(scene.polygons.size());
            for (const auto& p : scene.polygons) s.planes.push_back(hsr::plane_of(p));
            s.k = 0;
            s.phase = n == 0 ? Phase::Finish : (per_pixel ? Phase::Setup : Phase::Polygon);
            return;
        }
        case Phase::Polygon: {  // Scan-convert one polygon, comparing depths
            const auto spans = hsr::polygon_spans(scene.polygons[s.k], scene.width, scene.height);
            const Plane& pl = s.planes[s.k];
            long long pixels = 0, wins = 0;
            for (const PixelSpan& sp : spans) {
                const std::size_t row = at(s, 0, sp.j);
                const double y = sp.j + 0.5;
                for (int i = sp.i_first; i < sp.i_end; ++i) {
                    const double z = hsr::depth_at(pl, i + 0.5, y);
                    ++pixels;
                    if (z < s.depth[row + i]) {
                        s.depth[row + i] = z;
                        s.ids[row + i] = s.k;
                        ++wins;
                    }
                }
            }
            s.step_pixels = pixels, s.step_wins = wins;
            s.compares += pixels, s.writes += wins;
            if (++s.k == n) s.phase = Phase::Finish;
            return;
        }
        case Phase::Setup: {  // The plane and the pixels of the next polygon
            s.spans = hsr::polygon_spans(scene.polygons[s.k], scene.width, scene.height);
            s.step_pixels = count_pixels(s.spans), s.step_wins = 0;
            s.span = 0;
            if (!s.spans.empty()) {
                s.i = s.spans[0].i_first;
                s.phase = Phase::Pixel;
            } else if (s.k + 1 == n) {
                s.phase = Phase::Finish;
            } else {
                ++s.k;  // covers nothing: on to the next polygon's set-up
            }
            return;
        }
        case Phase::Pixel: {  // Compare one pixel's depth
            const PixelSpan& sp = s.spans[s.span];
            s.pi = s.i, s.pj = sp.j;
            const std::size_t a = at(s, s.pi, s.pj);
            s.z = hsr::depth_at(s.planes[s.k], s.pi + 0.5, s.pj + 0.5);
            s.z_old = s.depth[a], s.id_old = s.ids[a];
            s.won = s.z < s.z_old;
            ++s.compares;
            if (s.won) {
                s.depth[a] = s.z, s.ids[a] = s.k;
                ++s.writes, ++s.step_wins;
            }
            if (++s.i >= sp.i_end && ++s.span < s.spans.size()) s.i = s.spans[s.span].i_first;
            if (s.span == s.spans.size()) {
                if (s.k + 1 == n) {
                    s.phase = Phase::Finish;
                } else {
                    ++s.k;
                    s.phase = Phase::Setup;
                }
            }
            return;
        }
        case Phase::Finish:  // Every polygon is drawn
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string plane_text(const Plane& p) {
    // z = −(a x + b y + d)/c as z = α + β x + γ y
    const double alpha = -p.d / p.c, beta = -p.a / p.c, gamma = -p.b / p.c;
    return num(alpha, 4) + (beta < 0 ? " − " : " + ") + num(std::fabs(beta), 4) + "·x" +
           (gamma < 0 ? " − " : " + ") + num(std::fabs(gamma), 4) + "·y";
}

std::string plane_tex(const Plane& p) {
    const double alpha = -p.d / p.c, beta = -p.a / p.c, gamma = -p.b / p.c;
    return tex(alpha, 4) + (beta < 0 ? " - " : " + ") + tex(std::fabs(beta), 4) + "\\,x" +
           (gamma < 0 ? " - " : " + ") + tex(std::fabs(gamma), 4) + "\\,y";
}

std::string depth_text(double z) { return std::isinf(z) ? "∞" : num(z, 4); }
std::string depth_tex(double z) { return std::isinf(z) ? "\\infty" : tex(z, 4); }

std::string plural(long long n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

void ZBuffer::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    const auto& scene = s.in.scene;
    // The polygon the step was about: Polygon advanced k past it.
    const int k = s.last == Phase::Polygon ? s.k - 1 : s.k;
    switch (s.last) {
        case Phase::Clear:
            info.event = "clear";
            info.line = kLineClear;
            info.narration = "Clear the " + std::to_string(scene.width) + " × " +
                             std::to_string(scene.height) +
                             " depth buffer to ∞ and the colour buffer to background; " +
                             plural(static_cast<long long>(scene.polygons.size()), "polygon") +
                             " to draw in index order.";
            info.math = "\\text{depth}[i, j] = \\infty \\text{ for all } " +
                        std::to_string(scene.width * scene.height) + " \\text{ pixels}";
            break;
        case Phase::Polygon: {
            info.event = "polygon";
            info.line = kLineScan;
            const long long lost = s.step_pixels - s.step_wins;
            info.narration = "Polygon P" + std::to_string(k) + ", z = " + plane_text(s.planes[k]) +
                             ": scan conversion gives " + plural(s.step_pixels, "pixel") + "; " +
                             std::to_string(s.step_pixels) + " depth compares, " +
                             std::to_string(s.step_wins) + " won (depth and colour written), " +
                             std::to_string(lost) + " kept what was there (as near or nearer).";
            info.math = "z_" + std::to_string(k) + "(x, y) = " + plane_tex(s.planes[k]) +
                        ",\\quad \\text{compares} = " + std::to_string(s.step_pixels) +
                        ",\\quad \\text{written} = " + std::to_string(s.step_wins);
            break;
        }
        case Phase::Setup: {
            info.event = "polygon-start";
            info.line = kLinePlane;
            const int kk = s.phase == Phase::Setup ? s.k - 1 : s.k;  // an empty polygon moved on
            info.narration = "Polygon P" + std::to_string(kk) + ": its plane gives z = " +
                             plane_text(s.planes[kk]) + "; it covers " +
                             plural(s.step_pixels, "pixel centre") +
                             (s.step_pixels == 0 ? ", so there is nothing to compare." : ", each to be compared.");
            info.math = "z_" + std::to_string(kk) + "(x, y) = -\\frac{a x + b y + d}{c} = " +
                        plane_tex(s.planes[kk]);
            break;
        }
        case Phase::Pixel: {
            const int kk = s.phase == Phase::Setup ? s.k - 1 : s.k;  // Setup: moved on to the next
            const std::string P = "P" + std::to_string(kk);
            const std::string where = "(" + std::to_string(s.pi) + ", " + std::to_string(s.pj) + ")";
            const std::string centre = "(" + num(s.pi + 0.5) + ", " + num(s.pj + 0.5) + ")";
            const std::string old = s.id_old < 0 ? "background" : "P" + std::to_string(s.id_old);
            info.math = "z = " + tex(s.z, 4) + (s.won ? " < " : " \\ge ") + depth_tex(s.z_old) +
                        " = \\text{depth}[" + std::to_string(s.pi) + ", " + std::to_string(s.pj) + "]";
            if (s.won) {
                info.event = "pixel-write";
                info.line = kLineWrite;
                info.narration = "Pixel " + where + ": " + P + " at the centre " + centre + " has z = " +
                                 num(s.z, 4) + " < " + depth_text(s.z_old) + " (" + old +
                                 "), so write depth " + num(s.z, 4) + " and " + P + "'s colour.";
            } else {
                info.event = "pixel-keep";
                info.line = kLineCompare;
                info.narration = "Pixel " + where + ": " + P + " at the centre " + centre + " has z = " +
                                 num(s.z, 4) + " ≥ " + depth_text(s.z_old) + " held by " + old +
                                 (s.z == s.z_old ? " (a tie: the earlier polygon stays)" : "") +
                                 ", so the pixel is unchanged.";
            }
            info.vars.push_back({"i", static_cast<long long>(s.pi)});
            info.vars.push_back({"j", static_cast<long long>(s.pj)});
            info.vars.push_back({"z", s.z});
            info.vars.push_back({"depth_before", std::isinf(s.z_old) ? Value(std::string("∞")) : Value(s.z_old)});
            break;
        }
        case Phase::Finish:
        case Phase::Done: {
            info.event = "done";
            info.line = kLineDone;
            long long shown = 0;
            for (int id : s.ids) shown += id >= 0;
            info.narration = "All polygons drawn: " + std::to_string(s.compares) + " depth compares (one per scan-converted pixel), " +
                             std::to_string(s.writes) + " writes; " + std::to_string(shown) +
                             " pixels show a polygon, the rest background.";
            info.math = "p_c = " + std::to_string(s.compares) + ",\\quad \\text{writes} = " +
                        std::to_string(s.writes);
            break;
        }
    }
    if (s.last == Phase::Polygon || s.last == Phase::Setup) info.vars.push_back({"k", static_cast<long long>(k)});
    info.vars.push_back({"compares", s.compares});
    info.vars.push_back({"writes", s.writes});
}

void ZBuffer::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and render] --------------------------------------------------------------------

ZBuffer::Result ZBuffer::result(const State& s) {
    Result r;
    r.width = s.in.scene.width, r.height = s.in.scene.height;
    r.ids = s.ids;
    r.depth = s.depth;
    if (r.ids.empty()) {  // before the clear step
        const std::size_t size = static_cast<std::size_t>(s.in.scene.width * s.in.scene.height);
        r.ids.assign(size, -1);
        r.depth.assign(size, kFar);
    }
    r.compares = s.compares;
    r.writes = s.writes;
    return r;
}

[[gnu::flatten]] ZBuffer::Result ZBuffer::render(const Input& in) {
    const auto& scene = in.scene;
    Result r;
    r.width = scene.width, r.height = scene.height;
    const std::size_t W = static_cast<std::size_t>(scene.width);
    r.ids.assign(W * static_cast<std::size_t>(scene.height), -1);
    r.depth.assign(r.ids.size(), kFar);
    for (std::size_t k = 0; k < scene.polygons.size(); ++k) {
        const Plane pl = hsr::plane_of(scene.polygons[k]);
        for (const PixelSpan& sp : hsr::polygon_spans(scene.polygons[k], scene.width, scene.height)) {
            const std::size_t row = static_cast<std::size_t>(sp.j) * W;
            for (int i = sp.i_first; i < sp.i_end; ++i) {
                const double z = hsr::depth_at(pl, i + 0.5, sp.j + 0.5);
                ++r.compares;
                if (z < r.depth[row + i]) {
                    r.depth[row + i] = z;
                    r.ids[row + i] = static_cast<int>(k);
                    ++r.writes;
                }
            }
        }
    }
    return r;
}

}  // namespace cg
