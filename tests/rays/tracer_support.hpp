// What the tracer's tests share: a scene read and validated from its JSON text, and one ray's
// or one pixel's tree stepped to the end.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "io/json.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"
#include "support/traced.hpp"

namespace cg::test {

// A scene file's text as `ray-tracer` reads it (its "stepping" allowed), validated.
inline rt::Scene scene_of(const std::string& text) {
    rt::Scene s = rt::scene_from_json(parse_json(text), {"stepping"});
    rt::validate(s);
    return s;
}

// One given ray's tree, stepped to the end: the result and each step (`events(t)` lists the
// steps' events).
using RayTree = Traced<RayTracer>;

inline RayTree ray_tree(const rt::Scene& s, glm::dvec3 origin, glm::dvec3 direction) {
    RayTracer::Input in;
    in.scene = s;
    in.granularity = RayTracer::Granularity::RayTree;
    in.explicit_ray = true;
    in.ray_origin = origin;
    in.ray_direction = direction;
    return run_traced<RayTracer>(in);
}

// One pixel's tree (the pixel containing `pixel`), stepped to the end with every step narrated.
inline RayTree pixel_tree(const rt::Scene& s, glm::dvec2 pixel) {
    RayTracer::Input in;
    in.scene = s;
    in.granularity = RayTracer::Granularity::RayTree;
    in.pixel = pixel;
    return run_traced<RayTracer>(in);
}

}  // namespace cg::test
