// Image morphing, the picture (2D): six panels of the same size. Top: image A with its feature
// lines, image B with its own, and the morph of the current frame (rows not yet made left empty,
// the row just made outlined). Bottom: A warped onto the interpolated lines, B warped onto them,
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

struct Place {
    glm::dvec2 origin;  // the lower left corner, in the scene
    int height;
    glm::dvec2 at(glm::dvec2 p) const { return origin + glm::dvec2(p.x, height - p.y); }
};

void image(Scene& scene, const Place& panel, const Image& img, double lo, double hi, int rows) {
    PixelGrid2 g;
    g.origin = panel.origin;
    g.width = img.width;
    g.height = img.height;
    g.grid_lines = img.width <= 16 && img.height <= 16;
    g.rgba.assign(img.v.size(), 0);
    const double scale = hi > lo ? 255 / (hi - lo) : 0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < img.width; ++c)
            g.rgba[std::size_t(img.height - 1 - r) * std::size_t(img.width) + std::size_t(c)] =
                grey_cell(scale > 0 ? (img.at(c, r) - lo) * scale : 128);
    scene.grids.push_back(std::move(g));
    const double w = img.width, h = img.height;
    const glm::dvec2 o = panel.origin;
    scene.polygons.push_back({{o, o + glm::dvec2(w, 0), o + glm::dvec2(w, h), o + glm::dvec2(0, h)},
                              {Role::Subject, 1.0f},
                              true,
                              false});
}

void lines(Scene& scene, const Place& panel, const std::vector<Line>& ls, Role role) {
    for (std::size_t i = 0; i < ls.size(); ++i) {
        scene.segments.push_back({panel.at(ls[i].p), panel.at(ls[i].q),
                                  ls.size() <= 8 ? std::to_string(i) : std::string(),
                                  {role, 2.5f}, true});
    }
}

}  // namespace

void ImageMorph::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Frame& f = s.frames.back();
    const int w = in.image_a.width, h = in.image_a.height;
    const double gap = std::max(2.0, w / 5.0);
    const double label = std::max(0.6, h / 12.0);
    double lo = 1e300, hi = -1e300;
    for (const Image* img : {&in.image_a, &in.image_b})
        for (double g : img->v) lo = std::min(lo, g), hi = std::max(hi, g);
    const int made = s.row;
    const double top = h + gap;
    const Place pa{{0, top}, h}, pb{{w + gap, top}, h}, pm{{2 * (w + gap), top}, h};
    const Place wa{{0, 0}, h}, wb{{w + gap, 0}, h}, pd{{2 * (w + gap), 0}, h};
    image(scene, pa, in.image_a, lo, hi, h);
    image(scene, pb, in.image_b, lo, hi, h);
    image(scene, pm, f.morph, lo, hi, made);
    image(scene, wa, f.warped_a, lo, hi, made);
    image(scene, wb, f.warped_b, lo, hi, made);
    image(scene, pd, f.dissolve, lo, hi, made);
    std::vector<Line> la, lb;
    for (const Pair& p : in.lines) la.push_back(p.a), lb.push_back(p.b);
    lines(scene, pa, la, Role::Kept);
    lines(scene, pb, lb, Role::Entering);
    for (const Place* p : {&pm, &wa, &wb}) lines(scene, *p, f.lines, Role::Active);
    const std::string a = "α = " + num(f.alpha, 3);
    scene.labels.push_back({pa.origin + glm::dvec2(0, -label), "A (its lines)", {Role::Kept}});
    scene.labels.push_back({pb.origin + glm::dvec2(0, -label), "B (its lines)", {Role::Entering}});
    scene.labels.push_back({pm.origin + glm::dvec2(0, -label), "morph, " + a, {Role::Active}});
    scene.labels.push_back({wa.origin + glm::dvec2(0, -label), "A warped", {Role::Neutral}});
    scene.labels.push_back({wb.origin + glm::dvec2(0, -label), "B warped", {Role::Neutral}});
    scene.labels.push_back({pd.origin + glm::dvec2(0, -label), "plain dissolve", {Role::Neutral}});
    if (s.last == Phase::Row && made > 0) {
        // The row just made, and its narrated pixel traced back into A and B.
        const int r = made - 1;
        const glm::dvec2 o = pm.at({0, double(r + 1)});
        scene.polygons.push_back({{o, o + glm::dvec2(w, 0), o + glm::dvec2(w, 1), o + glm::dvec2(0, 1)},
                                  {Role::Window, 2.0f},
                                  true,
                                  false});
        const Focus p = focus(in, f, in.focus_x, r);
        scene.points.push_back({pm.at(p.centre), "X", {Role::Active}, 5.0f});
        scene.points.push_back({pa.at(p.a.source), "X'_A", {Role::Kept}, 5.0f});
        scene.points.push_back({pb.at(p.b.source), "X'_B", {Role::Entering}, 5.0f});
    }
}

}  // namespace cg
