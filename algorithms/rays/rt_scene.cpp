// Sections: [validate] [prepare and the camera] [intersection] [shading] [the plain tracer]
#include "rays/rt_scene.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <thread>

#include "core/format.hpp"
#include "core/scene.hpp"
#include "core/step.hpp"
#include "core/threads.hpp"
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
                field, "must be a colour with components in [0, 1e6] (got " + given(c, 6) + ")");
}

void check_nonzero(dvec3 v, const std::string& field, const char* what) {
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (m == 0) throw InputError(field, std::string("must not be the zero vector: it is ") + what);
    if (!(m >= 1e-150))
        throw InputError(
            field, std::string("is too short to give a direction (largest component ") + given(m) +
                       " < 1e-150): it is " + what);
}

}  // namespace

void check_coordinates(dvec3 p, const std::string& field) {
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(p[k]) || std::fabs(p[k]) > kMaxCoordinate)
            throw InputError(
                field + "[" + std::to_string(k) + "]",
                "must be a finite number of magnitude at most 1e12 (got " + given(p[k]) + ")");
}

Distribution distribution(const Scene& s) {
    Distribution d;
    d.anti_aliasing = s.settings.samples_per_pixel > 1;
    d.depth_of_field = s.camera.aperture > 0;
    d.motion_blur = s.camera.shutter > 0;
    for (const Light& l : s.lights) d.soft_shadows = d.soft_shadows || l.area != Light::Area::None;
    for (const Material& m : s.materials) d.glossy_reflection = d.glossy_reflection || m.gloss > 0;
    return d;
}

double tree_rays(const Scene& s) {
    bool mirrors = false, glass = false;
    int gloss = 1;  // the most reflected rays one hit casts
    for (const Material& m : s.materials) {
        const bool mirror = s.settings.reflections && any_positive(m.kr);
        mirrors = mirrors || mirror;
        glass = glass || (s.settings.refractions && any_positive(m.kt));
        if (mirror && m.gloss > 0) gloss = std::max(gloss, m.gloss_samples);
    }
    const int d = s.settings.max_depth;
    if (gloss > 1) {  // a tree branching (gloss + 1) or gloss ways per level
        const double b = mirrors * double(gloss) + glass;
        double n = 1, level = 1;
        for (int k = 0; k < d; ++k) n += (level *= b);
        return n;
    }
    if (mirrors && glass) return std::ldexp(1.0, d + 1) - 1;
    if (mirrors || glass) return d + 1.0;
    return 1;
}

namespace {
// Shadow rays per hit: one per point light, `samples` per area light.
double shadow_rays(const Scene& s) {
    double n = 0;
    for (const Light& l : s.lights) n += l.area == Light::Area::None ? 1.0 : double(l.samples);
    return n;
}
}  // namespace

double scene_tests(const Scene& s) {
    double n = 0;
    for (const Object& o : s.objects)
        n += o.kind == ObjectKind::Mesh ? o.mesh->bvh.cost : static_cast<double>(object_tests(o));
    return n;
}

std::size_t scene_triangles(const Scene& s) {
    std::size_t n = 0;
    for (const Object& o : s.objects)
        if (o.kind == ObjectKind::Mesh) n += o.mesh->mesh.triangles.size();
    return n;
}

TriangleMesh make_triangle_mesh(mesh::Mesh m, std::vector<std::uint32_t> source) {
    TriangleMesh t;
    // Made unit, as a triangle object's are in prepare; but a normal already unit to rounding
    // is kept as it is. unit() is not idempotent (unit(unit(n)) can differ from unit(n) in the
    // last bit), and a scene written out lists its meshes' normals as they stand here: read
    // back, they must come out the same (a fuzz find, tests/fuzz/regressions/fuzz_scene/).
    for (dvec3& n : m.normals)
        if (!(std::fabs(glm::dot(n, n) - 1) <= 1e-14)) n = unit(n);
    t.bvh = build_mesh_bvh(m);
    for (const auto& tri : m.triangles)
        for (std::uint32_t i : tri) t.reach = std::max(t.reach, glm::length(m.vertices[i]));
    t.mesh = std::move(m);
    t.source = std::move(source);
    return t;
}

