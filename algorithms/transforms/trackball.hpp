// The two mouse-driven rotation interfaces of the course: the virtual sphere and the arcball.
//
// Both imagine a ball filling the viewport: a mouse position (pixels, origin bottom-left, y up)
// is first expressed relative to the ball, m = (2 (x − cx) / d, 2 (y − cy) / d) with (cx, cy)
// the viewport's centre and d = min(width, height) its diameter, so the ball is the unit disc.
// Inside the disc a point lifts onto the front of the unit sphere, (m.x, m.y, √(1 − |m|²));
// outside it (the rim case) it is pulled onto the sphere's silhouette, (m / |m|, 0).
//
// Virtual sphere (Chen et al.): from two successive samples S then T, the mouse motion T − S is
// a tangential velocity at S's point on the sphere; the ball turns about the axis
// s × (T − S, 0) (perpendicular to both the point and the motion) by an angle proportional to
// the distance moved, |T − S| in ball units, in radians. When S lies outside the ball the
// rotation is about the view (z) axis instead, by the angle between S and T seen from the
// centre. The result of a drag depends on the path the mouse takes.
//
// Arcball (Shoemake): T is lifted onto the sphere as well, and the ball turns in the plane of
// s and t about the axis s × t by twice the angle between them — as a quaternion
// q = t s* = (s · t, s × t). Because t s* composed over successive samples telescopes,
// (u t*)(t s*) = u s*, a drag's rotation depends only on where it starts and ends: any path
// from S to T gives the same rotation, and a closed mouse loop returns the ball to its start.
//
// Rotations are unit quaternions [w, x, y, z] acting on column vectors, right-handed, in view
// coordinates (x right, y up, z toward the viewer).
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace cg::trackball {

struct BallPoint {
    glm::dvec2 m;   // the mouse position in ball units (the ball is the unit disc)
    glm::dvec3 p;   // its point on the unit sphere
    bool rim;       // outside the ball: pulled onto the silhouette (p.z = 0)
    bool operator==(const BallPoint&) const = default;
};

// The viewport is [0, width] × [0, height] pixels; width, height > 0.
BallPoint to_ball(glm::dvec2 mouse, glm::dvec2 viewport);

// The arcball rotation taking a drag from S to T: q = (s · t, s × t), rotating by twice the
// angle between s and t. Identity when s = t.
glm::dquat arcball(const BallPoint& s, const BallPoint& t);

// The virtual sphere's rotation for one sample pair S → T (see above).
glm::dquat virtual_sphere(const BallPoint& s, const BallPoint& t);

}  // namespace cg::trackball
