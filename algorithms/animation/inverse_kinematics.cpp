// Sections: [kinematics] [solvers] [spec] [validate] [advance] [narrate] [result and compute]
#include "animation/inverse_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <numbers>

#include "core/format.hpp"

namespace cg {

namespace {

using IK = InverseKinematics;
using Input = IK::Input;
using Method = IK::Method;
using Phase = IK::Phase;
using State = IK::State;
using V3 = std::vector<glm::dvec3>;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;

enum Line {
    kLineForward = 1,
    kLineDistance,
    kLineElbow,
    kLineShoulder,
    kLineCCD,
    kLineJacobian,
    kLineTranspose,
    kLineDLS,
    kLineUpdate,
    kLineReport
};

double deg(double r) {
    return r * kDeg;
}

// Rodrigues: Rot(a, θ) = cos θ I + sin θ [a]× + (1 − cos θ) a aᵀ, a unit (glm is column-major).
glm::dmat3 rotation(glm::dvec3 a, double theta) {
    const double c = std::cos(theta), s = std::sin(theta), t = 1 - c;
    return glm::dmat3(t * a.x * a.x + c, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y,
                      t * a.x * a.y - s * a.z, t * a.y * a.y + c, t * a.y * a.z + s * a.x,
                      t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c);
}

double total_length(const Input& in) {
    double s = 0;
    for (double l : in.lengths) s += l;
    return s;
}

}  // namespace

const char* IK::method_name(Method m) {
    switch (m) {
        case Method::Forward:
            return "forward";
        case Method::Analytic:
            return "analytic";
        case Method::CCD:
            return "ccd";
        case Method::JacobianTranspose:
            return "jacobian-transpose";
        case Method::DLS:
            return "dls";
    }
    return "?";
}

double IK::wrap(double r) {
    double x = std::remainder(r, 2 * kPi);
    if (x <= -kPi) x += 2 * kPi;
    return x;
}

// ---- [kinematics] ---------------------------------------------------------------------------

void IK::forward(const Input& in, const std::vector<double>& theta, V3& p, V3* w) {
    const std::size_t n = in.lengths.size();
    p.resize(n + 1);
    if (w) w->resize(n);
    p[0] = in.base;
    glm::dmat3 R(1.0);
    for (std::size_t i = 0; i < n; ++i) {
        R = R * rotation(in.axes[i], theta[i]);
        if (w) (*w)[i] = R * in.axes[i];
        p[i + 1] = p[i] + in.lengths[i] * R[0];  // R (l, 0, 0) = l × R's first column
    }
}

void IK::jacobian(const V3& w, const V3& p, V3& J) {
    const std::size_t n = w.size();
    J.resize(n);
    for (std::size_t i = 0; i < n; ++i) J[i] = glm::cross(w[i], p[n] - p[i]);
}

bool IK::is_planar(const Input& in) {
    for (const glm::dvec3& a : in.axes)
        if (a.x != 0 || a.y != 0) return false;
    return !in.has_target || in.target.z == in.base.z;
}

bool IK::reachable(const Input& in) {
    if (!in.has_target) return true;
    const double sum = total_length(in);
    const double d = glm::length(in.target - in.base);
    const double slack = 1e-12 * sum;
    if (d > sum + slack) return false;
    if (!is_planar(in)) return true;
    const double longest = *std::max_element(in.lengths.begin(), in.lengths.end());
    return d >= 2 * longest - sum - slack;
}

// ---- [solvers] ------------------------------------------------------------------------------

IK::TwoLink IK::two_link(double l1_in, double l2_in, double tx_in, double ty_in) {
    TwoLink r;
    r.d = std::hypot(tx_in, ty_in);
    // Worked in units of about l_1 + l_2, so that squares of tiny or huge lengths neither underflow
    // nor overflow; every angle is the same at any scale.
    // A power of two: scaling by it is exact, so ordinary arms get the unscaled numbers.
    const double scale = std::ldexp(1.0, std::ilogb(l1_in + l2_in));
    const double l1 = l1_in / scale, l2 = l2_in / scale, tx = tx_in / scale, ty = ty_in / scale;
    const double d = r.d / scale;
    // d² from the coordinates, not from d: (2, 1) gives 5, not 5.000000000000001.
    r.cos_theta2 = ((tx * tx + ty * ty - l1 * l1) - l2 * l2) / (2 * l1 * l2);
    const double slack = 1e-12;
    const double phi = std::atan2(ty, tx);  // 0 on the base
    r.reachable = d <= l1 + l2 + slack && d >= std::fabs(l1 - l2) - slack;
    auto set = [](double* out, double t1, double t2) {
        out[0] = deg(wrap(t1));
        out[1] = deg(wrap(t2));
    };
    if (!r.reachable) {
        if (d > l1 + l2) {  // stretched toward the target
            set(r.up, phi, 0);
            set(r.down, phi, 0);
        } else {  // folded, its end on the line to the target at |l1 − l2|
            const double t1 = l1 >= l2 ? phi : phi + kPi;
            set(r.up, t1, kPi);
            set(r.down, t1, kPi);
        }
        return r;
    }
    const double c = std::clamp(r.cos_theta2, -1.0, 1.0);
    if (c == -1) {  // folded: sin θ_2 = 0 exactly, the first link toward the target or away
        const double t1 = l1 >= l2 ? phi : phi + kPi;
        set(r.up, t1, kPi);
        set(r.down, t1, kPi);
        return r;
    }
    const double t2 = std::acos(c);
    for (int sgn : {-1, 1}) {
        const double th2 = sgn * t2;
        const double th1 = phi - std::atan2(l2 * std::sin(th2), l1 + l2 * std::cos(th2));
        set(sgn < 0 ? r.up : r.down, th1, th2);
    }
    return r;
}

double IK::ccd_delta(glm::dvec3 w, glm::dvec3 pivot, glm::dvec3 end, glm::dvec3 target,
                     glm::dvec3* u_out, glm::dvec3* v_out) {
    glm::dvec3 u = end - pivot, v = target - pivot;
    u -= glm::dot(u, w) * w;  // only the part ⊥ w turns
    v -= glm::dot(v, w) * w;
    if (u_out) *u_out = u;
    if (v_out) *v_out = v;
    // The end or the target on the joint's axis (within rounding: cos 90° is 6e-17, not 0):
    // every turn is as good, so none is made rather than one by a direction of rounding noise.
    const double eps = 1e-12 * (glm::length(end - pivot) + glm::length(target - pivot));
    const double lu = glm::length(u), lv = glm::length(v);
    if (lu <= eps || lv <= eps) return 0;
    // Opposite within rounding: half a turn, as +180° (angles live in (−180°, 180°]).
    const double sine = glm::dot(w, glm::cross(u, v)), cosine = glm::dot(u, v);
    if (cosine < 0 && std::fabs(sine) <= 1e-15 * lu * lv) return kPi;
    return std::atan2(sine, cosine);
}

double IK::transpose_step(const V3& J, glm::dvec3 e, std::vector<double>& dtheta) {
    const std::size_t n = J.size();
    dtheta.resize(n);
    glm::dvec3 JJte(0);
    double g2 = 0;  // |Jᵀe|² = e·JJᵀe
    for (std::size_t i = 0; i < n; ++i) {
        dtheta[i] = glm::dot(J[i], e);
        JJte += dtheta[i] * J[i];
        g2 += dtheta[i] * dtheta[i];
    }
    const double den = glm::dot(JJte, JJte);
    const double alpha = den > 0 ? g2 / den : 0;
    for (double& d : dtheta) d *= alpha;
    return alpha;
}

void IK::dls_step(const V3& J, glm::dvec3 e, double lambda, std::vector<double>& dtheta) {
    const std::size_t n = J.size();
    glm::dmat3 A(lambda * lambda);  // λ² I + Σ J_i J_iᵀ
    for (const glm::dvec3& c : J) A += glm::outerProduct(c, c);
    const glm::dvec3 y = glm::inverse(A) * e;
    dtheta.resize(n);
    for (std::size_t i = 0; i < n; ++i) dtheta[i] = glm::dot(J[i], y);
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& IK::spec() {
    static const Spec spec{
        "inverse-kinematics",
        "Inverse kinematics: a chain of joints reaching for a target (law of cosines, CCD, "
        "Jacobian transpose, damped least squares)",
        "Animation",
        {
            "forward kinematics: p_0 ← base;  R_i ← R_{i−1} Rot(a_i, θ_i),  "
            "p_i ← p_{i−1} + R_i (l_i, 0, 0)",
            "two links: d ← |target − p_0|;  d > l_1 + l_2 or d < |l_1 − l_2|: unreachable, "
            "take the nearest pose (stretched or folded)",
            "cos θ_2 ← (d² − l_1² − l_2²) / (2 l_1 l_2);   θ_2 ← ∓acos(cos θ_2)  "
            "(elbow up / elbow down)",
            "θ_1 ← atan2(t_y, t_x) − atan2(l_2 sin θ_2, l_1 + l_2 cos θ_2)",
            "CCD, joint j from the last to the first: u ← p_n − p_j,  v ← target − p_j  "
            "(⊥ w_j);  θ_j ← θ_j + atan2(w_j·(u × v), u·v)",
            "Jacobian: J_i ← w_i × (p_n − p_i),   e ← target − p_n",
            "transpose: Δθ ← α Jᵀe,   α = (e·JJᵀe) / |JJᵀe|²",
            "damped least squares: Δθ ← Jᵀ (JJᵀ + λ²I)⁻¹ e",
            "θ ← θ + Δθ;  p ← FK(θ);  stop at |e| ≤ tolerance, when it stalls, or after the "
            "iterations",
            "report the pose, the end effector and its distance to the target",
        },
        {
            {"link", "forward kinematics: the next joint position from the angles so far"},
            {"distance", "two links: the target's distance is within reach"},
            {"unreachable", "two links: the target is out of reach; the nearest pose is taken"},
            {"elbow", "two links: the elbow angle θ_2 by the law of cosines, both signs"},
            {"shoulder", "two links: the shoulder angle θ_1 for each elbow"},
            {"ccd-update", "CCD: one joint turned so that joint→end points at joint→target"},
            {"jacobian-step", "one Jacobian iteration: J, e, Δθ and the new pose"},
            {"summary", "the final pose and its error"},
        },
        {},  // no sliders
        {
            .predict = {{"link", {"p"}}, {"elbow", {"cos_theta2"}}, {"ccd-update", {"delta"}}},
            .mistakes =
                {
                    {"ccd-update", "delta", "negate",
                     "measured the angle from joint→target to joint→end: the joint turns away"},
                    {"elbow", "cos_theta2", "negate",
                     "took (l_1² + l_2² − d²) / (2 l_1 l_2): the cosine of the triangle's "
                     "inner angle, not of the bend"},
                    {"link", "p", "keep", "forgot to add the link to the previous joint"},
                },
            .variants = {{"ccd", "/method", "\"ccd\""},
                         {"jacobian-transpose", "/method", "\"jacobian-transpose\""},
                         {"dls", "/method", "\"dls\""}},
        },
        // No clock: a step is one solver iteration (or one joint update), not a frame of
        // simulated time, so Play steps at the viewer's step rate.
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

std::string at(const char* list, std::size_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
}

void check_point(glm::dvec3 p, const std::string& field) {
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(p[c])) throw InputError(field, "must be finite (got " + given(p[c]) + ")");
        if (std::fabs(p[c]) > IK::kMaxCoordinate)
            throw InputError(field, "is too large (" + given(p[c]) + "): at most 1e6 in size");
    }
}

}  // namespace

void IK::validate(const Input& in) {
    const std::size_t n = in.lengths.size();
    if (n == 0) throw InputError("lengths", "must have at least 1 link (got none)");
    if (n > std::size_t(kMaxLinks))
        throw InputError(
            "lengths", "has " + std::to_string(n) + " links; at most " + std::to_string(kMaxLinks));
    for (std::size_t i = 0; i < n; ++i) {
        const double l = in.lengths[i];
        if (!std::isfinite(l) || l <= 0)
            throw InputError(at("lengths", i),
                             "must be > 0 (a link of zero length has no direction), got " + given(l));
        if (l > kMaxCoordinate)
            throw InputError(at("lengths", i), "is too large (" + given(l) + "): at most 1e6");
    }
    if (!in.angles.empty() && in.angles.size() != n)
        throw InputError("angles", "must give one angle per link: " + std::to_string(n) + " (got " +
                                       std::to_string(in.angles.size()) + ")");
    for (std::size_t i = 0; i < in.angles.size(); ++i)
        if (!std::isfinite(in.angles[i]) || std::fabs(in.angles[i]) > kMaxAngle)
            throw InputError(at("angles", i),
                             "must be a finite angle in degrees, at most 1e6 in size (got " +
                                 given(in.angles[i]) + ")");
    if (!in.axes.empty() && in.axes.size() != n)
        throw InputError("axes", "must give one axis per link: " + std::to_string(n) + " (got " +
                                     std::to_string(in.axes.size()) + ")");
    for (std::size_t i = 0; i < in.axes.size(); ++i) {
        check_point(in.axes[i], at("axes", i));
        if (!(glm::length(in.axes[i]) > 1e-12))
            throw InputError(at("axes", i), "must not be zero: a hinge needs a direction");
    }
    check_point(in.base, "base");
    if (in.has_target) check_point(in.target, "target");
    if (!in.has_target && in.method != Method::Forward)
        throw InputError("target", std::string("is missing: ") + method_name(in.method) +
                                       " needs a target to reach");
    if (in.method == Method::Analytic) {
        if (n != 2)
            throw InputError("lengths", "analytic solves a two-link arm: give 2 lengths (got " +
                                            std::to_string(n) + ")");
        for (std::size_t i = 0; i < in.axes.size(); ++i) {
            const glm::dvec3 a = in.axes[i];
            if (a.x != 0 || a.y != 0 || a.z <= 0)
                throw InputError(at("axes", i),
                                 "analytic is the planar arm: every axis must be [0, 0, 1]");
        }
        if (in.target.z != in.base.z)
            throw InputError("target",
                             "analytic is the planar arm: the target must have the "
                             "base's z (" +
                                 given(in.base.z) + ")");
    }
    if (in.method == Method::DLS &&
        (!std::isfinite(in.damping) || in.damping <= 0 || in.damping > kMaxCoordinate))
        throw InputError("damping",
                         "must be λ > 0 and at most 1e6 (a length), got " + given(in.damping));
    if (!std::isfinite(in.tolerance) || in.tolerance <= 0 || in.tolerance > kMaxCoordinate)
        throw InputError("tolerance",
                         "must be > 0 and at most 1e6 (a distance), got " + given(in.tolerance));
    if (in.iterations < 1 || in.iterations > kMaxIterations)
        throw InputError("iterations", "must be 1 to " + std::to_string(kMaxIterations) + " (got " +
                                           std::to_string(in.iterations) + ")");
    if (in.method == Method::CCD && (long long)in.iterations * (long long)n > kMaxSteps)
        throw InputError("iterations",
                         std::to_string(in.iterations) + " sweeps of " + std::to_string(n) +
                             " joints is too many updates: at most " + std::to_string(kMaxSteps));
}

IK::Input IK::resolve(const Input& given) {
    validate(given);
    Input in = given;
    const std::size_t n = in.lengths.size();
    if (in.angles.empty()) in.angles.assign(n, 0.0);
    if (in.axes.empty()) in.axes.assign(n, glm::dvec3(0, 0, 1));
    for (glm::dvec3& a : in.axes) a = glm::normalize(a);
    return in;
}

IK::State IK::start(const Input& in) {
    return begin(Shared<Input>(resolve(in)));
}

namespace {

double error_of(const Input& in, const V3& p) {
    return in.has_target ? glm::length(in.target - p.back()) : 0.0;
}

}  // namespace

IK::State IK::begin(Shared<Input> shared) {
    const Input& in = *shared;
    State s;
    s.in = std::move(shared);
    const std::size_t n = in.lengths.size();
    s.planar = is_planar(in);
    s.size = std::max(total_length(in), in.has_target ? glm::length(in.target - in.base) : 0.0);
    s.theta.resize(n);
    for (std::size_t i = 0; i < n; ++i) s.theta[i] = wrap(in.angles[i] / kDeg);
    forward(in, s.theta, s.p, &s.axes);
    s.error = error_of(in, s.p);
    s.sweep_start_error = s.error;
    switch (in.method) {
        case Method::Forward:
            s.phase = Phase::Link;
            break;
        case Method::Analytic:
            s.phase = Phase::Distance;
            break;
        default:
            s.history.reserve(std::min<std::size_t>(
                std::size_t(in.iterations) * (in.method == Method::CCD ? n : 1) + 1, 4096));
            s.history.push_back(s.error);
            s.phase = s.error <= in.tolerance ? Phase::Summary : Phase::Update;
            if (s.error <= in.tolerance) s.stop = "reached";
            break;
    }
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void IK::take_step(State& s) {
    const Input& in = *s.in;
    const std::size_t n = in.lengths.size();
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Link:
            ++s.links_done;
            if (s.links_done == int(n)) {
                s.phase = Phase::Summary;
                s.stop = "forward";
            }
            return;
        case Phase::Distance:
            s.two_link = two_link(in.lengths[0], in.lengths[1], in.target.x - in.base.x,
                                  in.target.y - in.base.y);
            if (!s.two_link.reachable) {
                const double* pose = in.elbow_up ? s.two_link.up : s.two_link.down;
                s.theta = {pose[0] / kDeg, pose[1] / kDeg};
                forward(in, s.theta, s.p);
                s.error = error_of(in, s.p);
                s.stop = "analytic";
                s.phase = Phase::Summary;
            } else {
                s.phase = Phase::Elbow;
            }
            return;
        case Phase::Elbow:
            s.phase = Phase::Shoulder;
            return;
        case Phase::Shoulder: {
            const double* pose = in.elbow_up ? s.two_link.up : s.two_link.down;
            s.theta = {pose[0] / kDeg, pose[1] / kDeg};
            forward(in, s.theta, s.p);
            s.error = error_of(in, s.p);
            s.stop = "analytic";
            s.phase = Phase::Summary;
            return;
        }
        case Phase::Update: {
            V3& w = s.axes;  // the world axes of the current pose
            bool sweep_end = true;
            if (in.method == Method::CCD) {
                const int j = int(n) - 1 - s.k % int(n);
                s.joint = j;
                s.w = w[std::size_t(j)];
                s.e = in.target - s.p[n];
                s.delta = ccd_delta(s.w, s.p[std::size_t(j)], s.p[n], in.target, &s.u, &s.v);
                s.theta[std::size_t(j)] = wrap(s.theta[std::size_t(j)] + s.delta);
                if (s.k == 0) {
                    s.first_joint = j;
                    s.first_delta = deg(s.delta);
                }
                sweep_end = j == 0;
            } else {
                s.e = in.target - s.p[n];
                jacobian(w, s.p, s.J);
                if (in.method == Method::JacobianTranspose)
                    s.alpha = transpose_step(s.J, s.e, s.dtheta);
                else
                    dls_step(s.J, s.e, in.damping, s.dtheta);
                for (std::size_t i = 0; i < n; ++i) s.theta[i] = wrap(s.theta[i] + s.dtheta[i]);
            }
            ++s.k;
            forward(in, s.theta, s.p, &w);
            s.error = error_of(in, s.p);
            s.history.push_back(s.error);
            if (sweep_end) ++s.iterations;
            if (s.error <= in.tolerance) {
                s.stop = "reached";
            } else if (sweep_end) {
                if (std::fabs(s.sweep_start_error - s.error) <= kStall * s.size)
                    s.stop = "stalled";
                else if (s.iterations >= in.iterations)
                    s.stop = "iterations";
                s.sweep_start_error = s.error;
            }
            if (!s.stop.empty()) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void IK::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    take_step(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::vector<double> degrees(const std::vector<double>& r) {
    std::vector<double> d;
    d.reserve(r.size());
    for (double x : r) d.push_back(deg(x));
    return d;
}

std::string angle_list(const std::vector<double>& r) {
    std::string t = "(";
    for (std::size_t i = 0; i < r.size(); ++i) t += (i ? ", " : "") + num(deg(r[i])) + "°";
    return t + ")";
}

// A point as the chain lives: (x, y) for a planar chain, (x, y, z) otherwise.
std::string pt(const State& s, glm::dvec3 p) {
    return s.planar ? num(glm::dvec2(p)) : num(p);
}
std::vector<double> pv(const State& s, glm::dvec3 p) {
    return s.planar ? vec(glm::dvec2(p)) : vec(p);
}

void narrate_link(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t i = std::size_t(s.links_done);  // p_i is new
    info.event = "link";
    info.line = kLineForward;
    const glm::dvec3 dir = (s.p[i] - s.p[i - 1]) / in.lengths[i - 1];
    std::string t = "Link " + std::to_string(i) + ": θ_" + std::to_string(i) + " = " +
                    num(deg(s.theta[i - 1])) + "°";
    if (s.planar) {
        double phi = 0;
        for (std::size_t q = 0; q < i; ++q) phi += in.axes[q].z * s.theta[q];
        t +=
            ", so the link points at the sum of the angles so far, φ = " + num(deg(IK::wrap(phi))) +
            "°: p_" + std::to_string(i) + " = p_" + std::to_string(i - 1) + " + l_" +
            std::to_string(i) + " (cos φ, sin φ) = " + pt(s, s.p[i - 1]) + " + " +
            num(in.lengths[i - 1]) + " · " + pt(s, dir) + " = " + pt(s, s.p[i]) + ".";
        info.math = "p_{" + std::to_string(i) + "} = " + tex(glm::dvec2(s.p[i]));
    } else {
        t += " about a = " + num(in.axes[i - 1]) + ": R_" + std::to_string(i) + " = R_" +
             std::to_string(i - 1) + " Rot(a, θ) turns the link to " + num(dir) + ", p_" +
             std::to_string(i) + " = " + num(s.p[i - 1]) + " + " + num(in.lengths[i - 1]) + " · " +
             num(dir) + " = " + num(s.p[i]) + ".";
        info.math = "p_{" + std::to_string(i) + "} = " + tex(s.p[i]);
    }
    if (i == in.lengths.size()) t += " That is the end effector.";
    info.narration = t;
    info.vars = {{"i", (long long)i},
                 {"theta", deg(s.theta[i - 1])},
                 {"dir", pv(s, dir)},
                 {"p", pv(s, s.p[i])}};
}

void two_link_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& r = s.two_link;
    info.vars = {{"d", r.d},
                 {"l1_plus_l2", in.lengths[0] + in.lengths[1]},
                 {"l1_minus_l2", std::fabs(in.lengths[0] - in.lengths[1])},
                 {"reachable", r.reachable}};
}

void narrate_distance(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& r = s.two_link;
    const double l1 = in.lengths[0], l2 = in.lengths[1];
    info.line = kLineDistance;
    std::string t = "The target is at t = target − p_0 = " + num(glm::dvec2(in.target - in.base)) +
                    ", d = |t| = " + num(r.d) + ". ";
    if (r.reachable) {
        info.event = "distance";
        t += "It lies in the reach |l_1 − l_2| = " + num(std::fabs(l1 - l2)) +
             " ≤ d ≤ l_1 + l_2 = " + num(l1 + l2) +
             ": the arm can reach it, in general in two ways.";
    } else {
        info.event = "unreachable";
        const bool far = r.d > l1 + l2;
        const double* pose = in.elbow_up ? r.up : r.down;
        t += far ? "That is beyond l_1 + l_2 = " + num(l1 + l2) +
                       ": unreachable. The nearest pose is the arm stretched toward the target, "
                       "θ_1 = atan2(t_y, t_x) = " +
                       num(pose[0]) + "°, θ_2 = 0"
                 : "That is inside |l_1 − l_2| = " + num(std::fabs(l1 - l2)) +
                       ": unreachable, the arm cannot fold that tight. The nearest pose is "
                       "folded, θ_2 = 180°, with its end on the line to the target: θ_1 = " +
                       num(pose[0]) + "°";
        t += "; its end is at " + pt(s, s.p.back()) + ", " + num(s.error) + " from the target.";
    }
    info.narration = t;
    info.math = "d = " + tex(r.d) + (r.reachable ? " \\in " : " \\notin ") + "[" +
                tex(std::fabs(l1 - l2)) + ", " + tex(l1 + l2) + "]";
    two_link_vars(s, info);
}

void narrate_elbow(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& r = s.two_link;
    const double l1 = in.lengths[0], l2 = in.lengths[1];
    info.event = "elbow";
    info.line = kLineElbow;
    info.narration =
        "Law of cosines in the triangle base, elbow, target: cos θ_2 = (d² − l_1² − "
        "l_2²) / (2 l_1 l_2) = (" +
        num(r.d * r.d) + " − " + num(l1 * l1) + " − " + num(l2 * l2) + ") / " + num(2 * l1 * l2) +
        " = " + num(r.cos_theta2) + ", so θ_2 = ±" + num(r.down[1]) + "°: " + num(r.up[1]) +
        "° bends the elbow up, +" + num(r.down[1]) + "° down.";
    info.math = "\\cos\\theta_2 = \\frac{d^2 - l_1^2 - l_2^2}{2 l_1 l_2} = " + tex(r.cos_theta2);
    info.vars = {{"cos_theta2", r.cos_theta2}, {"theta2_up", r.up[1]}, {"theta2_down", r.down[1]}};
}

// "− x", or "+ |x|" for a negative x: no "− -26.6".
std::string minus(double x) {
    return x < 0 ? "+ " + num(-x) : "− " + num(x);
}

void narrate_shoulder(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& r = s.two_link;
    const double l1 = in.lengths[0], l2 = in.lengths[1];
    const glm::dvec2 t = glm::dvec2(in.target - in.base);
    info.event = "shoulder";
    info.line = kLineShoulder;
    const double phi = deg(std::atan2(t.y, t.x));
    auto beta = [&](double th2) {
        const double a = th2 / kDeg;
        return deg(std::atan2(l2 * std::sin(a), l1 + l2 * std::cos(a)));
    };
    info.narration =
        "θ_1 = atan2(t_y, t_x) − atan2(l_2 sin θ_2, l_1 + l_2 cos θ_2): the target's "
        "direction " +
        num(phi) +
        "° less the angle the elbow bends the end by. "
        "Elbow up: θ_1 = " +
        num(phi) + "° " + minus(beta(r.up[1])) + "° = " + num(r.up[0]) +
        "°; elbow down: θ_1 = " + num(phi) + "° " + minus(beta(r.down[1])) +
        "° = " + num(r.down[0]) + "°. Taking elbow " + (in.elbow_up ? "up" : "down") +
        ", forward kinematics puts the end at " + pt(s, s.p.back()) + " (error " + num(s.error, 3) +
        ").";
    info.math = "\\theta_1 = " + tex(in.elbow_up ? r.up[0] : r.down[0]) + "°";
    info.vars = {{"theta1_up", r.up[0]},     {"theta2_up", r.up[1]},     {"theta1_down", r.down[0]},
                 {"theta2_down", r.down[1]}, {"end", pv(s, s.p.back())}, {"error", s.error}};
}

void narrate_ccd(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t n = in.lengths.size();
    const int j = s.joint;
    info.event = "ccd-update";
    info.line = kLineCCD;
    const int sweep = (s.k - 1) / int(n) + 1;
    std::string t = "Sweep " + std::to_string(sweep) + ", joint " + std::to_string(j + 1) +
                    " at p_" + std::to_string(j) + " = " + pt(s, s.p[std::size_t(j)]) + ": u = p_" +
                    std::to_string(n) + " − p_" + std::to_string(j) + " = " + pt(s, s.u) +
                    ", v = target − p_" + std::to_string(j) + " = " + pt(s, s.v);
    if (!s.planar) t += " (both projected ⊥ the axis w = " + num(s.w) + ")";
    t += ". The angle from u to v is Δθ = atan2(w·(u × v), u·v) = " + num(deg(s.delta)) +
         "°, so θ_" + std::to_string(j + 1) + " ← " + num(deg(s.theta[std::size_t(j)])) +
         "° and the end moves to " + pt(s, s.p[n]) + ": |e| = " + num(s.error, 4) + " (was " +
         num(s.history[s.history.size() - 2], 4) + ").";
    if (s.delta == 0 && glm::length(s.v) == 0)
        t += " The target lies on this joint's axis: any turn is as good, none is made.";
    info.narration = t;
    info.math = "\\Delta\\theta_{" + std::to_string(j + 1) + "} = " + tex(deg(s.delta)) +
                "°,\\ |e| = " + tex(s.error, 4);
    info.vars = {{"k", (long long)s.k},
                 {"sweep", (long long)sweep},
                 {"j", (long long)(j + 1)},
                 {"u", pv(s, s.u)},
                 {"v", pv(s, s.v)},
                 {"delta", deg(s.delta)},
                 {"theta_j", deg(s.theta[std::size_t(j)])},
                 {"end", pv(s, s.p[n])},
                 {"error", s.error}};
}

void narrate_jacobian(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t n = in.lengths.size();
    const bool dls = in.method == Method::DLS;
    info.event = "jacobian-step";
    info.line = dls ? kLineDLS : kLineTranspose;
    std::string t = "Iteration " + std::to_string(s.k) + ": e = target − p_" + std::to_string(n) +
                    " = " + pt(s, s.e) + "; the Jacobian's columns J_i = w_i × (p_n − p_i) are";
    const std::size_t shown = std::min<std::size_t>(n, 6);
    for (std::size_t i = 0; i < shown; ++i)
        t += std::string(i ? "," : "") + " J_" + std::to_string(i + 1) + " = " + pt(s, s.J[i]);
    if (shown < n) t += " and " + std::to_string(n - shown) + " more";
    if (dls)
        t += ". Damped least squares with λ = " + num(in.damping) + ": Δθ = Jᵀ (JJᵀ + λ²I)⁻¹ e = ";
    else
        t += ". Transpose: α = (e·JJᵀe) / |JJᵀe|² = " + num(s.alpha) + ", Δθ = α Jᵀe = ";
    std::vector<double> d = degrees(s.dtheta);
    t += angle_list(s.dtheta) + ". The new pose " + angle_list(s.theta) + " puts the end at " +
         pt(s, s.p[n]) + ": |e| = " + num(s.error, 4) + " (was " +
         num(s.history[s.history.size() - 2], 4) + ").";
    info.narration = t;
    info.math =
        dls ? "\\Delta\\theta = J^T (J J^T + \\lambda^2 I)^{-1} e,\\ |e| = " + tex(s.error, 4)
            : "\\Delta\\theta = " + tex(s.alpha) + "\\, J^T e,\\ |e| = " + tex(s.error, 4);
    std::vector<std::vector<double>> rows(s.planar ? 2 : 3, std::vector<double>(n));
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t i = 0; i < n; ++i) rows[r][i] = s.J[i][int(r)];
    info.vars = {{"k", (long long)s.k}, {"e", pv(s, s.e)}, {"J", rows}};
    if (dls)
        info.vars.push_back({"lambda", in.damping});
    else
        info.vars.push_back({"alpha", s.alpha});
    info.vars.push_back({"dtheta", std::move(d)});
    info.vars.push_back({"end", pv(s, s.p[n])});
    info.vars.push_back({"error", s.error});
}

void narrate_summary(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t n = in.lengths.size();
    info.event = "summary";
    info.line = kLineReport;
    std::string t;
    if (in.method == Method::Forward) {
        t = "Forward kinematics done: the angles " + angle_list(s.theta) +
            " put the end effector at " + pt(s, s.p[n]) + ".";
        if (in.has_target) t += " It is " + num(s.error, 4) + " from the target.";
    } else if (in.method == Method::Analytic) {
        const auto& r = s.two_link;
        t = std::string(r.reachable ? "Reached" : "Unreachable") + ": elbow up (" + num(r.up[0]) +
            "°, " + num(r.up[1]) + "°), elbow down (" + num(r.down[0]) + "°, " + num(r.down[1]) +
            "°). The pose taken puts the end at " + pt(s, s.p[n]) + ", " + num(s.error, 4) +
            " from the target.";
    } else {
        const std::string what = in.method == Method::CCD
                                     ? " sweeps (" + std::to_string(s.k) + " joint updates)"
                                     : " iterations";
        const int its = in.method == Method::CCD ? (s.k + int(n) - 1) / int(n) : s.k;
        t = (s.stop == "reached" ? "Reached the target to " + num(s.error, 3) + " ≤ tolerance " +
                                       num(in.tolerance) + " after "
             : s.stop == "stalled"
                 ? "Stalled at |e| = " + num(s.error, 4) + " (no more progress) after "
                 : "Stopped at the iteration limit with |e| = " + num(s.error, 4) + " after ") +
            std::to_string(its) + what + ". Pose " + angle_list(s.theta) + ", end at " +
            pt(s, s.p[n]) + ".";
        if (!IK::reachable(in))
            t += " The target is out of reach (beyond the chain's length" +
                 std::string(s.planar ? " or inside its inner radius" : "") +
                 "): this is the nearest the chain gets.";
    }
    info.narration = t;
    info.math = "|e| = " + tex(s.error, 4);
    info.vars = {{"angles", degrees(s.theta)},
                 {"end", pv(s, s.p[n])},
                 {"error", s.error},
                 {"updates", (long long)s.k}};
}

}  // namespace

void IK::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Link:
            narrate_link(s, info);
            break;
        case Phase::Distance:
            narrate_distance(s, info);
            break;
        case Phase::Elbow:
            narrate_elbow(s, info);
            break;
        case Phase::Shoulder:
            narrate_shoulder(s, info);
            break;
        case Phase::Update:
            if (s.in->method == Method::CCD)
                narrate_ccd(s, info);
            else
                narrate_jacobian(s, info);
            break;
        case Phase::Summary:
        case Phase::Done:
            narrate_summary(s, info);
            break;
    }
}

