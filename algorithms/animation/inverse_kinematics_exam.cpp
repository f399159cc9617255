// Inverse kinematics exam problems, on planar arms with small whole numbers:
//   two in five: the two-link arm by the law of cosines — both solutions (θ_1, θ_2) for a target
//                with integer coordinates, one time in eight out of reach (then the nearest pose);
//   two in five: forward kinematics — the joint positions of 2 or 3 links at given angles;
//   one in five: one CCD joint update — the turn Δθ of the last joint toward the target.
#include <glm/geometric.hpp>

#include "animation/inverse_kinematics.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

std::string list(const std::vector<double>& v, const char* unit = "") {
    std::string t = "(";
    for (std::size_t i = 0; i < v.size(); ++i) t += (i ? ", " : "") + num(v[i]) + unit;
    return t + ")";
}

}  // namespace

InverseKinematics::Input InverseKinematics::exam_input(Rng& rng) {
    const double nice[] = {0, 30, 45, 60, 90, 120, -30, -45, -60, -90, 180};
    Input in;
    const double kind = rng.uniform(0, 1);
    if (kind < 0.4) {
        in.method = Method::Analytic;
        in.lengths = {double(rng.integer(1, 3)), double(rng.integer(1, 3))};
        const double reach = in.lengths[0] + in.lengths[1];
        const double inner = std::fabs(in.lengths[0] - in.lengths[1]);
        const bool out = rng.chance(0.125);
        for (int tries = 0; tries < 100; ++tries) {
            in.target = {double(rng.integer(-4, 4)), double(rng.integer(-4, 4)), 0};
            const double d = std::hypot(in.target.x, in.target.y);
            const bool inside = d <= reach && d >= inner;
            if (inside != out && d > 0) break;
        }
        in.elbow_up = rng.chance(0.5);
    } else if (kind < 0.8) {
        in.method = Method::Forward;
        const int n = int(rng.integer(2, 3));
        for (int i = 0; i < n; ++i) {
            in.lengths.push_back(double(rng.integer(1, 3)));
            in.angles.push_back(nice[rng.integer(0, 10)]);
        }
    } else {
        in.method = Method::CCD;
        const int n = int(rng.integer(2, 3));
        for (int i = 0; i < n; ++i) {
            in.lengths.push_back(double(rng.integer(1, 2)));
            in.angles.push_back(nice[rng.integer(0, 5)]);
        }
        in.iterations = 1;
        // Not on the last joint nor on the end (no turn to speak of there).
        Input fk = in;
        fk.method = Method::Forward;
        const Result r = compute(fk);
        for (int tries = 0; tries < 100; ++tries) {
            in.target = {double(rng.integer(-3, 3)), double(rng.integer(1, 3)), 0};
            if (glm::length(in.target - r.positions[std::size_t(n) - 1]) > 0.5 &&
                glm::length(in.target - r.end) > 0.5)
                break;
        }
    }
    in.has_target = in.method != Method::Forward;
    return in;
}

std::string InverseKinematics::question(const Input& in) {
    const std::size_t n = in.lengths.size();
    const std::string arm = "A planar arm with its base at the origin has " + std::to_string(n) +
                            " links of lengths " + list(in.lengths) +
                            "; each joint angle is measured counter-clockwise from the previous "
                            "link (the first from the x axis). ";
    switch (in.method) {
        case Method::Analytic:
            return arm + "Find the joint angles (θ_1, θ_2) in degrees that put the end at " +
                   num(glm::dvec2(in.target)) +
                   " by the law of cosines: both solutions, elbow_up with θ_2 ≤ 0 and "
                   "elbow_down with θ_2 ≥ 0, each in (−180°, 180°]. If the target is out of "
                   "reach, give the nearest pose (stretched toward it, or folded with θ_2 = 180°) "
                   "for both.";
        case Method::Forward:
            return arm + "The joint angles are " + list(in.angles, "°") +
                   ". Give the joint positions p_0 … p_" + std::to_string(n) +
                   " (positions, each [x, y]).";
        default: {
            return arm + "The joint angles are " + list(in.angles, "°") + " and the target is " +
                   num(glm::dvec2(in.target)) +
                   ". Cyclic coordinate descent starts at the last joint: by how many degrees "
                   "(Δθ, counter-clockwise positive, in (−180°, 180°]) does it turn so that the "
                   "direction joint→end points at joint→target? (first_update/delta)";
        }
    }
}

std::vector<std::string> InverseKinematics::answer_fields(const Input& in) {
    switch (in.method) {
        case Method::Analytic:
            return {"elbow_up", "elbow_down"};
        case Method::Forward:
            return {"positions"};
        default:
            return {"first_update/delta"};
    }
}

}  // namespace cg
