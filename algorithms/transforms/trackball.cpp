#include "transforms/trackball.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace cg::trackball {

BallPoint to_ball(glm::dvec2 mouse, glm::dvec2 viewport) {
    const glm::dvec2 centre = viewport * 0.5;
    const double d = std::min(viewport.x, viewport.y);
    BallPoint b;
    b.m = 2.0 * (mouse - centre) / d;
    const double r2 = glm::dot(b.m, b.m);
    b.rim = r2 > 1.0;
    if (b.rim) {
        const glm::dvec2 u = b.m / std::sqrt(r2);
        b.p = {u.x, u.y, 0.0};
    } else {
        b.p = {b.m.x, b.m.y, std::sqrt(1.0 - r2)};
    }
    return b;
}

glm::dquat arcball(const BallPoint& s, const BallPoint& t) {
    // t s* for pure unit quaternions s, t: (s · t, s × t). Already unit length; normalise
    // anyway so that round-off does not accumulate when drags are composed for hours.
    const glm::dvec3 axis = glm::cross(s.p, t.p);
    return glm::normalize(glm::dquat(glm::dot(s.p, t.p), axis.x, axis.y, axis.z));
}

glm::dquat virtual_sphere(const BallPoint& s, const BallPoint& t) {
    if (s.rim) {
        // Rotation about the view axis by the signed angle from S to T around the centre.
        const double angle = std::atan2(s.m.x * t.m.y - s.m.y * t.m.x, glm::dot(s.m, t.m));
        return glm::angleAxis(angle, glm::dvec3(0, 0, 1));
    }
    const glm::dvec3 velocity(t.m - s.m, 0.0);
    const glm::dvec3 axis = glm::cross(s.p, velocity);
    const double len = glm::length(axis);
    if (len == 0.0) return glm::dquat(1, 0, 0, 0);
    return glm::angleAxis(glm::length(velocity), axis / len);
}

}  // namespace cg::trackball
