// Subdivision surfaces: the cube under Catmull–Clark and the octahedron under Loop against
// positions worked by hand (5/9, 33/64, 3/8, 3/4); the counts per level against the formulas and
// against the edges counted again (V − E + F unchanged); one level against an independent
// long-double reference written as the subdivision matrix — each new point a row of weights on
// the OLD vertices (face points expanded into their corners), built from std::map adjacency and
// summed in long double — on 3,000 seeded random meshes (random positions on fixed topologies:
// cube, octahedron, tetrahedron, quad and triangle grids with a boundary, mixed triangle/quad
// pyramids and grids, a bowtie pinch, an unused vertex; coincident and collinear positions;
// far-off and tiny scales), the new faces checked by what their corners are; the course's
// centroid averaging against Catmull–Clark (equal on quads at valence 4); the state machine
// against compute; bad input naming the field; replay; the picture; the exam problems.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "modelling/subdivision_surface.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::SubdivisionSurface;
using S = SubdivisionSurface;
using Input = S::Input;
using Mesh = S::Mesh;
using glm::dvec3;
using LD = long double;

namespace {

// ---- meshes ----

Mesh cube(double h = 1) {
    return {{{-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h},
             {-h, -h, h}, {h, -h, h}, {h, h, h}, {-h, h, h}},
            {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}}};
}

Mesh octahedron(double h = 1) {
    return {{{h, 0, 0}, {-h, 0, 0}, {0, h, 0}, {0, -h, 0}, {0, 0, h}, {0, 0, -h}},
            {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
}

Mesh tetrahedron() {
    return {{{0, 0, 0}, {2, 2, 0}, {2, 0, 2}, {0, 2, 2}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

// An nx × ny grid of quads (or each quad split into two triangles; `mixed`: every other one).
Mesh grid(int nx, int ny, int split) {  // split: 0 quads, 1 triangles, 2 mixed
    Mesh m;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) m.vertices.push_back({double(i), double(j), 0});
    auto id = [&](int i, int j) { return j * (nx + 1) + i; };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if (split == 1 || (split == 2 && (i + j) % 2 == 1)) {
                m.faces.push_back({a, b, c});
                m.faces.push_back({a, c, d});
            } else {
                m.faces.push_back({a, b, c, d});
            }
        }
    return m;
}

Mesh pyramid() {
    return {{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 2}},
            {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2, 1}}};
}

Mesh bowtie() {  // two triangles meeting at V0 only: a pinch; plus V5 in no face
    return {{{0, 0, 0}, {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0}, {5, 5, 5}},
            {{0, 1, 3}, {0, 2, 4}}};
}

Input make(Mesh m, S::Scheme scheme, int levels = 1) {
    Input in;
    in.mesh = std::move(m);
    in.scheme = scheme;
    in.levels = levels;
    return in;
}

// ---- the reference: one level as the subdivision matrix, in long double ----

using Row = std::map<int, LD>;  // weights on the old vertices

void add(Row& r, const Row& o, LD scale) {
    for (const auto& [v, w] : o) r[v] += scale * w;
}

struct Reference {
    std::vector<Row> vertex_rows, face_rows;
    std::map<std::pair<int, int>, Row> edge_rows;  // by (min, max) end
};

std::pair<int, int> key(int a, int b) {
    return {std::min(a, b), std::max(a, b)};
}

Reference reference(const Mesh& m, S::Scheme scheme) {
    Reference ref;
    std::map<std::pair<int, int>, std::vector<int>> faces_of_edge;
    std::vector<std::set<int>> nb(m.vertices.size()), faces_of(m.vertices.size());
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        const auto& f = m.faces[k];
        Row centroid;
        for (std::size_t i = 0; i < f.size(); ++i) {
            const int a = f[i], b = f[(i + 1) % f.size()];
            faces_of_edge[key(a, b)].push_back(int(k));
            nb[std::size_t(a)].insert(b);
            nb[std::size_t(b)].insert(a);
            faces_of[std::size_t(a)].insert(int(k));
            centroid[a] += 1.0L / LD(f.size());
        }
        ref.face_rows.push_back(centroid);
    }
    for (const auto& [e, fs] : faces_of_edge) {
        Row r;
        if (fs.size() == 1) {
            r[e.first] = r[e.second] = 0.5L;
        } else if (scheme == S::Scheme::Loop) {
            r[e.first] = r[e.second] = 0.375L;
            for (int f : fs)
                for (int v : m.faces[std::size_t(f)])
                    if (v != e.first && v != e.second) r[v] += 0.125L;
        } else {
            r[e.first] = r[e.second] = 0.25L;
            for (int f : fs) add(r, ref.face_rows[std::size_t(f)], 0.25L);
        }
        ref.edge_rows[e] = r;
    }
    for (int v = 0; v < int(m.vertices.size()); ++v) {
        std::vector<int> border;
        for (int w : nb[std::size_t(v)])
            if (faces_of_edge[key(v, w)].size() == 1) border.push_back(w);
        Row r;
        const LD n = LD(nb[std::size_t(v)].size());
        if (nb[std::size_t(v)].empty() || border.size() > 2) {
            r[v] = 1;
        } else if (border.size() == 2) {
            r[v] = 0.75L;
            r[border[0]] += 0.125L;
            r[border[1]] += 0.125L;
        } else if (scheme == S::Scheme::Loop) {
            const LD c = 0.375L + 0.25L * std::cos(2 * 3.14159265358979323846264338327950288L / n);
            const LD beta = (0.625L - c * c) / n;
            r[v] = 1 - n * beta;
            for (int w : nb[std::size_t(v)]) r[w] += beta;
        } else {
            // (Q + 2R + (n − 3) v)/n, Q and R as averages, each expanded onto old vertices.
            Row Q, R;
            for (int f : faces_of[std::size_t(v)])
                add(Q, ref.face_rows[std::size_t(f)], 1.0L / LD(faces_of[std::size_t(v)].size()));
            for (int w : nb[std::size_t(v)]) {
                R[v] += 0.5L / n;
                R[w] += 0.5L / n;
            }
            add(r, Q, 1 / n);
            add(r, R, 2 / n);
            r[v] += (n - 3) / n;
        }
        ref.vertex_rows.push_back(r);
    }
    return ref;
}

