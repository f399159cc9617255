// The 3D canvas's camera: a perspective camera orbiting a target point.
//
// A world point p is first turned into view coordinates, v = rotation · (p − target) (x right,
// y up, z toward the viewer), then seen by a pinhole camera sitting at (0, 0, distance) in
// view coordinates and looking down −z: depth d = distance − v.z, screen = centre +
// f · (v.x, −v.y) / d with f = (height / 2) / tan(fov / 2) pixels. Orbiting changes only
// `rotation`, by the project's own arcball (algorithms/transforms/trackball.hpp): a drag from
// S to T multiplies it by the arcball rotation from S to T, so the view depends only on where
// the drag went, never on the path the mouse took there.
#pragma once

#include <optional>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "transforms/trackball.hpp"
#include "viewer/geometry.hpp"

namespace cg::viewer {

struct View3 {
    glm::dquat rotation{1, 0, 0, 0};  // world → view
    glm::dvec3 target{0, 0, 0};       // the point orbited, at the canvas's centre
    double distance = 10;             // from the camera to the target
    double fov_y_deg = 30;
    // Orthographic: parallel projection, `focal() / distance` pixels per world unit at any
    // depth (a planar construction seen face-on keeps its right angles and lengths).
    bool orthographic = false;
};

// The camera with the interaction's memory: a drag remembers where it started.
struct Camera3 {
    View3 view;
    bool orbiting = false, panning = false;
    trackball::BallPoint grab{};         // S: where the orbit drag started, on the ball
    glm::dquat grab_rotation{1, 0, 0, 0};  // the rotation when it started
};

// World → screen for one canvas.
struct Projector {
    Box canvas;
    View3 view;

    glm::dvec3 to_view(glm::dvec3 p) const { return view.rotation * (p - view.target); }
    // Distance in front of the camera (> 0 in front); orthographically, only an order.
    double depth(glm::dvec3 v) const { return view.distance - v.z; }
    // Nothing is cut orthographically: the camera sees the whole slab.
    double near() const { return view.orthographic ? -1e300 : 0.02 * view.distance; }
    double focal() const;  // pixels
    glm::dvec2 centre() const { return (canvas.min + canvas.max) * 0.5; }
    // Screen position of a view-space point in front of the near plane.
    glm::dvec2 project_view(glm::dvec3 v) const;
    std::optional<glm::dvec2> screen(glm::dvec3 world) const;
};

// The default orientation: looking at the origin from above the +x/+z quadrant, y up.
glm::dquat default_rotation();

// The rotation (world → view) of a camera looking along `look` with `up` up on screen; the
// default rotation when `look` is zero or parallel to `up`.
glm::dquat look_rotation(glm::dvec3 look, glm::dvec3 up);

}  // namespace cg::viewer
