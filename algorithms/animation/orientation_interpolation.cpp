// Sections: [key forms] [squad] [frames] [spec] [validate] [advance] [narrate]
//           [result and compute]
#include "animation/orientation_interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/format.hpp"
#include "transforms/quaternion.hpp"
#include "transforms/rotation_common.hpp"
#include "transforms/slerp.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dquat;
using glm::dvec3;
using OI = OrientationInterpolation;
using Input = OI::Input;
using Phase = OI::Phase;
using State = OI::State;
using Prepared = OI::Prepared;
using Frame = OI::Frame;

enum Line {
    kLineKey = 1,
    kLineAlign,
    kLineOmega,
    kLineTangents,
    kLineFrame,
    kLineEuler,
    kLineMatrix,
    kLineSlerp,
    kLineSquad,
    kLineSpeed,
    kLineReport
};

double dot4(const dquat& a, const dquat& b) {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

// slerp(a, b, u) by the slerp lesson's own code (the short way, the sin ω → 0 fallback).
dquat slerp(const dquat& a, const dquat& b, double u) {
    return Slerp::interpolate({a, b, u, Slerp::Method::Slerp}).q;
}

// Squad's slerps follow the arc from a to b as given, with no choice of sign (Shoemake's, and
// GLM's mix): a (a⁻¹ b)^t = a exp(t log(ā b)). Choosing the short way there would make the
// curve jump where the two inner points are 90° apart in 4D.
dquat arc(const dquat& a, const dquat& b, double t) {
    return Slerp::product(a, OI::exp_pure(t * OI::log_unit(Slerp::product(Slerp::conjugate(a), b))));
}

}  // namespace

const char* OI::form_name(Form f) {
    return f == Form::Euler ? "euler" : f == Form::AxisAngle ? "axis-angle" : "quaternion";
}

// ---- [key forms] ----------------------------------------------------------------------------

dvec3 OI::euler_of(const std::string& order, const dmat3& m) {
    // P maps axis order[n] to axis n, so P R Pᵀ is R with the axes renamed to "xyz". A
    // relabelling with det P = −1 (an odd permutation) is a reflection, which turns every
    // rotation's sense: P R_a(θ) Pᵀ = R_x(−θ). So the angles are det P × those of P R Pᵀ.
    dmat3 P(0.0);  // P[column][row]: row n is the unit vector of axis order[n]
    for (int n = 0; n < 3; ++n) P[order[std::size_t(n)] - 'x'][n] = 1;
    const double d = glm::determinant(P);
    const dvec3 e = rot::euler_xyz_of(P * m * glm::transpose(P));
    return d > 0 ? e : dvec3(rot::wrap_deg(-e.x), -e.y, rot::wrap_deg(-e.z));
}

void OI::key_forms(const Key& k, const std::string& order, dquat& q, dmat3& m, dvec3& e) {
    switch (k.form) {
        case Form::Euler:
            m = rot::euler_matrix(order, k.euler_deg);
            q = Quaternion::from_matrix(m);
            e = k.euler_deg;
            return;
        case Form::AxisAngle: {
            Quaternion::Input qi;
            qi.op = Quaternion::Op::FromAxisAngle;
            qi.axis = k.axis;
            qi.angle_deg = k.angle_deg;
            q = Quaternion::compute(qi).q;
            break;
        }
        case Form::Quaternion: {
            const double n = Quaternion::length(k.q);
            q = {k.q.w / n, k.q.x / n, k.q.y / n, k.q.z / n};
            break;
        }
    }
    m = Slerp::to_matrix(q);
    e = euler_of(order, m);
}

// ---- [squad] --------------------------------------------------------------------------------

dvec3 OI::log_unit(const dquat& q) {
    // q = (cos θ, sin θ v̂), θ ∈ [0, π]: log q = θ v̂ (0 when the vector part is 0).
    const dvec3 v(q.x, q.y, q.z);
    const double s = glm::length(v);
    if (s == 0) return dvec3(0);
    return (std::atan2(s, q.w) / s) * v;
}

