// An independent recursive ray tracer in long double, written from the course's formulas with
// no code shared with rays/rt_scene.cpp: quadrics through quadric_reference.hpp's long-double
// solver (the ray and the quadric's matrix carried to world space), planes and triangles solved
// by Cramer's rule on E + t d = P0 + β e1 + γ e2, lighting by phong_reference.hpp, and the mirror
// and Snell directions as the textbook writes them. It follows the same conventions (screen,
// offsets of secondary rays, facing normals, total internal reflection) so that the two tracers
// must agree away from the edges of objects and shadows.
#pragma once

#include <cmath>
#include <random>

#include "rays/phong_reference.hpp"
#include "rays/quadric_reference.hpp"
#include "rays/rt_scene.hpp"

namespace cg::test {

struct RefHit {
    int object = -1;
    long double t = 0;
    L3 point{}, normal{};  // normal: unit, facing the ray
    bool entering = true;
    long double second = INFINITY;  // the next nearest t among the other objects (for margins)
};

class ReferenceTracer {
  public:
    explicit ReferenceTracer(const rt::Scene& s) : s_(s) {
        long double scale = 1;
        scale = std::max(scale, len(l3(s.camera.eye)));
        scale = std::max(scale, len(l3(s.camera.center)));
        for (const rt::Object& o : s.objects) {
            if (o.kind == rt::ObjectKind::Quadric)
                scale = std::max(scale, len(l3(glm::dvec3(o.quadric.world_from_model[3]))));
            else
                scale = std::max({scale, len(l3(o.p0)),
                                  o.kind == rt::ObjectKind::Triangle ? len(l3(o.p1)) : 0.0L,
                                  o.kind == rt::ObjectKind::Triangle ? len(l3(o.p2)) : 0.0L});
        }
        eps_ = 1e-7L * scale;
    }

    // The smallest gap seen between the nearest and the next hit, or between a shadow ray's
    // blocker and its light: a ray near such a tie may be decided either way by round-off.
    long double min_margin = INFINITY;

    L3 pixel(int i, int j) {
        const rt::Camera& c = s_.camera;
        const L3 eye = l3(c.eye);
        const L3 w = norm(sub(l3(c.center), eye));
        const L3 u = norm(cross(w, norm(l3(c.up))));
        const L3 v = cross(u, w);
        const long double hh = std::tan((long double)c.fov_y_deg * 3.14159265358979323846L / 360);
        const long double hw = hh * c.width / c.height;
        const long double sx = (2 * (i + 0.5L) / c.width - 1) * hw;
        const long double sy = (2 * (j + 0.5L) / c.height - 1) * hh;
        L3 P;
        for (int k = 0; k < 3; ++k) P[k] = eye[k] + w[k] + sx * u[k] + sy * v[k];
        return trace(eye, sub(P, eye), 0);
    }

    L3 trace(const L3& o, const L3& d, int depth) {
        const RefHit h = nearest(o, d, 1e-9L, INFINITY);
        if (h.object < 0) return l3(s_.background);
        min_margin = std::min(min_margin, (h.second - h.t) / std::max(1.0L, h.t));
        const rt::Material& m = s_.materials[s_.objects[h.object].material];
        const L3 dn = norm(d);
        const L3 v{-dn[0], -dn[1], -dn[2]};
        L3 c{};
        for (int k = 0; k < 3; ++k) c[k] = (long double)m.ka[k] * s_.ambient[k];
        for (const rt::Light& light : s_.lights) {
            // The lighting terms from the long-double model of phong_reference.hpp.
            PhongLighting::Input in;
            in.model = s_.settings.model == rt::Model::Phong ? PhongLighting::Model::Phong
                                                             : PhongLighting::Model::BlinnPhong;
            in.point = dv(h.point);
            in.normal = dv(h.normal);
            in.eye = dv(add(h.point, v));
            in.material.kd = m.kd, in.material.ks = m.ks, in.material.shininess = m.shininess;
            PhongLighting::Light L;
            L.directional = light.directional;
            L.position = light.position;
            L.direction = light.direction;
            L.intensity = light.intensity;
            L.attenuation = light.attenuation;
            in.lights = {L};
            const LongShade sh = reference_shade(in);
            const LongLight& t = sh.lights[0];
            if (!(t.n_dot_l > 0)) continue;
            if (s_.settings.shadows) {
                long double dist = INFINITY;
                if (!light.directional) dist = len(sub(l3(light.position), h.point));
                const L3 from = offset(h.point, h.normal);
                const RefHit b = nearest(from, t.l, 1e-9L, dist);
                if (b.object >= 0) {
                    min_margin = std::min(min_margin, (dist - b.t) / std::max(1.0L, dist));
                    continue;
                }
                if (b.second < INFINITY)
                    min_margin = std::min(min_margin, (b.second - dist) / std::max(1.0L, dist));
            }
            for (int k = 0; k < 3; ++k) c[k] += sh.diffuse[k] + sh.specular[k];
        }
        if (depth >= s_.settings.max_depth) return c;
        const long double dn_n = ldot(dn, h.normal);
        L3 r;
        for (int k = 0; k < 3; ++k) r[k] = dn[k] - 2 * dn_n * h.normal[k];
        if (s_.settings.reflections && positive(m.kr)) {
            const L3 cr = trace(offset(h.point, h.normal), r, depth + 1);
            for (int k = 0; k < 3; ++k) c[k] += m.kr[k] * cr[k];
        }
        if (s_.settings.refractions && positive(m.kt)) {
            const long double eta = h.entering ? 1 / (long double)m.ior : m.ior;
            const long double c1 = -dn_n;
            const long double k2 = 1 - eta * eta * (1 - c1 * c1);
            L3 ct;
            if (k2 < 0) {
                ct = trace(offset(h.point, h.normal), r, depth + 1);
            } else {
                L3 t;
                for (int k = 0; k < 3; ++k)
                    t[k] = eta * dn[k] + (eta * c1 - std::sqrt(k2)) * h.normal[k];
                const L3 back{-h.normal[0], -h.normal[1], -h.normal[2]};
                ct = trace(offset(h.point, back), norm(t), depth + 1);
            }
            for (int k = 0; k < 3; ++k) c[k] += m.kt[k] * ct[k];
        }
        return c;
    }

