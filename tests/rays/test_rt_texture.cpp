// Textures in the ray tracer: a textured hit shades exactly as an untextured material whose k_a,
// k_d are the texture's colour times the material's; a bump changes the lighting and nothing
// else (the same hits, shadows and secondary rays); the mipmap level grows with distance on a
// receding floor; on 150 random textured scenes the stepped ray tree gives the plain tracer's
// colour bit for bit and shows the texture step; scene files with textures read, written back
// and refused with the field named; the golden textured images through render-scene.
#include <stb/stb_image.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "io/registry.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_scene_json.hpp"
#include "rays/texture_reference.hpp"
#include "rays/tracer_support.hpp"
#include "support/process.hpp"

using cg::RayTracer;
using glm::dvec2;
using glm::dvec3;
namespace rt = cg::rt;

namespace {

rt::Scene scene(const std::string& text) {
    return cg::test::scene_of(text);
}

std::string scene_error(const std::string& text) {
    try {
        scene(text);
    } catch (const cg::InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

RayTracer::Result tree_of(const rt::Scene& s, int i, int j,
                          std::set<std::string>* events = nullptr) {
    RayTracer::Input in;
    in.scene = s;
    in.granularity = RayTracer::Granularity::RayTree;
    in.pixel = {i + 0.5, j + 0.5};
    auto st = RayTracer::start(in);
    while (!RayTracer::done(st)) {
        cg::StepInfo info;
        RayTracer::step(st, &info);
        if (events) events->insert(info.event);
    }
    return RayTracer::result(st);
}

const std::string kGlobe = R"({
  "camera": {"eye": [0, 0, 5], "center": [0, 0, 0], "size": [16, 12]},
  "ambient": 0.2,
  "materials": [{"name": "m", "ka": 0.9, "kd": 0.8, "ks": 0.3, "shininess": 10,
                 "texture": {"grid": {"width": 4, "height": 2, "texels": [[[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0]], [[0, 1, 1], [1, 0, 1], [0.5, 0.5, 0.5], [1, 1, 1]]]}}}],
  "lights": [{"position": [2, 3, 6], "intensity": 1}],
  "objects": [{"type": "sphere", "params": {"r": 1.5}, "material": "m",
               "transform": [[1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]]}]})";

// A random scene with every kind of texture on its materials.
rt::Scene textured_scene(cg::Rng& rng) {
    rt::Scene s;
    s.camera.eye = {rng.uniform(-3, 3), rng.uniform(1, 3), rng.uniform(5, 7)};
    s.camera.center = {0, 0, 0};
    s.camera.width = 20, s.camera.height = 15;
    s.settings.max_depth = static_cast<int>(rng.integer(0, 2));
    s.settings.model = rng.chance(0.5) ? rt::Model::Phong : rt::Model::BlinnPhong;
    s.ambient = dvec3(0.15);
    for (int k = 0; k < 4; ++k) {
        rt::Material m;
        m.name = "m" + std::to_string(k);
        m.ka = m.kd = {rng.uniform(0.3, 1), rng.uniform(0.3, 1), rng.uniform(0.3, 1)};
        m.ks = dvec3(0.3);
        if (k == 1) m.kr = dvec3(0.3);
        const int tex = static_cast<int>(rng.integer(0, 2));
        if (tex == 0 || k == 0) {
            m.tex.has_texture = true;
            const int W = 1 << rng.integer(1, 4), H = 1 << rng.integer(1, 4);
            m.tex.texture.image.width = W, m.tex.texture.image.height = H;
            for (int q = 0; q < W * H; ++q)
                m.tex.texture.image.texels.push_back(
                    {rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)});
            m.tex.texture.filter = static_cast<cg::TexFilter>(rng.integer(0, 2));
            m.tex.texture.wrap = rng.chance(0.5) ? cg::TexWrap::Repeat : cg::TexWrap::Clamp;
        } else if (tex == 1) {
            m.tex.has_solid = true;
            m.tex.solid.kind = static_cast<cg::SolidKind>(rng.integer(0, 3));
            m.tex.solid.seed = rng.next() >> 20;
            m.tex.solid.octaves = 3;
        }
        if (rng.chance(0.5)) {
            m.tex.has_bump = true;
            m.tex.bump.kind = rng.chance(0.5) ? cg::HeightKind::Sines : cg::HeightKind::Noise;
            m.tex.bump.amplitude = rng.uniform(-0.02, 0.02);
            m.tex.bump.frequency = {rng.uniform(1, 10), rng.uniform(1, 10)};
            m.tex.bump.seed = rng.next() >> 20;
        }
        s.materials.push_back(m);
    }
    rt::Light l;
    l.position = {rng.uniform(-4, 4), 5, rng.uniform(-1, 5)};
    s.lights.push_back(l);
    auto add = [&](rt::Object o) {
        o.name = o.field = "objects[" + std::to_string(s.objects.size()) + "]";
        o.material = static_cast<int>(rng.integer(0, 3));
        s.objects.push_back(o);
    };
    rt::Object floor;
    floor.kind = rt::ObjectKind::Plane;
    floor.p0 = {0, -1, 0};
    floor.normal = {0, 1, 0};
    floor.uv.scale = rng.uniform(0.5, 2);
    add(floor);
    for (int k = 0; k < 3; ++k) {
        rt::Object o;
        o.kind = rt::ObjectKind::Quadric;
        o.quadric.kind = k == 2 ? cg::QuadricKind::Cylinder : cg::QuadricKind::Sphere;
        o.quadric.r = rng.uniform(0.4, 0.9);
        o.quadric.zmin = -0.5, o.quadric.zmax = 0.5;
        if (o.quadric.kind == cg::QuadricKind::Sphere)
            o.quadric.zmin = -cg::Quadric::kInf, o.quadric.zmax = cg::Quadric::kInf;
        glm::dmat4 m(1.0);
        m[3] = glm::dvec4(rng.uniform(-2, 2), rng.uniform(-0.5, 0.5), rng.uniform(-1, 1), 1);
        o.quadric.world_from_model = m;
        add(o);
    }
    rt::Object tri;
    tri.kind = rt::ObjectKind::Triangle;
    tri.p0 = {-2, -1, -1}, tri.p1 = {2, -1, -1}, tri.p2 = {0, 2, -1.5};
    tri.uv.has_uv = true;
    tri.uv.uv = {dvec2(0, 0), dvec2(2, 0), dvec2(1, 2)};
    add(tri);
    rt::validate(s);
    return s;
}

}  // namespace

