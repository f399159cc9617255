// The bounding volume hierarchy: the lesson's cases worked by hand (exact trees, costs, nodes
// popped); 10,000 random rays per random scene (spheres, boxes, triangles; nested and
// overlapping; rays from inside, along faces, through corners and edges; both splits, max_leaf
// 1 to 4) against brute force; the tree's invariants; every SAH choice against an independent
// long-double recomputation; run-to-end equals the plain function; errors naming the field;
// replay; the picture; the exam.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>

#include "accel/bvh.hpp"
#include "accel/primitive.hpp"
#include "core/format.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Bvh;
using cg::Primitive;
using cg::PrimitiveKind;
using glm::dvec3;

namespace {

using cg::prim::box;
using cg::prim::sphere;
using cg::prim::triangle;

Bvh::Input scene(std::vector<Primitive> ps, Bvh::Split split, int max_leaf, dvec3 E, dvec3 d) {
    Bvh::Input in;
    in.primitives = std::move(ps);
    in.split = split, in.max_leaf = max_leaf;
    in.origin = E, in.direction = d;
    return in;
}

// Four unit spheres on the x axis at 0, 3, 6, 9.
std::vector<Primitive> four_on_a_line() {
    return {sphere({0, 0, 0}, 1), sphere({3, 0, 0}, 1), sphere({6, 0, 0}, 1), sphere({9, 0, 0}, 1)};
}
// The example: two rows of three unit spheres, y = 0 and y = 4, x = 0, 3, 6.
std::vector<Primitive> six_in_two_rows() {
    return {sphere({0, 0, 0}, 1), sphere({3, 0, 0}, 1), sphere({6, 0, 0}, 1),
            sphere({0, 4, 0}, 1), sphere({3, 4, 0}, 1), sphere({6, 4, 0}, 1)};
}

std::vector<std::vector<int>> leaves(const Bvh::Result& r) {
    std::vector<std::vector<int>> out;
    for (const auto& nd : r.nodes)
        if (nd.leaf()) {
            std::vector<int> ids(r.order.begin() + nd.first, r.order.begin() + nd.first + nd.count);
            std::sort(ids.begin(), ids.end());
            out.push_back(ids);
        }
    return out;
}

// ---- The reference: every primitive, the nearest t ≥ 0, the first index on a tie -------------

struct BruteHit {
    int primitive = -1;
    double t = Bvh::kInf;
};

BruteHit brute_force(const Bvh::Input& in) {
    BruteHit best;
    for (std::size_t i = 0; i < in.primitives.size(); ++i) {
        const cg::PrimitiveHit h = cg::intersect(in.primitives[i], in.origin, in.direction);
        if (h.hit() && h.t < best.t) best.primitive = static_cast<int>(i), best.t = h.t;
    }
    return best;
}

// ---- The tree's invariants ----------------------------------------------------------------

bool inside(const cg::Bounds& inner, const cg::Bounds& outer) {
    for (int k = 0; k < 3; ++k)
        if (inner.min[k] < outer.min[k] || inner.max[k] > outer.max[k]) return false;
    return true;
}

void check_tree(const Bvh::Input& in, const Bvh::Result& r) {
    const int n = static_cast<int>(in.primitives.size());
    REQUIRE(!r.nodes.empty());
    REQUIRE(r.nodes[0].first == 0);
    REQUIRE(r.nodes[0].count == n);
    std::vector<int> in_leaf(n, 0);
    std::vector<int> sorted = r.order;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < n; ++i) REQUIRE(sorted[i] == i);  // order is a permutation
    for (std::size_t id = 0; id < r.nodes.size(); ++id) {
        const Bvh::Node& nd = r.nodes[id];
        CAPTURE(id);
        REQUIRE(nd.count >= 1);
        cg::Bounds u;
        for (int k = 0; k < nd.count; ++k) u.grow(cg::bounds(in.primitives[r.order[nd.first + k]]));
        REQUIRE(u == nd.bounds);  // the union of its primitives' bounds
        if (nd.parent >= 0) {
            const Bvh::Node& p = r.nodes[nd.parent];
            REQUIRE(inside(nd.bounds, p.bounds));
            REQUIRE(nd.depth == p.depth + 1);
            REQUIRE((p.left == static_cast<int>(id) || p.right == static_cast<int>(id)));
        } else {
            REQUIRE(id == 0);
        }
        if (nd.leaf()) {
            REQUIRE((nd.count <= in.max_leaf || nd.kind == Bvh::NodeKind::NoGain));
            if (in.split == Bvh::Split::Median) REQUIRE(nd.kind == Bvh::NodeKind::Leaf);
            for (int k = 0; k < nd.count; ++k) ++in_leaf[r.order[nd.first + k]];
        } else {
            REQUIRE(nd.count > in.max_leaf);
            const Bvh::Node& L = r.nodes[nd.left];
            const Bvh::Node& R = r.nodes[nd.right];
            REQUIRE(L.first == nd.first);
            REQUIRE(L.count == nd.cut);
            REQUIRE(R.first == nd.first + nd.cut);
            REQUIRE(L.count + R.count == nd.count);
            REQUIRE(nd.left == static_cast<int>(id) + 1);  // depth first, left first
            if (in.split == Bvh::Split::Median) REQUIRE(nd.cut == nd.count / 2);
        }
    }
    for (int i = 0; i < n; ++i) REQUIRE(in_leaf[i] == 1);  // in exactly one leaf
}

