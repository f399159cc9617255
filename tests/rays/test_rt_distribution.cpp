// Distribution ray tracing in the recursive tracer: with one sample and no aperture, light area,
// shutter time or gloss the image is exactly the plain tracer's (random scenes, with the new
// fields present at their neutral values); the same seed gives the same image on 1, 2 and 3
// threads, another seed another; the stepped ray tree of a distributed pixel gives the plain
// tracer's colour bit for bit, every distributed event seen; the pixel means converge on a
// high-sample reference with an error falling like 1/√N (measured); soft shadows — the shadow
// rays against a long-double brute force over the same light points, and the penumbra's width
// against the geometric prediction for a sphere over a plane; a plane in focus stays sharp and
// one out of focus blurs; motion blur equals the average of still frames; the Phong lobe's
// mean cosine; bad fields; and the golden images of the new scenes.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <random>
#include <set>

#include "io/registry.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"
#include "rays/tracer_support.hpp"
#include "sampling/coverage.hpp"
#include "support/replay.hpp"

using cg::RayTracer;
using glm::dvec3;
namespace rt = cg::rt;

namespace {

const cg::Algorithm& tracer() {
    static const cg::Registry r = cg::builtin_registry();
    return *r.find("ray-tracer");
}

std::string error_of(const std::string& text) {
    try {
        tracer().create(cg::parse_json(text));
    } catch (const cg::InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

// A small random scene: a floor, spheres (some moving), a glossy and a glass material, a point
// light and an area light (rectangle or disc).
rt::Scene random_scene(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1), c(-1, 1);
    rt::Scene s;
    s.camera.eye = {2 * c(rng), 1 + 2 * u(rng), 6 + 2 * u(rng)};
    s.camera.center = {0.3 * c(rng), 0.2 * c(rng), 0};
    s.camera.width = 12, s.camera.height = 9;
    s.settings.max_depth = 1 + static_cast<int>(2 * u(rng));
    s.background = {0.1, 0.12, 0.2};
    for (int k = 0; k < 3; ++k) {
        rt::Material m;
        m.name = "m" + std::to_string(k);
        m.ka = m.kd = {u(rng), u(rng), u(rng)};
        m.ks = dvec3(0.4 * u(rng));
        m.shininess = 5 + 40 * u(rng);
        if (k == 1)
            m.kr = dvec3(0.4 + 0.4 * u(rng)), m.gloss = 20 + 200 * u(rng), m.gloss_samples = 3;
        if (k == 2) m.kt = dvec3(0.7), m.ior = 1.4;
        s.materials.push_back(m);
    }
    rt::Light point;
    point.position = {3 * c(rng), 4 + 2 * u(rng), 3 * c(rng)};
    point.intensity = dvec3(0.5);
    s.lights.push_back(point);
    rt::Light area;
    area.position = {3 * c(rng), 5 + u(rng), 2 * c(rng)};
    area.intensity = dvec3(0.7);
    area.samples = 4;
    if (u(rng) < 0.5) {
        area.area = rt::Light::Area::Rectangle;
        area.edge_u = {1 + u(rng), 0, 0};
        area.edge_v = {0, 0.3 * c(rng), 1 + u(rng)};
    } else {
        area.area = rt::Light::Area::Disc;
        area.radius = 0.5 + u(rng);
        area.normal = {0.2 * c(rng), -1, 0.2 * c(rng)};
    }
    s.lights.push_back(area);
    rt::Object floor;
    floor.kind = rt::ObjectKind::Plane;
    floor.name = floor.field = "objects[0]";
    floor.p0 = {0, -1, 0};
    floor.normal = {0, 1, 0};
    floor.material = static_cast<int>(2 * u(rng));  // plain or glossy
    s.objects.push_back(floor);
    for (int k = 1; k < 4; ++k) {
        rt::Object o;
        o.kind = rt::ObjectKind::Quadric;
        o.name = o.field = "objects[" + std::to_string(k) + "]";
        o.material = static_cast<int>(3 * u(rng)) % 3;
        o.quadric.kind = cg::QuadricKind::Sphere;
        o.quadric.r = 0.4 + 0.5 * u(rng);
        glm::dmat4 m(1.0);
        m[3] = glm::dvec4(2.5 * c(rng), 0.8 * c(rng), 2 * c(rng), 1);
        o.quadric.world_from_model = m;
        if (u(rng) < 0.4) o.velocity = {c(rng), 0.3 * c(rng), 0};
        s.objects.push_back(o);
    }
    s.settings.samples_per_pixel = u(rng) < 0.5 ? 4 : 9;
    s.settings.pattern = static_cast<cg::sampling::Pattern>(rng() % 4);
    s.settings.filter = static_cast<cg::sampling::Filter>(rng() % 3);
    s.settings.seed = rng() % 1000;
    if (u(rng) < 0.5) s.camera.aperture = 0.1 + 0.2 * u(rng), s.camera.focal_distance = 6;
    if (u(rng) < 0.5) s.camera.shutter = 0.5 + u(rng);
    rt::validate(s);
    return s;
}

std::vector<dvec3> image_colours(const rt::Scene& s) {
    const rt::Prepared p = rt::prepare(s);
    std::vector<dvec3> out;
    rt::RayCounts counts;
    for (int j = 0; j < s.camera.height; ++j)
        for (int i = 0; i < s.camera.width; ++i) out.push_back(rt::pixel_color(s, p, i, j, counts));
    return out;
}

double rms(const std::vector<dvec3>& a, const std::vector<dvec3>& b) {
    double sum = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const dvec3 d = a[k] - b[k];
        sum += glm::dot(d, d) / 3;
    }
    return std::sqrt(sum / double(a.size()));
}

// A sphere of radius r at height h over the floor y = 0, under a disc light of radius R at
// height H, all on the y axis; the floor is white and diffuse, nothing else lights it.
const char* kPenumbra = R"({
  "camera": {"eye": [0, 3, 8], "center": [0, 0, 0], "size": [8, 6]},
  "settings": {"max_depth": 0, "seed": 5},
  "ambient": 0,
  "materials": [{"name": "white", "ka": 0, "kd": 1, "ks": 0}],
  "lights": [{"position": [0, 6, 0], "intensity": 1,
              "area": {"shape": "disc", "radius": 1, "normal": [0, -1, 0]}, "samples": 1024}],
  "objects": [
    {"name": "ball", "type": "sphere", "params": {"r": 0.5}, "material": "white",
     "transform": [[1, 0, 0, 0], [0, 1, 0, 2], [0, 0, 1, 0], [0, 0, 0, 1]]},
    {"name": "floor", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"}]})";

// The right end of the ball's shadow on the floor, in the plane through the axis, seen from the
// light point (a, H): where the ray from it tangent to the circle (0, h), radius r, on the +x
// side meets y = 0.
double shadow_edge(double a, double H, double h, double r) {
    const double dx = -a, dy = h - H, D = std::hypot(dx, dy);
    const double alpha = std::asin(r / D), base = std::atan2(dy, dx);
    double best = -1e300;
    for (double sgn : {1.0, -1.0}) {
        const double ang = base + sgn * alpha;
        best = std::max(best, a + (-H / std::sin(ang)) * std::cos(ang));
    }
    return best;
}

}  // namespace

TEST_CASE("distribution: one sample, no aperture, area, time or gloss is today's image, exactly",
          "[rays][ray-tracer][distribution]") {
    for (int trial = 0; trial < 40; ++trial) {
        CAPTURE(trial);
        std::mt19937_64 rng(500 + trial);
        rt::Scene s = random_scene(rng);
        // Neutral values of every new field: one sample (any pattern, filter and seed), no lens,
        // no shutter (the velocities stay), the area light shrunk to its centre, gloss 0.
        rt::Scene neutral = s;
        neutral.settings.samples_per_pixel = 1;
        neutral.camera.aperture = 0;
        neutral.camera.shutter = 0;
        neutral.lights[1].edge_u = neutral.lights[1].edge_v = dvec3(0.0);
        neutral.lights[1].radius = 0;
        neutral.lights[1].samples = 1;
        neutral.materials[1].gloss = 0;
        neutral.materials[1].gloss_samples = 1;
        // ... and the same scene without any of them: a point light, no velocities.
        rt::Scene plain = neutral;
        plain.settings = rt::Settings{};
        plain.settings.max_depth = s.settings.max_depth;
        plain.lights[1].area = rt::Light::Area::None;
        for (auto& o : plain.objects) o.velocity = dvec3(0.0);
        REQUIRE_FALSE(rt::distributed(plain));
        const rt::Image a = rt::render(neutral, 2), b = rt::render(plain, 2);
        CHECK(a.rgba == b.rgba);
        CHECK(a.rays == b.rays);
        CHECK(image_colours(neutral) == image_colours(plain));  // every bit
    }
}

TEST_CASE("distribution: the same scene and seed give the same image on any number of threads",
          "[rays][ray-tracer][distribution]") {
    for (int trial = 0; trial < 8; ++trial) {
        CAPTURE(trial);
        std::mt19937_64 rng(700 + trial);
        rt::Scene s = random_scene(rng);
        const rt::Image one = rt::render(s, 1), two = rt::render(s, 2), three = rt::render(s, 3);
        CHECK(one == two);
        CHECK(one == three);
        CHECK(one.rays.primary ==
              std::uint64_t(s.camera.width) * s.camera.height * s.settings.samples_per_pixel -
                  (s.settings.pattern == cg::sampling::Pattern::Poisson ? 0 : 0));
        s.settings.seed += 1;
        CHECK(rt::render(s, 2).rgba != one.rgba);  // another seed, other noise
    }
}

TEST_CASE("distribution: the stepped ray tree gives the plain tracer's colour, bit for bit",
          "[rays][ray-tracer][distribution]") {
    std::set<std::string> events;
    for (int trial = 0; trial < 60; ++trial) {
        std::mt19937_64 rng(900 + trial);
        const rt::Scene s = random_scene(rng);
        const rt::Prepared p = rt::prepare(s);
        for (int k = 0; k < 3; ++k) {
            const int i = static_cast<int>(rng() % s.camera.width),
                      j = static_cast<int>(rng() % s.camera.height);
            CAPTURE(trial, i, j);
            const cg::test::RayTree t = cg::test::pixel_tree(s, {i + 0.5, j + 0.5});
            for (const cg::StepInfo& info : t.steps) {
                events.insert(info.event);
                REQUIRE(info.narration.find("nan") == std::string::npos);
            }
            const RayTracer::Result& r = t.result;
            rt::RayCounts counts;
            const rt::Color want = rt::pixel_color(s, p, i, j, counts);
            CHECK(r.color == want);  // exactly
            CHECK(r.rays == counts);
            int primaries = 0;
            for (const auto& n : r.tree) primaries += n.kind == RayTracer::RayKind::Primary;
            CHECK(primaries == static_cast<int>(r.samples.size()));
        }
    }
    for (const char* e : {"primary", "hit", "area-light", "glossy", "return", "colour"}) {
        CAPTURE(e);
        CHECK(events.count(e) == 1);
    }
}

TEST_CASE("distribution: pixel means converge on a high-sample reference like 1/√N",
          "[rays][ray-tracer][distribution]") {
    // Everything at once: an area light, a lens, a shutter, a glossy floor.
    rt::Scene s = cg::test::scene_of(R"({
      "camera": {"eye": [0, 1.5, 6], "center": [0, 0.5, 0], "fov_y_deg": 40, "size": [10, 8],
                 "aperture": 0.2, "focal_distance": 6, "shutter": 1},
      "settings": {"max_depth": 1, "pattern": "random", "seed": 1},
      "background": [0.1, 0.1, 0.2],
      "materials": [{"name": "red", "ka": [0.8, 0.2, 0.1], "kd": [0.8, 0.2, 0.1], "ks": 0.4},
                    {"name": "floor", "ka": 0.5, "kd": 0.6, "ks": 0.1, "kr": 0.4, "gloss": 40}],
      "lights": [{"position": [1, 4, 2], "intensity": 1, "area": {"shape": "rectangle",
                  "u": [1.5, 0, 0], "v": [0, 0, 1.5]}, "samples": 1}],
      "objects": [
        {"type": "sphere", "params": {"r": 0.8}, "material": "red", "velocity": [0.8, 0, 0],
         "transform": [[1, 0, 0, -0.4], [0, 1, 0, 0.8], [0, 0, 1, 0], [0, 0, 0, 1]]},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})");
    s.settings.samples_per_pixel = 1024;
    const std::vector<dvec3> reference = image_colours(s);
    std::string table;
    std::vector<double> errors;
    for (int n : {4, 16, 64}) {
        double sum = 0;
        const int seeds = 6;
        for (int seed = 0; seed < seeds; ++seed) {
            s.settings.samples_per_pixel = n;
            s.settings.seed = 100 + seed;
            sum += rms(image_colours(s), reference);
        }
        errors.push_back(sum / seeds);
        table += " N=" + std::to_string(n) + ": " + std::to_string(errors.back());
    }
    const double slope = std::log(errors[2] / errors[0]) / std::log(16.0);
    WARN("RMS error against 1024 samples:" << table << "; slope " << slope);
    CHECK(errors[1] < errors[0]);
    CHECK(errors[2] < errors[1]);
    CHECK(slope == Approx(-0.5).margin(0.12));  // random samples: the standard error, N^−½
}

TEST_CASE(
    "distribution: soft shadows — the shadow rays against a brute force, the penumbra's width",
    "[rays][ray-tracer][distribution]") {
    const rt::Scene s = cg::test::scene_of(kPenumbra);
    rt::Scene open = s;
    open.objects.erase(open.objects.begin());  // no ball: every light point seen
    const rt::Prepared p = rt::prepare(s), po = rt::prepare(open);
    const double R = 1, H = 6, h = 2, r = 0.5;
    double umbra = -1, lit = 1e9;
    int partial = 0;
    for (int q = 0; q <= 400; ++q) {
        const double x = 0.004 * q;
        CAPTURE(x);
        // A ray from the side, low enough to pass under the ball, to the floor point (x, 0, 0).
        const dvec3 origin(x, 0.1, -10), dir(0, -0.1, 10);
        cg::Rng rng(1234 + q), rng_open = rng, rng_points = rng;
        rt::RayCounts counts;
        const double with = rt::trace(s, p, origin, dir, 0, counts, nullptr, &rng).x;
        const double without = rt::trace(open, po, origin, dir, 0, counts, nullptr, &rng_open).x;
        const double f = with / without;
        // The same light points, each tested against the ball in long double.
        const std::vector<dvec3> pts = rt::light_points(s.lights[0], rng_points);
        long double seen = 0, all = 0;
        for (const dvec3& L : pts) {
            const long double dx = L.x - x, dy = L.y, dz = L.z;
            const long double len = std::sqrt(dx * dx + dy * dy + dz * dz);
            const long double cosine = dy / len;  // n · l, n = (0, 1, 0)
            // Segment (x, 0, 0) + t (L − X), t ∈ (0, 1), against the ball at (0, h, 0).
            const long double mx = x, my = -h, mz = 0;
            const long double a = dx * dx + dy * dy + dz * dz,
                              b = 2 * (dx * mx + dy * my + dz * mz),
                              c = mx * mx + my * my + mz * mz - r * r;
            const long double disc = b * b - 4 * a * c;
            bool blocked = false;
            if (disc > 0) {
                const long double t1 = (-b - std::sqrt(disc)) / (2 * a),
                                  t2 = (-b + std::sqrt(disc)) / (2 * a);
                blocked = (t1 > 0 && t1 < 1) || (t2 > 0 && t2 < 1);
            }
            all += cosine;
            if (!blocked) seen += cosine;
        }
        REQUIRE(std::fabs(f - double(seen / all)) <= 2.0 / pts.size());
        if (f == 0) umbra = x;
        if (f == 1) lit = std::min(lit, x);
        partial += f > 0 && f < 1;
    }
    const double umbra_edge = shadow_edge(R, H, h, r), lit_edge = shadow_edge(-R, H, h, r);
    CAPTURE(umbra, lit, umbra_edge, lit_edge);
    CHECK(lit_edge - umbra_edge == Approx(1.0476).epsilon(1e-3));  // the prediction itself
    // Measured with 1,024 points over the disc: its rim is reached to within about 2% of R.
    CHECK(std::fabs(umbra - umbra_edge) < 0.04);
    CHECK(std::fabs(lit - lit_edge) < 0.04);
    CHECK((lit - umbra) == Approx(lit_edge - umbra_edge).epsilon(0.05));
    CHECK(partial > 200);
}

TEST_CASE("distribution: depth of field — the focal plane stays sharp, the rest blurs",
          "[rays][ray-tracer][distribution]") {
    const std::string wall = R"({
      "camera": {"eye": [0, 0, 6], "center": [0, 0, 0], "fov_y_deg": 40, "size": [16, 12]},
      "settings": {"max_depth": 0, "samples_per_pixel": 16, "seed": 2},
      "ambient": 1,
      "materials": [{"name": "checks", "ka": 1, "kd": 0, "ks": 0,
                     "solid_texture": {"type": "checker", "size": 0.5, "colors": [[1, 1, 1], [0, 0, 0]]}}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": "checks"}]})";
    const rt::Scene pinhole = cg::test::scene_of(wall);
    rt::Scene focused = pinhole, blurred = pinhole;
    focused.camera.aperture = blurred.camera.aperture = 0.4;
    focused.camera.focal_distance = 6;  // the wall
    blurred.camera.focal_distance = 3;
    const auto a = image_colours(pinhole), b = image_colours(focused), c = image_colours(blurred);
    int same = 0;
    double worst_blur = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        same += glm::length(a[k] - b[k]) < 1e-9;
        worst_blur = std::max(worst_blur, glm::length(a[k] - c[k]));
    }
    // In focus, every lens ray of a sample meets the pinhole ray's point on the wall.
    CHECK(same >= int(a.size()) - 2);
    CHECK(worst_blur > 0.3);
    CHECK(rms(a, c) > 0.05);
}

TEST_CASE("distribution: motion blur is the average of still frames over the shutter",
          "[rays][ray-tracer][distribution]") {
    const std::string ball = R"({
      "camera": {"eye": [0, 0, 8], "center": [0, 0, 0], "fov_y_deg": 30, "size": [16, 6]},
      "settings": {"max_depth": 0, "samples_per_pixel": 256, "pattern": "random", "seed": 3},
      "ambient": 1,
      "materials": [{"name": "white", "ka": 1, "kd": 0, "ks": 0}],
      "objects": [{"type": "sphere", "params": {"r": 0.6}, "material": "white",
                   "transform": [[1, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}]})";
    rt::Scene moving = cg::test::scene_of(ball);
    moving.objects[0].velocity = {2, 0, 0};
    moving.camera.shutter = 1;
    const auto blurred = image_colours(moving);
    std::vector<dvec3> average(blurred.size(), dvec3(0.0));
    const int frames = 32;
    for (int k = 0; k < frames; ++k) {
        rt::Scene still = cg::test::scene_of(ball);
        still.objects[0].quadric.world_from_model[3].x += 2 * (k + 0.5) / frames;
        const auto img = image_colours(still);
        for (std::size_t q = 0; q < img.size(); ++q) average[q] += img[q] / double(frames);
    }
    // 256 random times and pixel points per pixel: a coverage's standard error is at most 0.03.
    CHECK(rms(blurred, average) < 0.03);
    // Smeared: many more pixels partly covered than in the still frame half way.
    rt::Scene half = cg::test::scene_of(ball);
    half.objects[0].quadric.world_from_model[3].x += 1;
    const auto still = image_colours(half);
    int smeared = 0, sharp = 0;
    for (std::size_t q = 0; q < still.size(); ++q) {
        smeared += blurred[q].x > 0.02;
        sharp += still[q].x > 0.02;
    }
    CHECK(smeared >= 2 * sharp);
}

TEST_CASE("distribution: glossy rays follow the Phong lobe", "[rays][ray-tracer][distribution]") {
    for (double g : {1.0, 10.0, 100.0}) {
        cg::Rng rng(static_cast<std::uint64_t>(g));
        const dvec3 r = glm::normalize(dvec3(0.3, 0.8, -0.5));
        double sum = 0;
        const int n = 20000;
        for (int k = 0; k < n; ++k) {
            const dvec3 d = rt::glossy_direction(r, g, rng);
            REQUIRE(std::fabs(glm::length(d) - 1) < 1e-12);
            sum += glm::dot(d, r);
        }
        // For density ∝ cos^g θ over the hemisphere about r, E[cos θ] = (g + 1)/(g + 2).
        CHECK(sum / n == Approx((g + 1) / (g + 2)).margin(0.01));
    }
}

TEST_CASE("distribution: bad fields are refused, naming them",
          "[rays][ray-tracer][distribution][errors]") {
    auto with = [](const std::string& settings, const std::string& light = "",
                   const std::string& material = "", const std::string& camera = "") {
        return R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0], "size": [8, 6])" + camera +
               R"(}, "settings": {"max_depth": 1)" + settings + R"(}, "materials": [{"name": "m")" +
               material + R"(}], "lights": [{"position": [0, 3, 3])" + light +
               R"(}], "objects": [{"type": "sphere", "params": {"r": 1}, "material": "m"}]})";
    };
    CHECK(error_of(with(R"(, "samples_per_pixel": 0)")) ==
          "settings.samples_per_pixel: must be between 1 and 1024 (got 0)");
    CHECK(error_of(with(R"(, "samples_per_pixel": 8)")) ==
          "settings.samples_per_pixel: must be a square number n × n (4, 9, 16, …) for the "
          "jittered pattern (got 8)");
    CHECK(error_of(with(R"(, "samples_per_pixel": 8, "pattern": "random")")) == "(accepted)");
    CHECK(error_of(with(R"(, "pattern": "stripes")")) ==
          "settings.pattern: must be \"regular\", \"random\", \"jittered\" or \"poisson\", got a "
          "string (\"stripes\")");
    CHECK(error_of(with("", "", "", R"(, "aperture": -1)")) ==
          "camera.aperture: must be a lens radius between 0 and 1e6 (got −1)");
    CHECK(error_of(with("", "", "", R"(, "shutter": -0.5)")) ==
          "camera.shutter: must be a time span between 0 and 1e6 (got −0.5)");
    CHECK(error_of(with("", R"(, "samples": 4)")) ==
          "lights[0].samples: is for an area light (\"area\"): a point light needs one shadow ray");
    CHECK(error_of(with("", R"(, "area": {"shape": "sphere"})")) ==
          "lights[0].area.shape: must be \"rectangle\" or \"disc\" (got \"sphere\")");
    CHECK(error_of(with("", R"(, "area": {"shape": "disc", "radius": -1})")) ==
          "lights[0].area.radius: must be between 0 and 1e12 (got −1)");
    CHECK(error_of(with("", R"(, "area": {"shape": "disc", "radius": 1, "normal": [0, 0, 0]})")) ==
          "lights[0].area.normal: must not be the zero vector: it is the disc's normal");
    CHECK(error_of(with("", "", R"(, "gloss_samples": 4)")) ==
          "materials[0].gloss_samples: needs \"gloss\" > 0: a mirror (gloss 0) reflects one ray");
    CHECK(error_of(with("", "", R"(, "gloss": -2)")) ==
          "materials[0].gloss: must be a Phong exponent between 0 (a mirror) and 1e6 (got −2)");
    CHECK(error_of(
              R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0]}, "materials": [{"name": "m"}],
        "lights": [{"direction": [0, -1, 0], "area": {"shape": "disc", "radius": 1}}], "objects": []})") ==
          "lights[0].area: applies to point lights only: a directional light has no position");
    CHECK(error_of(
              R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0]}, "materials": [{"name": "m"}],
        "objects": [{"type": "sphere", "params": {"r": 1}, "material": "m", "velocity": [1e300, 0, 0]}]})") ==
          "objects[0].velocity[0]: must be a finite number of magnitude at most 1e12 (got 10³⁰⁰)");
    // Too many samples for a costly scene: the work limit names samples_per_pixel.
    CHECK_THAT(error_of(with(R"(, "samples_per_pixel": 1024)",
                             R"(, "area": {"shape": "disc", "radius": 1}, "samples": 1024)",
                             R"(, "kr": 0.5, "gloss": 10, "gloss_samples": 16)")),
               Catch::StartsWith("settings.samples_per_pixel: makes one pixel cost up to"));
}

