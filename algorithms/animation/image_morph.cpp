// Sections: [field warp] [frames] [patterns] [spec] [validate] [state machine] [narrate]
//           [result and compute]
#include "animation/image_morph.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using Input = ImageMorph::Input;
using Image = ImageMorph::Image;
using Line = ImageMorph::Line;
using Term = ImageMorph::Term;
using Frame = ImageMorph::Frame;
using Phase = ImageMorph::Phase;
using State = ImageMorph::State;

enum Line_ { kLineFrame = 1, kLineLines, kLineEach, kLineUV, kLineWeight, kLineSample, kLineBlend, kLineReport };

double length(glm::dvec2 p) {
    return std::hypot(p.x, p.y);
}

glm::dvec2 perp(glm::dvec2 e) {
    return {-e.y, e.x};
}

}  // namespace

// ---- [field warp] ---------------------------------------------------------------------------

glm::dvec2 ImageMorph::lerp(glm::dvec2 p, glm::dvec2 q, double alpha) {
    // p + α (q − p): exactly p at α = 0 and when p = q; q itself at α = 1.
    return alpha == 1 ? q : p + alpha * (q - p);
}

std::vector<ImageMorph::Line> ImageMorph::interpolate(const Input& in, double alpha) {
    std::vector<Line> out;
    out.reserve(in.lines.size());
    for (const Pair& pr : in.lines)
        out.push_back({lerp(pr.a.p, pr.b.p, alpha), lerp(pr.a.q, pr.b.q, alpha)});
    return out;
}

glm::dvec2 ImageMorph::source(const std::vector<Line>& dst, const std::vector<Pair>& pairs,
                              bool to_b, const Params& w, glm::dvec2 x, std::vector<Term>* terms) {
    glm::dvec2 sum{0, 0};
    double total = 0;
    if (terms) terms->clear();
    for (std::size_t i = 0; i < dst.size(); ++i) {
        const Line& d = dst[i];
        const Line& s = to_b ? pairs[i].b : pairs[i].a;
        Term t;
        const glm::dvec2 e = d.q - d.p;
        const double len = length(e);
        if (!(len >= kMinLength)) {  // no direction this frame: left out
            if (terms) terms->push_back(t);
            continue;
        }
        t.used = true;
        const glm::dvec2 xp = x - d.p;
        t.u = glm::dot(xp, e) / (len * len);
        t.v = glm::dot(xp, perp(e)) / len;
        if (d == s) {  // the line maps onto itself: X'_i = X, exactly
            t.source = x;
        } else {
            const glm::dvec2 e2 = s.q - s.p;
            t.source = s.p + t.u * e2 + t.v * perp(e2) / length(e2);
            t.displacement = t.source - x;
        }
        // The distance to the segment (not the infinite line): beyond an end, to that end.
        t.dist = t.u < 0 ? length(xp) : t.u > 1 ? length(x - d.q) : std::fabs(t.v);
        const double strength = (w.p == 0.5 ? std::sqrt(len) : std::pow(len, w.p)) / (w.a + t.dist);
        t.weight = w.b == 2 ? strength * strength : std::pow(strength, w.b);
        sum += t.weight * t.displacement;
        total += t.weight;
        if (terms) terms->push_back(t);
    }
    return total > 0 ? x + sum / total : x;
}

double ImageMorph::sample(const Image& img, glm::dvec2 x) {
    // Pixel centres at (c + 0.5, r + 0.5): shift, clamp into the centres' rectangle, then
    // interpolate between the four centres around the point.
    const double fx = std::clamp(x.x - 0.5, 0.0, double(img.width - 1));
    const double fy = std::clamp(x.y - 0.5, 0.0, double(img.height - 1));
    const int c0 = int(fx), r0 = int(fy);
    const int c1 = std::min(c0 + 1, img.width - 1), r1 = std::min(r0 + 1, img.height - 1);
    const double tx = fx - c0, ty = fy - r0;
    const double top = (1 - tx) * img.at(c0, r0) + tx * img.at(c1, r0);
    const double bottom = (1 - tx) * img.at(c0, r1) + tx * img.at(c1, r1);
    return (1 - ty) * top + ty * bottom;
}

// ---- [frames] -------------------------------------------------------------------------------

ImageMorph::Frame ImageMorph::new_frame(const Input& in, double alpha) {
    Frame f;
    f.alpha = alpha;
    f.lines = interpolate(in, alpha);
    const int w = in.image_a.width, h = in.image_a.height;
    for (Image* img : {&f.warped_a, &f.warped_b, &f.morph, &f.dissolve}) {
        img->width = w;
        img->height = h;
        img->v.assign(std::size_t(w) * std::size_t(h), 0.0);
    }
    return f;
}

