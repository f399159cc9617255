// Fractal terrain: an independent reference in long double — the triangle refined as a list of
// triangles (each split into four through its edges' midpoints, a shared edge's midpoint found
// in a map by its two ends), the grid by its own diamond and square sets, the new points of a
// level sorted row by row to draw the generator's numbers in the documented order — against
// compute and the state machine on 2,000 random inputs; bit-for-bit reproducibility, a
// different seed differing; crack-free meshes (every interior edge in exactly two triangles,
// no two vertices at one place); amplitude 0 giving the plane exactly (dyadic heights); every
// offset within its level's amplitude, measured against long-double averages, and the offsets
// filling that range; the closed-form counts per level; rays/mesh_gen's terrain the same
// heights as its former loop; the steps (point by point, then batched); bad input; the exam;
// replay; the picture.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>

#include "core/format.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "modelling/fractal_terrain.hpp"
#include "rays/mesh_gen.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::FractalTerrain;
using Input = FractalTerrain::Input;
using Method = FractalTerrain::Method;
using LD = long double;

namespace {

using IJ = std::pair<int, int>;  // (i, j) on the lattice of side N

Input triangle(std::array<glm::dvec3, 3> t, int levels, double amplitude, double roughness,
               std::uint64_t seed) {
    Input in;
    in.method = Method::Triangle;
    in.triangle = t;
    in.levels = levels;
    in.amplitude = amplitude;
    in.roughness = roughness;
    in.seed = seed;
    return in;
}

Input grid(std::array<double, 4> corners, int levels, double amplitude, double roughness,
           std::uint64_t seed, double size = 2) {
    Input in;
    in.method = Method::Grid;
    in.corners = corners;
    in.size = size;
    in.levels = levels;
    in.amplitude = amplitude;
    in.roughness = roughness;
    in.seed = seed;
    return in;
}

Input random_input(cg::Rng& rng) {
    const int levels = int(rng.integer(0, 6));
    const double amplitude = rng.chance(0.1) ? 0.0 : rng.uniform(0, 5);
    const double roughness = rng.chance(0.1) ? double(rng.integer(0, 4)) : rng.uniform(0, 4);
    const auto seed = std::uint64_t(rng.integer(0, 1LL << 40));
    if (rng.chance(0.5)) {
        std::array<glm::dvec3, 3> t;
        do {
            for (auto& p : t) p = {rng.uniform(-10, 10), rng.uniform(-3, 3), rng.uniform(-10, 10)};
        } while (cg::mesh::degenerate({t[0].x, 0, t[0].z}, {t[1].x, 0, t[1].z},
                                      {t[2].x, 0, t[2].z}));
        return triangle(t, levels, amplitude, roughness, seed);
    }
    return grid({rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3)},
                levels, amplitude, roughness, seed, rng.uniform(0.5, 20));
}

// The reference: heights by (i, j), in long double; the new points of each level with their
// ends (or neighbours), and the amplitude schedule.
struct Reference {
    int N = 1;
    std::map<IJ, LD> h;
    std::vector<LD> amplitude;                      // per level
    std::vector<std::vector<std::pair<IJ, std::vector<IJ>>>> added;  // per level: point, neighbours
};

