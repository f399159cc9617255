// An independent, straightforward long-double evaluation of the course's lighting model, term
// by term as the formulas read (no shared code with the algorithm).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "rays/phong_lighting.hpp"

namespace cg::test {

using L3 = std::array<long double, 3>;

inline L3 l3(glm::dvec3 v) {
    return {v.x, v.y, v.z};
}
inline long double ldot(const L3& a, const L3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline L3 lnorm(const L3& a) {
    const long double n = std::sqrt(ldot(a, a));
    if (n == 0) return {0, 0, 0};
    return {a[0] / n, a[1] / n, a[2] / n};
}

struct LongLight {
    L3 l{}, r{}, h{};
    long double n_dot_l = 0, r_dot_v = 0, n_dot_h = 0, attenuation = 1;
};
struct LongShade {
    L3 ambient{}, diffuse{}, specular{}, intensity{};
    std::vector<LongLight> lights;
    L3 v{};
};

inline LongShade reference_shade(const PhongLighting::Input& in) {
    LongShade out;
    const L3 P = l3(in.point), n = lnorm(l3(in.normal));
    out.v = lnorm({in.eye.x - P[0], in.eye.y - P[1], in.eye.z - P[2]});
    const L3 v = out.v;
    const auto& m = in.material;
    for (int c = 0; c < 3; ++c) out.ambient[c] = (long double)m.ka[c] * in.ambient[c];
    for (const auto& L : in.lights) {
        LongLight t;
        if (L.directional) {
            const L3 d = lnorm(l3(L.direction));
            t.l = {-d[0], -d[1], -d[2]};
        } else {
            const L3 to{L.position.x - P[0], L.position.y - P[1], L.position.z - P[2]};
            const long double r = std::sqrt(ldot(to, to));
            t.l = lnorm(to);
            t.attenuation =
                1 / ((long double)L.attenuation.x + L.attenuation.y * r + L.attenuation.z * r * r);
        }
        t.n_dot_l = ldot(t.l, n);
        for (int c = 0; c < 3; ++c) t.r[c] = -t.l[c] + 2 * t.n_dot_l * n[c];
        t.r_dot_v = ldot(t.r, v);
        t.h = lnorm({v[0] + t.l[0], v[1] + t.l[1], v[2] + t.l[2]});
        t.n_dot_h = ldot(n, t.h);
        const long double lambert = t.n_dot_l > 0 ? t.n_dot_l : 0;
        long double spec = 0;
        if (t.n_dot_l > 0) {
            const long double c = in.model == PhongLighting::Model::Phong ? t.r_dot_v : t.n_dot_h;
            spec = std::pow(c > 0 ? c : 0.0L, (long double)m.shininess);
        }
        for (int c = 0; c < 3; ++c) {
            out.diffuse[c] += t.attenuation * L.intensity[c] * m.kd[c] * lambert;
            out.specular[c] += t.attenuation * L.intensity[c] * m.ks[c] * spec;
        }
        out.lights.push_back(t);
    }
    for (int c = 0; c < 3; ++c)
        out.intensity[c] = out.ambient[c] + out.diffuse[c] + out.specular[c];
    return out;
}

}  // namespace cg::test
