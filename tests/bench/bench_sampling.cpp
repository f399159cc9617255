// Aliasing and anti-aliasing, each state machine run to the end vs its plain function: sampling
// 1,000 random 1D signals (1 to 3 sines, about 20 samples, linear and sinc reconstruction) and a
// 32 × 32 zone plate with 16 jittered samples per pixel; supersampling 2,000 random pixels with
// 16 jittered samples, and with Poisson dart throwing; one narrated step plus its picture each,
// and for the convergence study a step (one point: 400 supersamples) plus its plot, and the plot.
// Distribution ray tracing: rays per second (items) with 16 samples per pixel — the reference
// scene at 160 × 120 (anti-aliasing only), the soft-shadow scene (a disc light of 16 shadow rays)
// and the depth-of-field scene, plain on one and two threads and the state machine pixel by
// pixel; and one narrated step of a distributed ray tree plus its picture.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"
#include "sampling/sampling.hpp"
#include "sampling/supersampling.hpp"

namespace {

const std::vector<cg::Sampling::Input>& signals() {
    static const auto v = [] {
        cg::Rng rng(42);
        std::vector<cg::Sampling::Input> out(1000);
        for (std::size_t k = 0; k < out.size(); ++k) {
            auto& in = out[k];
            in.mode = cg::Sampling::Mode::Signal;
            in.rate = rng.uniform(5, 20);
            in.duration = 1;
            in.reconstruction =
                k % 2 ? cg::Sampling::Reconstruction::Sinc : cg::Sampling::Reconstruction::Linear;
            for (long long c = rng.integer(1, 3); c > 0; --c) {
                const double f = rng.uniform(0, 25);
                const double a = rng.uniform(0.2, 1);
                const double p = rng.uniform(-180, 180);
                in.signal.push_back({f, a, p});
            }
        }
        return out;
    }();
    return v;
}

const cg::Sampling::Input& zone_plate() {
    static const auto in = [] {
        cg::Sampling::Input z;
        z.mode = cg::Sampling::Mode::Image;
        z.width = z.height = 32;
        z.image.kind = cg::Sampling::ImageKind::ZonePlate;
        z.image.nyquist_radius = 8;
        return z;
    }();
    return in;
}

double sampling_machine(const cg::Sampling::Input& in) {
    cg::Sampling::State s = cg::Sampling::start(in);
    const auto r = cg::run_to_end<cg::Sampling>(std::move(s));
    return r.error_rms + r.rms_difference;
}

void BM_Sampling_Signal_Plain(benchmark::State& state) {
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : signals()) sum += cg::Sampling::run(in).error_rms;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * signals().size());
}
BENCHMARK(BM_Sampling_Signal_Plain)->Unit(benchmark::kMillisecond);

void BM_Sampling_Signal_StateMachine(benchmark::State& state) {
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : signals()) sum += sampling_machine(in);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * signals().size());
}
BENCHMARK(BM_Sampling_Signal_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Sampling_Image_Plain(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(cg::Sampling::run(zone_plate()).rms_difference);
}
BENCHMARK(BM_Sampling_Image_Plain)->Unit(benchmark::kMillisecond);

void BM_Sampling_Image_StateMachine(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(sampling_machine(zone_plate()));
}
BENCHMARK(BM_Sampling_Image_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Sampling_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "sampling");
}
BENCHMARK(BM_Sampling_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_Sampling_Image_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "sampling", [](cg::json& in) {
        in = cg::json{{"image", {{"type", "zone-plate"}}}, {"width", 32}, {"height", 32}};
    });
}
BENCHMARK(BM_Sampling_Image_StepAndPicture)->Unit(benchmark::kMicrosecond);

std::vector<cg::Supersampling::Input> pixels(cg::sampling::Pattern pattern, int samples,
                                             cg::sampling::Filter filter) {
    cg::Rng rng(42);
    std::vector<cg::Supersampling::Input> v(2000);
    for (std::size_t k = 0; k < v.size(); ++k) {
        auto& in = v[k];
        in.pattern = pattern;
        in.samples = samples;
        in.filter = filter;
        in.i = static_cast<int>(rng.integer(0, 99));
        in.j = static_cast<int>(rng.integer(0, 99));
        in.scene.kind = cg::sampling::RegionKind::Edge;
        const double x = in.i + rng.uniform(0, 1);
        const double y = in.j + rng.uniform(0, 1);
        in.scene.point = {x, y};
        in.scene.angle_deg = rng.uniform(0, 360);
        in.seed = k;
    }
    return v;
}

const std::vector<cg::Supersampling::Input>& jittered16() {
    static const auto v = pixels(cg::sampling::Pattern::Jittered, 16, cg::sampling::Filter::Tent);
    return v;
}
const std::vector<cg::Supersampling::Input>& poisson16() {
    static const auto v = pixels(cg::sampling::Pattern::Poisson, 16, cg::sampling::Filter::Box);
    return v;
}