// The triangle as a list of triangles of lattice points, split level by level; a midpoint is
// the edge's, looked up by its two ends (sorted), so the two triangles on an edge share it.
Reference reference(const Input& in) {
    Reference r;
    r.N = 1 << in.levels;
    const int N = r.N;
    const LD factor = std::pow(2.0L, -LD(in.roughness));
    for (int L = 1; L <= in.levels; ++L)
        r.amplitude.push_back(LD(in.amplitude) * std::pow(factor, LD(L - 1)));
    std::vector<std::vector<IJ>> order(std::size_t(in.levels));
    if (in.method == Method::Triangle) {
        r.h[{0, 0}] = in.triangle[0].y;
        r.h[{N, 0}] = in.triangle[1].y;
        r.h[{0, N}] = in.triangle[2].y;
        std::vector<std::array<IJ, 3>> tris = {{IJ{0, 0}, IJ{N, 0}, IJ{0, N}}};
        r.added.resize(std::size_t(in.levels));
        for (int L = 1; L <= in.levels; ++L) {
            std::map<std::pair<IJ, IJ>, IJ> edges;  // sorted ends → midpoint
            std::map<IJ, std::vector<IJ>> ends;
            std::vector<std::array<IJ, 3>> next;
            for (const auto& t : tris) {
                IJ m[3];
                for (int e = 0; e < 3; ++e) {
                    IJ p = t[e], q = t[(e + 1) % 3];
                    if (q < p) std::swap(p, q);
                    const IJ mid{(p.first + q.first) / 2, (p.second + q.second) / 2};
                    const auto [it, fresh] = edges.emplace(std::make_pair(p, q), mid);
                    m[e] = it->second;
                    if (fresh) {
                        REQUIRE(ends.count(mid) == 0);  // one edge per midpoint
                        ends[mid] = {p, q};
                    }
                }
                next.push_back({t[0], m[0], m[2]});
                next.push_back({m[0], t[1], m[1]});
                next.push_back({m[2], m[1], t[2]});
                next.push_back({m[0], m[1], m[2]});
            }
            tris = std::move(next);
            // Row by row: (j, i) ascending.
            std::vector<IJ> pts;
            for (const auto& [p, e] : ends) pts.push_back(p);
            std::sort(pts.begin(), pts.end(), [](IJ a, IJ b) {
                return std::tie(a.second, a.first) < std::tie(b.second, b.first);
            });
            for (const IJ& p : pts) r.added[L - 1].push_back({p, ends[p]});
        }
    } else {
        r.h[{0, 0}] = in.corners[0];
        r.h[{N, 0}] = in.corners[1];
        r.h[{0, N}] = in.corners[2];
        r.h[{N, N}] = in.corners[3];
        r.added.resize(std::size_t(in.levels));
        for (int L = 1; L <= in.levels; ++L) {
            const int s = N >> (L - 1), h = s / 2;
            std::vector<std::pair<IJ, std::vector<IJ>>> diamonds, squares;
            for (int j = 0; j <= N; j += h)
                for (int i = 0; i <= N; i += h) {
                    if (i % s == 0 && j % s == 0) continue;
                    if (i % s != 0 && j % s != 0) {
                        diamonds.push_back(
                            {{i, j}, {{i - h, j - h}, {i + h, j - h}, {i - h, j + h}, {i + h, j + h}}});
                    } else {
                        std::vector<IJ> nb;
                        for (IJ q : {IJ{i - h, j}, IJ{i + h, j}, IJ{i, j - h}, IJ{i, j + h}})
                            if (q.first >= 0 && q.first <= N && q.second >= 0 && q.second <= N)
                                nb.push_back(q);
                        squares.push_back({{i, j}, nb});
                    }
                }
            r.added[L - 1] = diamonds;
            r.added[L - 1].insert(r.added[L - 1].end(), squares.begin(), squares.end());
        }
    }
    // The heights, drawing the generator's numbers in that order.
    cg::Rng rng(in.seed);
    for (int L = 1; L <= in.levels; ++L) {
        // The amplitude as the algorithm's doubles multiply it (the draw depends on its bits).
        double a = in.amplitude;
        for (int k = 1; k < L; ++k) a *= std::exp2(-in.roughness);
        for (const auto& [p, nb] : r.added[L - 1]) {
            LD sum = 0;
            for (const IJ& q : nb) sum += r.h.at(q);
            r.h[p] = sum / LD(nb.size()) + LD(rng.uniform(-a, a));
        }
    }
    return r;
}

// The result's vertices by (i, j), in lattice order.
std::map<IJ, glm::dvec3> by_lattice(const Input& in, const FractalTerrain::Result& res) {
    const int N = 1 << in.levels;
    std::map<IJ, glm::dvec3> out;
    std::size_t k = 0;
    for (int j = 0; j <= N; ++j)
        for (int i = 0; in.method == Method::Grid ? i <= N : i + j <= N; ++i)
            out[{i, j}] = res.vertices.at(k++);
    REQUIRE(k == res.vertices.size());
    return out;
}


const cg::Lesson& lesson() {
    static const cg::Lesson l = [] {
        const auto lessons =
            cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
        for (const auto& x : lessons.lessons)
            if (x.algorithm == "fractal-terrain") return x;
        FAIL("no fractal-terrain lesson");
        return cg::Lesson{};
    }();
    return l;
}

}  // namespace

