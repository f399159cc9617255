// Spring-mass, the picture. 3D: the springs coloured by strain (|d| − L)/L (blue compressed,
// grey at rest, red stretched, full colour at ±20%), the masses (pinned ones in the window's
// blue, the watched one orange), the forces on the watched mass as arrows (each spring, gravity,
// drag, and the total dashed; all scaled together), and the watched mass's path so far. The
// camera is framed on the masses as they are now (and the arrows); a system that stays in the
// plane z = 0 is seen face-on. Beside it, a chart of the total energy E (J) against t (s) over
// the whole run, with E_0 dashed; its range is at least E_0 ± E_scale (from 0 for a positive
// E_0), so a wobble of a few per cent looks like one, and explicit Euler's climb and symplectic Euler's bounded wobble show at a glance.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "animation/spring_mass.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

constexpr std::size_t kMaxPathSegments = 400;
constexpr std::size_t kMaxPlotPoints = 512;

std::uint32_t lerp_rgb(std::uint32_t a, std::uint32_t b, double t) {
    auto ch = [&](int shift) {
        const double x = double((a >> shift) & 0xFF), y = double((b >> shift) & 0xFF);
        return std::uint32_t(std::lround(x + (y - x) * t)) << shift;
    };
    return ch(24) | ch(16) | ch(8) | 0xFF;
}

std::uint32_t strain_colour(double strain) {
    const double t = std::clamp(strain / 0.2, -1.0, 1.0);
    return t >= 0 ? lerp_rgb(0x909090FF, 0xD02828FF, t) : lerp_rgb(0x909090FF, 0x2850D0FF, -t);
}

}  // namespace

