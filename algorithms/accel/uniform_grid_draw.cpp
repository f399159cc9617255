// Uniform grids, the picture. The 3D view: the grid's lattice (thin grey lines), the
// primitives (grey; orange when tested in this step, dark when tested before, green the hit),
// the cells visited (blue, translucent; the current one orange), the ray from E, its entry
// point, the current cell's exit and the hit, and the next plane crossings t_max per axis.
// A grid one cell deep (n_z = 1) is also drawn flat in the world, as the exam draws it: the
// cells visited, the columns i and rows j, every x- and y-plane crossing of the ray as a tick
// (x: blue squares, y: grey dots — they come t_delta_x and t_delta_y apart, the key to the 3D-DDA),
// and for the cell just visited its two exits t_max_x and t_max_y, the nearer one orange: the axis
// the walk steps along.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "accel/uniform_grid.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Cell = UniformGrid::Cell;
using Grid = UniformGrid::Grid;
using Input = UniformGrid::Input;
using Outcome = UniformGrid::Outcome;
using Phase = UniformGrid::Phase;
using Walk = UniformGrid::Walk;
using Test = UniformGrid::Test;

const char* const kAxis[3] = {"x", "y", "z"};

std::string tn(double t) {
    if (std::isinf(t)) return t > 0 ? "∞" : "−∞";
    return num(t);
}

