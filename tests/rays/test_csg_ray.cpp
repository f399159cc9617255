// CSG on ray segments: the course's question and hand cases for every rule (tangent rays
// dropped, touching segments joined in a union and vanishing in an intersection, the reversed
// normal of a subtracted operand, the eye inside, unbounded primitives with null ends, caps,
// boxes, transforms on a subtree); 10,000 random rays through random trees of up to 6 spheres,
// boxes and capped cylinders (now and then an unbounded cone, hyperboloid, open cylinder or
// paraboloid) against the exact long-double intervals and the brute-force
// classification of csg_reference.hpp, hits on their surfaces; the state machine against the
// plain functions; errors naming the path; exam problems; determinism and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <set>
#include <sstream>

#include "core/format.hpp"
#include "io/exam.hpp"
#include "io/registry.hpp"
#include "rays/csg_json.hpp"
#include "rays/csg_ray.hpp"
#include "rays/csg_reference.hpp"
#include "support/process.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::CsgRay;
using cg::CsgTree;
using glm::dvec3;

namespace {

// A number as JSON text (cg::num is for students' eyes: "−1", "10⁻⁵").
std::string jnum(double x, int = 17) {
    return cg::json(x).dump();
}

using cg::test::events;
using cg::test::registry;
using Run = cg::test::JsonTraced;

const cg::Algorithm& algorithm() {
    return cg::test::algorithm("csg-ray");
}

cg::test::JsonTraced run_json(const std::string& text) {
    return cg::test::run_json("csg-ray", text);
}

std::string error_of(const std::string& text) {
    return cg::test::error_of("csg-ray", text);
}

using Events = std::vector<std::string>;

std::string sphere(double r, dvec3 c = dvec3(0.0), const std::string& name = "") {
    std::string s = R"({"primitive": {"type": "sphere", "params": {"r": )" + jnum(r) + "}";
    if (c != dvec3(0.0))
        s += R"(, "transform": [[1, 0, 0, )" + jnum(c.x) + "], [0, 1, 0, " + jnum(c.y) +
             "], [0, 0, 1, " + jnum(c.z) + "], [0, 0, 0, 1]]";
    s += "}";
    if (!name.empty()) s += R"(, "name": ")" + name + "\"";
    return s + "}";
}

std::string box(dvec3 lo, dvec3 hi, const std::string& name = "") {
    std::string s = R"({"primitive": {"type": "box", "min": [)" + jnum(lo.x) + ", " + jnum(lo.y) +
                    ", " + jnum(lo.z) + "], \"max\": [" + jnum(hi.x) + ", " + jnum(hi.y) + ", " +
                    jnum(hi.z) + "]}";
    if (!name.empty()) s += R"(, "name": ")" + name + "\"";
    return s + "}";
}

std::string node(const char* op, const std::string& l, const std::string& r,
                 const std::string& extra = "") {
    return std::string(R"({"op": ")") + op + R"(", "left": )" + l + R"(, "right": )" + r + extra +
           "}";
}

std::string input(const std::string& tree, dvec3 o, dvec3 d) {
    auto p = [](dvec3 v) {
        return "[" + jnum(v.x, 17) + ", " + jnum(v.y, 17) + ", " + jnum(v.z, 17) + "]";
    };
    return R"({"tree": )" + tree + R"(, "origin": )" + p(o) + R"(, "direction": )" + p(d) + "}";
}

cg::json spans(const std::string& text) {
    return cg::json::parse(text);
}

bool near(const cg::json& j, std::vector<double> want, double tol = 1e-12) {
    if (!j.is_array() || j.size() != want.size()) return false;
    for (std::size_t i = 0; i < want.size(); ++i)
        if (std::fabs(j[i].get<double>() - want[i]) > tol) return false;
    return true;
}

}  // namespace

TEST_CASE("csg-ray: the course's question, a sphere minus a sphere", "[rays][csg-ray]") {
    // (0, 0, −5) + t(0, 0, 1); A = sphere r = 2, B = sphere r = 1 at (0, 0, −1): A = [3, 7],
    // B = [3, 5], A − B = [5, 7]; the hit t = 5 at the origin, on B, n = −(0, 0, 1).
    const Run r = run_json(algorithm().example().dump());
    CHECK(events(r) == Events{"leaf", "leaf", "difference", "hit"});
    CHECK(r.result["lists"] == spans(R"({"A": [[3, 7]], "B": [[3, 5]], "A − B": [[5, 7]]})"));
    CHECK(r.result["segments"] == spans("[[5, 7]]"));
    CHECK(r.result["hit"] == true);
    CHECK(r.result["t"] == 5);
    CHECK(r.result["point"] == spans("[0, 0, 0]"));
    CHECK(near(r.result["normal"], {0, 0, -1}));
    CHECK(r.result["from"] == "B");
    CHECK(r.result["entering"] == true);
    CHECK(r.steps[0].narration.find("t² − 10t + 21") != std::string::npos);
    CHECK(r.steps[1].narration.find("E_m = (0, 0, −4)") != std::string::npos);
    CHECK(r.steps[2].narration.find("reversed") != std::string::npos);
    CHECK(r.steps[3].narration.find("reversed") != std::string::npos);
}

