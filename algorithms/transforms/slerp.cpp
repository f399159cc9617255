// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and interpolate]; the picture
// is in slerp_draw.cpp
#include "transforms/slerp.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dquat;
using glm::dvec3;
using Phase = Slerp::Phase;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineNormalise = 1,
    kLineDot,
    kLineFlip,
    kLineAngle,
    kLineBlend,
    kLineRotate,
    kLineMatrix,
    kLineSample,
};

double dot4(const dquat& a, const dquat& b) {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
double norm4(const dquat& q) {
    return std::sqrt(dot4(q, q));
}
dquat scaled(const dquat& q, double f) {
    return {q.w * f, q.x * f, q.y * f, q.z * f};
}
dquat sum(const dquat& a, const dquat& b) {
    return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
}
dquat diff(const dquat& a, const dquat& b) {
    return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z};
}
double max_abs(const dquat& q) {
    return std::max({std::fabs(q.w), std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
}

// q / |q|, scaled first by the largest component so that nothing over- or underflows.
dquat unit(const dquat& q) {
    const dquat s = scaled(q, 1 / max_abs(q));
    return scaled(s, 1 / norm4(s));
}
double length(const dquat& q) {
    const double m = max_abs(q);
    return m * norm4(scaled(q, 1 / m));
}

struct Weights {
    double omega, sin_omega, w0, w1;
    bool fallback;
};

// ω = 2 atan2(|q0 − q1|, |q0 + q1|) = arccos(q0 · q1), accurate also for nearly equal q0, q1.
Weights weights(const dquat& q0, const dquat& q1, double u) {
    Weights w;
    w.omega = 2 * std::atan2(norm4(diff(q0, q1)), norm4(sum(q0, q1)));
    w.sin_omega = std::sin(w.omega);
    w.fallback = w.sin_omega < Slerp::kFallbackSin;
    if (w.fallback) {
        w.w0 = 1 - u, w.w1 = u;
    } else {
        w.w0 = std::sin((1 - u) * w.omega) / w.sin_omega;
        w.w1 = std::sin(u * w.omega) / w.sin_omega;
    }
    return w;
}

dquat blend(const dquat& q0, const dquat& q1, const Weights& w) {
    const dquat q = sum(scaled(q0, w.w0), scaled(q1, w.w1));
    return w.fallback ? scaled(q, 1 / norm4(q)) : q;
}

std::string qtext(const dquat& q, int digits = 4) {
    return "[" + num(rot::clean(q.w), digits) + ", " + num(rot::clean(q.x), digits) + ", " +
           num(rot::clean(q.y), digits) + ", " + num(rot::clean(q.z), digits) + "]";
}
std::string qtex(const dquat& q, int digits = 4) {
    return "(" + tex(rot::clean(q.w), digits) + ", " + tex(rot::clean(q.x), digits) + ", " +
           tex(rot::clean(q.y), digits) + ", " + tex(rot::clean(q.z), digits) + ")";
}
std::vector<double> qvec(const dquat& q) {
    return {q.w, q.x, q.y, q.z};
}

// "a turn by 90° about (0, 0, 1)" for a unit quaternion.
std::string turn_text(const dquat& q) {
    const dvec3 v(q.x, q.y, q.z);
    const double s = glm::length(v);
    if (s == 0) return q.w > 0 ? "no turn (the identity)" : "a turn by 360° (the identity)";
    const double angle = rot::deg(2 * std::atan2(s, q.w));
    return "a turn by " + num(angle, 4) + "° about " + num(v / s, 4);
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

void check_quat(const dquat& q, const std::string& name) {
    const double c[4] = {q.w, q.x, q.y, q.z};
    for (int i = 0; i < 4; ++i) check_finite(c[i], name + "[" + std::to_string(i) + "]");
    if (max_abs(q) == 0)
        throw InputError(name,
                         "must not be the zero quaternion [0, 0, 0, 0]: it is no rotation "
                         "and cannot be normalised");
    if (!std::isfinite(length(q)))
        throw InputError(name,
                         "is too large: its length overflows a double; scale it down (only "
                         "its direction matters)");
}

}  // namespace

dquat Slerp::product(const dquat& a, const dquat& b) {
    // (s1 s2 − v1 · v2, s1 v2 + s2 v1 + v1 × v2)
    const dvec3 va(a.x, a.y, a.z), vb(b.x, b.y, b.z);
    const dvec3 v = a.w * vb + b.w * va + glm::cross(va, vb);
    return {a.w * b.w - glm::dot(va, vb), v.x, v.y, v.z};
}

dmat3 Slerp::to_matrix(const dquat& q) {
    const double w = q.w, x = q.x, y = q.y, z = q.z;
    dmat3 m;  // m[column][row]
    m[0] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
    m[1] = {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
    m[2] = {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)};
    return m;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Slerp::spec() {
    static const Spec spec{
        "slerp",
        "Quaternions and slerp",
        "Orientation and Interpolation",
        {
            "q0 ← q0/|q0|;  q1 ← q1/|q1|        ▷ unit: (cos θ/2, sin θ/2 v̂), a turn by θ about v̂",
            "cos ω ← q0 · q1                     ▷ = the scalar part of q1 q̄0",
            "if cos ω < 0: q1 ← −q1              ▷ same rotation, the short way round",
            "ω ← arccos(q0 · q1);  w0 ← sin((1−u)ω)/sin ω,  w1 ← sin(uω)/sin ω   "
            "(sin ω ≈ 0: w0 ← 1−u, w1 ← u, normalise)",
            "q(u) ← w0 q0 + w1 q1",
            "P′ ← q (0, P) q̄                    ▷ rotating a point: two products",
            "M ← the rotation matrix of q(u)",
            "for u_k = 0, 1/8, …, 1: compare slerp with lerp of matrices and of Euler angles",
        },
        {
            {"normalise", "both quaternions scaled to unit length, each read as angle and axis"},
            {"dot", "cos ω = q0 · q1 ≥ 0: the short way round already"},
            {"flip", "q0 · q1 < 0: q1 is negated (same rotation) so slerp takes the short way"},
            {"angle", "ω and the two slerp weights"},
            {"nearly-equal", "sin ω is tiny: the normalised linear blend replaces 0/0"},
            {"blend", "q(u) as the weighted sum of q0 and q1"},
            {"rotate-point", "the x axis rotated by q(u) as q (0, P) q̄"},
            {"matrix", "q(u) written as a 3×3 rotation matrix (or, to compare, the naive blend at u)"},
            {"sample", "one u on the paths: slerp vs lerp of matrices vs lerp of Euler angles"},
        },
        {},  // no sliders
        {
            .predict = {{"dot", {"cos_omega"}}, {"angle", {"omega_deg", "w0"}}, {"blend", {"q"}}},
            .mistakes = {
                {"angle", "w0", "swap:w1", "put sin(u ω) on q0 and sin((1 − u) ω) on q1"},
                {"dot", "flipped", "not", "got the shorter-arc test backwards when negating q1"},
                {"matrix", "M", "transpose", "wrote the matrix of conj(q): the inverse rotation"},
            },
            // Slerp against lerping the matrices or the Euler angles: the orientation at u.
            .variants = {{"slerp", "/method", "\"slerp\""},
                         {"matrix-lerp", "/method", "\"matrix-lerp\""},
                         {"euler-lerp", "/method", "\"euler-lerp\""}},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void Slerp::validate(const Input& in) {
    check_quat(in.q0, "q0");
    check_quat(in.q1, "q1");
    check_finite(in.u, "u");
    if (in.u < 0 || in.u > 1)
        throw InputError("u", "must be in [0, 1] (got " + given(in.u) +
                                  "): slerp interpolates between the two orientations; "
                                  "extrapolating past them is not supported");
}

Slerp::State Slerp::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    return s;
}

// The orientation at u as a matrix, by the input's method: slerp's q, or a naive blend of the
// keys (matrices entry by entry, or Euler angles xyz), as the sampled paths make them.
dmat3 in_between(const Slerp::Input& in, const dquat& q, const dquat& q0, const dquat& q1) {
    switch (in.method) {
        case Slerp::Method::MatrixLerp:
            return (1 - in.u) * Slerp::to_matrix(q0) + in.u * Slerp::to_matrix(q1);
        case Slerp::Method::EulerLerp:
            return rot::euler_matrix("xyz", (1 - in.u) * rot::euler_xyz_of(Slerp::to_matrix(q0)) +
                                                in.u * rot::euler_xyz_of(Slerp::to_matrix(q1)));
        case Slerp::Method::Slerp:
            break;
    }
    return Slerp::to_matrix(q);
}

// ---- [advance] ------------------------------------------------------------------------------

void Slerp::advance(State& s) {
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Normalise:  // Unit quaternions
            s.norm0 = length(s.in.q0);
            s.norm1 = length(s.in.q1);
            s.q0 = unit(s.in.q0);
            s.q1 = unit(s.in.q1);
            s.phase = Phase::Dot;
            return;
        case Phase::Dot:  // cos ω, and the flip to the short way
            s.cos_omega = dot4(s.q0, s.q1);
            s.flipped = s.cos_omega < 0;
            if (s.flipped) {
                s.q1 = scaled(s.q1, -1);
                s.cos_omega = -s.cos_omega;
            }
            s.relative = product(s.q1, conjugate(s.q0));
            s.phase = Phase::Angle;
            return;
        case Phase::Angle: {  // ω and the weights
            const Weights w = weights(s.q0, s.q1, s.in.u);
            s.omega = w.omega;
            s.sin_omega = w.sin_omega;
            s.fallback = w.fallback;
            s.w0 = w.w0;
            s.w1 = w.w1;
            s.phase = Phase::Blend;
            return;
        }
        case Phase::Blend:
            s.q = blend(s.q0, s.q1, {s.omega, s.sin_omega, s.w0, s.w1, s.fallback});
            s.phase = Phase::RotatePoint;
            return;
        case Phase::RotatePoint:  // q (0, x̂) q̄
            s.qp = product(s.q, dquat(0, 1, 0, 0));
            s.qpq = product(s.qp, conjugate(s.q));
            s.phase = Phase::Matrix;
            return;
        case Phase::Matrix:
            s.matrix = in_between(s.in, s.q, s.q0, s.q1);
            s.phase = Phase::Sample;
            return;
        case Phase::Sample: {  // One u on the three paths
            if (++s.k == 0) {  // the keys as matrices and as Euler angles, once
                s.m0 = to_matrix(s.q0);
                s.m1 = to_matrix(s.q1);
                s.e0 = rot::euler_xyz_of(s.m0);
                s.e1 = rot::euler_xyz_of(s.m1);
                s.tip_slerp.reserve(kSamples);
                s.tip_matrix.reserve(kSamples);
                s.tip_euler.reserve(kSamples);
            }
            const double u = s.k / double(kSamples - 1);
            const dquat q = blend(s.q0, s.q1, weights(s.q0, s.q1, u));
            s.tip_slerp.push_back(to_matrix(q)[0]);
            s.tip_matrix.push_back((1 - u) * s.m0[0] + u * s.m1[0]);
            s.tip_euler.push_back(rot::euler_matrix("xyz", (1 - u) * s.e0 + u * s.e1)[0]);
            if (s.k + 1 == kSamples) s.phase = Phase::Done;
            return;
        }
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = Slerp::State;

void narrate_normalise(const State& s, StepInfo& info) {
    auto one = [](const char* name, const dquat& raw, double n, const dquat& q) {
        std::string t = std::string(name) + " = " + qtext(raw, 6);
        t += std::fabs(n - 1) <= 1e-12
                 ? " is already unit length"
                 : " has length " + num(n, 6) + ", so " + name + " ← " + qtext(q);
        return t + ": " + turn_text(q);
    };
    info.event = "normalise";
    info.line = kLineNormalise;
    info.narration = one("q0", s.in.q0, s.norm0, s.q0) + "; " + one("q1", s.in.q1, s.norm1, s.q1) +
                     ". (A unit quaternion (cos θ/2, sin θ/2 v̂) is the turn by θ about v̂.)";
    info.math = "q_0 = \\frac{" + qtex(s.in.q0, 6) + "}{" + tex(s.norm0, 6) + "} = " + qtex(s.q0) +
                ",\\; q_1 = \\frac{" + qtex(s.in.q1, 6) + "}{" + tex(s.norm1, 6) +
                "} = " + qtex(s.q1);
}

void narrate_dot(const State& s, StepInfo& info) {
    const std::string rel = "The relative rotation q1 q̄0 = " + qtext(s.relative) + " is " +
                            turn_text(s.relative) + ": its scalar part is q0 · q1 = cos ω.";
    if (s.flipped) {
        info.event = "flip";
        info.line = kLineFlip;
        info.narration = "q0 · q1 = " + num(-s.cos_omega, 4) +
                         " < 0: going from q0 to q1 would take the long way round the sphere. −q1 "
                         "is the same rotation, so q1 ← −q1 = " +
                         qtext(s.q1) + " and cos ω = " + num(s.cos_omega, 4) + ". " + rel;
    } else {
        info.event = "dot";
        info.line = kLineDot;
        info.narration = "cos ω = q0 · q1 = " + num(s.cos_omega, 4) +
                         " ≥ 0: the short way round already, no flip. " + rel;
    }
    info.math = "\\cos\\omega = q_0 \\cdot q_1 = " + tex(s.cos_omega, 4) +
                ",\\; q_1 \\bar q_0 = " + qtex(s.relative);
}

void narrate_angle(const State& s, StepInfo& info) {
    const double u = s.in.u;
    if (s.fallback) {
        info.event = "nearly-equal";
        info.narration =
            "ω = " + num(rot::deg(s.omega), 4) + "°, sin ω = " + num(s.sin_omega, 4) +
            " < 10⁻⁶: q0 and q1 are (nearly) the same orientation and the slerp "
            "formula would divide by ≈ 0. Use the normalised linear blend: w0 = 1 − u = " +
            num(s.w0, 4) + ", w1 = u = " + num(s.w1, 4) +
            " (it differs from slerp "
            "by O(ω³)).";
        info.math = "\\sin\\omega = " + tex(s.sin_omega, 4) +
                    " \\approx 0:\\; w_0 = 1 - u = " + tex(s.w0, 4) +
                    ",\\; w_1 = u = " + tex(s.w1, 4);
    } else {
        info.event = "angle";
        info.narration = "ω = arccos(" + num(s.cos_omega, 4) + ") = " + num(rot::deg(s.omega), 6) +
                         "° (the rotations differ by 2ω = " + num(2 * rot::deg(s.omega), 4) +
                         "°), sin ω = " + num(s.sin_omega, 4) + ". At u = " + num(u, 4) +
                         ": w0 = sin((1−u)ω)/sin ω = " + num(s.w0, 4) +
                         ", w1 = sin(uω)/sin ω = " + num(s.w1, 4) + ".";
        info.math =
            "\\omega = \\cos^{-1}(" + tex(s.cos_omega, 4) + ") = " + tex(rot::deg(s.omega), 6) +
            "^\\circ,\\; w_0 = \\frac{\\sin((1-u)\\omega)}{\\sin\\omega} = " + tex(s.w0, 4) +
            ",\\; w_1 = \\frac{\\sin(u\\omega)}{\\sin\\omega} = " + tex(s.w1, 4);
    }
    info.line = kLineAngle;
}

void narrate_blend(const State& s, StepInfo& info) {
    info.event = "blend";
    info.line = kLineBlend;
    info.narration = "q(" + num(s.in.u, 4) + ") = " + num(s.w0, 4) + " q0 + " + num(s.w1, 4) +
                     " q1 = " + qtext(s.q) + (s.fallback ? " (normalised)" : "") +
                     ", |q| = " + num(norm4(s.q), 6) + ": " + turn_text(s.q) + ".";
    info.math = "q(u) = " + tex(s.w0, 4) + "\\, " + qtex(s.q0) + " + " + tex(s.w1, 4) + "\\, " +
                qtex(s.q1) + " = " + qtex(s.q);
}

void narrate_rotate(const State& s, StepInfo& info) {
    info.event = "rotate-point";
    info.line = kLineRotate;
    info.narration =
        "Rotate the x axis's tip P = (1, 0, 0) as the pure quaternion (0, P): q (0, P) = " +
        qtext(s.qp) + ", then times q̄ = " + qtext(Slerp::conjugate(s.q)) + " gives " +
        qtext(s.qpq) + ": P′ = " + num(dvec3(s.qpq.x, s.qpq.y, s.qpq.z), 4) +
        " (the scalar part is 0 again).";
    info.math = "q\\,(0, \\hat x)\\,\\bar q = " + qtex(s.qp) + "\\, " +
                qtex(Slerp::conjugate(s.q)) + " = " + qtex(s.qpq);
}

void narrate_matrix(const State& s, StepInfo& info) {
    info.event = "matrix";
    info.line = kLineMatrix;
    if (s.in.method != Slerp::Method::Slerp) {
        const bool by_matrix = s.in.method == Slerp::Method::MatrixLerp;
        const double det = glm::determinant(s.matrix);
        info.narration =
            std::string(by_matrix ? "Lerping the two matrices entry by entry instead, (1 − u) M0 + u M1 = "
                                  : "Lerping the two sets of Euler angles (x, y, z rolls) instead gives ") +
            rot::matrix_text(s.matrix) + (by_matrix ? ": its determinant is " + num(det, 4) +
                                                          (std::fabs(det - 1) > 1e-9 ? ", so it is no rotation" : "")
                                                    : ", a rotation, but not slerp's") +
            " (slerp's q(u) would give " + rot::matrix_text(Slerp::to_matrix(s.q)) + ").";
        info.math = std::string(by_matrix ? "M = (1 - u) M_0 + u M_1 = " : "M = R_{xyz}((1 - u) e_0 + u e_1) = ") +
                    rot::matrix_tex(s.matrix);
        return;
    }
    info.narration =
        "As a matrix, q(u) = " + rot::matrix_text(s.matrix) + " (its first column is P′ above).";
    info.math =
        "M = \\begin{bmatrix} 1 - 2(y^2 + z^2) & 2(xy - wz) & 2(xz + wy) \\\\ 2(xy + wz) & "
        "1 - 2(x^2 + z^2) & 2(yz - wx) \\\\ 2(xz - wy) & 2(yz + wx) & 1 - 2(x^2 + y^2) "
        "\\end{bmatrix} = " +
        rot::matrix_tex(s.matrix);
}

void narrate_sample(const State& s, StepInfo& info) {
    const double u = s.k / double(Slerp::kSamples - 1);
    auto clean = [](dvec3 v) { return dvec3(rot::clean(v.x), rot::clean(v.y), rot::clean(v.z)); };
    const dvec3 a = clean(s.tip_slerp[s.k]), b = clean(s.tip_matrix[s.k]),
                c = clean(s.tip_euler[s.k]);
    const double euler_off = rot::deg(std::atan2(glm::length(glm::cross(a, c)), glm::dot(a, c)));
    info.event = "sample";
    info.line = kLineSample;
    const std::string keys =
        s.k == 0 ? "For the comparison, q0 has Euler angles (x, y, z rolls, in that order) " +
                       num(s.e0, 4) + "° and q1 " + num(s.e1, 4) + "°. "
                 : "";
    info.narration =
        keys + "u = " + num(u, 4) + ": the x axis's tip is at " + num(a, 4) +
        " under slerp; lerp of the matrices puts it at " + num(b, 4) + ", length " +
        num(glm::length(b), 4) +
        (glm::length(b) < 1 - 1e-9 ? " (inside the sphere: the blend is no rotation)" : "") +
        "; lerp of the Euler angles at " + num(c, 4) + ", " + num(euler_off, 4) +
        "° away from slerp's.";
    info.math = "u = " + tex(u, 4) +
                ":\\; |(1-u)M_0\\hat x + uM_1\\hat x| = " + tex(glm::length(b), 4) +
                ",\\; \\angle(\\text{slerp}, \\text{Euler}) = " + tex(euler_off, 4) + "^\\circ";
}

void fill_vars(const State& s, StepInfo& info) {
    info.vars = {{"q0", qvec(s.q0)}, {"q1", qvec(s.q1)}, {"u", s.in.u}};
    if (s.last >= Phase::Dot) {
        info.vars.push_back({"cos_omega", s.cos_omega});
        info.vars.push_back({"flipped", s.flipped});
        info.vars.push_back({"q1 conj(q0)", qvec(s.relative)});
    }
    if (s.last >= Phase::Angle) {
        info.vars.push_back({"omega_deg", rot::deg(s.omega)});
        info.vars.push_back({"w0", s.w0});
        info.vars.push_back({"w1", s.w1});
    }
    if (s.last >= Phase::Blend) info.vars.push_back({"q", qvec(s.q)});
    if (s.last >= Phase::RotatePoint) info.vars.push_back({"q (0,x) conj(q)", qvec(s.qpq)});
    if (s.last >= Phase::Matrix) info.vars.push_back({"M", rot::rows3(s.matrix)});
    if (s.last == Phase::Sample) {
        info.vars.push_back({"u_k", s.k / double(Slerp::kSamples - 1)});
        info.vars.push_back({"tip slerp", vec(s.tip_slerp[s.k])});
        info.vars.push_back({"tip matrix lerp", vec(s.tip_matrix[s.k])});
        info.vars.push_back({"tip Euler lerp", vec(s.tip_euler[s.k])});
    }
}

}  // namespace

void Slerp::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Normalise:
            narrate_normalise(s, info);
            break;
        case Phase::Dot:
            narrate_dot(s, info);
            break;
        case Phase::Angle:
            narrate_angle(s, info);
            break;
        case Phase::Blend:
            narrate_blend(s, info);
            break;
        case Phase::RotatePoint:
            narrate_rotate(s, info);
            break;
        case Phase::Matrix:
            narrate_matrix(s, info);
            break;
        case Phase::Sample:
        case Phase::Done:
            narrate_sample(s, info);
            break;
    }
    fill_vars(s, info);
}

void Slerp::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and interpolate] ---------------------------------------------------------------

Slerp::Result Slerp::result(const State& s) {
    return {s.q, rot::deg(s.omega), s.matrix, s.flipped, s.fallback};
}

[[gnu::flatten]] Slerp::Result Slerp::interpolate(const Input& in) {
    Result r;
    const dquat q0 = unit(in.q0);
    dquat q1 = unit(in.q1);
    r.flipped = dot4(q0, q1) < 0;
    if (r.flipped) q1 = scaled(q1, -1);
    const Weights w = weights(q0, q1, in.u);
    r.fallback = w.fallback;
    r.omega_deg = rot::deg(w.omega);
    r.q = blend(q0, q1, w);
    r.matrix = in_between(in, r.q, q0, q1);
    return r;
}

}  // namespace cg
