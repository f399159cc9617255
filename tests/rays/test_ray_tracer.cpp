// The recursive ray tracer: hand cases for every branch (hit, miss, shadow, light behind,
// mirror, refraction straight through a ball, total internal reflection, the depth limit, ray
// casting); Snell's law on random rays; random scenes against the independent long-double
// tracer of tracer_reference.hpp; the stepped ray tree bit for bit against the plain tracer;
// the image the same for pixels, rows, one thread and two; the shadow and reflection toggles
// changing exactly the pixels they should; golden images through `cgsandbox render-scene`;
// bad scene files; exam problems; determinism.
#include <stb/stb_image.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"
#include "rays/tracer_reference.hpp"
#include "rays/tracer_support.hpp"
#include "support/process.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"

using cg::RayTracer;
using glm::dvec3;
namespace rt = cg::rt;

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

const cg::Algorithm& tracer() {
    return *registry().find("ray-tracer");
}

// A scene from JSON text (the scene file format), validated.
rt::Scene scene(const std::string& text) {
    return cg::test::scene_of(text);
}

using Tree = cg::test::RayTree;
using cg::test::events;
using cg::test::ray_tree;

std::string error_of(const std::string& text) {
    try {
        tracer().create(cg::parse_json(text));
    } catch (const cg::InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

// A ball of radius 1 at the origin, seen from +z, a light on the axis.
const std::string kBall = R"({
  "camera": {"eye": [0, 0, 5], "center": [0, 0, 0], "size": [8, 6]},
  "background": 0.25, "ambient": 0.2,
  "materials": [{"name": "m", "ka": 0.5, "kd": 0.6, "ks": 0.3, "shininess": 10}],
  "lights": [{"position": [0, 0, 10], "intensity": 1}],
  "objects": [{"type": "sphere", "params": {"r": 1}, "material": "m"}]})";

void check_colour(dvec3 got, dvec3 want, double tol = 1e-12) {
    CAPTURE(got.x, got.y, got.z, want.x, want.y, want.z);
    CHECK(std::fabs(got.x - want.x) <= tol);
    CHECK(std::fabs(got.y - want.y) <= tol);
    CHECK(std::fabs(got.z - want.z) <= tol);
}

// ---- random scenes ---------------------------------------------------------------------

rt::Scene random_scene(std::mt19937_64& rng, bool secondary) {
    std::uniform_real_distribution<double> u(0, 1), c(-1, 1);
    rt::Scene s;
    s.camera.eye = {3 * c(rng), 1 + 2 * u(rng), 6 + 2 * u(rng)};
    s.camera.center = {0.5 * c(rng), 0.3 * c(rng), 0};
    s.camera.fov_y_deg = 35 + 20 * u(rng);
    s.camera.width = 24, s.camera.height = 18;
    s.settings.model = u(rng) < 0.5 ? rt::Model::Phong : rt::Model::BlinnPhong;
    s.settings.max_depth = secondary ? 1 + static_cast<int>(3 * u(rng)) : 0;
    s.background = {0.1 * u(rng), 0.1 * u(rng), 0.2 * u(rng)};
    s.ambient = dvec3(0.1 + 0.1 * u(rng));
    const int materials = 3;
    for (int k = 0; k < materials; ++k) {
        rt::Material m;
        m.name = "m" + std::to_string(k);
        m.ka = m.kd = {u(rng), u(rng), u(rng)};
        m.ks = dvec3(0.5 * u(rng));
        m.shininess = 1 + 60 * u(rng);
        if (secondary && k == 1) m.kr = dvec3(0.3 + 0.5 * u(rng));
        if (secondary && k == 2) m.kt = dvec3(0.5 + 0.4 * u(rng)), m.ior = 1.2 + 0.6 * u(rng);
        s.materials.push_back(m);
    }
    const int lights = 1 + static_cast<int>(2 * u(rng));
    for (int k = 0; k < lights; ++k) {
        rt::Light l;
        if (u(rng) < 0.3) {
            l.directional = true;
            l.direction = {c(rng), -1 - u(rng), c(rng)};
        } else {
            l.position = {4 * c(rng), 3 + 3 * u(rng), 4 * c(rng)};
            if (u(rng) < 0.5) l.attenuation = {1, 0.05 * u(rng), 0.01 * u(rng)};
        }
        l.intensity = dvec3(0.5 + 0.5 * u(rng));
        s.lights.push_back(l);
    }
    const int objects = 3 + static_cast<int>(4 * u(rng));
    for (int k = 0; k < objects; ++k) {
        rt::Object o;
        o.name = o.field = "objects[" + std::to_string(k) + "]";
        o.material = static_cast<int>(materials * u(rng)) % materials;
        const double pick = u(rng);
        if (k == 0) {  // a floor
            o.kind = rt::ObjectKind::Plane;
            o.p0 = {0, -1 - u(rng), 0};
            o.normal = {0.1 * c(rng), 1, 0.1 * c(rng)};
        } else if (pick < 0.6) {
            o.kind = rt::ObjectKind::Quadric;
            o.quadric.kind = u(rng) < 0.6 ? cg::QuadricKind::Sphere : cg::QuadricKind::Ellipsoid;
            o.quadric.r = 0.4 + 0.6 * u(rng);
            o.quadric.a = 0.4 + 0.6 * u(rng), o.quadric.b = 0.4 + 0.6 * u(rng),
            o.quadric.c = 0.4 + 0.6 * u(rng);
            glm::dmat4 m(1.0);
            m[0][1] = 0.3 * c(rng), m[1][0] = 0.3 * c(rng), m[2][1] = 0.3 * c(rng);
            m[3] = glm::dvec4(2.5 * c(rng), 1.2 * c(rng), 2 * c(rng), 1);
            o.quadric.world_from_model = m;
        } else if (pick < 0.75) {
            o.kind = rt::ObjectKind::Quadric;
            o.quadric.kind = cg::QuadricKind::Cylinder;
            o.quadric.p = 0.3 + 0.3 * u(rng), o.quadric.q = 0.3 + 0.3 * u(rng);
            o.quadric.zmin = -1, o.quadric.zmax = 0.5 + u(rng);
            glm::dmat4 m(1.0);  // standing up: model z → world y
            m[1] = glm::dvec4(0, 0, -1, 0), m[2] = glm::dvec4(0, 1, 0, 0);
            m[3] = glm::dvec4(2.5 * c(rng), 0, 2 * c(rng), 1);
            o.quadric.world_from_model = m;
        } else {
            o.kind = rt::ObjectKind::Triangle;
            const dvec3 at(2 * c(rng), 0.5 * c(rng), 2 * c(rng));
            o.p0 = at + dvec3(c(rng), c(rng), c(rng));
            o.p1 = at + dvec3(c(rng), c(rng), c(rng));
            o.p2 = at + dvec3(c(rng), c(rng), c(rng));
        }
        s.objects.push_back(o);
    }
    rt::validate(s);
    return s;
}

}  // namespace

