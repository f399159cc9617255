// The painter's algorithm: against the brute-force definition (hsr::visible_ids), the z-buffer
// and Warnock on 1,000 random scenes without intersecting polygons (about half with three strips
// woven in a cycle) and on random scenes with intersecting ones; pieces sharing their polygon's
// centres out exactly; the course's tests, one case each; cycles and splits; ties; bad input.
#include <catch2/catch.hpp>

#include "hsr/complexity.hpp"
#include "hsr/painters.hpp"
#include "hsr/random_scene.hpp"
#include "hsr/screen_scene.hpp"
#include "hsr/screen_scene_json.hpp"
#include "hsr/warnock.hpp"
#include "hsr/z_buffer.hpp"
#include "io/registry.hpp"
#include "support/replay.hpp"

using cg::Painters;
using namespace cg::hsr;

namespace {

ScreenPolygon rect(double x0, double y0, double x1, double y1, double z) {
    return {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, {1, 1, 1}};
}

Painters::Result run(const ScreenScene& s) { return cg::run_to_end<Painters>(Painters::start({s})); }

// Steps a run to the end, counting cyclic splits and grid cuts, and checking at every drawn
// piece's split that each centre of a polygon is covered by exactly one of its pieces.
struct Stats {
    long long cycles = 0, grid_cuts = 0;
};
Painters::Result run_checked(const ScreenScene& scene, Stats& stats) {
    Painters::State s = Painters::start({scene});
    while (!Painters::done(s)) {
        Painters::step(s, nullptr);
        if (s.last == Painters::Phase::Pair && s.pair.outcome == Painters::Outcome::Split) {
            stats.cycles += s.cycle;
            stats.grid_cuts += s.split_cut.kind != Painters::Cut::Kind::Plane;
        }
    }
    for (std::size_t k = 0; k < scene.polygons.size(); ++k)
        for (long long j = 0; j < scene.height; ++j)
            for (long long i = 0; i < scene.width; ++i) {
                int pieces = 0;
                for (const auto& p : s.settled)
                    if (p.parent == static_cast<int>(k)) pieces += Painters::covers(s, p, i + 0.5, j + 0.5);
                if (pieces != int(covers(scene.polygons[k], i + 0.5, j + 0.5))) {
                    CAPTURE(k, i, j, pieces);
                    FAIL("a centre of a polygon is not covered by exactly one of its pieces");
                }
            }
    return Painters::result(s);
}

}  // namespace

TEST_CASE("painters: agrees with the brute force, z-buffer and Warnock on 1,000 random scenes", "[hsr][painters]") {
    Stats stats;
    long long splits = 0, moves = 0, triples = 0;
    for (std::uint64_t trial = 1; trial <= 1000; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(trial);
        const long long W = rng.integer(1, 24), H = rng.integer(1, 24);
        const ScreenScene scene = random_layered_scene(rng, W, H, static_cast<int>(rng.integer(0, 8)));
        triples += scene.polygons.size() >= 3;
        const auto expected = visible_ids(scene);
        const auto r = run_checked(scene, stats);
        REQUIRE(r.ids == expected);
        REQUIRE(cg::run_to_end<cg::ZBuffer>(cg::ZBuffer::start({scene})).ids == expected);
        REQUIRE(cg::Warnock::render({scene}).ids == expected);
        REQUIRE(Painters::render({scene}) == r);
        splits += r.splits, moves += r.moves;
        // Every polygon that covers a centre is drawn, whole or in pieces.
        for (std::size_t k = 0; k < scene.polygons.size(); ++k)
            if (!polygon_spans(scene.polygons[k], W, H).empty())
                REQUIRE(std::count(r.order.begin(), r.order.end(), static_cast<int>(k)) >= 1);
    }
    CAPTURE(splits, moves, triples, stats.cycles, stats.grid_cuts);
    CHECK(triples > 300);  // scenes of three or more polygons, where orders can cycle
    CHECK(splits > 100);
    CHECK(moves > 100);
    CHECK(stats.grid_cuts == 0);  // plane splits resolved every cycle met (see the README)
}

