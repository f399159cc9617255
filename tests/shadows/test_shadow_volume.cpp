// Shadow volumes: the box and the tetrahedron worked by hand (lit faces, the silhouette in
// order, the crossings and counts); 4,000 random scenes — cubes, tetrahedra and octahedra under
// random affine maps, one or two per mesh so shadows overlap — with 6 eye rays each, aimed at the
// floor and at the occluder: the count equals the number of lit faces a long-double shadow ray
// from P crosses (so the verdict equals the shadow ray's), rays grazing an edge or corner within
// 1e-7 skipped and counted; the silhouette against a brute-force search over face pairs, one closed
// loop for a single convex shape; the eye inside the volume; errors naming the field; replay on
// the example and the presets; the exam problems; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "shadows/shadow_volume.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::ShadowVolume;
using glm::dvec3;
using Input = ShadowVolume::Input;

namespace {

using LD = long double;

const std::vector<dvec3> kCubeV = {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1},
                                   {-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1}};
const std::vector<std::array<int, 3>> kCubeF = {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6},
                                                {3, 2, 6}, {3, 6, 7}, {0, 5, 1}, {0, 4, 5},
                                                {1, 5, 6}, {1, 6, 2}, {0, 3, 7}, {0, 7, 4}};
const std::vector<dvec3> kTetV = {{-1, 1, -1}, {1, 1, -1}, {0, 1, 1}, {0, 2, 0}};
const std::vector<std::array<int, 3>> kTetF = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
const std::vector<dvec3> kOctV = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
const std::vector<std::array<int, 3>> kOctF = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                               {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

Input make(std::vector<dvec3> v, std::vector<std::array<int, 3>> f, dvec3 light, dvec3 eye,
           std::vector<dvec3> targets) {
    Input in;
    in.vertices = std::move(v);
    in.faces = std::move(f);
    in.light = light;
    in.eye = eye;
    in.targets = std::move(targets);
    in.has_floor = true;
    in.floor = 0;
    return in;
}

const Input kBox = make(kCubeV, kCubeF, {0, 6, 0}, {6, 4, 3}, {{0, 0, 0}, {3, 0, -1}});

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("shadow-volume");
    if (!l) throw std::runtime_error("no lesson for shadow-volume");
    return *l;
}

Input input_of(const cg::json& j) {
    return cg::test::input_of<ShadowVolume>("shadow-volume", j);
}

// ---- the long-double reference ----