struct LPoint {
    LD x = 0, y = 0, z = 0;
};

LPoint apply(const Row& r, const Mesh& m) {
    LPoint p;
    for (const auto& [v, w] : r) {
        p.x += w * LD(m.vertices[std::size_t(v)].x);
        p.y += w * LD(m.vertices[std::size_t(v)].y);
        p.z += w * LD(m.vertices[std::size_t(v)].z);
    }
    return p;
}

LD weight_sum(const Row& r) {
    LD s = 0;
    for (const auto& [v, w] : r) s += w;
    return s;
}

double gap(dvec3 a, LPoint b) {
    return double(std::max({std::fabs(LD(a.x) - b.x), std::fabs(LD(a.y) - b.y),
                            std::fabs(LD(a.z) - b.z)}));
}

double scale_of(const Mesh& m) {
    double s = 0;
    for (const auto& p : m.vertices) s = std::max({s, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    return s;
}

long long count_edges(const Mesh& m) {
    std::set<std::pair<int, int>> e;
    for (const auto& f : m.faces)
        for (std::size_t i = 0; i < f.size(); ++i) e.insert(key(f[i], f[(i + 1) % f.size()]));
    return (long long)e.size();
}

// One level of the code against the reference: every new point, every weight row summing to 1,
// the new mesh's vertices in the documented order and its faces made of the right corners.
void check_level(const Input& in, const S::Result& r, double tol_rel) {
    const Mesh& m = in.mesh;
    const Reference ref = reference(m, in.scheme);
    const double tol = tol_rel * std::max(scale_of(m), 1e-300);
    const int nv = int(m.vertices.size()), nf = int(m.faces.size());
    const bool cc = in.scheme == S::Scheme::CatmullClark;
    REQUIRE(r.first.vertex.size() == m.vertices.size());
    REQUIRE(r.first_topology.edges.size() == ref.edge_rows.size());
    for (int v = 0; v < nv; ++v) {
        CHECK(std::fabs(double(weight_sum(ref.vertex_rows[std::size_t(v)]) - 1)) < 1e-15);
        CHECK(gap(r.first.vertex[std::size_t(v)], apply(ref.vertex_rows[std::size_t(v)], m)) <= tol);
        CHECK(r.mesh.vertices[std::size_t(v)] == r.first.vertex[std::size_t(v)]);
    }
    if (cc) {
        REQUIRE(r.first.face.size() == m.faces.size());
        for (int f = 0; f < nf; ++f) {
            CHECK(gap(r.first.face[std::size_t(f)], apply(ref.face_rows[std::size_t(f)], m)) <= tol);
            CHECK(r.mesh.vertices[std::size_t(nv + f)] == r.first.face[std::size_t(f)]);
        }
    } else {
        CHECK(r.first.face.empty());
    }
    const int edge0 = cc ? nv + nf : nv;
    std::map<std::pair<int, int>, int> edge_index;
    for (std::size_t e = 0; e < r.first_topology.edges.size(); ++e) {
        const auto [a, b] = r.first_topology.edges[e];
        const auto k = key(a, b);
        REQUIRE(ref.edge_rows.count(k) == 1);
        CHECK(edge_index.count(k) == 0);  // each edge once
        edge_index[k] = edge0 + int(e);
        CHECK(std::fabs(double(weight_sum(ref.edge_rows.at(k)) - 1)) < 1e-15);
        CHECK(gap(r.first.edge[e], apply(ref.edge_rows.at(k), m)) <= tol);
        CHECK(r.mesh.vertices[std::size_t(edge0) + e] == r.first.edge[e]);
    }
    // The faces, by what their corners are.
    std::size_t next = 0;
    for (int f = 0; f < nf; ++f) {
        const auto& c = m.faces[std::size_t(f)];
        const int n = int(c.size());
        auto E = [&](int i, int j) { return edge_index.at(key(c[std::size_t(i % n)], c[std::size_t(j % n)])); };
        if (cc) {
            for (int i = 0; i < n; ++i) {
                REQUIRE(next < r.mesh.faces.size());
                CHECK(r.mesh.faces[next++] ==
                      std::vector<int>{c[std::size_t(i)], E(i, i + 1), nv + f, E(i + n - 1, i)});
            }
        } else {
            CHECK(r.mesh.faces[next++] == std::vector<int>{c[0], E(0, 1), E(2, 0)});
            CHECK(r.mesh.faces[next++] == std::vector<int>{c[1], E(1, 2), E(0, 1)});
            CHECK(r.mesh.faces[next++] == std::vector<int>{c[2], E(2, 0), E(1, 2)});
            CHECK(r.mesh.faces[next++] == std::vector<int>{E(0, 1), E(1, 2), E(2, 0)});
        }
    }
    CHECK(next == r.mesh.faces.size());
}

void check_counts(const Input& in, const S::Result& r) {
    REQUIRE(r.counts.size() == std::size_t(in.levels) + 1);
    const auto& c0 = r.counts[0];
    CHECK(c0.V == (long long)in.mesh.vertices.size());
    CHECK(c0.E == count_edges(in.mesh));
    CHECK(c0.F == (long long)in.mesh.faces.size());
    for (std::size_t l = 1; l < r.counts.size(); ++l) CHECK(r.counts[l].euler() == c0.euler());
    const auto& last = r.counts.back();
    CHECK(last.V == (long long)r.mesh.vertices.size());
    CHECK(last.E == count_edges(r.mesh));
    CHECK(last.F == (long long)r.mesh.faces.size());
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("subdivision-surface");
    if (!l) throw std::runtime_error("no lesson for subdivision-surface");
    return *l;
}

}  // namespace

TEST_CASE("subdivision-surface: the cube under Catmull–Clark, by hand", "[modelling][subdivision-surface]") {
    Input in = make(cube(), S::Scheme::CatmullClark, 2);
    const auto r = S::compute(in);
    // Face F1 (z = 1): its centroid (0, 0, 1).
    CHECK(r.first.face[1] == dvec3(0, 0, 1));
    // The edge V5–V6, x = 1 and z = 1: (V5 + V6 + F1 + F4)/4 = ((1,−1,1) + (1,1,1) + (0,0,1) + (1,0,0))/4.
    const int e = S::find_edge(r.first_topology, 5, 6);
    REQUIRE(e >= 0);
    CHECK(r.first.edge[std::size_t(e)] == dvec3(0.75, 0, 0.75));
    // The corner V6 = (1, 1, 1), n = 3: Q = (1/3, 1/3, 1/3), R = (2/3, 2/3, 2/3), (Q + 2R)/3 = 5/9.
    for (int v = 0; v < 8; ++v)
        for (int c = 0; c < 3; ++c)
            CHECK(r.first.vertex[std::size_t(v)][c] == Approx(in.mesh.vertices[std::size_t(v)][c] * 5.0 / 9.0).epsilon(1e-15));
    CHECK(r.counts == std::vector<S::Counts>{{8, 12, 6}, {26, 48, 24}, {98, 192, 96}});
    // The second level: the old corner again at valence 3; its exact position (Q + 2R)/3 from
    // level 1's neighbours worked by hand: 55/108 = 0.509259…
    CHECK(r.mesh.vertices[6].x == Approx(55.0 / 108.0).epsilon(1e-14));
    check_counts(in, r);
    // The focus answers the exam's question.
    in.focus = S::FocusKind::Vertex;
    in.focus_a = 6;
    CHECK(S::compute(in).focus_point == r.first.vertex[6]);
}

TEST_CASE("subdivision-surface: the octahedron under Loop, by hand", "[modelling][subdivision-surface]") {
    const Input in = make(octahedron(), S::Scheme::Loop, 2);
    const auto r = S::compute(in);
    // n = 4: β = (1/4)(5/8 − (3/8)²) = 31/256, 1 − 4β = 33/64; the neighbours sum to 0.
    CHECK(S::loop_beta(4) == Approx(31.0 / 256.0).epsilon(1e-15));
    CHECK(r.first.vertex[0].x == Approx(33.0 / 64.0).epsilon(1e-15));
    CHECK(std::fabs(r.first.vertex[0].y) < 1e-16);
    // The edge V0–V2: 3/8 (V0 + V2) + 1/8 (V4 + V5) = (3/8, 3/8, 0).
    const int e = S::find_edge(r.first_topology, 0, 2);
    REQUIRE(e >= 0);
    CHECK(r.first.edge[std::size_t(e)] == dvec3(0.375, 0.375, 0));
    CHECK(r.counts == std::vector<S::Counts>{{6, 12, 8}, {18, 48, 32}, {66, 192, 128}});
    check_counts(in, r);
    // The tetrahedron, n = 3: β = 3/16, V0' = 7/16·0 + 3/16·(4, 4, 4) = (3/4, 3/4, 3/4).
    const auto t = S::compute(make(tetrahedron(), S::Scheme::Loop));
    CHECK(t.first.vertex[0] == dvec3(0.75, 0.75, 0.75));
    CHECK(S::loop_beta(3) == 3.0 / 16.0);
    CHECK(S::loop_beta(6) == 1.0 / 16.0);
}

TEST_CASE("subdivision-surface: boundaries — midpoints and 1/8, 3/4, 1/8", "[modelling][subdivision-surface]") {
    Mesh quad{{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {{0, 1, 2, 3}}};
    const auto r = S::compute(make(quad, S::Scheme::CatmullClark));
    CHECK(r.first.face[0] == dvec3(1, 1, 0));
    for (std::size_t e = 0; e < 4; ++e) {
        const auto [a, b] = r.first_topology.edges[e];
        CHECK(r.first.edge[e] == 0.5 * (quad.vertices[std::size_t(a)] + quad.vertices[std::size_t(b)]));
    }
    CHECK(r.first.vertex[0] == dvec3(0.25, 0.25, 0));  // 1/8 (2, 0) + 1/8 (0, 2)
    CHECK(r.counts == std::vector<S::Counts>{{4, 4, 1}, {9, 12, 4}});
    // The pinch and the unused vertex stay put, under both schemes.
    for (auto scheme : {S::Scheme::Loop, S::Scheme::CatmullClark}) {
        const auto b = S::compute(make(bowtie(), scheme, 2));
        CHECK(b.mesh.vertices[0] == dvec3(0, 0, 0));
        CHECK(b.mesh.vertices[5] == dvec3(5, 5, 5));
        check_counts(make(bowtie(), scheme, 2), b);
    }
}

TEST_CASE("subdivision-surface: 3,000 random meshes against the long-double subdivision matrix",
          "[modelling][subdivision-surface]") {
    const std::vector<std::pair<Mesh, int>> shapes = {
        // (mesh, 0 both schemes / 1 Catmull–Clark only)
        {cube(), 1},          {octahedron(), 0},   {tetrahedron(), 0}, {grid(3, 2, 0), 1},
        {grid(3, 3, 1), 0},   {grid(2, 3, 2), 1},  {pyramid(), 1},     {bowtie(), 0},
        {grid(1, 1, 0), 1},   {grid(4, 1, 1), 0},
    };
    cg::Rng rng(2026);
    int loops = 0, ccs = 0, boundary = 0, degenerate = 0, far = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const auto& [shape, only_cc] = shapes[std::size_t(trial) % shapes.size()];
        Input in = make(shape, only_cc || rng.chance(0.5) ? S::Scheme::CatmullClark : S::Scheme::Loop);
        const double kind = rng.uniform(0, 1);
        double scale = std::pow(10.0, rng.uniform(-3, 3));
        dvec3 offset(0.0);
        if (kind < 0.05) {
            ++far;
            offset = dvec3(1e6, -2e6, 3e5);
        }
        const dvec3 base(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        const dvec3 dir(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        for (auto& p : in.mesh.vertices) {
            if (kind > 0.95) {
                p = base;  // all coincident
            } else if (kind > 0.9) {
                p = base + rng.uniform(-1, 1) * dir;  // all on one line
            } else {
                p = offset + scale * dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            }
        }
        degenerate += kind > 0.9;
        (in.scheme == S::Scheme::Loop ? loops : ccs)++;
        CAPTURE(trial, in.mesh.vertices.size(), int(in.scheme));
        const auto r = S::compute(in);
        check_level(in, r, 1e-14);
        check_counts(in, r);
        for (const auto& ef : r.first_topology.edge_faces) boundary += ef[1] < 0;
        // Two levels compose: the second is one level of the first's mesh.
        if (trial % 10 == 0) {
            Input two = in;
            two.levels = 2;
            const auto r2 = S::compute(two);
            Input next = in;
            next.mesh = r.mesh;
            const auto again = S::compute(next);
            CHECK(r2.mesh == again.mesh);
            check_level(next, again, 1e-14);
            check_counts(two, r2);
        }
    }
    CHECK(loops > 600);
    CHECK(ccs > 1500);
    CHECK(boundary > 1000);
    CHECK(degenerate > 200);
    CHECK(far > 100);
}

TEST_CASE("subdivision-surface: the course's centroid averaging is Catmull–Clark on quads at valence 4",
          "[modelling][subdivision-surface]") {
    // Split linearly (edge midpoints, face centroids, old vertices in place, each quad into four),
    // then move every vertex to the average of the centroids of its faces in the split mesh.
    cg::Rng rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        Mesh m = grid(3, 3, 0);
        for (auto& p : m.vertices) p += dvec3(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-1, 1));
        const auto r = S::compute(make(m, S::Scheme::CatmullClark));
        // The linear split, with the code's numbering (checked against the reference above).
        Mesh lin = r.mesh;
        const int nv = int(m.vertices.size()), nf = int(m.faces.size());
        for (int v = 0; v < nv; ++v) lin.vertices[std::size_t(v)] = m.vertices[std::size_t(v)];
        for (std::size_t e = 0; e < r.first_topology.edges.size(); ++e) {
            const auto [a, b] = r.first_topology.edges[e];
            lin.vertices[std::size_t(nv + nf) + e] =
                0.5 * (m.vertices[std::size_t(a)] + m.vertices[std::size_t(b)]);
        }
        std::vector<LPoint> sum(lin.vertices.size());
        std::vector<int> count(lin.vertices.size(), 0);
        for (const auto& f : lin.faces) {
            LPoint c;
            for (int v : f) {
                c.x += LD(lin.vertices[std::size_t(v)].x) / 4;
                c.y += LD(lin.vertices[std::size_t(v)].y) / 4;
                c.z += LD(lin.vertices[std::size_t(v)].z) / 4;
            }
            for (int v : f) {
                sum[std::size_t(v)].x += c.x, sum[std::size_t(v)].y += c.y, sum[std::size_t(v)].z += c.z;
                ++count[std::size_t(v)];
            }
        }
        for (std::size_t v = 0; v < lin.vertices.size(); ++v) {
            if (count[v] != 4) continue;  // on the boundary: the averaging has no rule there
            const bool old = v < std::size_t(nv);
            if (old) {  // old vertices: valence 4 inside a quad grid
                const LPoint a{sum[v].x / 4, sum[v].y / 4, sum[v].z / 4};
                CHECK(gap(r.mesh.vertices[v], a) < 1e-14);
            } else {  // face points and interior edge points
                const LPoint a{sum[v].x / 4, sum[v].y / 4, sum[v].z / 4};
                CHECK(gap(r.mesh.vertices[v], a) < 1e-14);
            }
        }
    }
    // At valence 3 they differ: the cube's corner goes to 5/9 under Catmull–Clark, while the
    // averaging gives v/4 + R/2 + Q/4 = 1/4 + 1/3 + 1/12 = 2/3.
    const auto r = S::compute(make(cube(), S::Scheme::CatmullClark));
    CHECK(r.first.vertex[6].x == Approx(5.0 / 9.0));
    CHECK(r.first.vertex[6].x != Approx(2.0 / 3.0));
}

TEST_CASE("subdivision-surface: the state machine gives what compute gives, through the registry too",
          "[modelling][subdivision-surface]") {
    cg::Rng rng(11);
    const std::vector<Mesh> tris = {octahedron(), tetrahedron(), grid(2, 2, 1), bowtie()};
    const std::vector<Mesh> quads = {cube(), pyramid(), grid(2, 2, 2), grid(3, 1, 0)};
    for (int k = 0; k < 120; ++k) {
        const bool loop = k % 2 == 0;
        Input in = make(loop ? tris[std::size_t(k / 2) % 4] : quads[std::size_t(k / 2) % 4],
                        loop ? S::Scheme::Loop : S::Scheme::CatmullClark, int(rng.integer(0, 3)));
        for (auto& p : in.mesh.vertices) p += dvec3(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), 0);
        in.focus = S::FocusKind::Vertex;
        in.focus_a = rng.integer(0, (long long)in.mesh.vertices.size() - 1);
        CAPTURE(k);
        const auto traced = cg::test::run_traced<S>(in);
        CHECK(traced.result == S::compute(in));
        // The narrated weights are the vertex's row of the reference and give its point.
        for (const auto& st : traced.steps) {
            if (st.event != "vertex-points") continue;
            bool found = false;
            for (const auto& v : st.vars)
                if (v.name == "weights") {
                    found = true;
                    double sum = 0;
                    for (double w : std::get<std::vector<double>>(v.value)) sum += w;
                    CHECK(sum == Approx(1.0).epsilon(1e-14));
                }
            CHECK(found);
        }
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const Input in = cg::test::input_of<S>("subdivision-surface", p.input);
        const auto j = cg::test::result_of("subdivision-surface", p.input);
        const auto r = S::compute(in);
        CHECK(j["faces"].size() == r.mesh.faces.size());
        CHECK(j["euler"] == r.counts[0].euler());
        check_counts(in, r);
        if (in.levels > 0) check_level(make(in.mesh, in.scheme), S::compute(make(in.mesh, in.scheme)), 1e-14);
    }
}

