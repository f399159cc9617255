// Sections: [validate] [prepare and the camera] [intersection] [shading] [the plain tracer]
#include "rays/rt_scene.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <thread>

#include "core/format.hpp"
#include "core/step.hpp"
#include "rays/rt_csg.hpp"

namespace cg::rt {

using glm::dvec3;

// ---- [validate] -----------------------------------------------------------------------------

namespace {

std::string at(const std::string& list, std::size_t i) {
    return list + "[" + std::to_string(i) + "]";
}

void check_colour(const Color& c, const std::string& field) {
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(c[k]) || c[k] < 0 || c[k] > 1e6)
            throw InputError(
                field, "must be a colour with components in [0, 1e6] (got " + num(c, 6) + ")");
}

void check_nonzero(dvec3 v, const std::string& field, const char* what) {
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (m == 0) throw InputError(field, std::string("must not be the zero vector: it is ") + what);
    if (!(m >= 1e-150))
        throw InputError(
            field, std::string("is too short to give a direction (largest component ") + num(m) +
                       " < 1e-150): it is " + what);
}

}  // namespace

void check_coordinates(dvec3 p, const std::string& field) {
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(p[k]) || std::fabs(p[k]) > kMaxCoordinate)
            throw InputError(
                field + "[" + std::to_string(k) + "]",
                "must be a finite number of magnitude at most 1e12 (got " + num(p[k]) + ")");
}

double tree_rays(const Scene& s) {
    bool mirrors = false, glass = false;
    for (const Material& m : s.materials) {
        mirrors = mirrors || (s.settings.reflections && any_positive(m.kr));
        glass = glass || (s.settings.refractions && any_positive(m.kt));
    }
    const int d = s.settings.max_depth;
    if (mirrors && glass) return std::ldexp(1.0, d + 1) - 1;
    if (mirrors || glass) return d + 1.0;
    return 1;
}

double scene_tests(const Scene& s) {
    double n = 0;
    for (const Object& o : s.objects) n += static_cast<double>(object_tests(o));
    return n;
}

double pixel_work(const Scene& s) {
    return tree_rays(s) * (1.0 + static_cast<double>(s.lights.size())) *
           std::max<double>(1, scene_tests(s));
}

