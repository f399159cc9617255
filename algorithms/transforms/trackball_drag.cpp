// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and drag]; the picture is in
// trackball_drag_draw.cpp
#include "transforms/trackball_drag.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dquat;
using glm::dvec2;
using glm::dvec3;
using trackball::BallPoint;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180 / kPi;

// ---- [helpers] ------------------------------------------------------------------------------

// Pseudocode, 1-based lines as the steps report them.
enum Line { kLinePair = 1, kLineMapS, kLineMapT, kLineRotate, kLineAccumulate, kLineSummary };

// A summary's angle below this (degrees) counts as "the same rotation": round-off in a product
// of a few hundred unit quaternions stays near 1e-12°.
constexpr double kSameDeg = 1e-6;

// −0 + 0 = +0: no "-0" in results and narration.
double unsigned_zero(double x) { return x + 0.0; }

dquat canonical(dquat q) {
    if (q.w < 0) q = -q;
    return {unsigned_zero(q.w), unsigned_zero(q.x), unsigned_zero(q.y), unsigned_zero(q.z)};
}

std::vector<double> quat_vec(const dquat& q) { return {q.w, q.x, q.y, q.z}; }

std::string quat_text(const dquat& q, int digits = 4) {
    return "[" + num(q.w, digits) + ", " + num(q.x, digits) + ", " + num(q.y, digits) + ", " +
           num(q.z, digits) + "]";
}

std::string quat_tex(const dquat& q, int digits = 4) {
    return "(" + tex(q.w, digits) + ", " + tex(dvec3(q.x, q.y, q.z), digits) + ")";
}

std::vector<std::vector<double>> rows(const dmat3& m) {
    return {{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}};
}

std::string matrix_tex(const dmat3& m) {
    std::string t = "\\begin{bmatrix} ";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) t += (c ? " & " : "") + tex(m[c][r], 4);
        t += r < 2 ? " \\\\ " : " \\end{bmatrix}";
    }
    return t;
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

std::string sample_name(int k) { return "S" + std::to_string(k); }

template <TrackballKind K>
dquat pair_rotation(const BallPoint& s, const BallPoint& t) {
    if constexpr (K == TrackballKind::Arcball)
        return trackball::arcball(s, t);
    else
        return trackball::virtual_sphere(s, t);
}

template <TrackballKind K>
bool pair_rim(const BallPoint& s, const BallPoint& t) {
    return K == TrackballKind::Arcball ? s.rim || t.rim : s.rim;
}

}  // namespace

AxisAngle axis_angle(const dquat& q) {
    const dvec3 v(q.x, q.y, q.z);
    const double len = glm::length(v);
    if (len == 0) return {};
    const dvec3 axis = v / len + dvec3(0.0);  // −0 + 0 = +0
    return {axis, 2 * std::atan2(len, q.w) * kDeg};
}

double rotation_angle_deg(const dquat& q) {
    return 2 * std::atan2(glm::length(dvec3(q.x, q.y, q.z)), std::fabs(q.w)) * kDeg;
}

// ---- [spec] ---------------------------------------------------------------------------------