void SpringMass::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const std::size_t n = s.x.size(), w = std::size_t(in.watch);

    // The size of the system (from the start, so that the view stays put): for arrow lengths.
    glm::dvec3 lo = in.masses[0].position, hi = lo;
    for (const Mass& m : in.masses) lo = glm::min(lo, m.position), hi = glm::max(hi, m.position);
    double size = glm::length(hi - lo);
    for (const Spring& sp : in.springs) size = std::max(size, sp.rest);
    if (!(size > 0)) size = 1;
    // Where the masses are now: the arrows are scaled to it (a system that blew up is large).
    glm::dvec3 now_lo = s.x[0], now_hi = now_lo;
    for (const glm::dvec3& x : s.x) now_lo = glm::min(now_lo, x), now_hi = glm::max(now_hi, x);
    const double now_size = std::max(size, glm::length(now_hi - now_lo));
    // In the plane z = 0 for ever: no z in the positions, the velocities or gravity.
    bool planar = in.gravity.z == 0;
    for (const Mass& m : in.masses) planar = planar && m.position.z == 0 && m.velocity.z == 0;

    for (const Spring& sp : in.springs) {
        const glm::dvec3 a = s.x[std::size_t(sp.i)], b = s.x[std::size_t(sp.j)];
        const double len = glm::length(a - b);
        const double strain = sp.rest > 0 ? (len - sp.rest) / sp.rest : (len > 0 ? 1.0 : 0.0);
        scene.segments3.push_back(
            {a, b, "", {Role::Neutral, 2.0f, false, strain_colour(strain)}, false});
    }
    for (std::size_t i = 0; i < n; ++i) {
        const bool watched = i == w;
        const Role role = watched               ? Role::Active
                          : in.masses[i].pinned ? Role::Window
                                                : Role::Subject;
        scene.points3.push_back({s.x[i],
                                 watched ? "m" + std::to_string(i) : "",
                                 {role},
                                 watched   ? 6.0f
                                 : n > 100 ? 3.0f
                                           : 4.0f});
    }

    // The path of the watched mass, at most kMaxPathSegments pieces.
    if (s.path.size() > 1) {
        const std::size_t stride = (s.path.size() - 1 + kMaxPathSegments - 1) / kMaxPathSegments;
        std::size_t prev = 0;
        for (std::size_t q = stride; prev + 1 < s.path.size(); q += stride) {
            const std::size_t cur = std::min(q, s.path.size() - 1);
            scene.segments3.push_back(
                {s.path[prev], s.path[cur], "", {Role::Construction, 1.0f, true}, false});
            prev = cur;
        }
    }

    // The forces on the watched mass now, each one and their sum.
    struct Arrow {
        glm::dvec3 f;
        std::string label;
        Role role;
        bool dashed;
    };
    std::vector<Arrow> arrows;
    const Mass& m = in.masses[w];
    arrows.push_back({m.mass * in.gravity, "m g", Role::Construction, false});
    if (in.drag != 0) arrows.push_back({-in.drag * s.v[w], "drag", Role::Construction, false});
    glm::dvec3 total = m.mass * in.gravity - in.drag * s.v[w];
    for (const Spring& sp : in.springs) {
        if (sp.i != int(w) && sp.j != int(w)) continue;
        glm::dvec3 h, d;
        spring_force(sp, s.x[std::size_t(sp.i)], s.x[std::size_t(sp.j)], s.v[std::size_t(sp.i)],
                     s.v[std::size_t(sp.j)], h, d);
        const glm::dvec3 f = sp.i == int(w) ? h + d : -(h + d);
        total += f;
        if (arrows.size() < 8) arrows.push_back({f, "", Role::Entering, false});
    }
    // One label for the springs' arrows: "spring", or "springs" on the first of several.
    std::size_t springs = 0;
    for (const Arrow& a : arrows) springs += a.role == Role::Entering;
    for (Arrow& a : arrows)
        if (a.role == Role::Entering) {
            a.label = springs > 1 ? "springs" : "spring";
            break;
        }
    arrows.push_back({total, "F", Role::Active, true});
    double biggest = 0;
    for (const Arrow& a : arrows) biggest = std::max(biggest, glm::length(a.f));
    if (biggest > 0 && std::isfinite(biggest)) {
        const double scale = 0.4 * now_size / biggest;
        for (const Arrow& a : arrows) {
            if (glm::length(a.f) == 0) continue;
            const glm::dvec3 tip = s.x[w] + scale * a.f;
            scene.segments3.push_back({s.x[w], tip, a.label, {a.role, 2.0f, a.dashed}, true});
            now_lo = glm::min(now_lo, tip), now_hi = glm::max(now_hi, tip);
        }
    }

    // The camera frames the region the system starts in, with room for its motion, and the
    // masses as they are now with the arrows on the watched one (a run that blows up is seen
    // whole, at its size).
    const glm::dvec3 centre = (lo + hi) / 2.0;
    const double room = 0.5 * glm::length(hi - lo) + 0.5 * size;
    add_focus(scene, glm::min(now_lo, centre - glm::dvec3(room)),
              glm::max(now_hi, centre + glm::dvec3(room)));
    if (planar) scene.view3 = {{0, 0, -1}, {0, 1, 0}, true};

    // The total energy against t over the whole run. t spans the run; E spans at least
    // E_0 ± E_scale (E_scale = max(|E_0|, K_0 + S_0 + |G_0|), so from 0 for a positive E_0),
    // so a drift is seen as the fraction of E_scale the narration gives, never blown up to fill
    // the chart; a run that leaves that range widens it.
    const double t_end = double(in.steps) * in.dt;
    const double e0 = s.history.front();
    double e_lo = e0 - s.energy_scale, e_hi = e0 + s.energy_scale;
    double h_lo = e_lo, h_hi = e_hi;
    for (double e : s.history)
        if (std::isfinite(e)) h_lo = std::min(h_lo, e), h_hi = std::max(h_hi, e);
    const double pad = 0.05 * (h_hi - h_lo);
    if (h_lo < e_lo) e_lo = h_lo - pad;
    if (h_hi > e_hi) e_hi = h_hi + pad;
    Panel& chart = add_chart(scene,
                             s.blew_up ? "total energy: blew up at t = " +
                                             num(double(s.k) * in.dt, 4) + " s"
                                       : "total energy E(t) = " + num(s.history.back(), 4) + " J",
                             Axis{"t (s)", 0, t_end}, Axis{"E (J)", e_lo, e_hi});
    std::vector<glm::dvec2> line;
    const std::size_t stride = (s.history.size() + kMaxPlotPoints - 1) / kMaxPlotPoints;
    for (std::size_t q = 0; q < s.history.size(); q += stride)
        line.push_back({double(q) * in.dt, s.history[q]});
    if ((s.history.size() - 1) % stride != 0)
        line.push_back({double(s.history.size() - 1) * in.dt, s.history.back()});
    add_line(chart, {{0, s.history.front()}, {t_end, s.history.front()}},
             {Role::Window, 1.0f, true}, "E_0 = " + num(s.history.front(), 4) + " J");
    add_line(chart, std::move(line), {s.blew_up ? Role::Discarded : Role::Active, 2.0f}, "E(t)");
    chart.points.push_back({{double(s.history.size() - 1) * in.dt, s.history.back()},
                            "",
                            {s.blew_up ? Role::Discarded : Role::Active},
                            5.0f});
}

}  // namespace cg
