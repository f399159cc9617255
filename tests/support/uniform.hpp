// Uniform random numbers for the tests' random scenes: u in [0, 1), c in [−1, 1), and a point
// in the cube [−r, r)³, from one seeded generator (the same seed, the same scene).
#pragma once

#include <glm/vec3.hpp>
#include <random>

namespace cg::test {

struct Gen {
    std::mt19937_64 rng;
    double u() { return std::uniform_real_distribution<double>(0, 1)(rng); }
    double c() { return std::uniform_real_distribution<double>(-1, 1)(rng); }
    glm::dvec3 point(double r) { return {r * c(), r * c(), r * c()}; }
};

}  // namespace cg::test
