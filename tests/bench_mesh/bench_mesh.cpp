// The tracer's mesh hierarchy (rays/rt_mesh.hpp) against Intel Embree 3, the reference CPU ray
// tracer, on the same triangles and the same rays, in one binary: a generated scene of about
// 10⁶ triangles (a fractal terrain of 704² cells, five tessellated spheres and a Bézier patch)
// seen by a 640 × 480 camera, and a point light above it.
//
//   Build     the hierarchy from the triangle list: ours (binned SAH, two threads) against
//             rtcCommitScene (Embree's default build, its own threads); bytes per triangle.
//   Primary   the 307,200 primary rays, nearest hit: mesh_nearest against rtcIntersect1.
//   Shadow    a shadow ray from every primary hit to the light: mesh_occluded against
//             rtcOccluded1.
//
// Single rays on one thread for both (Embree's packets are not used: ours are not packets).
// Embree works in floats and we in doubles, so a handful of rays grazing an edge may differ:
// the "differ" counter reports how many. CG_MESH_RESOLUTION sets the terrain's cells a side
// (the smoke test runs a small scene).
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <atomic>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <vector>

#include "rays/mesh_gen.hpp"
#include "rays/rt_mesh.hpp"
#include "rays/rt_scene.hpp"

using namespace cg;
using glm::dvec3;

namespace {

struct Setup {
    mesh::Mesh mesh;
    std::vector<dvec3> origins, directions;  // the primary rays
    std::vector<dvec3> shadow_origins, shadow_directions;
    dvec3 light{0, 40, 10};
    rt::MeshBvh bvh;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
};

// Every generated mesh has smooth normals and (u, v): so does their union.
void append(mesh::Mesh& to, const mesh::Mesh& m) {
    const auto base = static_cast<std::uint32_t>(to.vertices.size());
    to.vertices.insert(to.vertices.end(), m.vertices.begin(), m.vertices.end());
    to.normals.insert(to.normals.end(), m.normals.begin(), m.normals.end());
    to.uv.insert(to.uv.end(), m.uv.begin(), m.uv.end());
    for (auto t : m.triangles) to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

mesh::Mesh make_scene() {
    mesh::TerrainParams tp;
    const char* env = std::getenv("CG_MESH_RESOLUTION");
    tp.resolution = env ? std::atoi(env) : 704;
    tp.size = {20, 20};
    tp.height = 2;
    tp.roughness = 0.55;
    tp.seed = 7;
    mesh::Mesh m = mesh::terrain(tp);
    for (int k = 0; k < 5; ++k) {
        mesh::SphereParams sp;
        sp.center = {-6 + 3 * k, 3, -2 + (k % 2) * 3};
        sp.radius = 1.2;
        sp.segments = 64;
        append(m, mesh::sphere(sp));
    }
    mesh::PatchParams pp;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            pp.control_points[i][j] = {-4 + 2.5 * j, 5 + ((i + j) % 3), -6 + 1.5 * i};
    pp.segments = 32;
    append(m, mesh::patch(pp));
    return m;
}

RTCScene embree_scene(RTCDevice device, const mesh::Mesh& m) {
    RTCScene scene = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.vertices.size()));
    for (std::size_t k = 0; k < m.vertices.size(); ++k)
        for (int a = 0; a < 3; ++a) v[3 * k + a] = static_cast<float>(m.vertices[k][a]);
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), m.triangles.size()));
    for (std::size_t k = 0; k < m.triangles.size(); ++k)
        for (int a = 0; a < 3; ++a) idx[3 * k + a] = m.triangles[k][a];
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
    return scene;
}

// What Embree holds for the scene (its memory monitor's net bytes while building it): the
// vertex and index buffers and the hierarchy.
std::atomic<long long> embree_net{0};
double embree_bytes = 0;
bool monitor(void*, ssize_t bytes, bool) {
    embree_net += bytes;
    return true;
}

