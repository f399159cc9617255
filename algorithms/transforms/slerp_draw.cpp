// Slerp, the picture (3D). The unit sphere (its outline and three great circles, faint), the two
// keys as the tips of their x axes ("q0 x̂", "q1 x̂"), the orientation at u as a house with its x
// axis, and the three paths of the x axis's tip as far as they have been sampled, each named
// once at its middle where they part most: slerp (green) on the sphere, the lerp of matrices
// (red) on the chord inside it, with a dashed tick out to the sphere from its current point, and
// the lerp of Euler angles (magenta) off on a road of its own.
//
// The camera looks straight at the plane of slerp's arc (orthographic, along the normal of the
// plane through the tip's start, middle and end), so the arc bows away from the chord and both
// keep their true shapes; from the default camera the arc could lie exactly over the chord.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "transforms/rotation_common.hpp"
#include "transforms/slerp.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dvec3;
using Phase = Slerp::Phase;

// The x axis's tip at u on slerp's path between the input's keys.
dvec3 slerp_tip(const Slerp::Input& in, double u) {
    Slerp::Input at = in;
    at.u = u;
    at.method = Slerp::Method::Slerp;
    return Slerp::to_matrix(Slerp::interpolate(at).q)[0];
}

}  // namespace

void Slerp::draw(const State& s, Scene& scene) {
    // The view: along the normal of the arc's plane, from the default camera's side of it.
    const dvec3 a = slerp_tip(s.in, 0), m = slerp_tip(s.in, 0.5), b = slerp_tip(s.in, 1);
    dvec3 normal = glm::cross(m - a, b - a);
    const dvec3 usual(0.54, 0.34, 0.77);  // roughly where the default camera stands
    const bool planar = glm::length(normal) > 1e-6;
    double half = 1.05;  // the focus box's half side: the sphere and a margin
    if (planar) {
        normal = glm::normalize(normal);
        if (glm::dot(normal, usual) < 0) normal = -normal;
        const dvec3 up = std::fabs(normal.y) < 0.95 ? dvec3(0, 1, 0) : dvec3(0, 0, -1);
        scene.view3 = {-normal, up, true};
        // Orthographic: a box of half side h spans h·(|e.x| + |e.y| + |e.z|) along a screen
        // axis e, so this h makes it span the sphere's 1.05 and no more.
        const dvec3 right = glm::normalize(glm::cross(-normal, up)),
                    top = glm::cross(right, -normal);
        auto l1 = [](dvec3 e) { return std::fabs(e.x) + std::fabs(e.y) + std::fabs(e.z); };
        half = 1.05 / std::max(l1(right), l1(top));
    }
    add_focus(scene, dvec3(-half), dvec3(half));

    // The sphere: its outline as the camera sees it, and three great circles, faint.
    const Style sphere{Role::Construction, 1.0f, false};
    rot::draw_circle(scene, {0, 0, 0}, planar ? normal : glm::normalize(usual), 1.0,
                     {Role::Construction, 1.5f, false}, 72);
    rot::draw_circle(scene, {0, 0, 0}, {0, 0, 1}, 1.0, sphere);
    rot::draw_circle(scene, {0, 0, 0}, {0, 1, 0}, 1.0, sphere);
    rot::draw_circle(scene, {0, 0, 0}, {1, 0, 0}, 1.0, sphere);

    // The keys' x axes.
    const bool started = s.phase != Phase::Normalise;
    scene.segments3.push_back({{0, 0, 0}, a, "", {Role::Subject, 1.5f}, true});
    scene.segments3.push_back({{0, 0, 0}, b, "", {Role::Subject, 1.5f}, true});
    scene.labels3.push_back({a, "q0 x̂", {Role::Subject}, 1});
    scene.labels3.push_back({b, "q1 x̂", {Role::Subject}, 1});

    // The orientation now: slerp at the sample's u, or at the input's u (the matrix step shows
    // the input's method: a matrix blend is no rotation, and the house shows it).
    const bool sampling = s.last == Phase::Sample;
    if (sampling || (started && s.last >= Phase::Blend)) {
        dmat3 now = Slerp::to_matrix(s.q);
        if (sampling) {
            Input at = s.in;
            at.u = s.k / double(kSamples - 1);
            at.method = Method::Slerp;
            now = Slerp::to_matrix(interpolate(at).q);
        } else if (s.last == Phase::Matrix) {
            now = s.matrix;
        }
        rot::HousePlacement h;
        h.size = 0.6;
        rot::draw_house(scene, h, now, false);
        scene.segments3.push_back(
            {{0, 0, 0}, now[0], sampling ? "" : "q x̂", {Role::Active, 3.0f}, true, 0, 2});
    }

    // The three paths, each named once at its middle sample, its current end a dot.
    auto path = [&](const std::vector<dvec3>& tips, Role role, const std::string& name) {
        for (std::size_t i = 1; i < tips.size(); ++i)
            scene.segments3.push_back({tips[i - 1], tips[i], "", {role, 2.5f}, false});
        if (tips.empty()) return;
        scene.points3.push_back({tips.back(), "", {role}, 5.0f});
        const std::size_t n = tips.size();
        if (n >= 2)
            scene.labels3.push_back(
                {n >= 3 ? tips[(n - 1) / 2] : (tips[0] + tips[1]) / 2.0, name, {role}, 2});
    };
    path(s.tip_slerp, Role::Kept, "slerp");
    path(s.tip_matrix, Role::Discarded, "lerp of matrices");
    path(s.tip_euler, Role::Leaving, "lerp of Euler angles");
    if (sampling && glm::length(s.tip_matrix.back()) > 1e-9)  // how far inside
        scene.segments3.push_back({s.tip_matrix.back(),
                                   glm::normalize(s.tip_matrix.back()),
                                   "",
                                   {Role::Construction, 1.0f, true},
                                   false});
}

}  // namespace cg
