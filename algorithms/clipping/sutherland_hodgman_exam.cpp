// Sutherland-Hodgman exam problems: a small window with integer corners (mostly an
// axis-aligned rectangle, about one time in five a convex triangle, quadrilateral or pentagon,
// either way round) and a simple polygon of 3 to 6 integer vertices, convex or concave.
//
// What a problem guarantees (it is drawn again until all of this holds; after kAttempts draws
// a fixed problem is used, so the generator always ends; over 20,000 seeds that happened 3
// times, never in the tests' first 1,000):
//   - every coordinate of every intersection I is a multiple of 1/20 (halves, quarters,
//     fifths, ...: at most two decimals), and so is every crossing parameter t, except where a
//     polygon edge meets an axis-parallel window edge at a right angle (a vertical edge
//     crossing y = 4, say): there I is read off without dividing and t is not needed. Those t
//     too are nice when that can be had within the first quarter of the attempts;
//   - no side test is a rounding accident: every list point is on the 1/20 grid, so an exact
//     side value is 0 or at least 1/20 in size, and a computed one nearer 0 than 1e-6 (but not
//     0) is refused. So the doubles classify every point as a hand calculation does;
//   - the work stays small: at most kMaxCrossings intersections in the run and lists of at
//     most kMaxList vertices; and no slivers: the polygon's area is at least 3 and, where
//     something is visible, the clipped area at least 1.
// About one problem in four is degenerate in a way exams like: the polygon entirely inside,
// entirely outside, around the window, with a vertex on a window edge, or with an edge along a
// window edge. The ordinary problems cross the window, some concave ones cut into two pieces,
// and touch no window edge's line exactly.
//
// Sections: [geometry] exact tests on integer points  [windows]  [polygons]  [checks] the run
//           [exam_input]  [question]
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <string>

#include "clipping/sutherland_hodgman.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec2;
using Points = std::vector<dvec2>;

constexpr int kAttempts = 2000;   // draws before the fixed problem is used
constexpr int kMaxCrossings = 8;  // intersections computed in the whole run
constexpr std::size_t kMaxList = 9;

enum class Kind { Crossing, Inside, Outside, AroundWindow, VertexOnEdge, EdgeAlongEdge };

// ---- [geometry] ------------------------------------------------------------------------------
// On integer points (and centres that are halves) every product below is exact in doubles.

double cross(dvec2 a, dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

double twice_area(const Points& p) {
    double a2 = 0;
    for (std::size_t i = 0; i < p.size(); ++i) a2 += cross(p[i], p[(i + 1) % p.size()]);
    return a2;
}

int sign(double v) {
    return (v > 0) - (v < 0);
}

bool segments_touch(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    auto orient = [](dvec2 p, dvec2 q, dvec2 r) { return sign(cross(q - p, r - p)); };
    auto on = [](dvec2 p, dvec2 q, dvec2 r) {  // r on segment pq, given collinear
        return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
               std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
    };
    const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
              o4 = orient(c, d, b);
    if (o1 != o2 && o3 != o4) return true;
    return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
           (o4 == 0 && on(c, d, b));
}

// Simple, with a real turn at every vertex (no straight angles, no folding back).
bool simple(const Points& p) {
    const std::size_t n = p.size();
    if (n < 3 || twice_area(p) == 0) return false;
    for (std::size_t i = 0; i < n; ++i) {
        const dvec2 a = p[i], b = p[(i + 1) % n], c = p[(i + 2) % n];
        if (a == b || cross(b - a, c - b) == 0) return false;
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
            if (segments_touch(a, b, p[j], p[(j + 1) % n])) return false;
        }
    }
    return true;
}

bool concave(const Points& p) {
    const int turn = sign(twice_area(p));
    for (std::size_t i = 0; i < p.size(); ++i) {
        const dvec2 a = p[i], b = p[(i + 1) % p.size()], c = p[(i + 2) % p.size()];
        if (sign(cross(b - a, c - b)) != turn) return true;
    }
    return false;
}

