// Marching cubes: hand-worked cubes (the example's case 3, one corner, a saddle face joined and
// separated, a corner exactly at iso); the GENERATED table checked for every case and every
// decision of its saddle faces (triangles only on crossed edges, every crossed edge used, the
// triangles' boundary exactly the face segments, no diagonal lying in a face, complement
// symmetry, two neighbouring cubes drawing the same segments on their common face whatever
// else they hold); 3,000 seeded random grids (integer values so corners at iso and face
// centres at iso are common, real values over many scales, constant grids, 1 × 1 × 1 grids)
// against an independent long-double brute force: the cases, one vertex per sign-changing grid
// edge at the interpolated point, every triangle inside one cube, every mesh edge on exactly
// two triangles (one on the grid's border) with opposite directions, the saddle faces, the
// area; the sphere closed and manifold with area → 4πr² and vertices on the sphere to the
// interpolation's accuracy; torus and blobs by their Euler characteristic; the state machine
// against compute; steps, errors, replay, exam problems, the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "modelling/marching_cubes.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::MarchingCubes;
using MC = MarchingCubes;
using Input = MC::Input;
using LD = long double;
using Values = std::vector<std::vector<std::vector<double>>>;

namespace {

Input grid(Values values, double iso = 0) {
    Input in;
    in.field = MC::Field::Grid;
    in.values = std::move(values);
    in.iso = iso;
    return in;
}

// One cube from its eight corner values f0 … f7.
Input cube(const std::array<double, 8>& f, double iso = 0) {
    return grid({{{f[0], f[1]}, {f[3], f[2]}}, {{f[4], f[5]}, {f[7], f[6]}}}, iso);
}

Input named(MC::Field f, int cells, double radius, double iso = 0) {
    Input in;
    in.field = f;
    in.cells = cells;
    in.radius = radius;
    in.iso = iso;
    return in;
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("marching-cubes");
    if (!l) throw std::runtime_error("no lesson for marching-cubes");
    return *l;
}

// ---- the generated table, checked against what it must be ----

// The cycles of a row as canonical sets (each cycle rotated to start at its smallest edge).
std::set<std::vector<int>> cycles_of(const MC::Row& r, bool reversed) {
    std::set<std::vector<int>> out;
    for (int q = 0, at = 0; q < r.cycles; at += r.length[std::size_t(q)], ++q) {
        std::vector<int> c(r.cycle.begin() + at, r.cycle.begin() + at + r.length[std::size_t(q)]);
        if (reversed) std::reverse(c.begin(), c.end());
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        out.insert(c);
    }
    return out;
}

int faces_of_edge(int e) {
    int m = 0;
    for (int F = 0; F < 6; ++F)
        for (int k = 0; k < 4; ++k) m |= int(MC::face_edges()[std::size_t(F)][std::size_t(k)] == e) << F;
    return m;
}

// The directed triangle edges of a row lying in face F (both ends on F).
std::set<std::pair<int, int>> face_boundary(const MC::Row& r, int F) {
    std::set<std::pair<int, int>> out;
    for (int n = 0; n < r.triangles; ++n)
        for (int e = 0; e < 3; ++e) {
            const int a = r.tri[std::size_t(n)][std::size_t(e)], b = r.tri[std::size_t(n)][std::size_t((e + 1) % 3)];
            if ((faces_of_edge(a) & faces_of_edge(b)) >> F & 1) out.insert({a, b});
        }
    return out;
}

// ---- the brute-force reference, in long double, written apart from the code ----

struct Tally {
    long long vertices = 0, triangles = 0, interior_edges = 0, border_edges = 0, at_corner = 0,
              saddle_faces = 0, grids = 0, centres = 0;
};

// A grid edge id 3·(point) + axis → its two end points (i, j, k).
std::array<std::array<int, 3>, 2> edge_ends(const MC::Grid& g, int id) {
    const int axis = id % 3, p = id / 3;
    const int i = p % (g.nx + 1), j = p / (g.nx + 1) % (g.ny + 1), k = p / ((g.nx + 1) * (g.ny + 1));
    std::array<int, 3> b = {i, j, k};
    b[std::size_t(axis)] += 1;
    return {{{i, j, k}, b}};
}

void check_against_reference(const Input& in, const MC::Result& r, Tally& tally, bool exact) {
    const MC::Grid g = MC::sample(in);
    const LD iso = in.iso;
    ++tally.grids;
    REQUIRE(r.cases.size() == std::size_t(g.nx * g.ny * g.nz));
    auto F = [&](int i, int j, int k) { return LD(g.at(i, j, k)); };
    auto inside = [&](int i, int j, int k) { return F(i, j, k) < iso; };
    // The cases, by the definition.
    const int off[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    long long saddles = 0, joined = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                int bits = 0;
                for (int c = 0; c < 8; ++c)
                    bits += inside(i + off[c][0], j + off[c][1], k + off[c][2]) ? 1 << c : 0;
                CHECK(int(r.cases[std::size_t((k * g.ny + j) * g.nx + i)]) == bits);
                // Its six faces: a saddle when the diagonal corners agree and neighbours differ.
                const int quads[6][4][3] = {
                    {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},
                    {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}},
                    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
                if (bits == 0 || bits == 255) continue;
                for (const auto& q : quads) {
                    bool s[4];
                    LD sum = 0;
                    for (int c = 0; c < 4; ++c) {
                        s[c] = inside(i + q[c][0], j + q[c][1], k + q[c][2]);
                        sum += F(i + q[c][0], j + q[c][1], k + q[c][2]);
                    }
                    if (s[0] == s[2] && s[1] == s[3] && s[0] != s[1]) {
                        ++saddles;
                        joined += sum / 4 < iso;
                    }
                }
            }
    CHECK(r.ambiguous == saddles);
    if (exact) CHECK(r.joined == joined);  // small integers: the centre sums are exact in double
    tally.saddle_faces += saddles;
    // One vertex per sign-changing grid edge, at the interpolated point.
    std::map<int, int> vertex_of;  // grid edge → vertex
    REQUIRE(r.vertex_edge.size() == r.vertices.size());
    for (std::size_t v = 0; v < r.vertices.size(); ++v) {
        if (r.vertex_edge[v] < 0) continue;  // a cycle's centre, checked below
        REQUIRE(vertex_of.count(r.vertex_edge[v]) == 0);
        vertex_of[r.vertex_edge[v]] = int(v);
    }
    const LD scale = std::max<LD>(1, LD(g.h) * std::max({g.nx, g.ny, g.nz}) + 2);
    long long changes = 0;
    for (int k = 0; k <= g.nz; ++k)
        for (int j = 0; j <= g.ny; ++j)
            for (int i = 0; i <= g.nx; ++i)
                for (int axis = 0; axis < 3; ++axis) {
                    int b[3] = {i, j, k};
                    b[axis] += 1;
                    if (b[0] > g.nx || b[1] > g.ny || b[2] > g.nz) continue;
                    const LD fa = F(i, j, k), fb = F(b[0], b[1], b[2]);
                    const int id = 3 * int(g.index(i, j, k)) + axis;
                    if ((fa < iso) == (fb < iso)) {
                        CHECK(vertex_of.count(id) == 0);
                        continue;
                    }
                    ++changes;
                    REQUIRE(vertex_of.count(id) == 1);
                    const LD t = (iso - fa) / (fb - fa);
                    tally.at_corner += t == 0 || t == 1;
                    const glm::dvec3 pa = g.point(i, j, k), pb = g.point(b[0], b[1], b[2]);
                    const glm::dvec3 p = r.vertices[std::size_t(vertex_of[id])];
                    for (int d = 0; d < 3; ++d) {
                        const LD want = LD(pa[d]) + t * (LD(pb[d]) - LD(pa[d]));
                        CHECK(std::fabs(LD(p[d]) - want) <= 1e-12L * scale);
                    }
                    ++tally.vertices;
                }
    CHECK((long long)vertex_of.size() == changes);
    // Every triangle inside one cube; every mesh edge on two triangles with opposite directions
    // (one triangle when it lies in the grid's border).
    std::map<std::pair<int, int>, int> directed;
    LD area = 0;
    for (const auto& t : r.triangles) {
        int lo[3] = {1 << 30, 1 << 30, 1 << 30}, hi[3] = {-1, -1, -1};
        for (int v : t) {
            REQUIRE(v >= 0);
            REQUIRE(v < int(r.vertices.size()));
            if (r.vertex_edge[std::size_t(v)] < 0) continue;
            for (const auto& e : edge_ends(g, r.vertex_edge[std::size_t(v)]))
                for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], e[std::size_t(d)]), hi[d] = std::max(hi[d], e[std::size_t(d)]);
        }
        for (int d = 0; d < 3; ++d) CHECK(hi[d] - lo[d] <= 1);
        for (int e = 0; e < 3; ++e) ++directed[{t[std::size_t(e)], t[std::size_t((e + 1) % 3)]}];
        LD a[3], b[3];
        const glm::dvec3 p0 = r.vertices[std::size_t(t[0])], p1 = r.vertices[std::size_t(t[1])],
                         p2 = r.vertices[std::size_t(t[2])];
        for (int d = 0; d < 3; ++d) a[d] = LD(p1[d]) - p0[d], b[d] = LD(p2[d]) - p0[d];
        const LD cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2],
                 cz = a[0] * b[1] - a[1] * b[0];
        area += std::sqrt(cx * cx + cy * cy + cz * cz) / 2;
        ++tally.triangles;
    }
    CHECK(std::fabs(LD(r.area) - area) <= 1e-9L * std::max<LD>(area, 1e-300L) + 1e-300L);
    long long boundary = 0;
    for (const auto& [e, n] : directed) {
        CHECK(n == 1);  // never the same direction twice: consistently oriented
        if (directed.count({e.second, e.first})) {
            ++tally.interior_edges;
            continue;
        }
        ++boundary;
        ++tally.border_edges;
        REQUIRE(r.vertex_edge[std::size_t(e.first)] >= 0);  // a centre is never on the rim
        REQUIRE(r.vertex_edge[std::size_t(e.second)] >= 0);
        // An open edge must lie in the grid's border: both grid edges in one outer plane.
        const auto A = edge_ends(g, r.vertex_edge[std::size_t(e.first)]);
        const auto B = edge_ends(g, r.vertex_edge[std::size_t(e.second)]);
        const int top[3] = {g.nx, g.ny, g.nz};
        bool border = false;
        for (int d = 0; d < 3; ++d)
            for (int side : {0, top[d]})
                border = border || (A[0][std::size_t(d)] == side && A[1][std::size_t(d)] == side &&
                                    B[0][std::size_t(d)] == side && B[1][std::size_t(d)] == side);
        CHECK(border);
    }
    CHECK(r.boundary == boundary);
    CHECK(r.nonmanifold == 0);
    // A cycle's centre: the average of the crossings round it (its fan's rim), a closed fan.
    std::map<int, std::set<int>> rim;
    std::map<int, int> fan;
    for (const auto& t : r.triangles)
        for (int e = 0; e < 3; ++e)
            if (r.vertex_edge[std::size_t(t[std::size_t(e)])] < 0) {
                ++fan[t[std::size_t(e)]];
                rim[t[std::size_t(e)]].insert(t[std::size_t((e + 1) % 3)]);
                rim[t[std::size_t(e)]].insert(t[std::size_t((e + 2) % 3)]);
            }
    for (const auto& [c, around] : rim) {
        CHECK(fan[c] == int(around.size()));
        LD sum[3] = {0, 0, 0};
        for (int v : around) {
            CHECK(r.vertex_edge[std::size_t(v)] >= 0);
            for (int d = 0; d < 3; ++d) sum[d] += r.vertices[std::size_t(v)][d];
        }
        for (int d = 0; d < 3; ++d)
            CHECK(std::fabs(LD(r.vertices[std::size_t(c)][d]) - sum[d] / LD(around.size())) <= 1e-12L * scale);
        ++tally.centres;
    }
}

}  // namespace