TEST_CASE("fractal-terrain: the course's triangle refined once, by hand",
          "[modelling][fractal-terrain]") {
    // A = (0, 2, 0), B = (4, 6, 0), C = (0, 4, 4), amplitude 1, seed 5.
    const Input in = triangle({glm::dvec3(0, 2, 0), glm::dvec3(4, 6, 0), glm::dvec3(0, 4, 4)}, 1,
                              1, 1, 5);
    cg::Rng rng(5);
    const double r_ab = rng.uniform(-1, 1), r_ac = rng.uniform(-1, 1), r_bc = rng.uniform(-1, 1);
    const auto res = FractalTerrain::compute(in);
    REQUIRE(res.vertices.size() == 6);
    // Order: A, mid AB, B, mid AC, mid BC, C.
    CHECK(res.vertices[0] == glm::dvec3(0, 2, 0));
    CHECK(res.vertices[1] == glm::dvec3(2, 4 + r_ab, 0));
    CHECK(res.vertices[2] == glm::dvec3(4, 6, 0));
    CHECK(res.vertices[3] == glm::dvec3(0, 3 + r_ac, 2));
    CHECK(res.vertices[4] == glm::dvec3(2, 5 + r_bc, 2));
    CHECK(res.vertices[5] == glm::dvec3(0, 4, 4));
    CHECK(res.triangle_count == 4);
    CHECK(res.amplitudes == std::vector<double>{1});
    CHECK(res.largest_offsets ==
          std::vector<double>{std::max({std::fabs(r_ab), std::fabs(r_ac), std::fabs(r_bc)})});

    // One diamond–square level on corners 1, 3, 5, 7: the centre averages four, each edge
    // midpoint three (its edge's corners and the centre).
    const Input g = grid({1, 3, 5, 7}, 1, 2, 1, 11, 4);
    cg::Rng q(11);
    const double rc = q.uniform(-2, 2), rf = q.uniform(-2, 2), rl = q.uniform(-2, 2),
                 rr = q.uniform(-2, 2), rb = q.uniform(-2, 2);
    const auto gr = FractalTerrain::compute(g);
    const double c = 4 + rc;
    const std::vector<double> want = {1, (1 + 3 + c) / 3 + rf, 3, (1 + 5 + c) / 3 + rl, c,
                                      (3 + 7 + c) / 3 + rr, 5, (5 + 7 + c) / 3 + rb, 7};
    REQUIRE(gr.vertices.size() == 9);
    for (std::size_t k = 0; k < 9; ++k) CHECK(gr.vertices[k].y == Approx(want[k]).epsilon(1e-15));
    CHECK(gr.vertices[0].x == -2);
    CHECK(gr.vertices[8].z == 2);
}

TEST_CASE("fractal-terrain: 2,000 random inputs against the long-double reference",
          "[modelling][fractal-terrain]") {
    cg::Rng rng(2026);
    int flat = 0, triangles = 0;
    for (int k = 0; k < 2000; ++k) {
        const Input in = random_input(rng);
        CAPTURE(k, in.levels, in.amplitude, in.roughness, in.seed);
        const auto res = FractalTerrain::compute(in);
        // The state machine, stepped to the end, gives the same bits.
        CHECK(cg::run_to_end<FractalTerrain>(FractalTerrain::start(in)) == res);
        const Reference ref = reference(in);
        const auto v = by_lattice(in, res);
        LD scale = 1;
        for (const auto& [p, y] : ref.h) scale = std::max(scale, std::fabs(y));
        for (const auto& [p, y] : ref.h) CHECK(std::fabs(LD(v.at(p).y) - y) <= 1e-13L * scale);
        // Every displacement within its level's amplitude, measured from the result's own
        // heights with long-double averages.
        for (int L = 1; L <= in.levels; ++L) {
            const LD a = ref.amplitude[L - 1];
            CHECK(std::fabs(LD(res.amplitudes[L - 1]) - a) <= 1e-15L * a);
            for (const auto& [p, nb] : ref.added[L - 1]) {
                LD sum = 0, size = 0;
                for (const IJ& q : nb) sum += LD(v.at(q).y), size += std::fabs(LD(v.at(q).y));
                const LD y = LD(v.at(p).y);
                const LD offset = y - sum / LD(nb.size());
                // The rounding of the double sum, average and height: a few ulps of the
                // summands (the sum may cancel) and of the height.
                const LD slack = 4 * LD(std::numeric_limits<double>::epsilon()) *
                                 (size + std::fabs(y));
                CHECK(std::fabs(offset) <= a * (1 + 1e-15L) + slack);
            }
            CHECK(res.largest_offsets[L - 1] <= res.amplitudes[L - 1]);
        }
        flat += in.amplitude == 0;
        triangles += in.method == Method::Triangle;
    }
    CHECK(flat > 100);
    CHECK(triangles > 800);
    CHECK(triangles < 1200);
}

