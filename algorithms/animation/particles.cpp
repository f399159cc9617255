// Sections: [physics] [emit] [frame] [spec] [validate] [advance] [narrate] [result and compute]
#include "animation/particles.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using Input = Particles::Input;
using Phase = Particles::Phase;
using State = Particles::State;
using Fate = Particles::Fate;
using Particle = Particles::Particle;

constexpr double kPi = 3.14159265358979323846;

__extension__ typedef unsigned __int128 U128;  // GCC and Clang: exact 128-bit products

enum Line { kLineStart = 1, kLineAge, kLineEuler, kLineBounce, kLineEmit, kLinePlot, kLineReport };

double max_abs(glm::dvec3 p) {
    return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
}

// Two unit vectors perpendicular to the unit vector w and to each other.
void basis(glm::dvec3 w, glm::dvec3& a, glm::dvec3& b) {
    const glm::dvec3 helper = std::fabs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    a = glm::normalize(glm::cross(w, helper));
    b = glm::cross(w, a);
}

glm::dvec3 axis_of(glm::dvec3 v) {
    const double len = glm::length(v);
    return len > 0 ? v / len : glm::dvec3(0, 1, 0);
}

// Moves x along n until n·x − h ≥ 0 as computed (a rounding case only: at most a few ulps).
void lift(const Particles::Plane& p, double d, glm::dvec3& x) {
    double delta = std::max(-d, 4 * 2.220446049250313e-16 * (max_abs(x) + std::fabs(p.h)));
    for (int i = 0; d < 0 && i < 200; ++i, delta *= 2) {
        x += delta * p.normal;
        d = Particles::distance(p, x);
    }
}

}  // namespace

const char* Particles::shape_name(Shape s) {
    return s == Shape::Point ? "point" : s == Shape::Disc ? "disc" : "line";
}

// ---- [physics] ------------------------------------------------------------------------------

long long Particles::emitted_by(double rate, double dt, int k) {
    // rate = m_r 2^e_r, dt = m_d 2^e_d with 53-bit integer mantissas: m_r m_d k < 2^123 fits in
    // 128 bits, so ⌊rate dt k⌋ is a shift of an exact integer (no rounding anywhere).
    if (!(rate > 0) || !(dt > 0) || k <= 0) return 0;
    int er = 0, ed = 0;
    const double fr = std::frexp(rate, &er), fd = std::frexp(dt, &ed);
    const auto mr = static_cast<std::uint64_t>(std::ldexp(fr, 53));
    const auto md = static_cast<std::uint64_t>(std::ldexp(fd, 53));
    const U128 m = U128(mr) * md * std::uint64_t(k);
    const int e = er + ed - 106;
    if (e >= 0) return e >= 64 ? kMaxEmitted + 1 : static_cast<long long>(m << e);
    if (e <= -128) return 0;
    return static_cast<long long>(m >> -e);
}

double Particles::carry(double rate, double dt, int k) {
    // The same exact product as emitted_by, keeping the bits below the binary point.
    if (!(rate > 0) || !(dt > 0) || k <= 0) return 0;
    int er = 0, ed = 0;
    const double fr = std::frexp(rate, &er), fd = std::frexp(dt, &ed);
    const U128 m = U128(static_cast<std::uint64_t>(std::ldexp(fr, 53))) *
                   static_cast<std::uint64_t>(std::ldexp(fd, 53)) * std::uint64_t(k);
    const int e = er + ed - 106;
    if (e >= 0) return 0;
    const U128 low = e <= -128 ? m : m & ((U128(1) << -e) - 1);
    const double f = std::ldexp(double(low), e);
    return f < 1e-9 ? 0 : f;  // what is left of 0.1's binary error is not a carry worth showing
}

bool Particles::aged_out(int frames, double dt, double lifetime) {
    if (lifetime == kForever) return false;
    // fma rounds frames·dt − L once, so its sign is the exact comparison's.
    return std::fma(double(frames), dt, -lifetime) >= 0;
}

double Particles::distance(const Plane& p, glm::dvec3 x) {
    return glm::dot(p.normal, x) - p.h;
}

void Particles::bounce(const Plane& p, double d, glm::dvec3& x, glm::dvec3& v) {
    const glm::dvec3 n = p.normal;
    x -= (1 + p.restitution) * d * n;  // the overshoot below, mirrored and scaled by e
    const double vn = glm::dot(v, n);
    if (vn < 0) {  // moving into the plane (always, but for rounding): reverse and damp
        const glm::dvec3 v_n = vn * n, v_t = v - v_n;
        v = -p.restitution * v_n + (1 - p.friction) * v_t;
    }
    const double after = distance(p, x);
    if (after < 0) lift(p, after, x);
}

