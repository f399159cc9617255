// The tracer's mesh hierarchy (rays/rt_mesh.hpp): on random meshes — triangle soups, nested
// and overlapping, shared edges and corners, a flat terrain of zero height with rays aimed at
// its grid's corners and edges, copies of one triangle — the nearest hit equals testing every
// triangle (same triangle, same t, same β and γ), occlusion equals "some triangle in range",
// and the tree is the same built on one thread or two; its depth stays bounded on inputs that
// defeat the surface area heuristic. The triangle test itself is checked against a long-double
// solve of E + t d = P0 + β e1 + γ e2 by Cramer's rule on the 3 × 3 determinants.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "rays/mesh_gen.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_mesh.hpp"
#include "rays/rt_scene.hpp"
#include "support/uniform.hpp"

using namespace cg;
using glm::dvec3;

namespace {

using cg::test::Gen;

struct Brute {
    double t = INFINITY;
    std::uint32_t id = 0;
    bool hit = false;
};

Brute brute_nearest(const mesh::Mesh& m, dvec3 o, dvec3 d, double t_min, double t_max) {
    Brute b;
    b.t = t_max;
    for (std::uint32_t k = 0; k < m.triangles.size(); ++k) {
        const dvec3 p0 = m.vertices[m.triangles[k][0]];
        const double t = rt::triangle_t(p0, m.vertices[m.triangles[k][1]] - p0,
                                        m.vertices[m.triangles[k][2]] - p0, o, d, t_min);
        if (t < b.t) b.t = t, b.id = k, b.hit = true;  // strict: the first index wins a tie
    }
    return b;
}

void add_triangle(mesh::Mesh& m, dvec3 a, dvec3 b, dvec3 c) {
    const auto n = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {a, b, c});
    m.triangles.push_back({n, n + 1, n + 2});
}

mesh::Mesh soup(Gen& g, int n, double spread) {
    mesh::Mesh m;
    dvec3 last = g.point(spread);
    for (int k = 0; k < n; ++k) {
        const double size = spread * (g.u() < 0.85 ? 0.05 : 0.6);
        const dvec3 a = g.u() < 0.4 ? last : g.point(spread);
        const dvec3 b = a + g.point(size), c = a + g.point(size);
        if (mesh::degenerate(a, b, c)) continue;
        add_triangle(m, a, b, c);
        last = c;
        if (g.u() < 0.05) add_triangle(m, a, b, c);  // an exact duplicate: ties in t
    }
    return m;
}

// Checks `rays` rays against brute force; returns how many hit.
int check_rays(const mesh::Mesh& m, const rt::MeshBvh& bvh, Gen& g, int rays, double spread,
               bool aim_at_vertices) {
    int hits = 0;
    for (int r = 0; r < rays; ++r) {
        dvec3 o = g.point(2 * spread), target;
        if (aim_at_vertices && !m.vertices.empty() && g.u() < 0.5) {
            const auto& tri = m.triangles[static_cast<std::size_t>(g.u() * m.triangles.size())];
            const dvec3 a = m.vertices[tri[0]], b = m.vertices[tri[1]];
            const double w = g.u() < 0.5 ? 0.0 : std::floor(4 * g.u()) / 4;  // corner or edge
            target = a + w * (b - a);
        } else {
            target = g.point(spread);
        }
        if (g.u() < 0.1) o = g.point(0.5 * spread);  // from inside the mesh's box
        dvec3 d = target - o;
        if (g.u() < 0.1) d[static_cast<int>(3 * g.u()) % 3] = 0;  // a component 0
        if (d == dvec3(0.0)) continue;
        const double t_min = 1e-9, t_max = g.u() < 0.2 ? 0.7 : INFINITY;
        const Brute b = brute_nearest(m, o, d, t_min, t_max);
        rt::MeshHit h;
        const bool found = rt::mesh_nearest(bvh, o, d, t_min, t_max, h);
        INFO("ray " << r << " from " << o.x << ", " << o.y << ", " << o.z);
        REQUIRE(found == b.hit);
        REQUIRE(rt::mesh_occluded(bvh, o, d, t_min, t_max) == b.hit);
        if (!found) continue;
        ++hits;
        REQUIRE(h.triangle == b.id);
        REQUIRE(h.t == b.t);
        const auto& tri = m.triangles[h.triangle];
        const dvec3 p = (1 - h.beta - h.gamma) * m.vertices[tri[0]] + h.beta * m.vertices[tri[1]] +
                        h.gamma * m.vertices[tri[2]];
        REQUIRE(glm::length(p - (o + h.t * d)) <=
                1e-9 * (1 + glm::length(o) + h.t * glm::length(d)));
    }
    return hits;
}

}  // namespace

