// A small seeded random generator that gives the same numbers on every machine.
//
// The standard distributions (std::uniform_int_distribution, ...) are implementation-defined,
// so the same seed could give a different exam problem with another standard library. This is
// SplitMix64 with the mappings written out, so a seed names one problem everywhere.
#pragma once

#include <cstdint>

namespace cg {

class Rng {
public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    // An integer in [lo, hi], both included (the modulo bias is below 2^-40 for our ranges).
    long long integer(long long lo, long long hi) {
        return lo + static_cast<long long>(next() % static_cast<std::uint64_t>(hi - lo + 1));
    }
    // A double in [lo, hi), from the top 53 bits.
    double uniform(double lo, double hi) {
        return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53;
    }
    bool chance(double p) { return uniform(0, 1) < p; }

    bool operator==(const Rng&) const = default;

private:
    std::uint64_t state_;
};

}  // namespace cg