// ---- hand cases -------------------------------------------------------------------------------

TEST_CASE("ray-tracer: a ray straight down onto a ball, worked by hand", "[rays][ray-tracer]") {
    const rt::Scene s = scene(kBall);
    const Tree t = ray_tree(s, {0, 0, 5}, {0, 0, -1});
    // t = 4, P = (0, 0, 1), n = l = v = (0, 0, 1): ambient 0.5·0.2, diffuse 0.6, specular 0.3.
    CHECK(events(t) == std::vector<std::string>{"primary", "hit", "lit", "colour"});
    const auto& root = t.result.tree[0];
    CHECK(root.hit.t == Approx(4).epsilon(1e-15));
    CHECK(root.hit.point.z == Approx(1));
    CHECK(root.hit.normal == dvec3(0, 0, 1));
    check_colour(t.result.color, dvec3(0.1 + 0.6 + 0.3));
    CHECK(t.result.rays.primary == 1);
    CHECK(t.result.rays.shadow == 1);

    // The same through the JSON layer (the exam's answer fields).
    auto run = tracer().create(cg::parse_json(std::string(kBall).insert(
        kBall.size() - 1,
        R"(, "stepping": {"granularity": "ray-tree", "ray": {"origin": [0, 0, 5], "direction": [0, 0, -2]}})")));
    while (!run->done()) run->step(nullptr);
    const cg::json r = tracer().result(*run);
    CHECK(r["hit"] == true);
    CHECK(r["t"].get<double>() == Approx(2));  // in units of the given direction
    CHECK(r["shadowed"] == cg::json::array({false}));
    CHECK(r["reflected"].is_null());
    CHECK(r["color"][0].get<double>() == Approx(1.0));
    CHECK(r["rgb8"] == cg::json::array({255, 255, 255}));
}

TEST_CASE("ray-tracer: misses, shadows and lights behind the surface", "[rays][ray-tracer]") {
    const rt::Scene ball = scene(kBall);
    SECTION("a miss returns the background") {
        const Tree t = ray_tree(ball, {3, 0, 5}, {0, 0, -1});
        CHECK(events(t) == std::vector<std::string>{"primary", "miss", "colour"});
        check_colour(t.result.color, dvec3(0.25));
    }
    SECTION("a ball between the point and the light casts a shadow") {
        rt::Scene s = ball;
        rt::Object blocker = s.objects[0];
        blocker.quadric.r = 0.5;
        blocker.quadric.world_from_model[3] = glm::dvec4(0, 0, 3, 1);
        s.objects.push_back(blocker);
        const Tree t = ray_tree(s, {0, 0.2, 2.0}, {0, 0, -1});  // starts below the blocker
        // Two balls: the hierarchy over them is built first (one step).
        CHECK(events(t) ==
              std::vector<std::string>{"build", "primary", "hit", "shadowed", "colour"});
        check_colour(t.result.color, dvec3(0.1));  // ambient only
        CHECK(t.result.tree[1].blocker == 1);
        // Without shadow rays the light counts again.
        s.settings.shadows = false;
        const Tree off = ray_tree(s, {0, 0.2, 2.0}, {0, 0, -1});
        CHECK(events(off) == std::vector<std::string>{"build", "primary", "hit", "lit", "colour"});
        CHECK(off.result.rays.shadow == 0);
        CHECK(off.result.color.x > 0.5);
    }
    SECTION("a light behind the surface casts no shadow ray and adds nothing") {
        rt::Scene s = ball;
        s.lights[0].position = {0, 0, -10};
        const Tree t = ray_tree(s, {0, 0, 5}, {0, 0, -1});
        CHECK(events(t) == std::vector<std::string>{"primary", "hit", "light-behind", "colour"});
        CHECK(t.result.rays.shadow == 0);
        check_colour(t.result.color, dvec3(0.1));
    }
    SECTION("a directional light is not attenuated") {
        rt::Scene s = ball;
        s.lights[0] = rt::Light{};
        s.lights[0].directional = true;
        s.lights[0].direction = {0, 0, -3};
        const Tree t = ray_tree(s, {0, 0, 5}, {0, 0, -1});
        check_colour(t.result.color, dvec3(1.0));
    }
}