TEST_CASE("subdivision-surface: the steps, one group per level", "[modelling][subdivision-surface]") {
    const auto cc = cg::test::events(cg::test::run_traced<S>(make(cube(), S::Scheme::CatmullClark, 2)));
    CHECK(cc == std::vector<std::string>{"split", "face-points", "edge-points", "vertex-points",
                                         "connect", "split", "face-points", "edge-points",
                                         "vertex-points", "connect", "summary"});
    const auto lp = cg::test::run_traced<S>(make(octahedron(), S::Scheme::Loop, 1));
    CHECK(cg::test::events(lp) ==
          std::vector<std::string>{"split", "edge-points", "vertex-points", "connect", "summary"});
    CHECK(lp.steps[2].narration.find("β = 31/256") != std::string::npos);
    CHECK(lp.steps[2].narration.find("33/64·V0") != std::string::npos);
    const auto zero = cg::test::run_traced<S>(make(cube(), S::Scheme::CatmullClark, 0));
    CHECK(cg::test::events(zero) == std::vector<std::string>{"summary"});
    CHECK(zero.result.mesh == cube());
    CHECK(cg::subdivision_weight(0.375) == "3/8");
    CHECK(cg::subdivision_weight(31.0 / 256) == "31/256");
    CHECK(cg::subdivision_weight(1.0 / 9) == "1/9");
}

