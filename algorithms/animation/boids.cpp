// Sections: [geometry] [rules] [advance] [flock order] [spec] [validate] [state machine]
//           [narrate] [result and compute]
#include "animation/boids.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

#include "core/format.hpp"

namespace cg {

namespace {

using Input = Boids::Input;
using Rules = Boids::Rules;
using Phase = Boids::Phase;
using State = Boids::State;
using Edges = Boids::Edges;
using V2 = std::vector<glm::dvec2>;

enum Line {
    kLineEach = 1,
    kLineNeighbours,
    kLineSeparation,
    kLineAlignCohere,
    kLineAvoid,
    kLineSteer,
    kLineMove,
    kLineSwap,
    kLineReport
};

double length(glm::dvec2 p) {
    return std::hypot(p.x, p.y);
}

// p taken round into [lo, hi) (a torus: leaving on the right comes back on the left).
double wrap(double p, double lo, double hi) {
    if (p >= lo && p < hi) return p;
    const double size = hi - lo;
    double r = std::fmod(p - lo, size);
    if (r < 0) r += size;
    const double q = lo + r;
    return q < hi && q >= lo ? q : lo;  // lo + r may round up to hi, which is lo again
}

}  // namespace

const char* Boids::edges_name(Edges e) {
    return e == Edges::Wrap ? "wrap" : "steer";
}

double Boids::epsilon(const Input& in) {
    return std::max(1e-3 * in.radius, 1e-6);
}

// ---- [geometry] -----------------------------------------------------------------------------

glm::dvec2 Boids::offset(const Input& in, glm::dvec2 from, glm::dvec2 to) {
    glm::dvec2 d = to - from;
    if (in.edges == Edges::Wrap) {
        // Both points lie in the world, so one correction by a whole side gives the shortest.
        const glm::dvec2 size = in.world_max - in.world_min;
        for (int c = 0; c < 2; ++c) {
            if (d[c] > 0.5 * size[c])
                d[c] -= size[c];
            else if (d[c] < -0.5 * size[c])
                d[c] += size[c];
        }
    }
    return d;
}

glm::dvec2 Boids::truncate(glm::dvec2 w, double cap) {
    const double len = length(w);
    if (!(len > cap)) return w;
    if (!(cap > 0)) return {0, 0};
    glm::dvec2 r = w * (cap / len);
    // cap / len rounds either way; shave an ulp until the length is at most cap (once or twice).
    while (length(r) > cap) r *= 1 - 0x1p-52;
    return r;
}

// ---- [rules] --------------------------------------------------------------------------------

Boids::Rules Boids::rules(const Input& in, const V2& x, const V2& v, std::size_t i,
                          Seen* seen) {
    const double r = in.radius, r_sep = in.separation_radius, eps = epsilon(in);
    const glm::dvec2 xi = x[i], vi = v[i];
    const double speed = length(vi);
    // The field of view: d is seen when the angle between v_i and d is at most fov/2, i.e.
    // v_i·d ≥ |v_i| |d| cos(fov/2). A still boid has no heading and sees all round.
    const bool look = in.fov < 360 && speed > 0;
    const double cos_half = std::cos(in.fov * std::numbers::pi / 360);
    Rules out;
    glm::dvec2 sum_v{0, 0}, sum_d{0, 0};
    const std::size_t n = x.size();
    for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        const glm::dvec2 d = offset(in, xi, x[j]);
        if (!(std::fabs(d.x) < r && std::fabs(d.y) < r)) continue;  // cheap: outside the square
        // Inside the square |d| < √2·10⁶, so d·d cannot overflow; hypot only where it could
        // underflow.
        const double dd = glm::dot(d, d);
        const double len = dd > 1e-200 ? std::sqrt(dd) : length(d);
        if (!(len < r)) continue;
        if (look && len > 0 && glm::dot(vi, d) < speed * len * cos_half) continue;
        ++out.neighbours;
        sum_v += v[j];
        sum_d += d;
        if (seen) seen->ids.push_back(int(j)), seen->offsets.push_back(d);
        if (len < r_sep) {
            ++out.close;
            glm::dvec2 away{0, 0};
            if (len > 0) {
                away = -d / len;
            } else {  // coincident: apart along the relative velocity (0 when that is 0 too)
                const glm::dvec2 rel = vi - v[j];
                const double rl = length(rel);
                if (rl > 0) away = rel / rl;
            }
            out.separation += away / std::max(len, eps);
        }
    }
    if (out.neighbours > 0) {
        const double m = double(out.neighbours);
        out.alignment = sum_v / m - vi;
        out.cohesion = sum_d / m;
    }
    for (const Obstacle& o : in.obstacles) {
        const glm::dvec2 e = offset(in, o.center, xi);  // from the centre to the boid
        const double dist = length(e);
        const double gap = dist - o.radius;
        if (!(gap < r)) continue;
        ++out.obstacles;
        const glm::dvec2 n_hat = dist > 0    ? e / dist
                                 : speed > 0 ? -vi / speed
                                             : glm::dvec2(1, 0);
        out.avoidance += n_hat / std::max(gap, eps);
    }
    if (in.edges == Edges::Steer) {
        const double m = in.margin;
        for (int c = 0; c < 2; ++c) {
            const double low = in.world_min[c] + m, high = in.world_max[c] - m;
            if (xi[c] < low) out.bounds[c] += (low - xi[c]) / m;
            if (xi[c] > high) out.bounds[c] -= (xi[c] - high) / m;
        }
    }
    const Weights& w = in.weights;
    out.sum = w.separation * out.separation + w.alignment * out.alignment +
              w.cohesion * out.cohesion + w.avoidance * out.avoidance + w.bounds * out.bounds;
    out.steering = truncate(out.sum, in.max_force);
    return out;
}