TEST_CASE("ray-tracer: a mirror, the depth limit and ray casting", "[rays][ray-tracer]") {
    // A mirror floor y = 0 (it has no colour of its own) under a red ball; the eye ray hits the
    // floor at 45° and its mirror ray rises into the ball.
    const std::string text = R"({
      "camera": {"eye": [0, 1, 4], "center": [0, 0, 0], "size": [8, 6]},
      "background": 0.3, "ambient": 1,
      "materials": [{"name": "mirror", "ka": 0, "kd": 0, "ks": 0, "kr": 0.5},
                    {"name": "red", "ka": [1, 0, 0], "kd": 0, "ks": 0}],
      "lights": [],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "mirror"},
                  {"type": "sphere", "params": {"r": 1}, "material": "red",
                   "transform": [[1, 0, 0, 0], [0, 1, 0, 3], [0, 0, 1, -4], [0, 0, 0, 1]]}]})";
    const rt::Scene s = scene(text);
    const Tree t = ray_tree(s, {0, 1, 0}, {0, -1, -1});  // hits the floor at (0, 0, −1)
    CHECK(events(t) ==
          std::vector<std::string>{"primary", "hit", "reflect", "hit", "return", "colour"});
    // r = d − 2(d·n)n = (0, 1, −1)/√2, from (0, 0, −1) straight at the ball's centre (0, 3, −4).
    const auto& mirror = t.result.tree[1];
    CHECK(mirror.kind == RayTracer::RayKind::Reflected);
    CHECK(mirror.direction.x == Approx(0).margin(1e-15));
    CHECK(mirror.direction.y == Approx(std::sqrt(0.5)));
    CHECK(mirror.direction.z == Approx(-std::sqrt(0.5)));
    CHECK(mirror.hit.point.y == Approx(3 - std::sqrt(0.5)));
    CHECK(mirror.hit.object == 1);
    check_colour(t.result.color, dvec3(0.5, 0, 0));  // k_r × the red ball's ambient

    SECTION("depth 0: ray casting, no secondary rays") {
        rt::Scene c = s;
        c.settings.max_depth = 0;
        const Tree ct = ray_tree(c, {0, 1, 0}, {0, -1, -1});
        CHECK(events(ct) == std::vector<std::string>{"primary", "hit", "depth-limit", "colour"});
        check_colour(ct.result.color, dvec3(0.0));
    }
    SECTION("reflections off") {
        rt::Scene c = s;
        c.settings.reflections = false;
        const Tree ct = ray_tree(c, {0, 1, 0}, {0, -1, -1});
        CHECK(events(ct) == std::vector<std::string>{"primary", "hit", "colour"});
    }
    SECTION("the ray_casting setting") {
        auto j = cg::parse_json(text);
        j["settings"] = {{"ray_casting", true}};
        const rt::Scene c = rt::scene_from_json(j);
        CHECK(c.settings.max_depth == 0);
        CHECK_FALSE(c.settings.shadows);
        j["settings"] = {{"ray_casting", true}, {"shadows", true}};
        CHECK_THROWS_WITH(
            rt::scene_from_json(j),
            Catch::StartsWith("settings.ray_casting: ray casting casts no secondary rays"));
    }
}

TEST_CASE("ray-tracer: refraction through a glass ball and total internal reflection",
          "[rays][ray-tracer]") {
    const std::string text = R"({
      "camera": {"eye": [0, 0, 5], "center": [0, 0, 0], "size": [8, 6]},
      "background": [0, 0, 1], "ambient": 0,
      "materials": [{"name": "glass", "ka": 0, "kd": 0, "ks": 0, "kt": 1, "ior": 1.5}],
      "lights": [],
      "objects": [{"type": "sphere", "params": {"r": 1}, "material": "glass"}]})";
    rt::Scene s = scene(text);
    SECTION("through the centre the ray is not bent, in and out") {
        const Tree t = ray_tree(s, {0, 0, 5}, {0, 0, -1});
        CHECK(events(t) == std::vector<std::string>{"primary", "hit", "refract", "hit", "refract",
                                                    "miss", "return", "return", "colour"});
        const auto& inside = t.result.tree[1];
        CHECK(inside.kind == RayTracer::RayKind::Refracted);
        CHECK(inside.direction.z == Approx(-1));
        CHECK(t.result.tree[1].hit.entering == false);  // it meets the far side from inside
        CHECK(t.result.tree[1].hit.point.z == Approx(-1));
        check_colour(t.result.color, dvec3(0, 0, 1));
    }
    SECTION("off-centre: Snell's law at both surfaces") {
        const Tree t = ray_tree(s, {0.5, 0, 5}, {0, 0, -1});
        const auto& root = t.result.tree[0];
        const auto& in = t.result.tree[1];
        REQUIRE(in.kind == RayTracer::RayKind::Refracted);
        const double sin1 = glm::length(glm::cross(dvec3(0, 0, -1), root.hit.normal));
        const double sin2 = glm::length(glm::cross(in.direction, root.hit.normal));
        CHECK(sin1 == Approx(1.5 * sin2).epsilon(1e-12));
        CHECK(sin1 == Approx(0.5));
    }
    SECTION("from inside at a grazing angle: total internal reflection") {
        // Inside the ball, a ray meeting the surface at sin θ₁ = 0.9 > 1/1.5.
        const Tree t = ray_tree(s, {0.9, -0.2, 0}, {0, 1, 0});
        REQUIRE(events(t).size() >= 3);
        CHECK(events(t)[2] == "total-internal-reflection");
        CHECK(t.result.tree[1].total_internal);
        CHECK(t.result.tree[1].kind == RayTracer::RayKind::Reflected);
    }
}

TEST_CASE("ray-tracer: Snell's law and the mirror law on 10,000 random rays",
          "[rays][ray-tracer]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> c(-1, 1), eta_d(0.3, 2.5);
    int tir = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        CAPTURE(trial);
        const dvec3 n = cg::unit({c(rng), c(rng), c(rng)});
        dvec3 d = cg::unit({c(rng), c(rng), c(rng)});
        if (glm::dot(d, n) > 0) d = -d;  // n faces −d
        if (glm::dot(d, n) > -1e-6) continue;
        const double eta = eta_d(rng);
        const dvec3 r = rt::reflect(d, n);
        CHECK(glm::dot(r, n) == Approx(-glm::dot(d, n)).margin(1e-14));
        CHECK(glm::length(glm::cross(d, n) - glm::cross(r, n)) <
              1e-12);  // the tangential part kept
        dvec3 t;
        const double sin1 = glm::length(glm::cross(d, n));
        const bool ok = rt::refract(d, n, eta, t);
        // Total internal reflection exactly when η sin θ₁ > 1.
        if (std::fabs(eta * sin1 - 1) > 1e-12) CHECK(ok == (eta * sin1 < 1));
        if (!ok) {
            ++tir;
            continue;
        }
        const double sin2 = glm::length(glm::cross(t, n));
        CHECK(sin2 == Approx(eta * sin1).margin(1e-12));  // η₁ sin θ₁ = η₂ sin θ₂ with η = η₁/η₂
        CHECK(glm::dot(t, n) < 0);                        // it goes through
        CHECK(std::fabs(glm::dot(glm::cross(d, n), t)) < 1e-12);  // in the plane of d and n
        CHECK(glm::length(t) == Approx(1).epsilon(1e-14));
    }
    CHECK(tir > 500);
}

