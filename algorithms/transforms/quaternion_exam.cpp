// Quaternion exam problems, with small integers a student works by hand:
//   multiply (3 in 10)        q1, q2 with components in −2..2; about one in six has parallel
//                             vector parts (they commute);
//   rotate (1 in 5)           a point with components in −3..3 turned by a quaternion of a
//                             quarter, half or third turn about a coordinate axis or (1, 1, 1),
//                             often not unit length (normalising is part of the work);
//   from_axis_angle (1 in 5)  a coordinate or diagonal axis (not unit), θ a multiple of 45° or 60°;
//   to_matrix (3 in 20)       a quaternion from the same set as rotate;
//   inverse, from_matrix (1 in 20 each): small integer q; the matrix of a quarter or half turn.
// The answer fields are the same for all: q, q2q1, point, matrix (null where the op gives none).
#include <cmath>

#include "core/format.hpp"
#include "transforms/quaternion.hpp"
#include "transforms/rotation_common.hpp"
#include "transforms/slerp.hpp"

namespace cg {

namespace {

using Op = Quaternion::Op;

glm::dquat nice_rotation(Rng& rng) {
    static constexpr double kQ[][4] = {{1, 0, 0, 1},  {1, 1, 0, 0}, {1, 0, 1, 0},  {0, 0, 0, 1},
                                       {0, 1, 0, 0},  {0, 0, 1, 0}, {1, 1, 1, 1},  {1, 0, 0, -1},
                                       {1, -1, 0, 0}, {2, 0, 0, 2}, {1, -1, 1, 1}, {0, 1, 1, 0}};
    const auto& c = kQ[rng.integer(0, std::size(kQ) - 1)];
    return {c[0], c[1], c[2], c[3]};
}

double small(Rng& rng, int m) {
    return double(rng.integer(-m, m));
}

std::string qtext(const glm::dquat& q) {
    return "[" + num(q.w) + ", " + num(q.x) + ", " + num(q.y) + ", " + num(q.z) + "]";
}

std::string rows_text(const glm::dmat3& m) {
    std::string t = "[";
    for (int r = 0; r < 3; ++r) {
        t += "[";
        for (int c = 0; c < 3; ++c) t += (c ? ", " : "") + num(rot::clean(m[c][r]), 6);
        t += r < 2 ? "], " : "]]";
    }
    return t;
}

}  // namespace

Quaternion::Input Quaternion::exam_input(Rng& rng) {
    Input in;
    const long long kind = rng.integer(0, 19);
    if (kind < 6) {
        in.op = Op::Multiply;
        do {
            in.q1 = {small(rng, 2), small(rng, 2), small(rng, 2), small(rng, 2)};
        } while (in.q1 == glm::dquat(0, 0, 0, 0));
        if (rng.chance(1.0 / 6)) {  // parallel vector parts: they commute
            const double k = double(rng.integer(1, 2)) * (rng.chance(0.5) ? 1 : -1);
            in.q2 = {small(rng, 2), k * in.q1.x, k * in.q1.y, k * in.q1.z};
        } else {
            in.q2 = {small(rng, 2), small(rng, 2), small(rng, 2), small(rng, 2)};
        }
    } else if (kind < 10) {
        in.op = Op::Rotate;
        in.q = nice_rotation(rng);
        do {
            in.point = {small(rng, 3), small(rng, 3), small(rng, 3)};
        } while (in.point == glm::dvec3(0));
    } else if (kind < 14) {
        in.op = Op::FromAxisAngle;
        static constexpr double kAxes[][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0},  {0, 0, 2},
                                              {1, 1, 0}, {1, 1, 1}, {0, -1, 0}, {0, 1, 1}};
        static constexpr double kAngles[] = {90, 180, 60, 120, -90, 45, 270, 240, 30, 360};
        const auto& a = kAxes[rng.integer(0, std::size(kAxes) - 1)];
        in.axis = {a[0], a[1], a[2]};
        in.angle_deg = kAngles[rng.integer(0, std::size(kAngles) - 1)];
    } else if (kind < 17) {
        in.op = Op::ToMatrix;
        in.q = nice_rotation(rng);
    } else if (kind < 18) {
        in.op = Op::Inverse;
        do {
            in.q = {small(rng, 2), small(rng, 2), small(rng, 2), small(rng, 2)};
        } while (in.q == glm::dquat(0, 0, 0, 0));
    } else {
        in.op = Op::FromMatrix;
        in.matrix = Slerp::to_matrix(glm::normalize(nice_rotation(rng)));
        for (int c = 0; c < 3; ++c)  // exact 0, ±1 entries as a student writes them
            for (int r = 0; r < 3; ++r) in.matrix[c][r] = rot::clean(in.matrix[c][r]);
    }
    return in;
}

std::string Quaternion::question(const Input& in) {
    const std::string rest =
        " (Quaternions [w, x, y, z]; the answer fields that do not apply are "
        "none.)";
    switch (in.op) {
        case Op::Multiply:
            return "Compute q1 q2 (q) and q2 q1 (q2q1) for q1 = " + qtext(in.q1) +
                   " and q2 = " + qtext(in.q2) +
                   " with q1 q2 = (s1 s2 − v1 · v2, s1 v2 + s2 v1 + v1 × v2). Do they differ?" +
                   rest;
        case Op::Conjugate:
            return "Give the conjugate q̄ (q) of q = " + qtext(in.q) + "." + rest;
        case Op::Inverse:
            return "Give the inverse q⁻¹ = q̄ / |q|² (q) of q = " + qtext(in.q) + "." + rest;
        case Op::Rotate:
            return "Rotate the point P = " + num(in.point) + " by the quaternion " + qtext(in.q) +
                   ": normalise it (q, unit length) and compute (0, P′) = q (0, P) q̄ (point)." +
                   rest;
        case Op::FromAxisAngle:
            return "Give the unit quaternion (q) of a " + num(in.angle_deg) + "° turn about " +
                   num(in.axis) + " (right-handed; q = (cos θ/2, sin θ/2 â))." + rest;
        case Op::ToMatrix:
            return "Give the 3×3 rotation matrix (matrix, rows, acting on column vectors) of the "
                   "quaternion " +
                   qtext(in.q) + ", after normalising it (q)." + rest;
        case Op::FromMatrix:
            return "Give the unit quaternion (q, with w ≥ 0; if w = 0, the first non-zero "
                   "component positive) of the rotation matrix R = " +
                   rows_text(in.matrix) + " (rows)." + rest;
    }
    return "";
}

std::vector<std::string> Quaternion::answer_fields() {
    return {"q", "q2q1", "point", "matrix"};
}

}  // namespace cg
