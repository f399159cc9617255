// The canvas's grid, axes and tick labels.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "core/format.hpp"
#include "viewer/canvas_draw.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/palette.hpp"

namespace cg::viewer {

namespace {

constexpr double kMajorPixels = 70;  // the least distance between labelled grid lines
constexpr double kMaxLines = 400;    // per direction; more would only be a grey smear

// A crisp 1-pixel line sits on a pixel centre.
float pixel_centre(double v) {
    return static_cast<float>(std::floor(v) + 0.5);
}

// The subdivisions that keep a 1/2/5 step round: 1 → 0.2, 2 → 0.5, 5 → 1.
int subdivisions(double step) {
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
    return mantissa > 1.5 && mantissa < 3 ? 4 : 5;
}

}  // namespace

double nice_step(double at_least) {
    const double decade = std::pow(10.0, std::floor(std::log10(at_least)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= at_least * (1 - 1e-9)) return m * decade;
    return 10 * decade;
}

void draw_grid(ImDrawList* dl, const ScreenMap& map, const Fonts& fonts) {
    const Box& c = map.canvas;
    const glm::dvec2 lo = map.to_world({c.min.x, c.max.y}), hi = map.to_world({c.max.x, c.min.y});
    const double step = nice_step(kMajorPixels / map.view.zoom);
    const double fine_step = step / subdivisions(step);

    // Lines at every multiple of `step` in view; `label` also writes the tick numbers.
    auto lines = [&](double step, ImU32 colour, bool label) {
        const double x0 = std::ceil(lo.x / step), x1 = std::floor(hi.x / step);
        const double y0 = std::ceil(lo.y / step), y1 = std::floor(hi.y / step);
        if (x1 - x0 > kMaxLines || y1 - y0 > kMaxLines) return;
        const glm::dvec2 origin = map.to_screen({0, 0});
        const float size = fonts.small->FontSize;
        const ImU32 text = im_colour(kTickLabel);
        for (double i = x0; i <= x1; ++i) {
            const float x = pixel_centre(map.to_screen({i * step, 0}).x);
            dl->AddLine({x, float(c.min.y)}, {x, float(c.max.y)}, colour);
            if (!label || i == 0) continue;
            const std::string t = num(i * step);
            // Under the x axis, or along the canvas's bottom or top edge when it is off screen.
            const double y = std::clamp(origin.y + 3, c.min.y + 2, c.max.y - size - 2);
            dl->AddText(fonts.small, size, {x + 3, float(y)}, text, t.c_str());
        }
        for (double i = y0; i <= y1; ++i) {
            const float y = pixel_centre(map.to_screen({0, i * step}).y);
            dl->AddLine({float(c.min.x), y}, {float(c.max.x), y}, colour);
            if (!label || i == 0) continue;
            const std::string t = num(i * step);
            const float w = fonts.small->CalcTextSizeA(size, FLT_MAX, 0, t.c_str()).x;
            const double x = std::clamp(origin.x - w - 4, c.min.x + 3, c.max.x - w - 3);
            dl->AddText(fonts.small, size, {float(x), y - size - 1}, text, t.c_str());
        }
        if (label && c.contains(origin))
            dl->AddText(fonts.small, size, {float(origin.x) - 10, float(origin.y) + 2}, text, "0");
    };
    if (fine_step * map.view.zoom >= 8) lines(fine_step, im_colour(kGridMinor), false);
    lines(step, im_colour(kGridMajor), true);

    // The axes, over the grid.
    const glm::dvec2 origin = map.to_screen({0, 0});
    const ImU32 axis = im_colour(kAxis);
    if (origin.x >= c.min.x && origin.x <= c.max.x) {
        const float x = pixel_centre(origin.x);
        dl->AddLine({x, float(c.min.y)}, {x, float(c.max.y)}, axis, 1.0f);
    }
    if (origin.y >= c.min.y && origin.y <= c.max.y) {
        const float y = pixel_centre(origin.y);
        dl->AddLine({float(c.min.x), y}, {float(c.max.x), y}, axis, 1.0f);
    }
}

}  // namespace cg::viewer
