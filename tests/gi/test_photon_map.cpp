// Photon mapping: the k nearest photons from the kd-tree equal brute force's exactly (ties by
// index) on 3,000 random point sets with duplicates and coincident points; the tree is a valid
// median kd-tree; the estimate converges to the direct irradiance Φ / (4π h²) cos³θ on a lit
// black plane (long double closed form); power per photon Φ_L / n_L with an uneven split;
// specular paths land where geometry says (a mirror, a glass ball's axis), and they are caustic
// photons; Russian roulette keeps Σ stored = 1 / (1 − ρ) photons per emitted one between two
// planes; the caustic under the glass ball is brighter than the direct light; the stepped run
// equals compute() and its search equals brute force on 300 random scenes; errors name the
// field; replay; the exam problems; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "core/rng.hpp"
#include "gi/photon_map.hpp"
#include "io/exam.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::PhotonMap;
using glm::dvec3;
using Input = PhotonMap::Input;
using Photon = PhotonMap::Photon;

namespace {

using LD = long double;
constexpr LD kPiL = 3.141592653589793238462643383279502884L;

PhotonMap::Object plane(dvec3 p, dvec3 n, double albedo) {
    PhotonMap::Object o;
    o.shape = PhotonMap::Shape::Plane;
    o.center = p, o.normal = n, o.albedo = albedo;
    return o;
}
PhotonMap::Object ball(dvec3 c, double r, PhotonMap::Material m) {
    PhotonMap::Object o;
    o.shape = PhotonMap::Shape::Sphere;
    o.center = c, o.radius = r, o.material = m;
    return o;
}
PhotonMap::Light light(dvec3 p, double power) {
    PhotonMap::Light l;
    l.position = p, l.power = power;
    return l;
}
PhotonMap::Light spot(dvec3 p, double power, dvec3 dir, double cone) {
    PhotonMap::Light l = light(p, power);
    l.direction = dir, l.cone_deg = cone;
    return l;
}

// The reference k nearest: every (d², index) in long double, sorted. The algorithm's d² is a
// double; the comparison in long double must agree on which photons are nearest except where
// two double d² tie, so the reference uses the same double d² for ordering and checks it
// against long double.
std::vector<int> reference_nearest(const std::vector<Photon>& ph, dvec3 x, int k) {
    std::vector<std::pair<std::pair<double, int>, LD>> all;
    for (std::size_t i = 0; i < ph.size(); ++i) {
        const dvec3 p = ph[i].position;
        const double dx = x.x - p.x, dy = x.y - p.y, dz = x.z - p.z;
        const LD exact = LD(dx) * dx + LD(dy) * dy + LD(dz) * dz;
        all.push_back({{dx * dx + dy * dy + dz * dz, int(i)}, exact});
    }
    std::sort(all.begin(), all.end());
    std::vector<int> out;
    for (std::size_t i = 0; i < std::min(all.size(), std::size_t(k)); ++i) {
        CHECK(std::fabs(double(all[i].second) - all[i].first.first) <= 1e-15 * (1 + all[i].first.first));
        out.push_back(all[i].first.second);
    }
    return out;
}

// Random photons: clustered, on a grid (many equal coordinates and equal distances), or copies
// of a few points (coincident photons).
std::vector<Photon> random_photons(cg::Rng& rng, int n) {
    std::vector<Photon> ph(static_cast<std::size_t>(n));
    const int kind = int(rng.integer(0, 3));
    std::vector<dvec3> few;
    for (int i = 0; i < 4; ++i) few.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
    for (auto& p : ph) {
        if (kind == 0)
            p.position = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        else if (kind == 1)
            p.position = {double(rng.integer(-3, 3)), double(rng.integer(-3, 3)), double(rng.integer(-1, 1))};
        else if (kind == 2)
            p.position = few[std::size_t(rng.integer(0, 3))];
        else  // flat: every photon on the plane y = 0
            p.position = {rng.uniform(-1, 1), 0, rng.uniform(-1, 1)};
        p.power = 1;
    }
    return ph;
}

// The tree is a kd-tree: at every node, the photons left have (coordinate, index) below the
// median's and those right above it, on the node's axis; and the axis is its box's widest.
void check_tree(const std::vector<Photon>& ph, const std::vector<int>& order,
                const std::vector<std::uint8_t>& axis, int lo, int hi) {
    if (lo >= hi) return;
    const int m = (lo + hi) / 2, a = axis[std::size_t(m)], pm = order[std::size_t(m)];
    dvec3 blo = ph[std::size_t(order[std::size_t(lo)])].position, bhi = blo;
    for (int i = lo; i < hi; ++i) {
        blo = glm::min(blo, ph[std::size_t(order[std::size_t(i)])].position);
        bhi = glm::max(bhi, ph[std::size_t(order[std::size_t(i)])].position);
    }
    const dvec3 size = bhi - blo;
    for (int c = 0; c < 3; ++c) CHECK(size[a] >= size[c]);
    auto key = [&](int i) { return std::make_pair(ph[std::size_t(i)].position[a], i); };
    for (int i = lo; i < m; ++i) CHECK(key(order[std::size_t(i)]) < key(pm));
    for (int i = m + 1; i < hi; ++i) CHECK(key(pm) < key(order[std::size_t(i)]));
    check_tree(ph, order, axis, lo, m);
    check_tree(ph, order, axis, m + 1, hi);
}

Input lit_plane(int photons, int k, dvec3 query, std::uint64_t seed) {
    Input in;
    in.objects = {plane({0, 0, 0}, {0, 1, 0}, 0)};
    in.lights = {light({0, 1, 0}, 100)};
    in.photons = photons, in.k = k, in.query = query, in.seed = seed;
    return in;
}

// E = Φ / (4π) cos θ / d² at x on the floor, the light at height 1: cos θ = 1/d.
LD direct_on_floor(LD power, dvec3 x) {
    const LD d2 = LD(x.x) * x.x + LD(x.z) * x.z + 1;
    return power / (4 * kPiL) / (d2 * std::sqrt(d2));
}

// The mean of E over the disc of radius r about x on the floor (the light at (0, 1, 0)), in long
// double: a polar midpoint rule, 400 × 400 cells.
LD disc_mean_on_floor(LD power, dvec3 x, double r) {
    if (!(r > 0)) return 0;
    const int n = 400;
    LD sum = 0, area = 0;
    for (int i = 0; i < n; ++i) {
        const LD rho = (i + 0.5L) * r / n;
        for (int j = 0; j < n; ++j) {
            const LD phi = (j + 0.5L) * 2 * kPiL / n;
            const dvec3 p{double(x.x + rho * std::cos(phi)), 0, double(x.z + rho * std::sin(phi))};
            const LD w = rho;  // the polar area element's ρ
            sum += w * direct_on_floor(power, p);
            area += w;
        }
    }
    return sum / area;
}

Input random_scene(cg::Rng& rng) {
    Input in;
    in.objects.push_back(plane({0, 0, 0}, {0, 1, 0}, rng.uniform(0, 1)));
    if (rng.chance(0.5)) in.objects.push_back(plane({0, 3, 0}, {0, -1, 0}, rng.uniform(0, 0.9)));
    if (rng.chance(0.5)) in.objects.push_back(plane({2, 0, 0}, {-1, 0, 0}, 0.5));
    const int balls = int(rng.integer(0, 3));
    for (int i = 0; i < balls; ++i) {
        const auto m = static_cast<PhotonMap::Material>(rng.integer(0, 2));
        auto b = ball({rng.uniform(-1.5, 1.5), rng.uniform(0.5, 2), rng.uniform(-1.5, 1.5)},
                      rng.uniform(0.2, 0.6), m);
        b.albedo = rng.uniform(0, 1), b.ior = rng.uniform(1, 2.5);
        in.objects.push_back(b);
    }
    const int lights = int(rng.integer(1, 3));
    for (int i = 0; i < lights; ++i)
        in.lights.push_back(rng.chance(0.5)
                                ? light({rng.uniform(-1, 1), 2.5, rng.uniform(-1, 1)}, rng.uniform(1, 100))
                                : spot({rng.uniform(-1, 1), 2.5, rng.uniform(-1, 1)}, rng.uniform(1, 100),
                                       {0, -1, 0}, rng.uniform(5, 90)));
    in.photons = int(rng.integer(1, 400));
    in.max_bounces = int(rng.integer(1, 10));
    in.seed = rng.next();
    in.k = int(rng.integer(1, 60));
    in.query = rng.chance(0.7) ? dvec3(rng.uniform(-1, 1), 0, rng.uniform(-1, 1))
                               : dvec3(rng.uniform(-2, 2), rng.uniform(0, 3), rng.uniform(-2, 2));
    return in;
}

}  // namespace

