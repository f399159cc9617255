// Photon mapping: the state machine run to completion vs the straight-line compute() on the
// showcase scene (a glass ball over a floor under a spot light) at 2,000 photons and on a lit
// plane at 20,000 photons, k = 50; and the cost of one narrated step plus its picture.
#include <benchmark/benchmark.h>

#include "bench/bench_support.hpp"
#include "gi/photon_map.hpp"
#include "io/registry.hpp"

namespace {

using cg::PhotonMap;

PhotonMap::Input scene(int which) {
    PhotonMap::Input in;
    PhotonMap::Object floor;
    floor.shape = PhotonMap::Shape::Plane;
    floor.center = {0, 0, 0};
    floor.normal = {0, 1, 0};
    in.objects = {floor};
    PhotonMap::Light l;
    l.position = {0, 4, 0};
    l.power = 100;
    if (which == 0) {
        PhotonMap::Object ball;
        ball.center = {0, 1.2, 0};
        ball.radius = 0.8;
        ball.material = PhotonMap::Material::Glass;
        in.objects.push_back(ball);
        l.cone_deg = 20;
        in.photons = 2000;
    } else {
        in.photons = 20000;
    }
    in.lights = {l};
    in.k = 50;
    return in;
}

void BM_PhotonMap_Plain(benchmark::State& state) {
    const PhotonMap::Input in = scene(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(PhotonMap::compute(in).irradiance);
    state.SetItemsProcessed(state.iterations() * in.photons);
}
BENCHMARK(BM_PhotonMap_Plain)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_PhotonMap_StateMachine(benchmark::State& state) {
    const PhotonMap::Input in = scene(int(state.range(0)));
    const PhotonMap::State start = PhotonMap::start(in);
    for (auto _ : state)
        benchmark::DoNotOptimize(cg::run_to_end<PhotonMap>(start).irradiance);
    state.SetItemsProcessed(state.iterations() * in.photons);
}
BENCHMARK(BM_PhotonMap_StateMachine)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_PhotonMap_StepAndPicture(benchmark::State& state) {
    cg::bench::step_and_picture(state, "photon-map");
}
BENCHMARK(BM_PhotonMap_StepAndPicture)->Unit(benchmark::kMicrosecond);

}  // namespace