TEST_CASE("mesh triangle test: t, beta, gamma against a long-double Cramer solve", "[rt_mesh]") {
    Gen g{std::mt19937_64(5)};
    int hits = 0;
    for (int k = 0; k < 20000; ++k) {
        const dvec3 p0 = g.point(2), p1 = p0 + g.point(1), p2 = p0 + g.point(1);
        // Aimed at the triangle's plane around it (β, γ in [−0.2, 1.2]): hits and near misses.
        const dvec3 o = g.point(3);
        const dvec3 aim = p0 + (1.4 * g.u() - 0.2) * (p1 - p0) + (1.4 * g.u() - 0.2) * (p2 - p0);
        const dvec3 d = (aim - o) * (0.5 + g.u());
        double beta = 0, gamma = 0;
        const double t = rt::triangle_t(p0, p1 - p0, p2 - p0, o, d, 0, &beta, &gamma);
        // [−d  e1  e2] (t, β, γ)ᵀ = o − p0, each unknown a ratio of determinants.
        using L = long double;
        auto det3 = [](const L a[3], const L b[3], const L c[3]) {
            return a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) +
                   c[0] * (a[1] * b[2] - a[2] * b[1]);
        };
        L md[3], e1[3], e2[3], r[3];
        for (int i = 0; i < 3; ++i)
            md[i] = -L(d[i]), e1[i] = L(p1[i]) - p0[i], e2[i] = L(p2[i]) - p0[i],
            r[i] = L(o[i]) - p0[i];
        const L D = det3(md, e1, e2);
        const L T = det3(r, e1, e2) / D, B = det3(md, r, e2) / D, G = det3(md, e1, r) / D;
        const bool inside = B >= 0 && G >= 0 && B + G <= 1 && T > 0;
        const bool clear = std::fabs(static_cast<double>(B)) > 1e-9 &&
                           std::fabs(static_cast<double>(G)) > 1e-9 &&
                           std::fabs(static_cast<double>(1 - B - G)) > 1e-9 &&
                           std::fabs(static_cast<double>(T)) > 1e-9;
        if (!clear) continue;  // on an edge to rounding: either answer is right
        REQUIRE(std::isfinite(t) == inside);
        if (!inside) continue;
        ++hits;
        REQUIRE(t == Approx(static_cast<double>(T)).epsilon(1e-9));
        REQUIRE(beta == Approx(static_cast<double>(B)).margin(1e-9));
        REQUIRE(gamma == Approx(static_cast<double>(G)).margin(1e-9));
    }
    CHECK(hits > 5000);
}

TEST_CASE("mesh hierarchy: random soups equal brute force on 10,000 rays each", "[rt_mesh]") {
    Gen g{std::mt19937_64(11)};
    int hits = 0;
    for (int scene = 0; scene < 12; ++scene) {
        const int n = scene < 4 ? 1 + scene * 7 : 200 * scene;
        const mesh::Mesh m = soup(g, n, 1.0);
        const rt::MeshBvh bvh = rt::build_mesh_bvh(m, 1);
        REQUIRE(bvh.triangles.size() == m.triangles.size());
        hits += check_rays(m, bvh, g, 10000, 1.0, true);
    }
    CHECK(hits > 20000);
}

TEST_CASE("mesh hierarchy: a flat terrain, rays at its grid's corners and edges", "[rt_mesh]") {
    mesh::TerrainParams p;
    p.resolution = 40;
    p.height = 0;  // every triangle at y = 0: boxes of zero height before padding
    p.size = {8, 8};
    const mesh::Mesh m = mesh::terrain(p);
    const rt::MeshBvh bvh = rt::build_mesh_bvh(m, 2);
    Gen g{std::mt19937_64(3)};
    int hits = 0;
    for (int r = 0; r < 10000; ++r) {
        // A grid point (a corner, or half-way along an edge) inside the terrain.
        const double x = -4 + 0.1 * std::floor(80 * g.u() + 0.5),
                     z = -4 + 0.1 * std::floor(80 * g.u() + 0.5);
        const dvec3 o = dvec3(5 * g.c(), 1 + 3 * g.u(), 5 * g.c());
        const dvec3 d = dvec3(x, 0, z) - o;
        const Brute b = brute_nearest(m, o, d, 1e-9, INFINITY);
        rt::MeshHit h;
        REQUIRE(rt::mesh_nearest(bvh, o, d, 1e-9, INFINITY, h) == b.hit);
        if (!b.hit) continue;
        ++hits;
        REQUIRE(h.triangle == b.id);
        REQUIRE(h.t == b.t);
    }
    CHECK(hits > 9000);  // the rare miss: a point exactly on the rim, lost to rounding by both
}

