#include "accel/complexity.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "accel/uniform_grid.hpp"

namespace cg::accel {

using glm::dvec3;

std::vector<Primitive> random_scene(Rng& rng, int n) {
    std::vector<Primitive> out(static_cast<std::size_t>(std::max(n, 0)));
    const double scale = std::cbrt(1.0 / std::max(n, 1));  // n^(−1/3)
    for (Primitive& p : out) {
        const dvec3 c(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1));
        if (rng.chance(0.5)) {
            p.kind = PrimitiveKind::Sphere;
            p.a = c;
            p.radius = 0.25 * scale * rng.uniform(0.2, 1);
        } else {
            p.kind = PrimitiveKind::Triangle;
            const double s = 0.5 * scale;
            auto corner = [&] {
                return c + dvec3(rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s));
            };
            p.a = corner();
            p.b = corner();
            p.c = corner();
        }
    }
    return out;
}

std::vector<Ray> random_rays(Rng& rng, int count) {
    std::vector<Ray> out(static_cast<std::size_t>(std::max(count, 0)));
    for (Ray& r : out) {
        do {
            r.origin =
                dvec3(rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5));
            r.direction = dvec3(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)) - r.origin;
        } while (r.direction == dvec3(0.0));
    }
    return out;
}

namespace {

// Brute force's order: the least t, on a tie the smaller index.
void keep(CountedHit& h, int k, double t) {
    if (t < h.t || (t == h.t && t < CountedHit::kInf && k < h.primitive)) h.t = t, h.primitive = k;
}

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace

CountedHit brute_nearest(const std::vector<Primitive>& prims, const Ray& ray) {
    CountedHit h;
    for (std::size_t k = 0; k < prims.size(); ++k) {
        keep(h, static_cast<int>(k), intersect(prims[k], ray.origin, ray.direction).t);
        ++h.primitive_tests;
    }
    return h;
}

CountedHit bvh_nearest(const rt::ObjectBvh& bvh, const std::vector<Primitive>& prims,
                       const Ray& ray) {
    CountedHit h;
    // Objects outside the tree (all of them in a scene too small for one) are tested one by one.
    for (int p : bvh.unbounded) {
        keep(h, p, intersect(prims[static_cast<std::size_t>(p)], ray.origin, ray.direction).t);
        ++h.primitive_tests;
    }
    rt::traverse(
        bvh, rt::box_ray(ray.origin, ray.direction), 0, [&] { return h.t; },
        [&](int p) {
            keep(h, p, intersect(prims[static_cast<std::size_t>(p)], ray.origin, ray.direction).t);
            ++h.primitive_tests;
            return false;
        },
        &h.box_tests);
    return h;
}

std::vector<ComplexityRow> complexity(const std::vector<int>& counts, int rays, std::uint64_t seed,
                                      int check_limit) {
    std::vector<ComplexityRow> rows;
    for (int n : counts) {
        ComplexityRow row;
        row.n = n, row.rays = rays;
        Rng rng(seed + 104729 * static_cast<std::uint64_t>(n));
        UniformGrid::Input in;
        in.primitives = random_scene(rng, n);
        const std::vector<Ray> ray_list = random_rays(rng, rays);
        const auto& prims = in.primitives;

        auto start = std::chrono::steady_clock::now();
        std::vector<Bounds> boxes(prims.size());
        for (std::size_t k = 0; k < prims.size(); ++k) boxes[k] = bounds(prims[k]);
        const rt::ObjectBvh bvh = rt::build_bvh(boxes);
        row.bvh_build_ms = ms_since(start);
        row.bvh_nodes = static_cast<int>(bvh.nodes.size());
        row.bvh_depth = bvh.depth;

        // About one primitive per cell.
        row.grid_side =
            std::max(1, static_cast<int>(std::lround(std::cbrt(static_cast<double>(n)))));
        in.cells = {row.grid_side, row.grid_side, row.grid_side};
        start = std::chrono::steady_clock::now();
        const Shared<UniformGrid::Grid> grid(UniformGrid::build(in));
        row.grid_build_ms = ms_since(start);

        for (const Ray& ray : ray_list) {
            const CountedHit b = bvh_nearest(bvh, prims, ray);
            row.bvh_box_tests += b.box_tests;
            row.bvh_primitive_tests += b.primitive_tests;
            row.hits += b.primitive >= 0;
            in.origin = ray.origin, in.direction = ray.direction;
            const UniformGrid::Result g = UniformGrid::trace(in, grid);
            row.grid_cells += static_cast<long long>(g.cells_visited.size());
            row.grid_primitive_tests += g.primitive_tests;
            if (n <= check_limit) {
                const CountedHit f = brute_nearest(prims, ray);
                ++row.checked;
                const bool grid_same =
                    g.hit ? g.primitive == f.primitive && g.t == f.t : f.primitive < 0;
                row.agree += grid_same && b.primitive == f.primitive && b.t == f.t;
            }
        }
        rows.push_back(row);
    }
    return rows;
}

std::string complexity_table(const std::vector<ComplexityRow>& rows) {
    std::string out =
        "Ray-primitive tests per ray on random scenes (n primitives in the unit cube, mean over "
        "the rays)\n"
        "  brute force: n tests, O(n)\n"
        "  BVH (binned SAH): box and primitive tests per ray, about O(log n)\n"
        "  grid (g^3 cells, g = round(cbrt n)): cells visited and primitive tests per ray\n"
        "  guides: n and log2 n; build times in ms; agree: rays where BVH and grid give brute\n"
        "  force's hit (t and primitive), of those checked\n\n";
    char line[256];
    std::snprintf(line, sizeof line, "%8s %6s %9s %9s %8s %8s %6s %9s %8s %8s %9s %9s %11s\n", "n",
                  "rays", "brute", "log2 n", "bvh box", "bvh prim", "depth", "bvh ms", "g", "cells",
                  "grid prim", "grid ms", "agree");
    out += line;
    for (const auto& r : rows) {
        const std::string agree = r.checked > 0
                                      ? std::to_string(r.agree) + "/" + std::to_string(r.checked)
                                      : std::string("-");
        std::snprintf(line, sizeof line,
                      "%8d %6d %9d %9.2f %8.2f %8.2f %6d %9.2f %8d %8.2f %9.2f %9.2f %11s\n", r.n,
                      r.rays, r.n, r.n > 0 ? std::log2(double(r.n)) : 0.0,
                      r.per_ray(r.bvh_box_tests), r.per_ray(r.bvh_primitive_tests), r.bvh_depth,
                      r.bvh_build_ms, r.grid_side, r.per_ray(r.grid_cells),
                      r.per_ray(r.grid_primitive_tests), r.grid_build_ms, agree.c_str());
        out += line;
    }
    return out;
}

}  // namespace cg::accel
