// Change-of-basis exam problems: F2 is usually orthonormal — a quarter turn about z (the 2D
// problems), an axis-aligned 3D rotation (a signed permutation), or the 3-4-5 rotation — and
// now and then a scale by 2 or a shear, whose inverses are halves and integers; F1 is the
// world frame, a scale, a shear or a turned frame with small integer axes; origins and points
// are small integers. So every answer is a short decimal.
#include <array>

#include "core/format.hpp"
#include "transforms/change_of_basis.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Axes = std::array<dvec3, 3>;

const Axes kIdentity = {dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)};

// Frames that keep z = 0 on z = 0 (usable in the 2D problems), as axes.
const std::array<Axes, 8> kPlanar = {{
    kIdentity,
    {dvec3(0, 1, 0), dvec3(-1, 0, 0), dvec3(0, 0, 1)},   // turned by 90°
    {dvec3(-1, 0, 0), dvec3(0, -1, 0), dvec3(0, 0, 1)},  // 180°
    {dvec3(0, -1, 0), dvec3(1, 0, 0), dvec3(0, 0, 1)},   // 270°
    {dvec3(2, 0, 0), dvec3(0, 2, 0), dvec3(0, 0, 1)},    // scaled by 2
    {dvec3(1, 0, 0), dvec3(1, 1, 0), dvec3(0, 0, 1)},    // sheared
    {dvec3(1, 1, 0), dvec3(-1, 1, 0), dvec3(0, 0, 1)},   // turned by 45°, scaled by √2
    {dvec3(2, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)},    // x scaled by 2
}};

// A rotation that maps the coordinate axes to coordinate axes: a permutation with signs whose
// determinant is +1.
Axes signed_permutation(Rng& rng) {
    static constexpr int kPerms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                         {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    const auto& p = kPerms[rng.integer(0, 5)];
    Axes a{};
    for (int i = 0; i < 3; ++i) {
        a[i] = dvec3(0);
        a[i][p[i]] = rng.chance(0.5) ? -1 : 1;
    }
    if (glm::dot(a[0], glm::cross(a[1], a[2])) < 0) a[2] = -a[2];
    return a;
}

double small(Rng& rng, int lo, int hi) {
    return static_cast<double>(rng.integer(lo, hi));
}

}  // namespace

ChangeOfBasis::Input ChangeOfBasis::exam_input(Rng& rng) {
    Input in;
    const bool planar = rng.chance(0.5);
    // F2, the frame the answer is in: orthonormal four times in five.
    const double kind = rng.uniform(0, 1);
    if (kind < 0.8) {
        if (planar)
            in.to.axes = kPlanar[static_cast<std::size_t>(rng.integer(0, 3))];
        else if (kind < 0.7)
            in.to.axes = signed_permutation(rng);
        else
            in.to.axes = {dvec3(0.6, 0.8, 0), dvec3(-0.8, 0.6, 0), dvec3(0, 0, 1)};
    } else {
        in.to.axes = kPlanar[static_cast<std::size_t>(rng.integer(4, 5))];  // scale or shear
    }
    in.from.axes = kPlanar[static_cast<std::size_t>(rng.integer(0, kPlanar.size() - 1))];
    if (!planar && rng.chance(0.5)) in.from.axes = signed_permutation(rng);
    if (rng.chance(0.3)) in.from.axes = kIdentity;  // "the world coordinates of P are …"
    const int z = planar ? 0 : 1;
    in.from.origin = {small(rng, -2, 3), small(rng, -2, 3), z * small(rng, -2, 2)};
    in.to.origin = {small(rng, -2, 3), small(rng, -2, 3), z * small(rng, -2, 2)};
    const int n = static_cast<int>(rng.integer(1, 2));
    for (int k = 0; k < n; ++k)
        in.points.push_back({small(rng, -2, 3), small(rng, -2, 3), z * small(rng, -2, 2)});
    return in;
}

std::string ChangeOfBasis::question(const Input& in) {
    const auto frame = [](const Frame& f, const char* axis, const char* origin) {
        std::string t = std::string(origin) + " = " + num(f.origin);
        for (int i = 0; i < 3; ++i)
            t += std::string(i ? ", " : " and axes ") + axis + std::to_string(i + 1) + " = " +
                 num(f.axes[i]);
        return t;
    };
    std::string q = "Frame F1 has origin " + frame(in.from, "v", "O_v") + "; frame F2 has origin " +
                    frame(in.to, "w", "O_w") + " (all in world coordinates). ";
    bool planar = in.from.origin.z == 0 && in.to.origin.z == 0 &&
                  in.from.axes[2] == dvec3(0, 0, 1) && in.to.axes[2] == dvec3(0, 0, 1);
    for (const dvec3& p : in.points) planar = planar && p.z == 0;
    if (planar) q += "(A 2D problem written in 3D: every z is 0 and both third axes are z.) ";
    q += in.points.size() > 1 ? "The points " : "The point ";
    for (std::size_t k = 0; k < in.points.size(); ++k)
        q += (k ? ", " : "") + std::string("P") + std::to_string(k) + " = " + num(in.points[k]);
    q += in.points.size() > 1 ? " are given by their coordinates" : " is given by its coordinates";
    q += " relative to F1. Give the coordinates of each point "
         "relative to F2 (points), the change-of-basis matrix M₁,₂ that maps coordinates "
         "relative to F1 to coordinates relative to F2 (matrix, 4×4 rows, column vectors with "
         "w = 1 for points), and whether F2 is orthonormal (orthonormal_to).";
    return q;
}

std::vector<std::string> ChangeOfBasis::answer_fields() {
    return {"points", "matrix", "orthonormal_to"};
}

}  // namespace cg
