// Sections: [spec] [validate and start] [the image rows] [stepping] [narration] [result]; the
// picture is in ray_tracer_draw.cpp.
#include "rays/ray_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "rays/csg_ray.hpp"
#include "sampling/patterns.hpp"

namespace cg {

using glm::dvec3;
using rt::Color;
using Event = RayTracer::Event;
using RayKind = RayTracer::RayKind;
using Next = RayTracer::Next;

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& RayTracer::spec() {
    static const Spec s{
        "ray-tracer",
        "Recursive ray tracing",
        "Ray Tracing",
        {
            "for each pixel (i, j) of the virtual screen:",
            "    primary ray E + t (P_ij − E), t > 0",
            "    colour(i, j) ← trace(primary ray, depth 0)",
            "trace(ray, depth):",
            "    nearest hit P, normal n (t > ε); no hit: return the background",
            "    k_a, k_d, n ← textured, bumped at P (if the material says);  c ← k_a I_a",
            "    for each light L with n·l > 0: cast a shadow ray P → L",
            "        unblocked: c += att (k_d (n·l) + k_s (r·v)^p) I_L",
            "    if depth < max depth:",
            "        c += k_r · trace(mirror ray r = d − 2 (d·n) n, depth + 1)",
            "        c += k_t · trace(refracted ray (Snell), depth + 1)",
            "    return c",
            "distributed: colour(i, j) ← Σ w_k trace(ray k: pixel point, lens point, time) / Σ w_k",
            "    area light: M shadow rays to points over its area, each adding 1/M of its terms",
            "    glossy: c += k_r/G · trace(ray drawn from the Phong lobe about r), G times",
            "first, once: a bounding volume hierarchy over the objects (SAH), so a ray tests few",
        },
        {
            {"pixel", "a pixel's colour is computed (its whole ray tree)"},
            {"row", "a row of pixels is computed"},
            {"primary", "the primary ray from the eye through the pixel is cast"},
            {"hit", "the nearest intersection: its point, normal and the ambient term"},
            {"texture",
             "the hit's textures: (u, v) and the texel lookup, the solid texture, the bumped "
             "normal"},
            {"miss", "the ray hits nothing: it returns the background colour"},
            {"lit", "the shadow ray reaches the light: its diffuse and specular terms are added"},
            {"shadowed", "the shadow ray is blocked: the point is in this light's shadow"},
            {"light-behind", "the light is behind the surface (n·l ≤ 0): it adds nothing"},
            {"reflect", "a mirror ray is cast from the hit"},
            {"refract", "a refracted ray is cast into or out of the material (Snell's law)"},
            {"total-internal-reflection",
             "no refracted ray exists (total internal reflection): the mirror ray takes its share"},
            {"depth-limit", "the depth limit stops the secondary rays here"},
            {"return", "a ray's colour is weighted and summed into the ray that cast it"},
            {"colour", "the primary ray's colour is the pixel's colour"},
            {"area-light",
             "shadow rays over an area light: the share of its points the hit sees, and their "
             "terms"},
            {"glossy", "a reflected ray drawn from the Phong lobe about the mirror direction"},
            {"build",
             "the bounding volume hierarchy over the scene's objects is built (once, before the "
             "first ray): what a ray's nearest-hit search will walk"},
        },
        {},  // no sliders
        {
            .predict =
                {
                    {"hit", {"t", "n"}},
                    {"lit", {"n·l"}},
                    {"reflect", {"direction"}},
                    {"refract", {"cos θ2"}},
                },
            .mistakes =
                {
                    {"lit", "l", "negate", "took l from the light to the point"},
                    {"shadowed", "", "event:lit", "ignored the blocker on the way to the light"},
                    {"reflect", "direction", "negate", "reflected the wrong way: r = 2(d·n)n − d"},
                    {"hit", "n", "negate", "took the normal pointing into the surface"},
                },
            .costs = {"rays"},
        },
    };
    return s;
}

namespace {

const char* event_id(Event e) {
    static const char* ids[] = {"",
                                "pixel",
                                "row",
                                "primary",
                                "hit",
                                "miss",
                                "lit",
                                "shadowed",
                                "light-behind",
                                "reflect",
                                "refract",
                                "total-internal-reflection",
                                "depth-limit",
                                "return",
                                "colour",
                                "texture",
                                "area-light",
                                "glossy",
                                "build"};
    return ids[static_cast<int>(e)];
}

// Whether the scene's rays go through a hierarchy: an object tree, or a mesh's own.
bool has_hierarchy(const rt::Prepared& p) {
    if (!p.bvh.nodes.empty()) return true;
    for (const rt::PreparedObject& o : p.objects)
        if (o.kind == rt::ObjectKind::Mesh) return true;
    return false;
}

int event_line(Event e) {
    switch (e) {
        case Event::Pixel:
        case Event::Row:
        case Event::Colour:
            return 3;
        case Event::Primary:
            return 2;
        case Event::Hit:
        case Event::Miss:
            return 5;
        case Event::Lit:
            return 8;
        case Event::Shadowed:
        case Event::LightBehind:
            return 7;
        case Event::Reflect:
            return 10;
        case Event::Refract:
        case Event::TotalInternal:
            return 11;
        case Event::DepthLimit:
            return 9;
        case Event::Return:
            return 12;
        case Event::Texture:
            return 6;
        case Event::AreaLight:
            return 14;
        case Event::Glossy:
            return 15;
        case Event::Build:
            return 16;
        case Event::None:
            break;
    }
    return 0;
}

}  // namespace

// ---- [validate and start] -------------------------------------------------------------------

void RayTracer::validate(const Input& in) {
    rt::validate(in.scene);
    if (in.granularity != Granularity::RayTree) return;
    if (in.explicit_ray) {
        rt::check_coordinates(in.ray_origin, "stepping.ray.origin");
        rt::check_coordinates(in.ray_direction, "stepping.ray.direction");
        const double m = std::max({std::fabs(in.ray_direction.x), std::fabs(in.ray_direction.y),
                                   std::fabs(in.ray_direction.z)});
        if (m == 0)
            throw InputError("stepping.ray.direction",
                             "must not be the zero vector: a ray needs a direction");
        if (!(m >= 1e-150))
            throw InputError("stepping.ray.direction",
                             "is too short (largest component " + given(m) +
                                 " < 1e-150): t is in units of the direction");
        return;
    }
    const rt::Camera& c = in.scene.camera;
    if (!(in.pixel.x >= 0 && in.pixel.x < c.width && in.pixel.y >= 0 && in.pixel.y < c.height))
        throw InputError("stepping.pixel", "must lie on the " + std::to_string(c.width) + "×" +
                                               std::to_string(c.height) +
                                               " screen: 0 ≤ x < width, 0 ≤ y < height (got " +
                                               given(in.pixel) + ")");
}

RayTracer::State RayTracer::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.prepared = Shared<rt::Prepared>(rt::prepare(in.scene));
    const rt::Camera& c = in.scene.camera;
    if (in.granularity == Granularity::RayTree) {
        s.pixel_i = std::min(static_cast<int>(std::floor(in.pixel.x)), c.width - 1);
        s.pixel_j = std::min(static_cast<int>(std::floor(in.pixel.y)), c.height - 1);
        // A small image is cheap to render whole: the picture shows the pixel inside it (a
        // distributed one only when that stays cheap).
        const bool cheap = !s.prepared->distributed ||
                           rt::pixel_work(in.scene) * c.width * c.height <= kPreviewWork;
        if (!in.explicit_ray && static_cast<long long>(c.width) * c.height <= kPreviewPixels &&
            cheap)
            s.preview = Shared<std::vector<std::uint32_t>>(rt::render(in.scene, 1).rgba);
        if (s.prepared->distributed) {
            s.rng = in.explicit_ray ? rt::pixel_rng(in.scene, -1, -1)
                                    : rt::pixel_rng(in.scene, s.pixel_i, s.pixel_j);
            s.samples = in.explicit_ray ? std::vector<rt::PixelSample>(1)
                                        : rt::pixel_samples(in.scene, s.pixel_i, s.pixel_j, s.rng);
        }
    } else {
        s.image.reset(c.width, c.height);
        s.row_rays.assign(static_cast<std::size_t>(c.height), rt::RayCounts{});
    }
    return s;
}

