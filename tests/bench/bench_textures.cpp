// Textures: texture-map, bump-map and solid-texture run to completion against their plain
// functions (10^5 lookups on spheres and planes, bilinear and mipmapped; 10^5 bumped normals;
// 10^5 marble points in one input), one narrated step plus its picture for each, and what
// textures cost the tracer (the marble-vase scene with and without its textures).
#include <benchmark/benchmark.h>

#include <fstream>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "io/registry.hpp"
#include "rays/bump_map.hpp"
#include "rays/rt_scene_json.hpp"
#include "rays/solid_texture.hpp"
#include "rays/texture_map.hpp"

namespace {

using glm::dvec3;

cg::TextureImage random_image(cg::Rng& rng, int w, int h) {
    cg::TextureImage im;
    im.width = w, im.height = h;
    for (int k = 0; k < w * h; ++k)
        im.texels.push_back({rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)});
    return im;
}

std::vector<cg::TextureMap::Input> texture_inputs(cg::TexFilter filter) {
    cg::Rng rng(42);
    const cg::TextureImage im = random_image(rng, 16, 16);
    std::vector<cg::TextureMap::Input> v(100'000);
    for (auto& in : v) {
        if (rng.chance(0.5)) {
            in.surface.kind = cg::UvKind::Quadric;
            in.surface.quadric.r = rng.uniform(0.5, 2);
            in.point =
                in.surface.quadric.r *
                glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        } else {
            in.surface.kind = cg::UvKind::Plane;
            in.point = {rng.uniform(-3, 3), rng.uniform(-3, 3), 0};
        }
        in.texture.image = im;
        in.texture.filter = filter;
        in.footprint = std::exp2(rng.uniform(-6, 0));
    }
    return v;
}

const std::vector<cg::TextureMap::Input>& bilinear_inputs() {
    static const auto v = texture_inputs(cg::TexFilter::Bilinear);
    return v;
}
const std::vector<cg::TextureMap::Input>& mipmap_inputs() {
    static const auto v = texture_inputs(cg::TexFilter::Mipmap);
    return v;
}

// Started states (validated, prepared, the input shared), made once: each run starts from a
// copy, as the viewer's timeline does.
template <class A>
std::vector<typename A::State> started(const std::vector<typename A::Input>& inputs) {
    std::vector<typename A::State> s;
    s.reserve(inputs.size());
    for (const auto& in : inputs) s.push_back(A::start(in));
    return s;
}

void texture_plain(benchmark::State& state, const std::vector<cg::TextureMap::Input>& inputs) {
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::TextureMap::solve(in).lookup.color.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void texture_machine(benchmark::State& state, const std::vector<cg::TextureMap::Input>& inputs) {
    static std::vector<cg::TextureMap::State> bilinear, mipmap;
    auto& states = &inputs == &bilinear_inputs() ? bilinear : mipmap;
    if (states.empty()) states = started<cg::TextureMap>(inputs);
    for (auto _ : state) {
        double sum = 0;
        for (const auto& s : states) sum += cg::run_to_end<cg::TextureMap>(s).lookup.color.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

// The plain arithmetic with the surface prepared beforehand, as the state machine's started
// states have it (and as a tracer does it): the parametrisation and the lookup only.
void BM_TextureMap_PlainPrepared(benchmark::State& state) {
    const auto& inputs = bilinear_inputs();
    std::vector<cg::PreparedUv> prepared;
    for (const auto& in : inputs) prepared.push_back(cg::prepare_uv(in.surface));
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t k = 0; k < inputs.size(); ++k) {
            const cg::UvFrame f = cg::uv_frame(prepared[k], inputs[k].point);
            sum += cg::lookup(inputs[k].texture, nullptr, f.uv, 0).color.x;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_TextureMap_PlainPrepared)->Unit(benchmark::kMillisecond);

void BM_TextureMap_Plain(benchmark::State& state) {
    texture_plain(state, bilinear_inputs());
}
void BM_TextureMap_StateMachine(benchmark::State& state) {
    texture_machine(state, bilinear_inputs());
}
void BM_TextureMap_Mipmap_Plain(benchmark::State& state) {
    texture_plain(state, mipmap_inputs());
}
void BM_TextureMap_Mipmap_StateMachine(benchmark::State& state) {
    texture_machine(state, mipmap_inputs());
}
BENCHMARK(BM_TextureMap_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TextureMap_StateMachine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TextureMap_Mipmap_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TextureMap_Mipmap_StateMachine)->Unit(benchmark::kMillisecond);

const std::vector<cg::BumpMap::Input>& bump_inputs() {
    static const auto v = [] {
        cg::Rng rng(43);
        std::vector<cg::BumpMap::Input> v(100'000);
        for (auto& in : v) {
            in.surface.kind = cg::UvKind::Quadric;
            in.surface.quadric.r = rng.uniform(0.5, 2);
            in.point =
                in.surface.quadric.r *
                glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
            in.height.kind = rng.chance(0.5) ? cg::HeightKind::Sines : cg::HeightKind::Noise;
            in.height.amplitude = 0.01;
            in.height.frequency = {8, 4};
        }
        return v;
    }();
    return v;
}

void BM_BumpMap_Plain(benchmark::State& state) {
    const auto& inputs = bump_inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::BumpMap::solve(in).bump.perturbed.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_BumpMap_Plain)->Unit(benchmark::kMillisecond);

// The same with the surface, its outward normal and the noise's permutation made beforehand.
void BM_BumpMap_PlainPrepared(benchmark::State& state) {
    const auto& inputs = bump_inputs();
    std::vector<cg::PreparedUv> prepared;
    std::vector<glm::dvec3> outward;
    for (const auto& in : inputs) {
        prepared.push_back(cg::prepare_uv(in.surface));
        outward.push_back(cg::outward_normal(prepared.back(), in.point));
    }
    const cg::Perlin perlin = cg::make_perlin(0);
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t k = 0; k < inputs.size(); ++k) {
            const cg::UvFrame f = cg::uv_frame(prepared[k], inputs[k].point);
            sum += cg::blinn_bump(f, outward[k], inputs[k].height, perlin).perturbed.x;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_BumpMap_PlainPrepared)->Unit(benchmark::kMillisecond);

void BM_BumpMap_StateMachine(benchmark::State& state) {
    static const auto states = started<cg::BumpMap>(bump_inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& s : states) sum += cg::run_to_end<cg::BumpMap>(s).bump.perturbed.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * states.size());
}
BENCHMARK(BM_BumpMap_StateMachine)->Unit(benchmark::kMillisecond);

const cg::SolidTextureAlgo::Input& marble_input() {
    static const auto in = [] {
        cg::Rng rng(44);
        cg::SolidTextureAlgo::Input in;
        in.texture.kind = cg::SolidKind::Marble;
        in.texture.seed = 7;
        for (int k = 0; k < 100'000; ++k)
            in.points.push_back({rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)});
        return in;
    }();
    return in;
}

void BM_SolidTexture_Plain(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(cg::SolidTextureAlgo::solve(marble_input()).samples.data());
    state.SetItemsProcessed(state.iterations() * marble_input().points.size());
}
BENCHMARK(BM_SolidTexture_Plain)->Unit(benchmark::kMillisecond);

void BM_SolidTexture_StateMachine(benchmark::State& state) {
    const auto start = cg::SolidTextureAlgo::start(marble_input());
    for (auto _ : state)
        benchmark::DoNotOptimize(cg::run_to_end<cg::SolidTextureAlgo>(start).samples.data());
    state.SetItemsProcessed(state.iterations() * marble_input().points.size());
}
BENCHMARK(BM_SolidTexture_StateMachine)->Unit(benchmark::kMillisecond);

void BM_TextureMap_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "texture-map");
}
void BM_BumpMap_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "bump-map");
}
void BM_SolidTexture_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "solid-texture");
}
BENCHMARK(BM_TextureMap_StepAndPicture)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BumpMap_StepAndPicture)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolidTexture_StepAndPicture)->Unit(benchmark::kMicrosecond);

// The tracer: the marble-vase golden scene (marble, wood and a 3D checker) against the same
// scene with its textures taken off, on one thread.
cg::rt::Scene vase(bool textured) {
    std::ifstream f(std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/marble-vase.json");
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    cg::rt::Scene s = cg::rt::scene_from_json(cg::parse_json(text));
    if (!textured)
        for (auto& m : s.materials) m.tex = {};
    cg::rt::validate(s);
    return s;
}

void BM_Render_Vase_Textured(benchmark::State& state) {
    const cg::rt::Scene s = vase(true);
    for (auto _ : state) benchmark::DoNotOptimize(cg::rt::render(s, 1).rgba.data());
}
void BM_Render_Vase_Untextured(benchmark::State& state) {
    const cg::rt::Scene s = vase(false);
    for (auto _ : state) benchmark::DoNotOptimize(cg::rt::render(s, 1).rgba.data());
}
BENCHMARK(BM_Render_Vase_Textured)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Render_Vase_Untextured)->Unit(benchmark::kMillisecond);

}  // namespace