Setup& setup() {
    static Setup s = [] {
        Setup s;
        s.mesh = make_scene();
        s.bvh = rt::build_mesh_bvh(s.mesh, 2);
        rt::Camera c;
        c.eye = {0, 12, 16};
        c.center = {0, 0, -1};
        c.fov_y_deg = 50;
        c.width = 640, c.height = 480;
        const rt::View view = rt::make_view(c);
        for (int j = 0; j < c.height; ++j)
            for (int i = 0; i < c.width; ++i) {
                s.origins.push_back(view.eye);
                s.directions.push_back(rt::screen_point(view, i + 0.5, j + 0.5) - view.eye);
            }
        for (std::size_t r = 0; r < s.origins.size(); ++r) {
            rt::MeshHit h;
            if (!rt::mesh_nearest(s.bvh, s.origins[r], s.directions[r], 1e-9, INFINITY, h))
                continue;
            const dvec3 p = s.origins[r] + h.t * s.directions[r];
            const auto& tri = s.mesh.triangles[h.triangle];
            dvec3 n = glm::normalize(glm::cross(s.mesh.vertices[tri[1]] - s.mesh.vertices[tri[0]],
                                                s.mesh.vertices[tri[2]] - s.mesh.vertices[tri[0]]));
            if (glm::dot(n, s.directions[r]) > 0) n = -n;
            const dvec3 o = p + 1e-6 * n;
            s.shadow_origins.push_back(o);
            s.shadow_directions.push_back(s.light - o);  // t in (0, 1): to the light
        }
        s.device = rtcNewDevice(nullptr);
        rtcSetDeviceMemoryMonitorFunction(s.device, monitor, nullptr);
        s.scene = embree_scene(s.device, s.mesh);
        embree_bytes = static_cast<double>(embree_net.load());
        rtcSetDeviceMemoryMonitorFunction(s.device, nullptr, nullptr);
        return s;
    }();
    return s;
}