TEST_CASE("photon-map: the kd-tree's k nearest equal brute force on 3,000 random point sets",
          "[photon-map]") {
    cg::Rng rng(2026);
    int ties = 0;
    for (int t = 0; t < 3000; ++t) {
        CAPTURE(t);
        const auto ph = random_photons(rng, int(rng.integer(1, t < 2900 ? 120 : 3000)));
        std::vector<int> order;
        std::vector<std::uint8_t> axis;
        PhotonMap::build_tree(ph, order, axis);
        std::vector<int> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t i = 0; i < sorted.size(); ++i) REQUIRE(sorted[i] == int(i));  // a permutation
        if (t % 10 == 0) check_tree(ph, order, axis, 0, int(ph.size()));
        for (int q = 0; q < 5; ++q) {
            // Query points: random, a photon itself, or on the grid.
            dvec3 x{rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)};
            if (q == 1) x = ph[std::size_t(rng.integer(0, int(ph.size()) - 1))].position;
            if (q == 2) x = {double(rng.integer(-3, 3)), 0, double(rng.integer(-1, 1))};
            const int k = int(rng.integer(1, int(ph.size()) + 2));
            int visited = 0, pruned = 0;
            const auto near = PhotonMap::nearest(ph, order, axis, x, k, &visited, &pruned);
            std::vector<int> got;
            for (const auto& n : near) got.push_back(n.photon);
            const auto want = reference_nearest(ph, x, k);
            REQUIRE(got == want);
            CHECK(got == PhotonMap::nearest_brute_force(ph, x, k));
            CHECK(visited <= int(ph.size()));
            if (near.size() > 1 && near[near.size() - 1].d2 == near[near.size() - 2].d2) ++ties;
        }
    }
    CHECK(ties > 100);  // the sets do exercise the tie-break by index
}

