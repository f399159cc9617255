// The complexity lab for the acceleration structures (`cgsandbox complexity accel`): on random
// scenes of 10 to 10⁴ primitives, every ray's nearest hit through the BVH and through the grid
// equals brute force's (t and primitive exactly); brute force makes n tests; the BVH's and the
// grid's tests per ray stay far below n and grow slowly.
#include <catch2/catch.hpp>
#include <cmath>

#include "accel/complexity.hpp"

using namespace cg::accel;

TEST_CASE("complexity accel: BVH and grid hits equal brute force on every ray",
          "[accel][complexity]") {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const auto rows = complexity({10, 100, 1000, 10000}, seed == 1 ? 400 : 150, seed, 10000);
        REQUIRE(rows.size() == 4);
        for (const auto& r : rows) {
            INFO("seed " << seed << ", n " << r.n);
            CHECK(r.checked == r.rays);
            CHECK(r.agree == r.checked);
            CHECK(r.hits > 0);  // the rays do meet the scene
            CHECK(r.grid_side == static_cast<int>(std::lround(std::cbrt(r.n))));
        }
    }
}

TEST_CASE("complexity accel: one ray by hand — counts and the hit", "[accel][complexity]") {
    // Two spheres on the x axis: the ray from x = −1 meets the first at t = 0.5.
    std::vector<cg::Primitive> prims(2);
    prims[0].a = {0, 0, 0}, prims[0].radius = 0.5;
    prims[1].a = {3, 0, 0}, prims[1].radius = 0.5;
    const Ray ray{{-1, 0, 0}, {1, 0, 0}};
    const CountedHit f = brute_nearest(prims, ray);
    CHECK(f.primitive == 0);
    CHECK(f.t == 0.5);
    CHECK(f.primitive_tests == 2);
    CHECK(f.box_tests == 0);
    std::vector<cg::Bounds> boxes{cg::bounds(prims[0]), cg::bounds(prims[1])};
    const auto bvh = cg::rt::build_bvh(boxes);
    const CountedHit b = bvh_nearest(bvh, prims, ray);
    CHECK(b.primitive == 0);
    CHECK(b.t == 0.5);
    CHECK(b.box_tests >= 1);
    CHECK(b.primitive_tests <= 2);
    // A ray that misses the root's box: one box test, no primitive test.
    const CountedHit m = bvh_nearest(bvh, prims, Ray{{-1, 5, 0}, {1, 0, 0}});
    CHECK(m.primitive == -1);
    CHECK(m.box_tests == 1);
    CHECK(m.primitive_tests == 0);
}

TEST_CASE("complexity accel: the counts grow as the course says", "[accel][complexity]") {
    // Brute force checked only up to n = 10⁴: at 10⁵ the structures alone.
    const auto rows = complexity({10, 100, 1000, 10000, 100000}, 200, 7, 1000);
    REQUIRE(rows.size() == 5);
    for (const auto& r : rows) {
        INFO("n " << r.n << ": bvh prim " << r.per_ray(r.bvh_primitive_tests) << ", box "
                  << r.per_ray(r.bvh_box_tests) << "; grid prim "
                  << r.per_ray(r.grid_primitive_tests) << ", cells " << r.per_ray(r.grid_cells));
        CHECK(r.per_ray(r.bvh_primitive_tests) <= r.n);
        CHECK(r.per_ray(r.grid_primitive_tests) <= r.n);
        CHECK((r.n > 1000 || r.agree == r.checked));
    }
    const auto& big = rows.back();
    CHECK(big.n == 100000);
    // Less than 1% of brute force's n tests per ray.
    CHECK(big.per_ray(big.bvh_primitive_tests) < 0.01 * big.n);
    CHECK(big.per_ray(big.bvh_box_tests) < 0.01 * big.n);
    CHECK(big.per_ray(big.grid_primitive_tests) < 0.01 * big.n);
    CHECK(big.per_ray(big.grid_cells) < 0.01 * big.n);
    // 10³ times the primitives (n = 100 → 10⁵): the BVH's tests per ray grow a few times, like
    // log n, not 10³ times; so do the grid's cells (fewer than ∛(10³) = 10 times more: at this
    // density most rays stop at a hit long before they cross the grid).
    const auto& small = rows[1];
    CHECK(small.n == 100);
    CHECK(big.per_ray(big.bvh_box_tests) < 10 * small.per_ray(small.bvh_box_tests));
    CHECK(big.per_ray(big.bvh_primitive_tests) < 10 * small.per_ray(small.bvh_primitive_tests));
    CHECK(big.per_ray(big.grid_cells) < 10 * small.per_ray(small.grid_cells));
    CHECK(big.per_ray(big.grid_primitive_tests) < 10 * small.per_ray(small.grid_primitive_tests));
    // The table names what it measures.
    const std::string table = complexity_table(rows);
    CHECK_THAT(table, Catch::Contains("brute force: n tests"));
    CHECK_THAT(table, Catch::Contains("100000"));
}

TEST_CASE("complexity accel: brute force makes n tests, and the scene is seeded",
          "[accel][complexity]") {
    cg::Rng a(5), b(5);
    const auto s1 = random_scene(a, 500), s2 = random_scene(b, 500);
    CHECK(s1 == s2);
    const auto rays = random_rays(a, 20);
    for (const Ray& r : rays) CHECK(brute_nearest(s1, r).primitive_tests == 500);
}
