// Orientation interpolation, the picture. 3D: one fan a method, side by side (Euler, matrix,
// slerp, and squad when there are three keys or more): every frame so far as a thin axis
// triad from the fan's centre, the path of the x axis's tip (evenly spaced dots mean an even
// speed; the matrix blend's dips inside the unit circle), the keys' triads faint, and the
// current frame as a small house turned (or, for the matrix blend, sheared) by it.
// 2D beside it: the angular speed of Euler, slerp and squad against time, and below it the
// matrix blend's det M(t) with det = 1 dashed.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "animation/orientation_interpolation.hpp"
#include "core/format.hpp"
#include "transforms/rotation_common.hpp"
#include "transforms/slerp.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dvec2;
using glm::dvec3;
using OI = OrientationInterpolation;

constexpr std::size_t kMaxTriads = 48;  // per fan
constexpr std::size_t kMaxPlotPoints = 400;
constexpr double kSpacing = 2.7;  // between fan centres

struct Method {
    const char* name;
    Role role;
};
constexpr Method kMethods[4] = {{"Euler lerp", Role::Leaving},
                                {"matrix lerp", Role::Discarded},
                                {"slerp", Role::Kept},
                                {"squad", Role::Entering}};

dmat3 orientation(const OI::Frame& f, int method) {
    switch (method) {
        case 0:
            return Slerp::to_matrix(f.euler_q);
        case 1:
            return f.matrix;
        case 2:
            return Slerp::to_matrix(f.slerp);
        default:
            return Slerp::to_matrix(f.squad);
    }
}

void triad(Scene& scene, dvec3 c, const dmat3& m, double len, bool faint) {
    static constexpr std::uint32_t kStrong[3] = {0xD03030FF, 0x309030FF, 0x3050D0FF};
    static constexpr std::uint32_t kFaint[3] = {0xE8A8A8FF, 0xA8D8A8FF, 0xA8B8E8FF};
    for (int a = 0; a < 3; ++a)
        scene.segments3.push_back(
            {c, c + len * m[a], "", {Role::Neutral, faint ? 1.0f : 2.0f, false,
                                     faint ? kFaint[a] : kStrong[a]}, false});
}

double speed_of(const OI::Frame& f, int method) {
    return method == 0 ? f.speed_euler : method == 2 ? f.speed_slerp : f.speed_squad;
}

}  // namespace

