// The uniform grid: the 4 × 4 exam cases worked by hand (the cells visited, t_max and t_delta);
// on random scenes (spheres, boxes, triangles, nested and overlapping, resolutions 1 to 8 per
// axis) 10,000 random rays each — from inside, along cell planes, grazing vertices, components
// 0 — whose hit equals brute force and whose cells visited equal an independent long-double
// reference (every cell the ray meets, sorted by entry t); every primitive listed in every
// cell it meets (against clipping in long double); run-to-end equals the plain function;
// errors naming the field; replay; the picture; the exam.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>

#include "accel/uniform_grid.hpp"
#include "core/format.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Bounds;
using cg::Primitive;
using cg::PrimitiveKind;
using cg::UniformGrid;
using glm::dvec3;
using Cell = UniformGrid::Cell;
using Cells = std::vector<Cell>;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using cg::prim::box;
using cg::prim::sphere;
using cg::prim::triangle;

// A 4 × 4 × 1 grid of unit cells over [0, 4]² × [z0, z1].
UniformGrid::Input grid4(std::vector<Primitive> prims, dvec3 E, dvec3 d, double z0 = 0,
                         double z1 = 1) {
    UniformGrid::Input in;
    in.primitives = std::move(prims);
    in.cells = {4, 4, 1};
    in.has_bounds = true;
    in.bounds.min = {0, 0, z0};
    in.bounds.max = {4, 4, z1};
    in.origin = E;
    in.direction = d;
    return in;
}

cg::test::Traced<UniformGrid> traced(const UniformGrid::Input& in) {
    return cg::test::run_traced<UniformGrid>(in);
}

std::vector<std::string> walk_events(const cg::test::Traced<UniformGrid>& t) {
    std::vector<std::string> e;
    for (const auto& s : t.steps)
        if (s.event != "place") e.push_back(s.event);
    return e;
}

const cg::StepInfo& first(const cg::test::Traced<UniformGrid>& t, const std::string& event) {
    for (const auto& s : t.steps)
        if (s.event == event) return s;
    throw std::runtime_error("no step " + event);
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("uniform-grid");
    if (!l) throw std::runtime_error("no lesson for uniform-grid");
    return *l;
}

UniformGrid::Input input_of(const cg::json& j) {
    return cg::test::input_of<UniformGrid>("uniform-grid", j);
}

UniformGrid::Input preset(const std::string& name) {
    const cg::LessonPreset* p = lesson().preset(name);
    if (!p) throw std::runtime_error("no preset " + name);
    return input_of(p->input);
}

// ---- The independent references -------------------------------------------------------------

using LD = long double;
constexpr LD kLInf = std::numeric_limits<LD>::infinity();

// The ray's t interval in the closed box [mn, mx], long double (empty: lo > hi).
struct Interval {
    LD lo = -kLInf, hi = kLInf;
};
// `shrink` > 0 asks for the ray strictly inside on an axis it runs parallel to (by that much):
// a ray sliding along a cell's face meets the closed cell but does not pass through it.
Interval slab_ld(dvec3 mn, dvec3 mx, dvec3 E, dvec3 d, dvec3 shrink = dvec3(0.0)) {
    Interval r;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            const LD lo = LD(mn[a]) + LD(shrink[a]), hi = LD(mx[a]) - LD(shrink[a]);
            const bool in =
                shrink[a] > 0 ? lo < LD(E[a]) && LD(E[a]) < hi : lo <= LD(E[a]) && LD(E[a]) <= hi;
            if (!in) return {kLInf, -kLInf};
            continue;
        }
        const LD t0 = (LD(mn[a]) - LD(E[a])) / LD(d[a]), t1 = (LD(mx[a]) - LD(E[a])) / LD(d[a]);
        r.lo = std::max(r.lo, std::min(t0, t1));
        r.hi = std::min(r.hi, std::max(t0, t1));
    }
    return r;
}

// Whether the closed triangle meets the closed box: the triangle clipped (Sutherland–Hodgman,
// long double) by the box's six half-spaces keeps a point. `grow` grows (> 0) or shrinks the
// box, to tell a real answer from a rounding.
bool triangle_box_ld(const Primitive& t, const Bounds& b, LD grow) {
    using V = std::array<LD, 3>;
    std::vector<V> poly = {V{t.a.x, t.a.y, t.a.z}, V{t.b.x, t.b.y, t.b.z}, V{t.c.x, t.c.y, t.c.z}};
    for (int a = 0; a < 3 && !poly.empty(); ++a)
        for (int side = 0; side < 2 && !poly.empty(); ++side) {
            const LD plane = side == 0 ? LD(b.min[a]) - grow : LD(b.max[a]) + grow;
            auto inside = [&](const V& p) { return side == 0 ? p[a] >= plane : p[a] <= plane; };
            std::vector<V> out;
            for (std::size_t i = 0; i < poly.size(); ++i) {
                const V& p = poly[i];
                const V& q = poly[(i + 1) % poly.size()];
                const bool ip = inside(p), iq = inside(q);
                if (ip) out.push_back(p);
                if (ip != iq) {
                    const LD s = (plane - p[a]) / (q[a] - p[a]);
                    V m;
                    for (int k = 0; k < 3; ++k) m[k] = p[k] + s * (q[k] - p[k]);
                    m[a] = plane;
                    out.push_back(m);
                }
            }
            poly = std::move(out);
        }
    return !poly.empty();
}

