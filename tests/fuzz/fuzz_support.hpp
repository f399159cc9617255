// Shared by the fuzz targets (libFuzzer; built by the `sanitize` preset, see
// tests/fuzz/CMakeLists.txt).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "io/registry.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"

namespace cg::fuzz {

inline const Registry& registry() {
    static const Registry r = builtin_registry();
    return r;
}

// The algorithm a fuzz input's first byte picks.
inline const Algorithm& pick(std::uint8_t byte) {
    const auto& all = registry().all();
    return all[byte % all.size()];
}

// A state machine that runs longer than this on a fuzzed input is cut off: inputs of this size
// finish in far fewer steps, so the cap only keeps one input from eating the fuzzing time.
constexpr std::size_t kStepCap = 20'000;

// Whether a run of this input would cost more than a fuzz iteration should (the ray tracer's
// scenes may legally cost up to rt::kMaxWork ray-object tests: minutes, not the milliseconds
// a fuzzer needs). Such inputs are still created (validation is fuzzed) but not run.
inline bool too_costly(const Algorithm& a, const json& input) {
    if (a.spec->id != "ray-tracer") return false;
    try {
        const rt::Scene s = rt::scene_from_json(input, {"stepping"});
        const bool tree = input.contains("stepping") && input["stepping"].is_object() &&
                          input["stepping"].value("granularity", "") == "ray-tree";
        const double pixels =
            tree ? 1.0 + RayTracer::kPreviewPixels : double(s.camera.width) * s.camera.height;
        return rt::pixel_work(s) * pixels > 2e6;
    } catch (const InputError&) {
        return false;  // create() refuses it
    }
}

// Stops the fuzzer with a message: a broken invariant, not an input error.
[[noreturn]] inline void fail(const std::string& what) {
    __builtin_fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
    __builtin_trap();
}

}  // namespace cg::fuzz