void OrientationInterpolation::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const bool squad = in.keys.size() >= 3;
    const int fans = squad ? 4 : 3;
    const double x0 = -0.5 * (fans - 1) * kSpacing;
    scene.extent3 = 0.5 * (fans - 1) * kSpacing + 1.4;
    auto centre = [&](int m) { return dvec3(x0 + m * kSpacing, 0, 0); };
    const std::size_t nf = s.frames.size();
    const std::size_t stride = std::max<std::size_t>(1, (nf + kMaxTriads - 1) / kMaxTriads);

    for (int m = 0; m < fans; ++m) {
        const dvec3 c = centre(m);
        const Role role = kMethods[m].role;
        rot::draw_circle(scene, c, {0, 0, 1}, 1.0, {Role::Construction, 1.0f, false}, 32);
        // The keys, faint, with their x tips marked.
        for (std::size_t k = 0; k < s.p.m.size(); ++k) {
            scene.segments3.push_back(
                {c, c + s.p.m[k][0], "", {Role::Construction, 1.0f, true}, false});
            scene.points3.push_back(
                {c + s.p.m[k][0], m == 0 ? "k" + std::to_string(k) : "", {Role::Subject}, 4.0f});
        }
        scene.labels3.push_back({c + dvec3(-0.5, 1.25, 0), kMethods[m].name, {role}});
        if (nf == 0) continue;
        // The frames so far: triads, and the path of the x tip with a dot per frame drawn.
        dvec3 prev_tip{0};
        for (std::size_t k = 0; k < nf; ++k) {
            const bool drawn = k % stride == 0 || k + 1 == nf;
            const dmat3 r = orientation(s.frames[k], m);
            const dvec3 tip = c + r[0];
            if (k > 0) scene.segments3.push_back({prev_tip, tip, "", {role, 2.0f}, false});
            prev_tip = tip;
            if (!drawn) continue;
            if (k + 1 < nf) triad(scene, c, r, 0.9, true);
            scene.points3.push_back({tip, "", {role}, 3.0f});
        }
        // The current frame: strong triad and a small house turned by it.
        const dmat3 now = orientation(s.frames.back(), m);
        triad(scene, c, now, 1.0, false);
        const std::size_t first = scene.faces3.size();
        rot::HousePlacement h;
        h.size = 0.55;
        rot::draw_house(scene, h, now, false);
        for (std::size_t f = first; f < scene.faces3.size(); ++f)
            for (dvec3& p : scene.faces3[f].points) p += c;
    }
    if (nf > 0) {
        const Frame& f = s.frames.back();
        scene.labels3.push_back({centre(1) + dvec3(-0.9, -1.3, 0),
                                 "det " + num(f.det, 3) + ", |MᵀM − I| " + num(f.orth_error, 2),
                                 {Role::Discarded}});
    }

    // 2D, upper: angular speed against t for the whole run's time span (a fixed frame).
    const double pw = 6, ph = 4, py = 2.6;
    const double T = in.segment_time * segments(in);
    double top = 1e-9;
    for (double w : s.p.omega_deg) top = std::max(top, 2 * w / in.segment_time);
    for (const Frame& f : s.frames)
        top = std::max({top, f.speed_euler, f.speed_slerp, f.speed_squad});
    top *= 1.15;
    scene.polygons.push_back(
        {{{0, py}, {pw, py}, {pw, py + ph}, {0, py + ph}}, {Role::Construction, 1.0f}});
    scene.labels.push_back(
        {{0, py + ph + 0.35}, "angular speed, top " + num(top, 4) + "°/s", {Role::Neutral}});
    scene.labels.push_back({{0, py + ph + 0.9}, kMethods[0].name, {kMethods[0].role}});
    scene.labels.push_back({{2.2, py + ph + 0.9}, kMethods[2].name, {kMethods[2].role}});
    if (squad) scene.labels.push_back({{3.4, py + ph + 0.9}, kMethods[3].name, {kMethods[3].role}});
    const std::size_t pstride = std::max<std::size_t>(1, (nf + kMaxPlotPoints - 1) / kMaxPlotPoints);
    for (int which : {0, 2, 3}) {
        if (which == 3 && !squad) continue;
        Polygon2 line{{}, {kMethods[which].role, 2.0f}, false, false};
        for (std::size_t k = 1; k < nf; k += pstride)
            line.points.push_back(
                {pw * s.frames[k].t / T, py + ph * speed_of(s.frames[k], which) / top});
        if (nf > 1 && (nf - 2) % pstride != 0)
            line.points.push_back(
                {pw * s.frames.back().t / T, py + ph * speed_of(s.frames.back(), which) / top});
        if (line.points.size() == 1) line.points.push_back(line.points[0] + dvec2(0.01, 0));
        if (!line.points.empty()) scene.polygons.push_back(std::move(line));
    }
    // 2D, lower: det M(t) of the matrix blend, 0 to 1.
    const double dh = 1.6;
    scene.polygons.push_back({{{0, 0}, {pw, 0}, {pw, dh}, {0, dh}}, {Role::Construction, 1.0f}});
    scene.segments.push_back({{0, dh}, {pw, dh}, "", {Role::Window, 1.0f, true}, false});
    scene.labels.push_back({{pw + 0.15, dh}, "det = 1", {Role::Window}});
    scene.labels.push_back({{pw + 0.15, 0}, "0", {Role::Neutral}});
    Polygon2 det{{}, {Role::Discarded, 2.0f}, false, false};
    for (std::size_t k = 0; k < nf; k += pstride)
        det.points.push_back({pw * s.frames[k].t / T, dh * std::clamp(s.frames[k].det, -0.2, 1.2)});
    if (nf > 0 && (nf - 1) % pstride != 0)
        det.points.push_back({pw * s.frames.back().t / T, dh * std::clamp(s.frames.back().det, -0.2, 1.2)});
    if (det.points.size() == 1) det.points.push_back(det.points[0] + dvec2(0.01, 0));
    if (!det.points.empty()) scene.polygons.push_back(std::move(det));
    scene.labels.push_back({{0, dh + 0.3}, "det M(t), matrix lerp", {Role::Discarded}});
    scene.labels.push_back({{0, -0.35}, "t = 0", {Role::Neutral}});
    scene.labels.push_back({{pw - 1, -0.35}, "t = " + num(T, 4) + " s", {Role::Neutral}});
}

}  // namespace cg