TEST_CASE("distribution: determinism and stepping back through a distributed ray tree",
          "[rays][ray-tracer][distribution]") {
    std::mt19937_64 rng(42);
    RayTracer::Input in;
    in.scene = random_scene(rng);
    in.granularity = RayTracer::Granularity::RayTree;
    in.pixel = {6.5, 4.5};
    cg::json j = cg::json::parse(tracer().example().dump());
    // The same through JSON: the scene written out and read back runs the same.
    const cg::json written = cg::rt::scene_to_json(in.scene);
    CHECK(cg::rt::scene_to_json(cg::rt::scene_from_json(written)) == written);
    cg::json input = written;
    input["stepping"] = {{"granularity", "ray-tree"}, {"pixel", {6.5, 4.5}}};
    cg::test::check_replay(tracer(), input, 7);
    const cg::json result = [&] {
        auto run = tracer().create(input);
        while (!run->done()) run->step(nullptr);
        return tracer().result(*run);
    }();
    REQUIRE(result.contains("distributed"));
    CHECK(result["distributed"]["primary"][0] == "pixel area");
    CHECK(result["distributed"]["samples"].size() ==
          std::size_t(in.scene.settings.samples_per_pixel));
}

TEST_CASE(
    "distribution: anti-aliasing an edge — 1 sample is all or nothing, 16 come near the coverage",
    "[rays][ray-tracer][distribution]") {
    const std::string dir = std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/";
    auto read = [](const std::string& path) {
        std::ifstream f(path);
        return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    };
    const rt::Scene one = cg::test::scene_of(read(dir + "aa-edge-1.json"));
    const rt::Scene sixteen = cg::test::scene_of(read(dir + "aa-edge-16.json"));
    const auto a = image_colours(one), b = image_colours(sixteen);
    // The triangle seen straight on: its corners in pixel units are where the pinhole rays to
    // them cross the screen; its exact coverage of each pixel is sampling/coverage.hpp's.
    const rt::View v = rt::make_view(one.camera);
    cg::sampling::Region tri;
    tri.kind = cg::sampling::RegionKind::Polygon;
    for (const dvec3& P : {one.objects[0].p0, one.objects[0].p1, one.objects[0].p2}) {
        const dvec3 d = P - v.eye;
        const double sx = glm::dot(d, v.u) / glm::dot(d, v.w),
                     sy = glm::dot(d, v.v) / glm::dot(d, v.w);
        tri.points.push_back(
            {(sx / v.half_width + 1) * v.width / 2, (sy / v.half_height + 1) * v.height / 2});
    }
    int grey_one = 0, grey_sixteen = 0;
    double sum = 0;
    for (int j = 0; j < v.height; ++j)
        for (int i = 0; i < v.width; ++i) {
            const std::size_t k = std::size_t(j) * v.width + i;
            const double exact = cg::sampling::exact_coverage(tri, cg::sampling::Filter::Box, i, j);
            grey_one += a[k].x > 0 && a[k].x < 1;
            grey_sixteen += b[k].x > 0 && b[k].x < 1;
            CHECK(a[k].x == cg::sampling::region_value(tri, {i + 0.5, j + 0.5}));
            CHECK(std::fabs(b[k].x - exact) <= 0.25);
            sum += (b[k].x - exact) * (b[k].x - exact);
        }
    CHECK(grey_one == 0);
    CHECK(grey_sixteen > 30);  // the pixels the two slanted edges cross
    CHECK(std::sqrt(sum / double(a.size())) < 0.03);
}