struct V {
    LD x, y, z;
};
V lv(const dvec3& p) {
    return {p.x, p.y, p.z};
}
V sub(V a, V b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V cross(V a, V b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
LD dot(V a, V b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
LD len(V a) {
    return std::sqrt(dot(a, a));
}

// Where o + t d meets the triangle's plane and its barycentric margin (the smallest of the
// three barycentric coordinates: < 0 outside). False when parallel.
bool plane_hit(V o, V d, V a, V b, V c, LD& t, LD& margin) {
    const V n = cross(sub(b, a), sub(c, a));
    const LD den = dot(n, d);
    if (den == 0) return false;
    t = dot(n, sub(a, o)) / den;
    const V x{o.x + t * d.x, o.y + t * d.y, o.z + t * d.z};
    const LD nn = dot(n, n);
    const LD u = dot(cross(sub(c, b), sub(x, b)), n) / nn;
    const LD v = dot(cross(sub(a, c), sub(x, c)), n) / nn;
    margin = std::min({u, v, 1 - u - v});
    return true;
}

struct Reference {
    int surface = ShadowVolume::kNone;
    V hit{0, 0, 0};
    int cones = 0;  // lit faces the segment from P to L crosses (P's own face skipped)
    bool blocked = false;
    bool grazing = false;
};

constexpr LD kGraze = 1e-7L;

Reference reference(const Input& in, const dvec3& target, const std::vector<bool>& lit) {
    Reference r;
    const V E = lv(in.eye), L = lv(in.light), d = sub(lv(target), E);
    LD best = std::numeric_limits<LD>::infinity();
    if (d.y != 0) {
        const LD t = (LD(in.floor) - E.y) / d.y;
        if (t > 0) best = t, r.surface = ShadowVolume::kFloor;
    }
    for (std::size_t f = 0; f < in.faces.size(); ++f) {
        LD t, m;
        const V a = lv(in.vertices[in.faces[f][0]]), b = lv(in.vertices[in.faces[f][1]]),
                c = lv(in.vertices[in.faces[f][2]]);
        if (!plane_hit(E, d, a, b, c, t, m) || t <= 0) continue;
        if (std::fabs(m) < kGraze) r.grazing = true;
        if (m >= 0 && t < best) best = t, r.surface = int(f);
    }
    if (r.surface == ShadowVolume::kNone) return r;
    r.hit = {E.x + best * d.x, E.y + best * d.y, E.z + best * d.z};
    if (r.surface == ShadowVolume::kFloor) r.hit.y = in.floor;
    // The shadow ray, P to L.
    const V s = sub(L, r.hit);
    for (std::size_t f = 0; f < in.faces.size(); ++f) {
        if (int(f) == r.surface) continue;
        LD t, m;
        const V a = lv(in.vertices[in.faces[f][0]]), b = lv(in.vertices[in.faces[f][1]]),
                c = lv(in.vertices[in.faces[f][2]]);
        if (!plane_hit(r.hit, s, a, b, c, t, m)) continue;
        if (t > -kGraze && t < 1 + kGraze && std::fabs(m) < kGraze) r.grazing = true;
        if (std::fabs(t) < kGraze && m > -kGraze) r.grazing = true;  // P on or by another face
        if (t > 0 && t < 1 && m >= 0) {
            r.blocked = true;
            r.cones += lit[f] ? 1 : 0;
        }
    }
    // The eye ray passing close to a shadow quad's boundary: the line L + u (p − L) through
    // each vertex, met by the eye ray within kGraze (relative).
    for (const dvec3& p : in.vertices) {
        const V w = sub(lv(p), L);
        const V n = cross(w, d);
        const LD nl = len(n);
        if (nl == 0) continue;
        const LD dist = std::fabs(dot(sub(E, L), n)) / nl;
        if (dist < kGraze * (len(sub(E, L)) + len(w) + 1)) r.grazing = true;
    }
    return r;
}

// Random closed meshes: cubes, tetrahedra, octahedra under random affine maps (turned inside
// out back when the map reflects), floating over the floor; now and then two in one mesh.
Input random_scene(cg::Rng& rng, bool& convex) {
    Input in;
    in.has_floor = true;
    in.floor = 0;
    const int shapes = rng.chance(0.25) ? 2 : 1;
    convex = shapes == 1;
    for (int k = 0; k < shapes; ++k) {
        const int kind = int(rng.integer(0, 2));
        const auto& V0 = kind == 0 ? kCubeV : kind == 1 ? kTetV : kOctV;
        const auto& F0 = kind == 0 ? kCubeF : kind == 1 ? kTetF : kOctF;
        glm::dmat3 m;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = rng.uniform(-0.8, 0.8) + (i == j ? 1.0 : 0.0);
        const dvec3 shift{rng.uniform(-2, 2), rng.uniform(2.5, 4), rng.uniform(-2, 2)};
        dvec3 centre(0);
        for (const auto& v : V0) centre += v / double(V0.size());
        const int base = int(in.vertices.size());
        for (const auto& v : V0) in.vertices.push_back(shift + 0.7 * (m * (v - centre)));
        const bool flip = glm::determinant(m) < 0;
        for (auto f : F0) {
            if (flip) std::swap(f[1], f[2]);
            in.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
        }
    }
    in.light = {rng.uniform(-3, 3), rng.uniform(7, 10), rng.uniform(-3, 3)};
    in.eye = {rng.uniform(-8, 8), rng.uniform(0.2, 8), rng.uniform(5, 9)};
    if (rng.chance(0.15)) in.eye = {rng.uniform(-1, 1), rng.uniform(0.1, 0.8), rng.uniform(-1, 1)};
    for (int k = 0; k < 6; ++k) {
        if (k % 2 == 0) {
            in.targets.push_back({rng.uniform(-5, 5), 0, rng.uniform(-5, 5)});
        } else {  // a point on a random face
            const auto& f = in.faces[rng.integer(0, int(in.faces.size()) - 1)];
            double u = rng.uniform(0, 1), v = rng.uniform(0, 1);
            if (u + v > 1) u = 1 - u, v = 1 - v;
            const dvec3 a = in.vertices[f[0]], b = in.vertices[f[1]], c = in.vertices[f[2]];
            in.targets.push_back(a + u * (b - a) + v * (c - a));
        }
    }
    return in;
}

// Silhouette by brute force: every pair of faces sharing two vertices.
std::set<std::pair<int, int>> brute_silhouette(const Input& in, const std::vector<bool>& lit) {
    std::set<std::pair<int, int>> out;
    for (std::size_t f = 0; f < in.faces.size(); ++f)
        for (std::size_t g = f + 1; g < in.faces.size(); ++g) {
            std::vector<int> common;
            for (int a : in.faces[f])
                for (int b : in.faces[g])
                    if (a == b) common.push_back(a);
            if (common.size() == 2 && lit[f] != lit[g])
                out.insert(std::minmax(common[0], common[1]));
        }
    return out;
}

}  // namespace

TEST_CASE("shadow-volume: the box over the floor, by hand", "[shadows][shadow-volume]") {
    const auto t = cg::test::run_traced<ShadowVolume>(kBox);
    // Only the two top triangles face the light (0, 6, 0): n = (0, 4, 0), n · (L − a) = 12.
    std::vector<bool> lit(12, false);
    lit[2] = lit[3] = true;
    CHECK(t.result.lit == lit);
    CHECK_THAT(t.steps[2].narration, Catch::Contains("n_f · (L − a) = 12 > 0"));
    CHECK_THAT(t.steps[8].narration, Catch::Contains("n_f · (L − a) = −4 < 0"));
    // The top's four outer edges, as they run in the lit top faces; its diagonal (4, 6) is not.
    CHECK(t.result.silhouette == std::vector<std::array<int, 2>>{{6, 5}, {5, 4}, {4, 7}, {7, 6}});
    // Ray 0 to (0, 0, 0): enters through the quad of edge (6, 5) (the side x = (6 − y) / 3) at
    // t = 8/11; the quad of (4, 7) is crossed behind P, at t = 10/7.
    REQUIRE(t.result.rays.size() == 2);
    const auto& r0 = t.result.rays[0];
    CHECK(r0.surface == ShadowVolume::kFloor);
    CHECK(r0.hit == dvec3(0, 0, 0));
    CHECK(r0.crossings == std::vector<int>{+1});
    CHECK(r0.count == 1);
    CHECK(r0.in_shadow);
    CHECK(r0.shadow_ray);
    CHECK(r0.behind == 1);
    const auto cs = ShadowVolume::crossings(kBox, t.result.silhouette, {0, 0, 0});
    REQUIRE(cs.size() == 2);
    CHECK(cs[0].t == Approx(8.0 / 11));
    CHECK(cs[0].quad == 0);
    // Ray 1 to (3, 0, −1): no quad before P, lit.
    const auto& r1 = t.result.rays[1];
    CHECK(r1.crossings.empty());
    CHECK(r1.count == 0);
    CHECK_FALSE(r1.in_shadow);
    CHECK_FALSE(r1.shadow_ray);
    const auto ev = cg::test::events(t);
    CHECK(std::count(ev.begin(), ev.end(), "silhouette") == 4);
    CHECK(std::count(ev.begin(), ev.end(), "inner-edge") == 14);
    CHECK(std::vector<std::string>(ev.end() - 5, ev.end()) ==
          std::vector<std::string>{"ray", "enter", "verdict", "ray", "verdict"});
    CHECK_THAT(t.steps[t.steps.size() - 4].narration,
               Catch::Contains("front-facing — the ray enters the shadow volume: +1, count = 1"));
    CHECK_THAT(t.steps[t.steps.size() - 3].narration,
               Catch::Contains("count = 0 + 1 = 1, > 0: P = (0, 0, 0) is in shadow"));
}

TEST_CASE("shadow-volume: the tetrahedron, the exam case, by hand", "[shadows][shadow-volume]") {
    // Base (0, 1, 2) faces down (n = (0, −4, 0)): dark; the three sides are lit
    // (n · (L − a) = 8, 4, 4). The silhouette is the base's loop, run as in the sides.
    const Input in = make(kTetV, kTetF, {0, 6, 0}, {5, 3, 5}, {{0, 0, 0}, {2, 0, 2}});
    const auto r = ShadowVolume::solve(in);
    CHECK(r.lit == std::vector<bool>{false, true, true, true});
    CHECK(r.silhouette == std::vector<std::array<int, 2>>{{1, 0}, {2, 1}, {0, 2}});
    // (0, 0, 0) is inside the floor shadow (the base scaled by 6/5); (2, 0, 2) is not.
    CHECK(r.rays[0].count == 1);
    CHECK(r.rays[0].in_shadow);
    CHECK(r.rays[0].shadow_ray);
    CHECK(r.rays[1].count == 0);
    CHECK_FALSE(r.rays[1].shadow_ray);
    CHECK(cg::run_to_end<ShadowVolume>(ShadowVolume::start(in)) == r);
}

TEST_CASE("shadow-volume: the eye inside the volume starts from its own count",
          "[shadows][shadow-volume]") {
    // Under the box: the eye's segment to the light crosses the lit top once.
    const Input in = make(kCubeV, kCubeF, {0, 6, 0}, {0.5, 0.5, 0.25}, {{4, 0, 1}, {-1, 0, -1}});
    const auto t = cg::test::run_traced<ShadowVolume>(in);
    const auto& r = t.result.rays;
    CHECK(r[0].start == 1);
    CHECK(r[0].crossings == std::vector<int>{-1});  // leaves the volume on the way out
    CHECK(r[0].count == 0);                         // lit; plain z-pass from 0 would say −1
    CHECK_FALSE(r[0].shadow_ray);
    CHECK(r[1].start == 1);
    CHECK(r[1].crossings.empty());
    CHECK(r[1].count == 1);  // in shadow; plain z-pass would say 0, lit
    CHECK(r[1].shadow_ray);
    const auto ev = cg::test::events(t);
    CHECK(std::count(ev.begin(), ev.end(), "eye-in-shadow") == 2);
}

TEST_CASE("shadow-volume: edge-on faces, a miss, rays landing on the occluder",
          "[shadows][shadow-volume]") {
    SECTION("the light in the top face's plane: the top counts as dark") {
        const Input in = make(kCubeV, kCubeF, {4, 3, 0}, {-2, 4, 7}, {{-3, 0, 0}});
        const auto t = cg::test::run_traced<ShadowVolume>(in);
        CHECK_FALSE(t.result.lit[2]);
        CHECK_FALSE(t.result.lit[3]);
        CHECK(t.result.lit[8]);  // the side x = 1 faces the light
        CHECK(t.result.silhouette.size() == 4);
        CHECK_THAT(t.steps[2].narration, Catch::Contains("edge-on"));
        for (const auto& r : t.result.rays) CHECK(r.in_shadow == r.shadow_ray);
    }
    SECTION("a ray into the sky meets nothing") {
        const Input in = make(kCubeV, kCubeF, {0, 6, 0}, {6, 4, 3}, {{5, 5, 2}});
        const auto t = cg::test::run_traced<ShadowVolume>(in);
        CHECK(t.result.rays[0].surface == ShadowVolume::kNone);
        CHECK_FALSE(t.result.rays[0].in_shadow);
        CHECK(cg::test::events(t).back() == "miss");
    }
    SECTION("the lit top: count 0; the dark side: count 1 (the quad passed just before it)") {
        const Input in = make(kCubeV, kCubeF, {0, 6, 0}, {6, 5, 3}, {{0, 3, 0}, {1, 2, 0}});
        const auto r = ShadowVolume::solve(in);
        CHECK(r.rays[0].surface >= 0);
        CHECK(r.rays[0].count == 0);
        CHECK_FALSE(r.rays[0].shadow_ray);
        CHECK(r.rays[0].behind > 0);  // quads behind the top, not counted
        CHECK(r.rays[1].surface >= 0);
        CHECK(r.rays[1].count == 1);
        CHECK(r.rays[1].shadow_ray);
    }
}

TEST_CASE("shadow-volume: bad input names the field", "[shadows][shadow-volume]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto with = [](auto change) {
        Input in = kBox;
        change(in);
        return in;
    };
    CHECK_THROWS_WITH(
        ShadowVolume::start(with([](Input& in) { in.faces.pop_back(); })),
        Catch::Contains("has no neighbouring face") && Catch::Contains("the mesh is not closed"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) { in.faces.pop_back(); })),
                      Catch::StartsWith("occluder.faces[7]: its edge (0, 4)"));
    CHECK_THROWS_WITH(
        ShadowVolume::start(with([](Input& in) { std::swap(in.faces[0][1], in.faces[0][2]); })),
        Catch::StartsWith("occluder.faces[") && Catch::Contains("in the same direction as face"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) {
                          for (auto& f : in.faces) std::swap(f[1], f[2]);
                      })),
                      Catch::StartsWith("occluder.faces: wind clockwise"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) {
                          in.light = {0, 2, 0};
                      })),
                      Catch::StartsWith("light: is inside the occluder"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) {
                          in.light = {0, 3, 0.5};
                      })),
                      Catch::StartsWith("light: lies on face"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) {
                          in.eye = {0.5, 2, 0};
                      })),
                      Catch::StartsWith("eye: is inside the occluder"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) {
                          in.eye = {1, 2, 0};
                      })),
                      Catch::StartsWith("eye: lies on face"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) { in.vertices[6] = in.vertices[5]; })),
                      Catch::Contains("has zero area"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) { in.faces[3][1] = 8; })),
                      Catch::StartsWith("occluder.faces[3][1]: vertex index 8 is out of range"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) { in.faces[3][1] = 4; })),
                      Catch::StartsWith("occluder.faces[3]: repeats a vertex"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([&](Input& in) { in.light.y = nan; })),
                      "light[1]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) {
                          in.vertices[2].x = std::numeric_limits<double>::infinity();
                      })),
                      Catch::StartsWith("occluder.vertices[2][0]: must be a finite number"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) { in.targets[1] = in.eye; })),
                      Catch::StartsWith("targets[1]: equals the eye"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) { in.targets.clear(); })),
                      Catch::StartsWith("targets: must list at least one point"));
    CHECK_THROWS_WITH(ShadowVolume::start(with([](Input& in) { in.eye.z = 1e12; })),
                      Catch::StartsWith("eye[2]: is too large"));
    auto error = [](const std::string& text) { return cg::test::error_of("shadow-volume", text); };
    CHECK_THAT(error(R"({"occluder": {"vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],
                      "faces": [[0,2,1],[0,1,3],[1,2,3],[2,0,3.5]]},
                      "light": [0,5,0], "eye": [3,3,3], "targets": [[0,0,0]]})"),
               Catch::StartsWith("occluder.faces[3][2]: must be a whole vertex index"));
    CHECK_THAT(error(R"({"occluder": {"vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],
                      "faces": [[0,2,1],[0,1,3],[1,2,3],[2,0]]},
                      "light": [0,5,0], "eye": [3,3,3], "targets": [[0,0,0]]})"),
               Catch::StartsWith("occluder.faces[3]: must be a triangle"));
}