TEST_CASE("photon-map: the search prunes — a big set visits far fewer nodes than it holds",
          "[photon-map]") {
    cg::Rng rng(5);
    std::vector<Photon> ph(20000);
    for (auto& p : ph) p.position = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    std::vector<int> order;
    std::vector<std::uint8_t> axis;
    const int depth = PhotonMap::build_tree(ph, order, axis);
    CHECK(depth == 15);  // ⌈log₂(20001)⌉: balanced
    int visited = 0, pruned = 0;
    PhotonMap::nearest(ph, order, axis, {0.1, 0.2, 0.3}, 10, &visited, &pruned);
    CHECK(visited < 400);
    CHECK(pruned > 10);
}

TEST_CASE("photon-map: the estimate converges to the direct irradiance on a lit plane",
          "[photon-map]") {
    // Φ = 100 at height 1 over a black floor: E(x) = Φ/(4π) · cos θ / d². With k ∝ √N the disc
    // shrinks (bias ≈ 0.75 r² at the centre) and the noise 1/√k falls: averaged over 8 seeds each
    // level's error stays inside its bias plus 4 standard errors; at 200,000 photons, within 3%.
    // Against the exact mean of E over the run's own disc of radius r, the estimate has no
    // smoothing bias at all: within 4 standard errors at every level and point.
    const std::vector<dvec3> points{{0, 0, 0}, {0.5, 0, 0}, {-0.3, 0, 0.8}};
    const int seeds = 8;
    for (const auto& [photons, k] : std::vector<std::pair<int, int>>{{2000, 45}, {20000, 141}, {200000, 447}}) {
        const double sigma = 1 / std::sqrt(double(k) * seeds);
        for (const dvec3& x : points) {
            double sum = 0, disc = 0, r2 = 0;
            for (int s = 1; s <= seeds; ++s) {
                const auto r = PhotonMap::compute(lit_plane(photons, k, x, std::uint64_t(s)));
                CHECK(r.caustic == 0);
                CHECK(r.absorbed == int(r.photons.size()));
                sum += r.irradiance;
                disc += double(disc_mean_on_floor(100, x, r.radius));
                r2 += r.radius * r.radius;
                CHECK(r.direct_irradiance == Approx(double(direct_on_floor(100, x))).epsilon(1e-12));
            }
            const double want = double(direct_on_floor(100, x));
            const double err = std::fabs(sum / seeds - want) / want;
            CAPTURE(photons, k, x.x, x.z, err, r2 / seeds);
            CHECK(err < 0.75 * r2 / seeds + 4 * sigma);
            CHECK(std::fabs(sum - disc) / disc < 4 * sigma);
            if (photons == 200000) CHECK(err < 0.03);  // these seeds: 0.6 to 1.9% (2,000 photons: 7 to 10%)
        }
    }
}