// The "rays/s" counter: `rays` per iteration, over the wall time.
void rays_per_second(benchmark::State& state, double rays) {
    state.counters["rays/s"] = benchmark::Counter(rays * static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}

RTCRayHit embree_ray(dvec3 o, dvec3 d, float tfar) {
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(o.x), rh.ray.org_y = static_cast<float>(o.y);
    rh.ray.org_z = static_cast<float>(o.z);
    rh.ray.dir_x = static_cast<float>(d.x), rh.ray.dir_y = static_cast<float>(d.y);
    rh.ray.dir_z = static_cast<float>(d.z);
    rh.ray.tnear = 0;
    rh.ray.tfar = tfar;
    rh.ray.mask = 0xFFFFFFFF;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

void BM_MeshBuild_Ours(benchmark::State& state) {
    const Setup& s = setup();
    for (auto _ : state) {
        const rt::MeshBvh b = rt::build_mesh_bvh(s.mesh, static_cast<int>(state.range(0)));
        benchmark::DoNotOptimize(b.nodes.data());
    }
    state.counters["triangles"] = static_cast<double>(s.mesh.triangles.size());
    state.counters["bytes/triangle"] =
        static_cast<double>(s.bvh.bytes()) / static_cast<double>(s.mesh.triangles.size());
    state.counters["depth"] = s.bvh.depth;
}
BENCHMARK(BM_MeshBuild_Ours)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_MeshBuild_Embree(benchmark::State& state) {
    const Setup& s = setup();
    for (auto _ : state) {
        RTCScene scene = embree_scene(s.device, s.mesh);
        benchmark::DoNotOptimize(scene);
        state.PauseTiming();
        rtcReleaseScene(scene);
        state.ResumeTiming();
    }
    state.counters["triangles"] = static_cast<double>(s.mesh.triangles.size());
    state.counters["bytes/triangle"] = embree_bytes / static_cast<double>(s.mesh.triangles.size());
}
BENCHMARK(BM_MeshBuild_Embree)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_MeshPrimary_Ours(benchmark::State& state) {
    const Setup& s = setup();
    long long hits = 0;
    for (auto _ : state) {
        hits = 0;
        for (std::size_t r = 0; r < s.origins.size(); ++r) {
            rt::MeshHit h;
            hits += rt::mesh_nearest(s.bvh, s.origins[r], s.directions[r], 1e-9, INFINITY, h);
        }
    }
    // What a ray costs: box tests and triangle tests, on average.
    long long boxes = 0, triangles = 0;
    for (std::size_t r = 0; r < s.origins.size(); ++r) {
        rt::MeshHit h;
        rt::mesh_nearest(s.bvh, s.origins[r], s.directions[r], 1e-9, INFINITY, h, &boxes,
                         &triangles);
    }
    const double rays = static_cast<double>(s.origins.size());
    state.counters["boxes/ray"] = static_cast<double>(boxes) / rays;
    state.counters["triangles/ray"] = static_cast<double>(triangles) / rays;
    state.counters["hits"] = static_cast<double>(hits);
    rays_per_second(state, static_cast<double>(s.origins.size()));
}
BENCHMARK(BM_MeshPrimary_Ours)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_MeshPrimary_Embree(benchmark::State& state) {
    const Setup& s = setup();
    long long hits = 0, differ = 0;
    RTCIntersectContext context;
    for (auto _ : state) {
        hits = 0;
        for (std::size_t r = 0; r < s.origins.size(); ++r) {
            rtcInitIntersectContext(&context);
            RTCRayHit rh = embree_ray(s.origins[r], s.directions[r], INFINITY);
            rtcIntersect1(s.scene, &context, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    // Where the two disagree on which triangle is hit (floats against doubles at edges).
    for (std::size_t r = 0; r < s.origins.size(); ++r) {
        rtcInitIntersectContext(&context);
        RTCRayHit rh = embree_ray(s.origins[r], s.directions[r], INFINITY);
        rtcIntersect1(s.scene, &context, &rh);
        rt::MeshHit h;
        const bool ours = rt::mesh_nearest(s.bvh, s.origins[r], s.directions[r], 1e-9, INFINITY, h);
        const bool theirs = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        differ += ours != theirs || (ours && h.triangle != rh.hit.primID);
    }
    state.counters["hits"] = static_cast<double>(hits);
    state.counters["differ"] = static_cast<double>(differ);
    rays_per_second(state, static_cast<double>(s.origins.size()));
}
BENCHMARK(BM_MeshPrimary_Embree)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_MeshShadow_Ours(benchmark::State& state) {
    const Setup& s = setup();
    long long blocked = 0;
    for (auto _ : state) {
        blocked = 0;
        for (std::size_t r = 0; r < s.shadow_origins.size(); ++r)
            blocked += rt::mesh_occluded(s.bvh, s.shadow_origins[r], s.shadow_directions[r], 0, 1);
    }
    state.counters["blocked"] = static_cast<double>(blocked);
    rays_per_second(state, static_cast<double>(s.shadow_origins.size()));
}
BENCHMARK(BM_MeshShadow_Ours)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_MeshShadow_Embree(benchmark::State& state) {
    const Setup& s = setup();
    long long blocked = 0;
    RTCIntersectContext context;
    for (auto _ : state) {
        blocked = 0;
        for (std::size_t r = 0; r < s.shadow_origins.size(); ++r) {
            rtcInitIntersectContext(&context);
            RTCRay ray = embree_ray(s.shadow_origins[r], s.shadow_directions[r], 1).ray;
            rtcOccluded1(s.scene, &context, &ray);
            blocked += ray.tfar < 0;  // Embree marks an occluded ray with tfar = −∞
        }
    }
    state.counters["blocked"] = static_cast<double>(blocked);
    rays_per_second(state, static_cast<double>(s.shadow_origins.size()));
}
BENCHMARK(BM_MeshShadow_Embree)->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole tracer on the same scene: the mesh as one object, a point light, shadows, no
// secondary rays (primary and shadow rays only), shading included. Arg: threads.
void BM_MeshTracer(benchmark::State& state) {
    const Setup& s = setup();
    static const rt::Scene scene = [&] {
        rt::Scene sc;
        sc.camera.eye = {0, 12, 16};
        sc.camera.center = {0, 0, -1};
        sc.camera.fov_y_deg = 50;
        sc.camera.width = 640, sc.camera.height = 480;
        sc.settings.max_depth = 0;
        sc.settings.shadows = true;
        rt::Material m;
        m.name = "m";
        sc.materials.push_back(m);
        rt::Light l;
        l.position = s.light;
        sc.lights.push_back(l);
        rt::Object o;
        o.kind = rt::ObjectKind::Mesh;
        o.name = o.field = "objects[0]";
        o.mesh = Shared<rt::TriangleMesh>(rt::make_triangle_mesh(s.mesh));
        sc.objects.push_back(o);
        rt::validate(sc);
        return sc;
    }();
    rt::Image image;
    for (auto _ : state) {
        image = rt::render(scene, static_cast<int>(state.range(0)));
        benchmark::DoNotOptimize(image.rgba.data());
    }
    state.counters["rays"] = static_cast<double>(image.rays.total());
    rays_per_second(state, static_cast<double>(image.rays.total()));
}
BENCHMARK(BM_MeshTracer)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