TEST_CASE("fractal-terrain: the same input gives the same bits, another seed another terrain",
          "[modelling][fractal-terrain]") {
    cg::Rng rng(3);
    for (int k = 0; k < 200; ++k) {
        Input in = random_input(rng);
        in.levels = std::max(in.levels, 1);
        in.amplitude = std::max(in.amplitude, 0.5);
        const auto a = FractalTerrain::compute(in), b = FractalTerrain::compute(in);
        REQUIRE(a == b);
        for (std::size_t i = 0; i < a.vertices.size(); ++i)
            CHECK(std::memcmp(&a.vertices[i], &b.vertices[i], sizeof(glm::dvec3)) == 0);
        Input other = in;
        other.seed = in.seed + 1;
        CHECK_FALSE(FractalTerrain::compute(other).vertices == a.vertices);
    }
    // Pinned bits: a changed generator, order or formula changes them.
    const auto ex = cg::test::result_of("fractal-terrain", cg::test::algorithm("fractal-terrain").example());
    CHECK(ex["heights"][13].get<double>() == 1.7356347571799748);
    CHECK(ex["heights"][7].get<double>() == 0.6186671681506578);
}

TEST_CASE("fractal-terrain: no cracks, and the counts of the closed form",
          "[modelling][fractal-terrain]") {
    for (Method m : {Method::Triangle, Method::Grid})
        for (int n = 0; n <= FractalTerrain::kMaxLevels; ++n) {
            CAPTURE(int(m), n);
            Input in = m == Method::Triangle
                           ? triangle({glm::dvec3(0, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 2, 1)},
                                      n, 1, 0.5, 9)
                           : grid({0, 1, 2, 3}, n, 1, 0.5, 9);
            const auto res = FractalTerrain::compute(in);
            const long long N = 1LL << n;
            const long long V = m == Method::Triangle ? (N + 1) * (N + 2) / 2 : (N + 1) * (N + 1);
            const long long T = m == Method::Triangle ? (1LL << (2 * n)) : 2 * N * N;
            CHECK(res.vertex_count == V);
            CHECK(res.triangle_count == T);
            CHECK(res.vertices.size() == std::size_t(V));
            CHECK(res.amplitudes.size() == std::size_t(n));
            if (n > 6) continue;
            // Each interior edge in exactly two triangles, each border edge in one, and no two
            // vertices at one place: a split edge's midpoint is one vertex for both sides.
            std::map<std::pair<int, int>, int> edges;
            for (const auto& t : res.triangles)
                for (int e = 0; e < 3; ++e) {
                    const int a = t[e], b = t[(e + 1) % 3];
                    REQUIRE(a != b);
                    edges[{std::min(a, b), std::max(a, b)}]++;
                }
            long long border = 0;
            for (const auto& [e, c] : edges) {
                CHECK((c == 1 || c == 2));
                border += c == 1;
            }
            CHECK(border == (m == Method::Triangle ? 3 * N : 4 * N));
            CHECK((long long)edges.size() == V + T - 1);  // Euler: V − E + F = 1 for a disc
            std::set<std::pair<double, double>> places;
            for (const auto& p : res.vertices) places.insert({p.x, p.z});
            CHECK((long long)places.size() == V);
        }
}

TEST_CASE("fractal-terrain: amplitude 0 gives the plane exactly", "[modelling][fractal-terrain]") {
    cg::Rng rng(4);
    for (int k = 0; k < 200; ++k) {
        // Integer heights: every average is a dyadic fraction, exact in a double.
        const double ha = double(rng.integer(-50, 50)), hb = double(rng.integer(-50, 50)),
                     hc = double(rng.integer(-50, 50));
        const int n = int(rng.integer(0, 8));
        const Input in = triangle({glm::dvec3(0, ha, 0), glm::dvec3(3, hb, 0), glm::dvec3(1, hc, 5)},
                                  n, 0, rng.uniform(0, 4), std::uint64_t(k));
        const auto res = FractalTerrain::compute(in);
        const auto v = by_lattice(in, res);
        const int N = 1 << n;
        for (const auto& [p, q] : v)
            CHECK(LD(q.y) * N == LD(N - p.first - p.second) * ha + LD(p.first) * hb +
                                     LD(p.second) * hc);
        CHECK(res.largest_offsets == std::vector<double>(std::size_t(n), 0.0));
        // The grid stays flat on equal corners.
        // Dyadic heights (eighths): 3c and 3c/3 are exact, as a border average needs.
        const double c = double(rng.integer(-40, 40)) / 8;
        const auto g = FractalTerrain::compute(grid({c, c, c, c}, std::min(n, 6), 0, 1, 1));
        for (const auto& q : g.vertices) CHECK(q.y == c);
    }
    // A tilted grid is not kept planar: a border point averages three neighbours, one inside.
    const auto tilted = FractalTerrain::compute(grid({0, 4, 0, 4}, 1, 0, 1, 1, 4));
    CHECK(tilted.vertices[1].y == Approx(2));          // front midpoint: (0 + 4 + 2)/3 = 2
    CHECK(tilted.vertices[3].y == Approx(2.0 / 3));    // left: (0 + 0 + 2)/3, not 0
}

