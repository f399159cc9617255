// Exam practice for the ray tracer: one eye ray into a sphere lit by a point light, the course's
// "trace this ray by hand" question. The numbers are chosen to stay exact: the hit's offset
// from the centre is a Pythagorean triple times r (so t, P and n are short decimals), the light
// sits at P + k (a 3-4-5 direction) so l is exact too, and sometimes a second ball is placed
// on the shadow ray, or the surface is a mirror whose ray escapes to the background.
#include <cmath>

#include "core/format.hpp"
#include "rays/ray_tracer.hpp"

namespace cg {

using glm::dvec3;

namespace {

// Unit offsets with short decimal coordinates: (a, b, c), a² + b² + c² = 1, c > 0 (toward the eye).
const dvec3 kOffsets[] = {{0, 0, 1},          {0.6, 0, 0.8},    {0, 0.6, 0.8}, {-0.6, 0, 0.8},
                          {0, -0.6, 0.8},     {0.8, 0, 0.6},    {0, 0.8, 0.6}, {0.48, 0.64, 0.6},
                          {-0.48, 0.64, 0.6}, {0.36, 0.48, 0.8}};
// Unit directions toward the light, 3-4-5 and axis ones.
const dvec3 kToLight[] = {{0, 0.6, 0.8},  {0.6, 0, 0.8}, {0, 0.8, 0.6}, {0.8, 0, 0.6},
                          {-0.6, 0, 0.8}, {0, 0, 1},     {0.6, 0.8, 0}, {0, 1, 0}};

// Short decimals stay short: 0.8 − 1 is −0.19999999999999996 in binary, written −0.2.
dvec3 tidy(dvec3 v) {
    for (int k = 0; k < 3; ++k) v[k] = std::round(v[k] * 1e6) / 1e6;
    return v;
}

double pick(Rng& rng, std::initializer_list<double> xs) {
    const auto k = rng.integer(0, static_cast<long long>(xs.size()) - 1);
    return *(xs.begin() + k);
}

}  // namespace

RayTracer::Input RayTracer::exam_input(Rng& rng) {
    for (;;) {
        Input in;
        rt::Scene& sc = in.scene;
        const double r = pick(rng, {1, 2, 0.5});
        const dvec3 C(rng.integer(-2, 2), rng.integer(-1, 1), rng.integer(-3, 0));
        const dvec3 off = kOffsets[rng.integer(0, 9)];
        const dvec3 P = tidy(C + r * off);  // the hit
        const double h = pick(rng, {4, 5, 6});
        const dvec3 E(P.x, P.y, P.z + h);  // straight down −z onto P
        in.explicit_ray = true;
        in.granularity = Granularity::RayTree;
        in.ray_origin = E;
        in.ray_direction = {0, 0, pick(rng, {-1, -2})};

        sc.camera.eye = E;
        sc.camera.center = E + dvec3(0, 0, -1);
        sc.settings.max_depth = 1;
        sc.settings.model = rng.chance(0.5) ? rt::Model::Phong : rt::Model::BlinnPhong;
        sc.background = dvec3(pick(rng, {0, 0.1, 0.2}));
        sc.ambient = dvec3(pick(rng, {0.1, 0.2}));

        rt::Material m;
        m.name = "ball";
        m.ka = dvec3(pick(rng, {0.2, 0.5, 1}));
        m.kd = dvec3(pick(rng, {0.4, 0.5, 0.6}));
        m.ks = dvec3(pick(rng, {0.2, 0.3, 0.5}));
        m.shininess = pick(rng, {1, 2, 4, 10});
        m.kr = dvec3(rng.chance(0.4) ? pick(rng, {0.25, 0.5}) : 0.0);
        sc.materials.push_back(m);

        const dvec3 l = kToLight[rng.integer(0, 7)];
        const double dist = pick(rng, {5, 10});
        rt::Light light;
        light.position = tidy(P + dist * l);
        light.intensity = dvec3(pick(rng, {0.8, 1}));
        sc.lights.push_back(light);

        rt::Object ball;
        ball.kind = rt::ObjectKind::Quadric;
        ball.name = "ball";
        ball.field = "objects[0]";
        ball.quadric.kind = QuadricKind::Sphere;
        ball.quadric.r = r;
        ball.quadric.world_from_model[3] = glm::dvec4(C, 1);
        sc.objects.push_back(ball);
        if (rng.chance(0.35)) {  // a small ball halfway to the light: a shadow
            rt::Object blocker = ball;
            blocker.name = "blocker";
            blocker.field = "objects[1]";
            blocker.quadric.r = 0.5;
            blocker.quadric.world_from_model[3] = glm::dvec4(tidy(P + (dist / 2) * l), 1);
            sc.objects.push_back(blocker);
        }
        // Keep problems a student can finish by hand: the eye ray hits the ball where we aimed
        // (facing the light), and a mirror ray escapes.
        State s = start(in);
        while (!done(s)) step(s, nullptr);
        const Result res = result(s);
        const RayNode& primary = res.tree.front();
        if (primary.hit.object != 0 || glm::length(primary.hit.point - P) > 1e-9) continue;
        bool escapes = true;
        int shadow_rays = 0;
        for (const RayNode& n : res.tree) {
            if (n.kind == RayKind::Reflected && n.hit.object >= 0) escapes = false;
            if (n.kind == RayKind::Shadow) ++shadow_rays;
        }
        if (!escapes || shadow_rays != 1) continue;  // the light must face the surface
        return in;
    }
}

std::string RayTracer::question(const Input& in) {
    const rt::Scene& sc = in.scene;
    const rt::Material& m = sc.materials[0];
    const rt::Light& L = sc.lights[0];
    std::string q = "Trace the eye ray $E + t\\,d$ with $E = " + tex(in.ray_origin) +
                    "$ and $d = " + tex(in.ray_direction) + "$. The scene: ";
    for (std::size_t k = 0; k < sc.objects.size(); ++k) {
        const rt::Object& o = sc.objects[k];
        q += std::string(k ? "; " : "") + "a sphere \"" + o.name + "\" of radius " +
             num(o.quadric.r) + " centred at " + num(dvec3(o.quadric.world_from_model[3]));
    }
    q += ", all of one material with $k_a = " + tex(m.ka.x) + "$, $k_d = " + tex(m.kd.x) +
         "$, $k_s = " + tex(m.ks.x) + "$, $p = " + tex(m.shininess) + "$" +
         (m.kr.x > 0 ? ", and mirror share $k_r = " + tex(m.kr.x) + "$" : std::string()) +
         "; a point light at " + num(L.position) + " of intensity " + num(L.intensity.x) +
         " (no attenuation); ambient $I_a = " + tex(sc.ambient.x) + "$; background " +
         num(sc.background.x) + ". Use the " +
         (sc.settings.model == rt::Model::Phong ? "Phong" : "Blinn-Phong") +
         " model, shadow rays, and at most one level of reflection. Give t of the first hit, the "
         "hit point, the unit normal there, whether the shadow ray is blocked (a list, one entry "
         "per light), the mirror ray's direction (none if the surface is not a mirror) and the "
         "colour of the ray.";
    return q;
}

std::vector<std::string> RayTracer::answer_fields() {
    return {"t", "point", "normal", "shadowed", "reflected", "color"};
}

}  // namespace cg