double pixel_work(const Scene& s) {
    const double n = s.settings.samples_per_pixel;
    // Poisson dart throwing compares each dart with the points kept so far: about n² tests.
    const double darts = s.settings.pattern == sampling::Pattern::Poisson && n > 1 ? n * n : 0;
    return n * tree_rays(s) * (1.0 + shadow_rays(s)) * std::max<double>(1, scene_tests(s)) + darts;
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
                                          given(view, 4) + ": the screen's orientation is undefined");
    if (!(c.fov_y_deg >= 0.01 && c.fov_y_deg <= 179))
        throw InputError(
            "camera.fov_y_deg",
            "must be a field of view between 0.01° and 179° (got " + given(c.fov_y_deg) + ")");
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
    const int spp = s.settings.samples_per_pixel;
    if (spp < 1 || spp > kMaxSamplesPerPixel)
        throw InputError("settings.samples_per_pixel", "must be between 1 and " +
                                                           std::to_string(kMaxSamplesPerPixel) +
                                                           " (got " + std::to_string(spp) + ")");
    if (spp > 1 && sampling::is_grid(s.settings.pattern) && sampling::grid_side(spp) == 0)
        throw InputError("settings.samples_per_pixel",
                         std::string("must be a square number n × n (4, 9, 16, …) for the ") +
                             sampling::pattern_id(s.settings.pattern) + " pattern (got " +
                             std::to_string(spp) + ")");
    if (!(c.aperture >= 0 && c.aperture <= 1e6))
        throw InputError("camera.aperture",
                         "must be a lens radius between 0 and 1e6 (got " + given(c.aperture) + ")");
    if (!(c.focal_distance >= 0 && c.focal_distance <= kMaxCoordinate))
        throw InputError("camera.focal_distance",
                         "must be a distance between 0 (the look-at point's) and 1e12 (got " +
                             given(c.focal_distance) + ")");
    if (!(c.shutter >= 0 && c.shutter <= 1e6))
        throw InputError("camera.shutter",
                         "must be a time span between 0 and 1e6 (got " + given(c.shutter) + ")");

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
                                                   given(m.shininess) + ")");
        if (!(m.ior >= 0.01 && m.ior <= 100))
            throw InputError(f + ".ior", "must be a refraction index between 0.01 and 100 (got " +
                                             given(m.ior) + ")");
        if (!(m.gloss >= 0 && m.gloss <= 1e6))
            throw InputError(
                f + ".gloss",
                "must be a Phong exponent between 0 (a mirror) and 1e6 (got " + given(m.gloss) + ")");
        if (m.gloss_samples < 1 || m.gloss_samples > kMaxGlossSamples)
            throw InputError(f + ".gloss_samples", "must be between 1 and " +
                                                       std::to_string(kMaxGlossSamples) + " (got " +
                                                       std::to_string(m.gloss_samples) + ")");
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
                    "must be three coefficients c1, c2, c3 in [0, 1e6] (got " + given(a) + ")");
            if (a.x == 0 && a.y == 0 && a.z == 0)
                throw InputError(f + ".attenuation",
                                 "must not be all zero: 1/(c1 + c2 r + c3 r²) would be infinite");
        }
        if (l.area == Light::Area::None) continue;
        if (l.samples < 1 || l.samples > kMaxLightSamples)
            throw InputError(f + ".samples", "must be between 1 and " +
                                                 std::to_string(kMaxLightSamples) + " (got " +
                                                 std::to_string(l.samples) + ")");
        if (l.area == Light::Area::Rectangle) {
            check_coordinates(l.edge_u, f + ".area.u");
            check_coordinates(l.edge_v, f + ".area.v");
        } else {
            if (!(l.radius >= 0 && l.radius <= kMaxCoordinate))
                throw InputError(f + ".area.radius",
                                 "must be between 0 and 1e12 (got " + given(l.radius) + ")");
            check_coordinates(l.normal, f + ".area.normal");
            check_nonzero(l.normal, f + ".area.normal", "the disc's normal");
        }
    }

    if (scene_triangles(s) > kMaxTriangles)
        throw InputError("objects", "has " + std::to_string(scene_triangles(s)) +
                                        " triangles in its meshes; the limit is " +
                                        std::to_string(kMaxTriangles));
    if (scene_tests(s) > static_cast<double>(kMaxObjects))
        throw InputError("objects", "costs " + given(scene_tests(s), 4) +
                                        " ray-object tests per ray (triangles and CSG leaves "
                                        "counted one by one, a mesh as its hierarchy's expected "
                                        "cost); the limit is " +
                                        std::to_string(kMaxObjects));
    // What a run would cost, now that the counts are known to be sane.
    const double per_pixel = pixel_work(s);
    if (per_pixel > kMaxPixelWork && distributed(s))
        throw InputError(
            tree_rays(s) > 64                  ? "settings.max_depth"
            : s.settings.samples_per_pixel > 1 ? "settings.samples_per_pixel"
                                               : "objects",
            "makes one pixel cost up to " + given(per_pixel, 3) + " ray-object tests (" +
                std::to_string(s.settings.samples_per_pixel) + " samples × " + given(tree_rays(s)) +
                " rays per tree × " + given(1 + shadow_rays(s)) + " for the shadow rays × " +
                given(scene_tests(s)) +
                " objects); the limit is 1e7: use fewer samples, a lower max_depth, or fewer "
                "objects or lights");
    if (per_pixel > kMaxPixelWork)
        throw InputError(
            tree_rays(s) > 64 ? "settings.max_depth" : "objects",
            "makes one pixel cost up to " + given(per_pixel, 3) + " ray-object tests (" +
                given(tree_rays(s)) + " rays per tree × " + std::to_string(s.lights.size() + 1) +
                " for the lights × " + given(scene_tests(s)) +
                " objects); the limit is 1e7: lower max_depth, or use fewer objects or lights");
    const double total = per_pixel * c.width * c.height;
    if (total > kMaxWork)
        throw InputError("camera.size", "makes the image cost up to " + given(total, 3) +
                                            " ray-object tests (" + std::to_string(c.width) + "×" +
                                            std::to_string(c.height) + " pixels × " +
                                            given(per_pixel, 3) +
                                            " per pixel); the limit is 2e10: use fewer pixels");
    for (const Object& o : s.objects) {
        if (o.material < 0 || o.material >= static_cast<int>(s.materials.size()))
            throw InputError(o.field + ".material", "names no material");
        if (o.velocity != dvec3(0.0)) check_coordinates(o.velocity, o.field + ".velocity");
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
                    throw InputError(o.field, "is degenerate: its corners " + given(o.p0, 4) + ", " +
                                                  given(o.p1, 4) + ", " + given(o.p2, 4) +
                                                  " are collinear or coincide (zero area)");
                if (o.smooth) {
                    const dvec3* n[3] = {&o.n0, &o.n1, &o.n2};
                    for (int k = 0; k < 3; ++k) {
                        const std::string nf = o.field + ".normals[" + std::to_string(k) + "]";
                        check_coordinates(*n[k], nf);
                        check_nonzero(*n[k], nf, "a vertex normal");
                    }
                }
                break;
            }
            case ObjectKind::Csg:
                validate_csg_object(o);
                break;
            case ObjectKind::Mesh: {
                const mesh::Mesh& m = o.mesh->mesh;
                if (m.triangles.empty()) throw InputError(o.field, "has no triangles");
                for (std::size_t k = 0; k < m.vertices.size(); ++k)
                    check_coordinates(m.vertices[k], o.field + ".vertices[" + std::to_string(k) + "]");
                if (!m.normals.empty() && m.normals.size() != m.vertices.size())
                    throw InputError(o.field + ".normals", "must give one normal per vertex");
                for (std::size_t k = 0; k < m.normals.size(); ++k)
                    if (!(std::fabs(glm::length(m.normals[k]) - 1) < 1e-9))
                        throw InputError(o.field + ".normals[" + std::to_string(k) + "]",
                                         "must be a nonzero, finite normal");
                if (!m.uv.empty() && m.uv.size() != m.vertices.size())
                    throw InputError(o.field + ".uv", "must give one (u, v) per vertex");
                for (const auto& t : m.triangles)
                    for (std::uint32_t i : t)
                        if (i >= m.vertices.size())
                            throw InputError(o.field + ".triangles",
                                             "refers to vertex " + std::to_string(i) + ", but only " +
                                                 std::to_string(m.vertices.size()) + " are given");
                break;
            }
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
    p.focal_distance = s.camera.focal_distance > 0 ? s.camera.focal_distance
                                                   : glm::length(s.camera.center - s.camera.eye);
    p.distributed = distributed(s);
    double scale = std::max({1.0, glm::length(s.camera.eye), glm::length(s.camera.center)});
    p.objects.reserve(s.objects.size());
    for (const Object& o : s.objects) {
        PreparedObject q;
        q.kind = o.kind;
        q.material = o.material;
        q.velocity = o.velocity;
        q.moving = o.velocity != dvec3(0.0);
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
                q.smooth = o.smooth;
                if (o.smooth) q.n0 = unit(o.n0), q.n1 = unit(o.n1), q.n2 = unit(o.n2);
                scale = std::max({scale, glm::length(o.p0), glm::length(o.p1), glm::length(o.p2)});
                break;
            case ObjectKind::Csg:
                q.csg = Shared<PreparedCsg>(prepare_csg(o.csg));
                for (const PreparedCsgLeaf& l : q.csg->leaves)
                    scale = std::max(scale, glm::length(l.quadric.translation));
                break;
            case ObjectKind::Mesh:
                q.mesh = o.mesh;
                scale = std::max(scale, o.mesh->reach);
                break;
        }
        p.objects.push_back(q);
    }
    p.epsilon = 1e-7 * scale;
    std::vector<Bounds> boxes;
    boxes.reserve(s.objects.size());
    for (const Object& o : s.objects) boxes.push_back(object_bounds(o));
    p.bvh = build_bvh(boxes);
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
        case ObjectKind::Triangle:  // Möller-Trumbore (rays/rt_mesh.hpp)
            return triangle_t(o.p0, o.e1, o.e2, origin, d, t_min);
        case ObjectKind::Mesh: {
            MeshHit h;
            return mesh_nearest(o.mesh->bvh, origin, d, t_min, kInf, h) ? h.t : kInf;
        }
        case ObjectKind::Csg:
            return intersect_csg(*o.csg, origin, d, t_min);
    }
    return kInf;
}

