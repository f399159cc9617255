// CSG on ray segments: 10^4 random rays through 100 random trees of 1 to 6 spheres, boxes and
// capped cylinders (a quarter of the nodes transformed), the state machine run to the end vs the
// plain function (every node's list and the hit: CsgRay::solve; and the hit alone, what a tracer
// calls: csg_intersect on a tree prepared once); one narrated step plus its picture; and the die
// (a cube minus six spheres, tests/golden/ray-tracer/die.json) rendered at 320 × 240.
#include <benchmark/benchmark.h>

#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>

#include "bench/bench_support.hpp"
#include "core/rng.hpp"
#include "rays/csg_ray.hpp"
#include "rays/rt_scene_json.hpp"

namespace {

using glm::dvec3;

struct Gen {
    cg::Rng& rng;
    cg::CsgTree t;

    glm::dmat4 placement() {
        glm::dmat4 m = glm::translate(glm::dmat4(1.0), {rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5),
                                                        rng.uniform(-1.5, 1.5)});
        return glm::rotate(m, rng.uniform(0, 6.283), glm::normalize(dvec3(0.3, 1, 0.2)));
    }
    int leaf() {
        cg::CsgNode n;
        const double k = rng.uniform(0, 1);
        if (k < 0.4) {
            n.quadric.r = rng.uniform(0.4, 2);
            n.quadric.world_from_model = placement();
        } else if (k < 0.7) {
            n.kind = cg::CsgPrimitive::Box;
            n.box.min = {rng.uniform(-2, 1), rng.uniform(-2, 1), rng.uniform(-2, 1)};
            n.box.max = n.box.min + dvec3(rng.uniform(0.3, 2.5));
        } else {
            n.quadric.kind = cg::QuadricKind::Cylinder;
            n.quadric.p = n.quadric.q = rng.uniform(0.3, 1.5);
            n.quadric.zmin = -1, n.quadric.zmax = 1;
            n.quadric.world_from_model = placement();
        }
        n.leaf_index = t.leaves++;
        t.nodes.push_back(n);
        return static_cast<int>(t.nodes.size()) - 1;
    }
    int tree(int leaves) {
        if (leaves == 1) return leaf();
        const int l = static_cast<int>(rng.integer(1, leaves - 1));
        cg::CsgNode n;
        n.leaf = false;
        n.op = static_cast<cg::CsgOp>(rng.integer(0, 2));
        if (rng.chance(0.25)) n.has_transform = true, n.transform = placement();
        n.left = tree(l);
        n.right = tree(leaves - l);
        t.nodes.push_back(n);
        return static_cast<int>(t.nodes.size()) - 1;
    }
};

struct Case {
    cg::Shared<cg::CsgRay::Input> in;
    const cg::PreparedCsg* prepared;
};

const std::vector<Case>& cases() {
    static std::vector<cg::PreparedCsg> trees;
    static const std::vector<Case> v = [] {
        cg::Rng rng(42);
        std::vector<cg::CsgTree> forest;
        for (int k = 0; k < 100; ++k) {
            Gen g{rng, {}};
            g.tree(static_cast<int>(rng.integer(1, 6)));
            forest.push_back(g.t);
            trees.push_back(cg::prepare_csg(g.t));
        }
        std::vector<Case> out;
        for (int i = 0; i < 10'000; ++i) {
            cg::CsgRay::Input in;
            in.tree = forest[i % 100];
            in.origin = {rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(-6, 6)};
            in.direction =
                dvec3(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)) - in.origin;
            out.push_back({cg::Shared<cg::CsgRay::Input>(in), &trees[i % 100]});
        }
        return out;
    }();
    return v;
}

void BM_Csg_Plain(benchmark::State& state) {
    const auto& in = cases();
    for (auto _ : state) {
        double sum = 0;
        for (const Case& c : in) sum += cg::CsgRay::solve(c.in).hit.t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * in.size());
}
BENCHMARK(BM_Csg_Plain)->Unit(benchmark::kMillisecond);

void BM_Csg_StateMachine(benchmark::State& state) {
    const auto& in = cases();
    for (auto _ : state) {
        double sum = 0;
        for (const Case& c : in) sum += cg::run_to_end<cg::CsgRay>(cg::CsgRay::begin(c.in)).hit.t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * in.size());
}
BENCHMARK(BM_Csg_StateMachine)->Unit(benchmark::kMillisecond);

// What a tracer pays: the trees prepared once, the hit alone.
void BM_Csg_Prepared(benchmark::State& state) {
    const auto& in = cases();
    for (auto _ : state) {
        double sum = 0;
        for (const Case& c : in) sum += cg::csg_intersect(*c.prepared, c.in->origin, c.in->direction).t;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * in.size());
}
BENCHMARK(BM_Csg_Prepared)->Unit(benchmark::kMillisecond);

void BM_Csg_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "csg-ray");
}
BENCHMARK(BM_Csg_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_Csg_DieRender(benchmark::State& state) {
    std::ifstream f(std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/die.json");
    std::stringstream text;
    text << f.rdbuf();
    cg::json j = cg::parse_json(text.str());
    j["camera"]["size"] = {320, 240};
    const cg::rt::Scene s = cg::rt::scene_from_json(j);
    std::uint64_t rays = 0;
    for (auto _ : state) {
        const cg::rt::Image img = cg::rt::render(s, 1);
        rays += img.rays.total();
        benchmark::DoNotOptimize(img.rgba.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(rays));
}
BENCHMARK(BM_Csg_DieRender)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
