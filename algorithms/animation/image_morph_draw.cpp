// Image morphing, the picture: six image panels of the same size, each pixel-exact with its title
// above it. Top: image A with its feature lines, image B with its own, and the morph of the
// current frame (rows not yet made pale blue, the row just made outlined and marked as the
// step's subject). Bottom: A warped onto the interpolated lines, B warped onto them,
// and the plain cross-dissolve for contrast. The interpolated lines are drawn on the three warped
// panels; every line is an arrow P → Q labelled with its index. On the row just made, the
// narrated pixel X is marked in the morph and its sources X'_A in A and X'_B in B. Grey values
// are shown over the range of A and B together (darkest black, brightest white).
#include <algorithm>
#include <cmath>

#include "animation/image_morph.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using Image = ImageMorph::Image;
using Line = ImageMorph::Line;

std::uint32_t grey_cell(double g) {
    const auto v = std::uint32_t(std::lround(std::clamp(g, 0.0, 255.0)));
    return (v << 24) | (v << 16) | (v << 8) | 0xffu;
}

// A row not made yet: pale blue, which no grey value is (white would read as a value of 255).
constexpr std::uint32_t kNotMade = 0xdce6f2ffu;

// An image's pixel coordinates (x right, y down from the top row) in its panel's cells (y up).
glm::dvec2 at(const Image& img, glm::dvec2 p) {
    return {p.x, img.height - p.y};
}

Panel& image(Scene& scene, std::string title, const Image& img, double lo, double hi, int rows) {
    PixelGrid2 g;
    g.width = img.width;
    g.height = img.height;
    g.grid_lines = img.width <= 12 && img.height <= 12;
    g.rgba.assign(img.v.size(), kNotMade);
    const double scale = hi > lo ? 255 / (hi - lo) : 0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < img.width; ++c)
            g.rgba[std::size_t(img.height - 1 - r) * std::size_t(img.width) + std::size_t(c)] =
                grey_cell(scale > 0 ? (img.at(c, r) - lo) * scale : 128);
    return add_image(scene, std::move(title), std::move(g));
}

void lines(Panel& panel, const Image& img, const std::vector<Line>& ls, Role role) {
    for (std::size_t i = 0; i < ls.size(); ++i)
        panel.segments.push_back({at(img, ls[i].p), at(img, ls[i].q),
                                  ls.size() <= 8 ? std::to_string(i) : std::string(),
                                  {role, 2.5f}, true});
}

}  // namespace

void ImageMorph::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Frame& f = s.frames.back();
    const int w = in.image_a.width;
    double lo = 1e300, hi = -1e300;
    for (const Image* img : {&in.image_a, &in.image_b})
        for (double g : img->v) lo = std::min(lo, g), hi = std::max(hi, g);
    const int made = s.row;
    const Image& ia = in.image_a;
    // The panels in the lecture's order (the viewer lays six out three by two).
    image(scene, "A (its lines)", in.image_a, lo, hi, in.image_a.height);
    image(scene, "B (its lines)", in.image_b, lo, hi, in.image_b.height);
    image(scene, "morph, α = " + num(f.alpha, 3), f.morph, lo, hi, made);
    image(scene, "A warped", f.warped_a, lo, hi, made);
    image(scene, "B warped", f.warped_b, lo, hi, made);
    image(scene, "plain dissolve", f.dissolve, lo, hi, made);
    Panel &pa = scene.panels[0], &pb = scene.panels[1], &pm = scene.panels[2];
    std::vector<Line> la, lb;
    for (const Pair& p : in.lines) la.push_back(p.a), lb.push_back(p.b);
    lines(pa, ia, la, Role::Kept);
    lines(pb, in.image_b, lb, Role::Entering);
    for (std::size_t k : {2, 3, 4}) lines(scene.panels[k], ia, f.lines, Role::Active);
    if (s.last == Phase::Row && made > 0) {
        // The row just made, and its narrated pixel traced back into A and B.
        const int r = made - 1;
        const glm::dvec2 o = at(ia, {0, double(r + 1)});
        pm.polygons.push_back({{o, o + glm::dvec2(w, 0), o + glm::dvec2(w, 1), o + glm::dvec2(0, 1)},
                               {Role::Window, 2.0f},
                               true,
                               false});
        const Focus p = focus(in, f, in.focus_x, r);
        pm.points.push_back({at(ia, p.centre), "X", {Role::Active}, 5.0f});
        pa.points.push_back({at(ia, p.a.source), "X'_A", {Role::Kept}, 5.0f});
        pb.points.push_back({at(in.image_b, p.b.source), "X'_B", {Role::Entering}, 5.0f});
        add_focus(scene, o, o + glm::dvec2(w, 1), 2);
    }
}

}  // namespace cg