// ---- [the image rows] -----------------------------------------------------------------------

void RayTracer::Rows::reset(int width, int height) {
    width_ = width;
    const auto blank = std::make_shared<std::vector<std::uint32_t>>(width, 0u);
    rows_.assign(height, blank);
}

void RayTracer::Rows::set(int i, int j, std::uint32_t v) {
    auto& row = rows_[j];
    if (row.use_count() != 1) row = std::make_shared<std::vector<std::uint32_t>>(*row);
    (*row)[i] = v;
}

std::vector<std::uint32_t> RayTracer::Rows::pixels() const {
    std::vector<std::uint32_t> out;
    out.reserve(static_cast<std::size_t>(width_) * rows_.size());
    for (const auto& r : rows_) out.insert(out.end(), r->begin(), r->end());
    return out;
}

bool RayTracer::Rows::operator==(const Rows& o) const {
    if (width_ != o.width_ || rows_.size() != o.rows_.size()) return false;
    for (std::size_t j = 0; j < rows_.size(); ++j)
        if (rows_[j] != o.rows_[j] && *rows_[j] != *o.rows_[j]) return false;
    return true;
}

// ---- [stepping] -----------------------------------------------------------------------------

void RayTracer::advance(State& s) {
    const Input& in = *s.in;
    const rt::Scene& sc = in.scene;
    const int W = sc.camera.width, H = sc.camera.height;
    switch (s.phase) {
        case Phase::Start:
            s.phase = in.granularity == Granularity::RayTree ? Phase::Tree : Phase::Pixels;
            // The hierarchy (built in start, with the prepared scene) is shown first, when
            // there is one to show.
            if (has_hierarchy(*s.prepared)) {
                s.last_event = Event::Build;
                return;
            }
            advance(s);
            return;
        case Phase::Pixels: {
            const long long total = static_cast<long long>(W) * H;
            const rt::RayCounts before = s.rays;
            if (in.granularity == Granularity::Rows) {
                const int j = static_cast<int>(s.next_pixel / W);
                for (int i = 0; i < W; ++i)
                    s.image.set(i, j, pack_rgba(rt::pixel_color(sc, *s.prepared, i, j, s.rays)));
                s.last_i = -1, s.last_j = j;
                s.next_pixel += W;
                s.last_event = Event::Row;
            } else {
                const int i = static_cast<int>(s.next_pixel % W),
                          j = static_cast<int>(s.next_pixel / W);
                s.last_color = rt::pixel_color(sc, *s.prepared, i, j, s.rays);
                s.image.set(i, j, pack_rgba(s.last_color));
                s.last_i = i, s.last_j = j;
                ++s.next_pixel;
                s.last_event = Event::Pixel;
            }
            rt::RayCounts& row = s.row_rays[static_cast<std::size_t>(s.last_j)];
            row.primary += s.rays.primary - before.primary;
            row.shadow += s.rays.shadow - before.shadow;
            row.reflected += s.rays.reflected - before.reflected;
            row.refracted += s.rays.refracted - before.refracted;
            if (s.next_pixel >= total) s.phase = Phase::Done;
            return;
        }
        case Phase::Tree:
            advance_tree(s);
            return;
        case Phase::Done:
            return;
    }
}