// ---- The SAH, recomputed in long double ---------------------------------------------------

using LD = long double;

LD area_ld(const cg::Bounds& b) {
    const LD x = LD(b.max.x) - LD(b.min.x), y = LD(b.max.y) - LD(b.min.y),
             z = LD(b.max.z) - LD(b.min.z);
    return 2 * (x * y + y * z + z * x);
}

// For every node that was split or refused a split by the SAH: its items sorted independently
// along the longest centroid axis, each cut's cost in long double, and the choice checked.
int check_sah(const Bvh::Input& in, const Bvh::Result& r) {
    int checked = 0;
    for (const Bvh::Node& nd : r.nodes) {
        if (nd.kind == Bvh::NodeKind::Leaf) continue;
        std::vector<int> items(r.order.begin() + nd.first, r.order.begin() + nd.first + nd.count);
        std::sort(items.begin(), items.end());
        // The longest axis of the centroids' box (centroid = the middle of the bounds).
        LD lo[3], hi[3];
        for (int k = 0; k < 3; ++k) lo[k] = 1e4000L, hi[k] = -1e4000L;
        auto centre = [&](int i, int k) {
            const cg::Bounds b = cg::bounds(in.primitives[i]);
            return (LD(b.min[k]) + LD(b.max[k])) / 2;
        };
        for (int i : items)
            for (int k = 0; k < 3; ++k)
                lo[k] = std::min(lo[k], centre(i, k)), hi[k] = std::max(hi[k], centre(i, k));
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
        REQUIRE(nd.axis == axis);
        std::stable_sort(items.begin(), items.end(),
                         [&](int a, int b) { return centre(a, axis) < centre(b, axis); });
        // The two sides as sets (the children re-sort their own ranges afterwards; a leaf
        // keeps the order).
        if (nd.kind == Bvh::NodeKind::Inner) {
            const auto at = r.order.begin() + nd.first;
            REQUIRE(std::is_permutation(items.begin(), items.begin() + nd.cut, at));
        } else {
            for (int k = 0; k < nd.count; ++k) REQUIRE(items[k] == r.order[nd.first + k]);
        }
        const LD S = area_ld(nd.bounds);
        if (S == 0) {
            REQUIRE(nd.kind == Bvh::NodeKind::NoGain);
            continue;
        }
        std::vector<LD> cost(nd.count, 0);
        LD best = 1e4000L;
        for (int k = 1; k < nd.count; ++k) {
            cg::Bounds L, R;
            for (int m = 0; m < k; ++m) L.grow(cg::bounds(in.primitives[items[m]]));
            for (int m = k; m < nd.count; ++m) R.grow(cg::bounds(in.primitives[items[m]]));
            cost[k] = 1 + area_ld(L) / S * k + area_ld(R) / S * (nd.count - k);
            best = std::min(best, cost[k]);
        }
        const LD tol = 1e-12L * best;
        if (nd.kind == Bvh::NodeKind::Inner) {
            REQUIRE(std::fabs(LD(nd.cost) - cost[nd.cut]) <= tol);            // the cost it states
            REQUIRE(cost[nd.cut] <= best + tol);                              // the cheapest
            for (int k = 1; k < nd.cut; ++k) REQUIRE(cost[k] >= best - tol);  // smallest k
            REQUIRE(cost[nd.cut] < LD(nd.count) * (1 + 1e-12L));
        } else {
            REQUIRE(best >= LD(nd.count) * (1 - 1e-12L));  // no split helps
            REQUIRE(std::fabs(LD(nd.cost) - best) <= tol);
        }
        ++checked;
    }
    return checked;
}

// ---- Random scenes --------------------------------------------------------------------------

// n primitives: spheres, boxes and triangles; integer coordinates (exact ties, shared faces and
// corners) in a third of the scenes; some big boxes that nest others; overlaps everywhere.
std::vector<Primitive> random_scene(cg::Rng& rng, int n) {
    const bool integers = rng.chance(0.35);
    auto coord = [&](double lo, double hi) {
        return integers ? static_cast<double>(
                              rng.integer(static_cast<long long>(lo), static_cast<long long>(hi)))
                        : rng.uniform(lo, hi);
    };
    auto point = [&](double s) { return dvec3(coord(-s, s), coord(-s, s), coord(-s, s)); };
    std::vector<Primitive> ps;
    while (static_cast<int>(ps.size()) < n) {
        const double what = rng.uniform(0, 1);
        if (what < 0.35) {
            ps.push_back(sphere(
                point(8), integers ? static_cast<double>(rng.integer(1, 3)) : rng.uniform(0.2, 3)));
        } else if (what < 0.65) {
            const dvec3 a = point(8), b = point(8);
            dvec3 mn = glm::min(a, b), mx = glm::max(a, b);
            if (rng.chance(0.15)) mx.z = mn.z;                          // flat
            if (rng.chance(0.08)) mn = point(9) - 1.0, mx = mn + 14.0;  // big: nests others
            ps.push_back(box(mn, mx));
        } else {
            const dvec3 a = point(8);
            const dvec3 b = a + point(3), c = a + point(3);
            const dvec3 nrm = glm::cross(b - a, c - a);
            if (glm::dot(nrm, nrm) == 0) continue;
            ps.push_back(triangle(a, b, c));
        }
    }
    return ps;
}