// side(X) for window edge k, positive inside, as the algorithm defines it.
double side(const Points& w, std::size_t k, dvec2 x) {
    const dvec2 a = w[k], b = w[(k + 1) % w.size()];
    return sign(twice_area(w)) * cross(b - a, x - a);
}

bool strictly_inside(const Points& w, dvec2 x) {
    for (std::size_t k = 0; k < w.size(); ++k)
        if (side(w, k, x) <= 0) return false;
    return true;
}

dvec2 point(Rng& rng, long long x0, long long x1, long long y0, long long y1) {
    return {static_cast<double>(rng.integer(x0, x1)), static_cast<double>(rng.integer(y0, y1))};
}

// Sorts the points by angle round `c`, making a polygon star-shaped about c. False when two
// points lie in the same direction from c (or on it): then the order would not be unique.
bool sort_around(Points& p, dvec2 c) {
    auto half = [](dvec2 d) { return d.y > 0 || (d.y == 0 && d.x > 0) ? 0 : 1; };
    for (const dvec2 q : p)
        if (q == c) return false;
    std::sort(p.begin(), p.end(), [&](dvec2 a, dvec2 b) {
        const int ha = half(a - c), hb = half(b - c);
        return ha != hb ? ha < hb : cross(a - c, b - c) > 0;
    });
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        if (half(p[i] - c) == half(p[i + 1] - c) && cross(p[i] - c, p[i + 1] - c) == 0)
            return false;
    return true;
}

// Starts the list at a random vertex; half the time reverses it.
void shuffle_start(Points& p, Rng& rng) {
    std::rotate(p.begin(), p.begin() + rng.integer(0, static_cast<long long>(p.size()) - 1),
                p.end());
    if (rng.chance(0.5)) std::reverse(p.begin(), p.end());
}

// ---- [windows] -------------------------------------------------------------------------------

struct Box {
    long long x0, y0, x1, y1;
};

Box bounds(const Points& p) {
    Box b{1LL << 40, 1LL << 40, -(1LL << 40), -(1LL << 40)};
    for (const dvec2 q : p) {
        b.x0 = std::min(b.x0, static_cast<long long>(q.x));
        b.y0 = std::min(b.y0, static_cast<long long>(q.y));
        b.x1 = std::max(b.x1, static_cast<long long>(q.x));
        b.y1 = std::max(b.y1, static_cast<long long>(q.y));
    }
    return b;
}

// Mostly counter-clockwise from the bottom-left corner (edges bottom, right, top, left), as
// the course draws it; now and then from another corner, or clockwise.
Points rectangle(Rng& rng) {
    const double x0 = static_cast<double>(rng.integer(0, 3)),
                 y0 = static_cast<double>(rng.integer(0, 3));
    const double x1 = x0 + static_cast<double>(rng.integer(4, 7));
    const double y1 = y0 + static_cast<double>(rng.integer(3, 6));
    Points w = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    if (rng.chance(1.0 / 3)) shuffle_start(w, rng);
    return w;
}