TEST_CASE("fractal-terrain: the offsets fill each level's range", "[modelling][fractal-terrain]") {
    for (Method m : {Method::Triangle, Method::Grid}) {
        const Input in = m == Method::Triangle
                             ? triangle({glm::dvec3(0, 0, 0), glm::dvec3(8, 0, 0), glm::dvec3(0, 0, 8)},
                                        7, 2, 0.8, 77)
                             : grid({0, 0, 0, 0}, 7, 2, 0.8, 77);
        const auto res = FractalTerrain::compute(in);
        const Reference ref = reference(in);
        const auto v = by_lattice(in, res);
        for (int L = 1; L <= in.levels; ++L) {
            const auto& pts = ref.added[L - 1];
            LD sum = 0, sum2 = 0;
            for (const auto& [p, nb] : pts) {
                LD avg = 0;
                for (const IJ& q : nb) avg += LD(v.at(q).y);
                const LD r = LD(v.at(p).y) - avg / LD(nb.size());
                sum += r, sum2 += r * r;
            }
            const LD a = ref.amplitude[L - 1], count = LD(pts.size());
            CAPTURE(int(m), L, count);
            // Uniform on [−a, a): mean 0 (σ = a/√3), mean square a²/3.
            CHECK(std::fabs(sum / count) <= 4 * a / std::sqrt(3 * count));
            if (count >= 100) CHECK(std::fabs(sum2 / count / (a * a / 3) - 1) < 0.25L);
            if (count >= 20) CHECK(res.largest_offsets[L - 1] > 0.8 * double(a));
        }
    }
}

TEST_CASE("fractal-terrain: rays/mesh_gen's terrain is this diamond-square",
          "[modelling][fractal-terrain]") {
    // mesh_gen's former loop, kept here as the reference: corners from the generator, then
    // a = ρ, ρ², … per level.
    for (int resolution : {1, 2, 5, 16, 33}) {
        for (double rho : {0.0, 0.35, 0.5, 1.0}) {
            cg::mesh::TerrainParams p;
            p.resolution = resolution;
            p.roughness = rho;
            p.seed = std::uint64_t(resolution * 7 + 1);
            p.height = 3;
            const cg::mesh::Mesh mesh = cg::mesh::terrain(p);
            int N = 1;
            while (N < resolution) N *= 2;
            const std::size_t side = std::size_t(N) + 1;
            std::vector<double> h(side * side, 0.0);
            auto at = [&](int i, int j) -> double& { return h[std::size_t(j) * side + i]; };
            cg::Rng rng(p.seed);
            at(0, 0) = rng.uniform(-1, 1);
            at(N, 0) = rng.uniform(-1, 1);
            at(0, N) = rng.uniform(-1, 1);
            at(N, N) = rng.uniform(-1, 1);
            double a = rho;
            for (int step = N; step > 1; step /= 2, a *= rho) {
                const int half = step / 2;
                for (int j = half; j < N; j += step)
                    for (int i = half; i < N; i += step)
                        at(i, j) = 0.25 * (at(i - half, j - half) + at(i + half, j - half) +
                                           at(i - half, j + half) + at(i + half, j + half)) +
                                   rng.uniform(-a, a);
                for (int j = 0; j <= N; j += half)
                    for (int i = (j / half) % 2 == 0 ? half : 0; i <= N; i += step) {
                        double sum = 0;
                        int count = 0;
                        if (i - half >= 0) sum += at(i - half, j), ++count;
                        if (i + half <= N) sum += at(i + half, j), ++count;
                        if (j - half >= 0) sum += at(i, j - half), ++count;
                        if (j + half <= N) sum += at(i, j + half), ++count;
                        at(i, j) = sum / count + rng.uniform(-a, a);
                    }
            }
            double big = 0;
            for (int j = 0; j <= resolution; ++j)
                for (int i = 0; i <= resolution; ++i) big = std::max(big, std::fabs(at(i, j)));
            const double scale = big > 0 ? p.height / big : 0.0;
            for (int j = 0; j <= resolution; ++j)
                for (int i = 0; i <= resolution; ++i)
                    CHECK(mesh.vertices[std::size_t(j) * (resolution + 1) + i].y ==
                          scale * at(i, j));
            // And the algorithm's diamond-square with those corners and ρ = 2^(−H) (H = 1 is
            // exact) gives the same unscaled heights.
            if (rho == 0.5 && (N & (N - 1)) == 0) {
                int levels = 0;
                while ((1 << levels) < N) ++levels;
                cg::Rng corners(p.seed);
                Input in = grid({}, levels, 0.5, 1, p.seed);
                for (double& c : in.corners) c = corners.uniform(-1, 1);
                // The algorithm seeds a fresh generator; mesh_gen's is four draws on.
                std::vector<double> g = FractalTerrain::start_heights(in);
                cg::fractal::diamond_square(g, levels, 0.5, 0.5, corners);
                for (int j = 0; j <= N; ++j)
                    for (int i = 0; i <= N; ++i)
                        CHECK(g[std::size_t(j) * side + i] == at(i, j));
            }
        }
    }
}

