// Sections: [physics] [integrators] [spec] [validate] [advance] [narrate] [result and compute]
//           [draw]
#include "animation/spring_mass.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using Input = SpringMass::Input;
using Integrator = SpringMass::Integrator;
using Phase = SpringMass::Phase;
using State = SpringMass::State;
using Energy = SpringMass::Energy;
using V3 = std::vector<glm::dvec3>;

enum Line {
    kLineStart = 1,
    kLineForces,
    kLineExplicit,
    kLineSymplectic,
    kLineRK4,
    kLineEnergy,
    kLineBlowUp,
    kLineReport
};

int integrator_line(Integrator i) {
    return i == Integrator::ExplicitEuler     ? kLineExplicit
           : i == Integrator::SymplecticEuler ? kLineSymplectic
                                              : kLineRK4;
}

bool finite(glm::dvec3 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace

const char* SpringMass::integrator_name(Integrator i) {
    return i == Integrator::ExplicitEuler     ? "explicit-euler"
           : i == Integrator::SymplecticEuler ? "symplectic-euler"
                                              : "rk4";
}

// ---- [physics] ------------------------------------------------------------------------------

void SpringMass::spring_force(const Spring& s, glm::dvec3 xi, glm::dvec3 xj, glm::dvec3 vi,
                              glm::dvec3 vj, glm::dvec3& hooke, glm::dvec3& damping) {
    const glm::dvec3 d = xi - xj;
    const double len = glm::length(d);
    if (!(len > 0)) {  // coincident ends: no direction, no force (and no 0/0)
        hooke = damping = glm::dvec3(0);
        return;
    }
    const glm::dvec3 u = d / len;
    hooke = -s.stiffness * (len - s.rest) * u;
    damping = -s.damping * glm::dot(vi - vj, u) * u;
}

void SpringMass::forces(const Input& in, const V3& x, const V3& v, V3& f) {
    const std::size_t n = in.masses.size();
    f.resize(n);
    for (std::size_t i = 0; i < n; ++i) f[i] = in.masses[i].mass * in.gravity - in.drag * v[i];
    for (const Spring& s : in.springs) {
        glm::dvec3 h, d;
        spring_force(s, x[s.i], x[s.j], v[s.i], v[s.j], h, d);
        f[s.i] += h + d;
        f[s.j] -= h + d;  // Newton's third law: internal forces sum to zero
    }
}

SpringMass::Energy SpringMass::energy(const Input& in, const V3& x, const V3& v) {
    Energy e;
    for (std::size_t i = 0; i < in.masses.size(); ++i) {
        const Mass& m = in.masses[i];
        if (m.pinned) continue;  // a pinned mass neither moves nor falls: a constant left out
        e.kinetic += 0.5 * m.mass * glm::dot(v[i], v[i]);
        e.gravity -= m.mass * glm::dot(in.gravity, x[i]);
    }
    for (const Spring& s : in.springs) {
        const double stretch = glm::length(x[s.i] - x[s.j]) - s.rest;
        e.spring += 0.5 * s.stiffness * stretch * stretch;
    }
    return e;
}

double SpringMass::energy_scale(const Energy& e0) {
    const double s = e0.kinetic + e0.spring + std::fabs(e0.gravity);
    return s > 0 ? s : 1;
}

bool SpringMass::blows_up(const V3& x, const V3& v, const Energy& e, double scale) {
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!finite(x[i]) || !finite(v[i])) return true;
    const double E = e.total();
    return !std::isfinite(E) || std::fabs(E) > kBlowUp * scale;
}

// ---- [integrators] --------------------------------------------------------------------------

namespace {

// a = F/m, 0 for a pinned mass; returns F on `watch`.
glm::dvec3 accelerations(const Input& in, const V3& x, const V3& v, V3& a) {
    SpringMass::forces(in, x, v, a);
    const glm::dvec3 f = a[std::size_t(in.watch)];
    for (std::size_t i = 0; i < a.size(); ++i)
        a[i] = in.masses[i].pinned ? glm::dvec3(0) : a[i] / in.masses[i].mass;
    return f;
}

}  // namespace

