// L-systems: the state machine run to completion vs the straight-line compute on the classic
// systems at picture sizes (the fractal plant, 5 generations, 6,263 symbols; the bush, 4, 11,116;
// the Koch snowflake, 4, 1,792; the dragon curve, 10, 4,094; the Sierpinski arrowhead, 6, 1,457);
// and the cost of one narrated step plus its picture on the example (the Koch curve, 36 symbols)
// and on the fractal plant (each picture re-walks the string up to the turtle).
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "io/registry.hpp"
#include "modelling/l_system.hpp"

namespace {

using cg::LSystem;

LSystem::Input make(std::string axiom, std::vector<LSystem::Rule> rules, int n, double angle,
                    double heading, std::string draw = "F") {
    LSystem::Input in;
    in.axiom = std::move(axiom);
    in.rules = std::move(rules);
    in.generations = n;
    in.angle = angle;
    in.heading = heading;
    in.draw = std::move(draw);
    LSystem::validate(in);
    return in;
}

const std::vector<LSystem::Input>& inputs() {
    static const std::vector<LSystem::Input> v = {
        make("X", {{'X', "F+[[X]-X]-F[-FX]+X"}, {'F', "FF"}}, 5, 25, 65),
        make("F", {{'F', "FF+[+F-F-F]-[-F+F+F]"}}, 4, 22.5, 90),
        make("F--F--F", {{'F', "F+F--F+F"}}, 4, 60, 0),
        make("FX", {{'X', "X+YF+"}, {'Y', "-FX-Y"}}, 10, 90, 0),
        make("A", {{'A', "B-A-B"}, {'B', "A+B+A"}}, 6, 60, 0, "AB"),
    };
    return v;
}

void BM_LSystem_Plain(benchmark::State& state) {
    const auto& v = inputs();
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : v) sum += LSystem::compute(in).end.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * v.size());
}
BENCHMARK(BM_LSystem_Plain)->Unit(benchmark::kMillisecond);

void BM_LSystem_StateMachine(benchmark::State& state) {
    static const auto shared = cg::bench::shared_inputs<LSystem>(inputs());
    for (auto _ : state) {
        double sum = 0;
        for (const auto& in : shared) sum += cg::run_to_end<LSystem>(LSystem::begin(in)).end.x;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * shared.size());
}
BENCHMARK(BM_LSystem_StateMachine)->Unit(benchmark::kMillisecond);

void BM_LSystem_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "l-system");
}
BENCHMARK(BM_LSystem_StepAndPicture)->Unit(benchmark::kMicrosecond);

void BM_LSystem_StepAndPicturePlant(benchmark::State& state) {
    cg::bench::step_and_picture(state, "l-system", [](cg::json& in) {
        in = cg::parse_json(R"({"axiom": "X", "rules": {"X": "F+[[X]-X]-F[-FX]+X", "F": "FF"},
                                "generations": 5, "angle": 25, "heading": 65})");
    });
}
BENCHMARK(BM_LSystem_StepAndPicturePlant)->Unit(benchmark::kMicrosecond);

}  // namespace
