// Shadow maps, the picture. The 3D view: the triangles, the light with its frustum and view
// direction f, the eye; while rasterising, the triangle being drawn into the map and its texels'
// samples (each texel centre's light ray to the surface it keeps); while looking up, the eye ray
// to P, P's ray to the light (green: it reaches the light, red: blocked) and the surface point
// the texel remembers (d_map), with the occluder outlined — the camera is framed on the light,
// P and the occluder. Two image panels: the depth map from the light (near dark, far light,
// cleared texels pale blue), the texel being rasterised or looked up outlined in orange; and the
// eye image filling in pixel by pixel in the verdicts' colours, the pixel being shaded outlined.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "shadows/shadow_map.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Phase = ShadowMap::Phase;
using Verdict = ShadowMap::Verdict;
using Frame = ShadowMap::Frame;
using Input = ShadowMap::Input;
using State = ShadowMap::State;

bool finite3(const dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::uint32_t verdict_colour(Verdict v) {
    switch (v) {
        case Verdict::Pending:
            return 0;
        case Verdict::Background:
            return 0xd8dde4ffu;
        case Verdict::Outside:
            return 0xf3eccdffu;
        case Verdict::Lit:
            return 0xf2c94cffu;
        case Verdict::Shadow:
            return 0x3b4a6bffu;
        case Verdict::Acne:
            return 0xd13fc2ffu;
        case Verdict::FalseShadow:
            return 0xd9472bffu;
        case Verdict::FalseLit:
            return 0x2bb3a6ffu;
    }
    return 0;
}

const char* verdict_name(Verdict v) {
    switch (v) {
        case Verdict::Pending:
            return "pending";
        case Verdict::Background:
            return "background";
        case Verdict::Outside:
            return "outside";
        case Verdict::Lit:
            return "lit";
        case Verdict::Shadow:
            return "shadow";
        case Verdict::Acne:
            return "acne";
        case Verdict::FalseShadow:
            return "false shadow";
        case Verdict::FalseLit:
            return "false lit";
    }
    return "";
}

std::uint32_t grey(double g) {
    const auto v = std::uint32_t(std::clamp(g, 0.0, 255.0));
    return (v << 24) | (v << 16) | (v << 8) | 0xffu;
}

// A cell's outline, in an image panel's cell units.
void cell_box(Layer2& layer, int i, int j, Role role, float width) {
    const dvec2 a(i, j);
    layer.polygons.push_back(
        {{a, a + dvec2(1, 0), a + dvec2(1, 1), a + dvec2(0, 1)}, {role, width}, true, false});
}

void focus_points(Scene& scene, const std::vector<dvec3>& points) {
    dvec3 lo(1e300), hi(-1e300);
    for (const dvec3& p : points)
        if (finite3(p)) lo = glm::min(lo, p), hi = glm::max(hi, p);
    if (lo.x <= hi.x) add_focus(scene, lo, hi);
}

}  // namespace