// Whether primitive p meets the closed box b in long double, the box grown by `grow`.
bool overlaps_ld(const Primitive& p, const Bounds& b, LD grow) {
    switch (p.kind) {
        case PrimitiveKind::Sphere: {
            LD d2 = 0;
            for (int a = 0; a < 3; ++a) {
                const LD c = p.a[a], lo = LD(b.min[a]) - grow, hi = LD(b.max[a]) + grow;
                const LD g = c < lo ? lo - c : c > hi ? c - hi : 0;
                d2 += g * g;
            }
            return d2 <= LD(p.radius) * LD(p.radius);
        }
        case PrimitiveKind::Box:
            for (int a = 0; a < 3; ++a)
                if (LD(p.b[a]) < LD(b.min[a]) - grow || LD(b.max[a]) + grow < LD(p.a[a]))
                    return false;
            return true;
        case PrimitiveKind::Triangle:
            return triangle_box_ld(p, b, grow);
    }
    return true;
}

// ---- Random scenes and rays -------------------------------------------------------------------

UniformGrid::Input random_scene(cg::Rng& rng) {
    UniformGrid::Input in;
    const int n = static_cast<int>(rng.integer(1, 40));
    const double scale = rng.chance(0.2) ? rng.uniform(0.001, 1000) : 1.0;
    auto P = [&] {
        return scale * dvec3(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4));
    };
    for (int i = 0; i < n; ++i) {
        const double kind = rng.uniform(0, 1);
        if (kind < 0.35) {
            in.primitives.push_back(sphere(P(), scale * rng.uniform(0.05, 2.5)));
        } else if (kind < 0.65) {
            const dvec3 a = P(), b = P();
            dvec3 mn = glm::min(a, b), mx = glm::max(a, b);
            for (int k = 0; k < 3; ++k)
                if (rng.chance(0.1)) mx[k] = mn[k];  // flat
            in.primitives.push_back(box(mn, mx));
        } else {
            dvec3 a = P(), b = P(), c = P();
            if (rng.chance(0.3)) {  // in a coordinate plane (flat scenes, grazing rays)
                const int k = static_cast<int>(rng.integer(0, 2));
                b[k] = a[k], c[k] = a[k];
            }
            const dvec3 nrm = glm::cross(b - a, c - a);
            if (glm::dot(nrm, nrm) == 0) c += dvec3(scale, 0, 0);
            in.primitives.push_back(triangle(a, b, c));
        }
        if (rng.chance(0.1) && !in.primitives.empty()) {  // nested: a small copy inside
            const Bounds bb = cg::bounds(in.primitives.back());
            in.primitives.push_back(
                sphere(bb.centre(), 0.2 * std::max(1e-3 * scale, glm::length(bb.extent()))));
        }
    }
    if (rng.chance(0.4)) {  // exact ties: copies (same t, another index) and integer boxes
        const std::size_t m = in.primitives.size();  // sharing faces with their neighbours
        for (std::size_t i = 0; i < m; i += 3) in.primitives.push_back(in.primitives[i]);
        for (int i = 0; i < 6; ++i) {
            const dvec3 c(double(rng.integer(-4, 3)), double(rng.integer(-4, 3)),
                          double(rng.integer(-4, 3)));
            in.primitives.push_back(box(scale * c, scale * (c + dvec3(1.0))));
            in.primitives.push_back(
                box(scale * (c + dvec3(1, 0, 0)), scale * (c + dvec3(2, 1, 1))));
        }
    }
    if (in.primitives.size() > UniformGrid::kMaxPrimitives)
        in.primitives.resize(UniformGrid::kMaxPrimitives);
    for (int a = 0; a < 3; ++a) in.cells[a] = static_cast<int>(rng.integer(1, 8));
    if (rng.chance(0.3)) {  // bounds given, a margin around the scene
        Bounds b;
        for (const auto& p : in.primitives) b.grow(cg::bounds(p));
        in.has_bounds = true;
        in.bounds.min = b.min - scale * dvec3(rng.uniform(0, 1));
        in.bounds.max = b.max + scale * dvec3(rng.uniform(0.01, 1));
    }
    return in;
}

// A point of a primitive: a vertex, an edge point, a corner, a pole.
dvec3 feature(cg::Rng& rng, const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Sphere: {
            dvec3 q = p.a;
            q[rng.integer(0, 2)] += rng.chance(0.5) ? p.radius : -p.radius;
            return q;
        }
        case PrimitiveKind::Box:
            return dvec3(rng.chance(0.5) ? p.a.x : p.b.x, rng.chance(0.5) ? p.a.y : p.b.y,
                         rng.chance(0.5) ? p.a.z : p.b.z);
        case PrimitiveKind::Triangle: {
            const double s = rng.chance(0.5) ? 0.0 : rng.uniform(0, 1);
            const dvec3 v[3] = {p.a, p.b, p.c};
            const int i = static_cast<int>(rng.integer(0, 2));
            return v[i] + s * (v[(i + 1) % 3] - v[i]);
        }
    }
    return p.a;
}

void random_ray(cg::Rng& rng, const UniformGrid::Input& scene, const UniformGrid::Grid& g,
                UniformGrid::Input& in) {
    const dvec3 lo = g.box.min, ext = g.box.extent();
    auto in_box = [&] {
        return dvec3(lo.x + rng.uniform(0, 1) * ext.x, lo.y + rng.uniform(0, 1) * ext.y,
                     lo.z + rng.uniform(0, 1) * ext.z);
    };
    const double what = rng.uniform(0, 1);
    dvec3 E;
    if (what < 0.3)
        E = in_box();  // from inside
    else
        E = g.box.centre() + 1.5 * (in_box() - g.box.centre()) +
            dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * ext;
    if (rng.chance(0.15)) {  // on a cell plane
        const int a = static_cast<int>(rng.integer(0, 2));
        E[a] = g.plane(a, static_cast<int>(rng.integer(0, g.n[a])));
    }
    dvec3 target = in_box();
    if (rng.chance(0.35))  // at a vertex, an edge, a corner, a pole: grazing
        target = feature(rng, scene.primitives[static_cast<std::size_t>(rng.integer(
                                  0, static_cast<long long>(scene.primitives.size()) - 1))]);
    dvec3 d = target - E;
    for (int a = 0; a < 3; ++a)
        if (rng.chance(0.12)) d[a] = 0;
    if (rng.chance(0.05)) d = dvec3(0.0), d[rng.integer(0, 2)] = rng.chance(0.5) ? 1 : -1;
    if (d == dvec3(0.0)) d = dvec3(1, 0, 0);
    in.origin = E;
    in.direction = d;
}