// ---- against the independent tracer -----------------------------------------------------------

TEST_CASE("ray-tracer: random scenes agree with an independent long-double tracer",
          "[rays][ray-tracer][reference]") {
    int compared = 0, skipped = 0;
    for (int trial = 0; trial < 60; ++trial) {
        std::mt19937_64 rng(1000 + trial);
        const bool secondary = trial % 3 != 0;
        const rt::Scene s = random_scene(rng, secondary);
        const rt::Prepared p = rt::prepare(s);
        cg::test::ReferenceTracer ref(s);
        for (int j = 0; j < s.camera.height; ++j)
            for (int i = 0; i < s.camera.width; ++i) {
                CAPTURE(trial, i, j);
                ref.min_margin = INFINITY;
                const cg::test::L3 want = ref.pixel(i, j);
                rt::RayCounts counts;
                const rt::Color got = rt::pixel_color(s, p, i, j, counts);
                // A ray within round-off of a tie (an edge, a shadow's boundary) may go either way.
                if (ref.min_margin < 1e-7) {
                    ++skipped;
                    continue;
                }
                ++compared;
                for (int k = 0; k < 3; ++k) {
                    CAPTURE(k, got[k], double(want[k]));
                    CHECK(std::fabs(got[k] - double(want[k])) <=
                          1e-9 * std::max(1.0, double(want[k])));
                }
            }
    }
    CAPTURE(compared, skipped);
    CHECK(compared > 20000);
    CHECK(skipped < compared / 100);
}

TEST_CASE("ray-tracer: primary hits agree with the long-double intersections",
          "[rays][ray-tracer][reference]") {
    int hits = 0;
    for (int trial = 0; trial < 40; ++trial) {
        std::mt19937_64 rng(5000 + trial);
        const rt::Scene s = random_scene(rng, false);
        const rt::Prepared p = rt::prepare(s);
        cg::test::ReferenceTracer ref(s);
        std::uniform_real_distribution<double> u(0, 1);
        for (int k = 0; k < 250; ++k) {
            const dvec3 P =
                rt::screen_point(p.view, u(rng) * s.camera.width, u(rng) * s.camera.height);
            const dvec3 d = P - p.view.eye;
            const rt::Hit h = rt::nearest_hit(p, p.view.eye, d);
            const cg::test::RefHit r =
                ref.nearest(cg::test::l3(p.view.eye), cg::test::l3(d), 1e-9L, INFINITY);
            CAPTURE(trial, k);
            if (r.object >= 0 && (r.second - r.t) < 1e-9 * r.t) continue;  // a tie
            REQUIRE(h.object == r.object);
            if (h.object < 0) continue;
            ++hits;
            CHECK(h.t == Approx(double(r.t)).epsilon(1e-9));
            CHECK(h.entering == r.entering);
            for (int c = 0; c < 3; ++c) {
                CHECK(h.point[c] == Approx(double(r.point[c])).epsilon(1e-9).margin(1e-9));
                CHECK(h.normal[c] == Approx(double(r.normal[c])).margin(1e-9));
            }
        }
    }
    CHECK(hits > 4000);
}

// ---- the state machine against the plain tracer -------------------------------------------

TEST_CASE("ray-tracer: the stepped ray tree gives the plain tracer's colour, bit for bit",
          "[rays][ray-tracer]") {
    std::set<std::string> events;
    for (int trial = 0; trial < 200; ++trial) {
        std::mt19937_64 rng(9000 + trial);
        const rt::Scene s = random_scene(rng, true);
        const rt::Prepared p = rt::prepare(s);
        std::uniform_int_distribution<int> pi(0, s.camera.width - 1), pj(0, s.camera.height - 1);
        for (int k = 0; k < 5; ++k) {
            const int i = pi(rng), j = pj(rng);
            CAPTURE(trial, i, j);
            const cg::test::RayTree t = cg::test::pixel_tree(s, {i + 0.25, j + 0.75});
            for (const cg::StepInfo& info : t.steps) events.insert(info.event);
            const RayTracer::Result& r = t.result;
            rt::RayCounts counts;
            const rt::Color want = rt::pixel_color(s, p, i, j, counts);
            CHECK(r.pixel_i == i);
            CHECK(r.pixel_j == j);
            CHECK(r.color == want);  // exactly
            CHECK(r.rays == counts);
            // Every secondary ray's colour was summed into its parent with its weight.
            for (const auto& n : r.tree)
                if (n.kind != RayTracer::RayKind::Shadow) CHECK(n.returned);
        }
    }
    for (const char* e :
         {"primary", "hit", "miss", "lit", "shadowed", "light-behind", "reflect", "refract",
          "total-internal-reflection", "depth-limit", "return", "colour"}) {
        CAPTURE(e);
        CHECK(events.count(e) == 1);
    }
}

