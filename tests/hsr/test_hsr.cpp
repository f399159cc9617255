// Hidden-surface removal: the shared scene's coverage rule against the triangle scan
// conversion, Warnock and the z-buffer against the brute-force definition (hsr::visible_ids) on
// 1,000 random scenes, hand cases, and refused input.
#include <catch2/catch.hpp>

#include "hsr/screen_scene.hpp"
#include "hsr/warnock.hpp"
#include "hsr/z_buffer.hpp"
#include "hsr/random_scene.hpp"
#include "io/registry.hpp"
#include "raster/scan_triangle.hpp"

using cg::Warnock;
using cg::ZBuffer;
using namespace cg::hsr;

namespace {

ScreenPolygon flat_rect(double x0, double y0, double x1, double y1, double z) {
    return {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, {1, 1, 1}};
}

std::vector<int> warnock_ids(const ScreenScene& s) { return cg::run_to_end<Warnock>(Warnock::start({s})).ids; }
std::vector<int> zbuffer_ids(const ScreenScene& s, ZBuffer::Granularity g = ZBuffer::Granularity::Polygon) {
    return cg::run_to_end<ZBuffer>(ZBuffer::start({s, g})).ids;
}

}  // namespace

TEST_CASE("hsr: covers() is the scan conversion's top-left rule", "[hsr]") {
    for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        cg::ScanTriangle::Input in;
        in.width = 9, in.height = 9;
        for (int k = 0; k < 3; ++k)
            in.triangle.push_back({static_cast<double>(rng.integer(-2, 20)) / 2, static_cast<double>(rng.integer(-2, 20)) / 2});
        const auto r = cg::ScanTriangle::scan(in);
        std::vector<int> filled(81, 0);
        for (auto p : r.pixels) filled[static_cast<std::size_t>(p.y * 9 + p.x)] = 1;
        ScreenPolygon poly;
        for (auto v : in.triangle) poly.vertices.push_back({v.x, v.y, 0});
        const bool degenerate = (in.triangle[1].x - in.triangle[0].x) * (in.triangle[2].y - in.triangle[0].y) ==
                                (in.triangle[2].x - in.triangle[0].x) * (in.triangle[1].y - in.triangle[0].y);
        for (int j = 0; j < 9; ++j)
            for (int i = 0; i < 9; ++i) {
                CAPTURE(i, j);
                const int expected = degenerate ? 0 : covers(poly, i + 0.5, j + 0.5);
                REQUIRE(filled[static_cast<std::size_t>(j * 9 + i)] == expected);
            }
    }
}

TEST_CASE("hsr: a convex polygon's fan spans are exactly the centres covers() accepts", "[hsr]") {
    for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const ScreenPolygon p = valid_polygon(rng, 12, 10, false);
        std::vector<int> spans(120, 0);
        for (const PixelSpan& s : polygon_spans(p, 12, 10))
            for (int i = s.i_first; i < s.i_end; ++i) spans[static_cast<std::size_t>(s.j * 12 + i)]++;
        for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 12; ++i) {
                CAPTURE(i, j);
                REQUIRE(spans[static_cast<std::size_t>(j * 12 + i)] == int(covers(p, i + 0.5, j + 0.5)));
            }
    }
}

TEST_CASE("hsr: Warnock and the z-buffer agree with the brute force on 1,000 random scenes", "[hsr]") {
    for (std::uint64_t trial = 1; trial <= 1000; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(trial);
        const long long W = rng.integer(1, 24), H = rng.integer(1, 24);
        const ScreenScene scene = random_scene(rng, W, H, static_cast<int>(rng.integer(0, 6)));
        const auto expected = visible_ids(scene);
        const auto w = cg::run_to_end<Warnock>(Warnock::start({scene}));
        REQUIRE(w.ids == expected);
        REQUIRE(Warnock::render({scene}) == w);
        const auto z = cg::run_to_end<ZBuffer>(ZBuffer::start({scene}));
        REQUIRE(z.ids == expected);
        REQUIRE(ZBuffer::render({scene}) == z);
        if (trial % 10 == 0) {
            const auto zp = cg::run_to_end<ZBuffer>(ZBuffer::start({scene, ZBuffer::Granularity::Pixel}));
            REQUIRE(zp == z);
        }
        // The z-buffer's compares are the scan-converted pixels: the sum of the coverages.
        long long covered = 0;
        for (const auto& p : scene.polygons)
            for (const auto& s : polygon_spans(p, W, H)) covered += s.i_end - s.i_first;
        REQUIRE(z.compares == covered);
    }
}

