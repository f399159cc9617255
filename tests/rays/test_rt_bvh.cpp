// The ray tracer's bounding volume hierarchy (rays/rt_bvh.hpp): on random scenes of every
// object kind — spheres and ellipsoids under random affine maps, paraboloids, hyperboloids,
// cones and cylinders cut by z slabs and not, triangles (nested, overlapping, sharing edges),
// planes, moving objects — the hierarchy's nearest hit and shadow blocker equal brute force's
// exactly (same object, same t, same normal) on 10,000 rays per scene, rays aimed at triangle
// corners and edges and started inside objects included; its invariants; object bounds that
// hold every surface point found; images bit-identical with and without it.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "rays/rt_scene.hpp"
#include "support/uniform.hpp"
#include "rays/rt_scene_json.hpp"

using namespace cg;
using glm::dvec3;

namespace {

using cg::test::Gen;

glm::dmat4 random_affine(Gen& g, double spread) {
    glm::dmat4 m(1.0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = (i == j ? 1.0 : 0.0) + 0.4 * g.c();
    m[3] = glm::dvec4(g.point(spread), 1);
    return m;
}

rt::Scene random_scene(Gen& g, int objects, double spread) {
    rt::Scene s;
    s.camera.eye = {0, 0, 3 * spread};
    s.camera.center = {0, 0, 0};
    s.camera.width = 16, s.camera.height = 12;
    rt::Material m;
    m.name = "m";
    s.materials.push_back(m);
    rt::Light l;
    l.position = {0, 2 * spread, spread};
    s.lights.push_back(l);
    dvec3 last_corner = g.point(spread);
    for (int k = 0; k < objects; ++k) {
        rt::Object o;
        o.name = o.field = "objects[" + std::to_string(k) + "]";
        const double pick = g.u();
        if (pick < 0.45) {  // triangles: some share a corner with the last one (edges meet)
            o.kind = rt::ObjectKind::Triangle;
            const double size = spread * (g.u() < 0.8 ? 0.15 : 0.8);
            o.p0 = g.u() < 0.4 ? last_corner : g.point(spread);
            o.p1 = o.p0 + g.point(size);
            o.p2 = o.p0 + g.point(size);
            if (glm::length(glm::cross(o.p1 - o.p0, o.p2 - o.p0)) < 1e-6 * size * size) continue;
            last_corner = o.p2;
        } else if (pick < 0.9) {
            o.kind = rt::ObjectKind::Quadric;
            Quadric& q = o.quadric;
            q.kind = static_cast<QuadricKind>(static_cast<int>(6 * g.u()) % 6);
            q.r = q.a = q.b = q.c = q.p = q.q = 0;
            q.r = 0.1 + 0.3 * g.u(), q.a = 0.1 + 0.3 * g.u(), q.b = 0.1 + 0.3 * g.u();
            q.c = 0.1 + 0.3 * g.u(), q.p = 0.1 + 0.3 * g.u(), q.q = 0.1 + 0.3 * g.u();
            q.r *= spread, q.a *= spread, q.b *= spread, q.c *= spread, q.p *= spread;
            q.q *= spread;
            if (q.kind != QuadricKind::Sphere && q.kind != QuadricKind::Ellipsoid) {
                // Mostly cut on both sides (bounded), sometimes on one side or not at all.
                const double r = g.u();
                const double lo = -spread * 0.5 * g.u(), hi = spread * 0.5 * g.u() + 1e-3;
                if (r < 0.8)
                    q.zmin = lo, q.zmax = hi;
                else if (r < 0.9)
                    q.zmax = hi;
            } else if (g.u() < 0.2) {
                q.zmin = -0.2 * spread * g.u();  // a cut sphere: its slab shrinks the box
            }
            if (q.kind == QuadricKind::Paraboloid && std::isfinite(q.zmax) && g.u() < 0.5)
                q.zmin = 0.5 * q.zmax;  // a band off the apex
            q.world_from_model = random_affine(g, spread);
        } else if (pick < 0.95) {
            o.kind = rt::ObjectKind::Plane;
            o.p0 = g.point(spread);
            o.normal = g.point(1) + dvec3(0, 1e-3, 0);
        } else {  // a moving sphere: tested for every ray
            o.kind = rt::ObjectKind::Quadric;
            o.quadric.r = 0.2 * spread;
            o.quadric.world_from_model[3] = glm::dvec4(g.point(spread), 1);
            o.velocity = g.point(0.3 * spread);
        }
        s.objects.push_back(o);
        // Now and then the same object again (an exact tie in t: the smaller index must win).
        if (g.u() < 0.08 && o.kind != rt::ObjectKind::Plane) {
            o.name = o.field = "objects[" + std::to_string(s.objects.size()) + "]";
            s.objects.insert(s.objects.begin() + static_cast<long>(g.u() * s.objects.size()), o);
        }
    }
    for (std::size_t k = 0; k < s.objects.size(); ++k)
        s.objects[k].name = s.objects[k].field = "objects[" + std::to_string(k) + "]";
    return s;
}

// A ray: from anywhere, from inside an object's box, or aimed at a triangle's corner or a
// point on its edge (where a too-tight box would lose the hit).
void random_ray(Gen& g, const rt::Scene& s, double spread, dvec3& origin, dvec3& d) {
    origin = g.point(2 * spread);
    const rt::Object& o =
        s.objects[static_cast<std::size_t>(g.u() * s.objects.size()) % s.objects.size()];
    const double r = g.u();
    dvec3 target = g.point(spread);
    if (o.kind == rt::ObjectKind::Triangle) {
        if (r < 0.3)
            target = o.p0;
        else if (r < 0.6)
            target = o.p1 + g.u() * (o.p2 - o.p1);
        else
            target = o.p0 + 0.3 * (o.p1 - o.p0) + 0.3 * (o.p2 - o.p0);
    } else if (o.kind == rt::ObjectKind::Quadric) {
        const dvec3 centre(o.quadric.world_from_model[3]);
        if (r < 0.3) origin = centre + g.point(0.05 * spread);  // from inside
        target = centre + g.point(0.3 * spread);
    }
    d = target - origin;
    if (g.u() < 0.1) d.x = 0;  // axis-parallel components
    if (g.u() < 0.1) d.y = 0;
    if (d == dvec3(0.0)) d = {0, 0, -1};
}

rt::Prepared without_hierarchy(const rt::Prepared& p) {
    rt::Prepared q = p;
    q.bvh = rt::ObjectBvh{};
    for (int k = 0; k < static_cast<int>(p.objects.size()); ++k) q.bvh.unbounded.push_back(k);
    return q;
}

}  // namespace

TEST_CASE("tracer bvh: nearest hits and blockers equal brute force on 10,000 rays per scene",
          "[rays][bvh]") {
    Gen g{std::mt19937_64(2024)};
    long long rays = 0, hits = 0, blocked = 0, via_tree = 0;
    for (int scene = 0; scene < 24; ++scene) {
        const double spread = scene % 3 == 0 ? 1e-3 : scene % 3 == 1 ? 1 : 1e4;
        const int n = scene < 4 ? 3 + scene : 30 + 10 * scene;
        const rt::Scene s = random_scene(g, n, spread);
        rt::validate(s);
        const rt::Prepared p = rt::prepare(s);
        CAPTURE(scene, n, spread);
        for (int k = 0; k < 10000; ++k) {
            dvec3 e, d;
            random_ray(g, s, spread, e, d);
            const double time = g.u();
            const double t_min = cg::kRayEpsilon;
            const rt::Hit a = rt::nearest_hit(p, e, d, t_min, Quadric::kInf, time);
            const rt::Hit b = rt::nearest_hit_brute_force(p, e, d, t_min, Quadric::kInf, time);
            CAPTURE(k, e.x, e.y, e.z, d.x, d.y, d.z, a.object, b.object, a.t, b.t);
            REQUIRE(a == b);
            ++rays;
            if (b.object >= 0) {
                ++hits;
                via_tree += std::find(p.bvh.unbounded.begin(), p.bvh.unbounded.end(), b.object) ==
                            p.bvh.unbounded.end();
            }
            // A shadow ray's segment, ending short of the nearest hit, at it, or beyond.
            const double t_max = b.object >= 0 ? b.t * (0.5 + g.u()) : 10 * spread * g.u();
            const int fa = rt::first_blocker(p, e, d, t_min, t_max, time);
            const int fb = rt::first_blocker_brute_force(p, e, d, t_min, t_max, time);
            REQUIRE(fa == fb);
            REQUIRE(rt::blocked(p, e, d, t_min, t_max, time) == (fb >= 0));
            blocked += fb >= 0;
        }
    }
    // The test sees hits, misses, blockers, and hits found through the tree (not only the
    // objects tested for every ray).
    CHECK(rays == 240000);
    CHECK(hits > 60000);
    CHECK(rays - hits > 5000);
    CHECK(blocked > 30000);
    CHECK(via_tree > 40000);
}

TEST_CASE("tracer bvh: the tree's invariants, and bounds that hold every surface point", "[rays][bvh]") {
    Gen g{std::mt19937_64(7)};
    for (int scene = 0; scene < 8; ++scene) {
        const rt::Scene s = random_scene(g, 300, 1);
        const rt::Prepared p = rt::prepare(s);
        const rt::ObjectBvh& bvh = p.bvh;
        // Every object is either in the tree, in exactly one leaf, or tested for every ray.
        std::vector<int> seen(s.objects.size(), 0);
        for (int k : bvh.unbounded) ++seen[k];
        REQUIRE_FALSE(bvh.nodes.empty());
        for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
            const rt::BvhNode& n = bvh.nodes[i];
            if (n.count > 0) {
                REQUIRE(n.count <= 16);
                for (int k = n.first; k < n.first + n.count; ++k) {
                    ++seen[bvh.items[k]];
                    const Bounds ob = rt::object_bounds(s.objects[bvh.items[k]]);
                    for (int a = 0; a < 3; ++a) {
                        REQUIRE(n.box.min[a] <= ob.min[a]);
                        REQUIRE(n.box.max[a] >= ob.max[a]);
                    }
                }
            } else {
                REQUIRE(n.right > static_cast<int>(i) + 1);
                for (const rt::BvhNode* child : {&bvh.nodes[i + 1], &bvh.nodes[n.right]})
                    for (int a = 0; a < 3; ++a) {
                        REQUIRE(n.box.min[a] <= child->box.min[a]);
                        REQUIRE(n.box.max[a] >= child->box.max[a]);
                    }
            }
        }
        for (int c : seen) REQUIRE(c == 1);
        REQUIRE(bvh.depth <= rt::kMaxBvhDepth);
        // The planes, moving objects and unbounded quadrics are the unbounded ones.
        for (int k : bvh.unbounded) {
            const rt::Object& o = s.objects[k];
            const bool expected =
                o.kind == rt::ObjectKind::Plane || o.velocity != dvec3(0.0) ||
                (o.kind == rt::ObjectKind::Quadric && o.quadric.kind != QuadricKind::Sphere &&
                 o.quadric.kind != QuadricKind::Ellipsoid &&
                 !(std::isfinite(o.quadric.zmax) &&
                   (std::isfinite(o.quadric.zmin) || o.quadric.kind == QuadricKind::Paraboloid)));
            CAPTURE(k, int(o.kind), int(o.quadric.kind), o.quadric.zmin, o.quadric.zmax);
            CHECK(expected);
        }
        // Every point brute force finds on a bounded object lies in that object's box (to the
        // rounding of the point itself).
        for (int k = 0; k < 20000; ++k) {
            const dvec3 e = g.point(2), d = g.point(1) - e;
            const rt::Hit h = rt::nearest_hit_brute_force(p, e, d);
            if (h.object < 0) continue;
            const Bounds b = rt::object_bounds(s.objects[h.object]);
            if (b.empty()) continue;
            for (int a = 0; a < 3; ++a) {
                const double tol = 1e-9 * (1 + std::fabs(h.point[a]));
                REQUIRE(h.point[a] >= b.min[a] - tol);
                REQUIRE(h.point[a] <= b.max[a] + tol);
            }
        }
    }
}