template <TrackballKind K>
const Spec& TrackballDrag<K>::spec() {
    static const Spec spec = [] {
        Spec s;
        s.topic = "3D Rotation User Interfaces";
        s.pseudocode = {
            "for each pair of successive mouse samples S → T:",
            "  s ← S on the ball: m = 2(S − c)/d; (m, √(1 − |m|²)), or (m/|m|, 0) outside",
            kArcball ? "  t ← T on the ball, the same way"
                     : "  v ← (T − S, 0)·2/d: the mouse's motion, a tangential velocity at s",
            kArcball ? "  q ← (s · t, s × t): turn about s × t by twice the angle from s to t"
                     : "  q ← turn about s × v by |v| radians  (S outside: about z by ∠(S, T))",
            "  q_total ← q · q_total                       ▷ the newest turn acts last",
            kArcball ? "compare q_total with q from the first sample straight to the last"
                     : "compare q_total with one step from the first sample straight to the last",
        };
        s.events = {
            {"sample-on-sphere", "S lies inside the ball: lifted onto the sphere's front"},
            {"sample-outside", kArcball ? "S lies outside the ball: pulled onto its rim"
                                        : "S lies outside the ball: the turn will be about z"},
        };
        if constexpr (kArcball) {
            s.id = "arcball";
            s.title = "Arcball (Shoemake)";
            s.events.push_back({"target-on-sphere", "T lies inside the ball: lifted onto the sphere"});
            s.events.push_back({"target-outside", "T lies outside the ball: pulled onto its rim"});
        } else {
            s.id = "virtual-sphere";
            s.title = "Virtual sphere (Chen)";
            s.events.push_back({"velocity", "the mouse motion T − S, a tangent at s"});
            s.events.push_back({"rim-rotation", "S outside the ball: a turn about the view axis z"});
        }
        s.events.push_back({"pair-rotation", "this pair's axis, angle and quaternion"});
        s.events.push_back({"no-rotation", "this pair does not turn the ball"});
        s.events.push_back({"accumulate", "the pair's turn composed onto the drag's rotation"});
        s.events.push_back(
            {"path-independent", "the drag's rotation equals the one straight from first to last"});
        s.events.push_back({"loop-returns", "a closed mouse loop leaves the ball where it started"});
        if constexpr (!kArcball) {
            s.events.push_back(
                {"path-dependent", "the drag's rotation differs from one step first to last"});
            s.events.push_back({"loop-drifts", "a closed mouse loop leaves the ball turned"});
        }
        if constexpr (kArcball) {
            s.study = {
                .predict = {
                    {"sample-on-sphere", {"s"}},
                    {"target-on-sphere", {"t"}},
                    {"pair-rotation", {"axis", "angle_deg"}},
                    {"accumulate", {"q_total"}},
                },
                .mistakes = {
                    {"pair-rotation", "axis", "negate",
                     "crossed t × s: the axis points the other way"},
                    {"accumulate", "q_total", "keep",
                     "forgot to compose this pair's turn into q_total"},
                    {"target-on-sphere", "", "event:target-outside",
                     "pulled T onto the rim though it lies inside the ball"},
                },
            };
        } else {
            s.study = {
                .predict = {
                    {"sample-on-sphere", {"s"}},
                    {"velocity", {"v"}},
                    {"pair-rotation", {"axis", "angle_deg"}},
                    {"accumulate", {"q_total"}},
                },
                .mistakes = {
                    {"velocity", "v", "negate", "took the motion as S − T"},
                    {"pair-rotation", "axis", "negate",
                     "crossed v × s: the axis points the other way"},
                    {"accumulate", "q_total", "keep",
                     "forgot to compose this pair's turn into q_total"},
                },
            };
        }
        return s;
    }();
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

template <TrackballKind K>
void TrackballDrag<K>::validate(const Input& in) {
    check_finite(in.viewport.x, "viewport[0]");
    check_finite(in.viewport.y, "viewport[1]");
    if (in.viewport.x <= 0)
        throw InputError("viewport[0]", "the width must be positive (got " + given(in.viewport.x) + ")");
    if (in.viewport.y <= 0)
        throw InputError("viewport[1]",
                         "the height must be positive (got " + given(in.viewport.y) + ")");
    if (in.viewport.x < 1e-100 || in.viewport.x > 1e100 || in.viewport.y < 1e-100 ||
        in.viewport.y > 1e100)
        throw InputError(in.viewport.x < 1e-100 || in.viewport.x > 1e100 ? "viewport[0]" : "viewport[1]",
                         "must lie between 1e-100 and 1e100 pixels (got " + given(in.viewport) + ")");
    if (in.samples.size() < 2)
        throw InputError("samples", "needs at least 2 mouse samples to make a drag (got " +
                                        std::to_string(in.samples.size()) + ")");
    for (std::size_t k = 0; k < in.samples.size(); ++k) {
        const std::string f = "samples[" + std::to_string(k) + "]";
        check_finite(in.samples[k].x, f + "[0]");
        check_finite(in.samples[k].y, f + "[1]");
        // Ball units must stay finite, |m|² included (1e300 pixels from a 1e-300 wide viewport).
        const BallPoint b = trackball::to_ball(in.samples[k], in.viewport);
        if (!std::isfinite(glm::dot(b.m, b.m)) || !std::isfinite(b.p.x) || !std::isfinite(b.p.y))
            throw InputError(f, "is too far from the viewport to map onto the ball (" +
                                    given(in.samples[k]) + " in a " + given(in.viewport.x) + " × " +
                                    given(in.viewport.y) + " viewport)");
    }
    for (std::size_t k = 0; k < in.object.size(); ++k) {
        const std::string f = "object[" + std::to_string(k) + "]";
        check_finite(in.object[k].x, f + "[0]");
        check_finite(in.object[k].y, f + "[1]");
        check_finite(in.object[k].z, f + "[2]");
        if (std::fabs(in.object[k].x) > 1e150 || std::fabs(in.object[k].y) > 1e150 ||
            std::fabs(in.object[k].z) > 1e150)
            throw InputError(f, "is too large to rotate (" + given(in.object[k]) + ")");
    }
}

template <TrackballKind K>
typename TrackballDrag<K>::State TrackballDrag<K>::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    s.pairs.reserve(in.samples.size() - 1);
    s.front.reserve(in.samples.size());
    s.front.push_back({0, 0, 1});
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

template <TrackballKind K>
void TrackballDrag<K>::advance(State& s) {
    s.last = s.phase;
    const int pairs = static_cast<int>(s.in.samples.size()) - 1;
    switch (s.phase) {
        case Phase::MapS:  // Map S onto the ball
            s.s = trackball::to_ball(s.in.samples[s.k], s.in.viewport);
            s.phase = Phase::MapT;
            return;
        case Phase::MapT:  // Map T onto the ball (arcball) or take T − S (virtual sphere)
            s.t = trackball::to_ball(s.in.samples[s.k + 1], s.in.viewport);
            s.velocity = dvec3(s.t.m - s.s.m, 0.0);
            s.phase = Phase::Rotate;
            return;
        case Phase::Rotate: {  // The pair's rotation
            s.q_pair = pair_rotation<K>(s.s, s.t);
            const AxisAngle aa = axis_angle(s.q_pair);
            s.pairs.push_back({aa.axis, aa.angle_deg, pair_rim<K>(s.s, s.t)});
            s.phase = Phase::Accumulate;
            return;
        }
        case Phase::Accumulate:  // Compose onto the drag's rotation
            s.q_total = glm::normalize(s.q_pair * s.q_total);
            s.front.push_back(s.q_total * dvec3(0, 0, 1));
            ++s.k;
            s.phase = s.k < pairs ? Phase::MapS : Phase::Summary;
            return;
        case Phase::Summary: {  // Compare with the pair from the first sample to the last
            const BallPoint a = trackball::to_ball(s.in.samples.front(), s.in.viewport);
            const BallPoint b = trackball::to_ball(s.in.samples.back(), s.in.viewport);
            s.direct = pair_rotation<K>(a, b);
            s.path_gap_deg = rotation_angle_deg(s.q_total * glm::conjugate(s.direct));
            s.net_angle_deg = rotation_angle_deg(s.q_total);
            s.phase = Phase::Done;
            return;
        }
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

template <TrackballKind K>
void narrate_map(const typename TrackballDrag<K>::State& st, StepInfo& info, bool target) {
    constexpr bool arcball = K == TrackballKind::Arcball;
    const BallPoint& b = target ? st.t : st.s;
    const int index = st.k + (target ? 1 : 0);
    const dvec2 px = st.in.samples[index];
    const dvec2 c = st.in.viewport * 0.5;
    const double d = std::min(st.in.viewport.x, st.in.viewport.y);
    const double r2 = glm::dot(b.m, b.m);
    const std::string name = target ? "T" : "S", lower = target ? "t" : "s";
    std::string text = name + " = " + sample_name(index) + " = " + num(px) +
                       " px: relative to the ball (centre " + num(c) + ", diameter " + num(d) +
                       ") m = 2(" + name + " − c)/d = " + num(b.m, 4) + ", |m|² = " + num(r2, 4);
    if (b.rim) {
        info.event = target ? "target-outside" : "sample-outside";
        text += " > 1: outside the ball, pulled onto its rim, " + lower + " = m/|m| = " +
                num(b.p, 4) + ".";
        if (!arcball) text += " The virtual sphere turns about the view axis z for this pair.";
        info.math = lower + " = \\left(\\frac{m}{|m|}, 0\\right) = " + tex(b.p, 4);
    } else {
        info.event = target ? "target-on-sphere" : "sample-on-sphere";
        text += " ≤ 1: inside the ball, lifted onto the sphere, " + lower + " = (m, √(1 − " +
                num(r2, 4) + ")) = " + num(b.p, 4) + ".";
        info.math = lower + " = \\left(m, \\sqrt{1 - |m|^2}\\right) = \\left(" + tex(b.m, 4) +
                    ", \\sqrt{1 - " + tex(r2, 4) + "}\\right) = " + tex(b.p, 4);
    }
    info.line = target ? kLineMapT : kLineMapS;
    info.narration = std::move(text);
}

template <TrackballKind K>
void narrate_velocity(const typename TrackballDrag<K>::State& st, StepInfo& info) {
    const dvec2 v = st.t.m - st.s.m;
    info.event = "velocity";
    info.line = kLineMapT;
    info.narration = "T = " + sample_name(st.k + 1) + " = " + num(st.in.samples[st.k + 1]) +
                     " px, at m_T = " + num(st.t.m, 4) +
                     " in ball units: the mouse moved by v = m_T − m_S = " + num(v, 4) +
                     ", |v| = " + num(glm::length(v), 4) +
                     " ball radii — a velocity along the sphere at s, not a second point on it.";
    info.math = "v = m_T - m_S = " + tex(v, 4) + ",\\ |v| = " + tex(glm::length(v), 4);
}

template <TrackballKind K>
void narrate_rotate(const typename TrackballDrag<K>::State& st, StepInfo& info) {
    constexpr bool arcball = K == TrackballKind::Arcball;
    const auto& pair = st.pairs.back();
    const dquat& q = st.q_pair;
    info.line = kLineRotate;
    const std::string turn = "q = " + quat_text(q) + ", a turn of " + num(pair.angle_deg, 4) +
                             "° about " + num(pair.axis, 4);
    if (pair.angle_deg == 0) {
        info.event = "no-rotation";
        info.narration = arcball ? (glm::dot(st.s.p, st.t.p) < 0
                                        ? "t = −s (opposite points of the rim): twice 180° is "
                                          "a full turn, q = " + quat_text(q) +
                                              ", the identity rotation."
                                        : "s = t: the mouse did not move on the ball, q = [1, "
                                          "0, 0, 0].")
                                 : (glm::length(st.velocity) == 0
                                        ? "T = S: the mouse did not move, q = [1, 0, 0, 0]."
                                        : "s × v = 0: the motion points straight along s, which "
                                          "gives no turn, q = [1, 0, 0, 0].");
        info.math = "q = (1, \\mathbf{0})";
        return;
    }
    info.event = "pair-rotation";
    if constexpr (arcball) {
        const double dot = glm::dot(st.s.p, st.t.p);
        const double half = std::atan2(glm::length(glm::cross(st.s.p, st.t.p)), dot) * kDeg;
        info.narration = "s · t = " + num(dot, 4) + " (the angle from s to t is " + num(half, 4) +
                         "°) and s × t = " + num(glm::cross(st.s.p, st.t.p), 4) + ": " + turn +
                         ", twice the angle, so that s itself would move past t by as much again.";
        info.math = "q = (s \\cdot t,\\ s \\times t) = " + quat_tex(q) + " = \\left(\\cos\\frac{" +
                    tex(pair.angle_deg, 4) + "^\\circ}{2},\\ \\sin\\frac{" +
                    tex(pair.angle_deg, 4) + "^\\circ}{2}\\," + tex(pair.axis, 4) + "\\right)";
    } else if (st.s.rim) {
        info.event = "rim-rotation";
        const double signed_deg =
            std::atan2(st.s.m.x * st.t.m.y - st.s.m.y * st.t.m.x, glm::dot(st.s.m, st.t.m)) * kDeg;
        info.narration = "S is outside the ball, so the ball spins about the view axis z by the "
                         "angle S and T make at the centre, " +
                         num(signed_deg, 4) + "°: " + turn + ".";
        info.math = "\\theta = \\operatorname{atan2}(m_S \\times m_T,\\ m_S \\cdot m_T) = " +
                    tex(signed_deg, 4) + "^\\circ,\\ q = " + quat_tex(q);
    } else {
        const dvec3 axis = glm::cross(st.s.p, st.velocity);
        const double len = glm::length(st.velocity);
        info.narration = "axis s × v = " + num(axis, 4) + ", angle |v| = " + num(len, 4) +
                         " rad = " + num(len * kDeg, 4) + "°: " + turn + ".";
        info.math = "q = \\left(\\cos\\frac{|v|}{2},\\ \\sin\\frac{|v|}{2}\\,\\frac{s \\times "
                    "v}{|s \\times v|}\\right) = " +
                    quat_tex(q);
    }
}

template <TrackballKind K>
void narrate_accumulate(const typename TrackballDrag<K>::State& st, StepInfo& info) {
    const AxisAngle total = axis_angle(canonical(st.q_total));
    info.event = "accumulate";
    info.line = kLineAccumulate;
    info.narration = "q_total = q · q_total = " + quat_text(canonical(st.q_total)) +
                     ": after " + std::to_string(st.k) + " pair" + (st.k == 1 ? "" : "s") +
                     " the ball has turned " + num(total.angle_deg, 4) + "° about " +
                     num(total.axis, 4) + "; its front point (0, 0, 1) is now at " +
                     num(st.front.back(), 4) + ".";
    info.math = "q_{total} \\leftarrow q\\, q_{total} = " + quat_tex(canonical(st.q_total)) +
                ",\\ R = " + matrix_tex(glm::mat3_cast(st.q_total));
}

template <TrackballKind K>
void narrate_summary(const typename TrackballDrag<K>::State& st, StepInfo& info) {
    constexpr bool arcball = K == TrackballKind::Arcball;
    info.line = kLineSummary;
    const int n = static_cast<int>(st.in.samples.size()) - 1;
    const bool closed = st.in.samples.front() == st.in.samples.back();
    const AxisAngle total = axis_angle(canonical(st.q_total));
    const AxisAngle direct = axis_angle(canonical(st.direct));
    const std::string ends = sample_name(0) + " = " + num(st.in.samples.front()) + " and " +
                             sample_name(n) + " = " + num(st.in.samples.back());
    if (closed) {
        const bool returns = st.net_angle_deg <= kSameDeg;
        info.event = arcball || returns ? "loop-returns" : "loop-drifts";
        info.narration =
            "The mouse ended where it started (" + ends + "). " +
            (returns ? "The ball is back where it began: the drag's rotation is the identity (its "
                       "angle is " + num(st.net_angle_deg, 3) + "°, round-off)" +
                           (arcball ? ", as the telescoping product (S0 S0*) promises." : ".")
                     : "Yet the ball has turned " + num(total.angle_deg, 4) + "° about " +
                           num(total.axis, 4) +
                           ": the virtual sphere does not return when the mouse does.");
        info.math = "q_{total} = " + quat_tex(canonical(st.q_total)) + ",\\ \\theta = " +
                    tex(st.net_angle_deg, 4) + "^\\circ";
        return;
    }
    const bool same = st.path_gap_deg <= kSameDeg;
    info.event = arcball || same ? "path-independent" : "path-dependent";
    const std::string straight =
        std::string(arcball ? "One arcball pair" : "One virtual-sphere step") + " straight from " +
        ends + " gives " + quat_text(canonical(st.direct)) + " (" + num(direct.angle_deg, 4) +
        "° about " + num(direct.axis, 4) + "); the " + std::to_string(n) + " pair" +
        (n == 1 ? "" : "s") + " of the path gave " + quat_text(canonical(st.q_total)) + " (" +
        num(total.angle_deg, 4) + "° about " + num(total.axis, 4) + "). ";
    if (same)
        info.narration = straight + "They agree (they differ by " + num(st.path_gap_deg, 3) +
                         "°, round-off): " +
                         (arcball ? "the products telescope, (u t*)(t s*) = u s*, so the "
                                    "rotation depends only on where the drag starts and ends."
                                  : n == 1 ? "with one pair there is no path to depend on."
                                           : "this path happens not to matter (outside the "
                                             "ball the virtual sphere only spins about z, and "
                                             "those angles add up; a pause adds nothing).");
    else
        info.narration = straight + "They differ by " + num(st.path_gap_deg, 4) +
                         "°: the virtual sphere's rotation depends on the path the mouse took.";
    info.math = "q_{total}\\, q_{direct}^{-1} \\text{ turns by } " + tex(st.path_gap_deg, 4) +
                "^\\circ";
}

template <TrackballKind K>
void fill_vars(const typename TrackballDrag<K>::State& st, StepInfo& info) {
    using Phase = typename TrackballDrag<K>::Phase;
    constexpr bool arcball = K == TrackballKind::Arcball;
    info.vars.clear();
    if (st.last == Phase::Summary) {
        info.vars = {{"q_total", quat_vec(canonical(st.q_total))},
                     {"q_direct", quat_vec(canonical(st.direct))},
                     {"path_gap_deg", st.path_gap_deg},
                     {"net_angle_deg", st.net_angle_deg},
                     {"R", rows(glm::mat3_cast(st.q_total))}};
        return;
    }
    const int k = st.last == Phase::Accumulate ? st.k - 1 : st.k;
    info.vars.push_back({"k", static_cast<long long>(k)});
    info.vars.push_back({"S", vec(st.in.samples[k])});
    info.vars.push_back({"m_S", vec(st.s.m)});
    info.vars.push_back({"s", vec(st.s.p)});
    if (st.last != Phase::MapS) {
        info.vars.push_back({"T", vec(st.in.samples[k + 1])});
        info.vars.push_back({"m_T", vec(st.t.m)});
        if (arcball)
            info.vars.push_back({"t", vec(st.t.p)});
        else
            info.vars.push_back({"v", vec(st.velocity)});
    }
    if (st.last == Phase::Rotate || st.last == Phase::Accumulate) {
        info.vars.push_back({"axis", vec(st.pairs.back().axis)});
        info.vars.push_back({"angle_deg", st.pairs.back().angle_deg});
        info.vars.push_back({"q", quat_vec(st.q_pair)});
    }
    info.vars.push_back({"q_total", quat_vec(canonical(st.q_total))});
    if (st.last == Phase::Accumulate) info.vars.push_back({"R", rows(glm::mat3_cast(st.q_total))});
}

}  // namespace

template <TrackballKind K>
void TrackballDrag<K>::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::MapS: narrate_map<K>(s, info, false); break;
        case Phase::MapT:
            if constexpr (kArcball)
                narrate_map<K>(s, info, true);
            else
                narrate_velocity<K>(s, info);
            break;
        case Phase::Rotate: narrate_rotate<K>(s, info); break;
        case Phase::Accumulate: narrate_accumulate<K>(s, info); break;
        case Phase::Summary:
        case Phase::Done: narrate_summary<K>(s, info); break;
    }
    fill_vars<K>(s, info);
}