// A ray for the scene: from anywhere, from inside a primitive, along a face, through a corner
// or a vertex, or grazing an edge; a third of the directions with components 0.
void random_ray(cg::Rng& rng, const std::vector<Primitive>& ps, dvec3& E, dvec3& d) {
    const Primitive& p = ps[rng.integer(0, static_cast<long long>(ps.size()) - 1)];
    const bool integers = rng.chance(0.4);
    auto comp = [&]() {
        if (rng.chance(0.12)) return 0.0;
        return integers ? static_cast<double>(rng.integer(-3, 3)) : rng.uniform(-1, 1);
    };
    d = dvec3(comp(), comp(), comp());
    if (d == dvec3(0.0)) d.x = 1;
    const cg::Bounds b = cg::bounds(p);
    const double what = rng.uniform(0, 1);
    auto corner = [&]() {
        return dvec3(rng.chance(0.5) ? b.min.x : b.max.x, rng.chance(0.5) ? b.min.y : b.max.y,
                     rng.chance(0.5) ? b.min.z : b.max.z);
    };
    if (what < 0.3) {  // anywhere
        E = dvec3(rng.uniform(-14, 14), rng.uniform(-14, 14), rng.uniform(-14, 14));
    } else if (what < 0.45) {  // from inside (the bounds' centre: in a sphere or a box)
        E = b.centre();
    } else if (what < 0.6) {  // at a corner of a box / bounds, or a triangle's vertex
        const dvec3 target = p.kind == PrimitiveKind::Triangle
                                 ? (rng.chance(0.5) ? p.a : (rng.chance(0.5) ? p.b : p.c))
                                 : corner();
        E = target - static_cast<double>(rng.integer(1, 4)) * d;
    } else if (what < 0.75) {  // along an edge: two components 0, E on two faces
        const int k = static_cast<int>(rng.integer(0, 2));
        d = dvec3(0.0);
        d[k] = rng.chance(0.5) ? 1 : -1;
        E = corner();
        E[k] = d[k] > 0 ? b.min[k] - 3 : b.max[k] + 3;
    } else if (what < 0.85) {  // a triangle's edge midpoint, or a sphere's tangent plane
        const dvec3 target = p.kind == PrimitiveKind::Triangle
                                 ? 0.5 * (p.a + p.b)
                                 : b.centre() + dvec3(0, b.extent().y / 2, 0);
        E = target - 5.0 * d;
    } else {  // aimed at the centre from far away
        E = b.centre() - 20.0 * d;
    }
}

std::string text(const Bvh::Input& in) {
    return "E " + cg::num(in.origin, 17) + " d " + cg::num(in.direction, 17);
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("bvh");
    if (!l) throw std::runtime_error("no lesson for bvh");
    return *l;
}

Bvh::Input input_of(const cg::json& j) {
    return cg::test::input_of<Bvh>("bvh", j);
}

}  // namespace

