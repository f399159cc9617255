// CSG objects in the recursive ray tracer: a lens (two spheres intersected) hit by hand; shadow
// rays respecting CSG (light through a hole, blocked beside it); a ray refracted into a CSG lens
// leaving through its back; the stepped ray tree bit for bit against the plain tracer on random
// CSG scenes, with the merge narrated at each hit; pixels, rows and threads the same image; the
// cost limits counting leaves; the scene file with CSG objects read, refused naming the path,
// written back; the golden lens and die through `cgsandbox render-scene`.
#include <stb/stb_image.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <set>

#include "core/format.hpp"
#include "io/registry.hpp"
#include "rays/ray_tracer.hpp"
#include "rays/rt_csg.hpp"
#include "rays/rt_scene_json.hpp"
#include "rays/tracer_support.hpp"
#include "support/process.hpp"

using cg::RayTracer;
using glm::dvec3;
namespace rt = cg::rt;

namespace {

// A number as JSON text (cg::num is for students' eyes: "−1", "10⁻⁵").
std::string jnum(double x, int = 17) { return cg::json(x).dump(); }


rt::Scene scene(const std::string& text) {
    return cg::test::scene_of(text);
}

using Tree = cg::test::RayTree;
using cg::test::events;
using cg::test::ray_tree;

std::string error_of(const std::string& text) {
    try {
        scene(text);
    } catch (const cg::InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

std::string sphere_at(double r, double z) {
    return R"({"primitive": {"type": "sphere", "params": {"r": )" + jnum(r) +
           R"(}, "transform": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, )" + jnum(z) +
           "], [0, 0, 0, 1]]}}";
}

// A lens: two unit spheres at z = ±0.5 intersected, seen from +z.
const std::string kLens = R"({
  "camera": {"eye": [0, 0, 5], "center": [0, 0, 0], "size": [8, 6]},
  "materials": [{"name": "m", "ka": 0.5, "kd": 0.6, "ks": 0.3, "shininess": 10},
                {"name": "glass", "ka": 0, "kd": 0, "ks": 0, "kt": 1, "ior": 1.5}],
  "lights": [{"position": [0, 0, 10], "intensity": 1}],
  "objects": [{"name": "lens", "type": "csg", "material": "MATERIAL",
               "tree": {"op": "intersection", "left": )" + sphere_at(1, -0.5) +
                            R"(, "right": )" + sphere_at(1, 0.5) + R"(}}]})";

std::string lens(const char* material) {
    std::string s = kLens;
    s.replace(s.find("MATERIAL"), 8, material);
    return s;
}

// A plate y ∈ [1, 1.2] with a round hole (radius 0.5) about the y axis over a floor, lit from
// straight above: the floor is lit through the hole and in shadow beside it.
const std::string kPlate = R"({
  "camera": {"eye": [0, 3, 6], "center": [0, 0, 0], "size": [16, 12]},
  "materials": [{"name": "m", "ka": 0.1, "kd": 0.8, "ks": 0, "shininess": 1}],
  "lights": [{"position": [0, 5, 0], "intensity": 1}],
  "objects": [{"name": "floor", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"},
              {"name": "plate", "type": "csg", "material": "m",
               "tree": {"op": "difference",
                        "left": {"primitive": {"type": "box", "min": [-2, 1, -2], "max": [2, 1.2, 2]}},
                        "right": {"name": "hole", "primitive": {"type": "cylinder", "params": {"p": 0.5, "q": 0.5},
                                  "transform": [[1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]]}}}}]})";

}  // namespace

TEST_CASE("ray-tracer CSG: a lens hit by hand, its merge narrated", "[rays][ray-tracer][csg]") {
    const rt::Scene s = scene(lens("m"));
    // The sphere at z = −0.5 spans z ∈ [−1.5, 0.5], the other [−0.5, 1.5]: the lens is
    // z ∈ [−0.5, 0.5], t ∈ [4.5, 5.5] from (0, 0, 5) down the axis; the hit is t = 4.5 on the
    // sphere at z = −0.5, normal +z.
    const Tree t = ray_tree(s, {0, 0, 5}, {0, 0, -1});
    REQUIRE(events(t).size() > 2);
    CHECK(events(t)[1] == "hit");
    const auto& primary = t.result.tree[0];
    CHECK(primary.hit.t == 4.5);
    CHECK(primary.hit.point == dvec3(0, 0, 0.5));
    CHECK(primary.hit.normal == dvec3(0, 0, 1));
    CHECK(primary.hit.entering);
    CHECK_THAT(t.steps[1].narration, Catch::Contains("CSG segments along the ray") &&
                                         Catch::Contains("leaf 0: [4.5, 6.5]") &&
                                         Catch::Contains("leaf 1: [3.5, 5.5]") &&
                                         Catch::Contains("leaf 0 ∩ leaf 1: [4.5, 5.5]"));
    bool var = false;
    for (const auto& v : t.steps[1].vars) var = var || v.name == "CSG segments";
    CHECK(var);
    // Off the axis the lens is thinner: at x = 0.6 the spheres' chords are z = −0.5 ± 0.8 and
    // 0.5 ± 0.8, so the lens is z ∈ [−0.3, 0.3].
    const Tree off = ray_tree(s, {0.6, 0, 5}, {0, 0, -1});
    CHECK(off.result.tree[0].hit.t == Approx(4.7).epsilon(1e-14));
    // A ray beside it misses (the spheres alone would have been hit).
    CHECK(events(ray_tree(s, {0.9, 0, 5}, {0, 0, -1}))[1] == "miss");
}

TEST_CASE("ray-tracer CSG: shadow rays and refracted rays respect the tree",
          "[rays][ray-tracer][csg]") {
    const rt::Scene plate = scene(kPlate);
    // Through the hole the floor sees the light; beside it the plate blocks it.
    // (Down through the hole onto (0.1, 0, 0.1); from the side, under the plate, onto (1, 0, 0.3).)
    const Tree lit = ray_tree(plate, {0.1, 3, 0.1}, {0, -1, 0});
    const Tree dark = ray_tree(plate, {3, 0.5, 0.3}, {-2, -0.5, 0});
    CHECK(lit.result.tree[0].hit.object == 0);
    CHECK(dark.result.tree[0].hit.object == 0);
    CHECK(std::ranges::count(events(lit), "lit") == 1);
    CHECK(std::ranges::count(events(dark), "shadowed") == 1);
    // Glass: the refracted ray starts inside the lens and leaves through its back (the exit
    // of the segment it starts in), then misses.
    const rt::Scene glass = scene(lens("glass"));
    const Tree t = ray_tree(glass, {0, 0, 5}, {0, 0, -1});
    std::vector<RayTracer::RayNode> refracted;
    for (const auto& n : t.result.tree)
        if (n.kind == RayTracer::RayKind::Refracted) refracted.push_back(n);
    REQUIRE(refracted.size() >= 2);
    CHECK(refracted[0].hit.object == 0);
    CHECK(refracted[0].hit.t == Approx(1.0).margin(1e-6));  // from z = 0.5 to z = −0.5
    CHECK_FALSE(refracted[0].hit.entering);
    CHECK(refracted[0].hit.point.z == Approx(-0.5).margin(1e-9));
    CHECK(refracted[1].hit.object < 0);  // out of the back, into the background
}

namespace {

// Random scenes of CSG objects (two or three primitives each), planes and spheres, with
// mirrors and glass.
rt::Scene random_csg_scene(std::uint64_t seed) {
    cg::Rng rng(seed);
    rt::Scene s;
    s.camera.eye = {rng.uniform(-3, 3), rng.uniform(1, 3), rng.uniform(5, 7)};
    s.camera.center = {0, 0, 0};
    s.camera.width = 16, s.camera.height = 12;
    s.settings.max_depth = static_cast<int>(rng.integer(1, 3));
    for (int k = 0; k < 3; ++k) {
        rt::Material m;
        m.name = "m" + std::to_string(k);
        m.ka = m.kd = {rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)};
        if (k == 1) m.kr = glm::dvec3(0.4);
        if (k == 2) m.kt = glm::dvec3(0.8), m.ior = 1.4;
        s.materials.push_back(m);
    }
    rt::Light l;
    l.position = {rng.uniform(-4, 4), 5, rng.uniform(-4, 4)};
    s.lights.push_back(l);
    rt::Object floor;
    floor.kind = rt::ObjectKind::Plane;
    floor.name = floor.field = "objects[0]";
    floor.p0 = {0, -1.5, 0};
    floor.normal = {0, 1, 0};
    s.objects.push_back(floor);
    const int n = static_cast<int>(rng.integer(1, 3));
    for (int k = 0; k < n; ++k) {
        rt::Object o;
        o.kind = rt::ObjectKind::Csg;
        o.name = o.field = "objects[" + std::to_string(k + 1) + "]";
        o.material = static_cast<int>(rng.integer(0, 2));
        cg::CsgTree& t = o.csg;
        auto leaf = [&](const std::string& path) {
            cg::CsgNode n;
            n.path = path;
            n.depth = 1;
            if (rng.chance(0.5)) {
                n.kind = cg::CsgPrimitive::Box;
                n.box.min = {rng.uniform(-1.5, 0), rng.uniform(-1.5, 0), rng.uniform(-1.5, 0)};
                n.box.max = n.box.min + dvec3(rng.uniform(0.5, 2), rng.uniform(0.5, 2),
                                              rng.uniform(0.5, 2));
            } else {
                n.quadric.r = rng.uniform(0.4, 1.2);
                n.quadric.world_from_model[3] = glm::dvec4(
                    rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), 1);
            }
            n.leaf_index = t.leaves++;
            t.nodes.push_back(n);
        };
        leaf(o.field + ".tree.left");
        leaf(o.field + ".tree.right");
        cg::CsgNode root;
        root.leaf = false;
        root.op = static_cast<cg::CsgOp>(rng.integer(0, 2));
        root.left = 0, root.right = 1;
        root.path = o.field + ".tree";
        root.has_transform = true;
        root.transform[3] = glm::dvec4(rng.uniform(-2, 2), rng.uniform(-0.5, 0.5),
                                       rng.uniform(-2, 2), 1);
        t.nodes.push_back(root);
        s.objects.push_back(o);
    }
    rt::validate(s);
    return s;
}

}  // namespace

TEST_CASE("ray-tracer CSG: the stepped ray tree equals the plain tracer bit for bit",
          "[rays][ray-tracer][csg]") {
    std::set<std::string> events;
    int csg_hits = 0;
    for (int trial = 0; trial < 120; ++trial) {
        const rt::Scene s = random_csg_scene(5000 + trial);
        const rt::Prepared p = rt::prepare(s);
        cg::Rng rng(trial);
        for (int k = 0; k < 6; ++k) {
            const int i = static_cast<int>(rng.integer(0, s.camera.width - 1)),
                      j = static_cast<int>(rng.integer(0, s.camera.height - 1));
            CAPTURE(trial, i, j);
            const cg::test::RayTree t = cg::test::pixel_tree(s, {i + 0.5, j + 0.5});
            for (const cg::StepInfo& info : t.steps) {
                events.insert(info.event);
                csg_hits += info.narration.find("CSG segments") != std::string::npos;
            }
            const RayTracer::Result& r = t.result;
            rt::RayCounts counts;
            CHECK(r.color == rt::pixel_color(s, p, i, j, counts));  // exactly
            CHECK(r.rays == counts);
        }
        if (trial % 20 == 0) {  // pixels, rows and threads: the same image
            const rt::Image one = rt::render(s, 1), two = rt::render(s, 2);
            CHECK(one == two);
            RayTracer::Input in;
            in.scene = s;
            in.granularity = RayTracer::Granularity::Rows;
            auto st = RayTracer::start(in);
            while (!RayTracer::done(st)) RayTracer::step(st, nullptr);
            CHECK(RayTracer::result(st).image == one.rgba);
        }
    }
    CHECK(csg_hits > 100);
    for (const char* e : {"hit", "lit", "shadowed", "reflect", "refract", "return"}) {
        CAPTURE(e);
        CHECK(events.count(e) == 1);
    }
}

TEST_CASE("ray-tracer CSG: scene files with CSG objects", "[rays][ray-tracer][csg][errors]") {
    const std::string ok = lens("m");
    CHECK(error_of(ok) == "(accepted)");
    auto with_tree = [&](const std::string& tree) {
        std::string s = ok;
        const auto a = s.find("\"tree\": ") + 8, b = s.rfind("}]}");
        return s.substr(0, a) + tree + s.substr(b);
    };
    CHECK(error_of(with_tree(R"({"op": "xor", "left": )" + sphere_at(1, 0) + R"(, "right": )" +
                             sphere_at(1, 0) + "}")) ==
          "objects[0].tree.op: unknown op \"xor\" (union, intersection, difference)");
    CHECK(error_of(with_tree(R"({"op": "union", "left": )" + sphere_at(1, 0) + "}")) ==
          "objects[0].tree.right: is missing");
    CHECK_THAT(error_of(with_tree(R"({"primitive": {"type": "sphere", "params": {"r": 0}}})")),
               Catch::StartsWith("objects[0].tree.primitive.params.r: must be positive"));
    CHECK_THAT(error_of(with_tree(R"({"primitive": {"type": "box", "min": [0, 0, 0], "max": [1e13, 1, 1]}})")),
               Catch::StartsWith("objects[0].tree.primitive.max[0]: must be a finite number of "
                                 "magnitude at most 1e12"));
    CHECK_THAT(error_of(with_tree(R"({"primitive": {"type": "sphere", "params": {"r": 1}}, "transform": [[1, 0, 0, 1e13], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})")),
               Catch::StartsWith("objects[0].tree: is placed at"));
    CHECK_THAT(error_of(R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0]}, "materials": [{"name": "m"}],
                            "objects": [{"type": "csg", "material": "m"}]})"),
               Catch::StartsWith("objects[0].tree: is missing"));
    CHECK_THAT(error_of(R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0]}, "materials": [{"name": "m"}],
                            "objects": [{"type": "csg", "material": "m", "params": {}}]})"),
               Catch::StartsWith("objects[0].params: is not a known field"));
    // Textures: a solid texture colours a CSG object (it needs only the point); an image
    // texture or a bump needs (u, v), which a CSG surface pieced from its leaves does not have.
    auto with_material = [&](const std::string& extra) {
        std::string s = ok;
        const auto at = s.find(R"("shininess": 10)") + std::string(R"("shininess": 10)").size();
        return s.substr(0, at) + ", " + extra + s.substr(at);
    };
    CHECK(error_of(with_material(R"("solid_texture": {"type": "checker", "size": 0.25})")) ==
          "(accepted)");
    CHECK_THAT(error_of(with_material(R"("texture": {"checker": {"size": 4}})")),
               Catch::StartsWith("objects[0].material: material \"m\" has an image texture, "
                                 "which needs (u, v) on the surface; a CSG object has none"));
    CHECK_THAT(error_of(with_material(R"("bump": {"type": "sines", "amplitude": 0.1, "frequency": [4, 4]})")),
               Catch::StartsWith("objects[0].material: material \"m\" has a bump map"));
    {  // ... and it shows: the checkered lens differs from the plain one
        const rt::Image plain = rt::render(scene(ok), 1);
        const rt::Image checked =
            rt::render(scene(with_material(R"("solid_texture": {"type": "checker", "size": 0.25})")), 1);
        CHECK(plain.rgba != checked.rgba);
    }
    // Written back and read again: the same scene.
    const rt::Scene s = scene(ok);
    const cg::json j = rt::scene_to_json(s);
    CHECK(rt::scene_to_json(scene(j.dump())) == j);
    CHECK(scene(j.dump()).objects[0].csg == s.objects[0].csg);
}

