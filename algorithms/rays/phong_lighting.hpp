// The course's lighting model at one surface point, term by term (Phong and Blinn-Phong):
//
//   I = k_a I_a + Σ_i  I_i / (c1 + c2 r_i + c3 r_i²) · ( k_d max(l_i·n, 0) + k_s S_i )
//   Phong:        S_i = max(r_i·v, 0)^p,   r_i = −l_i + 2(l_i·n) n   (l_i mirrored about n)
//   Blinn-Phong:  S_i = max(h_i·n, 0)^p,   h_i = (v + l_i)/|v + l_i| (the halfway vector)
//
// Conventions. Products of colours are per channel (r, g, b); a scalar is the same number on
// every channel, and the result is a scalar when every coefficient and intensity was one.
// n is the given normal normalised; v = (E − P)/|E − P| points from the point to the eye; l
// points from the point toward the light: for a point light l = (L − P)/|L − P| and r = |L − P|
// is its distance, attenuated by 1/(c1 + c2 r + c3 r²) (default c = (1, 0, 0): none); a
// directional light is given by the direction its light TRAVELS (the sun's rays, pointing down
// for a sun overhead), so l = −direction/|direction|, and it is never attenuated. Negative dot
// products clamp to 0; a light behind the surface (l·n ≤ 0) contributes neither diffuse nor
// specular light, even where r·v or h·n would be positive. 0⁰ = 1 (shininess 0 makes the
// highlight cover the whole lit side). When v + l = 0 there is no halfway vector: h = 0 and
// Blinn-Phong's term is 0 (the light is then behind the surface for an eye in front). The
// result is not clamped to [0, 1]: a display clamps it. The reported dot products are the raw
// (signed) values; the terms use the clamped ones.
//
// Steps: the unit vectors n and v; the ambient term; per light: its direction and attenuation,
// the diffuse (Lambert) term, the specular term; the total.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct PhongLighting {
    enum class Model : std::uint8_t { Phong, BlinnPhong };
    using Color = glm::dvec3;  // r, g, b; a scalar is stored on all three

    struct Light {
        bool directional = false;
        glm::dvec3 position{0.0};         // a point light's position (world)
        glm::dvec3 direction{0.0};        // a directional light's direction of travel
        Color intensity{1.0};             // I_i, ≥ 0
        glm::dvec3 attenuation{1, 0, 0};  // c1, c2, c3 ≥ 0, not all 0; point lights only
        bool operator==(const Light&) const = default;
    };
    struct Material {
        Color ka{0.0}, kd{0.0}, ks{0.0};  // ≥ 0
        double shininess = 1;             // p ≥ 0
        bool operator==(const Material&) const = default;
    };
    struct Input {
        Model model = Model::Phong;
        glm::dvec3 point{0.0};       // P
        glm::dvec3 normal{0, 0, 1};  // n (any length > 0)
        glm::dvec3 eye{0, 0, 1};     // E ≠ P
        Color ambient{0.0};          // I_a
        Material material;
        std::vector<Light> lights;
        bool rgb = false;  // some colour was given as [r, g, b]: report colours, not scalars
        bool operator==(const Input&) const = default;
    };

    struct LightTerms {
        glm::dvec3 l{0.0}, r{0.0}, h{0.0};             // unit (h = 0 when v + l = 0)
        double n_dot_l = 0, r_dot_v = 0, n_dot_h = 0;  // raw, signed
        double distance = 0;                // |L − P| for a point light; 0 for a directional one
        double attenuation = 1;             // 1/(c1 + c2 r + c3 r²); 1 for a directional light
        Color diffuse{0.0}, specular{0.0};  // this light's two terms
        bool operator==(const LightTerms&) const = default;
    };
    struct Result {
        Color intensity{0.0}, ambient{0.0}, diffuse{0.0}, specular{0.0};
        std::vector<LightTerms> lights;
        glm::dvec3 n{0.0}, v{0.0};
        bool rgb = false;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { View, Ambient, LightDir, Diffuse, Specular, Total, Done };

    struct State {
        Shared<Input> in;  // never changes during a run: copies of the state share it
        Phase phase = Phase::View;
        Phase last = Phase::View;
        int k = -1;  // the light being worked on
        Result out;  // filled as the steps go
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    // The checks that do not depend on the point: the ambient light, the material and each
    // light's intensity, direction and attenuation constants (not its distance to the point).
    // For callers that light many points with one Input (the shading of a mesh).
    static void validate_lighting(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // start() for an input already validated
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.out; }
    static Result result(State&& s) { return std::move(s.out); }
    static void draw(const State& s, Scene& scene);

    // Exam practice (phong_lighting_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The whole model as one plain function (benchmark; a tracer's shading).
    static Result shade(const Input& in);
    // The same at another point and normal, with in's eye, lights and material (in.point and
    // in.normal are not read): a mesh's shading lights many points with one Input.
    static Result shade(const Input& in, glm::dvec3 point, glm::dvec3 normal);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
