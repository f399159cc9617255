// The viewer under bad input: handles dragged onto each other, NaN typed into a field, a broken
// checkpoint or lesson opened. The viewer's session shows why an input was refused and keeps
// its last run; the CLI's render path (under Xvfb) and the lesson loader refuse broken files
// with one clear line and keep the good ones.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "checkpoint.hpp"
#include "io/lesson.hpp"
#include "support/process.hpp"
#include "viewer/session.hpp"

using cg::json;

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Whether what the canvas would draw is finite.
bool scene_finite(const cg::Scene& s) {
    for (const auto& p : s.points) if (!finite(p.p)) return false;
    for (const auto& g : s.segments) if (!finite(g.a) || !finite(g.b)) return false;
    for (const auto& p : s.polygons)
        for (auto q : p.points) if (!finite(q)) return false;
    for (const auto& h : s.handles) if (!finite(h.p)) return false;
    return true;
}

struct Leaf {
    std::string pointer, path;
};

void numeric_leaves(const json& j, const std::string& pointer, const std::string& path,
                    std::vector<Leaf>& out) {
    if (j.is_number()) out.push_back({pointer, path});
    if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i)
            numeric_leaves(j[i], pointer + "/" + std::to_string(i), path + "[" + std::to_string(i) + "]", out);
    if (j.is_object())
        for (auto it = j.begin(); it != j.end(); ++it)
            numeric_leaves(it.value(), pointer + "/" + it.key(), path + (path.empty() ? "" : ".") + it.key(), out);
}

// After a refusal the viewer still has its last run, and moving through it works.
void check_still_running(cg::viewer::Session& s, std::size_t index_before) {
    REQUIRE(s.timeline);
    CHECK(s.index() == index_before);
    CHECK(scene_finite(s.scene()));
    s.run_to_end();
    s.step_back();
    s.jump(0);
    CHECK(s.index() == 0);
}

}  // namespace

TEST_CASE("viewer: dragging a handle onto another runs or is refused naming a field, and the viewer keeps going",
          "[gui][errors][robustness]") {
    std::size_t pairs = 0, refused = 0;
    for (const cg::Algorithm& a : registry().all()) {
        cg::viewer::Session s(registry());
        s.choose(a);
        REQUIRE(s.timeline);
        const std::vector<cg::Handle2> handles = s.scene().handles;
        const json good = s.input;
        for (std::size_t i = 0; i < handles.size(); ++i)
            for (std::size_t j = 0; j < handles.size(); ++j) {
                if (i == j || handles[i].x_field.empty() || handles[i].y_field.empty()) continue;
                CAPTURE(a.spec->id, handles[i].name, handles[j].name);
                s.try_start(a, good, 2);
                const std::size_t before = s.index();
                json dragged = good;
                dragged[json::json_pointer(handles[i].x_field)] = handles[j].p.x;
                dragged[json::json_pointer(handles[i].y_field)] = handles[j].p.y;
                ++pairs;
                if (s.edit(dragged)) {
                    CHECK(s.input_error.empty());
                    CHECK(s.input == dragged);
                    check_still_running(s, std::min(before, s.index()));
                } else {
                    ++refused;
                    CAPTURE(s.input_error);
                    // The editor keeps the dragged input and says which field is wrong.
                    CHECK(s.input == dragged);
                    CHECK(s.input_error.find(": ") != std::string::npos);
                    check_still_running(s, before);
                }
            }
    }
    CHECK(pairs > 20);
    WARN(pairs << " handle pairs dragged together, " << refused << " refused");
}