TEST_CASE("fractal-terrain: the steps, point by point, then a level or phase at a time",
          "[modelling][fractal-terrain]") {
    using V = std::vector<std::string>;
    SECTION("triangle, 3 levels: 3 and 9 midpoints one by one, then 30 in one step") {
        const Input in = triangle({glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)},
                                  3, 1, 1, 1);
        const auto t = cg::test::run_traced<FractalTerrain>(in);
        V want = {"level", "midpoint", "midpoint", "midpoint", "level"};
        for (int k = 0; k < 9; ++k) want.push_back("midpoint");
        want.insert(want.end(), {"level", "batch", "summary"});
        CHECK(cg::test::events(t) == want);
        const auto& batch = t.steps[want.size() - 2];
        CHECK(batch.narration.rfind("In one step, all 30 edge midpoints of level 3", 0) == 0);
        CHECK(t.steps[0].narration.find("one per step") != std::string::npos);
        CHECK(t.steps[14].narration.find("all in one step") != std::string::npos);
        CHECK(std::get<double>(t.steps[14].vars[1].value) == 0.25);  // amplitude 1 · 2^(−1·2)
    }
    SECTION("grid, 3 levels: 1 + 4, 4 + 12 one by one, then the two phases of level 3") {
        const Input in = grid({0, 0, 0, 0}, 3, 1, 1, 1);
        const auto t = cg::test::run_traced<FractalTerrain>(in);
        V want = {"level", "diamond", "square", "square", "square", "square", "level"};
        for (int k = 0; k < 4; ++k) want.push_back("diamond");
        for (int k = 0; k < 12; ++k) want.push_back("square");
        want.insert(want.end(), {"level", "batch", "batch", "summary"});
        CHECK(cg::test::events(t) == want);
        CHECK(t.steps[24].narration.find("the diamond phase of level 3: all 16") !=
              std::string::npos);
        CHECK(t.steps[25].narration.find("the square phase of level 3: all 40") !=
              std::string::npos);
        // The first square step: the front midpoint, three neighbours.
        CHECK(t.steps[2].narration.find("3 neighbours: on the border") != std::string::npos);
    }
    SECTION("0 levels: only the summary") {
        const auto t = cg::test::run_traced<FractalTerrain>(grid({1, 2, 3, 4}, 0, 1, 1, 1));
        CHECK(cg::test::events(t) == V{"summary"});
        CHECK(t.result.triangle_count == 2);
    }
    SECTION("a midpoint step's variables: the average of the two ends, the offset, the sum") {
        const auto t = cg::test::run_traced<FractalTerrain>(
            triangle({glm::dvec3(0, 2, 0), glm::dvec3(4, 6, 0), glm::dvec3(0, 4, 4)}, 1, 1, 1, 5));
        const auto& s = t.steps[1];
        std::map<std::string, cg::Value> v;
        for (const auto& x : s.vars) v[x.name] = x.value;
        CHECK(std::get<std::vector<double>>(v["neighbours"]) == std::vector<double>{2, 6});
        CHECK(std::get<double>(v["average"]) == 4);
        CHECK(std::get<double>(v["height"]) == 4 + std::get<double>(v["offset"]));
        CHECK(s.narration.find("of the edge (0, 0)–(2, 0)") != std::string::npos);
    }
}

