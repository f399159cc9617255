// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and map]; the picture is in
// window_viewport_draw.cpp.
#include "viewing/window_viewport.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dvec2;
using Rect = WindowViewport::Rect;
using Phase = WindowViewport::Phase;
using Form = WindowViewport::Form;

// ---- [helpers] ------------------------------------------------------------------------------

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineSizes = 1,
    kLineAspect,
    kLineNdcMatrix,
    kLineToNdc,
    kLineDeviceMatrix,
    kLineToDevice,
    kLineCompose,
};

double width(const Rect& r) { return r.xmax - r.xmin; }
double height(const Rect& r) { return r.ymax - r.ymin; }

// glm matrices are indexed m[column][row].
dmat3 ndc_from(const Rect& w) {
    dmat3 m(1.0);
    m[0][0] = 2 / width(w);
    m[1][1] = 2 / height(w);
    m[2][0] = -(w.xmax + w.xmin) / width(w);
    m[2][1] = -(w.ymax + w.ymin) / height(w);
    return m;
}

dmat3 device_from(const Rect& v) {
    dmat3 m(1.0);
    m[0][0] = width(v) / 2;
    m[1][1] = height(v) / 2;
    m[2][0] = (v.xmax + v.xmin) / 2;
    m[2][1] = (v.ymax + v.ymin) / 2;
    return m;
}

// The points are mapped with the formulas the matrices' rows stand for (M_ndc p and M_vp q,
// written out): the same numbers, rounded less — 2 (x − xw_min)/Lw − 1 puts the window's
// corners exactly on ±1, where m00·x + m02 may miss by an ulp.
dvec2 to_ndc(const Rect& w, dvec2 p) {
    return {2 * (p.x - w.xmin) / width(w) - 1, 2 * (p.y - w.ymin) / height(w) - 1};
}
dvec2 to_device(const Rect& v, dvec2 q) {
    return {v.xmin + (q.x + 1) * width(v) / 2, v.ymin + (q.y + 1) * height(v) / 2};
}