TEST_CASE("shadow-volume: 4,000 random scenes against long-double shadow rays",
          "[shadows][shadow-volume]") {
    cg::Rng rng(2121);
    int rays = 0, skipped = 0, shadowed = 0, lit_points = 0, doubles = 0, on_occluder = 0,
        eye_inside = 0, loops = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        CAPTURE(trial);
        bool convex = false;
        const Input in = random_scene(rng, convex);
        try {
            ShadowVolume::validate(in);
        } catch (const cg::InputError& e) {
            // Overlapping shapes (a closed mesh that intersects itself), the eye inside.
            continue;
        }
        const auto r = ShadowVolume::solve(in);
        CHECK(cg::run_to_end<ShadowVolume>(ShadowVolume::start(in)) == r);

        // Lit faces in long double; skip scenes with a face nearly edge-on to the light.
        std::vector<bool> lit(in.faces.size());
        bool edge_on = false;
        for (std::size_t f = 0; f < in.faces.size(); ++f) {
            const V a = lv(in.vertices[in.faces[f][0]]), b = lv(in.vertices[in.faces[f][1]]),
                    c = lv(in.vertices[in.faces[f][2]]);
            const V n = cross(sub(b, a), sub(c, a));
            const V l = sub(lv(in.light), a);
            const LD v = dot(n, l);
            lit[f] = v > 0;
            edge_on = edge_on || std::fabs(v) < 1e-9L * len(n) * len(l);
        }
        if (edge_on) continue;
        CHECK(r.lit == lit);
        // The silhouette: the same edges as the brute force, each run as in its lit face.
        const auto brute = brute_silhouette(in, lit);
        std::set<std::pair<int, int>> got;
        for (const auto& q : r.silhouette) {
            got.insert(std::minmax(q[0], q[1]));
            bool in_lit_face = false;
            for (std::size_t f = 0; f < in.faces.size(); ++f)
                for (int k = 0; k < 3; ++k)
                    in_lit_face = in_lit_face || (lit[f] && in.faces[f][k] == q[0] &&
                                                  in.faces[f][(k + 1) % 3] == q[1]);
            CHECK(in_lit_face);
        }
        CHECK(got == brute);
        CHECK(got.size() == r.silhouette.size());
        if (convex) {  // one closed loop: each vertex once as a start and once as an end
            std::map<int, int> next;
            for (const auto& q : r.silhouette) {
                CHECK(next.count(q[0]) == 0);
                next[q[0]] = q[1];
            }
            int v = r.silhouette.at(0)[0], steps = 0;
            do {
                v = next.at(v);
                ++steps;
            } while (v != r.silhouette[0][0] && steps <= int(next.size()));
            CHECK(steps == int(r.silhouette.size()));
            ++loops;
        }
        if (r.rays[0].start > 0) ++eye_inside;
        for (std::size_t k = 0; k < in.targets.size(); ++k) {
            CAPTURE(k);
            const Reference ref = reference(in, in.targets[k], lit);
            if (ref.grazing) {
                ++skipped;
                continue;
            }
            const auto& ray = r.rays[k];
            REQUIRE(ray.surface == ref.surface);
            if (ray.surface == ShadowVolume::kNone) continue;
            ++rays;
            CHECK(std::fabs(LD(ray.hit.x) - ref.hit.x) <= 1e-9L);
            CHECK(std::fabs(LD(ray.hit.z) - ref.hit.z) <= 1e-9L);
            // The stencil's count is the number of cones around P: the lit faces its shadow
            // ray crosses. So the verdict is the shadow ray's.
            CHECK(ray.count == ref.cones);
            CHECK(ray.in_shadow == ref.blocked);
            CHECK(ray.shadow_ray == ref.blocked);
            ray.in_shadow ? ++shadowed : ++lit_points;
            doubles += ray.count >= 2;
            on_occluder += ray.surface >= 0;
        }
    }
    INFO(rays << " rays, " << skipped << " grazing skipped, " << shadowed << " in shadow, "
              << lit_points << " lit, " << doubles << " count ≥ 2, " << on_occluder
              << " on the occluder, " << eye_inside << " eyes in shadow, " << loops << " loops");
    CHECK(rays > 12000);
    CHECK(skipped < rays / 50);
    CHECK(shadowed > 2000);
    CHECK(lit_points > 4000);
    CHECK(doubles > 20);
    CHECK(on_occluder > 3000);
    CHECK(eye_inside > 50);
    CHECK(loops > 2000);
}