TEST_CASE("ray-tracer: pixels, rows, one thread and two give the same image",
          "[rays][ray-tracer]") {
    for (int trial = 0; trial < 12; ++trial) {
        std::mt19937_64 rng(300 + trial);
        const rt::Scene s = random_scene(rng, true);
        const rt::Image one = rt::render(s, 1), two = rt::render(s, 2), three = rt::render(s, 3);
        CHECK(one == two);
        CHECK(one == three);
        for (auto g : {RayTracer::Granularity::Pixels, RayTracer::Granularity::Rows}) {
            RayTracer::Input in;
            in.scene = s;
            in.granularity = g;
            auto st = RayTracer::start(in);
            std::size_t steps = 0, builds = 0;
            while (!RayTracer::done(st)) {
                cg::StepInfo info;
                RayTracer::step(st, &info);
                ++steps;
                builds += info.event == "build";
            }
            const RayTracer::Result r = RayTracer::result(st);
            CHECK(r.image == one.rgba);
            CHECK(r.rays == one.rays);
            // One step a pixel (or row), after the hierarchy's build when it has one.
            CHECK(builds == (rt::prepare(s).bvh.nodes.empty() ? 0u : 1u));
            CHECK(steps == builds + (g == RayTracer::Granularity::Rows
                                         ? std::size_t(s.camera.height)
                                         : std::size_t(s.camera.width) * s.camera.height));
        }
    }
}

TEST_CASE("ray-tracer: the shadow and reflection toggles change exactly the pixels they should",
          "[rays][ray-tracer]") {
    const rt::Scene base = rt::scene_from_json(tracer().example(), {"stepping"});
    const int W = base.camera.width, H = base.camera.height;
    const rt::Prepared prepared = rt::prepare(base);
    // Per pixel, what its ray tree holds (stepped with everything on).
    std::vector<bool> blocked(W * H), mirrored(W * H);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const dvec3 P = rt::screen_point(prepared.view, i + 0.5, j + 0.5);
            const Tree t = ray_tree(base, prepared.view.eye, P - prepared.view.eye);
            for (const auto& n : t.result.tree) {
                if (n.kind == RayTracer::RayKind::Shadow && n.blocker >= 0)
                    blocked[j * W + i] = true;
                if (n.kind == RayTracer::RayKind::Reflected) mirrored[j * W + i] = true;
            }
        }
    const rt::Image on = rt::render(base, 2);
    auto changed = [&](const rt::Image& other) {
        std::vector<bool> c(W * H);
        for (int k = 0; k < W * H; ++k) c[k] = other.rgba[k] != on.rgba[k];
        return c;
    };
    rt::Scene no_shadows = base;
    no_shadows.settings.shadows = false;
    const std::vector<bool> by_shadows = changed(rt::render(no_shadows, 2));
    rt::Scene no_mirrors = base;
    no_mirrors.settings.reflections = false;
    const std::vector<bool> by_mirrors = changed(rt::render(no_mirrors, 2));
    int shadow_pixels = 0, mirror_pixels = 0, unchanged_blocked = 0;
    for (int k = 0; k < W * H; ++k) {
        CAPTURE(k % W, k / W);
        // Only a pixel with a blocked shadow ray somewhere in its tree may change, and only a
        // pixel whose tree has a mirror ray may change when mirrors are off.
        if (by_shadows[k]) CHECK(blocked[k]);
        if (by_mirrors[k]) CHECK(mirrored[k]);
        shadow_pixels += by_shadows[k];
        mirror_pixels += by_mirrors[k];
        unchanged_blocked += blocked[k] && !by_shadows[k];
    }
    // And the effects are real: the shadows and the reflections cover many pixels.
    CHECK(shadow_pixels > W * H / 20);
    CHECK(mirror_pixels > W * H / 10);
    CAPTURE(unchanged_blocked);
    CHECK(unchanged_blocked <
          shadow_pixels / 4);  // a blocked weak light may round to the same byte
}

// ---- golden images through the CLI ------------------------------------------------------------

namespace {

struct Png {
    int w = 0, h = 0;
    std::vector<unsigned char> rgba;
};

Png load_png(const std::string& path) {
    Png p;
    int n = 0;
    unsigned char* data = stbi_load(path.c_str(), &p.w, &p.h, &n, 4);
    REQUIRE(data != nullptr);
    p.rgba.assign(data, data + static_cast<std::size_t>(p.w) * p.h * 4);
    stbi_image_free(data);
    return p;
}

}  // namespace

TEST_CASE("ray-tracer: render-scene matches the golden images", "[rays][ray-tracer][golden]") {
    const std::string dir = std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/";
    for (const char* name :
         {"reference", "no-shadows", "ray-casting", "glass", "mesh",
          // distribution ray tracing (test_rt_distribution.cpp)
          "aa-edge-1", "aa-edge-16", "soft-shadows", "depth-of-field", "motion-blur"}) {
        CAPTURE(name);
        const std::string out = cg::test::output_path(std::string("golden-") + name + ".png");
        auto r = cg::test::cgsandbox({"render-scene", dir + name + ".json", "--out", out});
        CAPTURE(r.out, r.err);
        REQUIRE(r.exit_code == 0);
        CHECK_THAT(r.out, Catch::Contains("rays"));
        const Png got = load_png(out), want = load_png(dir + name + ".png");
        REQUIRE(got.w == want.w);
        REQUIRE(got.h == want.h);
        // Within 2 levels per channel everywhere but a few edge pixels (round-off may move an
        // edge by a pixel between compilers).
        int off = 0;
        for (std::size_t k = 0; k < got.rgba.size(); ++k)
            if (std::abs(int(got.rgba[k]) - int(want.rgba[k])) > 2) ++off;
        CHECK(off <= static_cast<int>(got.rgba.size() / 4 / 500));
    }
}

TEST_CASE("ray-tracer: render-scene refuses bad scenes and sizes with one clear line",
          "[rays][ray-tracer][errors]") {
    const std::string good = cg::test::write_temp("scene.json", kBall);
    const std::string out = cg::test::output_path("bad.png");
    auto r = cg::test::cgsandbox({"render-scene", good, "--out", out, "--size", "100000x100000"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::StartsWith("cgsandbox: --size must be WxH"));
    r = cg::test::cgsandbox({"render-scene", good, "--out", out, "--size", "32x24"});
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("32×24"));
    const std::string huge = cg::test::write_temp(
        "huge.json", std::string(kBall).replace(kBall.find("[8, 6]"), 6, "[40000, 25000]"));
    r = cg::test::cgsandbox({"render-scene", huge, "--out", out});
    CHECK(r.exit_code == 2);
    CHECK(r.err ==
          "cgsandbox: " + huge +
              ": camera.size: has 1000000000 pixels; the limit is 4096 × 4096 = 16777216\n");
    r = cg::test::cgsandbox(
        {"render-scene", cg::test::write_temp("broken.json", "{\"camera\": "), "--out", out});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("not valid JSON"));
    r = cg::test::cgsandbox({"render-scene", good, "--out", "/nonexistent/dir/x.png"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("cannot write the PNG file"));
}