TEST_CASE("rt-texture: a textured hit shades as k_a, k_d times the texture's colour",
          "[rays][ray-tracer][texture]") {
    const rt::Scene s = scene(kGlobe);
    const rt::Prepared p = rt::prepare(s);
    int hits = 0;
    for (int j = 0; j < 12; ++j)
        for (int i = 0; i < 16; ++i) {
            const dvec3 P = rt::screen_point(p.view, i + 0.5, j + 0.5);
            const rt::Hit h = rt::nearest_hit(p, p.view.eye, P - p.view.eye);
            if (h.object < 0) continue;
            ++hits;
            CAPTURE(i, j);
            // The texture's (u, v) at the hit, from the model point, in long double.
            const cg::Quadric& q = s.objects[0].quadric;
            const dvec3 m = glm::inverse(glm::dmat3(q.world_from_model)) * h.point;
            cg::test::LD u, v;
            cg::test::quadric_uv_ref(q, cg::test::lv(m), u, v);
            const cg::TextureLookup l =
                cg::lookup(s.materials[0].tex.texture, nullptr, dvec2(double(u), double(v)), 0);
            // The same scene without the texture, k_a and k_d multiplied by hand.
            rt::Scene plain = s;
            plain.materials[0].tex = {};
            plain.materials[0].ka = s.materials[0].ka * l.color;
            plain.materials[0].kd = s.materials[0].kd * l.color;
            rt::RayCounts c1, c2;
            const rt::Color want = rt::pixel_color(plain, rt::prepare(plain), i, j, c2);
            const rt::Color got = rt::pixel_color(s, p, i, j, c1);
            CHECK(glm::length(got - want) < 1e-9);
        }
    CHECK(hits > 40);
}