std::string cells_text(const Cells& cs) {
    std::string s;
    for (const Cell& c : cs)
        s += "[" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) +
             "] ";
    return s;
}

// Every coordinate of a scene is finite ("" if so, else what is not).
std::string scene_problem(const cg::Scene& s) {
    auto f3 = [](dvec3 p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    for (const auto& p : s.points3)
        if (!f3(p.p)) return "points3";
    for (const auto& g : s.segments3)
        if (!f3(g.a) || !f3(g.b)) return "segments3";
    for (const auto& f : s.faces3)
        for (auto q : f.points)
            if (!f3(q)) return "faces3";
    for (const auto& l : s.labels3)
        if (!f3(l.p)) return "labels3";
    auto f2 = [](glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); };
    for (const auto& g : s.segments)
        if (!f2(g.a) || !f2(g.b)) return "segments";
    for (const auto& p : s.points)
        if (!f2(p.p)) return "points";
    for (const auto& l : s.labels)
        if (!f2(l.p)) return "labels";
    for (const auto& g : s.polygons)
        for (auto q : g.points)
            if (!f2(q)) return "polygons";
    return "";
}

}  // namespace

// ---- Worked by hand -------------------------------------------------------------------------

TEST_CASE("uniform-grid: the 4 × 4 exam cases worked by hand", "[accel][uniform-grid]") {
    SECTION("a hit beyond the cell's exit is not final: a nearer sphere waits in the next cell") {
        // E = (-1, 0.25), d = (1, 0.5): in at t = 1, (0, 0.75), cell [0, 0];
        // t_max = (2, 1.5, ∞), t_delta = (1, 2, ∞).
        const auto in = input_of(cg::test::algorithm("uniform-grid").example());
        const auto t = traced(in);
        CHECK(walk_events(t) ==
              std::vector<std::string>{"enter", "empty-cell", "hit-beyond-exit", "hit"});
        CHECK(t.result.cells_visited == Cells{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}});
        CHECK(t.result.hit);
        CHECK(t.result.primitive == 1);
        CHECK(t.result.t == Approx(2.3).epsilon(1e-14));
        CHECK(t.result.cell == Cell{1, 1, 0});
        CHECK(t.result.primitive_tests == 2);
        CHECK(t.result.mailbox_skips == 1);  // sphere 0 again in [1, 1, 0]
        CHECK(t.result.brute_force_tests == 3);
        const auto& enter = first(t, "enter");
        CHECK_THAT(enter.narration, Catch::Contains("t_max_x = (1 − (−1))/1 = 2") &&
                                        Catch::Contains("t_delta_x = 1/1 = 1") &&
                                        Catch::Contains("t_max_y = (1 − 0.25)/0.5 = 1.5") &&
                                        Catch::Contains("t_delta_y = 1/0.5 = 2") &&
                                        Catch::Contains("t_max_z = t_delta_z = ∞"));
        const auto& beyond = first(t, "hit-beyond-exit");
        CHECK_THAT(beyond.narration,
                   Catch::Contains("primitive 0 at t = 2.56") &&
                       Catch::Contains("beyond this cell's exit t_exit = 2") &&
                       Catch::Contains("nearer primitive may sit in the next cell"));
        CHECK_THAT(t.steps.back().narration, Catch::Contains("0: skipped (mailbox"));
        // The build: sphere 0 spans x 0–3, y 1–3 by its bounds.
        const auto& g = *t.result.grid;
        CHECK(g.placed[0].lo == Cell{0, 1, 0});
        CHECK(g.placed[0].hi == Cell{3, 3, 0});
        CHECK(g.placed[0].candidates == 12);
        CHECK(g.placed[0].kept == 12);  // it reaches into every one
        CHECK(g.placed[1].kept == 2);   // its bounds touch y = 1: [1, 0, 0] too (closed)
        CHECK(g.placed[2].kept == 2);   // the box over [2, 0] and [3, 0]
    }
    SECTION("the hit beyond the exit becomes final in the next cell (mailbox: not re-tested)") {
        // E = (-1, 0.25), d = (2, 1): in at t = 0.5, (0, 0.75); t_max = (1, 0.75),
        // t_delta = (0.5, 1). Sphere (0.75, 1.25) r 0.3 pokes into [0, 0] from above.
        const auto t = traced(grid4({sphere({0.75, 1.25, 0.5}, 0.3)}, {-1, 0.25, 0.5}, {2, 1, 0}));
        CHECK(walk_events(t) == std::vector<std::string>{"enter", "hit-beyond-exit", "hit"});
        CHECK(t.result.cells_visited == Cells{{0, 0, 0}, {0, 1, 0}});
        CHECK(t.result.t == Approx((4.5 - std::sqrt(0.3875)) / 5).epsilon(1e-14));
        CHECK(t.result.primitive_tests == 1);
        CHECK(t.result.mailbox_skips == 1);
        CHECK_THAT(first(t, "hit-beyond-exit").narration,
                   Catch::Contains("t_exit = 0.75") &&
                       Catch::Contains("step y by +1 to cell [0, 1, 0], and t_max_y = 0.75 + 1 = "
                                       "1.75"));
    }
    SECTION("a miss: the whole walk, t_max and t_delta at every step") {
        const auto t = traced(grid4({sphere({3.5, 0.5, 0.5}, 0.3)}, {-1, 0.25, 0.5}, {2, 1, 0}));
        CHECK(t.result.cells_visited ==
              Cells{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {3, 2, 0}});
        CHECK_FALSE(t.result.hit);
        CHECK(t.result.primitive_tests == 0);
        CHECK(walk_events(t).back() == "exit");
        // The exits: min(t_max) at each cell.
        std::vector<double> exits;
        for (const auto& s : t.steps)
            for (const auto& v : s.vars)
                if (v.name == "t_exit") exits.push_back(std::get<double>(v.value));
        CHECK(exits == std::vector<double>{0.75, 1, 1.5, 1.75, 2, 2.5});
        CHECK_THAT(
            t.steps[2].narration,
            Catch::Contains("step y by +1 to cell [0, 1, 0], and t_max_y = 0.75 + 1 = 1.75"));
        CHECK_THAT(t.steps[3].narration,
                   Catch::Contains("step x by +1 to cell [1, 1, 0], and t_max_x = 1 + 0.5 = 1.5"));
    }
    SECTION("the origin inside: the walk starts in E's cell at t = 0") {
        const auto t = traced(grid4({sphere({3.5, 1.5, 0.5}, 0.25)}, {1.5, 1.5, 0.5}, {1, 0, 0}));
        CHECK(walk_events(t).front() == "start-inside");
        CHECK(t.result.cells_visited == Cells{{1, 1, 0}, {2, 1, 0}, {3, 1, 0}});
        CHECK(t.result.t == 1.75);
        CHECK_THAT(first(t, "start-inside").narration,
                   Catch::Contains("t_max_x = (2 − 1.5)/1 = 0.5") &&
                       Catch::Contains("t_max_y = t_delta_y = ∞"));
    }
    SECTION("the origin on a cell plane, going down: the cell below") {
        const auto t = traced(grid4({sphere({0.5, 1.5, 0.5}, 0.25)}, {2, 1.5, 0.5}, {-1, 0, 0}));
        CHECK(t.result.cells_visited == Cells{{1, 1, 0}, {0, 1, 0}});
        CHECK(t.result.t == 1.25);
        CHECK_THAT(first(t, "start-inside").narration,
                   Catch::Contains("t_max_x = (1 − 2)/(−1) = 1"));
    }
    SECTION("a ray that misses the grid: no cell, no test") {
        const auto t = traced(grid4({sphere({0.5, 0.5, 0.5}, 0.25)}, {-1, 5, 0.5}, {1, 0, 0}));
        CHECK(walk_events(t) == std::vector<std::string>{"miss-grid"});
        CHECK(t.result.cells_visited.empty());
        CHECK_FALSE(t.result.entered);
        CHECK(t.result.primitive_tests == 0);
    }
    SECTION("along the cell plane y = 2: grazing a sphere that touches it from below") {
        const auto t = traced(grid4({sphere({1.5, 1.5, 0.5}, 0.5)}, {-1, 2, 0.5}, {1, 0, 0}));
        CHECK(t.result.cells_visited == Cells{{0, 2, 0}, {1, 2, 0}});
        CHECK(t.result.hit);
        CHECK(t.result.t == 2.5);
        CHECK(t.result.cell == Cell{1, 2, 0});
    }
    SECTION("through lattice corners: a tie, x steps first (a zero-length visit)") {
        const auto t = traced(grid4({sphere({3.5, 0.5, 0.5}, 0.25)}, {-1, -1, 0.5}, {1, 1, 0}));
        CHECK(t.result.cells_visited ==
              Cells{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {3, 2, 0}, {3, 3, 0}});
        CHECK_THAT(t.steps[2].narration,
                   Catch::Contains("A tie: t_max_y = 2 too") && Catch::Contains("zero length"));
    }
    SECTION("3D: a 2 × 2 × 2 grid, the ray along the diagonal plane") {
        UniformGrid::Input in;
        in.primitives = {box({1.25, 1, 1}, {2, 1.5, 2}), sphere({0.5, 0.5, 0.5}, 0.1)};
        in.cells = {2, 2, 2};
        in.has_bounds = true;
        in.bounds.min = {0, 0, 0};
        in.bounds.max = {2, 2, 2};
        in.origin = {0.25, 1.25, 0.75};
        in.direction = {1, 0, 1};
        const auto r = UniformGrid::trace(in);
        // x and z cross their planes at t = 0.75 and 0.25: z first, then x; the box's face
        // x = 1.25 at t = 1.
        CHECK(r.cells_visited == Cells{{0, 1, 0}, {0, 1, 1}, {1, 1, 1}});
        CHECK(r.hit);
        CHECK(r.t == 1);
    }
}