dquat OI::exp_pure(dvec3 v) {
    const double t = glm::length(v);
    if (t == 0) return {1, 0, 0, 0};
    const dvec3 w = (std::sin(t) / t) * v;
    return {std::cos(t), w.x, w.y, w.z};
}

void OI::align(Prepared& p, int i) {
    const std::size_t a = std::size_t(i), b = a + 1;
    double c = dot4(p.q[a], p.q[b]);
    const bool flip = c < 0;
    if (flip) {
        p.q[b] = {-p.q[b].w, -p.q[b].x, -p.q[b].y, -p.q[b].z};
        c = -c;
    }
    p.cos_omega.push_back(c);
    p.flipped.push_back(flip);
    // ω = acos(q_i · q_{i+1}), as the slerp lesson computes it (accurate also near 0).
    p.omega_deg.push_back(Slerp::interpolate({p.q[a], p.q[b], 0, Slerp::Method::Slerp}).omega_deg);
}

void OI::tangents(Prepared& p) {
    const std::size_t n = p.q.size();
    p.s.assign(p.q.begin(), p.q.end());  // the ends: s_0 = q_0, s_n = q_n
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const dquat inv = Slerp::conjugate(p.q[i]);  // unit: q⁻¹ = q̄
        const dvec3 l = log_unit(Slerp::product(inv, p.q[i + 1])) +
                        log_unit(Slerp::product(inv, p.q[i - 1]));
        p.s[i] = Slerp::product(p.q[i], exp_pure(-0.25 * l));
    }
}

double OI::turn_deg(const dquat& a, const dquat& b) {
    const double t = Quaternion::angle_deg_of(Slerp::product(b, Slerp::conjugate(a)));
    return t > 180 ? 360 - t : t;
}

// ---- [frames] -------------------------------------------------------------------------------

