// Sections: [field] [cell] [loops] [spec] [validate] [advance] [narrate] [result and compute]
//           [draw]
#include "modelling/marching_squares.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"

namespace cg {

namespace {

using MS = MarchingSquares;
using Input = MS::Input;
using Grid = MS::Grid;
using Phase = MS::Phase;
using State = MS::State;
using Field = MS::Field;

enum Line { kLineSample = 1, kLineCase, kLineSaddle, kLineCross, kLineEmit, kLineReport };

// The 16 cases: the (from edge, to edge) of each segment, the inside on the left. Edges:
// 0 bottom, 1 right, 2 top, 3 left. Walking the cell's border counter-clockwise, a segment
// runs from an edge where the walk leaves the inside to one where it enters it.
struct Row {
    int n;
    int seg[2][2];
};
constexpr Row kTable[16] = {
    {0, {}},                // 0: all outside
    {1, {{0, 3}}},          // 1: corner 0
    {1, {{1, 0}}},          // 2: corner 1
    {1, {{1, 3}}},          // 3: corners 0, 1
    {1, {{2, 1}}},          // 4: corner 2
    {2, {{0, 3}, {2, 1}}},  // 5: corners 0, 2 — saddle, separated (joined below)
    {1, {{2, 0}}},          // 6: corners 1, 2
    {1, {{2, 3}}},          // 7: corners 0, 1, 2
    {1, {{3, 2}}},          // 8: corner 3
    {1, {{0, 2}}},          // 9: corners 0, 3
    {2, {{1, 0}, {3, 2}}},  // 10: corners 1, 3 — saddle, separated (joined below)
    {1, {{1, 2}}},          // 11: corners 0, 1, 3
    {1, {{3, 1}}},          // 12: corners 2, 3
    {1, {{0, 1}}},          // 13: corners 0, 2, 3
    {1, {{3, 0}}},          // 14: corners 1, 2, 3
    {0, {}},                // 15: all inside
};
// The saddles with the inside corners joined: the segments cut off the outside corners.
constexpr int kJoined5[2][2] = {{0, 1}, {2, 3}};
constexpr int kJoined10[2][2] = {{1, 2}, {3, 0}};

constexpr const char* kEdgeName[4] = {"bottom", "right", "top", "left"};

bool crossed_case(int index) {
    return index != 0 && index != 15;
}

std::string bits_text(int index) {
    std::string b;
    for (int k = 3; k >= 0; --k) b += (index >> k & 1) ? '1' : '0';
    return b;
}

}  // namespace

// ---- [field] --------------------------------------------------------------------------------

double MarchingSquares::field_value(const Input& in, glm::dvec2 p) {
    switch (in.field) {
        case Field::Circle:
            return p.x * p.x + p.y * p.y - in.radius * in.radius;
        case Field::Blobs: {
            const double r2 = in.radius * in.radius;
            const glm::dvec2 a = p - glm::dvec2(-0.4, 0), b = p - glm::dvec2(0.4, 0);
            return 0.5 - std::exp(-(a.x * a.x + a.y * a.y) / r2) -
                   std::exp(-(b.x * b.x + b.y * b.y) / r2);
        }
        case Field::Grid:
        case Field::Noise:
            break;
    }
    return 0;
}

MarchingSquares::Grid MarchingSquares::sample(const Input& in) {
    Grid g;
    if (in.field == Field::Grid) {
        g.ny = int(in.values.size()) - 1;
        g.nx = int(in.values[0].size()) - 1;
        g.f.reserve(std::size_t(g.nx + 1) * std::size_t(g.ny + 1));
        for (const auto& row : in.values) g.f.insert(g.f.end(), row.begin(), row.end());
        return g;
    }
    g.nx = g.ny = in.cells;
    g.origin = {-1, -1};
    g.h = 2.0 / in.cells;
    g.f.resize(std::size_t(g.nx + 1) * std::size_t(g.ny + 1));
    if (in.field == Field::Noise) {
        Rng rng(in.seed);
        for (double& v : g.f) v = rng.uniform(-1, 1);
        return g;
    }
    for (int j = 0; j <= g.ny; ++j)
        for (int i = 0; i <= g.nx; ++i)
            g.f[std::size_t(j) * std::size_t(g.nx + 1) + std::size_t(i)] =
                field_value(in, g.point(i, j));
    return g;
}

// ---- [cell] ---------------------------------------------------------------------------------

int MarchingSquares::case_index(const Grid& g, int i, int j, double iso) {
    return int(g.at(i, j) < iso) | int(g.at(i + 1, j) < iso) << 1 |
           int(g.at(i + 1, j + 1) < iso) << 2 | int(g.at(i, j + 1) < iso) << 3;
}

int MarchingSquares::edge_id(const Grid& g, int i, int j, int edge) {
    const int w = g.nx + 1;
    switch (edge) {
        case 0: return 2 * (j * w + i);
        case 1: return 2 * (j * w + i + 1) + 1;
        case 2: return 2 * ((j + 1) * w + i);
        default: return 2 * (j * w + i) + 1;
    }
}

int MarchingSquares::table(int index, bool joined, std::array<std::array<int, 2>, 2>& seg) {
    const Row& r = kTable[index & 15];
    const int(*pairs)[2] = r.seg;
    if (joined && index == 5) pairs = kJoined5;
    if (joined && index == 10) pairs = kJoined10;
    for (int k = 0; k < r.n; ++k) seg[std::size_t(k)] = {pairs[k][0], pairs[k][1]};
    return r.n;
}

MarchingSquares::Cell MarchingSquares::march(const Grid& g, int i, int j, double iso) {
    Cell c;
    c.i = i;
    c.j = j;
    c.f = {g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1), g.at(i, j + 1)};
    for (int k = 0; k < 4; ++k) c.index |= int(c.f[std::size_t(k)] < iso) << k;
    if (!crossed_case(c.index)) return c;
    // Each edge from its lower-coordinate end: (corner a, corner b, point a, point b).
    static constexpr int ends[4][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}};
    const glm::dvec2 corner[4] = {g.point(i, j), g.point(i + 1, j), g.point(i + 1, j + 1),
                                  g.point(i, j + 1)};
    for (int e = 0; e < 4; ++e) {
        const int a = ends[e][0], b = ends[e][1];
        const double fa = c.f[std::size_t(a)], fb = c.f[std::size_t(b)];
        if ((fa < iso) == (fb < iso)) continue;
        const double t = (iso - fa) / (fb - fa);
        c.crossed |= 1 << e;
        c.t[std::size_t(e)] = t;
        c.p[std::size_t(e)] = corner[a] + t * (corner[b] - corner[a]);
    }
    if (c.index == 5 || c.index == 10) {
        c.centre = 0.25 * (c.f[0] + c.f[1] + c.f[2] + c.f[3]);
        c.joined = c.centre < iso;
    }
    c.segments = table(c.index, c.joined, c.seg);
    return c;
}

