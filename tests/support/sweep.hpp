// How many cases a sweep over seeds or random inputs runs in this build.
//
// The normal build runs every sweep in full: that is where a reference comparison on thousands
// of inputs finds wrong answers. The sanitizer build (CG_TEST_SANITIZED) runs the same code ten
// to twenty times slower, looking for memory and undefined-behaviour errors; the first quarter
// of a sweep reaches the same code paths as the rest, so it runs that quarter and keeps
// `make test` within CI's time.
#pragma once

#include <algorithm>
#include <cstddef>

namespace cg::test {

#ifdef CG_TEST_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// n in the normal build, a quarter of it (at least one) under the sanitizers.
constexpr std::size_t sweep(std::size_t n) { return kSanitized ? std::max<std::size_t>(1, n / 4) : n; }

}  // namespace cg::test