// ---- [emit] ---------------------------------------------------------------------------------

Particles::Particle Particles::emit(const Emitter& e, int id, int frame, Rng& rng) {
    // Six numbers a particle, always in this order, whatever the shape: position (2),
    // direction (2), speed, lifetime.
    const double u1 = rng.uniform(0, 1), u2 = rng.uniform(0, 1);
    const double u3 = rng.uniform(0, 1), u4 = rng.uniform(0, 1);
    const double u5 = rng.uniform(-1, 1);
    const double life = rng.uniform(e.life_min, e.life_max);
    const double speed = glm::length(e.velocity);
    glm::dvec3 w = axis_of(e.velocity), a, b;
    basis(w, a, b);
    Particle p;
    p.id = id;
    p.born = frame;
    p.lifetime = e.life_min == e.life_max ? e.life_min : life;
    switch (e.shape) {
        case Shape::Point:
            p.x = e.position;
            break;
        case Shape::Disc: {  // uniform over the disc: r = R √u
            const double r = e.radius * std::sqrt(u1), phi = 2 * kPi * u2;
            p.x = e.position + r * (std::cos(phi) * a + std::sin(phi) * b);
            break;
        }
        case Shape::Line:
            p.x = e.position + u1 * (e.end - e.position);
            break;
    }
    // Uniform over the cap of half-angle `spread`: cos θ uniform in [cos spread, 1].
    const double cos_spread = std::cos(e.spread * kPi / 180);
    const double c = 1 - u3 * (1 - cos_spread), s = std::sqrt(std::max(0.0, 1 - c * c));
    const double psi = 2 * kPi * u4;
    const double factor = 1 + e.jitter * u5;
    if (speed > 0)
        p.v = factor * (c * e.velocity + (s * speed) * (std::cos(psi) * a + std::sin(psi) * b));
    return p;
}

// ---- [frame] --------------------------------------------------------------------------------

Particles::Counts Particles::frame(const Input& in, int k, Rng& rng, long long& emitted,
                                   std::vector<Particle>& alive, Focus& focus) {
    Counts c;
    const double dt = in.dt;
    const int f = in.focus;
    bool seen = false;
    std::size_t w = 0;
    for (std::size_t r = 0; r < alive.size(); ++r) {
        Particle p = alive[r];
        if (aged_out(k - p.born, dt, p.lifetime)) {  // age t − t_birth reached the lifetime
            ++c.killed;
            if (p.id == f) focus.fate = Fate::Died, focus.x = p.x, focus.v = p.v, seen = true;
            continue;
        }
        const glm::dvec3 x0 = p.x, v0 = p.v;
        const glm::dvec3 a = in.gravity - in.drag * p.v;
        p.v += dt * a;  // semi-implicit Euler: the new velocity moves the particle
        p.x += dt * p.v;
        const glm::dvec3 x1 = p.x, v1 = p.v;
        double d = 0;
        bool hit = false;
        if (in.plane.on) {
            d = distance(in.plane, p.x);
            if (d < 0) {
                bounce(in.plane, d, p.x, p.v);
                hit = true;
                ++c.bounced;
            }
        }
        if (p.id == f) {
            focus.fate = Fate::Moved;
            focus.x0 = x0, focus.v0 = v0, focus.a = a, focus.x1 = x1, focus.v1 = v1;
            focus.x = p.x, focus.v = p.v, focus.hit = hit, focus.d = d;
            focus.lifetime = p.lifetime, focus.born = p.born;
            seen = true;
        }
        alive[w++] = p;
    }
    alive.resize(w);

    const long long n = emitted_by(in.emitter.rate, dt, k);
    const int first = int(in.start.size());
    for (long long i = emitted; i < n; ++i) {
        Particle p = emit(in.emitter, first + int(i), k, rng);
        if (in.plane.on) {
            const double d = distance(in.plane, p.x);
            if (d < 0) lift(in.plane, d, p.x);  // an emitter on the plane, by rounding below
        }
        ++c.emitted;
        if (p.id == f) {
            focus.fate = Fate::Born, focus.x = p.x, focus.v = p.v, focus.hit = false;
            focus.lifetime = p.lifetime, focus.born = k;
            seen = true;
        }
        if (aged_out(0, dt, p.lifetime)) {  // lifetime 0: born and gone in the same frame
            ++c.killed;
            continue;
        }
        alive.push_back(p);
    }
    emitted = n;
    if (!seen) focus.fate = f < first + emitted ? Fate::Gone : Fate::NotBorn;
    return c;
}