void ImageMorph::warp_row(const Input& in, Frame& f, int r) {
    const int w = in.image_a.width;
    const double al = f.alpha;
    for (int c = 0; c < w; ++c) {
        const glm::dvec2 x{c + 0.5, r + 0.5};
        const double a = sample(in.image_a, source(f.lines, in.lines, false, in.params, x));
        const double b = sample(in.image_b, source(f.lines, in.lines, true, in.params, x));
        const std::size_t at = std::size_t(r) * std::size_t(w) + std::size_t(c);
        f.warped_a.v[at] = a;
        f.warped_b.v[at] = b;
        f.morph.v[at] = (1 - al) * a + al * b;
        f.dissolve.v[at] = (1 - al) * in.image_a.v[at] + al * in.image_b.v[at];
    }
}

ImageMorph::Focus ImageMorph::focus(const Input& in, const Frame& f, int x, int y) {
    Focus out;
    out.x = x;
    out.y = y;
    out.alpha = f.alpha;
    out.centre = {x + 0.5, y + 0.5};
    out.a.source = source(f.lines, in.lines, false, in.params, out.centre, &out.a.terms);
    out.b.source = source(f.lines, in.lines, true, in.params, out.centre, &out.b.terms);
    out.a.value = sample(in.image_a, out.a.source);
    out.b.value = sample(in.image_b, out.b.source);
    out.morph = (1 - f.alpha) * out.a.value + f.alpha * out.b.value;
    out.dissolve = (1 - f.alpha) * in.image_a.at(x, y) + f.alpha * in.image_b.at(x, y);
    return out;
}

double ImageMorph::difference(const Frame& f) {
    double sum = 0;
    for (std::size_t k = 0; k < f.morph.v.size(); ++k) sum += std::fabs(f.morph.v[k] - f.dissolve.v[k]);
    return f.morph.v.empty() ? 0 : sum / double(f.morph.v.size());
}

// ---- [patterns] -----------------------------------------------------------------------------