TEST_CASE("uniform-grid: the build — padding a flat scene, exact membership",
          "[accel][uniform-grid]") {
    UniformGrid::Input in;
    in.primitives = {triangle({0, 0, 0}, {4, 0, 0}, {0, 4, 0})};  // flat in z
    in.cells = {4, 4, 1};
    in.origin = {1, 1, 5};
    in.direction = {0, 0, -1};
    const auto g = UniformGrid::build(in);
    CHECK(g.padded == std::array<bool, 3>{false, false, true});
    CHECK(g.box.min.z == -2);
    CHECK(g.box.max.z == 2);
    // The triangle x + y ≤ 4 meets the cells with i + j ≤ 3, and touches those with i + j = 4
    // at a corner (closed cells list them too).
    int listed = 0;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const bool has = !g.cells[static_cast<std::size_t>(g.index({i, j, 0}))].empty();
            CHECK(has == (i + j <= 4));
            listed += has;
        }
    CHECK(listed == 13);
    CHECK(g.placed[0].candidates == 16);
    const auto r = UniformGrid::trace(in);
    CHECK(r.hit);
    CHECK(r.t == 5);
}

TEST_CASE("uniform-grid: the lesson's presets run to the plain function's result",
          "[accel][uniform-grid]") {
    CHECK(lesson().presets.size() == 10);
    CHECK(UniformGrid::trace(preset("a ray that misses the grid: no cell, no test")).entered ==
          false);
    CHECK(UniformGrid::trace(preset("through lattice corners: a tie, x steps first"))
              .cells_visited.size() == 7);
    // 3D: the triangle reaches into [1, 2, 2] but is met beyond its exit (t = 4.444 > 4); the
    // sphere in [2, 2, 2] is nearer.
    const auto d3 = traced(
        preset("3D: a 4 × 4 × 4 grid over spheres, boxes and a triangle (the scene's bounds)"));
    CHECK(walk_events(d3) ==
          std::vector<std::string>{"enter", "empty-cell", "empty-cell", "hit-beyond-exit", "hit"});
    CHECK(d3.result.cells_visited == Cells{{0, 1, 2}, {1, 1, 2}, {1, 2, 2}, {2, 2, 2}});
    CHECK(d3.result.primitive == 0);
    CHECK(d3.result.mailbox_skips == 1);
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        const auto in = input_of(p.input);
        CHECK(UniformGrid::trace(in) == cg::run_to_end<UniformGrid>(UniformGrid::start(in)));
    }
}

