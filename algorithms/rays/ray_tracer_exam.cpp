// Exam practice for the ray tracer. Most problems are the course's "trace this ray by hand"
// question: one eye ray into a sphere lit by a point light. Three in ten instead take the same
// scene into distribution ray tracing (some of: several samples per pixel, a thin lens, a
// shutter time with the ball moving, an area light, a glossy ball) and ask the other exam
// question: what each effect spreads its rays over. The numbers are chosen to stay exact: the hit's
// offset from the centre is a Pythagorean triple times r (so t, P and n are short decimals), the
// light sits at P + k (a 3-4-5 direction) so l is exact too, and sometimes a second ball is placed
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

// The by-hand problem.
RayTracer::Input traced_by_hand(Rng& rng) {
    using Input = RayTracer::Input;
    using Granularity = RayTracer::Granularity;
    using RayKind = RayTracer::RayKind;
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
        sc.camera.center = tidy(E + dvec3(0, 0, -1));
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
        const RayTracer::Result res = run_to_end<RayTracer>(RayTracer::start(in));
        const RayTracer::RayNode& primary = res.tree.front();
        if (primary.hit.object != 0 || glm::length(primary.hit.point - P) > 1e-9) continue;
        bool escapes = true;
        int shadow_rays = 0;
        for (const RayTracer::RayNode& n : res.tree) {
            if (n.kind == RayKind::Reflected && n.hit.object >= 0) escapes = false;
            if (n.kind == RayKind::Shadow) ++shadow_rays;
        }
        if (!escapes || shadow_rays != 1) continue;  // the light must face the surface
        return in;
    }
}

// The pixel at the centre of a 9 × 9 image instead of the given ray: it looks straight down at
// the hit.
void centre_pixel(RayTracer::Input& in) {
    in.explicit_ray = false;
    in.scene.camera.width = in.scene.camera.height = 9;
    in.scene.camera.fov_y_deg = 30;
    in.pixel = {4.5, 4.5};
}

// The same scene, distributed, seen through the centre pixel; each effect is on with even odds
// (one at least).
void spread(RayTracer::Input& in, Rng& rng) {
    rt::Scene& sc = in.scene;
    centre_pixel(in);
    sc.settings.seed = static_cast<std::uint64_t>(rng.integer(1, 999));
    bool on[5];
    for (bool& b : on) b = rng.chance(0.5);
    if (!(on[0] || on[1] || on[2] || on[3] || on[4])) on[rng.integer(0, 4)] = true;
    if (on[0]) sc.settings.samples_per_pixel = static_cast<int>(pick(rng, {4, 9, 16}));
    if (on[1]) {
        sc.camera.aperture = pick(rng, {0.05, 0.1, 0.2});
        sc.camera.focal_distance = pick(rng, {4, 5, 6});
    }
    if (on[2]) {
        sc.camera.shutter = pick(rng, {0.5, 1});
        sc.objects[0].velocity =
            rng.chance(0.5) ? dvec3(pick(rng, {0.5, 1}), 0, 0) : dvec3(0, pick(rng, {0.5, 1}), 0);
    }
    if (on[3]) {
        rt::Light& L = sc.lights[0];
        if (rng.chance(0.5)) {
            L.area = rt::Light::Area::Rectangle;
            L.edge_u = {pick(rng, {1, 2}), 0, 0};
            L.edge_v = {0, 0, pick(rng, {1, 2})};
        } else {
            L.area = rt::Light::Area::Disc;
            L.radius = pick(rng, {0.5, 1});
            L.normal = {0, -1, 0};
        }
        L.samples = static_cast<int>(pick(rng, {4, 9, 16}));
    }
    if (on[4]) {
        rt::Material& m = sc.materials[0];
        if (m.kr.x == 0) m.kr = dvec3(0.25);
        m.gloss = pick(rng, {10, 50, 100});
        m.gloss_samples = static_cast<int>(pick(rng, {4, 8}));
    }
}