TEST_CASE("ray-tracer: bad scenes are refused with the field named", "[rays][ray-tracer][errors]") {
    auto with = [](const std::string& from, const std::string& to) {
        std::string t = kBall;
        const auto at = t.find(from);
        REQUIRE(at != std::string::npos);
        return error_of(t.replace(at, from.size(), to));
    };
    CHECK(with(R"("center": [0, 0, 0])", R"("center": [0, 0, 5])") ==
          "camera.center: must not be the zero vector: it is center − eye, the direction the "
          "camera looks in");
    CHECK_THAT(with(R"("center": [0, 0, 0])", R"("center": [0, 0, 0], "up": [0, 0, 2])"),
               Catch::StartsWith("camera.up: must not be parallel to the view direction"));
    CHECK_THAT(with(R"("size": [8, 6])", R"("size": [8, 6], "fov_y_deg": 180)"),
               Catch::StartsWith("camera.fov_y_deg: must be a field of view between"));
    CHECK(with(R"("size": [8, 6])", R"("size": [8.5, 6])") ==
          "camera.size[0]: must be an integer number of pixels, got 8.5");
    CHECK_THAT(with(R"("size": [8, 6])", R"("size": [8, 6, 1])"),
               Catch::StartsWith("camera.size: must be [width, height] in whole pixels"));
    CHECK_THAT(with(R"("size": [8, 6])", R"("size": [0, 6])"),
               Catch::StartsWith("camera.size: must be at least 1×1"));
    CHECK(with(R"("material": "m")", R"("material": "gold")") ==
          "objects[0].material: no material \"gold\" (materials: m)");
    CHECK_THAT(with(R"("type": "sphere")", R"("type": "torus")"),
               Catch::StartsWith("objects[0].type: must be one of sphere, ellipsoid, paraboloid, "
                                 "hyperboloid, cone, cylinder, plane, triangle, mesh"));
    CHECK(with(R"("params": {"r": 1})", R"("params": {"r": 0})") ==
          "objects[0].params.r: must be positive: it is a semi-axis length (got 0)");
    CHECK_THAT(
        with(R"("intensity": 1)", R"("intensity": -1)"),
        Catch::StartsWith("lights[0].intensity: must be a colour with components in [0, 1e6]"));
    CHECK(with(R"("intensity": 1)", R"("intensity": 1, "attenuation": [0, 0, 0])") ==
          "lights[0].attenuation: must not be all zero: 1/(c1 + c2 r + c3 r²) would be infinite");
    CHECK(with(R"("position": [0, 0, 10])", R"("position": [0, 0, 10], "direction": [0, 0, -1])") ==
          "lights[0]: needs exactly one of \"position\" (a point light) and \"direction\" (a "
          "directional light)");
    CHECK_THAT(with(R"("shininess": 10)", R"("shininess": 10, "ior": 0)"),
               Catch::StartsWith("materials[0].ior: must be a refraction index"));
    CHECK_THAT(with(R"("shininess": 10)", R"("shininess": 10, "kt": "clear")"),
               Catch::StartsWith("materials[0].kt: must be a number or a colour [r, g, b]"));
    CHECK(with(R"("objects": [)", R"("settings": {"max_depth": 1000000}, "objects": [)") ==
          "settings.max_depth: must be between 0 and 16 (got 1000000)");
    CHECK(
        with(
            R"({"type": "sphere", "params": {"r": 1}, "material": "m"})",
            R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "material": "m"})") ==
        "objects[0].vertices: is degenerate: its corners (0, 0, 0), (1, 1, 1), (2, 2, 2) are "
        "collinear or "
        "coincide (zero area)");
    CHECK(
        with(
            R"({"type": "sphere", "params": {"r": 1}, "material": "m"})",
            R"({"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 3]], "material": "m"})") ==
        "objects[0].triangles[0][2]: must be a vertex index from 0 to 2, got 3");
    CHECK(with(R"({"type": "sphere", "params": {"r": 1}, "material": "m"})",
               R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0], "material": "m"})") ==
          "objects[0].normal: must not be the zero vector: it is the plane's normal");
    CHECK(with(R"("objects": [)",
               R"("stepping": {"granularity": "ray-tree", "pixel": [8, 0]}, "objects": [)") ==
          "stepping.pixel: must lie on the 8×6 screen: 0 ≤ x < width, 0 ≤ y < height (got (8, 0))");
    CHECK(
        with(
            R"("objects": [)",
            R"("stepping": {"granularity": "ray-tree", "ray": {"origin": [0, 0, 5], "direction": [0, 0, 0]}}, "objects": [)") ==
        "stepping.ray.direction: must not be the zero vector: a ray needs a direction");
    CHECK(with(R"("objects": [)", R"("stepping": {"pixel": [1, 1]}, "objects": [)") ==
          "stepping.pixel: is for \"granularity\": \"ray-tree\" (one pixel's ray tree)");
    CHECK_THAT(with(R"("objects": [)", R"("camrea": {}, "objects": [)"),
               Catch::StartsWith("camrea: is not a field of a scene"));
    // Materials with one name, and an empty list.
    CHECK(with(R"([{"name": "m", "ka")", R"([{"name": "m"}, {"name": "m", "ka")") ==
          "materials[1].name: \"m\" names two materials");
}

