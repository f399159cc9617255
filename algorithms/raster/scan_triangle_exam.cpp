// Triangle scan conversion exam problems: a grid of 8 to 12 by 8 to 10 pixels and a triangle
// whose vertices are whole or half numbers, so centres land exactly on edges and vertices as
// often as exams like. The triangle is drawn again until every inverse slope and the split
// point are short decimals (multiples of 1/1000), so each x_left and x_right can be worked by
// hand, and until it fills 8 to 40 pixels. About one problem in four is a case exams single
// out: a flat bottom or flat top (no split needed), three collinear vertices (nothing to
// fill), or a vertex outside the grid (spans are clipped).
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "raster/scan_triangle.hpp"

namespace cg {

namespace {

using glm::dvec2;

constexpr int kAttempts = 500;  // draws before the fixed problem is used

enum class Kind { General, FlatBottom, FlatTop, Collinear, Outside };

bool short_decimal(double x) { return std::fabs(x * 1000 - std::round(x * 1000)) < 1e-6; }

// A whole number, or now and then a half, in [lo, hi].
double coordinate(Rng& rng, int lo, int hi) {
    if (rng.chance(0.35) && hi > lo) return static_cast<double>(rng.integer(lo, hi - 1)) + 0.5;
    return static_cast<double>(rng.integer(lo, hi));
}

ScanTriangle::Input draw_one(Rng& rng, Kind kind, int w, int h) {
    ScanTriangle::Input in;
    in.width = w;
    in.height = h;
    dvec2 a{coordinate(rng, 0, w), coordinate(rng, 0, h)};
    dvec2 b{coordinate(rng, 0, w), coordinate(rng, 0, h)};
    dvec2 c{coordinate(rng, 0, w), coordinate(rng, 0, h)};
    switch (kind) {
        case Kind::FlatBottom: b.y = a.y = std::min(a.y, c.y - 2); break;
        case Kind::FlatTop: b.y = a.y = std::max(a.y, c.y + 2); break;
        case Kind::Collinear: {
            const dvec2 d{static_cast<double>(rng.integer(-3, 3)),
                          static_cast<double>(rng.integer(1, 3))};
            b = a + d * static_cast<double>(rng.integer(1, 2));
            c = a - d;
            break;
        }
        case Kind::Outside:
            if (rng.chance(0.5))
                c.x = rng.chance(0.5) ? -static_cast<double>(rng.integer(1, 3))
                                      : w + static_cast<double>(rng.integer(1, 3));
            else
                c.y = rng.chance(0.5) ? -static_cast<double>(rng.integer(1, 2))
                                      : h + static_cast<double>(rng.integer(1, 2));
            break;
        case Kind::General: break;
    }
    in.triangle = {a, b, c};
    return in;
}

bool acceptable(const ScanTriangle::Input& in, Kind kind) {
    try {
        ScanTriangle::validate(in);
    } catch (const InputError&) {
        return false;
    }
    const ScanTriangle::Result r = ScanTriangle::scan(in);
    bool outside = false;
    for (const dvec2 p : in.triangle)
        outside = outside || p.x < 0 || p.y < 0 || p.x > in.width || p.y > in.height;
    if (outside != (kind == Kind::Outside)) return false;
    if (kind == Kind::Collinear) return !r.split;
    if (!r.split || !short_decimal(r.split->x)) return false;
    for (const auto& m : r.inverse_slopes)
        if (m && !short_decimal(*m)) return false;
    const bool flat = !r.inverse_slopes[1] || !r.inverse_slopes[2];
    if ((kind == Kind::FlatBottom || kind == Kind::FlatTop) != flat) return false;
    return r.pixels.size() >= 8 && r.pixels.size() <= 40;
}

}  // namespace

ScanTriangle::Input ScanTriangle::exam_input(Rng& rng) {
    const int w = static_cast<int>(rng.integer(8, 12)), h = static_cast<int>(rng.integer(8, 10));
    Kind kind = Kind::General;
    switch (rng.integer(0, 15)) {
        case 0: kind = Kind::FlatBottom; break;
        case 1: kind = Kind::FlatTop; break;
        case 2: kind = Kind::Collinear; break;
        case 3: kind = Kind::Outside; break;
        default: break;
    }
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        Input in = draw_one(rng, kind, w, h);
        if (acceptable(in, kind)) return in;
    }
    Input in;  // the fallback: the example's triangle
    in.width = 10;
    in.height = 8;
    in.triangle = {{1.5, 0.5}, {8, 3}, {3, 7.5}};
    return in;
}

std::string ScanTriangle::question(const Input& in) {
    std::string q = "Scan-convert the triangle P0 = " + num(in.triangle[0]) + ", P1 = " +
                    num(in.triangle[1]) + ", P2 = " + num(in.triangle[2]) + " on a grid of " +
                    std::to_string(in.width) + " × " + std::to_string(in.height) +
                    " pixels. Pixel (i, j) covers [i, i+1) × [j, j+1) with y up and is filled "
                    "when its centre (i + ½, j + ½) is inside; a centre exactly on a left edge or "
                    "a horizontal top edge counts as inside, on a right edge or a horizontal "
                    "bottom edge as outside. Sort the vertices by y (v0, v1, v2), give the split "
                    "point [x_split, y1] where the line y = y1 meets the long edge v0→v2, and the "
                    "inverse slopes dx/dy of v0→v2, v0→v1 and v1→v2 (null for a horizontal edge; "
                    "give null for both if the vertices are collinear). Then for each scanline j "
                    "compute x_left and x_right at y = j + ½ and the pixels i with "
                    "x_left ≤ i + ½ < x_right inside the grid: give the spans as [j, i_first, "
                    "i_last] for the scanlines that fill pixels, and the list of pixels [i, j] "
                    "sorted by j, then i.";
    if (!in.colors.empty()) q += " (The vertex colours do not change which pixels are filled.)";
    return q;
}

std::vector<std::string> ScanTriangle::answer_fields() {
    return {"split", "inverse_slopes", "spans", "pixels"};
}

}  // namespace cg