namespace {

// A smooth triangle's shading normal at `point` (on it): its unit vertex normals interpolated
// at the point's barycentric coordinates (the flat normal where they cancel).
dvec3 triangle_normal(dvec3 p0, dvec3 e1, dvec3 e2, dvec3 flat, const dvec3 vertex_normals[3],
                      dvec3 point, dvec3 d) {
    // The hit's barycentric coordinates: point − p0 = β e1 + γ e2, by the areas of the
    // sub-triangles over N = e1 × e2 (Möller-Trumbore's β, γ for a point on the triangle).
    const dvec3 q = point - p0, N = glm::cross(e1, e2);
    const double nn = glm::dot(N, N);
    const double beta = glm::dot(glm::cross(q, e2), N) / nn;
    const double gamma = glm::dot(glm::cross(e1, q), N) / nn;
    dvec3 n = (1 - beta - gamma) * vertex_normals[0] + beta * vertex_normals[1] +
              gamma * vertex_normals[2];
    const double len = glm::length(n);
    if (!(len > 0) || !std::isfinite(len)) return flat;  // opposed normals: flat
    n /= len;
    // Near the outline the interpolated normal can face away from a ray that meets the
    // triangle's front (or the other way round): it is then bent, along the ray, just far
    // enough to lie on the geometric normal's side, so that which side the ray came from
    // (entering or leaving) is the geometric one.
    const dvec3 dn = unit(d);
    const double a = glm::dot(n, dn), b = glm::dot(flat, dn);
    if (b != 0 && (a < 0) != (b < 0)) n = unit(n + (std::copysign(1e-3, b) - a) * dn);
    return n;
}

// A mesh triangle's normal, as a triangle object with the same corners (and vertex normals)
// would have it.
dvec3 mesh_triangle_normal(const TriangleMesh& tm, int triangle, dvec3 point, dvec3 d) {
    const mesh::Mesh& m = tm.mesh;
    const auto& t = m.triangles[static_cast<std::size_t>(triangle)];
    const dvec3 p0 = m.vertices[t[0]], e1 = m.vertices[t[1]] - p0, e2 = m.vertices[t[2]] - p0;
    const dvec3 flat = unit(glm::cross(e1, e2));
    if (m.normals.empty()) return flat;
    const dvec3 n[3] = {m.normals[t[0]], m.normals[t[1]], m.normals[t[2]]};
    return triangle_normal(p0, e1, e2, flat, n, point, d);
}

}  // namespace