TEST_CASE("marching-cubes: cubes worked by hand", "[modelling][marching-cubes]") {
    SECTION("the example: corners 0 and 1 inside, case 3, a quad as two triangles") {
        const auto r = MC::compute(cube({-2, -1, 3, 2, 1, 2, 4, 3}));
        REQUIRE(r.cases == std::vector<std::uint8_t>{3});
        // Edges 1 (t = 1/4), 3 (t = 1/2), 8 (t = 2/3), 9 (t = 1/3), in edge order.
        REQUIRE(r.vertices.size() == 4);
        CHECK(r.vertices[0].x == 1);
        CHECK(r.vertices[0].y == Approx(0.25));
        CHECK(r.vertices[1].y == Approx(0.5));
        CHECK(r.vertices[2].z == Approx(2.0 / 3));
        CHECK(r.vertices[3].z == Approx(1.0 / 3));
        CHECK(r.triangles.size() == 2);
        CHECK(r.boundary == 4);
        const auto j = cg::test::result_of("marching-cubes", cg::test::algorithm("marching-cubes").example());
        CHECK(j["cases"][0][0][0] == 3);
        CHECK(j["triangle_count"] == 2);
    }
    SECTION("one corner inside: one triangle, its normal pointing away from the corner") {
        const auto r = MC::compute(cube({-1, 1, 1, 1, 1, 1, 1, 1}));
        REQUIRE(r.triangles.size() == 1);
        const auto& t = r.triangles[0];
        const glm::dvec3 a = r.vertices[std::size_t(t[0])], b = r.vertices[std::size_t(t[1])],
                         c = r.vertices[std::size_t(t[2])];
        CHECK(glm::dot(glm::cross(b - a, c - a), glm::dvec3(1, 1, 1)) > 0);
        CHECK(r.vertices[0] == glm::dvec3(0.5, 0, 0));
        CHECK(r.volume == Approx(1.0 / 48));  // the cone from corner 0: outward normals
    }
    SECTION("a saddle on the bottom face (case 5): separated, then joined") {
        // Corners 0 and 2 inside; the bottom face's centre average decides.
        const auto sep = MC::compute(cube({-1, 2, -1, 2, 3, 3, 3, 3}));
        CHECK(sep.cases[0] == 5);
        CHECK(sep.ambiguous == 1);
        CHECK(sep.joined == 0);
        CHECK(sep.triangles.size() == 2);  // two corners cut off
        const auto join = MC::compute(cube({-3, 1, -3, 1, 3, 3, 3, 3}));
        CHECK(join.cases[0] == 5);
        CHECK(join.joined == 1);
        CHECK(join.triangles.size() == 4);  // one hexagon through the face's centre
        // The centre exactly at iso: outside, separated (f < iso is inside).
        const auto at = MC::compute(cube({-1, 1, -1, 1, 3, 3, 3, 3}));
        CHECK(at.joined == 0);
        CHECK(at.triangles.size() == 2);
    }
    SECTION("a corner exactly at iso is outside; its crossings sit on it") {
        const auto r = MC::compute(cube({-1, 0, 1, 1, 1, 1, 1, 1}));
        CHECK(r.cases[0] == 1);
        REQUIRE(r.vertices.size() == 3);
        CHECK(r.vertices[0] == glm::dvec3(1, 0, 0));  // edge 0 reaches corner 1 at t = 1
    }
    SECTION("constant grids and iso on every corner: nothing") {
        CHECK(MC::compute(cube({0, 0, 0, 0, 0, 0, 0, 0})).triangles.empty());
        CHECK(MC::compute(cube({-1, -1, -1, -1, -1, -1, -1, -1})).cases[0] == 255);
    }
}

