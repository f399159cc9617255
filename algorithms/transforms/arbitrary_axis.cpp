// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and rotate] [draw]
#include "transforms/arbitrary_axis.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dvec3;
using Phase = ArbitraryAxis::Phase;
using rot::axis_name;
using rot::CosSin;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineChoose = 1,
    kLineToPlane,
    kLineToAxis,
    kLineRotate,
    kLineUndoAxis,
    kLineUndoPlane,
    kLineCompose,
    kLinePoint,
};

// The construction's numbers, shared by the state machine and the straight-line function so
// that both compute exactly the same thing.
struct Frame {
    int i, j, k;
    double scale;  // max |a_i|: the axis is scaled by 1/scale so that nothing over- or underflows
    dvec3 as;      // a / scale
};

Frame choose(dvec3 a) {
    const dvec3 m = glm::abs(a);
    const int i = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    const double scale = m[i];
    return {i, (i + 1) % 3, (i + 2) % 3, scale, a / scale};
}

// φ: R_j(−φ) zeroes the k component. cos φ = a_i / r, sin φ = −a_k / r, r = √(a_i² + a_k²).
CosSin phi_of(const Frame& f) {
    const double r = std::hypot(f.as[f.i], f.as[f.k]);
    return {f.as[f.i] / r, -f.as[f.k] / r + 0.0};  // + 0.0: no −0
}
double phi_deg_of(const Frame& f) {
    return rot::deg(std::atan2(-f.as[f.k] + 0.0, f.as[f.i]));
}

// γ: the angle of c = (r, a_j, 0) with axis i; cos γ = r / |a|, sin γ = a_j / |a|.
CosSin gamma_of(const Frame& f) {
    const double r = std::hypot(f.as[f.i], f.as[f.k]), n = std::hypot(r, f.as[f.j]);
    return {r / n, f.as[f.j] / n};
}
double gamma_deg_of(const Frame& f) {
    return rot::deg(std::atan2(f.as[f.j], std::hypot(f.as[f.i], f.as[f.k])));
}