// Andrew's monotone chain: counter-clockwise, without collinear points.
Points convex_hull(Points pts) {
    std::sort(pts.begin(), pts.end(),
              [](dvec2 a, dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return {};
    Points hull(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1);
    return hull;
}

// A triangle, quadrilateral or pentagon in [0, 7] × [0, 6], of area at least 10 so that it
// has room inside, either way round.
Points convex_window(Rng& rng) {
    const int m = static_cast<int>(rng.integer(3, 5));
    for (int attempt = 0; attempt < 1000; ++attempt) {
        Points pts;
        for (int i = 0; i < m; ++i) pts.push_back(point(rng, 0, 7, 0, 6));
        Points hull = convex_hull(pts);
        if (static_cast<int>(hull.size()) != m || twice_area(hull) < 20) continue;
        shuffle_start(hull, rng);
        return hull;
    }
    return {{1, 1}, {7, 2}, {3, 6}};
}

// ---- [polygons] ------------------------------------------------------------------------------

// n integer points round the centre c, within `reach` of it in x and y, sorted by angle.
Points star(Rng& rng, dvec2 c, int n, long long reach) {
    Points p;
    for (int i = 0; i < n; ++i) {
        const long long cx = static_cast<long long>(std::floor(c.x)),
                        cy = static_cast<long long>(std::floor(c.y));
        p.push_back(point(rng, cx - reach, cx + reach, cy - reach, cy + reach));
    }
    if (!sort_around(p, c)) return {};
    return p;
}

// The lattice points on window edge k, from its start to its end.
Points lattice_on_edge(const Points& w, std::size_t k) {
    const dvec2 a = w[k], d = w[(k + 1) % w.size()] - a;
    const long long g =
        std::gcd(std::llabs(static_cast<long long>(d.x)), std::llabs(static_cast<long long>(d.y)));
    Points p;
    for (long long i = 0; i <= g; ++i) p.push_back(a + d * (static_cast<double>(i) / g));
    return p;
}

// Window edge k as a lattice frame: A + s·u + h·n is a lattice point for integers s and h, with
// u the smallest lattice step along the edge (g of them from A to B) and n the normal pointing
// into the window, so h > 0 inside edge k's half-plane.
struct Frame {
    dvec2 A, u, n;
    long long g;
    dvec2 at(long long s, long long h) const {
        return A + u * static_cast<double>(s) + n * static_cast<double>(h);
    }
};

Frame frame(const Points& w, std::size_t k) {
    const Points on = lattice_on_edge(w, k);
    const dvec2 u = on[1] - on[0];
    const double orient = twice_area(w) > 0 ? 1 : -1;
    return {w[k], u, orient * dvec2(-u.y, u.x), static_cast<long long>(on.size()) - 1};
}

// A crown hanging through window edge k: two teeth reach inside, the notch between them and
// the rest stay outside, so the polygon is cut into two pieces (joined by a bridge along the
// edge in the output). Five vertices, or six with a peak on the outer side.
Points crown(const Points& w, Rng& rng) {
    const std::size_t k =
        static_cast<std::size_t>(rng.integer(0, static_cast<long long>(w.size()) - 1));
    const Frame f = frame(w, k);
    if (f.g < 3) return {};
    // Five distinct positions along the edge, the teeth (s[1], s[3]) on it.
    long long s[5];
    for (long long& x : s) x = rng.integer(-1, f.g + 1);
    std::sort(s, s + 5);
    if (std::adjacent_find(s, s + 5) != s + 5 || s[1] < 0 || s[3] > f.g) return {};
    const long long high = rng.integer(2, 3);
    Points p = {f.at(s[0], -high), f.at(s[1], rng.integer(1, 3)),
                f.at(s[2], -rng.integer(1, high - 1)), f.at(s[3], rng.integer(1, 3)),
                f.at(s[4], -high)};
    if (rng.chance(0.5)) p.push_back(f.at(rng.integer(s[1], s[3]), -high - 1));
    return p;
}

// The window's box grown by 1 to 3 on each side, with up to two corners cut off.
Points box_around(const Points& w, Rng& rng) {
    const Box b = bounds(w);
    const double x0 = static_cast<double>(b.x0 - rng.integer(1, 3)),
                 y0 = static_cast<double>(b.y0 - rng.integer(1, 3)),
                 x1 = static_cast<double>(b.x1 + rng.integer(1, 3)),
                 y1 = static_cast<double>(b.y1 + rng.integer(1, 3));
    const Points corners = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    const int cuts = static_cast<int>(rng.integer(0, 2));
    const long long first = rng.integer(0, 3), second = (first + rng.integer(1, 3)) % 4;
    Points p;
    for (long long i = 0; i < 4; ++i) {
        const dvec2 c = corners[i];
        if ((cuts >= 1 && i == first) || (cuts == 2 && i == second)) {
            const dvec2 in = c - corners[(i + 3) % 4], out = corners[(i + 1) % 4] - c;
            const auto unit = [](dvec2 d) { return d / std::max(std::fabs(d.x), std::fabs(d.y)); };
            p.push_back(c - unit(in) * static_cast<double>(rng.integer(1, 2)));
            p.push_back(c + unit(out) * static_cast<double>(rng.integer(1, 2)));
        } else {
            p.push_back(c);
        }
    }
    return p;
}

Points draw_polygon(Kind kind, const Points& w, Rng& rng, bool want_concave) {
    const Box b = bounds(w);
    switch (kind) {
        case Kind::Crossing:
            if (want_concave && rng.chance(0.5)) return crown(w, rng);
            {
                // One draw per statement: the order of a call's arguments is unspecified (gcc and
                // clang differ), and the same seed must give the same problem from either.
                const long long r = rng.integer(3, 5);
                const int n = static_cast<int>(rng.integer(3, 6));
                const dvec2 c = point(rng, b.x0, b.x1, b.y0, b.y1);
                return star(rng, c, n, r);
            }
        case Kind::Inside: {
            const int n = static_cast<int>(rng.integer(3, 5));
            return star(rng, point(rng, b.x0 + 1, b.x1 - 1, b.y0 + 1, b.y1 - 1), n, 2);
        }
        case Kind::Outside: {
            // A centre beyond one or two of the window's sides.
            const long long dx = rng.integer(-1, 1),
                            dy = dx == 0 ? 2 * rng.integer(0, 1) - 1 : rng.integer(-1, 1);
            const dvec2 c{dx < 0   ? b.x0 - rng.integer(2, 4)
                          : dx > 0 ? b.x1 + rng.integer(2, 4)
                                   : rng.integer(b.x0, b.x1),
                          dy < 0   ? b.y0 - rng.integer(2, 4)
                          : dy > 0 ? b.y1 + rng.integer(2, 4)
                                   : rng.integer(b.y0, b.y1)};
            const long long r = rng.integer(1, 3);
            const int n = static_cast<int>(rng.integer(3, 5));
            return star(rng, c, n, r);
        }
        case Kind::AroundWindow:
            return box_around(w, rng);
        case Kind::VertexOnEdge: {
            const long long r = rng.integer(2, 4);
            const int n = static_cast<int>(rng.integer(3, 6));
            const dvec2 c = point(rng, b.x0, b.x1, b.y0, b.y1);
            Points p = star(rng, c, n, r);
            if (p.empty()) return p;
            const std::size_t k =
                static_cast<std::size_t>(rng.integer(0, static_cast<long long>(w.size()) - 1));
            const Points on = lattice_on_edge(w, k);
            p[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(p.size()) - 1))] =
                on[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(on.size()) - 1))];
            return p;
        }
        case Kind::EdgeAlongEdge: {
            // Two lattice points on the line of window edge k (possibly a step past its
            // corners), the others strictly on its inner side, in a fan about their midpoint.
            const std::size_t k =
                static_cast<std::size_t>(rng.integer(0, static_cast<long long>(w.size()) - 1));
            const Points on = lattice_on_edge(w, k);
            const long long g = static_cast<long long>(on.size()) - 1;
            const dvec2 step = on[1] - on[0];
            const long long i = rng.integer(-1, g - 1),
                            j = rng.integer(std::max(i + 1, 1LL), g + 1);
            const dvec2 p1 = on[0] + step * static_cast<double>(i),
                        p2 = on[0] + step * static_cast<double>(j);
            Points p = {p1, p2};
            const int others = static_cast<int>(rng.integer(1, 4));
            for (int t = 0; t < others; ++t) {
                const dvec2 q = point(rng, b.x0 - 2, b.x1 + 2, b.y0 - 2, b.y1 + 2);
                if (side(w, k, q) <= 0) return {};
                p.push_back(q);
            }
            if (!sort_around(p, (p1 + p2) / 2.0)) return {};
            return p;
        }
    }
    return {};
}