glm::dvec3 SpringMass::advance(const Input& in, const V3& x, const V3& v, V3& x1, V3& v1,
                               Scratch& w) {
    const std::size_t n = x.size();
    const double dt = in.dt;
    x1.resize(n);
    v1.resize(n);
    glm::dvec3 f{0, 0, 0};
    switch (in.integrator) {
        case Integrator::ExplicitEuler:
            f = accelerations(in, x, v, w.a);
            for (std::size_t i = 0; i < n; ++i) {
                x1[i] = x[i] + dt * v[i];
                v1[i] = v[i] + dt * w.a[i];
            }
            break;
        case Integrator::SymplecticEuler:
            f = accelerations(in, x, v, w.a);
            for (std::size_t i = 0; i < n; ++i) {
                v1[i] = v[i] + dt * w.a[i];
                x1[i] = x[i] + dt * v1[i];
            }
            break;
        case Integrator::RK4: {
            // Stage q evaluates f = (v, a) at y + h_q k_{q−1}: h = 0, dt/2, dt/2, dt.
            const double h[4] = {0, dt / 2, dt / 2, dt};
            w.x.resize(n);
            w.v.resize(n);
            for (int q = 0; q < 4; ++q) {
                const V3* xs = &x;
                const V3* vs = &v;
                if (q > 0) {
                    for (std::size_t i = 0; i < n; ++i) {
                        w.x[i] = x[i] + h[q] * w.kx[q - 1][i];
                        w.v[i] = v[i] + h[q] * w.kv[q - 1][i];
                    }
                    xs = &w.x;
                    vs = &w.v;
                }
                w.kx[q].assign(vs->begin(), vs->end());
                const glm::dvec3 fq = accelerations(in, *xs, *vs, w.kv[q]);
                if (q == 0) f = fq;
            }
            for (std::size_t i = 0; i < n; ++i) {
                x1[i] =
                    x[i] + dt / 6 * (w.kx[0][i] + 2.0 * w.kx[1][i] + 2.0 * w.kx[2][i] + w.kx[3][i]);
                v1[i] =
                    v[i] + dt / 6 * (w.kv[0][i] + 2.0 * w.kv[1][i] + 2.0 * w.kv[2][i] + w.kv[3][i]);
            }
            break;
        }
    }
    return f;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& SpringMass::spec() {
    static const Spec spec{
        "spring-mass",
        "Spring-mass systems: point masses and damped springs, integrated step by step",
        "Animation",
        {
            "x, v ← the masses' initial positions and velocities;  t ← 0",
            "F_i ← m_i g − drag v_i + Σ_springs [−k (|d| − L) d̂ − c ((v_i − v_j)·d̂) d̂],  "
            "d = x_i − x_j   ▷ −F on mass j",
            "explicit Euler:    x ← x + dt v,   v ← v + dt F/m   (both from the old state)",
            "symplectic Euler:  v ← v + dt F/m,   x ← x + dt v   (the new v)",
            "RK4:  k1..k4 = (v, F/m) at y, y + dt/2 k1, y + dt/2 k2, y + dt k3;  "
            "y ← y + dt/6 (k1 + 2k2 + 2k3 + k4)",
            "E ← Σ ½ m v² + Σ ½ k (|d| − L)² − Σ m g·x;   t ← t + dt",
            "if the new state is not finite or |E| > 10¹² E_scale: blow-up, stop",
            "report the final state, the energy after every step and the largest drift",
        },
        {
            {"step", "one time step of the whole system, with the energies after it"},
            {"blow-up", "the step's new state is not finite or its energy exploded: the run stops"},
            {"summary", "the run's end: the final state and the largest energy drift"},
        },
        {},  // no sliders
        {
            .predict = {{"step", {"x", "v"}}},
            .mistakes =
                {
                    {"step", "F", "negate",
                     "took the spring force as +k (|d| − L) d̂: a stretched spring pushes the "
                     "masses apart"},
                    {"step", "v", "keep", "moved x with v but forgot to update v from the force"},
                },
            .variants = {{"explicit-euler", "/integrator", "\"explicit-euler\""},
                         {"symplectic-euler", "/integrator", "\"symplectic-euler\""},
                         {"rk4", "/integrator", "\"rk4\""}},
        },
        "t",  // the clock: a step is one frame of dt seconds, so Play keeps real time
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

std::string at(const char* list, std::size_t i, const char* field) {
    return std::string(list) + "[" + std::to_string(i) + "]." + field;
}

void check_point(glm::dvec3 p, const std::string& field) {
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(p[c])) throw InputError(field, "must be finite (got " + given(p[c]) + ")");
        if (std::fabs(p[c]) > SpringMass::kMaxCoordinate)
            throw InputError(field, "is too large (" + given(p[c]) + "): at most 1e6 in size");
    }
}

void check_range(double x, double hi, const std::string& field, const char* what) {
    if (!std::isfinite(x) || x < 0)
        throw InputError(field, std::string("must be ≥ 0 (") + what + "), got " + given(x));
    if (x > hi) throw InputError(field, "is too large (" + given(x) + "): at most " + given(hi));
}

}  // namespace