bool finite3(dvec3 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Whether the step just taken visited a cell (as opposed to building, entering or missing).
bool cell_step(const UniformGrid::State& s) {
    return s.last != Outcome::Placed && s.last != Outcome::None && s.last != Outcome::Entered &&
           s.last != Outcome::StartInside && s.last != Outcome::MissGrid;
}

// The t at which the ray leaves cell c through its far plane on axis a (∞ when d_a = 0): the
// cell's t_max_a, as the walk had it when it visited the cell.
double exit_t(const Grid& g, const Input& in, const Cell& c, int a) {
    const double d = in.direction[a];
    if (d == 0) return UniformGrid::kInf;
    return (g.plane(a, d > 0 ? c[a] + 1 : c[a]) - in.origin[a]) / d;
}

void grid_push(Scene& scene, const Segment3& s) {
    if (finite3(s.a) && finite3(s.b)) scene.segments3.push_back(s);
}
void grid_push(Scene& scene, const Point3& p) {
    if (finite3(p.p)) scene.points3.push_back(p);
}
void grid_push(Scene& scene, const Face3& f) {
    for (const dvec3& p : f.points)
        if (!finite3(p)) return;
    scene.faces3.push_back(f);
}

// A box as 6 faces (a flat one as its one face, seen from the front).
void grid_box_faces(Scene& scene, const Bounds& b, Style style, float alpha, bool outline) {
    auto corner = [&](int c) {
        return dvec3(c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y,
                     c & 4 ? b.max.z : b.min.z);
    };
    static const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                    {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (const auto& q : quads)
        grid_push(scene, Face3{{corner(q[0]), corner(q[1]), corner(q[2]), corner(q[3])},
                               style,
                               alpha,
                               outline,
                               true});
}

// A sphere as three great circles (and its outline seen from +z, the z circle).
void grid_sphere(Scene& scene, const Primitive& p, Style style) {
    constexpr int kN = 32;
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        dvec3 prev{};
        for (int i = 0; i <= kN; ++i) {
            const double phi = 2 * 3.14159265358979323846 * i / kN;
            dvec3 q = p.a;
            q[u] += p.radius * std::cos(phi);
            q[v] += p.radius * std::sin(phi);
            if (i > 0) grid_push(scene, Segment3{prev, q, "", style, false});
            prev = q;
        }
    }
}

void grid_primitive(Scene& scene, const Primitive& p, Style style, float alpha) {
    switch (p.kind) {
        case PrimitiveKind::Sphere:
            grid_sphere(scene, p, style);
            break;
        case PrimitiveKind::Triangle:
            grid_push(scene, Face3{{p.a, p.b, p.c}, style, alpha, true, true});
            break;
        case PrimitiveKind::Box:
            grid_box_faces(scene, bounds(p), style, alpha, true);
            break;
    }
}

bool finite2(glm::dvec2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

void grid_push2(Scene& scene, Polygon2 poly) {
    for (const glm::dvec2& p : poly.points)
        if (!finite2(p)) return;
    scene.polygons.push_back(std::move(poly));
}

glm::dvec2 xy(dvec3 p) {
    return {p.x, p.y};
}

Polygon2 grid_rect(dvec3 mn, dvec3 mx, Style style, bool filled) {
    return Polygon2{{{mn.x, mn.y}, {mx.x, mn.y}, {mx.x, mx.y}, {mn.x, mx.y}}, style, true, filled};
}

// The primitive seen from the front (along −z): a sphere's outline circle, a box's rectangle,
// the triangle's projection.
void grid_primitive2(Scene& scene, const Primitive& p, Style style) {
    switch (p.kind) {
        case PrimitiveKind::Sphere: {
            Polygon2 c{{}, style, true, true};
            for (int i = 0; i < 48; ++i) {
                const double phi = 2 * 3.14159265358979323846 * i / 48;
                c.points.push_back(xy(p.a) + p.radius * glm::dvec2(std::cos(phi), std::sin(phi)));
            }
            grid_push2(scene, std::move(c));
            break;
        }
        case PrimitiveKind::Triangle:
            grid_push2(scene, Polygon2{{xy(p.a), xy(p.b), xy(p.c)}, style, true, true});
            break;
        case PrimitiveKind::Box:
            grid_push2(scene, grid_rect(p.a, p.b, style, true));
            break;
    }
}

// How far to draw the ray: past the grid's exit, or a grid's diagonal when it misses.
double grid_ray_far(const Grid& g, const Input& in) {
    const RayAabb::Result box = RayAabb::intersect({g.box.min, g.box.max, in.origin, in.direction});
    const double diag = glm::length(g.box.extent()) / glm::length(in.direction);
    double t_far = 1;
    if (box.hit)
        t_far = box.t_max + 0.15 * diag;
    else if (std::isfinite(diag))
        t_far = std::max(diag, 1.0);
    return std::isfinite(t_far) ? t_far : 1.0;
}

Cell grid_cell_of(const Grid& g, std::size_t ci) {
    const int i = static_cast<int>(ci);
    return {i % g.n[0], (i / g.n[0]) % g.n[1], i / (g.n[0] * g.n[1])};
}

// The grid seen from the front (one layer in z): the cells visited filled (blue; the current
// one orange), the lattice, the column and row numbers, the ray and its points.
void front_view(const UniformGrid::State& s, Scene& scene) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    const Walk& w = s.w;
    const bool visited = cell_step(s);
    for (std::size_t i = 0; i < w.visited.size(); ++i) {
        const bool current = visited && i + 1 == w.visited.size();
        const Bounds b = g.cell_box(w.visited[i]);
        grid_push2(scene,
                   grid_rect(b.min, b.max, {current ? Role::Active : Role::Window, 2.0f}, true));
    }
    if (w.inside && !visited && s.phase == Phase::Cell) {  // the first cell, about to be visited
        const Bounds b = g.cell_box(w.cell);
        grid_push2(scene, grid_rect(b.min, b.max, {Role::Active, 2.0f, true}, false));
    }
    if (s.last == Outcome::Placed) {
        const int p = s.built - 1;
        for (std::size_t ci = 0; ci < g.cells.size(); ++ci) {
            const auto& list = g.cells[ci];
            if (std::find(list.begin(), list.end(), p) == list.end()) continue;
            const Bounds b = g.cell_box(grid_cell_of(g, ci));
            grid_push2(scene, grid_rect(b.min, b.max, {Role::Kept, 1.0f}, true));
        }
    }
    const Style lattice{Role::Construction, 1.0f};
    for (int i = 0; i <= g.n[0]; ++i) {
        const double x = g.plane(0, i);
        scene.segments.push_back({{x, g.box.min.y}, {x, g.box.max.y}, "", lattice, false});
    }
    for (int j = 0; j <= g.n[1]; ++j) {
        const double y = g.plane(1, j);
        scene.segments.push_back({{g.box.min.x, y}, {g.box.max.x, y}, "", lattice, false});
    }
    for (int i = 0; i < g.n[0]; ++i)
        scene.labels.push_back({{g.box.min.x + (i + 0.5) * g.size.x, g.box.min.y - 0.3 * g.size.y},
                                "i " + std::to_string(i),
                                {Role::Neutral}});
    for (int j = 0; j < g.n[1]; ++j)
        scene.labels.push_back({{g.box.max.x + 0.35 * g.size.x, g.box.min.y + (j + 0.5) * g.size.y},
                                "j " + std::to_string(j),
                                {Role::Neutral}});

    const dvec3 E = in.origin, d = in.direction;
    const double t_far = grid_ray_far(g, in);
    if (d.x != 0 || d.y != 0) {
        const Segment2 ray{xy(E), xy(E + t_far * d), "", {Role::Subject, 1.5f}, true};
        if (finite2(ray.a) && finite2(ray.b)) scene.segments.push_back(ray);
    }
    auto point = [&](double t, const std::string& label, Role role, float radius) {
        const glm::dvec2 p = xy(E + t * d);
        if (finite2(p)) scene.points.push_back({p, label, {role}, radius});
    };
    point(0, "E", Role::Subject, 5.0f);
    const bool walking = s.phase != Phase::Build && s.last != Outcome::Placed;
    if (walking && s.entry.hit && s.entry.t_min > 0)
        point(s.entry.t_min, "in t = " + num(s.entry.t_min, 4), Role::Entering, 5.0f);
    // Every x- and y-plane crossing inside the grid: t_delta_x (and t_delta_y) apart.
    if (walking && s.entry.hit) {
        const double t0 = std::max(s.entry.t_min, 0.0), t1 = s.entry.t_max;
        for (int a = 0; a < 2; ++a) {
            if (d[a] == 0) continue;
            for (int k = 0; k <= g.n[a]; ++k) {
                const double t = (g.plane(a, k) - E[a]) / d[a];
                if (!(t > t0 && t < t1)) continue;
                const glm::dvec2 p = xy(E + t * d);
                if (!finite2(p)) continue;
                if (a == 0)
                    scene.polygons.push_back(
                        {{p + dvec2(-0.08, -0.08) * g.size.x, p + dvec2(0.08, -0.08) * g.size.x,
                          p + dvec2(0.08, 0.08) * g.size.x, p + dvec2(-0.08, 0.08) * g.size.x},
                         {Role::Window, 1.0f},
                         true,
                         true});
                else
                    scene.points.push_back({p, "", {Role::Neutral}, 3.5f});
            }
        }
        // How far apart they come, over the grid.
        std::string apart;
        for (int a = 0; a < 2; ++a)
            if (d[a] != 0)
                apart += std::string(apart.empty() ? "" : " · ") + "t_delta_" + kAxis[a] + " = " +
                         tn(w.t_delta[a]);
        scene.labels.push_back(
            {{g.box.min.x, g.box.max.y + 0.45 * g.size.y}, apart, {Role::Neutral}, 5});
    }
    // The cell just visited: its exits on x and y; the nearer is where the walk steps.
    if (visited && !w.visited.empty()) {
        const Cell& c = w.visited.back();
        const double tx = exit_t(g, in, c, 0), ty = exit_t(g, in, c, 1);
        for (int a = 0; a < 2; ++a) {
            const double t = a == 0 ? tx : ty, other = a == 0 ? ty : tx;
            if (!std::isfinite(t)) continue;
            const bool nearer = a == 0 ? t <= other : t < other;
            const glm::dvec2 p = xy(E + t * d);
            if (!finite2(p)) continue;
            scene.points.push_back({p,
                                    std::string("t_max_") + kAxis[a] + " = " + num(t, 4),
                                    {nearer ? Role::Active : Role::Neutral},
                                    nearer ? 6.0f : 4.5f,
                                    nearer ? 30 : 10});
        }
    }
    if (w.best >= 0 && walking) {
        if (s.phase == Phase::Done)
            point(w.best_t, "hit t = " + num(w.best_t, 4), Role::Kept, 8.0f);
        else
            point(w.best_t, "not final: t = " + num(w.best_t, 4), Role::Discarded, 7.0f);
    }
}

}  // namespace