void validate(const Scene& s) {
    const Camera& c = s.camera;
    check_coordinates(c.eye, "camera.eye");
    check_coordinates(c.center, "camera.center");
    check_coordinates(c.up, "camera.up");
    const dvec3 view = c.center - c.eye;
    check_nonzero(view, "camera.center", "center − eye, the direction the camera looks in");
    check_nonzero(c.up, "camera.up", "the camera's up direction");
    const dvec3 wv = unit(view), wu = unit(c.up);
    if (glm::length(glm::cross(wv, wu)) < 1e-9)
        throw InputError("camera.up", "must not be parallel to the view direction center − eye " +
                                          num(view, 4) + ": the screen's orientation is undefined");
    if (!(c.fov_y_deg >= 0.01 && c.fov_y_deg <= 179))
        throw InputError(
            "camera.fov_y_deg",
            "must be a field of view between 0.01° and 179° (got " + num(c.fov_y_deg) + ")");
    if (c.width < 1 || c.height < 1)
        throw InputError("camera.size", "must be at least 1×1 pixels (got " +
                                            std::to_string(c.width) + "×" +
                                            std::to_string(c.height) + ")");
    if (static_cast<long long>(c.width) * c.height > kMaxPixels)
        throw InputError("camera.size",
                         "has " + std::to_string(static_cast<long long>(c.width) * c.height) +
                             " pixels; the limit is 4096 × 4096 = 16777216");
    if (s.settings.max_depth < 0 || s.settings.max_depth > kMaxDepth)
        throw InputError("settings.max_depth", "must be between 0 and " +
                                                   std::to_string(kMaxDepth) + " (got " +
                                                   std::to_string(s.settings.max_depth) + ")");
    check_colour(s.background, "background");
    check_colour(s.ambient, "ambient");

    if (s.materials.empty()) throw InputError("materials", "must list at least one material");
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const Material& m = s.materials[i];
        const std::string f = at("materials", i);
        check_colour(m.ka, f + ".ka");
        check_colour(m.kd, f + ".kd");
        check_colour(m.ks, f + ".ks");
        check_colour(m.kr, f + ".kr");
        check_colour(m.kt, f + ".kt");
        if (!(m.shininess >= 0 && m.shininess <= 1e4))
            throw InputError(f + ".shininess", "must be an exponent between 0 and 10000 (got " +
                                                   num(m.shininess) + ")");
        if (!(m.ior >= 0.01 && m.ior <= 100))
            throw InputError(f + ".ior", "must be a refraction index between 0.01 and 100 (got " +
                                             num(m.ior) + ")");
    }

    if (s.lights.size() > kMaxLights)
        throw InputError("lights", "has " + std::to_string(s.lights.size()) +
                                       " lights; the limit is " + std::to_string(kMaxLights));
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        const Light& l = s.lights[i];
        const std::string f = at("lights", i);
        check_colour(l.intensity, f + ".intensity");
        if (l.directional) {
            check_coordinates(l.direction, f + ".direction");
            check_nonzero(l.direction, f + ".direction", "the way the light travels");
        } else {
            check_coordinates(l.position, f + ".position");
            const dvec3 a = l.attenuation;
            if (!(a.x >= 0 && a.y >= 0 && a.z >= 0 && a.x <= 1e6 && a.y <= 1e6 && a.z <= 1e6))
                throw InputError(
                    f + ".attenuation",
                    "must be three coefficients c1, c2, c3 in [0, 1e6] (got " + num(a) + ")");
            if (a.x == 0 && a.y == 0 && a.z == 0)
                throw InputError(f + ".attenuation",
                                 "must not be all zero: 1/(c1 + c2 r + c3 r²) would be infinite");
        }
    }

    if (scene_tests(s) > static_cast<double>(kMaxObjects))
        throw InputError("objects", "has " + num(scene_tests(s)) +
                                        " objects (triangles and CSG leaves counted one by one); "
                                        "the limit is " +
                                        std::to_string(kMaxObjects));
    // What a run would cost, now that the counts are known to be sane.
    const double per_pixel = pixel_work(s);
    if (per_pixel > kMaxPixelWork)
        throw InputError(
            tree_rays(s) > 64 ? "settings.max_depth" : "objects",
            "makes one pixel cost up to " + num(per_pixel, 3) + " ray-object tests (" +
                num(tree_rays(s)) + " rays per tree × " + std::to_string(s.lights.size() + 1) +
                " for the lights × " + num(scene_tests(s)) +
                " objects); the limit is 1e7: lower max_depth, or use fewer objects or lights");
    const double total = per_pixel * c.width * c.height;
    if (total > kMaxWork)
        throw InputError("camera.size", "makes the image cost up to " + num(total, 3) +
                                            " ray-object tests (" + std::to_string(c.width) + "×" +
                                            std::to_string(c.height) + " pixels × " +
                                            num(per_pixel, 3) +
                                            " per pixel); the limit is 2e10: use fewer pixels");
    for (const Object& o : s.objects) {
        if (o.material < 0 || o.material >= static_cast<int>(s.materials.size()))
            throw InputError(o.field + ".material", "names no material");
        switch (o.kind) {
            case ObjectKind::Quadric:
                validate_quadric(o.quadric, o.field);
                check_coordinates(dvec3(o.quadric.world_from_model[3]),
                                  o.field + ".transform[][3]");
                break;
            case ObjectKind::Plane:
                check_coordinates(o.p0, o.field + ".point");
                check_coordinates(o.normal, o.field + ".normal");
                check_nonzero(o.normal, o.field + ".normal", "the plane's normal");
                break;
            case ObjectKind::Triangle: {
                check_coordinates(o.p0, o.field + "[0]");
                check_coordinates(o.p1, o.field + "[1]");
                check_coordinates(o.p2, o.field + "[2]");
                const dvec3 e1 = o.p1 - o.p0, e2 = o.p2 - o.p0;
                const double area2 = glm::length(glm::cross(e1, e2));
                if (!(area2 > 1e-12 * glm::length(e1) * glm::length(e2)) || !(area2 > 0))
                    throw InputError(o.field, "is degenerate: its corners " + num(o.p0, 4) + ", " +
                                                  num(o.p1, 4) + ", " + num(o.p2, 4) +
                                                  " are collinear or coincide (zero area)");
                break;
            }
            case ObjectKind::Csg:
                validate_csg_object(o);
                break;
        }
    }
    validate_textures(s);
}

