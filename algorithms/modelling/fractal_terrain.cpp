// Sections: [walk] [spec] [validate] [advance] [narrate] [result and compute] [draw]
#include "modelling/fractal_terrain.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "rays/mesh_gen.hpp"

namespace cg {

using Input = FractalTerrain::Input;
using State = FractalTerrain::State;
using Phase = FractalTerrain::Phase;
using Last = FractalTerrain::Last;
using fractal::Method;
using fractal::Visit;

// ---- [walk] ---------------------------------------------------------------------------------
// Level L works on cells (or triangles) of side s = N / 2^(L−1); its new points are those of
// the lattice of spacing s/2 that are not on the lattice of spacing s.

namespace fractal {

namespace {

int spacing(int N, int level) {
    return N >> (level - 1);
}

// The triangle's next new point of the level, row by row; (i, j) = (−s/2, 0) gives the first.
bool next_triangle(int N, int s, int& i, int& j) {
    const int h = s / 2;
    for (;;) {
        i += h;
        if (i + j > N) {
            j += h;
            i = -h;
            if (j > N) return false;
            continue;
        }
        if (i % s != 0 || j % s != 0) return true;
    }
}

// The grid's next new point of the phase: the diamonds (cell centres) row by row, then the
// squares (edge midpoints) row by row, each row of the squares starting at s/2 or at 0.
bool next_grid(int N, int s, Visit& v) {
    const int h = s / 2;
    if (v.phase == 0) {
        v.i += s;
        if (v.i < N) return true;
        v.i = h;
        v.j += s;
        if (v.j < N) return true;
        v.phase = 1;
        v.i = h;
        v.j = 0;
        return true;
    }
    v.i += s;
    if (v.i <= N) return true;
    v.j += h;
    if (v.j > N) return false;
    v.i = (v.j / h) % 2 == 0 ? h : 0;
    return true;
}

Visit first_of(Method m, int N, int level) {
    Visit v;
    v.level = level;
    const int s = spacing(N, level);
    if (m == Method::Grid) {
        v.i = v.j = s / 2;
    } else {
        v.i = -s / 2;
        v.j = 0;
        next_triangle(N, s, v.i, v.j);  // (s/2, 0): the first edge's midpoint
    }
    return v;
}

}  // namespace

Visit first(Method m, int N) {
    return first_of(m, N, 1);
}

Visit first_at(Method m, int N, int level) {
    return first_of(m, N, level);
}

bool advance(Method m, int N, Visit& v) {
    const int s = spacing(N, v.level);
    const bool more = m == Method::Grid ? next_grid(N, s, v) : next_triangle(N, s, v.i, v.j);
    if (more) return true;
    if (spacing(N, v.level + 1) < 2) return false;
    v = first_of(m, N, v.level + 1);
    return true;
}

int index(Method m, int N, int i, int j) {
    if (m == Method::Grid) return j * (N + 1) + i;
    return j * (N + 1) - j * (j - 1) / 2 + i;  // rows 0 … j−1 hold N + 1, N, … points
}

int vertex_count(Method m, int N) {
    return m == Method::Grid ? (N + 1) * (N + 1) : (N + 1) * (N + 2) / 2;
}

int neighbour_points(Method m, int N, const Visit& v, std::array<std::array<int, 2>, 4>& ij) {
    const int h = spacing(N, v.level) / 2, i = v.i, j = v.j;
    if (m == Method::Triangle) {
        const int s = 2 * h;
        if (j % s == 0)  // on a row: the edge (i − h, j)–(i + h, j)
            ij = {{{i - h, j}, {i + h, j}}};
        else if (i % s == 0)  // on a column: (i, j − h)–(i, j + h)
            ij = {{{i, j - h}, {i, j + h}}};
        else  // on a diagonal i + j = const: (i + h, j − h)–(i − h, j + h)
            ij = {{{i + h, j - h}, {i - h, j + h}}};
        return 2;
    }
    if (v.phase == 0) {
        ij = {{{i - h, j - h}, {i + h, j - h}, {i - h, j + h}, {i + h, j + h}}};
        return 4;
    }
    int count = 0;
    if (i - h >= 0) ij[count++] = {i - h, j};
    if (i + h <= N) ij[count++] = {i + h, j};
    if (j - h >= 0) ij[count++] = {i, j - h};
    if (j + h <= N) ij[count++] = {i, j + h};
    return count;
}

int neighbours(Method m, int N, const Visit& v, std::array<int, 4>& out) {
    std::array<std::array<int, 2>, 4> ij{};
    const int count = neighbour_points(m, N, v, ij);
    for (int k = 0; k < count; ++k) out[k] = index(m, N, ij[k][0], ij[k][1]);
    return count;
}

double average(const std::vector<double>& h, const std::array<int, 4>& nb, int count,
               int phase) {
    if (count == 2) return (h[nb[0]] + h[nb[1]]) / 2;
    if (phase == 0) return 0.25 * (h[nb[0]] + h[nb[1]] + h[nb[2]] + h[nb[3]]);
    double sum = 0;
    for (int k = 0; k < count; ++k) sum += h[nb[k]];
    return sum / count;
}

namespace {
// One new point: its average plus r = uniform(−a, a); returns r.
double displace(Method m, int N, const Visit& v, double a, Rng& rng, std::vector<double>& h,
                double& avg) {
    std::array<int, 4> nb{};
    const int count = neighbours(m, N, v, nb);
    avg = average(h, nb, count, v.phase);
    const double r = rng.uniform(-a, a);
    h[index(m, N, v.i, v.j)] = avg + r;
    return r;
}
}  // namespace

void refine(Method m, int levels, double a0, double factor, Rng& rng, std::vector<double>& h,
            std::vector<double>* amplitudes, std::vector<double>* largest) {
    if (levels < 1) return;
    const int N = 1 << levels;
    Visit v = first(m, N);
    double a = a0, avg = 0, big = 0;
    int level = 1;
    do {
        if (v.level != level) {
            if (largest) largest->push_back(big);
            if (amplitudes) amplitudes->push_back(a);
            level = v.level;
            a *= factor;
            big = 0;
        }
        big = std::max(big, std::fabs(displace(m, N, v, a, rng, h, avg)));
    } while (advance(m, N, v));
    if (largest) largest->push_back(big);
    if (amplitudes) amplitudes->push_back(a);
}

}  // namespace fractal

// ---- [spec] ---------------------------------------------------------------------------------

namespace {

enum Line {
    kLineStart = 1,
    kLineLevel,
    kLineTriangle,
    kLineDiamond,
    kLineSquare,
    kLineSplit,
    kLineResult,
};

}  // namespace

const Spec& FractalTerrain::spec() {
    static const Spec spec{
        "fractal-terrain",
        "Fractal terrain: midpoint displacement on a triangle, diamond–square on a grid",
        "Modelling",
        {
            "h ← the corners' heights (A, B, C, or the square's four);  a ← amplitude",
            "for level L = 1 … n:   (from L = 2: a ← a · 2^(−H))",
            "    triangle: every edge once:  h_m ← (h_p + h_q)/2 + uniform(−a, a)",
            "    grid, diamond: every cell's centre ← average of its 4 corners + uniform(−a, a)",
            "    grid, square: every edge midpoint ← average of its 3 or 4 neighbours + "
            "uniform(−a, a)",
            "    every triangle (cell) is now four",
            "N = 2^n: (N + 1)(N + 2)/2 vertices and 4^n triangles  (grid: (N + 1)², 2N²)",
        },
        {
            {"level", "a level begins: the amplitude a of its random offsets"},
            {"midpoint", "one edge's midpoint: the average of its two ends plus a random offset"},
            {"diamond", "one cell's centre: the average of its four corners plus an offset"},
            {"square", "one edge midpoint of the grid: the average of its 3 or 4 neighbours plus "
                       "an offset"},
            {"batch", "all the new points of a level (or of a grid phase) at once"},
            {"summary", "the finished terrain: its counts and height range"},
        },
        {},  // no sliders
        {
            .predict = {{"level", {"amplitude"}},
                        {"midpoint", {"average"}},
                        {"diamond", {"average"}},
                        {"square", {"average"}},
                        {"summary", {"vertex_count", "triangle_count"}}},
            .mistakes =
                {
                    {"midpoint", "height", "copy:average",
                     "left the midpoint at the average of the edge's ends: forgot the random "
                     "offset"},
                    {"level", "amplitude", "keep",
                     "kept the amplitude of the level before instead of scaling it by 2^(−H)"},
                    {"summary", "triangle_count", "off-by-one",
                     "counted the triangles as 4^n + 1, as if the original stayed"},
                },
            .variants = {{"rough", "/roughness", "0.25"}, {"smooth", "/roughness", "2"}},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

void check_value(double x, const std::string& field) {
    if (!std::isfinite(x))
        throw InputError(field, "must be a finite number (got " + given(x) + ")");
    if (std::fabs(x) > FractalTerrain::kMaxValue)
        throw InputError(field, "is too large (" + given(x) + "): at most 1e12 in size");
}

}  // namespace

void FractalTerrain::validate(const Input& in) {
    if (in.levels < 0 || in.levels > kMaxLevels)
        throw InputError("levels", "must be 0 to " + std::to_string(kMaxLevels) + " (got " +
                                       std::to_string(in.levels) +
                                       "): each level makes four times the triangles, and " +
                                       std::to_string(kMaxLevels) + " levels are 65 536");
    check_value(in.amplitude, "amplitude");
    if (!(in.amplitude >= 0))
        throw InputError("amplitude", "must be at least 0: the random offsets' bound at level "
                                      "1 (got " + given(in.amplitude) + ")");
    if (!std::isfinite(in.roughness) || in.roughness < 0 || in.roughness > kMaxRoughness)
        throw InputError("roughness",
                         "must be between 0 (the amplitude kept, roughest) and 4 (divided by "
                         "16 a level, smooth): H in a ← a · 2^(−H) (got " +
                             given(in.roughness) + ")");
    if (in.method == Method::Triangle) {
        const char* names[3] = {"triangle[0]", "triangle[1]", "triangle[2]"};
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c)
                check_value(in.triangle[k][c],
                            std::string(names[k]) + "[" + std::to_string(c) + "]");
        auto ground = [&](int k) { return glm::dvec3(in.triangle[k].x, 0, in.triangle[k].z); };
        if (mesh::degenerate(ground(0), ground(1), ground(2)))
            throw InputError("triangle",
                             "has no area seen from above: its corners are collinear (or "
                             "coincide) in x and z, so it cannot be split into smaller "
                             "triangles whose heights are displaced");
    } else {
        check_value(in.size, "size");
        if (!(in.size > 0))
            throw InputError("size", "must be positive: the square's side (got " +
                                         given(in.size) + ")");
        for (int k = 0; k < 4; ++k)
            check_value(in.corners[k], "corners[" + std::to_string(k) + "]");
    }
}

double FractalTerrain::factor(const Input& in) {
    return std::exp2(-in.roughness);
}

std::vector<double> FractalTerrain::start_heights(const Input& in) {
    const int N = 1 << in.levels;
    std::vector<double> h(std::size_t(fractal::vertex_count(in.method, N)), 0.0);
    if (in.method == Method::Triangle) {
        h[fractal::index(in.method, N, 0, 0)] = in.triangle[0].y;
        h[fractal::index(in.method, N, N, 0)] = in.triangle[1].y;
        h[fractal::index(in.method, N, 0, N)] = in.triangle[2].y;
    } else {
        h[fractal::index(in.method, N, 0, 0)] = in.corners[0];
        h[fractal::index(in.method, N, N, 0)] = in.corners[1];
        h[fractal::index(in.method, N, 0, N)] = in.corners[2];
        h[fractal::index(in.method, N, N, N)] = in.corners[3];
    }
    return h;
}

glm::dvec3 FractalTerrain::position(const Input& in, int N, int i, int j, double height) {
    if (in.method == Method::Grid)
        return {in.size * (double(i) / N - 0.5), height, in.size * (double(j) / N - 0.5)};
    const glm::dvec3 &A = in.triangle[0], &B = in.triangle[1], &C = in.triangle[2];
    return {A.x + (i * (B.x - A.x) + j * (C.x - A.x)) / N, height,
            A.z + (i * (B.z - A.z) + j * (C.z - A.z)) / N};
}

namespace {

// Every triangle of the lattice of spacing s, as three (i, j): the triangle's in the order of
// A, B, C (each cell's lower triangle, then the upper one where it fits); the grid's two per
// cell, counter-clockwise seen from above as in mesh_gen.
template <class F>
void for_each_face(Method m, int N, int s, F&& face) {
    for (int j = 0; j + s <= N; j += s)
        for (int i = 0; m == Method::Grid ? i + s <= N : i + j + s <= N; i += s) {
            if (m == Method::Grid) {
                face(i, j, i + s, j + s, i + s, j);
                face(i, j, i, j + s, i + s, j + s);
            } else {
                face(i, j, i + s, j, i, j + s);
                if (i + j + 2 * s <= N) face(i + s, j, i + s, j + s, i, j + s);
            }
        }
}

}  // namespace

std::vector<std::array<int, 3>> FractalTerrain::triangles(Method m, int N, int s) {
    std::vector<std::array<int, 3>> t;
    t.reserve(std::size_t(m == Method::Grid ? 2 : 1) * std::size_t(N / s) * std::size_t(N / s));
    for_each_face(m, N, s, [&](int i0, int j0, int i1, int j1, int i2, int j2) {
        t.push_back({fractal::index(m, N, i0, j0), fractal::index(m, N, i1, j1),
                     fractal::index(m, N, i2, j2)});
    });
    return t;
}

FractalTerrain::State FractalTerrain::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

FractalTerrain::State FractalTerrain::begin(Shared<Input> in) {
    State s;
    s.in = in;
    s.N = 1 << in->levels;
    s.h = start_heights(*in);
    s.rng = Rng(in->seed);
    s.a = in->amplitude;
    if (in->levels == 0) {
        s.phase = Phase::Summary;
    } else {
        s.at = fractal::first(in->method, s.N);
        s.amplitudes.reserve(std::size_t(in->levels));
        s.largest.reserve(std::size_t(in->levels));
    }
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void FractalTerrain::advance(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Level:
            if (s.at.level > 1) s.a *= factor(in);
            s.amplitudes.push_back(s.a);
            s.largest.push_back(0);
            s.last = Last::Level;
            s.phase = Phase::Points;
            return;
        case Phase::Points: {
            const bool single = s.at.level <= kSingleLevels;
            const int level = s.at.level, phase = s.at.phase;
            s.done_at = s.at;
            s.batch = 0;
            bool more;
            do {
                s.offset = fractal::displace(in.method, s.N, s.at, s.a, s.rng, s.h, s.avg);
                s.largest.back() = std::max(s.largest.back(), std::fabs(s.offset));
                ++s.batch;
                more = fractal::advance(in.method, s.N, s.at);
            } while (!single && more && s.at.level == level && s.at.phase == phase);
            s.last = single ? Last::Point : Last::Batch;
            s.phase = !more ? Phase::Summary : s.at.level != level ? Phase::Level : Phase::Points;
            return;
        }
        case Phase::Summary:
            s.last = Last::Summary;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void FractalTerrain::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

long long new_points(Method m, int N, int level) {
    const long long n = N >> (level - 1);  // cells (or triangles) of side n … per side N/n
    const long long k = N / n;             // cells a side before the level
    // triangle: 3 k (k + 1)/2 edges; grid: k² centres and 2 k (k + 1) edge midpoints.
    return m == Method::Triangle ? 3 * k * (k + 1) / 2 : k * k + 2 * k * (k + 1);
}

std::string point_name(const Visit& v) {
    return "(" + std::to_string(v.i) + ", " + std::to_string(v.j) + ")";
}

}  // namespace

void FractalTerrain::narrate(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Method m = in.method;
    info.math.clear();
    info.vars.clear();
    const int level = int(s.amplitudes.size());
    switch (s.last) {
        case Last::None:
            return;
        case Last::Level: {
            const long long count = new_points(m, s.N, level);
            info.event = "level";
            info.line = kLineLevel;
            info.narration =
                "Level " + std::to_string(level) + " of " + std::to_string(in.levels) +
                (level == 1 ? ": the amplitude starts at a = " + num(s.a)
                            : ": the amplitude shrinks by 2^(−H) = 2^(−" + num(in.roughness) +
                                  ") = " + num(factor(in)) + " to a = " + num(s.a)) +
                ". Every " + (m == Method::Triangle ? "triangle" : "cell") +
                " is split into four: " + std::to_string(count) +
                " new points, each moved by a random offset in [−a, a)" +
                (level > FractalTerrain::kSingleLevels
                     ? "; from level 3 on they are done " +
                           std::string(m == Method::Triangle ? "all in one step"
                                                             : "a phase (diamonds, squares) "
                                                               "per step") +
                           ", as the first levels showed them one by one."
                     : ", one per step.");
            info.math = "a_{" + std::to_string(level) + "} = " + tex(in.amplitude) + " \\cdot 2^{-" +
                        tex(in.roughness) + " \\cdot " + std::to_string(level - 1) + "} = " +
                        tex(s.a);
            info.vars = {{"level", (long long)level},
                         {"amplitude", s.a},
                         {"factor", factor(in)},
                         {"new_points", count}};
            return;
        }
        case Last::Point: {
            std::array<int, 4> nb{};
            std::array<std::array<int, 2>, 4> ij{};
            const int count = fractal::neighbours(m, s.N, s.done_at, nb);
            fractal::neighbour_points(m, s.N, s.done_at, ij);
            std::vector<double> hs;
            std::string list, ends;
            for (int k = 0; k < count; ++k) {
                hs.push_back(s.h[nb[k]]);
                list += (k ? ", " : "") + num(s.h[nb[k]]);
                ends += (k ? "–" : "") + point_name({0, 0, ij[k][0], ij[k][1]});
            }
            const double height = s.h[fractal::index(m, s.N, s.done_at.i, s.done_at.j)];
            const bool tri = m == Method::Triangle;
            const bool diamond = !tri && s.done_at.phase == 0;
            info.event = tri ? "midpoint" : diamond ? "diamond" : "square";
            info.line = tri ? kLineTriangle : diamond ? kLineDiamond : kLineSquare;
            const std::string what =
                tri ? "The midpoint " + point_name(s.done_at) + " of the edge " + ends +
                          " (split once: both triangles on it share this point)"
                : diamond ? "The cell's centre " + point_name(s.done_at)
                          : "The edge midpoint " + point_name(s.done_at) + " (" +
                                std::to_string(count) + " neighbours" +
                                (count == 3 ? ": on the border" : "") + ")";
            info.narration = what + ": the average of " + list + " is " + num(s.avg) +
                             "; the random offset r = " + num(s.offset) + " (in [−" + num(s.a) +
                             ", " + num(s.a) + ")) makes its height " + num(height) + ".";
            info.math = "h = " + tex(s.avg) + (s.offset < 0 ? " - " : " + ") +
                        tex(std::fabs(s.offset)) + " = " + tex(height);
            info.vars = {{"level", (long long)level},
                         {"amplitude", s.a},
                         {"point", std::vector<double>{double(s.done_at.i), double(s.done_at.j)}},
                         {"neighbours", hs},
                         {"average", s.avg},
                         {"offset", s.offset},
                         {"height", height}};
            return;
        }
        case Last::Batch: {
            const bool tri = m == Method::Triangle;
            const std::string what =
                tri ? "all " + std::to_string(s.batch) + " edge midpoints of level " +
                          std::to_string(level)
                : s.done_at.phase == 0
                    ? "the diamond phase of level " + std::to_string(level) + ": all " +
                          std::to_string(s.batch) + " cell centres"
                    : "the square phase of level " + std::to_string(level) + ": all " +
                          std::to_string(s.batch) + " edge midpoints";
            info.event = "batch";
            info.line = tri ? kLineTriangle : s.done_at.phase == 0 ? kLineDiamond : kLineSquare;
            info.narration = "In one step, " + what +
                             ", each the average of its neighbours plus a random offset in [−" +
                             num(s.a) + ", " + num(s.a) + "); the largest |offset| so far at " +
                             "this level is " + num(s.largest.back()) + ".";
            info.vars = {{"level", (long long)level},
                         {"amplitude", s.a},
                         {"points", (long long)s.batch},
                         {"largest_offset", s.largest.back()}};
            return;
        }
        case Last::Summary: {
            const Result r = result(s);
            info.event = "summary";
            info.line = kLineResult;
            info.narration =
                "After " + std::to_string(in.levels) + " level" + (in.levels == 1 ? "" : "s") +
                " the terrain has " + std::to_string(r.vertex_count) + " vertices and " +
                std::to_string(r.triangle_count) + " triangles; its heights run from " +
                num(r.min_height) + " to " + num(r.max_height) + ".";
            info.vars = {{"vertex_count", r.vertex_count},
                         {"triangle_count", r.triangle_count},
                         {"min_height", r.min_height},
                         {"max_height", r.max_height}};
            return;
        }
    }
}

// ---- [result and compute] -------------------------------------------------------------------

namespace {

FractalTerrain::Result make_result(const Input& in, const std::vector<double>& h,
                                   std::vector<double> amplitudes, std::vector<double> largest) {
    FractalTerrain::Result r;
    const int N = 1 << in.levels;
    r.vertices.reserve(h.size());
    for (int j = 0; j <= N; ++j)
        for (int i = 0; in.method == Method::Grid ? i <= N : i + j <= N; ++i)
            r.vertices.push_back(FractalTerrain::position(
                in, N, i, j, h[std::size_t(fractal::index(in.method, N, i, j))]));
    r.triangles = FractalTerrain::triangles(in.method, N, 1);
    r.amplitudes = std::move(amplitudes);
    r.largest_offsets = std::move(largest);
    r.vertex_count = (long long)r.vertices.size();
    r.triangle_count = (long long)r.triangles.size();
    const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
    r.min_height = *lo;
    r.max_height = *hi;
    return r;
}

}  // namespace

FractalTerrain::Result FractalTerrain::result(const State& s) {
    return make_result(*s.in, s.h, s.amplitudes, s.largest);
}

FractalTerrain::Result FractalTerrain::result(State&& s) {
    return make_result(*s.in, s.h, std::move(s.amplitudes), std::move(s.largest));
}

FractalTerrain::Result FractalTerrain::compute(const Input& in) {
    std::vector<double> h = start_heights(in);
    std::vector<double> amplitudes, largest;
    Rng rng(in.seed);
    fractal::refine(in.method, in.levels, in.amplitude, factor(in), rng, h, &amplitudes,
                    &largest);
    return make_result(in, h, std::move(amplitudes), std::move(largest));
}

// ---- [draw] ---------------------------------------------------------------------------------

namespace {

// Low green, middle brown, high white.
std::uint32_t height_colour(double t) {
    t = std::clamp(t, 0.0, 1.0);
    const glm::dvec3 lo(46, 125, 50), mid(141, 110, 99), hi(245, 245, 245);
    const glm::dvec3 c = t < 0.5 ? lo + (mid - lo) * (2 * t) : mid + (hi - mid) * (2 * t - 1);
    auto byte = [](double v) { return std::uint32_t(std::clamp(v, 0.0, 255.0)); };
    return byte(c.x) << 24 | byte(c.y) << 16 | byte(c.z) << 8 | 0xffu;
}

}  // namespace

void FractalTerrain::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Method m = in.method;
    const int N = s.N;
    const bool finished = s.phase == Phase::Summary || s.phase == Phase::Done;
    // The lattice finished so far: the level in progress (or about to start) still has cells of
    // side N / 2^(L−1).
    const int level = finished ? in.levels + 1 : s.at.level;
    const int side = N >> (level - 1);
    auto pos = [&](int i, int j) {
        return position(in, N, i, j, s.h[std::size_t(fractal::index(m, N, i, j))]);
    };
    // The points of the level in progress already displaced.
    std::vector<Visit> fresh;
    if (!finished && s.phase == Phase::Points) {
        Visit v = fractal::first_at(m, N, level);
        while (!(v == s.at) && v.level == level) {
            fresh.push_back(v);
            if (!fractal::advance(m, N, v)) break;
        }
    }
    auto height = [&](int i, int j) { return s.h[std::size_t(fractal::index(m, N, i, j))]; };
    double lo = INFINITY, hi = -INFINITY;
    for_each_face(m, N, side, [&](int i0, int j0, int i1, int j1, int i2, int j2) {
        for (double y : {height(i0, j0), height(i1, j1), height(i2, j2)})
            lo = std::min(lo, y), hi = std::max(hi, y);
    });
    for (const Visit& v : fresh) lo = std::min(lo, height(v.i, v.j)), hi = std::max(hi, height(v.i, v.j));
    const double range = hi > lo ? hi - lo : 1;
    const std::size_t cells = std::size_t(N / side) * std::size_t(N / side);
    scene.faces3.reserve(2 * cells);
    for_each_face(m, N, side, [&](int i0, int j0, int i1, int j1, int i2, int j2) {
        Face3 f;
        f.points = {pos(i0, j0), pos(i1, j1), pos(i2, j2)};
        const double mean = (f.points[0].y + f.points[1].y + f.points[2].y) / 3;
        f.style.rgba = height_colour((mean - lo) / range);
        // Lighter while a point is displaced: the new point may lie under the coarse face.
        f.alpha = s.last == Last::Point && !finished ? 0.55f : 0.85f;
        f.outline = cells <= 512;
        scene.faces3.push_back(std::move(f));
    });
    const bool small = fresh.size() <= 256;
    for (const Visit& v : fresh)
        if (small) scene.points3.push_back({pos(v.i, v.j), "", {Role::Kept}, 3.5f});
    double extent = 0;
    for (const auto& f : scene.faces3)
        for (const auto& q : f.points)
            extent = std::max({extent, std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
    scene.extent3 = extent > 0 ? 1.2 * extent : 1;
    // The point just displaced: its neighbours, their average and the offset. The camera frames
    // them with some of the terrain around; the new height's label is placed first, the
    // neighbours' heights last.
    if (s.last == Last::Point && !finished) {
        const Visit& v = s.done_at;
        std::array<int, 4> nb{};
        const int count = fractal::neighbours(m, N, v, nb);
        const glm::dvec3 p = pos(v.i, v.j);
        const glm::dvec3 base = position(in, N, v.i, v.j, s.avg);
        std::array<std::array<int, 2>, 4> ij{};
        fractal::neighbour_points(m, N, v, ij);
        glm::dvec3 box_lo = glm::min(p, base), box_hi = glm::max(p, base);
        for (int k = 0; k < count; ++k) {
            const glm::dvec3 q = pos(ij[k][0], ij[k][1]);
            box_lo = glm::min(box_lo, q), box_hi = glm::max(box_hi, q);
            scene.points3.push_back({q, num(s.h[nb[k]], 3), {Role::Entering}, 5.0f, -1});
            scene.segments3.push_back({q, base, "", {Role::Construction, 1.0f, true}});
        }
        scene.points3.push_back({base, "avg " + num(s.avg, 3), {Role::Construction}, 4.0f});
        scene.segments3.push_back(
            {base, p, "r = " + num(s.offset, 3), {Role::Active, 2.5f}, true, 0, 5});
        scene.points3.push_back({p, "h = " + num(s.h[fractal::index(m, N, v.i, v.j)], 3),
                                 {Role::Active}, 6.0f, 10});
        const glm::dvec3 c = (box_lo + box_hi) / 2.0;
        const glm::dvec3 half = glm::max((box_hi - box_lo) / 2.0, glm::dvec3(0.45 * extent));
        add_focus(scene, c - half, c + half);
    }
}

}  // namespace cg