TEST_CASE("fractal-terrain: bad input names the field and the reason",
          "[modelling][fractal-terrain]") {
    auto err = [](const std::string& text) { return cg::test::error_of("fractal-terrain", text); };
    const std::string tri = R"("triangle": [[0, 0, 0], [1, 0, 0], [0, 0, 1]])";
    const std::string head = R"("levels": 2, "amplitude": 1, "roughness": 1, )";
    CHECK(err("{" + head + tri + "}") == "(accepted)");
    CHECK(err(R"({"levels": 9, "amplitude": 1, "roughness": 1, )" + tri + "}")
              .rfind("levels: must be 0 to 8 levels", 0) == 0);
    CHECK(err(R"({"levels": -1, "amplitude": 1, "roughness": 1, )" + tri + "}")
              .rfind("levels: must be 0 to 8", 0) == 0);
    CHECK(err(R"({"levels": 2, "amplitude": -1, "roughness": 1, )" + tri + "}")
              .rfind("amplitude: must be at least 0", 0) == 0);
    CHECK(err(R"({"levels": 2, "amplitude": 1e13, "roughness": 1, )" + tri + "}")
              .rfind("amplitude: is too large", 0) == 0);
    CHECK(err(R"({"levels": 2, "amplitude": 1, "roughness": -0.5, )" + tri + "}")
              .rfind("roughness: must be between 0", 0) == 0);
    CHECK(err(R"({"levels": 2, "amplitude": 1, "roughness": 4.5, )" + tri + "}")
              .rfind("roughness: must be between 0", 0) == 0);
    CHECK(err("{" + head + R"("triangle": [[0, 0, 0], [1, 5, 1], [2, -3, 2]]})")
              .rfind("triangle: has no area seen from above", 0) == 0);
    CHECK(err("{" + head + R"("triangle": [[0, 0, 0], [0, 0, 0], [1, 0, 1]]})")
              .rfind("triangle: has no area seen from above", 0) == 0);
    CHECK(err("{" + head + R"("triangle": [[0, 0, 0], [1, 0, 0]]})") ==
          "triangle: must be three points [x, y, z], got 2");
    CHECK(err("{" + head + R"("triangle": [[0, 0, 0], [1, 0, 0], [0, 1e13, 1]]})")
              .rfind("triangle[2][1]: is too large", 0) == 0);
    CHECK(err("{" + head + R"("triangle": [[0, 0, 0], [1, 0, 0], [0, "a", 1]]})")
              .rfind("triangle[2]", 0) == 0);
    CHECK(err("{" + head + tri + R"(, "corners": [0, 0, 0, 0]})")
              .rfind("corners: belongs to \"diamond-square\"", 0) == 0);
    CHECK(err("{" + head + R"("method": "diamond-square", "size": 1, "corners": [0, 0, 0]})")
              .rfind("corners: must be a list of four heights", 0) == 0);
    CHECK(err("{" + head + R"("method": "diamond-square", "size": 0, "corners": [0, 0, 0, 0]})")
              .rfind("size: must be positive", 0) == 0);
    CHECK(err("{" + head + R"("method": "diamond-square", "size": 1, "corners": [0, 0, 0, 0]})") ==
          "(accepted)");
    CHECK(err("{" + head + R"("method": "diamond-square", "size": 1, "corners": [0, 0, 0, 0], )" +
              tri + "}")
              .rfind("triangle: belongs to \"midpoint-triangle\"", 0) == 0);
    CHECK(err("{" + head + R"("method": "plasma", )" + tri + "}")
              .rfind("method: must be \"midpoint-triangle\" or \"diamond-square\"", 0) == 0);
    CHECK(err(R"({"levels": 2, "amplitude": 1, )" + tri + "}").rfind("roughness: is missing", 0) ==
          0);
    CHECK(err(R"({"levels": 2, "amplitude": NaN, "roughness": 1, )" + tri + "}")
              .rfind("amplitude: not valid JSON", 0) == 0);
    // NaN and infinities through the C++ interface, which JSON cannot carry.
    auto refused = [](Input in) -> std::string {
        try {
            FractalTerrain::validate(in);
        } catch (const cg::InputError& e) {
            return e.field() + ": " + e.reason();
        }
        return "(accepted)";
    };
    const Input good = triangle({glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)},
                                2, 1, 1, 1);
    CHECK(refused(good) == "(accepted)");
    Input bad = good;
    bad.amplitude = std::nan("");
    CHECK(refused(bad).rfind("amplitude: must be a finite number", 0) == 0);
    bad = good;
    bad.roughness = INFINITY;
    CHECK(refused(bad).rfind("roughness: must be between 0", 0) == 0);
    bad = good;
    bad.triangle[1].z = -INFINITY;
    CHECK(refused(bad).rfind("triangle[1][2]: must be a finite number", 0) == 0);
    bad = good;
    bad.levels = 1000;
    CHECK(refused(bad).rfind("levels: must be 0 to 8", 0) == 0);
    Input g = grid({0, 0, 0, 0}, 2, 1, 1, 1);
    g.corners[3] = std::nan("");
    CHECK(refused(g).rfind("corners[3]: must be a finite number", 0) == 0);
    g = grid({0, 0, 0, 0}, 2, 1, 1, 1);
    g.size = INFINITY;
    CHECK(refused(g).rfind("size: must be a finite number", 0) == 0);
    // The limit's picture: 8 levels run, 65 536 triangles.
    CHECK(err(R"({"levels": 8, "amplitude": 1, "roughness": 1, )" + tri + "}") == "(accepted)");
}