// ---- [prepare and the camera] ---------------------------------------------------------------

View make_view(const Camera& c) {
    View v;
    v.eye = c.eye;
    v.w = unit(c.center - c.eye);
    v.u = unit(glm::cross(v.w, unit(c.up)));
    v.v = glm::cross(v.u, v.w);
    v.half_height = std::tan(glm::radians(c.fov_y_deg) / 2);
    v.half_width = v.half_height * c.width / c.height;
    v.width = c.width;
    v.height = c.height;
    return v;
}

dvec3 screen_point(const View& v, double x, double y) {
    const double sx = (2 * x / v.width - 1) * v.half_width;
    const double sy = (2 * y / v.height - 1) * v.half_height;
    return v.eye + v.w + sx * v.u + sy * v.v;
}

Prepared prepare(const Scene& s) {
    Prepared p;
    p.view = make_view(s.camera);
    double scale = std::max({1.0, glm::length(s.camera.eye), glm::length(s.camera.center)});
    p.objects.reserve(s.objects.size());
    for (const Object& o : s.objects) {
        PreparedObject q;
        q.kind = o.kind;
        q.material = o.material;
        switch (o.kind) {
            case ObjectKind::Quadric:
                q.quadric = cg::prepare(o.quadric);
                scale = std::max(scale, glm::length(dvec3(o.quadric.world_from_model[3])));
                break;
            case ObjectKind::Plane:
                q.p0 = o.p0;
                q.normal = unit(o.normal);
                scale = std::max(scale, glm::length(o.p0));
                break;
            case ObjectKind::Triangle:
                q.p0 = o.p0;
                q.e1 = o.p1 - o.p0;
                q.e2 = o.p2 - o.p0;
                q.normal = unit(glm::cross(q.e1, q.e2));
                scale = std::max({scale, glm::length(o.p0), glm::length(o.p1), glm::length(o.p2)});
                break;
            case ObjectKind::Csg:
                q.csg = Shared<PreparedCsg>(prepare_csg(o.csg));
                for (const PreparedCsgLeaf& l : q.csg->leaves)
                    scale = std::max(scale, glm::length(l.quadric.translation));
                break;
        }
        p.objects.push_back(q);
    }
    p.epsilon = 1e-7 * scale;
    p.textures = prepare_textures(s);
    return p;
}

// ---- [intersection] -------------------------------------------------------------------------

double intersect_object(const PreparedObject& o, dvec3 origin, dvec3 d, double t_min) {
    constexpr double kInf = Quadric::kInf;
    switch (o.kind) {
        case ObjectKind::Quadric:
            return intersect_t(o.quadric, origin, d, t_min);
        case ObjectKind::Plane: {
            // (E + t d − P0)·n = 0  ⇒  t = (P0 − E)·n / (d·n); no hit when d ∥ plane.
            const double dn = glm::dot(d, o.normal);
            if (std::fabs(dn) <= 1e-15 * glm::length(d)) return kInf;
            const double t = glm::dot(o.p0 - origin, o.normal) / dn;
            return t > t_min ? t : kInf;
        }
        case ObjectKind::Triangle: {
            // Möller-Trumbore: solve E + t d = P0 + β e1 + γ e2 by Cramer's rule.
            const dvec3 pv = glm::cross(d, o.e2);
            const double det = glm::dot(o.e1, pv);
            if (std::fabs(det) <= 1e-15 * glm::length(o.e1) * glm::length(pv)) return kInf;
            const double inv = 1 / det;
            const dvec3 tv = origin - o.p0;
            const double beta = glm::dot(tv, pv) * inv;
            if (beta < 0 || beta > 1) return kInf;
            const dvec3 qv = glm::cross(tv, o.e1);
            const double gamma = glm::dot(d, qv) * inv;
            if (gamma < 0 || beta + gamma > 1) return kInf;
            const double t = glm::dot(o.e2, qv) * inv;
            return t > t_min ? t : kInf;
        }
        case ObjectKind::Csg:
            return intersect_csg(*o.csg, origin, d, t_min);
    }
    return kInf;
}