void ShadowMap::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const bool started = s.phase != Phase::Setup;
    const Frame light = started ? s.light : light_frame(in.light);
    const Frame eye = started ? s.eye : eye_frame(in.eye);
    const int n = in.map_size;
    const bool rasterising = s.last == Phase::Rasterise && started;
    const bool looking = s.last == Phase::Lookup && started;
    const Lookup& l = s.look;
    // The surface that shadows P (the shadow ray's blocker), or the one its texel holds when
    // that is not P's own.
    const int occluder = !looking                               ? -1
                         : l.blocker >= 0                       ? l.blocker
                         : l.map_tri >= 0 && l.map_tri != l.tri ? l.map_tri
                                                                : -1;

    // ---- 3D ----
    for (std::size_t k = 0; k < in.triangles.size(); ++k) {
        const auto& t = in.triangles[k];
        const bool now = rasterising && int(k) == s.k;
        const bool seen = looking && l.tri == int(k);
        const bool blocks = int(k) == occluder;
        scene.faces3.push_back({{t[0], t[1], t[2]},
                                {now      ? Role::Active
                                 : blocks ? Role::Discarded
                                 : seen   ? Role::Kept
                                          : Role::Subject,
                                 now || blocks ? 2.5f : 1.0f},
                                now ? 0.6f : 0.35f});
    }
    // The light's frustum, drawn to the far plane or just past the scene, whichever is nearer.
    double reach = in.light.near;
    for (const auto& t : in.triangles)
        for (const auto& p : t) reach = std::max(reach, glm::dot(p - light.origin, light.forward));
    reach = std::min(in.light.far, reach * 1.1 + 0.1);
    auto corner = [&](double d, double x, double y) {
        const double w = light.perspective ? d * light.half : light.half;
        return light.origin + d * light.forward + x * w * light.right + y * w * light.up;
    };
    const double xs[4] = {-1, 1, 1, -1}, ys[4] = {-1, -1, 1, 1};
    for (int c = 0; c < 4; ++c) {
        const int c2 = (c + 1) % 4;
        const Style frustum{Role::Window, 1.0f, true};
        scene.segments3.push_back({corner(in.light.near, xs[c], ys[c]),
                                   corner(in.light.near, xs[c2], ys[c2]), "", frustum, false});
        scene.segments3.push_back(
            {corner(reach, xs[c], ys[c]), corner(reach, xs[c2], ys[c2]), "", frustum, false});
        scene.segments3.push_back({light.perspective ? light.origin : corner(0, xs[c], ys[c]),
                                   corner(reach, xs[c], ys[c]), "", frustum, false});
    }
    scene.points3.push_back({light.origin, "light", {Role::Window}, 7.0f, 20});
    Segment3 f{light.origin,
               light.origin + light.forward * std::min(reach, 1.0 + 0.2 * reach),
               "f",
               {Role::Window, 2.0f},
               true};
    f.min_pixels = 30;
    scene.segments3.push_back(f);
    scene.points3.push_back({eye.origin, "eye", {Role::Neutral}, 6.0f});

    std::vector<dvec3> focus;
    if (rasterising && n <= 16) {
        // The map's samples: where each texel's centre ray meets the surface it holds.
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::size_t at = std::size_t(j) * n + i;
                if (s.owner[at] < 0) continue;
                dvec3 o, d;
                texel_ray(light, n, i, j, o, d);
                const dvec3 q = o + s.depth[at] * d;
                const bool now = s.owner[at] == s.k;
                scene.points3.push_back(
                    {q, "", {now ? Role::Active : Role::Construction}, now ? 3.5f : 2.5f});
                if (now)
                    scene.segments3.push_back({o, q, "", {Role::Construction, 0.75f, true}, false});
            }
    }
    if (looking) {
        const int w = in.eye.width, h = in.eye.height;
        const double aspect = double(w) / h;
        const double x = (2.0 * (l.i + 0.5) / w - 1.0) * eye.half * aspect;
        const double y = (2.0 * (l.j + 0.5) / h - 1.0) * eye.half;
        const dvec3 dir = eye.forward + x * eye.right + y * eye.up;
        if (l.tri < 0) {
            const dvec3 end = eye.origin + dir * (reach + 1);
            scene.segments3.push_back({eye.origin,
                                       end,
                                       "eye ray: no surface",
                                       {Role::Discarded, 1.5f, true},
                                       true,
                                       0,
                                       20});
            focus = {eye.origin, end};
        } else {
            scene.segments3.push_back({eye.origin, l.p, "eye ray", {Role::Active, 2.0f}, false});
            scene.points3.push_back({l.p, "P", {Role::Active}, 7.0f, 30});
            focus = {l.p, light.origin};
            if (l.ti >= 0) {
                const dvec3 to = light.perspective ? light.origin : l.p - light.forward * l.d_p;
                scene.segments3.push_back(
                    {l.p,
                     to,
                     l.exact_shadow ? "blocked" : "to the light",
                     {l.exact_shadow ? Role::Discarded : Role::Kept, 1.5f, true},
                     false});
                dvec3 o, d;
                texel_ray(light, n, l.ti, l.tj, o, d);
                scene.segments3.push_back(
                    {o, o + l.d_map * d, "", {Role::Window, 1.0f, true}, false});
                scene.points3.push_back({o + l.d_map * d, "d_map", {Role::Window}, 5.0f, 10});
                focus.push_back(o + l.d_map * d);
                focus.push_back(to);
            }
            if (occluder >= 0)
                for (const dvec3& v : in.triangles[std::size_t(occluder)]) focus.push_back(v);
        }
    } else if (rasterising) {
        focus = {light.origin};
        for (const dvec3& v : in.triangles[std::size_t(s.k)]) focus.push_back(v);
    } else {
        focus = {light.origin};
        for (const auto& t : in.triangles) focus.insert(focus.end(), t.begin(), t.end());
    }
    std::erase_if(scene.segments3,
                  [](const Segment3& g) { return !finite3(g.a) || !finite3(g.b); });
    std::erase_if(scene.points3, [](const Point3& q) { return !finite3(q.p); });
    focus_points(scene, focus);

    // ---- the depth map, seen from the light ----
    PixelGrid2 map;
    map.width = map.height = n;
    map.rgba.assign(std::size_t(n) * n, 0xdbe7f5ffu);  // cleared: far
    if (started) {
        double lo = 1e300, hi = -1e300;
        for (std::size_t q = 0; q < s.depth.size(); ++q)
            if (s.owner[q] >= 0) lo = std::min(lo, s.depth[q]), hi = std::max(hi, s.depth[q]);
        for (std::size_t q = 0; q < s.depth.size(); ++q)
            if (s.owner[q] >= 0)
                map.rgba[q] = grey(hi > lo ? 40 + 170 * (s.depth[q] - lo) / (hi - lo) : 110);
    }
    Panel& depth = add_image(scene, "depth map (dark = near)", std::move(map));
    depth.weight = 0.4;
    if (rasterising) {
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (s.owner[std::size_t(j) * n + i] == s.k)
                    cell_box(depth, i, j, Role::Active, 1.5f);
    }
    if (looking && l.ti >= 0) {
        cell_box(depth, l.ti, l.tj, Role::Active, 3.0f);
        depth.labels.push_back(
            {{l.ti + 0.5, l.tj + 0.5}, "d_map = " + num(l.d_map, 3), {Role::Active}});
    }

    // ---- the eye image ----
    PixelGrid2 img;
    img.width = in.eye.width;
    img.height = in.eye.height;
    img.rgba.assign(std::size_t(img.width) * img.height, 0);
    bool present[8] = {};
    for (std::size_t q = 0; q < s.image.size(); ++q) {
        img.rgba[q] = verdict_colour(s.image[q]);
        present[int(s.image[q])] = true;
    }
    Panel& eye_img = add_image(scene, "eye image", std::move(img));
    eye_img.weight = 0.45;
    for (Verdict v : {Verdict::Lit, Verdict::Shadow, Verdict::Outside, Verdict::Acne,
                      Verdict::FalseShadow, Verdict::FalseLit})
        if (present[int(v)])
            eye_img.legend.push_back(
                {verdict_name(v), {Role::Neutral, 2, false, verdict_colour(v)}, true});
    if (looking) {
        cell_box(eye_img, l.i, l.j, Role::Active, 3.0f);
        eye_img.labels.push_back({{l.i + 0.5, l.j + 0.5}, verdict_name(l.verdict), {Role::Active}});
    }
}

}  // namespace cg
