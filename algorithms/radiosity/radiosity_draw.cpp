// Radiosity, the picture. The 3D view: every patch shaded by its current B (tone-mapped as the
// camera's image), seen from behind the camera and a little above it when the camera is inside
// a closed room (else from above, obliquely), the walls that face away from that view drawn
// faint so the inside shows. While the form factors are
// computed (phase 1): patch i outlined in orange and every other patch shaded by F_ij (bright:
// much of i's view), an image panel with the matrix F filling in row by row, row i outlined,
// and a bar chart of the row sums so far against 1 (a closed scene). While solving (phase 2): the
// shooter outlined (progressive), an image panel with the camera's picture, and a chart of the
// residual per step on a log axis against the tolerance.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "core/format.hpp"
#include "radiosity/radiosity.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Phase = Radiosity::Phase;
using Method = Radiosity::Method;
using Scene3 = Radiosity::Scene3;

std::vector<dvec3> outline(const Patch& p) {
    if (p.type == Patch::Type::Triangle) return {p.a, p.b, p.c};
    return {p.a, p.a + p.b, p.a + p.b + p.c, p.a + p.c};
}

std::uint32_t grey(double v) {
    const auto g = std::uint32_t(std::lround(255 * std::clamp(v, 0.0, 1.0)));
    return g << 24 | g << 16 | g << 8 | 0xffu;
}

constexpr std::size_t kMaxMatrix = 128;          // the matrix is drawn up to this many patches
constexpr std::uint32_t kPending = 0xdbe7f5ffu;  // a row not computed yet: pale blue

}  // namespace