// One event of the ray tree. The arithmetic mirrors rt::trace() step for step (same operands,
// same order), so the colour is the plain tracer's to the last bit.
void RayTracer::advance_tree(State& s) {
    const Input& in = *s.in;
    const rt::Scene& sc = in.scene;
    const rt::Prepared& p = *s.prepared;

    const bool distributed = p.distributed;
    if (s.stack.empty()) {  // the primary ray (of the next pixel sample)
        RayNode n;
        n.kind = RayKind::Primary;
        if (in.explicit_ray) {
            n.origin = in.ray_origin;
            n.direction = in.ray_direction;
        } else if (distributed) {
            const rt::PixelSample& ps = s.samples[s.next_sample];
            rt::primary_ray(p, sc.camera, s.pixel_i, s.pixel_j, ps, n.origin, n.direction);
            n.time = ps.time;
        } else {
            n.origin = p.view.eye;
            n.direction = rt::screen_point(p.view, s.pixel_i + 0.5, s.pixel_j + 0.5) - p.view.eye;
        }
        if (distributed) n.sample = s.next_sample++;
        const int id = static_cast<int>(s.tree.size());
        s.tree.push_back(n);
        s.stack.push_back({id, Next::Cast, 0, Color(0.0)});
        ++s.rays.primary;
        s.active = id;
        s.last_event = Event::Primary;
        return;
    }

    for (;;) {  // until something a student should see happens
        Frame& f = s.stack.back();
        RayNode& ray = s.tree[f.node];
        s.active = f.node;
        switch (f.next) {
            case Next::Cast: {
                ray.hit = rt::nearest_hit(p, ray.origin, ray.direction, kRayEpsilon, Quadric::kInf,
                                          ray.time);
                ray.traced = true;
                if (ray.hit.object < 0) {
                    f.c = sc.background;
                    f.next = Next::Return;
                    s.last_event = Event::Miss;
                    return;
                }
                const rt::Material& m = sc.materials[p.objects[ray.hit.object].material];
                // The primary ray of a pixel carries its differential (for mipmaps), as in
                // rt::pixel_color.
                const bool pixel_ray = ray.parent < 0 && !in.explicit_ray;
                const rt::RayDifferential diff =
                    rt::pixel_differential(p.view, s.pixel_i, s.pixel_j);
                rt::SurfaceDetail detail;
                const bool textured = m.tex.any();
                ray.surface = rt::moving_surface_at(sc, p, ray.hit, ray.origin, ray.direction,
                                                    pixel_ray ? &diff : nullptr, ray.time,
                                                    textured ? &detail : nullptr);
                if (textured) {
                    ray.detail = static_cast<int>(s.details.size());
                    s.details.push_back(detail);
                }
                f.c = ray.surface.ka * sc.ambient;
                f.next = textured ? Next::Texture : Next::Light;
                f.light = 0;
                s.last_event = Event::Hit;
                return;
            }
            case Next::Texture:  // the lookup was made with the hit; this step shows it
                f.next = Next::Light;
                s.last_event = Event::Texture;
                return;
            case Next::Light: {
                if (f.light >= static_cast<int>(sc.lights.size())) {
                    f.next = Next::Secondary;
                    continue;
                }
                const int k = f.light++;
                const rt::Material& m = sc.materials[p.objects[ray.hit.object].material];
                const dvec3 v = -unit(ray.direction);
                if (distributed && sc.lights[k].area != rt::Light::Area::None) {
                    // Shadow rays over the light's area, all in this step.
                    const std::vector<dvec3> points = rt::light_points(sc.lights[k], s.rng);
                    const double share = 1.0 / double(points.size());
                    rt::Light at = sc.lights[k];
                    const int node = f.node;
                    const rt::Hit hit = ray.hit;
                    const rt::Surface surface = ray.surface;
                    const int depth = ray.depth;
                    const double time = ray.time;
                    s.area_lit = 0, s.area_rays = 0;
                    for (std::size_t q = 0; q < points.size(); ++q) {
                        at.position = points[q];
                        const rt::LightTerm lt =
                            rt::light_term(sc, at, surface.kd, m, hit.point, surface.normal, v);
                        if (!lt.facing) continue;
                        if (sc.settings.shadows) {
                            RayNode sh;
                            sh.kind = RayKind::Shadow;
                            sh.parent = node;
                            sh.depth = depth;
                            sh.time = time;
                            sh.origin = rt::offset_point(p, hit.point, hit.normal);
                            sh.direction = lt.l;
                            sh.light = k;
                            sh.light_sample = static_cast<int>(q);
                            sh.light_point = points[q];
                            sh.t_max = lt.distance;
                            sh.blocker = rt::first_blocker(p, sh.origin, sh.direction, kRayEpsilon,
                                                           lt.distance, time);
                            sh.traced = true;
                            ++s.rays.shadow;
                            ++s.area_rays;
                            const bool blocked = sh.blocker >= 0;
                            if (!blocked) sh.color = (lt.diffuse + lt.specular) * share;
                            s.tree.push_back(sh);
                            if (blocked) continue;
                        }
                        ++s.area_lit;
                        s.stack.back().c += (lt.diffuse + lt.specular) * share;
                    }
                    s.active = node;
                    s.last_event = Event::AreaLight;
                    return;
                }
                s.last_term = rt::light_term(sc, sc.lights[k], ray.surface.kd, m, ray.hit.point,
                                             ray.surface.normal, v);
                const rt::LightTerm& lt = s.last_term;
                if (!lt.facing) {
                    s.last_event = Event::LightBehind;
                    return;
                }
                if (sc.settings.shadows) {
                    RayNode sh;
                    sh.kind = RayKind::Shadow;
                    sh.parent = f.node;
                    sh.depth = ray.depth;
                    sh.origin = rt::offset_point(p, ray.hit.point, ray.hit.normal);
                    sh.direction = lt.l;
                    sh.light = k;
                    sh.t_max = lt.distance;
                    sh.time = ray.time;
                    sh.blocker = rt::first_blocker(p, sh.origin, sh.direction, kRayEpsilon,
                                                   lt.distance, ray.time);
                    sh.traced = true;
                    ++s.rays.shadow;
                    const bool blocked = sh.blocker >= 0;
                    if (!blocked) sh.color = lt.diffuse + lt.specular;
                    s.active = static_cast<int>(s.tree.size());
                    s.tree.push_back(sh);  // invalidates `ray`; f is still valid
                    if (blocked) {
                        s.last_event = Event::Shadowed;
                        return;
                    }
                }
                s.stack.back().c += lt.diffuse + lt.specular;
                s.last_event = Event::Lit;
                return;
            }
            case Next::Secondary:
            case Next::Refract: {
                const rt::Material& m = sc.materials[p.objects[ray.hit.object].material];
                const bool wants_reflect = sc.settings.reflections && rt::any_positive(m.kr);
                const bool wants_refract = sc.settings.refractions && rt::any_positive(m.kt);
                if (ray.depth >= sc.settings.max_depth) {
                    f.next = Next::Return;
                    if (wants_reflect || wants_refract) {
                        s.last_event = Event::DepthLimit;
                        return;
                    }
                    continue;
                }
                const dvec3 dn = unit(ray.direction);
                RayNode child;
                child.parent = f.node;
                child.depth = ray.depth + 1;
                child.time = ray.time;
                rt::SecondaryRay sec;
                if (f.next == Next::Secondary && wants_reflect && distributed && m.gloss > 0) {
                    // Glossy: G rays from the Phong lobe about the mirror direction, one a step.
                    sec = rt::mirror_ray(p, ray.hit, dn);
                    s.gloss_skipped = 0;
                    bool cast = false;
                    while (f.gloss < m.gloss_samples) {
                        const dvec3 dir = rt::glossy_direction(sec.direction, m.gloss, s.rng);
                        ++f.gloss;
                        if (!(glm::dot(dir, ray.hit.normal) > 0)) {  // below the surface
                            ++s.gloss_skipped;
                            continue;
                        }
                        sec.direction = dir;
                        cast = true;
                        break;
                    }
                    if (!cast) {
                        f.next = Next::Refract;
                        continue;
                    }
                    if (f.gloss == m.gloss_samples) f.next = Next::Refract;
                    child.kind = RayKind::Reflected;
                    child.glossy = true;
                    child.origin = sec.origin;
                    child.direction = sec.direction;
                    child.weight = m.kr * (1.0 / double(m.gloss_samples));
                    ++s.rays.reflected;
                    const int id = static_cast<int>(s.tree.size());
                    s.tree.push_back(child);
                    s.stack.push_back({id, Next::Cast, 0, Color(0.0)});
                    s.active = id;
                    s.last_event = Event::Glossy;
                    return;
                }
                if (f.next == Next::Secondary) {
                    f.next = Next::Refract;
                    if (!wants_reflect) continue;
                    sec = rt::mirror_ray(p, ray.hit, dn);
                    child.weight = m.kr;
                    s.last_event = Event::Reflect;
                } else {
                    f.next = Next::Return;
                    if (!wants_refract) continue;
                    sec = rt::transmitted_ray(p, ray.hit, dn, m.ior);
                    child.weight = m.kt;
                    s.last_event = sec.refracted ? Event::Refract : Event::TotalInternal;
                }
                child.kind = sec.refracted ? RayKind::Refracted : RayKind::Reflected;
                child.total_internal = sec.total_internal;
                child.origin = sec.origin;
                child.direction = sec.direction;
                ++(sec.refracted ? s.rays.refracted : s.rays.reflected);
                const int id = static_cast<int>(s.tree.size());
                s.tree.push_back(child);
                s.stack.push_back({id, Next::Cast, 0, Color(0.0)});
                s.active = id;
                return;
            }
            case Next::Return: {
                ray.color = f.c;
                ray.returned = true;
                const int node = f.node;
                s.stack.pop_back();
                s.active = node;
                if (s.stack.empty() && distributed) {  // one pixel sample done
                    const rt::PixelSample& ps = s.samples[s.tree[node].sample];
                    s.sum += ps.weight * s.tree[node].color;
                    s.sum_w += ps.weight;
                    if (s.next_sample < static_cast<int>(s.samples.size())) {
                        s.last_event = Event::Return;
                        return;
                    }
                    s.pixel_color = s.sum / s.sum_w;
                    s.phase = Phase::Done;
                    s.last_event = Event::Colour;
                    return;
                }
                if (s.stack.empty()) {
                    s.pixel_color = s.tree[0].color;
                    s.phase = Phase::Done;
                    s.last_event = Event::Colour;
                    return;
                }
                s.stack.back().c += s.tree[node].weight * s.tree[node].color;
                s.last_event = Event::Return;
                return;
            }
        }
    }
}

