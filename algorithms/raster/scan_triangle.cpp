// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and scan] [draw]
#include "raster/scan_triangle.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "core/format.hpp"
#include "raster/orient2d.hpp"
#include "raster/triangle_spans.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Edge = ScanTriangle::Edge;
// The span arithmetic is shared with the hidden-surface algorithms (raster/triangle_spans.hpp).
using Row = raster::TriangleRow;
using raster::first_centre_above;
using raster::index;
using raster::inverse_slope;
using raster::lower_end;
using raster::lower_index;
using raster::row_at;
using raster::sort_vertices;
using raster::split_x;
using raster::upper_end;
using raster::upper_index;
constexpr const auto& kEdges = raster::kTriangleEdges;

// ---- [helpers] ------------------------------------------------------------------------------

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineSort = 1,
    kLineSplit,
    kLineCollinear,
    kLineSlopes,
    kLineLoop,
    kLinePart,
    kLineEnds,
    kLineFill,
    kLineShade,
    kLineDone,
};

constexpr const char* kEdgeName[] = {"v0→v2", "v0→v1", "v1→v2"};
constexpr const char* kEdgeTex[] = {"v_0 v_2", "v_0 v_1", "v_1 v_2"};

// A span the state recorded, as the Row it came from.
Row row_of_span(const std::array<dvec2, 3>& v, int orient, const ScanTriangle::Span& span) {
    Row r;
    r.y = span.j + 0.5;
    r.upper = r.y > v[1].y;
    const Edge short_edge = r.upper ? Edge::Upper : Edge::Lower;
    r.left = orient > 0 ? short_edge : Edge::Long;
    r.right = orient > 0 ? Edge::Long : short_edge;
    r.x_left = span.x_left, r.x_right = span.x_right;
    r.i_first = span.i_first, r.i_end = span.i_end;
    return r;
}

// Gouraud: the colour along edge e at height y, then along the span at x.
dvec3 edge_colour(const std::array<dvec2, 3>& v, const std::array<dvec3, 3>& c, Edge e, double y) {
    const int a = lower_index(e), b = upper_index(e);
    const double t = (y - v[a].y) / (v[b].y - v[a].y);
    return c[a] + t * (c[b] - c[a]);
}

void fill_row(const Row& r, int j, bool shaded, const std::array<dvec2, 3>& v,
              const std::array<dvec3, 3>& c, std::vector<glm::ivec2>& pixels,
              std::vector<dvec3>& colors) {
    for (int i = r.i_first; i < r.i_end; ++i) pixels.push_back({i, j});
    if (!shaded || r.i_first >= r.i_end) return;
    const dvec3 c_left = edge_colour(v, c, r.left, r.y), c_right = edge_colour(v, c, r.right, r.y);
    const double width = r.x_right - r.x_left;  // > 0: the span holds a pixel centre
    for (int i = r.i_first; i < r.i_end; ++i) {
        const double u = (i + 0.5 - r.x_left) / width;
        colors.push_back(glm::clamp(c_left + u * (c_right - c_left), dvec3(0), dvec3(1)));
    }
}

