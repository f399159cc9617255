// Sutherland-Hodgman's exam generator: over 1,000 seeds every problem is of the promised shape
// (integer window and polygon, small), its expected answer has Clipper's area, every number a
// student computes is a multiple of 1/20, and each degenerate kind exams like turns up.
// (tests/lessons checks for every algorithm that the expected answers are the run's result,
// that wrong answers are graded wrong and that the CLI agrees.)
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "clipping/sutherland_hodgman.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "polygon_reference.hpp"

using cg::SutherlandHodgman;
using glm::dvec2;
using polygon_reference::cross;
using polygon_reference::shoelace;
using Points = std::vector<dvec2>;

namespace {

bool integral(const Points& p) {
    return std::all_of(p.begin(), p.end(), [](dvec2 v) {
        return v.x == std::round(v.x) && v.y == std::round(v.y) && std::fabs(v.x) <= 20 &&
               std::fabs(v.y) <= 20;
    });
}

// A multiple of 1/20: at most two decimals, as the generator promises.
bool nice(double x) {
    return std::fabs(x * 20 - std::round(x * 20)) < 1e-9;
}

bool convex_window_ok(const Points& w) {
    const double orient = shoelace(w) > 0 ? 1 : -1;
    for (std::size_t i = 0; i < w.size(); ++i) {
        const dvec2 a = w[i], b = w[(i + 1) % w.size()], c = w[(i + 2) % w.size()];
        if (orient * cross(b - a, c - b) <= 0) return false;
    }
    return true;
}

bool rectangle(const Points& w) {
    if (w.size() != 4) return false;
    for (std::size_t i = 0; i < 4; ++i)
        if (w[i].x != w[(i + 1) % 4].x && w[i].y != w[(i + 1) % 4].y) return false;
    return true;
}

// Exact on integer points.
double side(const Points& w, std::size_t k, dvec2 x) {
    const dvec2 a = w[k], b = w[(k + 1) % w.size()];
    return (shoelace(w) > 0 ? 1 : -1) * cross(b - a, x - a);
}

bool strictly_inside(const Points& w, dvec2 x) {
    for (std::size_t k = 0; k < w.size(); ++k)
        if (side(w, k, x) <= 0) return false;
    return true;
}

bool on_edge(dvec2 a, dvec2 b, dvec2 x) {
    return cross(b - a, x - a) == 0 && std::min(a.x, b.x) <= x.x && x.x <= std::max(a.x, b.x) &&
           std::min(a.y, b.y) <= x.y && x.y <= std::max(a.y, b.y);
}

bool vertex_on_window_edge(const Points& w, const Points& p) {
    for (dvec2 v : p)
        for (std::size_t k = 0; k < w.size(); ++k)
            if (on_edge(w[k], w[(k + 1) % w.size()], v)) return true;
    return false;
}

// A polygon edge on the line of a window edge, sharing a piece of positive length with it.
bool edge_along_window_edge(const Points& w, const Points& p) {
    for (std::size_t i = 0; i < p.size(); ++i) {
        const dvec2 c = p[i], d = p[(i + 1) % p.size()];
        for (std::size_t k = 0; k < w.size(); ++k) {
            const dvec2 a = w[k], b = w[(k + 1) % w.size()];
            if (cross(b - a, c - a) != 0 || cross(b - a, d - a) != 0) continue;
            // Overlap of the two intervals along the edge's direction.
            const dvec2 u = b - a;
            auto along = [&](dvec2 x) { return (x - a).x * u.x + (x - a).y * u.y; };
            const double lo = std::max(0.0, std::min(along(c), along(d)));
            const double hi = std::min(along(b), std::max(along(c), along(d)));
            if (hi > lo) return true;
        }
    }
    return false;
}

std::vector<Points> lists(const cg::json& j) {
    std::vector<Points> out;
    for (const auto& list : j) {
        Points pts;
        for (const auto& p : list) pts.push_back({p[0].get<double>(), p[1].get<double>()});
        out.push_back(pts);
    }
    return out;
}

}  // namespace