TEST_CASE("bvh: four spheres on a line, median split, max_leaf 1 — by hand", "[accel][bvh]") {
    const auto t = cg::test::run_traced<Bvh>(
        scene(four_on_a_line(), Bvh::Split::Median, 1, {-3, 0, 0}, {1, 0, 0}));
    const Bvh::Result& r = t.result;
    // Root [0 1 2 3] → node 1 [0 1] (→ 2 [0], 3 [1]), node 4 [2 3] (→ 5 [2], 6 [3]).
    REQUIRE(r.nodes.size() == 7);
    CHECK(leaves(r) == std::vector<std::vector<int>>{{0}, {1}, {2}, {3}});
    CHECK((r.nodes[0].left == 1 && r.nodes[0].right == 4));
    CHECK((r.nodes[1].left == 2 && r.nodes[1].right == 3));
    CHECK((r.nodes[4].left == 5 && r.nodes[4].right == 6));
    CHECK(r.nodes[0].bounds == cg::Bounds{{-1, -1, -1}, {10, 1, 1}});
    CHECK(r.nodes[1].bounds == cg::Bounds{{-1, -1, -1}, {4, 1, 1}});
    CHECK(r.nodes[4].bounds == cg::Bounds{{5, -1, -1}, {10, 1, 1}});
    CHECK(r.nodes[0].axis == 0);
    // Root hit on [2, 13]: push 4, then 1; node 1 on [2, 7]: push 3, then 2; leaf 2: sphere 0
    // at t = 2; node 3 (x ∈ [2, 4], t ≥ 5) and node 4 (t ≥ 8) pruned.
    CHECK(r.visited == std::vector<int>{0, 1, 2, 3, 4});
    CHECK(r.hit.primitive == 0);
    CHECK(r.hit.t == 2);
    CHECK(r.hit.point == dvec3(-1, 0, 0));
    CHECK(r.box_tests == 5);
    CHECK(r.primitive_tests == 1);
    CHECK(r.brute_force_tests == 4);
    CHECK(cg::test::events(t) ==
          std::vector<std::string>{"split-median", "split-median", "leaf", "leaf", "split-median",
                                   "leaf", "leaf", "push-children", "push-children", "leaf-hit",
                                   "box-pruned", "box-pruned", "result"});
    CHECK_THAT(t.steps[0].narration, Catch::Contains("first ⌊4/2⌋ = 2 go left [0, 1]") &&
                                         Catch::Contains("right [2, 3]"));
    CHECK_THAT(t.steps[10].narration,
               Catch::Contains("t_enter = 5 > t_best = 2") && Catch::Contains("Pruned"));
    CHECK_THAT(t.steps[12].narration,
               Catch::Contains("5 box tests and 1 primitive tests, against 4"));

    SECTION("from the other end: the right child is near") {
        const auto b = Bvh::build_and_trace(
            scene(four_on_a_line(), Bvh::Split::Median, 1, {12, 0, 0}, {-1, 0, 0}));
        CHECK(b.visited == std::vector<int>{0, 4, 6, 5, 1});
        CHECK((b.hit.primitive == 3 && b.hit.t == 2));
        CHECK(b.primitive_tests == 1);
    }
    SECTION("a ray that misses the root: one box test, no primitive test") {
        const auto b = Bvh::build_and_trace(
            scene(four_on_a_line(), Bvh::Split::Median, 1, {-3, 5, 0}, {1, 0, 0}));
        CHECK(b.visited == std::vector<int>{0});
        CHECK(b.hit.primitive == -1);
        CHECK((b.box_tests == 1 && b.primitive_tests == 0));
    }
    SECTION("max_leaf 2: two leaves of two") {
        const auto b = Bvh::build_and_trace(
            scene(four_on_a_line(), Bvh::Split::Median, 2, {-3, 0, 0}, {1, 0, 0}));
        CHECK(leaves(b) == std::vector<std::vector<int>>{{0, 1}, {2, 3}});
        CHECK(b.visited == std::vector<int>{0, 1, 2});
        CHECK(b.primitive_tests == 2);
    }
    SECTION("between the spheres, along y: only node 1's right half") {
        const auto b = Bvh::build_and_trace(
            scene(four_on_a_line(), Bvh::Split::Median, 1, {3, -5, 0}, {0, 1, 0}));
        CHECK(b.visited == std::vector<int>{0, 1, 2, 3, 4});  // node 2, 4 missed
        CHECK((b.hit.primitive == 1 && b.hit.t == 4));
        CHECK(b.primitive_tests == 1);
    }
}

TEST_CASE("bvh: the example, SAH with max_leaf 1 — every cost by hand", "[accel][bvh]") {
    const auto t = cg::test::run_traced<Bvh>(
        scene(six_in_two_rows(), Bvh::Split::Sah, 1, {-3, 0.5, 0}, {1, 0, 0}));
    const Bvh::Result& r = t.result;
    // Root: S = 2(8·6 + 6·2 + 2·8) = 152, sorted by x: 0 3 1 4 2 5. k = 2 and k = 4 both cost
    // 1 + (56·2 + 104·4)/152 = 4.4737 (mirror images): the smaller k wins.
    REQUIRE(r.nodes.size() == 7);
    CHECK(std::vector<int>(r.order.begin(), r.order.begin() + 2) == std::vector<int>{0, 3});
    CHECK(r.nodes[0].cut == 2);
    CHECK(r.nodes[0].cost == Approx(1 + 528.0 / 152).epsilon(1e-14));
    // Node 1 [0 3]: along y, k = 1: 1 + (24 + 24)/56 = 1.857 < 2: split.
    CHECK(r.nodes[1].axis == 1);
    CHECK(r.nodes[1].cost == Approx(1 + 48.0 / 56).epsilon(1e-14));
    // Node 4 [1 4 2 5]: S = 104, along y (4 > 3): 1 2 | 4 5 at 1 + (48·2 + 48·2)/104.
    CHECK(r.nodes[4].axis == 1);
    CHECK(r.nodes[4].cut == 2);
    CHECK(r.nodes[4].cost == Approx(1 + 192.0 / 104).epsilon(1e-14));
    // Nodes 5 [1 2] and 6 [4 5]: k = 1 costs 1 + (24 + 24)/48 = 2, not below the leaf's 2.
    CHECK(r.nodes[5].kind == Bvh::NodeKind::NoGain);
    CHECK(r.nodes[5].cost == 2);
    CHECK(r.nodes[6].kind == Bvh::NodeKind::NoGain);
    CHECK(leaves(r) == std::vector<std::vector<int>>{{0}, {3}, {1, 2}, {4, 5}});
    // The ray y = 0.5: root [2, 10], node 1 [2, 4], leaf 2: sphere 0 at t = 3 − √0.75; node 3
    // missed (y ∈ [3, 5]); node 4 entered at 5 > t_best: pruned.
    CHECK(r.visited == std::vector<int>{0, 1, 2, 3, 4});
    CHECK(r.hit.primitive == 0);
    CHECK(r.hit.t == Approx(3 - std::sqrt(0.75)).epsilon(1e-15));
    CHECK((r.box_tests == 5 && r.primitive_tests == 1));
    CHECK(cg::test::events(t) ==
          std::vector<std::string>{"split-sah", "split-sah", "leaf", "leaf", "split-sah",
                                   "leaf-no-gain", "leaf-no-gain", "push-children", "push-children",
                                   "leaf-hit", "box-miss", "box-pruned", "result"});
    CHECK_THAT(t.steps[0].narration, Catch::Contains("k = 2: 1 + 56/152·2 + 104/152·4 = 4.474") &&
                                         Catch::Contains("The cheapest is k = 2"));
    CHECK_THAT(t.steps[5].narration, Catch::Contains("no split helps"));
    CHECK(cg::test::result_of("bvh", cg::test::algorithm("bvh").example())["leaves"] ==
          cg::json::parse("[[0], [3], [1, 2], [4, 5]]"));
}