TEST_CASE("subdivision-surface: bad input names the field and the reason", "[modelling][subdivision-surface]") {
    auto err = [](const std::string& text) { return cg::test::error_of("subdivision-surface", text); };
    const std::string tri = R"("vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,1]], )";
    CHECK(err("{" + tri + R"("faces": [[0,1,2,3]], "scheme": "loop", "levels": 1})") ==
          "faces[0]: Loop subdivision needs triangles; this face has 4 vertices");
    CHECK(err("{" + tri + R"("faces": [[0,1,1]], "scheme": "loop", "levels": 1})") ==
          "faces[0]: lists vertex 1 twice: a face's corners must differ");
    CHECK(err("{" + tri + R"("faces": [[0,1,7]], "scheme": "loop", "levels": 1})")
              .rfind("faces[0][2]: index 7 is out of range", 0) == 0);
    CHECK(err("{" + tri + R"("faces": [[0,1,2],[1,0,3],[0,1,3]], "scheme": "loop", "levels": 1})") ==
          "faces[2]: the edge 0–1 is in a third face: a non-manifold edge (at most two faces share "
          "an edge)");
    CHECK(err("{" + tri + R"("faces": [[0,1]], "scheme": "loop", "levels": 1})")
              .rfind("faces[0]: must be a triangle or a quad", 0) == 0);
    CHECK(err("{" + tri + R"("faces": [[0,1,2]], "scheme": "doo-sabin", "levels": 1})") ==
          "scheme: must be \"loop\" or \"catmull-clark\", got \"doo-sabin\"");
    CHECK(err("{" + tri + R"("faces": [[0,1,2]], "scheme": "loop", "levels": 6})") ==
          "levels: must be 0 to 5 (got 6)");
    CHECK(err("{" + tri + R"("faces": [[0,1,2]], "scheme": "loop", "levels": 1, "focus": {"face": 0}})") ==
          "focus.face: Loop subdivision has no face points");
    CHECK(err("{" + tri + R"("faces": [[0,1,2]], "scheme": "loop", "levels": 1, "focus": {"edge": [0, 3]}})") ==
          "focus.edge: [0, 3] is not an edge of the mesh");
    CHECK(err("{" + tri + R"("faces": [], "scheme": "loop", "levels": 1})") == "faces: needs at least one face");
    CHECK(err(R"({"vertices": [], "faces": [], "scheme": "loop", "levels": 1})") ==
          "vertices: needs at least one vertex");
    CHECK(err("{" + tri + R"("faces": [[0,1,2]], "scheme": "loop", "levels": 1, "colour": 1})")
              .rfind("colour: is not a known field", 0) == 0);
    // The face cap from the formulas, before anything is built: 30 × 30 quads, 900 · 4³ at level 3.
    Input big = make(grid(30, 30, 0), S::Scheme::CatmullClark, 5);
    CHECK_THROWS_WITH(S::start(big), "levels: level 3 would have 57600 faces; at most 50000 are built and drawn");
    big.levels = 2;
    CHECK_NOTHROW(S::start(big));
    Input nan = make(tetrahedron(), S::Scheme::Loop);
    nan.mesh.vertices[1].y = std::nan("");
    CHECK_THROWS_WITH(S::start(nan), "vertices[1]: coordinates must be finite numbers within ±1e100");
}