// ---- [checks] --------------------------------------------------------------------------------

bool nice(double x) {
    return std::fabs(x * 20 - std::round(x * 20)) < 1e-6;
}

struct RunFacts {
    bool nice = true;  // every I and every needed t on the 1/20 grid, no side value a rounding
                       // accident
    bool every_t_nice = true;  // also the t that are not needed
    bool any_zero = false;     // some side value exactly 0 (a point on a window edge's line)
    int crossings = 0;
    std::size_t longest = 0;  // the longest list
    SutherlandHodgman::Result result;
};

// Whether the polygon edge S→P just tested meets an axis-parallel window edge at a right angle:
// then I is read off (x from the one, y from the other) and t is not needed by hand.
bool read_off(const SutherlandHodgman::State& s) {
    const dvec2 P = s.input[s.j - 1], S = s.input[s.j >= 2 ? s.j - 2 : s.input.size() - 1];
    return (s.A.x == s.B.x && S.y == P.y) || (s.A.y == s.B.y && S.x == P.x);
}

// Runs the algorithm itself (the expected answer is its result, so its own arithmetic is what
// must come out nice).
RunFacts run(const SutherlandHodgman::Input& in) {
    RunFacts f;
    auto s = SutherlandHodgman::start(in);
    f.longest = in.polygon.size();
    while (!SutherlandHodgman::done(s)) {
        SutherlandHodgman::step(s, nullptr);
        if (s.phase != SutherlandHodgman::Phase::Clip &&
            s.phase != SutherlandHodgman::Phase::EdgeDone)
            continue;
        // Exact side values are multiples of 1/20 here, so anything nearer 0 is rounding.
        if (s.side_P == 0)
            f.any_zero = true;
        else if (std::fabs(s.side_P) < 1e-6)
            f.nice = false;
        const SutherlandHodgman::Case which = SutherlandHodgman::which_case(s);
        if (which == SutherlandHodgman::Case::InOut || which == SutherlandHodgman::Case::OutIn) {
            ++f.crossings;
            const dvec2 I = SutherlandHodgman::intersection_I(s);
            const double t = SutherlandHodgman::crossing_t(s);
            f.nice = f.nice && nice(I.x) && nice(I.y) && (nice(t) || read_off(s));
            f.every_t_nice = f.every_t_nice && nice(t);
        }
        f.longest = std::max(f.longest, s.output.size());
    }
    f.result = SutherlandHodgman::result(s);
    return f;
}