TEST_CASE("ray-tracer: scenes too big to run are refused with their limit",
          "[rays][ray-tracer][limits]") {
    std::string many =
        R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0]}, "materials": [{"name": "m"}],
                          "objects": [{"type": "mesh", "material": "m", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                          "triangles": [)";
    for (int k = 0; k < 20001; ++k) many += std::string(k ? "," : "") + "[0, 1, 2]";
    many += "]}]}";
    // 20,001 copies of one triangle: every ray meeting it tests them all, and the mesh's
    // hierarchy says so (its expected cost is about 20,001 tests, over the 20,000 per ray).
    CHECK_THAT(error_of(many),
               Catch::StartsWith("objects: costs 2") &&
                   Catch::Contains("ray-object tests per ray (triangles and CSG leaves counted one "
                                   "by one, a mesh as its hierarchy's expected cost); the limit "
                                   "is 20000"));

    // Costs: a full binary ray tree 16 deep (mirror and glass) with 200 objects and 3 lights
    // could cast 2^17 − 1 rays per pixel, each tested against everything.
    rt::Scene deep = scene(kBall);
    deep.settings.max_depth = 16;
    deep.materials[0].kr = dvec3(0.5);
    deep.materials[0].kt = dvec3(0.5);
    deep.lights.resize(3, deep.lights[0]);
    deep.objects.resize(200, deep.objects[0]);
    CHECK_THROWS_WITH(
        rt::validate(deep),
        Catch::StartsWith("settings.max_depth: makes one pixel cost up to 104856800 "
                          "ray-object tests (131071 rays per tree × 4 for the lights × "
                          "200 objects); the limit is 1e7"));
    deep.settings.max_depth = 3;  // 15 rays per tree: fine per pixel, but 4096² pixels are not
    rt::validate(deep);
    deep.camera.width = deep.camera.height = 4096;
    CHECK_THROWS_WITH(
        rt::validate(deep),
        Catch::StartsWith("camera.size: makes the image cost up to 201326592000 ray-object "
                          "tests (4096×4096 pixels × 12000 per pixel); the limit is 2e10"));
    // Only mirrors: a chain, max_depth + 1 rays.
    deep.materials[0].kt = dvec3(0.0);
    CHECK(rt::tree_rays(deep) == 4);
    deep.settings.reflections = false;
    CHECK(rt::tree_rays(deep) == 1);
}

// ---- exams, determinism, the picture ---------------------------------------------------------

TEST_CASE("ray-tracer: exam problems are answered right", "[rays][ray-tracer][exam]") {
    const cg::Algorithm& a = tracer();
    int shadowed = 0, mirrors = 0, distributed = 0;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        if (p.input["stepping"].contains("pixel")) {  // the distribution question: checked below
            ++distributed;
            continue;
        }
        CHECK_THAT(p.question, Catch::Contains("Trace the eye ray"));
        CHECK(p.answers ==
              std::vector<std::string>{"t", "point", "normal", "shadowed", "reflected", "color"});
        // The expected answers against the independent tracer, by hand-free means.
        const rt::Scene sc = rt::scene_from_json(p.input, {"stepping"});
        const cg::json& ray = p.input["stepping"]["ray"];
        const dvec3 E(ray["origin"][0].get<double>(), ray["origin"][1].get<double>(),
                      ray["origin"][2].get<double>());
        const dvec3 d(ray["direction"][0].get<double>(), ray["direction"][1].get<double>(),
                      ray["direction"][2].get<double>());
        cg::test::ReferenceTracer ref(sc);
        const cg::test::L3 want = ref.trace(cg::test::l3(E), cg::test::l3(d), 0);
        for (int k = 0; k < 3; ++k)
            CHECK(p.expected["color"][k].get<double>() == Approx(double(want[k])).epsilon(1e-12));
        // The numbers are short decimals a student can reach.
        for (int k = 0; k < 3; ++k) {
            const double n = p.expected["normal"][k].get<double>();
            CHECK(std::fabs(n * 100 - std::round(n * 100)) < 1e-9);
        }
        shadowed += p.expected["shadowed"][0].get<bool>();
        mirrors += !p.expected["reflected"].is_null();
        // Grading accepts the expected answers.
        for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
    }
    CHECK(shadowed > 5);
    CHECK(mirrors > 5);
    CHECK(distributed > 10);  // three in ten
}

// The course's table, read off the input file (not from the tracer's own rt::distribution), and
// the ray tree must show each effect's rays really spread over that quantity.
TEST_CASE("ray-tracer: distribution exam problems — what each effect's rays are spread over",
          "[rays][ray-tracer][exam][distribution]") {
    const cg::Algorithm& a = tracer();
    std::map<std::string, int> seen;
    for (std::uint64_t seed = 1; seed <= 400; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const cg::json& in = p.input;
        if (!in["stepping"].contains("pixel")) continue;
        CHECK_THAT(p.question, Catch::Contains("distributed over"));
        std::map<std::string, std::string> want;
        const int spp = in["settings"].value("samples_per_pixel", 1);
        if (spp > 1) want["anti_aliasing"] = "pixel area";
        if (in["camera"].value("aperture", 0.0) > 0) want["depth_of_field"] = "lens aperture";
        if (in["camera"].value("shutter", 0.0) > 0) want["motion_blur"] = "shutter time";
        if (in["lights"][0].contains("area")) want["soft_shadows"] = "light area";
        if (in["materials"][0].value("gloss", 0.0) > 0) want["glossy_reflection"] = "Phong lobe";
        REQUIRE_FALSE(want.empty());
        std::vector<std::string> fields;
        for (const auto& [effect, over] : want) {
            fields.push_back("distributed_over/" + effect);
            CHECK(p.expected.at("distributed_over/" + effect) == over);
            ++seen[effect];
        }
        std::vector<std::string> answers = p.answers;
        std::sort(answers.begin(), answers.end());
        CHECK(answers == fields);
        // The trace spreads the rays as the answer says.
        const cg::json result = cg::test::result_of("ray-tracer", in);
        int primaries = 0, area_shadows = 0, glossy = 0;
        std::set<double> times;
        bool off_axis_origin = false;
        const cg::json& eye = in["camera"]["eye"];
        for (const cg::json& n : result["tree"]) {
            if (n["kind"] == "primary") {
                ++primaries;
                times.insert(n["time"].get<double>());
                off_axis_origin = off_axis_origin || n["origin"] != eye;
            }
            area_shadows += n.contains("light_sample");
            glossy += n.value("glossy", false);
        }
        CHECK(primaries == spp);
        CHECK(off_axis_origin == want.contains("depth_of_field"));
        if (want.contains("motion_blur"))
            CHECK(*times.rbegin() > 0);
        else
            CHECK(times == std::set<double>{0.0});
        CHECK((area_shadows > 0) == want.contains("soft_shadows"));
        CHECK((glossy > 0) == want.contains("glossy_reflection"));
        // Grading accepts the expected answers and refuses a swapped pair.
        for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
        cg::json wrong = p.expected;
        const std::string& first = p.answers[0];
        wrong[first] = p.expected[first] == "light area" ? "pixel area" : "light area";
        CHECK_FALSE(cg::grade(p, wrong)[0].correct);
    }
    for (const char* effect :
         {"anti_aliasing", "depth_of_field", "motion_blur", "soft_shadows", "glossy_reflection"})
        CHECK(seen[effect] > 10);
}