TEST_CASE("bvh: degenerate builds", "[accel][bvh]") {
    SECTION("one primitive: the root is a leaf") {
        const auto r = Bvh::build_and_trace(
            scene({sphere({0, 0, 0}, 1)}, Bvh::Split::Sah, 1, {-3, 0, 0}, {1, 0, 0}));
        CHECK(r.nodes.size() == 1);
        CHECK((r.hit.primitive == 0 && r.hit.t == 2 && r.box_tests == 1));
    }
    SECTION("equal centroids: median still cuts by index; SAH keeps a leaf") {
        std::vector<Primitive> ps{sphere({0, 0, 0}, 2), sphere({0, 0, 0}, 2.5),
                                  sphere({0, 0, 0}, 3)};
        const auto m =
            Bvh::build_and_trace(scene(ps, Bvh::Split::Median, 1, {-5, 0, 0}, {1, 0, 0}));
        CHECK(leaves(m) == std::vector<std::vector<int>>{{0}, {1}, {2}});
        CHECK((m.hit.primitive == 2 && m.hit.t == 2));
        const auto s = Bvh::build_and_trace(scene(ps, Bvh::Split::Sah, 1, {-5, 0, 0}, {1, 0, 0}));
        CHECK(s.nodes.size() == 1);
        CHECK(s.nodes[0].kind == Bvh::NodeKind::NoGain);
    }
    SECTION("point boxes at one point: S = 0, a leaf") {
        std::vector<Primitive> ps{box({1, 1, 1}, {1, 1, 1}), box({1, 1, 1}, {1, 1, 1})};
        const auto s = Bvh::build_and_trace(scene(ps, Bvh::Split::Sah, 1, {0, 0, 0}, {1, 1, 1}));
        CHECK(s.nodes.size() == 1);
        CHECK((s.hit.primitive == 0 && s.hit.t == 1));
    }
    SECTION("a ray from inside a box that holds the others") {
        std::vector<Primitive> ps{box({-10, -10, -10}, {10, 10, 10}), sphere({3, 0, 0}, 1),
                                  sphere({-3, 0, 0}, 1)};
        const auto s = Bvh::build_and_trace(scene(ps, Bvh::Split::Sah, 1, {0, 0, 0}, {1, 0, 0}));
        CHECK((s.hit.primitive == 1 && s.hit.t == 2));
    }
    SECTION("huge and tiny scenes") {
        for (double scale : {0x1p-460, 0x1p460}) {  // about 1e-139 and 3e138
            std::vector<Primitive> ps = six_in_two_rows();
            for (auto& p : ps) p.a *= scale, p.radius *= scale;
            const auto r = Bvh::build_and_trace(
                scene(ps, Bvh::Split::Sah, 1, scale * dvec3(-3, 0.5, 0), {1, 0, 0}));
            CHECK(leaves(r) == std::vector<std::vector<int>>{{0}, {3}, {1, 2}, {4, 5}});
            CHECK(r.hit.t == Approx(scale * (3 - std::sqrt(0.75))).epsilon(1e-14));
        }
    }
}

