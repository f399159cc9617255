// Window-to-viewport exam problems: a window with integer corners whose width and height are
// 2, 4, 5, 8 or 10 (so 2/Lw and every NDC coordinate of an integer point is a short decimal),
// a viewport in device pixels that is the window scaled by a round factor, and two to four
// integer points near the window. About one problem in three scales x and y differently
// (distorted); now and then a point lies outside the window (its NDC coordinates leave
// [−1, 1]) or sits on a corner, and now and then there are no points at all (only the matrices).
// One problem in four puts the viewport on a screen whose pixel rows run downward (y down), as
// exam questions do: the window's bottom edge goes to the viewport's largest row.
#include <algorithm>

#include "core/format.hpp"
#include "viewing/window_viewport.hpp"

namespace cg {

namespace {

using Form = WindowViewport::Form;

double pick(Rng& rng, std::initializer_list<int> values) {
    const auto k =
        static_cast<std::size_t>(rng.integer(0, static_cast<long long>(values.size()) - 1));
    return *(values.begin() + k);
}

}  // namespace

WindowViewport::Input WindowViewport::exam_input(Rng& rng) {
    Input in;
    Rect& w = in.window;
    const double lw = pick(rng, {2, 4, 5, 8, 10}), hw = pick(rng, {2, 4, 5, 8, 10});
    w.xmin = static_cast<double>(rng.integer(-5, 5));
    w.ymin = static_cast<double>(rng.integer(-5, 5));
    if (rng.chance(0.15)) w.xmin = -lw / 2, w.ymin = -hw / 2;  // centred on the origin
    w.xmax = w.xmin + lw;
    w.ymax = w.ymin + hw;

    Rect& v = in.viewport;
    const double sx = pick(rng, {10, 20, 25, 40, 50, 80, 100});
    double sy = sx;
    if (rng.chance(1.0 / 3))
        while (sy == sx) sy = pick(rng, {10, 20, 25, 40, 50, 80, 100});
    v.xmin = pick(rng, {0, 0, 10, 20, 50, 100});
    v.ymin = pick(rng, {0, 0, 10, 20, 50});
    v.xmax = v.xmin + sx * lw;
    v.ymax = v.ymin + sy * hw;

    const int n = rng.chance(1.0 / 16) ? 0 : static_cast<int>(rng.integer(2, 4));
    while (static_cast<int>(in.points.size()) < n) {
        glm::dvec2 p{static_cast<double>(rng.integer(static_cast<long long>(w.xmin),
                                                     static_cast<long long>(w.xmax))),
                     static_cast<double>(rng.integer(static_cast<long long>(w.ymin),
                                                     static_cast<long long>(w.ymax)))};
        if (rng.chance(0.1)) p = {w.xmax, w.ymax};                           // a corner
        if (rng.chance(0.1)) p.x = rng.chance(0.5) ? w.xmin - 1 : w.xmax + 1;  // outside
        if (std::find(in.points.begin(), in.points.end(), p) == in.points.end())
            in.points.push_back(p);
    }
    if (rng.chance(0.25)) {  // rows counted from the top: the window's ymin goes to row ymax
        in.form = Form::YDown;
        std::swap(v.ymin, v.ymax);
    }
    return in;
}

std::string WindowViewport::question(const Input& in) {
    auto range = [](double x0, double x1, double y0, double y1) {
        return "[" + num(x0) + ", " + num(x1) + "] × [" + num(y0) + ", " + num(y1) + "]";
    };
    const Rect &w = in.window, &v = in.viewport;
    std::string device;
    switch (in.form) {
        case Form::Rect:
            device = "the viewport " + range(v.xmin, v.xmax, v.ymin, v.ymax) +
                     " (device coordinates, y up)";
            break;
        case Form::YDown:
            device = "the viewport " + range(v.xmin, v.xmax, v.ymax, v.ymin) +
                     " of a screen whose pixel rows are numbered downward from the top (y down: "
                     "the window's bottom-left corner goes to " + num(glm::dvec2(v.xmin, v.ymin)) +
                     " and its top-right corner to " + num(glm::dvec2(v.xmax, v.ymax)) + ")";
            break;
        case Form::Corners:
            device = "the device, its corner " + num(glm::dvec2(w.xmin, w.ymin)) + " going to " +
                     num(glm::dvec2(v.xmin, v.ymin)) + " and " + num(glm::dvec2(w.xmax, w.ymax)) +
                     " to " + num(glm::dvec2(v.xmax, v.ymax));
            break;
    }
    std::string q = "Map the window " + range(w.xmin, w.xmax, w.ymin, w.ymax) +
                    " (world coordinates) to " + device +
                    " through normalised device coordinates, NDC = "
                    "[−1, 1] × [−1, 1]. Give the 3×3 homogeneous matrices (as rows, acting on "
                    "column vectors (x, y, 1)) window_to_ndc and ndc_to_device, and their product "
                    "matrix (window to device)";
    if (in.points.empty()) {
        q += ".";
    } else {
        q += "; map the points ";
        for (std::size_t k = 0; k < in.points.size(); ++k)
            q += (k ? ", " : "") + std::string("P") + std::to_string(k) + " = " + num(in.points[k]);
        q += " to NDC (ndc) and then to the device (device).";
    }
    q += " Does the mapping distort shapes (distorted: compare the aspect ratios width/height)?";
    return q;
}

std::vector<std::string> WindowViewport::answer_fields() {
    return {"window_to_ndc", "ndc", "ndc_to_device", "device", "matrix", "distorted"};
}

}  // namespace cg
