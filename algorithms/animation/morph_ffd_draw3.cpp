// Free-form deformation in space, the picture (on the 3D canvas). The box (blue, its 12 edges);
// the bent space: the box's edges carried through the deformation, sampled (teal, thin), which
// shows how the lattice bends the whole block; the moved lattice (magenta lines between
// neighbouring P_ijk, the points as dots, a moved one joined to its rest place by a thin grey
// arrow and named). The shape before (grey, its polyline or its wireframe edges) and, for the
// points deformed so far, after (green): an edge between two deformed points is sampled through
// the deformation, so a straight edge shows the curve it becomes. The point of the last step is
// orange with an arrow from X to X'; a point left outside the box is red.
#include <algorithm>
#include <cmath>

#include "animation/morph_ffd.hpp"

namespace cg {

namespace {

constexpr int kBoxSamples = 24;   // samples along each edge of the bent box
constexpr int kEdgeSamples = 8;   // samples along each edge of the deformed shape
constexpr int kMaxLabels = 12;    // moved control points named, at most

using V3 = std::vector<glm::dvec3>;

// The shape's edges: the wireframe's pairs when given, else the polyline (closed: a polygon).
std::vector<std::array<int, 2>> shape_edges(const MorphFfd::Input& in) {
    if (!in.edges.empty()) return in.edges;
    std::vector<std::array<int, 2>> e;
    const int n = int(in.shape3.size());
    for (int q = 0; q + 1 < n; ++q) e.push_back({q, q + 1});
    if (in.closed && n > 2) e.push_back({n - 1, 0});
    return e;
}

}  // namespace

void MorphFfd::draw3(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const glm::dvec3 lo = in.box3_min, hi = in.box3_max;
    auto corner = [&](int c) {
        return glm::dvec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
    };
    // The 12 edges of the box: corners differing in one bit.
    for (int c = 0; c < 8; ++c)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(c & bit)) scene.segments3.push_back({corner(c), corner(c | bit), "", {Role::Window, 1.5f}});

    // Before the first step the lattice is drawn undeformed.
    const bool started = s.phase != Phase::Lattice;
    Input undeformed = in;
    undeformed.moves3.clear();
    const V3 p = started ? *s.lattice3 : lattice3(undeformed);

    // The bent space: each box edge (in local coordinates) sampled through X(s, t, u).
    if (started)
        for (int c = 0; c < 8; ++c)
            for (int bit = 1; bit < 8; bit <<= 1) {
                if (c & bit) continue;
                const glm::dvec3 a = local3(in, corner(c)), b = local3(in, corner(c | bit));
                glm::dvec3 prev = blend3(in, p, a);
                for (int q = 1; q <= kBoxSamples; ++q) {
                    const glm::dvec3 next = blend3(in, p, a + (b - a) * (double(q) / kBoxSamples));
                    scene.segments3.push_back({prev, next, "", {Role::Entering, 1.5f}});
                    prev = next;
                }
            }

    // The lattice: lines between neighbours along i, j and k, and the control points.
    auto at = [&](int i, int j, int k) {
        return (std::size_t(i) * std::size_t(in.m + 1) + std::size_t(j)) * std::size_t(in.n + 1) +
               std::size_t(k);
    };
    const int count = (in.l + 1) * (in.m + 1) * (in.n + 1);
    const float dot = count > 64 ? 2.5f : 3.5f;
    int named = 0;
    for (int i = 0; i <= in.l; ++i)
        for (int j = 0; j <= in.m; ++j)
            for (int k = 0; k <= in.n; ++k) {
                const glm::dvec3 P = p[at(i, j, k)];
                if (i < in.l) scene.segments3.push_back({P, p[at(i + 1, j, k)], "", {Role::Leaving, 1.0f}});
                if (j < in.m) scene.segments3.push_back({P, p[at(i, j + 1, k)], "", {Role::Leaving, 1.0f}});
                if (k < in.n) scene.segments3.push_back({P, p[at(i, j, k + 1)], "", {Role::Leaving, 1.0f}});
                const glm::dvec3 r = rest3(in, i, j, k);
                const bool moved = P != r;
                if (moved) scene.segments3.push_back({r, P, "", {Role::Construction, 1.0f}, true});
                std::string name;
                if (moved && named < kMaxLabels) {
                    ++named;
                    name = "P" + std::to_string(i) + std::to_string(j) + std::to_string(k);
                }
                scene.points3.push_back({P, name, {Role::Leaving}, moved ? dot + 1 : dot});
            }

    // The shape before, and after for the points done.
    const std::vector<std::array<int, 2>> edges = shape_edges(in);
    for (const auto& e : edges)
        scene.segments3.push_back({in.shape3[std::size_t(e[0])], in.shape3[std::size_t(e[1])], "",
                                   {Role::Subject, 1.5f}});
    const std::size_t done = s.deformed3.size();
    for (const auto& e : edges) {
        const std::size_t a = std::size_t(e[0]), b = std::size_t(e[1]);
        if (a >= done || b >= done) continue;
        const glm::dvec3 xa = in.shape3[a], xb = in.shape3[b];
        glm::dvec3 prev = s.deformed3[a];
        for (int q = 1; q <= kEdgeSamples; ++q) {
            const glm::dvec3 next = q == kEdgeSamples
                                        ? s.deformed3[b]
                                        : deform3(in, p, xa + (xb - xa) * (double(q) / kEdgeSamples));
            scene.segments3.push_back({prev, next, "", {Role::Kept, 2.5f}});
            prev = next;
        }
    }
    for (std::size_t q = 0; q < done; ++q)
        scene.points3.push_back({s.deformed3[q], "", {s.inside[q] ? Role::Kept : Role::Discarded},
                                 s.inside[q] ? 2.5f : 3.5f});
    if (s.last == Phase::Point && done > 0) {
        const std::size_t q = done - 1;
        const glm::dvec3 x = in.shape3[q], X = s.deformed3[q];
        scene.points3.push_back({x, "X", {Role::Active}, 4.0f});
        if (X != x) scene.segments3.push_back({x, X, "", {Role::Active, 2.0f}, true});
        scene.points3.push_back({X, "X'", {Role::Active}, 6.0f});
    }
}

}  // namespace cg
