// Orientation interpolation, the picture. 3D: one fan a method, side by side (Euler, matrix,
// slerp, and squad when there are three keys or more): every frame so far as a thin axis
// triad from the fan's centre, the path of the x axis's tip (evenly spaced dots mean an even
// speed; the matrix blend's dips inside the unit circle), the keys' triads faint, and the
// current frame as a small house turned (or, for the matrix blend, sheared) by it.
// The fans are seen from the front and a little above, framed whole. Beside them two charts
// against t (s): the angular speed (°/s) of Euler, slerp and squad, and the matrix blend's
// det M(t) with det = 1 dashed.
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
    // The fans side by side, seen from the front and a little above: a circle stays nearly
    // round, the triads keep their depth, and no fan hides another.
    scene.view3 = {glm::normalize(dvec3(-0.15, -0.35, -1)), {0, 1, 0}, false};
    add_focus(scene, centre(0) - dvec3(1.2, 1.2, 1.2), centre(fans - 1) + dvec3(1.2, 1.5, 1.2));

    // Chart: the angular speed against t over the whole run (t and the top fixed while the
    // keys' own speeds bound it, so the chart stays put).
    const double T = in.segment_time * segments(in);
    double top = 0;
    for (double w : s.p.omega_deg) top = std::max(top, 2 * w / in.segment_time);
    for (const Frame& f : s.frames)
        top = std::max({top, f.speed_euler, f.speed_slerp, f.speed_squad});
    // (No titles: the y axes say what is plotted, and the room goes to the plots.)
    // (Before the keys are read there is no speed yet: 0 to 1.)
    Panel& speed = add_chart(scene, "", Axis{"t (s)", 0, T},
                             Axis{"angular speed ω (°/s)", 0, top > 1e-6 ? 1.1 * top : 1.0});
    const std::size_t pstride =
        std::max<std::size_t>(1, (nf + kMaxPlotPoints - 1) / kMaxPlotPoints);
    for (int which : {0, 2, 3}) {
        if (which == 3 && !squad) continue;
        std::vector<dvec2> line;
        for (std::size_t k = 1; k < nf; k += pstride)
            line.push_back({s.frames[k].t, speed_of(s.frames[k], which)});
        if (nf > 1 && (nf - 2) % pstride != 0)
            line.push_back({s.frames.back().t, speed_of(s.frames.back(), which)});
        add_line(speed, std::move(line), {kMethods[which].role, 2.0f}, kMethods[which].name);
    }

    // Chart: det M(t) of the matrix blend, against det = 1 (a rotation).
    double det_lo = 0;
    for (const Frame& f : s.frames) det_lo = std::min(det_lo, f.det);
    Panel& det = add_chart(scene, "", Axis{"t (s)", 0, T},
                           Axis{nf > 0 ? "matrix lerp: det M = " + num(s.frames.back().det, 3)
                                       : std::string("matrix lerp: det M(t)"),
                                det_lo, 1.15});
    add_line(det, {{0, 1}, {T, 1}}, {Role::Window, 1.0f, true}, "det = 1: a rotation");
    std::vector<dvec2> dets;
    for (std::size_t k = 0; k < nf; k += pstride) dets.push_back({s.frames[k].t, s.frames[k].det});
    if (nf > 0 && (nf - 1) % pstride != 0) dets.push_back({s.frames.back().t, s.frames.back().det});
    add_line(det, std::move(dets), {Role::Discarded, 2.0f}, "det M(t)");
    if (nf > 0) det.points.push_back({{s.frames.back().t, s.frames.back().det}, "", {Role::Discarded}, 4.5f});
}

}  // namespace cg