TEST_CASE(
    "sutherland-hodgman exam: 1,000 seeds give problems workable by hand, agreeing with Clipper",
    "[clipping][sutherland-hodgman][exam]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* sh = registry.find("sutherland-hodgman");
    REQUIRE(sh);
    REQUIRE(cg::has_exam(*sh));
    CHECK(sh->answer_fields(sh->example()) == std::vector<std::string>{"after_edge", "polygon"});

    int inside = 0, outside = 0, around = 0, vertex_on = 0, edge_along = 0, degenerate = 0;
    int concave = 0, bridged = 0, rectangles = 0, clockwise = 0, fifths = 0, fallback = 0;
    int crossings = 0, not_needed = 0;
    double worst_area = 0;
    const SutherlandHodgman::Input kFallback{{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                                             {{2, 1}, {6, 3}, {2, 6}}};
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const SutherlandHodgman::Input in = SutherlandHodgman::exam_input(rng);
        const Points &w = in.window, &p = in.polygon;
        CAPTURE(cg::exam_to_json(cg::make_exam(*sh, seed)).dump());
        fallback += in == kFallback;

        // The promised shape: a convex integer window of 3 to 5 vertices, a simple integer
        // polygon of 3 to 6.
        REQUIRE_NOTHROW(SutherlandHodgman::validate(in));
        CHECK(w.size() >= 3);
        CHECK(w.size() <= 5);
        CHECK(p.size() >= 3);
        CHECK(p.size() <= 6);
        CHECK(integral(w));
        CHECK(integral(p));
        CHECK(convex_window_ok(w));
        CHECK(polygon_reference::simple(p));
        rectangles += rectangle(w);
        clockwise += shoelace(w) < 0;

        // The expected answer, as the exam gives it (through JSON).
        const cg::ExamProblem problem = cg::make_exam(*sh, seed);
        CHECK(problem.question.find("S starts at the list's last vertex") != std::string::npos);
        CHECK(problem.question.find("W" + std::to_string(w.size() - 1) + "→W0") !=
              std::string::npos);
        const std::vector<Points> after_edge = lists(problem.expected.at("after_edge"));
        const Points polygon = lists(cg::json::array({problem.expected.at("polygon")}))[0];
        REQUIRE_FALSE(after_edge.empty());
        CHECK(after_edge.size() <= w.size());
        CHECK(after_edge.back() == polygon);
        CHECK((after_edge.size() == w.size() || polygon.empty()));

        // Its area is the true intersection's (bridges are walked there and back: no area).
        const double area = std::fabs(shoelace(polygon));
        const double ref = polygon_reference::intersection_area(w, p);
        CAPTURE(area, ref);
        CHECK(std::fabs(area - ref) <= 1e-9 * std::max(1.0, ref));
        worst_area = std::max(worst_area, std::fabs(area - ref));

        // Every number a student writes is a multiple of 1/20: the coordinates of every list,
        // and every crossing parameter t that is needed (t is not when S→P meets an
        // axis-parallel window edge at a right angle: I is then read off, x from one and y from
        // the other).
        for (const Points& list : after_edge)
            for (dvec2 v : list) {
                CAPTURE(v.x, v.y);
                CHECK(nice(v.x));
                CHECK(nice(v.y));
                // Off the quarter grid: a fifth or a twentieth.
                fifths += std::fabs(v.x * 4 - std::round(v.x * 4)) > 1e-9 ||
                          std::fabs(v.y * 4 - std::round(v.y * 4)) > 1e-9;
            }
        auto s = SutherlandHodgman::start(in);
        while (!SutherlandHodgman::done(s)) {
            SutherlandHodgman::step(s, nullptr);
            const SutherlandHodgman::Case which = SutherlandHodgman::which_case(s);
            const bool crossing =
                which == SutherlandHodgman::Case::InOut || which == SutherlandHodgman::Case::OutIn;
            if (!crossing) continue;
            ++crossings;
            const dvec2 P = s.input[s.j - 1], S = s.input[s.j >= 2 ? s.j - 2 : s.input.size() - 1];
            const bool read_off = (s.A.x == s.B.x && S.y == P.y) || (s.A.y == s.B.y && S.x == P.x);
            const double t = SutherlandHodgman::crossing_t(s);
            not_needed += !nice(t);
            CAPTURE(t, read_off);
            CHECK((nice(t) || read_off));
        }

        // The kinds of problem, told from the geometry alone.
        const bool is_inside =
            std::all_of(p.begin(), p.end(), [&](dvec2 v) { return strictly_inside(w, v); });
        const bool is_outside = polygon.empty() && ref == 0;
        const bool is_around = !is_inside && std::fabs(ref - std::fabs(shoelace(w))) < 1e-9;
        const bool is_vertex_on = vertex_on_window_edge(w, p);
        const bool is_edge_along = edge_along_window_edge(w, p);
        inside += is_inside;
        outside += is_outside;
        around += is_around;
        vertex_on += is_vertex_on && !is_edge_along;
        edge_along += is_edge_along;
        degenerate += is_inside || is_outside || is_around || is_vertex_on || is_edge_along;
        if (!is_inside && !is_outside && !is_around && !is_vertex_on && !is_edge_along) {
            // An ordinary problem really clips: something is cut off and something is left.
            CHECK(ref > 0);
            CHECK(ref < std::fabs(shoelace(p)));
        }
        concave += !convex_window_ok(p);
        bridged += polygon_reference::intersection(w, p).size() > 1;
    }
    // Shown when a check below fails. (Seen: inside 54, outside 58, window inside the polygon
    // 42, vertex on an edge 31, edge along an edge 67, degenerate in all 251; concave 322, cut
    // in pieces 174, rectangles 808, clockwise windows 230, points with fifths 1811, crossings
    // 2744 of which 250 read off with t off the grid, fallbacks 0, worst area error 1.3e-12.)
    INFO("inside " << inside << ", outside " << outside << ", window inside the polygon " << around
                   << ", vertex on an edge " << vertex_on << ", edge along an edge " << edge_along
                   << ", degenerate " << degenerate << "; concave " << concave << ", cut in pieces "
                   << bridged << ", rectangles " << rectangles << ", clockwise " << clockwise
                   << ", points with fifths " << fifths << ", crossings " << crossings << " ("
                   << not_needed << " read off, t off the grid), fallbacks " << fallback
                   << ", worst area error " << worst_area);
    // About one problem in four is degenerate, and every kind occurs.
    CHECK(degenerate >= 150);
    CHECK(degenerate <= 350);
    CHECK(inside >= 20);
    CHECK(outside >= 20);
    CHECK(around >= 20);
    CHECK(vertex_on >= 20);
    CHECK(edge_along >= 20);
    // The mix: mostly rectangles, some other windows either way round; concave polygons,
    // some cut in pieces; fifths as well as halves and quarters.
    CHECK(rectangles >= 650);
    CHECK(rectangles <= 900);
    CHECK(clockwise >= 50);
    CHECK(concave >= 200);
    CHECK(bridged >= 10);
    CHECK(fifths >= 20);
    CHECK(fallback == 0);
}