TEST_CASE("viewer: NaN or infinity typed into any number is refused naming the field, and the run stays",
          "[gui][errors][robustness]") {
    for (const cg::Algorithm& a : registry().all()) {
        cg::viewer::Session s(registry());
        s.choose(a);
        const json good = s.input;
        std::vector<Leaf> leaves;
        numeric_leaves(good, "", "", leaves);
        CAPTURE(a.spec->id);
        if (leaves.empty()) {
            // An input of text alone (affine-combination's expressions): its numbers are typed
            // inside the text, and a broken expression is refused in the same way.
            REQUIRE(a.spec->id == "affine-combination");
            for (const char* bad : {"(P + ", "1e999 P", "P $ Q"}) {
                CAPTURE(bad);
                s.try_start(a, good, 1);
                const std::size_t before = s.index();
                json typed = good;
                typed["expressions"][0] = bad;
                CHECK_FALSE(s.edit(typed));
                CHECK(s.input_error.rfind("expressions[0]: at character ", 0) == 0);
                check_still_running(s, before);
            }
            continue;
        }
        for (const Leaf& leaf : leaves)
            for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity()}) {
                CAPTURE(a.spec->id, leaf.path, bad);
                s.try_start(a, good, 1);
                const std::size_t before = s.index();
                json typed = good;
                typed[json::json_pointer(leaf.pointer)] = bad;
                CHECK_FALSE(s.edit(typed));
                CAPTURE(s.input_error);
                // The field's own path, or (for a value checked as part of a list) its list's.
                const std::string top = leaf.path.substr(0, leaf.path.find_first_of(".["));
                CHECK(s.input_error.rfind(top, 0) == 0);
                // "must be a finite number", or for a count or index "must be an integer".
                CHECK((s.input_error.find("finite") != std::string::npos ||
                       s.input_error.find("integer") != std::string::npos));
                check_still_running(s, before);
            }
    }
}

TEST_CASE("viewer: a broken checkpoint shows its error and the viewer carries on", "[gui][errors][robustness]") {
    cg::viewer::Session s(registry());
    s.choose(*registry().find("liang-barsky"));
    cg::Checkpoint c;
    c.algorithm = "no-such-algorithm";
    s.load(c);
    CHECK(s.status_is_error);
    CHECK(s.timeline);  // the run before is still there

    c.algorithm = "sutherland-hodgman";
    c.input = json::parse(R"({"window": [[0, 0], [2, 2], [4, 4]], "polygon": [[1, 1], [3, 1], [2, 3]]})");
    c.step = 5;
    s.load(c);
    CHECK_THAT(s.input_error, Catch::Contains("window: has zero area"));
    // Another algorithm's refused input: the editor shows it, the canvas is empty, and choosing
    // again works.
    s.choose(*registry().find("sutherland-hodgman"));
    REQUIRE(s.timeline);
    s.run_to_end();
    CHECK(s.at_end());

    // A checkpoint far past the end is clamped to it.
    c.input = registry().find("sutherland-hodgman")->example();
    c.step = std::size_t{1} << 40;
    s.load(c);
    CHECK(s.input_error.empty());
    CHECK(s.at_end());
}

TEST_CASE("viewer: broken checkpoints are refused by render in one line naming the problem", "[gui][errors][robustness]") {
    struct Case {
        const char* name;
        std::string text, expected;
    };
    const std::vector<Case> cases = {
        {"not JSON", "{\"algorithm\": ", "not valid JSON"},
        {"empty", "", "not valid JSON"},
        {"unknown algorithm", R"({"algorithm": "nope", "input": {}, "step": 0})", "algorithm: unknown algorithm \"nope\""},
        {"negative step", R"({"algorithm": "liang-barsky", "input": {}, "step": -1})", "step: must be 0 or more"},
        {"refused input", R"({"algorithm": "sutherland-hodgman", "step": 0,
                              "input": {"window": [[0, 0], [2, 2], [4, 4]], "polygon": [[1, 1], [3, 1], [2, 3]]}})",
         "window: has zero area"},
        {"NaN zoom", R"({"algorithm": "liang-barsky", "input": {}, "step": 0, "view": {"center": [0, 0], "zoom": NaN}})",
         "view.zoom: not valid JSON"},
        {"zero zoom", R"({"algorithm": "liang-barsky", "input": {}, "step": 0, "view": {"center": [0, 0], "zoom": 0}})",
         "view.zoom: must be positive"},
        {"deeply nested", R"({"algorithm": "liang-barsky", "step": 0, "input": )" + std::string(100000, '[') +
                              std::string(100000, ']') + "}",
         "(the limit)"},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.name) {
            const std::string path = cg::test::write_temp("broken-checkpoint.json", c.text);
            auto r = cg::test::run_process({"xvfb-run", "-a", CG_BINARY, "render", "--checkpoint", path,
                                            "--out", cg::test::output_path("never.png")});
            CHECK(r.exit_code == 2);
            CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
            CHECK_THAT(r.err, Catch::StartsWith("cgsandbox: " + path + ": ") && Catch::Contains(c.expected));
        }
    }
    SECTION("a checkpoint far past the end renders the end") {
        const std::string path = cg::test::write_temp(
            "far-checkpoint.json",
            R"({"algorithm": "liang-barsky", "step": 1000000000000, "input": {"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [2, 2], "p1": [2, 2]}})");
        auto r = cg::test::run_process({"xvfb-run", "-a", CG_BINARY, "render", "--checkpoint", path,
                                        "--size", "64x48", "--out", cg::test::output_path("far.png")});
        CHECK(r.exit_code == 0);
        CHECK(r.err.empty());
    }
    SECTION("a 10^9-pixel picture is refused") {
        auto r = cg::test::cgsandbox({"render", "liang-barsky", "--size", "40000x25000", "--out",
                                      cg::test::output_path("never.png")});
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.err, Catch::Contains("--size must be WxH with 16 <= W, H <= 8192"));
    }
}

