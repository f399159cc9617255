// Boids exam problems: one boid and 2 to 4 neighbours, one frame by hand. Boid 0 sits at a
// small integer point with a small integer velocity; its neighbours lie 1 or 2 away along an
// axis (inside the separation radius 2.5) or at a 3-4-5 offset (outside it, inside r = 6), with
// small integer velocities; one time in three a further boid sits beyond r and must be left out.
// Weights 1, dt = 1, max_force 10 and max_speed 5 (the new velocity is sometimes capped: one
// time in five max_speed is 2). The answer: s, a, c and the new velocity v' = v + F, capped.
#include "animation/boids.hpp"
#include "core/format.hpp"

namespace cg {

Boids::Input Boids::exam_input(Rng& rng) {
    // Offsets from boid 0: close ones (|d| = 1 or 2) and far ones (|d| = 5).
    const glm::dvec2 offsets[] = {{1, 0}, {-1, 0}, {0, 1},  {0, -1}, {2, 0},  {-2, 0},
                                  {0, 2}, {0, -2}, {3, 4},  {-4, 3}, {4, -3}, {-3, -4}};
    const glm::dvec2 beyond[] = {{7, 0}, {0, -7}, {-6, 4}, {5, 5}};
    Input in;
    in.world_min = {-20, -20};
    in.world_max = {20, 20};
    in.edges = Edges::Wrap;
    in.radius = 6;
    in.separation_radius = 2.5;
    in.fov = 360;
    in.weights = {1, 1, 1, 1, 1};
    in.max_force = 10;
    in.max_speed = rng.chance(0.2) ? 2 : 5;
    in.min_speed = 0;
    in.dt = 1;
    in.steps = 1;
    in.focus = 0;
    const glm::dvec2 x0{double(rng.integer(-2, 2)), double(rng.integer(-2, 2))};
    auto velocity = [&] { return glm::dvec2(double(rng.integer(-1, 1)), double(rng.integer(-1, 1))); };
    Boid focus{x0, velocity()};
    if (focus.velocity == glm::dvec2(0)) focus.velocity = {1, 0};
    in.boids.push_back(focus);
    const int m = int(rng.integer(2, 4));
    bool used[12] = {};
    for (int q = 0; q < m; ++q) {
        int k;
        do k = int(rng.integer(0, 11));
        while (used[k]);
        used[k] = true;
        in.boids.push_back({x0 + offsets[k], velocity()});
    }
    if (rng.chance(1.0 / 3)) in.boids.push_back({x0 + beyond[rng.integer(0, 3)], velocity()});
    return in;
}

std::string Boids::question(const Input& in) {
    std::string q = "Boid 0 is at x = " + num(in.boids.at(0).position) + " with velocity v = " +
                    num(in.boids.at(0).velocity) + ". The other boids:";
    for (std::size_t j = 1; j < in.boids.size(); ++j)
        q += std::string(j > 1 ? ";" : "") + " boid " + std::to_string(j) + " at " +
             num(in.boids[j].position) + " with velocity " + num(in.boids[j].velocity);
    q += ". Boid 0 sees the boids closer than r = " + num(in.radius) +
         " (all round). With d_j = x_j − x, compute the separation s = Σ −d_j / |d_j|² over the "
         "neighbours closer than r_sep = " +
         num(in.separation_radius) +
         ", the alignment a = (mean velocity of the neighbours) − v and the cohesion c = (centre "
         "of the neighbours) − x. The steering is F = s + a + c (weights 1, at most max_force = " +
         num(in.max_force) + " long), and the new velocity v' = v + dt F with dt = " + num(in.dt) +
         ", scaled down to max_speed = " + num(in.max_speed) +
         " if it is longer. Give separation, alignment, cohesion and v' as [x, y].";
    return q;
}

}  // namespace cg