TEST_CASE("marching-cubes: the generated table — every case, every saddle decision",
          "[modelling][marching-cubes]") {
    long long rows = 0, triangles = 0, max_cycle = 0, centred = 0;
    for (int c = 0; c < 256; ++c) {
        const int amb = MC::ambiguous_faces(c);
        for (int J = 0; J < 64; ++J) {
            if (J & ~amb) continue;
            CAPTURE(c, J);
            ++rows;
            const MC::Row& r = MC::table(c, J);
            // The crossed edges, by the definition.
            int crossed = 0;
            for (int e = 0; e < 12; ++e) {
                const auto& ends = MC::edge_ends()[std::size_t(e)];
                crossed |= int((c >> ends[0] & 1) != (c >> ends[1] & 1)) << e;
            }
            int used = 0, want = 0;
            for (int q = 0; q < r.cycles; ++q) {
                const int n = r.length[std::size_t(q)];
                want += (r.centres >> q & 1) ? n : n - 2;  // round the centre: n; a cut: n − 2
                max_cycle = std::max<long long>(max_cycle, n);
                CHECK(n >= 3);
                CHECK((!(r.centres >> q & 1) || n >= 6));
            }
            CHECK(r.triangles == want);
            CHECK(r.centres >> r.cycles == 0);
            centred += r.centres != 0;
            triangles += r.triangles;
            for (int n = 0; n < r.triangles; ++n)
                for (int v : r.tri[std::size_t(n)]) {
                    if (v >= 12) {  // a cycle's centre, only where the row says so
                        CHECK((r.centres >> (v - 12) & 1) == 1);
                        continue;
                    }
                    CHECK((crossed >> v & 1) == 1);  // a vertex only on a crossed edge
                    used |= 1 << v;
                }
            CHECK(used == crossed);  // and every crossed edge used
            // Closed within the cube: every triangle edge either matched by its reverse (an
            // inner diagonal) or the reverse of one of the faces' marching-squares segments,
            // and every face segment appears so.
            std::set<std::pair<int, int>> dir, segs;
            for (int n = 0; n < r.triangles; ++n)
                for (int e = 0; e < 3; ++e) {
                    const auto& t = r.tri[std::size_t(n)];
                    CHECK(dir.insert({t[std::size_t(e)], t[std::size_t((e + 1) % 3)]}).second);
                }
            for (int F = 0; F < 6; ++F) {
                std::array<std::array<int, 2>, 2> s{};
                const int n = MC::face_segments(c, F, (J >> F & 1) != 0, s);
                for (int k = 0; k < n; ++k) segs.insert({s[std::size_t(k)][1], s[std::size_t(k)][0]});
            }
            for (const auto& d : dir) {
                if (dir.count({d.second, d.first})) {
                    // An inner diagonal: its ends share no face of the cube.
                    CHECK((faces_of_edge(d.first) & faces_of_edge(d.second)) == 0);
                } else {
                    CHECK(segs.count(d) == 1);
                }
            }
            for (const auto& s : segs) CHECK(dir.count(s) == 1);
            // Complement symmetry: inside and outside swapped, the saddles decided the other
            // way, gives the same cycles run backwards.
            CHECK(cycles_of(MC::table(255 - c, amb & ~J), true) == cycles_of(r, false));
        }
    }
    CHECK(rows > 256);
    CHECK(max_cycle >= 6);
    WARN("table rows " << rows << ", triangles " << triangles << ", longest cycle " << max_cycle
                        << ", rows with a cycle fanned round its centre " << centred);
    CHECK(triangles > 0);
    CHECK(centred * 4 < rows);  // the exception, not the rule (116 of 656 rows)
    for (int c = 0; c < 256; ++c)  // never with at most one saddle face
        if (__builtin_popcount(unsigned(MC::ambiguous_faces(c))) <= 1)
            for (int J = 0; J < 64; ++J) CHECK(MC::table(c, J).centres == 0);
    // Neighbours: cube A's face x = 1 (y = 1, z = 1) and cube B's face x = 0 (y = 0, z = 0) are
    // the same square. Whatever the other corners hold, the two cubes' triangles meet it in the
    // same segments, run in opposite directions.
    const auto& order = MC::face_sum_order();
    long long pairs = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const int FA = 2 * axis + 1, FB = 2 * axis;
        auto edge_map = [&](int e) {  // an edge of face FA → the same edge of face FB
            const auto& ends = MC::edge_ends()[std::size_t(e)];
            int q[2];
            for (int s = 0; s < 2; ++s)
                for (int k = 0; k < 4; ++k)
                    if (order[std::size_t(FA)][std::size_t(k)] == ends[std::size_t(s)]) q[s] = order[std::size_t(FB)][std::size_t(k)];
            for (int b = 0; b < 12; ++b) {
                const auto& eb = MC::edge_ends()[std::size_t(b)];
                if ((eb[0] == q[0] && eb[1] == q[1]) || (eb[0] == q[1] && eb[1] == q[0])) return b;
            }
            return -1;
        };
        for (int bits = 0; bits < 16; ++bits)
            for (int joined = 0; joined < 2; ++joined)
                for (int restA = 0; restA < 16; ++restA)
                    for (int restB = 0; restB < 16; ++restB) {
                        int ca = 0, cb = 0, ra = 0, rb = 0;
                        for (int k = 0; k < 4; ++k) {
                            ca |= (bits >> k & 1) << order[std::size_t(FA)][std::size_t(k)];
                            cb |= (bits >> k & 1) << order[std::size_t(FB)][std::size_t(k)];
                            ra |= (restA >> k & 1) << order[std::size_t(FB)][std::size_t(k)];
                            rb |= (restB >> k & 1) << order[std::size_t(FA)][std::size_t(k)];
                        }
                        // Other faces' decisions: all joined for A, none for B (any would do).
                        const MC::Row& A = MC::table(ca | ra, 63 & ~(joined ? 0 : 1 << FA));
                        const MC::Row& B = MC::table(cb | rb, joined ? 1 << FB : 0);
                        std::set<std::pair<int, int>> a, b;
                        for (const auto& [x, y] : face_boundary(A, FA)) a.insert({edge_map(y), edge_map(x)});
                        b = face_boundary(B, FB);
                        CHECK(a == b);
                        ++pairs;
                    }
    }
    CHECK(pairs == 3 * 16 * 2 * 256);
}

