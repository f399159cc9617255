#include "rays/texture_draw.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "core/format.hpp"
#include "rays/quadric_mesh.hpp"

namespace cg::texdraw {

using glm::dvec2;
using glm::dvec3;

Panel& add_image(const TextureImage& im, Scene& scene, const std::string& label, int& shown) {
    constexpr int kMaxShown = 128;  // cells on a side: a big image is shown every k-th texel
    const int k = std::max(1, (std::max(im.width, im.height) + kMaxShown - 1) / kMaxShown);
    PixelGrid2 g;
    g.width = (im.width + k - 1) / k;
    g.height = (im.height + k - 1) / k;
    g.grid_lines = k == 1 && im.width * im.height <= 64 * 64;
    g.rgba.resize(static_cast<std::size_t>(g.width) * g.height);
    for (int j = 0; j < g.height; ++j)
        for (int i = 0; i < g.width; ++i)
            g.rgba[static_cast<std::size_t>(j) * g.width + i] = pack_rgba(im.at(i * k, j * k));
    std::string text = std::to_string(im.width) + " × " + std::to_string(im.height) + " texels";
    if (!label.empty()) text = label + ": " + text;
    if (k > 1) text += " (every " + std::to_string(k) + "th shown)";
    shown = k;
    return cg::add_image(scene, text, std::move(g));
}

void outline_texel(glm::ivec2 t, int shown, const std::string& label, Role role, Panel& panel) {
    const double x0 = std::floor(double(t.x) / shown), y0 = std::floor(double(t.y) / shown);
    panel.polygons.push_back(
        {{{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}}, {role, 2.5f}, true, false});
    if (!label.empty()) panel.labels.push_back({{x0 + 0.5, y0 + 0.5}, label, {role}, 2});
}

double surface_size(const PreparedUv& p, const UvSurface& s) {
    switch (s.kind) {
        case UvKind::Quadric: {
            const glm::dmat3& m = p.linear;
            const double stretch =
                std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
            return largest_param(s.quadric) * stretch;
        }
        case UvKind::Plane:
            return s.scale;
        case UvKind::Triangle:
            return std::max({glm::length(p.e1), glm::length(p.e2), glm::length(p.e2 - p.e1)});
    }
    return 1;
}

void uv_domain(const PreparedUv& p, const UvSurface& s, dvec2 uv, dvec2& lo, dvec2& hi) {
    lo = uv - dvec2(1.0);
    hi = uv + dvec2(1.0);
    if (s.kind != UvKind::Quadric) return;
    lo.x = 0, hi.x = 1;
    const bool sphere_like =
        s.quadric.kind == QuadricKind::Sphere || s.quadric.kind == QuadricKind::Ellipsoid;
    const bool cut = std::isfinite(s.quadric.zmin) && std::isfinite(s.quadric.zmax);
    if (sphere_like || cut) {
        lo.y = 0, hi.y = 1;
        return;
    }
    const double reach = 1.5 * largest_param(s.quadric);
    lo.y = uv.y - reach, hi.y = uv.y + reach;
    if (s.quadric.kind == QuadricKind::Paraboloid) lo.y = std::max(lo.y, 0.0);
    (void)p;
}

void add_surface(const PreparedUv& p, const UvSurface& s, dvec2 lo, dvec2 hi, int nu, int nv,
                 const std::function<dvec3(dvec2, dvec3)>& color, dvec3 offset, float alpha,
                 Scene& scene) {
    if (s.kind == UvKind::Triangle) {  // subdivided in barycentric steps
        const int n = nu;
        auto corner = [&](int a, int b) {
            const double beta = double(a) / n, gamma = double(b) / n;
            return std::pair{p.p0 + beta * p.e1 + gamma * p.e2, p.uv0 + beta * p.j1 + gamma * p.j2};
        };
        for (int a = 0; a < n; ++a)
            for (int b = 0; a + b < n; ++b)
                for (int up = 0; up < (a + b + 1 < n ? 2 : 1); ++up) {
                    const auto c0 = up ? corner(a + 1, b + 1) : corner(a, b);
                    const auto c1 = corner(a + 1, b), c2 = corner(a, b + 1);
                    const dvec2 uv = (c0.second + c1.second + c2.second) / 3.0;
                    const dvec3 P = (c0.first + c1.first + c2.first) / 3.0;
                    scene.faces3.push_back(
                        {{c0.first + offset, c1.first + offset, c2.first + offset},
                         {Role::Subject, 1.0f, false, pack_rgba(color(uv, P))},
                         alpha,
                         false,
                         true});
                }
        return;
    }
    // The grid's corners once (each is shared by four faces); a face's centre is their mean.
    std::vector<dvec3> corner(static_cast<std::size_t>(nu + 1) * (nv + 1));
    auto at = [&](int i, int j) -> dvec3& {
        return corner[static_cast<std::size_t>(j) * (nu + 1) + i];
    };
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i)
            at(i, j) = uv_point(p, {lo.x + (hi.x - lo.x) * i / nu, lo.y + (hi.y - lo.y) * j / nv});
    scene.faces3.reserve(scene.faces3.size() + static_cast<std::size_t>(nu) * nv);
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const dvec2 mid{lo.x + (hi.x - lo.x) * (i + 0.5) / nu,
                            lo.y + (hi.y - lo.y) * (j + 0.5) / nv};
            const dvec3 P = 0.25 * (at(i, j) + at(i + 1, j) + at(i + 1, j + 1) + at(i, j + 1));
            scene.faces3.push_back({{at(i, j) + offset, at(i + 1, j) + offset,
                                     at(i + 1, j + 1) + offset, at(i, j + 1) + offset},
                                    {Role::Subject, 1.0f, false, pack_rgba(color(mid, P))},
                                    alpha,
                                    false,
                                    true});
        }
}

void add_textured_surface(const PreparedUv& p, const UvSurface& s, dvec2 uv, const Texture& t,
                          const void*, Scene& scene) {
    dvec2 lo, hi;
    uv_domain(p, s, uv, lo, hi);
    const int nu = s.kind == UvKind::Quadric ? 24 : 12, nv = 12;
    add_surface(
        p, s, lo, hi, s.kind == UvKind::Triangle ? 8 : nu, nv,
        [&](dvec2 q, dvec3) { return sample_nearest(t.image, wrap_uv(q, t.wrap), t.wrap).color; },
        dvec3(0.0), 1.0f, scene);
}

void add_point_frame(const PreparedUv& p, dvec3 P, const UvFrame* f, Scene& scene) {
    scene.points3.push_back({P, "P", {Role::Active}, 6.0f});
    if (!f) return;
    // The directions of growing u and v, scaled to a visible length (and at least 30 px).
    const double L = 0.3 * std::max({glm::length(f->P_u) / 6.3, glm::length(f->P_v) / 3.2, 0.2});
    if (glm::length(f->P_u) > 0)
        scene.segments3.push_back(
            {P, P + L * unit(f->P_u), "u", {Role::Entering, 2.0f}, true, 30.0f});
    if (glm::length(f->P_v) > 0)
        scene.segments3.push_back(
            {P, P + L * unit(f->P_v), "v", {Role::Leaving, 2.0f}, true, 30.0f});
    (void)p;
}

}  // namespace cg::texdraw