void RayTracer::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narration] ----------------------------------------------------------------------------

const char* RayTracer::kind_id(RayKind k) {
    switch (k) {
        case RayKind::Primary:
            return "primary";
        case RayKind::Shadow:
            return "shadow";
        case RayKind::Reflected:
            return "reflected";
        case RayKind::Refracted:
            return "refracted";
    }
    return "";
}

namespace {

std::string object_name(const rt::Scene& sc, int k) {
    return k < 0 ? std::string("nothing") : sc.objects[k].name;
}

// What a ray hit: the object's name, and for a mesh which of its triangles
// ("terrain.triangles[7]").
std::string hit_name(const rt::Scene& sc, const rt::Hit& h) {
    if (h.object < 0) return "nothing";
    const rt::Object& o = sc.objects[h.object];
    if (o.kind != rt::ObjectKind::Mesh || h.triangle < 0) return o.name;
    return o.name + ".triangles[" +
           std::to_string(o.mesh->source_index(static_cast<std::size_t>(h.triangle))) + "]";
}

std::vector<double> colour_vec(const Color& c) {
    return {c.x, c.y, c.z};
}

std::string rgb8_text(std::uint32_t v) {
    return "(" + std::to_string(v >> 24) + ", " + std::to_string((v >> 16) & 0xff) + ", " +
           std::to_string((v >> 8) & 0xff) + ")";
}

}  // namespace

std::string RayTracer::ray_label(const std::vector<RayNode>& tree, int k) {
    const RayNode& n = tree[k];
    const char* letter = n.kind == RayKind::Primary     ? "R"
                         : n.kind == RayKind::Shadow    ? "S"
                         : n.kind == RayKind::Reflected ? "M"
                                                        : "T";
    return letter + std::to_string(k);
}

