// Perspective exam problems: a 90° field of view (cot 45° = 1) with aspect 1, 2, 0.5 or 1.25,
// near and far pairs whose (f+n)/(f−n) and 2fn/(f−n) are short decimals, and two or three
// integer points at integer depths — mostly between the planes, now and then nearer than the
// near plane, beyond the far one or behind the eye. Mostly the course's convention with the
// points in view coordinates; sometimes OpenGL's, sometimes a look-at along the z axis, and
// sometimes a segment crossing the near plane.
#include <array>

#include "core/format.hpp"
#include "transforms/perspective.hpp"

namespace cg {

namespace {

constexpr std::array<std::array<double, 2>, 6> kPlanes = {{{1, 3}, {1, 2}, {2, 6}, {1, 5}, {1, 9}, {2, 4}}};
constexpr std::array<double, 4> kAspects = {1, 2, 0.5, 1.25};

template <class T, std::size_t N>
T pick(Rng& rng, const std::array<T, N>& values) {
    return values[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(N) - 1))];
}

}  // namespace

Perspective::Input Perspective::exam_input(Rng& rng) {
    Input in;
    in.convention = rng.chance(0.75) ? Convention::Course : Convention::OpenGL;
    in.fov_y_deg = 90;
    in.aspect = rng.chance(0.5) ? 1 : pick(rng, kAspects);
    const auto planes = pick(rng, kPlanes);
    in.near = planes[0];
    in.far = planes[1];
    const double z = in.convention == Convention::Course ? 1 : -1;  // view z of depth 1
    double shift = 0;  // a look-at moves the eye back along the view axis by `shift`
    if (rng.chance(0.2)) {
        in.look_at = true;
        shift = static_cast<double>(rng.integer(1, 5));
        in.eye = {0, 0, -z * shift};  // looking at the origin down the convention's axis
        in.center = {0, 0, 0};
        in.up = {0, 1, 0};
    }
    const int n = rng.chance(0.3) ? 3 : 2;
    for (int k = 0; k < n; ++k) {
        double depth = static_cast<double>(rng.integer(static_cast<long long>(in.near),
                                                       static_cast<long long>(in.far)));
        if (rng.chance(0.12)) depth = in.near / 2;  // between the eye and the near plane
        if (rng.chance(0.08)) depth = in.far + 1;   // beyond the far plane
        if (rng.chance(0.06)) depth = -1;           // behind the eye
        const double reach = depth > 0 ? depth : 1;
        in.points.push_back({static_cast<double>(rng.integer(-static_cast<long long>(reach) - 1,
                                                             static_cast<long long>(reach) + 1)),
                             static_cast<double>(rng.integer(-static_cast<long long>(reach),
                                                             static_cast<long long>(reach))),
                             z * (depth - shift)});
    }
    if (rng.chance(0.25)) {  // from behind the eye to beyond the near plane
        const double d0 = -static_cast<double>(rng.integer(1, 2));
        const double d1 = in.near + static_cast<double>(rng.integer(0, 2));
        in.segments.push_back({glm::dvec3(static_cast<double>(rng.integer(-1, 1)), 1, z * (d0 - shift)),
                               glm::dvec3(static_cast<double>(rng.integer(-1, 1)), -1, z * (d1 - shift))});
    }
    return in;
}

std::string Perspective::question(const Input& in) {
    const bool course = in.convention == Convention::Course;
    std::string q = std::string("Use ") +
                    (course ? "the course's perspective matrix (the view looks down +z, w = z)"
                            : "OpenGL's perspective matrix (the view looks down −z, w = −z, as "
                              "glm::perspective)") +
                    " with a vertical field of view of " + num(in.fov_y_deg) + "°, aspect " +
                    num(in.aspect) + ", near " + num(in.near) + " and far " + num(in.far) +
                    ", mapping the near plane to z_ndc = −1 and the far plane to +1. ";
    if (in.look_at)
        q += "The camera sits at eye = " + num(in.eye) + " looking at " + num(in.center) +
             " with up = " + num(in.up) + "; the points are in world coordinates. ";
    else
        q += "The points are in view coordinates. ";
    q += "Give the 4×4 matrix (matrix, rows), the clip coordinates [x, y, z, w] of ";
    for (std::size_t k = 0; k < in.points.size(); ++k)
        q += (k ? (k + 1 == in.points.size() ? " and " : ", ") : "") + std::string("P") +
             std::to_string(k) + " = " + num(in.points[k]);
    q += " (clip), and their NDC after the divide (ndc; null for a point with w ≤ 0).";
    if (!in.segments.empty())
        q += " Also clip the segment from " + num(in.segments[0][0]) + " to " +
             num(in.segments[0][1]) + " against the near plane in clip space (z + w ≥ 0) before "
             "dividing (not graded: the worked solution shows it).";
    return q;
}

std::vector<std::string> Perspective::answer_fields() { return {"matrix", "clip", "ndc"}; }

}  // namespace cg