// ---- [advance] ------------------------------------------------------------------------------

void Boids::advance(const Input& in, const V2& x, const V2& v, V2& x1, V2& v1, Rules& focus_rules,
                    Seen& focus_seen) {
    const std::size_t n = x.size(), f = std::size_t(in.focus);
    x1.resize(n);
    v1.resize(n);
    focus_seen.clear();
    const bool wrapped = in.edges == Edges::Wrap;
    for (std::size_t i = 0; i < n; ++i) {
        // Everything read from (x, v), everything written to (x1, v1): double buffered.
        const Rules r = rules(in, x, v, i, i == f ? &focus_seen : nullptr);
        if (i == f) focus_rules = r;
        glm::dvec2 nv = v[i] + in.dt * r.steering;
        const double speed = length(nv);
        if (speed > 0 && speed < in.min_speed) nv *= in.min_speed / speed;
        nv = truncate(nv, in.max_speed);
        glm::dvec2 nx = x[i] + in.dt * nv;
        if (wrapped) {
            nx.x = wrap(nx.x, in.world_min.x, in.world_max.x);
            nx.y = wrap(nx.y, in.world_min.y, in.world_max.y);
        }
        v1[i] = nv;
        x1[i] = nx;
    }
}

// ---- [flock order] --------------------------------------------------------------------------

double Boids::polarisation(const V2& v) {
    glm::dvec2 sum{0, 0};
    for (const glm::dvec2& u : v) {
        const double s = length(u);
        if (s > 0) sum += u / s;
    }
    return v.empty() ? 0 : length(sum) / double(v.size());
}

