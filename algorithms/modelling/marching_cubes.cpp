// Sections: [geometry] [table] [field] [cube] [spec] [validate] [advance] [narrate]
//           [result and compute]   (the picture is in marching_cubes_draw.cpp)
#include "modelling/marching_cubes.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using MC = MarchingCubes;
using Input = MC::Input;
using Grid = MC::Grid;
using Phase = MC::Phase;
using State = MC::State;
using Field = MC::Field;
using Row = MC::Row;

enum Line { kLineSample = 1, kLineCase, kLineFace, kLineCross, kLineEmit, kLineReport };

constexpr std::array<std::array<int, 3>, 8> kCorner = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
constexpr std::array<std::array<int, 2>, 12> kEdge = {{{0, 1}, {1, 2}, {3, 2}, {0, 3},
                                                       {4, 5}, {5, 6}, {7, 6}, {4, 7},
                                                       {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
// Faces x = 0, x = 1, y = 0, y = 1, z = 0, z = 1, corners counter-clockwise seen from outside
// (the right-hand rule gives the outward normal).
constexpr std::array<std::array<int, 4>, 6> kFace = {{{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                                      {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}}};
// The same corners by position in the face's plane, lower axis first: (0,0), (1,0), (0,1), (1,1).
// Opposite faces list corners at the same in-plane positions, so a face shared by two cubes is
// summed in the same order by both.
constexpr std::array<std::array<int, 4>, 6> kFaceSum = {{{0, 3, 4, 7}, {1, 2, 5, 6}, {0, 1, 4, 5},
                                                         {3, 2, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}}};
constexpr const char* kFaceName[6] = {"x = 0", "x = 1", "y = 0", "y = 1", "z = 0", "z = 1"};

constexpr int edge_between(int a, int b) {
    for (int e = 0; e < 12; ++e)
        if ((kEdge[std::size_t(e)][0] == a && kEdge[std::size_t(e)][1] == b) ||
            (kEdge[std::size_t(e)][0] == b && kEdge[std::size_t(e)][1] == a))
            return e;
    return -1;
}

constexpr std::array<std::array<int, 4>, 6> make_face_edges() {
    std::array<std::array<int, 4>, 6> fe{};
    for (int F = 0; F < 6; ++F)
        for (int m = 0; m < 4; ++m)
            fe[std::size_t(F)][std::size_t(m)] =
                edge_between(kFace[std::size_t(F)][std::size_t(m)], kFace[std::size_t(F)][std::size_t((m + 1) % 4)]);
    return fe;
}
constexpr std::array<std::array<int, 4>, 6> kFaceEdge = make_face_edges();

// Bit F set when edge e lies on face F.
int edge_faces(int e) {
    int m = 0;
    for (int F = 0; F < 6; ++F)
        for (int k = 0; k < 4; ++k) m |= int(kFaceEdge[std::size_t(F)][std::size_t(k)] == e) << F;
    return m;
}

bool crossed_case(int index) {
    return index != 0 && index != 255;
}

std::string bits_text(int index) {
    std::string b;
    for (int k = 7; k >= 0; --k) b += (index >> k & 1) ? '1' : '0';
    return b;
}

}  // namespace

// ---- [geometry] -----------------------------------------------------------------------------

const std::array<std::array<int, 3>, 8>& MarchingCubes::corner_offset() { return kCorner; }
const std::array<std::array<int, 2>, 12>& MarchingCubes::edge_ends() { return kEdge; }
const std::array<std::array<int, 4>, 6>& MarchingCubes::face_corners() { return kFace; }
const std::array<std::array<int, 4>, 6>& MarchingCubes::face_edges() { return kFaceEdge; }
const std::array<std::array<int, 4>, 6>& MarchingCubes::face_sum_order() { return kFaceSum; }

int MarchingCubes::ambiguous_faces(int index) {
    int m = 0;
    for (int F = 0; F < 6; ++F) {
        const auto& c = kFace[std::size_t(F)];
        const int b0 = index >> c[0] & 1, b1 = index >> c[1] & 1, b2 = index >> c[2] & 1,
                  b3 = index >> c[3] & 1;
        m |= int(b0 == b2 && b1 == b3 && b0 != b1) << F;
    }
    return m;
}

// Marching squares on one face, seen from outside: walking the face's corners in order, a
// segment runs from an edge where the walk leaves the inside to one where it enters it. A
// saddle pairs a leaving edge with the next edge (joined: the outside corner between them cut
// off) or with the edge before it (separated: the inside corner cut off).
int MarchingCubes::face_segments(int index, int face, bool joined,
                                 std::array<std::array<int, 2>, 2>& seg) {
    const auto& c = kFace[std::size_t(face)];
    const auto& fe = kFaceEdge[std::size_t(face)];
    auto in = [&](int m) { return (index >> c[std::size_t(m % 4)] & 1) != 0; };
    int leave[2], enter[2], nl = 0, ne = 0;
    for (int m = 0; m < 4; ++m) {
        if (in(m) && !in(m + 1)) leave[nl++] = m;
        if (!in(m) && in(m + 1)) enter[ne++] = m;
    }
    if (nl == 1) {
        seg[0] = {fe[std::size_t(leave[0])], fe[std::size_t(enter[0])]};
        return 1;
    }
    for (int k = 0; k < nl; ++k) {
        const int m = leave[k];
        const int partner = joined ? (m + 1) % 4 : (m + 3) % 4;
        seg[std::size_t(k)] = {fe[std::size_t(m)], fe[std::size_t(partner)]};
    }
    return nl;
}

// ---- [table] --------------------------------------------------------------------------------

namespace {

// A chord of the polygon may join two crossings only when they share no face of the cube: two
// crossings on one face joined by a chord would put an edge inside that face, where the
// neighbouring cube could draw it too (and cross its segments). A fan from one apex is used
// when some apex has only such chords; otherwise (a few long cycles of saddle cases) the
// polygon is cut by the first allowed chord into two smaller ones, recursively.
bool chord_ok(int a, int b) {
    return (edge_faces(a) & edge_faces(b)) == 0;
}

// Can the polygon v[i], v[i+1], …, v[j] (closed by the chord or side j → i) be triangulated
// with allowed chords only? (Memoised on the pair; n ≤ 12.)
bool splittable(const int* v, int i, int j, signed char (&memo)[12][12]) {
    if (j - i < 2) return true;
    if (memo[i][j] >= 0) return memo[i][j] != 0;
    bool ok = false;
    for (int k = i + 1; k < j && !ok; ++k)
        ok = (k == i + 1 || chord_ok(v[i], v[k])) && (k == j - 1 || chord_ok(v[k], v[j])) &&
             splittable(v, i, k, memo) && splittable(v, k, j, memo);
    memo[i][j] = ok ? 1 : 0;
    return ok;
}

void split(const int* v, int i, int j, signed char (&memo)[12][12], Row& row) {
    if (j - i < 2) return;
    for (int k = i + 1; k < j; ++k)
        if ((k == i + 1 || chord_ok(v[i], v[k])) && (k == j - 1 || chord_ok(v[k], v[j])) &&
            splittable(v, i, k, memo) && splittable(v, k, j, memo)) {
            row.tri[std::size_t(row.triangles++)] = {std::uint8_t(v[i]), std::uint8_t(v[k]),
                                                     std::uint8_t(v[j])};
            split(v, i, k, memo, row);
            split(v, k, j, memo, row);
            return;
        }
}

void triangulate(const int* cyc, int n, int cycle_number, Row& row) {
    for (int a = 0; a < n; ++a) {
        bool ok = true;
        for (int k = 2; k < n - 1 && ok; ++k) ok = chord_ok(cyc[a], cyc[(a + k) % n]);
        if (!ok) continue;
        for (int k = 1; k + 1 < n; ++k)
            row.tri[std::size_t(row.triangles++)] = {std::uint8_t(cyc[a]),
                                                     std::uint8_t(cyc[(a + k) % n]),
                                                     std::uint8_t(cyc[(a + k + 1) % n])};
        return;
    }
    // No fan: rotate so that the polygon can be split, then split it.
    for (int a = 0; a < n; ++a) {
        int v[12];
        for (int k = 0; k < n; ++k) v[k] = cyc[(a + k) % n];
        signed char memo[12][12];
        std::fill(&memo[0][0], &memo[0][0] + 144, (signed char)-1);
        if (splittable(v, 0, n - 1, memo)) {
            split(v, 0, n - 1, memo, row);
            return;
        }
    }
    // No triangulation keeps every chord off the faces (a cycle that meets a separated saddle
    // face twice, running round a bent chain of inside corners): fan it round its centre, a
    // new point inside the cube (the average of its crossings), numbered 12 + the cycle.
    row.centres |= 1 << cycle_number;
    for (int k = 0; k < n; ++k)
        row.tri[std::size_t(row.triangles++)] = {std::uint8_t(12 + cycle_number),
                                                 std::uint8_t(cyc[k]),
                                                 std::uint8_t(cyc[(k + 1) % n])};
}

// The face segments of a case, chained into cycles, each fanned into triangles.
Row generate(int index, int joined) {
    Row row;
    int next[12];
    std::fill(next, next + 12, -1);
    for (int F = 0; F < 6; ++F) {
        std::array<std::array<int, 2>, 2> seg{};
        const int n = MC::face_segments(index, F, (joined >> F & 1) != 0, seg);
        for (int s = 0; s < n; ++s) next[seg[std::size_t(s)][0]] = seg[std::size_t(s)][1];
    }
    bool seen[12] = {};
    int used = 0;
    for (int e0 = 0; e0 < 12; ++e0) {
        if (next[e0] < 0 || seen[e0]) continue;
        int cyc[12], n = 0;
        for (int e = e0; !seen[e]; e = next[e]) {
            seen[e] = true;
            cyc[n++] = e;
        }
        // The walk has the inside on its left seen from outside the cube, i.e. it turns
        // counter-clockwise seen from the inside; reversed, it is counter-clockwise from outside.
        std::reverse(cyc, cyc + n);
        row.length[std::size_t(row.cycles++)] = std::uint8_t(n);
        for (int k = 0; k < n; ++k) row.cycle[std::size_t(used + k)] = std::uint8_t(cyc[k]);
        used += n;
        triangulate(cyc, n, row.cycles - 1, row);
    }
    return row;
}

struct Table {
    std::vector<Row> rows;  // 256 × 64: the case, then the face decisions
    Table() : rows(256 * 64) {
        for (int c = 0; c < 256; ++c) {
            const int amb = MC::ambiguous_faces(c);
            for (int j = 0; j < 64; ++j)
                if ((j & ~amb) == 0) rows[std::size_t(c * 64 + j)] = generate(c, j);
        }
    }
};

}  // namespace

const MarchingCubes::Row& MarchingCubes::table(int index, int joined) {
    static const Table t;
    return t.rows[std::size_t((index & 255) * 64 + (joined & ambiguous_faces(index & 255)))];
}

// ---- [field] --------------------------------------------------------------------------------

double MarchingCubes::field_value(const Input& in, glm::dvec3 p) {
    const double r2 = in.radius * in.radius;
    switch (in.field) {
        case Field::Sphere:
            return p.x * p.x + p.y * p.y + p.z * p.z - r2;
        case Field::Torus: {
            const double q = std::sqrt(p.x * p.x + p.y * p.y) - 0.6;
            return q * q + p.z * p.z - r2;
        }
        case Field::Blobs: {
            const glm::dvec3 a = p - glm::dvec3(-0.4, 0, 0), b = p - glm::dvec3(0.4, 0, 0);
            return 0.5 - std::exp(-glm::dot(a, a) / r2) - std::exp(-glm::dot(b, b) / r2);
        }
        case Field::Gyroid: {
            const double w = 2 * M_PI;
            return std::sin(w * p.x) * std::cos(w * p.y) + std::sin(w * p.y) * std::cos(w * p.z) +
                   std::sin(w * p.z) * std::cos(w * p.x);
        }
        case Field::Grid:
            break;
    }
    return 0;
}

MarchingCubes::Grid MarchingCubes::sample(const Input& in) {
    Grid g;
    if (in.field == Field::Grid) {
        g.nz = int(in.values.size()) - 1;
        g.ny = int(in.values[0].size()) - 1;
        g.nx = int(in.values[0][0].size()) - 1;
        g.f.reserve(std::size_t(g.nx + 1) * std::size_t(g.ny + 1) * std::size_t(g.nz + 1));
        for (const auto& layer : in.values)
            for (const auto& row : layer) g.f.insert(g.f.end(), row.begin(), row.end());
        return g;
    }
    g.nx = g.ny = g.nz = in.cells;
    g.origin = {-1, -1, -1};
    g.h = 2.0 / in.cells;
    g.f.resize(std::size_t(g.nx + 1) * std::size_t(g.ny + 1) * std::size_t(g.nz + 1));
    for (int k = 0; k <= g.nz; ++k)
        for (int j = 0; j <= g.ny; ++j)
            for (int i = 0; i <= g.nx; ++i) g.f[g.index(i, j, k)] = field_value(in, g.point(i, j, k));
    return g;
}

// ---- [cube] ---------------------------------------------------------------------------------

int MarchingCubes::case_index(const Grid& g, int i, int j, int k, double iso) {
    int index = 0;
    for (int c = 0; c < 8; ++c) {
        const auto& o = kCorner[std::size_t(c)];
        index |= int(g.at(i + o[0], j + o[1], k + o[2]) < iso) << c;
    }
    return index;
}

int MarchingCubes::edge_id(const Grid& g, int i, int j, int k, int edge) {
    const auto& a = kCorner[std::size_t(kEdge[std::size_t(edge)][0])];
    const auto& b = kCorner[std::size_t(kEdge[std::size_t(edge)][1])];
    const int axis = b[0] != a[0] ? 0 : b[1] != a[1] ? 1 : 2;
    return 3 * int(g.index(i + a[0], j + a[1], k + a[2])) + axis;
}

MarchingCubes::Cube MarchingCubes::march(const Grid& g, int i, int j, int k, double iso) {
    Cube c;
    c.i = i;
    c.j = j;
    c.k = k;
    for (int n = 0; n < 8; ++n) {
        const auto& o = kCorner[std::size_t(n)];
        c.f[std::size_t(n)] = g.at(i + o[0], j + o[1], k + o[2]);
        c.index |= int(c.f[std::size_t(n)] < iso) << n;
    }
    if (!crossed_case(c.index)) {
        c.row = &table(c.index, 0);
        return c;
    }
    for (int e = 0; e < 12; ++e) {
        const int a = kEdge[std::size_t(e)][0], b = kEdge[std::size_t(e)][1];
        const double fa = c.f[std::size_t(a)], fb = c.f[std::size_t(b)];
        if ((fa < iso) == (fb < iso)) continue;
        const double t = (iso - fa) / (fb - fa);
        const auto& oa = kCorner[std::size_t(a)];
        const auto& ob = kCorner[std::size_t(b)];
        const glm::dvec3 pa = g.point(i + oa[0], j + oa[1], k + oa[2]);
        const glm::dvec3 pb = g.point(i + ob[0], j + ob[1], k + ob[2]);
        c.crossed |= 1 << e;
        c.t[std::size_t(e)] = t;
        c.p[std::size_t(e)] = pa + t * (pb - pa);
    }
    c.ambiguous = ambiguous_faces(c.index);
    for (int F = 0; F < 6; ++F) {
        if (!(c.ambiguous >> F & 1)) continue;
        const auto& o = kFaceSum[std::size_t(F)];
        const double m = 0.25 * ((c.f[std::size_t(o[0])] + c.f[std::size_t(o[1])]) +
                                 (c.f[std::size_t(o[2])] + c.f[std::size_t(o[3])]));
        c.centre[std::size_t(F)] = m;
        c.joined |= int(m < iso) << F;
    }
    c.row = &table(c.index, c.joined);
    return c;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& MarchingCubes::spec() {
    static const Spec spec{
        "marching-cubes",
        "Marching cubes: the surface of a sampled field, cube by cube",
        "Modelling",
        {
            "sample f at every grid point; a point is inside when f < iso",
            "for each cube: case ← Σ b_k·2^k   ▷ b_k = 1 when corner k is inside, k = 0 … 7",
            "for each face whose inside corners are diagonal: m ← average of its four corners; "
            "join them when m < iso",
            "on each edge a→b whose corners differ: t ← (iso − f_a)/(f_b − f_a), p ← a + t·(b − a)",
            "emit the table's triangles for the case (face segments traced into cycles, fanned)",
            "report the triangles, the area, the enclosed volume and whether the mesh is closed",
        },
        {
            {"sample", "the field sampled at every grid point, each marked inside or outside"},
            {"cube", "a cube the surface crosses: its case, crossings and triangles"},
            {"ambiguous", "a crossed cube with a saddle face, decided by the face-centre average"},
            {"empty", "a run of cubes the surface does not cross (case 0 or 255)"},
            {"batch", "many cubes in one step (after the first steps)"},
            {"summary", "the triangles, the area, the volume, open and non-manifold edges"},
        },
        {},
        {
            .predict = {{"cube", {"case"}}, {"ambiguous", {"case", "joined_faces"}}},
            .mistakes =
                {
                    {"cube", "t", "swap:one_minus_t",
                     "measured t from the wrong end of the edge (1 − t instead of t)"},
                    {"cube", "case", "keep", "kept the case of the cube before"},
                    {"ambiguous", "t", "swap:one_minus_t",
                     "measured t from the wrong end of the edge in a cube with a saddle face"},
                },
            .variants = {{"iso 0", "/iso", "0"}, {"iso 0.1", "/iso", "0.1"}},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void MarchingCubes::validate(const Input& in) {
    if (!std::isfinite(in.iso) || std::fabs(in.iso) > kMaxValue)
        throw InputError("iso", "must be a finite number of at most 1e100 in size");
    const std::size_t most = std::size_t(kMaxCells) + 1;
    if (in.field == Field::Grid) {
        const auto& v = in.values;
        if (v.size() < 2)
            throw InputError("values", "needs at least 2 layers (one cube), got " +
                                           std::to_string(v.size()));
        if (v.size() > most)
            throw InputError("values", "has " + std::to_string(v.size()) + " layers; at most " +
                                           std::to_string(most));
        const std::size_t h = v[0].size();
        if (h < 2) throw InputError("values[0]", "needs at least 2 rows (one cube)");
        if (h > most)
            throw InputError("values[0]", "has " + std::to_string(h) + " rows; at most " +
                                              std::to_string(most));
        const std::size_t w = v[0][0].size();
        if (w < 2) throw InputError("values[0][0]", "needs at least 2 values (one cube)");
        if (w > most)
            throw InputError("values[0][0]", "has " + std::to_string(w) + " values; at most " +
                                                 std::to_string(most));
        for (std::size_t k = 0; k < v.size(); ++k) {
            const std::string layer = "values[" + std::to_string(k) + "]";
            if (v[k].size() != h)
                throw InputError(layer, "has " + std::to_string(v[k].size()) +
                                            " rows, layer 0 has " + std::to_string(h) +
                                            ": every layer the same size");
            for (std::size_t j = 0; j < h; ++j) {
                const std::string row = layer + "[" + std::to_string(j) + "]";
                if (v[k][j].size() != w)
                    throw InputError(row, "has " + std::to_string(v[k][j].size()) +
                                              " values, row 0 has " + std::to_string(w) +
                                              ": every row the same length");
                for (std::size_t i = 0; i < w; ++i)
                    if (!std::isfinite(v[k][j][i]) || std::fabs(v[k][j][i]) > kMaxValue)
                        throw InputError(row + "[" + std::to_string(i) + "]",
                                         "must be a finite number of at most 1e100 in size");
            }
        }
        return;
    }
    if (in.cells < 1 || in.cells > kMaxCells)
        throw InputError("cells", "must be 1 to " + std::to_string(kMaxCells) + " (got " +
                                      std::to_string(in.cells) + ")");
    if (!(in.radius > 0) || in.radius > 10)
        throw InputError("radius", "must be above 0 and at most 10");
}

MarchingCubes::State MarchingCubes::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

MarchingCubes::State MarchingCubes::begin(Shared<Input> shared) {
    State s;
    s.grid = Shared<Grid>(sample(*shared));
    s.in = std::move(shared);
    const Grid& g = *s.grid;
    s.cases.reserve(std::size_t(g.nx) * std::size_t(g.ny) * std::size_t(g.nz));
    s.edge_vertex.assign(3 * g.f.size(), -1);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

namespace {

// The running mesh: the state machine and compute share it.
struct Mesh {
    std::vector<glm::dvec3>& vertices;
    std::vector<int>& vertex_edge;
    std::vector<int>& edge_vertex;
    std::vector<std::array<int, 3>>& triangles;
    long long& ambiguous;
    long long& joined;
    double& area;
    double& volume;
};

// One crossed cube into the mesh: its crossings as vertices (a grid edge met before keeps its
// vertex), then its triangles, their area and their share of the volume (p0 · (p1 × p2))/6.
inline void emit(const Grid& g, int i, int j, int k, double iso, Mesh& m) {
    const MC::Cube c = MC::march(g, i, j, k, iso);
    int v[16];
    glm::dvec3 p[16];
    for (int e = 0; e < 12; ++e) {
        if (!(c.crossed >> e & 1)) continue;
        const int id = MC::edge_id(g, i, j, k, e);
        int& slot = m.edge_vertex[std::size_t(id)];
        if (slot < 0) {
            slot = int(m.vertices.size());
            m.vertices.push_back(c.p[std::size_t(e)]);
            m.vertex_edge.push_back(id);
        }
        v[e] = slot;
        p[e] = c.p[std::size_t(e)];
    }
    // A cycle fanned round its centre: the average of its crossings, a vertex of its own.
    const MC::Row& row = *c.row;
    for (int q = 0, at = 0; q < row.cycles; at += row.length[std::size_t(q)], ++q) {
        if (!(row.centres >> q & 1)) continue;
        glm::dvec3 sum(0);
        for (int n = 0; n < row.length[std::size_t(q)]; ++n) sum += p[row.cycle[std::size_t(at + n)]];
        p[12 + q] = sum / double(row.length[std::size_t(q)]);
        v[12 + q] = int(m.vertices.size());
        m.vertices.push_back(p[12 + q]);
        m.vertex_edge.push_back(-1);
    }
    for (int F = 0; F < 6; ++F) {
        m.ambiguous += c.ambiguous >> F & 1;
        m.joined += c.joined >> F & 1;
    }
    for (int n = 0; n < c.row->triangles; ++n) {
        const auto& t = c.row->tri[std::size_t(n)];
        const std::array<int, 3> tri = {v[t[0]], v[t[1]], v[t[2]]};
        const glm::dvec3 a = p[t[0]], b = p[t[1]], d = p[t[2]];
        m.area += 0.5 * glm::length(glm::cross(b - a, d - a));
        m.volume += glm::dot(a, glm::cross(b, d)) / 6;
        m.triangles.push_back(tri);
    }
}

// Mesh edges: how many, how many on one triangle only (open), on more than two (non-manifold).
void count_edges(const std::vector<std::array<int, 3>>& tris, long long& edges,
                 long long& boundary, long long& nonmanifold) {
    std::vector<std::uint64_t> keys;
    keys.reserve(3 * tris.size());
    for (const auto& t : tris)
        for (int e = 0; e < 3; ++e) {
            const auto a = std::uint64_t(t[std::size_t(e)]), b = std::uint64_t(t[std::size_t((e + 1) % 3)]);
            keys.push_back(std::min(a, b) << 32 | std::max(a, b));
        }
    std::sort(keys.begin(), keys.end());
    edges = boundary = nonmanifold = 0;
    for (std::size_t a = 0; a < keys.size();) {
        std::size_t b = a;
        while (b < keys.size() && keys[b] == keys[a]) ++b;
        ++edges;
        boundary += b - a == 1;
        nonmanifold += b - a > 2;
        a = b;
    }
}

}  // namespace

void MarchingCubes::advance(State& s) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    Mesh m{s.vertices, s.vertex_edge, s.edge_vertex, s.triangles,
           s.ambiguous, s.joined,     s.area,        s.volume};
    switch (s.phase) {
        case Phase::Sample:
            s.last = Phase::Sample;
            s.phase = Phase::Cubes;
            return;
        case Phase::Cubes: {
            const int total = g.nx * g.ny * g.nz;
            if (s.batch == 0 && s.steps >= kStepped)
                s.batch = std::max(1, (total - s.next + kBatches - 1) / kBatches);
            s.from = s.next;
            s.tri_from = s.triangles.size();
            int c = s.next;
            while (c < total) {
                const int i = c % g.nx, j = c / g.nx % g.ny, k = c / (g.nx * g.ny);
                const int index = case_index(g, i, j, k, in.iso);
                const bool crossed = crossed_case(index);
                if (s.batch == 0 && crossed && c > s.from) break;  // a run ends before it
                s.cases.push_back(std::uint8_t(index));
                if (crossed) emit(g, i, j, k, in.iso, m);
                ++c;
                if (s.batch ? c - s.from == s.batch : crossed) break;
            }
            s.next = c;
            ++s.steps;
            s.last = Phase::Cubes;
            if (c == total) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:
            count_edges(s.triangles, s.edges, s.boundary, s.nonmanifold);
            s.euler = (long long)s.vertices.size() - s.edges + (long long)s.triangles.size();
            s.last = Phase::Summary;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

long long inside_count(const Grid& g, double iso) {
    long long n = 0;
    for (double v : g.f) n += v < iso;
    return n;
}

const char* field_name(Field f) {
    switch (f) {
        case Field::Grid: return "the given grid of values";
        case Field::Sphere: return "the sphere f = x² + y² + z² − r²";
        case Field::Torus: return "the torus f = (√(x² + y²) − 0.6)² + z² − r²";
        case Field::Blobs: return "two blobs f = ½ − Σ exp(−|p − c_k|²/r²)";
        case Field::Gyroid: return "the gyroid-like f = sin 2πx cos 2πy + sin 2πy cos 2πz + sin 2πz cos 2πx";
    }
    return "";
}

std::string cube_name(const Grid& g, int c) {
    return "(" + std::to_string(c % g.nx) + ", " + std::to_string(c / g.nx % g.ny) + ", " +
           std::to_string(c / (g.nx * g.ny)) + ")";
}

void narrate_cube(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    const int n = s.from;
    const MC::Cube c = MC::march(g, n % g.nx, n / g.nx % g.ny, n / (g.nx * g.ny), in.iso);
    const bool amb = c.ambiguous != 0;
    info.event = amb ? "ambiguous" : "cube";
    info.line = amb ? kLineFace : kLineEmit;
    std::string corners;
    for (int k = 0; k < 8; ++k)
        corners += (k ? ", " : "") + std::string("f") + std::to_string(k) + " = " +
                   num(c.f[std::size_t(k)]) + (c.f[std::size_t(k)] < in.iso ? " (in)" : "");
    std::string text = "Cube " + cube_name(g, n) + ": " + corners + " against iso = " +
                       num(in.iso) + "; bits b7…b0 = " + bits_text(c.index) + ", so case " +
                       std::to_string(c.index) + ".";
    for (int F = 0; F < 6; ++F)
        if (c.ambiguous >> F & 1)
            text += " Face " + std::string(kFaceName[F]) + " is a saddle: its centre average " +
                    num(c.centre[std::size_t(F)]) + ((c.joined >> F & 1) ? " < iso, joined." : " ≥ iso, separated.");
    std::string crossings;
    std::vector<std::vector<double>> points;
    std::vector<double> edges;
    double first_t = 0;
    bool have_t = false;
    for (int e = 0; e < 12; ++e) {
        if (!(c.crossed >> e & 1)) continue;
        if (!have_t) first_t = c.t[std::size_t(e)];
        have_t = true;
        const glm::dvec3 p = c.p[std::size_t(e)];
        crossings += std::string(crossings.empty() ? "" : "; ") + "e" + std::to_string(e) +
                     " t = " + num(c.t[std::size_t(e)]) + " at " + num(p);
        points.push_back({p.x, p.y, p.z});
        edges.push_back(e);
    }
    text += " Crossings (t = (iso − f_a)/(f_b − f_a)): " + crossings + ".";
    const Row& r = *c.row;
    std::string cycles;
    for (int q = 0, at = 0; q < r.cycles; at += r.length[std::size_t(q)], ++q) {
        cycles += q ? ", " : "";
        for (int k = 0; k < r.length[std::size_t(q)]; ++k)
            cycles += (k ? "–" : "") + std::string("e") + std::to_string(r.cycle[std::size_t(at + k)]);
    }
    text += " The face segments close into " + std::to_string(r.cycles) +
            (r.cycles == 1 ? " polygon " : " polygons ") + cycles + ", fanned into " +
            std::to_string(r.triangles) + (r.triangles == 1 ? " triangle" : " triangles") +
            (r.centres ? " (a polygon that cannot be cut without a diagonal lying in a face of "
                         "the cube is fanned round its centre, the average of its crossings)."
                       : ".");
    info.narration = text;
    info.math = "\\text{case} = \\sum_{k=0}^{7} b_k 2^k = " + std::to_string(c.index);
    info.vars = {{"cube", std::vector<double>{double(c.i), double(c.j), double(c.k)}},
                 {"case", (long long)c.index},
                 {"bits", bits_text(c.index)},
                 {"corners", std::vector<double>(c.f.begin(), c.f.end())},
                 {"edges", edges},
                 {"t", first_t},
                 {"one_minus_t", 1 - first_t},
                 {"crossings", points},
                 {"triangles_here", (long long)r.triangles}};
    if (amb) info.vars.push_back({"joined_faces", (long long)c.joined});
    info.vars.push_back({"triangles", (long long)s.triangles.size()});
}

void narrate_run(const State& s, StepInfo& info, bool batch) {
    const Grid& g = *s.grid;
    const int n = s.next - s.from;
    info.event = batch ? "batch" : "empty";
    info.line = batch ? kLineEmit : kLineCase;
    const std::size_t added = s.triangles.size() - s.tri_from;
    const std::string range = n == 1 ? "Cube " + cube_name(g, s.from)
                                     : "Cubes " + cube_name(g, s.from) + " to " +
                                           cube_name(g, s.next - 1) + " (" + std::to_string(n) +
                                           " cubes)";
    if (batch) {
        info.narration = range + " in one step: " + std::to_string(added) +
                         " triangles added, " + std::to_string(s.triangles.size()) +
                         " so far. After the first " + std::to_string(MC::kStepped) +
                         " steps the rest go in batches.";
    } else {
        int inside = 0;
        for (int c = s.from; c < s.next; ++c) inside += s.cases[std::size_t(c)] == 255;
        info.narration = range + ": " +
                         (inside == n   ? std::string("every corner inside (case 255)")
                          : inside == 0 ? std::string("every corner outside (case 0)")
                                        : std::to_string(inside) +
                                              " all inside (case 255), the rest all outside "
                                              "(case 0)") +
                         ". No edge changes sign, so the surface does not pass through.";
    }
    info.vars = {{"cubes", (long long)n},
                 {"added", (long long)added},
                 {"triangles", (long long)s.triangles.size()}};
}

void narrate_summary(const State& s, StepInfo& info) {
    info.event = "summary";
    info.line = kLineReport;
    const bool closed = s.boundary == 0 && s.nonmanifold == 0;
    info.narration =
        std::to_string(s.triangles.size()) + " triangles on " + std::to_string(s.vertices.size()) +
        " vertices, area " + num(s.area) + ", enclosed volume " + num(s.volume) + "; " +
        std::to_string(s.edges) + " edges, " + std::to_string(s.boundary) +
        " on one triangle only (where the surface leaves the grid), " +
        std::to_string(s.nonmanifold) + " on more than two; " +
        (closed ? "the mesh is closed and manifold, " : "") + "Euler characteristic V − E + F = " +
        std::to_string(s.euler) + ". " + std::to_string(s.ambiguous) + " saddle faces met (" +
        std::to_string(s.joined) + " joined).";
    info.math = "A = " + tex(s.area) + ",\\ V = " + tex(s.volume);
    info.vars = {{"triangles", (long long)s.triangles.size()},
                 {"vertices", (long long)s.vertices.size()},
                 {"area", s.area},
                 {"volume", s.volume},
                 {"boundary", s.boundary},
                 {"euler", s.euler}};
}

}  // namespace

void MarchingCubes::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    switch (s.last) {
        case Phase::Sample: {
            const long long inside = inside_count(g, in.iso);
            info.event = "sample";
            info.line = kLineSample;
            info.narration = "Sample " + std::string(field_name(in.field)) + " at the " +
                             std::to_string(g.f.size()) + " points of a " + std::to_string(g.nx) +
                             " × " + std::to_string(g.ny) + " × " + std::to_string(g.nz) +
                             " grid (spacing " + num(g.h) + "): " + std::to_string(inside) +
                             " are inside (f < " + num(in.iso) + "), the rest outside.";
            info.vars = {{"cubes", (long long)(g.nx * g.ny * g.nz)},
                         {"inside", inside},
                         {"iso", in.iso}};
            return;
        }
        case Phase::Cubes:
            if (s.batch == 0 && s.next - s.from == 1 && crossed_case(s.cases[std::size_t(s.from)]))
                narrate_cube(s, info);
            else
                narrate_run(s, info, s.batch != 0);
            return;
        case Phase::Summary:
        case Phase::Done:
            narrate_summary(s, info);
            return;
    }
}

void MarchingCubes::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compute] -------------------------------------------------------------------

namespace {

template <class S>
MC::Result make_result(S&& s) {
    MC::Result r;
    r.nx = s.grid->nx;
    r.ny = s.grid->ny;
    r.nz = s.grid->nz;
    r.inside = inside_count(*s.grid, s.in->iso);
    r.cases = std::forward<S>(s).cases;
    r.vertices = std::forward<S>(s).vertices;
    r.vertex_edge = std::forward<S>(s).vertex_edge;
    r.triangles = std::forward<S>(s).triangles;
    r.ambiguous = s.ambiguous;
    r.joined = s.joined;
    r.area = s.area;
    r.volume = s.volume;
    r.edges = s.edges;
    r.boundary = s.boundary;
    r.nonmanifold = s.nonmanifold;
    r.euler = s.euler;
    return r;
}

}  // namespace

MarchingCubes::Result MarchingCubes::result(const State& s) { return make_result(s); }
MarchingCubes::Result MarchingCubes::result(State&& s) { return make_result(std::move(s)); }

MarchingCubes::Result MarchingCubes::compute(const Input& in) {
    const Grid g = sample(in);
    Result r;
    r.nx = g.nx;
    r.ny = g.ny;
    r.nz = g.nz;
    r.cases.reserve(std::size_t(g.nx) * std::size_t(g.ny) * std::size_t(g.nz));
    std::vector<int> edge_vertex(3 * g.f.size(), -1);
    Mesh m{r.vertices, r.vertex_edge, edge_vertex, r.triangles, r.ambiguous, r.joined, r.area, r.volume};
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const int index = case_index(g, i, j, k, in.iso);
                r.cases.push_back(std::uint8_t(index));
                if (crossed_case(index)) emit(g, i, j, k, in.iso, m);
            }
    r.inside = inside_count(g, in.iso);
    count_edges(r.triangles, r.edges, r.boundary, r.nonmanifold);
    r.euler = (long long)r.vertices.size() - r.edges + (long long)r.triangles.size();
    return r;
}

}  // namespace cg