TEST_CASE("painters: agrees with the brute force when polygons intersect (split along the intersection)", "[hsr][painters]") {
    Stats stats;
    for (std::uint64_t trial = 1; trial <= 400; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(5000 + trial);
        const long long W = rng.integer(1, 20), H = rng.integer(1, 20);
        const ScreenScene scene = random_scene(rng, W, H, static_cast<int>(rng.integer(0, 6)));
        REQUIRE(run_checked(scene, stats).ids == visible_ids(scene));
    }
}

namespace {

ScreenPolygon poly(std::vector<glm::dvec3> v) { return {std::move(v), {1, 1, 1}}; }
ScreenPolygon tilted_rect(double x0, double y0, double x1, double y1, double z0, double zx, double zy) {
    auto z = [&](double x, double y) { return z0 + zx * x + zy * y; };
    return poly({{x0, y0, z(x0, y0)}, {x1, y0, z(x1, y0)}, {x1, y1, z(x1, y1)}, {x0, y1, z(x0, y1)}});
}
std::vector<std::string> codes(const Painters::Result& r) {
    std::vector<std::string> out;
    for (const auto& d : r.decisions) out.push_back(Painters::test_code(d));
    return out;
}

}  // namespace

TEST_CASE("painters: the course's tests, each deciding one pair", "[hsr][painters]") {
    using V = std::vector<std::string>;
    SECTION("1: z extents overlap but x extents do not") {
        const ScreenScene s{8, 4, {tilted_rect(0, 0, 2, 2, 4, 1, 0), rect(3, 0, 5, 2, 5)}};
        const auto r = run(s);
        CHECK(codes(r) == V{"1"});
        CHECK(r.order == std::vector<int>{0, 1});
        CHECK(r.ids == visible_ids(s));
    }
    SECTION("2: z and x extents overlap, y extents do not") {
        const ScreenScene s{4, 8, {tilted_rect(0, 0, 2, 2, 4, 1, 0), rect(0, 3, 2, 5, 5)}};
        CHECK(codes(run(s)) == V{"2"});
    }
    SECTION("3: P wholly behind Q's plane") {
        const ScreenScene s{8, 8, {tilted_rect(0, 0, 4, 4, 6, 0.5, 0), tilted_rect(2, 2, 6, 6, 4, 0.5, 0)}};
        const auto r = run(s);
        CHECK(codes(r) == V{"3"});
        CHECK(r.ids == visible_ids(s));
        CHECK(r.ids[3 * 8 + 3] == 1);
    }
    SECTION("4: P crosses Q's plane, but Q is wholly in front of P's") {
        const ScreenScene s{8, 8, {tilted_rect(0, 0, 4, 4, 4, 0, 0.5), tilted_rect(2, 1, 6, 5, 6, -1, 0)}};
        const auto r = run(s);
        CHECK(codes(r) == V{"4"});
        CHECK(r.ids == visible_ids(s));
    }
    SECTION("5: extents overlap and each crosses the other's plane, but the projections are apart") {
        auto z_p = [](double x, double y) { return 5 + x - y; };
        auto z_q = [](double x, double y) { return 5 - x + y; };
        const ScreenScene s{6, 6, {poly({{0, 0, z_p(0, 0)}, {4, 0, z_p(4, 0)}, {0, 4, z_p(0, 4)}}),
                                   poly({{4, 1, z_q(4, 1)}, {4, 4, z_q(4, 4)}, {1, 4, z_q(1, 4)}})}};
        CHECK(codes(run(s)) == V{"5"});
    }
    SECTION("every test fails, the reversed 3' holds: Q moves to the far end") {
        const ScreenScene s{8, 8, {tilted_rect(0, 0, 4, 4, 3, 1.5, 0), rect(0, 2, 2, 6, 8)}};
        const auto r = run(s);
        CHECK(codes(r) == V{"move", "3"});
        CHECK(r.order == std::vector<int>{1, 0});
        CHECK(r.moves == 1);
        CHECK(r.ids == visible_ids(s));
    }
    SECTION("z extents apart: no pair test at all") {
        const ScreenScene s{4, 4, {rect(0, 0, 4, 4, 1), rect(1, 1, 3, 3, 9)}};
        const auto r = run(s);
        CHECK(r.pair_tests == 0);
        CHECK(r.order == std::vector<int>{1, 0});
        CHECK(r.ids[5] == 0);
    }
    SECTION("one flat plane: the tie rule orders them (the lower index drawn later)") {
        const ScreenScene s{4, 4, {rect(0, 0, 3, 3, 5), rect(1, 1, 4, 4, 5)}};
        const auto r = run(s);
        CHECK(codes(r) == V{"3"});
        CHECK(r.order == std::vector<int>{1, 0});
        CHECK(r.ids == visible_ids(s));
        CHECK(r.ids[1 * 4 + 1] == 0);
    }
}

