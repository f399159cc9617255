// Solid textures and Perlin noise, the picture.
// 3D: the block of material the points are carved from — its three far walls painted with the
// texture, so the rings, veins or cubes show — and the points in their colours (grey until
// computed); while a point's noise is worked, its lattice cell, the corner gradients and the
// point, and the camera frames that cell; otherwise it frames the points.
// Chart: the fade curve 6t⁵ − 15t⁴ + 10t³ (and the classic 3t² − 2t³, dashed) with the point's
// three fractions on it once they are faded.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "rays/solid_texture.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Phase = SolidTextureAlgo::Phase;

std::string corner_name(int k) {
    return std::string("g") + char('0' + (k >> 2)) + char('0' + ((k >> 1) & 1)) +
           char('0' + (k & 1));
}

// The walls at the box's low x, y and z (the far side from the default camera), n × n faces
// each, coloured by the texture at their centres: about four faces a period of rings or
// stripes (a checker's cube, a vein), 16 to 48 a side (noise at least 32).
void add_walls(const SolidTexture& t, const Perlin& perlin, dvec3 lo, dvec3 hi, Scene& scene) {
    const double feature = t.kind == SolidKind::Checker ? t.size : t.period;
    const double side = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const double least = uses_noise(t.kind) ? 32 : 16;  // noise needs the finer faces
    const int n = static_cast<int>(std::clamp(std::ceil(4 * side / feature), least, 48.0));
    for (int axis = 0; axis < 3; ++axis) {
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                auto at = [&](double x, double y) {
                    dvec3 p = lo;
                    p[a] = lo[a] + (hi[a] - lo[a]) * x / n;
                    p[b] = lo[b] + (hi[b] - lo[b]) * y / n;
                    return p;
                };
                const dvec3 c = solid_sample(t, perlin, at(i + 0.5, j + 0.5)).color;
                scene.faces3.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)},
                                        {Role::Subject, 1.0f, false, pack_rgba(c)},
                                        0.9f,
                                        false,
                                        true});
            }
    }
    // The walls' edges, so that a pale colour on a white background still reads as a wall.
    const dvec3 corners[] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {lo.x, hi.y, lo.z},
                             {lo.x, lo.y, hi.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, hi.z},
                             {hi.x, lo.y, hi.z}};
    const int edges[][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 4}, {2, 4}, {2, 5}, {3, 5}, {1, 6}, {3, 6}};
    for (const auto& e : edges)
        scene.segments3.push_back(
            {corners[e[0]], corners[e[1]], "", {Role::Construction, 1.0f}, false});
}

}  // namespace

void SolidTextureAlgo::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const SolidTexture& t = in.texture;

    // ---- 3D ----
    dvec3 lo(1e300), hi(-1e300);
    const std::size_t shown = std::min<std::size_t>(in.points.size(), 4000);
    for (std::size_t i = 0; i < shown; ++i)
        lo = glm::min(lo, in.points[i]), hi = glm::max(hi, in.points[i]);
    if (shown == 0) lo = dvec3(-1), hi = dvec3(1);
    // The block: the points' box, padded by a quarter of its size (at least one unit across).
    const double pad = std::max(0.25 * glm::length(hi - lo), 0.5);
    add_walls(t, s.perlin, lo - dvec3(pad), hi + dvec3(pad), scene);
    for (std::size_t i = 0; i < shown; ++i) {
        const bool known = i < s.r.samples.size();
        scene.points3.push_back(
            {in.points[i],
             "",
             {Role::Subject, 1.0f, false, known ? pack_rgba(s.r.samples[i].color) : 0x80808060u},
             known ? 7.0f : 4.0f});
    }
    const bool working = s.r.has_detail && (s.last >= Phase::Lattice && s.last <= Phase::Colour) &&
                         s.last != Phase::Point;
    if (working) {
        const NoiseDetail& d = s.r.detail;
        const dvec3 c0(d.cell[0], d.cell[1], d.cell[2]);
        const double f = t.frequency;
        auto world = [&](dvec3 q) { return q / f; };
        for (int a = 0; a < 8; ++a)
            for (int axis = 0; axis < 3; ++axis) {
                if (a & (4 >> axis)) continue;
                const dvec3 A = c0 + dvec3((a >> 2) & 1, (a >> 1) & 1, a & 1);
                dvec3 B = A;
                B[axis] += 1;
                scene.segments3.push_back({world(A), world(B), "", {Role::Window, 1.0f}, false});
            }
        const auto& G = perlin_gradients();
        for (int k = 0; k < 8; ++k) {
            const dvec3 c = c0 + dvec3((k >> 2) & 1, (k >> 1) & 1, k & 1);
            scene.segments3.push_back({world(c),
                                       world(c + 0.35 * G[d.gradient[k]]),
                                       s.last >= Phase::Gradients ? corner_name(k) : "",
                                       {Role::Entering, 2.0f},
                                       true});
        }
        scene.points3.push_back({in.points[in.detail], "p", {Role::Active}, 7.0f, 3});
        add_focus(scene, world(c0 - dvec3(0.2)), world(c0 + dvec3(1.2)));
    } else {
        add_focus(scene, lo - dvec3(pad), hi + dvec3(pad));
    }

    // ---- the chart: the fade curve ----
    if (!uses_noise(t.kind)) return;
    std::vector<dvec2> quintic, cubic;
    for (int i = 0; i <= 60; ++i) {
        const double x = i / 60.0;
        quintic.push_back({x, fade(x)});
        cubic.push_back({x, x * x * (3 - 2 * x)});
    }
    Panel& chart = add_chart(scene, "the fade curve: a fraction's weight",
                             Axis{"t (fraction in the cell)", 0, 1}, Axis{"fade(t)", 0, 1});
    chart.weight = 1.2;
    add_line(chart, std::move(quintic), {Role::Subject, 2.0f}, "6t⁵ − 15t⁴ + 10t³");
    add_line(chart, std::move(cubic), {Role::Construction, 1.0f, true}, "3t² − 2t³");
    if (working && s.last >= Phase::Fade) {
        const NoiseDetail& d = s.r.detail;
        const char* names[] = {"x", "y", "z"};
        const bool now = s.last == Phase::Fade;
        for (int k = 0; k < 3; ++k)
            chart.points.push_back({{d.frac[k], d.fade[k]},
                                    names[k],
                                    {now ? Role::Active : Role::Kept},
                                    5.5f,
                                    now ? 3 : 0});
    }
}

}  // namespace cg