TEST_CASE("csg-ray: the rules for touching, tangent and unbounded segments", "[rays][csg-ray]") {
    const dvec3 E{0, 0, -5}, d{0, 0, 1};
    const std::string lower = box({-1, -1, -2}, {1, 1, 0}), upper = box({-1, -1, 0}, {1, 1, 2});
    SECTION("touching segments join in a union") {
        const Run r = run_json(input(node("union", lower, upper), E, d));
        CHECK(r.result["segments"] == spans("[[3, 7]]"));
        CHECK(r.result["t"] == 3);
        CHECK(near(r.result["normal"], {0, 0, -1}));
    }
    SECTION("touching segments vanish in an intersection") {
        const Run r = run_json(input(node("intersection", lower, upper), E, d));
        CHECK(r.result["segments"] == spans("[]"));
        CHECK(r.result["hit"] == false);
        CHECK(events(r).back() == "miss");
    }
    SECTION("A minus a B that touches it leaves A whole") {
        const Run r = run_json(input(node("difference", lower, upper), E, d));
        CHECK(r.result["segments"] == spans("[[3, 5]]"));
        CHECK(near(r.result["normal"], {0, 0, -1}));
    }
    SECTION("a tangent sphere gives a zero-length segment, dropped") {
        const Run r = run_json(
            input(node("union", sphere(1), box({-0.5, -0.5, 2}, {1.5, 0.5, 3})), {1, 0, -5}, d));
        CHECK(events(r) == Events{"tangent", "leaf", "union", "hit"});
        CHECK(r.result["lists"]["tree.left"] == spans("[]"));
        CHECK(r.result["segments"] == spans("[[7, 8]]"));
        CHECK(r.steps[0].narration.find("dropped") != std::string::npos);
    }
    SECTION("a ray through a box's edge, and along its face, only touches") {
        const Run edge = run_json(input(box({0, 0, -1}, {1, 1, 1}), {-1, 1, 0}, {1, -1, 0}));
        CHECK(events(edge).front() == "tangent");
        CHECK(edge.result["segments"] == spans("[]"));
        const Run face = run_json(input(box({0, -1, -1}, {1, 1, 1}), {0, 0, -5}, d));
        CHECK(events(face).front() == "tangent");
        const Run miss = run_json(input(box({2, -1, -1}, {3, 1, 1}), {0, 0, -5}, d));
        CHECK(events(miss).front() == "leaf-miss");
    }
    SECTION("an open cone holds the ray at both ends: null ends") {
        const Run r = run_json(
            input(node("intersection",
                       R"({"primitive": {"type": "cone", "params": {"p": 1, "q": 1, "r": 1}}})",
                       box({-5, -5, 0.5}, {5, 5, 3})),
                  {0.25, 0, -6}, d));
        CHECK(r.result["lists"]["tree.left"] == spans("[[null, 5.75], [6.25, null]]"));
        CHECK(r.result["segments"] == spans("[[6.5, 9]]"));
        CHECK(r.result["t"] == 6.5);
        CHECK(r.steps[0].narration.find("(−∞, 5.75] ∪ [6.25, ∞)") != std::string::npos);
    }
    SECTION("an uncut cylinder along the ray: the whole line, and no hit") {
        const Run r = run_json(
            input(R"({"primitive": {"type": "cylinder", "params": {"p": 1, "q": 1}}})", E, d));
        CHECK(r.result["segments"] == spans("[[null, null]]"));
        CHECK(r.result["hit"] == false);
    }
    SECTION("caps close a cylinder: their normals are ±z") {
        const Run r = run_json(input(
            R"({"primitive": {"type": "cylinder", "params": {"p": 1, "q": 1}, "zmin": -1, "zmax": 2}})",
            E, d));
        CHECK(r.result["segments"] == spans("[[4, 7]]"));
        CHECK(near(r.result["normal"], {0, 0, -1}));
        // From the side it is the curved wall, cut where the caps are.
        const Run side = run_json(input(
            R"({"primitive": {"type": "cylinder", "params": {"p": 1, "q": 1}, "zmin": -1, "zmax": 2}})",
            {-3, 0, -3}, {1, 0, 1}));
        // x = −3 + t hits x² = 1 at t = 2 (z = −1: the rim) and t = 4 (z = 1); the cap z = −1
        // at t = 2 too: the tie stays on the curved surface.
        CHECK(side.result["segments"] == spans("[[2, 4]]"));
        CHECK(near(side.result["normal"], {-1, 0, 0}));
    }
    SECTION("the eye inside: the hit is where the ray leaves") {
        const Run r =
            run_json(input(node("union", sphere(2), box({-1, -1, 1}, {1, 1, 4})), {0, 0, 0}, d));
        CHECK(r.result["segments"] == spans("[[-2, 4]]"));
        CHECK(r.result["t"] == 4);
        CHECK(r.result["entering"] == false);
        CHECK(r.result["normal"] == spans("[0, 0, 1]"));  // outward, not turned to the eye
        CHECK(events(r).back() == "exit-hit");
    }
    SECTION("a solid behind the eye is missed; t is in units of d") {
        const Run back = run_json(input(sphere(1), E, {0, 0, -1}));
        CHECK(back.result["segments"] == spans("[[-6, -4]]"));
        CHECK(back.result["hit"] == false);
        const Run twice = run_json(input(sphere(1), E, {0, 0, 2}));
        CHECK(twice.result["segments"] == spans("[[2, 3]]"));
    }
    SECTION("difference inside difference: a normal reversed twice is not reversed") {
        // A − (B − C): C inside B; the ray meets C's front inside B's hollow... the end from C
        // is flipped twice (−(−n)).
        const std::string t = node("difference", box({-2, -2, -2}, {2, 2, 2}, "A"),
                                   node("difference", sphere(1.5, {}, "B"), sphere(0.5, {}, "C")));
        const Run r = run_json(input(t, E, d));
        // A = [3, 7]; B = [3.5, 6.5], C = [4.5, 5.5], B − C = [3.5, 4.5] ∪ [5.5, 6.5];
        // A − (B − C) = [3, 3.5] ∪ [4.5, 5.5] ∪ [6.5, 7].
        CHECK(r.result["segments"] == spans("[[3, 3.5], [4.5, 5.5], [6.5, 7]]"));
        const cg::CsgTree tree = cg::csg_json::tree(cg::parse_json(t), "tree");
        const cg::CsgHit h =
            cg::csg_intersect(cg::prepare_csg(tree), {0, 0, 0}, d);  // from the centre
        // From the centre (inside C, so inside A − (B − C)), the ray leaves C at t = 0.5: C's
        // end flipped twice keeps C's own outward normal +z.
        CHECK(h.t == 0.5);
        CHECK(h.end.flip == false);
        CHECK(h.normal == dvec3(0, 0, 1));
    }
}

