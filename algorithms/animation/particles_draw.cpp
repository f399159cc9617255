// Particle systems, the picture. 3D: the plane (a translucent square under the emitter), the
// emitter (a point, a disc or a line, in the window's blue), the particles coloured by age as a
// share of their lifetime (yellow when born, through orange to dark red when about to die), a
// velocity tick on a few of them, and the focus particle in orange with its velocity arrow.
// The camera frames the region the particles reach and the focus particle. Beside it a chart of
// the counts against t (s) over the whole run — alive (thick), emitted and killed per frame
// (thinner) — so a fountain's ramp up to rate × lifetime and its steady state show at a glance.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "animation/particles.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

constexpr std::size_t kMaxDrawn = 2000;  // particles drawn (a stride beyond)
constexpr std::size_t kTicks = 8;        // velocity ticks
constexpr std::size_t kMaxPlotPoints = 400;

std::uint32_t lerp_rgb(std::uint32_t a, std::uint32_t b, double t) {
    auto ch = [&](int shift) {
        const double x = double((a >> shift) & 0xFF), y = double((b >> shift) & 0xFF);
        return std::uint32_t(std::lround(x + (y - x) * t)) << shift;
    };
    return ch(24) | ch(16) | ch(8) | 0xFF;
}

std::uint32_t age_colour(double share) {
    const double t = std::clamp(share, 0.0, 1.0);
    return t < 0.5 ? lerp_rgb(0xF0C000FF, 0xF07010FF, 2 * t)
                   : lerp_rgb(0xF07010FF, 0x801010FF, 2 * t - 1);
}

void tangent_basis(glm::dvec3 n, glm::dvec3& a, glm::dvec3& b) {
    const glm::dvec3 helper = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    a = glm::normalize(glm::cross(n, helper));
    b = glm::cross(n, a);
}

}  // namespace