TEST_CASE("viewer: a lessons folder full of broken files lists each once, and the good lesson still opens",
          "[gui][errors][lessons][robustness]") {
    namespace fs = std::filesystem;
    const fs::path dir = cg::test::output_path("broken-lessons");
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(CG_SOURCE_DIR "/lessons/040-liang-barsky.json", dir / "good.json");
    const json good = json::parse(std::ifstream(CG_SOURCE_DIR "/lessons/040-liang-barsky.json"));
    auto variant = [&](const std::string& name, auto change) {
        json j = good;
        j["id"] = name;
        change(j);
        std::ofstream(dir / (name + ".json")) << j.dump();
    };
    std::ofstream(dir / "not-json.json") << R"({"id": "x", "title": )";
    std::ofstream(dir / "empty.json") << "";
    std::ofstream(dir / "nested.json") << std::string(10000, '[') << std::string(10000, ']');
    variant("bad-preset", [](json& j) { j["presets"][0]["input"]["p0"] = json::array({1, "two"}); });
    variant("no-presets", [](json& j) { j["presets"] = json::array(); });
    variant("unknown-algorithm", [](json& j) { j["algorithm"] = "nope"; });
    variant("unknown-event", [](json& j) { j["events"]["no-such-event"] = "text"; });
    variant("wrong-types", [](json& j) { j["sections"] = 3; });
    const std::size_t broken = 8;

    const std::string env = "CGSANDBOX_LESSONS=" + dir.string();
    auto listed = cg::test::run_process({"env", env, CG_BINARY, "lessons", "--check"});
    CHECK(listed.exit_code == 2);
    CHECK(std::count(listed.err.begin(), listed.err.end(), '\n') == std::ptrdiff_t(broken));
    CHECK_THAT(listed.out, Catch::Contains("liang-barsky\t"));
    for (const char* name : {"not-json", "empty", "nested", "bad-preset", "no-presets", "unknown-algorithm",
                             "unknown-event", "wrong-types"})
        CHECK_THAT(listed.err, Catch::Contains(std::string(name) + ".json: "));
    CHECK_THAT(listed.err, Catch::Contains("presets[0].input.p0[1]: must be a number"));

    // The viewer with that folder: the good lesson opens and draws, the broken ones are refused.
    auto r = cg::test::run_process({"env", env, "xvfb-run", "-a", CG_BINARY, "render", "--lesson", "liang-barsky",
                                    "--full", "--size", "640x480", "--out", cg::test::output_path("good-lesson.png")});
    CHECK(r.exit_code == 0);
    auto bad = cg::test::run_process({"env", env, CG_BINARY, "render", "--lesson", "bad-preset", "--out",
                                      cg::test::output_path("never.png")});
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.err, Catch::Contains("no lesson \"bad-preset\""));
}