namespace {

// How the nearest hit was found: the hierarchy's box and object tests for this ray (counted
// again here, for the narration only; a mesh's triangle tests count as object tests) against
// brute force's one test per object and per mesh triangle.
void narrate_search(const RayTracer::State& s, const RayTracer::RayNode& n, StepInfo& info) {
    const rt::Prepared& p = *s.prepared;
    const rt::TraversalCounts c =
        rt::traversal_counts(p, n.origin, n.direction, kRayEpsilon, Quadric::kInf, n.time);
    long long all = 0;
    for (const rt::PreparedObject& o : p.objects)
        all += o.kind == rt::ObjectKind::Mesh
                   ? static_cast<long long>(o.mesh->mesh.triangles.size())
                   : 1;
    if (all < 2) return;
    auto count = [](long long k, const char* what) {
        return std::to_string(k) + " " + what + (k == 1 ? "" : "s");
    };
    info.narration +=
        " Found with " + count(c.box_tests, "box test") + " and " +
        count(c.object_tests, "object test") +
        " in the scene's bounding volume hierarchy (brute force: " + count(all, "object test") +
        ").";
    info.vars.push_back({"box tests", c.box_tests});
    info.vars.push_back({"object tests", c.object_tests});
}

// A hit on a CSG object: the segment lists of its tree for this ray, leaf by leaf and node by
// node, and which end is the hit (the lists are recomputed here, for the narration only).
void narrate_csg_hit(const rt::Object& o, const PreparedCsg& p, const RayTracer::RayNode& ray,
                     StepInfo& info) {
    std::vector<CsgSpans> lists;
    csg_lists(p, ray.origin, ray.direction, lists);
    std::string merge;
    for (std::size_t k = 0; k < o.csg.nodes.size(); ++k) {
        const CsgNode& n = o.csg.nodes[k];
        std::string name = csg_node_label(n);
        if (!n.leaf)
            name += " = " + csg_node_label(o.csg.nodes[n.left]) + " " + csg_op_symbol(n.op) + " " +
                    csg_node_label(o.csg.nodes[n.right]);
        merge += (merge.empty() ? "" : "; ") + name + ": " + csg_spans_text(lists[k]);
    }
    info.narration += " CSG segments along the ray: " + merge +
                      "; the first end beyond ε, t = " + num(ray.hit.t, 6) + ", is the hit.";
    info.vars.push_back({"CSG segments", csg_spans_text(lists.back())});
}

// The texture step: what the hit's material did to k_a, k_d and the normal.
void narrate_texture(const rt::Scene& sc, const rt::SurfaceDetail& d, const RayTracer::RayNode& n,
                     StepInfo& info) {
    const rt::Material& m = sc.materials[sc.objects[n.hit.object].material];
    std::string text, math;
    auto add = [&](std::string name, Value v) {
        info.vars.push_back({std::move(name), std::move(v)});
    };
    if (d.textured) {
        const TextureLookup& l = d.lookup;
        text = "Texture: (u, v) = " + num(d.frame.uv, 4) + " → texel (" +
               std::to_string(l.taps.texel[0].x) + ", " + std::to_string(l.taps.texel[0].y) +
               ") of the " + std::to_string(m.tex.texture.image.width) + "×" +
               std::to_string(m.tex.texture.image.height) + " " + m.tex.texture.source + ", " +
               filter_id(m.tex.texture.filter) +
               (m.tex.texture.filter == TexFilter::Mipmap
                    ? " (footprint " + num(d.footprint, 3) + ", λ = " + num(l.lambda, 3) + ")"
                    : "") +
               ": T = " + num(l.color, 4) + ". ";
        math = "T(" + tex(d.frame.uv, 4) + ") = " + tex(l.color, 4);
        add("uv", vec(d.frame.uv));
        add("texel", std::vector<double>{double(l.taps.texel[0].x), double(l.taps.texel[0].y)});
        add("T", vec(l.color));
    }
    if (d.solid) {
        text = std::string("Solid texture (") + solid_kind_id(m.tex.solid.kind) + ") at " +
               num(d.solid_point, 4) +
               (uses_noise(m.tex.solid.kind) ? ": noise " + num(d.solid_sample.noise, 4) : "") +
               ", mix " + num(d.solid_sample.t, 4) + ": T = " + num(d.solid_sample.color, 4) + ". ";
        math = "T = (1 - t)\\,c_0 + t\\,c_1 = " + tex(d.solid_sample.color, 4);
        add("solid point", vec(d.solid_point));
        add("T", vec(d.solid_sample.color));
    }
    if (d.textured || d.solid)
        text += "k_a = " + num(n.surface.ka, 4) + ", k_d = " + num(n.surface.kd, 4) + ". ";
    if (d.bumped) {
        text += "Bump: B_u = " + num(d.bump.B_u, 4) + ", B_v = " + num(d.bump.B_v, 4) +
                ", the normal " + num(n.hit.normal, 4) + " becomes " + num(n.surface.normal, 4) +
                " for the lighting.";
        if (!math.empty()) math += ",\\; ";
        math += "n' = n + \\frac{B_u (n \\times P_v) - B_v (n \\times P_u)}{|n|}";
        add("B_u", d.bump.B_u);
        add("B_v", d.bump.B_v);
        add("n'", vec(n.surface.normal));
    }
    info.narration = text;
    info.math = math;
}

}  // namespace

