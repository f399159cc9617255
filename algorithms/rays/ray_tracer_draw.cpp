// Recursive and distribution ray tracing, the picture.
// 3D: the scene's objects (a moving ball also where the shutter closes, faint), the lights, the
// eye with the virtual screen and the pixel; ray-tree: the pixel's rays so far (primary orange,
// shadow green when it reaches its light and red when blocked, mirror teal, refracted magenta),
// the ray in hand thicker with its normal at least 30 px (a big tree names only the rays that
// led to it); pixels and rows: the last pixel's primary ray. The camera frames what the step is
// about: the ray in hand and the object it meets (an area light's shadow rays and the light),
// the whole tree when the colour is summed, the hierarchy's root box at the build, the eye and
// the objects while the image fills in.
// Panels: the image (pixels/rows: as computed; ray-tree: a dimmed preview) with the pixel or the
// row outlined and the pixel's row and column dashed (ray-tree: the pixel a handle, dragged from
// pixel centre to pixel centre); below it
//   pixels/rows  the rays each row cost, stacked by kind;
//   ray-tree     the ray tree as the course draws it (a diagram), each ray's returned colour
//                beside it;
//   a distributed pixel: its samples — where each crosses the pixel (magnified), its lens
//                point, its time — the one in hand orange;
//   an area light once its shadow rays are cast: the light's area with each ray's point, green
//                where it reached the light, red where it was blocked (the penumbra's share).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "core/format.hpp"
#include "rays/csg_ray.hpp"
#include "rays/quadric_mesh.hpp"
#include "rays/ray_tracer.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using rt::Color;
using Event = RayTracer::Event;
using RayKind = RayTracer::RayKind;
using RayNode = RayTracer::RayNode;

// The scene's size: for the picture's extent and for cutting unbounded surfaces.
double scene_extent(const rt::Scene& sc) {
    double e = glm::length(sc.camera.eye - sc.camera.center);
    for (const rt::Light& l : sc.lights)
        if (!l.directional) e = std::max(e, glm::length(l.position - sc.camera.center));
    return std::max(e, 1e-6);
}

