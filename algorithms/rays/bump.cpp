#include "rays/bump.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "core/format.hpp"
#include "core/step.hpp"

namespace cg {

using glm::dvec2;
using glm::dvec3;

const char* height_kind_id(HeightKind k) {
    switch (k) {
        case HeightKind::Sines:
            return "sines";
        case HeightKind::Noise:
            return "noise";
        case HeightKind::Image:
            return "image";
    }
    return "";
}

void validate_height(const HeightField& h, const std::string& field) {
    if (!(std::fabs(h.amplitude) <= 1e6))
        throw InputError(field + ".amplitude", "must be a number of magnitude at most 1e6 (got " +
                                                   given(h.amplitude) + ")");
    if (!(h.step >= 1e-9 && h.step <= 0.1))
        throw InputError(field + ".step",
                         "must be between 1e-9 and 0.1: the (u, v) step of the finite "
                         "differences B_u, B_v (got " +
                             given(h.step) + ")");
    switch (h.kind) {
        case HeightKind::Sines:
        case HeightKind::Noise:
            for (int k = 0; k < 2; ++k)
                if (!(std::fabs(h.frequency[k]) <= 1e6))
                    throw InputError(field + ".frequency[" + std::to_string(k) + "]",
                                     "must be a number of magnitude at most 1e6 (got " +
                                         given(h.frequency[k]) + ")");
            return;
        case HeightKind::Image:
            validate_texture(h.image, field + ".image");
            return;
    }
}

double height_at(const HeightField& h, const Perlin& perlin, dvec2 uv) {
    constexpr double kTwoPi = 2 * std::numbers::pi;
    switch (h.kind) {
        case HeightKind::Sines:
            return h.amplitude * std::sin(kTwoPi * h.frequency.x * uv.x) *
                   std::sin(kTwoPi * h.frequency.y * uv.y);
        case HeightKind::Noise:
            return h.amplitude *
                   perlin_noise(perlin, dvec3(h.frequency.x * uv.x, h.frequency.y * uv.y, 0));
        case HeightKind::Image: {
            const TexelTaps t =
                sample_bilinear(h.image.image, wrap_uv(uv, h.image.wrap), h.image.wrap);
            return h.amplitude * (t.color.x + t.color.y + t.color.z) / 3;
        }
    }
    return 0;
}

void bump_heights(const HeightField& h, const Perlin& perlin, dvec2 uv, BumpResult& r) {
    const double s = h.step;
    r.B = height_at(h, perlin, uv);
    r.samples = {height_at(h, perlin, uv + dvec2(s, 0)), height_at(h, perlin, uv - dvec2(s, 0)),
                 height_at(h, perlin, uv + dvec2(0, s)), height_at(h, perlin, uv - dvec2(0, s))};
    r.B_u = (r.samples[0] - r.samples[1]) / (2 * s);
    r.B_v = (r.samples[2] - r.samples[3]) / (2 * s);
}

void bump_normal(const UvFrame& f, dvec3 outward, BumpResult& r) {
    r.n = glm::cross(f.P_u, f.P_v);
    const double len = glm::length(r.n);
    r.singular =
        f.singular || !(len > 1e-12 * glm::length(f.P_u) * glm::length(f.P_v)) || !(len > 0);
    if (r.singular) {
        r.normal = r.perturbed = outward;
        return;
    }
    if (glm::dot(r.n, outward) < 0) {  // mirrored parametrisation: orient n outward
        r.n = -r.n;
        r.flipped = true;
    }
    // With n negated, the formula's D is negated too (it is odd in n): the same bump.
    r.n_cross_pv = glm::cross(r.n, f.P_v);
    r.n_cross_pu = glm::cross(r.n, f.P_u);
    r.D = (r.B_u * r.n_cross_pv - r.B_v * r.n_cross_pu) / len;
    if (r.flipped) r.D = -r.D;
    r.normal = r.n / len;
    r.perturbed = unit(r.n + r.D);
    if (r.perturbed == dvec3(0.0)) r.perturbed = r.normal;
}

BumpResult blinn_bump(const UvFrame& f, dvec3 outward, const HeightField& h, const Perlin& perlin) {
    BumpResult r;
    bump_heights(h, perlin, f.uv, r);
    bump_normal(f, outward, r);
    return r;
}

dvec3 outward_normal(const PreparedUv& p, dvec3 P) {
    switch (p.kind) {
        case UvKind::Quadric:
            return normal_at(p.quadric, P);
        case UvKind::Plane:
            return p.n;
        case UvKind::Triangle:
            return unit(glm::cross(p.e1, p.e2));
    }
    return p.n;
}

}  // namespace cg