TEST_CASE("csg-ray: transforms apply to whole subtrees, t is the same in every frame",
          "[rays][csg-ray]") {
    // A cube [−1, 1]³ minus a sphere of radius 1.2, the pair turned a quarter about y and moved
    // by (1, 0, 0): the cube occupies x ∈ [0, 2], the sphere is centred at (1, 0, 0).
    const std::string t =
        node("difference", box({-1, -1, -1}, {1, 1, 1}, "A"), sphere(1.2, {}, "B"),
             R"(, "transform": [[0, 0, 1, 1], [0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 0, 1]])");
    const Run r = run_json(input(t, {-4, 0.6, 0.5}, {1, 0, 0}));
    const double h = std::sqrt(1.44 - 0.36 - 0.25);
    CHECK(r.result["lists"]["A"] == spans("[[4, 6]]"));
    REQUIRE(r.result["lists"]["B"].size() == 1);
    CHECK(r.result["lists"]["B"][0][0].get<double>() == Approx(5 - h).epsilon(1e-14));
    CHECK(r.result["segments"].size() == 2);
    CHECK(r.result["t"] == 4);
    CHECK(near(r.result["normal"], {-1, 0, 0}));
    CHECK(r.steps[0].narration.find("In its frame") != std::string::npos);
    // The same solid built without transforms gives the same lists.
    const std::string plain =
        node("difference", box({0, -1, -1}, {2, 1, 1}, "A"), sphere(1.2, {1, 0, 0}, "B"));
    const Run p = run_json(input(plain, {-4, 0.6, 0.5}, {1, 0, 0}));
    CHECK(p.result["lists"]["A"] == r.result["lists"]["A"]);
    CHECK(p.result["lists"]["B"][0][0].get<double>() ==
          Approx(r.result["lists"]["B"][0][0].get<double>()).epsilon(1e-14));
    // A non-uniform scale: normals by the inverse transpose.
    const std::string squashed =
        R"({"primitive": {"type": "sphere", "params": {"r": 1}}, "transform": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})";
    const double x = std::sqrt(2.0), y = std::sqrt(0.5);
    const Run s = run_json(input(squashed, {x, y + 3, 0}, {0, -1, 0}));
    const dvec3 want = glm::normalize(dvec3(x / 4, y, 0));
    CHECK(near(s.result["normal"], {want.x, want.y, want.z}, 1e-12));
}

// ---- random trees against the references ------------------------------------------------------

namespace {

struct TreeGen {
    cg::Rng& rng;
    CsgTree t;
    bool unbounded = true;  // now and then a cone, hyperboloid, open cylinder or paraboloid