dvec3 object_normal(const PreparedObject& o, dvec3 point, dvec3 origin, dvec3 d, double t_min) {
    if (o.kind == ObjectKind::Quadric) return normal_at(o.quadric, point);
    if (o.kind == ObjectKind::Csg) return csg_hit_normal(*o.csg, origin, d, t_min);
    if (o.kind == ObjectKind::Mesh) {  // which triangle: the ray's nearest (the one it hit)
        MeshHit h;
        if (!mesh_nearest(o.mesh->bvh, origin, d, t_min, Quadric::kInf, h)) return dvec3(0.0);
        return mesh_triangle_normal(*o.mesh, static_cast<int>(h.triangle), point, d);
    }
    if (o.kind == ObjectKind::Triangle && o.smooth) {
        const dvec3 n[3] = {o.n0, o.n1, o.n2};
        return triangle_normal(o.p0, o.e1, o.e2, o.normal, n, point, d);
    }
    return o.normal;
}

namespace {
// Where a moving object is at `time`: the ray is moved the other way instead.
dvec3 offset_at(const PreparedObject& o, double time) {
    return o.moving ? o.velocity * time : dvec3(0.0);
}
}  // namespace

namespace {

constexpr double kInf = Quadric::kInf;

// One object's t at `time` (a moving object is tested where it is then). A mesh is searched
// for t < t_max only (its hierarchy prunes by it), and tells which triangle it hit; `brute`
// tests every one of its triangles instead (the reference).
double object_t(const PreparedObject& o, dvec3 origin, dvec3 d, double t_min, double time,
                double t_max = kInf, int* triangle = nullptr, bool brute = false,
                TraversalCounts* counts = nullptr) {
    if (o.moving) origin -= o.velocity * time;
    if (o.kind != ObjectKind::Mesh) return intersect_object(o, origin, d, t_min);
    if (brute) {
        const mesh::Mesh& m = o.mesh->mesh;
        double best = t_max;
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            const dvec3 p0 = m.vertices[m.triangles[k][0]];
            const double t = triangle_t(p0, m.vertices[m.triangles[k][1]] - p0,
                                        m.vertices[m.triangles[k][2]] - p0, origin, d, t_min);
            if (t < best) best = t, *triangle = static_cast<int>(k);
        }
        return best < t_max ? best : kInf;
    }
    MeshHit h;
    long long boxes = 0, tests = 0;
    const bool found = mesh_nearest(o.mesh->bvh, origin, d, t_min, t_max, h,
                                    counts ? &boxes : nullptr, counts ? &tests : nullptr);
    if (counts) counts->box_tests += boxes, counts->object_tests += tests;
    if (!found) return kInf;
    if (triangle) *triangle = static_cast<int>(h.triangle);
    return h.t;
}

// Whether the object lies on the ray at t_min < t < t_max (a mesh: any of its triangles).
bool object_blocks(const PreparedObject& o, dvec3 origin, dvec3 d, double t_min, double t_max,
                   double time) {
    if (o.kind != ObjectKind::Mesh) return object_t(o, origin, d, t_min, time) < t_max;
    if (o.moving) origin -= o.velocity * time;
    return mesh_occluded(o.mesh->bvh, origin, d, t_min, t_max);
}