void plain(benchmark::State& state, const std::vector<cg::Supersampling::Input>& inputs) {
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::Supersampling::supersample(in).error;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void machine(benchmark::State& state, const std::vector<cg::Supersampling::Input>& inputs) {
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            cg::Supersampling::State s;  // start() without re-validating: inputs are known good
            s.in = cg::Shared<cg::Supersampling::Input>(in);
            s.radius = cg::Supersampling::radius_of(in);
            sum += cg::run_to_end<cg::Supersampling>(std::move(s)).error;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void BM_Supersampling_Plain(benchmark::State& state) {
    plain(state, jittered16());
}
BENCHMARK(BM_Supersampling_Plain)->Unit(benchmark::kMillisecond);
void BM_Supersampling_StateMachine(benchmark::State& state) {
    machine(state, jittered16());
}
BENCHMARK(BM_Supersampling_StateMachine)->Unit(benchmark::kMillisecond);
void BM_Supersampling_Poisson_Plain(benchmark::State& state) {
    plain(state, poisson16());
}
BENCHMARK(BM_Supersampling_Poisson_Plain)->Unit(benchmark::kMillisecond);
void BM_Supersampling_Poisson_StateMachine(benchmark::State& state) {
    machine(state, poisson16());
}
BENCHMARK(BM_Supersampling_Poisson_StateMachine)->Unit(benchmark::kMillisecond);

void BM_Supersampling_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "supersampling");
}
BENCHMARK(BM_Supersampling_StepAndPicture)->Unit(benchmark::kMicrosecond);

// The convergence study: a step measures one (pattern, N) point over 400 edges, so it costs
// 400 supersamples; the picture alone (the plot of the finished study) is the viewer's part.
void BM_Supersampling_Study_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "supersampling", [](cg::json& in) {
        in = cg::json{{"study", cg::json::object()}};
    });
}
BENCHMARK(BM_Supersampling_Study_StepAndPicture)->Unit(benchmark::kMicrosecond);
void BM_Supersampling_Study_Picture(benchmark::State& state) {
    const cg::Registry registry = cg::builtin_registry();
    auto run = registry.find("supersampling")->create(cg::json{{"study", cg::json::object()}});
    while (!run->done()) run->step(nullptr);
    cg::Scene scene;
    for (auto _ : state) {
        scene.clear();
        run->draw(scene);
        benchmark::DoNotOptimize(scene.labels.data());
    }
}
BENCHMARK(BM_Supersampling_Study_Picture)->Unit(benchmark::kMicrosecond);

// ---- distribution ray tracing ----------------------------------------------------------------

cg::json golden_scene(const char* name) {
    std::ifstream f(std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/" + name + ".json");
    std::stringstream text;
    text << f.rdbuf();
    return cg::parse_json(text.str());
}

const cg::rt::Scene& distributed_scene(int which) {
    static const cg::rt::Scene scenes[3] = {
        [] {
            cg::json j = golden_scene("reference");
            j["camera"]["size"] = {160, 120};
            j["settings"]["samples_per_pixel"] = 16;
            return cg::rt::scene_from_json(j);
        }(),
        [] {
            cg::json j = golden_scene("soft-shadows");
            j["settings"]["samples_per_pixel"] = 16;
            return cg::rt::scene_from_json(j);
        }(),
        cg::rt::scene_from_json(golden_scene("depth-of-field")),
    };
    return scenes[which];
}

// range(0): the scene (0 reference, 1 soft shadows, 2 depth of field); range(1): threads.
void BM_DistributionRayTracer_16spp_Plain(benchmark::State& state) {
    const cg::rt::Scene& s = distributed_scene(static_cast<int>(state.range(0)));
    std::uint64_t rays = 0;
    for (auto _ : state) {
        const cg::rt::Image img = cg::rt::render(s, static_cast<int>(state.range(1)));
        rays += img.rays.total();
        benchmark::DoNotOptimize(img.rgba.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(rays));
}
BENCHMARK(BM_DistributionRayTracer_16spp_Plain)
    ->Args({0, 1})
    ->Args({0, 2})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_DistributionRayTracer_16spp_StateMachine(benchmark::State& state) {
    cg::RayTracer::Input in;
    in.scene = distributed_scene(static_cast<int>(state.range(0)));
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
BENCHMARK(BM_DistributionRayTracer_16spp_StateMachine)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_DistributionRayTracer_TreeStepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "ray-tracer", [](cg::json& in) {
        in = golden_scene("soft-shadows");
        in["camera"]["size"] = {48, 36};
        in["stepping"] = {{"granularity", "ray-tree"}, {"pixel", {16.5, 14.5}}};
    });
}
BENCHMARK(BM_DistributionRayTracer_TreeStepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