// The objects and the lights.
void draw_objects(const rt::Scene& sc, double extent, Scene& scene) {
    constexpr std::size_t kMaxDrawnTriangles = 4000;
    std::size_t triangles = 0;
    for (const rt::Object& o : sc.objects) {
        const rt::Material& m = sc.materials[o.material];
        // The surface's own colour, toward pale blue when it is transparent and toward grey
        // when it is a mirror, so glass and mirrors do not draw black.
        Color look = m.kd + 0.3 * m.ks;
        const double t = std::min(1.0, std::max({m.kt.x, m.kt.y, m.kt.z}));
        const double r = std::min(1.0, std::max({m.kr.x, m.kr.y, m.kr.z}));
        look = (1 - t) * look + t * Color(0.6, 0.8, 1.0);
        look = (1 - r) * look + r * Color(0.7);
        const Style style{Role::Subject, 1.0f, false, pack_rgba(look, 1)};
        switch (o.kind) {
            case rt::ObjectKind::Quadric: {
                const double L = largest_param(o.quadric);
                double z_lo, z_hi;
                drawn_z_range(o.quadric, std::min(extent, 50 * L), z_lo, z_hi);
                add_quadric_mesh(o.quadric, z_lo, z_hi, style, 0.35f, 20, 10, scene.faces3);
                if (o.velocity != dvec3(0.0) && sc.camera.shutter > 0) {
                    // Where it is when the shutter closes: motion blur spreads it over this.
                    Quadric moved = o.quadric;
                    moved.world_from_model[3] += glm::dvec4(sc.camera.shutter * o.velocity, 0);
                    add_quadric_mesh(moved, z_lo, z_hi, {Role::Construction, 1.0f, true}, 0.1f, 20,
                                     10, scene.faces3);
                }
                break;
            }
            case rt::ObjectKind::Plane: {
                // A square of the plane around the point nearest the look-at centre.
                const dvec3 n = unit(o.normal);
                const dvec3 c = sc.camera.center - glm::dot(sc.camera.center - o.p0, n) * n;
                const dvec3 a = unit(std::fabs(n.x) < 0.9 ? glm::cross(n, dvec3(1, 0, 0))
                                                          : glm::cross(n, dvec3(0, 1, 0)));
                const dvec3 b = glm::cross(n, a);
                const double h = 0.6 * extent;
                scene.faces3.push_back(
                    {{c - h * a - h * b, c + h * a - h * b, c + h * a + h * b, c - h * a + h * b},
                     style,
                     0.25f,
                     true,
                     true});
                break;
            }
            case rt::ObjectKind::Triangle:
                if (++triangles > kMaxDrawnTriangles) break;
                scene.faces3.push_back({{o.p0, o.p1, o.p2}, style, 0.5f, true, true});
                break;
            case rt::ObjectKind::Mesh: {
                // Spread over the whole mesh when it has more than there is room for: every
                // stride-th triangle, so that its shape shows.
                const mesh::Mesh& m = o.mesh->mesh;
                const std::size_t room =
                    triangles < kMaxDrawnTriangles ? kMaxDrawnTriangles - triangles : 0;
                const std::size_t stride =
                    room == 0 ? 1
                              : std::max<std::size_t>(1, (m.triangles.size() + room - 1) / room);
                for (std::size_t k = 0; room > 0 && k < m.triangles.size(); k += stride) {
                    const auto& t = m.triangles[k];
                    scene.faces3.push_back({{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]},
                                            style,
                                            0.5f,
                                            true,
                                            true});
                }
                triangles += m.triangles.size();
                break;
            }
            case rt::ObjectKind::Csg:  // every primitive of the tree, fainter than a solid
                for (std::size_t k = 0; k < o.csg.nodes.size(); ++k)
                    if (o.csg.nodes[k].leaf)
                        add_csg_leaf_mesh(o.csg, static_cast<int>(k), extent, style, 0.2f,
                                          scene.faces3);
                break;
        }
    }
    if (triangles > kMaxDrawnTriangles)
        scene.labels3.push_back({sc.camera.center,
                                 std::to_string(triangles) + " triangles: about " +
                                     std::to_string(kMaxDrawnTriangles) + " of them drawn",
                                 {Role::Construction}});
    for (std::size_t k = 0; k < sc.lights.size(); ++k) {
        const rt::Light& l = sc.lights[k];
        const std::string name = "light " + std::to_string(k);
        const Role role = Role::Neutral;
        if (l.directional) {
            const dvec3 from = sc.camera.center - 0.8 * extent * unit(l.direction);
            scene.segments3.push_back(
                {from, from + 0.3 * extent * unit(l.direction), name, {role, 2.0f, true}, true});
        } else {
            scene.points3.push_back({l.position, name, {role}, 7.0f});
        }
        if (l.area == rt::Light::Area::Rectangle) {
            const dvec3 a = 0.5 * l.edge_u, b = 0.5 * l.edge_v;
            scene.faces3.push_back(
                {{l.position - a - b, l.position + a - b, l.position + a + b, l.position - a + b},
                 {role, 1.5f},
                 0.35f,
                 true,
                 true});
        } else if (l.area == rt::Light::Area::Disc) {
            const dvec3 n3 = unit(l.normal);
            const dvec3 e1 = unit(std::fabs(n3.x) < 0.9 ? glm::cross(n3, dvec3(1, 0, 0))
                                                        : glm::cross(n3, dvec3(0, 1, 0)));
            const dvec3 e2 = glm::cross(n3, e1);
            std::vector<dvec3> rim;
            for (int q = 0; q < 24; ++q)
                rim.push_back(l.position + l.radius * (std::cos(q * M_PI / 12) * e1 +
                                                       std::sin(q * M_PI / 12) * e2));
            scene.faces3.push_back({std::move(rim), {role, 1.5f}, 0.35f, true, true});
        }
    }
}

// The eye and the virtual screen (at distance 1 along the view direction), and the pixel.
void draw_camera(const rt::Prepared& p, int i, int j, Scene& scene) {
    const rt::View& v = p.view;
    const dvec3 c00 = rt::screen_point(v, 0, 0), c10 = rt::screen_point(v, v.width, 0),
                c11 = rt::screen_point(v, v.width, v.height),
                c01 = rt::screen_point(v, 0, v.height);
    scene.points3.push_back({v.eye, "E", {Role::Neutral}, 6.0f});
    scene.faces3.push_back({{c00, c10, c11, c01}, {Role::Window, 1.0f}, 0.08f, true, true});
    if (i >= 0 && j >= 0)
        scene.faces3.push_back({{rt::screen_point(v, i, j), rt::screen_point(v, i + 1, j),
                                 rt::screen_point(v, i + 1, j + 1), rt::screen_point(v, i, j + 1)},
                                {Role::Active, 1.5f},
                                0.9f,
                                true,
                                true});
}

Role ray_role(const RayTracer::RayNode& n) {
    switch (n.kind) {
        case RayKind::Primary:
            return Role::Active;
        case RayKind::Shadow:
            return n.blocker >= 0 ? Role::Discarded : Role::Kept;
        case RayKind::Reflected:
            return Role::Entering;
        case RayKind::Refracted:
            return Role::Leaving;
    }
    return Role::Neutral;
}

void draw_box(const dvec3& lo, const dvec3& hi, const Style& style, Scene& scene) {
    auto corner = [&](int c) {
        return dvec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
    };
    for (int c = 0; c < 8; ++c)
        for (int axis = 1; axis < 8; axis <<= 1)
            if (!(c & axis)) scene.segments3.push_back({corner(c), corner(c | axis), "", style});
}