dvec3 object_normal(const PreparedObject& o, dvec3 point, dvec3 origin, dvec3 d, double t_min) {
    if (o.kind == ObjectKind::Quadric) return normal_at(o.quadric, point);
    if (o.kind == ObjectKind::Csg) return csg_hit_normal(*o.csg, origin, d, t_min);
    return o.normal;
}

Hit nearest_hit(const Prepared& p, dvec3 origin, dvec3 d, double t_min, double t_max) {
    Hit h;
    double best = t_max;
    for (std::size_t k = 0; k < p.objects.size(); ++k) {
        const double t = intersect_object(p.objects[k], origin, d, t_min);
        if (t < best) best = t, h.object = static_cast<int>(k);
    }
    if (h.object < 0) return h;
    h.t = best;
    h.point = origin + best * d;
    dvec3 n = object_normal(p.objects[h.object], h.point, origin, d, t_min);
    if (n == dvec3(0.0)) n = -unit(d);  // a cone's apex: no gradient; face the ray
    h.entering = glm::dot(n, d) <= 0;   // a grazing ray counts as arriving from outside
    h.normal = h.entering ? n : -n;
    return h;
}

int first_blocker(const Prepared& p, dvec3 origin, dvec3 d, double t_min, double t_max) {
    for (std::size_t k = 0; k < p.objects.size(); ++k)
        if (intersect_object(p.objects[k], origin, d, t_min) < t_max) return static_cast<int>(k);
    return -1;
}

// ---- [shading] ------------------------------------------------------------------------------

LightTerm light_term(const Scene& s, const Light& light, const Material& m, dvec3 point, dvec3 n,
                     dvec3 v) {
    return light_term(s, light, m.kd, m, point, n, v);
}

LightTerm light_term(const Scene& s, const Light& light, const Color& kd, const Material& m,
                     dvec3 point, dvec3 n, dvec3 v) {
    LightTerm t;
    if (light.directional) {
        t.l = -unit(light.direction);
    } else {
        const dvec3 to = light.position - point;
        t.distance = glm::length(to);
        t.l = t.distance > 0 ? to / t.distance : n;  // a light on the surface: straight above
        const dvec3 c = light.attenuation;
        // Capped, so that a light touching the surface (r = 0 with c1 = 0) stays finite.
        t.attenuation =
            std::min(kMaxAttenuation, 1 / (c.x + c.y * t.distance + c.z * t.distance * t.distance));
    }
    t.n_dot_l = glm::dot(n, t.l);
    if (s.settings.model == Model::Phong) {
        const dvec3 r = -t.l + 2 * t.n_dot_l * n;
        t.spec_dot = glm::dot(r, v);
    } else {
        const dvec3 h = unit(v + t.l);
        t.spec_dot = glm::dot(h, n);
    }
    t.facing = t.n_dot_l > 0;
    if (t.facing) {
        const Color I = t.attenuation * light.intensity;
        t.diffuse = I * kd * t.n_dot_l;
        t.specular = I * m.ks * std::pow(std::max(t.spec_dot, 0.0), m.shininess);
    }
    return t;
}

dvec3 offset_point(const Prepared& p, dvec3 point, dvec3 toward) {
    return point + p.epsilon * toward;
}

dvec3 reflect(dvec3 d, dvec3 n) {
    return d - 2 * glm::dot(d, n) * n;
}

bool refract(dvec3 d, dvec3 n, double eta, dvec3& out) {
    // cos θ₁ = −d·n; sin²θ₂ = η² (1 − cos²θ₁); t = η d + (η cos θ₁ − cos θ₂) n.
    const double cos1 = -glm::dot(d, n);
    const double sin2_sq = eta * eta * std::max(0.0, 1 - cos1 * cos1);
    if (sin2_sq > 1) return false;
    const double cos2 = std::sqrt(1 - sin2_sq);
    out = unit(eta * d + (eta * cos1 - cos2) * n);
    return true;
}

SecondaryRay mirror_ray(const Prepared& p, const Hit& h, dvec3 d) {
    return {offset_point(p, h.point, h.normal), reflect(d, h.normal), false, false};
}