// Room for the pixels: the area plus a border's worth, at most the grid.
std::size_t expected_pixels(const std::array<dvec2, 3>& v, long long width, long long height) {
    const double area = std::fabs((v[1].x - v[0].x) * (v[2].y - v[0].y) -
                                  (v[2].x - v[0].x) * (v[1].y - v[0].y)) / 2;
    const double x_extent = std::max({v[0].x, v[1].x, v[2].x}) - std::min({v[0].x, v[1].x, v[2].x});
    const double estimate = area + x_extent + (v[2].y - v[0].y) + 4;
    return static_cast<std::size_t>(std::min(estimate, double(width * height)));
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ScanTriangle::spec() {
    static const Spec spec{
        "scan-triangle",
        "Triangle scan conversion",
        "Polygons",
        {
            "sort the vertices by y:  v0 lowest, v1 middle, v2 highest",
            "split with the line y = y1:  x_split ← x0 + (y1 − y0)·(x2 − x0)/(y2 − y0)",
            "if v0, v1, v2 are collinear: nothing to fill, stop",
            "inverse slopes m = dx/dy of v0→v2 (long), v0→v1 (lower), v1→v2 (upper)",
            "for each scanline j with y0 < j + ½ ≤ y2, bottom to top:",
            "    y ← j + ½;  part ← lower (edges v0→v1, v0→v2) if y ≤ y1, else upper (v1→v2, "
            "v0→v2)",
            "    x_left, x_right ← the part's two edges at y:  x = x_a + (y − y_a)·m",
            "    fill pixels ⌈x_left − ½⌉ ≤ i < ⌈x_right − ½⌉      ▷ x_left ≤ i + ½ < x_right",
            "    (colours: along both edges to y, then along the span to i + ½)",
            "done: every pixel whose centre is inside",
        },
        {
            {"sort", "the vertices in order of y: v0 lowest, v1 middle, v2 highest"},
            {"split", "the line y = y1 cuts the triangle into a flat-top and a flat-bottom part"},
            {"flat-edge", "two vertices share their y: one part has no height, no split needed"},
            {"collinear", "the vertices lie on one line: no area, no pixel"},
            {"slopes", "the inverse slopes dx/dy of the edges, and the scanlines to visit"},
            {"span", "a scanline: its span between the two edges, and the pixels filled"},
            {"empty-span", "a scanline whose span holds no pixel centre (inside the grid)"},
            {"done", "all scanlines are filled"},
        },
        {},  // no sliders
        {
            .predict = {
                {"split", {"x_split"}},
                {"slopes", {"m_long"}},
                {"span", {"x_left", "x_right"}},
            },
            .mistakes = {
                {"span", "i_first", "off-by-one",
                 "started the span at the pixel whose centre is left of x_left"},
                {"span", "x_right", "keep", "forgot to step x_right by its inverse slope"},
                {"slopes", "m_upper", "negate", "took dx/dy of the upper edge from the wrong end"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void ScanTriangle::validate(const Input& in) {
    const std::string max = std::to_string(kMaxSize);
    if (in.width < 1 || in.width > kMaxSize)
        throw InputError("width", "must be a whole number of pixels from 1 to " + max + " (got " +
                                      std::to_string(in.width) + ")");
    if (in.height < 1 || in.height > kMaxSize)
        throw InputError("height", "must be a whole number of pixels from 1 to " + max +
                                       " (got " + std::to_string(in.height) + ")");
    if (in.triangle.size() != 3)
        throw InputError("triangle", "must have exactly 3 vertices (got " +
                                         std::to_string(in.triangle.size()) + ")");
    for (std::size_t k = 0; k < 3; ++k)
        for (int d = 0; d < 2; ++d) {
            const std::string field =
                "triangle[" + std::to_string(k) + "][" + std::to_string(d) + "]";
            const double v = in.triangle[k][d];
            check_finite(v, field);
            if (std::fabs(v) > kMaxCoordinate)
                throw InputError(field,
                                 "must lie within ±1e9 pixels of the origin (got " + given(v) + ")");
            // The exact inside test multiplies coordinates; far below a pixel they could underflow.
            if (v != 0 && std::fabs(v) < 1e-100)
                throw InputError(field,
                                 "must be 0 or at least 1e-100 in size (got " + given(v) + ")");
        }
    if (!in.colors.empty() && in.colors.size() != 3)
        throw InputError("colors", "must give one colour per vertex, 3 in all (got " +
                                       std::to_string(in.colors.size()) + ")");
    for (std::size_t k = 0; k < in.colors.size(); ++k)
        for (int d = 0; d < 3; ++d) {
            const std::string field =
                "colors[" + std::to_string(k) + "][" + std::to_string(d) + "]";
            const double v = in.colors[k][d];
            check_finite(v, field);
            if (v < 0 || v > 1) throw InputError(field, "must be from 0 to 1 (got " + given(v) + ")");
        }
}

ScanTriangle::State ScanTriangle::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

// The algorithm proper: one step of the math. Kept apart from the narration below so that
// running to completion (no StepInfo) costs about what the plain scan() does.
void ScanTriangle::advance(State& s) {
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Sort:  // Sort the vertices by y
            sort_vertices(s.in.triangle, s.order);
            for (int k = 0; k < 3; ++k) s.v[k] = s.in.triangle[s.order[k]];
            if (!s.in.colors.empty())
                for (int k = 0; k < 3; ++k) s.c[k] = s.in.colors[s.order[k]];
            s.phase = Phase::Split;
            return;
        case Phase::Split:  // Split at the middle vertex's y
            s.orient = orient2d(s.v[0], s.v[2], s.v[1]);
            if (s.orient == 0) {  // collinear: no area
                s.phase = Phase::Finish;
                return;
            }
            s.x_split = split_x(s.v);
            s.phase = Phase::Slopes;
            return;
        case Phase::Slopes: {  // Inverse slopes, and the scanlines to visit
            for (Edge e : kEdges) s.m[index(e)] = inverse_slope(s.v, e);
            const int height = static_cast<int>(s.in.height);
            s.j_begin = first_centre_above(s.v[0].y, 0, height);
            s.j_end = first_centre_above(s.v[2].y, 0, height);
            s.spans.reserve(static_cast<std::size_t>(s.j_end - s.j_begin));
            s.j = s.j_begin - 1;
            s.phase = s.j_begin < s.j_end ? Phase::Scanline : Phase::Finish;
            return;
        }
        case Phase::Scanline: {  // Fill one scanline's span
            const Row r = row_at(s.v, s.m, s.orient, ++s.j, static_cast<int>(s.in.width));
            s.upper = r.upper;
            s.x_left = r.x_left, s.x_right = r.x_right;
            s.i_first = r.i_first, s.i_end = r.i_end;
            if (r.i_first < r.i_end) {
                s.spans.push_back({s.j, r.i_first, r.i_end, r.x_left, r.x_right});
                s.filled += r.i_end - r.i_first;
            }
            if (s.j + 1 >= s.j_end) s.phase = Phase::Finish;
            return;
        }
        case Phase::Finish:  // Every scanline is done
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

constexpr int kFar = 1'000'000'001;  // beyond any coordinate: scanline numbers unclipped

std::string vertex_name(int k) { return "v" + std::to_string(k); }

// A factor after "·": negative ones in parentheses, "·(−1.111)".
std::string signed_num(double m, int digits = 4) {
    return m < 0 ? "(" + num(m, digits) + ")" : num(m, digits);
}
std::string signed_tex(double m, int digits = 4) {
    return m < 0 ? "(" + tex(m, digits) + ")" : tex(m, digits);
}

bool horizontal(const std::array<dvec2, 3>& v, Edge e) {
    return lower_end(v, e).y == upper_end(v, e).y;
}

std::string slope_text(const ScanTriangle::State& s, Edge e) {
    const dvec2 a = lower_end(s.v, e), b = upper_end(s.v, e);
    const std::string name = kEdgeName[index(e)];
    if (a.y == b.y) return name + " horizontal (no slope needed)";
    return name + " m = " + num(b.x - a.x) + "/" + num(b.y - a.y) + " = " + num(s.m[index(e)], 4);
}

std::string slope_tex(const ScanTriangle::State& s, Edge e) {
    const dvec2 a = lower_end(s.v, e), b = upper_end(s.v, e);
    const std::string name = std::string("m_{") + kEdgeTex[index(e)] + "}";
    if (a.y == b.y) return name + " = \\text{none (horizontal)}";
    return name + " = \\frac{" + tex(b.x - a.x) + "}{" + tex(b.y - a.y) + "} = " +
           tex(s.m[index(e)], 4);
}

// Scanline j's row as the state holds it.
Row row_of(const ScanTriangle::State& s) {
    return row_of_span(s.v, s.orient, {s.j, s.i_first, s.i_end, s.x_left, s.x_right});
}

void narrate_sort(const ScanTriangle::State& s, StepInfo& info) {
    info.event = "sort";
    info.line = kLineSort;
    info.narration = "Sorted by y: ";
    for (int k = 0; k < 3; ++k) {
        info.narration += (k ? ", " : "") + vertex_name(k) + " = " + num(s.v[k]) + " (P" +
                          std::to_string(s.order[k]) + ")";
        info.math += (k ? ",\\quad " : "") + std::string("v_") + std::to_string(k) + " = " +
                     tex(s.v[k]);
    }
    info.narration += ". The long edge v0→v2 spans the whole height, y = " + num(s.v[0].y) +
                      " to " + num(s.v[2].y) + ".";
}

void narrate_split(const ScanTriangle::State& s, StepInfo& info) {
    const auto& v = s.v;
    if (s.orient == 0) {
        info.event = "collinear";
        info.line = kLineCollinear;
        info.narration = "v0, v1 and v2 lie on one line ((v2 − v0) × (v1 − v0) = 0): the "
                         "triangle has no area, so no pixel is filled.";
        info.math = "(v_2 - v_0) \\times (v_1 - v_0) = " + tex(v[2] - v[0]) + " \\times " +
                    tex(v[1] - v[0]) + " = 0";
        return;
    }
    const std::string where = std::string("v1 lies to the ") + (s.orient > 0 ? "left" : "right") +
                              " of the long edge, so the long edge is the span's " +
                              (s.orient > 0 ? "right" : "left") + " end.";
    info.line = kLineSplit;
    info.math = "x_{split} = x_0 + \\frac{y_1 - y_0}{y_2 - y_0}(x_2 - x_0) = " + tex(v[0].x) +
                " + \\frac{" + tex(v[1].y - v[0].y) + "}{" + tex(v[2].y - v[0].y) + "} \\cdot " +
                signed_tex(v[2].x - v[0].x, 6) + " = " + tex(s.x_split, 4);
    if (v[0].y == v[1].y) {
        info.event = "flat-edge";
        info.narration = "v0 and v1 share y = " + num(v[0].y) +
                         ": the bottom edge is already horizontal, so there is no lower part and "
                         "nothing to split; the whole triangle is one flat-bottom part. " + where;
    } else if (v[1].y == v[2].y) {
        info.event = "flat-edge";
        info.narration = "v1 and v2 share y = " + num(v[2].y) +
                         ": the top edge is already horizontal, so there is no upper part and "
                         "nothing to split; the whole triangle is one flat-top part. " + where;
    } else {
        info.event = "split";
        info.narration = "The line y = y1 = " + num(v[1].y) + " meets the long edge at x_split = " +
                         num(v[0].x) + " + (" + num(v[1].y - v[0].y) + "/" + num(v[2].y - v[0].y) +
                         ")·" + signed_num(v[2].x - v[0].x, 6) + " = " + num(s.x_split, 4) +
                         ": a flat-top lower part from y = " + num(v[0].y) + " to " + num(v[1].y) +
                         " and a flat-bottom upper part from y = " + num(v[1].y) + " to " +
                         num(v[2].y) + ". " + where;
    }
}

void narrate_slopes(const ScanTriangle::State& s, StepInfo& info) {
    info.event = "slopes";
    info.line = kLineSlopes;
    info.narration = "Inverse slopes dx/dy: " + slope_text(s, Edge::Long) + "; " +
                     slope_text(s, Edge::Lower) + "; " + slope_text(s, Edge::Upper) + ". ";
    info.math = slope_tex(s, Edge::Long) + ",\\quad " + slope_tex(s, Edge::Lower) + ",\\quad " +
                slope_tex(s, Edge::Upper);
    const int all_begin = first_centre_above(s.v[0].y, -kFar, kFar);
    const int all_end = first_centre_above(s.v[2].y, -kFar, kFar);
    if (s.j_begin < s.j_end) {
        info.narration +=
            "Scanlines j = " + std::to_string(s.j_begin) + " to " + std::to_string(s.j_end - 1) +
            " have their centre y = j + ½ in (" + num(s.v[0].y) + ", " + num(s.v[2].y) + "]" +
            (all_end - all_begin > s.j_end - s.j_begin ? " and lie in the grid." : ".");
        info.math += ",\\quad " + std::to_string(s.j_begin) + " \\le j \\le " +
                     std::to_string(s.j_end - 1);
    } else {
        info.narration += all_begin < all_end
                              ? "The scanlines it covers lie outside the grid: nothing to fill."
                              : "No scanline centre y = j + ½ lies in (" + num(s.v[0].y) + ", " +
                                    num(s.v[2].y) + "]: the triangle is too thin to fill a pixel.";
    }
}

void narrate_scanline(const ScanTriangle::State& s, StepInfo& info) {
    const Row r = row_of(s);
    const std::string y = num(r.y);
    auto edge_x = [&](Edge e, double x) {
        const dvec2 a = lower_end(s.v, e);
        return num(a.x) + " + (" + y + " − " + num(a.y) + ")·" + signed_num(s.m[index(e)]) +
               " = " + num(x, 4);
    };
    auto edge_x_tex = [&](const char* name, Edge e, double x) {
        const dvec2 a = lower_end(s.v, e);
        return std::string(name) + " = " + tex(a.x) + " + (" + tex(r.y) + " - " + tex(a.y) +
               ") \\cdot " + signed_tex(s.m[index(e)]) + " = " + tex(x, 4);
    };
    info.narration = "Scanline j = " + std::to_string(s.j) + ", y = " + y + " (" +
                     (s.upper ? "upper" : "lower") +
                     " part): x_left = " + edge_x(r.left, r.x_left) + " on " +
                     kEdgeName[index(r.left)] + ", x_right = " + edge_x(r.right, r.x_right) +
                     " on " + kEdgeName[index(r.right)] + ". ";
    info.math = edge_x_tex("x_{left}", r.left, r.x_left) + ",\\quad " +
                edge_x_tex("x_{right}", r.right, r.x_right);
    // The unclipped ends, as a hand calculation has them; the state's are exact and clipped.
    const double lo = std::ceil(r.x_left - 0.5), hi = std::ceil(r.x_right - 0.5);
    const int n = r.i_end - r.i_first;
    if (n > 0) {
        const bool clipped = r.i_first != lo || r.i_end != hi;
        info.event = "span";
        info.line = s.in.colors.empty() ? kLineFill : kLineShade;
        info.narration += "Fill i = " + std::to_string(r.i_first) + " to " +
                          std::to_string(r.i_end - 1) + " (⌈" + num(r.x_left, 4) + " − ½⌉ = " +
                          num(lo) + " to ⌈" + num(r.x_right, 4) + " − ½⌉ − 1 = " + num(hi - 1) +
                          (clipped ? ", clipped to the grid" : "") + "): " + std::to_string(n) +
                          " pixel" + (n == 1 ? "" : "s") + ".";
        info.math += ",\\quad " + tex(lo) + " = \\lceil x_{left} - \\tfrac12 \\rceil \\le i < " +
                     "\\lceil x_{right} - \\tfrac12 \\rceil = " + tex(hi);
        if (!s.in.colors.empty()) {
            const dvec3 cl = edge_colour(s.v, s.c, r.left, r.y);
            const dvec3 cr = edge_colour(s.v, s.c, r.right, r.y);
            info.narration += " Colour " + num(cl, 3) + " at x_left to " + num(cr, 3) +
                              " at x_right, interpolated at each centre i + ½.";
        }
    } else {
        info.event = "empty-span";
        info.line = kLineFill;
        info.narration += hi <= 0 || lo >= s.in.width
                              ? "The span lies outside the grid (0 ≤ i < " +
                                    std::to_string(s.in.width) + "): nothing to fill."
                              : "No pixel centre i + ½ lies in [" + num(r.x_left, 4) + ", " +
                                    num(r.x_right, 4) + "): nothing to fill.";
        info.math += ",\\quad \\lceil x_{left} - \\tfrac12 \\rceil = " + tex(lo) + " \\ge " +
                     tex(hi) + " = \\lceil x_{right} - \\tfrac12 \\rceil";
    }
}

void fill_vars(const ScanTriangle::State& s, StepInfo& info) {
    for (int k = 0; k < 3; ++k) info.vars.push_back({vertex_name(k), vec(s.v[k])});
    if (s.last == ScanTriangle::Phase::Sort || s.orient == 0) return;
    info.vars.push_back({"x_split", s.x_split});
    if (s.last == ScanTriangle::Phase::Split) return;
    static constexpr const char* kSlopeName[] = {"m_long", "m_lower", "m_upper"};
    for (Edge e : kEdges)
        info.vars.push_back({kSlopeName[index(e)], horizontal(s.v, e)
                                                       ? Value(std::string("none (horizontal)"))
                                                       : Value(s.m[index(e)])});
    if (s.last == ScanTriangle::Phase::Scanline) {
        info.vars.push_back({"j", static_cast<long long>(s.j)});
        info.vars.push_back({"y", s.j + 0.5});
        info.vars.push_back({"part", std::string(s.upper ? "upper" : "lower")});
        info.vars.push_back({"x_left", s.x_left});
        info.vars.push_back({"x_right", s.x_right});
        if (s.i_first < s.i_end) {
            info.vars.push_back({"i_first", static_cast<long long>(s.i_first)});
            info.vars.push_back({"i_last", static_cast<long long>(s.i_end - 1)});
        }
    }
    info.vars.push_back({"filled", s.filled});
}

}  // namespace

// What the step just taken means, told with its numbers. `s` is the state after the step.
void ScanTriangle::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Sort: narrate_sort(s, info); break;
        case Phase::Split: narrate_split(s, info); break;
        case Phase::Slopes: narrate_slopes(s, info); break;
        case Phase::Scanline: narrate_scanline(s, info); break;
        case Phase::Finish:
        case Phase::Done: {
            const long long n = s.filled;
            info.event = "done";
            info.line = kLineDone;
            info.narration = "Every scanline is done: " + std::to_string(n) + " pixel" +
                             (n == 1 ? "" : "s") + " filled.";
            info.math = "\\text{pixels filled} = " + std::to_string(n);
            break;
        }
    }
    fill_vars(s, info);
}

void ScanTriangle::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and scan] ----------------------------------------------------------------------

ScanTriangle::Result ScanTriangle::result(const State& s) {
    Result r;
    const bool shaded = !s.in.colors.empty();
    r.pixels.reserve(static_cast<std::size_t>(s.filled));
    if (shaded) r.colors.reserve(static_cast<std::size_t>(s.filled));
    r.spans.reserve(s.spans.size());
    for (const Span& span : s.spans) {
        const Row row = row_of_span(s.v, s.orient, span);
        r.spans.push_back({span.j, span.i_first, span.i_end - 1});
        fill_row(row, span.j, shaded, s.v, s.c, r.pixels, r.colors);
    }
    if (s.orient != 0 && s.phase > Phase::Split) r.split = dvec2(s.x_split, s.v[1].y);
    if (s.orient != 0 && s.phase > Phase::Slopes)
        for (Edge e : kEdges)
            if (!horizontal(s.v, e)) r.inverse_slopes[index(e)] = s.m[index(e)];
    return r;
}

// Flattened like run_to_end, so that the comparison is between two fully inlined loops.
[[gnu::flatten]] ScanTriangle::Result ScanTriangle::scan(const Input& in) {
    Result r;
    std::array<int, 3> order;
    sort_vertices(in.triangle, order);
    std::array<dvec2, 3> v;
    std::array<dvec3, 3> c{};
    const bool shaded = !in.colors.empty();
    for (int k = 0; k < 3; ++k) {
        v[k] = in.triangle[order[k]];
        if (shaded) c[k] = in.colors[order[k]];
    }
    const int orient = orient2d(v[0], v[2], v[1]);
    if (orient == 0) return r;
    r.split = dvec2(split_x(v), v[1].y);
    std::array<double, 3> m;
    for (Edge e : kEdges) {
        m[index(e)] = inverse_slope(v, e);
        if (!horizontal(v, e)) r.inverse_slopes[index(e)] = m[index(e)];
    }
    const int width = static_cast<int>(in.width), height = static_cast<int>(in.height);
    const int j_begin = first_centre_above(v[0].y, 0, height);
    const int j_end = first_centre_above(v[2].y, 0, height);
    r.pixels.reserve(expected_pixels(v, in.width, in.height));
    if (shaded) r.colors.reserve(r.pixels.capacity());
    for (int j = j_begin; j < j_end; ++j) {
        const Row row = row_at(v, m, orient, j, width);
        if (row.i_first < row.i_end) r.spans.push_back({j, row.i_first, row.i_end - 1});
        fill_row(row, j, shaded, v, c, r.pixels, r.colors);
    }
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

namespace {

}  // namespace

void ScanTriangle::draw(const State& s, Scene& scene) {
    const int w = static_cast<int>(s.in.width), h = static_cast<int>(s.in.height);
    const bool shaded = !s.in.colors.empty();

    // The pixels filled so far.
    PixelGrid2 grid;
    grid.width = w;
    grid.height = h;
    grid.rgba.assign(static_cast<std::size_t>(w) * h, 0);
    const Result r = result(s);
    for (std::size_t k = 0; k < r.pixels.size(); ++k) {
        const glm::ivec2 p = r.pixels[k];
        grid.rgba[static_cast<std::size_t>(p.y) * w + p.x] =
            shaded ? pack_rgba(r.colors[k]) : PixelGrid2::kRoleColour;
    }
    scene.grids.push_back(std::move(grid));
    const double W = w, H = h;
    scene.polygons.push_back(
        {{{0, 0}, {W, 0}, {W, H}, {0, H}}, {Role::Construction, 1.0f}, true, false});

    const bool sorted = s.phase != Phase::Sort;
    const bool split = sorted && s.phase > Phase::Split && s.orient != 0;
    const bool finished = s.phase == Phase::Done;

    // The row this step filled, the scanline's centre line and the span's two ends.
    if (s.last == Phase::Scanline && !finished) {
        const double y = s.j + 0.5;
        if (s.i_first < s.i_end)
            scene.polygons.push_back({{{double(s.i_first), double(s.j)},
                                       {double(s.i_end), double(s.j)},
                                       {double(s.i_end), s.j + 1.0},
                                       {double(s.i_first), s.j + 1.0}},
                                      {Role::Active, 2.5f},
                                      true,
                                      false});
        scene.segments.push_back({{std::min(0.0, s.x_left), y},
                                  {std::max(W, s.x_right), y},
                                  "",
                                  {Role::Active, 1.5f},
                                  false});
        scene.points.push_back(
            {{s.x_left, y}, "x_left = " + num(s.x_left, 4), {Role::Entering}, 5.0f});
        scene.points.push_back(
            {{s.x_right, y}, "x_right = " + num(s.x_right, 4), {Role::Leaving}, 5.0f});
        scene.labels.push_back({{W, y}, "j = " + std::to_string(s.j), {Role::Active}});
    }

    // The triangle, and the split line through the middle vertex.
    scene.polygons.push_back({s.in.triangle, {Role::Neutral, 2.0f}, true, false});
    if (split && s.v[0].y != s.v[1].y && s.v[1].y != s.v[2].y) {
        const dvec2 at{s.x_split, s.v[1].y};
        scene.segments.push_back({at, s.v[1], "", {Role::Construction, 2.0f, true}, false});
        scene.points.push_back({at, "split (" + num(at.x, 4) + ", " + num(at.y, 4) + ")",
                                {Role::Construction},
                                4.0f});
    }
    // The inverse slopes, on their edges, in the step that computes them.
    if (s.last == Phase::Slopes && s.orient != 0 && !finished)
        for (Edge e : kEdges)
            if (!horizontal(s.v, e))
                scene.segments.push_back({lower_end(s.v, e), upper_end(s.v, e),
                                          "dx/dy = " + num(s.m[index(e)], 4),
                                          {Role::Neutral, 2.0f},
                                          false});

    for (int k = 0; k < 3; ++k)
        scene.labels.push_back(
            {sorted ? s.v[k] : s.in.triangle[k],
             sorted ? vertex_name(k) + (k == 1 && split ? ", y1 = " + num(s.v[1].y) : "")
                    : "P" + std::to_string(k),
             {Role::Neutral}});
    for (int k = 0; k < 3; ++k) {
        const std::string K = std::to_string(k);
        scene.handles.push_back(
            {s.in.triangle[k], "P" + K, "/triangle/" + K + "/0", "/triangle/" + K + "/1"});
    }
}

}  // namespace cg
