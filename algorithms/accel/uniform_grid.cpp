// Sections: [helpers] [spec] [validate] [build] [walk] [step] [narrate]
// (the picture: uniform_grid_draw.cpp)
#include "accel/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Cell = UniformGrid::Cell;
using Grid = UniformGrid::Grid;
using Input = UniformGrid::Input;
using Outcome = UniformGrid::Outcome;
using Phase = UniformGrid::Phase;
using Walk = UniformGrid::Walk;
using Test = UniformGrid::Test;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineBuild = 1,
    kLinePlace,
    kLineEnter,
    kLineSetup,
    kLineLoop,
    kLineTest,
    kLineFinal,
    kLineStep,
    kLineLeave,
};

const char* const kAxis[3] = {"x", "y", "z"};

std::string tn(double t) {
    if (std::isinf(t)) return t > 0 ? "∞" : "−∞";
    return num(t);
}
std::string tt(double t) {
    if (std::isinf(t)) return t > 0 ? "\\infty" : "-\\infty";
    return tex(t);
}
Value tv(double t) {
    if (std::isinf(t)) return std::string(t > 0 ? "inf" : "-inf");
    return t;
}

// A number after a minus sign: negative ones in parentheses, "1 − (−1)".
std::string sub(double x) {
    return x < 0 ? "(" + num(x) + ")" : num(x);
}

std::string at(const char* name, int i) {
    return std::string(name) + "[" + std::to_string(i) + "]";
}

std::string cell_text(const Cell& c) {
    return "[" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
           "]";
}