TEST_CASE("ray-tracer CSG: the cost limits count every leaf", "[rays][ray-tracer][csg]") {
    // A union of 256 spheres is 256 ray-object tests per ray.
    std::function<std::string(int)> balanced = [&](int n) {
        return n == 1 ? sphere_at(0.1, 0)
                      : R"({"op": "union", "left": )" + balanced(n / 2) + R"(, "right": )" +
                            balanced(n - n / 2) + "}";
    };
    auto scene_with = [&](int copies, int depth) {
        std::string objects;
        for (int k = 0; k < copies; ++k)
            objects += std::string(k ? ", " : "") +
                       R"({"type": "csg", "material": "m", "tree": )" + balanced(256) + "}";
        return R"({"camera": {"eye": [0, 0, 5], "center": [0, 0, 0], "size": [4, 4]},
                   "settings": {"max_depth": )" + std::to_string(depth) + R"(},
                   "materials": [{"name": "m", "kr": 0.5, "kt": 0.5}],
                   "lights": [{"position": [0, 5, 5]}],
                   "objects": [)" + objects + "]}";
    };
    const rt::Scene one = scene(scene_with(1, 0));
    CHECK(rt::scene_tests(one) == 256);
    CHECK(rt::pixel_work(one) == 256 * 2);
    // 2^(d+1) − 1 rays × 2 × 256 tests: depth 10 is 2047 × 512 ≈ 1.05e6, fine; depth 14 is
    // 32767 × 512 ≈ 1.7e7, over 1e7.
    CHECK(error_of(scene_with(1, 10)) == "(accepted)");
    CHECK_THAT(error_of(scene_with(1, 14)),
               Catch::StartsWith("settings.max_depth: makes one pixel cost up to 16776704") &&
                   Catch::Contains("× 256 objects"));
    // 20,000 objects counted leaf by leaf: 79 trees of 256 leaves are over.
    CHECK_THAT(error_of(scene_with(79, 0)),
               Catch::StartsWith("objects: costs 20224 ray-object tests per ray (triangles "
                                 "and CSG leaves counted one by one"));
}

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

TEST_CASE("ray-tracer CSG: render-scene matches the golden lens and die",
          "[rays][ray-tracer][csg][golden]") {
    const std::string dir = std::string(CG_SOURCE_DIR) + "/tests/golden/ray-tracer/";
    for (const char* name : {"lens", "die"}) {
        CAPTURE(name);
        const std::string out = cg::test::output_path(std::string("golden-") + name + ".png");
        auto r = cg::test::cgsandbox({"render-scene", dir + name + ".json", "--out", out});
        CAPTURE(r.out, r.err);
        REQUIRE(r.exit_code == 0);
        const Png got = load_png(out), want = load_png(dir + name + ".png");
        REQUIRE(got.w == want.w);
        REQUIRE(got.h == want.h);
        int off = 0;
        for (std::size_t k = 0; k < got.rgba.size(); ++k)
            if (std::abs(int(got.rgba[k]) - int(want.rgba[k])) > 2) ++off;
        CHECK(off <= static_cast<int>(got.rgba.size() / 4 / 500));
    }
}