TEST_CASE("hsr: hand cases", "[hsr]") {
    SECTION("equal depths: the lower index wins, whatever the drawing order") {
        ScreenScene s{4, 4, {flat_rect(0, 0, 3, 3, 5), flat_rect(1, 1, 4, 4, 5)}};
        const auto ids = visible_ids(s);
        CHECK(ids[1 * 4 + 1] == 0);  // the overlap
        CHECK(ids[3 * 4 + 3] == 1);
        CHECK(warnock_ids(s) == ids);
        CHECK(zbuffer_ids(s) == ids);
        std::swap(s.polygons[0], s.polygons[1]);  // now the other is P0 and wins the overlap
        CHECK(visible_ids(s)[1 * 4 + 1] == 0);
        CHECK(visible_ids(s)[0] == 1);
    }
    SECTION("a polygon surrounding the screen behind the others is the background") {
        ScreenScene s{8, 8, {flat_rect(-1, -1, 9, 9, 10), flat_rect(2, 2, 6, 6, 3)}};
        const auto ids = visible_ids(s);
        CHECK(ids[0] == 0);
        CHECK(ids[3 * 8 + 3] == 1);
        const auto w = cg::run_to_end<Warnock>(Warnock::start({s}));
        CHECK(w.ids == ids);
        // The screen splits once into quarters, each splits once more into 2 × 2 areas: the inner
        // square's quarter-corner areas are then surrounded by P1 in front: 1 + 4 + 16 areas.
        CHECK(w.areas == 21);
        CHECK(zbuffer_ids(s) == ids);
    }
    SECTION("a surrounding polygon in front hides everything at once") {
        ScreenScene s{8, 8, {flat_rect(2, 2, 6, 6, 3), flat_rect(-1, -1, 9, 9, 1)}};
        const auto w = cg::run_to_end<Warnock>(Warnock::start({s}));
        CHECK(w.areas == 1);
        CHECK(w.ids == std::vector<int>(64, 1));
    }
    SECTION("the course-style 8 × 8 screen with three polygons (the example)") {
        const cg::Registry reg = cg::builtin_registry();
        const auto* a = reg.find("warnock");
        REQUIRE(a);
        auto run = a->create(a->example());
        while (!run->done()) run->step(nullptr);
        const auto r = a->result(*run);
        CHECK(r["areas"] == 73);
        CHECK(r["ids"][0] == cg::json::array({0, 0, 0, 0, 0, 0, 0, 0}));
        CHECK(r["ids"][3] == cg::json::array({0, 1, 1, 2, 1, 1, 0, 0}));  // (4.5, 3.5) is on P2's right edge: out
    }
    SECTION("a 1 × k screen splits in one direction only") {
        ScreenScene s{1, 5, {flat_rect(0, 0.5, 1, 2.5, 2), flat_rect(0, 1.5, 1, 4.5, 1)}};
        CHECK(warnock_ids(s) == visible_ids(s));
    }
}