    RefHit nearest(const L3& o, const L3& d, long double t_min, long double t_max) {
        RefHit h;
        long double best = t_max;
        for (std::size_t k = 0; k < s_.objects.size(); ++k) {
            L3 n{};
            const long double t = intersect(s_.objects[k], o, d, t_min, n);
            if (t < best) {
                h.second = std::min(h.second, best);
                best = t;
                h.object = static_cast<int>(k);
                h.normal = n;
            } else {
                h.second = std::min(h.second, t);
            }
        }
        if (h.object < 0) return h;
        h.t = best;
        for (int k = 0; k < 3; ++k) h.point[k] = o[k] + best * d[k];
        if (h.normal == L3{0, 0, 0}) h.normal = norm(L3{-d[0], -d[1], -d[2]});
        h.entering = ldot(h.normal, d) <= 0;
        if (!h.entering) h.normal = {-h.normal[0], -h.normal[1], -h.normal[2]};
        return h;
    }

  private:
    long double intersect(const rt::Object& obj, const L3& o, const L3& d, long double t_min,
                          L3& n) const {
        switch (obj.kind) {
            case rt::ObjectKind::Quadric: {
                const LongHit h = reference_intersect(obj.quadric, dv(o), dv(d), t_min);
                if (!h.hit) return INFINITY;
                n = h.normal;
                return h.t;
            }
            case rt::ObjectKind::Plane: {
                const L3 nn = norm(l3(obj.normal));
                const long double dn = ldot(d, nn);
                if (dn == 0) return INFINITY;
                const long double t = ldot(sub(l3(obj.p0), o), nn) / dn;
                n = nn;
                return t > t_min ? t : INFINITY;
            }
            case rt::ObjectKind::Triangle: {
                // [e1 e2 −d] (β, γ, t)ᵀ = E − P0, by Cramer's rule.
                const L3 e1 = sub(l3(obj.p1), l3(obj.p0)), e2 = sub(l3(obj.p2), l3(obj.p0));
                const L3 md{-d[0], -d[1], -d[2]}, rhs = sub(o, l3(obj.p0));
                const long double det = ldot(e1, cross(e2, md));
                if (det == 0) return INFINITY;
                const long double beta = ldot(rhs, cross(e2, md)) / det;
                const long double gamma = ldot(e1, cross(rhs, md)) / det;
                const long double t = ldot(e1, cross(e2, rhs)) / det;
                if (beta < 0 || gamma < 0 || beta + gamma > 1 || !(t > t_min)) return INFINITY;
                n = norm(cross(e1, e2));
                return t;
            }
            case rt::ObjectKind::Csg:
                break;  // the random reference scenes have no CSG objects (test_rt_csg.cpp)
            case rt::ObjectKind::Mesh:
                break;  // nor meshes (test_rt_mesh.cpp, test_rt_bvh.cpp)
        }
        return INFINITY;
    }

    L3 offset(const L3& p, const L3& n) const {
        return {p[0] + eps_ * n[0], p[1] + eps_ * n[1], p[2] + eps_ * n[2]};
    }
    static bool positive(const glm::dvec3& c) { return c.x > 0 || c.y > 0 || c.z > 0; }
    static L3 sub(const L3& a, const L3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
    static L3 add(const L3& a, const L3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
    static L3 cross(const L3& a, const L3& b) {
        return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    static long double len(const L3& a) { return std::sqrt(ldot(a, a)); }
    static L3 norm(const L3& a) { return lnorm(a); }
    static glm::dvec3 dv(const L3& a) { return {double(a[0]), double(a[1]), double(a[2])}; }

    const rt::Scene& s_;
    long double eps_ = 1e-7L;
};

}  // namespace cg::test