TEST_CASE("photon-map: power per photon is the light's power over its photon count",
          "[photon-map]") {
    Input in = lit_plane(7, 3, {0, 0, 0}, 1);
    in.lights = {light({0, 1, 0}, 90), light({1, 1, 0}, 40), light({-1, 2, 0}, 10)};
    const auto r = PhotonMap::compute(in);
    CHECK(r.emitted == std::vector<int>{3, 2, 2});
    REQUIRE(r.power_per_photon.size() == 3);
    CHECK(r.power_per_photon[0] == 30);
    CHECK(r.power_per_photon[1] == 20);
    CHECK(r.power_per_photon[2] == 5);
    for (const auto& p : r.photons) CHECK(p.power == r.power_per_photon[std::size_t(p.light)]);
    // Every photon is stored, escapes, or is cut off: nothing lost in the count.
    CHECK(r.escaped + r.absorbed + r.limited == 7);
}

TEST_CASE("photon-map: a mirror sends the photons where the law of reflection says",
          "[photon-map]") {
    // A thin spot from (0, 1, 0) along (1, −0.5, 0) meets the mirror x = 1 at (1, 0.5, 0) and
    // is reflected along (−1, −0.5, 0) to the floor at (0, 0, 0).
    Input in;
    in.objects = {plane({0, 0, 0}, {0, 1, 0}, 0)};
    PhotonMap::Object mirror = plane({1, 0, 0}, {-1, 0, 0}, 0);
    mirror.material = PhotonMap::Material::Mirror;
    in.objects.push_back(mirror);
    in.lights = {spot({0, 1, 0}, 10, {1, -0.5, 0}, 0.001)};
    in.photons = 50, in.k = 5, in.query = {0, 0, 0};
    const auto r = PhotonMap::compute(in);
    REQUIRE(r.photons.size() == 50);
    CHECK(r.caustic == 50);
    for (const auto& p : r.photons) {
        CHECK(glm::length(p.position) < 1e-4);
        CHECK(glm::length(p.direction - glm::normalize(dvec3(-1, -0.5, 0))) < 1e-4);
    }
    // The light cannot see x directly past... it can: the direct term is the spot's, x is
    // outside its 0.001° cone.
    CHECK(r.direct_irradiance == 0);
}

