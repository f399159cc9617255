// Bump mapping, step by step (Blinn's perturbed normal; the formulas and conventions are
// rays/bump.hpp's): at a point P of a surface,
//   the parametrisation: (u, v) and the partials P_u, P_v (rays/uv_map.hpp);
//   the height B(u, v) and its four neighbours at ±h;
//   the central differences B_u, B_v;
//   the normal n = P_u × P_v and the perturbation D = (B_u (n × P_v) − B_v (n × P_u))/|n|;
//   the perturbed normal n' = (n + D)/|n + D|, and how far it tilts from n.
// The geometry does not move: only the normal used for lighting does. The picture shows both
// normals at P and a lit patch of the surface around P beside the same patch unbumped.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "rays/bump.hpp"

namespace cg {

struct BumpMap {
    struct Input {
        UvSurface surface;
        glm::dvec3 point{0.0};  // on the surface
        HeightField height;
        bool has_light = false;
        glm::dvec3 light{0.0};  // the picture's light: the direction toward it (default oblique)
        bool operator==(const Input&) const = default;
    };
    struct Result {
        UvFrame frame;
        BumpResult bump;
        double tilt_deg = 0;  // the angle between n and n'
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Frame, Height, Differences, Normal, Normalise, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Frame;
        Phase last = Phase::Frame;
        PreparedUv prepared;
        Perlin perlin;  // noise heights
        glm::dvec3 outward{0.0};
        Result r;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    static Result solve(const Input& in);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