// The hit's normal and side, once the nearest object (and a mesh's triangle) is known.
Hit finish_hit(const Prepared& p, int object, int triangle, double t, dvec3 origin, dvec3 d,
               double t_min, double time) {
    Hit h;
    h.object = object;
    h.triangle = triangle;
    h.t = t;
    h.point = origin + t * d;
    const PreparedObject& o = p.objects[object];
    const dvec3 shift = offset_at(o, time);
    dvec3 n = o.kind == ObjectKind::Mesh ? mesh_triangle_normal(*o.mesh, triangle, h.point - shift, d)
              : o.moving ? object_normal(o, h.point - shift, origin - shift, d, t_min)
                         : object_normal(o, h.point, origin, d, t_min);
    if (n == dvec3(0.0)) n = -unit(d);  // a cone's apex: no gradient; face the ray
    h.entering = glm::dot(n, d) <= 0;   // a grazing ray counts as arriving from outside
    h.normal = h.entering ? n : -n;
    return h;
}

// The nearest-hit search with brute force's rule: the least t, and on a tie the smaller object
// index (a mesh is searched up to just past the best t when it comes first, to see the tie).
struct Nearest {
    double best;
    int object = -1, triangle = -1;
    void test(const Prepared& p, int k, dvec3 origin, dvec3 d, double t_min, double time,
              TraversalCounts* counts = nullptr) {
        int tri = -1;
        const double limit = object >= 0 && k < object ? std::nextafter(best, kInf) : best;
        const double t = object_t(p.objects[k], origin, d, t_min, time, limit, &tri, false, counts);
        if (t < best || (t == best && object >= 0 && k < object)) best = t, object = k, triangle = tri;
    }
};

}  // namespace

Hit nearest_hit(const Prepared& p, dvec3 origin, dvec3 d, double t_min, double t_max, double time) {
    Nearest n{t_max};
    auto test = [&](int k) {
        n.test(p, k, origin, d, t_min, time);
        return false;
    };
    // Without a tree every object is on the unbounded list (a mesh still uses its own).
    for (int k : p.bvh.unbounded) test(k);
    traverse(p.bvh, box_ray(origin, d), t_min, [&] { return n.best; }, test);
    if (n.object < 0) return Hit{};
    return finish_hit(p, n.object, n.triangle, n.best, origin, d, t_min, time);
}

TraversalCounts traversal_counts(const Prepared& p, dvec3 origin, dvec3 d, double t_min,
                                 double t_max, double time) {
    TraversalCounts c;
    Nearest n{t_max};
    auto test = [&](int k) {
        // A mesh counts its own box and triangle tests (and not itself as one object test).
        if (p.objects[k].kind != ObjectKind::Mesh) ++c.object_tests;
        n.test(p, k, origin, d, t_min, time, &c);
        return false;
    };
    for (int k : p.bvh.unbounded) test(k);
    traverse(p.bvh, box_ray(origin, d), t_min, [&] { return n.best; }, test, &c.box_tests);
    return c;
}

Hit nearest_hit_brute_force(const Prepared& p, dvec3 origin, dvec3 d, double t_min, double t_max,
                            double time) {
    double best = t_max;
    int object = -1, triangle = -1;
    for (std::size_t k = 0; k < p.objects.size(); ++k) {
        int tri = -1;
        const double t = object_t(p.objects[k], origin, d, t_min, time, best, &tri, true);
        if (t < best) best = t, object = static_cast<int>(k), triangle = tri;
    }
    if (object < 0) return Hit{};
    return finish_hit(p, object, triangle, best, origin, d, t_min, time);
}

int first_blocker(const Prepared& p, dvec3 origin, dvec3 d, double t_min, double t_max,
                  double time) {
    // The smallest index among the blockers (brute force's answer): the unbounded objects in
    // order, then every leaf the shadow ray's segment meets, testing only smaller indices.
    int first = -1;
    for (int k : p.bvh.unbounded)
        if (object_blocks(p.objects[k], origin, d, t_min, t_max, time)) {
            first = k;
            break;
        }
    traverse(p.bvh, box_ray(origin, d), t_min, [&] { return t_max; }, [&](int k) {
        if ((first < 0 || k < first) && object_blocks(p.objects[k], origin, d, t_min, t_max, time))
            first = k;
        return false;
    });
    return first;
}

int first_blocker_brute_force(const Prepared& p, dvec3 origin, dvec3 d, double t_min,
                              double t_max, double time) {
    for (std::size_t k = 0; k < p.objects.size(); ++k) {
        int tri = -1;
        if (object_t(p.objects[k], origin, d, t_min, time, t_max, &tri, true) < t_max)
            return static_cast<int>(k);
    }
    return -1;
}

bool blocked(const Prepared& p, dvec3 origin, dvec3 d, double t_min, double t_max, double time) {
    for (int k : p.bvh.unbounded)
        if (object_blocks(p.objects[k], origin, d, t_min, t_max, time)) return true;
    bool hit = false;
    traverse(p.bvh, box_ray(origin, d), t_min, [&] { return t_max; }, [&](int k) {
        return hit = object_blocks(p.objects[k], origin, d, t_min, t_max, time);
    });
    return hit;
}