TEST_CASE("photon-map: glass refracts by Snell's law — through the centre undeflected, "
          "off-centre bent toward the axis",
          "[photon-map]") {
    Input in;
    in.objects = {plane({0, 0, 0}, {0, 1, 0}, 0), ball({0, 2, 0}, 1, PhotonMap::Material::Glass)};
    in.lights = {spot({0, 5, 0}, 1, {0, -1, 0}, 1e-4)};
    in.photons = 20, in.k = 1;
    auto r = PhotonMap::compute(in);
    REQUIRE(r.photons.size() == 20);
    for (const auto& p : r.photons) CHECK(glm::length(p.position) < 1e-4);
    CHECK(r.caustic == 20);
    // A ray parallel to the axis at offset b = 0.5 (the light far away and aimed at (0.5, 2, 0)):
    // the exact exit point and direction, by Snell's law twice in long double.
    in.lights = {spot({0.5, 12, 0}, 1, {0, -1, 0}, 1e-4)};
    r = PhotonMap::compute(in);
    REQUIRE(!r.photons.empty());
    const LD n = 1.5L, b = 0.5L;
    const LD th1 = std::asin(b), th2 = std::asin(b / n);
    // Inside, the chord turns the ray by th1 − th2 toward the axis; at the exit it turns again.
    const LD deviation = 2 * (th1 - th2);
    // The exit point: rotate the entry point (sin th1, cos th1) about the centre by π − 2 th2.
    const LD phi = kPiL - 2 * th2;
    const LD ex = b * std::cos(phi) + std::cos(th1) * std::sin(phi);
    const LD ey = -b * std::sin(phi) + std::cos(th1) * std::cos(phi);
    const LD dx = -std::sin(deviation), dy = -std::cos(deviation);
    const LD t = -(2 + ey) / dy;  // down to y = 0 from (ex, 2 + ey)
    const LD landing = ex + t * dx;
    for (const auto& p : r.photons) CHECK(p.position.x == Approx(double(landing)).margin(1e-3));
}

TEST_CASE("photon-map: Russian roulette keeps on average 1 / (1 − ρ) stored photons per photon "
          "between two planes",
          "[photon-map]") {
    for (double rho : {0.0, 0.25, 0.5, 0.8}) {
        CAPTURE(rho);
        Input in;
        in.objects = {plane({0, 0, 0}, {0, 1, 0}, rho), plane({0, 1, 0}, {0, -1, 0}, rho)};
        in.lights = {light({0, 0.5, 0}, 1)};
        in.photons = 20000, in.max_bounces = 64, in.k = 1;
        const auto r = PhotonMap::compute(in);
        const double mean = double(r.photons.size()) / in.photons;
        // Geometric: mean 1/(1 − ρ), variance ρ/(1 − ρ)²; 5 standard errors.
        const double sd = std::sqrt(rho) / (1 - rho) / std::sqrt(double(in.photons));
        CHECK(std::fabs(mean - 1 / (1 - rho)) < 5 * sd + 1e-3);
        CHECK(r.absorbed + r.escaped + r.limited == in.photons);
        CHECK(r.escaped < in.photons / 100);  // grazing photons only
    }
}

TEST_CASE("photon-map: the showcase caustic under the glass ball is brighter than the direct light",
          "[photon-map]") {
    const cg::json ex = cg::test::algorithm("photon-map").example();
    Input in = cg::test::input_of<PhotonMap>("photon-map", ex);
    in.photons = 20000, in.k = 100;
    const auto under = PhotonMap::compute(in);
    CHECK(under.caustic > 1000);
    CHECK(under.direct_irradiance == 0);  // the ball blocks the shadow ray
    // Without the ball, the spot's direct light at x.
    Input bare = in;
    bare.objects.pop_back();
    const auto lit = PhotonMap::compute(bare);
    CHECK(lit.direct_irradiance == Approx(100 / (2 * 3.141592653589793 * (1 - std::cos(20 * 3.141592653589793 / 180))) / 16));
    CHECK(lit.irradiance == Approx(lit.direct_irradiance).epsilon(0.1));
    CHECK(under.irradiance > 2 * lit.irradiance);  // the ball focuses the light
}