TEST_CASE("hsr: refused scenes name the field", "[hsr]") {
    auto error = [](const ScreenScene& s) {
        try {
            validate(s);
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK_THAT(error({0, 4, {}}), Catch::Contains("width"));
    CHECK_THAT(error({4, 5000, {}}), Catch::Contains("height") && Catch::Contains("limit"));
    ScreenPolygon two{{{0, 0, 0}, {1, 1, 0}}};
    CHECK_THAT(error({4, 4, {two}}), Catch::Contains("polygons[0].vertices") && Catch::Contains("at least 3"));
    ScreenPolygon edge_on{{{0, 0, 0}, {2, 2, 1}, {4, 4, 2}}};
    CHECK_THAT(error({4, 4, {edge_on}}), Catch::Contains("no area"));
    ScreenPolygon dart{{{0, 0, 0}, {4, 0, 0}, {1, 1, 0}, {0, 4, 0}}};
    CHECK_THAT(error({4, 4, {dart}}), Catch::Contains("polygons[0].vertices[2]") && Catch::Contains("convex"));
    ScreenPolygon bent{{{0, 0, 0}, {4, 0, 0}, {4, 4, 1}, {0, 4, 0}}};
    CHECK_THAT(error({4, 4, {bent}}), Catch::Contains("planar"));
    ScreenPolygon star{{{0, 4, 0}, {2.4, -3.2, 0}, {-3.8, 1.2, 0}, {3.8, 1.2, 0}, {-2.4, -3.2, 0}}};
    CHECK_THAT(error({4, 4, {star}}), Catch::Contains("polygons[0].vertices"));
    ScreenPolygon bad_colour{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {1, 2, 0}};
    CHECK_THAT(error({4, 4, {bad_colour}}), Catch::Contains("polygons[0].color[1]"));
}

TEST_CASE("hsr: Warnock's classification of a polygon against an area", "[hsr]") {
    const auto square = ccw_outline(flat_rect(2, 2, 6, 6, 0));
    CHECK(Warnock::classify(square, 0, 0, 8, 8) == Warnock::Class::Contained);
    CHECK(Warnock::classify(square, 3, 3, 5, 5) == Warnock::Class::Surrounding);
    CHECK(Warnock::classify(square, 2, 2, 6, 6) == Warnock::Class::Surrounding);
    CHECK(Warnock::classify(square, 5, 5, 8, 8) == Warnock::Class::Intersecting);
    CHECK(Warnock::classify(square, 6, 0, 8, 8) == Warnock::Class::Disjoint);  // touching only
    const auto triangle = ccw_outline({{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}});
    CHECK(Warnock::classify(triangle, 2, 2, 4, 4) == Warnock::Class::Disjoint);  // the hypotenuse separates
    CHECK(Warnock::classify(triangle, 1, 1, 4, 4) == Warnock::Class::Intersecting);
}

TEST_CASE("z-buffer: the picture — the colour buffer in the world, the depth buffer an image beside it",
          "[hsr][z-buffer]") {
    const ScreenScene sc{4, 4, {flat_rect(0, 0, 3, 3, 5), flat_rect(1, 1, 4, 4, 2)}};
    auto s = ZBuffer::start({sc, ZBuffer::Granularity::Pixel});
    while (!ZBuffer::done(s) && s.last != ZBuffer::Phase::Pixel) ZBuffer::step(s, nullptr);
    cg::Scene pic;
    ZBuffer::draw(s, pic);
    REQUIRE(pic.grids.size() == 1);  // the colour buffer, in screen pixels
    REQUIRE(pic.panels.size() == 1);
    const cg::Panel& depth = pic.panels[0];
    CHECK(depth.kind == cg::PanelKind::Image);
    REQUIRE(depth.grids.size() == 1);
    CHECK(depth.grids[0].width == 4);
    CHECK(depth.grids[0].height == 4);
    // The first pixel compared was written: the depth panel says what the buffer held and holds.
    REQUIRE(depth.points.size() == 1);
    CHECK(depth.points[0].label == "∞ → 5");
    CHECK(depth.points[0].style.role == cg::Role::Kept);
    CHECK(depth.grids[0].rgba[static_cast<std::size_t>(s.pj * 4 + s.pi)] != 0);
}