TEST_CASE("subdivision-surface: replay on the example and the presets", "[modelling][subdivision-surface]") {
    const auto& a = cg::test::algorithm("subdivision-surface");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
    CHECK(lesson().presets.size() >= 4);
}

TEST_CASE("subdivision-surface: exam problems answered by the reference",
          "[modelling][subdivision-surface][exam]") {
    const auto& a = cg::test::algorithm("subdivision-surface");
    int faces = 0, edges = 0, vertices = 0, loops = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = cg::test::input_of<S>("subdivision-surface", p.input);
        CAPTURE(seed, p.question);
        CHECK(in.levels == 1);
        const Reference ref = reference(in.mesh, in.scheme);
        LPoint expect;
        if (in.focus == S::FocusKind::Face) {
            ++faces;
            expect = apply(ref.face_rows[std::size_t(in.focus_a)], in.mesh);
        } else if (in.focus == S::FocusKind::Edge) {
            ++edges;
            expect = apply(ref.edge_rows.at(key(int(in.focus_a), int(in.focus_b))), in.mesh);
        } else {
            ++vertices;
            expect = apply(ref.vertex_rows[std::size_t(in.focus_a)], in.mesh);
        }
        const auto& fp = p.expected["focus_point"];
        CHECK(gap(dvec3(fp[0].get<double>(), fp[1].get<double>(), fp[2].get<double>()), expect) < 1e-14);
        // Counts by the formulas, from the input alone.
        const long long V = (long long)in.mesh.vertices.size(), E = count_edges(in.mesh),
                        F = (long long)in.mesh.faces.size();
        long long corners = 0;
        for (const auto& f : in.mesh.faces) corners += (long long)f.size();
        const bool loop = in.scheme == S::Scheme::Loop;
        loops += loop;
        CHECK(p.expected["counts/1"] == (loop ? cg::json{V + E, 2 * E + 3 * F, 4 * F}
                                              : cg::json{V + F + E, 2 * E + corners, corners}));
        CHECK(p.answers == std::vector<std::string>{"focus_point", "counts/1"});
    }
    CHECK(faces > 20);
    CHECK(edges > 60);
    CHECK(vertices > 60);
    CHECK(loops > 60);
}

