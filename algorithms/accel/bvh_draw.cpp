// Bounding volume hierarchies, the picture. The 3D view: every node box made so far as a
// wireframe coloured by depth (the node in hand orange and shaded, red when the ray misses it or
// it is pruned), the primitives (the node's or the leaf's under test orange, those tested
// before teal, the closest hit so far green) with their indices, the ray from E with the box's
// [t_enter, t_exit] and the hit point; a scene that lies in a plane with the ray is seen
// face-on, and the camera frames the whole scene with E. Beside
// it, a diagram panel: the tree as built so far — each node at the middle of its range of
// primitives, one row per depth, the leaves' primitives under them — with the nodes popped so
// far coloured by what the traversal found there, the stack ringed magenta, and a key.
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "accel/bvh.hpp"
#include "accel/ray_aabb.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Node = Bvh::Node;
using NodeKind = Bvh::NodeKind;
using Phase = Bvh::Phase;
using Visit = Bvh::Visit;

std::string list(const int* items, int n) {
    std::string out = "[";
    for (int i = 0; i < n; ++i) out += (i ? ", " : "") + std::to_string(items[i]);
    return out + "]";
}

// Depth colours for the node boxes (0xRRGGBBAA): blue, purple, olive, brown, steel, plum —
// none of them a role's colour (teal, magenta, orange, green and red mean something).
constexpr std::uint32_t kDepthColour[] = {0x2f6fd0ff, 0x8a4fc4ff, 0x8c8c1fff,
                                          0xb0603aff, 0x3a8fb0ff, 0x9a4a7aff};

std::uint32_t depth_colour(int depth) {
    return kDepthColour[depth % 6];
}

void box_edges(const Bounds& b, Style style, Scene& scene) {
    auto c = [&](int k) {
        return dvec3(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y,
                     k & 4 ? b.max.z : b.min.z);
    };
    static const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                     {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& e : edges) scene.segments3.push_back({c(e[0]), c(e[1]), "", style, false});
}

void box_faces(const Bounds& b, Style style, float alpha, Scene& scene) {
    auto c = [&](int k) {
        return dvec3(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y,
                     k & 4 ? b.max.z : b.min.z);
    };
    static const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                    {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (const auto& q : quads)
        scene.faces3.push_back({{c(q[0]), c(q[1]), c(q[2]), c(q[3])}, style, alpha, true, true});
}

void draw_primitive(const Primitive& p, Style style, float alpha, bool coarse, Scene& scene) {
    switch (p.kind) {
        case PrimitiveKind::Triangle:
            scene.faces3.push_back({{p.a, p.b, p.c}, style, alpha, true, true});
            break;
        case PrimitiveKind::Box:
            box_faces({p.a, p.b}, style, alpha, scene);
            break;
        case PrimitiveKind::Sphere: {  // a UV sphere, without outlines: 10 × 5 faces, or
                                       // 6 × 3 in a scene of many
            struct Unit {
                int around, rings;
                std::vector<dvec3> dirs;  // (rings + 1) × (around + 1) unit directions
            };
            static const std::array<Unit, 2> units = [] {
                std::array<Unit, 2> out{Unit{10, 5, {}}, Unit{6, 3, {}}};
                constexpr double kPi = 3.14159265358979323846;
                for (Unit& u : out)
                    for (int j = 0; j <= u.rings; ++j)
                        for (int i = 0; i <= u.around; ++i) {
                            const double th = kPi * j / u.rings, ph = 2 * kPi * i / u.around;
                            u.dirs.push_back({std::sin(th) * std::cos(ph), std::cos(th),
                                              std::sin(th) * std::sin(ph)});
                        }
                return out;
            }();
            const Unit& u = units[coarse ? 1 : 0];
            auto at = [&](int i, int j) { return p.a + p.radius * u.dirs[j * (u.around + 1) + i]; };
            for (int j = 0; j < u.rings; ++j)
                for (int i = 0; i < u.around; ++i)
                    scene.faces3.push_back(
                        {{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)},
                         style,
                         alpha,
                         false,
                         true});
            break;
        }
    }
}