// Every effect must show in the pixel's ray tree: each primary ray (moved by the lens or the
// shutter) still hits the ball, an area light gets shadow rays, a glossy ball reflects. A draw
// that fails is drawn again; soft shadows alone, which leave the primary ray as it was, always
// pass.
void distribute(RayTracer::Input& in, Rng& rng) {
    for (int attempt = 0;; ++attempt) {
        RayTracer::Input d = in;
        spread(d, rng);
        if (attempt == 20) {  // a ball at the rim of the view: soft shadows only
            d = in;
            centre_pixel(d);
            rt::Light& L = d.scene.lights[0];
            L.area = rt::Light::Area::Disc;
            L.radius = 0.5;
            L.normal = {0, -1, 0};
            L.samples = 4;
        }
        const RayTracer::Result res = run_to_end<RayTracer>(RayTracer::start(d));
        const rt::Distribution want = rt::distribution(d.scene);
        bool all_hit = true, area = false, glossy = false;
        for (const RayTracer::RayNode& n : res.tree) {
            if (n.kind == RayTracer::RayKind::Primary) all_hit = all_hit && n.hit.object == 0;
            area = area || n.light_sample >= 0;
            glossy = glossy || n.glossy;
        }
        if (all_hit && area == want.soft_shadows && glossy == want.glossy_reflection) {
            in = d;
            return;
        }
    }
}

}  // namespace

RayTracer::Input RayTracer::exam_input(Rng& rng) {
    Input in = traced_by_hand(rng);
    if (rng.chance(0.3)) distribute(in, rng);  // drawn last: the by-hand scenes stay as they were
    return in;
}

namespace {

// "what is each effect's rays spread over": the scene's distribution in words.
std::string distribution_question(const RayTracer::Input& in) {
    const rt::Scene& sc = in.scene;
    const rt::Distribution d = rt::distribution(sc);
    const rt::Light& L = sc.lights[0];
    const rt::Material& m = sc.materials[0];
    const rt::Object& ball = sc.objects[0];
    std::string q = "A ball of radius " + num(ball.quadric.r) + " centred at " +
                    num(dvec3(ball.quadric.world_from_model[3])) + ", seen from " +
                    num(sc.camera.eye) +
                    " looking down −z, is rendered by distribution ray tracing:";
    if (d.anti_aliasing)
        q += " " + std::to_string(sc.settings.samples_per_pixel) + " jittered samples per pixel;";
    if (d.depth_of_field)
        q += " a thin lens of radius " + num(sc.camera.aperture) + " focused at distance " +
             num(sc.camera.focal_distance) + ";";
    if (d.motion_blur)
        q += " a shutter open over [0, " + num(sc.camera.shutter) + "] while the ball moves at " +
             num(ball.velocity) + " per unit time;";
    if (d.soft_shadows)
        q += L.area == rt::Light::Area::Rectangle
                 ? " the light is a rectangle at " + num(L.position) + " with edges " +
                       num(L.edge_u) + " and " + num(L.edge_v) + ", sampled by " +
                       std::to_string(L.samples) + " shadow rays;"
                 : " the light is a disc of radius " + num(L.radius) + " at " + num(L.position) +
                       ", sampled by " + std::to_string(L.samples) + " shadow rays;";
    if (d.glossy_reflection)
        q += " the ball is glossy (Phong exponent " + num(m.gloss) + ", " +
             std::to_string(m.gloss_samples) + " reflected rays per hit);";
    q.back() = '.';
    q += " For each effect, name what its rays are distributed over: one of pixel area, lens "
         "aperture, shutter time, light area, Phong lobe.";
    return q;
}

}  // namespace

std::string RayTracer::question(const Input& in) {
    if (rt::distributed(in.scene)) return distribution_question(in);
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

std::vector<std::string> RayTracer::answer_fields(const Input& in) {
    if (!rt::distributed(in.scene))
        return {"t", "point", "normal", "shadowed", "reflected", "color"};
    const rt::Distribution d = rt::distribution(in.scene);
    std::vector<std::string> fields;
    if (d.anti_aliasing) fields.push_back("distributed_over/anti_aliasing");
    if (d.depth_of_field) fields.push_back("distributed_over/depth_of_field");
    if (d.motion_blur) fields.push_back("distributed_over/motion_blur");
    if (d.soft_shadows) fields.push_back("distributed_over/soft_shadows");
    if (d.glossy_reflection) fields.push_back("distributed_over/glossy_reflection");
    return fields;
}

}  // namespace cg
