// The recursive ray tracer on the reference scene (six quadrics and a floor, two lights,
// shadows, reflection depth 3; tests/golden/ray-tracer/reference.json) at 640 × 480: the plain
// renderer on one thread and on two, and the state machine (one step per pixel) run to the end
// on one thread — the "within 1.5× of a plain loop" figure. Rays per second are reported as
// items. Also one narrated step of a ray tree plus its picture, and one pixel step plus its
// picture, what the viewer pays per step.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"

namespace {

const cg::rt::Scene& reference_scene() {
    static const cg::rt::Scene s = [] {
        std::ifstream f(std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/reference.json");
        std::stringstream text;
        text << f.rdbuf();
        cg::json j = cg::parse_json(text.str());
        j["camera"]["size"] = {640, 480};
        return cg::rt::scene_from_json(j);
    }();
    return s;
}

void BM_RayTracer_Plain(benchmark::State& state) {
    const cg::rt::Scene& s = reference_scene();
    const int threads = static_cast<int>(state.range(0));
    std::uint64_t rays = 0;
    for (auto _ : state) {
        const cg::rt::Image img = cg::rt::render(s, threads);
        rays += img.rays.total();
        benchmark::DoNotOptimize(img.rgba.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(rays));
}
BENCHMARK(BM_RayTracer_Plain)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RayTracer_StateMachine(benchmark::State& state) {
    cg::RayTracer::Input in;
    in.scene = reference_scene();
    in.granularity = cg::RayTracer::Granularity::Pixels;
    const cg::RayTracer::State start = cg::RayTracer::start(in);
    std::uint64_t rays = 0;
    for (auto _ : state) {
        const cg::RayTracer::Result r = cg::run_to_end<cg::RayTracer>(start);
        rays += r.rays.total();
        benchmark::DoNotOptimize(r.image.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(rays));
}
BENCHMARK(BM_RayTracer_StateMachine)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RayTracer_TreeStepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "ray-tracer");
}
BENCHMARK(BM_RayTracer_TreeStepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_RayTracer_PixelStepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "ray-tracer", [](cg::json& input) {
        input["stepping"] = {{"granularity", "pixels"}};
    });
}
BENCHMARK(BM_RayTracer_PixelStepAndPicture)->Unit(benchmark::kMicrosecond);

// ---- the bounding volume hierarchy (rays/rt_bvh.hpp): many objects ------------------------
// 4,000 small spheres and 4,000 triangles scattered over a floor, one light, shadows, no
// mirrors, 80 × 60 pixels: the plain tracer with its hierarchy against the same Prepared scene
// with every object moved to the "tested for every ray" list (brute force). Rays per second
// are the items; the images are identical (tests/rays/test_rt_bvh.cpp).
const cg::rt::Scene& many_objects_scene() {
    static const cg::rt::Scene s = [] {
        cg::rt::Scene sc;
        sc.camera.eye = {0, 6, 14};
        sc.camera.center = {0, 0, 0};
        sc.camera.width = 80, sc.camera.height = 60;
        sc.settings.max_depth = 0;
        cg::rt::Material m;
        m.name = "m";
        sc.materials.push_back(m);
        cg::rt::Light l;
        l.position = {3, 12, 6};
        sc.lights.push_back(l);
        cg::rt::Object floor;
        floor.kind = cg::rt::ObjectKind::Plane;
        floor.p0 = {0, -1, 0}, floor.normal = {0, 1, 0};
        sc.objects.push_back(floor);
        cg::Rng rng(5);
        for (int k = 0; k < 8000; ++k) {
            const glm::dvec3 c(rng.uniform(-8, 8), rng.uniform(-1, 3), rng.uniform(-8, 8));
            cg::rt::Object o;
            if (k % 2 == 0) {
                o.quadric.r = rng.uniform(0.05, 0.15);
                o.quadric.world_from_model[3] = glm::dvec4(c, 1);
            } else {
                o.kind = cg::rt::ObjectKind::Triangle;
                o.p0 = c;
                o.p1 = c +
                       glm::dvec3(rng.uniform(-.3, .3), rng.uniform(-.3, .3), rng.uniform(-.3, .3));
                o.p2 = c +
                       glm::dvec3(rng.uniform(-.3, .3), rng.uniform(-.3, .3), rng.uniform(-.3, .3));
            }
            o.name = o.field = "objects[" + std::to_string(sc.objects.size()) + "]";
            sc.objects.push_back(o);
        }
        cg::rt::validate(sc);
        return sc;
    }();
    return s;
}

void BM_RayTracer_ManyObjects(benchmark::State& state) {
    const cg::rt::Scene& s = many_objects_scene();
    cg::rt::Prepared p = cg::rt::prepare(s);
    if (state.range(0) == 0) {  // brute force
        p.bvh = cg::rt::ObjectBvh{};
        for (int k = 0; k < static_cast<int>(p.objects.size()); ++k) p.bvh.unbounded.push_back(k);
    }
    std::uint64_t rays = 0;
    for (auto _ : state) {
        cg::rt::RayCounts counts;
        for (int j = 0; j < s.camera.height; ++j)
            for (int i = 0; i < s.camera.width; ++i)
                benchmark::DoNotOptimize(cg::rt::pixel_color(s, p, i, j, counts));
        rays += counts.total();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(rays));
    state.SetLabel(state.range(0) ? "bvh" : "brute force");
}
BENCHMARK(BM_RayTracer_ManyObjects)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// Building the hierarchy over the 8,000 objects (bounds and binned SAH).
void BM_RayTracer_ManyObjects_Prepare(benchmark::State& state) {
    const cg::rt::Scene& s = many_objects_scene();
    for (auto _ : state) benchmark::DoNotOptimize(cg::rt::prepare(s).bvh.nodes.size());
}
BENCHMARK(BM_RayTracer_ManyObjects_Prepare)->Unit(benchmark::kMillisecond);

}  // namespace
