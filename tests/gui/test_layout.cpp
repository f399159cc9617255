// The picture's layout, from the viewer's own drawing pass run without a GPU (layout_pass.hpp):
// every lesson preset at its first, middle and last step, in the whole window at 1280×720 and
// 1920×1080 — no two labels overlap, none leaves its panel or runs under the title, the title
// is whole, every focus element is at least 24 px, every chart and image uses at least half of
// its panel.
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <set>
#include <sstream>

#include "io/lesson.hpp"
#include "support/sweep.hpp"
#include "io/registry.hpp"
#include "viewer/layout_pass.hpp"
#include "viewer/session.hpp"

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

std::size_t run_length(const cg::Algorithm& a, const cg::json& input) {
    auto run = a.create(input);
    std::size_t n = 0;
    while (!run->done()) run->step(nullptr), ++n;
    return n;
}

}  // namespace

TEST_CASE("layout: boxes, the views' split and the checks on a record", "[layout]") {
    using cg::viewer::Box;
    cg::Scene scene;
    scene.points.push_back({{0, 0}, "P"});
    cg::add_chart(scene, "f(t)", {"t"}, {"f"});
    const Box area{{0, 0}, {900, 500}};
    const auto views = cg::viewer::layout_views(scene, area);
    REQUIRE(views.size() == 2);
    CHECK(views[0].kind == cg::viewer::ViewKind::World2d);
    CHECK(views[1].kind == cg::viewer::ViewKind::Chart);
    CHECK(views[0].box.max.x < views[1].box.min.x);  // wide: side by side
    CHECK(views[0].box.max.x - views[0].box.min.x > views[1].box.max.x - views[1].box.min.x);
    const auto tall = cg::viewer::layout_views(scene, Box{{0, 0}, {400, 800}});
    CHECK(tall[0].box.max.y < tall[1].box.min.y);  // tall: stacked

    cg::viewer::LayoutRecord r;
    r.canvas = area;
    r.title = {{0, 0}, {900, 30}};
    r.panels.push_back(
        {cg::viewer::ViewKind::World2d, {{0, 30}, {500, 500}}, {{10, 40}, {490, 490}}});
    r.panels.push_back(
        {cg::viewer::ViewKind::Chart, {{506, 30}, {900, 500}}, {{520, 40}, {600, 100}}});
    r.labels.push_back({"a", {{10, 40}, {40, 60}}, 0});
    r.labels.push_back({"b", {{30, 50}, {60, 70}}, 0});    // overlaps a
    r.labels.push_back({"c", {{480, 40}, {520, 60}}, 0});  // leaves its panel
    r.labels.push_back({"d", {{100, 20}, {130, 40}}, 0});  // under the title
    r.focus.push_back({{{100, 100}, {110, 110}}, 0});      // 10 px
    const auto problems = cg::viewer::layout_problems(r);
    CAPTURE(problems);
    // a and b overlap, c and d leave their panel, d is under the title, the focus element is
    // small, the chart uses a fraction of its panel.
    CHECK(problems.size() == 6);
    r.title_fits = false;
    CHECK(cg::viewer::layout_problems(r).size() == 7);
}

TEST_CASE("layout: every lesson preset, first, middle and last step, at 1280x720 and 1920x1080",
          "[layout][lessons]") {
    const cg::LessonLibrary lessons = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    REQUIRE(lessons.errors.empty());
    // CG_LAYOUT_LESSONS="id id …": only those lessons (while reworking their pictures).
    std::set<std::string> only;
    if (const char* ids = std::getenv("CG_LAYOUT_LESSONS")) {
        std::istringstream in(ids);
        for (std::string id; in >> id;) only.insert(id);
    }
    cg::viewer::LayoutPass pass;
    std::size_t pictures = 0, failures = 0, labels = 0, dropped = 0;
    const auto start = std::chrono::steady_clock::now();
    for (const cg::Lesson& l : lessons.lessons) {
        if (!only.empty() && !only.count(l.id)) continue;
        const cg::Algorithm* a = registry().find(l.algorithm);
        REQUIRE(a);
        for (const cg::LessonPreset& p : l.presets) {
            // Under the sanitizers (7× slower) each lesson's first preset: the same drawing
            // code, at a seventh of the cost.
            if (cg::test::kSanitized && &p != &l.presets.front()) continue;
            const std::size_t n = run_length(*a, p.input);
            for (const std::size_t step : {std::size_t{0}, n / 2, n}) {
                for (const auto [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}}) {
                    cg::viewer::Session s(registry());
                    cg::Checkpoint c;
                    c.algorithm = l.algorithm;
                    c.input = p.input;
                    c.step = step;
                    c.lesson = l.id;
                    c.preset = p.name;
                    cg::viewer::open_checkpoint(s, c, lessons);
                    const cg::viewer::LayoutRecord r = pass.record(s, w, h, true);
                    ++pictures;
                    labels += r.labels.size();
                    dropped += r.dropped.size();
                    for (const std::string& problem : cg::viewer::layout_problems(r))
                        if (++failures <= 60)
                            FAIL_CHECK(l.id << " \"" << p.name << "\" step " << step << " at " << w
                                            << "x" << h << ": " << problem);
                    CHECK(r.panels.size() >= 1);
                }
            }
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    WARN(pictures << " pictures laid out in " << seconds << " s; " << labels << " labels placed, "
                  << dropped << " dropped for want of room; " << failures << " problems");
    CHECK(failures == 0);
}
