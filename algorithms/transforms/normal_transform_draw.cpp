// Transforming normals, the picture (3D). On the left the surface patch (spanned by the
// tangents) with its normal n; on the right, 3 units along the screen, its image under L
// (scaled to fit: a uniform scale keeps every angle), with the naive L n (red when it is no
// longer perpendicular) and the correct N n = (L⁻¹)ᵀ n (green).
//
// When the construction lies in a coordinate plane — n in it and L mapping the plane into
// itself, as in "squash y by 2" — the camera looks along the plane's normal, orthographic: the
// patch is then seen edge-on as the surface's trace, a line, and a small square marks the right
// angle between each surface and its normal, so a student can see at a glance that N n is
// perpendicular and L n is not. Otherwise the default camera, framed on both patches.
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "transforms/normal_transform.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dvec3;
using Phase = NormalTransform::Phase;

bool parallel(dvec3 a, dvec3 b) {
    return glm::length(glm::cross(a, b)) <= 1e-12 * glm::length(a) * glm::length(b);
}

// The axis whose plane holds the construction: n ⊥ d, L d ∥ d and Lᵀ d ∥ d (so L maps the plane
// d⊥ into itself and n's image stays in it as well); (0, 0, 0) when there is none.
dvec3 plane_axis(const dmat3& l, dvec3 n) {
    for (const dvec3 d : {dvec3(0, 0, 1), dvec3(0, 1, 0), dvec3(1, 0, 0)})
        if (std::fabs(glm::dot(n, d)) <= 1e-12 * glm::length(n) && parallel(l * d, d) &&
            parallel(glm::transpose(l) * d, d))
            return d;
    return dvec3(0);
}

}  // namespace

void NormalTransform::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const bool tangents = s.phase > Phase::Tangents;
    const std::array<dvec3, 2> t = tangents ? s.r.tangents : tangents_of(in);
    const std::array<dvec3, 2> u = {glm::normalize(t[0]), glm::normalize(t[1])};
    const std::array<dvec3, 4> corners = {-u[0] - u[1], u[0] - u[1], u[0] + u[1], -u[0] + u[1]};
    const dvec3 n = glm::normalize(in.normal);

    // The view, and the screen's right and up to lay the two patches out by.
    const dvec3 d = plane_axis(in.linear, in.normal);
    const bool planar = d != dvec3(0);
    dvec3 right(1, 0, 0), up(0, 1, 0);
    if (planar) {
        const dvec3 look = -d, view_up = d.y != 0 ? dvec3(0, 0, -1) : dvec3(0, 1, 0);
        scene.view3 = {look, view_up, true};
        right = glm::normalize(glm::cross(look, view_up));
        up = glm::cross(right, look);
    }
    dvec3 lo(0.0), hi(0.0);
    const auto frame = [&](dvec3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); };

    // The surface's trace in the plane (planar view): the tangent direction that is not d.
    const dvec3 trace = planar ? glm::normalize(glm::cross(d, n)) : dvec3(0);
    const auto right_angle = [&](dvec3 at, dvec3 along, dvec3 normal, Role role) {
        const double k = 0.15;
        scene.segments3.push_back({at + k * along, at + k * (along + normal), "", {role, 1.5f}});
        scene.segments3.push_back({at + k * (along + normal), at + k * normal, "", {role, 1.5f}});
    };

    std::vector<dvec3> before;
    for (const dvec3& c : corners) before.push_back(0.7 * c), frame(0.7 * c);
    scene.faces3.push_back({before, {Role::Subject}, 0.3f, true, true});
    if (planar) {
        scene.segments3.push_back({-0.9 * trace, 0.9 * trace, "", {Role::Subject, 3.0f}});
        right_angle({0, 0, 0}, trace, n, Role::Neutral);
    }
    Segment3 normal{{0, 0, 0}, n, "n", {Role::Neutral, 2.5f}, true};
    normal.min_pixels = 30;
    scene.segments3.push_back(normal);
    frame(n);
    scene.labels3.push_back({-1.3 * up, "before", {Role::Neutral}});
    frame(-1.3 * up);

    const dvec3 o = 3.0 * right;
    double reach = 0;
    for (const dvec3& c : corners) reach = std::max(reach, glm::length(in.linear * c));
    const double k = 1.0 / reach;  // the image scaled so that its farthest corner is at 1
    for (const dvec3& c : corners) frame(o + k * (in.linear * c));
    frame(o + 1.3 * up), frame(o - 1.3 * up);
    if (!tangents) {
        add_focus(scene, lo, hi);
        return;
    }
    for (int i = 0; i < 2; ++i)
        if (!planar || !parallel(u[i], d))  // not one pointing straight at the viewer
            scene.segments3.push_back(
                {{0, 0, 0}, 0.7 * u[i], i == 0 ? "t₁" : "t₂", {Role::Construction, 1.5f}, true});
    std::vector<dvec3> after;
    for (const dvec3& c : corners) after.push_back(o + k * (in.linear * c));
    scene.faces3.push_back({after, {Role::Window}, 0.3f, true, true});
    const dvec3 image = planar ? glm::normalize(in.linear * trace) : dvec3(0);
    if (planar)
        scene.segments3.push_back({o - 0.9 * image, o + 0.9 * image, "", {Role::Window, 3.0f}});
    scene.labels3.push_back({o - 1.3 * up, "after L (scaled to fit)", {Role::Window}});
    if (s.phase > Phase::Naive) {
        Segment3 naive{o,
                       o + glm::normalize(s.r.naive),
                       "L n",
                       {s.r.naive_ok ? Role::Kept : Role::Discarded, 2.5f},
                       true};
        naive.min_pixels = 30;
        scene.segments3.push_back(naive);
    }
    if (s.phase == Phase::Done) {
        Segment3 correct{o, o + s.r.unit_normal, "N n", {Role::Kept, 3.0f}, true};
        correct.min_pixels = 30;
        correct.priority = 1;
        scene.segments3.push_back(correct);
        if (planar) right_angle(o, image, s.r.unit_normal, Role::Kept);
    }
    add_focus(scene, lo, hi);
}

}  // namespace cg