namespace {

// A quadric's model-space box, or the empty box when its surface is unbounded (or the slab
// leaves none of it). F ≤ 0 inside; the box holds the part with zmin ≤ z ≤ zmax.
Bounds quadric_model_bounds(const Quadric& q) {
    const bool cut = std::isfinite(q.zmin) && std::isfinite(q.zmax);
    const double zm = cut ? std::max(std::fabs(q.zmin), std::fabs(q.zmax)) : 0;
    Bounds b;
    switch (q.kind) {
        case QuadricKind::Sphere:
            b.min = dvec3(-q.r), b.max = dvec3(q.r);
            break;
        case QuadricKind::Ellipsoid:
            b.min = -dvec3(q.a, q.b, q.c), b.max = dvec3(q.a, q.b, q.c);
            break;
        case QuadricKind::Paraboloid: {  // x²/p² + y²/q² = z ≥ 0
            if (!std::isfinite(q.zmax) || q.zmax < 0) return {};
            const double s = std::sqrt(q.zmax);
            b.min = dvec3(-q.p * s, -q.q * s, std::max(0.0, q.zmin));
            b.max = dvec3(q.p * s, q.q * s, q.zmax);
            return b;
        }
        case QuadricKind::Hyperboloid: {  // x²/a² + y²/b² = 1 + z²/c²
            if (!cut) return {};
            const double s = std::sqrt(1 + (zm / q.c) * (zm / q.c));
            b.min = dvec3(-q.a * s, -q.b * s, q.zmin), b.max = dvec3(q.a * s, q.b * s, q.zmax);
            return b;
        }
        case QuadricKind::Cone: {  // x²/p² + y²/q² = z²/r²
            if (!cut) return {};
            const double s = zm / q.r;
            b.min = dvec3(-q.p * s, -q.q * s, q.zmin), b.max = dvec3(q.p * s, q.q * s, q.zmax);
            return b;
        }
        case QuadricKind::Cylinder:  // x²/p² + y²/q² = 1
            if (!cut) return {};
            b.min = dvec3(-q.p, -q.q, q.zmin), b.max = dvec3(q.p, q.q, q.zmax);
            return b;
    }
    // Closed surfaces: the slab can only shrink them.
    b.min.z = std::max(b.min.z, q.zmin);
    b.max.z = std::min(b.max.z, q.zmax);
    if (b.min.z > b.max.z) return {};
    return b;
}

}  // namespace

Bounds object_bounds(const Object& o) {
    if (o.velocity != dvec3(0.0)) return {};  // it moves: tested for every ray
    Bounds b;
    switch (o.kind) {
        case ObjectKind::Triangle:
            b.grow(o.p0), b.grow(o.p1), b.grow(o.p2);
            return b;
        case ObjectKind::Quadric: {
            const Bounds m = quadric_model_bounds(o.quadric);
            if (m.empty()) return {};
            // The world box of the model box's eight corners (M is affine).
            for (int c = 0; c < 8; ++c) {
                const dvec3 corner(c & 1 ? m.max.x : m.min.x, c & 2 ? m.max.y : m.min.y,
                                   c & 4 ? m.max.z : m.min.z);
                b.grow(dvec3(o.quadric.world_from_model * glm::dvec4(corner, 1.0)));
            }
            return b;
        }
        case ObjectKind::Mesh:  // its hierarchy's root box (padded, rounded outward)
            for (int a = 0; a < 3; ++a)
                b.min[a] = o.mesh->bvh.root_lo[a], b.max[a] = o.mesh->bvh.root_hi[a];
            return b;
        case ObjectKind::Plane:
        case ObjectKind::Csg:
            return {};
    }
    return {};
}

Surface moving_surface_at(const Scene& s, const Prepared& p, const Hit& h, dvec3 origin, dvec3 d,
                          const RayDifferential* diff, double time, SurfaceDetail* detail) {
    const PreparedObject& o = p.objects[h.object];
    if (!o.moving) return surface_at(s, p, h, origin, d, diff, detail);
    Hit at_rest = h;  // the hit where the object sits at time 0, for its textures
    const dvec3 shift = o.velocity * time;
    at_rest.point -= shift;
    return surface_at(s, p, at_rest, origin - shift, d, diff, detail);
}

// ---- [shading] ------------------------------------------------------------------------------

LightTerm light_term(const Scene& s, const Light& light, const Material& m, dvec3 point, dvec3 n,
                     dvec3 v) {
    return light_term(s, light, m.kd, m, point, n, v);
}