double Particles::max_lifetime(const Input& in) {
    double m = in.emitter.rate > 0 ? in.emitter.life_max : 0;
    for (const Start& s : in.start) m = std::max(m, s.lifetime);
    return m;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Particles::spec() {
    static const Spec spec{
        "particles",
        "Particle systems: emit, move under gravity and drag, bounce off a plane, age and kill",
        "Animation",
        {
            "t ← 0;  N ← 0;  the particles given at the start are alive, age 0",
            "t ← t + dt;  kill every particle whose age t − t_birth ≥ its lifetime",
            "a ← g − c v;   v ← v + dt a;   x ← x + dt v   (semi-implicit Euler)",
            "if d = n·x − h < 0:  x ← x − (1 + e) d n;   v ← −e v_n + (1 − μ) v_t   (bounce)",
            "N_new ← ⌊rate · t⌋;  emit N_new − N particles (emitter point, velocity in the cone, "
            "lifetime);  N ← N_new",
            "plot alive, emitted and killed for this frame",
            "report the counts and the particles alive at the end",
        },
        {
            {"frame", "one frame of dt: particles aged, killed, moved, and new ones emitted"},
            {"bounce", "a frame in which the focus particle hit the plane and bounced"},
            {"summary", "the run's end: totals and the particles still alive"},
        },
        {},  // no sliders
        {
            .predict = {{"frame", {"N", "v"}}, {"bounce", {"v"}}},
            .mistakes =
                {
                    {"frame", "N", "off-by-one",
                     "rounded rate · t up instead of down: one particle too many"},
                    {"frame", "v", "keep", "moved x with the old velocity and forgot v ← v + dt a"},
                    {"bounce", "v", "negate",
                     "reversed the whole velocity at the bounce, not just its normal part"},
                },
        },
        "t",  // the clock: a step is one frame of dt seconds, so Play keeps real time
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

void check_point(glm::dvec3 p, const std::string& field) {
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(p[c])) throw InputError(field, "must be finite (got " + given(p[c]) + ")");
        if (std::fabs(p[c]) > Particles::kMaxCoordinate)
            throw InputError(field, "is too large (" + given(p[c]) + "): at most 1e6 in size");
    }
}

void check_range(double x, double lo, double hi, const std::string& field, const char* what) {
    if (!std::isfinite(x) || x < lo || x > hi)
        throw InputError(field, std::string("must be ") + what + " (got " + given(x) + ")");
}

// The emitter's lowest signed distance to the plane.
double lowest(const Particles::Emitter& e, const Particles::Plane& p) {
    double d = Particles::distance(p, e.position);
    if (e.shape == Particles::Shape::Line) d = std::min(d, Particles::distance(p, e.end));
    if (e.shape == Particles::Shape::Disc) {  // the rim's lowest point: r |n − (n·w) w|
        const glm::dvec3 w = axis_of(e.velocity);
        d -= e.radius * glm::length(p.normal - glm::dot(p.normal, w) * w);
    }
    return d;
}

}  // namespace