TEST_CASE("fractal-terrain: replay on the example and the presets", "[modelling][fractal-terrain]") {
    const auto& a = cg::test::algorithm("fractal-terrain");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    REQUIRE(lesson().presets.size() >= 3);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 3);
        // The registry's run holds the plain function's numbers.
        CHECK(cg::test::result_of("fractal-terrain", p.input) == a.plain(p.input));
    }
}

TEST_CASE("fractal-terrain: exam problems are one level by hand, answered by the offsets stated",
          "[modelling][fractal-terrain][exam]") {
    const auto& a = cg::test::algorithm("fractal-terrain");
    int tris = 0, grids = 0, flat = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = cg::test::input_of<FractalTerrain>("fractal-terrain", p.input);
        CAPTURE(seed, p.question);
        CHECK(in.levels == 1);
        cg::Rng rng(in.seed);
        const double A = in.amplitude;
        std::vector<double> want;
        if (in.method == Method::Triangle) {
            ++tris;
            const double ha = in.triangle[0].y, hb = in.triangle[1].y, hc = in.triangle[2].y;
            const double r1 = rng.uniform(-A, A), r2 = rng.uniform(-A, A), r3 = rng.uniform(-A, A);
            want = {ha, (ha + hb) / 2 + r1, hb, (ha + hc) / 2 + r2, (hb + hc) / 2 + r3, hc};
            for (double r : {r1, r2, r3}) CHECK(p.question.find(cg::num(r, 6)) != std::string::npos);
            CHECK(p.expected["triangle_count"] == 4);
            flat += ha == hb && hb == hc;
        } else {
            ++grids;
            const auto& c = in.corners;
            const double ctr = (c[0] + c[1] + c[2] + c[3]) / 4 + rng.uniform(-A, A);
            const double f = (c[0] + c[1] + ctr) / 3 + rng.uniform(-A, A);
            const double l = (c[0] + c[2] + ctr) / 3 + rng.uniform(-A, A);
            const double r = (c[1] + c[3] + ctr) / 3 + rng.uniform(-A, A);
            const double b = (c[2] + c[3] + ctr) / 3 + rng.uniform(-A, A);
            want = {c[0], f, c[1], l, ctr, r, c[2], b, c[3]};
        }
        const auto got = p.expected["heights"].get<std::vector<double>>();
        REQUIRE(got.size() == want.size());
        for (std::size_t k = 0; k < want.size(); ++k) CHECK(got[k] == Approx(want[k]).epsilon(1e-14));
        CHECK(cg::answer_matches(p.expected["heights"], cg::json(want)));
    }
    CHECK(tris > 150);
    CHECK(grids > 60);
    CHECK(flat > 3);
}

TEST_CASE("fractal-terrain: the picture — the surface coloured by height, the point just moved",
          "[modelling][fractal-terrain]") {
    const Input in = triangle({glm::dvec3(0, 0, 0), glm::dvec3(4, 0, 0), glm::dvec3(0, 0, 4)}, 2,
                              1, 1, 3);
    auto s = FractalTerrain::start(in);
    cg::Scene scene;
    FractalTerrain::draw(s, scene);
    CHECK(scene.faces3.size() == 1);  // nothing split yet
    FractalTerrain::step(s, nullptr);  // level 1
    FractalTerrain::step(s, nullptr);  // the first midpoint
    scene.clear();
    FractalTerrain::draw(s, scene);
    CHECK(scene.faces3.size() == 1);
    int active = 0, ends = 0;
    for (const auto& p : scene.points3) {
        active += p.style.role == cg::Role::Active;
        ends += p.style.role == cg::Role::Entering;
    }
    CHECK(active == 1);
    CHECK(ends == 2);
    bool offset_arrow = false;
    for (const auto& seg : scene.segments3) offset_arrow |= seg.arrow && seg.label.rfind("r = ", 0) == 0;
    CHECK(offset_arrow);
    while (!FractalTerrain::done(s)) FractalTerrain::step(s, nullptr);
    scene.clear();
    FractalTerrain::draw(s, scene);
    CHECK(scene.faces3.size() == 16);
    std::set<std::uint32_t> colours;
    for (const auto& f : scene.faces3) colours.insert(f.style.rgba);
    CHECK(colours.size() > 4);  // heights coloured
    CHECK(scene.extent3 > 0);
}