TEST_CASE("photon-map: the stepped run equals compute and its search equals brute force on 300 random scenes",
          "[photon-map]") {
    cg::Rng rng(77);
    for (int t = 0; t < 300; ++t) {
        CAPTURE(t);
        const Input in = random_scene(rng);
        const auto r = PhotonMap::compute(in);
        const auto traced = cg::test::run_traced<PhotonMap>(in);
        REQUIRE(traced.result == r);
        CHECK(cg::run_to_end<PhotonMap>(PhotonMap::start(in)) == r);
        CHECK(r.neighbours == PhotonMap::nearest_brute_force(r.photons, in.query, in.k));
        check_tree(r.photons, r.order, r.axis, 0, int(r.photons.size()));
        CHECK(std::isfinite(r.irradiance));
        double sum = 0;
        for (int p : r.neighbours) sum += r.photons[std::size_t(p)].power;
        CHECK(r.sum_power == Approx(sum));
        if (!r.degenerate)
            CHECK(r.irradiance == Approx(sum / (3.141592653589793 * r.radius * r.radius)));
        // The steps: one per photon up to 20, batches after; one per node; the search's visits.
        int photons = 0, batches = 0, nodes = 0, visits = 0, prunes = 0;
        for (const auto& s : traced.steps) {
            photons += s.event == "photon", batches += s.event == "photon-batch";
            nodes += s.event == "build-node", visits += s.event == "visit", prunes += s.event == "prune";
        }
        CHECK(photons == std::min(in.photons, 20));
        CHECK(batches <= PhotonMap::kBatches);
        CHECK(nodes == int(r.photons.size()));
        CHECK(visits == r.visited);
        CHECK(prunes == r.pruned);
        CHECK(traced.steps.back().event == "estimate");
    }
}

TEST_CASE("photon-map: degenerate scenes — nothing stored, k above the photons stored",
          "[photon-map]") {
    Input in = lit_plane(10, 5, {0, 0, 0}, 1);
    in.lights = {spot({0, 1, 0}, 1, {0, 1, 0}, 30)};  // pointing away from the floor
    auto r = PhotonMap::compute(in);
    CHECK(r.photons.empty());
    CHECK(r.degenerate);
    CHECK(r.irradiance == 0);
    CHECK(r.escaped == 10);
    CHECK(cg::test::run_traced<PhotonMap>(in).result == r);
    in = lit_plane(10, 500, {0, 0, 0}, 1);
    r = PhotonMap::compute(in);
    CHECK(r.neighbours.size() == r.photons.size());
    CHECK_FALSE(r.degenerate);
}

TEST_CASE("photon-map: bad input names the field", "[photon-map]") {
    auto err = [](const Input& in) {
        try {
            PhotonMap::start(in);
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    const Input good = lit_plane(10, 3, {0, 0, 0}, 1);
    CHECK(err(good) == "(accepted)");
    Input in = good;
    in.objects.clear();
    CHECK_THAT(err(in), Catch::StartsWith("objects: must have at least 1 object"));
    in = good;
    in.objects[0].normal = {0, 0, 0};
    CHECK_THAT(err(in), Catch::StartsWith("objects[0].normal: must not be the zero vector"));
    in = good;
    in.objects.push_back(ball({0, 1, 0}, 0, PhotonMap::Material::Glass));
    CHECK_THAT(err(in), Catch::StartsWith("objects[1].radius: must be 1e-6 to 1e6"));
    in = good;
    in.lights[0].power = 0;
    CHECK_THAT(err(in), Catch::StartsWith("lights[0].power: must be > 0"));
    in = good;
    in.lights[0].cone_deg = 0;
    CHECK_THAT(err(in), Catch::StartsWith("lights[0].cone_deg"));
    in = good;
    in.lights[0].position = {0, 1e7, 0};
    CHECK_THAT(err(in), Catch::StartsWith("lights[0].position[1]: must be within ±1e6"));
    CHECK_THAT(cg::test::error_of("photon-map", R"({"objects": [{"type": "cube"}], "lights": []})"),
               Catch::StartsWith("objects[0].material: is missing"));
    CHECK_THAT(cg::test::error_of("photon-map",
                                  R"({"objects": [{"type": "cube", "material": "glass"}], "lights": []})"),
               Catch::StartsWith("objects[0].type: must be \"sphere\" or \"plane\""));
    CHECK_THAT(cg::test::error_of("photon-map", R"({"objects": [{"type": "plane", "point": [0,0,0],
                  "normal": [0,1,0], "material": "mirror", "albedo": 0.5}], "lights": []})"),
               Catch::StartsWith("objects[0].albedo: is not a known field"));
    CHECK_THAT(cg::test::error_of("photon-map", R"({"objects": [{"type": "plane", "point": [0,0,0],
                  "normal": [0,1,0], "material": "diffuse"}], "lights": [], "photons": 0,
                  "query": [0,0,0], "k": 1})"),
               Catch::StartsWith("photons: must be 1 to 1000000"));
}