// ---- [result and compute] -------------------------------------------------------------------

IK::Result IK::result(const State& s) {
    const Input& in = *s.in;
    const int n = int(in.lengths.size());
    Result r;
    r.method = in.method;
    r.angles = degrees(s.theta);
    r.positions = s.p;
    r.end = s.p.back();
    r.error = s.error;
    r.reached = in.has_target && s.error <= in.tolerance;
    r.reachable = reachable(in);
    r.planar = s.planar;
    r.updates = s.k;
    r.iterations = in.method == Method::CCD ? (s.k + n - 1) / n : s.k;
    r.errors = s.history;
    r.stop = s.stop;
    r.two_link = s.two_link;
    r.first_joint = s.first_joint;
    r.first_delta = s.first_delta;
    return r;
}

IK::Result IK::compute(const Input& given) {
    const Input in = resolve(given);
    const std::size_t n = in.lengths.size();
    Result r;
    r.method = in.method;
    r.planar = is_planar(in);
    r.reachable = reachable(in);
    std::vector<double> theta(n);
    for (std::size_t i = 0; i < n; ++i) theta[i] = wrap(in.angles[i] / kDeg);
    V3 p, w, J;
    forward(in, theta, p, &w);
    double error = error_of(in, p);
    if (in.method == Method::Analytic) {
        r.two_link = two_link(in.lengths[0], in.lengths[1], in.target.x - in.base.x,
                              in.target.y - in.base.y);
        const double* pose = in.elbow_up ? r.two_link.up : r.two_link.down;
        theta = {pose[0] / kDeg, pose[1] / kDeg};
        forward(in, theta, p);
        error = error_of(in, p);
        r.stop = "analytic";
    } else if (in.method == Method::Forward) {
        r.stop = "forward";
    } else {
        const double size =
            std::max(total_length(in), in.has_target ? glm::length(in.target - in.base) : 0.0);
        r.errors.reserve(std::min<std::size_t>(
            std::size_t(in.iterations) * (in.method == Method::CCD ? n : 1) + 1, 4096));
        r.errors.push_back(error);
        std::vector<double> dtheta;
        int k = 0, sweeps = 0;
        double sweep_start = error;
        if (error <= in.tolerance) r.stop = "reached";
        while (r.stop.empty()) {
            bool sweep_end = true;
            if (in.method == Method::CCD) {
                const std::size_t j = n - 1 - std::size_t(k) % n;
                const double delta = ccd_delta(w[j], p[j], p[n], in.target);
                theta[j] = wrap(theta[j] + delta);
                if (k == 0) {
                    r.first_joint = int(j);
                    r.first_delta = deg(delta);
                }
                sweep_end = j == 0;
            } else {
                jacobian(w, p, J);
                if (in.method == Method::JacobianTranspose)
                    transpose_step(J, in.target - p[n], dtheta);
                else
                    dls_step(J, in.target - p[n], in.damping, dtheta);
                for (std::size_t i = 0; i < n; ++i) theta[i] = wrap(theta[i] + dtheta[i]);
            }
            ++k;
            forward(in, theta, p, &w);
            error = error_of(in, p);
            r.errors.push_back(error);
            if (sweep_end) ++sweeps;
            if (error <= in.tolerance) {
                r.stop = "reached";
            } else if (sweep_end) {
                if (std::fabs(sweep_start - error) <= kStall * size)
                    r.stop = "stalled";
                else if (sweeps >= in.iterations)
                    r.stop = "iterations";
                sweep_start = error;
            }
        }
        r.updates = k;
        r.iterations = in.method == Method::CCD ? (k + int(n) - 1) / int(n) : k;
    }
    r.angles = degrees(theta);
    r.end = p[n];
    r.error = error;
    r.reached = in.has_target && error <= in.tolerance;
    r.positions = std::move(p);
    return r;
}

}  // namespace cg