SecondaryRay transmitted_ray(const Prepared& p, const Hit& h, dvec3 d, double ior) {
    const double eta = h.entering ? 1 / ior : ior;
    dvec3 t;
    if (!refract(d, h.normal, eta, t)) {
        SecondaryRay r = mirror_ray(p, h, d);
        r.total_internal = true;
        return r;
    }
    return {offset_point(p, h.point, -h.normal), t, true, false};
}

// ---- [the plain tracer] ---------------------------------------------------------------------

Color trace(const Scene& s, const Prepared& p, dvec3 origin, dvec3 d, int depth,
            RayCounts& counts, const RayDifferential* diff) {
    const Hit h = nearest_hit(p, origin, d);
    if (h.object < 0) return s.background;
    const Material& m = s.materials[p.objects[h.object].material];
    const dvec3 v = -unit(d);
    const Surface sf = surface_at(s, p, h, origin, d, diff);  // textured k_a, k_d and normal
    Color c = sf.ka * s.ambient;
    for (const Light& light : s.lights) {
        const LightTerm lt = light_term(s, light, sf.kd, m, h.point, sf.normal, v);
        if (!lt.facing) continue;  // a light behind the surface needs no shadow ray
        if (s.settings.shadows) {
            ++counts.shadow;
            if (first_blocker(p, offset_point(p, h.point, h.normal), lt.l, kRayEpsilon,
                              lt.distance) >= 0)
                continue;
        }
        c += lt.diffuse + lt.specular;
    }
    if (depth >= s.settings.max_depth) return c;
    const dvec3 dn = unit(d);
    if (s.settings.reflections && any_positive(m.kr)) {
        const SecondaryRay r = mirror_ray(p, h, dn);
        ++counts.reflected;
        c += m.kr * trace(s, p, r.origin, r.direction, depth + 1, counts);
    }
    if (s.settings.refractions && any_positive(m.kt)) {
        // At total internal reflection the transmitted share is reflected.
        const SecondaryRay t = transmitted_ray(p, h, dn, m.ior);
        ++(t.refracted ? counts.refracted : counts.reflected);
        c += m.kt * trace(s, p, t.origin, t.direction, depth + 1, counts);
    }
    return c;
}

Color pixel_color(const Scene& s, const Prepared& p, int i, int j, RayCounts& counts) {
    ++counts.primary;
    const dvec3 P = screen_point(p.view, i + 0.5, j + 0.5);
    const RayDifferential diff = pixel_differential(p.view, i, j);
    return trace(s, p, p.view.eye, P - p.view.eye, 0, counts, &diff);
}

std::uint32_t to_rgba8(Color c) {
    auto byte = [](double x) {
        return static_cast<std::uint32_t>(std::lround(255 * std::clamp(x, 0.0, 1.0)));
    };
    return byte(c.x) << 24 | byte(c.y) << 16 | byte(c.z) << 8 | 0xffu;
}

namespace {
// Rows k, k + step, k + 2 step, ... of the image. Flattened, so the tracer's calls inline into
// the loop as they do into a state machine's run_to_end.
[[gnu::flatten]] void render_rows(const Scene& s, const Prepared& p, Image& img, int k, int step,
                                  RayCounts& counts) {
    for (int j = k; j < img.height; j += step)
        for (int i = 0; i < img.width; ++i)
            img.rgba[static_cast<std::size_t>(j) * img.width + i] =
                to_rgba8(pixel_color(s, p, i, j, counts));
}
}  // namespace

Image render(const Scene& s, int threads) {
    const Prepared p = prepare(s);
    Image img;
    img.width = s.camera.width;
    img.height = s.camera.height;
    img.rgba.assign(static_cast<std::size_t>(img.width) * img.height, 0);
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, img.height);
    std::vector<RayCounts> counts(threads);
    // Rows interleaved between the threads (row j to thread j mod n), which balances the work
    // when the expensive part of the picture is in a band; every pixel is computed alone, so
    // the image is the same for any number of threads.
    auto work = [&](int k) { render_rows(s, p, img, k, threads, counts[k]); };
    if (threads == 1) {
        work(0);
    } else {
        std::vector<std::thread> pool;
        for (int k = 0; k < threads; ++k) pool.emplace_back(work, k);
        for (std::thread& t : pool) t.join();
    }
    for (const RayCounts& c : counts) img.rays += c;
    return img;
}

}  // namespace cg::rt