TEST_CASE("painters: cycles and splits", "[hsr][painters]") {
    SECTION("the example: three strips woven in a cycle, resolved by splitting") {
        const cg::Registry reg = cg::builtin_registry();
        const auto* a = reg.find("painters");
        REQUIRE(a);
        const Painters::Input in{read_screen_scene(cg::Reader(a->example()))};
        const auto r = run(in.scene);
        CHECK(r.splits >= 1);
        CHECK(r.ids == visible_ids(in.scene));
        CHECK(std::count(r.order.begin(), r.order.end(), 2) >= 2);  // P2 drawn in pieces
        CHECK(r.names.front() == "P3");                             // the backdrop first
    }
    SECTION("a cycle found by the marks: Q would move a second time") {
        const double t = 2;
        ScreenScene s{12, 12, {}};
        s.polygons.push_back(poly({{0, 2 - t / 2, 1.88172}, {10, 2 - t / 2, 9.79342}, {10, 2 + t / 2, 9.79342}, {0, 2 + t / 2, 1.88172}}));
        s.polygons.push_back(poly({{8 - t / 2, 0, 7.04865}, {8 + t / 2, 0, 7.04865}, {8 + t / 2, 11, 6.72534}, {8 - t / 2, 11, 6.72534}}));
        s.polygons.push_back(poly({{2 - t / 2, 0, 9.04127}, {2 + t / 2, 0, 9.04127}, {10 + t / 2, 10, 1.76575}, {10 - t / 2, 10, 1.76575}}));
        Stats stats;
        const auto r = run_checked(s, stats);
        CHECK(stats.cycles >= 1);
        CHECK(r.ids == visible_ids(s));
    }
    SECTION("folded along a shared edge (touching planes): split exactly") {
        const ScreenScene s{6, 6, {rect(0, 0, 4, 4, 5), poly({{4, 0, 5}, {0, 0, 1}, {0, 4, 1}, {4, 4, 5}})}};
        Stats stats;
        CHECK(run_checked(s, stats).ids == visible_ids(s));
        const ScreenScene t{6, 6, {poly({{4, 0, 5}, {0, 0, 1}, {0, 4, 1}, {4, 4, 5}}), rect(0, 0, 4, 4, 5)}};
        CHECK(run_checked(t, stats).ids == visible_ids(t));
    }
    SECTION("two polygons piercing each other: split along the intersection") {
        const ScreenScene s{8, 8, {tilted_rect(0, 0, 8, 8, 1, 1, 0), tilted_rect(0, 0, 8, 8, 9, -1, 0)}};
        const auto r = run(s);
        CHECK(r.splits >= 1);
        CHECK(r.ids == visible_ids(s));
    }
}

TEST_CASE("painters: degenerate scenes", "[hsr][painters]") {
    SECTION("no polygons") {
        const auto r = run({3, 2, {}});
        CHECK(r.ids == std::vector<int>(6, -1));
        CHECK(r.order.empty());
    }
    SECTION("a polygon off the screen and one covering no centre") {
        const ScreenScene s{4, 4, {rect(10, 10, 12, 12, 1), rect(1.1, 1.1, 1.4, 1.4, 2), rect(0, 0, 4, 4, 3)}};
        const auto r = run(s);
        CHECK(r.ids == visible_ids(s));
        CHECK(r.order.size() == 3);
    }
    SECTION("a 1 x 1 screen") {
        const ScreenScene s{1, 1, {rect(0, 0, 1, 1, 2), tilted_rect(0, 0, 1, 1, 1, 1, 1)}};
        CHECK(run(s).ids == visible_ids(s));
    }
}