void Particles::validate(const Input& in) {
    const Emitter& e = in.emitter;
    if (!std::isfinite(in.dt) || in.dt <= 0)
        throw InputError("dt", "must be a time step > 0, got " + given(in.dt));
    check_range(in.dt, kMinDt, 10, "dt", "from 1e-6 to 10 seconds");
    if (in.frames < 1 || in.frames > kMaxFrames)
        throw InputError("frames", "must be 1 to " + std::to_string(kMaxFrames) + " (got " +
                                       std::to_string(in.frames) + ")");
    check_point(e.position, "emitter.position");
    if (e.shape == Shape::Line) check_point(e.end, "emitter.end");
    if (e.shape == Shape::Disc)
        check_range(e.radius, 0, kMaxCoordinate, "emitter.radius", "0 to 1e6");
    check_point(e.velocity, "emitter.velocity");
    check_range(e.spread, 0, 180, "emitter.spread", "an angle from 0 to 180 degrees");
    check_range(e.jitter, 0, 1, "emitter.jitter", "0 to 1 (a share of the speed)");
    check_range(e.rate, 0, 1e6, "emitter.rate", "0 to 1e6 particles per second");
    check_range(e.life_min, 0, kMaxLifetime, "emitter.lifetime", "0 to 1e6 seconds");
    check_range(e.life_max, 0, kMaxLifetime, "emitter.lifetime", "0 to 1e6 seconds");
    if (e.life_min > e.life_max)
        throw InputError("emitter.lifetime", "must be [min, max] with min ≤ max (got [" +
                                                 given(e.life_min) + ", " + given(e.life_max) + "])");
    const double total = e.rate * in.dt * double(in.frames);
    if (total > double(kMaxEmitted))
        throw InputError("emitter.rate", given(e.rate) + " per second for " + given(in.dt * in.frames) +
                                             " s makes " + given(total) +
                                             " particles; at most 100000 in a run");
    if (in.start.size() > std::size_t(kMaxStart))
        throw InputError("start", "has " + std::to_string(in.start.size()) +
                                      " particles; at most " + std::to_string(kMaxStart));
    for (std::size_t i = 0; i < in.start.size(); ++i) {
        const std::string at = "start[" + std::to_string(i) + "].";
        check_point(in.start[i].position, at + "position");
        check_point(in.start[i].velocity, at + "velocity");
        const double L = in.start[i].lifetime;
        if (L != kForever) check_range(L, 1e-300, kMaxLifetime, at + "lifetime", "> 0 seconds");
    }
    check_point(in.gravity, "gravity");
    check_range(in.drag, 0, 1e6, "drag", "≥ 0 (per second)");
    if (in.drag * in.dt > 1)
        throw InputError("drag", "times dt must be at most 1 (got " + given(in.drag * in.dt) +
                                     "): a larger c·dt would reverse the velocity in one step");
    if (in.plane.on) {
        const Plane& p = in.plane;
        check_point(p.point, "plane.point");
        check_point(p.normal, "plane.normal");
        if (!(glm::length(p.normal) > 1e-12))
            throw InputError("plane.normal", "must not be zero: a plane needs a direction");
        check_range(p.restitution, 0, 1, "plane.restitution", "0 to 1");
        check_range(p.friction, 0, 1, "plane.friction", "0 to 1");
    }
    // The most particles alive at once, for the work limit.
    const long long emitted_max = emitted_by(e.rate, in.dt, in.frames);
    const double at_once =
        std::min(double(emitted_max), e.rate * (e.life_max + in.dt) + 1) + double(in.start.size());
    if (at_once * in.frames > double(kMaxWork))
        throw InputError("frames", std::to_string(in.frames) + " frames with up to " +
                                       given(std::floor(at_once)) +
                                       " particles alive is too much work: frames × alive must "
                                       "be at most 2e7");
    if (in.focus < 0 || in.focus > kMaxStart + kMaxEmitted)
        throw InputError("focus", "must name a particle 0 to " +
                                      std::to_string(kMaxStart + kMaxEmitted) + " (got " +
                                      std::to_string(in.focus) + ")");
}

Particles::Input Particles::resolve(const Input& given) {
    validate(given);
    Input in = given;
    if (in.plane.on) {
        in.plane.normal = glm::normalize(in.plane.normal);
        in.plane.h = glm::dot(in.plane.normal, in.plane.point);
        const double scale = 1 + max_abs(in.emitter.position) + max_abs(in.plane.point);
        if (lowest(in.emitter, in.plane) < -1e-9 * scale)
            throw InputError("emitter.position", "is below the plane (signed distance " +
                                                     cg::given(lowest(in.emitter, in.plane)) +
                                                     "): particles would start inside the ground");
        for (std::size_t i = 0; i < in.start.size(); ++i)
            if (distance(in.plane, in.start[i].position) < -1e-9 * scale)
                throw InputError("start[" + std::to_string(i) + "].position",
                                 "is below the plane: a particle must start on or above it");
    } else {
        in.plane = Plane{};
    }
    if (in.emitter.shape != Shape::Line) in.emitter.end = Emitter{}.end;
    if (in.emitter.shape != Shape::Disc) in.emitter.radius = Emitter{}.radius;
    return in;
}

Particles::State Particles::start(const Input& in) {
    return begin(Shared<Input>(resolve(in)));
}

