// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and compose] [draw]
#include "transforms/euler_angles.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dvec3;
using Phase = EulerAngles::Phase;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line { kLineRoll = 1, kLineCompose, kLineLockTest, kLineLock };

int axis_of(const std::string& order, int n) {
    return order[n] - 'x';
}
dvec3 unit_axis(int a) {
    return dvec3(a == 0, a == 1, a == 2);
}

struct Lock {
    bool locked;
    int sign;  // R_b(θ2) e_a = sign · e_c when locked
    double cos_mid;
};

Lock lock_of(const std::string& order, dvec3 angles) {
    const rot::CosSin mid = rot::cos_sin_deg(angles[1]);
    const dvec3 turned = rot::rotation(axis_of(order, 1), mid) * unit_axis(axis_of(order, 0));
    const double along = turned[axis_of(order, 2)];
    return {std::fabs(mid.c) < EulerAngles::kLockCos, along < 0 ? -1 : 1, mid.c};
}

dvec3 demo_angles(dvec3 angles, int sign) {
    return {angles[0] + EulerAngles::kDemoDeg, angles[1], angles[2] - sign * EulerAngles::kDemoDeg};
}

std::string theta(int n) {
    return std::string("θ") + char('1' + n);
}
std::string roll_name(const std::string& order, int n) {
    return std::string("R_") + order[n] + "(" + theta(n) + ")";
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& EulerAngles::spec() {
    static const Spec spec{
        "euler-angles",
        "Euler angles and gimbal lock",
        "Orientation and Interpolation",
        {
            "for n = 1, 2, 3: roll about axis order[n] by θn:  R ← R_order[n](θn) R",
            "R = R_c(θ3) R_b(θ2) R_a(θ1)            ▷ order \"abc\": a applied first",
            "if cos θ2 = 0:                          ▷ θ2 = ±90°",
            "    R_b(θ2) turns axis a onto ±c: R = R_c(θ3 ± θ1) R_b(θ2), a degree of freedom lost",
        },
        {
            {"roll", "one roll about a coordinate axis, and the product of the rolls so far"},
            {"compose", "the three rolls multiplied: the orientation's matrix"},
            {"gimbal-lock", "the middle angle is ±90°: the first and last rolls share an axis"},
            {"no-lock", "the middle angle is not ±90°: the three angles act independently"},
        },
        {},  // no sliders
        {
            .predict = {{"roll", {"so far"}}, {"compose", {"R"}}},
            .mistakes = {
                {"roll", "R_y(theta2)", "transpose", "put the minus sign of R_y on the wrong sine"},
                {"roll", "so far", "keep", "forgot to multiply this roll into the product"},
                {"gimbal-lock", "", "event:no-lock",
                 "missed that theta2 = ±90° locks the outer axes"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void EulerAngles::validate(const Input& in) {
    if (!rot::valid_order(in.order))
        throw InputError("order",
                         "must name the three axes once each in the order the rolls are "
                         "applied: \"xyz\", \"xzy\", \"yxz\", \"yzx\", \"zxy\" or \"zyx\" "
                         "(got \"" +
                             in.order + "\")");
    for (int n = 0; n < 3; ++n)
        if (!std::isfinite(in.angles_deg[n]))
            throw InputError("angles_deg[" + std::to_string(n) + "]",
                             "must be a finite number (got " + given(in.angles_deg[n]) + ")");
}

EulerAngles::State EulerAngles::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void EulerAngles::advance(State& s) {
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Roll:  // One roll, applied after those before it
            ++s.k;
            s.R = rot::rotation(axis_of(s.in.order, s.k), rot::cos_sin_deg(s.in.angles_deg[s.k])) *
                  s.R;
            if (s.k == 2) s.phase = Phase::Compose;
            return;
        case Phase::Compose:  // R = R_c(θ3) R_b(θ2) R_a(θ1), already multiplied: say so
            s.phase = Phase::Gimbal;
            return;
        case Phase::Gimbal: {  // The lock test, and the demonstration
            const Lock l = lock_of(s.in.order, s.in.angles_deg);
            s.lock = l.locked;
            s.sign = l.sign;
            s.cos_mid = l.cos_mid;
            s.phase = Phase::Done;
            return;
        }
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = EulerAngles::State;

std::string deg_text(double d) {
    return num(d, 6) + "°";
}

dmat3 roll(const State& s, int n) {
    return rot::rotation(axis_of(s.in.order, n), rot::cos_sin_deg(s.in.angles_deg[n]));
}

void narrate_roll(const State& s, StepInfo& info) {
    const std::string& o = s.in.order;
    const int n = s.k;
    const rot::CosSin cs = rot::cos_sin_deg(s.in.angles_deg[n]);
    static const char* kOrdinal[] = {"First", "Second", "Third"};
    info.event = "roll";
    info.line = kLineRoll;
    std::string t = std::string(kOrdinal[n]) + " roll, about " + o[n] + " by " + theta(n) + " = " +
                    deg_text(s.in.angles_deg[n]) + " (cos " + num(cs.c, 4) + ", sin " +
                    num(cs.s, 4) + "): " + roll_name(o, n) + " = " + rot::matrix_text(roll(s, n));
    if (n > 0) {
        t += ". It acts after the roll" + std::string(n > 1 ? "s" : "") +
             " before it, so it multiplies from the left: ";
        for (int m = n; m >= 0; --m) t += roll_name(o, m) + (m ? " " : "");
        t += " = " + rot::matrix_text(s.R);
    }
    info.narration = t + ".";
    info.math = std::string("R_") + o[n] + "(" + tex(s.in.angles_deg[n]) +
                "^\\circ) = " + rot::matrix_tex(roll(s, n));
    if (n > 0) info.math += ",\\quad \\text{so far: } " + rot::matrix_tex(s.R);
}

void narrate_compose(const State& s, StepInfo& info) {
    const std::string& o = s.in.order;
    info.event = "compose";
    info.line = kLineCompose;
    info.narration = "Order \"" + o + "\": " + o[0] + " first, then " + o[1] + ", then " + o[2] +
                     ", so R = " + roll_name(o, 2) + " " + roll_name(o, 1) + " " + roll_name(o, 0) +
                     " = " + rot::matrix_text(s.R) +
                     ". Its columns are where the x, y and z axes go.";
    info.math = std::string("R = R_") + o[2] + "(\\theta_3) R_" + o[1] + "(\\theta_2) R_" + o[0] +
                "(\\theta_1) = " + rot::matrix_tex(roll(s, 2)) + rot::matrix_tex(roll(s, 1)) +
                rot::matrix_tex(roll(s, 0)) + " = " + rot::matrix_tex(s.R);
}

// The demonstration: θ1 + 30°, θ3 − s·30°, and how much the matrix changes. Computed for the
// narration only, so running to the end costs what the plain function does.
dmat3 changed_matrix(const State& s) {
    return rot::euler_matrix(s.in.order, demo_angles(s.in.angles_deg, s.sign));
}

void narrate_gimbal(const State& s, StepInfo& info) {
    const std::string& o = s.in.order;
    const dvec3 a = s.in.angles_deg, b = demo_angles(a, s.sign);
    const dmat3 changed = changed_matrix(s);
    const double change = rot::max_diff(changed, s.R);
    const std::string sgn = s.sign > 0 ? "+" : "−";
    const std::string angles =
        "(" + num(b[0], 6) + "°, " + num(b[1], 6) + "°, " + num(b[2], 6) + "°)";
    info.line = s.lock ? kLineLock : kLineLockTest;
    if (s.lock) {
        info.event = "gimbal-lock";
        info.narration = std::string("Gimbal lock: θ2 = ") + deg_text(a[1]) + ", so R_" + o[1] +
                         "(θ2) turns the " + o[0] + " axis onto " + (s.sign > 0 ? "+" : "−") +
                         o[2] + ". The first roll (about " + o[0] + ") and the last (about " +
                         o[2] + ") now turn about the same line: R = R_" + o[2] + "(θ3 " + sgn +
                         " θ1) R_" + o[1] + "(θ2), and only θ3 " + sgn +
                         " θ1 = " + deg_text(rot::wrap_deg(a[2] + s.sign * a[0])) +
                         " matters. One degree of freedom is gone: the angles " + angles +
                         " (θ1 + 30°, θ3 " + (s.sign > 0 ? "−" : "+") +
                         " 30°) give the same matrix (largest difference " + num(change, 3) +
                         "), and no change of the angles near these turns the object about the "
                         "third direction.";
        info.math = "\\cos\\theta_2 = 0:\\; R = R_" + std::string(1, o[2]) + "(\\theta_3 " +
                    (s.sign > 0 ? "+" : "-") + " \\theta_1)\\, R_" + std::string(1, o[1]) +
                    "(\\theta_2),\\; R(" + tex(b[0]) + "^\\circ, " + tex(b[1]) + "^\\circ, " +
                    tex(b[2]) + "^\\circ) = " + rot::matrix_tex(changed) + " = R";
    } else {
        info.event = "no-lock";
        info.narration = "cos θ2 = " + num(s.cos_mid, 4) +
                         " ≠ 0: the three roll axes are "
                         "independent and the angles are (locally) unique. Changing θ1 by +30° "
                         "and θ3 by " +
                         (s.sign > 0 ? "−" : "+") + "30°, to " + angles +
                         ", gives a different matrix (entries change by up to " + num(change, 4) +
                         "). At θ2 = ±90° that change would do nothing.";
        info.math = "\\cos\\theta_2 = " + tex(s.cos_mid, 4) + " \\ne 0,\\; R(" + tex(b[0]) +
                    "^\\circ, " + tex(b[1]) + "^\\circ, " + tex(b[2]) +
                    "^\\circ) = " + rot::matrix_tex(changed) + " \\ne R";
    }
}

void fill_vars(const State& s, StepInfo& info) {
    const std::string& o = s.in.order;
    info.vars = {{"order", o}, {"angles_deg", vec(s.in.angles_deg)}};
    for (int n = 0; n <= std::min(s.k, 2); ++n)
        info.vars.push_back(
            {std::string("R_") + o[n] + "(theta" + char('1' + n) + ")", rot::rows3(roll(s, n))});
    info.vars.push_back({"so far", rot::rows3(s.R)});
    if (s.last >= Phase::Compose) info.vars.push_back({"R", rot::rows3(s.R)});
    if (s.last >= Phase::Gimbal) {
        info.vars.push_back({"cos theta2", s.cos_mid});
        info.vars.push_back({"gimbal_lock", s.lock});
        const dmat3 changed = changed_matrix(s);
        info.vars.push_back({"R with theta1 + 30, theta3 - s 30", rot::rows3(changed)});
        info.vars.push_back({"difference", rot::max_diff(changed, s.R)});
    }
}

}  // namespace

void EulerAngles::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Roll:
            narrate_roll(s, info);
            break;
        case Phase::Compose:
            narrate_compose(s, info);
            break;
        case Phase::Gimbal:
        case Phase::Done:
            narrate_gimbal(s, info);
            break;
    }
    fill_vars(s, info);
}

void EulerAngles::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compose] -------------------------------------------------------------------

EulerAngles::Result EulerAngles::result(const State& s) {
    Result r;
    r.matrix = s.R;
    r.gimbal_lock = s.lock;
    r.lock_sign = s.lock ? s.sign : 0;
    r.lock_angle_deg = s.lock ? rot::wrap_deg(s.in.angles_deg[2] + s.sign * s.in.angles_deg[0]) : 0;
    return r;
}

[[gnu::flatten]] EulerAngles::Result EulerAngles::compose(const Input& in) {
    Result r;
    r.matrix = rot::euler_matrix(in.order, in.angles_deg);
    const Lock l = lock_of(in.order, in.angles_deg);
    r.gimbal_lock = l.locked;
    r.lock_sign = l.locked ? l.sign : 0;
    r.lock_angle_deg = l.locked ? rot::wrap_deg(in.angles_deg[2] + l.sign * in.angles_deg[0]) : 0;
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

// The house turned by the rolls applied so far (faint where it started), its frame, the axis
// of the current roll with an arc for its angle; from the product on, the three axes the rolls
// turn about as the gimbal sees them — the last roll's axis c fixed (outer ring), the middle
// one b carried by the last roll, the first one a carried by both — each with the circle it
// turns things in. At the lock the inner and outer axes coincide and are drawn in red.
void EulerAngles::draw(const State& s, Scene& scene) {
    const std::string& o = s.in.order;
    // The camera frames the house and its frame (and the gimbal's rings from the product on).
    const double frame = s.last == Phase::Roll ? 1.25 : 1.6;
    add_focus(scene, dvec3(-frame), dvec3(frame));
    scene.frames3.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.5, "", 0.35f});
    rot::HousePlacement h;
    h.size = 0.9;
    const bool moved = s.R != dmat3(1.0);
    if (moved) rot::draw_house(scene, h, dmat3(1.0), true);
    rot::draw_house(scene, h, s.R, false);
    scene.frames3.push_back({{0, 0, 0}, s.R[0], s.R[1], s.R[2], 1.2, "R·", 1.0f});

    if (s.last == Phase::Roll && s.k >= 0) {
        const int a = axis_of(o, s.k);
        const dvec3 e = unit_axis(a);
        scene.segments3.push_back(
            {-1.7 * e, 1.7 * e, std::string("roll about ") + o[s.k], {Role::Active, 3.0f}, true});
        rot::draw_arc(scene, {0, 0, 0}, e, rot::perpendicular(e), 1.0, 0,
                      rot::wrap_deg(s.in.angles_deg[s.k]), {Role::Active, 2.0f}, true,
                      theta(s.k) + " = " + num(s.in.angles_deg[s.k], 4) + "°");
        return;
    }
    if (s.last == Phase::Roll) return;

    // The gimbal's three axes: c (outer), R_c(θ3) b (middle), R_c(θ3) R_b(θ2) a (inner).
    const dmat3 outer = rot::rotation(axis_of(o, 2), rot::cos_sin_deg(s.in.angles_deg[2]));
    const dmat3 middle = rot::rotation(axis_of(o, 1), rot::cos_sin_deg(s.in.angles_deg[1]));
    const dvec3 axes[3] = {outer * (middle * unit_axis(axis_of(o, 0))),
                           outer * unit_axis(axis_of(o, 1)), unit_axis(axis_of(o, 2))};
    const double radius[3] = {1.1, 1.3, 1.5};
    const Role roles[3] = {Role::Leaving, Role::Kept, Role::Window};
    const bool locked = s.last == Phase::Gimbal && s.lock;
    for (int n = 0; n < 3; ++n) {
        const bool red = locked && n != 1;
        const Role role = red ? Role::Discarded : roles[n];
        const std::string name = std::string(n == 0   ? "inner"
                                             : n == 1 ? "middle"
                                                      : "outer") +
                                 " axis (" + theta(n) + ", " + o[n] + ")";
        scene.segments3.push_back(
            {-radius[n] * axes[n], (radius[n] + 0.3) * axes[n], "", {role, 2.0f, false}, true});
        scene.labels3.push_back({(radius[n] + 0.35) * axes[n], name, {role}});
        rot::draw_circle(scene, {0, 0, 0}, axes[n], radius[n], {role, red ? 2.5f : 1.5f, !red});
    }
    if (locked)
        scene.labels3.push_back(
            {{0, -1.8, 0},
             "gimbal lock: " + std::string(1, o[0]) + " and " + o[2] + " rolls share one axis",
             {Role::Discarded}});
}

}  // namespace cg