void SpringMass::validate(const Input& in) {
    const std::size_t n = in.masses.size();
    if (n == 0) throw InputError("masses", "must have at least 1 mass (got none)");
    if (n > std::size_t(kMaxMasses))
        throw InputError("masses", "has " + std::to_string(n) + " masses; at most " +
                                       std::to_string(kMaxMasses) + " are simulated");
    if (in.springs.size() > std::size_t(kMaxSprings))
        throw InputError("springs", "has " + std::to_string(in.springs.size()) +
                                        " springs; at most " + std::to_string(kMaxSprings));
    for (std::size_t i = 0; i < n; ++i) {
        const Mass& m = in.masses[i];
        check_point(m.position, at("masses", i, "position"));
        check_point(m.velocity, at("masses", i, "velocity"));
        if (!std::isfinite(m.mass) || m.mass <= 0)
            throw InputError(at("masses", i, "mass"),
                             "must be > 0 (F = m a needs a positive mass), got " + given(m.mass));
        if (m.mass > kMaxMass)
            throw InputError(at("masses", i, "mass"),
                             "is too large (" + given(m.mass) + "): at most 1e12");
        if (m.pinned && m.velocity != glm::dvec3(0))
            throw InputError(at("masses", i, "velocity"),
                             "must be 0 for a pinned mass: a pinned mass does not move");
    }
    for (std::size_t k = 0; k < in.springs.size(); ++k) {
        const Spring& s = in.springs[k];
        for (int end = 0; end < 2; ++end) {
            const int idx = end == 0 ? s.i : s.j;
            if (idx < 0 || std::size_t(idx) >= n)
                throw InputError(at("springs", k, end == 0 ? "i" : "j"),
                                 "must name a mass 0 to " + std::to_string(n - 1) + " (got " +
                                     std::to_string(idx) + ")");
        }
        if (s.i == s.j)
            throw InputError(at("springs", k, "j"),
                             "joins mass " + std::to_string(s.i) +
                                 " to itself: a spring needs two different masses");
        check_range(s.stiffness, kMaxStiffness, at("springs", k, "stiffness"),
                    "force per unit stretch");
        check_range(s.damping, kMaxStiffness, at("springs", k, "damping"), "force per unit speed");
        if (s.has_rest) check_range(s.rest, 1e7, at("springs", k, "rest_length"), "a length");
    }
    check_point(in.gravity, "gravity");
    check_range(in.drag, kMaxStiffness, "drag", "force per unit speed");
    if (!std::isfinite(in.dt) || in.dt <= 0)
        throw InputError("dt", "must be a time step > 0, got " + given(in.dt));
    if (in.dt > 1e3) throw InputError("dt", "is too large (" + given(in.dt) + "): at most 1000");
    if (in.steps < 1 || in.steps > kMaxSteps)
        throw InputError("steps", "must be 1 to " + std::to_string(kMaxSteps) + " (got " +
                                      std::to_string(in.steps) + ")");
    const long long work = (long long)in.steps * (long long)(n + in.springs.size());
    if (work > kMaxWork)
        throw InputError("steps", std::to_string(in.steps) + " steps of " + std::to_string(n) +
                                      " masses and " + std::to_string(in.springs.size()) +
                                      " springs is too much work: steps × (masses + springs) "
                                      "must be at most " +
                                      std::to_string(kMaxWork));
    if (in.watch < -1 || in.watch >= int(n))
        throw InputError("watch", "must name a mass 0 to " + std::to_string(n - 1) + " (got " +
                                      std::to_string(in.watch) + ")");
}

SpringMass::Input SpringMass::resolve(const Input& given) {
    validate(given);
    Input in = given;
    for (Spring& s : in.springs)
        if (!s.has_rest) {
            s.rest = glm::length(in.masses[s.i].position - in.masses[s.j].position);
            s.has_rest = true;
        }
    if (in.watch < 0) {
        in.watch = 0;
        for (std::size_t i = 0; i < in.masses.size(); ++i)
            if (!in.masses[i].pinned) {
                in.watch = int(i);
                break;
            }
    }
    return in;
}