TEST_CASE("marching-cubes: 3,000 random grids against the long-double brute force",
          "[modelling][marching-cubes]") {
    cg::Rng rng(2026);
    Tally tally;
    for (int n = 0; n < 3000; ++n) {
        const int nx = n % 10 == 0 ? 1 : int(rng.integer(1, 5));
        const int ny = n % 10 == 0 ? 1 : int(rng.integer(1, 5));
        const int nz = n % 10 == 0 ? 1 : int(rng.integer(1, 4));
        const bool exact = n % 2 == 0;
        const bool constant = n % 97 == 0;
        const double scale = std::pow(10.0, double(rng.integer(-8, 8)));
        const double iso = exact ? double(rng.integer(-1, 1)) : scale * rng.uniform(-0.5, 0.5);
        Values v(std::size_t(nz + 1), std::vector<std::vector<double>>(
                                          std::size_t(ny + 1), std::vector<double>(std::size_t(nx + 1))));
        for (auto& layer : v)
            for (auto& row : layer)
                for (double& x : row)
                    x = constant ? iso : exact ? double(rng.integer(-3, 3)) : scale * rng.uniform(-1, 1);
        const Input in = grid(v, iso);
        CAPTURE(n, nx, ny, nz);
        const auto r = MC::compute(in);
        check_against_reference(in, r, tally, exact);
        if (constant) CHECK(r.triangles.empty());
        if (n % 25 == 0) CHECK(cg::run_to_end<MC>(MC::start(in)) == r);
    }
    INFO("vertices " << tally.vertices << ", triangles " << tally.triangles << ", interior edges "
                     << tally.interior_edges << ", border edges " << tally.border_edges
                     << ", at corner " << tally.at_corner << ", saddle faces " << tally.saddle_faces);
    CHECK(tally.vertices > 100000);
    CHECK(tally.at_corner > 1000);
    CHECK(tally.saddle_faces > 1000);
    CHECK(tally.centres > 50);
    WARN("random grids: vertices " << tally.vertices << ", triangles " << tally.triangles
                                   << ", interior edges " << tally.interior_edges
                                   << ", border edges " << tally.border_edges << ", at corner "
                                   << tally.at_corner << ", saddle faces " << tally.saddle_faces
                                   << ", centres " << tally.centres);
}