TEST_CASE("bvh: 10,000 random rays per random scene against brute force", "[accel][bvh]") {
    long long rays = 0, hits = 0, ties = 0, fewer = 0, tests = 0, brute = 0, sah_nodes = 0;
    int scenes = 0;
    for (int trial = 0; trial < 16; ++trial) {
        cg::Rng rng(7000 + trial);
        const int n =
            trial < 2 ? static_cast<int>(rng.integer(1, 6)) : static_cast<int>(rng.integer(8, 64));
        const std::vector<Primitive> ps = random_scene(rng, n);
        for (Bvh::Split split : {Bvh::Split::Median, Bvh::Split::Sah}) {
            const int max_leaf = 1 + (trial + (split == Bvh::Split::Sah)) % 4;
            CAPTURE(trial, n, max_leaf, static_cast<int>(split));
            Bvh::Input in = scene(ps, split, max_leaf, {0, 0, 0}, {1, 0, 0});
            // The tree and its SAH choices once per scene (the ray does not change it).
            const Bvh::Result tree = Bvh::build_and_trace(in);
            check_tree(in, tree);
            if (split == Bvh::Split::Sah) sah_nodes += check_sah(in, tree);
            ++scenes;
            for (int k = 0; k < 10'000; ++k) {
                random_ray(rng, ps, in.origin, in.direction);
                CAPTURE(k, text(in));
                const Bvh::Result r = Bvh::build_and_trace(in);
                const BruteHit b = brute_force(in);
                ++rays;
                if (r.hit.primitive != b.primitive) {
                    for (int i = 0; i < n; ++i)
                        UNSCOPED_INFO(i << ": " << cg::describe(ps[i]) << " t "
                                        << cg::intersect(ps[i], in.origin, in.direction).t);
                    for (const auto& nd : r.nodes)
                        UNSCOPED_INFO("node " << cg::num(nd.bounds.min, 17) << " "
                                              << cg::num(nd.bounds.max, 17) << " leaf "
                                              << nd.leaf());
                }
                REQUIRE(r.hit.primitive == b.primitive);  // the tie rule is brute force's
                if (b.primitive >= 0) {
                    ++hits;
                    REQUIRE(r.hit.t == b.t);  // the same intersect on the same primitive
                    REQUIRE(r.hit.point == in.origin + b.t * in.direction);
                    // An exact tie: another primitive hit at the same t.
                    for (int i = 0; i < n; ++i)
                        if (i != b.primitive &&
                            cg::intersect(ps[i], in.origin, in.direction).t == b.t) {
                            ++ties;
                            break;
                        }
                }
                REQUIRE(r.primitive_tests <= n);
                REQUIRE(r.box_tests <= static_cast<int>(r.nodes.size()));
                REQUIRE(r.box_tests == static_cast<int>(r.visited.size()));
                REQUIRE(r.brute_force_tests == n);
                fewer += r.primitive_tests < n;
                tests += r.primitive_tests, brute += n;
            }
        }
    }
    CHECK(rays == 320'000);
    CHECK(hits > rays / 3);
    CHECK(ties > 100);  // exact ties occur (shared faces, nested boxes) and agree
    CHECK(fewer > rays / 2);
    CHECK(sah_nodes > 100);
    WARN("bvh random: " << scenes << " scenes, " << rays << " rays, " << hits << " hits, " << ties
                        << " exact ties, primitive tests " << tests << " against brute "
                        << "force's " << brute << "; " << sah_nodes << " SAH nodes recomputed");
}

TEST_CASE("bvh: the state machine run to the end is the plain function", "[accel][bvh]") {
    for (int trial = 0; trial < 300; ++trial) {
        cg::Rng rng(9000 + trial);
        const std::vector<Primitive> ps = random_scene(rng, static_cast<int>(rng.integer(1, 64)));
        Bvh::Input in = scene(ps, rng.chance(0.5) ? Bvh::Split::Sah : Bvh::Split::Median,
                              static_cast<int>(rng.integer(1, 4)), {}, {});
        random_ray(rng, ps, in.origin, in.direction);
        in.has_ray = rng.chance(0.9);
        CAPTURE(trial);
        const Bvh::Result plain = Bvh::build_and_trace(in);
        CHECK(cg::run_to_end<Bvh>(Bvh::start(in)) == plain);
        // Narrated or not, the same states.
        auto a = Bvh::start(in), b = a;
        while (!Bvh::done(a)) {
            cg::StepInfo info;
            Bvh::step(a, &info);
            Bvh::step(b, nullptr);
            REQUIRE(a == b);
            REQUIRE(info.narration.find("nan") == std::string::npos);
            REQUIRE(info.narration.find("inf") == std::string::npos);
        }
    }
}

TEST_CASE("bvh: bad input is refused, naming the field", "[accel][bvh]") {
    auto error = [](const std::string& text) { return cg::test::error_of("bvh", text); };
    const std::string sp = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";
    auto with = [&](const std::string& rest) {
        return "{\"primitives\": [" + sp + "], " + rest + "}";
    };
    CHECK(error(with(R"("split": "sah", "max_leaf": 2)")) == "(accepted)");
    CHECK(
        error(with(
            R"("split": "sah", "max_leaf": 2, "ray": {"origin": [-3, 0, 0], "direction": [1, 0, 0]})")) ==
        "(accepted)");
    CHECK(error(with(R"("split": "middle", "max_leaf": 2)")) ==
          "split: must be \"median\" or \"sah\", got a string (\"middle\")");
    CHECK(error(with(R"("split": "sah", "max_leaf": 0)")) ==
          "max_leaf: must be a whole number from 1 to 16, got 0");
    CHECK_THAT(error(with(R"("split": "sah", "max_leaf": 1.5)")),
               Catch::StartsWith("max_leaf: must be an integer"));
    CHECK_THAT(error(with(R"("split": "sah")")), Catch::StartsWith("max_leaf: is missing"));
    CHECK_THAT(
        error(with(
            R"("split": "sah", "max_leaf": 2, "ray": {"origin": [0, 0, 0], "direction": [0, 0, 0]})")),
        Catch::StartsWith("ray.direction: must not be the zero vector"));
    CHECK_THAT(error(with(R"("split": "sah", "max_leaf": 2, "ray": {"origin": [0, 0, 0]})")),
               Catch::StartsWith("ray.direction: is missing"));
    CHECK_THAT(
        error(with(
            R"("split": "sah", "max_leaf": 2, "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0], "t": 1})")),
        Catch::StartsWith("ray.t: is not a known field"));
    CHECK_THAT(
        error(with(
            R"("split": "sah", "max_leaf": 2, "ray": {"origin": [2e150, 0, 0], "direction": [1, 0, 0]})")),
        Catch::StartsWith("ray.origin[0]: must be a number within ±1e150"));
    CHECK_THAT(
        error(with(
            R"("split": "sah", "max_leaf": 2, "ray": {"origin": [-1e150, 0, 0], "direction": [1e-200, 1, 0]})")),
        Catch::StartsWith("ray.direction[0]: is too small against the distance"));
    CHECK_THAT(error(R"({"primitives": [], "split": "sah", "max_leaf": 2})"),
               Catch::StartsWith("primitives: must list at least one primitive"));
    CHECK_THAT(
        error(
            R"({"primitives": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}], "split": "sah", "max_leaf": 2})"),
        Catch::StartsWith("primitives[0].radius: must be > 0"));
    CHECK_THAT(
        error(
            R"({"primitives": [{"type": "sphere", "center": [3e150, 0, 0], "radius": 1}], "split": "sah", "max_leaf": 2})"),
        Catch::StartsWith("primitives[0]: must be a number within ±1e150"));
    CHECK_THAT(error(with(R"("split": "sah", "max_leaf": 2, "extra": 1)")),
               Catch::StartsWith("extra: is not a known field"));
    std::string many = "{\"primitives\": [";
    for (int i = 0; i < 65; ++i) many += (i ? ", " : "") + sp;
    many += R"(], "split": "sah", "max_leaf": 2})";
    CHECK(error(many) == "primitives: lists 65 primitives; at most 64");
}