namespace {

// The hierarchy's shape: what a student checks against the course's "fewer ray-object tests".
[[gnu::cold]] void narrate_build(const RayTracer::State& s, StepInfo& info) {
    const rt::Scene& sc = s.in->scene;
    const rt::Prepared& p = *s.prepared;
    const rt::ObjectBvh& b = p.bvh;
    auto add = [&](std::string name, Value v) {
        info.vars.push_back({std::move(name), std::move(v)});
    };
    long long leaves = 0;
    for (const rt::BvhNode& n : b.nodes) leaves += n.count > 0;
    auto count = [](std::size_t k, const char* one, const char* many) {
        return std::to_string(k) + " " + (k == 1 ? one : many);
    };
    const std::size_t bounded = sc.objects.size() - b.unbounded.size();
    std::string text;
    if (!b.nodes.empty()) {
        text = "Built the bounding volume hierarchy over the " + std::to_string(bounded) +
               " objects with a bounding box: " + count(b.nodes.size(), "node", "nodes") + ", " +
               count(static_cast<std::size_t>(leaves), "leaf", "leaves") + ", depth " +
               std::to_string(b.depth) +
               " (surface area heuristic: a node is split where ½ + (S_L/S) N_L + (S_R/S) N_R is "
               "least). A ray now tests a box before the objects inside it.";
        if (!b.unbounded.empty())
            text += " " + std::to_string(b.unbounded.size()) +
                    " object(s) without a finite box (planes, CSG, moving or open quadrics) are "
                    "tested for every ray.";
    } else {
        text =
            "No tree over the objects (fewer than two have a bounding box): every object is "
            "tested for every ray.";
    }
    info.math = "C = C_{trav} + \\frac{S_L}{S} N_L C_{isect} + \\frac{S_R}{S} N_R C_{isect}";
    add("objects", static_cast<long long>(sc.objects.size()));
    add("in the tree", static_cast<long long>(b.nodes.empty() ? 0 : bounded));
    add("nodes", static_cast<long long>(b.nodes.size()));
    add("leaves", leaves);
    add("depth", static_cast<long long>(b.depth));
    add("tested for every ray", static_cast<long long>(b.unbounded.size()));
    for (std::size_t k = 0; k < sc.objects.size(); ++k) {
        if (sc.objects[k].kind != rt::ObjectKind::Mesh) continue;
        const rt::MeshBvh& m = sc.objects[k].mesh->bvh;
        const std::size_t tris = m.triangles.size();
        text += " Mesh " + sc.objects[k].name + ": its own hierarchy over " + std::to_string(tris) +
                " triangles, " + std::to_string(m.nodes.size()) +
                " nodes of four children, depth " + std::to_string(m.depth) + ", " +
                num(static_cast<double>(m.bytes()) / static_cast<double>(tris), 3) +
                " bytes a triangle; a ray meeting its box costs about " + num(m.cost, 3) +
                " tests instead of " + std::to_string(tris) + ".";
        add(sc.objects[k].name + " triangles", static_cast<long long>(tris));
        add(sc.objects[k].name + " expected tests", m.cost);
    }
    info.narration = text;
}

}  // namespace

