// Bump mapping, the picture.
// 3D: two patches of the surface around P, lit by one light with Lambert's law — the left one
// with the perturbed normals (bumps), the right one with the surface's own (smooth) — and at P
// the surface's n and the perturbed n' (the last step's subject), each at least 30 px long; the
// camera frames both patches from 30° above the surface, u to the right and n up.
// Charts: the height B along u through P and along v through P, in their own units, with B at
// P; the differences step adds the two neighbours B(u ± h) (B(v ± h)) and the slope B_u (B_v)
// through P.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "rays/bump_map.hpp"
#include "rays/texture_draw.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Phase = BumpMap::Phase;

}  // namespace

void BumpMap::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const HeightField& h = in.height;
    const PreparedUv& p = s.prepared;
    const UvFrame& f = s.r.frame;
    const bool framed = s.phase != Phase::Frame;  // the first step has been taken
    const UvFrame frame = framed ? f : uv_frame(p, in.point);
    // One or two bump periods each way.
    double freq = std::max(std::fabs(h.frequency.x), std::fabs(h.frequency.y));
    if (h.kind == HeightKind::Image)
        freq = std::max(h.image.image.width, h.image.image.height) / 4.0;
    const double half = std::min(0.5, 1.0 / std::max(freq, 1.0));
    const dvec2 lo = frame.uv - dvec2(half), hi = frame.uv + dvec2(half);
    dvec3 light = in.has_light ? unit(in.light)
                               : unit(s.outward + 0.8 * unit(frame.P_u) + 0.4 * unit(frame.P_v));
    if (light == dvec3(0.0)) light = s.outward;
    auto shade = [&](dvec3 n) { return dvec3(0.15 + 0.85 * std::max(0.0, glm::dot(n, light))); };

    // ---- 3D ----
    const double size = texdraw::surface_size(p, in.surface);
    const dvec3 side = unit(frame.P_u) == dvec3(0.0) ? dvec3(1, 0, 0) : unit(frame.P_u);
    const dvec3 offset = (glm::length(uv_point(p, hi) - uv_point(p, lo)) + 0.2 * size) * side;
    constexpr int kCells = 12;
    texdraw::add_surface(
        p, in.surface, lo, hi, kCells, kCells,
        [&](dvec2 uv, dvec3 P) {
            const UvFrame q = uv_frame(p, P);
            UvFrame at = q;
            at.uv = uv;  // the cell's own (u, v), not the one the point maps back to
            return shade(blinn_bump(at, outward_normal(p, P), h, s.perlin).perturbed);
        },
        dvec3(0.0), 0.95f, scene);
    texdraw::add_surface(
        p, in.surface, lo, hi, kCells, kCells,
        [&](dvec2, dvec3 P) { return shade(outward_normal(p, P)); }, offset, 0.95f, scene);
    const dvec3 P = in.point;
    const double L = 0.45 * std::max(glm::length(uv_point(p, hi) - uv_point(p, lo)), 1e-6);
    const bool perturbed = s.phase == Phase::Done && !s.r.bump.singular;
    scene.points3.push_back({P, "P", {perturbed ? Role::Neutral : Role::Active}, 6.0f});
    scene.segments3.push_back({P, P + L * s.outward, "n", {Role::Neutral, 2.0f}, true, 30.0f});
    scene.segments3.push_back(
        {P + offset, P + offset + L * s.outward, "n (smooth)", {Role::Neutral, 2.0f}, true, 30.0f});
    if (perturbed)
        scene.segments3.push_back(
            {P, P + L * s.r.bump.perturbed, "n'", {Role::Active, 3.0f}, true, 30.0f, 3});
    scene.segments3.push_back({P + 1.5 * L * light,
                               P + 0.6 * L * light,
                               "light",
                               {Role::Construction, 1.5f, true},
                               true});
    scene.extent3 = 0.8 * glm::length(offset) + L;
    dvec3 box_lo = P, box_hi = P;
    for (const Face3& face : scene.faces3)
        for (const dvec3& q : face.points)
            box_lo = glm::min(box_lo, q), box_hi = glm::max(box_hi, q);
    box_hi = glm::max(box_hi, P + L * s.outward);
    add_focus(scene, box_lo, box_hi);
    // Seen from 30° above the tangent plane, u to the right (the bumped patch left, the smooth
    // one right) and n up, so that n' leans visibly away from n.
    const dvec3 u_dir = unit(frame.P_u);
    if (u_dir != dvec3(0.0) && glm::length(glm::cross(s.outward, u_dir)) > 1e-9) {
        const dvec3 w = glm::normalize(glm::cross(s.outward, u_dir));
        const double c = std::sqrt(3.0) / 2, sn = 0.5;  // cos 30°, sin 30°
        scene.view3 = {c * w - sn * s.outward, s.outward, false};
    }

    // ---- the charts: B along u and along v through P, in their own units ----
    const BumpResult& b = s.r.bump;
    const bool heights = s.last >= Phase::Height && s.phase != Phase::Frame;
    const bool slopes = s.last >= Phase::Differences && s.phase > Phase::Differences;
    constexpr int kSamples = 120;
    for (int axis = 0; axis < 2; ++axis) {
        const double at = frame.uv[axis];
        const char* name = axis == 0 ? "u" : "v";
        auto point = [&](double x) {
            dvec2 uv = frame.uv;
            uv[axis] = x;
            return uv;
        };
        const std::string title = axis == 0 ? "B along u, at v = " + num(frame.uv.y, 4)
                                            : "B along v, at u = " + num(frame.uv.x, 4);
        Panel& chart = add_chart(scene, title, Axis{name, lo[axis], hi[axis]}, Axis{"B"});
        std::vector<dvec2> curve;
        for (int i = 0; i <= kSamples; ++i) {
            const double x = lo[axis] + (hi[axis] - lo[axis]) * i / kSamples;
            curve.push_back({x, height_at(h, s.perlin, point(x))});
        }
        add_line(chart, std::move(curve), {Role::Subject, 2.0f});
        if (!heights) continue;
        const bool step_here = s.last == Phase::Height;
        chart.points.push_back(
            {{at, b.B}, "B", {step_here ? Role::Active : Role::Neutral}, 6.0f, step_here ? 3 : 0});
        if (!slopes) continue;
        // The central difference: the neighbours at ± h and the chord through them, drawn as
        // the slope through P across a quarter of the plot.
        const double step = h.step, slope = axis == 0 ? b.B_u : b.B_v;
        const double up = b.samples[axis == 0 ? 0 : 2], down = b.samples[axis == 0 ? 1 : 3];
        chart.points.push_back({{at + step, up}, "", {Role::Entering}, 4.0f});
        chart.points.push_back({{at - step, down}, "", {Role::Leaving}, 4.0f});
        const double du = 0.25 * (hi[axis] - lo[axis]);
        const bool active = s.last == Phase::Differences;
        chart.segments.push_back({{at - du, b.B - du * slope},
                                  {at + du, b.B + du * slope},
                                  std::string(axis == 0 ? "B_u" : "B_v") + " = " + num(slope, 4),
                                  {active ? Role::Active : Role::Kept, 2.0f},
                                  false,
                                  active ? 3 : 1});
    }
}

}  // namespace cg