bool on_boundary(const Points& w, dvec2 x) {
    for (std::size_t k = 0; k < w.size(); ++k) {
        const dvec2 a = w[k], b = w[(k + 1) % w.size()];
        if (cross(b - a, x - a) == 0 && segments_touch(a, b, x, x)) return true;
    }
    return false;
}

bool acceptable(Kind kind, const Points& w, const Points& p, bool want_concave, bool strict) {
    // No slivers: a polygon of area at least 3, and (below) a visible part of area at least 1.
    if (p.size() < 3 || p.size() > 6 || !simple(p) || std::fabs(twice_area(p)) < 6) return false;
    const RunFacts f = run({w, p});
    if (!f.nice || (strict && !f.every_t_nice) || f.crossings > kMaxCrossings ||
        f.longest > kMaxList)
        return false;
    const double area = std::fabs(twice_area(f.result.polygon)) / 2;
    const double window_area = std::fabs(twice_area(w)) / 2;
    const bool some_outside = std::any_of(
        p.begin(), p.end(), [&](dvec2 v) { return !strictly_inside(w, v) && !on_boundary(w, v); });
    switch (kind) {
        case Kind::Crossing:
            return !f.any_zero && some_outside && f.crossings >= 2 && area >= 1 &&
                   area < window_area && concave(p) == want_concave;
        case Kind::Inside:
            return std::all_of(p.begin(), p.end(), [&](dvec2 v) { return strictly_inside(w, v); });
        case Kind::Outside:
            return !f.any_zero && f.result.polygon.empty();
        case Kind::AroundWindow:
            return !f.any_zero && std::fabs(area - window_area) < 1e-9 &&
                   std::none_of(w.begin(), w.end(), [&](dvec2 v) { return on_boundary(p, v); });
        case Kind::VertexOnEdge:
            return std::any_of(p.begin(), p.end(), [&](dvec2 v) { return on_boundary(w, v); }) &&
                   some_outside && area >= 1;
        case Kind::EdgeAlongEdge:
            return area >= 1;
    }
    return false;
}

}  // namespace

// ---- [exam_input] ----------------------------------------------------------------------------