double Boids::mean_nearest(const Input& in, const V2& x) {
    const std::size_t n = x.size();
    if (n < 2) return 0;
    thread_local std::vector<double> best;
    best.assign(n, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const glm::dvec2 d = offset(in, x[i], x[j]);
            const double dd = glm::dot(d, d);
            best[i] = std::min(best[i], dd);
            best[j] = std::min(best[j], dd);
        }
    double sum = 0;
    for (double b : best) sum += std::sqrt(b);
    return sum / double(n);
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Boids::spec() {
    static const Spec spec{
        "boids",
        "Boids: Reynolds' flocking, separation, alignment and cohesion from local perception",
        "Animation",
        {
            "for every boid i, reading only the previous state (x, v):",
            "  N_i ← { j ≠ i : |d_j| < r, within ±fov/2 of v_i },   d_j = x_j − x_i",
            "  s ← Σ_{j ∈ N_i, |d_j| < r_sep} −d̂_j / max(|d_j|, ε)   ▷ separation",
            "  a ← mean_{N_i} v_j − v_i   ▷ alignment;   c ← mean_{N_i} d_j   ▷ cohesion",
            "  o ← Σ_obstacles n̂ / max(gap, ε);   b ← push back from the edges (steer)",
            "  F ← w_s s + w_a a + w_c c + w_o o + w_b b,  truncated to max_force",
            "  v_i' ← v_i + dt F (speed in [min_speed, max_speed]);  x_i' ← x_i + dt v_i'",
            "(x, v) ← (x', v') for all at once;  t ← t + dt;  record φ and the mean nearest "
            "distance",
            "report the flock and its order against time",
        },
        {
            {"step", "one frame: every boid steered from the same previous state, then moved"},
            {"summary", "the run's end: the final flock and how its order changed"},
        },
        {},  // no sliders
        {
            .predict = {{"step", {"neighbours", "v"}}},
            .mistakes =
                {
                    {"step", "separation", "negate",
                     "took x_j − x_i for the separation: steered toward the close neighbours"},
                    {"step", "cohesion", "negate",
                     "took x_i − centre for the cohesion: steered away from the flock's centre"},
                    {"step", "v", "keep", "computed the steering but never added it to v"},
                },
            .variants = {{"wrap", "/edges", "\"wrap\""}, {"steer", "/edges", "\"steer\""}},
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

void check_point(glm::dvec2 p, const std::string& field) {
    for (int c = 0; c < 2; ++c) {
        if (!std::isfinite(p[c])) throw InputError(field, "must be finite (got " + given(p[c]) + ")");
        if (std::fabs(p[c]) > Boids::kMaxCoordinate)
            throw InputError(field, "is too large (" + given(p[c]) + "): at most 1e6 in size");
    }
}

void check_range(double x, double hi, const std::string& field, const char* what) {
    if (!std::isfinite(x) || x < 0)
        throw InputError(field, std::string("must be ≥ 0 (") + what + "), got " + given(x));
    if (x > hi) throw InputError(field, "is too large (" + given(x) + "): at most " + given(hi));
}

}  // namespace

void Boids::validate(const Input& in) {
    const std::size_t n = in.random.count > 0 ? std::size_t(in.random.count) : in.boids.size();
    if (in.random.count < 0 || in.random.count > kMaxBoids)
        throw InputError("random.count", "must be 1 to " + std::to_string(kMaxBoids) + " (got " +
                                             std::to_string(in.random.count) + ")");
    if (in.random.count > 0 && !in.boids.empty())
        throw InputError("random", "give either \"boids\" or \"random\", not both");
    if (n == 0) throw InputError("boids", "must have at least 1 boid (got none)");
    if (n > std::size_t(kMaxBoids))
        throw InputError("boids", "has " + std::to_string(n) + " boids; at most " +
                                      std::to_string(kMaxBoids) + " are simulated");
    for (std::size_t i = 0; i < in.boids.size(); ++i) {
        check_point(in.boids[i].position, at("boids", i, "position"));
        check_point(in.boids[i].velocity, at("boids", i, "velocity"));
    }
    check_point(in.world_min, "world.min");
    check_point(in.world_max, "world.max");
    for (int c = 0; c < 2; ++c)
        if (!(in.world_max[c] > in.world_min[c]))
            throw InputError("world", std::string("max must be above min in ") + "xy"[c] +
                                          " (got " + given(in.world_min[c]) + " to " +
                                          given(in.world_max[c]) + ")");
    check_range(in.radius, kMaxCoordinate, "radius", "the perception radius r");
    if (in.separation_radius != -1)
        check_range(in.separation_radius, kMaxCoordinate, "separation_radius",
                    "the separation radius r_sep");
    if (!std::isfinite(in.fov) || in.fov < 0 || in.fov > 360)
        throw InputError("fov", "must be a field of view of 0 to 360 degrees, got " + given(in.fov));
    if (in.edges == Edges::Wrap) {
        const glm::dvec2 size = in.world_max - in.world_min;
        const double side = std::min(size.x, size.y);
        if (in.radius > 0.5 * side)
            throw InputError("world", "is " + given(side) +
                                          " across at its narrowest, less than 2r = " +
                                          given(2 * in.radius) +
                                          ": in a wrapped world the perception circle would meet "
                                          "itself");
    }
    if (in.margin != -1) {
        if (!std::isfinite(in.margin) || in.margin < 1e-6 || in.margin > kMaxCoordinate)
            throw InputError("margin", "must be a width of 1e-6 to 1e6, got " + given(in.margin));
    }
    for (std::size_t k = 0; k < in.obstacles.size(); ++k) {
        const Obstacle& o = in.obstacles[k];
        check_point(o.center, at("obstacles", k, "center"));
        if (!std::isfinite(o.radius) || o.radius <= 0)
            throw InputError(at("obstacles", k, "radius"), "must be > 0, got " + given(o.radius));
        if (o.radius > kMaxCoordinate)
            throw InputError(at("obstacles", k, "radius"),
                             "is too large (" + given(o.radius) + "): at most 1e6");
    }
    if (in.obstacles.size() > std::size_t(kMaxObstacles))
        throw InputError("obstacles", "has " + std::to_string(in.obstacles.size()) +
                                          " obstacles; at most " + std::to_string(kMaxObstacles));
    check_range(in.weights.separation, kMaxValue, "weights.separation", "a weight");
    check_range(in.weights.alignment, kMaxValue, "weights.alignment", "a weight");
    check_range(in.weights.cohesion, kMaxValue, "weights.cohesion", "a weight");
    check_range(in.weights.avoidance, kMaxValue, "weights.avoidance", "a weight");
    check_range(in.weights.bounds, kMaxValue, "weights.bounds", "a weight");
    check_range(in.max_speed, kMaxValue, "max_speed", "a speed");
    check_range(in.min_speed, kMaxValue, "min_speed", "a speed");
    check_range(in.max_force, kMaxValue, "max_force", "a steering limit");
    if (in.min_speed > in.max_speed)
        throw InputError("min_speed", "must be at most max_speed = " + given(in.max_speed) +
                                          " (got " + given(in.min_speed) + ")");
    if (!std::isfinite(in.dt) || in.dt <= 0)
        throw InputError("dt", "must be a time step > 0, got " + given(in.dt));
    if (in.dt > 10) throw InputError("dt", "is too large (" + given(in.dt) + "): at most 10");
    if (in.steps < 1 || in.steps > kMaxSteps)
        throw InputError("steps", "must be 1 to " + std::to_string(kMaxSteps) + " (got " +
                                      std::to_string(in.steps) + ")");
    const long long work = (long long)in.steps * (long long)n * (long long)n;
    if (work > kMaxWork)
        throw InputError("steps", std::to_string(in.steps) + " steps of " + std::to_string(n) +
                                      " boids is too much work: steps × boids² must be at most " +
                                      std::to_string(kMaxWork));
    if (in.focus < 0 || std::size_t(in.focus) >= n)
        throw InputError("focus", "must name a boid 0 to " + std::to_string(n - 1) + " (got " +
                                      std::to_string(in.focus) + ")");
}

Boids::Input Boids::resolve(const Input& given) {
    validate(given);
    Input in = given;
    const glm::dvec2 size = in.world_max - in.world_min;
    if (in.separation_radius == -1) in.separation_radius = in.radius;
    if (in.margin == -1) in.margin = std::max(0.1 * std::min(size.x, size.y), 1e-6);
    if (in.random.count > 0) {
        // Uniform in the world, outside the obstacles (up to 100 tries a boid), any heading.
        Rng rng(in.random.seed);
        const double lo = std::max(in.min_speed, 0.5 * in.max_speed);
        for (int b = 0; b < in.random.count; ++b) {
            glm::dvec2 p{0, 0};
            for (int tries = 0; tries < 100; ++tries) {
                p = {rng.uniform(in.world_min.x, in.world_max.x),
                     rng.uniform(in.world_min.y, in.world_max.y)};
                bool inside = false;
                for (const Obstacle& o : in.obstacles)
                    inside = inside || length(p - o.center) < o.radius;
                if (!inside) break;
            }
            const double heading = rng.uniform(0, 2 * std::numbers::pi);
            const double speed = rng.uniform(lo, std::max(lo, in.max_speed));
            in.boids.push_back({p, speed * glm::dvec2(std::cos(heading), std::sin(heading))});
        }
        in.random.count = 0;
        in.generated = true;
    }
    // A boid or an obstacle outside a wrapped world is taken round into it (so that one
    // correction by a side gives every shortest offset); no boid starts too fast.
    if (in.edges == Edges::Wrap)
        for (Obstacle& o : in.obstacles) {
            o.center.x = wrap(o.center.x, in.world_min.x, in.world_max.x);
            o.center.y = wrap(o.center.y, in.world_min.y, in.world_max.y);
        }
    for (Boid& b : in.boids) {
        if (in.edges == Edges::Wrap) {
            b.position.x = wrap(b.position.x, in.world_min.x, in.world_max.x);
            b.position.y = wrap(b.position.y, in.world_min.y, in.world_max.y);
        }
        b.velocity = truncate(b.velocity, in.max_speed);
    }
    return in;
}

// ---- [state machine] ------------------------------------------------------------------------

Boids::State Boids::start(const Input& in) {
    return begin(Shared<Input>(resolve(in)));
}

Boids::State Boids::begin(Shared<Input> shared) {
    const Input& in = *shared;
    State s;
    s.in = std::move(shared);
    s.x.reserve(in.boids.size());
    s.v.reserve(in.boids.size());
    for (const Boid& b : in.boids) {
        s.x.push_back(b.position);
        s.v.push_back(b.velocity);
    }
    s.polarisation.reserve(std::size_t(in.steps) + 1);
    s.nearest.reserve(std::size_t(in.steps) + 1);
    s.polarisation.push_back(polarisation(s.v));
    s.nearest.push_back(mean_nearest(in, s.x));
    return s;
}

void Boids::take_step(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Step: {
            const std::size_t f = std::size_t(in.focus);
            s.x0 = s.x[f];
            s.v0 = s.v[f];
            Scratch& w = s.scratch;
            advance(in, s.x, s.v, w.nx, w.nv, s.rules, s.seen);
            std::swap(s.x, w.nx);  // the new state replaces the old one all at once
            std::swap(s.v, w.nv);
            ++s.k;
            s.polarisation.push_back(polarisation(s.v));
            s.nearest.push_back(mean_nearest(in, s.x));
            s.last = Phase::Step;
            if (s.k == in.steps) s.phase = Phase::Summary;
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

void Boids::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    take_step(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string boid_list(const std::vector<int>& ids) {
    std::string t;
    const std::size_t shown = std::min<std::size_t>(ids.size(), 8);
    for (std::size_t q = 0; q < shown; ++q) t += (q ? ", " : "") + std::to_string(ids[q]);
    if (ids.size() > shown) t += " and " + std::to_string(ids.size() - shown) + " more";
    return t;
}

void step_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t f = std::size_t(in.focus);
    const Rules& r = s.rules;
    info.vars = {{"t", double(s.k) * in.dt},
                 {"k", (long long)s.k},
                 {"dt", in.dt},
                 {"x", vec(s.x[f])},
                 {"v", vec(s.v[f])},
                 {"neighbours", (long long)r.neighbours},
                 {"separation", vec(r.separation)},
                 {"alignment", vec(r.alignment)},
                 {"cohesion", vec(r.cohesion)},
                 {"avoidance", vec(r.avoidance)},
                 {"bounds", vec(r.bounds)},
                 {"F", vec(r.steering)},
                 {"polarisation", s.polarisation.back()},
                 {"nearest", s.nearest.back()}};
}

std::string order_text(const State& s) {
    return "Flock: polarisation φ = |mean v̂| = " + num(s.polarisation.back(), 4) +
           ", mean nearest-neighbour distance " + num(s.nearest.back(), 4) + ".";
}

// The separation term by term for the first few close neighbours: −d̂ / max(|d|, ε).
std::string separation_terms(const Input& in, const Boids::Seen& seen) {
    const double eps = Boids::epsilon(in);
    std::string t;
    int shown = 0, close = 0;
    for (std::size_t q = 0; q < seen.ids.size(); ++q) {
        const glm::dvec2 d = seen.offsets[q];
        const double len = length(d);
        if (!(len < in.separation_radius)) continue;
        if (++close > 4) continue;
        t += std::string(shown++ ? ", " : " (") + std::to_string(seen.ids[q]) + ": ";
        if (len > 0)
            t += "d = " + num(d) + ", |d| = " + num(len) + (len < eps ? " < ε" : "") + " → " +
                 num(-d / len / std::max(len, eps));
        else
            t += "on the same point: pushed along v_i − v_j with 1/ε = " + num(1 / eps);
    }
    if (close > shown) t += ", and " + std::to_string(close - shown) + " more";
    return shown ? t + ")" : t;
}

void narrate_step(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t f = std::size_t(in.focus);
    const Rules& r = s.rules;
    const Boids::Weights& w = in.weights;
    info.event = "step";
    info.line = kLineMove;
    std::string t = "Step " + std::to_string(s.k) + " (t = " + num(double(s.k) * in.dt) +
                    "): every boid steers from the same previous state, then all move at once. "
                    "Boid " +
                    std::to_string(f) + " was at x = " + num(s.x0) + " with v = " + num(s.v0) +
                    " and saw ";
    const std::string view =
        in.fov < 360 ? " in its " + num(in.fov) + "° field of view" : std::string();
    if (r.neighbours == 0) {
        t += "no neighbour within r = " + num(in.radius) + view +
             ": separation, alignment and cohesion are 0.";
    } else {
        t += std::to_string(r.neighbours) + (r.neighbours == 1 ? " neighbour" : " neighbours") +
             " within r = " + num(in.radius) + view + " (" + boid_list(s.seen.ids) + "). ";
        if (r.close == 0)
            t += "None is closer than r_sep = " + num(in.separation_radius) +
                 ", so the separation is 0; ";
        else
            t += "Separation Σ −d̂/|d| over the " + std::to_string(r.close) +
                 " closer than r_sep = " + num(in.separation_radius) +
                 separation_terms(in, s.seen) + ": s = " + num(r.separation) + "; ";
        const glm::dvec2 mean_v = r.alignment + s.v0;
        t += "alignment a = mean v_j − v = " + num(mean_v) + " − " + num(s.v0) + " = " +
             num(r.alignment) + "; cohesion c = centre − x = " + num(s.x0 + r.cohesion) + " − " +
             num(s.x0) + " = " + num(r.cohesion) + ".";
    }
    if (r.obstacles > 0)
        t += " Avoidance from " + std::to_string(r.obstacles) +
             (r.obstacles == 1 ? " obstacle" : " obstacles") + " within r: o = " +
             num(r.avoidance) + ".";
    if (r.bounds != glm::dvec2(0)) t += " The edge pushes back: b = " + num(r.bounds) + ".";
    t += " F = " + num(w.separation) + " s + " + num(w.alignment) + " a + " + num(w.cohesion) +
         " c";
    if (r.obstacles > 0) t += " + " + num(w.avoidance) + " o";
    if (r.bounds != glm::dvec2(0)) t += " + " + num(w.bounds) + " b";
    t += " = " + num(r.sum);
    if (r.steering != r.sum)
        t += ", longer than max_force = " + num(in.max_force) + " (|F| = " +
             num(length(r.sum)) + "), so scaled to " + num(r.steering);
    const glm::dvec2 raw_v = s.v0 + in.dt * r.steering;
    t += ". v ← v + dt F = " + num(s.v0) + " + " + num(in.dt) + " · " + num(r.steering) + " = " +
         num(raw_v);
    if (raw_v != s.v[f])
        t += ", speed " + num(length(raw_v)) + " clamped to [" + num(in.min_speed) + ", " +
             num(in.max_speed) + "]: " + num(s.v[f]);
    const glm::dvec2 raw_x = s.x0 + in.dt * s.v[f];
    t += "; x ← x + dt v = " + num(raw_x);
    if (raw_x != s.x[f]) t += ", wrapped round to " + num(s.x[f]);
    info.narration = t + ". " + order_text(s);
    info.math = "F = " + tex(w.separation) + "\\,s + " + tex(w.alignment) + "\\,a + " +
                tex(w.cohesion) + "\\,c + \\ldots = " + tex(r.steering) +
                ",\\quad v' = " + tex(s.v[f]);
    step_vars(s, info);
}

void narrate_summary(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t f = std::size_t(in.focus);
    info.event = "summary";
    info.line = kLineReport;
    const auto [lo, hi] = std::minmax_element(s.polarisation.begin(), s.polarisation.end());
    info.narration = "Done: " + std::to_string(s.x.size()) + " boids, " + std::to_string(s.k) +
                     " steps of dt = " + num(in.dt) + " (t = " + num(double(s.k) * in.dt) +
                     "). Polarisation φ went from " + num(s.polarisation.front(), 4) + " to " +
                     num(s.polarisation.back(), 4) + " (lowest " + num(*lo, 4) + ", highest " +
                     num(*hi, 4) + "; 1 means every boid flies the same way), the mean "
                     "nearest-neighbour distance from " +
                     num(s.nearest.front(), 4) + " to " + num(s.nearest.back(), 4) + ". Boid " +
                     std::to_string(f) + " ends at x = " + num(s.x[f]) + ", v = " + num(s.v[f]) +
                     ".";
    info.math = "\\varphi = \\left|\\tfrac{1}{n}\\textstyle\\sum_i \\hat v_i\\right| = " +
                tex(s.polarisation.back(), 4);
    info.vars = {{"t", double(s.k) * in.dt},     {"k", (long long)s.k},
                 {"dt", in.dt},                  {"x", vec(s.x[f])},
                 {"v", vec(s.v[f])},             {"polarisation", s.polarisation.back()},
                 {"nearest", s.nearest.back()}};
}

}  // namespace

void Boids::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    if (s.last == Phase::Step)
        narrate_step(s, info);
    else
        narrate_summary(s, info);
}

// ---- [result and compute] -------------------------------------------------------------------

Boids::Result Boids::result(const State& s) {
    const Input& in = *s.in;
    Result r;
    r.dt = in.dt;
    r.steps = s.k;
    r.t = double(s.k) * in.dt;
    r.positions = s.x;
    r.velocities = s.v;
    r.focus = in.focus;
    r.rules = s.rules;
    r.x = s.x[std::size_t(in.focus)];
    r.v = s.v[std::size_t(in.focus)];
    r.polarisation = s.polarisation;
    r.nearest = s.nearest;
    return r;
}

Boids::Result Boids::compute(const Input& given) {
    const Input in = resolve(given);
    Result r;
    r.dt = in.dt;
    r.focus = in.focus;
    V2 x, v, x1, v1;
    for (const Boid& b : in.boids) {
        x.push_back(b.position);
        v.push_back(b.velocity);
    }
    r.polarisation.reserve(std::size_t(in.steps) + 1);
    r.nearest.reserve(std::size_t(in.steps) + 1);
    r.polarisation.push_back(polarisation(v));
    r.nearest.push_back(mean_nearest(in, x));
    Seen seen;
    for (int k = 0; k < in.steps; ++k) {
        advance(in, x, v, x1, v1, r.rules, seen);
        std::swap(x, x1);
        std::swap(v, v1);
        r.polarisation.push_back(polarisation(v));
        r.nearest.push_back(mean_nearest(in, x));
    }
    r.steps = in.steps;
    r.t = double(in.steps) * in.dt;
    r.x = x[std::size_t(in.focus)];
    r.v = v[std::size_t(in.focus)];
    r.positions = std::move(x);
    r.velocities = std::move(v);
    return r;
}

}  // namespace cg