Value cell_value(const Cell& c) {
    return std::vector<double>{double(c[0]), double(c[1]), double(c[2])};
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

bool finite3(dvec3 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// The grid's box: the bounds given, or the scene's with flat axes padded.
Bounds grid_box(const Input& in, std::array<bool, 3>* padded) {
    if (padded) *padded = {};
    if (in.has_bounds) return in.bounds;
    Bounds b;
    for (const Primitive& p : in.primitives) b.grow(bounds(p));
    const dvec3 e = b.extent();
    const double largest = std::max({e.x, e.y, e.z});
    const double pad = largest > 0 ? 0.5 * largest : 0.5;
    for (int i = 0; i < 3; ++i)
        if (!(e[i] > 0)) {
            b.min[i] -= pad, b.max[i] += pad;
            if (padded) (*padded)[i] = true;
        }
    return b;
}

// The cell index of coordinate x on axis a, clamped into the grid, consistent with the planes:
// plane(a, c) ≤ x < plane(a, c + 1) inside the grid (the division may round across a plane).
int index_of(const Grid& g, int a, double x) {
    const double u = std::floor((x - g.box.min[a]) / g.size[a]);
    int c = !(u >= 0) ? 0 : u >= g.n[a] - 1 ? g.n[a] - 1 : static_cast<int>(u);
    while (c > 0 && x < g.plane(a, c)) --c;
    while (c < g.n[a] - 1 && x >= g.plane(a, c + 1)) ++c;
    return c;
}

}  // namespace

Bounds UniformGrid::Grid::cell_box(const Cell& c) const {
    Bounds b;
    for (int a = 0; a < 3; ++a) b.min[a] = plane(a, c[a]), b.max[a] = plane(a, c[a] + 1);
    return b;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& UniformGrid::spec() {
    static const Spec spec{
        "uniform-grid",
        "Spatial subdivision: a uniform grid walked by 3D-DDA",
        "Bounding Boxes and Spatial Subdivision",
        {
            "B ← bounds of the scene;  s_i ← (max_i − min_i)/n_i       ▷ n_x × n_y × n_z cells",
            "for each primitive: list it in every cell it meets     ▷ bounds → candidates, exact "
            "test",
            "(t_min, t_max) ← slab test of E + t d against B;  miss → no cell is visited",
            "cell ← the cell of P(max(t_min, 0));  step_i ← sign d_i;  t_max_i ← next plane's t;  "
            "t_delta_i ← s_i/|d_i|",
            "loop:  t_exit ← min(t_max_x, t_max_y, t_max_z)",
            "  test the cell's primitives not yet tested (mailbox); keep the nearest hit",
            "  if nearest hit t ≤ t_exit: return it      ▷ inside this cell: final",
            "  i ← axis of the smallest t_max;  cell_i ← cell_i + step_i;  t_max_i ← t_max_i + "
            "t_delta_i",
            "  if cell is outside the grid: return miss",
        },
        {
            {"place", "build: a primitive listed in the cells it meets (bounds, then exact test)"},
            {"enter", "the ray enters the grid's box (slab test): the first cell, t_max, t_delta"},
            {"start-inside", "the origin is in the grid: the walk starts in E's own cell"},
            {"miss-grid", "the ray misses the grid's box: no cell is visited, nothing is tested"},
            {"empty-cell", "a cell lists no primitive: nothing to test, step on"},
            {"no-hit", "the cell's primitives are tested (or skipped by the mailbox): no hit yet"},
            {"hit-beyond-exit",
             "the nearest hit so far lies beyond this cell's exit: not final, step on"},
            {"hit", "the nearest hit lies in this cell (t ≤ t_exit): final, the walk stops"},
            {"exit", "the walk leaves the grid with no hit: the ray misses every primitive"},
        },
        {},  // no sliders
        {
            .predict = {
                {"enter", {"cell"}},
                {"empty-cell", {"t_exit"}},
                {"hit", {"t_nearest"}},
                {"hit-beyond-exit", {"t_nearest"}},
            },
            .mistakes = {
                {"hit-beyond-exit", "", "event:hit",
                 "accepted a hit beyond the cell without checking"},
                {"empty-cell", "t_max_y", "keep", "stepped a cell but forgot to advance t_max"},
            },
            .costs = {"counts", "brute_force"},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void UniformGrid::validate(const Input& in) {
    const std::size_t n = in.primitives.size();
    if (n == 0) throw InputError("primitives", "must list at least one primitive");
    if (n > kMaxPrimitives)
        throw InputError("primitives", "lists " + std::to_string(n) + " primitives; at most " +
                                           std::to_string(kMaxPrimitives) + " in a lesson");
    for (std::size_t p = 0; p < n; ++p) {
        const Bounds b = bounds(in.primitives[p]);
        if (!finite3(b.min) || !finite3(b.max) || !finite3(b.extent()))
            throw InputError(at("primitives", int(p)),
                             "is too large: its bounds overflow a double (beyond 1.8e308)");
    }
    long long total = 1;
    for (int a = 0; a < 3; ++a) {
        const int c = in.cells[a];
        if (c < 1 || c > kMaxAxisCells)
            throw InputError(at("cells", a), "must be a whole number from 1 to " +
                                                 std::to_string(kMaxAxisCells) + ", got " +
                                                 std::to_string(c));
        total *= c;
    }
    if (total > kMaxCells)
        throw InputError("cells",
                         std::to_string(in.cells[0]) + " × " + std::to_string(in.cells[1]) + " × " +
                             std::to_string(in.cells[2]) + " = " + std::to_string(total) +
                             " cells; at most " + std::to_string(kMaxCells) + " in a lesson");
    if (in.has_bounds) {
        for (int a = 0; a < 3; ++a) {
            check_finite(in.bounds.min[a], at("bounds.min", a));
            check_finite(in.bounds.max[a], at("bounds.max", a));
        }
        for (int a = 0; a < 3; ++a)
            if (!(in.bounds.min[a] < in.bounds.max[a]))
                throw InputError(at("bounds.max", a),
                                 "must be greater than bounds.min[" + std::to_string(a) + "] (" +
                                     given(in.bounds.max[a]) + " ≤ " + given(in.bounds.min[a]) +
                                     "): every cell needs a size on every axis");
        for (std::size_t p = 0; p < n; ++p) {
            const Bounds b = bounds(in.primitives[p]);
            for (int a = 0; a < 3; ++a)
                if (b.min[a] < in.bounds.min[a] || b.max[a] > in.bounds.max[a])
                    throw InputError(
                        at("primitives", static_cast<int>(p)),
                        std::string("reaches ") + kAxis[a] + " = " +
                            given(b.min[a] < in.bounds.min[a] ? b.min[a] : b.max[a]) +
                            ", outside the grid's bounds [" + given(in.bounds.min[a]) + ", " +
                            given(in.bounds.max[a]) +
                            "]: the grid would never test it (bounds must hold every primitive)");
        }
    }
    const Bounds box = grid_box(in, nullptr);
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(box.max[a] - box.min[a]) || !std::isfinite(box.min[a]) ||
            !std::isfinite(box.max[a]))
            throw InputError(in.has_bounds ? "bounds" : "primitives",
                             std::string("span too much on the ") + kAxis[a] +
                                 " axis: the grid's size overflows a double (beyond 1.8e308)");
    for (int a = 0; a < 3; ++a) {
        check_finite(in.origin[a], at("origin", a));
        check_finite(in.direction[a], at("direction", a));
    }
    if (in.direction == dvec3(0.0))
        throw InputError("direction",
                         "must not be the zero vector (0, 0, 0): a ray needs a direction");
    // Every t of the walk is a double: the planes' t and t_delta.
    for (int a = 0; a < 3; ++a) {
        const double d = in.direction[a];
        if (d == 0) continue;
        const double lo = box.min[a] - in.origin[a], hi = box.max[a] - in.origin[a];
        if (!std::isfinite(lo) || !std::isfinite(hi))
            throw InputError(at("origin", a),
                             "is too far from the grid: the distance to its planes overflows a "
                             "double (beyond 1.8e308)");
        const double size = (box.max[a] - box.min[a]) / in.cells[a];
        if (!std::isfinite(lo / d) || !std::isfinite(hi / d) || !std::isfinite(size / std::fabs(d)))
            throw InputError(at("direction", a),
                             "is too small against the grid: t = (plane − E)/d overflows a "
                             "double (beyond 1.8e308); scale the direction up");
    }
    // Hit points E + t d must be doubles too (a huge E with a huge d).
    if (!finite3(in.origin + in.direction) || !std::isfinite(glm::dot(in.direction, in.direction)))
        throw InputError("direction", "is too large: |d|² overflows a double; scale it down");
}

// ---- [build] --------------------------------------------------------------------------------

UniformGrid::Grid UniformGrid::build(const Input& in) {
    Grid g;
    g.box = grid_box(in, &g.padded);
    g.n = in.cells;
    for (int a = 0; a < 3; ++a) g.size[a] = (g.box.max[a] - g.box.min[a]) / g.n[a];
    g.cells.assign(static_cast<std::size_t>(g.n[0] * g.n[1] * g.n[2]), {});
    g.placed.resize(in.primitives.size());
    for (std::size_t p = 0; p < in.primitives.size(); ++p) {
        const Primitive& prim = in.primitives[p];
        const Bounds b = bounds(prim);
        Placement& pl = g.placed[p];
        for (int a = 0; a < 3; ++a) {
            const double m = kMargin * g.size[a];
            pl.lo[a] = index_of(g, a, b.min[a] - m);
            pl.hi[a] = index_of(g, a, b.max[a] + m);
        }
        pl.candidates =
            (pl.hi[0] - pl.lo[0] + 1) * (pl.hi[1] - pl.lo[1] + 1) * (pl.hi[2] - pl.lo[2] + 1);
        Cell c;
        for (c[2] = pl.lo[2]; c[2] <= pl.hi[2]; ++c[2])
            for (c[1] = pl.lo[1]; c[1] <= pl.hi[1]; ++c[1])
                for (c[0] = pl.lo[0]; c[0] <= pl.hi[0]; ++c[0]) {
                    Bounds cb = g.cell_box(c);
                    const dvec3 m = kMargin * g.size;
                    cb.min -= m, cb.max += m;
                    if (!overlaps(prim, cb)) continue;
                    g.cells[static_cast<std::size_t>(g.index(c))].push_back(static_cast<int>(p));
                    ++pl.kept;
                }
    }
    return g;
}

int UniformGrid::brute_force(const Input& in, double& t) {
    int best = -1;
    t = kInf;
    for (std::size_t p = 0; p < in.primitives.size(); ++p) {
        const PrimitiveHit h = intersect(in.primitives[p], in.origin, in.direction);
        if (h.hit() && h.t < t) t = h.t, best = static_cast<int>(p);
    }
    return best;
}

// ---- [walk] ---------------------------------------------------------------------------------

namespace {

// The slab test against the grid's box, then the first cell, t_max and t_delta.
void grid_enter(const Input& in, const Grid& g, RayAabb::Result& entry, Walk& w) {
    entry = RayAabb::intersect({g.box.min, g.box.max, in.origin, in.direction});
    w.tested.assign(in.primitives.size(), 0);
    if (!entry.hit) return;
    w.inside = true;
    const double t0 = std::max(entry.t_min, 0.0);
    w.t_enter = t0;
    const dvec3 P = in.origin + t0 * in.direction;
    for (int a = 0; a < 3; ++a) {
        const double d = in.direction[a];
        int c;
        if (entry.t_min > 0 && entry.axes[a].t_near == entry.t_min && d != 0) {
            c = d > 0 ? 0 : g.n[a] - 1;  // the entry face: exactly the first cell on this axis
        } else {
            c = index_of(g, a, P[a]);
            // On a cell plane going down: the cell below, which the ray goes into.
            if (d < 0 && c > 0 && P[a] == g.plane(a, c)) --c;
        }
        w.cell[a] = c;
        w.step[a] = d > 0 ? 1 : d < 0 ? -1 : 0;
        if (d > 0)
            w.t_max[a] = (g.plane(a, c + 1) - in.origin[a]) / d;
        else if (d < 0)
            w.t_max[a] = (g.plane(a, c) - in.origin[a]) / d;
        else
            w.t_max[a] = UniformGrid::kInf;
        w.t_delta[a] = d != 0 ? g.size[a] / std::fabs(d) : UniformGrid::kInf;
    }
}

// Visits the current cell; returns how it ended. `log` (may be null) gets the tests.
Outcome grid_visit(const Input& in, const Grid& g, Walk& w, std::vector<Test>* log, int* axis) {
    w.visited.push_back(w.cell);
    const std::vector<int>& list = g.cells[static_cast<std::size_t>(g.index(w.cell))];
    for (int p : list) {
        if (w.tested[static_cast<std::size_t>(p)]) {
            ++w.mailbox_skips;
            if (log) log->push_back({p, UniformGrid::kInf, true});
            continue;
        }
        w.tested[static_cast<std::size_t>(p)] = 1;
        ++w.primitive_tests;
        const PrimitiveHit h =
            intersect(in.primitives[static_cast<std::size_t>(p)], in.origin, in.direction);
        if (h.hit() && (h.t < w.best_t || (h.t == w.best_t && p < w.best)))
            w.best_t = h.t, w.best = p;
        if (log) log->push_back({p, h.t, false});
    }
    w.t_exit = std::min({w.t_max.x, w.t_max.y, w.t_max.z});
    if (w.best >= 0 && w.best_t <= w.t_exit) {
        w.inside = false;
        return Outcome::Hit;
    }
    int a = 0;
    if (w.t_max.y < w.t_max[a]) a = 1;
    if (w.t_max.z < w.t_max[a]) a = 2;
    if (axis) *axis = a;
    w.cell[a] += w.step[a];
    if (w.cell[a] < 0 || w.cell[a] >= g.n[a]) {
        w.inside = false;
        return w.best >= 0 ? Outcome::Hit : Outcome::Exit;  // (a hit past the box: rounding)
    }
    w.t_enter = w.t_max[a];
    w.t_max[a] += w.t_delta[a];
    if (w.best >= 0) return Outcome::Beyond;
    return list.empty() ? Outcome::Empty : Outcome::NoHit;
}

UniformGrid::Result make_result(const Input& in, const Shared<Grid>& g, const RayAabb::Result& e,
                                const Walk& w, const Cell& last) {
    UniformGrid::Result r;
    r.entered = e.hit;
    if (e.hit) r.t_start = std::max(e.t_min, 0.0), r.t_end = e.t_max;
    r.hit = w.best >= 0 && !w.inside;
    if (r.hit) {
        r.primitive = w.best;
        r.t = w.best_t;
        r.point = in.origin + w.best_t * in.direction;
        r.cell = last;
    }
    r.cells_visited = w.visited;
    r.primitive_tests = w.primitive_tests;
    r.mailbox_skips = w.mailbox_skips;
    r.brute_force_tests = static_cast<int>(in.primitives.size());
    r.grid = g;
    return r;
}

}  // namespace

UniformGrid::Result UniformGrid::trace(const Input& in) {
    return trace(in, Shared<Grid>(build(in)));
}

UniformGrid::Result UniformGrid::trace(const Input& in, const Shared<Grid>& g) {
    RayAabb::Result entry;
    Walk w;
    grid_enter(in, *g, entry, w);
    Cell last{};
    while (w.inside) {
        last = w.cell;
        grid_visit(in, *g, w, nullptr, nullptr);
    }
    return make_result(in, g, entry, w, last);
}

UniformGrid::State UniformGrid::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.grid = Shared<Grid>(build(in));
    return s;
}

UniformGrid::Result UniformGrid::result(const State& s) {
    return make_result(*s.in, s.grid, s.entry, s.w, s.visited_cell);
}

// ---- [step] ---------------------------------------------------------------------------------

void UniformGrid::step(State& s, StepInfo* info) {
    switch (s.phase) {
        case Phase::Build:
            ++s.built;
            s.last = Outcome::Placed;
            if (s.built == static_cast<int>(s.in->primitives.size())) s.phase = Phase::Enter;
            break;
        case Phase::Enter:
            grid_enter(*s.in, *s.grid, s.entry, s.w);
            s.last = !s.entry.hit         ? Outcome::MissGrid
                     : s.entry.t_min <= 0 ? Outcome::StartInside
                                          : Outcome::Entered;
            s.phase = s.entry.hit ? Phase::Cell : Phase::Done;
            break;
        case Phase::Cell:
            s.tests.clear();
            s.visited_cell = s.w.cell;
            s.stepped_axis = -1;
            s.last = grid_visit(*s.in, *s.grid, s.w, &s.tests, &s.stepped_axis);
            if (!s.w.inside) s.phase = Phase::Done;
            break;
        case Phase::Done:
            return;
    }
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = UniformGrid::State;

std::string range_text(int lo, int hi) {
    return lo == hi ? std::to_string(lo) : std::to_string(lo) + "–" + std::to_string(hi);
}

void narrate_place(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    const int p = s.built - 1;
    const Primitive& prim = in.primitives[static_cast<std::size_t>(p)];
    const UniformGrid::Placement& pl = g.placed[static_cast<std::size_t>(p)];
    const Bounds b = bounds(prim);
    info.event = "place";
    info.line = kLinePlace;
    std::string kept;
    int shown = 0;
    Cell c;
    for (c[2] = pl.lo[2]; c[2] <= pl.hi[2]; ++c[2])
        for (c[1] = pl.lo[1]; c[1] <= pl.hi[1]; ++c[1])
            for (c[0] = pl.lo[0]; c[0] <= pl.hi[0]; ++c[0]) {
                const auto& list = g.cells[static_cast<std::size_t>(g.index(c))];
                if (std::find(list.begin(), list.end(), p) == list.end()) continue;
                if (shown < 12) kept += (shown ? ", " : "") + cell_text(c);
                ++shown;
            }
    if (shown > 12) kept += ", …";
    std::string text = "Build: primitives[" + std::to_string(p) + "], the " + describe(prim) +
                       ". Its bounds " + num(b.min) + "–" + num(b.max) + " span cells x " +
                       range_text(pl.lo[0], pl.hi[0]) + ", y " + range_text(pl.lo[1], pl.hi[1]) +
                       ", z " + range_text(pl.lo[2], pl.hi[2]) + " (" +
                       std::to_string(pl.candidates) + " candidate" +
                       (pl.candidates == 1 ? "" : "s") + "); the exact " + kind_name(prim.kind) +
                       "–box test keeps " + std::to_string(pl.kept) + ": " + kept + ".";
    if (pl.kept < pl.candidates)
        text += " The other " + std::to_string(pl.candidates - pl.kept) +
                " only meet its bounding box, not the " + kind_name(prim.kind) + " itself.";
    if (p == 0) {
        text += " (The grid: " + num(g.box.min) + "–" + num(g.box.max) + ", " +
                std::to_string(g.n[0]) + " × " + std::to_string(g.n[1]) + " × " +
                std::to_string(g.n[2]) + " cells of size " + num(g.size) + ".)";
    }
    info.narration = std::move(text);
    info.vars = {{"primitive", static_cast<long long>(p)},
                 {"candidates", static_cast<long long>(pl.candidates)},
                 {"kept", static_cast<long long>(pl.kept)},
                 {"s", vec(g.size)}};
}

std::string axis_setup(const State& s, int a) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    const Walk& w = s.w;
    const double d = in.direction[a];
    const std::string A = kAxis[a];
    if (d == 0)
        return A + ": d_" + A + " = 0, so t_max_" + A + " = t_delta_" + A +
               " = ∞ (the ray never steps on " + A + ")";
    const double plane = g.plane(a, w.cell[a] + (d > 0 ? 1 : 0));
    return A + ": step " + (d > 0 ? "+1" : "−1") + ", t_max_" + A + " = (" + num(plane) + " − " +
           sub(in.origin[a]) + ")/" + sub(d) + " = " + tn(w.t_max[a]) + ", t_delta_" + A + " = " +
           num(g.size[a]) + "/" + num(std::fabs(d)) + " = " + tn(w.t_delta[a]);
}

void narrate_enter(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const RayAabb::Result& e = s.entry;
    info.line = kLineEnter;
    if (!e.hit) {
        info.event = "miss-grid";
        info.narration =
            "The slab test against the grid's box gives t_min = " + tn(e.t_min) +
            ", t_max = " + tn(e.t_max) +
            (e.t_min > e.t_max ? " (t_min > t_max)" : " (t_max < 0: behind E)") +
            ": the ray misses the whole grid, so no cell is visited and no primitive is tested — "
            "brute force would still have tested all " +
            std::to_string(in.primitives.size()) + ".";
        info.math =
            "t_{min} = " + tt(e.t_min) + ",\\; t_{max} = " + tt(e.t_max) + ":\\ \\text{miss}";
        info.vars = {{"t_min", tv(e.t_min)}, {"t_max", tv(e.t_max)}};
        return;
    }
    const Walk& w = s.w;
    const dvec3 P = in.origin + w.t_enter * in.direction;
    std::string text;
    if (e.t_min <= 0) {
        info.event = "start-inside";
        text = "The origin E = " + num(in.origin) +
               " is in the grid (slab test: t_min = " + tn(e.t_min) +
               " ≤ 0 ≤ t_max = " + tn(e.t_max) + "), so the walk starts at t = 0 in E's own cell " +
               cell_text(w.cell) + ".";
    } else {
        info.event = "enter";
        text = "The slab test against the grid's box: t_min = " + tn(e.t_min) +
               ", t_max = " + tn(e.t_max) + ". The ray enters at t = " + tn(e.t_min) +
               ", the point " + num(P) + ", in cell " + cell_text(w.cell) + ".";
    }
    info.line = kLineSetup;
    text +=
        " Per axis — " + axis_setup(s, 0) + "; " + axis_setup(s, 1) + "; " + axis_setup(s, 2) + ".";
    info.narration = std::move(text);
    info.math = "t_{max} = (" + tt(w.t_max.x) + ", " + tt(w.t_max.y) + ", " + tt(w.t_max.z) +
                "),\\; t_{\\Delta} = (" + tt(w.t_delta.x) + ", " + tt(w.t_delta.y) + ", " +
                tt(w.t_delta.z) + ")";
    info.vars = {{"t_min", tv(e.t_min)},         {"t_max", tv(e.t_max)},
                 {"cell", cell_value(w.cell)},   {"step", cell_value(w.step)},
                 {"t_max_x", tv(w.t_max.x)},     {"t_max_y", tv(w.t_max.y)},
                 {"t_max_z", tv(w.t_max.z)},     {"t_delta_x", tv(w.t_delta.x)},
                 {"t_delta_y", tv(w.t_delta.y)}, {"t_delta_z", tv(w.t_delta.z)}};
}

void narrate_cell(const State& s, StepInfo& info) {
    const Grid& g = *s.grid;
    const Walk& w = s.w;
    const Cell& c = s.visited_cell;
    const auto& list = g.cells[static_cast<std::size_t>(g.index(c))];
    std::string text = "Cell " + cell_text(c) + " (visit " + std::to_string(w.visited.size()) +
                       ", the ray in it up to t_exit = " + tn(w.t_exit) + "): ";
    if (list.empty()) {
        text += "it lists no primitive, so nothing is tested.";
    } else {
        text += "it lists " + std::to_string(list.size()) + " primitive" +
                (list.size() == 1 ? "" : "s") + ". ";
        std::string tests;
        for (const Test& t : s.tests) {
            if (!tests.empty()) tests += "; ";
            tests += std::to_string(t.primitive) + ": ";
            if (t.skipped)
                tests += "skipped (mailbox: tested already on this ray)";
            else
                tests += t.t < UniformGrid::kInf ? "hit at t = " + num(t.t) : "miss";
        }
        text += "Tests — " + tests + ".";
    }
    info.line = kLineTest;
    switch (s.last) {
        case Outcome::Hit:
            info.event = "hit";
            info.line = kLineFinal;
            if (w.best_t <= w.t_exit)
                text += " The nearest hit, primitive " + std::to_string(w.best) +
                        " at t = " + num(w.best_t) + ", is ≤ t_exit = " + tn(w.t_exit) +
                        ": it lies in this cell, and every cell the ray passed before has been "
                        "tested, so nothing nearer exists.";
            else  // past the last cell's exit only by a rounding: nothing is left to test
                text += " The walk leaves the grid here, and the nearest hit, primitive " +
                        std::to_string(w.best) + " at t = " + num(w.best_t) +
                        ", lies past this last exit t_exit = " + tn(w.t_exit) +
                        " only by a rounding: no cell is left, so it is final.";
            text += " Final: the walk stops after " + std::to_string(w.visited.size()) + " cell" +
                    (w.visited.size() == 1 ? "" : "s") + " and " +
                    std::to_string(w.primitive_tests) + " primitive test" +
                    (w.primitive_tests == 1 ? "" : "s") +
                    " (brute force: " + std::to_string(s.in->primitives.size()) + ").";
            info.math = "t = " + tt(w.best_t) + (w.best_t <= w.t_exit ? " \\le" : " >") +
                        " t_{exit} = " + tt(w.t_exit);
            break;
        case Outcome::Exit:
            info.event = "exit";
            info.line = kLineLeave;
            text += " No hit, and stepping " + std::string(kAxis[s.stepped_axis]) +
                    " leaves the grid: the ray misses every primitive, found with " +
                    std::to_string(w.primitive_tests) + " test" +
                    (w.primitive_tests == 1 ? "" : "s") +
                    " (brute force: " + std::to_string(s.in->primitives.size()) + ").";
            break;
        default: {
            if (s.last == Outcome::Beyond) {
                info.event = "hit-beyond-exit";
                text += " The nearest hit so far, primitive " + std::to_string(w.best) +
                        " at t = " + num(w.best_t) +
                        ", is beyond this cell's exit t_exit = " + tn(w.t_exit) +
                        ": not final. The primitive reaches into this cell, but "
                        "the ray meets it further on, in a later cell — and a nearer primitive "
                        "may sit in the next cell, between t_exit and that hit. Keep it and "
                        "walk on.";
            } else {
                info.event = list.empty() ? "empty-cell" : "no-hit";
            }
            const int a = s.stepped_axis;
            const std::string A = kAxis[a];
            text += " Next: t_max_" + A + " = " + tn(w.t_enter) + " is the smallest, so step " + A +
                    " by " + (w.step[a] > 0 ? "+1" : "−1") + " to cell " + cell_text(w.cell) +
                    ", and t_max_" + A + " = " + tn(w.t_enter) + " + " + tn(w.t_delta[a]) + " = " +
                    tn(w.t_max[a]) + ".";
            std::string tied;
            for (int b = 0; b < 3; ++b)
                if (b != a && w.t_max[b] == w.t_enter)
                    tied += std::string(tied.empty() ? "" : " and ") + "t_max_" + kAxis[b];
            if (!tied.empty())
                text += " A tie: " + tied + " = " + tn(w.t_enter) +
                        " too — the ray passes through a lattice edge or corner there. The tie "
                        "goes to x before y before z, so the next cell is visited for zero length "
                        "(it only touches the ray at that point).";
            info.math =
                "t_{max} = (" + tt(w.t_max.x) + ", " + tt(w.t_max.y) + ", " + tt(w.t_max.z) + ")";
            break;
        }
    }
    info.narration = std::move(text);
    info.vars = {{"cell", cell_value(c)},
                 {"t_exit", tv(w.t_exit)},
                 {"t_max_x", tv(w.t_max.x)},
                 {"t_max_y", tv(w.t_max.y)},
                 {"t_max_z", tv(w.t_max.z)},
                 {"cells_visited", static_cast<long long>(w.visited.size())},
                 {"primitive_tests", static_cast<long long>(w.primitive_tests)},
                 {"mailbox_skips", static_cast<long long>(w.mailbox_skips)}};
    if (w.best >= 0) {
        info.vars.push_back({"nearest", static_cast<long long>(w.best)});
        info.vars.push_back({"t_nearest", w.best_t});
    }
}

}  // namespace

void UniformGrid::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Outcome::Placed:
            narrate_place(s, info);
            break;
        case Outcome::Entered:
        case Outcome::StartInside:
        case Outcome::MissGrid:
            narrate_enter(s, info);
            break;
        default:
            narrate_cell(s, info);
            break;
    }
}

}  // namespace cg