// ---- Random scenes ------------------------------------------------------------------------------

TEST_CASE("uniform-grid: every primitive is listed in every cell it meets (long-double clipping)",
          "[accel][uniform-grid]") {
    int pairs = 0, met = 0, ties = 0;
    for (int scene = 0; scene < 200; ++scene) {
        cg::Rng rng(5000 + scene);
        const auto in = random_scene(rng);
        UniformGrid::validate(in);
        const auto g = UniformGrid::build(in);
        for (std::size_t p = 0; p < in.primitives.size(); ++p) {
            Cell c;
            for (c[2] = 0; c[2] < g.n[2]; ++c[2])
                for (c[1] = 0; c[1] < g.n[1]; ++c[1])
                    for (c[0] = 0; c[0] < g.n[0]; ++c[0]) {
                        const auto& list = g.cells[static_cast<std::size_t>(g.index(c))];
                        const bool listed =
                            std::find(list.begin(), list.end(), static_cast<int>(p)) != list.end();
                        const Bounds cb = g.cell_box(c);
                        const LD hair = 1e-7L * LD(glm::length(g.size));
                        const bool in_ref = overlaps_ld(in.primitives[p], cb, 0);
                        const bool near_ref = overlaps_ld(in.primitives[p], cb, hair);
                        const bool far_ref = overlaps_ld(in.primitives[p], cb, -hair);
                        CAPTURE(scene, p, cells_text({c}));
                        ++pairs;
                        met += in_ref;
                        if (far_ref) REQUIRE(listed);          // clearly meets it: listed
                        if (!near_ref) REQUIRE_FALSE(listed);  // clearly apart: not listed
                        ties += near_ref != far_ref;
                        if (in_ref) REQUIRE(listed);  // touching counts (closed cells)
                    }
        }
    }
    CHECK(met > 10'000);
    WARN("uniform-grid membership: " << pairs << " primitive–cell pairs, " << met << " meeting, "
                                     << ties << " within a hair of touching");
}

TEST_CASE(
    "uniform-grid: 10,000 random rays per random scene — the hit is brute force's, the "
    "cells are every cell the ray meets, in order",
    "[accel][uniform-grid]") {
    long rays = 0, hits = 0, ties = 0, exact_ties = 0, inside = 0, zero = 0, beyond = 0,
         missed_grid = 0, skipped_cells = 0, corner_cases = 0;
    long grid_tests = 0, brute_tests = 0;
    for (int scene = 0; scene < 12; ++scene) {
        cg::Rng rng(100 + scene);
        UniformGrid::Input in = random_scene(rng);
        UniformGrid::validate(in);
        const cg::Shared<UniformGrid::Grid> grid(UniformGrid::build(in));
        const auto& g = *grid;
        for (int k = 0; k < 10'000; ++k) {
            random_ray(rng, in, g, in);
            CAPTURE(scene, k, cg::num(in.origin, 17), cg::num(in.direction, 17));
            try {
                UniformGrid::validate(in);
            } catch (const cg::InputError&) {
                FAIL("refused");
            }
            ++rays;
            const auto r = UniformGrid::trace(in, grid);
            double bt = 0;
            const int bp = UniformGrid::brute_force(in, bt);
            grid_tests += r.primitive_tests;
            brute_tests += r.brute_force_tests;
            REQUIRE(r.hit == (bp >= 0));
            if (r.hit) {
                ++hits;
                int at_min = 0;  // primitives brute force finds at the same nearest t
                for (const auto& p : in.primitives)
                    at_min += cg::intersect(p, in.origin, in.direction).t == bt;
                exact_ties += at_min > 1;
                REQUIRE(std::fabs(r.t - bt) <= 1e-12 * std::fabs(bt) + 1e-300);
                if (r.primitive != bp) {  // only at an exact tie
                    const auto h =
                        cg::intersect(in.primitives[static_cast<std::size_t>(r.primitive)],
                                      in.origin, in.direction);
                    REQUIRE(h.t == bt);
                    ++ties;
                }
            }
            for (int a = 0; a < 3; ++a) zero += in.direction[a] == 0;
            if (!r.entered) {
                REQUIRE(r.cells_visited.empty());
                ++missed_grid;
                continue;
            }
            inside += r.t_start == 0;
            // The cells: no repeats; each met by the ray (closed, a hair of slack); in order of
            // entry; and every cell the ray passes through with some length before the walk
            // stopped is among them.
            const LD scale = std::max<LD>(std::fabs(LD(r.t_end)), 1e-300L);
            const LD tol = 1e-9L * scale;
            std::set<Cell> seen;
            LD prev_lo = -kLInf;
            LD stop = LD(r.t_end);
            for (std::size_t i = 0; i < r.cells_visited.size(); ++i) {
                const Cell& c = r.cells_visited[i];
                REQUIRE(seen.insert(c).second);
                const Bounds cb = g.cell_box(c);
                const Interval iv = slab_ld(cb.min, cb.max, in.origin, in.direction);
                const LD lo = std::max(iv.lo, LD(r.t_start)), hi = iv.hi;
                CAPTURE(cells_text(r.cells_visited), i);
                REQUIRE(lo <= hi + tol);       // the ray meets it
                REQUIRE(lo >= prev_lo - tol);  // in order
                prev_lo = lo;
                if (i + 1 == r.cells_visited.size()) stop = hi;
            }
            if (r.hit)
                beyond += r.cells_visited.size() > 0 && [&] {
                    const Bounds cb = g.cell_box(r.cell);
                    return LD(r.t) > slab_ld(cb.min, cb.max, in.origin, in.direction).lo + tol;
                }();
            Cell c;
            for (c[2] = 0; c[2] < g.n[2]; ++c[2])
                for (c[1] = 0; c[1] < g.n[1]; ++c[1])
                    for (c[0] = 0; c[0] < g.n[0]; ++c[0]) {
                        const Bounds cb = g.cell_box(c);
                        if (seen.count(c)) continue;
                        // Passed through (strictly inside on the parallel axes, a hair in):
                        // must have been visited; met only on a face or at a corner: a tie.
                        const Interval iv =
                            slab_ld(cb.min, cb.max, in.origin, in.direction, 1e-9 * g.size);
                        const LD lo = std::max(iv.lo, LD(r.t_start)), hi = std::min(iv.hi, stop);
                        const Interval touch = slab_ld(cb.min, cb.max, in.origin, in.direction);
                        const LD tlo = std::max(touch.lo, LD(r.t_start)),
                                 thi = std::min(touch.hi, stop);
                        if (hi - lo > tol) {
                            CAPTURE(cells_text(r.cells_visited), cells_text({c}));
                            FAIL("a cell the ray passes through was not visited");
                        }
                        if (thi - tlo >= -tol) ++corner_cases;  // touched only: a tie, either way
                    }
            skipped_cells += static_cast<long>(g.cells.size()) - static_cast<long>(seen.size());
        }
    }
    CHECK(rays == 120'000);
    CHECK(hits > 30'000);
    CHECK(inside > 20'000);
    CHECK(zero > 20'000);
    CHECK(missed_grid > 5'000);
    CHECK(grid_tests < brute_tests);
    CHECK(exact_ties > 1'000);
    WARN("uniform-grid random: " << rays << " rays on 12 scenes, " << hits << " hits ("
                                 << exact_ties << " with several primitives at the nearest t, "
                                 << ties << " of them won by another primitive), " << inside
                                 << " from inside, " << missed_grid << " missing the grid, "
                                 << corner_cases << " cells touched only (corners, edges), "
                                 << skipped_cells << " cells rightly never visited, " << beyond
                                 << " hits past their cell's entry; "
                                 << grid_tests << " primitive tests against brute force's "
                                 << brute_tests);
}

TEST_CASE("accel overlaps: a primitive against a closed box, against long-double references",
          "[accel][uniform-grid]") {
    int met = 0, apart = 0, hair = 0;
    for (int trial = 0; trial < 100'000; ++trial) {
        cg::Rng rng(300'000 + trial);
        const UniformGrid::Input one = random_scene(rng);
        const Primitive& p = one.primitives[static_cast<std::size_t>(
            rng.integer(0, static_cast<long long>(one.primitives.size()) - 1))];
        const Bounds pb = cg::bounds(p);
        Bounds b;  // a box near the primitive, sometimes starting on its bounds' far face
        const dvec3 ext = glm::max(pb.extent(), dvec3(1e-3));
        for (int a = 0; a < 3; ++a) {
            b.min[a] = rng.chance(0.1) ? pb.max[a] : pb.min[a] + rng.uniform(-0.5, 1.2) * ext[a];
            b.max[a] = b.min[a] + rng.uniform(0, 0.8) * ext[a];
        }
        const LD h = 1e-9L * LD(glm::length(ext));
        const bool near_ref = overlaps_ld(p, b, h), far_ref = overlaps_ld(p, b, -h);
        const bool got = cg::overlaps(p, b);
        CAPTURE(trial, cg::describe(p), cg::num(b.min, 17), cg::num(b.max, 17));
        if (far_ref) REQUIRE(got);
        if (!near_ref) REQUIRE_FALSE(got);
        met += far_ref;
        apart += !near_ref;
        hair += near_ref != far_ref;
    }
    CHECK(met > 20'000);
    CHECK(apart > 20'000);
    WARN("overlaps(): " << met << " meeting, " << apart << " apart, " << hair
                        << " within a hair (either answer)");
}

TEST_CASE("uniform-grid: run to the end equals the plain function", "[accel][uniform-grid]") {
    for (int trial = 0; trial < 300; ++trial) {
        cg::Rng rng(9000 + trial);
        UniformGrid::Input in = random_scene(rng);
        const auto g = UniformGrid::build(in);
        random_ray(rng, in, g, in);
        CAPTURE(trial);
        CHECK(cg::run_to_end<UniformGrid>(UniformGrid::start(in)) == UniformGrid::trace(in));
    }
}

// ---- Errors, replay, picture, exam --------------------------------------------------------------

TEST_CASE("uniform-grid: bad input is refused, naming the field", "[accel][uniform-grid]") {
    auto error = [](const std::string& text) { return cg::test::error_of("uniform-grid", text); };
    const std::string S =
        R"("primitives": [{"type": "sphere", "center": [1, 1, 1], "radius": 0.5}])";
    CHECK(
        error("{" + S + R"(, "cells": [2, 2, 1], "origin": [-1, 1, 1], "direction": [1, 0, 0]})") ==
        "(accepted)");
    CHECK_THAT(
        error("{" + S + R"(, "cells": [2, 0, 1], "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("cells[1]: must be a whole number from 1 to 16"));
    CHECK_THAT(
        error("{" + S + R"(, "cells": [2, 1.5, 1], "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("cells[1]: must be a whole number"));
    CHECK_THAT(
        error("{" + S + R"(, "cells": [16, 16, 4], "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("cells: 16 × 16 × 4 = 1024 cells; at most 512"));
    CHECK_THAT(
        error("{" + S + R"(, "cells": [2, 2], "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("cells: must be [n_x, n_y, n_z]"));
    CHECK_THAT(
        error("{" + S + R"(, "cells": [2, 2, 1], "origin": [-1, 1, 1], "direction": [0, 0, 0]})"),
        Catch::StartsWith("direction: must not be the zero vector"));
    CHECK_THAT(
        error(
            "{" + S +
            R"(, "cells": [2, 2, 1], "bounds": {"min": [0, 0, 0], "max": [2, 2, 0]}, "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("bounds.max[2]: must be greater than bounds.min[2]"));
    CHECK_THAT(
        error(
            "{" + S +
            R"(, "cells": [2, 2, 1], "bounds": {"min": [0, 0, 0], "max": [1.2, 2, 2]}, "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("primitives[0]: reaches x = 1.5, outside the grid's bounds [0, 1.2]"));
    CHECK_THAT(
        error(
            R"({"primitives": [], "cells": [2, 2, 1], "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("primitives: must list at least one primitive"));
    std::string many = R"({"primitives": [)";
    for (int i = 0; i < 65; ++i)
        many += std::string(i ? ", " : "") +
                R"({"type": "sphere", "center": [1, 1, 1], "radius": 0.5})";
    CHECK_THAT(
        error(many + R"(], "cells": [2, 2, 1], "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("primitives: lists 65 primitives; at most 64"));
    CHECK_THAT(
        error(
            R"({"primitives": [{"type": "sphere", "center": [1, 1, 1], "radius": -1}], "cells": [2, 2, 1], "origin": [-1, 1, 1], "direction": [1, 0, 0]})"),
        Catch::StartsWith("primitives[0].radius: must be > 0"));
    CHECK_THAT(
        error("{" + S +
              R"(, "cells": [2, 2, 1], "origin": [-1e300, 1, 1], "direction": [1e-300, 0, 0]})"),
        Catch::StartsWith("direction[0]: is too small against the grid"));
    CHECK_THAT(
        error(
            "{" + S +
            R"(, "cells": [2, 2, 1], "origin": [-1, 1, 1], "direction": [1, 0, 0], "octree": true})"),
        Catch::StartsWith("octree: "));
    CHECK_THAT(error("{" + S + R"(, "cells": [2, 2, 1], "origin": [-1, 1, 1]})"),
               Catch::StartsWith("direction: is missing"));
}

TEST_CASE("uniform-grid: deterministic traces, replay on the example and the presets",
          "[accel][uniform-grid]") {
    const cg::Algorithm& a = cg::test::algorithm("uniform-grid");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
}

TEST_CASE("uniform-grid: the picture — the lattice, the cells visited, the tested, the hit",
          "[accel][uniform-grid]") {
    const auto in = input_of(cg::test::algorithm("uniform-grid").example());
    auto s = UniformGrid::start(in);
    for (int i = 0; i < 3; ++i) UniformGrid::step(s, nullptr);  // the build
    UniformGrid::step(s, nullptr);                              // enter
    UniformGrid::step(s, nullptr);                              // [0, 0, 0]
    UniformGrid::step(s, nullptr);                              // [0, 1, 0]: beyond
    cg::Scene scene;
    UniformGrid::draw(s, scene);
    CHECK(scene.has_3d());
    int lattice = 0;
    for (const auto& g : scene.segments3) lattice += g.style.role == cg::Role::Construction;
    CHECK(lattice == 5 * 2 + 2 * 5 + 5 * 5);  // lines along x, y and z
    // The current cell [0, 1, 0] strongest (orange), the earlier one blue.
    int current = 0, earlier = 0;
    for (const auto& f : scene.faces3) {
        if (f.style.role == cg::Role::Active && f.points.size() == 4 && f.alpha > 0.3f) {
            for (const auto& p : f.points) CHECK((p.x >= 0 && p.x <= 1 && p.y >= 1 && p.y <= 2));
            ++current;
        }
        if (f.style.role == cg::Role::Window) {
            for (const auto& p : f.points) CHECK((p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1));
            ++earlier;
        }
    }
    CHECK(current == 6);
    CHECK(earlier == 6);
    // The pending hit is marked "not final", sphere 0 drawn as tested (orange).
    bool pending = false;
    for (const auto& p : scene.points3)
        if (p.style.role == cg::Role::Discarded)
            pending = p.label.find("not final") != std::string::npos;
    CHECK(pending);
    // The front view (one layer in z): the same cells as filled squares, the ray, the lattice.
    CHECK(scene.has_2d());
    int current2 = 0, earlier2 = 0;
    for (const auto& g : scene.polygons) {
        if (g.points.size() != 4 || !g.filled) continue;
        const glm::dvec2 lo = glm::min(glm::min(g.points[0], g.points[1]), g.points[2]);
        if (g.style.role == cg::Role::Active) current2 += lo == glm::dvec2(0, 1);
        if (g.style.role == cg::Role::Window) earlier2 += lo == glm::dvec2(0, 0);
    }
    CHECK((current2 == 1 && earlier2 == 1));
    int lattice2 = 0;
    for (const auto& g : scene.segments) lattice2 += g.style.role == cg::Role::Construction;
    CHECK(lattice2 == 5 + 5);
    // The cell's two exits, t_max_x and t_max_y, the nearer (the cell's t_exit) orange, and how
    // far apart the plane crossings come.
    int exits = 0, nearer = 0;
    for (const auto& p : scene.points) {
        if (p.label.rfind("t_max_", 0) != 0) continue;
        ++exits;
        if (p.style.role != cg::Role::Active) continue;
        ++nearer;
        CHECK(p.label.substr(p.label.find(" = ") + 3) == cg::num(s.w.t_exit, 4));
    }
    CHECK(exits == 2);
    CHECK(nearer == 1);
    bool apart = false;
    for (const auto& l : scene.labels)
        apart |= l.text.find("t_delta_x = " + cg::num(s.w.t_delta.x)) != std::string::npos &&
                 l.text.find("t_delta_y = " + cg::num(s.w.t_delta.y)) != std::string::npos;
    CHECK(apart);
    CHECK(scene.focus3.size() == 1);
    int orange_circles = 0;
    for (const auto& g : scene.segments3) orange_circles += g.style.role == cg::Role::Active;
    CHECK(orange_circles == 3 * 32);
    while (!UniformGrid::done(s)) UniformGrid::step(s, nullptr);
    scene.clear();
    UniformGrid::draw(s, scene);
    bool hit = false;
    for (const auto& p : scene.points3)
        if (p.style.role == cg::Role::Kept)
            hit = std::fabs(p.p.x - 1.3) < 1e-12 && std::fabs(p.p.y - 1.4) < 1e-12;
    CHECK(hit);

    // Every step of every preset and of 300 random scenes draws only finite coordinates.
    std::vector<UniformGrid::Input> inputs;
    for (const auto& p : lesson().presets) inputs.push_back(input_of(p.input));
    for (int trial = 0; trial < 300; ++trial) {
        cg::Rng rng(77'000 + trial);
        UniformGrid::Input r = random_scene(rng);
        const auto g = UniformGrid::build(r);
        random_ray(rng, r, g, r);
        inputs.push_back(r);
    }
    int drawn = 0;
    for (const auto& i : inputs) {
        auto st = UniformGrid::start(i);
        while (true) {
            cg::Scene sc;
            UniformGrid::draw(st, sc);
            REQUIRE(scene_problem(sc) == "");
            ++drawn;
            if (UniformGrid::done(st)) break;
            UniformGrid::step(st, nullptr);
        }
    }
    CHECK(drawn > 3'000);
}

TEST_CASE("uniform-grid: exam problems — 4 × 4 grids, no corner ties, graded right",
          "[accel][uniform-grid][exam]") {
    const cg::Algorithm& a = cg::test::algorithm("uniform-grid");
    int hits = 0, misses = 0, missed_grid = 0, inside = 0, beyond = 0, zero = 0;
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const auto in = input_of(p.input);
        CHECK(in.cells == Cell{4, 4, 1});
        const auto t = traced(in);
        const auto& r = t.result;
        hits += r.hit;
        misses += !r.hit;
        missed_grid += !r.entered;
        inside += r.entered && r.t_start == 0;
        zero += in.direction.x == 0 || in.direction.y == 0;
        for (int k = 0; k < 2; ++k)  // never along a cell plane (a tie rule, not a skill)
            if (in.direction[k] == 0) CHECK(in.origin[k] != std::floor(in.origin[k]));
        for (const auto& s : t.steps) beyond += s.event == "hit-beyond-exit";
        // No step ties two planes (a lattice corner): every exit is one axis's t_max alone.
        for (const auto& s : t.steps) {
            double tx = kInf, ty = kInf;
            bool cell = false;
            for (const auto& v : s.vars) {
                if (v.name == "t_exit") cell = true;
                if (v.name == "t_max_x" && std::holds_alternative<double>(v.value))
                    tx = std::get<double>(v.value);
                if (v.name == "t_max_y" && std::holds_alternative<double>(v.value))
                    ty = std::get<double>(v.value);
            }
            if (cell && s.event != "hit" && s.event != "exit") CHECK(tx != ty);
        }
        for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
    }
    CHECK(hits > 200);
    CHECK(misses > 100);
    CHECK(missed_grid > 10);
    CHECK(inside > 100);
    CHECK(beyond > 20);
    CHECK(zero > 50);
    const cg::ExamProblem p = cg::make_exam(a, 3);
    CHECK_THAT(p.question, Catch::Contains("4 × 4 × 1"));
    CHECK(p.answers == std::vector<std::string>{"cells_visited", "primitive", "t"});
}