TEST_CASE("mesh hierarchy: the same tree on one thread or two, on generated meshes", "[rt_mesh]") {
    mesh::TerrainParams tp;
    tp.resolution = 96;
    mesh::Mesh m = mesh::terrain(tp);
    mesh::SphereParams sp;
    sp.segments = 48;
    sp.center = {0, 1.5, 0};
    const mesh::Mesh s = mesh::sphere(sp);
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), s.vertices.begin(), s.vertices.end());
    for (auto t : s.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    const rt::MeshBvh one = rt::build_mesh_bvh(m, 1), two = rt::build_mesh_bvh(m, 2);
    REQUIRE(one.ids == two.ids);
    REQUIRE(one.nodes.size() == two.nodes.size());
    REQUIRE(std::memcmp(one.nodes.data(), two.nodes.data(),
                        one.nodes.size() * sizeof(rt::MeshNode)) == 0);
    REQUIRE(one.depth < 64);
    // Every triangle is in exactly one leaf, and every leaf's box holds its triangles' corners.
    std::vector<int> seen(m.triangles.size(), 0);
    for (std::uint32_t id : one.ids) ++seen[id];
    REQUIRE(std::count(seen.begin(), seen.end(), 1) == static_cast<long>(seen.size()));
    for (const rt::MeshNode& n : one.nodes)
        for (int k = 0; k < 4; ++k) {
            if (n.count[k] <= 0) continue;
            for (int t = n.child[k]; t < n.child[k] + n.count[k]; ++t)
                for (const dvec3 p :
                     {one.triangles[t].p0, one.triangles[t].p0 + one.triangles[t].e1,
                      one.triangles[t].p0 + one.triangles[t].e2})
                    for (int a = 0; a < 3; ++a) {
                        REQUIRE(n.lo[a][k] <= p[a]);
                        REQUIRE(p[a] <= n.hi[a][k]);
                    }
        }
    Gen g{std::mt19937_64(8)};
    CHECK(check_rays(m, one, g, 10000, 5.0, true) > 3000);
}