SpringMass::State SpringMass::start(const Input& in) {
    return begin(Shared<Input>(resolve(in)));
}

SpringMass::State SpringMass::begin(Shared<Input> shared) {
    const Input& in = *shared;
    State s;
    s.in = std::move(shared);
    for (const Mass& m : in.masses) {
        s.x.push_back(m.position);
        s.v.push_back(m.velocity);
    }
    s.energy = energy(in, s.x, s.v);
    s.energy_scale = energy_scale(s.energy);
    s.history.reserve(std::size_t(in.steps) + 1);
    s.path.reserve(std::size_t(in.steps) + 1);
    s.history.push_back(s.energy.total());
    s.path.push_back(s.x[std::size_t(in.watch)]);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void SpringMass::take_step(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Step: {
            Scratch& w = s.scratch;
            const glm::dvec3 f = advance(in, s.x, s.v, w.nx, w.nv, w);
            const Energy e = energy(in, w.nx, w.nv);
            if (blows_up(w.nx, w.nv, e, s.energy_scale)) {
                // The step is refused: the last finite state stays, and the run ends.
                s.blew_up = true;
                s.not_finite = !std::isfinite(e.total());
                for (std::size_t i = 0; i < w.nx.size() && !s.not_finite; ++i)
                    s.not_finite = !finite(w.nx[i]) || !finite(w.nv[i]);
                s.refused_energy = s.not_finite ? 0 : e.total();
                s.force = f;
                s.last = Phase::BlowUp;
                s.phase = Phase::Summary;
                return;
            }
            std::swap(s.x, w.nx);
            std::swap(s.v, w.nv);
            s.force = f;
            s.energy = e;
            ++s.k;
            s.history.push_back(e.total());
            s.path.push_back(s.x[std::size_t(in.watch)]);
            s.max_drift =
                std::max(s.max_drift, std::fabs(e.total() - s.history.front()) / s.energy_scale);
            s.last = Phase::Step;
            if (s.k == in.steps) s.phase = Phase::Summary;
            return;
        }
        case Phase::BlowUp:  // not a phase of its own: the refused step goes to Summary
        case Phase::Summary:
            s.last = Phase::Summary;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void SpringMass::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    take_step(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string mass_name(int i) {
    return "mass " + std::to_string(i);
}

void energy_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t w = std::size_t(in.watch);
    info.vars = {{"t", double(s.k) * in.dt},
                 {"k", (long long)s.k},
                 {"dt", in.dt},
                 {"x", vec(s.x[w])},
                 {"v", vec(s.v[w])},
                 {"F", vec(s.force)},
                 {"E_kin", s.energy.kinetic},
                 {"E_spring", s.energy.spring},
                 {"E_grav", s.energy.gravity},
                 {"E_total", s.energy.total()}};
}

std::string energy_text(const State& s) {
    const Energy& e = s.energy;
    const double drift = (e.total() - s.history.front()) / s.energy_scale;
    return "Energy: kinetic " + num(e.kinetic) + " + spring " + num(e.spring) + " + gravity " +
           num(e.gravity) + " = " + num(e.total()) + " (E_0 = " + num(s.history.front()) +
           ", drift " + num(drift, 3) + " of E_scale = " + num(s.energy_scale) + ").";
}

// The force on the watched mass at t = 0, term by term (the first step's narration).
std::string force_terms(const Input& in, const V3& x, const V3& v) {
    const int w = in.watch;
    const SpringMass::Mass& m = in.masses[std::size_t(w)];
    std::string t = "The force on " + mass_name(w) + " at t = 0: gravity m g = " + num(m.mass) +
                    " · " + num(in.gravity) + " = " + num(m.mass * in.gravity);
    if (in.drag != 0) t += "; drag −" + num(in.drag) + " v = " + num(-in.drag * v[std::size_t(w)]);
    int shown = 0, attached = 0;
    for (const SpringMass::Spring& s : in.springs) {
        if (s.i != w && s.j != w) continue;
        ++attached;
        if (shown == 4) continue;
        ++shown;
        const int o = s.i == w ? s.j : s.i;
        glm::dvec3 h, d;
        SpringMass::spring_force(s, x[std::size_t(s.i)], x[std::size_t(s.j)], v[std::size_t(s.i)],
                                 v[std::size_t(s.j)], h, d);
        if (s.j == w) h = -h, d = -d;  // the spring's force on its mass j is the negative
        const glm::dvec3 dv = x[std::size_t(w)] - x[std::size_t(o)];
        const double len = glm::length(dv);
        t += "; spring to " + mass_name(o) + ": d = x_" + std::to_string(w) + " − x_" +
             std::to_string(o) + " = " + num(dv) + ", |d| = " + num(len);
        if (!(len > 0)) {
            t += " (the ends coincide: no direction, so no force)";
            continue;
        }
        t += ", Hooke −k (|d| − L) d̂ = −" + num(s.stiffness) + " · (" + num(len) + " − " +
             num(s.rest) + ") · " + num(dv / len) + " = " + num(h);
        if (s.damping != 0) t += ", damping −c ((v_i − v_j)·d̂) d̂ = " + num(d);
    }
    if (attached > shown) t += "; and " + std::to_string(attached - shown) + " more springs";
    glm::dvec3 f;
    {
        V3 all;
        SpringMass::forces(in, x, v, all);
        f = all[std::size_t(w)];
    }
    t += ". Total F = " + num(f) +
         (m.pinned ? " (pinned: it does not move)." : ", a = F/m = " + num(f / m.mass) + ".");
    return t;
}

void narrate_step(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t w = std::size_t(in.watch);
    info.event = "step";
    info.line = integrator_line(in.integrator);
    const double t = double(s.k) * in.dt;
    std::string text = "Step " + std::to_string(s.k) + " (" +
                       SpringMass::integrator_name(in.integrator) + ", t = " + num(t) + "). ";
    if (s.k == 1) {
        V3 x0, v0;
        for (const SpringMass::Mass& m : in.masses) {
            x0.push_back(m.position);
            v0.push_back(m.velocity);
        }
        text += force_terms(in, x0, v0) + " ";
        const glm::dvec3 a = in.masses[w].pinned ? glm::dvec3(0) : s.force / in.masses[w].mass;
        if (in.integrator == Integrator::ExplicitEuler) {
            text += "Explicit Euler, both from the old state: x ← x + dt v = " + num(x0[w]) +
                    " + " + num(in.dt) + " · " + num(v0[w]) + " = " + num(s.x[w]) +
                    ", v ← v + dt a = " + num(v0[w]) + " + " + num(in.dt) + " · " + num(a) + " = " +
                    num(s.v[w]) + ". ";
        } else if (in.integrator == Integrator::SymplecticEuler) {
            text += "Symplectic Euler, velocity first: v ← v + dt a = " + num(v0[w]) + " + " +
                    num(in.dt) + " · " + num(a) + " = " + num(s.v[w]) +
                    ", then x ← x + dt v_new = " + num(x0[w]) + " + " + num(in.dt) + " · " +
                    num(s.v[w]) + " = " + num(s.x[w]) + ". ";
        } else {
            SpringMass::Scratch sc;
            V3 x1, v1;
            SpringMass::advance(in, x0, v0, x1, v1, sc);
            text += "RK4 for " + mass_name(in.watch) + ", each stage (velocity, acceleration):";
            for (int q = 0; q < 4; ++q)
                text += std::string(q ? ";" : "") + " k" + std::to_string(q + 1) + " = (" +
                        num(sc.kx[q][w]) + ", " + num(sc.kv[q][w]) + ")";
            text += ". y ← y + dt/6 (k1 + 2k2 + 2k3 + k4): x = " + num(s.x[w]) +
                    ", v = " + num(s.v[w]) + ". ";
        }
    } else {
        text += mass_name(in.watch) + ": x = " + num(s.x[w]) + ", v = " + num(s.v[w]) +
                " (force at the step's start F = " + num(s.force) + "). ";
    }
    info.narration = text + energy_text(s);
    auto plus = [](double v) { return (v < 0 ? " - " : " + ") + tex(std::fabs(v)); };
    info.math = "E = " + tex(s.energy.kinetic) + plus(s.energy.spring) + plus(s.energy.gravity) +
                " = " + tex(s.energy.total());
    energy_vars(s, info);
}

void narrate_blow_up(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "blow-up";
    info.line = kLineBlowUp;
    info.narration =
        "Step " + std::to_string(s.k + 1) + " (" + SpringMass::integrator_name(in.integrator) +
        ", t = " + num(double(s.k + 1) * in.dt) + ") blew up: " +
        (s.not_finite
             ? std::string("the new state is not finite (an overflow)")
             : "the total energy would be " + num(s.refused_energy) +
                   ", more than 10¹² × E_scale = " + num(SpringMass::kBlowUp * s.energy_scale)) +
        ". The step is not taken and the run stops at t = " + num(double(s.k) * in.dt) +
        (in.integrator == Integrator::ExplicitEuler
             ? ": explicit Euler adds energy every step (×(1 + ω²dt²) for a spring of frequency "
               "ω), "
               "so a stiff spring needs a much smaller dt."
             : ": dt is too large for the stiffest spring (symplectic Euler needs ω dt < 2, RK4 "
               "about ω dt < 2.8).");
    info.math = "E_{" + std::to_string(s.k + 1) + "} \\notin [-10^{12}, 10^{12}]\\, E_{scale}";
    energy_vars(s, info);
}

void narrate_summary(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t w = std::size_t(in.watch);
    info.event = "summary";
    info.line = kLineReport;
    info.narration =
        std::string(s.blew_up ? "Stopped by the blow-up after " : "Done: ") + std::to_string(s.k) +
        " steps of dt = " + num(in.dt) + " (t = " + num(double(s.k) * in.dt) + ", " +
        SpringMass::integrator_name(in.integrator) + "). " + mass_name(in.watch) +
        " ends at x = " + num(s.x[w]) + ", v = " + num(s.v[w]) + ". " + energy_text(s) +
        " The largest drift |E − E_0| / E_scale was " + num(s.max_drift, 4) + ".";
    info.math = "\\max_k |E_k - E_0| / E_{scale} = " + tex(s.max_drift, 4);
    energy_vars(s, info);
    info.vars.push_back({"max_drift", s.max_drift});
}

}  // namespace

void SpringMass::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Step:
            narrate_step(s, info);
            break;
        case Phase::BlowUp:
            narrate_blow_up(s, info);
            break;
        case Phase::Summary:
        case Phase::Done:
            narrate_summary(s, info);
            break;
    }
}

