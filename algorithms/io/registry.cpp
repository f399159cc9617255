#include "io/registry.hpp"

namespace cg {

// Each algorithm's *_json.cpp defines `Algorithm <name>_algorithm()`.
#define CG_ALGORITHM(name) Algorithm name##_algorithm();
#include "algorithms.def"
#undef CG_ALGORITHM

Registry builtin_registry() {
    return Registry({
#define CG_ALGORITHM(name) name##_algorithm(),
#include "algorithms.def"
#undef CG_ALGORITHM
    });
}

const Algorithm* Registry::find(std::string_view id) const {
    for (const Algorithm& a : algorithms_)
        if (a.spec->id == id) return &a;
    return nullptr;
}

}  // namespace cg