TEST_CASE("rt-texture: a bump changes the lighting, not the hits, the shadows or the rays",
          "[rays][ray-tracer][texture]") {
    const rt::Scene bumped = scene(R"({
      "camera": {"eye": [0, 2, 5], "center": [0, 0, 0], "size": [24, 18]},
      "materials": [{"name": "b", "kr": 0.2, "bump": {"type": "sines", "amplitude": 0.03, "frequency": 2}},
                    {"name": "m"}],
      "lights": [{"position": [-3, 2, 1], "intensity": 1}],
      "objects": [{"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "b"},
                  {"type": "sphere", "params": {"r": 0.7}, "material": "m"}]})");
    rt::Scene smooth = bumped;
    smooth.materials[0].tex = {};
    int changed = 0, floor = 0;
    for (int j = 0; j < 18; ++j)
        for (int i = 0; i < 24; ++i) {
            const RayTracer::Result a = tree_of(bumped, i, j), b = tree_of(smooth, i, j);
            // The mirror and primary rays, in order, and the shadow rays by (ray, light): a
            // shadow ray is cast only where the (perturbed) normal faces the light, so the
            // trees may differ by those; where both cast one, it is blocked alike.
            auto rays = [](const RayTracer::Result& r) {
                std::vector<int> index(r.tree.size(), -1);
                std::vector<const RayTracer::RayNode*> main;
                std::map<std::pair<int, int>, int> shadow;
                for (std::size_t k = 0; k < r.tree.size(); ++k) {
                    const auto& n = r.tree[k];
                    if (n.kind == RayTracer::RayKind::Shadow) {
                        shadow[{index[n.parent], n.light}] = n.blocker;
                    } else {
                        index[k] = static_cast<int>(main.size());
                        main.push_back(&n);
                    }
                }
                return std::pair{main, shadow};
            };
            const auto [ma, sa] = rays(a);
            const auto [mb, sb] = rays(b);
            REQUIRE(ma.size() == mb.size());
            for (std::size_t k = 0; k < ma.size(); ++k) {
                CHECK(ma[k]->hit == mb[k]->hit);
                CHECK(ma[k]->direction == mb[k]->direction);  // mirror rays: the geometric normal
            }
            for (const auto& [key, blocker] : sa)
                if (sb.count(key)) CHECK(sb.at(key) == blocker);
            if (a.tree[0].hit.object == 0) {
                ++floor;
                changed += a.color != b.color;
                CHECK(a.tree[0].surface.normal != a.tree[0].hit.normal);
            }
        }
    CHECK(floor > 100);
    CHECK(changed > floor / 2);
}

TEST_CASE("rt-texture: on a receding floor the mipmap level grows with distance",
          "[rays][ray-tracer][texture]") {
    const rt::Scene s = scene(R"({
      "camera": {"eye": [0, 1, 4], "center": [0, 0.4, 0], "size": [32, 24], "fov_y_deg": 50},
      "materials": [{"name": "c", "texture": {"checker": {"size": 64}, "filter": "mipmap"}}],
      "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "uv_scale": 4, "material": "c"}]})");
    double last = -1;
    int rising = 0;
    for (int j = 0; j < 10; ++j) {  // rows from the bottom (near) upward (far)
        const RayTracer::Result r = tree_of(s, 16, j);
        REQUIRE(r.tree[0].detail >= 0);
        const double lambda = r.details[r.tree[0].detail].lookup.lambda;
        CAPTURE(j, lambda);
        CHECK(lambda >= last - 1e-12);
        rising += lambda > last + 1e-6;
        last = lambda;
    }
    CHECK(rising >= 5);
    CHECK(last > 2);
}

TEST_CASE(
    "rt-texture: on random textured scenes the stepped tree equals the plain tracer, bit for bit",
    "[rays][ray-tracer][texture]") {
    std::set<std::string> events;
    int textured = 0;
    for (int trial = 0; trial < 150; ++trial) {
        cg::Rng rng(7000 + trial);
        const rt::Scene s = textured_scene(rng);
        const rt::Prepared p = rt::prepare(s);
        for (int k = 0; k < 5; ++k) {
            const int i = static_cast<int>(rng.integer(0, s.camera.width - 1)),
                      j = static_cast<int>(rng.integer(0, s.camera.height - 1));
            CAPTURE(trial, i, j);
            const RayTracer::Result r = tree_of(s, i, j, &events);
            rt::RayCounts counts;
            CHECK(r.color == rt::pixel_color(s, p, i, j, counts));
            CHECK(r.rays == counts);
            textured += !r.details.empty();
        }
        // The whole image: pixels stepped and rendered on two threads agree.
        if (trial % 10 == 0) {
            const rt::Image img = rt::render(s, 2);
            RayTracer::Input in;
            in.scene = s;
            in.granularity = RayTracer::Granularity::Rows;
            auto st = RayTracer::start(in);
            while (!RayTracer::done(st)) RayTracer::step(st, nullptr);
            CHECK(RayTracer::result(st).image == img.rgba);
        }
    }
    CHECK(textured > 300);
    CHECK(events.count("texture") == 1);
}