// The build step's picture: the object tree's boxes down to depth 3 (the root's bolder), and
// each mesh's box with its four children's.
void draw_hierarchy(const rt::Scene& sc, const rt::Prepared& p, Scene& scene) {
    const rt::ObjectBvh& b = p.bvh;
    struct Item {
        int node, depth;
    };
    std::vector<Item> todo;
    if (!b.nodes.empty()) todo.push_back({0, 0});
    while (!todo.empty()) {
        const Item it = todo.back();
        todo.pop_back();
        const rt::BvhNode& n = b.nodes[it.node];
        const Style style{it.depth == 0 ? Role::Active : Role::Construction,
                          it.depth == 0 ? 2.0f : 1.0f};
        draw_box(n.box.min, n.box.max, style, scene);
        if (n.count > 0 || it.depth >= 3) continue;
        todo.push_back({it.node + 1, it.depth + 1});
        todo.push_back({n.right, it.depth + 1});
    }
    for (const rt::Object& o : sc.objects) {
        if (o.kind != rt::ObjectKind::Mesh) continue;
        const rt::MeshBvh& m = o.mesh->bvh;
        draw_box(dvec3(m.root_lo[0], m.root_lo[1], m.root_lo[2]),
                 dvec3(m.root_hi[0], m.root_hi[1], m.root_hi[2]), {Role::Active, 2.0f}, scene);
        if (m.root_count > 0 || m.nodes.empty()) continue;
        const rt::MeshNode& n = m.nodes[static_cast<std::size_t>(m.root)];
        for (int k = 0; k < 4; ++k)
            if (n.count[k] >= 0)
                draw_box(dvec3(n.lo[0][k], n.lo[1][k], n.lo[2][k]),
                         dvec3(n.hi[0][k], n.hi[1][k], n.hi[2][k]), {Role::Construction, 1.0f},
                         scene);
    }
}