template <TrackballKind K>
void TrackballDrag<K>::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and drag] ----------------------------------------------------------------------

template <TrackballKind K>
typename TrackballDrag<K>::Result TrackballDrag<K>::result(const State& s) {
    Result r;
    r.rotation = canonical(s.q_total);
    r.matrix = glm::mat3_cast(s.q_total);
    r.pairs = s.pairs;
    r.direct = canonical(s.direct);
    r.path_gap_deg = s.path_gap_deg;
    r.closed = s.in.samples.front() == s.in.samples.back();
    r.net_angle_deg = s.net_angle_deg;
    r.object.reserve(s.in.object.size());
    for (const dvec3& p : s.in.object) r.object.push_back(s.q_total * p);
    return r;
}

template <TrackballKind K>
[[gnu::flatten]] typename TrackballDrag<K>::Result TrackballDrag<K>::drag(const Input& in) {
    Result r;
    r.pairs.reserve(in.samples.size() - 1);
    dquat total(1, 0, 0, 0);
    BallPoint s = trackball::to_ball(in.samples[0], in.viewport);
    for (std::size_t k = 1; k < in.samples.size(); ++k) {
        const BallPoint t = trackball::to_ball(in.samples[k], in.viewport);
        const dquat q = pair_rotation<K>(s, t);
        const AxisAngle aa = axis_angle(q);
        r.pairs.push_back({aa.axis, aa.angle_deg, pair_rim<K>(s, t)});
        total = glm::normalize(q * total);
        s = t;
    }
    const dquat direct =
        pair_rotation<K>(trackball::to_ball(in.samples.front(), in.viewport), s);
    r.rotation = canonical(total);
    r.matrix = glm::mat3_cast(total);
    r.direct = canonical(direct);
    r.path_gap_deg = rotation_angle_deg(total * glm::conjugate(direct));
    r.closed = in.samples.front() == in.samples.back();
    r.net_angle_deg = rotation_angle_deg(total);
    r.object.reserve(in.object.size());
    for (const dvec3& p : in.object) r.object.push_back(total * p);
    return r;
}

// Both interfaces (the exam members are instantiated in trackball_drag_exam.cpp, draw in
// trackball_drag_draw.cpp).
template struct TrackballDrag<TrackballKind::VirtualSphere>;
template struct TrackballDrag<TrackballKind::Arcball>;

}  // namespace cg