Frame OI::frame(const Input& in, const Prepared& p, int k, const Frame* prev) {
    Frame f;
    const int segs = segments(in);
    const int i = std::min(k / in.frames, segs - 1);
    const std::size_t a = std::size_t(i), b = a + 1;
    const double dt = in.segment_time / in.frames;
    f.t = k * dt;
    f.segment = i;
    f.u = double(k - i * in.frames) / in.frames;
    const double u = f.u;
    // Euler: the angles lerped, then composed in the order.
    f.euler_deg = (1 - u) * p.e[a] + u * p.e[b];
    f.euler_q = Quaternion::from_matrix(rot::euler_matrix(in.order, f.euler_deg));
    // Matrix: entry by entry; det and how far MᵀM is from I.
    f.matrix = (1 - u) * p.m[a] + u * p.m[b];
    f.det = glm::determinant(f.matrix);
    f.orth_error = rot::max_diff(glm::transpose(f.matrix) * f.matrix, dmat3(1.0));
    // Slerp, and squad through the control points.
    f.slerp = slerp(p.q[a], p.q[b], u);
    if (p.s.empty()) {
        f.squad = f.slerp;
    } else {
        f.squad = arc(f.slerp, arc(p.s[a], p.s[b], u), 2 * u * (1 - u));  // f.slerp: no flip
    }
    if (prev) {
        f.speed_euler = turn_deg(prev->euler_q, f.euler_q) / dt;
        f.speed_slerp = turn_deg(prev->slerp, f.slerp) / dt;
        f.speed_squad = turn_deg(prev->squad, f.squad) / dt;
    }
    return f;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& OI::spec() {
    static const Spec spec{
        "orientation-interpolation",
        "Orientation interpolation: Euler angles, matrices, slerp and squad between keys",
        "Animation",
        {
            "for each key: q_i ← its unit quaternion;  M_i ← its matrix;  e_i ← its Euler "
            "angles (order abc)",
            "if q_i · q_{i+1} < 0: q_{i+1} ← −q_{i+1}   ▷ the same rotation, the short way round",
            "ω_i ← acos(q_i · q_{i+1})   ▷ half the turn from key i to key i+1",
            "squad: s_i ← q_i exp(−(log(q_i⁻¹ q_{i+1}) + log(q_i⁻¹ q_{i−1})) / 4);  s_0 = q_0, "
            "s_n = q_n",
            "for each frame t = k dt:  key segment i, u ∈ [0, 1]",
            "Euler:  e(u) ← (1 − u) e_i + u e_{i+1};  R ← R_c(e3) R_b(e2) R_a(e1)",
            "matrix:  M(u) ← (1 − u) M_i + u M_{i+1}   ▷ det M ≠ 1, MᵀM ≠ I: no rotation",
            "slerp:  q(u) ← (sin((1 − u) ω_i) q_i + sin(u ω_i) q_{i+1}) / sin ω_i",
            "squad:  q(u) ← slerp(slerp(q_i, q_{i+1}, u), slerp(s_i, s_{i+1}, u), 2u(1 − u))",
            "angular speed ← (the turn from frame k − 1 to frame k) / dt, for each method",
            "report each method's slowest and fastest speed, the matrix blend's worst det and "
            "orthogonality error",
        },
        {
            {"key", "one key orientation as a unit quaternion, a matrix and Euler angles"},
            {"align", "q_i · q_{i+1} ≥ 0: already the short way; ω of the segment"},
            {"flip", "q_i · q_{i+1} < 0: q_{i+1} negated (the same rotation) for the short way"},
            {"tangents", "squad's inner control quaternions s_i, one per inner key"},
            {"frame", "one frame of the animation by all four methods, with their speeds"},
            {"summary", "the speeds' ranges and the matrix blend's worst det"},
        },
        {},  // no sliders
        {
            .predict = {{"align", {"omega_deg"}},
                        {"flip", {"omega_deg"}},
                        {"frame", {"det"}}},
            .mistakes =
                {
                    {"flip", "flipped", "not",
                     "kept q_{i+1} although q_i · q_{i+1} < 0: slerp goes the long way round"},
                    {"align", "omega_deg", "copy:turn_deg",
                     "took ω as the whole turn between the keys: the quaternion angle is half "
                     "of it"},
                    {"frame", "w0", "swap:w1", "put sin(u ω) on q_i and sin((1 − u) ω) on q_{i+1}"},
                },
            .variants = {{"xyz", "/order", "\"xyz\""}, {"zyx", "/order", "\"zyx\""}},
        },
        "t",  // the clock: a frame step is dt = segment_time / frames seconds
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

std::string key_field(std::size_t i, const char* field) {
    return "keys[" + std::to_string(i) + "]." + field;
}

void check_number(double x, const std::string& field) {
    if (!std::isfinite(x)) throw InputError(field, "must be a finite number (got " + given(x) + ")");
}

void check_angle(double a, const std::string& field) {
    check_number(a, field);
    if (std::fabs(a) > OI::kMaxAngleDeg)
        throw InputError(field, "is too large (" + given(a) + "°): at most 3600° (ten turns) in size");
}

}  // namespace

void OI::validate(const Input& in) {
    const std::size_t n = in.keys.size();
    if (n < 2)
        throw InputError("keys", "must have at least 2 key orientations to interpolate between (got " +
                                     std::to_string(n) + ")");
    if (n > std::size_t(kMaxKeys))
        throw InputError("keys", "has " + std::to_string(n) + " keys; at most " +
                                     std::to_string(kMaxKeys));
    if (!rot::valid_order(in.order))
        throw InputError("order", "must be one of xyz, xzy, yxz, yzx, zxy, zyx (got \"" + in.order +
                                      "\")");
    for (std::size_t i = 0; i < n; ++i) {
        const Key& k = in.keys[i];
        switch (k.form) {
            case Form::Euler:
                for (int c = 0; c < 3; ++c)
                    check_angle(k.euler_deg[c],
                                key_field(i, "euler") + std::string("[") + char('0' + c) + "]");
                break;
            case Form::AxisAngle: {
                for (int c = 0; c < 3; ++c)
                    check_number(k.axis[c],
                                 key_field(i, "axis") + std::string("[") + char('0' + c) + "]");
                const double big = std::max({std::fabs(k.axis.x), std::fabs(k.axis.y),
                                             std::fabs(k.axis.z)});
                if (big == 0)
                    throw InputError(key_field(i, "axis"),
                                     "must not be the zero vector: a turn needs an axis");
                if (big > 1e150)
                    throw InputError(key_field(i, "axis"),
                                     "is too large (above 1e150): only its direction matters");
                check_angle(k.angle_deg, key_field(i, "angle"));
                break;
            }
            case Form::Quaternion: {
                const double c[4] = {k.q.w, k.q.x, k.q.y, k.q.z};
                for (int j = 0; j < 4; ++j)
                    check_number(c[j], key_field(i, "quaternion") + "[" + std::to_string(j) + "]");
                const double len = Quaternion::length(k.q);
                if (len == 0)
                    throw InputError(key_field(i, "quaternion"),
                                     "must not be [0, 0, 0, 0]: it is no rotation and cannot be "
                                     "normalised");
                if (!std::isfinite(len) || len < 1e-150)
                    throw InputError(key_field(i, "quaternion"),
                                     "has a length (" + given(len) +
                                         ") too far from 1 to normalise safely: scale it");
                break;
            }
        }
    }
    if (in.frames < 1 || in.frames > kMaxFrames)
        throw InputError("frames", "must be 1 to " + std::to_string(kMaxFrames) +
                                       " frames per segment (got " + std::to_string(in.frames) +
                                       ")");
    if ((long long)in.frames * (long long)(n - 1) + 1 > kMaxTotalFrames)
        throw InputError("frames", std::to_string(in.frames) + " frames for each of " +
                                       std::to_string(n - 1) + " segments is more than " +
                                       std::to_string(kMaxTotalFrames) + " frames in all");
    check_number(in.segment_time, "segment_time");
    if (in.segment_time <= 0 || in.segment_time > kMaxSegmentTime)
        throw InputError("segment_time", "must be a time > 0 and at most 10000 seconds (got " +
                                             given(in.segment_time) + ")");
}

OI::State OI::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

OI::State OI::begin(Shared<Input> shared) {
    State s;
    const std::size_t n = shared->keys.size();
    s.in = std::move(shared);
    s.p.q.reserve(n);
    s.p.m.reserve(n);
    s.p.e.reserve(n);
    s.frames.reserve(std::size_t(frame_count(*s.in)));
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void OI::advance(State& s) {
    const Input& in = *s.in;
    const int n = int(in.keys.size());
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Key: {  // Each key in all three forms
            s.i = int(s.p.q.size());
            dquat q;
            dmat3 m;
            dvec3 e;
            key_forms(in.keys[std::size_t(s.i)], in.order, q, m, e);
            s.p.q.push_back(q);
            s.p.m.push_back(m);
            s.p.e.push_back(e);
            if (s.i + 1 == n) s.phase = Phase::Align;
            return;
        }
        case Phase::Align:  // The sign of q_{i+1}: the short way round
            s.i = int(s.p.cos_omega.size());
            align(s.p, s.i);
            if (s.i + 2 == n) s.phase = n >= 3 ? Phase::Tangents : Phase::Frame;
            return;
        case Phase::Tangents:  // Squad's control points
            tangents(s.p);
            s.phase = Phase::Frame;
            return;
        case Phase::Frame: {  // One frame by the four methods
            s.i = int(s.frames.size());
            s.frames.push_back(frame(in, s.p, s.i, s.frames.empty() ? nullptr : &s.frames.back()));
            if (s.i + 1 == frame_count(in)) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void OI::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string qtext(const dquat& q) {
    return "[" + num(rot::clean(q.w), 4) + ", " + num(rot::clean(q.x), 4) + ", " +
           num(rot::clean(q.y), 4) + ", " + num(rot::clean(q.z), 4) + "]";
}
std::vector<double> qvec(const dquat& q) {
    return {q.w, q.x, q.y, q.z};
}
std::string angles_text(dvec3 e) {
    return "(" + num(e.x, 4) + "°, " + num(e.y, 4) + "°, " + num(e.z, 4) + "°)";
}
// "a turn by 90° about (0, 0, 1)"
std::string turn_text(const dquat& q) {
    const auto axis = Quaternion::axis_of(q);
    if (!axis) return "no turn (the identity)";
    double a = Quaternion::angle_deg_of(q);
    dvec3 v = *axis;
    if (a > 180) a = 360 - a, v = -v;  // the same turn, the short way
    return "a turn by " + num(a, 4) + "° about " + num(v, 4);
}

void narrate_key(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t i = std::size_t(s.i);
    const OI::Key& k = in.keys[i];
    const dquat& q = s.p.q[i];
    const std::string name = "Key " + std::to_string(i);
    std::string t;
    switch (k.form) {
        case OI::Form::Euler:
            t = name + " is given as Euler angles " + angles_text(k.euler_deg) + " in the order " +
                in.order + ": R = R_" + in.order[2] + "(θ3) R_" + in.order[1] + "(θ2) R_" +
                in.order[0] + "(θ1) = " + rot::matrix_text(s.p.m[i]) +
                ", and as a unit quaternion (from the matrix) q = " + qtext(q) + ", " +
                turn_text(q) + ".";
            break;
        case OI::Form::AxisAngle:
            t = name + " is given as a turn by " + num(k.angle_deg, 6) + "° about " +
                num(k.axis, 4) + ": q = (cos θ/2, sin θ/2 â) = " + qtext(q) + ", the matrix " +
                rot::matrix_text(s.p.m[i]) + ", and the Euler angles (order " + in.order + ") " +
                angles_text(s.p.e[i]) + ".";
            break;
        case OI::Form::Quaternion: {
            const double len = Quaternion::length(k.q);
            t = name + " is given as the quaternion " + qtext(k.q) +
                (std::fabs(len - 1) <= 1e-12 ? std::string(", already unit length")
                                             : ", |q| = " + num(len, 6) + ", so q/|q| = " + qtext(q)) +
                ": " + turn_text(q) + ". Its matrix is " + rot::matrix_text(s.p.m[i]) +
                " and its Euler angles (order " + in.order + ") " + angles_text(s.p.e[i]) + ".";
            break;
        }
    }
    info.event = "key";
    info.line = kLineKey;
    info.narration = t;
    info.math = "q_{" + std::to_string(i) + "} = (" + tex(rot::clean(q.w), 4) + ", " +
                tex(rot::clean(q.x), 4) + ", " + tex(rot::clean(q.y), 4) + ", " +
                tex(rot::clean(q.z), 4) + ")";
    info.vars = {{"t", 0.0},
                 {"key", (long long)i},
                 {"q", qvec(q)},
                 {"M", rot::rows3(s.p.m[i])},
                 {"euler", vec(s.p.e[i])}};
}

void narrate_align(const State& s, StepInfo& info) {
    const std::size_t i = std::size_t(s.i);
    const bool flip = s.p.flipped[i] != 0;
    const double c = s.p.cos_omega[i], w = s.p.omega_deg[i];
    const std::string a = std::to_string(i), b = std::to_string(i + 1);
    std::string t = "Segment " + a + " (key " + a + " → key " + b + "): q_" + a + " · q_" + b +
                    " = " + num(flip ? -c : c, 6);
    if (flip)
        t += " < 0, so q_" + b + " ← −q_" + b + " = " + qtext(s.p.q[i + 1]) +
             ". The same orientation (q and −q turn every point alike), but now slerp takes the "
             "short way: ω = acos(" + num(c, 6) + ") = " + num(w, 6) + "° instead of " +
             num(180 - w, 6) + "°.";
    else
        t += " ≥ 0: the short way already. ω = acos(" + num(c, 6) + ") = " + num(w, 6) + "°.";
    t += " The keys are 2ω = " + num(2 * w, 6) + "° apart, so slerp turns at 2ω / " +
         num(s.in->segment_time) + " s = " + num(2 * w / s.in->segment_time, 6) + "°/s.";
    info.event = flip ? "flip" : "align";
    info.line = flip ? kLineAlign : kLineOmega;
    info.narration = t;
    info.math = "\\omega_{" + a + "} = \\arccos(" + tex(c, 6) + ") = " + tex(w, 6) + "^\\circ";
    info.vars = {{"t", 0.0},
                 {"segment", (long long)i},
                 {"cos_omega", c},
                 {"flipped", flip},
                 {"omega_deg", w},
                 {"turn_deg", 2 * w}};
}

void narrate_tangents(const State& s, StepInfo& info) {
    std::string t = "Squad's control points, one per inner key (the end keys are their own): ";
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < s.p.s.size(); ++i) {
        rows.push_back(qvec(s.p.s[i]));
        if (i == 0 || i + 1 == s.p.s.size()) continue;
        if (i > 1) t += "; ";
        t += "s_" + std::to_string(i) + " = " + qtext(s.p.s[i]) + ", " +
             num(OI::turn_deg(s.p.q[i], s.p.s[i]), 4) + "° from q_" + std::to_string(i);
    }
    t += ". Each s_i leans away from the average of its neighbours, so the curve passes through "
         "q_i with the same angular velocity on both sides.";
    info.event = "tangents";
    info.line = kLineTangents;
    info.narration = t;
    info.vars = {{"t", 0.0}, {"s", rows}};
}

void narrate_frame(const State& s, StepInfo& info) {
    const Frame& f = s.frames.back();
    const std::size_t i = std::size_t(f.segment);
    const double u = f.u, omega = rot::rad(s.p.omega_deg[i]);
    const bool fallback = std::sin(omega) < Slerp::kFallbackSin;
    const double w0 = fallback ? 1 - u : std::sin((1 - u) * omega) / std::sin(omega);
    const double w1 = fallback ? u : std::sin(u * omega) / std::sin(omega);
    const std::string a = std::to_string(i), b = std::to_string(i + 1);
    std::string t = "Frame " + std::to_string(s.i) + ", t = " + num(f.t, 6) + " s (segment " + a +
                    ", u = " + num(u, 4) + "). Euler: e = " + num(1 - u, 4) + " e_" + a + " + " +
                    num(u, 4) + " e_" + b + " = " + angles_text(f.euler_deg) +
                    ". Matrix: M = (1 − u) M_" + a + " + u M_" + b + " has det " + num(f.det, 4) +
                    " and max |MᵀM − I| = " + num(f.orth_error, 3) +
                    (f.orth_error > 1e-9 ? " (a rotation has 1 and 0)" : " (a rotation here)") +
                    ". Slerp: ";
    if (fallback)
        t += "ω ≈ 0, so w0 = 1 − u, w1 = u and the blend is normalised";
    else
        t += "w0 = sin((1−u)ω)/sin ω = " + num(w0, 4) + ", w1 = sin(uω)/sin ω = " + num(w1, 4);
    t += ", q = " + qtext(f.slerp) + ".";
    if (!s.p.s.empty()) t += " Squad: q = " + qtext(f.squad) + ".";
    if (s.i > 0) {
        t += " Angular speed since the frame before: Euler " + num(f.speed_euler, 4) +
             "°/s, slerp " + num(f.speed_slerp, 4) + "°/s";
        if (!s.p.s.empty()) t += ", squad " + num(f.speed_squad, 4) + "°/s";
        t += ".";
    }
    info.event = "frame";
    info.line = kLineFrame;
    info.narration = t;
    info.math = "q(" + tex(u, 4) + ") = " + tex(w0, 4) + "\\, q_{" + a + "} + " + tex(w1, 4) +
                "\\, q_{" + b + "}";
    info.vars = {{"t", f.t},
                 {"k", (long long)s.i},
                 {"segment", (long long)i},
                 {"u", u},
                 {"euler", vec(f.euler_deg)},
                 {"M", rot::rows3(f.matrix)},
                 {"det", f.det},
                 {"orth_error", f.orth_error},
                 {"w0", w0},
                 {"w1", w1},
                 {"q_slerp", qvec(f.slerp)},
                 {"q_squad", qvec(f.squad)},
                 {"speed_euler", f.speed_euler},
                 {"speed_slerp", f.speed_slerp},
                 {"speed_squad", f.speed_squad}};
}

void narrate_summary(const State& s, StepInfo& info) {
    const OI::Result r = OI::result(s);
    auto range = [&](int m) {
        return num(r.speed_min[std::size_t(m)], 4) + " to " + num(r.speed_max[std::size_t(m)], 4) +
               "°/s";
    };
    std::string t = "Done: " + std::to_string(s.frames.size()) + " frames of dt = " +
                    num(r.dt, 6) + " s. Slerp's speed: " + range(1) +
                    " (constant within each segment, 2ω_i / " + num(s.in->segment_time) +
                    " s); Euler's: " + range(0);
    if (!s.p.s.empty()) t += "; squad's: " + range(2) + " (no jump at the keys)";
    t += ". The matrix blend's det fell to " + num(r.min_det, 4) +
         " and its orthogonality error reached " + num(r.max_orth_error, 3) +
         (r.max_orth_error > 1e-9 ? ": in between it is not a rotation."
                                  : ": every key the same, so nothing to blend.");
    info.event = "summary";
    info.line = kLineReport;
    info.narration = t;
    info.vars = {{"t", s.frames.back().t},
                 {"min_det", r.min_det},
                 {"max_orth_error", r.max_orth_error},
                 {"speed_euler", std::vector<double>{r.speed_min[0], r.speed_max[0]}},
                 {"speed_slerp", std::vector<double>{r.speed_min[1], r.speed_max[1]}},
                 {"speed_squad", std::vector<double>{r.speed_min[2], r.speed_max[2]}}};
}

}  // namespace

void OI::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Key:
            narrate_key(s, info);
            break;
        case Phase::Align:
            narrate_align(s, info);
            break;
        case Phase::Tangents:
            narrate_tangents(s, info);
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

void summarise(OI::Result& r) {
    r.min_det = 1;
    r.max_orth_error = 0;
    for (const Frame& f : r.frames) {
        r.min_det = std::min(r.min_det, f.det);
        r.max_orth_error = std::max(r.max_orth_error, f.orth_error);
    }
    for (int m = 0; m < 3; ++m) {
        double lo = 0, hi = 0;
        for (std::size_t k = 1; k < r.frames.size(); ++k) {
            const Frame& f = r.frames[k];
            const double v = m == 0 ? f.speed_euler : m == 1 ? f.speed_slerp : f.speed_squad;
            lo = k == 1 ? v : std::min(lo, v);
            hi = k == 1 ? v : std::max(hi, v);
        }
        r.speed_min[std::size_t(m)] = lo;
        r.speed_max[std::size_t(m)] = hi;
    }
}

}  // namespace

OI::Result OI::result(const State& s) {
    return result(State(s));
}

// A spent state's lists are moved out, as compute() hands over its own.
OI::Result OI::result(State&& s) {
    Result r;
    r.keys = std::move(s.p);
    r.frames = std::move(s.frames);
    r.dt = s.in->segment_time / s.in->frames;
    summarise(r);
    return r;
}

OI::Result OI::compute(const Input& in) {
    validate(in);
    Result r;
    const std::size_t n = in.keys.size();
    Prepared& p = r.keys;
    p.q.resize(n);
    p.m.resize(n);
    p.e.resize(n);
    for (std::size_t i = 0; i < n; ++i) key_forms(in.keys[i], in.order, p.q[i], p.m[i], p.e[i]);
    for (int i = 0; i + 1 < int(n); ++i) align(p, i);
    if (n >= 3) tangents(p);
    const int count = frame_count(in);
    r.frames.reserve(std::size_t(count));
    for (int k = 0; k < count; ++k)
        r.frames.push_back(frame(in, p, k, k == 0 ? nullptr : &r.frames.back()));
    r.dt = in.segment_time / in.frames;
    summarise(r);
    return r;
}

}  // namespace cg
