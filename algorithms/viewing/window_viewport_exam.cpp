// Window-to-viewport exam problems: a window with integer corners whose width and height are
// 2, 4, 5, 8 or 10 (so 2/Lw and every NDC coordinate of an integer point is a short decimal),
// a viewport in device pixels that is the window scaled by a round factor, and two to four
// integer points near the window. About one problem in three scales x and y differently
// (distorted); now and then a point lies outside the window (its NDC coordinates leave
// [−1, 1]) or sits on a corner, and now and then there are no points at all (only the matrices).
#include <algorithm>

#include "core/format.hpp"
#include "viewing/window_viewport.hpp"

namespace cg {

namespace {

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
    return in;
}

std::string WindowViewport::question(const Input& in) {
    auto range = [](const Rect& r) {
        return "[" + num(r.xmin) + ", " + num(r.xmax) + "] × [" + num(r.ymin) + ", " + num(r.ymax) +
               "]";
    };
    std::string q = "Map the window " + range(in.window) + " (world coordinates) to the viewport " +
                    range(in.viewport) +
                    " (device coordinates, y up) through normalised device coordinates, NDC = "
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