void UniformGrid::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Grid& g = *s.grid;
    const Walk& w = s.w;
    // One layer in z: also the 2D picture seen from the front, the exam's "4 × 4 grid".
    const bool front = g.n[2] == 1;
    if (front) front_view(s, scene);

    // The lattice: lines along each axis through every plane crossing of the other two.
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        for (int i = 0; i <= g.n[u]; ++i)
            for (int j = 0; j <= g.n[v]; ++j) {
                dvec3 p0, p1;
                p0[a] = g.box.min[a], p1[a] = g.box.max[a];
                p0[u] = p1[u] = g.plane(u, i);
                p0[v] = p1[v] = g.plane(v, j);
                grid_push(scene, Segment3{p0, p1, "", {Role::Construction, 1.0f}, false});
            }
    }

    // The cells visited, the current one strongest.
    const bool walking = s.last != Outcome::Placed && s.last != Outcome::None;
    for (std::size_t i = 0; i < w.visited.size(); ++i) {
        const bool now = i + 1 == w.visited.size() && s.phase != Phase::Enter;
        const bool current = now && (s.last != Outcome::Entered && s.last != Outcome::StartInside);
        grid_box_faces(scene, g.cell_box(w.visited[i]),
                       {current ? Role::Active : Role::Window, current ? 2.0f : 1.0f},
                       current ? 0.35f : 0.12f, current);
    }
    if (walking && w.inside && (s.last == Outcome::Entered || s.last == Outcome::StartInside))
        grid_box_faces(scene, g.cell_box(w.cell), {Role::Active, 2.0f}, 0.3f, true);
    // During the build: the cells the primitive just placed went into.
    if (s.last == Outcome::Placed) {
        const int p = s.built - 1;
        for (std::size_t ci = 0; ci < g.cells.size(); ++ci) {
            const auto& list = g.cells[ci];
            if (std::find(list.begin(), list.end(), p) == list.end()) continue;
            const Cell c{static_cast<int>(ci) % g.n[0], (static_cast<int>(ci) / g.n[0]) % g.n[1],
                         static_cast<int>(ci) / (g.n[0] * g.n[1])};
            grid_box_faces(scene, g.cell_box(c), {Role::Kept, 1.0f}, 0.18f, false);
        }
    }

    // The primitives.
    std::vector<char> now(in.primitives.size(), 0);
    for (const Test& t : s.tests)
        if (!t.skipped) now[static_cast<std::size_t>(t.primitive)] = 1;
    const bool finished = s.phase == Phase::Done;
    for (std::size_t p = 0; p < in.primitives.size(); ++p) {
        const bool placed = s.phase != Phase::Build || static_cast<int>(p) < s.built;
        Style st{Role::Subject, 1.5f};
        float alpha = 0.2f;
        if (static_cast<int>(p) == w.best && finished)
            st = {Role::Kept, 2.5f}, alpha = 0.45f;
        else if (now[p] && s.phase != Phase::Build)
            st = {Role::Active, 2.5f}, alpha = 0.4f;
        else if (!w.tested.empty() && w.tested[p])
            st = {Role::Neutral, 1.5f}, alpha = 0.25f;
        else if (s.last == Outcome::Placed && static_cast<int>(p) == s.built - 1)
            st = {Role::Kept, 2.5f}, alpha = 0.4f;
        else if (!placed)
            st = {Role::Construction, 1.0f}, alpha = 0.08f;
        grid_primitive(scene, in.primitives[p], st, alpha);
        const Bounds b = bounds(in.primitives[p]);
        scene.labels3.push_back({b.max, std::to_string(p), {st.role}});
        if (front) {
            grid_primitive2(scene, in.primitives[p], st);
            const glm::dvec2 at2{b.max.x, b.max.y};
            if (finite2(at2)) scene.labels.push_back({at2, std::to_string(p), {st.role}});
        }
    }

    // The ray.
    const dvec3 E = in.origin, d = in.direction;
    const double t_far = grid_ray_far(g, in);
    grid_push(scene, Segment3{E, E + t_far * d, "E + t d", {Role::Subject, 1.5f}, true});
    grid_push(scene, Point3{E, "E", {Role::Subject}, 5.0f});
    if (walking && s.entry.hit && s.entry.t_min > 0)
        grid_push(scene, Point3{E + s.entry.t_min * d,
                                "enter t = " + num(s.entry.t_min, 4),
                                {Role::Entering},
                                5.0f});
    // The cell just visited: its exit (and, on a deep grid, the exit on each axis).
    if (cell_step(s) && !w.visited.empty()) {
        const Cell& c = w.visited.back();
        double t_exit = UniformGrid::kInf;
        int axis = 0;
        for (int a = 0; a < 3; ++a)
            if (exit_t(g, in, c, a) < t_exit) t_exit = exit_t(g, in, c, a), axis = a;
        if (front) {
            grid_push(scene, Point3{E + t_exit * d, "t_exit", {Role::Active}, 5.0f});
        } else {
            for (int a = 0; a < 3; ++a) {
                const double t = exit_t(g, in, c, a);
                if (std::isfinite(t))
                    grid_push(scene, Point3{E + t * d,
                                            std::string("t_max_") + kAxis[a] + " = " + num(t, 4),
                                            {a == axis ? Role::Active : Role::Neutral},
                                            a == axis ? 6.0f : 4.0f,
                                            a == axis ? 30 : 10});
            }
        }
    }
    // The camera frames the grid and where the ray comes into it.
    Bounds framed = g.box;
    framed.grow(E + (s.entry.hit ? std::max(s.entry.t_min, 0.0) : 0.0) * d);
    if (finite3(framed.min) && finite3(framed.max)) add_focus(scene, framed.min, framed.max);
    if (w.best >= 0 && walking) {
        const dvec3 H = E + w.best_t * d;
        if (finished)
            grid_push(scene, Point3{H, "hit t = " + num(w.best_t, 4), {Role::Kept}, 8.0f});
        else
            grid_push(scene,
                      Point3{H, "not final: t = " + num(w.best_t, 4), {Role::Discarded}, 7.0f});
    }
    scene.extent3 = 0;
}

}  // namespace cg