SutherlandHodgman::Input SutherlandHodgman::exam_input(Rng& rng) {
    static constexpr Kind kDegenerate[] = {Kind::Inside, Kind::Outside, Kind::AroundWindow,
                                           Kind::VertexOnEdge, Kind::EdgeAlongEdge};
    const Kind kind = rng.chance(0.25) ? kDegenerate[rng.integer(0, 4)] : Kind::Crossing;
    const bool want_concave = rng.chance(0.4);
    const bool rectangular = rng.chance(0.75);
    Points window;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        // A window on which nothing nice turns up is replaced now and then; slanted edges
        // make nice crossings rarer, so after half the attempts only rectangles are tried.
        if (attempt % 50 == 0)
            window = rectangular || 2 * attempt >= kAttempts ? rectangle(rng) : convex_window(rng);
        Points polygon = draw_polygon(kind, window, rng, want_concave);
        // Even the t that are not needed come out nice if that can be had in a quarter of the
        // attempts (it rarely can for a polygon round the window).
        const bool strict = 4 * attempt < kAttempts;
        if (!acceptable(kind, window, polygon, want_concave, strict)) continue;
        shuffle_start(polygon, rng);
        return {window, polygon};
    }
    // Never reached in the tests' 1,000 seeds; here so that the generator always ends. The
    // example: a triangle through the right and top edges of the square [0, 4]².
    return {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{2, 1}, {6, 3}, {2, 6}}};
}

// ---- [question] ------------------------------------------------------------------------------

namespace {

std::string vertex_list(const Points& p, const char* name) {
    std::string s;
    for (std::size_t i = 0; i < p.size(); ++i)
        s += (i ? ", " : "") + std::string(name) + std::to_string(i) + " = " + num(p[i]);
    return s;
}

// "W0→W1 (bottom, y = 1)" or "W1→W2, from (6, 1) to (3, 5)".
std::string window_edge(const Points& w, std::size_t k, bool rectangle) {
    const std::size_t next = (k + 1) % w.size();
    const dvec2 a = w[k], b = w[next];
    std::string s = "W" + std::to_string(k) + "→W" + std::to_string(next);
    const Box box = bounds(w);
    if (a.y == b.y) {
        const char* name = a.y == box.y0 ? "bottom" : "top";
        return s + " (" + (rectangle ? std::string(name) + ", " : "") + "y = " + num(a.y) + ")";
    }
    if (a.x == b.x) {
        const char* name = a.x == box.x0 ? "left" : "right";
        return s + " (" + (rectangle ? std::string(name) + ", " : "") + "x = " + num(a.x) + ")";
    }
    return s + " (from " + num(a) + " to " + num(b) + ")";
}

}  // namespace

std::string SutherlandHodgman::question(const Input& in) {
    const Points& w = in.window;
    bool rect = w.size() == 4;
    for (std::size_t k = 0; k < w.size() && rect; ++k) {
        const dvec2 a = w[k], b = w[(k + 1) % w.size()];
        rect = a.x == b.x || a.y == b.y;
    }
    const bool ccw = twice_area(w) > 0;
    std::string edges;
    for (std::size_t k = 0; k < w.size(); ++k) edges += (k ? ", " : "") + window_edge(w, k, rect);
    return "Clip the polygon " + vertex_list(in.polygon, "V") + " against the " +
           (rect ? "rectangular" : "convex") + " window " + vertex_list(w, "W") +
           " with the Sutherland-Hodgman algorithm. The window runs " +
           (ccw ? "counter-clockwise, so inside an edge means on its left"
                : "clockwise, so inside an edge means on its right") +
           "; a point on the edge counts as inside. Clip against the window edges in this order: " +
           edges +
           ". Against each window edge, walk the polygon edges S→P of the current list: S "
           "starts at the list's last vertex and P at its first, then S ← P. Output by the four "
           "cases: in → in: P; in → out: the intersection I; out → out: nothing; out → in: I, "
           "then P. Give the output list after each window edge (it is the input list for the "
           "next one; if a list comes out empty, stop there: nothing is visible), and the final "
           "clipped polygon.";
}

std::vector<std::string> SutherlandHodgman::answer_fields() {
    return {"after_edge", "polygon"};
}

}  // namespace cg