void Particles::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Emitter& e = in.emitter;
    const double duration = double(in.frames) * in.dt;

    // How far the particles get (from the input, so that the view stays put): the mean
    // particle's flight x = v̄ T + ½ g T² sampled over its life, kept above the plane, plus the
    // cone's sideways spread.
    glm::dvec3 centre = e.position;
    if (e.shape == Shape::Line) centre = 0.5 * (e.position + e.end);
    glm::dvec3 v_mean = e.velocity;
    if (e.rate == 0 && !in.start.empty())
        centre = in.start[0].position, v_mean = in.start[0].velocity;
    double speed = glm::length(v_mean) * (1 + e.jitter);
    const double life = std::min(max_lifetime(in), duration);
    const double T = life > 0 ? life : duration;
    const double side = std::sin(std::min(e.spread, 90.0) * 3.14159265358979323846 / 180);
    double reach = 0;
    for (int q = 1; q <= 16; ++q) {
        const double tq = T * q / 16;
        glm::dvec3 p = centre + tq * v_mean + 0.5 * tq * tq * in.gravity;
        if (in.plane.on) {
            const double d = distance(in.plane, p);
            if (d < 0) p -= d * in.plane.normal;
        }
        reach = std::max(reach, glm::length(p - centre) + (e.rate > 0 ? side * speed * tq : 0));
    }
    reach = std::clamp(reach, 1.0, 1e6);
    for (const Start& st : in.start) speed = std::max(speed, glm::length(st.velocity));
    scene.extent3 = std::min(1e7, glm::length(centre) + 0.7 * reach);

    if (in.plane.on) {
        const glm::dvec3 n = in.plane.normal;
        const glm::dvec3 c = centre - distance(in.plane, centre) * n;
        glm::dvec3 a, b;
        tangent_basis(n, a, b);
        const double S = 0.8 * reach;
        scene.faces3.push_back(
            {{c - S * a - S * b, c + S * a - S * b, c + S * a + S * b, c - S * a + S * b},
             {Role::Kept, 1.0f},
             0.18f,
             true,
             true});
        scene.labels3.push_back(
            {c + S * a + S * b,
             "plane e = " + num(in.plane.restitution, 3) + ", μ = " + num(in.plane.friction, 3),
             {Role::Neutral}});
    }

    // The emitter (none drawn when it is off).
    switch (e.shape) {
        case Shape::Point:
            if (e.rate == 0) break;
            scene.points3.push_back({e.position, "emitter", {Role::Window}, 6.0f});
            break;
        case Shape::Line:
            if (e.rate == 0) break;
            scene.segments3.push_back({e.position, e.end, "emitter", {Role::Window, 3.0f}, false});
            break;
        case Shape::Disc: {
            if (e.rate == 0) break;
            const double len = glm::length(e.velocity);
            const glm::dvec3 w = len > 0 ? e.velocity / len : glm::dvec3(0, 1, 0);
            glm::dvec3 a, b;
            tangent_basis(w, a, b);
            Face3 disc{{}, {Role::Window, 1.5f}, 0.35f, true, true};
            for (int q = 0; q < 32; ++q) {
                const double phi = 2 * 3.14159265358979323846 * q / 32;
                disc.points.push_back(e.position +
                                      e.radius * (std::cos(phi) * a + std::sin(phi) * b));
            }
            scene.faces3.push_back(std::move(disc));
            scene.labels3.push_back({e.position, "emitter", {Role::Window}});
            break;
        }
    }
    if (glm::length(e.velocity) > 0 && e.rate > 0)
        scene.segments3.push_back({e.position,
                                   e.position + 0.25 * reach / glm::length(e.velocity) * e.velocity,
                                   "v̄",
                                   {Role::Window, 1.5f, true},
                                   true});

    // The particles, coloured by age.
    const std::size_t n = s.alive.size();
    const std::size_t stride = (n + kMaxDrawn - 1) / kMaxDrawn;
    const float radius = n > 500 ? 2.5f : n > 100 ? 3.0f : 4.0f;
    const double now = double(s.k) * in.dt;
    for (std::size_t i = 0; i < n; i += std::max<std::size_t>(stride, 1)) {
        const Particle& p = s.alive[i];
        const double age = now - double(p.born) * in.dt;
        const double share = p.lifetime == kForever ? age / duration
                             : p.lifetime > 0       ? age / p.lifetime
                                                    : 1.0;
        scene.points3.push_back({p.x, "", {Role::Subject, 2.0f, false, age_colour(share)}, radius});
    }
    // Velocity ticks on a few: where each would be 0.1 of the view's reach later.
    const double tick = speed > 0 ? 0.12 * reach / speed : 0;
    for (std::size_t q = 0; q < std::min(n, kTicks); ++q) {
        const Particle& p = s.alive[q * n / std::min(n, kTicks)];
        if (p.id == in.focus || glm::length(p.v) == 0) continue;
        scene.segments3.push_back({p.x, p.x + tick * p.v, "", {Role::Construction, 1.0f}, true});
    }
    // The focus particle.
    const Focus& f = s.focus;
    if (f.fate == Fate::Moved || f.fate == Fate::Born) {
        scene.points3.push_back({f.x, "#" + std::to_string(in.focus), {Role::Active}, 6.0f});
        if (glm::length(f.v) > 0 && tick > 0)
            scene.segments3.push_back({f.x, f.x + tick * f.v, "v", {Role::Active, 2.0f}, true});
    }

    // The camera frames the region the particles reach (from the input, so it stays put) and
    // the focus particle.
    glm::dvec3 lo = centre - glm::dvec3(0.7 * reach), hi = centre + glm::dvec3(0.7 * reach);
    if (f.fate == Fate::Moved || f.fate == Fate::Born)
        lo = glm::min(lo, f.x), hi = glm::max(hi, f.x);
    add_focus(scene, lo, hi);

    // Chart: alive, emitted and killed per frame over the whole run.
    const int emitted_now = s.emitted_n.empty() ? 0 : s.emitted_n.back();
    const int killed_now = s.killed_n.empty() ? 0 : s.killed_n.back();
    Panel& counts = add_chart(scene, "particles, frame by frame", Axis{"t (s)", 0, duration},
                              Axis{"count", 0, 0, false, true});
    auto plot = [&](const std::vector<int>& c, Style style, std::string name) {
        std::vector<glm::dvec2> line;
        const std::size_t step = std::max<std::size_t>(1, (c.size() + kMaxPlotPoints - 1) / kMaxPlotPoints);
        for (std::size_t q = 0; q < c.size(); q += step)
            line.push_back({double(q + 1) * in.dt, double(c[q])});
        if (!c.empty() && (c.size() - 1) % step != 0)
            line.push_back({double(c.size()) * in.dt, double(c.back())});
        add_line(counts, std::move(line), style, std::move(name));
    };
    plot(s.alive_n, {Role::Active, 2.5f}, "alive " + std::to_string(n));
    plot(s.emitted_n, {Role::Entering, 1.5f}, "emitted " + std::to_string(emitted_now));
    plot(s.killed_n, {Role::Leaving, 1.5f}, "killed " + std::to_string(killed_now));
    if (!s.alive_n.empty())
        counts.points.push_back(
            {{double(s.alive_n.size()) * in.dt, double(s.alive_n.back())}, "", {Role::Active}, 4.5f});
}

}  // namespace cg