TEST_CASE("tracer bvh: hand-made bounds", "[rays][bvh]") {
    rt::Object sphere;
    sphere.quadric.r = 2;
    sphere.quadric.world_from_model[3] = glm::dvec4(1, 2, 3, 1);
    Bounds b = rt::object_bounds(sphere);
    CHECK(b.min == dvec3(-1, 0, 1));
    CHECK(b.max == dvec3(3, 4, 5));
    rt::Object cyl;
    cyl.quadric.kind = QuadricKind::Cylinder;
    cyl.quadric.p = 1, cyl.quadric.q = 2, cyl.quadric.zmin = -1, cyl.quadric.zmax = 4;
    b = rt::object_bounds(cyl);
    CHECK(b.min == dvec3(-1, -2, -1));
    CHECK(b.max == dvec3(1, 2, 4));
    cyl.quadric.zmin = -Quadric::kInf;  // open at one end: unbounded
    CHECK(rt::object_bounds(cyl).empty());
    rt::Object par;
    par.quadric.kind = QuadricKind::Paraboloid;
    par.quadric.p = 1, par.quadric.q = 3, par.quadric.zmax = 4;  // x² + y²/9 = z ≤ 4
    b = rt::object_bounds(par);
    CHECK(b.min == dvec3(-2, -6, 0));
    CHECK(b.max == dvec3(2, 6, 4));
    rt::Object plane;
    plane.kind = rt::ObjectKind::Plane;
    CHECK(rt::object_bounds(plane).empty());
    rt::Object tri;
    tri.kind = rt::ObjectKind::Triangle;
    tri.p0 = {0, 0, 0}, tri.p1 = {2, -1, 0}, tri.p2 = {1, 3, 4};
    b = rt::object_bounds(tri);
    CHECK(b.min == dvec3(0, -1, 0));
    CHECK(b.max == dvec3(2, 3, 4));
    tri.velocity = {1, 0, 0};
    CHECK(rt::object_bounds(tri).empty());
}

TEST_CASE("tracer bvh: images bit-identical with and without the hierarchy", "[rays][bvh]") {
    Gen g{std::mt19937_64(99)};
    for (int scene = 0; scene < 6; ++scene) {
        const rt::Scene s = random_scene(g, 60 + 40 * scene, 1);
        const rt::Prepared p = rt::prepare(s), q = without_hierarchy(p);
        for (int j = 0; j < s.camera.height; ++j)
            for (int i = 0; i < s.camera.width; ++i) {
                rt::RayCounts ca, cb;
                const rt::Color a = rt::pixel_color(s, p, i, j, ca);
                const rt::Color b = rt::pixel_color(s, q, i, j, cb);
                REQUIRE(a == b);
                REQUIRE(ca == cb);
            }
    }
}