    glm::dmat4 placement(bool scale) {
        glm::dmat4 m = glm::translate(
            glm::dmat4(1.0),
            {rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)});
        if (rng.chance(0.6))
            m = glm::rotate(
                m, rng.uniform(0, 6.283),
                glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.1, 1))));
        if (scale)
            m = glm::scale(m,
                           {rng.uniform(0.5, 1.8), rng.uniform(0.5, 1.8), rng.uniform(0.5, 1.8)});
        return m;
    }

    int leaf(const std::string& path, int depth) {
        cg::CsgNode n;
        n.path = path, n.depth = depth;
        const double k = rng.uniform(0, 1);
        if (unbounded && k < 0.08) {  // an unbounded solid: ends at ±∞
            static const cg::QuadricKind kinds[] = {
                cg::QuadricKind::Cone, cg::QuadricKind::Hyperboloid, cg::QuadricKind::Cylinder,
                cg::QuadricKind::Paraboloid};
            n.quadric.kind = kinds[rng.integer(0, 3)];
            n.quadric.a = rng.uniform(0.4, 1.5), n.quadric.b = rng.uniform(0.4, 1.5);
            n.quadric.c = rng.uniform(0.4, 1.5), n.quadric.p = rng.uniform(0.4, 1.5);
            n.quadric.q = rng.uniform(0.4, 1.5), n.quadric.r = rng.uniform(0.4, 1.5);
            n.quadric.world_from_model = placement(rng.chance(0.3));
        } else if (k < 0.4) {
            n.quadric.kind = cg::QuadricKind::Sphere;
            n.quadric.r = rng.uniform(0.4, 2);
            n.quadric.world_from_model = placement(rng.chance(0.3));
        } else if (k < 0.7) {
            n.kind = cg::CsgPrimitive::Box;
            n.box.min = {rng.uniform(-2, 1), rng.uniform(-2, 1), rng.uniform(-2, 1)};
            n.box.max = n.box.min +
                        dvec3(rng.uniform(0.3, 2.5), rng.uniform(0.3, 2.5), rng.uniform(0.3, 2.5));
            if (rng.chance(0.4)) n.has_transform = true, n.transform = placement(false);
        } else {
            n.quadric.kind = cg::QuadricKind::Cylinder;
            n.quadric.p = rng.uniform(0.3, 1.5), n.quadric.q = rng.uniform(0.3, 1.5);
            n.quadric.zmin = rng.uniform(-2, 0),
            n.quadric.zmax = n.quadric.zmin + rng.uniform(0.5, 3);
            n.quadric.world_from_model = placement(rng.chance(0.3));
        }
        n.leaf_index = t.leaves++;
        t.nodes.push_back(n);
        return static_cast<int>(t.nodes.size()) - 1;
    }

    int tree(int leaves, const std::string& path, int depth) {
        if (leaves == 1) return leaf(path, depth);
        const int left = static_cast<int>(rng.integer(1, leaves - 1));
        cg::CsgNode n;
        n.leaf = false;
        n.op = static_cast<cg::CsgOp>(rng.integer(0, 2));
        n.path = path, n.depth = depth;
        if (rng.chance(0.25)) n.has_transform = true, n.transform = placement(rng.chance(0.3));
        n.left = tree(left, path + ".left", depth + 1);
        n.right = tree(leaves - left, path + ".right", depth + 1);
        t.nodes.push_back(n);
        return static_cast<int>(t.nodes.size()) - 1;
    }
};

long double rel(long double a, long double b) {
    if (std::isinf(a) || std::isinf(b)) return a == b ? 0 : 1;
    return std::fabs(a - b) / std::max<long double>(1, std::fabs(b));
}

}  // namespace