// Grey 0 … 255 on a black ground, n × n: "disc" (radius 0.3 n, centred), "square" (side 0.5 n,
// centred), "bar" (a horizontal bar 0.2 n high, 0.8 n long), "column" (the bar upright),
// "cross", "ramp" (left to right).
ImageMorph::Image ImageMorph::pattern_image(const std::string& name, int n) {
    Image img;
    img.width = img.height = n;
    img.v.assign(std::size_t(n) * std::size_t(n), 0.0);
    const double m = 0.5 * n;
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const double x = c + 0.5 - m, y = r + 0.5 - m;
            double g = 0;
            if (name == "disc")
                g = std::hypot(x, y) <= 0.3 * n ? 255 : 0;
            else if (name == "square")
                g = std::fabs(x) <= 0.25 * n && std::fabs(y) <= 0.25 * n ? 255 : 0;
            else if (name == "bar")
                g = std::fabs(y) <= 0.1 * n && std::fabs(x) <= 0.4 * n ? 255 : 0;
            else if (name == "column")
                g = std::fabs(x) <= 0.1 * n && std::fabs(y) <= 0.4 * n ? 255 : 0;
            else if (name == "cross")
                g = (std::fabs(x) <= 0.1 * n || std::fabs(y) <= 0.1 * n) &&
                            std::max(std::fabs(x), std::fabs(y)) <= 0.4 * n
                        ? 255
                        : 0;
            else if (name == "ramp")
                g = n > 1 ? 255.0 * c / (n - 1) : 0;
            else
                throw InputError("pattern", "must be \"disc\", \"square\", \"bar\", \"column\", "
                                            "\"cross\" or \"ramp\", got \"" + name + "\"");
            img.v[std::size_t(r) * std::size_t(n) + std::size_t(c)] = g;
        }
    return img;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ImageMorph::spec() {
    static const Spec spec{
        "image-morph",
        "Image morphing: Beier–Neely feature lines, warp both images, then cross-dissolve",
        "Animation",
        {
            "for every frame α:",
            "  L_i ← lerp(P_iQ_i, P'_iQ'_i, α)   ▷ the interpolated feature lines",
            "  for every pixel centre X of the frame, row by row:",
            "    per line: u ← (X−P)·(Q−P)/|Q−P|²,  v ← (X−P)·perp(Q−P)/|Q−P|",
            "    X'_i ← P'+u(Q'−P')+v·perp(Q'−P')/|Q'−P'|;  w_i ← (|Q−P|^p/(a+dist))^b",
            "    X'_A, X'_B ← X + Σ w_i D_i / Σ w_i;  sample A at X'_A, B at X'_B (bilinear)",
            "    C(X) ← (1 − α) A_w(X) + α B_w(X)   ▷ plain dissolve: (1 − α) A(X) + α B(X)",
            "report the frame: what the warp changed against the plain dissolve",
        },
        {
            {"row", "one row of the frame: every pixel mapped into A and B, sampled, blended"},
            {"frame", "a frame finished: the morph against the plain cross-dissolve"},
        },
        {},  // no sliders
        {
            .predict = {{"row", {"u", "source_a"}}},
            .mistakes =
                {
                    {"row", "v", "negate",
                     "took perp(Q − P) the other way round: v, and the point beside the line, "
                     "on the wrong side"},
                    {"row", "morph", "copy:dissolve",
                     "blended A and B without warping them: the plain cross-dissolve, with ghosts"},
                    {"row", "source_a", "copy:source_b",
                     "sampled A where B's lines say: the two sources mixed up"},
                },
        },
        "t",  // the clock: the morph lasts one second, its frames evenly spaced in it
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

void check_image(const Image& img, const char* field) {
    if (img.width < 1 || img.height < 1)
        throw InputError(field, "must have at least one pixel (got none)");
    if (img.width > ImageMorph::kMaxSide || img.height > ImageMorph::kMaxSide)
        throw InputError(field, "is " + std::to_string(img.width) + " × " +
                                    std::to_string(img.height) + "; at most " +
                                    std::to_string(ImageMorph::kMaxSide) + " × " +
                                    std::to_string(ImageMorph::kMaxSide));
    if (img.v.size() != std::size_t(img.width) * std::size_t(img.height))
        throw InputError(field, "has " + std::to_string(img.v.size()) + " values for " +
                                    std::to_string(img.width) + " × " + std::to_string(img.height) +
                                    " pixels");
    for (std::size_t k = 0; k < img.v.size(); ++k) {
        const double g = img.v[k];
        if (std::isfinite(g) && std::fabs(g) <= ImageMorph::kMaxValue) continue;
        const std::string at = std::string(field) + "[" + std::to_string(k / std::size_t(img.width)) +
                               "][" + std::to_string(k % std::size_t(img.width)) + "]";
        if (!std::isfinite(g)) throw InputError(at, "must be finite (got " + given(g) + ")");
        throw InputError(at, "is too large (" + given(g) + "): at most 1e6 in size");
    }
}

void check_line(const Line& l, const std::string& field) {
    for (const auto& [p, name] : {std::pair{l.p, "[0]"}, std::pair{l.q, "[1]"}})
        for (int c = 0; c < 2; ++c) {
            if (!std::isfinite(p[c]))
                throw InputError(field + name, "must be finite (got " + given(p[c]) + ")");
            if (std::fabs(p[c]) > ImageMorph::kMaxCoordinate)
                throw InputError(field + name,
                                 "is too large (" + given(p[c]) + "): at most 1e4 in size");
        }
    if (!(length(l.q - l.p) >= ImageMorph::kMinLength))
        throw InputError(field, "is degenerate: P = " + given(l.p) + " and Q = " + given(l.q) +
                                    " coincide, so the line has no direction (it must be at "
                                    "least 1e-6 long)");
}

void check_param(double x, double lo, double hi, const char* field, const char* what) {
    if (!std::isfinite(x) || x < lo || x > hi)
        throw InputError(field, std::string("must be ") + what + " from " + given(lo) + " to " +
                                    given(hi) + ", got " + given(x));
}

}  // namespace

void ImageMorph::validate(const Input& in) {
    check_image(in.image_a, "image_a");
    check_image(in.image_b, "image_b");
    if (in.image_a.width != in.image_b.width || in.image_a.height != in.image_b.height)
        throw InputError("image_b", "is " + std::to_string(in.image_b.width) + " × " +
                                        std::to_string(in.image_b.height) +
                                        "; it must be the size of image_a, " +
                                        std::to_string(in.image_a.width) + " × " +
                                        std::to_string(in.image_a.height));
    if (in.lines.empty())
        throw InputError("lines", "must have at least one feature line pair (got none)");
    if (in.lines.size() > std::size_t(kMaxLines))
        throw InputError("lines", "has " + std::to_string(in.lines.size()) +
                                      " pairs; at most " + std::to_string(kMaxLines));
    for (std::size_t i = 0; i < in.lines.size(); ++i) {
        check_line(in.lines[i].a, "lines[" + std::to_string(i) + "].a");
        check_line(in.lines[i].b, "lines[" + std::to_string(i) + "].b");
    }
    check_param(in.params.a, 1e-6, 1e6, "params.a", "a positive constant");
    check_param(in.params.b, 0, 4, "params.b", "an exponent");
    check_param(in.params.p, 0, 2, "params.p", "an exponent");
    if (in.alphas.empty()) throw InputError("alphas", "must have at least one frame (got none)");
    if (in.alphas.size() > std::size_t(kMaxFrames))
        throw InputError("alphas", "has " + std::to_string(in.alphas.size()) +
                                       " frames; at most " + std::to_string(kMaxFrames));
    for (std::size_t k = 0; k < in.alphas.size(); ++k)
        if (!std::isfinite(in.alphas[k]) || in.alphas[k] < 0 || in.alphas[k] > 1)
            throw InputError("alphas[" + std::to_string(k) + "]",
                             "must be from 0 to 1, got " + given(in.alphas[k]));
    const long long pixels = (long long)in.alphas.size() * in.image_a.width * in.image_a.height;
    if (pixels > kMaxPixels)
        throw InputError("alphas", std::to_string(in.alphas.size()) + " frames of " +
                                       std::to_string(in.image_a.width) + " × " +
                                       std::to_string(in.image_a.height) +
                                       " pixels is too many: frames × pixels must be at most " +
                                       std::to_string(kMaxPixels));
    if (in.focus_x != -1 && (in.focus_x < 0 || in.focus_x >= in.image_a.width))
        throw InputError("focus", "x must be a column 0 to " + std::to_string(in.image_a.width - 1) +
                                      " (got " + std::to_string(in.focus_x) + ")");
    if (in.focus_y != -1 && (in.focus_y < 0 || in.focus_y >= in.image_a.height))
        throw InputError("focus", "y must be a row 0 to " + std::to_string(in.image_a.height - 1) +
                                      " (got " + std::to_string(in.focus_y) + ")");
}

ImageMorph::Input ImageMorph::resolve(const Input& given) {
    validate(given);
    Input in = given;
    if (in.focus_x == -1) in.focus_x = in.image_a.width / 2;
    if (in.focus_y == -1) in.focus_y = in.image_a.height / 2;
    return in;
}

// ---- [state machine] ------------------------------------------------------------------------

ImageMorph::State ImageMorph::start(const Input& in) {
    return begin(Shared<Input>(resolve(in)));
}

ImageMorph::State ImageMorph::begin(Shared<Input> shared) {
    State s;
    s.in = std::move(shared);
    s.frames.reserve(s.in->alphas.size());
    s.frames.push_back(new_frame(*s.in, s.in->alphas[0]));
    return s;
}

void ImageMorph::step(State& s, StepInfo* info) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Row:
            if (s.row == in.image_a.height) {  // the last frame is finished: begin the next
                ++s.frame;
                s.row = 0;
                s.frames.push_back(new_frame(in, in.alphas[std::size_t(s.frame)]));
            }
            warp_row(in, s.frames.back(), s.row);
            ++s.row;
            s.last = Phase::Row;
            if (s.row == in.image_a.height) s.phase = Phase::Frame;
            break;
        case Phase::Frame:
            s.last = Phase::Frame;
            s.phase = std::size_t(s.frame) + 1 == in.alphas.size() ? Phase::Done : Phase::Row;
            break;
        case Phase::Done:
            return;
    }
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

