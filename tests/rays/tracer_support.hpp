// What the tracer's tests share: a scene read and validated from its JSON text, and one ray's
// tree stepped to the end.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/step.hpp"
#include "io/json.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"

namespace cg::test {

// A scene file's text as `ray-tracer` reads it (its "stepping" allowed), validated.
inline rt::Scene scene_of(const std::string& text) {
    rt::Scene s = rt::scene_from_json(parse_json(text), {"stepping"});
    rt::validate(s);
    return s;
}

// One given ray's tree, stepped to the end: the result, and each step with its event.
struct RayTree {
    RayTracer::Result result;
    std::vector<StepInfo> steps;
    std::vector<std::string> events;
};

inline RayTree ray_tree(const rt::Scene& s, glm::dvec3 origin, glm::dvec3 direction) {
    RayTracer::Input in;
    in.scene = s;
    in.granularity = RayTracer::Granularity::RayTree;
    in.explicit_ray = true;
    in.ray_origin = origin;
    in.ray_direction = direction;
    auto st = RayTracer::start(in);
    RayTree t;
    while (!RayTracer::done(st)) {
        StepInfo info;
        RayTracer::step(st, &info);
        t.events.push_back(info.event);
        t.steps.push_back(std::move(info));
    }
    t.result = RayTracer::result(st);
    return t;
}

}  // namespace cg::test