TEST_CASE("csg-ray: 10,000 random rays through random trees agree with both references",
          "[rays][csg-ray][reference]") {
    std::size_t normal_out = 0;
    std::size_t total = 0, skipped = 0, hits = 0, nonempty = 0, samples_checked = 0,
                machine_checked = 0, infinite_ends = 0;
    std::set<int> sizes;
    for (int trial = 0; trial < 10'000; ++trial) {
        cg::Rng rng(77'000 + trial);
        TreeGen g{rng, {}, true};
        const int leaves = static_cast<int>(rng.integer(1, 6));
        g.tree(leaves, "tree", 0);
        const CsgTree& t = g.t;
        cg::validate_csg(t);
        sizes.insert(t.leaves);
        const dvec3 o{rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(-6, 6)};
        // Aimed near a random primitive's centre, so that most rays meet something.
        int aim = static_cast<int>(rng.integer(0, static_cast<long long>(t.nodes.size()) - 1));
        while (!t.nodes[aim].leaf) --aim;
        glm::dvec3 centre(cg::csg_world_from_leaf(t, aim)[3]);
        if (t.nodes[aim].kind == cg::CsgPrimitive::Box)
            centre = glm::dvec3(cg::csg_world_from_leaf(t, aim) *
                                glm::dvec4((t.nodes[aim].box.min + t.nodes[aim].box.max) / 2.0, 1));
        const dvec3 target =
            centre + dvec3(rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7));
        const dvec3 d = (target - o) * rng.uniform(0.2, 3);
        CAPTURE(trial, o.x, o.y, o.z, d.x, d.y, d.z);
        ++total;

        const cg::PreparedCsg p = cg::prepare_csg(t);
        const cg::CsgHit h = cg::csg_intersect(p, o, d);
        const cg::test::LSpans ref = cg::test::reference_segments(t, o, d);
        // Rays within round-off of a tie between two primitives' ends, or of a tangent, may
        // come out either way: skip those whose reference ends nearly coincide.
        bool borderline = ref.size() != h.segments.size();
        for (std::size_t i = 0; i + 1 < ref.size() && !borderline; ++i)
            borderline = rel(ref[i + 1].first, ref[i].second) < 1e-7L;
        for (const auto& s : ref) borderline = borderline || rel(s.second, s.first) < 1e-7L;
        if (borderline) {
            ++skipped;
            continue;
        }
        nonempty += !ref.empty();
        for (std::size_t i = 0; i < ref.size(); ++i) {
            CHECK(rel(h.segments[i].in.t, ref[i].first) < 1e-9L);
            CHECK(rel(h.segments[i].out.t, ref[i].second) < 1e-9L);
            infinite_ends += std::isinf(ref[i].first) + std::isinf(ref[i].second);
            CHECK(h.segments[i].in.t < h.segments[i].out.t);
            if (i) CHECK(h.segments[i - 1].out.t < h.segments[i].in.t);
        }

        // Brute force: dense samples, each classified against every primitive; a disagreement
        // with the segments must lie within a sample spacing of one of their ends.
        double lo = 0, hi = 1;
        for (const auto& s : h.segments)
            for (double e : {s.in.t, s.out.t})
                if (std::isfinite(e)) lo = std::min(lo, e), hi = std::max(hi, e);
        lo -= 0.5 * (hi - lo), hi += 0.5 * (hi - lo);
        constexpr int kSamples = 240;
        const double step = (hi - lo) / kSamples;
        const std::vector<cg::test::LeafFrame> frames = cg::test::leaf_frames(t);
        for (int k = 0; k <= kSamples; ++k) {
            const double ts = lo + k * step;
            const cg::test::LVec P{o.x + ts * d.x, o.y + ts * d.y, o.z + ts * d.z, 1};
            const bool brute =
                cg::test::tree_inside(t, static_cast<int>(t.nodes.size()) - 1, frames, P);
            bool listed = false, near_end = false;
            for (const auto& s : h.segments) {
                listed = listed || (s.in.t < ts && ts < s.out.t);
                near_end =
                    near_end || std::fabs(ts - s.in.t) <= step || std::fabs(ts - s.out.t) <= step;
            }
            if (brute != listed) CHECK(near_end);
            ++samples_checked;
        }

        // The hit: the first end ahead of ε, on its primitive's surface.
        const cg::CsgEnd* first = cg::first_end_after(h.segments, cg::kRayEpsilon);
        REQUIRE(h.hit == (first != nullptr));
        if (h.hit) {
            ++hits;
            const cg::CsgNode* leaf = nullptr;
            for (const auto& n : t.nodes)
                if (n.leaf && n.leaf_index == h.end.leaf) leaf = &n;
            REQUIRE(leaf != nullptr);
            const cg::test::LVec m =
                cg::test::mul(frames[h.end.leaf].model_from_world,
                              cg::test::LVec{h.point.x, h.point.y, h.point.z, 1});
            const long double scale = 1 + std::fabs(m[0]) + std::fabs(m[1]) + std::fabs(m[2]);
            if (leaf->kind == cg::CsgPrimitive::Box) {
                const int axis = h.end.face / 2;
                const double plane = h.end.face % 2 ? leaf->box.max[axis] : leaf->box.min[axis];
                CHECK(std::fabs(m[axis] - plane) < 1e-9L * scale);
            } else if (h.end.face == 0) {
                cg::Quadric q = leaf->quadric;
                q.world_from_model =
                    cg::csg_world_from_leaf(t, static_cast<int>(leaf - t.nodes.data()));
                CHECK(cg::test::relative_residual(q, h.point) < 1e-9L);
            } else {
                const double plane = h.end.face == 1 ? leaf->quadric.zmin : leaf->quadric.zmax;
                CHECK(std::fabs(m[2] - plane) < 1e-9L * scale);
            }
            REQUIRE(h.has_normal);
            CHECK(glm::length(h.normal) == Approx(1).epsilon(1e-12));
            // The normal points out of the solid: just beyond it along n the point is outside.
            const dvec3 out = h.point + 1e-6 * double(scale) * h.normal;
            const dvec3 in = h.point - 1e-6 * double(scale) * h.normal;
            const int root = static_cast<int>(t.nodes.size()) - 1;
            const bool ahead = cg::test::tree_inside(t, root, frames, {out.x, out.y, out.z, 1});
            const bool behind = cg::test::tree_inside(t, root, frames, {in.x, in.y, in.z, 1});
            CHECK_FALSE((ahead && !behind));  // never pointing into the solid
            normal_out += !ahead && behind;   // (at an edge both sides may be alike)
        }

        // Every 10th ray through the state machine, quiet and narrated, and the plain solve.
        if (trial % 10 == 0) {
            ++machine_checked;
            CsgRay::Input in{t, o, d};
            auto s = CsgRay::start(in);
            auto narrated = s;
            const CsgRay::Result quiet = cg::run_to_end<CsgRay>(s);
            CHECK(quiet.hit == h);
            CHECK(quiet == CsgRay::solve(cg::Shared<CsgRay::Input>(in)));
            while (!CsgRay::done(narrated)) {
                cg::StepInfo info;
                CsgRay::step(narrated, &info);
                CHECK(info.narration.find("nan") == std::string::npos);
            }
            CHECK(CsgRay::result(narrated) == quiet);
        }
    }
    CAPTURE(total, skipped, hits, nonempty, infinite_ends, samples_checked);
    WARN("csg reference: " << total << " rays, " << skipped << " skipped as ties, " << nonempty
                           << " with segments, " << hits << " hits, " << infinite_ends
                           << " infinite ends, " << samples_checked << " samples classified");
    CHECK(skipped < total / 200);
    CHECK(normal_out > hits * 99 / 100);
    CHECK(infinite_ends > 100);
    CHECK(hits > total / 3);
    CHECK(nonempty > total / 3);
    CHECK(machine_checked == 1000);
    CHECK(sizes.size() == 6);
}