TEST_CASE("marching-cubes: the sphere — closed, manifold, area → 4πr²",
          "[modelling][marching-cubes]") {
    const double r = 0.7;
    const LD exact = 4 * acosl(-1) * r * r;
    double last = 1;
    for (int cells : {8, 16, 32, 64}) {
        const Input in = named(MC::Field::Sphere, cells, r);
        const auto m = MC::compute(in);
        CAPTURE(cells);
        CHECK(m.boundary == 0);
        CHECK(m.nonmanifold == 0);
        CHECK(m.edges * 2 == 3 * (long long)m.triangles.size());  // each edge on two triangles
        CHECK(m.euler == 2);
        CHECK(m.volume > 0);  // normals outward
        const double h = 2.0 / cells;
        LD worst = 0;
        for (const auto& p : m.vertices) {
            const LD d = sqrtl(LD(p.x) * p.x + LD(p.y) * p.y + LD(p.z) * p.z) - r;
            worst = std::max(worst, fabsl(d));
        }
        // Linear interpolation of the quadratic f along an edge: off by at most h²/(8r)-ish.
        CHECK(worst <= LD(h * h / (4 * r)));
        const double err = double(fabsl(LD(m.area) - exact) / exact);
        WARN("sphere " << cells << " cells: relative area error " << err << ", worst radial "
                       << double(worst) << ", triangles " << m.triangles.size());
        CHECK(err < last / 2.5);
        last = err;
        Tally tally;
        if (cells <= 16) check_against_reference(in, m, tally, false);
    }
    CHECK(last < 1e-3);
}