TEST_CASE("rt-texture: scene files with textures are read, written back and refused by field",
          "[rays][ray-tracer][texture][errors]") {
    const std::string dir = std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/";
    for (const char* name : {"bumped-plane", "marble-vase"}) {
        std::ifstream f(dir + name + ".json");
        const std::string text((std::istreambuf_iterator<char>(f)),
                               std::istreambuf_iterator<char>());
        const rt::Scene s = scene(text);
        const rt::Scene back = rt::scene_from_json(rt::scene_to_json(s));
        CHECK(back == s);
    }
    const rt::Scene g = scene(kGlobe);
    CHECK(rt::scene_from_json(rt::scene_to_json(g)) == g);

    const std::string head =
        R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0]}, "materials": [{"name": "m", )";
    const std::string tail =
        R"(}], "objects": [{"type": "sphere", "params": {"r": 1}, "material": "m"}]})";
    CHECK(scene_error(head + R"("texture": {"image": "/nonexistent/earth.png"})" + tail) ==
          "materials[0].texture.image: cannot read \"/nonexistent/earth.png\": no such file");
    CHECK_THAT(
        scene_error(head + R"("texture": {"checker": {}}, "solid_texture": {"type": "wood"})" +
                    tail),
        Catch::StartsWith("materials[0].solid_texture: cannot be combined with \"texture\""));
    CHECK_THAT(
        scene_error(
            head +
            R"("texture": {"grid": {"width": 3, "height": 1, "texels": [[0, 1, 0]]}, "filter": "mipmap"})" +
            tail),
        Catch::StartsWith("materials[0].texture.filter: \"mipmap\" needs"));
    CHECK_THAT(scene_error(head + R"("bump": {"type": "sines", "step": 1})" + tail),
               Catch::StartsWith("materials[0].bump.step: must be between"));
    CHECK_THAT(scene_error(head + R"("solid_texture": {"type": "marble", "octaves": 99})" + tail),
               Catch::StartsWith("materials[0].solid_texture.octaves: must be"));
    CHECK_THAT(scene_error(head + R"("texture": 3)" + tail),
               Catch::StartsWith("materials[0].texture: must be a JSON object"));
    const std::string tex_head =
        R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0]}, "materials": [{"name": "m", "texture": {"checker": {}}}], "objects": [)";
    CHECK_THAT(
        scene_error(
            tex_head +
            R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "uv": [[0, 0], [1, 1], [2, 2]], "material": "m"}]})"),
        Catch::StartsWith("objects[0].uv: must not put the three corners on one line"));
    CHECK_THAT(
        scene_error(
            tex_head +
            R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "u_axis": [0, 2, 0], "material": "m"}]})"),
        Catch::StartsWith("objects[0].u_axis: must not be parallel"));
    CHECK_THAT(
        scene_error(
            tex_head +
            R"({"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]], "uv": [[0, 0]], "material": "m"}]})"),
        Catch::StartsWith("objects[0].uv: must give one (u, v) per vertex"));
    CHECK_THAT(
        scene_error(tex_head +
                    R"({"type": "sphere", "params": {"r": 1}, "uv": [[0, 0]], "material": "m"}]})"),
        Catch::StartsWith("objects[0].uv: is not a known field"));
}

TEST_CASE("rt-texture: render-scene matches the textured golden images",
          "[rays][ray-tracer][golden]") {
    const std::string dir = std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/";
    for (const char* name : {"globe", "bumped-plane", "marble-vase"}) {
        CAPTURE(name);
        const std::string out = cg::test::output_path(std::string("golden-") + name + ".png");
        auto r = cg::test::cgsandbox({"render-scene", dir + name + ".json", "--out", out});
        CAPTURE(r.out, r.err);
        REQUIRE(r.exit_code == 0);
        int w = 0, h = 0, n = 0, w2 = 0, h2 = 0;
        unsigned char* got = stbi_load(out.c_str(), &w, &h, &n, 4);
        unsigned char* want = stbi_load((dir + name + ".png").c_str(), &w2, &h2, &n, 4);
        REQUIRE(got != nullptr);
        REQUIRE(want != nullptr);
        REQUIRE(w == w2);
        REQUIRE(h == h2);
        int off = 0;
        for (int k = 0; k < w * h * 4; ++k) off += std::abs(int(got[k]) - int(want[k])) > 2;
        CHECK(off <= w * h / 500);
        stbi_image_free(got);
        stbi_image_free(want);
    }
    // The globe's texture is found beside the scene file, wherever render-scene is run from.
    auto r = cg::test::cgsandbox({"render-scene", dir + "globe.json", "--out",
                                  cg::test::output_path("globe-again.png"), "--size", "8x6"});
    CHECK(r.exit_code == 0);
    const std::string lonely =
        cg::test::write_temp("lonely.json", R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0]},
          "materials": [{"name": "m", "texture": {"image": "missing-texture.png"}}],
          "objects": [{"type": "sphere", "params": {"r": 1}, "material": "m"}]})");
    r = cg::test::cgsandbox({"render-scene", lonely, "--out", cg::test::output_path("lonely.png")});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("materials[0].texture.image: cannot read \"" +
                                      std::filesystem::path(lonely).parent_path().string() +
                                      "/missing-texture.png\": no such file"));
}