TEST_CASE("csg-ray: combine on hand-made lists, and leaves against the reference on tangents",
          "[rays][csg-ray]") {
    using cg::CsgOp;
    auto list = [](std::vector<std::pair<double, double>> v, int leaf) {
        cg::CsgSpans s;
        for (auto [a, b] : v) s.push_back({{a, leaf, 0, false}, {b, leaf, 0, false}});
        return s;
    };
    auto text = [](const cg::CsgSpans& s) { return cg::csg_spans_text(s); };
    const cg::CsgSpans A = list({{1, 4}, {6, 9}}, 0), B = list({{2, 3}, {4, 6}, {8, 10}}, 1);
    CHECK(text(cg::combine(CsgOp::Union, A, B)) == "[1, 10]");
    CHECK(text(cg::combine(CsgOp::Intersection, A, B)) == "[2, 3] ∪ [8, 9]");
    CHECK(text(cg::combine(CsgOp::Difference, A, B)) == "[1, 2] ∪ [3, 4] ∪ [6, 8]");
    CHECK(text(cg::combine(CsgOp::Difference, B, A)) == "[4, 6] ∪ [9, 10]");
    const cg::CsgSpans diff = cg::combine(CsgOp::Difference, A, B);
    CHECK(diff[0].out.leaf == 1);  // [1, 2]: ends where B starts ...
    CHECK(diff[0].out.flip);       // ... with B's normal reversed
    CHECK(diff[1].in.flip);
    CHECK_FALSE(diff[1].out.flip);
    CHECK(text(cg::combine(CsgOp::Union, A, {})) == text(A));
    CHECK(text(cg::combine(CsgOp::Intersection, A, {})) == "∅");
    CHECK(text(cg::combine(CsgOp::Difference, {}, A)) == "∅");
    const double inf = cg::Quadric::kInf;
    const cg::CsgSpans whole{{{-inf, -1, 0, false}, {inf, -1, 0, false}}};
    CHECK(text(cg::combine(CsgOp::Difference, whole, A)) == "(−∞, 1] ∪ [4, 6] ∪ [9, ∞)");
    CHECK(text(cg::combine(CsgOp::Intersection, whole, A)) == text(A));
}

TEST_CASE("csg-ray: the slab test", "[rays][csg-ray]") {
    const cg::Box b{{0, 0, 0}, {2, 1, 1}};
    cg::SlabHit h = cg::ray_slabs(b, {-1, 0.5, 0.5}, {1, 0, 0});
    CHECK(h.hit);
    CHECK(h.t_near == 1);
    CHECK(h.t_far == 3);
    CHECK(cg::entry_face(h, {1, 0, 0}) == 0);
    CHECK(cg::exit_face(h, {1, 0, 0}) == 1);
    h = cg::ray_slabs(b, {3, 0.5, 0.5}, {-2, 0, 0});
    CHECK(h.t_near == 0.5);
    CHECK(h.t_far == 1.5);
    CHECK(cg::entry_face(h, {-2, 0, 0}) == 1);
    CHECK(cg::box_face_normal(1) == dvec3(1, 0, 0));
    CHECK_FALSE(cg::ray_slabs(b, {-1, 1, 0.5}, {1, 0, 0}).hit);  // along the y = 1 face
    CHECK_FALSE(cg::ray_slabs(b, {-1, 0, 0.5}, {1, 1, 0}).hit);  // touches the edge x = 0, y = 1
    CHECK(cg::ray_slabs(b, {-1, -0.1, 0.5}, {1, 1, 0}).hit);
}