TEST_CASE("marching-cubes: torus, blobs, gyroid — topology from the Euler characteristic",
          "[modelling][marching-cubes]") {
    const auto torus = MC::compute(named(MC::Field::Torus, 32, 0.25));
    CHECK(torus.boundary == 0);
    CHECK(torus.euler == 0);
    const auto apart = MC::compute(named(MC::Field::Blobs, 32, 0.3));
    CHECK(apart.boundary == 0);
    CHECK(apart.euler == 4);  // two spheres
    const auto merged = MC::compute(named(MC::Field::Blobs, 32, 0.45));
    CHECK(merged.euler == 2);
    const auto gyroid = MC::compute(named(MC::Field::Gyroid, 24, 0.7));
    CHECK(gyroid.nonmanifold == 0);
    CHECK(gyroid.boundary > 0);  // it leaves the box
    Tally tally;
    check_against_reference(named(MC::Field::Gyroid, 12, 0.7), MC::compute(named(MC::Field::Gyroid, 12, 0.7)), tally, false);
}

TEST_CASE("marching-cubes: the state machine gives what compute gives",
          "[modelling][marching-cubes]") {
    cg::Rng rng(9);
    const MC::Field fields[4] = {MC::Field::Sphere, MC::Field::Torus, MC::Field::Blobs, MC::Field::Gyroid};
    for (int k = 0; k < 40; ++k) {
        const Input in = named(fields[k % 4], int(rng.integer(1, 14)), rng.uniform(0.2, 0.9),
                               rng.uniform(-0.1, 0.1));
        const auto t = cg::test::run_traced<MC>(in);
        CHECK(t.result == MC::compute(in));
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const Input in = cg::test::input_of<MC>("marching-cubes", p.input);
        const auto r = MC::compute(in);
        CHECK(cg::test::run_traced<MC>(in).result == r);
        const auto j = cg::test::result_of("marching-cubes", p.input);
        CHECK(j["triangle_count"] == r.triangles.size());
    }
}