bool aspects_differ(double a, double b) {
    return std::fabs(a - b) > WindowViewport::kAspectTolerance * std::max(a, b);
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

// The input's name for one of a rectangle's numbers: corner 0 or 1 (min or max), axis 0 or 1.
// A viewport given with "y_down" holds the row numbers swapped (its ymax is the image of the
// window's ymin); one given as "corners" names them by index.
std::string field_name(const std::string& name, Form form, int corner, int axis) {
    if (form == Form::Corners)
        return name + ".corners[" + std::to_string(corner) + "][" + std::to_string(axis) + "]";
    if (form == Form::YDown && axis == 1) corner = 1 - corner;
    return name + "." + (axis ? "y" : "x") + (corner ? "max" : "min");
}

// A rectangle that can be mapped: finite, with a width and a height, and — the window always,
// the viewport when given as a plain rectangle — min < max on both axes. `hint` follows the
// "inverted" error: how a flipped viewport may be given instead.
void check_rect(const Rect& r, const std::string& name, Form form, const std::string& hint) {
    auto field = [&](int corner, int axis) { return field_name(name, form, corner, axis); };
    check_finite(r.xmin, field(0, 0));
    check_finite(r.ymin, field(0, 1));
    check_finite(r.xmax, field(1, 0));
    check_finite(r.ymax, field(1, 1));
    const bool ordered = form == Form::Rect;
    const std::string relation = ordered ? "must be greater than " : "must differ from ";
    if (r.xmax == r.xmin)
        throw InputError(field(1, 0), relation + field(0, 0) + ": the " + name +
                                          " has zero width (xmin = xmax = " + given(r.xmin) + ")");
    if (ordered && r.xmax < r.xmin)
        throw InputError(field(1, 0), "must be greater than " + field(0, 0) + " (" +
                                          given(r.xmax) + " < " + given(r.xmin) +
                                          "): the rectangle is inverted" + hint);
    if (r.ymax == r.ymin)
        throw InputError(field(1, 1), relation + field(0, 1) + ": the " + name +
                                          " has zero height (ymin = ymax = " + given(r.ymin) + ")");
    if (ordered && r.ymax < r.ymin)
        throw InputError(field(1, 1), "must be greater than " + field(0, 1) + " (" +
                                          given(r.ymax) + " < " + given(r.ymin) +
                                          "): the rectangle is inverted" + hint);
}

bool flipped_x(const Rect& v) { return v.xmax < v.xmin; }
bool flipped_y(const Rect& v) { return v.ymax < v.ymin; }

bool finite(const dmat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

std::vector<std::vector<double>> rows(const dmat3& m) {
    return {{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}};
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& WindowViewport::spec() {
    static const Spec spec{
        "window-viewport",
        "Window to viewport through NDC",
        "Windows, Viewports, NDC",
        {
            "Lw, Hw ← window width, height;  Lv, Hv ← viewport's (signed: < 0 is a flip)",
            "if |Lw/Hw| ≠ |Lv/Hv|: warn, shapes will be distorted",
            "M_ndc ← [2/Lw 0 −(xw_max+xw_min)/Lw; 0 2/Hw −(yw_max+yw_min)/Hw; 0 0 1]",
            "for each point P:  P_ndc ← M_ndc P           ▷ the window goes to [−1, 1]²",
            "M_vp ← [Lv/2 0 (xv_max+xv_min)/2; 0 Hv/2 (yv_max+yv_min)/2; 0 0 1]",
            "for each point:  P_device ← M_vp P_ndc       ▷ [−1, 1]² goes to the viewport",
            "M ← M_vp · M_ndc                              ▷ window to device in one matrix",
        },
        {
            {"aspect-match", "window and viewport have the same aspect ratio: no distortion"},
            {"distortion", "the aspect ratios differ: x and y scale differently, shapes stretch"},
            {"window-to-ndc", "the matrix taking the window to the NDC square [−1, 1]²"},
            {"point-to-ndc", "one point mapped to NDC"},
            {"ndc-to-viewport", "the matrix taking the NDC square to the viewport"},
            {"point-to-device", "one point mapped from NDC to device coordinates"},
            {"compose", "the two matrices multiplied: window to device in one step"},
        },
        {},  // no sliders
        {
            .predict = {
                {"window-to-ndc", {"M_ndc"}},
                {"point-to-ndc", {"P_ndc"}},
                {"ndc-to-viewport", {"M_vp"}},
                {"point-to-device", {"P_device"}},
            },
            .mistakes = {
                {"distortion", "distorted", "not",
                 "compared the sizes, not the aspect ratios, and missed the stretch"},
                {"window-to-ndc", "M_ndc", "transpose",
                 "put the offsets in the bottom row, as for row vectors"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void WindowViewport::validate(const Input& in) {
    check_rect(in.window, "window", Form::Rect, "");
    // The viewport's corners may come in either order when the input says it means a flip.
    const std::string flip_hint =
        "; for a device whose y runs downward add \"y_down\": true, or give the images of the "
        "window's corners as \"corners\": [[x, y], [x, y]]";
    check_rect(in.viewport, "viewport", in.form, flip_hint);
    for (std::size_t k = 0; k < in.points.size(); ++k) {
        check_finite(in.points[k].x, "points[" + std::to_string(k) + "][0]");
        check_finite(in.points[k].y, "points[" + std::to_string(k) + "][1]");
    }
    // Sizes, scales and shifts must stay finite too (1e308 − (−1e308) overflows; 2/1e-320 too).
    for (const char* name : {"window", "viewport"}) {
        const Rect& r = name[0] == 'w' ? in.window : in.viewport;
        const dmat3 m = name[0] == 'w' ? ndc_from(r) : device_from(r);
        if (!std::isfinite(width(r)) || !std::isfinite(height(r)) || !finite(m) ||
            m[0][0] == 0 || m[1][1] == 0)
            throw InputError(name, "is too large or too small to map (" + given(width(r)) + " × " +
                                       given(height(r)) + ")");
    }
    // ... and so must the whole map and the points through it (a tiny window on a huge viewport
    // scales by 1e600).
    const dmat3 n = ndc_from(in.window), m = device_from(in.viewport) * n;
    if (!finite(m))
        throw InputError("viewport", "is too large for this window: the map's scale overflows");
    for (std::size_t k = 0; k < in.points.size(); ++k) {
        const glm::dvec3 p(in.points[k], 1.0);
        const glm::dvec3 q = n * p, d = m * p;
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(d.x) || !std::isfinite(d.y))
            throw InputError("points[" + std::to_string(k) + "]",
                             "maps outside the range of numbers (its coordinates overflow)");
    }
}

WindowViewport::State WindowViewport::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

WindowViewport::State WindowViewport::begin(Shared<Input> in) {
    State s;
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

// The algorithm proper: one step of the math. Kept apart from the narration below so that
// running to completion (no StepInfo) costs about what the plain map() does.
void WindowViewport::advance(State& s) {
    s.last = s.phase;
    const int n = static_cast<int>(s.in->points.size());
    switch (s.phase) {
        case Phase::Aspect:  // Compare the shapes of window and viewport
            s.aspect_window = std::fabs(width(s.in->window) / height(s.in->window));
            s.aspect_viewport = std::fabs(width(s.in->viewport) / height(s.in->viewport));
            s.distorted = aspects_differ(s.aspect_window, s.aspect_viewport);
            s.phase = Phase::NdcMatrix;
            return;
        case Phase::NdcMatrix:  // The window-to-NDC matrix
            s.ndc_from_window = ndc_from(s.in->window);
            s.ndc.reserve(s.in->points.size());
            s.k = -1;
            s.phase = n > 0 ? Phase::ToNdc : Phase::DeviceMatrix;
            return;
        case Phase::ToNdc:  // Map one point to NDC
            ++s.k;
            s.ndc.push_back(to_ndc(s.in->window, s.in->points[s.k]));
            if (s.k + 1 == n) s.phase = Phase::DeviceMatrix;
            return;
        case Phase::DeviceMatrix:  // The NDC-to-viewport matrix
            s.device_from_ndc = device_from(s.in->viewport);
            s.device.reserve(s.in->points.size());
            s.k = -1;
            s.phase = n > 0 ? Phase::ToDevice : Phase::Compose;
            return;
        case Phase::ToDevice:  // Map one point from NDC to the device
            ++s.k;
            s.device.push_back(to_device(s.in->viewport, s.ndc[s.k]));
            if (s.k + 1 == n) s.phase = Phase::Compose;
            return;
        case Phase::Compose:  // Window to device in one matrix
            s.device_from_window = s.device_from_ndc * s.ndc_from_window;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string matrix_text(const dmat3& m) {
    std::string t = "[";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) t += (c ? " " : "") + num(m[c][r]);
        t += r < 2 ? "; " : "]";
    }
    return t;
}

std::string matrix_tex(const dmat3& m) {
    std::string t = "\\begin{bmatrix} ";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) t += (c ? " & " : "") + tex(m[c][r]);
        t += r < 2 ? " \\\\ " : " \\end{bmatrix}";
    }
    return t;
}

// "2", "(−3)": a number after an operator.
std::string operand(double v) { return v < 0 ? "(" + num(v) + ")" : num(v); }

bool inside_ndc(dvec2 p) { return std::fabs(p.x) <= 1 && std::fabs(p.y) <= 1; }

std::string point_name(int k) { return "P" + std::to_string(k); }

// What a negative viewport size means, for the narration: "" when nothing is flipped.
std::string flip_note(const Rect& v) {
    const bool fx = flipped_x(v), fy = flipped_y(v);
    if (!fx && !fy) return "";
    std::string axes = fx && fy ? "Lv < 0 and Hv < 0: both axes are" : fx ? "Lv < 0: x is" : "Hv < 0: y is";
    return " " + axes + " flipped (a negative scale" +
           (fy ? ": the device's rows run downward, so the window's top lands on the smaller row"
               : "") +
           ").";
}

void narrate_aspect(const WindowViewport::State& s, StepInfo& info) {
    const Rect &w = s.in->window, &v = s.in->viewport;
    const double sx = width(v) / width(w), sy = height(v) / height(w);
    const std::string sizes = "Window " + num(width(w)) + " × " + num(height(w)) +
                              " (aspect Lw/Hw = " + num(s.aspect_window, 4) + "), viewport " +
                              num(width(v)) + " × " + num(height(v)) + (flipped_x(v) || flipped_y(v) ? " (aspect |Lv/Hv| = " : " (aspect Lv/Hv = ") +
                              num(s.aspect_viewport, 4) + ")";
    const bool flipped = flipped_x(v) != flipped_y(v);  // Lv/Hv < 0: compare its size
    info.math = "\\frac{L_w}{H_w} = \\frac{" + tex(width(w)) + "}{" + tex(height(w)) +
                "} = " + tex(s.aspect_window, 4) + (s.distorted ? " \\ne " : " = ") +
                tex(s.aspect_viewport, 4) + " = " + (flipped ? "\\left|" : "") + "\\frac{" +
                tex(width(v)) + "}{" + tex(height(v)) + "}" + (flipped ? "\\right|" : "") +
                " = " + (flipped ? "\\left|\\frac{L_v}{H_v}\\right|" : "\\frac{L_v}{H_v}");
    if (s.distorted) {
        info.event = "distortion";
        info.line = kLineAspect;
        info.narration = sizes + ": the aspect ratios differ. x will be scaled by Lv/Lw = " +
                         num(sx, 4) + " but y by Hv/Hw = " + num(sy, 4) +
                         ", so shapes come out stretched (a circle becomes an ellipse)." +
                         flip_note(v);
    } else {
        info.event = "aspect-match";
        info.line = kLineAspect;
        info.narration =
            sizes + ": the aspect ratios agree, " +
            (sx == sy ? "both axes scale by " + num(sx, 4)
                      : "x scales by " + num(sx, 4) + " and y by " + num(sy, 4) +
                            ", the same size") +
            " and shapes keep their proportions." + flip_note(v);
    }
}

void narrate_ndc_matrix(const WindowViewport::State& s, StepInfo& info) {
    const Rect& w = s.in->window;
    const dmat3& m = s.ndc_from_window;
    info.event = "window-to-ndc";
    info.line = kLineNdcMatrix;
    info.narration = "Window to NDC: scale x by 2/Lw = 2/" + num(width(w)) + " = " + num(m[0][0]) +
                     " and y by 2/Hw = 2/" + num(height(w)) + " = " + num(m[1][1]) +
                     ", then shift by −(xw_max + xw_min)/Lw = " + num(m[2][0]) +
                     " and −(yw_max + yw_min)/Hw = " + num(m[2][1]) + ": M_ndc = " +
                     matrix_text(m) + ". The corners " + num(dvec2(w.xmin, w.ymin)) + " and " +
                     num(dvec2(w.xmax, w.ymax)) + " go to (−1, −1) and (1, 1).";
    info.math =
        "M_{ndc} = \\begin{bmatrix} \\frac{2}{L_w} & 0 & -\\frac{x_{w,max} + x_{w,min}}{L_w} "
        "\\\\ 0 & \\frac{2}{H_w} & -\\frac{y_{w,max} + y_{w,min}}{H_w} \\\\ 0 & 0 & 1 "
        "\\end{bmatrix} = " +
        matrix_tex(m);
}

void narrate_to_ndc(const WindowViewport::State& s, StepInfo& info) {
    const Rect& w = s.in->window;
    const dvec2 p = s.in->points[s.k], q = s.ndc[s.k];
    info.event = "point-to-ndc";
    info.line = kLineToNdc;
    info.narration = point_name(s.k) + " = " + num(p) + ": x_ndc = 2·(" + num(p.x) + " − " +
                     operand(w.xmin) + ")/" + num(width(w)) + " − 1 = " + num(q.x) +
                     ", y_ndc = 2·(" + num(p.y) + " − " + operand(w.ymin) + ")/" + num(height(w)) +
                     " − 1 = " + num(q.y) + ", so " + point_name(s.k) + "_ndc = " + num(q) +
                     (inside_ndc(q) ? "."
                                    : ", outside [−1, 1]²: the point lies outside the window "
                                      "(mapping does not clip).");
    info.math = "M_{ndc} \\begin{bmatrix} " + tex(p.x) + " \\\\ " + tex(p.y) +
                " \\\\ 1 \\end{bmatrix} = \\begin{bmatrix} " + tex(q.x) + " \\\\ " + tex(q.y) +
                " \\\\ 1 \\end{bmatrix}";
}

void narrate_device_matrix(const WindowViewport::State& s, StepInfo& info) {
    const Rect& v = s.in->viewport;
    const dmat3& m = s.device_from_ndc;
    info.event = "ndc-to-viewport";
    info.line = kLineDeviceMatrix;
    info.narration = "NDC to viewport: scale x by Lv/2 = " + num(width(v)) +
                     "/2 = " + num(m[0][0]) + " and y by Hv/2 = " + num(height(v)) +
                     "/2 = " + num(m[1][1]) + ", then shift to the viewport's centre " +
                     num(dvec2(m[2][0], m[2][1])) + ": M_vp = " + matrix_text(m) +
                     ". (−1, −1) and (1, 1) go to " + num(dvec2(v.xmin, v.ymin)) + " and " +
                     num(dvec2(v.xmax, v.ymax)) + "." + flip_note(v);
    info.math = "M_{vp} = \\begin{bmatrix} \\frac{L_v}{2} & 0 & \\frac{x_{v,max} + x_{v,min}}{2} "
                "\\\\ 0 & \\frac{H_v}{2} & \\frac{y_{v,max} + y_{v,min}}{2} \\\\ 0 & 0 & 1 "
                "\\end{bmatrix} = " + matrix_tex(m);
}

void narrate_to_device(const WindowViewport::State& s, StepInfo& info) {
    const Rect& v = s.in->viewport;
    const dvec2 q = s.ndc[s.k], d = s.device[s.k];
    info.event = "point-to-device";
    info.line = kLineToDevice;
    info.narration = point_name(s.k) + "_ndc = " + num(q) + ": x_d = " + num(v.xmin) + " + (" +
                     num(q.x) + " + 1)·" + num(width(v)) + "/2 = " + num(d.x) + ", y_d = " +
                     num(v.ymin) + " + (" + num(q.y) + " + 1)·" + num(height(v)) + "/2 = " +
                     num(d.y) + ", so " + point_name(s.k) + "_device = " + num(d) + ".";
    info.math = "M_{vp} \\begin{bmatrix} " + tex(q.x) + " \\\\ " + tex(q.y) +
                " \\\\ 1 \\end{bmatrix} = \\begin{bmatrix} " + tex(d.x) + " \\\\ " + tex(d.y) +
                " \\\\ 1 \\end{bmatrix}";
}

void narrate_compose(const WindowViewport::State& s, StepInfo& info) {
    const dmat3& m = s.device_from_window;
    info.event = "compose";
    info.line = kLineCompose;
    info.narration = "Window to device in one matrix: M = M_vp · M_ndc = " + matrix_text(m) +
                     ", i.e. x_d = " + num(m[0][0]) + "·x + " + operand(m[2][0]) + ", y_d = " +
                     num(m[1][1]) + "·y + " + operand(m[2][1]) +
                     ": a scale by (Lv/Lw, Hv/Hw) and a shift, applied once per point.";
    info.math = "M = M_{vp} M_{ndc} = " + matrix_tex(s.device_from_ndc) +
                matrix_tex(s.ndc_from_window) + " = " + matrix_tex(m);
}

void fill_vars(const WindowViewport::State& s, StepInfo& info) {
    const Rect &w = s.in->window, &v = s.in->viewport;
    info.vars = {{"Lw", width(w)},
                 {"Hw", height(w)},
                 {"Lv", width(v)},
                 {"Hv", height(v)},
                 {"aspect_window", s.aspect_window},
                 {"aspect_viewport", s.aspect_viewport},
                 {"distorted", s.distorted}};
    if (s.last >= Phase::NdcMatrix) info.vars.push_back({"M_ndc", rows(s.ndc_from_window)});
    if (s.last >= Phase::DeviceMatrix) info.vars.push_back({"M_vp", rows(s.device_from_ndc)});
    if (s.last == Phase::Compose) info.vars.push_back({"M", rows(s.device_from_window)});
    if (s.last == Phase::ToNdc || s.last == Phase::ToDevice) {
        info.vars.push_back({"k", static_cast<long long>(s.k)});
        info.vars.push_back({"P", vec(s.in->points[s.k])});
        info.vars.push_back({"P_ndc", vec(s.ndc[s.k])});
        if (s.last == Phase::ToDevice) info.vars.push_back({"P_device", vec(s.device[s.k])});
    }
}

}  // namespace

// What the step just taken means, told with its numbers. `s` is the state after the step.
void WindowViewport::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Aspect: narrate_aspect(s, info); break;
        case Phase::NdcMatrix: narrate_ndc_matrix(s, info); break;
        case Phase::ToNdc: narrate_to_ndc(s, info); break;
        case Phase::DeviceMatrix: narrate_device_matrix(s, info); break;
        case Phase::ToDevice: narrate_to_device(s, info); break;
        case Phase::Compose:
        case Phase::Done: narrate_compose(s, info); break;
    }
    fill_vars(s, info);
}

void WindowViewport::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and map] -----------------------------------------------------------------------

WindowViewport::Result WindowViewport::result(const State& s) { return result(State(s)); }

// The spent state's lists move into the result, as map() builds its own in place.
WindowViewport::Result WindowViewport::result(State&& s) {
    Result r;
    r.ndc = std::move(s.ndc);
    r.device = std::move(s.device);
    r.ndc_from_window = s.ndc_from_window;
    r.device_from_ndc = s.device_from_ndc;
    r.device_from_window = s.device_from_window;
    r.distorted = s.distorted;
    r.aspect_window = s.aspect_window;
    r.aspect_viewport = s.aspect_viewport;
    return r;
}

// Flattened like run_to_end, so that the comparison is between two fully inlined loops.
[[gnu::flatten]] WindowViewport::Result WindowViewport::map(const Input& in) {
    Result r;
    r.aspect_window = std::fabs(width(in.window) / height(in.window));
    r.aspect_viewport = std::fabs(width(in.viewport) / height(in.viewport));
    r.distorted = aspects_differ(r.aspect_window, r.aspect_viewport);
    r.ndc_from_window = ndc_from(in.window);
    r.device_from_ndc = device_from(in.viewport);
    r.ndc.reserve(in.points.size());
    r.device.reserve(in.points.size());
    for (const dvec2 p : in.points) r.ndc.push_back(to_ndc(in.window, p));
    for (const dvec2 q : r.ndc) r.device.push_back(to_device(in.viewport, q));
    r.device_from_window = r.device_from_ndc * r.ndc_from_window;
    return r;
}

// The picture: window_viewport_draw.cpp.

}  // namespace cg