// The t range that covers the scene from E (for the ray's drawn length).
double ray_reach(const Bvh::Input& in, const Bounds& scene) {
    const RayAabb::Result r = RayAabb::intersect({scene.min, scene.max, in.origin, in.direction});
    double t = r.hit ? r.t_max : 0;
    const double size = glm::length(scene.extent()) / glm::length(in.direction);
    if (!std::isfinite(t) || t < 0) t = 0;
    if (std::isfinite(size)) t = std::max(t, 0.0) + 0.25 * size;
    return t > 0 ? t : 1;
}

}  // namespace

void Bvh::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Result& r = s.r;
    const bool tracing = s.last != Phase::Build && s.r.box_tests > 0;
    const int focus = s.node;

    // Room for everything at once (the lists would otherwise grow a dozen times per picture).
    std::size_t faces = 16;
    for (const Primitive& p : in.primitives)
        faces += p.kind == PrimitiveKind::Sphere ? 50 : p.kind == PrimitiveKind::Box ? 6 : 1;
    scene.faces3.reserve(scene.faces3.size() + faces);
    scene.segments3.reserve(scene.segments3.size() + 12 * r.nodes.size() + 16);

    // What each primitive is in this picture: in the node in hand (made, or the leaf under
    // test), or tested in an earlier step.
    const int n = static_cast<int>(in.primitives.size());
    std::vector<std::uint8_t> mark(n, 0);  // 0 plain, 1 in the node in hand, 2 tested before
    const std::size_t popped = r.visited.size();
    const std::size_t before = tracing && s.last == Phase::Trace ? popped - 1 : popped;
    if (tracing)
        for (std::size_t v = 0; v < before; ++v)
            if (s.visits[v] == Visit::Leaf) {
                const Node& nd = r.nodes[r.visited[v]];
                for (int k = 0; k < nd.count; ++k) mark[r.order[nd.first + k]] = 2;
            }
    if (focus >= 0 && focus < static_cast<int>(r.nodes.size())) {
        const Node& nd = r.nodes[focus];
        const bool active = s.last == Phase::Build || s.visit == Visit::Leaf;
        if (active)
            for (int k = 0; k < nd.count; ++k) mark[r.order[nd.first + k]] = 1;
    }

    for (int i = 0; i < n; ++i) {
        const Primitive& p = in.primitives[i];
        Role role = Role::Subject;
        float alpha = 0.25f;
        if (mark[i] == 1) role = Role::Active, alpha = 0.45f;
        if (mark[i] == 2) role = Role::Entering, alpha = 0.3f;
        if (tracing && i == r.hit.primitive) role = Role::Kept, alpha = 0.5f;
        if (p.kind == PrimitiveKind::Box)
            alpha *= 0.4f;  // six faces: lighter, not to hide the rest
        draw_primitive(p, {role, 1.0f}, alpha, n > 16, scene);
        scene.labels3.push_back({centroid(p), std::to_string(i), {role}});
    }

    // The node boxes, by depth; the one in hand shaded orange.
    for (std::size_t id = 0; id < r.nodes.size(); ++id) {
        const Node& nd = r.nodes[id];
        const bool now = static_cast<int>(id) == focus;
        if (now) continue;
        box_edges(nd.bounds, {Role::Neutral, 1.2f, false, depth_colour(nd.depth)}, scene);
    }
    if (focus >= 0 && focus < static_cast<int>(r.nodes.size())) {
        const Node& nd = r.nodes[focus];
        const bool missed = tracing && (s.visit == Visit::Missed || s.visit == Visit::Pruned);
        const Role role = missed ? Role::Discarded : Role::Active;
        box_edges(nd.bounds, {role, 3.0f}, scene);
        box_faces(nd.bounds, {role, 1.0f}, 0.08f, scene);
        scene.labels3.push_back({nd.bounds.max, "node " + std::to_string(focus), {role}});
        // The split plane of a node just split.
        if (s.last == Phase::Build && nd.kind == NodeKind::Inner) {
            const int a = nd.axis;
            const int* items = r.order.data() + nd.first;
            const double c0 = centroid(in.primitives[items[nd.cut - 1]])[a];
            const double c1 = centroid(in.primitives[items[nd.cut]])[a];
            const double c = 0.5 * (c0 + c1);
            const int j = (a + 1) % 3, k = (a + 2) % 3;
            dvec3 q[4];
            for (int m = 0; m < 4; ++m) {
                q[m][a] = c;
                q[m][j] = (m == 1 || m == 2) ? nd.bounds.max[j] : nd.bounds.min[j];
                q[m][k] = m >= 2 ? nd.bounds.max[k] : nd.bounds.min[k];
            }
            scene.faces3.push_back(
                {{q[0], q[1], q[2], q[3]}, {Role::Leaving, 1.5f}, 0.18f, true, true});
        }
    }

    // The ray.
    if (in.has_ray) {
        Bounds all;
        for (const Node& nd : r.nodes) all.grow(nd.bounds);
        if (r.nodes.empty())
            for (const Primitive& p : in.primitives) all.grow(bounds(p));
        const dvec3 E = in.origin, d = in.direction;
        const double reach = ray_reach(in, all);
        scene.segments3.push_back({E, E + reach * d, "E + t d", {Role::Subject, 1.5f}, true});
        scene.points3.push_back({E, "E", {Role::Subject}, 5.0f});
        if (tracing && s.last == Phase::Trace && s.visit != Visit::Missed &&
            std::isfinite(s.t_exit)) {
            scene.segments3.push_back(
                {E + s.t_enter * d, E + s.t_exit * d, "", {Role::Active, 5.0f}, false});
            scene.points3.push_back({E + s.t_enter * d, "t_enter", {Role::Entering}, 5.0f});
        }
        if (tracing && r.hit.primitive >= 0)
            scene.points3.push_back(
                {E + r.hit.t * d, "hit t = " + num(r.hit.t, 4), {Role::Kept}, 7.0f});
    }
    scene.extent3 = 0;

    // A scene whose primitives are centred in one plane with the ray (spheres in a row) is seen
    // face-on, along that plane's normal, orthographic: the boxes nest as rectangles.
    for (int a = 2; a >= 0 && n > 0; --a) {
        const double c = centroid(in.primitives[0])[a];
        bool flat = !in.has_ray || (in.direction[a] == 0 && in.origin[a] == c);
        for (const Primitive& p : in.primitives) flat = flat && centroid(p)[a] == c;
        if (!flat) continue;
        dvec3 look(0.0), up(0, 1, 0);
        look[a] = -1;
        if (a == 1) up = dvec3(0, 0, -1);
        scene.view3 = {look, up, true};
        break;
    }
    // The camera frames the whole scene and where the ray comes into it (E, or its entry into
    // the scene's box when E is far): the node in hand is seen among the others.
    Bounds framed;
    for (const Primitive& p : in.primitives) framed.grow(bounds(p));
    if (in.has_ray && !framed.empty()) {
        const RayAabb::Result box =
            RayAabb::intersect({framed.min, framed.max, in.origin, in.direction});
        const double t = box.hit && std::isfinite(box.t_min) ? std::max(box.t_min, 0.0) : 0.0;
        framed.grow(in.origin + t * in.direction);
    }
    if (!framed.empty()) add_focus(scene, framed.min, framed.max);

    // ---- the tree: a diagram panel, in units of its own ----
    // W × H units, about the panel's shape beside a 3D view. Node x = the middle of its range of
    // primitives, one row per depth from the top; past 31 nodes only the node in hand and those
    // on the stack are labelled, and the leaves' lists are left to the narration.
    std::vector<std::uint8_t> seen(r.nodes.size(), 0);  // 1 missed/pruned, 2 entered
    if (tracing)
        for (std::size_t v = 0; v < popped; ++v)
            seen[r.visited[v]] =
                s.visits[v] == Visit::Missed || s.visits[v] == Visit::Pruned ? 1 : 2;
    const bool crowded = r.nodes.size() > 31;
    std::vector<std::uint8_t> stacked(r.nodes.size(), 0);
    if (tracing)
        for (int id : s.stack) stacked[id] = 1;
    int depth = 1;
    for (const Node& nd : r.nodes) depth = std::max(depth, nd.depth);
    const int W = std::max(14, n + 2), H = static_cast<int>(std::lround(W / 0.7));
    Panel& tree = add_diagram(scene, "the tree, one row per depth");
    tree.weight = 1.1;
    // The tree's room, framed: the diagram keeps one scale while the tree grows into it.
    tree.polygons.push_back({{{0, 0}, {double(W), 0}, {double(W), double(H)}, {0, double(H)}},
                             {Role::Construction, 1.0f},
                             true,
                             false});
    // Room above the root for its number, and below the deepest row for two rows of lists.
    const double top = H - 1.8, below = 3.4;
    const double dy = (top - below) / depth, sx = (W - 2.0) / std::max(n, 1);
    auto pos = [&](const Node& nd) {
        return dvec2(1.0 + sx * (nd.first + 0.5 * nd.count), top - dy * nd.depth);
    };
    for (std::size_t id = 0; id < r.nodes.size(); ++id) {
        const Node& nd = r.nodes[id];
        if (nd.parent >= 0)
            tree.segments.push_back(
                {pos(r.nodes[nd.parent]), pos(nd), "", {Role::Construction, 1.0f}, false});
    }
    if (tracing)  // the stack, waiting: a ring under the node
        for (int id : s.stack)
            tree.points.push_back({pos(r.nodes[id]), "", {Role::Leaving, 1.0f}, 10.0f});
    int leaves = 0, leaf_count = 0;
    for (const Node& nd : r.nodes) leaf_count += nd.leaf();
    for (std::size_t id = 0; id < r.nodes.size(); ++id) {
        const Node& nd = r.nodes[id];
        const bool now = static_cast<int>(id) == focus;
        Role role = Role::Neutral;
        if (seen[id]) role = seen[id] == 1 ? Role::Discarded : Role::Entering;
        if (now)
            role = s.last == Phase::Trace && (s.visit == Visit::Missed || s.visit == Visit::Pruned)
                       ? Role::Discarded
                       : Role::Active;
        const std::uint32_t rgba = now || seen[id] || tracing ? 0u : depth_colour(nd.depth);
        tree.points.push_back({pos(nd), "", {role, 1.0f, false, rgba}, now ? 8.0f : 6.0f});
        if (crowded && !now && !stacked[id]) continue;
        tree.labels.push_back({pos(nd) + dvec2(0, 0.9), std::to_string(id), {role}, now ? 20 : 0});
        // A leaf's primitives below it, every other leaf a row lower; past six leaves only the
        // one in hand's (the rest are in the 3D view's numbers and the narration).
        if (nd.leaf() && !crowded && (leaf_count <= 6 || now)) {
            std::vector<int> ids(r.order.begin() + nd.first, r.order.begin() + nd.first + nd.count);
            std::sort(ids.begin(), ids.end());
            tree.labels.push_back(
                {pos(nd) + dvec2(0, leaves % 2 ? -2.3 : -1.1), list(ids.data(), nd.count), {role}});
            ++leaves;
        }
    }
    if (tracing) {
        tree.legend.push_back({"popped now", {Role::Active}, true});
        tree.legend.push_back({"entered", {Role::Entering}, true});
        tree.legend.push_back({"missed or pruned", {Role::Discarded}, true});
        tree.legend.push_back({"on the stack", {Role::Leaving}, true});
    } else if (focus >= 0) {
        tree.legend.push_back({"made now", {Role::Active}, true});
    }
}

}  // namespace cg