// The clock: the morph lasts one second, its frames evenly spaced in it (t = α for "frames").
double frame_time(const State& s) {
    const std::size_t n = s.in->alphas.size();
    return n > 1 ? double(s.frame) / double(n - 1) : 0.0;
}

std::string side_text(const ImageMorph::Side& side, const std::vector<Line>& lines,
                      const std::vector<ImageMorph::Pair>& pairs, bool to_b, glm::dvec2 x) {
    std::string t;
    int shown = 0, used = 0;
    for (std::size_t i = 0; i < side.terms.size(); ++i) {
        const Term& k = side.terms[i];
        if (!k.used) {
            t += " line " + std::to_string(i) + " has no length this frame (left out);";
            continue;
        }
        ++used;
        if (shown++ >= 3) continue;
        const Line& s = to_b ? pairs[i].b : pairs[i].a;
        t += " line " + std::to_string(i) + " (" + num(lines[i].p) + "→" + num(lines[i].q) +
             " onto " + num(s.p) + "→" + num(s.q) + "): u = " + num(k.u, 4) + ", v = " +
             num(k.v, 4) + ", X' = " + num(k.source, 4) + ", D = " + num(k.displacement, 4) +
             ", dist " + num(k.dist, 4) + ", w = " + num(k.weight, 4) + ";";
    }
    if (used > 3) t += " and " + std::to_string(used - 3) + " more lines;";
    t += " X' = X + Σ w D / Σ w = " + num(side.source, 4);
    if (used == 0) t += " (no line: X itself)";
    (void)x;
    return t;
}