void RayTracer::narrate(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const rt::Scene& sc = in.scene;
    info.event = event_id(s.last_event);
    info.line = event_line(s.last_event);
    auto add = [&](std::string name, Value v) {
        info.vars.push_back({std::move(name), std::move(v)});
    };
    switch (s.last_event) {
        case Event::Pixel: {
            const std::uint32_t v = s.image.get(s.last_i, s.last_j);
            info.narration = "Pixel (" + std::to_string(s.last_i) + ", " +
                             std::to_string(s.last_j) + "): colour " + num(s.last_color, 4) +
                             ", stored as " + rgb8_text(v) + ".";
            add("pixel", std::vector<double>{double(s.last_i), double(s.last_j)});
            add("colour", colour_vec(s.last_color));
            add("rays so far", static_cast<long long>(s.rays.total()));
            return;
        }
        case Event::Row:
            info.narration = "Row " + std::to_string(s.last_j) + " of " +
                             std::to_string(sc.camera.height) + " computed (" +
                             std::to_string(s.rays.total()) + " rays so far).";
            add("row", static_cast<long long>(s.last_j));
            add("rays so far", static_cast<long long>(s.rays.total()));
            return;
        case Event::Build:
            narrate_build(s, info);
            return;
        case Event::None:
            return;
        default:
            break;
    }
    const RayNode& n = s.tree[s.active];
    const std::string name = RayTracer::ray_label(s.tree, s.active);
    add("ray", name + " (" + kind_id(n.kind) + ")");
    add("depth", static_cast<long long>(n.depth));
    add("origin", vec(n.origin));
    add("direction", vec(n.direction));
    const bool distributed = s.prepared->distributed;
    switch (s.last_event) {
        case Event::Primary:
            if (distributed && !in.explicit_ray) {
                const rt::PixelSample& ps = s.samples[n.sample];
                const rt::Camera& c = sc.camera;
                // What the primary rays are spread over (one sample sits at the centre).
                std::vector<std::string> over;
                if (s.samples.size() > 1)
                    over.push_back("the pixel's area (" +
                                   std::string(sampling::pattern_id(sc.settings.pattern)) +
                                   " pattern, " + sampling::filter_id(sc.settings.filter) +
                                   " filter)");
                if (c.aperture > 0) over.push_back("the lens aperture (depth of field)");
                if (c.shutter > 0) over.push_back("the shutter time (motion blur)");
                std::string spread = "one primary ray, through the pixel's centre";
                if (!over.empty()) {
                    spread = "primary rays are distributed over " + over[0];
                    for (std::size_t k = 1; k < over.size(); ++k)
                        spread += (k + 1 == over.size() ? " and " : ", ") + over[k];
                }
                info.narration =
                    "Pixel (" + std::to_string(s.pixel_i) + ", " + std::to_string(s.pixel_j) +
                    "), sample " + std::to_string(n.sample + 1) + " of " +
                    std::to_string(s.samples.size()) + ": " + spread +
                    ". This one crosses the pixel at (" + num(ps.pixel.x, 4) + ", " +
                    num(ps.pixel.y, 4) + "), filter weight " + num(ps.weight, 4) +
                    (c.aperture > 0
                         ? "; it leaves the lens at " + num(n.origin, 4) + " (lens point " +
                               num(ps.lens, 3) + " × aperture) toward the focal plane"
                         : "") +
                    (c.shutter > 0 ? "; at time " + num(ps.time, 4) : "") + ": ray " + name +
                    " = " + num(n.origin, 4) + " + t " + num(n.direction, 4) + ".";
                info.line = 13;
                info.math = "w_k = " + tex(ps.weight, 4) + ",\\; \\tau = " + tex(ps.time, 4);
                add("sample", static_cast<long long>(n.sample + 1));
                add("pixel point",
                    std::vector<double>{s.pixel_i + ps.pixel.x, s.pixel_j + ps.pixel.y});
                add("lens", vec(ps.lens));
                add("time", ps.time);
                add("weight", ps.weight);
                break;
            }
            if (in.explicit_ray)
                info.narration = "The primary ray " + name +
                                 ": E + t d with E = " + num(n.origin, 4) +
                                 ", d = " + num(n.direction, 4) + ".";
            else
                info.narration =
                    "Pixel (" + std::to_string(s.pixel_i) + ", " + std::to_string(s.pixel_j) +
                    "): its centre on the screen is P = " + num(n.origin + n.direction, 4) +
                    "; the primary ray " + name + " is E + t (P − E) with E = " + num(n.origin, 4) +
                    ", P − E = " + num(n.direction, 4) + ".";
            info.math = "E + t\\,(P - E),\\; t > 0";
            break;
        case Event::Miss:
            info.narration = "Ray " + name + " hits nothing: it returns the background " +
                             num(sc.background, 4) + ".";
            narrate_search(s, n, info);
            break;
        case Event::Hit: {
            const rt::Material& m = sc.materials[s.prepared->objects[n.hit.object].material];
            info.narration =
                "Ray " + name + " first hits " + hit_name(sc, n.hit) +
                " at t = " + num(n.hit.t, 6) + ": P = " + num(n.hit.point, 4) +
                ", n = " + num(n.hit.normal, 4) +
                (n.hit.entering ? "" : " (from inside: the normal is turned to face the ray)") +
                ". Material " + m.name +
                (n.detail >= 0 ? " (textured: k_a after its texture)" : "") +
                "; ambient k_a I_a = " + num(n.surface.ka * sc.ambient, 4) + ".";
            info.math = "c = k_a I_a = " + tex(n.surface.ka * sc.ambient, 4);
            if (sc.objects[n.hit.object].kind == rt::ObjectKind::Csg)
                narrate_csg_hit(sc.objects[n.hit.object], *s.prepared->objects[n.hit.object].csg, n,
                                info);
            add("object", hit_name(sc, n.hit));
            add("t", n.hit.t);
            add("P", vec(n.hit.point));
            add("n", vec(n.hit.normal));
            narrate_search(s, n, info);
            break;
        }
        case Event::Texture:
            narrate_texture(sc, s.details[n.detail], n, info);
            break;
        case Event::Lit:
        case Event::Shadowed:
        case Event::LightBehind: {
            const rt::LightTerm& lt = s.last_term;
            const RayNode& hit_ray = n.kind == RayKind::Shadow ? s.tree[n.parent] : n;
            const int k = n.kind == RayKind::Shadow ? n.light : s.stack.back().light - 1;
            const std::string L = "light " + std::to_string(k);
            if (s.last_event == Event::LightBehind)
                info.narration = L + " is behind the surface at " + num(hit_ray.hit.point, 4) +
                                 " (n·l = " + num(lt.n_dot_l, 4) +
                                 " ≤ 0): no shadow ray, no light.";
            else if (s.last_event == Event::Shadowed)
                info.narration = "Shadow ray " + name + " toward " + L + " is blocked by " +
                                 object_name(sc, n.blocker) + ": the point is in its shadow.";
            else
                info.narration = (sc.settings.shadows ? "Shadow ray " + name + " reaches " + L
                                                      : L + " (shadows off)") +
                                 ": n·l = " + num(lt.n_dot_l, 4) + ", attenuation " +
                                 num(lt.attenuation, 4) + ", diffuse " + num(lt.diffuse, 4) +
                                 ", specular " + num(lt.specular, 4) + " are added.";
            add("l", vec(lt.l));
            add("n·l", lt.n_dot_l);
            add(sc.settings.model == rt::Model::Phong ? "r·v" : "h·n", lt.spec_dot);
            add("attenuation", lt.attenuation);
            if (s.last_event == Event::Lit) {
                add("diffuse", colour_vec(lt.diffuse));
                add("specular", colour_vec(lt.specular));
            }
            info.math = "k_d (n \\cdot l) = " + tex(lt.n_dot_l, 4) +
                        ",\\; \\mathrm{att} = " + tex(lt.attenuation, 4);
            break;
        }
        case Event::Reflect:
        case Event::TotalInternal:
            info.narration = std::string(s.last_event == Event::TotalInternal
                                             ? "No refracted ray: total internal reflection. "
                                             : "") +
                             "Mirror ray " + name + ": r = d − 2 (d·n) n = " + num(n.direction, 4) +
                             ", weighted by " + num(n.weight, 4) + ".";
            info.math = "r = d - 2\\,(d \\cdot n)\\,n = " + tex(n.direction, 4);
            add("weight", colour_vec(n.weight));
            break;
        case Event::Refract: {
            const RayNode& parent = s.tree[n.parent];
            const rt::Material& m = sc.materials[s.prepared->objects[parent.hit.object].material];
            const double eta = parent.hit.entering ? 1 / m.ior : m.ior;
            const double cos1 = -glm::dot(unit(parent.direction), parent.hit.normal);
            const double cos2 = -glm::dot(n.direction, parent.hit.normal);
            info.narration = "Refracted ray " + name +
                             (parent.hit.entering ? " enters " : " leaves ") + m.name +
                             " (η = " + num(eta, 4) + "): cos θ₁ = " + num(cos1, 4) +
                             ", cos θ₂ = " + num(cos2, 4) + ", t = " + num(n.direction, 4) +
                             ", weighted by " + num(n.weight, 4) + ".";
            info.math =
                "\\eta_1 \\sin\\theta_1 = \\eta_2 \\sin\\theta_2,\\; \\eta = " + tex(eta, 4);
            add("eta", eta);
            add("cos θ1", cos1);
            add("cos θ2", cos2);
            add("weight", colour_vec(n.weight));
            break;
        }
        case Event::DepthLimit:
            info.narration = "Ray " + name + " is at depth " + std::to_string(n.depth) +
                             " = the limit: no mirror or refracted rays from here.";
            break;
        case Event::Return: {
            if (n.parent < 0) {  // a pixel sample's primary ray
                const rt::PixelSample& ps = s.samples[n.sample];
                info.narration = "Sample " + std::to_string(n.sample + 1) + " of " +
                                 std::to_string(s.samples.size()) + ": ray " + name + " returns " +
                                 num(n.color, 4) + "; × its weight " + num(ps.weight, 4) +
                                 " it joins the pixel's sum, now " + num(s.sum, 4) +
                                 " over Σw = " + num(s.sum_w, 4) + ".";
                add("returned", colour_vec(n.color));
                add("sum", colour_vec(s.sum));
                add("sum_w", s.sum_w);
                break;
            }
            info.narration = "Ray " + name + " returns " + num(n.color, 4) + "; × " +
                             num(n.weight, 4) + " is added to " +
                             RayTracer::ray_label(s.tree, n.parent) + ", whose colour so far is " +
                             num(s.stack.back().c, 4) + ".";
            add("returned", colour_vec(n.color));
            add("weight", colour_vec(n.weight));
            break;
        }
        case Event::AreaLight: {
            const int k = s.stack.back().light - 1;
            const rt::Light& l = sc.lights[k];
            const char* shape = l.area == rt::Light::Area::Rectangle ? "rectangle" : "disc";
            info.narration =
                "Light " + std::to_string(k) + " is an area light (a " + shape +
                "): " + std::to_string(l.samples) + " shadow rays are distributed over its area, " +
                (sc.settings.shadows
                     ? std::to_string(s.area_rays) +
                           " of them cast (points in front of the "
                           "surface), " +
                           std::to_string(s.area_lit) + " reach the light"
                     : "shadows off, " + std::to_string(s.area_lit) + " points in front") +
                ": each adds 1/" + std::to_string(l.samples) +
                " of its point's diffuse and specular terms, so the point sees " +
                num(double(s.area_lit) / l.samples, 4) + " of the light" +
                (s.area_lit > 0 && s.area_lit < l.samples ? " — a penumbra" : "") + ".";
            info.math =
                "\\frac{1}{M}\\sum_m v_m\\,(k_d (n \\cdot l_m) + k_s (r_m \\cdot v)^p) I,\\; "
                "M = " +
                std::to_string(l.samples);
            add("light", static_cast<long long>(k));
            add("shadow rays", static_cast<long long>(s.area_rays));
            add("reaching the light", static_cast<long long>(s.area_lit));
            break;
        }
        case Event::Glossy: {
            const RayNode& parent = s.tree[n.parent];
            const rt::Material& m = sc.materials[s.prepared->objects[parent.hit.object].material];
            const dvec3 mirror = rt::reflect(unit(parent.direction), parent.hit.normal);
            const double angle =
                std::acos(std::clamp(glm::dot(unit(n.direction), mirror), -1.0, 1.0)) * 180 / M_PI;
            info.narration =
                "Glossy ray " + name + " (" + std::to_string(s.stack[s.stack.size() - 2].gloss) +
                " of " + std::to_string(m.gloss_samples) + "): reflected rays of " + m.name +
                " are distributed over the Phong lobe about the mirror direction r = " +
                num(mirror, 4) + ", density ∝ cos^" + num(m.gloss, 4) +
                " of the angle to r; this one is " + num(angle, 3) + "° off it, weighted k_r/" +
                std::to_string(m.gloss_samples) + " = " + num(n.weight, 4) +
                (s.gloss_skipped > 0 ? " (" + std::to_string(s.gloss_skipped) +
                                           " drawn below the surface before it add nothing)"
                                     : "") +
                ".";
            info.math = "\\cos\\theta = \\xi^{1/(p+1)},\\; \\theta = " + tex(angle, 3) + "^\\circ";
            add("angle to r", angle);
            add("weight", colour_vec(n.weight));
            break;
        }
        case Event::Colour:
            if (distributed && !in.explicit_ray) {
                info.narration = "The pixel's colour is the filtered average of its " +
                                 std::to_string(s.samples.size()) + " samples: " + num(s.sum, 4) +
                                 " / " + num(s.sum_w, 4) + " = " + num(s.pixel_color, 4) +
                                 ", stored as " + rgb8_text(pack_rgba(s.pixel_color)) + ".";
                info.line = 13;
                break;
            }
            info.narration = "The primary ray returns " + num(s.pixel_color, 4) +
                             ": the pixel's colour, stored as " +
                             rgb8_text(pack_rgba(s.pixel_color)) + " (clamped to [0, 1], × 255).";
            break;
        default:
            break;
    }
    if (!s.stack.empty()) add("c (so far)", colour_vec(s.stack.back().c));
    add("rays cast", static_cast<long long>(s.rays.total()));
}

// ---- [result] -------------------------------------------------------------------------------

RayTracer::Result RayTracer::result(const State& s) {
    Result r;
    r.granularity = s.in->granularity;
    r.width = s.in->scene.camera.width;
    r.height = s.in->scene.camera.height;
    r.rays = s.rays;
    if (r.granularity == Granularity::RayTree) {
        r.explicit_ray = s.in->explicit_ray;
        r.pixel_i = s.pixel_i;
        r.pixel_j = s.pixel_j;
        r.color = s.pixel_color;
        r.tree = s.tree;
        r.details = s.details;
        r.distributed = s.prepared->distributed;
        r.distribution = rt::distribution(s.in->scene);
        r.samples = s.samples;
    } else {
        r.image = s.image.pixels();
    }
    return r;
}

}  // namespace cg