TEST_CASE("csg-ray: bad trees are refused naming the path", "[rays][csg-ray][errors]") {
    const std::string s1 = sphere(1), E = R"(, "origin": [0, 0, -5], "direction": [0, 0, 1]})";
    CHECK(error_of(R"({"tree": )" + node("xor", s1, s1) + E) ==
          "tree.op: unknown op \"xor\" (union, intersection, difference)");
    CHECK(
        error_of(R"({"tree": )" + node("union", s1, node("union", s1, node("nand", s1, s1))) + E) ==
        "tree.right.right.op: unknown op \"nand\" (union, intersection, difference)");
    CHECK(error_of(R"({"tree": {"op": "union", "left": )" + s1 + "}" + E) ==
          "tree.right: is missing");
    CHECK(error_of(R"({"tree": {"left": )" + s1 + "}" + E) ==
          "tree: must be a boolean node {\"op\", \"left\", \"right\"} or a leaf {\"primitive\"}");
    CHECK_THAT(
        error_of(R"({"tree": {"primitive": {"type": "box", "min": [0, 0, 0], "max": [1, 0, 1]}})" +
                 E),
        Catch::StartsWith("tree.primitive.max[1]: must be greater than min[1]"));
    CHECK_THAT(error_of(R"({"tree": {"primitive": {"type": "box", "min": [0, 0, 0]}})" + E),
               Catch::StartsWith("tree.primitive.max: is missing"));
    CHECK_THAT(
        error_of(
            R"({"tree": {"primitive": {"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "params": {}}})" +
            E),
        Catch::StartsWith("tree.primitive.params: is not a known field"));
    CHECK_THAT(
        error_of(R"({"tree": )" +
                 node("union", s1, R"({"primitive": {"type": "sphere", "params": {"r": -1}}})") +
                 E),
        Catch::StartsWith("tree.right.primitive.params.r: must be positive"));
    CHECK_THAT(
        error_of(
            R"({"tree": )" +
            node("union", s1, s1,
                 R"(, "transform": [[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])") +
            E),
        Catch::StartsWith("tree.transform: is singular"));
    CHECK_THAT(
        error_of(R"({"tree": {"primitive": {"type": "sphere", "params": {"r": 1}}, "name": 3})" +
                 E),
        Catch::StartsWith("tree.name: must be a string"));
    // Depth: 32 levels below the root are accepted, 33 refused with the path.
    std::string deep = s1, deeper;
    for (int i = 0; i < 32; ++i) deep = node("union", deep, s1);
    CHECK(error_of(R"({"tree": )" + deep + E) == "(accepted)");
    deeper = node("union", deep, s1);
    std::string path = "tree";
    for (int i = 0; i < 33; ++i) path += ".left";
    CHECK(error_of(R"({"tree": )" + deeper + E) ==
          path + ": is 33 levels below the root; the limit is 32");
    // Leaves: 256 accepted, 257 refused (a balanced tree, so the depth stays small).
    std::function<std::string(int)> balanced = [&](int n) {
        return n == 1 ? s1 : node("union", balanced(n / 2), balanced(n - n / 2));
    };
    CHECK(error_of(R"({"tree": )" + balanced(256) + E) == "(accepted)");
    CHECK_THAT(error_of(R"({"tree": )" + balanced(257) + E),
               Catch::Contains("is primitive number 257 of the tree; the limit is 256"));
    // The ray.
    CHECK(error_of(R"({"tree": )" + s1 + R"(, "origin": [0, 0, -5], "direction": [0, 0, 0]})") ==
          "direction: must not be the zero vector: a ray needs a direction");
    CHECK_THAT(error_of(R"({"tree": )" + s1 + R"(, "origin": [0, 0, -5]})"),
               Catch::StartsWith("direction: is missing"));
    // A transform that sends the ray out of range in a leaf's frame names the leaf.
    CHECK_THAT(
        error_of(
            R"({"tree": {"primitive": {"type": "sphere", "params": {"r": 1}, "transform": [[1, 0, 0, 5e100], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}})" +
            E),
        Catch::StartsWith("tree: is placed so that the ray is too large"));
    // NaN from C++ (JSON cannot spell it): the field is named.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CsgRay::Input in;
    in.tree =
        cg::csg_json::tree(cg::parse_json(node("union", s1, box({0, 0, 0}, {1, 1, 1}))), "tree");
    in.origin = {0, 0, -5};
    in.direction = {0, 0, 1};
    auto with = [&](auto change) {
        CsgRay::Input copy = in;
        change(copy);
        try {
            CsgRay::start(copy);
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(with([](auto&) {}) == "(accepted)");
    CHECK(with([&](auto& i) { i.origin.x = nan; }) ==
          "origin[0]: must be a finite number (got NaN)");
    CHECK(with([&](auto& i) { i.tree.nodes[1].box.max.z = nan; }) ==
          "tree.right.primitive.max[2]: must be a finite number (got NaN)");
    CHECK(with([&](auto& i) { i.tree.nodes[0].quadric.r = nan; }) ==
          "tree.left.primitive.params.r: must be a finite number (got NaN)");
    CHECK(with([&](auto& i) {
              i.tree.nodes[2].has_transform = true;
              i.tree.nodes[2].transform[3][1] = nan;
          }) == "tree.transform[1][3]: must be a finite number (got NaN)");
}

TEST_CASE("csg-ray: exam problems are nice and answered right", "[rays][csg-ray][exam]") {
    const cg::Algorithm& a = algorithm();
    std::set<std::string> events;
    int hits = 0, three = 0, moved = 0, halves = 0;
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const CsgRay::Input in = [&] {
            cg::Rng rng(seed);
            return CsgRay::exam_input(rng);
        }();
        const Run r = run_json(p.input.dump());
        for (const std::string& e : cg::test::events(r)) events.insert(e);
        // The root's list against the exact reference; every end a multiple of 1/2.
        const cg::test::LSpans ref = cg::test::reference_segments(in.tree, in.origin, in.direction);
        const cg::json& seg = r.result["segments"];
        REQUIRE(seg.size() == ref.size());
        for (std::size_t i = 0; i < ref.size(); ++i)
            for (int e = 0; e < 2; ++e) {
                const long double want = e ? ref[i].second : ref[i].first;
                if (std::isinf(want)) {
                    CHECK(seg[i][e].is_null());
                    continue;
                }
                CHECK(std::fabs(seg[i][e].get<double>() - want) < 1e-12L);
                CHECK(std::fabs(want * 2 - std::round(want * 2)) < 1e-12L);
                halves += std::fabs(want - std::round(want)) > 0.25L;
            }
        hits += p.expected["hit"] == true;
        three += in.tree.leaves == 3;
        moved += in.tree.root().has_transform;
        CHECK(p.question.find("Give each list") != std::string::npos);
        CHECK(p.expected["lists"].size() == in.tree.nodes.size());
        for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
        if (p.expected["hit"] == true) {
            cg::json wrong = p.expected;
            wrong["normal"][2] = wrong["normal"][2].get<double>() * -1 + 0.5;
            CHECK_FALSE(cg::grade(p, wrong)[4].correct);
        }
    }
    CHECK(hits > 200);
    CHECK(three > 60);
    CHECK(moved > 40);
    CHECK(halves > 20);
    for (const char* ev :
         {"leaf", "tangent", "union", "intersection", "difference", "hit", "exit-hit", "miss"}) {
        CAPTURE(ev);
        CHECK(events.count(ev) == 1);
    }
    // The course's own question reads as the course asks it.
    const CsgRay::Input course = CsgRay::Input{
        cg::csg_json::tree(algorithm().example()["tree"], "tree"), {0, 0, -5}, {0, 0, 1}};
    CHECK(CsgRay::question(course).rfind(
              "The ray E + t·d = (0, 0, −5) + t·(0, 0, 1) meets the solid A − B, where A = sphere "
              "r = 2 centred at (0, 0, 0); B = sphere r = 1 centred at (0, 0, −1).",
              0) == 0);
}