TEST_CASE("shadow-volume: replay on the example and the presets, run-to-end is solve",
          "[shadows][shadow-volume]") {
    const cg::Algorithm& a = cg::test::algorithm("shadow-volume");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    std::set<std::string> seen;
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, cg::test::kEveryStep);
        const Input in = input_of(p.input);
        const auto r = ShadowVolume::solve(in);
        CHECK(cg::run_to_end<ShadowVolume>(ShadowVolume::start(in)) == r);
        for (const auto& ray : r.rays) CHECK(ray.in_shadow == ray.shadow_ray);
        for (const auto& e : cg::test::events(cg::test::run_traced<ShadowVolume>(in)))
            seen.insert(e);
    }
    for (const auto& e : ShadowVolume::spec().events) {
        CAPTURE(e.id);
        CHECK(seen.count(e.id));
    }
    const cg::json r = cg::test::result_of("shadow-volume", a.example());
    CHECK(r["silhouette"] == cg::json::parse("[[6, 5], [5, 4], [4, 7], [7, 6]]"));
    CHECK(r["quads"] == 4);
    CHECK(r["rays"][0]["count"] == 1);
    CHECK(r["rays"][0]["surface"] == "floor");
    CHECK(r["rays"][1]["in_shadow"] == false);
    // Two occluders: the overlap counts 2.
    const cg::json two = cg::test::result_of("shadow-volume", lesson().presets[4].input);
    CHECK(two["rays"][0]["count"] == 2);
    CHECK(two["rays"][1]["count"] == 1);
    CHECK(two["rays"][2]["count"] == 0);
}

