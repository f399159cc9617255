// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and compute] [draw]
#include "transforms/quaternion.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/format.hpp"
#include "transforms/rotation_common.hpp"
#include "transforms/slerp.hpp"  // the course's product, conjugate and matrix (one copy)

namespace cg {

namespace {

using glm::dmat3;
using glm::dquat;
using glm::dvec3;
using Op = Quaternion::Op;
using Phase = Quaternion::Phase;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineScalar = 1,
    kLineVector,
    kLineReverse,
    kLineConjugate,
    kLineInverse,
    kLineRotate,
    kLineAxisAngle,
    kLineToMatrix,
    kLineIsRotation,
    kLineShepperd,
};

dvec3 vpart(const dquat& q) {
    return {q.x, q.y, q.z};
}
dquat scaled(const dquat& q, double f) {
    return {q.w * f, q.x * f, q.y * f, q.z * f};
}
double max_abs(const dquat& q) {
    return std::max({std::fabs(q.w), std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
}
bool finite(const dquat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}
bool finite(const dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
// q / |q|, scaled first by its largest component so that nothing over- or underflows (q ≠ 0).
dquat unit_of(const dquat& q) {
    const dquat s = scaled(q, 1 / max_abs(q));
    const double n = std::sqrt(s.w * s.w + s.x * s.x + s.y * s.y + s.z * s.z);
    return scaled(s, 1 / n);
}
dvec3 unit_of(const dvec3& a) {
    const double m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
    const dvec3 s = a / m;
    return s / std::sqrt(glm::dot(s, s));
}
double length3(const dvec3& a) {
    const double m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
    if (m == 0) return 0;
    const dvec3 s = a / m;
    return m * std::sqrt(glm::dot(s, s));
}

// Round-off below 1e-15 shown as 0, in narrations only.
dquat cleaned(const dquat& q) {
    return {rot::clean(q.w), rot::clean(q.x), rot::clean(q.y), rot::clean(q.z)};
}
dvec3 cleaned(const dvec3& v) {
    return {rot::clean(v.x), rot::clean(v.y), rot::clean(v.z)};
}
std::string qtext(const dquat& q, int digits = 4) {
    const dquat c = cleaned(q);
    return "[" + num(c.w, digits) + ", " + num(c.x, digits) + ", " + num(c.y, digits) + ", " +
           num(c.z, digits) + "]";
}
std::string qtex(const dquat& q, int digits = 4) {
    const dquat c = cleaned(q);
    return "(" + tex(c.w, digits) + ", " + tex(c.x, digits) + ", " + tex(c.y, digits) + ", " +
           tex(c.z, digits) + ")";
}
std::string vtext(const dvec3& v, int digits = 4) {
    return num(cleaned(v), digits);
}
std::string vtex(const dvec3& v, int digits = 4) {
    return tex(cleaned(v), digits);
}
std::vector<double> qvec(const dquat& q) {
    return {q.w, q.x, q.y, q.z};
}

// "a turn by 90° about (0, 0, 1)" for a unit quaternion.
std::string turn_text(const dquat& q) {
    const auto axis = Quaternion::axis_of(q);
    if (!axis) return q.w > 0 ? "no turn (the identity)" : "a turn by 360° (the identity)";
    return "a turn by " + num(Quaternion::angle_deg_of(q), 4) + "° about " + vtext(*axis);
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}
void check_quat(const dquat& q, const std::string& name) {
    const double c[4] = {q.w, q.x, q.y, q.z};
    for (int i = 0; i < 4; ++i) check_finite(c[i], name + "[" + std::to_string(i) + "]");
}
void check_nonzero(const dquat& q, const std::string& name, const std::string& why) {
    if (max_abs(q) == 0)
        throw InputError(name, "must not be the zero quaternion [0, 0, 0, 0]: " + why);
}

}  // namespace

Phase Quaternion::first_phase(Op op) {
    switch (op) {
        case Op::Multiply:
            return Phase::ScalarPart;
        case Op::Conjugate:
        case Op::Inverse:
            return Phase::Conjugate;
        case Op::Rotate:
        case Op::ToMatrix:
            return Phase::Normalise;
        case Op::FromAxisAngle:
            return Phase::UnitAxis;
        case Op::FromMatrix:
            return Phase::IsRotation;
    }
    return Phase::Done;
}

namespace {

// The phase after `p` for `op`: each op walks its own run of the enum.
Phase next_phase(Op op, Phase p) {
    switch (p) {
        case Phase::Compare:
        case Phase::CheckInverse:
        case Phase::Image:
        case Phase::Build:
        case Phase::Matrix:
        case Phase::CheckBack:
            return Phase::Done;
        case Phase::Norm:
            return op == Op::Inverse ? Phase::Invert : Phase::Done;
        case Phase::Normalise:
            return op == Op::Rotate ? Phase::QTimesP : Phase::Terms;
        case Phase::Done:
            return Phase::Done;
        default:
            return Phase(int(p) + 1);
    }
}

struct Shepperd {
    std::array<double, 4> four_sq;  // 4w², 4x², 4y², 4z²
    int largest;
    dquat raw;  // before normalising
};

// r(i, j): row i, column j of R (glm stores m[column][row]).
Shepperd shepperd(const dmat3& m) {
    auto r = [&](int i, int j) { return m[j][i]; };
    const double tr = r(0, 0) + r(1, 1) + r(2, 2);
    Shepperd s;
    s.four_sq = {1 + tr, 1 + 2 * r(0, 0) - tr, 1 + 2 * r(1, 1) - tr, 1 + 2 * r(2, 2) - tr};
    s.largest = 0;
    for (int i = 1; i < 4; ++i)
        if (s.four_sq[i] > s.four_sq[s.largest]) s.largest = i;
    const double big = std::sqrt(s.four_sq[s.largest]) / 2, f = 1 / (4 * big);
    const double wx = r(2, 1) - r(1, 2), wy = r(0, 2) - r(2, 0), wz = r(1, 0) - r(0, 1);
    const double xy = r(0, 1) + r(1, 0), xz = r(0, 2) + r(2, 0), yz = r(1, 2) + r(2, 1);
    switch (s.largest) {
        case 0:
            s.raw = {big, wx * f, wy * f, wz * f};
            break;
        case 1:
            s.raw = {wx * f, big, xy * f, xz * f};
            break;
        case 2:
            s.raw = {wy * f, xy * f, big, yz * f};
            break;
        default:
            s.raw = {wz * f, xz * f, yz * f, big};
            break;
    }
    return s;
}

// w ≥ 0; when w = 0, the first non-zero of x, y, z positive.
bool needs_negating(const dquat& q) {
    for (double c : {q.w, q.x, q.y, q.z})
        if (c != 0) return c < 0;
    return false;
}

double max_entry(const dmat3& m) {
    double e = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) e = std::max(e, std::fabs(m[c][r]));
    return e;
}

// The intermediates that must stay finite (and the narration's too), for validate.
void check_multiply(const dquat& a, const dquat& b) {
    const dquat ab = Slerp::product(a, b), ba = Slerp::product(b, a);
    const double n = Quaternion::length(ab);
    const dvec3 twice_cross = 2.0 * glm::cross(vpart(a), vpart(b));
    if (!finite(ab) || !finite(ba) || !std::isfinite(n) || !finite(twice_cross))
        throw InputError("q1",
                         "is too large together with q2: their product overflows a double; "
                         "scale them down");
}

}  // namespace

const char* Quaternion::op_name(Op op) {
    switch (op) {
        case Op::Multiply:
            return "multiply";
        case Op::Conjugate:
            return "conjugate";
        case Op::Inverse:
            return "inverse";
        case Op::Rotate:
            return "rotate";
        case Op::FromAxisAngle:
            return "from_axis_angle";
        case Op::ToMatrix:
            return "to_matrix";
        case Op::FromMatrix:
            return "from_matrix";
    }
    return "?";
}

double Quaternion::length(const dquat& q) {
    const double m = max_abs(q);
    if (m == 0) return 0;
    const dquat s = scaled(q, 1 / m);
    return m * std::sqrt(s.w * s.w + s.x * s.x + s.y * s.y + s.z * s.z);
}

dquat Quaternion::inverse(const dquat& q) {
    const double n = length(q);  // q̄ / |q| / |q|: no |q|² to over- or underflow
    return scaled(scaled(Slerp::conjugate(q), 1 / n), 1 / n);
}

dquat Quaternion::from_matrix(const dmat3& r) {
    const dquat q = unit_of(shepperd(r).raw);
    return needs_negating(q) ? scaled(q, -1) : q;
}

double Quaternion::angle_deg_of(const dquat& q) {
    return rot::deg(2 * std::atan2(length3(vpart(q)), q.w));
}

std::optional<dvec3> Quaternion::axis_of(const dquat& q) {
    const dvec3 v = vpart(q);
    if (v == dvec3(0)) return std::nullopt;
    return unit_of(v);
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Quaternion::spec() {
    static const Spec spec{
        "quaternion",
        "Quaternion algebra",
        "Orientation and Interpolation",
        {
            "multiply: s ← s1 s2 − v1 · v2",
            "          v ← s1 v2 + s2 v1 + v1 × v2;  q1 q2 = (s, v)",
            "          q2 q1 = (s, s1 v2 + s2 v1 − v1 × v2)   ▷ equal iff v1 × v2 = 0",
            "conjugate: q̄ ← (s, −v);  q q̄ = (|q|², 0),  |q| = √(s² + |v|²)",
            "inverse:   q⁻¹ ← q̄ / |q|²                    ▷ q ≠ 0",
            "rotate:    q ← q/|q|;  (0, P′) ← q (0, P) q̄   ▷ two products",
            "from_axis_angle: â ← a/|a|;  q ← (cos θ/2, sin θ/2 â)",
            "to_matrix: q ← q/|q|;  M ← [1−2(y²+z²), 2(xy−wz), 2(xz+wy); 2(xy+wz), 1−2(x²+z²), "
            "2(yz−wx); 2(xz−wy), 2(yz+wx), 1−2(x²+y²)]",
            "from_matrix: check RᵀR = I and det R = 1",
            "             4w² = 1 + tr R, 4x² = 1 + 2r11 − tr R, …; the largest by √, the rest "
            "from r32 ∓ r23, …; w ≥ 0",
        },
        {
            {"scalar-part", "multiply: s1 s2 and v1 · v2, the scalar part s1 s2 − v1 · v2"},
            {"vector-part",
             "multiply: s1 v2, s2 v1 and v1 × v2, the three terms of the vector part"},
            {"product", "multiply: the parts summed, q1 q2"},
            {"reverse", "multiply: q2 q1 from the same parts, the cross product's sign flipped"},
            {"differ", "multiply: v1 × v2 ≠ 0, so q1 q2 ≠ q2 q1"},
            {"commute", "multiply: v1 × v2 = 0 (parallel vector parts), so q1 q2 = q2 q1"},
            {"conjugate", "q̄ = (s, −v)"},
            {"norm", "q q̄ = (|q|², 0): the squared length"},
            {"inverse", "q⁻¹ = q̄ / |q|²"},
            {"check-inverse", "q q⁻¹ = (1, 0)"},
            {"normalise", "q scaled to unit length (or already unit), read as angle and axis"},
            {"q-times-p", "rotate: the first product q (0, P)"},
            {"times-conjugate", "rotate: the second product (q (0, P)) q̄"},
            {"image", "rotate: P′ is the vector part; |P′| = |P|, and M(q) P agrees"},
            {"unit-axis", "from_axis_angle: the axis scaled to unit length"},
            {"half-angle", "from_axis_angle: cos θ/2 and sin θ/2"},
            {"build", "from_axis_angle: q = (cos θ/2, sin θ/2 â)"},
            {"terms", "to_matrix: the products x², y², z², xy, xz, yz, wx, wy, wz"},
            {"matrix", "to_matrix: the 3×3 rotation matrix; its columns are the turned axes"},
            {"is-rotation", "from_matrix: RᵀR = I and det R = 1 within the tolerance"},
            {"candidates",
             "from_matrix: 4w², 4x², 4y², 4z² from the diagonal; the largest is chosen"},
            {"extract",
             "from_matrix: the chosen component by its square root, the others from "
             "the off-diagonal entries"},
            {"sign", "from_matrix: q and −q are the same rotation; the one with w ≥ 0 is kept"},
            {"check-back", "from_matrix: M(q) rebuilt and compared with R"},
        },
        {},  // no sliders
        {
            .predict = {
                {"scalar-part", {"s1 s2", "v1 · v2"}},
                {"vector-part", {"v1 × v2"}},
                {"product", {"q1 q2"}},
                {"reverse", {"q2 q1"}},
                {"inverse", {"q⁻¹"}},
                {"image", {"P′"}},
                {"build", {"q"}},
                {"extract", {"q"}},
            },
            .mistakes = {
                {"vector-part", "v1 × v2", "negate",
                 "crossed v2 × v1: the sign of the cross term flipped"},
                {"reverse", "q2 q1", "copy:q1 q2", "assumed q2 q1 is the same as q1 q2"},
                {"differ", "commute", "not", "thought quaternion products commute"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void Quaternion::validate(const Input& in) {
    switch (in.op) {
        case Op::Multiply:
            check_quat(in.q1, "q1");
            check_quat(in.q2, "q2");
            check_multiply(in.q1, in.q2);
            return;
        case Op::Conjugate:
            check_quat(in.q, "q");
            if (!std::isfinite(length(in.q) * length(in.q)))
                throw InputError("q", "is too large: |q|² = q q̄ overflows a double; scale it down");
            return;
        case Op::Inverse: {
            check_quat(in.q, "q");
            check_nonzero(in.q, "q", "it has no inverse (|q|² = 0)");
            const double n2 = length(in.q) * length(in.q);
            if (!std::isfinite(n2))
                throw InputError("q", "is too large: |q|² overflows a double; scale it down");
            if (n2 < DBL_MIN)
                throw InputError("q", "is too small: |q|² underflows a double (|q| = " +
                                          given(length(in.q)) + "); scale it up");
            return;
        }
        case Op::Rotate: {
            check_quat(in.q, "q");
            check_nonzero(in.q, "q", "it is no rotation and cannot be normalised");
            for (int i = 0; i < 3; ++i)
                check_finite(in.point[i], "point[" + std::to_string(i) + "]");
            if (!std::isfinite(length3(in.point)))
                throw InputError("point", "is too large: its length overflows a double");
            const Result r = compute(in);
            if (!finite(*r.point))
                throw InputError("point", "is too large: its image overflows a double");
            return;
        }
        case Op::FromAxisAngle:
            for (int i = 0; i < 3; ++i) check_finite(in.axis[i], "axis[" + std::to_string(i) + "]");
            if (in.axis == dvec3(0))
                throw InputError("axis", "must not be the zero vector: it has no direction");
            check_finite(in.angle_deg, "angle_deg");
            return;
        case Op::ToMatrix:
            check_quat(in.q, "q");
            check_nonzero(in.q, "q", "it is no rotation and cannot be normalised");
            return;
        case Op::FromMatrix: {
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    check_finite(in.matrix[c][r],
                                 "matrix[" + std::to_string(r) + "][" + std::to_string(c) + "]");
            const double tol = kRotationTolerance;
            const double err = max_entry(glm::transpose(in.matrix) * in.matrix - dmat3(1.0));
            if (!(err <= tol))
                throw InputError(
                    "matrix",
                    "is not a rotation: its columns must be orthonormal (RᵀR = I within " +
                        given(tol) + "), but " +
                        (std::isfinite(err) ? "max |RᵀR − I| = " + given(err, 4)
                                            : std::string("RᵀR overflows a double")));
            const double det = glm::determinant(in.matrix);
            if (det < 0)
                throw InputError("matrix", "is a reflection (det R = " + given(det, 4) +
                                               "), not a rotation: a rotation has det R = 1");
            if (!(std::fabs(det - 1) <= tol))
                throw InputError("matrix", "is not a rotation: det R = " + given(det, 4) +
                                               " (must be 1 within " + given(tol) + ")");
            return;
        }
    }
}

Quaternion::State Quaternion::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

Quaternion::State Quaternion::begin(Shared<Input> in) {
    State s;
    s.phase = s.last = first_phase(in->op);
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void Quaternion::advance(State& s) {
    const Input& in = *s.in;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::ScalarPart:  // s1 s2 − v1 · v2
            s.s1s2 = in.q1.w * in.q2.w;
            s.v1v2 = glm::dot(vpart(in.q1), vpart(in.q2));
            break;
        case Phase::VectorPart:  // s1 v2 + s2 v1 + v1 × v2
            s.s1v2 = in.q1.w * vpart(in.q2);
            s.s2v1 = in.q2.w * vpart(in.q1);
            s.cross = glm::cross(vpart(in.q1), vpart(in.q2));
            break;
        case Phase::Product:
            s.q = Slerp::product(in.q1, in.q2);
            s.norm = length(s.q);
            break;
        case Phase::Reverse:
            s.q2q1 = Slerp::product(in.q2, in.q1);
            break;
        case Phase::Compare:  // q1 q2 − q2 q1 = (0, 2 v1 × v2)
            s.commute = s.cross == dvec3(0);
            break;
        case Phase::Conjugate:
            s.conj = Slerp::conjugate(in.q);
            s.norm = length(in.q);
            if (in.op == Op::Conjugate) s.q = s.conj;
            break;
        case Phase::Norm:  // q q̄ = (|q|², 0)
            s.check = Slerp::product(in.q, s.conj);
            break;
        case Phase::Invert:
            s.q = inverse(in.q);
            break;
        case Phase::CheckInverse:
            s.check = Slerp::product(in.q, s.q);
            break;
        case Phase::Normalise:
            s.norm = length(in.q);
            s.unit = unit_of(in.q);
            s.q = s.unit;
            break;
        case Phase::QTimesP:
            s.qp = Slerp::product(s.unit, dquat(0, in.point.x, in.point.y, in.point.z));
            break;
        case Phase::TimesConjugate:
            s.qpq = Slerp::product(s.qp, Slerp::conjugate(s.unit));
            break;
        case Phase::Image:
            s.matrix = Slerp::to_matrix(s.unit);
            break;
        case Phase::UnitAxis:
            s.axis_length = length3(in.axis);
            s.axis_unit = unit_of(in.axis);
            break;
        case Phase::HalfAngle: {
            const rot::CosSin cs = rot::cos_sin_deg(in.angle_deg / 2);
            s.half_cos = cs.c;
            s.half_sin = cs.s;
            break;
        }
        case Phase::Build: {
            const dvec3 v = s.half_sin * s.axis_unit;
            s.q = {s.half_cos, v.x, v.y, v.z};
            break;
        }
        case Phase::Terms:
            break;  // the products are read off the unit q in the narration
        case Phase::Matrix:
            s.matrix = Slerp::to_matrix(s.unit);
            break;
        case Phase::IsRotation:
            s.rtr = glm::transpose(in.matrix) * in.matrix;
            s.orth_error = max_entry(s.rtr - dmat3(1.0));
            s.det = glm::determinant(in.matrix);
            break;
        case Phase::Candidates: {
            const Shepperd sh = shepperd(in.matrix);
            s.four_sq = sh.four_sq;
            s.largest = sh.largest;
            s.raw = sh.raw;
            break;
        }
        case Phase::Extract:
            s.norm = length(s.raw);
            s.q = unit_of(s.raw);
            break;
        case Phase::Sign:
            s.negated = needs_negating(s.q);
            if (s.negated) s.q = scaled(s.q, -1);
            break;
        case Phase::CheckBack:
            s.matrix = Slerp::to_matrix(s.q);
            s.residual = max_entry(s.matrix - in.matrix);
            break;
        case Phase::Done:
            return;
    }
    s.phase = next_phase(in.op, s.phase);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = Quaternion::State;

void narrate_multiply(const State& s, StepInfo& info) {
    const dquat &a = s.in->q1, &b = s.in->q2;
    const std::string nums = "q1 = " + qtext(a) + ", q2 = " + qtext(b) + ". ";
    switch (s.last) {
        case Phase::ScalarPart:
            info.event = "scalar-part";
            info.line = kLineScalar;
            info.narration = nums + "Scalar part: s1 s2 = " + num(a.w, 4) + " · " + num(b.w, 4) +
                             " = " + num(s.s1s2, 4) + ", v1 · v2 = " + vtext(vpart(a)) + " · " +
                             vtext(vpart(b)) + " = " + num(s.v1v2, 4) +
                             ", so s = s1 s2 − v1 · v2 = " + num(s.s1s2 - s.v1v2, 4) + ".";
            info.math = "s = s_1 s_2 - v_1 \\cdot v_2 = " + tex(s.s1s2, 4) + " - " +
                        tex(s.v1v2, 4) + " = " + tex(s.s1s2 - s.v1v2, 4);
            return;
        case Phase::VectorPart:
            info.event = "vector-part";
            info.line = kLineVector;
            info.narration = "Vector part: s1 v2 = " + vtext(s.s1v2) +
                             ", s2 v1 = " + vtext(s.s2v1) + ", v1 × v2 = " + vtext(vpart(a)) +
                             " × " + vtext(vpart(b)) + " = " + vtext(s.cross) + ".";
            info.math = "s_1 v_2 = " + vtex(s.s1v2) + ",\\; s_2 v_1 = " + vtex(s.s2v1) +
                        ",\\; v_1 \\times v_2 = " + vtex(s.cross);
            return;
        case Phase::Product:
            info.event = "product";
            info.line = kLineVector;
            info.narration = "q1 q2 = (s1 s2 − v1 · v2, s1 v2 + s2 v1 + v1 × v2) = (" +
                             num(s.s1s2 - s.v1v2, 4) + ", " + vtext(s.s1v2) + " + " +
                             vtext(s.s2v1) + " + " + vtext(s.cross) + ") = " + qtext(s.q) +
                             ", with |q1 q2| = " + num(s.norm, 6) + " = |q1| |q2|.";
            info.math =
                "q_1 q_2 = (s_1 s_2 - v_1 \\cdot v_2,\\; s_1 v_2 + s_2 v_1 + v_1 \\times "
                "v_2) = " +
                qtex(s.q);
            return;
        case Phase::Reverse:
            info.event = "reverse";
            info.line = kLineReverse;
            info.narration =
                "q2 q1 uses the same parts, but v2 × v1 = −(v1 × v2) = " + vtext(-s.cross) +
                ": q2 q1 = (" + num(s.s1s2 - s.v1v2, 4) + ", " + vtext(s.s1v2) + " + " +
                vtext(s.s2v1) + " − " + vtext(s.cross) + ") = " + qtext(s.q2q1) + ".";
            info.math =
                "q_2 q_1 = (s_1 s_2 - v_1 \\cdot v_2,\\; s_1 v_2 + s_2 v_1 - v_1 \\times "
                "v_2) = " +
                qtex(s.q2q1);
            return;
        default:
            info.line = kLineReverse;
            if (s.commute) {
                info.event = "commute";
                info.narration =
                    "v1 × v2 = 0 (the vector parts are parallel, or one is zero), so "
                    "q1 q2 = q2 q1 = " +
                    qtext(s.q) + ": these two commute, as rotations about one axis do.";
                info.math = "v_1 \\times v_2 = 0 \\Rightarrow q_1 q_2 = q_2 q_1";
            } else {
                info.event = "differ";
                const dquat diff(0, 2 * s.cross.x, 2 * s.cross.y, 2 * s.cross.z);
                info.narration = "q1 q2 − q2 q1 = (0, 2 v1 × v2) = " + qtext(diff) +
                                 " ≠ 0: the product does not commute. As rotations, q1 q2 turns "
                                 "by q2 first and then by q1; q2 q1 the other way round.";
                info.math =
                    "q_1 q_2 - q_2 q_1 = (0,\\; 2\\,v_1 \\times v_2) = " + qtex(diff) + " \\ne 0";
            }
            return;
    }
}

void narrate_conjugate(const State& s, StepInfo& info) {
    const dquat& q = s.in->q;
    const double n2 = s.norm * s.norm;
    switch (s.last) {
        case Phase::Conjugate:
            info.event = "conjugate";
            info.line = kLineConjugate;
            info.narration = "q = " + qtext(q) + ", so q̄ = (s, −v) = " + qtext(s.conj) +
                             (s.in->op == Op::Inverse ? " (the first half of q⁻¹ = q̄ / |q|²)."
                                                     : ". As a rotation it is q's turn undone.");
            info.math = "\\bar q = (s, -v) = " + qtex(s.conj);
            return;
        case Phase::Norm:
            info.event = "norm";
            info.line = kLineConjugate;
            info.narration = "q q̄ = " + qtext(s.check) +
                             " = (|q|², 0): |q|² = s² + |v|² = " + num(n2, 6) +
                             ", |q| = " + num(s.norm, 6) +
                             (s.norm == 1 ? " (a unit quaternion: q̄ is its inverse)." : ".");
            info.math =
                "q \\bar q = " + qtex(s.check) + " = (|q|^2, 0),\\; |q| = " + tex(s.norm, 6);
            return;
        case Phase::Invert:
            info.event = "inverse";
            info.line = kLineInverse;
            info.narration = "q⁻¹ = q̄ / |q|² = " + qtext(s.conj) + " / " + num(n2, 6) + " = " +
                             qtext(s.q, 6) + ".";
            info.math = "q^{-1} = \\frac{\\bar q}{|q|^2} = \\frac{" + qtex(s.conj) + "}{" +
                        tex(n2, 6) + "} = " + qtex(s.q, 6);
            return;
        default:
            info.event = "check-inverse";
            info.line = kLineInverse;
            info.narration =
                "Check: q q⁻¹ = " + qtext(s.check, 6) + " = (1, 0, 0, 0), the identity.";
            info.math = "q\\,q^{-1} = " + qtex(s.check, 6);
            return;
    }
}

std::string normalise_text(const State& s) {
    const std::string t = std::fabs(s.norm - 1) <= 1e-12
                              ? "q = " + qtext(s.in->q, 6) + " is already unit length"
                              : "q = " + qtext(s.in->q, 6) + " has length " + num(s.norm, 6) +
                                    ", so it is normalised first: q ← q / |q| = " + qtext(s.unit);
    return t + ": " + turn_text(s.unit) + ".";
}

void narrate_rotate(const State& s, StepInfo& info) {
    const dvec3& p = s.in->point;
    info.line = kLineRotate;
    switch (s.last) {
        case Phase::Normalise:
            info.event = "normalise";
            info.narration = normalise_text(s) +
                             " (q and q/|q| turn a point the same way; q (0, P) "
                             "q̄ would also scale it by |q|².)";
            info.math = "q \\leftarrow \\frac{q}{|q|} = " + qtex(s.unit);
            return;
        case Phase::QTimesP:
            info.event = "q-times-p";
            info.narration =
                "P = " + vtext(p) +
                " as the pure quaternion (0, P). First product: q (0, P) = " + qtext(s.unit) + " " +
                qtext({0, p.x, p.y, p.z}) + " = " + qtext(s.qp) + " (s = −v · P, v = s P + v × P).";
            info.math = "q\\,(0, P) = (-v \\cdot P,\\; sP + v \\times P) = " + qtex(s.qp);
            return;
        case Phase::TimesConjugate:
            info.event = "times-conjugate";
            info.narration = "Second product: (q (0, P)) q̄ = " + qtext(s.qp) + " " +
                             qtext(Slerp::conjugate(s.unit)) + " = " + qtext(s.qpq) +
                             ": the scalar part is 0 again.";
            info.math = "(q\\,(0, P))\\,\\bar q = " + qtex(s.qp) + "\\, " +
                        qtex(Slerp::conjugate(s.unit)) + " = " + qtex(s.qpq);
            return;
        default: {
            const dvec3 image = vpart(s.qpq);
            info.event = "image";
            info.narration = "P′ = " + vtext(image) + ", |P′| = " + num(length3(image), 6) +
                             " = |P| (a rotation keeps lengths). The matrix of q gives the same: "
                             "M P = " +
                             vtext(s.matrix * p) + ".";
            info.math = "P' = " + vtex(image) + ",\\; |P'| = |P| = " + tex(length3(p), 6);
            return;
        }
    }
}

void narrate_axis_angle(const State& s, StepInfo& info) {
    info.line = kLineAxisAngle;
    const double half = s.in->angle_deg / 2;
    switch (s.last) {
        case Phase::UnitAxis:
            info.event = "unit-axis";
            info.narration = "a = " + vtext(s.in->axis) +
                             (std::fabs(s.axis_length - 1) <= 1e-12
                                  ? " is already unit length: â = a."
                                  : " has length " + num(s.axis_length, 6) +
                                        ", so â = a / |a| = " + vtext(s.axis_unit) + ".");
            info.math = "\\hat a = \\frac{a}{|a|} = " + vtex(s.axis_unit);
            return;
        case Phase::HalfAngle:
            info.event = "half-angle";
            info.narration = "θ = " + num(s.in->angle_deg, 6) + "°, so θ/2 = " + num(half, 6) +
                             "°: cos θ/2 = " + num(rot::clean(s.half_cos), 6) +
                             ", sin θ/2 = " + num(rot::clean(s.half_sin), 6) +
                             " (the half angle: q and −q are the same turn).";
            info.math = "\\cos\\frac{\\theta}{2} = " + tex(rot::clean(s.half_cos), 6) +
                        ",\\; \\sin\\frac{\\theta}{2} = " + tex(rot::clean(s.half_sin), 6);
            return;
        default:
            info.event = "build";
            info.narration = "q = (cos θ/2, sin θ/2 â) = (" + num(rot::clean(s.half_cos), 4) +
                             ", " + num(rot::clean(s.half_sin), 4) + " · " + vtext(s.axis_unit) +
                             ") = " + qtext(s.q) + ", a unit quaternion: " + turn_text(s.q) + ".";
            info.math = "q = (\\cos\\tfrac{\\theta}{2},\\; \\sin\\tfrac{\\theta}{2}\\,\\hat a) = " +
                        qtex(s.q);
            return;
    }
}

void narrate_to_matrix(const State& s, StepInfo& info) {
    info.line = kLineToMatrix;
    const dquat& q = s.unit;
    switch (s.last) {
        case Phase::Normalise:
            info.event = "normalise";
            info.narration = normalise_text(s) + " (The matrix formula holds for unit q only.)";
            info.math = "q \\leftarrow \\frac{q}{|q|} = " + qtex(s.unit);
            return;
        case Phase::Terms: {
            auto t = [](const char* name, double v) {
                return std::string(name) + " = " + num(rot::clean(v), 4);
            };
            info.event = "terms";
            info.narration = "With q = " + qtext(q) + ": " + t("x²", q.x * q.x) + ", " +
                             t("y²", q.y * q.y) + ", " + t("z²", q.z * q.z) + ", " +
                             t("xy", q.x * q.y) + ", " + t("xz", q.x * q.z) + ", " +
                             t("yz", q.y * q.z) + ", " + t("wx", q.w * q.x) + ", " +
                             t("wy", q.w * q.y) + ", " + t("wz", q.w * q.z) + ".";
            info.math = "x^2 = " + tex(rot::clean(q.x * q.x), 4) +
                        ",\\; y^2 = " + tex(rot::clean(q.y * q.y), 4) +
                        ",\\; z^2 = " + tex(rot::clean(q.z * q.z), 4) +
                        ",\\; xy = " + tex(rot::clean(q.x * q.y), 4) +
                        ",\\; wz = " + tex(rot::clean(q.w * q.z), 4);
            return;
        }
        default:
            info.event = "matrix";
            info.narration =
                "M = [1 − 2(y² + z²), 2(xy − wz), 2(xz + wy); 2(xy + wz), 1 − 2(x² + "
                "z²), 2(yz − wx); 2(xz − wy), 2(yz + wx), 1 − 2(x² + y²)] = " +
                rot::matrix_text(s.matrix) + ". Its columns are where the x, y and z axes turn to.";
            info.math =
                "M = \\begin{bmatrix} 1 - 2(y^2 + z^2) & 2(xy - wz) & 2(xz + wy) \\\\ 2(xy + wz) & "
                "1 - 2(x^2 + z^2) & 2(yz - wx) \\\\ 2(xz - wy) & 2(yz + wx) & 1 - 2(x^2 + y^2) "
                "\\end{bmatrix} = " +
                rot::matrix_tex(s.matrix);
            return;
    }
}

void narrate_from_matrix(const State& s, StepInfo& info) {
    static const char* kName[4] = {"w", "x", "y", "z"};
    const dmat3& m = s.in->matrix;
    switch (s.last) {
        case Phase::IsRotation:
            info.event = "is-rotation";
            info.line = kLineIsRotation;
            info.narration = "R = " + rot::matrix_text(m) +
                             ": max |RᵀR − I| = " + num(s.orth_error, 3) +
                             " and det R = " + num(s.det, 6) + ", both within " +
                             num(Quaternion::kRotationTolerance) + ": R is a rotation.";
            info.math =
                "\\max|R^TR - I| = " + tex(s.orth_error, 3) + ",\\; \\det R = " + tex(s.det, 6);
            return;
        case Phase::Candidates: {
            const double tr = m[0][0] + m[1][1] + m[2][2];
            info.event = "candidates";
            info.line = kLineShepperd;
            info.narration = "tr R = " + num(tr, 4) +
                             ": 4w² = 1 + tr R = " + num(rot::clean(s.four_sq[0]), 4) +
                             ", 4x² = 1 + 2r11 − tr R = " + num(rot::clean(s.four_sq[1]), 4) +
                             ", 4y² = 1 + 2r22 − tr R = " + num(rot::clean(s.four_sq[2]), 4) +
                             ", 4z² = 1 + 2r33 − tr R = " + num(rot::clean(s.four_sq[3]), 4) +
                             ". The largest is 4" + kName[s.largest] +
                             "²: taking its square root never divides by a small number.";
            info.math = "4w^2 = " + tex(rot::clean(s.four_sq[0]), 4) +
                        ",\\; 4x^2 = " + tex(rot::clean(s.four_sq[1]), 4) +
                        ",\\; 4y^2 = " + tex(rot::clean(s.four_sq[2]), 4) +
                        ",\\; 4z^2 = " + tex(rot::clean(s.four_sq[3]), 4);
            return;
        }
        case Phase::Extract: {
            static const char* kRest[4] = {
                "x = (r32 − r23)/4w, y = (r13 − r31)/4w, z = (r21 − r12)/4w",
                "w = (r32 − r23)/4x, y = (r12 + r21)/4x, z = (r13 + r31)/4x",
                "w = (r13 − r31)/4y, x = (r12 + r21)/4y, z = (r23 + r32)/4y",
                "w = (r21 − r12)/4z, x = (r13 + r31)/4z, y = (r23 + r32)/4z",
            };
            const double big = std::sqrt(s.four_sq[s.largest]) / 2;
            info.event = "extract";
            info.line = kLineShepperd;
            info.narration =
                std::string(kName[s.largest]) + " = √(" + num(s.four_sq[s.largest], 4) +
                ")/2 = " + num(big, 6) + "; then " + kRest[s.largest] + ": q = " + qtext(s.raw, 6) +
                (std::fabs(s.norm - 1) <= 1e-12
                     ? ", unit length."
                     : " of length " + num(s.norm, 8) +
                           " (R is not exactly orthonormal), normalised to " + qtext(s.q, 6) + ".");
            info.math = std::string(kName[s.largest]) + " = \\tfrac{1}{2}\\sqrt{" +
                        tex(s.four_sq[s.largest], 4) + "} = " + tex(big, 6) +
                        ",\\; q = " + qtex(s.q, 6);
            return;
        }
        case Phase::Sign:
            info.event = "sign";
            info.line = kLineShepperd;
            info.narration = s.negated
                                 ? "q and −q are the same rotation; the one with w ≥ 0 (w = 0: "
                                   "the first non-zero component positive) is kept: q ← −q = " +
                                       qtext(s.q) + ", " + turn_text(s.q) + "."
                                 : "q = " + qtext(s.q) +
                                       " already has w ≥ 0 (q and −q are the same "
                                       "rotation; this one is kept): " +
                                       turn_text(s.q) + ".";
            info.math = "q = " + qtex(s.q);
            return;
        default:
            info.event = "check-back";
            info.line = kLineToMatrix;
            info.narration = "Check: M(q) = " + rot::matrix_text(s.matrix) +
                             ", max |M(q) − R| = " + num(s.residual, 3) + ".";
            info.math = "M(q) = " + rot::matrix_tex(s.matrix) +
                        ",\\; \\max|M(q) - R| = " + tex(s.residual, 3);
            return;
    }
}

void fill_vars(const State& s, StepInfo& info) {
    const Phase p = s.last;
    auto at_least = [&](Phase from) { return p >= from; };
    switch (s.in->op) {
        case Op::Multiply:
            info.vars = {{"q1", qvec(s.in->q1)}, {"q2", qvec(s.in->q2)}};
            info.vars.push_back({"s1 s2", s.s1s2});
            info.vars.push_back({"v1 · v2", s.v1v2});
            if (at_least(Phase::VectorPart)) {
                info.vars.push_back({"s1 v2", vec(s.s1v2)});
                info.vars.push_back({"s2 v1", vec(s.s2v1)});
                info.vars.push_back({"v1 × v2", vec(s.cross)});
            }
            if (at_least(Phase::Product)) info.vars.push_back({"q1 q2", qvec(s.q)});
            if (at_least(Phase::Reverse)) info.vars.push_back({"q2 q1", qvec(s.q2q1)});
            if (at_least(Phase::Compare)) info.vars.push_back({"commute", s.commute});
            return;
        case Op::Conjugate:
        case Op::Inverse:
            info.vars = {{"q", qvec(s.in->q)}, {"conj(q)", qvec(s.conj)}, {"|q|", s.norm}};
            if (at_least(Phase::Norm)) info.vars.push_back({"|q|²", s.norm * s.norm});
            if (at_least(Phase::Invert)) info.vars.push_back({"q⁻¹", qvec(s.q)});
            if (at_least(Phase::CheckInverse)) info.vars.push_back({"q q⁻¹", qvec(s.check)});
            return;
        case Op::Rotate:
        case Op::ToMatrix:
            info.vars = {{"q", qvec(s.in->q)}, {"|q|", s.norm}, {"q/|q|", qvec(s.unit)}};
            if (s.in->op == Op::Rotate) {
                info.vars.push_back({"P", vec(s.in->point)});
                if (at_least(Phase::QTimesP)) info.vars.push_back({"q (0,P)", qvec(s.qp)});
                if (at_least(Phase::TimesConjugate))
                    info.vars.push_back({"q (0,P) conj(q)", qvec(s.qpq)});
                if (at_least(Phase::Image)) info.vars.push_back({"P′", vec(vpart(s.qpq))});
            } else if (at_least(Phase::Matrix)) {
                info.vars.push_back({"M", rot::rows3(s.matrix)});
            }
            return;
        case Op::FromAxisAngle:
            info.vars = {
                {"a", vec(s.in->axis)}, {"theta_deg", s.in->angle_deg}, {"â", vec(s.axis_unit)}};
            if (at_least(Phase::HalfAngle)) {
                info.vars.push_back({"cos θ/2", s.half_cos});
                info.vars.push_back({"sin θ/2", s.half_sin});
            }
            if (at_least(Phase::Build)) info.vars.push_back({"q", qvec(s.q)});
            return;
        case Op::FromMatrix:
            info.vars = {
                {"R", rot::rows3(s.in->matrix)}, {"max |RᵀR − I|", s.orth_error}, {"det R", s.det}};
            if (at_least(Phase::Candidates)) {
                info.vars.push_back({"4w², 4x², 4y², 4z²",
                                     std::vector<double>(s.four_sq.begin(), s.four_sq.end())});
                info.vars.push_back({"largest", std::string(1, "wxyz"[s.largest])});
            }
            if (at_least(Phase::Extract)) info.vars.push_back({"q", qvec(s.q)});
            if (at_least(Phase::CheckBack)) {
                info.vars.push_back({"M(q)", rot::rows3(s.matrix)});
                info.vars.push_back({"max |M(q) − R|", s.residual});
            }
            return;
    }
}

}  // namespace

void Quaternion::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.in->op) {
        case Op::Multiply:
            narrate_multiply(s, info);
            break;
        case Op::Conjugate:
        case Op::Inverse:
            narrate_conjugate(s, info);
            break;
        case Op::Rotate:
            narrate_rotate(s, info);
            break;
        case Op::FromAxisAngle:
            narrate_axis_angle(s, info);
            break;
        case Op::ToMatrix:
            narrate_to_matrix(s, info);
            break;
        case Op::FromMatrix:
            narrate_from_matrix(s, info);
            break;
    }
    fill_vars(s, info);
}

void Quaternion::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compute] -------------------------------------------------------------------

namespace {

void set_turn(Quaternion::Result& r, const dquat& unit) {
    r.angle_deg = Quaternion::angle_deg_of(unit);
    r.axis = Quaternion::axis_of(unit);
}

}  // namespace

Quaternion::Result Quaternion::result(const State& s) {
    Result r;
    r.op = s.in->op;
    r.q = s.q;
    switch (s.in->op) {
        case Op::Multiply:
            r.q2q1 = s.q2q1;
            r.commute = s.commute;
            r.norm = s.norm;
            break;
        case Op::Conjugate:
        case Op::Inverse:
            r.norm = s.norm;
            break;
        case Op::Rotate:
            r.norm = s.norm;
            r.point = vpart(s.qpq);
            set_turn(r, s.q);
            break;
        case Op::ToMatrix:
            r.norm = s.norm;
            r.matrix = s.matrix;
            set_turn(r, s.q);
            break;
        case Op::FromAxisAngle:
        case Op::FromMatrix:
            set_turn(r, s.q);
            break;
    }
    return r;
}

Quaternion::Result Quaternion::compute(const Input& in) {
    Result r;
    r.op = in.op;
    switch (in.op) {
        case Op::Multiply:
            r.q = Slerp::product(in.q1, in.q2);
            r.q2q1 = Slerp::product(in.q2, in.q1);
            r.commute = glm::cross(vpart(in.q1), vpart(in.q2)) == dvec3(0);
            r.norm = length(r.q);
            break;
        case Op::Conjugate:
            r.q = Slerp::conjugate(in.q);
            r.norm = length(in.q);
            break;
        case Op::Inverse:
            r.q = inverse(in.q);
            r.norm = length(in.q);
            break;
        case Op::Rotate: {
            r.norm = length(in.q);
            r.q = unit_of(in.q);
            const dquat qp = Slerp::product(r.q, dquat(0, in.point.x, in.point.y, in.point.z));
            r.point = vpart(Slerp::product(qp, Slerp::conjugate(r.q)));
            set_turn(r, r.q);
            break;
        }
        case Op::FromAxisAngle: {
            const rot::CosSin cs = rot::cos_sin_deg(in.angle_deg / 2);
            const dvec3 v = cs.s * unit_of(in.axis);
            r.q = {cs.c, v.x, v.y, v.z};
            set_turn(r, r.q);
            break;
        }
        case Op::ToMatrix:
            r.norm = length(in.q);
            r.q = unit_of(in.q);
            r.matrix = Slerp::to_matrix(r.q);
            set_turn(r, r.q);
            break;
        case Op::FromMatrix:
            r.q = from_matrix(in.matrix);
            set_turn(r, r.q);
            break;
    }
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

namespace {

const Style kAxisStyle{Role::Active, 3.0f};
const Style kConstruction{Role::Construction, 1.0f, true};

void world_frame(Scene& scene) {
    scene.frames3.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0, "", 0.45f});
}

void frame_of(Scene& scene, const dmat3& m, const std::string& name, double length, float alpha) {
    scene.frames3.push_back({{0, 0, 0}, m[0], m[1], m[2], length, name, alpha});
}

// The rotation axis of unit q through the origin, with its turn as an arc.
void axis_and_turn(Scene& scene, const dquat& unit, double reach, const std::string& label) {
    const auto axis = Quaternion::axis_of(unit);
    if (!axis) return;
    scene.segments3.push_back({-reach * *axis, reach * *axis, "", kAxisStyle, true});
    scene.labels3.push_back({reach * *axis, label, {Role::Active}});
    const double angle = Quaternion::angle_deg_of(unit);
    const dvec3 start = rot::perpendicular(*axis);
    rot::draw_arc(scene, 0.55 * reach * *axis, *axis, start, 0.45, 0, angle, {Role::Leaving, 2.0f},
                  true, "θ = " + num(angle, 4) + "°");
}

// A vector as an arrow from the origin.
void arrow(Scene& scene, const dvec3& v, double scale, const std::string& label, Role role) {
    if (v == dvec3(0)) return;
    scene.segments3.push_back({{0, 0, 0}, scale * v, "", {role, 2.5f}, true});
    scene.labels3.push_back({scale * v, label, {role}});
}

void draw_multiply(const State& s, Scene& scene) {
    const dvec3 v1 = vpart(s.in->q1), v2 = vpart(s.in->q2);
    const bool crossed = s.phase > Phase::VectorPart;
    const double big = std::max({length3(v1), length3(v2), crossed ? length3(s.cross) : 0.0});
    const double scale = big > 0 ? 1.2 / big : 1.0;  // the longest arrow 1.2 long
    arrow(scene, v1, scale, "v1", Role::Subject);
    arrow(scene, v2, scale, "v2", Role::Entering);
    if (crossed) arrow(scene, s.cross, scale, "v1 × v2", Role::Active);
    if (s.phase > Phase::Product && max_abs(s.q) > 0)
        frame_of(scene, Slerp::to_matrix(unit_of(s.q)), "q1q2·", 1.0, 1.0f);
    if (s.phase > Phase::Reverse && max_abs(s.q2q1) > 0)
        frame_of(scene, Slerp::to_matrix(unit_of(s.q2q1)), "q2q1·", 0.8, 0.55f);
}

void draw_conjugate(const State& s, Scene& scene) {
    if (max_abs(s.in->q) == 0) {
        scene.labels3.push_back({{0, -0.4, 0}, "q = 0: no rotation", {Role::Discarded}});
        return;
    }
    const dquat u = unit_of(s.in->q);
    axis_and_turn(scene, u, 1.4, "axis of q");
    frame_of(scene, Slerp::to_matrix(u), "q·", 1.0, 0.9f);
    if (s.phase > Phase::Conjugate || s.phase == Phase::Done)
        frame_of(scene, Slerp::to_matrix(Slerp::conjugate(u)),
                 s.in->op == Op::Inverse ? "q⁻¹·" : "conj(q)·", 0.8, 0.6f);
}

void draw_rotate(const State& s, Scene& scene, double reach) {
    const dquat u = unit_of(s.in->q);
    const dvec3 p = s.in->point;
    const auto axis = Quaternion::axis_of(u);
    if (axis) {
        scene.segments3.push_back({-reach * *axis, reach * *axis, "", kAxisStyle, true});
        scene.labels3.push_back({reach * *axis, "rotation axis", {Role::Active}});
    }
    scene.points3.push_back({p, "P", {Role::Subject}});
    if (s.phase > Phase::TimesConjugate || s.phase == Phase::Done) {
        const dvec3 image = vpart(s.qpq);
        scene.points3.push_back({image, "P′", {Role::Kept}});
        if (axis) {
            const dvec3 centre = glm::dot(p, *axis) * *axis, off = p - centre;
            const double r = length3(off);
            if (r > 1e-12 * std::max(1.0, length3(p))) {
                rot::draw_arc(scene, centre, *axis, off / r, r, 0, Quaternion::angle_deg_of(u),
                              {Role::Leaving, 2.0f}, true,
                              "θ = " + num(Quaternion::angle_deg_of(u), 4) + "°");
                scene.segments3.push_back({centre, p, "", kConstruction, false});
                scene.segments3.push_back({centre, image, "", kConstruction, false});
            }
        }
    }
}

}  // namespace

// The world axes; then, by operation: the vector parts v1, v2 and v1 × v2 with the frames of
// q1 q2 and q2 q1 as rotations (different frames: no commuting); q's axis, turn and frame
// beside its conjugate's (the turn undone); the axis, P and its image P′ on the arc of the turn;
// the axis, θ and the frame of the quaternion built; the frame of M (its columns); R's frame
// and the axis and angle read from it.
void Quaternion::draw(const State& s, Scene& scene) {
    // The camera frames the unit ball the frames and axes live in (the axis reaches 1.4; the
    // camera keeps a box's corners in view, so a box of half side 0.85 frames a ball of radius
    // 1.5), or the point and its image.
    add_focus(scene, dvec3(-0.85), dvec3(0.85));
    world_frame(scene);
    const bool first = s.phase == Quaternion::first_phase(s.in->op);
    switch (s.in->op) {
        case Op::Multiply:
            draw_multiply(s, scene);
            return;
        case Op::Conjugate:
        case Op::Inverse:
            draw_conjugate(s, scene);
            return;
        case Op::Rotate: {
            const double reach = std::max(1.4, 1.15 * length3(s.in->point));
            const double half = std::max(1.0, 0.8 * length3(s.in->point));
            scene.focus3 = {{dvec3(-half), dvec3(half)}};
            draw_rotate(s, scene, reach);
            return;
        }
        case Op::FromAxisAngle: {
            const dvec3 a = first ? unit_of(s.in->axis) : s.axis_unit;
            scene.segments3.push_back({{0, 0, 0}, 1.4 * a, "", kAxisStyle, true});
            scene.labels3.push_back({1.4 * a, "a = " + vtext(s.in->axis), {Role::Active}});
            if (s.phase > Phase::UnitAxis || s.phase == Phase::Done) {
                const dvec3 start = rot::perpendicular(a);
                rot::draw_arc(scene, 0.8 * a, a, start, 0.45, 0, std::fmod(s.in->angle_deg, 360.0),
                              {Role::Leaving, 2.0f}, true, "θ = " + num(s.in->angle_deg, 4) + "°");
            }
            if (s.phase == Phase::Done) frame_of(scene, Slerp::to_matrix(s.q), "q·", 1.0, 1.0f);
            return;
        }
        case Op::ToMatrix: {
            const dquat u = first ? unit_of(s.in->q) : s.unit;
            axis_and_turn(scene, u, 1.4, "axis of q");
            if (s.phase == Phase::Done) frame_of(scene, s.matrix, "M", 1.0, 1.0f);
            return;
        }
        case Op::FromMatrix:
            frame_of(scene, s.in->matrix, "R", 1.0, 1.0f);
            if (s.phase > Phase::Extract || s.phase == Phase::Done)
                axis_and_turn(scene, s.q, 1.4, "axis of q");
            return;
    }
}

}  // namespace cg