Particles::State Particles::begin(Shared<Input> shared) {
    const Input& in = *shared;
    State s;
    s.in = std::move(shared);
    s.rng = Rng(in.seed);
    for (std::size_t i = 0; i < in.start.size(); ++i) {
        Particle p;
        p.x = in.start[i].position;
        p.v = in.start[i].velocity;
        if (in.plane.on) {
            const double d = distance(in.plane, p.x);
            if (d < 0) lift(in.plane, d, p.x);
        }
        p.lifetime = in.start[i].lifetime;
        p.id = int(i);
        s.alive.push_back(p);
    }
    if (in.focus < int(in.start.size())) {
        s.focus.fate = Fate::Born;
        s.focus.x = s.alive[std::size_t(in.focus)].x;
        s.focus.v = s.alive[std::size_t(in.focus)].v;
        s.focus.lifetime = in.start[std::size_t(in.focus)].lifetime;
    }
    s.alive_n.reserve(std::size_t(in.frames));
    s.emitted_n.reserve(std::size_t(in.frames));
    s.killed_n.reserve(std::size_t(in.frames));
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void Particles::take_step(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Frame: {
            ++s.k;
            s.now = frame(in, s.k, s.rng, s.emitted, s.alive, s.focus);
            s.killed += s.now.killed;
            s.bounces += s.now.bounced;
            s.alive_n.push_back(int(s.alive.size()));
            s.emitted_n.push_back(s.now.emitted);
            s.killed_n.push_back(s.now.killed);
            s.last = Phase::Frame;
            if (s.k == in.frames) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:
            s.last = Phase::Summary;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void Particles::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    take_step(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

void frame_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const double t = double(s.k) * in.dt;
    info.vars = {{"t", t},
                 {"k", (long long)s.k},
                 {"dt", in.dt},
                 {"N", (long long)s.emitted},
                 {"carry", Particles::carry(in.emitter.rate, in.dt, s.k)},
                 {"emitted", (long long)s.now.emitted},
                 {"killed", (long long)s.now.killed},
                 {"alive", (long long)s.alive.size()},
                 {"x", vec(s.focus.x)},
                 {"v", vec(s.focus.v)}};
    if (s.focus.fate == Fate::Moved) info.vars.push_back({"a", vec(s.focus.a)});
    if (s.focus.hit && s.focus.fate == Fate::Moved) info.vars.push_back({"d", s.focus.d});
}

std::string counts_text(const State& s) {
    const Input& in = *s.in;
    const double t = double(s.k) * in.dt;
    std::string text = "Frame " + std::to_string(s.k) + ", t = " + num(t) + ": ";
    if (in.emitter.rate > 0)
        text += "N(t) = ⌊rate · t⌋ = ⌊" + num(in.emitter.rate) + " · " + num(t) +
                "⌋ = " + std::to_string(s.emitted) + ", so " + std::to_string(s.now.emitted) +
                " emitted (carry " + num(Particles::carry(in.emitter.rate, in.dt, s.k), 4) + "); ";
    else
        text += "the emitter is off (rate 0); ";
    text += std::to_string(s.now.killed) + " killed, " + std::to_string(s.alive.size()) + " alive" +
            (s.now.bounced ? ", " + std::to_string(s.now.bounced) + " bounced" : std::string()) +
            ". ";
    return text;
}

std::string focus_text(const State& s) {
    const Input& in = *s.in;
    const Particles::Focus& f = s.focus;
    const std::string name = "Particle #" + std::to_string(in.focus);
    switch (f.fate) {
        case Fate::NotBorn:
            return name + " is not born yet (it is emitted once N(t) > " +
                   std::to_string(in.focus - int(in.start.size())) + ").";
        case Fate::Gone:
            return name + " has died (it was last at x = " + num(f.x) + ").";
        case Fate::Died:
            return name + " reached its lifetime " + num(f.lifetime) + " s (age " +
                   num(double(s.k - f.born) * in.dt) + " s) and is killed at x = " + num(f.x) + ".";
        case Fate::Born:
            return name + " is born at the emitter: x = " + num(f.x) + ", v = " + num(f.v) +
                   ", lifetime " + num(f.lifetime) + " s" +
                   (Particles::aged_out(0, in.dt, f.lifetime) ? " (0: it dies at once)." : ".");
        case Fate::Moved:
            break;
    }
    std::string t = name + " (age " + num(double(s.k - f.born) * in.dt) +
                    " s): a = g − c v = " + num(in.gravity);
    if (in.drag != 0) t += " − " + num(in.drag) + " · " + num(f.v0);
    t += " = " + num(f.a) + "; v ← v + dt a = " + num(f.v0) + " + " + num(in.dt) + " · " +
         num(f.a) + " = " + num(f.v1) + "; x ← x + dt v = " + num(f.x0) + " + " + num(in.dt) +
         " · " + num(f.v1) + " = " + num(f.x1) + ".";
    if (f.hit) {
        const glm::dvec3 n = in.plane.normal;
        const double vn = glm::dot(f.v1, n);
        t += " Below the plane by d = n·x − h = " + num(f.d) +
             ": reflected, x ← x − (1 + e) d n = " + num(f.x) + "; v_n = " + num(vn * n) +
             ", v_t = " + num(f.v1 - vn * n) + ", v ← −e v_n + (1 − μ) v_t = −" +
             num(in.plane.restitution) + " v_n + " + num(1 - in.plane.friction) +
             " v_t = " + num(f.v) + ".";
    }
    return t;
}

int focus_line(const State& s) {
    switch (s.focus.fate) {
        case Fate::Died:
            return kLineAge;
        case Fate::Moved:
            return s.focus.hit ? kLineBounce : kLineEuler;
        default:
            return kLineEmit;
    }
}

}  // namespace

void Particles::narrate(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.math.clear();
    if (s.last == Phase::Frame) {
        const bool hit = s.focus.fate == Fate::Moved && s.focus.hit;
        info.event = hit ? "bounce" : "frame";
        info.line = focus_line(s);
        info.narration = counts_text(s) + focus_text(s);
        const double t = double(s.k) * in.dt;
        info.math = "N(" + tex(t) + ") = \\lfloor " + tex(in.emitter.rate) + " \\cdot " + tex(t) +
                    " \\rfloor = " + std::to_string(s.emitted);
        frame_vars(s, info);
        return;
    }
    info.event = "summary";
    info.line = kLineReport;
    const double t = double(s.k) * in.dt;
    info.narration =
        "Done: " + std::to_string(s.k) + " frames of dt = " + num(in.dt) + " (t = " + num(t) +
        "). Emitted " + std::to_string(s.emitted) +
        (in.start.empty() ? "" : " (and " + std::to_string(in.start.size()) + " at the start)") +
        ", killed " + std::to_string(s.killed) + ", " + std::to_string(s.alive.size()) +
        " alive, " + std::to_string(s.bounces) + " bounces in all.";
    info.math = "N(" + tex(t) + ") = " + std::to_string(s.emitted);
    frame_vars(s, info);
    info.vars.push_back({"bounces", (long long)s.bounces});
}

// ---- [result and compute] -------------------------------------------------------------------

namespace {

void fill_end(const Input& in, int k, const std::vector<Particle>& alive,
              const Particles::Focus& focus, Particles::Result& r) {
    r.dt = in.dt;
    r.frames = k;
    r.t = double(k) * in.dt;
    r.alive = int(alive.size());
    for (const Particle& p : alive) {
        r.ids.push_back(p.id);
        r.positions.push_back(p.x);
        r.velocities.push_back(p.v);
        r.ages.push_back(double(k - p.born) * in.dt);
    }
    r.focus = in.focus;
    r.focus_born = focus.fate != Fate::NotBorn;
    r.focus_alive = focus.fate == Fate::Moved ||
                    (focus.fate == Fate::Born && !Particles::aged_out(0, in.dt, focus.lifetime));
    r.x = focus.x;
    r.v = focus.v;
}

}  // namespace

Particles::Result Particles::result(const State& s) {
    Result r;
    r.emitted = s.emitted;
    r.killed = s.killed;
    r.bounces = s.bounces;
    r.alive_per_frame = s.alive_n;
    r.emitted_per_frame = s.emitted_n;
    r.killed_per_frame = s.killed_n;
    fill_end(*s.in, s.k, s.alive, s.focus, r);
    return r;
}

Particles::Result Particles::compute(const Input& given) {
    const State s0 = start(given);
    const Input& in = *s0.in;
    Rng rng = s0.rng;
    std::vector<Particle> alive = s0.alive;
    Focus focus = s0.focus;
    Result r;
    r.alive_per_frame.reserve(std::size_t(in.frames));
    r.emitted_per_frame.reserve(std::size_t(in.frames));
    r.killed_per_frame.reserve(std::size_t(in.frames));
    long long emitted = 0;
    for (int k = 1; k <= in.frames; ++k) {
        const Counts c = frame(in, k, rng, emitted, alive, focus);
        r.killed += c.killed;
        r.bounces += c.bounced;
        r.alive_per_frame.push_back(int(alive.size()));
        r.emitted_per_frame.push_back(c.emitted);
        r.killed_per_frame.push_back(c.killed);
    }
    r.emitted = emitted;
    fill_end(in, in.frames, alive, focus, r);
    return r;
}

}  // namespace cg
