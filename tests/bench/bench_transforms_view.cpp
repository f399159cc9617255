// Virtual sphere, arcball, the projection pipeline, normals and change of basis: each state
// machine run to completion vs its straight-line function (10^5 random drags of 8 samples; 10^5
// random cameras with 4 points and a segment; 10^5 normal maps; 10^5 frame pairs with 2 points
// and a vector), and the cost of one narrated step plus its picture.
#include <benchmark/benchmark.h>

#include <cmath>

#include "bench/bench_support.hpp"

#include "core/rng.hpp"
#include "transforms/change_of_basis.hpp"
#include "transforms/normal_transform.hpp"
#include "transforms/perspective.hpp"
#include "transforms/trackball_drag.hpp"

namespace {

template <class A>
const std::vector<typename A::Input>& drags() {
    static const std::vector<typename A::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<typename A::Input> v(100'000);
        for (auto& in : v) {
            in.viewport = {rng.uniform(200, 2000), rng.uniform(200, 2000)};
            for (int k = 0; k < 8; ++k)
                in.samples.push_back({rng.uniform(0, in.viewport.x), rng.uniform(0, in.viewport.y)});
        }
        return v;
    }();
    return inputs;
}

template <class A>
void drag_plain(benchmark::State& state) {
    const auto& inputs = drags<A>();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += A::drag(in).rotation.w;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

template <class A>
void drag_state_machine(benchmark::State& state) {
    const auto& inputs = drags<A>();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) {
            typename A::State s;  // start() without re-validating: inputs are known good
            s.in = in;
            s.pairs.reserve(in.samples.size() - 1);  // as start() does
            s.front.reserve(in.samples.size());
            s.front.push_back({0, 0, 1});
            sum += cg::run_to_end<A>(std::move(s)).rotation.w;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}

void BM_VirtualSphere_Plain(benchmark::State& state) { drag_plain<cg::VirtualSphere>(state); }
void BM_VirtualSphere_StateMachine(benchmark::State& state) { drag_state_machine<cg::VirtualSphere>(state); }
void BM_Arcball_Plain(benchmark::State& state) { drag_plain<cg::Arcball>(state); }
void BM_Arcball_StateMachine(benchmark::State& state) { drag_state_machine<cg::Arcball>(state); }
BENCHMARK(BM_VirtualSphere_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VirtualSphere_StateMachine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Arcball_Plain)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Arcball_StateMachine)->Unit(benchmark::kMillisecond);

const std::vector<cg::Perspective::Input>& cameras() {
    static const std::vector<cg::Perspective::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::Perspective::Input> v(100'000);
        for (auto& in : v) {
            in.convention = rng.chance(0.5) ? cg::Perspective::Convention::Course
                                            : cg::Perspective::Convention::OpenGL;
            in.fov_y_deg = rng.uniform(20, 120);
            in.aspect = rng.uniform(0.5, 2.5);
            in.near = rng.uniform(0.1, 2);
            in.far = in.near * rng.uniform(10, 1000);
            in.look_at = true;
            in.eye = {rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)};
            in.center = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
            in.up = {0, 1, 0};
            in.has_viewport = true;
            in.viewport = {1280, 720};
            for (int k = 0; k < 4; ++k)
                in.points.push_back({rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)});
            in.segments.push_back({glm::dvec3(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)),
                                   glm::dvec3(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10))});
        }
        return v;
    }();
    return inputs;
}

void BM_Perspective_Plain(benchmark::State& state) {
    const auto& inputs = cameras();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::Perspective::project(in).clip.back().w;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_Perspective_Plain)->Unit(benchmark::kMillisecond);

void BM_Perspective_StateMachine(benchmark::State& state) {
    const auto inputs = cg::bench::shared_inputs<cg::Perspective>(cameras());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::Perspective>(cg::Perspective::begin(in)).clip.back().w;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_Perspective_StateMachine)->Unit(benchmark::kMillisecond);