void narrate_row(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Frame& f = s.frames.back();
    const int r = s.row - 1;
    const ImageMorph::Focus p = ImageMorph::focus(in, f, in.focus_x, r);
    info.event = "row";
    info.line = kLineBlend;
    std::string t = "Frame " + std::to_string(s.frame + 1) + " of " +
                    std::to_string(in.alphas.size()) + " (α = " + num(f.alpha) + "), row " +
                    std::to_string(r) + ": every pixel of the row is mapped back into A and into " +
                    "B by the interpolated feature lines, sampled and blended. Pixel (" +
                    std::to_string(p.x) + ", " + std::to_string(r) + "), X = " + num(p.centre) +
                    ". Into A:";
    t += side_text(p.a, f.lines, in.lines, false, p.centre) + ", where A is " + num(p.a.value, 4) +
         ". Into B:";
    t += side_text(p.b, f.lines, in.lines, true, p.centre) + ", where B is " + num(p.b.value, 4) +
         ". C = (1 − α)·" + num(p.a.value, 4) + " + α·" + num(p.b.value, 4) + " = " +
         num(p.morph, 4) + "; the plain dissolve there gives " + num(p.dissolve, 4) + ".";
    info.narration = std::move(t);
    info.math = "C = (1-\\alpha)\\,A(X'_A) + \\alpha\\,B(X'_B) = " + tex(p.morph, 4);
    const Term& t0 = p.a.terms.front();
    info.vars = {{"t", frame_time(s)},
                 {"alpha", f.alpha},
                 {"frame", (long long)s.frame},
                 {"row", (long long)r},
                 {"X", vec(p.centre)},
                 {"u", t0.u},
                 {"v", t0.v},
                 {"source_a", vec(p.a.source)},
                 {"source_b", vec(p.b.source)},
                 {"value_a", p.a.value},
                 {"value_b", p.b.value},
                 {"morph", p.morph},
                 {"dissolve", p.dissolve}};
}

void narrate_frame(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Frame& f = s.frames.back();
    const double d = ImageMorph::difference(f);
    info.event = "frame";
    info.line = kLineReport;
    std::string t = "Frame " + std::to_string(s.frame + 1) + " of " +
                    std::to_string(in.alphas.size()) + " done (α = " + num(f.alpha) + "): " +
                    std::to_string(f.morph.width) + " × " + std::to_string(f.morph.height) +
                    " pixels warped from both images and blended. The morph differs from the "
                    "plain cross-dissolve by " + num(d, 4) + " on average per pixel";
    t += d == 0 ? " (nothing moves: the lines agree, or α is 0 or 1)." :
                  ": where the dissolve shows both shapes faintly, the morph moves one into the "
                  "other.";
    if (s.phase == Phase::Done) t += " That was the last frame.";
    info.narration = std::move(t);
    info.math = "\\tfrac{1}{N}\\textstyle\\sum |C - C_{\\mathrm{dissolve}}| = " + tex(d, 4);
    info.vars = {{"t", frame_time(s)}, {"alpha", f.alpha}, {"frame", (long long)s.frame},
                 {"difference", d}};
}

}  // namespace

void ImageMorph::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    if (s.last == Phase::Row)
        narrate_row(s, info);
    else
        narrate_frame(s, info);
}

// ---- [result and compute] -------------------------------------------------------------------

ImageMorph::Result ImageMorph::result(const State& s) {
    const Input& in = *s.in;
    Result r;
    r.frames = s.frames;
    r.focus = focus(in, r.frames.back(), in.focus_x, in.focus_y);
    for (const Frame& f : r.frames) r.difference = std::max(r.difference, difference(f));
    return r;
}

ImageMorph::Result ImageMorph::compute(const Input& given) {
    const Input in = resolve(given);
    Result r;
    r.frames.reserve(in.alphas.size());
    for (double alpha : in.alphas) {
        Frame f = new_frame(in, alpha);
        for (int row = 0; row < in.image_a.height; ++row) warp_row(in, f, row);
        r.frames.push_back(std::move(f));
    }
    r.focus = focus(in, r.frames.back(), in.focus_x, in.focus_y);
    for (const Frame& f : r.frames) r.difference = std::max(r.difference, difference(f));
    return r;
}

}  // namespace cg