// ---- [result and compute] -------------------------------------------------------------------

SpringMass::Result SpringMass::result(const State& s) {
    const Input& in = *s.in;
    Result r;
    r.dt = in.dt;
    r.steps = s.k;
    r.t = double(s.k) * in.dt;
    r.positions = s.x;
    r.velocities = s.v;
    r.x = s.x[std::size_t(in.watch)];
    r.v = s.v[std::size_t(in.watch)];
    r.energy = s.history;
    r.final_energy = s.energy;
    r.energy_scale = s.energy_scale;
    r.max_drift = s.max_drift;
    r.blew_up = s.blew_up;
    r.blow_up_step = s.blew_up ? s.k + 1 : -1;
    return r;
}

SpringMass::Result SpringMass::compute(const Input& given) {
    const Input in = resolve(given);
    Result r;
    r.dt = in.dt;
    V3 x, v, x1, v1;
    for (const Mass& m : in.masses) {
        x.push_back(m.position);
        v.push_back(m.velocity);
    }
    Energy e = energy(in, x, v);
    r.energy_scale = energy_scale(e);
    r.energy.reserve(std::size_t(in.steps) + 1);
    r.energy.push_back(e.total());
    Scratch w;
    int k = 0;
    for (; k < in.steps; ++k) {
        advance(in, x, v, x1, v1, w);
        const Energy e1 = energy(in, x1, v1);
        if (blows_up(x1, v1, e1, r.energy_scale)) {
            r.blew_up = true;
            r.blow_up_step = k + 1;
            break;
        }
        std::swap(x, x1);
        std::swap(v, v1);
        e = e1;
        r.energy.push_back(e.total());
        r.max_drift =
            std::max(r.max_drift, std::fabs(e.total() - r.energy.front()) / r.energy_scale);
    }
    r.steps = k;
    r.t = double(k) * in.dt;
    r.x = x[std::size_t(in.watch)];
    r.v = v[std::size_t(in.watch)];
    r.positions = std::move(x);
    r.velocities = std::move(v);
    r.final_energy = e;
    return r;
}

}  // namespace cg