TEST_CASE("bvh: the result's JSON", "[accel][bvh]") {
    const cg::json r = cg::test::result_of("bvh", cg::test::algorithm("bvh").example());
    CHECK(r["split"] == "sah");
    CHECK(r["nodes"].size() == 7);
    CHECK(r["nodes"][0]["children"] == cg::json::parse("[1, 4]"));
    CHECK(r["nodes"][0]["primitives"] == cg::json::parse("[0, 1, 2, 3, 4, 5]"));
    CHECK(r["nodes"][0]["axis"] == "x");
    CHECK(r["nodes"][5]["kind"] == "leaf-no-gain");
    CHECK(r["nodes"][2]["children"].is_null());
    CHECK(r["hit"]["primitive"] == 0);
    CHECK(r["counts"] == cg::json::parse(R"({"box_tests": 5, "primitive_tests": 1})"));
    CHECK(r["brute_force"] == cg::json::parse(R"({"primitive_tests": 6})"));
    CHECK(r["visited"] == cg::json::parse("[0, 1, 2, 3, 4]"));
    cg::json no_ray = cg::test::algorithm("bvh").example();
    no_ray.erase("ray");
    const cg::json b = cg::test::result_of("bvh", no_ray);
    CHECK(b["hit"].is_null());
    CHECK(b["counts"].is_null());
    CHECK(b["nodes"].size() == 7);
    cg::json miss = cg::test::algorithm("bvh").example();
    miss["ray"]["origin"] = {-3, 0.5, 5};
    const cg::json m = cg::test::result_of("bvh", miss);
    CHECK(m["hit"] == cg::json::parse(R"({"primitive": null, "t": null, "point": null})"));
}

TEST_CASE("bvh: deterministic traces, replay on the example and the presets", "[accel][bvh]") {
    const cg::Algorithm& a = cg::test::algorithm("bvh");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, cg::test::kEveryStep);
        const auto in = input_of(p.input);
        CHECK(cg::run_to_end<Bvh>(Bvh::start(in)) == Bvh::build_and_trace(in));
    }
}