// A box that grows to hold points: what the 3D camera frames.
struct Box3 {
    dvec3 lo{1e300}, hi{-1e300};
    bool empty() const { return lo.x > hi.x; }
    void add(dvec3 p) {
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    void add(const Bounds& b) {
        if (!b.empty()) add(b.min), add(b.max);
    }
    double size() const { return empty() ? 0 : glm::length(hi - lo); }
};

// Where a ray is drawn to: its hit, its blocker, its light, or a stretch into the scene.
dvec3 ray_end(const RayTracer::State& s, const RayNode& n, double extent) {
    const rt::Scene& sc = s.in->scene;
    const dvec3 d = unit(n.direction);
    if (n.kind == RayKind::Shadow) {
        if (n.blocker >= 0) {
            const double t = rt::intersect_object(s.prepared->objects[n.blocker], n.origin,
                                                  n.direction, kRayEpsilon);
            return n.origin + t * n.direction;
        }
        const rt::Light& l = sc.lights[n.light];
        return l.directional         ? n.origin + 0.6 * extent * d
               : n.light_sample >= 0 ? n.light_point
                                     : l.position;
    }
    if (!n.traced) return n.origin + 0.5 * extent * d;
    if (n.hit.object < 0) return n.origin + 1.5 * extent * d;
    return n.hit.point;
}

void draw_tree(const RayTracer::State& s, double extent, Scene& scene) {
    const rt::Scene& sc = s.in->scene;
    // A big tree names only the ray in hand and the rays that led to it (the diagram names the
    // rest).
    std::vector<char> named(s.tree.size(), s.tree.size() <= 12);
    for (int k = s.active; k >= 0; k = s.tree[static_cast<std::size_t>(k)].parent)
        named[static_cast<std::size_t>(k)] = 1;
    for (std::size_t k = 0; k < s.tree.size(); ++k) {
        const RayNode& n = s.tree[k];
        // An area light's shadow rays come in a batch: the light's panel counts them.
        const bool batch = n.kind == RayKind::Shadow && n.light_sample >= 0;
        const std::string label =
            batch || !named[k] ? "" : RayTracer::ray_label(s.tree, static_cast<int>(k));
        const bool active = static_cast<int>(k) == s.active;
        const float width = active ? 3.0f : 1.8f;
        const int priority = active ? 3 : 0;
        const dvec3 end = ray_end(s, n, extent);
        if (n.kind == RayKind::Shadow) {
            if (n.blocker >= 0) {
                const rt::Light& l = sc.lights[n.light];
                const dvec3 light = l.directional ? n.origin + 0.6 * extent * unit(n.direction)
                                    : n.light_sample >= 0 ? n.light_point
                                                          : l.position;
                scene.segments3.push_back(
                    {n.origin, end, label, {Role::Discarded, width}, true, 0, priority});
                scene.segments3.push_back(
                    {end, light, "", {Role::Construction, 1.0f, true}, false});
                scene.points3.push_back({end, "", {Role::Discarded}, 4.0f});
            } else {
                scene.segments3.push_back(
                    {n.origin, end, label, {Role::Kept, width, true}, true, 0, priority});
            }
            continue;
        }
        if (active && n.glossy && n.parent >= 0) {  // the lobe's axis: the mirror direction
            const RayNode& from = s.tree[static_cast<std::size_t>(n.parent)];
            const dvec3 d = unit(from.direction), nn = from.hit.normal;
            const dvec3 r = d - 2 * glm::dot(d, nn) * nn;
            scene.segments3.push_back({n.origin,
                                       n.origin + glm::length(end - n.origin) * r,
                                       "r",
                                       {Role::Construction, 1.5f, true},
                                       false});
        }
        if (!n.traced) {  // cast, its hit not yet found: an arrow into the scene
            scene.segments3.push_back(
                {n.origin, end, label, {ray_role(n), width, true}, true, 0, priority});
            continue;
        }
        if (n.hit.object < 0) {
            scene.segments3.push_back(
                {n.origin, end, label + " (miss)", {ray_role(n), width}, true, 0, priority});
            continue;
        }
        scene.segments3.push_back({n.origin, end, label, {ray_role(n), width}, true, 0, priority});
        scene.points3.push_back({n.hit.point, "", {ray_role(n)}, 5.0f});
        if (active && sc.objects[n.hit.object].kind == rt::ObjectKind::Csg) {
            // The solid's segments along the ray, as csg-ray draws them (clipped to t ≥ 0).
            const CsgHit h =
                csg_intersect(*s.prepared->objects[n.hit.object].csg, n.origin, n.direction);
            for (const CsgSpan& sp : h.segments) {
                const double a = std::max(0.0, sp.in.t),
                             b = std::min(sp.out.t, 1.5 * extent / glm::length(n.direction));
                if (a < b)
                    scene.segments3.push_back({n.origin + a * n.direction,
                                               n.origin + b * n.direction,
                                               "",
                                               {Role::Kept, 5.0f},
                                               false});
            }
        }
        // The normal at the hit: the one in hand at least 30 px long.
        const float seen = active ? 30.0f : 0.0f;
        scene.segments3.push_back({n.hit.point,
                                   n.hit.point + 0.12 * extent * n.hit.normal,
                                   active ? "n" : "",
                                   {Role::Neutral, 1.5f},
                                   true,
                                   seen});
        if (n.detail >= 0 && s.details[n.detail].bumped)  // the bumped shading normal
            scene.segments3.push_back({n.hit.point,
                                       n.hit.point + 0.12 * extent * n.surface.normal,
                                       active ? "n'" : "",
                                       {Role::Active, 1.5f},
                                       true,
                                       seen});
    }
}

// What the ray-tree step is about, for the camera: the ray in hand and the object it meets (an
// area light's shadow rays reach over the light), or the whole tree once the pixel is done.
Box3 tree_focus(const RayTracer::State& s, double extent) {
    Box3 box;
    const bool whole = s.active < 0 || s.last_event == Event::Colour;
    if (whole) {
        box.add(s.prepared->view.eye);
        for (const RayNode& n : s.tree) {
            box.add(n.origin);
            if (n.kind != RayKind::Shadow && n.traced && n.hit.object >= 0) box.add(n.hit.point);
        }
        if (s.tree.empty())
            for (const rt::Object& o : s.in->scene.objects) box.add(rt::object_bounds(o));
        return box;
    }
    const RayNode& a = s.tree[static_cast<std::size_t>(s.active)];
    box.add(a.origin);
    box.add(ray_end(s, a, extent));
    if (a.kind == RayKind::Primary) box.add(s.prepared->view.eye);
    if (a.kind != RayKind::Shadow && a.traced && a.hit.object >= 0)
        box.add(rt::object_bounds(s.in->scene.objects[a.hit.object]));
    if (a.kind == RayKind::Shadow && a.blocker >= 0)
        box.add(rt::object_bounds(s.in->scene.objects[a.blocker]));
    if (s.last_event == Event::AreaLight)  // its shadow rays, over the light's area
        for (const RayNode& n : s.tree)
            if (n.kind == RayKind::Shadow && n.parent == s.active) box.add(ray_end(s, n, extent));
    if (s.last_event == Event::Return && a.parent >= 0) box.add(s.tree[a.parent].origin);
    return box;
}

// The sample in hand: the primary ray at the root of the active ray's tree (-1: none).
int sample_in_hand(const RayTracer::State& s) {
    if (s.last_event == Event::Colour) return -1;  // all of them done
    int k = s.active;
    while (k >= 0 && s.tree[static_cast<std::size_t>(k)].parent >= 0)
        k = s.tree[static_cast<std::size_t>(k)].parent;
    return k >= 0 ? s.tree[static_cast<std::size_t>(k)].sample : -1;
}

// A distributed pixel's samples, side by side in one canvas (8 cells an image pixel): the pixel
// and its neighbours magnified with where each sample crosses the pixel; with depth of field
// the lens with each sample's point on it; with motion blur the shutter's interval with each
// sample's time going up. The sample in hand is orange, those traced green, the rest grey.
void add_samples_panel(const RayTracer::State& s, Scene& scene) {
    const rt::Camera& c = s.in->scene.camera;
    constexpr int K = 8, kPart = 3 * K, kGap = 4;
    const int pi = s.pixel_i, pj = s.pixel_j;
    const int i0 = std::clamp(pi - 1, 0, std::max(0, c.width - 3));
    const int j0 = std::clamp(pj - 1, 0, std::max(0, c.height - 3));
    const int w = std::min(3, c.width), h = std::min(3, c.height);
    const bool lens = c.aperture > 0, shutter = c.shutter > 0;
    int right = w * K;  // the canvas's width so far
    const int lens_x = right + kGap;
    if (lens) right = lens_x + kPart;
    const int strip_x = right + kGap;
    if (shutter) right = strip_x + K;
    PixelGrid2 canvas;
    canvas.width = right;
    canvas.height = kPart + (lens || shutter ? 3 : 0);  // room above for the parts' names
    canvas.grid_lines = false;
    canvas.rgba.assign(static_cast<std::size_t>(canvas.width) * canvas.height, 0u);
    auto set = [&](int x, int y, std::uint32_t v) {
        if (x >= 0 && x < canvas.width && y >= 0 && y < canvas.height)
            canvas.rgba[static_cast<std::size_t>(y) * canvas.width + x] = v;
    };
    for (int y = 0; y < h * K; ++y)
        for (int x = 0; x < w * K; ++x) {
            const std::size_t at = static_cast<std::size_t>(j0 + y / K) * c.width + (i0 + x / K);
            set(x, y, s.preview->empty() ? 0xe8e8e8ffu : (*s.preview)[at] | 0xffu);
        }
    if (lens)
        for (int y = 0; y < kPart; ++y)
            for (int x = 0; x < kPart; ++x) {
                const double u = (x + 0.5) / (kPart / 2.0) - 1, v = (y + 0.5) / (kPart / 2.0) - 1;
                if (u * u + v * v <= 1) set(lens_x + x, y, 0xdbe7f5ffu);
            }
    if (shutter)
        for (int y = 0; y < kPart; ++y)
            for (int x = 0; x < K; ++x) set(strip_x + x, y, 0xe4e4e4ffu);

    const int n = static_cast<int>(s.samples.size());
    // One line of title: the canvas's parts are named inside it.
    const std::string title = "pixel (" + std::to_string(pi) + ", " + std::to_string(pj) +
                              "): its " + std::to_string(n) + " samples";
    Panel& panel = add_image(scene, title, std::move(canvas));
    const double x0 = (pi - i0) * K, y0 = (pj - j0) * K;
    panel.polygons.push_back({{{x0, y0}, {x0 + K, y0}, {x0 + K, y0 + K}, {x0, y0 + K}},
                              {Role::Window, 2.0f},
                              true,
                              false});
    if (lens)
        panel.labels.push_back(
            {dvec2(lens_x + kPart / 2.0, kPart + 1.5), "lens", {Role::Construction}});
    if (shutter)
        panel.labels.push_back(
            {dvec2(strip_x + K / 2.0, kPart + 1.5), "time ↑", {Role::Construction}});
    const int now = sample_in_hand(s);
    for (int k = 0; k < n; ++k) {
        const rt::PixelSample& ps = s.samples[static_cast<std::size_t>(k)];
        const Role role = k == now ? Role::Active : k < s.next_sample ? Role::Kept : Role::Subject;
        const float r = k == now ? 7.0f : k < s.next_sample ? 5.0f : 4.0f;
        panel.points.push_back({dvec2(x0, y0) + double(K) * ps.pixel,
                                k == now ? "sample " + std::to_string(k + 1) : "",
                                {role},
                                r,
                                k == now ? 3 : 0});
        if (lens)
            panel.points.push_back(
                {dvec2(lens_x, 0) + (ps.lens + 1.0) * (kPart / 2.0), "", {role}, r});
        if (shutter)
            panel.points.push_back(
                {dvec2(strip_x + (k + 0.5) * K / n, kPart * ps.time / c.shutter), "", {role}, r});
    }
}

// The last area light's shadow rays over its area (a disc or a rectangle, in its own frame): green
// where the ray reached the light, red where something blocked it.
bool add_light_panel(const RayTracer::State& s, Scene& scene) {
    int last = -1;
    for (int k = static_cast<int>(s.tree.size()) - 1; k >= 0 && last < 0; --k)
        if (s.tree[k].kind == RayKind::Shadow && s.tree[k].light_sample >= 0) last = k;
    if (last < 0) return false;
    const RayNode& ref = s.tree[static_cast<std::size_t>(last)];
    const rt::Light& l = s.in->scene.lights[static_cast<std::size_t>(ref.light)];
    // The area's frame: a point q of it is position + a·eu + b·ev, drawn at cell (a, b) + half.
    dvec3 eu, ev;
    int w = 24, h = 24;
    if (l.area == rt::Light::Area::Disc) {
        const dvec3 n3 = unit(l.normal);
        const dvec3 e1 = unit(std::fabs(n3.x) < 0.9 ? glm::cross(n3, dvec3(1, 0, 0))
                                                    : glm::cross(n3, dvec3(0, 1, 0)));
        eu = 2 * l.radius * e1, ev = 2 * l.radius * glm::cross(n3, e1);
    } else {
        eu = l.edge_u, ev = l.edge_v;
        const double ratio = glm::length(ev) / std::max(glm::length(eu), 1e-300);
        if (ratio < 1)
            h = std::max(4, static_cast<int>(std::lround(24 * ratio)));
        else
            w = std::max(4, static_cast<int>(std::lround(24 / ratio)));
    }
    constexpr int kMargin = 2;  // cells round the area, so that a point on its rim is whole
    PixelGrid2 area;
    area.width = w + 2 * kMargin, area.height = h + 2 * kMargin;
    area.grid_lines = false;
    for (int j = 0; j < area.height; ++j)
        for (int i = 0; i < area.width; ++i) {
            const double x = (i - kMargin + 0.5) / w - 0.5, y = (j - kMargin + 0.5) / h - 0.5;
            const bool in = std::fabs(x) < 0.5 && std::fabs(y) < 0.5 &&
                            (l.area != rt::Light::Area::Disc || x * x + y * y <= 0.25);
            area.rgba.push_back(in ? 0xfff1c4ffu : 0xffffffffu);
        }
    // (a, b) from q − position = a·eu + b·ev, by the normal equations (the edges need not be
    // at right angles).
    const double uu = glm::dot(eu, eu), uv = glm::dot(eu, ev), vv = glm::dot(ev, ev);
    const double det = uu * vv - uv * uv;
    int reached = 0, cast = 0;
    std::vector<dvec2> lit, blocked;
    for (const RayNode& n : s.tree) {
        if (n.kind != RayKind::Shadow || n.parent != ref.parent || n.light != ref.light ||
            n.light_sample < 0)
            continue;
        const dvec3 q = n.light_point - l.position;
        const double qu = glm::dot(q, eu), qv = glm::dot(q, ev);
        const double a = det > 0 ? (vv * qu - uv * qv) / det : 0,
                     b = det > 0 ? (uu * qv - uv * qu) / det : 0;
        (n.blocker >= 0 ? blocked : lit)
            .push_back({kMargin + (a + 0.5) * w, kMargin + (b + 0.5) * h});
        ++cast;
        reached += n.blocker < 0;
    }
    Panel& panel =
        add_image(scene,
                  "light " + std::to_string(ref.light) + "'s area: " + std::to_string(reached) +
                      " of " + std::to_string(cast) + " shadow rays reach it",
                  std::move(area));
    for (dvec2 p : lit) panel.points.push_back({p, "", {Role::Kept}, 5.0f});
    for (dvec2 p : blocked) panel.points.push_back({p, "", {Role::Discarded}, 5.0f});
    return true;
}

// Pixels and rows: what each row of the image cost, in rays of each kind, stacked.
void add_rows_chart(const RayTracer::State& s, Scene& scene) {
    const int H = static_cast<int>(s.row_rays.size());
    // No title: the legend and the axes say it all, and the plot keeps the room.
    Panel& chart =
        add_chart(scene, "", Axis{"row j", -0.5, H - 0.5}, Axis{"rays per row", 0, 0, false, true});
    struct Kind {
        const char* name;
        Role role;
        std::uint64_t rt::RayCounts::*count;
    };
    const Kind kinds[] = {{"primary", Role::Active, &rt::RayCounts::primary},
                          {"shadow", Role::Kept, &rt::RayCounts::shadow},
                          {"mirror", Role::Entering, &rt::RayCounts::reflected},
                          {"refracted", Role::Leaving, &rt::RayCounts::refracted}};
    bool used[4] = {false, false, false, false};
    for (int j = 0; j < H; ++j) {
        const rt::RayCounts& c = s.row_rays[static_cast<std::size_t>(j)];
        double y = 0;
        for (int k = 0; k < 4; ++k) {
            const double n = static_cast<double>(c.*kinds[k].count);
            if (n <= 0) continue;
            used[k] = true;
            const double a = j - 0.4, b = j + 0.4;
            chart.polygons.push_back(
                {{{a, y}, {b, y}, {b, y + n}, {a, y + n}}, {kinds[k].role, 1.0f}, true, true});
            y += n;
        }
    }
    for (int k = 0; k < 4; ++k)
        if (used[k]) chart.legend.push_back({kinds[k].name, {kinds[k].role, 4.0f}, false});
    if (s.last_j >= 0) {  // the row just computed
        const rt::RayCounts& c = s.row_rays[static_cast<std::size_t>(s.last_j)];
        chart.points.push_back({{double(s.last_j), static_cast<double>(c.total())},
                                "row " + std::to_string(s.last_j),
                                {Role::Window},
                                5.0f,
                                2});
    }
}

// Ray-tree: the tree as the course draws it — each ray a node under the ray that cast it (shadow
// rays the leaves), in the 3D view's colours, with the colour each ray carried back once it has
// returned.
void add_tree_panel(const RayTracer::State& s, Scene& scene, bool alone) {
    const std::vector<RayNode>& tree = s.tree;
    const int n = static_cast<int>(tree.size());
    std::vector<std::vector<int>> children(static_cast<std::size_t>(n));
    std::vector<int> roots;
    for (int k = 0; k < n; ++k)
        (tree[k].parent >= 0 ? children[static_cast<std::size_t>(tree[k].parent)] : roots)
            .push_back(k);
    // Leaves one after another in depth-first order, a parent over the middle of its children.
    std::vector<double> x(static_cast<std::size_t>(n), 0);
    std::vector<int> level(static_cast<std::size_t>(n), 0);
    int leaves = 0, levels = 1;
    struct Item {
        int node;
        bool done;
    };
    std::vector<Item> todo;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) todo.push_back({*r, false});
    while (!todo.empty()) {
        const Item it = todo.back();
        todo.pop_back();
        const auto& kids = children[static_cast<std::size_t>(it.node)];
        if (it.done || kids.empty()) {
            x[it.node] =
                kids.empty() ? leaves++ : (x[kids.front()] + x[kids.back()]) / 2;  // after its kids
            continue;
        }
        todo.push_back({it.node, true});
        for (auto c = kids.rbegin(); c != kids.rend(); ++c) {
            level[*c] = level[it.node] + 1;
            levels = std::max(levels, level[*c] + 1);
            todo.push_back({*c, false});
        }
    }
    // A diagram, 2 units a leaf and 3 a level, in a framed room a little larger than the tree
    // and about 12 : 5 under the image (wide, so that the legend fits in a row above it), square
    // alone; fitted to its panel at one scale.
    constexpr double kDx = 2, kDy = 3;
    Panel& panel = add_diagram(scene, "the ray tree");
    auto pos = [&](int k) { return dvec2(kDx * x[k], -kDy * level[k]); };
    double room_w = kDx * std::max(leaves - 1, 0) + 3, room_h = kDy * (levels - 1) + 3;
    const double aspect = alone ? 1.0 : 2.4;
    room_w = std::max(room_w, aspect * room_h), room_h = std::max(room_h, room_w / aspect / 1.25);
    const double cx = kDx * std::max(leaves - 1, 0) / 2, cy = -kDy * (levels - 1) / 2.0;
    const dvec2 a(cx - room_w / 2, cy - room_h / 2), b(cx + room_w / 2, cy + room_h / 2);
    panel.polygons.push_back(
        {{a, {b.x, a.y}, b, {a.x, b.y}}, {Role::Construction, 1.0f}, true, false});
    for (int k = 0; k < n; ++k)
        if (tree[k].parent >= 0)
            panel.segments.push_back({pos(tree[k].parent),
                                      pos(k),
                                      "",
                                      {ray_role(tree[k]), 1.2f, tree[k].kind == RayKind::Shadow},
                                      false});
    const bool crowded = n > 24;
    bool kinds[5] = {false, false, false, false, false};
    for (int k = 0; k < n; ++k) {
        const RayNode& r = tree[k];
        const bool active = k == s.active;
        const dvec2 p = pos(k);
        if (r.returned && r.kind != RayKind::Shadow) {  // the colour it carried back
            const glm::dvec3 c = glm::clamp(r.color, 0.0, 1.0);
            panel.polygons.push_back({{p + dvec2(0.55, -0.5), p + dvec2(1.45, -0.5),
                                       p + dvec2(1.45, 0.4), p + dvec2(0.55, 0.4)},
                                      {Role::Neutral, 1.0f, false, pack_rgba(c)},
                                      true,
                                      true});
        }
        const bool label = !crowded || active || r.parent < 0;
        const bool batch = r.kind == RayKind::Shadow && r.light_sample >= 0;
        panel.points.push_back({p,
                                label && !batch ? RayTracer::ray_label(tree, k) : "",
                                {ray_role(r)},
                                active        ? 8.0f
                                : leaves > 12 ? 3.5f
                                              : 5.5f,
                                active ? 3 : 0});
        kinds[r.kind == RayKind::Shadow      ? (r.blocker >= 0 ? 2 : 1)
              : r.kind == RayKind::Primary   ? 0
              : r.kind == RayKind::Reflected ? 3
                                             : 4] = true;
    }
    // The key (the root is the primary ray, named R0 in its orange: no entry for it).
    const char* names[] = {"primary", "shadow, lit", "blocked", "mirror", "refracted"};
    const Role roles[] = {Role::Active, Role::Kept, Role::Discarded, Role::Entering, Role::Leaving};
    for (int k = 1; k < 5; ++k)
        if (kinds[k]) panel.legend.push_back({names[k], {roles[k]}, true});
}

}  // namespace

