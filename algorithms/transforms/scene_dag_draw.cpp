// Scene DAG, the picture (3D). The whole model stands from the start as a faint grey ghost (every
// box the traversal will draw, at its world matrix), so each step shows where it is going; the
// boxes drawn so far are green, the one just drawn orange and named. The path from the root is
// a chain of orange arrows from the world origin through each node's origin, each node named at
// its dot, the current one first. The current node's frame (the top matrix's columns) is three
// arrows in the axes' colours, marked x′, y′, z′, so they never read as the world's x, y, z
// (drawn once, by the world frame at the origin). The camera frames the whole model and the
// current frame.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "transforms/scene_dag.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec3;

constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                              {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
// The world axes' colours (as the viewer draws a frame), for the current node's own frame.
constexpr std::uint32_t kAxisColour[3] = {0xd62728ff, 0x2ca02cff, 0x1f77b4ff};

std::string leaf(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

void SceneDag::draw(const State& s, Scene& scene) {
    // The world frame at the origin (the viewer then leaves out its own axes).
    scene.frames3.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0, "", 0.5f});

    // The model: the boxes drawn so far, then the ghost of those still to come. Framed whole,
    // with the origin, so the camera stays put as the traversal runs (bounds by min/max, no
    // squared lengths: a part translated by 1e300 keeps them finite).
    const std::vector<Draw> all = expand(s.in, true);
    dvec3 lo(0.0), hi(0.0);
    for (const Draw& d : expand(s.in, false)) {
        const dvec3 o(d.matrix[3]);
        lo = glm::min(lo, o), hi = glm::max(hi, o);
    }
    for (std::size_t k = 0; k < all.size(); ++k) {
        const bool drawn = k < s.draws.size();
        const bool now = s.last == Event::Draw && k + 1 == s.draws.size();
        const std::vector<dvec3> c = corners(drawn ? s.draws[k].matrix : all[k].matrix);
        for (const dvec3& p : c) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const Role role = now ? Role::Active : drawn ? Role::Kept : Role::Construction;
        const float alpha = now ? 0.6f : drawn ? 0.35f : 0.06f;
        for (const auto& f : kFaces)
            scene.faces3.push_back({{c[f[0]], c[f[1]], c[f[2]], c[f[3]]}, {role, 1.0f}, alpha});
        // Named at its centre: the one just drawn first, the others if room — unless a node on
        // the path already names that spot.
        bool on_path = false;
        for (int d = 1; d <= depth(s) && drawn; ++d)
            on_path = on_path || (dvec3(s.stack[d][3]) == dvec3(s.draws[k].matrix[3]) &&
                                  s.in.nodes[s.path[d - 1].node].name == leaf(s.draws[k].path));
        if (drawn && !on_path)
            scene.labels3.push_back(
                {dvec3(s.draws[k].matrix[3]), leaf(s.draws[k].path), {role}, now ? 2 : -1});
    }

    // The path: stack level k (k ≥ 1) holds the world matrix of the k-th node on the path.
    dvec3 prev(0, 0, 0);
    for (int k = 1; k <= depth(s); ++k) {
        const dvec3 o(s.stack[k][3]);
        scene.segments3.push_back({prev, o, "", {Role::Active, 2.5f}, true});
        scene.points3.push_back(
            {o, s.in.nodes[s.path[k - 1].node].name, {Role::Active}, 5.0f, k == depth(s) ? 1 : 0});
        prev = o;
    }
    // The current node's frame: the top matrix's columns, unit length, at its origin.
    if (depth(s) >= 1) {
        const dmat4& m = s.stack.back();
        static const char* const kName[3] = {"x′", "y′", "z′"};
        for (int i = 0; i < 3; ++i) {
            dvec3 u(m[i]);
            const double l = std::hypot(u.x, u.y, u.z);
            if (l > 0) u /= l;
            Segment3 axis{
                dvec3(m[3]), dvec3(m[3]) + 0.8 * u, kName[i], {Role::Neutral, 2.5f}, true};
            axis.style.rgba = kAxisColour[i];
            axis.priority = -1;
            scene.segments3.push_back(axis);
            lo = glm::min(lo, axis.b), hi = glm::max(hi, axis.b);
        }
    }
    if (std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z)) add_focus(scene, lo, hi);
}

}  // namespace cg