TEST_CASE("mesh hierarchy: copies of one triangle and a sliver fan keep the depth bounded",
          "[rt_mesh]") {
    mesh::Mesh same;
    for (int k = 0; k < 5000; ++k) add_triangle(same, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const rt::MeshBvh a = rt::build_mesh_bvh(same, 2);
    REQUIRE(a.depth < 64);
    rt::MeshHit h;
    REQUIRE(rt::mesh_nearest(a, {0.2, 0.2, 1}, {0, 0, -1}, 0, INFINITY, h));
    REQUIRE(h.triangle == 0);  // 5,000 ties: the smallest index
    REQUIRE(h.t == 1);
    // Geometrically growing triangles (a classic worst case for centre-based splits).
    mesh::Mesh fan;
    for (int k = 0; k < 2000; ++k) {
        const double s = std::ldexp(1.0, -(k % 60));
        add_triangle(fan, {0, 0, 0}, {s, 0, 0}, {0, s, 1e-3 * k});
    }
    const rt::MeshBvh b = rt::build_mesh_bvh(fan, 1);
    REQUIRE(b.depth < 64);
    Gen g{std::mt19937_64(4)};
    check_rays(fan, b, g, 3000, 1.0, true);
    // Empty and single-triangle meshes.
    const rt::MeshBvh empty = rt::build_mesh_bvh(mesh::Mesh{}, 2);
    REQUIRE_FALSE(rt::mesh_nearest(empty, {0, 0, 1}, {0, 0, -1}, 0, INFINITY, h));
    REQUIRE_FALSE(rt::mesh_occluded(empty, {0, 0, 1}, {0, 0, -1}, 0, INFINITY));
    mesh::Mesh one;
    add_triangle(one, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const rt::MeshBvh single = rt::build_mesh_bvh(one, 2);
    REQUIRE(rt::mesh_nearest(single, {0.2, 0.2, 1}, {0, 0, -1}, 0, INFINITY, h));
    REQUIRE(h.t == 1);
    REQUIRE(h.beta == 0.2);
}

// ---- mesh objects in the ray tracer ------------------------------------------------------------

namespace {

rt::Scene base_scene() {
    rt::Scene s;
    s.camera.eye = {0.3, 2.5, 4};
    s.camera.center = {0, 0, 0};
    s.camera.width = 48, s.camera.height = 36;
    s.settings.max_depth = 2;
    rt::Material m;
    m.name = "m";
    m.kr = glm::dvec3(0.3);
    s.materials.push_back(m);
    rt::Light l;
    l.position = {2, 4, 3};
    s.lights.push_back(l);
    return s;
}

// The scene with every mesh replaced by its triangles, one triangle object each (what a mesh
// was before mesh objects existed).
rt::Scene as_triangles(const rt::Scene& s) {
    rt::Scene t = s;
    t.objects.clear();
    for (const rt::Object& o : s.objects) {
        if (o.kind != rt::ObjectKind::Mesh) {
            t.objects.push_back(o);
            continue;
        }
        const mesh::Mesh& m = o.mesh->mesh;
        for (const auto& ix : m.triangles) {
            rt::Object tri = o;
            tri.kind = rt::ObjectKind::Triangle;
            tri.mesh = {};
            tri.p0 = m.vertices[ix[0]], tri.p1 = m.vertices[ix[1]], tri.p2 = m.vertices[ix[2]];
            if (!m.normals.empty()) {
                tri.smooth = true;
                tri.n0 = m.normals[ix[0]], tri.n1 = m.normals[ix[1]], tri.n2 = m.normals[ix[2]];
            }
            t.objects.push_back(tri);
        }
    }
    return t;
}

rt::Object mesh_object(mesh::Mesh m, const std::string& name) {
    rt::Object o;
    o.kind = rt::ObjectKind::Mesh;
    o.name = o.field = name;
    o.mesh = cg::Shared<rt::TriangleMesh>(rt::make_triangle_mesh(std::move(m)));
    return o;
}

}  // namespace

TEST_CASE("mesh objects: the tracer's hits and blockers equal brute force over every triangle",
          "[rt_mesh]") {
    Gen g{std::mt19937_64(21)};
    int hits = 0, mesh_hits = 0;
    for (int scene = 0; scene < 6; ++scene) {
        rt::Scene s = base_scene();
        // Meshes (soups, a terrain, a sphere) between spheres and lone triangles; a lone
        // triangle that duplicates a mesh's first triangle exactly (a tie in t across objects).
        const mesh::Mesh soup1 = soup(g, 150, 1.0);
        rt::Object ball;
        ball.kind = rt::ObjectKind::Quadric;
        ball.quadric.r = 0.3;
        ball.quadric.world_from_model = glm::translate(glm::dmat4(1.0), g.point(1.0));
        ball.name = ball.field = "ball";
        s.objects.push_back(ball);
        s.objects.push_back(mesh_object(soup1, "soup"));
        rt::Object dup;
        dup.kind = rt::ObjectKind::Triangle;
        dup.name = dup.field = "dup";
        dup.p0 = soup1.vertices[soup1.triangles[0][0]];
        dup.p1 = soup1.vertices[soup1.triangles[0][1]];
        dup.p2 = soup1.vertices[soup1.triangles[0][2]];
        s.objects.push_back(dup);
        mesh::TerrainParams tp;
        tp.resolution = 12;
        tp.size = {3, 3};
        tp.center = {0, -0.8, 0};
        tp.height = 0.3;
        s.objects.push_back(mesh_object(mesh::terrain(tp), "terrain"));
        mesh::SphereParams sp;
        sp.center = g.point(0.8);
        sp.radius = 0.4;
        sp.segments = 12;
        s.objects.push_back(mesh_object(mesh::sphere(sp), "globe"));
        if (scene % 2) s.objects.push_back(mesh_object(soup(g, 60, 1.0), "soup2"));
        rt::validate(s);
        const rt::Prepared p = rt::prepare(s);
        REQUIRE_FALSE(p.bvh.nodes.empty());
        for (int r = 0; r < 10000; ++r) {
            dvec3 o = g.point(2.5);
            dvec3 target = g.point(1.0);
            if (r % 10 == 0) target = dup.p0 + 0.3 * (dup.p1 - dup.p0) + 0.3 * (dup.p2 - dup.p0);
            const dvec3 d = target - o;
            const rt::Hit a = rt::nearest_hit(p, o, d), b = rt::nearest_hit_brute_force(p, o, d);
            INFO("scene " << scene << " ray " << r);
            REQUIRE(a.object == b.object);
            REQUIRE(a.triangle == b.triangle);
            REQUIRE(a.t == b.t);
            REQUIRE(a.normal == b.normal);
            if (a.object >= 0) ++hits;
            if (a.object >= 0 && s.objects[a.object].kind == rt::ObjectKind::Mesh) ++mesh_hits;
            if (r % 10 == 0 && a.object >= 0 && a.t == b.t) {
                // At the duplicate: the soup (object 1) comes before "dup" (object 2).
                if (s.objects[a.object].name == "dup") CHECK(false);
            }
            const double t_max = 0.2 + 0.8 * g.u();
            REQUIRE(rt::first_blocker(p, o, d, 1e-9, t_max) ==
                    rt::first_blocker_brute_force(p, o, d, 1e-9, t_max));
            REQUIRE(rt::blocked(p, o, d, 1e-9, t_max) ==
                    (rt::first_blocker_brute_force(p, o, d, 1e-9, t_max) >= 0));
        }
    }
    CHECK(hits > 20000);
    CHECK(mesh_hits > 10000);
}

TEST_CASE("mesh objects: images bit-identical to the same triangles as separate objects",
          "[rt_mesh]") {
    Gen g{std::mt19937_64(4)};
    rt::Scene s = base_scene();
    mesh::TerrainParams tp;
    tp.resolution = 16;
    tp.size = {4, 4};
    tp.center = {0, -0.7, 0};
    tp.height = 0.4;
    s.objects.push_back(mesh_object(mesh::terrain(tp), "terrain"));  // smooth normals
    mesh::SphereParams sp;
    sp.center = {0.2, 0.1, 0};
    sp.radius = 0.5;
    s.objects.push_back(mesh_object(mesh::sphere(sp), "globe"));
    s.objects.push_back(mesh_object(soup(g, 40, 1.0), "soup"));  // flat
    rt::validate(s);
    const rt::Scene t = as_triangles(s);
    rt::validate(t);
    REQUIRE(t.objects.size() > 500);
    const rt::Image a = rt::render(s, 1), b = rt::render(t, 1);
    CHECK(a.rays == b.rays);
    int differ = 0;
    for (std::size_t k = 0; k < a.rgba.size(); ++k) differ += a.rgba[k] != b.rgba[k];
    CHECK(differ == 0);
    CHECK(rt::render(s, 2) == a);  // and the same on two threads
}

TEST_CASE("mesh objects: the ray tracer shows the hierarchy's build as its first step",
          "[rt_mesh]") {
    rt::Scene s = base_scene();
    mesh::TerrainParams tp;
    tp.resolution = 64;
    s.objects.push_back(mesh_object(mesh::terrain(tp), "terrain"));
    cg::RayTracer::Input in;
    in.scene = s;
    in.granularity = cg::RayTracer::Granularity::RayTree;
    in.pixel = {24, 18};
    auto st = cg::RayTracer::start(in);
    cg::StepInfo info;
    cg::RayTracer::step(st, &info);
    CHECK(info.event == "build");
    CHECK(info.line == 16);
    CHECK_THAT(info.narration,
               Catch::Contains("Mesh terrain: its own hierarchy over 8192 triangles"));
    cg::Scene pic;
    cg::RayTracer::draw(st, pic);
    CHECK(pic.segments3.size() >= 12 * 2);  // the mesh's box and its children's
    // The next step is the primary ray, and the image is what the plain tracer makes.
    cg::StepInfo next;
    cg::RayTracer::step(st, &next);
    CHECK(next.event == "primary");
    while (!cg::RayTracer::done(st)) cg::RayTracer::step(st, nullptr);
    rt::RayCounts counts;
    const rt::Prepared p = rt::prepare(s);
    CHECK(cg::pack_rgba(cg::RayTracer::result(st).color) ==
          cg::pack_rgba(rt::pixel_color(s, p, 24, 18, counts)));
}
