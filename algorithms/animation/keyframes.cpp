// Sections: [curves] [spec] [validate] [prepare] [advance] [narrate] [result and compute]
#include "animation/keyframes.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "curves/arc_length.hpp"

namespace cg {

namespace {

using Input = Keyframes::Input;
using Interpolation = Keyframes::Interpolation;
using Key = Keyframes::Key;
using Curve = Keyframes::Curve;
using Eval = Keyframes::Eval;
using Phase = Keyframes::Phase;
using Prepared = Keyframes::Prepared;
using State = Keyframes::State;

enum Line {
    kLineTangents = 1,
    kLineTable,
    kLineFrame,
    kLineSegment,
    kLineHermite,
    kLineEven,
    kLineReport
};

constexpr double kC1Tolerance = 1e-9;  // a jump below this × the slope scale is no jump

}  // namespace

const char* Keyframes::interpolation_name(Interpolation i) {
    return i == Interpolation::Linear       ? "linear"
           : i == Interpolation::CatmullRom ? "catmull-rom"
                                            : "kochanek-bartels";
}

// ---- [curves] -------------------------------------------------------------------------------

Keyframes::Curve Keyframes::make_curve(const Input& in, Interpolation kind) {
    Curve c;
    c.kind = kind;
    c.keys = in.keys;
    for (Key& k : c.keys)  // unused coordinates are 0, so a 2D path has z = 0
        for (int d = in.dim; d < 3; ++d) k.value[d] = 0;
    const std::size_t n = c.keys.size();
    c.m_in.assign(n, glm::dvec3(0));
    c.m_out.assign(n, glm::dvec3(0));
    for (std::size_t i = 0; i < n; ++i) {
        // The slopes either side; a missing one equals the other (the phantom key).
        const bool first = i == 0, last = i + 1 == n;
        glm::dvec3 before{0}, after{0};
        if (!first)
            before = (c.keys[i].value - c.keys[i - 1].value) / (c.keys[i].t - c.keys[i - 1].t);
        if (!last)
            after = (c.keys[i + 1].value - c.keys[i].value) / (c.keys[i + 1].t - c.keys[i].t);
        if (first) before = after;
        if (last) after = before;
        switch (kind) {
            case Interpolation::Linear:
                c.m_in[i] = before;
                c.m_out[i] = after;
                break;
            case Interpolation::CatmullRom:
                c.m_in[i] = c.m_out[i] = 0.5 * (before + after);
                break;
            case Interpolation::KochanekBartels: {
                const double T = c.keys[i].tension, C = c.keys[i].continuity, B = c.keys[i].bias;
                const double a_in = (1 - T) * (1 - C) * (1 + B) / 2,
                             b_in = (1 - T) * (1 + C) * (1 - B) / 2;
                const double a_out = (1 - T) * (1 + C) * (1 + B) / 2,
                             b_out = (1 - T) * (1 - C) * (1 - B) / 2;
                c.m_in[i] = a_in * before + b_in * after;
                c.m_out[i] = a_out * before + b_out * after;
                break;
            }
        }
    }
    return c;
}

Keyframes::Basis Keyframes::basis(double u) {
    const double u2 = u * u, u3 = u2 * u;
    Basis b;
    b.h00 = 2 * u3 - 3 * u2 + 1;
    b.h10 = u3 - 2 * u2 + u;
    b.h01 = -2 * u3 + 3 * u2;
    b.h11 = u3 - u2;
    b.d00 = 6 * u2 - 6 * u;
    b.d10 = 3 * u2 - 4 * u + 1;
    b.d01 = -6 * u2 + 6 * u;
    b.d11 = 3 * u2 - 2 * u;
    return b;
}

int Keyframes::segment_of(const std::vector<Key>& keys, double t) {
    // The last key with t_i ≤ t, but never the last key itself: t = t_{n−1} is u = 1 of the
    // last segment. A time on an inner key starts the segment after it.
    const auto it = std::upper_bound(keys.begin(), keys.end(), t,
                                     [](double x, const Key& k) { return x < k.t; });
    const int i = int(it - keys.begin()) - 1;
    return std::clamp(i, 0, int(keys.size()) - 2);
}

Keyframes::Eval Keyframes::evaluate_in(const Curve& c, int i, double u) {
    const Key& a = c.keys[std::size_t(i)];
    const Key& b = c.keys[std::size_t(i) + 1];
    const double delta = b.t - a.t;
    Eval e;
    e.segment = i;
    e.u = u;
    if (c.kind == Interpolation::Linear) {
        e.value = u == 1 ? b.value : a.value + u * (b.value - a.value);
        e.velocity = (b.value - a.value) / delta;
        return e;
    }
    const Basis h = basis(u);
    const glm::dvec3 m0 = delta * c.m_out[std::size_t(i)], m1 = delta * c.m_in[std::size_t(i) + 1];
    e.value = h.h00 * a.value + h.h10 * m0 + h.h01 * b.value + h.h11 * m1;
    e.velocity = (h.d00 * a.value + h.d10 * m0 + h.d01 * b.value + h.d11 * m1) / delta;
    return e;
}

Keyframes::Eval Keyframes::evaluate(const Curve& c, double t) {
    const int i = segment_of(c.keys, t);
    const double t0 = c.keys[std::size_t(i)].t, t1 = c.keys[std::size_t(i) + 1].t;
    // The ends exactly: u = 0 and u = 1 pass through the keys with no rounding.
    const double u = t == t0 ? 0.0 : t == t1 ? 1.0 : (t - t0) / (t1 - t0);
    return evaluate_in(c, i, u);
}

int Keyframes::frame_count(const Input& in) {
    const double span = in.keys.back().t - in.keys.front().t;
    const double K = std::ceil(span / in.dt * (1 - 1e-12));  // a span of exactly K dt: K frames
    return K >= double(kMaxFrames) ? kMaxFrames + 1 : int(std::max(1.0, K)) + 1;
}

double Keyframes::frame_time(const Prepared& p, int k) {
    return k + 1 == p.frames ? p.in.keys.back().t : p.in.keys.front().t + double(k) * p.in.dt;
}

namespace {

// The jumps of the velocity at the keys, for one curve: p'(t_i⁺) − p'(t_i⁻) = m⁺_i − m⁻_i for
// the cubic ones, the slope difference for linear; 0 at the two ends.
double max_jump(const Curve& c, std::vector<glm::dvec3>* jumps) {
    const std::size_t n = c.keys.size();
    if (jumps) jumps->assign(n, glm::dvec3(0));
    double worst = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const glm::dvec3 left = Keyframes::evaluate_in(c, int(i) - 1, 1.0).velocity;
        const glm::dvec3 right = Keyframes::evaluate_in(c, int(i), 0.0).velocity;
        if (jumps) (*jumps)[i] = right - left;
        worst = std::max(worst, glm::length(right - left));
    }
    return worst;
}

// The size of the slopes, against which a jump counts as one.
double slope_scale(const Curve& c) {
    double scale = 0;
    for (std::size_t i = 0; i + 1 < c.keys.size(); ++i)
        scale = std::max(scale, glm::length(c.keys[i + 1].value - c.keys[i].value) /
                                    (c.keys[i + 1].t - c.keys[i].t));
    return scale > 0 ? scale : 1;
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Keyframes::spec() {
    static const Spec spec{
        "keyframes",
        "Keyframe interpolation: linear, Catmull–Rom and Kochanek–Bartels channels, frame by frame",
        "Animation",
        {
            "tangents m⁻_i, m⁺_i from the slopes s⁻, s⁺ (Catmull–Rom (s⁻ + s⁺)/2; KB with T, C, B)",
            "path: u_j = t_0 + j (t_n − t_0)/N, s_j = s_{j−1} + |P(u_j) − P(u_{j−1})|, L = s_N",
            "for each frame t = t_0, t_0 + dt, …, t_n:",
            "    segment i with t_i ≤ t ≤ t_{i+1};  u ← (t − t_i) / (t_{i+1} − t_i)",
            "    p ← h00 p_i + h10 Δ m⁺_i + h01 p_{i+1} + h11 Δ m⁻_{i+1}  (linear: (1 − u) p_i + u "
            "p_{i+1})",
            "    constant speed: s ← L (t − t_0)/(t_n − t_0), u ← table⁻¹(s), point P(u)",
            "report the values, the velocity jumps at the keys (C1 or not)",
        },
        {
            {"tangents", "the tangent (velocity) at every key, arriving and leaving"},
            {"table", "the arc-length table of the path: N chords and the length L"},
            {"frame", "one frame: segment, u, the Hermite weights, the value and velocity"},
            {"key", "a frame exactly on a key: the value is the key's, the velocity may jump"},
            {"summary", "the end: the largest velocity jump at a key, C1 or not"},
        },
        {},  // no sliders
        {
            .predict = {{"frame", {"u", "p"}}, {"key", {"p"}}},
            .mistakes =
                {
                    {"frame", "u", "copy:t",
                     "put the global time t into the basis instead of the local u = (t − t_i)/Δ_i"},
                    {"frame", "i", "off-by-one",
                     "looked the time up in the next segment: the keys one further on"},
                },
            .variants = {{"linear", "/interpolation", "\"linear\""},
                         {"catmull-rom", "/interpolation", "\"catmull-rom\""},
                         {"kochanek-bartels", "/interpolation", "\"kochanek-bartels\""}},
        },
        "t",  // the clock: a step is one frame of dt seconds, so Play keeps real time
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

std::string key_field(std::size_t i, const char* field) {
    return "keys[" + std::to_string(i) + "]." + field;
}

void check_number(double x, double limit, const std::string& field) {
    if (!std::isfinite(x)) throw InputError(field, "must be finite (got " + given(x) + ")");
    if (std::fabs(x) > limit)
        throw InputError(field,
                         "is too large (" + given(x) + "): at most " + given(limit) + " in size");
}

}  // namespace

void Keyframes::validate(const Input& in) {
    if (in.dim < 1 || in.dim > 3)
        throw InputError("dim", "must be 1, 2 or 3 (got " + std::to_string(in.dim) + ")");
    const std::size_t n = in.keys.size();
    if (n < 2)
        throw InputError("keys", "must have at least 2 keys to interpolate between (got " +
                                     std::to_string(n) + ")");
    if (n > std::size_t(kMaxKeys))
        throw InputError("keys",
                         "has " + std::to_string(n) + " keys; at most " + std::to_string(kMaxKeys));
    for (std::size_t i = 0; i < n; ++i) {
        const Key& k = in.keys[i];
        check_number(k.t, kMaxMagnitude, key_field(i, "t"));
        for (int d = 0; d < in.dim; ++d)
            check_number(k.value[d], kMaxMagnitude, key_field(i, "value"));
        const double tcb[3] = {k.tension, k.continuity, k.bias};
        const char* names[3] = {"tension", "continuity", "bias"};
        for (int q = 0; q < 3; ++q)
            if (!std::isfinite(tcb[q]) || tcb[q] < -1 || tcb[q] > 1)
                throw InputError(key_field(i, names[q]),
                                 "must lie in [−1, 1] (got " + given(tcb[q]) + ")");
        if (i > 0 && !(k.t > in.keys[i - 1].t))
            throw InputError(
                key_field(i, "t"),
                k.t == in.keys[i - 1].t
                    ? "repeats the time of keys[" + std::to_string(i - 1) + "] (" + given(k.t) +
                          "): two values at one time are no function of time"
                    : "must be later than keys[" + std::to_string(i - 1) + "].t = " +
                          given(in.keys[i - 1].t) + " (got " + given(k.t) + "): keys in order of time");
        if (i > 0 && k.t - in.keys[i - 1].t < kMinGap)
            throw InputError(key_field(i, "t"),
                             "is only " + given(k.t - in.keys[i - 1].t) + " s after keys[" +
                                 std::to_string(i - 1) +
                                 "]: keys closer than 1e-6 s are refused (the slope between "
                                 "them would overflow)");
    }
    if (!std::isfinite(in.dt) || in.dt <= 0)
        throw InputError("dt", "must be a time step > 0, got " + given(in.dt));
    if (frame_count(in) > kMaxFrames)
        throw InputError("dt", "gives more than " + std::to_string(kMaxFrames) + " frames for " +
                                   given(in.keys.back().t - in.keys.front().t) +
                                   " seconds: take a larger dt");
    if (in.samples < 1 || in.samples > kMaxSamples)
        throw InputError("samples", "must be 1 to " + std::to_string(kMaxSamples) + " (got " +
                                        std::to_string(in.samples) + ")");
    if (in.constant_speed && in.dim < 2)
        throw InputError("constant_speed",
                         "needs a path (dim 2 or 3): a scalar channel has no arc length");
    if (in.has_query) {
        if (!std::isfinite(in.query) || in.query < in.keys.front().t || in.query > in.keys.back().t)
            throw InputError("query", "must lie between the first and last key's time [" +
                                          given(in.keys.front().t) + ", " + given(in.keys.back().t) +
                                          "] (got " + given(in.query) + ")");
    }
}

// ---- [prepare] ------------------------------------------------------------------------------

Keyframes::Prepared Keyframes::prepare(const Input& in) {
    validate(in);
    Prepared p;
    p.in = in;
    p.curve = make_curve(in, in.interpolation);
    p.in.keys = p.curve.keys;  // unused coordinates zeroed
    p.frames = frame_count(in);
    if (in.constant_speed) {
        // The chord table of ArcLength, over the path's own parameter (the time of the keys).
        const int N = in.samples;
        const double t0 = in.keys.front().t, t1 = in.keys.back().t;
        p.table_u.resize(std::size_t(N) + 1);
        p.table_s.resize(std::size_t(N) + 1);
        glm::dvec3 previous = p.curve.keys.front().value;
        for (int j = 0; j <= N; ++j) {
            const double u = j == N ? t1 : t0 + (t1 - t0) * double(j) / N;
            const glm::dvec3 point = evaluate(p.curve, u).value;
            p.table_u[std::size_t(j)] = u;
            p.table_s[std::size_t(j)] =
                j == 0 ? 0 : p.table_s[std::size_t(j) - 1] + glm::length(point - previous);
            previous = point;
        }
        p.length = p.table_s.back();
        // The true length, segment by segment as cubic Béziers (linear: straight pieces).
        long double exact = 0;
        for (std::size_t i = 0; i + 1 < p.curve.keys.size(); ++i) {
            const glm::dvec3 a = p.curve.keys[i].value, b = p.curve.keys[i + 1].value;
            const double delta = p.curve.keys[i + 1].t - p.curve.keys[i].t;
            if (in.interpolation == Interpolation::Linear)
                exact += glm::length(b - a);
            else
                exact += ArcLength::exact_length(
                    {a, a + delta / 3 * p.curve.m_out[i], b - delta / 3 * p.curve.m_in[i + 1], b});
        }
        p.length_exact = double(exact);
    }
    return p;
}

Keyframes::State Keyframes::begin(Shared<Prepared> p) {
    State s;
    s.p = std::move(p);
    s.t = s.p->in.keys.front().t;
    s.phase = Phase::Tangents;
    const std::size_t n = std::size_t(s.p->frames);
    s.times.reserve(n);
    s.values.reserve(n);
    s.velocities.reserve(n);
    if (s.p->in.constant_speed) s.evens.reserve(n);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

namespace {

// The point at constant speed at time t: s = L (t − t_0)/(t_n − t_0), u from the table.
ArcLength::Query even_point(const Prepared& p, double t) {
    const double t0 = p.in.keys.front().t, t1 = p.in.keys.back().t;
    const double s = t == t1 ? p.length : p.length * (t - t0) / (t1 - t0);
    return ArcLength::invert(p.table_u, p.table_s, s);
}

}  // namespace

void Keyframes::take_step(State& s) {
    const Prepared& p = *s.p;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Tangents:  // computed in prepare(): this step shows them
            s.phase = p.in.constant_speed ? Phase::Table : Phase::Frame;
            return;
        case Phase::Table:
            s.phase = Phase::Frame;
            return;
        case Phase::Frame: {
            ++s.k;
            s.t = frame_time(p, s.k);
            s.e = evaluate(p.curve, s.t);
            const double speed = glm::length(s.e.velocity);
            s.speed_min = s.k == 0 ? speed : std::min(s.speed_min, speed);
            s.speed_max = s.k == 0 ? speed : std::max(s.speed_max, speed);
            s.times.push_back(s.t);
            s.values.push_back(s.e.value);
            s.velocities.push_back(s.e.velocity);
            if (p.in.constant_speed) {
                const ArcLength::Query q = even_point(p, s.t);
                s.even_s = q.s;
                s.even_u = q.u;
                s.bracket = q.bracket;
                s.even = evaluate(p.curve, q.u).value;
                s.evens.push_back(s.even);
            }
            if (s.k + 1 == p.frames) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void Keyframes::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    take_step(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

// A channel's value as text and as a variable: a number for a scalar, a point otherwise.
std::string val(glm::dvec3 v, int dim) {
    if (dim == 1) return num(v.x);
    return dim == 2 ? num(glm::dvec2(v)) : num(v);
}
Value var(glm::dvec3 v, int dim) {
    if (dim == 1) return v.x;
    if (dim == 2) return std::vector<double>{v.x, v.y};
    return vec(v);
}

void narrate_tangents(const Prepared& p, StepInfo& info) {
    const Curve& c = p.curve;
    const int dim = p.in.dim;
    info.event = "tangents";
    info.line = kLineTangents;
    std::string text = std::to_string(c.keys.size()) + " keys, " +
                       Keyframes::interpolation_name(c.kind) + " interpolation. ";
    switch (c.kind) {
        case Interpolation::Linear:
            text +=
                "Linear needs no tangents: inside a segment the velocity is its slope "
                "(p_{i+1} − p_i)/Δ_i, so at an inner key it jumps from the slope before to "
                "the slope after. ";
            break;
        case Interpolation::CatmullRom:
            text +=
                "Catmull–Rom: the tangent at a key is the average of the slopes either side, "
                "m_i = (s⁻ + s⁺)/2 (for keys 1 s apart, (p_{i+1} − p_{i−1})/2); the same "
                "arriving and leaving, so the velocity is continuous. ";
            break;
        case Interpolation::KochanekBartels:
            text +=
                "Kochanek–Bartels: m⁻ = (1−T)[(1−C)(1+B) s⁻ + (1+C)(1−B) s⁺]/2 arriving, "
                "m⁺ = (1−T)[(1+C)(1+B) s⁻ + (1−C)(1−B) s⁺]/2 leaving; tension shortens both, "
                "bias tilts them toward one side, continuity ≠ 0 makes them differ. ";
            break;
    }
    const std::size_t shown = std::min<std::size_t>(c.keys.size(), 6);
    for (std::size_t i = 0; i < shown; ++i) {
        text += "Key " + std::to_string(i) + " (t = " + num(c.keys[i].t) +
                ", p = " + val(c.keys[i].value, dim) + "): ";
        if (c.m_in[i] == c.m_out[i])
            text += "m = " + val(c.m_out[i], dim);
        else
            text += "m⁻ = " + val(c.m_in[i], dim) + ", m⁺ = " + val(c.m_out[i], dim);
        text += i + 1 < shown ? "; " : ". ";
    }
    if (shown < c.keys.size())
        text += "And " + std::to_string(c.keys.size() - shown) + " more keys. ";
    text += "The first and last keys take the one slope they have.";
    info.narration = text;
    info.vars = {{"t", c.keys.front().t}, {"n", (long long)c.keys.size()}};
}

void narrate_table(const Prepared& p, StepInfo& info) {
    info.event = "table";
    info.line = kLineTable;
    const double t0 = p.in.keys.front().t, t1 = p.in.keys.back().t;
    info.narration = "The arc-length table of the path: N = " + std::to_string(p.in.samples) +
                     " samples at u_j = t_0 + j (t_n − t_0)/N, every " +
                     num((t1 - t0) / p.in.samples) +
                     " s, and s_j adds up the chords |P(u_j) − P(u_{j−1})|. Its length L = s_N = " +
                     num(p.length) + ", the true length " + num(p.length_exact) +
                     " (the chords are " + num(p.length_exact - p.length, 3) +
                     " short). Moving at constant speed means s = L (t − t_0)/(t_n − t_0) = " +
                     num(p.length / (t1 - t0)) + " per second.";
    info.math = "L = s_{" + std::to_string(p.in.samples) + "} = " + tex(p.length);
    info.vars = {
        {"t", t0}, {"N", (long long)p.in.samples}, {"L", p.length}, {"L_exact", p.length_exact}};
}

void narrate_frame(const State& s, StepInfo& info) {
    const Prepared& p = *s.p;
    const Curve& c = p.curve;
    const int dim = p.in.dim;
    const int i = s.e.segment;
    const Key& a = c.keys[std::size_t(i)];
    const Key& b = c.keys[std::size_t(i) + 1];
    const double delta = b.t - a.t;
    // On a key: the frame's time equals a key's exactly.
    int on_key = -1;
    if (s.t == a.t) on_key = i;
    if (s.t == b.t) on_key = i + 1;
    info.event = on_key >= 0 ? "key" : "frame";
    info.line = c.kind == Interpolation::Linear || on_key < 0 ? kLineHermite : kLineSegment;
    std::string text = "Frame " + std::to_string(s.k) + ", t = " + num(s.t) + ": segment " +
                       std::to_string(i) + " [" + num(a.t) + ", " + num(b.t) + "], u = (" +
                       num(s.t) + " − " + num(a.t) + ")/" + num(delta) + " = " + num(s.e.u) + ". ";
    const Keyframes::Basis h = Keyframes::basis(s.e.u);
    if (c.kind == Interpolation::Linear) {
        text += "Linear: p = (1 − u) p_" + std::to_string(i) + " + u p_" + std::to_string(i + 1) +
                " = " + num(1 - s.e.u) + " · " + val(a.value, dim) + " + " + num(s.e.u) + " · " +
                val(b.value, dim) + " = " + val(s.e.value, dim) + "; velocity the slope " +
                val(s.e.velocity, dim) + ". ";
        info.math = "p = " + tex(1 - s.e.u) + "\\,p_{" + std::to_string(i) + "} + " + tex(s.e.u) +
                    "\\,p_{" + std::to_string(i + 1) + "}";
    } else {
        const glm::dvec3 m0 = c.m_out[std::size_t(i)], m1 = c.m_in[std::size_t(i) + 1];
        text += "Hermite weights h00 = " + num(h.h00, 4) + ", h10 = " + num(h.h10, 4) +
                ", h01 = " + num(h.h01, 4) + ", h11 = " + num(h.h11, 4) + " on p_" +
                std::to_string(i) + " = " + val(a.value, dim) + ", Δ m⁺_" + std::to_string(i) +
                " = " + val(delta * m0, dim) + ", p_" + std::to_string(i + 1) + " = " +
                val(b.value, dim) + ", Δ m⁻_" + std::to_string(i + 1) + " = " +
                val(delta * m1, dim) + ": p = " + val(s.e.value, dim) + ", velocity " +
                val(s.e.velocity, dim) + ". ";
        info.math = "p = " + tex(h.h00, 4) + "\\,p_{" + std::to_string(i) + "} + " + tex(h.h10, 4) +
                    "\\,\\Delta m^+_{" + std::to_string(i) + "} + " + tex(h.h01, 4) + "\\,p_{" +
                    std::to_string(i + 1) + "} " + (h.h11 < 0 ? "- " : "+ ") +
                    tex(std::fabs(h.h11), 4) + "\\,\\Delta m^-_{" + std::to_string(i + 1) + "}";
    }
    if (on_key >= 0) {
        const std::size_t j = std::size_t(on_key);
        text += "This is key " + std::to_string(on_key) + ": the value is p_" +
                std::to_string(on_key) + " exactly. ";
        if (j > 0 && j + 1 < c.keys.size()) {
            const glm::dvec3 left = Keyframes::evaluate_in(c, on_key - 1, 1.0).velocity;
            const glm::dvec3 right = Keyframes::evaluate_in(c, on_key, 0.0).velocity;
            text += "Velocity arriving " + val(left, dim) + ", leaving " + val(right, dim) +
                    (left == right ? ": no jump, C1 here. "
                                   : ": a jump of " + val(right - left, dim) + ". ");
        }
    }
    if (p.in.constant_speed) {
        text += "At constant speed: s = " + num(s.even_s) + ", in the table between u_" +
                std::to_string(s.bracket) + " and u_" + std::to_string(s.bracket + 1) +
                ", so u = " + num(s.even_u) + " and the point is " + val(s.even, dim) +
                " (the naive point is at u = t).";
    }
    info.narration = text;
    info.vars = {{"t", s.t},
                 {"k", (long long)s.k},
                 {"i", (long long)i},
                 {"u", s.e.u},
                 {"h00", h.h00},
                 {"h10", h.h10},
                 {"h01", h.h01},
                 {"h11", h.h11},
                 {"p", var(s.e.value, dim)},
                 {"v", var(s.e.velocity, dim)},
                 {"speed", glm::length(s.e.velocity)}};
    if (c.kind == Interpolation::Linear)
        info.vars.erase(info.vars.begin() + 4, info.vars.begin() + 8);
    if (p.in.constant_speed) {
        info.vars.push_back({"s", s.even_s});
        info.vars.push_back({"u_s", s.even_u});
        info.vars.push_back({"P(u_s)", var(s.even, dim)});
    }
}

void narrate_summary(const State& s, StepInfo& info) {
    const Prepared& p = *s.p;
    info.event = "summary";
    info.line = kLineReport;
    const double worst = max_jump(p.curve, nullptr);
    const bool c1 = worst <= kC1Tolerance * slope_scale(p.curve);
    std::string text = "Done: " + std::to_string(s.k + 1) + " frames of dt = " + num(p.in.dt) +
                       " from t = " + num(p.in.keys.front().t) + " to " + num(s.t) + ". ";
    text += c1 ? "The velocity is continuous at every key (C1)."
               : "The largest velocity jump at a key is " + num(worst) +
                     ": the curve is C0 (it passes through the keys) but not C1.";
    text +=
        " Speed of the naive motion between " + num(s.speed_min) + " and " + num(s.speed_max) + ".";
    if (p.in.constant_speed)
        text += " At constant speed it is L/(t_n − t_0) = " +
                num(p.length / (p.in.keys.back().t - p.in.keys.front().t)) + " throughout.";
    info.narration = text;
    info.vars = {
        {"t", s.t}, {"max_jump", worst}, {"speed_min", s.speed_min}, {"speed_max", s.speed_max}};
}

}  // namespace

void Keyframes::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Tangents:
            narrate_tangents(*s.p, info);
            break;
        case Phase::Table:
            narrate_table(*s.p, info);
            break;
        case Phase::Frame:
            narrate_frame(s, info);
            break;
        case Phase::Summary:
        case Phase::Done:
            narrate_summary(s, info);
            break;
    }
}

// ---- [result and compute] -------------------------------------------------------------------

namespace {

void finish(const Prepared& p, Keyframes::Result& r) {
    r.dim = p.in.dim;
    r.m_in = p.curve.m_in;
    r.m_out = p.curve.m_out;
    const double scale = slope_scale(p.curve);
    r.max_jump = max_jump(p.curve, &r.jumps);
    r.c1 = r.max_jump <= kC1Tolerance * scale;
    const Curve lin = Keyframes::make_curve(p.in, Interpolation::Linear);
    const Curve cr = Keyframes::make_curve(p.in, Interpolation::CatmullRom);
    const Curve kb = Keyframes::make_curve(p.in, Interpolation::KochanekBartels);
    r.c1_linear = max_jump(lin, nullptr) <= kC1Tolerance * scale;
    r.c1_catmull_rom = max_jump(cr, nullptr) <= kC1Tolerance * scale;
    r.c1_kochanek_bartels = max_jump(kb, nullptr) <= kC1Tolerance * scale;
    r.length = p.length;
    r.length_exact = p.length_exact;
    r.has_query = p.in.has_query;
    if (p.in.has_query) {
        const Eval a = Keyframes::evaluate(lin, p.in.query),
                   b = Keyframes::evaluate(cr, p.in.query), c = Keyframes::evaluate(kb, p.in.query);
        r.at = {a.value, b.value, c.value, a.velocity, b.velocity, c.velocity};
    }
}

}  // namespace

Keyframes::Result Keyframes::result(const State& s) {
    return result(State(s));
}

Keyframes::Result Keyframes::result(State&& s) {
    Result r;
    r.times = std::move(s.times);
    r.values = std::move(s.values);
    r.velocities = std::move(s.velocities);
    r.even = std::move(s.evens);
    r.speed_min = s.speed_min;
    r.speed_max = s.speed_max;
    finish(*s.p, r);
    return r;
}

Keyframes::Result Keyframes::compute(const Input& in) {
    const Prepared p = prepare(in);
    Result r;
    r.times.reserve(std::size_t(p.frames));
    r.values.reserve(std::size_t(p.frames));
    r.velocities.reserve(std::size_t(p.frames));
    if (p.in.constant_speed) r.even.reserve(std::size_t(p.frames));
    for (int k = 0; k < p.frames; ++k) {
        const double t = frame_time(p, k);
        const Eval e = evaluate(p.curve, t);
        const double speed = glm::length(e.velocity);
        r.speed_min = k == 0 ? speed : std::min(r.speed_min, speed);
        r.speed_max = k == 0 ? speed : std::max(r.speed_max, speed);
        r.times.push_back(t);
        r.values.push_back(e.value);
        r.velocities.push_back(e.velocity);
        if (p.in.constant_speed) r.even.push_back(evaluate(p.curve, even_point(p, t).u).value);
    }
    finish(p, r);
    return r;
}

}  // namespace cg