LightTerm light_term(const Scene& s, const Light& light, const Color& kd, const Material& m,
                     dvec3 point, dvec3 n, dvec3 v) {
    // Computed into locals and assembled at the end: a default-initialised LightTerm filled in
    // field by field was cleared with `rep stos` on every call (it runs twice per hit here).
    dvec3 l;
    double distance = Quadric::kInf, attenuation = 1;
    if (light.directional) {
        l = -unit(light.direction);
    } else {
        const dvec3 to = light.position - point;
        distance = glm::length(to);
        l = distance > 0 ? to / distance : n;  // a light on the surface: straight above
        const dvec3 c = light.attenuation;
        // Capped, so that a light touching the surface (r = 0 with c1 = 0) stays finite.
        attenuation =
            std::min(kMaxAttenuation, 1 / (c.x + c.y * distance + c.z * distance * distance));
    }
    const double n_dot_l = glm::dot(n, l);
    double spec_dot;
    if (s.settings.model == Model::Phong) {
        const dvec3 r = -l + 2 * n_dot_l * n;
        spec_dot = glm::dot(r, v);
    } else {
        const dvec3 h = unit(v + l);
        spec_dot = glm::dot(h, n);
    }
    const bool facing = n_dot_l > 0;
    Color diffuse(0.0), specular(0.0);
    if (facing) {
        const Color I = attenuation * light.intensity;
        diffuse = I * kd * n_dot_l;
        // pow(+0, p) is +0 for every p > 0 (C's Annex F), so the highlight of a light reflected
        // away from the viewer (r·v ≤ 0, clamped to +0) needs no call to pow; −0, NaN and p = 0
        // still go through it, so the value is pow's in every case.
        const double sd = std::max(spec_dot, 0.0);
        const bool plus_zero = sd == 0 && !std::signbit(sd);
        specular = I * m.ks * (plus_zero && m.shininess > 0 ? 0.0 : std::pow(sd, m.shininess));
    }
    return LightTerm{l, distance, attenuation, n_dot_l, spec_dot, diffuse, specular, facing};
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

// ---- [distribution] -------------------------------------------------------------------------

Rng pixel_rng(const Scene& s, int i, int j) {
    return Rng(sampling::mix_seed(s.settings.seed, std::uint64_t(std::uint32_t(i)),
                                  std::uint64_t(std::uint32_t(j))));
}

std::vector<PixelSample> pixel_samples(const Scene& s, int i, int j, Rng& rng) {
    (void)i, (void)j;
    const int n = s.settings.samples_per_pixel;
    std::vector<PixelSample> out(static_cast<std::size_t>(n));
    if (n > 1) {
        const std::uint64_t seed = rng.next();
        const auto pts =
            sampling::generate(s.settings.pattern, n, seed, sampling::default_radius(n));
        out.resize(pts.size());  // Poisson dart throwing always reaches its default radius
        for (std::size_t k = 0; k < pts.size(); ++k) {
            out[k].pixel = pts[k].p;
            out[k].weight = sampling::weight(s.settings.filter, pts[k].p - glm::dvec2(0.5));
        }
    }
    for (PixelSample& ps : out) {
        if (s.camera.aperture > 0) {  // a uniform point of the unit disc
            const double r = std::sqrt(rng.uniform(0, 1));
            const double a = 2 * M_PI * rng.uniform(0, 1);
            ps.lens = {r * std::cos(a), r * std::sin(a)};
        }
        if (s.camera.shutter > 0) ps.time = s.camera.shutter * rng.uniform(0, 1);
    }
    return out;
}

void primary_ray(const Prepared& p, const Camera& c, int i, int j, const PixelSample& ps,
                 dvec3& origin, dvec3& direction) {
    const dvec3 P = screen_point(p.view, i + ps.pixel.x, j + ps.pixel.y);
    origin = p.view.eye;
    direction = P - p.view.eye;
    if (c.aperture <= 0) return;
    // The thin lens: every ray through this screen point meets at the focal plane, where the
    // pinhole ray E + t (P − E) is at t = focal distance (the screen is at distance 1).
    const dvec3 F = p.view.eye + p.focal_distance * direction;
    origin = p.view.eye + c.aperture * (ps.lens.x * p.view.u + ps.lens.y * p.view.v);
    direction = (F - origin) / p.focal_distance;
}

std::vector<dvec3> light_points(const Light& light, Rng& rng) {
    const int n = light.samples;
    const auto pattern =
        sampling::grid_side(n) > 0 ? sampling::Pattern::Jittered : sampling::Pattern::Random;
    const auto pts = sampling::generate(pattern, n, rng.next());
    std::vector<dvec3> out;
    out.reserve(pts.size());
    if (light.area == Light::Area::Rectangle) {
        for (const auto& q : pts)
            out.push_back(light.position + (q.p.x - 0.5) * light.edge_u +
                          (q.p.y - 0.5) * light.edge_v);
    } else {  // a disc: radius √x (uniform in area), angle 2π y
        const dvec3 n3 = unit(light.normal);
        const dvec3 e1 = unit(std::fabs(n3.x) < 0.9 ? glm::cross(n3, dvec3(1, 0, 0))
                                                    : glm::cross(n3, dvec3(0, 1, 0)));
        const dvec3 e2 = glm::cross(n3, e1);
        for (const auto& q : pts) {
            const double r = light.radius * std::sqrt(q.p.x), a = 2 * M_PI * q.p.y;
            out.push_back(light.position + r * std::cos(a) * e1 + r * std::sin(a) * e2);
        }
    }
    return out;
}

dvec3 glossy_direction(dvec3 r, double gloss, Rng& rng) {
    const double x1 = rng.uniform(0, 1);
    const double x2 = rng.uniform(0, 1);
    const double cos_t = std::pow(x1, 1 / (gloss + 1));
    const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
    const double a = 2 * M_PI * x2;
    const dvec3 t1 =
        unit(std::fabs(r.x) < 0.9 ? glm::cross(dvec3(1, 0, 0), r) : glm::cross(dvec3(0, 1, 0), r));
    const dvec3 t2 = glm::cross(r, t1);
    return sin_t * std::cos(a) * t1 + sin_t * std::sin(a) * t2 + cos_t * r;
}

// ---- [the plain tracer] ---------------------------------------------------------------------

Color trace(const Scene& s, const Prepared& p, dvec3 origin, dvec3 d, int depth, RayCounts& counts,
            const RayDifferential* diff, Rng* rng, double time) {
    const Hit h = nearest_hit(p, origin, d, kRayEpsilon, Quadric::kInf, time);
    if (h.object < 0) return s.background;
    const Material& m = s.materials[p.objects[h.object].material];
    const dvec3 v = -unit(d);
    // Textured k_a, k_d and normal.
    const Surface sf = moving_surface_at(s, p, h, origin, d, diff, time, nullptr);
    Color c = sf.ka * s.ambient;
    for (const Light& light : s.lights) {
        if (light.area != Light::Area::None && rng) {  // rays over the light's area
            const std::vector<dvec3> points = light_points(light, *rng);
            const double share = 1.0 / double(points.size());
            Light at = light;
            for (const dvec3& q : points) {
                at.position = q;
                const LightTerm lt = light_term(s, at, sf.kd, m, h.point, sf.normal, v);
                if (!lt.facing) continue;
                if (s.settings.shadows) {
                    ++counts.shadow;
                    if (blocked(p, offset_point(p, h.point, h.normal), lt.l, kRayEpsilon,
                                lt.distance, time))
                        continue;
                }
                c += (lt.diffuse + lt.specular) * share;
            }
            continue;
        }
        const LightTerm lt = light_term(s, light, sf.kd, m, h.point, sf.normal, v);
        if (!lt.facing) continue;  // a light behind the surface needs no shadow ray
        if (s.settings.shadows) {
            ++counts.shadow;
            if (blocked(p, offset_point(p, h.point, h.normal), lt.l, kRayEpsilon, lt.distance, time))
                continue;
        }
        c += lt.diffuse + lt.specular;
    }
    if (depth >= s.settings.max_depth) return c;
    const dvec3 dn = unit(d);
    if (s.settings.reflections && any_positive(m.kr)) {
        const SecondaryRay r = mirror_ray(p, h, dn);
        if (m.gloss > 0 && rng) {  // rays over the Phong lobe about the mirror direction
            const Color w = m.kr * (1.0 / double(m.gloss_samples));
            for (int g = 0; g < m.gloss_samples; ++g) {
                const dvec3 dir = glossy_direction(r.direction, m.gloss, *rng);
                if (!(glm::dot(dir, h.normal) > 0)) continue;  // below the surface: nothing
                ++counts.reflected;
                c += w * trace(s, p, r.origin, dir, depth + 1, counts, nullptr, rng, time);
            }
        } else {
            ++counts.reflected;
            c += m.kr * trace(s, p, r.origin, r.direction, depth + 1, counts, nullptr, rng, time);
        }
    }
    if (s.settings.refractions && any_positive(m.kt)) {
        // At total internal reflection the transmitted share is reflected.
        const SecondaryRay t = transmitted_ray(p, h, dn, m.ior);
        ++(t.refracted ? counts.refracted : counts.reflected);
        c += m.kt * trace(s, p, t.origin, t.direction, depth + 1, counts, nullptr, rng, time);
    }
    return c;
}

Color pixel_color(const Scene& s, const Prepared& p, int i, int j, RayCounts& counts) {
    const RayDifferential diff = pixel_differential(p.view, i, j);
    if (!p.distributed) {
        ++counts.primary;
        const dvec3 P = screen_point(p.view, i + 0.5, j + 0.5);
        return trace(s, p, p.view.eye, P - p.view.eye, 0, counts, &diff);
    }
    // Distribution ray tracing: the filtered average of the pixel's samples.
    Rng rng = pixel_rng(s, i, j);
    const std::vector<PixelSample> samples = pixel_samples(s, i, j, rng);
    Color sum(0.0);
    double weights = 0;
    for (const PixelSample& ps : samples) {
        ++counts.primary;
        dvec3 origin, direction;
        primary_ray(p, s.camera, i, j, ps, origin, direction);
        sum += ps.weight * trace(s, p, origin, direction, 0, counts, &diff, &rng, ps.time);
        weights += ps.weight;
    }
    return sum / weights;
}

namespace {
// Rows k, k + step, k + 2 step, ... of the image. Flattened, so the tracer's calls inline into
// the loop as they do into a state machine's run_to_end.
[[gnu::flatten]] void render_rows(const Scene& s, const Prepared& p, Image& img, int k, int step,
                                  RayCounts& counts) {
    for (int j = k; j < img.height; j += step)
        for (int i = 0; i < img.width; ++i)
            img.rgba[static_cast<std::size_t>(j) * img.width + i] =
                pack_rgba(pixel_color(s, p, i, j, counts));
}
}  // namespace

Image render(const Scene& s, int threads) {
    const Prepared p = prepare(s);
    Image img;
    img.width = s.camera.width;
    img.height = s.camera.height;
    img.rgba.assign(static_cast<std::size_t>(img.width) * img.height, 0);
    threads = usable_threads(threads);
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