const std::vector<cg::NormalTransform::Input>& normal_maps() {
    static const std::vector<cg::NormalTransform::Input> inputs = [] {
        cg::Rng rng(42);
        std::vector<cg::NormalTransform::Input> v(100'000);
        for (auto& in : v) {
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) in.linear[c][r] = rng.uniform(-3, 3) + (c == r ? 4 : 0);
            in.normal = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.5, 1)};
        }
        return v;
    }();
    return inputs;
}

// Both without validation; the plain side computes every field of the result straight through.
void BM_NormalTransform_Plain(benchmark::State& state) {
    const auto& inputs = normal_maps();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::NormalTransform::transform(in).normal.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_NormalTransform_Plain)->Unit(benchmark::kMillisecond);

void BM_NormalTransform_StateMachine(benchmark::State& state) {
    const auto inputs = cg::bench::shared_inputs<cg::NormalTransform>(normal_maps());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::NormalTransform>(cg::NormalTransform::begin(in)).normal.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_NormalTransform_StateMachine)->Unit(benchmark::kMillisecond);

void BM_NormalTransform_StepAndPicture(benchmark::State& state) { cg::bench::step_and_picture(state, "normal-transform"); }
BENCHMARK(BM_NormalTransform_StepAndPicture)->Unit(benchmark::kMicrosecond);

// Half of F2 orthonormal (the transpose shortcut), half general (cross products over det).
const std::vector<cg::ChangeOfBasis::Input>& frame_pairs() {
    static const std::vector<cg::ChangeOfBasis::Input> inputs = [] {
        cg::Rng rng(42);
        const auto random = [&](double r) {
            return glm::dvec3(rng.uniform(-r, r), rng.uniform(-r, r), rng.uniform(-r, r));
        };
        std::vector<cg::ChangeOfBasis::Input> v(100'000);
        for (std::size_t k = 0; k < v.size(); ++k) {
            auto& in = v[k];
            for (int i = 0; i < 3; ++i)
                in.from.axes[i] = random(1) + 3.0 * glm::dvec3(i == 0, i == 1, i == 2);
            in.from.origin = random(10);
            if (k % 2 == 0) {
                const double c = std::cos(0.001 * k), s = std::sin(0.001 * k);
                in.to.axes = {glm::dvec3(c, s, 0), glm::dvec3(-s, c, 0), glm::dvec3(0, 0, 1)};
            } else {
                for (int i = 0; i < 3; ++i)
                    in.to.axes[i] = random(1) + 3.0 * glm::dvec3(i == 0, i == 1, i == 2);
            }
            in.to.origin = random(10);
            in.points = {random(5), random(5)};
            in.vectors = {random(5)};
        }
        return v;
    }();
    return inputs;
}

// Both without validation; the plain side computes every field of the result straight through.
void BM_ChangeOfBasis_Plain(benchmark::State& state) {
    const auto& inputs = frame_pairs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs) sum += cg::ChangeOfBasis::transform(in).points.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ChangeOfBasis_Plain)->Unit(benchmark::kMillisecond);

void BM_ChangeOfBasis_StateMachine(benchmark::State& state) {
    const auto inputs = cg::bench::shared_inputs<cg::ChangeOfBasis>(frame_pairs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : inputs)
            sum += cg::run_to_end<cg::ChangeOfBasis>(cg::ChangeOfBasis::begin(in)).points.back().x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * inputs.size());
}
BENCHMARK(BM_ChangeOfBasis_StateMachine)->Unit(benchmark::kMillisecond);

void BM_ChangeOfBasis_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "change-of-basis");
}
BENCHMARK(BM_ChangeOfBasis_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_VirtualSphere_StepAndPicture(benchmark::State& state) { cg::bench::step_and_picture(state, "virtual-sphere"); }
void BM_Arcball_StepAndPicture(benchmark::State& state) { cg::bench::step_and_picture(state, "arcball"); }
void BM_Perspective_StepAndPicture(benchmark::State& state) { cg::bench::step_and_picture(state, "perspective"); }
BENCHMARK(BM_VirtualSphere_StepAndPicture)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Arcball_StepAndPicture)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Perspective_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