TEST_CASE("ray-tracer: traces are deterministic and stepping back reproduces them",
          "[rays][ray-tracer]") {
    cg::json in = tracer().example();
    cg::test::check_replay(tracer(), in, cg::test::kEveryStep);
    in["stepping"] = {{"granularity", "pixels"}};
    in["camera"]["size"] = {12, 9};
    cg::test::check_replay(tracer(), in, 50);
    in["stepping"] = {{"granularity", "rows"}};
    cg::test::check_replay(tracer(), in, 4);
}

TEST_CASE("ray-tracer: a copied state shares its image rows until it writes",
          "[rays][ray-tracer]") {
    const cg::json j = tracer().example();
    RayTracer::Input in;
    in.scene = rt::scene_from_json(j, {"stepping"});
    auto s = RayTracer::start(in);
    for (int k = 0; k < 100; ++k) RayTracer::step(s, nullptr);
    auto copy = s;
    CHECK(copy == s);
    RayTracer::step(copy, nullptr);
    CHECK_FALSE(copy == s);
    CHECK(s.image.get(1, 2) == copy.image.get(1, 2));  // the rows before are shared, unchanged
    while (!RayTracer::done(s)) RayTracer::step(s, nullptr);
    while (!RayTracer::done(copy)) RayTracer::step(copy, nullptr);
    CHECK(copy == s);
}

TEST_CASE("ray-tracer: the picture shows the image, the scene and the ray tree",
          "[rays][ray-tracer]") {
    auto run = tracer().create(tracer().example());
    int steps = 0;
    while (!run->done()) {
        run->step(nullptr);
        ++steps;
        cg::Scene pic;
        run->draw(pic);
        CHECK_FALSE(pic.has_2d());  // nothing on the world's grid
        // The image (a preview) in a panel of its own, the pixel outlined in its cells, and the
        // ray tree as a diagram below it.
        REQUIRE(pic.panels.size() == 2);
        const cg::Panel& image = pic.panels[0];
        CHECK(image.kind == cg::PanelKind::Image);
        REQUIRE(image.grids.size() == 1);
        CHECK(image.grids[0].width == 48);
        REQUIRE(image.polygons.size() == 1);
        CHECK(image.polygons[0].style.role == cg::Role::Active);
        // The pixel is a handle at its centre, dragged from centre to centre.
        REQUIRE(image.handles.size() == 1);
        CHECK(image.handles[0].cell_centres);
        CHECK(image.handles[0].x_field == "/stepping/pixel/0");
        CHECK(image.polygons[0].points[0] + glm::dvec2(0.5) == image.handles[0].p);
        CHECK(pic.panels[1].kind == cg::PanelKind::Diagram);  // the ray tree
        CHECK(pic.has_3d());
        CHECK(pic.focus3.size() == 1);  // the camera frames the step's rays
    }
    cg::Scene pic;
    run->draw(pic);
    // The tree: the primary ray, shadow rays, the mirror ray... in 3D and in the diagram, one
    // node each.
    CHECK(pic.segments3.size() >= 4);
    const auto result =
        cg::RayTracer::result(static_cast<const cg::RunOf<cg::RayTracer>&>(*run).state);
    CHECK(pic.panels[1].points.size() == result.tree.size());
    CHECK(steps >= 6);
}

TEST_CASE("ray-tracer: rows show the rays each row cost, a distributed pixel its samples",
          "[rays][ray-tracer]") {
    cg::json in = tracer().example();
    in["stepping"] = {{"granularity", "rows"}};
    auto run = tracer().create(in);
    for (int k = 0; k < 4; ++k) run->step(nullptr);
    cg::Scene pic;
    run->draw(pic);
    REQUIRE(pic.panels.size() == 2);
    const cg::Panel& chart = pic.panels[1];
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.x.label == "row j");
    CHECK_FALSE(chart.polygons.empty());  // stacked bars, one a kind of ray
    CHECK(chart.legend.front().text == "primary");

    // Four jittered samples: the pixel magnified with one dot a sample, the one in hand orange.
    in = tracer().example();
    in["settings"]["samples_per_pixel"] = 4;
    run = tracer().create(in);
    for (int k = 0; k < 3; ++k) run->step(nullptr);
    cg::Scene dist;
    run->draw(dist);
    REQUIRE(dist.panels.size() == 2);
    int dots = 0, active = 0;
    for (const auto& p : dist.panels[1].points) {
        ++dots;
        active += p.style.role == cg::Role::Active;
        CHECK(p.radius >= 4);  // big enough to see
    }
    CHECK(dots == 4);
    CHECK(active == 1);
}
