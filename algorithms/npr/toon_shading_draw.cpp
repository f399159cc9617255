// Toon shading, the picture. In 3D: the faces shaded so far, each filled flat in its band's
// colour (with its band number on a small mesh), the faces still to come faint; the face being
// shaded outlined orange with N̂ (orange) and L̂ (blue) from its centre, at least 30 px long; the
// light's direction beside the mesh. The camera is framed on the face and its two vectors.
// Beside it a chart of the rule itself: the 1D texture as a staircase — band b's colour over
// its cell [t_b, t_{b+1}) of u = d = max(0, N̂·L̂), at height b — with every face shaded so far
// as a dot at (d, band) and the current one large and orange, so the quantisation reads off
// the chart.
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "npr/toon_shading.hpp"

namespace cg {

void ToonShading::draw(const State& s, Scene& scene) {
    const auto& in = *s.in;
    const auto& m = in.mesh;
    const std::vector<glm::dvec3> colours =
        in.colours.empty() ? default_colours(static_cast<int>(in.thresholds.size()) + 1)
                           : in.colours;
    const auto [mid, size] = npr::bounds(m);
    const int shaded = static_cast<int>(s.r.band.size());
    const int current = s.last == Phase::Face && s.k > 0 && s.phase != Phase::Done ? s.k - 1 : -1;
    const bool small = m.faces.size() <= 24;
    auto centroid = [&](const std::vector<int>& f) {
        glm::dvec3 c{0, 0, 0};
        for (int i : f) c += m.vertices[static_cast<std::size_t>(i)];
        return c / static_cast<double>(f.size());
    };
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        Face3 face;
        for (int i : m.faces[k]) face.points.push_back(m.vertices[static_cast<std::size_t>(i)]);
        face.two_sided = false;
        if (static_cast<int>(k) < shaded) {
            const int b = s.r.band[k];
            face.style = {Role::Subject, 1.0f, false,
                          pack_rgba(colours[static_cast<std::size_t>(b)])};
            face.alpha = 1.0f;
            face.outline = small;
        } else {
            face.style = {Role::Neutral, 1.0f};
            face.alpha = 0.08f;
        }
        if (static_cast<int>(k) == current) face.style.width = 3.0f, face.outline = true;
        scene.faces3.push_back(std::move(face));
        if (small && static_cast<int>(k) < shaded && static_cast<int>(k) != current)
            scene.labels3.push_back(
                {centroid(m.faces[k]), std::to_string(s.r.band[k]), {Role::Neutral}});
    }
    // The light: an arrow pointing along L̂ towards the light, outside the mesh.
    const glm::dvec3 l = s.l;
    scene.segments3.push_back({mid + 0.6 * size * l, mid + 0.95 * size * l, "towards the light",
                               {Role::Window, 2.5f}, true});
    if (current >= 0) {
        const auto& f = m.faces[static_cast<std::size_t>(current)];
        const glm::dvec3 c = centroid(f);
        Segment3 n{c, c + 0.3 * size * s.n, "N̂", {Role::Active, 3.0f}, true};
        Segment3 ll{c, c + 0.3 * size * s.l, "L̂", {Role::Window, 2.5f}, true};
        n.min_pixels = ll.min_pixels = 30;
        n.priority = ll.priority = 20;
        scene.segments3.push_back(n);
        scene.segments3.push_back(ll);
        // Outline the current face on top, with its band.
        Face3 top;
        glm::dvec3 lo = c, hi = c;
        for (int i : f) {
            const glm::dvec3 p = m.vertices[static_cast<std::size_t>(i)];
            top.points.push_back(p);
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        top.style = {Role::Active, 3.0f};
        top.alpha = 0.0f;
        scene.faces3.push_back(std::move(top));
        // The face with its two vectors, and enough of the mesh around it to see where it is.
        const double reach = 0.45 * size;
        for (const glm::dvec3 p : {n.b, ll.b}) lo = glm::min(lo, p), hi = glm::max(hi, p);
        add_focus(scene, glm::min(lo, c - reach), glm::max(hi, c + reach));
    }

    // The rule as a chart: band against u = d, the texture's cells as a staircase.
    const auto& t = in.thresholds;
    const int bands = static_cast<int>(t.size()) + 1;
    Axis band_axis{"band", -0.6, bands - 0.4};
    band_axis.step = 1;  // whole bands: 0, 1, 2, …
    Panel& chart = add_chart(scene, "the 1D texture: band against u",
                             Axis{"u = d = max(0, N̂·L̂)", 0, 1}, band_axis);
    for (int b = 0; b < bands; ++b) {
        const double u0 = b == 0 ? 0 : t[static_cast<std::size_t>(b - 1)];
        const double u1 = b == bands - 1 ? 1 : t[static_cast<std::size_t>(b)];
        // (An alpha just under 1: the fill as given, not a role's faint one.)
        const Style cell{Role::Neutral, 1.0f, false,
                         pack_rgba(colours[static_cast<std::size_t>(b)], 0.99)};
        chart.polygons.push_back(
            {{{u0, b - 0.3}, {u1, b - 0.3}, {u1, b + 0.3}, {u0, b + 0.3}}, cell, true, true});
        if (b > 0)  // the threshold: where the staircase steps up
            chart.segments.push_back({{u0, -0.6},
                                      {u0, b + 0.3},
                                      "t" + std::to_string(b) + " = " + num(u0, 3),
                                      {Role::Construction, 1.0f, true}});
    }
    std::vector<glm::dvec2> done;
    for (int k = 0; k < shaded; ++k)
        if (k != current)
            done.push_back({std::max(0.0, s.r.ndotl[static_cast<std::size_t>(k)]),
                            s.r.band[static_cast<std::size_t>(k)]});
    if (!done.empty()) add_dots(chart, done, {Role::Neutral, 1.0f}, "faces shaded", 3.0f);
    if (current >= 0) {
        const double d = std::max(0.0, s.ndotl);
        chart.points.push_back({{d, double(s.band)},
                                "d = " + num(d, 3) + " → band " + std::to_string(s.band),
                                {Role::Active, 2.0f},
                                6.0f,
                                30});
        chart.legend.push_back({"this face", {Role::Active, 2.0f}, true});
    }
}

}  // namespace cg
