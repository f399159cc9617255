// Spring-mass, the picture. 3D: the springs coloured by strain (|d| − L)/L (blue compressed,
// grey at rest, red stretched, full colour at ±20%), the masses (pinned ones in the window's
// blue, the watched one orange), the forces on the watched mass as arrows (each spring, gravity,
// drag, and the total dashed; all scaled together), and the watched mass's path so far.
// 2D beside it: the total energy against time over the whole run, with E_0 dashed, so explicit
// Euler's climb and symplectic Euler's bounded wobble show at a glance.
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
    scene.extent3 = 0.5 * glm::length(hi + lo) + 0.9 * size;

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
        if (arrows.size() < 8) arrows.push_back({f, "spring", Role::Entering, false});
    }
    arrows.push_back({total, "F", Role::Active, true});
    double biggest = 0;
    for (const Arrow& a : arrows) biggest = std::max(biggest, glm::length(a.f));
    if (biggest > 0 && std::isfinite(biggest)) {
        const double scale = 0.4 * size / biggest;
        for (const Arrow& a : arrows) {
            if (glm::length(a.f) == 0) continue;
            scene.segments3.push_back(
                {s.x[w], s.x[w] + scale * a.f, a.label, {a.role, 2.0f, a.dashed}, true});
        }
    }

    // 2D: total energy against t over the whole run (a fixed frame: the layout stays put).
    const double pw = 5, ph = 6;  // about square: the 2D pane beside the 3D one is narrow
    scene.polygons.push_back({{{0, 0}, {pw, 0}, {pw, ph}, {0, ph}}, {Role::Construction, 1.0f}});
    double e_lo = s.history.front(), e_hi = e_lo;
    for (double e : s.history) e_lo = std::min(e_lo, e), e_hi = std::max(e_hi, e);
    const double min_e = e_lo, max_e = e_hi;
    const double pad = std::max(0.05 * (e_hi - e_lo), 1e-3 * s.energy_scale);
    e_lo -= pad;
    e_hi += pad;
    auto y_of = [&](double e) { return ph * (e - e_lo) / (e_hi - e_lo); };
    const double steps = double(in.steps);
    Polygon2 line{{}, {Role::Active, 2.0f}, false, false};
    const std::size_t stride = (s.history.size() + kMaxPlotPoints - 1) / kMaxPlotPoints;
    for (std::size_t q = 0; q < s.history.size(); q += stride)
        line.points.push_back({pw * double(q) / steps, y_of(s.history[q])});
    if ((s.history.size() - 1) % stride != 0)
        line.points.push_back({pw * double(s.history.size() - 1) / steps, y_of(s.history.back())});
    if (line.points.size() == 1) line.points.push_back(line.points[0] + glm::dvec2(0.01, 0));
    scene.polygons.push_back(std::move(line));
    const double y0 = y_of(s.history.front());
    scene.segments.push_back({{0, y0}, {pw, y0}, "E_0", {Role::Window, 1.0f, true}, false});
    scene.labels.push_back(
        {{0, ph + 0.4},
         "total energy E(t) = " + num(s.history.back(), 5) + (s.blew_up ? "  (blew up)" : ""),
         {s.blew_up ? Role::Discarded : Role::Neutral}});
    scene.labels.push_back({{0, -0.4}, "t = 0", {Role::Neutral}});
    scene.labels.push_back({{pw - 1, -0.4}, "t = " + num(steps * in.dt, 4), {Role::Neutral}});
    scene.labels.push_back({{pw + 0.2, y_of(max_e)}, "max " + num(max_e, 4), {Role::Neutral}});
    scene.labels.push_back({{pw + 0.2, y_of(min_e)}, "min " + num(min_e, 4), {Role::Neutral}});
}

}  // namespace cg