TEST_CASE("marching-cubes: the steps — crossed cubes one by one, empty runs, batches",
          "[modelling][marching-cubes]") {
    SECTION("the example: sample, one cube, summary") {
        const Input in = cg::test::input_of<MC>("marching-cubes", cg::test::algorithm("marching-cubes").example());
        const auto t = cg::test::run_traced<MC>(in);
        CHECK(cg::test::events(t) == std::vector<std::string>{"sample", "cube", "summary"});
        CHECK(t.steps[1].narration.find("case 3") != std::string::npos);
        CHECK(t.steps[1].narration.find("e1 t = 0.25") != std::string::npos);
    }
    SECTION("a saddle face is narrated with its decision") {
        const auto t = cg::test::run_traced<MC>(cube({-3, 1, -3, 1, 3, 3, 3, 3}));
        REQUIRE(t.steps.size() == 3);
        CHECK(t.steps[1].event == "ambiguous");
        CHECK(t.steps[1].narration.find("joined") != std::string::npos);
    }
    SECTION("a big grid: at most kStepped cube steps, then at most kBatches batches") {
        const Input in = named(MC::Field::Sphere, 32, 0.7);
        const auto t = cg::test::run_traced<MC>(in);
        CHECK(t.steps.size() <= std::size_t(2 + MC::kStepped + MC::kBatches));
        int batches = 0;
        for (const auto& s : t.steps) batches += s.event == "batch";
        CHECK(batches >= 20);
        CHECK(t.result == MC::compute(in));
        CHECK(t.steps.back().narration.find("closed and manifold") != std::string::npos);
    }
}

TEST_CASE("marching-cubes: bad input names the field", "[modelling][marching-cubes]") {
    auto err = [](const std::string& text) { return cg::test::error_of("marching-cubes", text); };
    CHECK(err(R"({"values": [[[1, 2], [3, 4]]], "iso": 0})").rfind("values: needs at least 2 layers", 0) == 0);
    CHECK(err(R"({"values": [[[1, 2], [3, 4]], [[1, 2]]], "iso": 0})").rfind("values[1]: has 1 rows", 0) == 0);
    CHECK(err(R"({"values": [[[1, 2], [3]], [[1, 2], [3, 4]]], "iso": 0})").rfind("values[0][1]: has 1 values", 0) == 0);
    CHECK(err(R"({"values": [[[1], [3]], [[1], [3]]], "iso": 0})").rfind("values[0][0]: needs at least 2", 0) == 0);
    CHECK(err(R"({"values": [[[1, "a"], [3, 4]], [[1, 2], [3, 4]]], "iso": 0})").rfind("values[0][0][1]: must be a number", 0) == 0);
    CHECK(err(R"({"values": [[[1, 2], [3, 4]], [[1, 2], [3, 4]]]})").rfind("iso: is missing", 0) == 0);
    CHECK(err(R"({"values": [[[1, 2], [3, 4]], [[1, 2], [3, 1e200]]], "iso": 0})").rfind("values[1][1][1]: must be a finite", 0) == 0);
    CHECK(err(R"({"values": 3, "iso": 0})").rfind("values: must be a list", 0) == 0);
    CHECK(err(R"({"field": "cube", "iso": 0})").rfind("field: must be", 0) == 0);
    CHECK(err(R"({"field": "sphere", "cells": 0, "iso": 0})").rfind("cells: must be 1 to 64", 0) == 0);
    CHECK(err(R"({"field": "sphere", "cells": 65, "iso": 0})").rfind("cells: must be 1 to 64", 0) == 0);
    CHECK(err(R"({"field": "sphere", "radius": -1, "iso": 0})").rfind("radius: must be above 0", 0) == 0);
    CHECK(err(R"({"field": "gyroid", "radius": 1, "iso": 0})").rfind("radius: is not used", 0) == 0);
    CHECK(err(R"({"field": "torus", "values": [], "iso": 0})").rfind("values: only with", 0) == 0);
    CHECK(err(R"({"values": [[[1, 2], [3, 4]], [[1, 2], [3, 4]]], "cells": 4, "iso": 0})").rfind("cells: is for a named field", 0) == 0);
    CHECK(err(R"({"field": "sphere", "iso": 0, "isovalue": 1})").rfind("isovalue: is not a known field", 0) == 0);
    CHECK_THROWS_WITH(MC::start(cube({1, 2, 3, 4, 5, 6, 7, std::nan("")})),
                      Catch::StartsWith("values[1][1][0]: must be a finite"));
    CHECK_THROWS_WITH(MC::start(cube({1, 2, 3, 4, 5, 6, 7, 8}, INFINITY)), Catch::StartsWith("iso: must be"));
}

