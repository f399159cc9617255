// Free-form deformation, the picture (2D). The box (blue) with the undeformed lattice's lines
// (light grey, dashed); the image of the box's space under the deformation, as the curves
// s = const and t = const at every eighth (teal, thin): how space is bent; the control polygon
// of the moved lattice (magenta lines between neighbouring P_ij, the points as dots, a moved
// one joined to its rest place by a thin arrow). The shape before (grey) and, for the points
// deformed so far, after (green): an edge between two deformed points is drawn through the
// deformation, sampled, so that a straight edge shows the curve it becomes. The point of the
// last step is orange with an arrow from X to X'; a point left outside the box is red.
#include <algorithm>
#include <cmath>

#include "animation/morph_ffd.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

constexpr int kIsoLines = 8;        // curves s = const and t = const: every 1/8
constexpr int kIsoSamples = 32;     // samples along each
constexpr int kEdgeSamples = 12;    // samples along each edge of the deformed shape

}  // namespace

void MorphFfd::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    if (in.spatial()) return draw3(s, scene);  // morph_ffd_draw3.cpp
    const glm::dvec2 lo = in.box_min, hi = in.box_max;
    scene.polygons.push_back(
        {{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, {Role::Window, 1.5f}, true, false});
    // The undeformed lattice lines.
    for (int i = 1; i < in.l; ++i)
        scene.segments.push_back({rest(in, i, 0), rest(in, i, in.m), "", {Role::Construction, 1.0f, true}});
    for (int j = 1; j < in.m; ++j)
        scene.segments.push_back({rest(in, 0, j), rest(in, in.l, j), "", {Role::Construction, 1.0f, true}});

    // Before the first step the lattice is drawn undeformed.
    const bool started = s.phase != Phase::Lattice;
    Input undeformed = in;
    undeformed.moves.clear();
    const std::vector<glm::dvec2> p = started ? *s.lattice : lattice(undeformed);

    // The bent space: X(s, t) along s = c and t = c.
    const glm::dvec2 size = hi - lo;
    if (started) {
        for (int c = 0; c <= kIsoLines; ++c) {
            const double u = double(c) / kIsoLines;
            Polygon2 a{{}, {Role::Entering, 1.0f}, false, false}, b = a;
            for (int q = 0; q <= kIsoSamples; ++q) {
                const double v = double(q) / kIsoSamples;
                a.points.push_back(blend(in, p, {u, v}));
                b.points.push_back(blend(in, p, {v, u}));
            }
            scene.polygons.push_back(std::move(a));
            scene.polygons.push_back(std::move(b));
        }
    }

    // The control polygon and the control points.
    auto P = [&](int i, int j) { return p[std::size_t(i) * std::size_t(in.m + 1) + std::size_t(j)]; };
    for (int i = 0; i <= in.l; ++i)
        for (int j = 0; j <= in.m; ++j) {
            if (i < in.l) scene.segments.push_back({P(i, j), P(i + 1, j), "", {Role::Leaving, 1.5f}});
            if (j < in.m) scene.segments.push_back({P(i, j), P(i, j + 1), "", {Role::Leaving, 1.5f}});
            const glm::dvec2 r = rest(in, i, j);
            if (P(i, j) != r)
                scene.segments.push_back({r, P(i, j), "", {Role::Construction, 1.0f}, true});
            scene.points.push_back({P(i, j), "", {Role::Leaving}, 4.0f});
        }
    // Labels on the control points when there are few enough to read.
    if ((in.l + 1) * (in.m + 1) <= 16) {
        const double off = 0.025 * std::max(size.x, size.y);
        for (int i = 0; i <= in.l; ++i)
            for (int j = 0; j <= in.m; ++j)
                scene.labels.push_back({P(i, j) + glm::dvec2(off, -off),
                                        "P" + std::to_string(i) + std::to_string(j), {Role::Leaving}});
    }

    // The shape before.
    scene.polygons.push_back({in.shape, {Role::Subject, 1.5f}, in.closed && in.shape.size() > 2, false});
    // After, for the points done: each edge between two done points sampled through the map.
    const std::size_t done = s.deformed.size(), n = in.shape.size();
    if (done > 0) {
        Polygon2 after{{}, {Role::Kept, 2.5f}, false, false};
        after.points.push_back(s.deformed[0]);
        const std::size_t edges = done == n && in.closed && n > 2 ? n : done - 1;
        for (std::size_t e = 0; e < edges; ++e) {
            const glm::dvec2 a = in.shape[e], b = in.shape[(e + 1) % n];
            for (int q = 1; q < kEdgeSamples; ++q)
                after.points.push_back(deform(in, p, a + (b - a) * (double(q) / kEdgeSamples)));
            after.points.push_back(s.deformed[(e + 1) % n]);
        }
        if (after.points.size() == 1) after.points.push_back(after.points[0]);
        scene.polygons.push_back(std::move(after));
        for (std::size_t q = 0; q < done; ++q)
            if (!s.inside[q]) scene.points.push_back({s.deformed[q], "", {Role::Discarded}, 3.5f});
    }
    if (s.last == Phase::Point && done > 0) {
        const std::size_t q = done - 1;
        const glm::dvec2 x = in.shape[q], X = s.deformed[q];
        scene.points.push_back({x, "X", {Role::Active}, 4.0f});
        if (X != x) scene.segments.push_back({x, X, "", {Role::Active, 2.0f}, true});
        scene.points.push_back({X, "X'", {Role::Active}, 6.0f});
    }

    // Dragging: the control points moved "to" a position (a "by" move is a displacement, edited
    // as numbers).
    for (std::size_t q = 0; q < in.moves.size(); ++q)
        if (in.moves[q].absolute) {
            const std::string base = "/moves/" + std::to_string(q) + "/to/";
            scene.handles.push_back({in.moves[q].value,
                                     "P" + std::to_string(in.moves[q].i) + std::to_string(in.moves[q].j),
                                     base + "0", base + "1"});
        }
}

}  // namespace cg