void RayTracer::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const rt::Scene& sc = in.scene;
    const int W = sc.camera.width, H = sc.camera.height;
    const double extent = scene_extent(sc);
    const bool tree_mode = in.granularity == Granularity::RayTree;

    // ---- the image panel (none for a given ray: it goes through no pixel) ----
    int hi = -1, hj = -1;  // the highlighted pixel
    if (!(tree_mode && in.explicit_ray)) {
        PixelGrid2 grid;
        grid.width = W;
        grid.height = H;
        grid.grid_lines = false;  // the pixels show as blocks; the one in hand is outlined
        const std::string size = std::to_string(W) + " × " + std::to_string(H);
        std::string title = "the image, " + size + " pixels";
        if (tree_mode) {
            if (!s.preview->empty()) {
                grid.rgba = *s.preview;
                for (auto& v : grid.rgba)
                    v = (v & 0xffffff00u) | 0x60u;  // dimmed: not computed here
                title = "the image (a preview)";
            } else {
                grid.rgba.assign(static_cast<std::size_t>(W) * H, 0xf0f0f0ffu);
            }
            if (!in.explicit_ray) {
                hi = s.pixel_i, hj = s.pixel_j;
                if (s.phase == Phase::Done)
                    grid.rgba[static_cast<std::size_t>(hj) * W + hi] = pack_rgba(s.pixel_color);
                title += ", pixel (" + std::to_string(hi) + ", " + std::to_string(hj) + ")";
            }
        } else {
            grid.rgba = s.image.pixels();
            hi = s.last_i, hj = s.last_j;
        }
        Panel& image = add_image(scene, title, std::move(grid));
        if (hj >= 0) {
            const double x0 = hi >= 0 ? hi : 0, x1 = hi >= 0 ? hi + 1 : W;
            if (hi >= 0) {  // the pixel's row and column, so that a small pixel is found at once
                image.segments.push_back(
                    {{0, hj + 0.5}, {W, hj + 0.5}, "", {Role::Construction, 1.0f, true}, false});
                image.segments.push_back(
                    {{hi + 0.5, 0}, {hi + 0.5, H}, "", {Role::Construction, 1.0f, true}, false});
            }
            image.polygons.push_back({{{x0, hj}, {x1, hj}, {x1, hj + 1.0}, {x0, hj + 1.0}},
                                      {Role::Active, 2.5f},
                                      true,
                                      false});
        }
        if (tree_mode && !in.explicit_ray)  // drag it to trace another pixel
            image.handles.push_back({{hi + 0.5, hj + 0.5},
                                     "pixel",
                                     "/stepping/pixel/0",
                                     "/stepping/pixel/1",
                                     true});
        // A little less than an equal share: a chart below needs its legend and axes' room.
        image.weight = tree_mode ? 1 : 0.95;
    }
    if (!tree_mode) {
        add_rows_chart(s, scene);
    } else if (!in.explicit_ray && s.samples.size() > 1) {  // a distributed pixel
        add_samples_panel(s, scene);
    } else {
        // An area light's shadow rays, once cast, say more than the tree of this one ray.
        if (!add_light_panel(s, scene)) add_tree_panel(s, scene, scene.panels.empty());
    }

    // ---- 3D ----
    draw_objects(sc, extent, scene);
    if (s.last_event == Event::Build) draw_hierarchy(sc, *s.prepared, scene);
    draw_camera(*s.prepared, hi, hj, scene);
    if (sc.camera.aperture > 0) {  // the thin lens, across the view direction at the eye
        const rt::View& v = s.prepared->view;
        std::vector<dvec3> rim;
        for (int q = 0; q < 24; ++q)
            rim.push_back(v.eye + sc.camera.aperture * (std::cos(q * M_PI / 12) * v.u +
                                                        std::sin(q * M_PI / 12) * v.v));
        scene.faces3.push_back({std::move(rim), {Role::Window, 1.5f}, 0.3f, true, true});
        scene.labels3.push_back({v.eye + sc.camera.aperture * v.v, "lens", {Role::Window}});
    }
    Box3 focus;
    if (tree_mode) {
        draw_tree(s, extent, scene);
        focus = tree_focus(s, extent);
    } else {
        focus.add(s.prepared->view.eye);
        for (const rt::Object& o : sc.objects) focus.add(rt::object_bounds(o));
        if (s.last_i >= 0) {  // the last pixel's primary ray, to its hit
            const rt::Prepared& p = *s.prepared;
            const dvec3 P = rt::screen_point(p.view, s.last_i + 0.5, s.last_j + 0.5);
            const rt::Hit h = rt::nearest_hit(p, p.view.eye, P - p.view.eye);
            const dvec3 end =
                h.object >= 0 ? h.point : p.view.eye + 1.5 * extent * unit(P - p.view.eye);
            scene.segments3.push_back({p.view.eye, end, "", {Role::Active, 2.0f}, true});
            if (h.object >= 0) focus.add(end);
        }
    }
    if (s.last_event == Event::Build && !s.prepared->bvh.nodes.empty()) {
        focus = Box3{};
        focus.add(s.prepared->bvh.nodes[0].box);
    }
    // A lone point (the eye, before anything bounded is known) is no frame: extent3 then.
    if (!focus.empty() && focus.size() > 1e-6 * extent) add_focus(scene, focus.lo, focus.hi);
    scene.extent3 = 0.6 * extent;
}

}  // namespace cg
