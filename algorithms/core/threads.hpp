// How many threads a parallel loop of the library may start.
#pragma once

#include <algorithm>
#include <thread>

namespace cg {

// `asked` threads, or for asked ≤ 0 the machine's core count (at least 1). The browser build
// is compiled without threads (no -pthread), where starting a std::thread throws: there, 1.
inline int usable_threads(int asked) {
#ifdef __EMSCRIPTEN__
    (void)asked;
    return 1;
#else
    return asked > 0 ? asked : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
#endif
}

}  // namespace cg