std::string comp(int axis) {
    return std::string("a_") + axis_name(axis);
}
std::string plane_name(int a, int b) {
    return std::string(1, axis_name(std::min(a, b))) + axis_name(std::max(a, b));
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ArbitraryAxis::spec() {
    static const Spec spec{
        "arbitrary-axis",
        "Rotation about an arbitrary axis",
        "Rotations About Arbitrary Axis",
        {
            "i ← the coordinate axis closest to a (largest |a_i|);  j, k ← the next two "
            "(x: y, z;  y: z, x;  z: x, y)",
            "φ ← atan2(−a_k, a_i);  c ← R_j(−φ) a           ▷ a turned into the i–j plane",
            "γ ← atan2(a_j, √(a_i² + a_k²));  R_k(−γ) c = |a| e_i   ▷ … and onto axis i",
            "rotate by θ about axis i:  R_i(θ)",
            "undo the second turn:  R_k(γ)",
            "undo the first turn:  R_j(φ)",
            "R ← R_j(φ) R_k(γ) R_i(θ) R_k(−γ) R_j(−φ)",
            "for each point P:  P′ ← R P",
        },
        {
            {"choose-axis", "the coordinate axis closest to a is chosen to carry the rotation"},
            {"to-plane", "a is turned about the second axis into a coordinate plane (angle φ)"},
            {"already-in-plane", "a already lies in that plane, a_i > 0: φ = 0 and the first turn is I"},
            {"to-axis", "a is turned about the third axis onto the chosen axis (angle γ)"},
            {"already-on-axis", "a already points along the chosen axis: γ = 0, this turn is I"},
            {"rotate", "the rotation by θ about the chosen coordinate axis"},
            {"undo-axis", "the second turn undone: R_k(γ)"},
            {"undo-plane", "the first turn undone: R_j(φ)"},
            {"compose", "the five matrices multiplied: the rotation about a in one matrix"},
            {"rotate-point", "one point rotated by R"},
        },
        {},  // no sliders
        {
            .predict = {
                {"to-plane", {"phi_deg"}},
                {"to-axis", {"gamma_deg"}},
                {"rotate-point", {"P'"}},
            },
            .mistakes = {
                {"to-axis", "R_z(-gamma)", "transpose",
                 "rotated by +gamma: c turned away from the axis"},
                {"rotate", "R_x(theta)", "transpose", "rotated by -theta: the sine signs swapped"},
                {"undo-axis", "R_z(gamma)", "transpose",
                 "undid with R_z(-gamma) again, not its inverse"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void ArbitraryAxis::validate(const Input& in) {
    for (int c = 0; c < 3; ++c) check_finite(in.axis[c], "axis[" + std::to_string(c) + "]");
    if (in.axis == dvec3(0))
        throw InputError("axis",
                         "must not be the zero vector (0, 0, 0): a rotation axis needs a "
                         "direction");
    const Frame f = choose(in.axis);
    if (!std::isfinite(f.scale * glm::length(f.as)))
        throw InputError("axis", "is too long: its length " + given(in.axis) +
                                     " overflows a double; scale it down (only its direction "
                                     "matters)");
    check_finite(in.angle_deg, "angle_deg");
    for (std::size_t p = 0; p < in.points.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            const std::string f = "points[" + std::to_string(p) + "][" + std::to_string(c) + "]";
            check_finite(in.points[p][c], f);
            // The picture sizes itself by |p|, whose square overflows past about 1e154.
            if (std::fabs(in.points[p][c]) > 1e100)
                throw InputError(f, "must be within ±1e100 (got " + given(in.points[p][c]) + ")");
        }
}

ArbitraryAxis::State ArbitraryAxis::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

ArbitraryAxis::State ArbitraryAxis::begin(Shared<Input> in) {
    State s;
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void ArbitraryAxis::advance(State& s) {
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Choose: {  // Pick the closest coordinate axis
            const Frame f = choose(s.in->axis);
            s.i = f.i, s.j = f.j, s.k = f.k;
            s.scale = f.scale;
            s.as = f.as;
            s.phase = Phase::ToPlane;
            return;
        }
        case Phase::ToPlane: {  // Turn a into the i–j plane
            const Frame f{s.i, s.j, s.k, s.scale, s.as};
            s.phi = phi_of(f);
            s.phi_deg = phi_deg_of(f);
            s.to_plane = rot::rotation(s.j, rot::inverse(s.phi));
            s.phase = Phase::ToAxis;
            return;
        }
        case Phase::ToAxis: {  // ... and onto axis i
            const Frame f{s.i, s.j, s.k, s.scale, s.as};
            s.gamma = gamma_of(f);
            s.gamma_deg = gamma_deg_of(f);
            s.to_axis = rot::rotation(s.k, rot::inverse(s.gamma));
            s.phase = Phase::Rotate;
            return;
        }
        case Phase::Rotate:  // Rotate by θ about axis i
            s.theta = rot::cos_sin_deg(s.in->angle_deg);
            s.spin = rot::rotation(s.i, s.theta);
            s.phase = Phase::UndoAxis;
            return;
        case Phase::UndoAxis:  // Undo the turn onto the axis
            s.undo_axis = rot::rotation(s.k, s.gamma);
            s.phase = Phase::UndoPlane;
            return;
        case Phase::UndoPlane:  // Undo the turn into the plane
            s.undo_plane = rot::rotation(s.j, s.phi);
            s.phase = Phase::Compose;
            return;
        case Phase::Compose:  // The product, as the course writes it
            s.R = s.undo_plane * s.undo_axis * s.spin * s.to_axis * s.to_plane;
            s.rotated.reserve(s.in->points.size());
            s.phase = s.in->points.empty() ? Phase::Done : Phase::Points;
            return;
        case Phase::Points:  // Rotate one point
            ++s.p;
            s.rotated.push_back(s.R * s.in->points[s.p]);
            if (s.p + 1 == static_cast<int>(s.in->points.size())) s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

double ArbitraryAxis::length(const State& s) {
    return s.scale * glm::length(s.as);
}
dvec3 ArbitraryAxis::unit(const State& s) {
    return s.as / glm::length(s.as);
}

dmat3 ArbitraryAxis::applied(const State& s) {
    if (s.phase == Phase::Choose) return dmat3(1.0);
    switch (s.last) {
        case Phase::Choose:
            return dmat3(1.0);
        case Phase::ToPlane:
            return s.to_plane;
        case Phase::ToAxis:
            return s.to_axis * s.to_plane;
        case Phase::Rotate:
            return s.spin * s.to_axis * s.to_plane;
        case Phase::UndoAxis:
            return s.undo_axis * s.spin * s.to_axis * s.to_plane;
        case Phase::UndoPlane:
            return s.undo_plane * s.undo_axis * s.spin * s.to_axis * s.to_plane;
        default:
            return s.R;
    }
}

namespace {

using State = ArbitraryAxis::State;

dvec3 c_of(const State& s) {
    return s.to_plane * s.in->axis;
}  // R_j(−φ) a
dvec3 d_of(const State& s) {
    return s.to_axis * (s.to_plane * s.in->axis);
}  // |a| e_i

std::string deg_text(double d) {
    return num(d, 6) + "°";
}

void narrate_choose(const State& s, StepInfo& info) {
    const dvec3 a = s.in->axis;
    const char I = axis_name(s.i), J = axis_name(s.j), K = axis_name(s.k);
    int zeros = 0;
    for (int c = 0; c < 3; ++c) zeros += a[c] == 0;
    const dvec3 m = glm::abs(a);
    const bool tie = (s.i < s.j && m[s.j] == m[s.i]) || (s.i < s.k && m[s.k] == m[s.i]);
    std::string t = "a = " + num(a) + ", |a| = " + num(ArbitraryAxis::length(s), 6);
    t += std::fabs(ArbitraryAxis::length(s) - 1) <= 1e-12
             ? " (a unit vector)"
             : " (not unit length, which does not matter: the construction uses only ratios of "
               "a's components, so a and a/|a| = " +
                   num(ArbitraryAxis::unit(s), 4) + " give the same matrix)";
    t += ". The largest component is |" + comp(s.i) + "| = " + num(m[s.i]) +
         (tie ? " (a tie, which goes to the earlier axis)" : "") + ", so a is closest to the " + I +
         " axis: turn it about " + J + " into the " + plane_name(s.i, s.j) + " plane, then about " +
         K + " onto " + I + ", rotate about " + I + " and turn back: R = R_" + J + "(φ) R_" + K +
         "(γ) R_" + I + "(θ) R_" + K + "(−γ) R_" + J + "(−φ).";
    if (zeros == 2)
        t += std::string(" a already lies on the ") + I + " axis" +
             (a[s.i] < 0 ? " but points the negative way, so the first turn is a half turn."
                         : ", so both turns will be the identity.");
    else if (zeros == 1)
        t += " a lies in a coordinate plane, so one of the two turns may be the identity.";
    info.event = "choose-axis";
    info.line = kLineChoose;
    info.narration = t;
    info.math = "a = " + tex(a) + ",\\; |a| = " + tex(ArbitraryAxis::length(s), 6) +
                ",\\; i = " + I + ":\\; R(\\theta, a) = R_" + J + "(\\phi)\\, R_" + K +
                "(\\gamma)\\, R_" + I + "(\\theta)\\, R_" + K + "(-\\gamma)\\, R_" + J + "(-\\phi)";
}

void narrate_to_plane(const State& s, StepInfo& info) {
    const dvec3 a = s.in->axis;
    const char J = axis_name(s.j);
    const std::string ai = comp(s.i), ak = comp(s.k), plane = plane_name(s.i, s.j);
    const double r = std::hypot(a[s.i], a[s.k]);
    const std::string M = rot::matrix_text(s.to_plane);
    if (s.phi_deg == 0) {
        info.event = "already-in-plane";
        info.narration = "a already lies in the " + plane + " plane (" + ak + " = 0, " + ai +
                         " > 0): φ = 0°, R_" + J + "(−φ) = I and c = a = " + num(c_of(s), 4) + ".";
    } else {
        info.event = "to-plane";
        info.narration = "Project a onto the " + plane_name(s.i, s.k) + " plane: b has " + ai +
                         " = " + num(a[s.i]) + " and " + ak + " = " + num(a[s.k]) +
                         ", length r = " + num(r, 4) + ". cos φ = " + ai +
                         "/r = " + num(s.phi.c, 4) + ", sin φ = −" + ak +
                         "/r = " + num(s.phi.s, 4) + ", so φ = " + deg_text(s.phi_deg) + ". R_" +
                         J + "(−φ) = " + M + " turns a about " + J + " into the " + plane +
                         " plane: c = R_" + J + "(−φ) a = " + num(c_of(s), 4) + ".";
    }
    info.line = kLineToPlane;
    info.math = "\\cos\\phi = \\frac{" + ai + "}{\\sqrt{" + ai + "^2 + " + ak +
                "^2}} = " + tex(s.phi.c, 4) + ",\\; \\sin\\phi = \\frac{-" + ak + "}{\\sqrt{" + ai +
                "^2 + " + ak + "^2}} = " + tex(rot::clean(s.phi.s), 4) +
                ",\\; \\phi = " + tex(s.phi_deg, 6) + "^\\circ,\\; c = R_" + J +
                "(-\\phi)\\, a = " + rot::matrix_tex(s.to_plane, true) + rot::vector_tex(a) +
                " = " + rot::vector_tex(c_of(s));
}

void narrate_to_axis(const State& s, StepInfo& info) {
    const char I = axis_name(s.i), K = axis_name(s.k);
    const std::string aj = comp(s.j), plane = plane_name(s.i, s.j);
    const std::string M = rot::matrix_text(s.to_axis);
    if (s.gamma_deg == 0) {
        info.event = "already-on-axis";
        info.narration = std::string("c = ") + num(c_of(s), 4) + " already lies on the " + I +
                         " axis (" + aj + " = 0): γ = 0°, R_" + K + "(−γ) = I.";
    } else {
        info.event = "to-axis";
        info.narration = "In the " + plane + " plane c = " + num(c_of(s), 4) +
                         " makes the angle γ with the " + I +
                         " axis: cos γ = r/|a| = " + num(s.gamma.c, 4) + ", sin γ = " + aj +
                         "/|a| = " + num(s.gamma.s, 4) + ", γ = " + deg_text(s.gamma_deg) + ". R_" +
                         K + "(−γ) = " + M + " turns c about " + K + " onto the " + I +
                         " axis: R_" + K + "(−γ) c = " + num(d_of(s), 4) + " = |a| e_" + I + ".";
    }
    info.line = kLineToAxis;
    info.math = "\\cos\\gamma = \\frac{\\sqrt{a_" + std::string(1, I) + "^2 + a_" +
                std::string(1, axis_name(s.k)) + "^2}}{|a|} = " + tex(s.gamma.c, 4) +
                ",\\; \\sin\\gamma = \\frac{" + aj + "}{|a|} = " + tex(rot::clean(s.gamma.s), 4) +
                ",\\; \\gamma = " + tex(s.gamma_deg, 6) + "^\\circ,\\; R_" + K +
                "(-\\gamma)\\, c = " + rot::matrix_tex(s.to_axis, true) + rot::vector_tex(c_of(s)) +
                " = " + rot::vector_tex(d_of(s));
}

void narrate_rotate(const State& s, StepInfo& info) {
    const char I = axis_name(s.i);
    info.event = "rotate";
    info.line = kLineRotate;
    info.narration = std::string("The axis now is the ") + I +
                     " axis: rotate by θ = " + deg_text(s.in->angle_deg) +
                     " about it (cos θ = " + num(s.theta.c, 4) + ", sin θ = " + num(s.theta.s, 4) +
                     "): R_" + I + "(θ) = " + rot::matrix_text(s.spin) + ".";
    info.math = std::string("R_") + I + "(" + tex(s.in->angle_deg) +
                "^\\circ) = " + rot::matrix_tex(s.spin, true);
}

void narrate_undo(const State& s, StepInfo& info, bool axis) {
    const int about = axis ? s.k : s.j;
    const char A = axis_name(about);
    const char* angle = axis ? "γ" : "φ";
    const double value = axis ? s.gamma_deg : s.phi_deg;
    const dmat3& m = axis ? s.undo_axis : s.undo_plane;
    info.event = axis ? "undo-axis" : "undo-plane";
    info.line = axis ? kLineUndoAxis : kLineUndoPlane;
    info.narration = std::string("Undo the ") + (axis ? "second" : "first") + " turn: R_" + A +
                     "(" + angle + ") = " + rot::matrix_text(m) +
                     ", the inverse (the transpose) of R_" + A + "(−" + angle + "), " + angle +
                     " = " + deg_text(value) +
                     (axis ? ": the axis goes back into the " + plane_name(s.i, s.j) + " plane."
                           : ": the axis is back where it started, and everything else has turned "
                             "by θ about it.");
    info.math =
        std::string("R_") + A + (axis ? "(\\gamma)" : "(\\phi)") + " = " + rot::matrix_tex(m, true);
}

void narrate_compose(const State& s, StepInfo& info) {
    const char I = axis_name(s.i), J = axis_name(s.j), K = axis_name(s.k);
    const dvec3 Ra = s.R * ArbitraryAxis::unit(s);
    info.event = "compose";
    info.line = kLineCompose;
    info.narration = std::string("R = R_") + J + "(φ) R_" + K + "(γ) R_" + I + "(θ) R_" + K +
                     "(−γ) R_" + J + "(−φ) = " + rot::matrix_text(s.R) +
                     " (as a 4×4 homogeneous matrix, with 0 0 0 1 as the last row and column). "
                     "Check: R leaves the axis alone, R a/|a| = " +
                     num(Ra, 4) + ".";
    info.math = std::string("R = ") + "R_" + J + "(\\phi) R_" + K + "(\\gamma) R_" + I +
                "(\\theta) R_" + K + "(-\\gamma) R_" + J +
                "(-\\phi) = " + rot::matrix_tex(s.undo_plane) + rot::matrix_tex(s.undo_axis) +
                rot::matrix_tex(s.spin) + rot::matrix_tex(s.to_axis) + rot::matrix_tex(s.to_plane) +
                " = " + rot::matrix_tex(s.R, true);
}

void narrate_point(const State& s, StepInfo& info) {
    const dvec3 p = s.in->points[s.p], q = s.rotated[s.p];
    const std::string name = "P" + std::to_string(s.p);
    info.event = "rotate-point";
    info.line = kLinePoint;
    info.narration = name + " = " + num(p) + ": " + name + "′ = R " + name + " = " + num(q, 4) +
                     " (its distance from the axis, and from the origin, is unchanged: |" + name +
                     "| = " + num(glm::length(p), 4) + ", |" + name +
                     "′| = " + num(glm::length(q), 4) + ").";
    info.math = "R " + rot::vector_tex(p) + " = " + rot::vector_tex(q);
}

void fill_vars(const State& s, StepInfo& info) {
    const char I = axis_name(s.i), J = axis_name(s.j), K = axis_name(s.k);
    info.vars = {{"a", vec(s.in->axis)},
                 {"|a|", ArbitraryAxis::length(s)},
                 {"theta_deg", s.in->angle_deg},
                 {"canonical_axis", std::string(1, I)}};
    if (s.last >= Phase::ToPlane) {
        info.vars.push_back({"phi_deg", s.phi_deg});
        info.vars.push_back({std::string("R_") + J + "(-phi)", rot::rows4(s.to_plane)});
        info.vars.push_back({"c", vec(c_of(s))});
    }
    if (s.last >= Phase::ToAxis) {
        info.vars.push_back({"gamma_deg", s.gamma_deg});
        info.vars.push_back({std::string("R_") + K + "(-gamma)", rot::rows4(s.to_axis)});
    }
    if (s.last >= Phase::Rotate)
        info.vars.push_back({std::string("R_") + I + "(theta)", rot::rows4(s.spin)});
    if (s.last >= Phase::UndoAxis)
        info.vars.push_back({std::string("R_") + K + "(gamma)", rot::rows4(s.undo_axis)});
    if (s.last >= Phase::UndoPlane)
        info.vars.push_back({std::string("R_") + J + "(phi)", rot::rows4(s.undo_plane)});
    if (s.last >= Phase::Compose) info.vars.push_back({"R", rot::rows4(s.R)});
    if (s.last == Phase::Points) {
        info.vars.push_back({"k", static_cast<long long>(s.p)});
        info.vars.push_back({"P", vec(s.in->points[s.p])});
        info.vars.push_back({"P'", vec(s.rotated[s.p])});
    }
}

}  // namespace

void ArbitraryAxis::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Choose:
            narrate_choose(s, info);
            break;
        case Phase::ToPlane:
            narrate_to_plane(s, info);
            break;
        case Phase::ToAxis:
            narrate_to_axis(s, info);
            break;
        case Phase::Rotate:
            narrate_rotate(s, info);
            break;
        case Phase::UndoAxis:
            narrate_undo(s, info, true);
            break;
        case Phase::UndoPlane:
            narrate_undo(s, info, false);
            break;
        case Phase::Compose:
        case Phase::Done:
            narrate_compose(s, info);
            break;
        case Phase::Points:
            narrate_point(s, info);
            break;
    }
    fill_vars(s, info);
}

void ArbitraryAxis::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and rotate] --------------------------------------------------------------------

ArbitraryAxis::Result ArbitraryAxis::result(const State& s) {
    return {s.R, s.phi_deg, s.gamma_deg, s.i, s.rotated};
}

ArbitraryAxis::Result ArbitraryAxis::result(State&& s) {
    return {s.R, s.phi_deg, s.gamma_deg, s.i, std::move(s.rotated)};
}

[[gnu::flatten]] ArbitraryAxis::Result ArbitraryAxis::rotate(const Input& in) {
    const Frame f = choose(in.axis);
    const CosSin phi = phi_of(f), gamma = gamma_of(f);
    Result r;
    r.canonical = f.i;
    r.phi_deg = phi_deg_of(f);
    r.gamma_deg = gamma_deg_of(f);
    r.matrix = rot::rotation(f.j, phi) * rot::rotation(f.k, gamma) *
               rot::rotation(f.i, rot::cos_sin_deg(in.angle_deg)) *
               rot::rotation(f.k, rot::inverse(gamma)) * rot::rotation(f.j, rot::inverse(phi));
    r.points.reserve(in.points.size());
    for (const dvec3& p : in.points) r.points.push_back(r.matrix * p);
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

// The world frame, the axis a (where the turns so far have carried it, and faintly where it
// started), a house standing beside the axis (faintly where it started, solid where the
// matrices applied so far have taken it), the angle of the current step as an arc, and the
// input points with their images.
void ArbitraryAxis::draw(const State& s, Scene& scene) {
    const Frame f = choose(s.in->axis);
    const dvec3 unit = f.as / glm::length(f.as);
    const dmat3 so_far = applied(s);
    double reach = 2.0;
    for (const dvec3& p : s.in->points) reach = std::max(reach, 1.15 * glm::length(p));
    scene.frames3.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.3, "", 0.9f});

    const double L = 0.85 * reach;
    const dvec3 now = so_far * unit;
    const bool moved = so_far != dmat3(1.0);
    const Style axis_style{Role::Active, 3.0f};
    const Style construction{Role::Construction, 1.0f, true};
    scene.segments3.push_back({-L * now, L * now, "", axis_style, true});
    scene.labels3.push_back({L * now,
                             moved && s.phase != Phase::Done && s.last < Phase::Compose
                                 ? "a (turned)"
                                 : "a = " + num(s.in->axis, 4),
                             {Role::Active}});
    if (moved && glm::length(now - unit) > 1e-9) {  // the axis away from where it started
        scene.segments3.push_back({-L * unit, L * unit, "", construction, true});
        scene.labels3.push_back({L * unit, "a (start)", {Role::Construction}});
    }

    // The house stands 1 unit from the axis, facing away from it, its roof along a.
    rot::HousePlacement h;
    h.front = rot::perpendicular(unit);
    h.up = unit;
    h.right = glm::cross(h.up, h.front);
    h.centre = 1.0 * h.front;
    h.size = 0.55;
    if (moved) rot::draw_house(scene, h, dmat3(1.0), true);
    rot::draw_house(scene, h, so_far, false);
    // The camera frames what is drawn: the axis (both where it started and where it is now),
    // the house (both), the points and their images — not a sphere round the origin.
    dvec3 lo = -L * unit, hi = -L * unit;
    const auto frame = [&](dvec3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); };
    for (const dvec3 p : {L * unit, L * now, -L * now}) frame(p);
    for (const dvec3& p : rot::house_points(h)) frame(p), frame(so_far * p);
    for (const dvec3& p : s.in->points) frame(p);
    for (const dvec3& p : s.rotated) frame(p);
    add_focus(scene, lo, hi);

    const dvec3 ei(s.i == 0, s.i == 1, s.i == 2), ej(s.j == 0, s.j == 1, s.j == 2),
        ek(s.k == 0, s.k == 1, s.k == 2);
    const Style arc{Role::Leaving, 2.0f};
    const bool started = s.phase != Phase::Choose;
    if (started) switch (s.last) {
            case Phase::ToPlane: {  // b, the projection, and the turn by −φ about j
                const dvec3 tip = L * unit, b = tip - glm::dot(tip, ej) * ej;
                scene.segments3.push_back({tip, b, "", construction, false});
                scene.segments3.push_back({{0, 0, 0}, b, "b", construction, false});
                if (s.phi_deg != 0)
                    rot::draw_arc(scene, {0, 0, 0}, ej, ei, 0.7, s.phi_deg, 0, arc, true,
                                  "−φ = " + num(-s.phi_deg, 4) + "°");
                break;
            }
            case Phase::ToAxis:
                if (s.gamma_deg != 0)
                    rot::draw_arc(scene, {0, 0, 0}, ek, ei, 0.7, s.gamma_deg, 0, arc, true,
                                  "−γ = " + num(-s.gamma_deg, 4) + "°");
                break;
            case Phase::Rotate: {
                const dvec3 before = glm::transpose(s.spin) * (so_far * h.centre);
                const dvec3 on = glm::dot(before, ei) * ei, off = before - on;
                if (glm::length(off) > 0)
                    rot::draw_arc(scene, on, ei, off / glm::length(off), glm::length(off), 0,
                                  rot::wrap_deg(s.in->angle_deg), arc, true,
                                  "θ = " + num(s.in->angle_deg, 4) + "°");
                break;
            }
            case Phase::UndoAxis:
                if (s.gamma_deg != 0)
                    rot::draw_arc(scene, {0, 0, 0}, ek, ei, 0.7, 0, s.gamma_deg, arc, true,
                                  "γ = " + num(s.gamma_deg, 4) + "°");
                break;
            case Phase::UndoPlane:
                if (s.phi_deg != 0)
                    rot::draw_arc(scene, {0, 0, 0}, ej, ei, 0.7, 0, s.phi_deg, arc, true,
                                  "φ = " + num(s.phi_deg, 4) + "°");
                break;
            case Phase::Compose:
            case Phase::Points:
            case Phase::Done: {
                const dvec3 on = glm::dot(h.centre, unit) * unit, off = h.centre - on;
                rot::draw_arc(scene, on, unit, off / glm::length(off), glm::length(off), 0,
                              rot::wrap_deg(s.in->angle_deg), arc, true,
                              "θ = " + num(s.in->angle_deg, 4) + "° about a");
                break;
            }
            case Phase::Choose:
                break;
        }

    for (int p = 0; p < static_cast<int>(s.in->points.size()); ++p) {
        const std::string name = "P" + std::to_string(p);
        const bool now_p = s.last == Phase::Points && p == s.p;
        scene.points3.push_back({s.in->points[p], name, {now_p ? Role::Active : Role::Subject}});
        if (p < static_cast<int>(s.rotated.size())) {
            scene.points3.push_back(
                {s.rotated[p], name + "′", {now_p ? Role::Active : Role::Kept}});
            const dvec3 on = glm::dot(s.in->points[p], unit) * unit, off = s.in->points[p] - on;
            if (glm::length(off) > 1e-12)
                rot::draw_arc(scene, on, unit, off / glm::length(off), glm::length(off), 0,
                              rot::wrap_deg(s.in->angle_deg),
                              {now_p ? Role::Active : Role::Construction, 1.0f, !now_p}, true, "");
        }
    }
}

}  // namespace cg
