// Shared by the fuzz targets (libFuzzer; built by the `sanitize` preset, see tests/fuzz/CMakeLists.txt).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "io/registry.hpp"

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

// Stops the fuzzer with a message: a broken invariant, not an input error.
[[noreturn]] inline void fail(const std::string& what) {
    __builtin_fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
    __builtin_trap();
}

}  // namespace cg::fuzz