TEST_CASE("csg-ray: traces are deterministic and stepping back reproduces them",
          "[rays][csg-ray]") {
    const cg::Algorithm& a = algorithm();
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (std::uint64_t seed : {3, 11, 29})
        cg::test::check_replay(a, a.exam_input(seed), cg::test::kEveryStep);
    // The input written back reads the same, and the same problem comes out.
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const cg::json j = a.exam_input(seed);
        CHECK(cg::exam_for_input(a, j).expected == cg::make_exam(a, seed).expected);
        const CsgRay::Input in = [&] {
            cg::Rng rng(seed);
            return CsgRay::exam_input(rng);
        }();
        CHECK(cg::csg_json::tree(cg::csg_json::tree_json(in.tree), "tree") == in.tree);
    }
}

TEST_CASE("csg-ray: the picture shows the solids, the ray's segments and the t chart",
          "[rays][csg-ray]") {
    const cg::Algorithm& a = algorithm();
    auto run = a.create(a.example());
    cg::Scene before;
    run->draw(before);
    CHECK(before.faces3.size() == 2 * 16 * 8);  // both spheres
    CHECK_FALSE(before.has_2d());               // nothing on the world's grid
    REQUIRE(before.panels.size() == 1);         // the chart: t across, no rows yet
    CHECK(before.panels[0].kind == cg::PanelKind::Chart);
    CHECK(before.panels[0].x.label == "t");
    CHECK(before.panels[0].segments.size() == 1);  // the eye's mark at t = 0
    CHECK(before.focus3.size() == 1);
    CHECK(before.view3.orthographic);  // seen from the side of the ray
    std::vector<cg::Scene> scenes;
    while (!run->done()) {
        run->step(nullptr);
        scenes.emplace_back();
        run->draw(scenes.back());
    }
    REQUIRE(scenes.size() == 4);
    // After the difference: what it kept ([5, 7]) green and what it threw away ([3, 5]) red,
    // along the ray in 3D; three rows on the strip.
    int kept = 0, thrown = 0;
    for (const auto& s : scenes[2].segments3) {
        kept += s.style.role == cg::Role::Kept && s.style.width >= 5;
        thrown += s.style.role == cg::Role::Discarded;
    }
    CHECK(kept == 1);
    CHECK(thrown == 1);
    // Three rows on the chart, named; the difference's row is [5, 7], its thrown-away part
    // [3, 5] thin and red.
    const cg::Panel& chart = scenes[2].panels.at(0);
    int rows = 0;
    for (const auto& name : chart.y.names)
        rows += name.rfind("A", 0) == 0 || name.rfind("B", 0) == 0;
    CHECK(rows == 3);  // named on the y axis: A, B, A − B
    bool kept_bar = false, red_bar = false;
    for (const auto& sg : chart.segments) {
        kept_bar = kept_bar || (sg.style.role == cg::Role::Kept && sg.a.x == 5 && sg.b.x == 7);
        red_bar = red_bar || (sg.style.role == cg::Role::Discarded && sg.a.x == 3 && sg.b.x == 5);
    }
    CHECK(kept_bar);
    CHECK(red_bar);
    // The hit: the point and its normal.
    bool normal = false, point = false;
    for (const auto& s : scenes[3].segments3)
        normal = normal || (s.arrow && s.label == "n" && s.min_pixels >= 30);
    for (const auto& p : scenes[3].points3) point = point || p.label == "P";
    CHECK(normal);
    CHECK(point);
    // A box's six faces, a cylinder's mesh between its caps.
    auto box_run =
        a.create(cg::parse_json(input(box({0, 0, 0}, {1, 2, 3}), {0.5, 0.5, -4}, {0, 0, 1})));
    cg::Scene b;
    box_run->draw(b);
    CHECK(b.faces3.size() == 6);
}

TEST_CASE("csg-ray: the worked example of the course's question matches its golden file",
          "[rays][csg-ray][worked]") {
    std::ifstream f(CG_SOURCE_DIR "/tests/golden/csg-ray-the-courses-question.md");
    std::stringstream golden;
    golden << f.rdbuf();
    REQUIRE_FALSE(golden.str().empty());
    auto r = cg::test::cgsandbox({"worked", "csg-ray", "--preset",
                                  "the course's question: a sphere minus a smaller one (A − B)"});
    REQUIRE(r.exit_code == 0);
    CHECK(r.out == golden.str());
}

TEST_CASE(
    "csg-ray: a direction component of 5e-324 overflows the slab's ends to infinity, said as ∞",
    "[rays][csg]") {
    // Found by fuzz_algorithm_input (its oracle: no "inf" in a narration): (3 − 0)/5e-324 is
    // beyond every double, and the slab's interval was printed "[-inf, inf]".
    const cg::json in = cg::json::parse(R"({"tree": {"name": "B", "primitive":
        {"type": "box", "min": [-1, -1, -1], "max": [3, 2, 2]}},
        "origin": [0, 0, 5], "direction": [5e-324, 0, -1]})");
    auto run = cg::builtin_registry().find("csg-ray")->create(in);
    bool said = false;
    while (!run->done()) {
        cg::StepInfo info;
        run->step(&info);
        CHECK(info.narration.find("inf") == std::string::npos);
        said = said || info.narration.find("x [−∞, ∞]") != std::string::npos;
    }
    CHECK(said);
}