void Radiosity::draw(const State& s, cg::Scene& scene) {
    const Scene3& sc = *s.scene;
    const Input& in = *s.in;
    const std::size_t n = sc.patches.size();
    const bool rows = s.last == Phase::FormFactors;  // phase 1 (or the start)
    const bool row_now = rows && s.row >= 0;
    const std::vector<std::uint32_t> colours = [&] {
        // One colour per patch: B through the image's tone mapping (one pixel per patch).
        Scene3 flat;
        flat.emission = sc.emission;
        flat.pixel.resize(n);
        for (std::size_t k = 0; k < n; ++k) flat.pixel[k] = int(k);
        return image(flat, s.B);
    }();

    // ---- 3D: from in front of the camera and a little above it when the camera is inside
    // the scene (a closed room), else from above the +x/+z quadrant ----
    dvec3 lo(1e300), hi(-1e300);
    for (const Patch& p : sc.patches)
        for (const dvec3& q : outline(p)) lo = glm::min(lo, q), hi = glm::max(hi, q);
    const Camera& cam = in.camera;
    const bool inside =
        glm::all(glm::greaterThan(cam.position, lo)) && glm::all(glm::lessThan(cam.position, hi));
    dvec3 look(-0.55, -0.4, -0.75), up(0, 1, 0);
    if (inside) {
        const dvec3 d = glm::normalize(cam.target - cam.position);
        up = glm::normalize(cam.up - glm::dot(cam.up, d) * d);
        look = d - 0.45 * up;
    }
    look = glm::normalize(look);
    scene.view3 = {look, up, false};
    if (lo.x <= hi.x) add_focus(scene, lo, hi);
    double fmax = 0;
    if (row_now)
        for (std::size_t j = 0; j < n; ++j) fmax = std::max(fmax, s.F[std::size_t(s.row) * n + j]);
    for (std::size_t k = 0; k < n; ++k) {
        const Patch& p = sc.patches[k];
        // A wall whose front faces away from the view hides the inside: faint.
        const bool emits = glm::length(sc.emission[k]) > 0;
        const bool away = glm::dot(normal(p), look) > 1e-9 && !emits;
        Face3 f{outline(p), {Role::Subject, 0.5f}, away ? 0.12f : 0.9f, true, true};
        if (row_now) {
            const double v = s.F[std::size_t(s.row) * n + k];
            f.style.rgba = grey(fmax > 0 ? std::sqrt(v / fmax) : 0);
            if (int(k) == s.row) f.style = {Role::Active, 2.5f}, f.alpha = 0.9f;
        } else {
            f.style.rgba = colours[k];
            if (s.last == Phase::Solve && in.method == Method::Progressive && int(k) == s.shooter) {
                // The shooter keeps its colour (its B), outlined in orange.
                f.alpha = 0.9f;
                for (std::size_t q = 0; q < f.points.size(); ++q)
                    scene.segments3.push_back({f.points[q],
                                               f.points[(q + 1) % f.points.size()],
                                               "",
                                               {Role::Active, 3.0f}});
                scene.labels3.push_back({centre(p), "shooter", {Role::Active}});
            }
        }
        scene.faces3.push_back(std::move(f));
    }
    if (row_now) {
        // Patch i's normal: the hemisphere its form factors are taken over.
        const Patch& p = sc.patches[std::size_t(s.row)];
        Segment3 nrm{
            centre(p), centre(p) + 0.15 * extent(p) * normal(p), "i", {Role::Active, 2.0f}, true};
        nrm.min_pixels = 30;
        nrm.priority = 20;
        scene.segments3.push_back(nrm);
    }

    if (rows) {
        // ---- the matrix F, row i at the top as it is written, bright where F_ij is large ----
        if (n <= kMaxMatrix) {
            PixelGrid2 m;
            m.width = m.height = int(n);
            m.rgba.assign(n * n, kPending);
            double top = 0;
            for (double v : s.F) top = std::max(top, v);
            for (std::size_t i = 0; i < n && int(i) <= s.row; ++i)
                for (std::size_t j = 0; j < n; ++j)
                    m.rgba[(n - 1 - i) * n + j] =
                        grey(top > 0 ? std::sqrt(s.F[i * n + j] / top) : 0);
            m.grid_lines = n <= 32;
            Panel& panel = add_image(scene, "form factors F_ij (bright = large)", std::move(m));
            panel.weight = 0.65;
            if (row_now) {
                const double y = double(n - 1 - std::size_t(s.row));
                panel.polygons.push_back({{{0, y}, {double(n), y}, {double(n), y + 1}, {0, y + 1}},
                                          {Role::Active, 2.5f}});
                panel.labels.push_back(
                    {{double(n) / 2, y + 0.5}, "row i = " + std::to_string(s.row), {Role::Active}});
            }
        }
        // ---- the row sums so far: 1 in a closed enclosure ----
        double most = 1.2;
        for (int i = 0; i <= s.row; ++i) most = std::max(most, row_sum(s.F, n, i) * 1.05);
        Panel& sums = add_chart(scene, "row sum Σ_j F_ij of each patch i",
                                Axis{"", -0.5, double(n) - 0.5}, Axis{"", 0, most});
        sums.weight = 0.5;
        add_line(sums, {{-0.5, 1}, {double(n) - 0.5, 1}}, {Role::Window, 1.5f, true});
        sums.labels.push_back({{double(n) - 0.5, 1}, "closed: 1", {Role::Window}});
        for (int i = 0; i <= s.row; ++i)
            add_bars(sums, {{double(i), row_sum(s.F, n, i)}}, 0.8,
                     {i == s.row ? Role::Active : Role::Kept, 1.0f});
        return;
    }

    // ---- the camera's picture ----
    PixelGrid2 img;
    img.width = cam.width;
    img.height = cam.height;
    img.rgba = image(sc, s.B);
    img.grid_lines = false;
    Panel& picture = add_image(scene, "the camera's image", std::move(img));
    picture.weight = 0.65;

    // ---- the residual per step, log y, against the tolerance ----
    Panel& chart =
        add_chart(scene, "residual max |ΔB| per step (log)", Axis{}, Axis{"", 0, 0, true});
    chart.weight = 0.5;
    const double last = std::max<double>(1, double(s.history.size()));
    add_line(chart, {{0, in.tolerance}, {last, in.tolerance}}, {Role::Window, 1.5f, true});
    chart.labels.push_back({{0, in.tolerance}, "tolerance", {Role::Window}});
    std::vector<dvec2> pts;
    for (std::size_t q = 0; q < s.history.size(); ++q) pts.push_back({double(q + 1), s.history[q]});
    if (!pts.empty()) {
        add_line(chart, pts, {Role::Active, 2.0f});
        if (pts.back().y > 0) chart.points.push_back({pts.back(), "", {Role::Active}, 5.0f});
    }
}

}  // namespace cg
