// Slerp exam problems: two orientations given as quaternions with small integer components
// (not unit length: normalising is part of the work) — the identity, quarter and half turns
// about coordinate axes, the 120° turn about (1, 1, 1) — at u ∈ {1/4, 1/3, 1/2, 2/3, 3/4}.
// Pairs with a negative dot product (the flip) come up about one time in three; now and then
// (about one problem in a hundred) the two keys are the same rotation (the fallback).
#include <cmath>

#include "core/format.hpp"
#include "transforms/slerp.hpp"

namespace cg {

namespace {

std::string fraction(double u) {
    for (int den : {2, 3, 4}) {
        const double top = u * den;
        const long long n = std::llround(top);
        if (std::fabs(top - double(n)) < 1e-12 && n > 0 && n < den)
            return std::to_string(n) + "/" + std::to_string(den);
    }
    return num(u);
}

std::string qtext(const glm::dquat& q) {
    return "[" + num(q.w) + ", " + num(q.x) + ", " + num(q.y) + ", " + num(q.z) + "]";
}

}  // namespace

Slerp::Input Slerp::exam_input(Rng& rng) {
    static constexpr double kKeys[][4] = {{1, 0, 0, 0}, {1, 0, 0, 1},  {1, 1, 0, 0},  {1, 0, 1, 0},
                                          {0, 0, 0, 1}, {0, 1, 0, 0},  {1, 1, 1, 1},  {1, 0, 0, -1},
                                          {0, 0, 1, 0}, {-1, 0, 0, 1}, {1, -1, 0, 0}, {2, 0, 0, 0}};
    static constexpr double kU[] = {0.25, 1.0 / 3, 0.5, 2.0 / 3, 0.75};
    Input in;
    const long long ia = rng.integer(0, std::size(kKeys) - 1);
    long long ib = rng.integer(0, std::size(kKeys) - 1);
    if (ib == ia && !rng.chance(1.0 / 8))
        ib = (ib + 1 + rng.integer(0, std::size(kKeys) - 2)) % std::ssize(kKeys);
    const auto& a = kKeys[ia];
    const auto& b = kKeys[ib];
    in.q0 = {a[0], a[1], a[2], a[3]};
    in.q1 = {b[0], b[1], b[2], b[3]};
    if (rng.chance(0.3)) in.q1 = -in.q1;  // the same rotation, the other sign: a flip
    in.u = kU[rng.integer(0, std::size(kU) - 1)];
    return in;
}

std::string Slerp::question(const Input& in) {
    return "Two orientations are given by the quaternions q0 = " + qtext(in.q0) +
           " and q1 = " + qtext(in.q1) +
           " ([w, x, y, z]; normalise them first). Slerp them at u = " + fraction(in.u) +
           ": take cos ω = q0 · q1, negating q1 first if that is negative (the short way round), "
           "and q(u) = (sin((1 − u)ω) q0 + sin(uω) q1) / sin ω (when sin ω = 0 the two are the "
           "same "
           "orientation and q(u) is it). Give ω in degrees (omega_deg), "
           "q(u) as [w, x, y, z] (q) and its 3×3 rotation matrix (matrix, rows, acting on column "
           "vectors).";
}

std::vector<std::string> Slerp::answer_fields() {
    return {"omega_deg", "q", "matrix"};
}

}  // namespace cg