TEST_CASE("marching-cubes: replay on the example and the presets", "[modelling][marching-cubes]") {
    const auto& a = cg::test::algorithm("marching-cubes");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
    CHECK(lesson().presets.size() >= 4);
}

TEST_CASE("marching-cubes: exam problems — the case index and the crossings of one cube",
          "[modelling][marching-cubes][exam]") {
    const auto& a = cg::test::algorithm("marching-cubes");
    int saddles = 0, on_iso = 0;
    const int off[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const int ends[12][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}, {4, 5}, {5, 6},
                             {7, 6}, {4, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<MC>("marching-cubes", p.input);
        const LD iso = in.iso;
        LD f[8];
        for (int c = 0; c < 8; ++c) f[c] = in.values[std::size_t(off[c][2])][std::size_t(off[c][1])][std::size_t(off[c][0])];
        int bits = 0;
        for (int c = 0; c < 8; ++c) {
            bits |= int(f[c] < iso) << c;
            on_iso += f[c] == iso;
        }
        CHECK(bits != 0);
        CHECK(bits != 255);
        saddles += MC::ambiguous_faces(bits) != 0;
        CHECK(p.expected["cases/0/0/0"] == bits);
        std::vector<std::array<LD, 3>> want;
        for (const auto& e : ends) {
            const LD fa = f[e[0]], fb = f[e[1]];
            if ((fa < iso) == (fb < iso)) continue;
            const LD t = (iso - fa) / (fb - fa);
            want.push_back({off[e[0]][0] + t * (off[e[1]][0] - off[e[0]][0]),
                            off[e[0]][1] + t * (off[e[1]][1] - off[e[0]][1]),
                            off[e[0]][2] + t * (off[e[1]][2] - off[e[0]][2])});
        }
        const auto& got = p.expected["vertices"];
        REQUIRE(got.size() == want.size());
        for (std::size_t k = 0; k < want.size(); ++k)
            for (int d = 0; d < 3; ++d)
                CHECK(std::fabs(got[k][std::size_t(d)].get<double>() - double(want[k][std::size_t(d)])) <= 1e-12);
        CHECK(p.answers == std::vector<std::string>{"cases/0/0/0", "vertices"});
    }
    CHECK(saddles > 40);
    CHECK(on_iso > 15);
}

TEST_CASE("marching-cubes: the picture", "[modelling][marching-cubes]") {
    auto s = MC::start(cube({-2, -1, 3, 2, 1, 2, 4, 3}));
    MC::step(s, nullptr);  // sampling
    {
        cg::Scene scene;
        MC::draw(s, scene);
        int inside = 0;
        for (const auto& p : scene.points3) inside += p.style.role == cg::Role::Kept;
        CHECK(inside == 2);
        CHECK(scene.points3.size() == 8);
    }
    MC::step(s, nullptr);  // the cube
    cg::Scene scene;
    MC::draw(s, scene);
    CHECK(scene.faces3.size() == 2);
    for (const auto& f : scene.faces3) CHECK(f.style.role == cg::Role::Active);
    int crossings = 0;
    for (const auto& p : scene.points3) crossings += p.style.role == cg::Role::Entering;
    CHECK(crossings == 4);
    bool label = false;
    for (const auto& l : scene.labels3) label = label || l.text.rfind("case 3 = 00000011", 0) == 0;
    CHECK(label);
}