TEST_CASE("bvh: the picture — boxes by depth, the node in hand, the ray, the hit", "[accel][bvh]") {
    auto s = Bvh::start(scene(four_on_a_line(), Bvh::Split::Median, 1, {-3, 0, 0}, {1, 0, 0}));
    Bvh::step(s, nullptr);  // the root, split
    cg::Scene pic;
    Bvh::draw(s, pic);
    CHECK(pic.has_3d());
    // The tree is a diagram panel of its own, not drawn into the world: the root, made now.
    CHECK(!pic.has_2d());
    REQUIRE(pic.panels.size() == 1);
    CHECK(pic.panels[0].kind == cg::PanelKind::Diagram);
    CHECK(pic.panels[0].grids.empty());  // no raster under it
    REQUIRE(pic.panels[0].points.size() == s.r.nodes.size());
    CHECK(pic.panels[0].points[0].style.role == cg::Role::Active);
    REQUIRE(pic.panels[0].legend.size() == 1);
    CHECK(pic.panels[0].legend[0].style.role == cg::Role::Active);
    // Four spheres on a line with the ray: seen face-on, along z.
    CHECK(pic.view3.look == dvec3(0, 0, -1));
    CHECK(pic.view3.orthographic);
    CHECK(pic.focus3.size() == 1);
    int active_faces = 0, split_plane = 0;
    for (const auto& f : pic.faces3) {
        if (f.style.role == cg::Role::Active && f.points.size() == 4 && f.outline) ++active_faces;
        if (f.style.role == cg::Role::Leaving) {
            ++split_plane;
            for (const auto& p : f.points) CHECK(p.x == 4.5);  // between centroids 3 and 6
        }
    }
    CHECK(active_faces == 6);  // the root's box, shaded
    CHECK(split_plane == 1);
    // Every sphere is the node's: orange.
    int labels = 0;
    for (const auto& l : pic.labels3)
        if (l.text.size() == 1) labels += l.style.role == cg::Role::Active;
    CHECK(labels == 4);
    while (!Bvh::done(s)) {
        Bvh::step(s, nullptr);
        if (s.phase == Bvh::Phase::Report) break;
    }
    pic.clear();
    Bvh::draw(s, pic);  // after the last pop (node 4, pruned)
    bool pruned_box = false, hit = false;
    for (const auto& g : pic.segments3)
        pruned_box |= g.style.role == cg::Role::Discarded && g.style.width == 3.0f;
    for (const auto& p : pic.points3)
        hit |= p.style.role == cg::Role::Kept && p.p == dvec3(-1, 0, 0);
    CHECK(pruned_box);
    CHECK(hit);
    // The tree's key names what its colours mean while tracing; node 4, pruned, is red in it.
    REQUIRE(pic.panels.size() == 1);
    CHECK(pic.panels[0].legend.size() == 4);
    bool red_four = false;
    for (const auto& l : pic.panels[0].labels)
        red_four |= l.text == "4" && l.style.role == cg::Role::Discarded;
    CHECK(red_four);
    // Sphere 0 green, the rest grey.
    for (const auto& l : pic.labels3)
        if (l.text == "0") CHECK(l.style.role == cg::Role::Kept);

    // Every step of every preset and of random scenes draws finite coordinates only.
    std::vector<Bvh::Input> inputs;
    for (const auto& p : lesson().presets) inputs.push_back(input_of(p.input));
    for (int trial = 0; trial < 40; ++trial) {
        cg::Rng rng(5000 + trial);
        const auto ps = random_scene(rng, static_cast<int>(rng.integer(1, 24)));
        Bvh::Input in = scene(ps, trial % 2 ? Bvh::Split::Sah : Bvh::Split::Median, 2, {}, {});
        random_ray(rng, ps, in.origin, in.direction);
        inputs.push_back(in);
    }
    auto finite3 = [](dvec3 p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    for (const auto& in : inputs) {
        auto st = Bvh::start(in);
        while (true) {
            cg::Scene sc;
            Bvh::draw(st, sc);
            for (const auto& f : sc.faces3)
                for (const auto& p : f.points) REQUIRE(finite3(p));
            for (const auto& g : sc.segments3) REQUIRE((finite3(g.a) && finite3(g.b)));
            for (const auto& p : sc.points3) REQUIRE(finite3(p.p));
            if (Bvh::done(st)) break;
            Bvh::step(st, nullptr);
        }
    }
}

TEST_CASE("bvh: exam problems are hand-workable and graded", "[accel][bvh][exam]") {
    const cg::Algorithm& a = cg::test::algorithm("bvh");
    int hits = 0, misses = 0, pruned = 0;
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const auto in = input_of(p.input);
        CHECK(in.split == Bvh::Split::Median);
        CHECK(in.primitives.size() <= 6);
        const auto r = Bvh::build_and_trace(in);
        const BruteHit b = brute_force(in);
        CHECK(r.hit.primitive == b.primitive);
        hits += b.primitive >= 0;
        misses += b.primitive < 0;
        pruned += r.box_tests > 1 && r.primitive_tests < static_cast<int>(in.primitives.size());
        for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
    }
    CHECK(hits > 500);
    CHECK(misses > 100);
    CHECK(pruned > 300);
    const cg::ExamProblem p = cg::make_exam(a, 3);
    CHECK(p.answers == std::vector<std::string>{"leaves", "visited", "hit/primitive"});
    CHECK_THAT(p.question, Catch::Contains("median split"));
    // The worked examples of the other presets ask what their input does.
    const cg::ExamProblem sah = cg::exam_for_input(a, a.example());
    CHECK_THAT(sah.question, Catch::Contains("surface area heuristic") &&
                                 Catch::Contains("C(k) = 1 + (S_L/S)·N_L + (S_R/S)·N_R"));
    CHECK(sah.expected["hit/primitive"] == 0);
    cg::json no_ray = a.example();
    no_ray.erase("ray");
    const cg::ExamProblem build = cg::exam_for_input(a, no_ray);
    CHECK(build.answers == std::vector<std::string>{"leaves"});
    CHECK_THAT(build.question, !Catch::Contains("trace the ray"));
}