TEST_CASE("shadow-volume: exam problems are clear floor cases, half of them in shadow",
          "[shadows][shadow-volume]") {
    const cg::Algorithm& a = cg::test::algorithm("shadow-volume");
    int shadow = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = input_of(p.input);
        const auto r = ShadowVolume::solve(in);
        REQUIRE(r.rays.size() == 1);
        CHECK(r.rays[0].surface == ShadowVolume::kFloor);
        CHECK(r.rays[0].in_shadow == r.rays[0].shadow_ray);
        CHECK(r.silhouette.size() >= 3);
        CHECK(p.answers.size() == 5);
        shadow += r.rays[0].in_shadow;
    }
    CHECK(shadow > 100);
    CHECK(shadow < 200);
}

TEST_CASE("shadow-volume: the picture — occluder, silhouette, quads, the ray's crossings",
          "[shadows][shadow-volume]") {
    auto s = ShadowVolume::start(kBox);
    cg::Scene pic;
    ShadowVolume::draw(s, pic);
    CHECK(pic.has_3d());
    CHECK(pic.faces3.size() == 13);  // the floor and 12 faces
    CHECK(pic.focus3.size() == 1);   // framed on the occluder and the light
    // Each edge step names its verdict on the edge itself: silhouette (orange) or inner (red).
    cg::StepInfo info;
    int silhouette = 0, inner = 0;
    while (!ShadowVolume::done(s)) {
        ShadowVolume::step(s, &info);
        if (s.last != ShadowVolume::Phase::Edge || s.edge < 0) continue;
        cg::Scene edge;
        ShadowVolume::draw(s, edge);
        for (const auto& g : edge.segments3) {
            silhouette += g.label.rfind("silhouette", 0) == 0 && g.style.role == cg::Role::Active;
            inner += g.label.rfind("inner", 0) == 0 && g.style.role == cg::Role::Discarded;
        }
        if (s.phase != ShadowVolume::Phase::Edge) break;
    }
    CHECK(silhouette == 4);
    CHECK(inner > 0);
    // Run to the first crossing of ray 0.
    s = ShadowVolume::start(kBox);
    while (!ShadowVolume::done(s)) {
        ShadowVolume::step(s, &info);
        if (info.event == "enter") break;
    }
    cg::Scene mid;
    ShadowVolume::draw(s, mid);
    CHECK(mid.faces3.size() == 13 + 4);  // + the four quads
    bool plus = false;
    for (const auto& p : mid.points3) plus = plus || p.label == "+1 → 1";
    CHECK(plus);
    int bold = 0;
    for (const auto& g : mid.segments3)
        bold += g.style.role == cg::Role::Kept && g.style.width >= 4;
    CHECK(bold == 4);  // the silhouette
    // Quads reach the floor.
    for (std::size_t k = 13; k < 17; ++k)
        for (const auto& q : mid.faces3[k].points) CHECK(q.y >= 0);
    while (!ShadowVolume::done(s)) ShadowVolume::step(s, nullptr);
    cg::Scene end;
    ShadowVolume::draw(s, end);
    bool ray = false;
    for (const auto& g : end.segments3) ray = ray || g.label == "shadow ray: clear";
    CHECK(ray);
}