TEST_CASE("subdivision-surface: the picture — the mesh, the new points, the rule's weights",
          "[modelling][subdivision-surface]") {
    Input in = make(cube(), S::Scheme::CatmullClark, 1);
    in.focus = S::FocusKind::Vertex;
    in.focus_a = 6;
    auto s = S::start(in);
    for (int i = 0; i < 4; ++i) S::step(s, nullptr);  // split, faces, edges, vertices
    cg::Scene scene;
    S::draw(s, scene);
    CHECK(scene.faces3.size() == 6);
    int teal = 0, magenta = 0, weights = 0;
    for (const auto& p : scene.points3) {
        teal += p.style.role == cg::Role::Entering;
        magenta += p.style.role == cg::Role::Leaving;
        weights += p.label.find(" ×1/9") != std::string::npos;
    }
    CHECK(teal == 6);
    CHECK(magenta == 12);
    CHECK(weights == 6);  // three neighbours and three face points at 1/9
    bool moved = false;
    for (const auto& p : scene.points3) moved = moved || (p.label == "V6'" && p.p == s.points.vertex[6]);
    CHECK(moved);
    S::step(s, nullptr);  // connect
    cg::Scene after;
    S::draw(s, after);
    CHECK(after.faces3.size() == 24);
    CHECK(after.faces3[0].style.role == cg::Role::Kept);
    // Everything finite at the largest preset size.
    auto big = S::start(make(octahedron(), S::Scheme::Loop, 5));
    while (!S::done(big)) S::step(big, nullptr);
    cg::Scene all;
    S::draw(big, all);
    CHECK(all.faces3.size() == 8192);
    for (const auto& f : all.faces3)
        for (const auto& q : f.points) CHECK(std::isfinite(q.x + q.y + q.z));
}