TEST_CASE("painters: bad input is refused naming the field", "[hsr][painters]") {
    const cg::Registry reg = cg::builtin_registry();
    const auto* a = reg.find("painters");
    REQUIRE(a);
    auto error = [&](const cg::json& j) {
        try {
            a->create(j);
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    cg::json j = a->example();
    j["polygons"][0]["vertices"][2][2] = 100;  // bent out of its plane
    CHECK_THAT(error(j), Catch::Contains("polygons[0].vertices") && Catch::Contains("planar"));
    j = a->example();
    j["polygons"][1]["vertices"] = {{0, 0, 1}, {2, 2, 1}, {4, 4, 1}};
    CHECK_THAT(error(j), Catch::Contains("polygons[1].vertices") && Catch::Contains("no area"));
    j = a->example();
    j["polygons"][2]["vertices"][0][0] = "NaN";
    CHECK(error(j) != "accepted");
    CHECK_THROWS_AS(Painters::start({ScreenScene{4, 4, {poly({{0, 0, std::nan("")}, {1, 0, 0}, {0, 1, 0}})}}}), cg::InputError);
    j = a->example();
    j["order"] = 1;
    CHECK_THAT(error(j), Catch::Contains("order"));
}

TEST_CASE("painters: the same input gives the same trace, and copies finish alike", "[hsr][painters]") {
    const cg::Registry reg = cg::builtin_registry();
    const auto* a = reg.find("painters");
    REQUIRE(a);
    cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);
}

TEST_CASE("painters: exam problems match the brute force", "[hsr][painters]") {
    int moves = 0, tests[7] = {};
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const auto in = Painters::exam_input(rng);
        REQUIRE_NOTHROW(Painters::validate(in));
        const auto r = run(in.scene);
        REQUIRE(r.ids == visible_ids(in.scene));
        for (const auto& d : r.decisions) {
            moves += d.outcome == Painters::Outcome::Move;
            const std::string c = Painters::test_code(d);
            if (c.size() == 1 && c[0] >= '1' && c[0] <= '6') ++tests[c[0] - '0'];
        }
    }
    CHECK(moves > 0);
    for (int k = 1; k <= 5; ++k) CHECK(tests[k] > 0);
}

TEST_CASE("painters: pair tests grow like n squared (the complexity table)", "[hsr][painters]") {
    const auto rows = complexity({32}, {4, 16, 64}, 3, 11);
    REQUIRE(rows.size() == 3);
    for (const auto& r : rows) REQUIRE(r.painter_pair_tests >= 0);
    // 4× the polygons: well over 4× the pair tests (about 16× for n² growth).
    CHECK(rows[1].painter_pair_tests > 8 * rows[0].painter_pair_tests);
    CHECK(rows[2].painter_pair_tests > 8 * rows[1].painter_pair_tests);
    CHECK_THAT(complexity_table(rows), Catch::Contains("pair tests"));
}

TEST_CASE("painters: the picture — the list as a chart of z extents in drawing order", "[painters]") {
    const ScreenScene sc{4, 4, {rect(0, 0, 3, 3, 5), rect(1, 1, 4, 4, 2)}};
    auto s = Painters::start({sc});
    cg::Scene before;
    Painters::draw(s, before);
    REQUIRE(before.panels.size() == 1);
    CHECK(before.panels[0].kind == cg::PanelKind::Chart);
    CHECK(before.panels[0].polygons.size() == 2);  // a bar per input polygon
    const auto r = cg::run_to_end<Painters>(Painters::start({sc}));
    auto end = Painters::start({sc});
    while (!Painters::done(end)) Painters::step(end, nullptr);
    cg::Scene pic;
    Painters::draw(end, pic);
    REQUIRE(pic.panels.size() == 1);
    const cg::Panel& chart = pic.panels[0];
    REQUIRE(chart.polygons.size() == r.order.size());
    // The x axis names the places in the drawing order, the k-th bar at k.
    CHECK(chart.x.names == std::vector<std::string>{"1st", "2nd"});
    // Drawn back to front: the first bar is P0's z extent [5, 5], drawn (green), at "1st".
    CHECK(chart.polygons[0].style.role == cg::Role::Kept);
    CHECK(chart.polygons[0].points[0].x < 0);
    CHECK(chart.polygons[0].points[1].x > 0);
    CHECK(chart.polygons[0].points[0].y == 5);
    REQUIRE_FALSE(chart.labels.empty());
    CHECK(chart.labels[0].text == "P0");
}
