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

}  // namespace