TEST_CASE("photon-map: replay on the example, the same trace twice, the events all happen",
          "[photon-map]") {
    const cg::Algorithm& a = cg::test::algorithm("photon-map");
    cg::test::check_replay(a, a.example(), 50);
    const Input in = cg::test::input_of<PhotonMap>("photon-map", a.example());
    const auto t = cg::test::run_traced<PhotonMap>(in);
    std::set<std::string> seen;
    for (const auto& e : cg::test::events(t)) seen.insert(e);
    for (const auto& e : PhotonMap::spec().events) {
        CAPTURE(e.id);
        CHECK(seen.count(e.id));
    }
    CHECK(t.result.caustic > 0);
}

TEST_CASE("photon-map: exam problems — the estimate from k photons and the direct irradiance",
          "[photon-map]") {
    const cg::Algorithm& a = cg::test::algorithm("photon-map");
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = cg::test::input_of<PhotonMap>("photon-map", p.input);
        const LD power = in.lights[0].power, h = in.lights[0].position.y;
        CHECK(p.expected["direct_irradiance"].get<double>() ==
              Approx(double(power / (4 * kPiL * h * h))).epsilon(1e-12));
        // From the question's own numbers: k photons of Φ/N each within the largest distance.
        const auto r = PhotonMap::compute(in);
        REQUIRE(r.distances.size() == 4);
        const LD phi_p = power / in.photons, rr = r.distances.back();
        CHECK(p.expected["sum_power"].get<double>() == Approx(double(4 * phi_p)).epsilon(1e-12));
        CHECK(p.expected["irradiance"].get<double>() ==
              Approx(double(4 * phi_p / (kPiL * rr * rr))).epsilon(1e-12));
        CHECK(p.question.find(std::to_string(in.photons) + " photons") != std::string::npos);
    }
}

TEST_CASE("photon-map: the picture — photons by power, the path, the splitting plane, the query sphere",
          "[photon-map]") {
    const Input in = cg::test::input_of<PhotonMap>("photon-map", cg::test::algorithm("photon-map").example());
    auto s = PhotonMap::start(in);
    PhotonMap::step(s, nullptr);
    cg::Scene first;
    PhotonMap::draw(s, first);
    CHECK(first.has_3d());
    CHECK(first.faces3.size() == 1);  // the floor
    CHECK(!first.segments3.empty());  // the ball's circles and the path
    while (s.phase == PhotonMap::Phase::Emit) PhotonMap::step(s, nullptr);
    PhotonMap::step(s, nullptr);  // the root node
    cg::Scene node;
    PhotonMap::draw(s, node);
    CHECK(node.faces3.size() == 2);  // the floor and the splitting plane
    std::size_t stored = 0;
    for (const auto& p : node.points3) stored += p.label.empty();
    CHECK(stored == s.photons.size());
    while (!PhotonMap::done(s)) PhotonMap::step(s, nullptr);
    cg::Scene last;
    PhotonMap::draw(s, last);
    std::size_t kept = 0;
    for (const auto& p : last.points3) kept += p.style.role == cg::Role::Kept;
    CHECK(kept == std::size_t(in.k));
    // The camera frames the query's neighbourhood with the light: both inside the focus.
    REQUIRE(last.focus3.size() == 1);
    const auto& f = last.focus3[0];
    for (const glm::dvec3& p : {in.query, in.lights[0].position})
        CHECK((p.x >= f.lo.x && p.y >= f.lo.y && p.z >= f.lo.z && p.x <= f.hi.x &&
               p.y <= f.hi.y && p.z <= f.hi.z));
}