// ---- [loops] --------------------------------------------------------------------------------

void MarchingSquares::count_loops(const Grid& g, const std::vector<Segment>& segs,
                                  long long& loops, long long& chains) {
    loops = chains = 0;
    if (segs.empty()) return;
    const std::size_t edges = 2 * std::size_t(g.nx + 1) * std::size_t(g.ny + 1);
    std::vector<int> starts(edges, -1);
    std::vector<char> ends(edges, 0);
    for (std::size_t k = 0; k < segs.size(); ++k) {
        starts[std::size_t(segs[k].ea)] = int(k);
        ends[std::size_t(segs[k].eb)] = 1;
    }
    std::vector<char> seen(segs.size(), 0);
    auto walk = [&](std::size_t k) {
        while (!seen[k]) {
            seen[k] = 1;
            const int n = starts[std::size_t(segs[k].eb)];
            if (n < 0) return;
            k = std::size_t(n);
        }
    };
    // A chain starts at an edge no segment ends at: the grid's border.
    for (std::size_t k = 0; k < segs.size(); ++k)
        if (!ends[std::size_t(segs[k].ea)]) {
            ++chains;
            walk(k);
        }
    for (std::size_t k = 0; k < segs.size(); ++k)
        if (!seen[k]) {
            ++loops;
            walk(k);
        }
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& MarchingSquares::spec() {
    static const Spec spec{
        "marching-squares",
        "Marching squares: the contour of a sampled field, cell by cell",
        "Modelling",
        {
            "sample f at every grid point; a point is inside when f < iso",
            "for each cell: case ← b0 + 2·b1 + 4·b2 + 8·b3   ▷ b_k = 1 when corner k is inside",
            "if case is 5 or 10 (a saddle): m ← (f0 + f1 + f2 + f3)/4; join the inside corners "
            "when m < iso",
            "on each edge a→b whose corners differ: t ← (iso − f_a)/(f_b − f_a), p ← a + t·(b − a)",
            "emit the case's segments between the crossings (inside on the left)",
            "report the segments, the contour's length and its closed loops",
        },
        {
            {"sample", "the field sampled at every grid point, each marked inside or outside"},
            {"cell", "a cell the contour crosses: its case, crossings and segments"},
            {"saddle", "an ambiguous cell (case 5 or 10), decided by the centre average"},
            {"empty", "a run of cells the contour does not cross (case 0 or 15)"},
            {"batch", "many cells in one step (after the first steps)"},
            {"summary", "the segments, the contour's length, its closed loops and open chains"},
        },
        {},
        {
            .predict = {{"cell", {"case"}}, {"saddle", {"case", "centre"}}},
            .mistakes =
                {
                    {"saddle", "joined", "not",
                     "decided the saddle the wrong way round: joined the inside corners when "
                     "the centre is outside"},
                    {"cell", "t", "swap:one_minus_t",
                     "measured t from the wrong end of the edge (1 − t instead of t)"},
                    {"cell", "case", "keep", "kept the case of the cell before"},
                },
            .variants = {{"iso 0", "/iso", "0"}, {"iso 0.25", "/iso", "0.25"}},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void MarchingSquares::validate(const Input& in) {
    if (!std::isfinite(in.iso) || std::fabs(in.iso) > kMaxValue)
        throw InputError("iso", "must be a finite number of at most 1e100 in size");
    if (in.field == Field::Grid) {
        if (in.values.size() < 2)
            throw InputError("values", "needs at least 2 rows (one cell), got " +
                                           std::to_string(in.values.size()));
        if (in.values.size() > std::size_t(kMaxCells) + 1)
            throw InputError("values", "has " + std::to_string(in.values.size()) +
                                           " rows; at most " + std::to_string(kMaxCells + 1));
        const std::size_t w = in.values[0].size();
        if (w < 2) throw InputError("values[0]", "needs at least 2 values (one cell)");
        if (w > std::size_t(kMaxCells) + 1)
            throw InputError("values[0]", "has " + std::to_string(w) + " values; at most " +
                                              std::to_string(kMaxCells + 1));
        for (std::size_t j = 0; j < in.values.size(); ++j) {
            const std::string row = "values[" + std::to_string(j) + "]";
            if (in.values[j].size() != w)
                throw InputError(row, "has " + std::to_string(in.values[j].size()) +
                                          " values, row 0 has " + std::to_string(w) +
                                          ": every row the same length");
            for (std::size_t i = 0; i < w; ++i)
                if (!std::isfinite(in.values[j][i]) || std::fabs(in.values[j][i]) > kMaxValue)
                    throw InputError(row + "[" + std::to_string(i) + "]",
                                     "must be a finite number of at most 1e100 in size");
        }
        return;
    }
    if (in.cells < 1 || in.cells > kMaxCells)
        throw InputError("cells", "must be 1 to " + std::to_string(kMaxCells) + " (got " +
                                      std::to_string(in.cells) + ")");
    if (!(in.radius > 0) || in.radius > 10)
        throw InputError("radius", "must be above 0 and at most 10");
}

MarchingSquares::State MarchingSquares::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

MarchingSquares::State MarchingSquares::begin(Shared<Input> shared) {
    State s;
    s.grid = Shared<Grid>(sample(*shared));
    s.in = std::move(shared);
    s.cases.reserve(std::size_t(s.grid->nx) * std::size_t(s.grid->ny));
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

namespace {

// One cell into the running lists (the state machine and compute share it).
inline void emit(const Grid& g, int i, int j, double iso, std::vector<MS::Segment>& out,
                 std::vector<glm::dvec2>& crossings, double& length, long long& saddles,
                 long long& joined) {
    const MS::Cell c = MS::march(g, i, j, iso);
    for (int e = 0; e < 4; ++e)
        if ((c.crossed >> e & 1) && (e == 1 || e == 2 || (e == 0 && j == 0) || (e == 3 && i == 0)))
            crossings.push_back(c.p[std::size_t(e)]);
    if (c.index == 5 || c.index == 10) {
        ++saddles;
        joined += c.joined;
    }
    for (int k = 0; k < c.segments; ++k) {
        const int ea = c.seg[std::size_t(k)][0], eb = c.seg[std::size_t(k)][1];
        MS::Segment sg{c.p[std::size_t(ea)], c.p[std::size_t(eb)], MS::edge_id(g, i, j, ea),
                       MS::edge_id(g, i, j, eb)};
        const glm::dvec2 d = sg.b - sg.a;
        length += std::sqrt(d.x * d.x + d.y * d.y);
        out.push_back(sg);
    }
}

}  // namespace

void MarchingSquares::advance(State& s) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    switch (s.phase) {
        case Phase::Sample:
            s.last = Phase::Sample;
            s.phase = Phase::Cells;
            return;
        case Phase::Cells: {
            const int total = g.nx * g.ny;
            if (s.batch == 0 && s.steps >= kStepped)
                s.batch = std::max(1, (total - s.next + kBatches - 1) / kBatches);
            s.from = s.next;
            s.seg_from = s.segments.size();
            int c = s.next;
            while (c < total) {
                const int i = c % g.nx, j = c / g.nx;
                const int index = case_index(g, i, j, in.iso);
                const bool crossed = crossed_case(index);
                if (s.batch == 0 && crossed && c > s.from) break;  // a run ends before it
                s.cases.push_back(std::uint8_t(index));
                if (crossed) emit(g, i, j, in.iso, s.segments, s.crossings, s.length, s.saddles, s.joined);
                ++c;
                if (s.batch ? c - s.from == s.batch : crossed) break;
            }
            s.next = c;
            ++s.steps;
            s.last = Phase::Cells;
            if (c == total) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:
            count_loops(g, s.segments, s.loops, s.chains);
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
        case Field::Circle: return "the circle f = x² + y² − r²";
        case Field::Blobs: return "two blobs f = ½ − Σ exp(−|p − c_k|²/r²)";
        case Field::Noise: return "seeded noise (uniform values in [−1, 1))";
    }
    return "";
}

void narrate_cell(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    const MS::Cell c = MS::march(g, s.from % g.nx, s.from / g.nx, in.iso);
    const bool saddle = c.index == 5 || c.index == 10;
    info.event = saddle ? "saddle" : "cell";
    info.line = saddle ? kLineSaddle : kLineEmit;
    std::string corners;
    for (int k = 0; k < 4; ++k)
        corners += (k ? ", " : "") + std::string("f") + std::to_string(k) + " = " +
                   num(c.f[std::size_t(k)]) + (c.f[std::size_t(k)] < in.iso ? " (in)" : " (out)");
    std::string text = "Cell (" + std::to_string(c.i) + ", " + std::to_string(c.j) +
                       "): corners " + corners + " against iso = " + num(in.iso) +
                       "; bits b3b2b1b0 = " + bits_text(c.index) + ", so case " +
                       std::to_string(c.index) + ".";
    if (saddle)
        text += " A saddle: the centre average m = " + num(c.centre) + (c.joined ? " < " : " ≥ ") +
                "iso, so the centre is " + (c.joined ? "inside and the inside corners are joined"
                                                     : "outside and the inside corners are "
                                                       "separated") +
                ".";
    std::string crossings;
    std::vector<std::vector<double>> points;
    double first_t = 0;
    bool have_t = false;
    for (int e = 0; e < 4; ++e) {
        if (!(c.crossed >> e & 1)) continue;
        if (!have_t) first_t = c.t[std::size_t(e)];
        have_t = true;
        crossings += std::string(crossings.empty() ? "" : "; ") + kEdgeName[e] + " t = " +
                     num(c.t[std::size_t(e)]) + " at " + num(c.p[std::size_t(e)]);
        points.push_back({c.p[std::size_t(e)].x, c.p[std::size_t(e)].y});
    }
    text += " Crossings (t = (iso − f_a)/(f_b − f_a)): " + crossings + ". " +
            std::to_string(c.segments) + (c.segments == 1 ? " segment" : " segments") + ": ";
    for (int k = 0; k < c.segments; ++k) {
        const auto& sg = c.seg[std::size_t(k)];
        text += std::string(k ? ", " : "") + kEdgeName[sg[0]] + " → " + kEdgeName[sg[1]];
    }
    text += " (inside on the left).";
    info.narration = text;
    info.math = "\\text{case} = " + std::to_string(c.index & 1) + " + 2\\cdot" +
                std::to_string(c.index >> 1 & 1) + " + 4\\cdot" +
                std::to_string(c.index >> 2 & 1) + " + 8\\cdot" +
                std::to_string(c.index >> 3 & 1) + " = " + std::to_string(c.index);
    info.vars = {{"cell", std::vector<double>{double(c.i), double(c.j)}},
                 {"case", (long long)c.index},
                 {"bits", bits_text(c.index)},
                 {"corners", std::vector<double>(c.f.begin(), c.f.end())},
                 {"t", first_t},
                 {"one_minus_t", 1 - first_t},
                 {"crossings", points}};
    if (saddle) {
        info.vars.push_back({"centre", c.centre});
        info.vars.push_back({"joined", c.joined});
    }
    info.vars.push_back({"segments", (long long)s.segments.size()});
}

void narrate_run(const State& s, StepInfo& info, bool batch) {
    const Grid& g = *s.grid;
    const int n = s.next - s.from;
    info.event = batch ? "batch" : "empty";
    info.line = batch ? kLineEmit : kLineCase;
    const std::size_t added = s.segments.size() - s.seg_from;
    auto cell = [&](int c) {
        return "(" + std::to_string(c % g.nx) + ", " + std::to_string(c / g.nx) + ")";
    };
    if (batch) {
        info.narration = "Cells " + cell(s.from) + " to " + cell(s.next - 1) + " (" +
                         std::to_string(n) + " cells) in one step: " + std::to_string(added) +
                         " segments added, " + std::to_string(s.segments.size()) +
                         " so far. After the first " + std::to_string(MS::kStepped) +
                         " steps the rest go in batches.";
    } else {
        int inside = 0;
        for (int c = s.from; c < s.next; ++c) inside += s.cases[std::size_t(c)] == 15;
        info.narration =
            (n == 1 ? "Cell " + cell(s.from) : "Cells " + cell(s.from) + " to " + cell(s.next - 1) +
                                                    " (" + std::to_string(n) + " cells)") +
            ": " +
            (inside == n ? std::string("every corner inside (case 15)")
             : inside == 0 ? std::string("every corner outside (case 0)")
                           : std::to_string(inside) + " all inside (case 15), the rest all "
                                                      "outside (case 0)") +
            ". No edge changes sign, so the contour does not pass through; nothing to emit.";
    }
    info.vars = {{"cells", (long long)n},
                 {"added", (long long)added},
                 {"segments", (long long)s.segments.size()}};
}

void narrate_summary(const State& s, StepInfo& info) {
    info.event = "summary";
    info.line = kLineReport;
    info.narration =
        std::to_string(s.segments.size()) + " segments, total length " + num(s.length) + "; " +
        std::to_string(s.loops) + (s.loops == 1 ? " closed loop" : " closed loops") + " and " +
        std::to_string(s.chains) + (s.chains == 1 ? " open chain" : " open chains") +
        " (ending on the grid's border); " + std::to_string(s.saddles) +
        (s.saddles == 1 ? " saddle" : " saddles") + " (" + std::to_string(s.joined) +
        " joined).";
    info.math = "L = " + tex(s.length);
    info.vars = {{"segments", (long long)s.segments.size()},
                 {"length", s.length},
                 {"loops", s.loops},
                 {"chains", s.chains},
                 {"saddles", s.saddles}};
}

}  // namespace

void MarchingSquares::narrate(const State& s, StepInfo& info) {
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
                             std::to_string((g.nx + 1) * (g.ny + 1)) + " points of a " +
                             std::to_string(g.nx) + " × " + std::to_string(g.ny) +
                             " grid (spacing " + num(g.h) + "): " + std::to_string(inside) +
                             " are inside (f < " + num(in.iso) + "), the rest outside.";
            info.vars = {{"cells", (long long)(g.nx * g.ny)},
                         {"inside", inside},
                         {"iso", in.iso}};
            return;
        }
        case Phase::Cells:
            if (s.batch == 0 && s.next - s.from == 1 &&
                crossed_case(s.cases[std::size_t(s.from)]))
                narrate_cell(s, info);
            else
                narrate_run(s, info, s.batch != 0);
            return;
        case Phase::Summary:
        case Phase::Done:
            narrate_summary(s, info);
            return;
    }
}

void MarchingSquares::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compute] -------------------------------------------------------------------

MarchingSquares::Result MarchingSquares::result(const State& s) {
    Result r;
    r.nx = s.grid->nx;
    r.ny = s.grid->ny;
    r.cases = s.cases;
    r.segments = s.segments;
    r.crossings = s.crossings;
    r.inside = inside_count(*s.grid, s.in->iso);
    r.saddles = s.saddles;
    r.joined = s.joined;
    r.length = s.length;
    r.loops = s.loops;
    r.chains = s.chains;
    return r;
}

MarchingSquares::Result MarchingSquares::result(State&& s) {
    Result r;
    r.nx = s.grid->nx;
    r.ny = s.grid->ny;
    r.cases = std::move(s.cases);
    r.segments = std::move(s.segments);
    r.crossings = std::move(s.crossings);
    r.inside = inside_count(*s.grid, s.in->iso);
    r.saddles = s.saddles;
    r.joined = s.joined;
    r.length = s.length;
    r.loops = s.loops;
    r.chains = s.chains;
    return r;
}

MarchingSquares::Result MarchingSquares::compute(const Input& in) {
    const Grid g = sample(in);
    Result r;
    r.nx = g.nx;
    r.ny = g.ny;
    r.cases.reserve(std::size_t(g.nx) * std::size_t(g.ny));
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const int index = case_index(g, i, j, in.iso);
            r.cases.push_back(std::uint8_t(index));
            if (crossed_case(index)) emit(g, i, j, in.iso, r.segments, r.crossings, r.length, r.saddles, r.joined);
        }
    r.inside = inside_count(g, in.iso);
    count_loops(g, r.segments, r.loops, r.chains);
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

// The grid lines in light grey; the sample points green when inside, grey when outside (with
// their values on a small grid); the segments so far in green, this step's in orange; the
// current cell outlined in orange with its case, its bits and its crossings.
void MarchingSquares::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    const double W = g.nx * g.h, H = g.ny * g.h;
    const int stride = std::max(1, std::max(g.nx, g.ny) / 32);  // at most ~33 grid lines a side
    for (int i = 0; i <= g.nx; i += stride)
        scene.segments.push_back({g.point(i, 0), g.point(i, g.ny), "", {Role::Construction, 1.0f}});
    for (int j = 0; j <= g.ny; j += stride)
        scene.segments.push_back({g.point(0, j), g.point(g.nx, j), "", {Role::Construction, 1.0f}});
    if (g.nx <= 32 && g.ny <= 32) {
        const bool values = g.nx <= 8 && g.ny <= 8;
        for (int j = 0; j <= g.ny; ++j)
            for (int i = 0; i <= g.nx; ++i) {
                const bool inside = g.at(i, j) < in.iso;
                scene.points.push_back({g.point(i, j), values ? num(g.at(i, j), 3) : "",
                                        {inside ? Role::Kept : Role::Subject},
                                        values ? 5.0f : 3.5f});
            }
    }
    for (std::size_t k = 0; k < s.segments.size(); ++k) {
        const bool recent = k >= s.seg_from && s.last == Phase::Cells;
        scene.segments.push_back({s.segments[k].a, s.segments[k].b, "",
                                  {recent ? Role::Active : Role::Kept, recent ? 3.0f : 2.0f}});
    }
    if (s.last != Phase::Cells || s.phase == Phase::Done) {
        scene.labels.push_back({g.origin + glm::dvec2(0, -0.06 * std::max(W, H)),
                                std::to_string(s.segments.size()) + " segments, length " +
                                    num(s.length, 4),
                                {Role::Neutral}});
        return;
    }
    // The cells of the last step: one cell highlighted, or the run as a label.
    const int i = s.from % g.nx, j = s.from / g.nx;
    const int last = s.next - 1;
    if (s.next - s.from == 1 && s.batch == 0) {
        const Cell c = march(g, i, j, in.iso);
        scene.polygons.push_back(
            {{g.point(i, j), g.point(i + 1, j), g.point(i + 1, j + 1), g.point(i, j + 1)},
             {Role::Active, 2.5f},
             true,
             true});
        for (int e = 0; e < 4; ++e)
            if (c.crossed >> e & 1)
                scene.points.push_back({c.p[std::size_t(e)], "", {Role::Entering}, 5.0f});
        std::string label = "case " + std::to_string(c.index) + " = " + bits_text(c.index) + "₂";
        if (c.index == 5 || c.index == 10) label += c.joined ? " (saddle, joined)" : " (saddle, separated)";
        scene.labels.push_back({g.point(i, j + 1) + glm::dvec2(0, 0.15 * g.h) +
                                    glm::dvec2(0, 0.02 * std::max(W, H)),
                                label,
                                {Role::Active}});
    } else if (s.next - s.from <= 64) {  // a run of empty cells (or a small batch), dashed
        for (int c = s.from; c <= last; ++c) {
            const int ci = c % g.nx, cj = c / g.nx;
            scene.polygons.push_back({{g.point(ci, cj), g.point(ci + 1, cj),
                                       g.point(ci + 1, cj + 1), g.point(ci, cj + 1)},
                                      {Role::Active, 1.5f, true},
                                      true,
                                      false});
        }
    }
}

}  // namespace cg
