// Orientation interpolation exam problems, three kinds told apart by how the keys are given:
//   quaternions (one time in two): slerp of two unit quaternions at u = 1/2, 1/3 or 1/4 with the
//     course's ω = acos(q1 · q2); one time in three q2 is given with the sign that makes the dot
//     product negative, so −q2 must be taken first. Answers ω and q(u) (frame 1).
//   Euler angles (three times in ten): the Euler-lerp midpoint against the slerp midpoint of two
//     keys in the order xyz, the first the identity. Answers the lerped angles and slerp's q.
//   axis-angle (one time in five): two turns about the same coordinate axis, by 0° and θ;
//     "why does matrix lerp not give a rotation": the half-way matrix (I + R)/2 and its
//     det = cos²(θ/2) (0 for θ = 180°: the object is flattened).
#include "animation/orientation_interpolation.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using OI = OrientationInterpolation;

OI::Key axis_angle(int axis, double deg) {
    OI::Key k;
    k.form = OI::Form::AxisAngle;
    k.axis = glm::dvec3(0);
    k.axis[axis] = 1;
    k.angle_deg = deg;
    return k;
}

// The quaternion of a turn by `deg` about a coordinate axis, written with the nice values.
OI::Key quaternion_key(int axis, double deg, bool negate) {
    glm::dquat q;
    glm::dmat3 m;
    glm::dvec3 e;
    OI::key_forms(axis_angle(axis, deg), "xyz", q, m, e);
    OI::Key k;
    k.form = OI::Form::Quaternion;
    const double s = negate ? -1 : 1;
    k.q = {s * q.w, s * q.x, s * q.y, s * q.z};
    return k;
}

std::string qtext(const glm::dquat& q) {
    return "[" + num(q.w, 4) + ", " + num(q.x, 4) + ", " + num(q.y, 4) + ", " + num(q.z, 4) + "]";
}

}  // namespace

OI::Input OI::exam_input(Rng& rng) {
    Input in;
    in.order = "xyz";
    in.segment_time = 1;
    const double pick = rng.uniform(0, 1);
    if (pick < 0.5) {
        const double angles[] = {60, 90, 120, 180};
        const int a1 = int(rng.integer(0, 2));
        const double d1 = rng.chance(0.5) ? 0 : angles[rng.integer(0, 1)];
        const int a2 = int(rng.integer(0, 2));
        const double d2 = angles[rng.integer(0, 3)];
        in.keys = {quaternion_key(a1, d1, false), quaternion_key(a2, d2, rng.chance(1.0 / 3))};
        in.frames = int(rng.integer(2, 4));
    } else if (pick < 0.8) {
        const double angles[] = {0, 90, 90, 180, -90};
        Key k0, k1;
        k0.form = k1.form = Form::Euler;
        do {
            k1.euler_deg = {angles[rng.integer(0, 4)], angles[rng.integer(0, 4)], 0};
        } while (k1.euler_deg == glm::dvec3(0) || std::fabs(k1.euler_deg.y) == 180);
        in.keys = {k0, k1};
        in.frames = 2;
    } else {
        const double angles[] = {60, 90, 120, 180};
        const int axis = int(rng.integer(0, 2));
        in.keys = {axis_angle(axis, 0), axis_angle(axis, angles[rng.integer(0, 3)])};
        in.frames = 2;
    }
    return in;
}

std::vector<std::string> OI::answer_fields(const Input& in) {
    switch (in.keys.at(0).form) {
        case Form::Quaternion:
            return {"omega_deg/0", "slerp/1"};
        case Form::Euler:
            return {"euler/1", "slerp/1"};
        case Form::AxisAngle:
            break;
    }
    return {"matrix/1", "matrix_det/1"};
}

std::string OI::question(const Input& in) {
    const Key& a = in.keys.at(0);
    const Key& b = in.keys.at(1);
    switch (a.form) {
        case Form::Quaternion:
            return "Two key orientations are given as unit quaternions q1 = " + qtext(a.q) +
                   " and q2 = " + qtext(b.q) + " ([w, x, y, z]). Interpolate them by slerp at u = 1/" +
                   std::to_string(in.frames) +
                   ": ω = acos(q1 · q2) (if q1 · q2 < 0, first replace q2 by −q2, the same "
                   "rotation, so that the shorter arc is taken), q(u) = (q1 sin((1 − u)ω) + q2 "
                   "sin(uω)) / sin ω (if ω = 0 the keys are one orientation and q(u) = q1). Give ω "
                   "in degrees (omega_deg/0) and q(u) as [w, x, y, z] (slerp/1).";
        case Form::Euler:
            return "Two key orientations are given by Euler angles in the order xyz (roll about x "
                   "by θ1 first, then y by θ2, then z by θ3, about the fixed axes: R = R_z(θ3) "
                   "R_y(θ2) R_x(θ1)): e1 = " + num(a.euler_deg) + "° and e2 = " + num(b.euler_deg) +
                   "°. (a) Interpolating the angles linearly, what are the Euler angles half way "
                   "(euler/1)? (b) What is the slerp of the two orientations' unit quaternions "
                   "half way, as [w, x, y, z] (slerp/1)? (Is it the same orientation as (a)?)";
        case Form::AxisAngle:
            break;
    }
    const char axis = char('x' + (b.axis.x != 0 ? 0 : b.axis.y != 0 ? 1 : 2));
    return "Key 1 is the identity and key 2 a turn by " + num(b.angle_deg) + "° about the " + axis +
           " axis. Interpolate their rotation matrices entry by entry half way, M = (M1 + M2)/2. "
           "Give M as rows (matrix/1) and det M (matrix_det/1). Why is M not a rotation?";
}

}  // namespace cg
