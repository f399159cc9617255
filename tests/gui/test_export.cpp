// The viewer's "Export worked example…", called as the button calls it, without ImGui or SDL.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>

#include "io/lesson.hpp"
#include "support/process.hpp"
#include "viewer/export.hpp"
#include "viewer/session.hpp"

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

std::string read(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

// A viewer session with the source tree's lessons and `preset` of the Liang-Barsky lesson.
cg::viewer::Session lesson_session(const std::string& preset) {
    cg::viewer::Session s(registry());
    s.lessons = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    const cg::Lesson* lesson = s.lessons.find("liang-barsky");
    REQUIRE(lesson);
    s.open_lesson(*lesson);
    const cg::LessonPreset* p = lesson->preset(preset);
    REQUIRE(p);
    s.load_preset(*p);
    return s;
}

const char* kCrossing = "a segment crossing two edges";

}  // namespace

TEST_CASE("export: a lesson preset exports byte for byte as `cgsandbox worked` and the golden file",
          "[gui][export]") {
    const std::string golden = read(CG_SOURCE_DIR "/tests/golden/liang-barsky-crossing-two-edges.md");
    REQUIRE_FALSE(golden.empty());
    cg::viewer::Session s = lesson_session(kCrossing);
    REQUIRE(s.loaded_preset());
    CHECK(cg::viewer::export_worked(s, false) == golden);
    auto cli = cg::test::cgsandbox({"worked", "liang-barsky", "--preset", kCrossing});
    REQUIRE(cli.exit_code == 0);
    CHECK(cg::viewer::export_worked(s, false) == cli.out);

    SECTION("wherever the student has stepped to") {
        s.jump(3);
        CHECK(cg::viewer::export_worked(s, false) == golden);
    }
    SECTION("as JSON, like `worked --format json`") {
        const cg::json doc = cg::json::parse(cg::viewer::export_worked(s, true));
        CHECK(doc["subtitle"] == kCrossing);
        CHECK(doc["steps"].size() == 6);
        auto json_cli = cg::test::cgsandbox({"worked", "liang-barsky", "--preset", kCrossing,
                                             "--format", "json"});
        CHECK(cg::viewer::export_worked(s, true) == json_cli.out);
    }
    SECTION("an edited input is no longer the preset: no subtitle") {
        cg::json edited = s.input;
        edited["p1"] = cg::json::array({4, 5});
        REQUIRE(s.edit(edited));
        CHECK(s.loaded_preset() == nullptr);
        const std::string md = cg::viewer::export_worked(s, false);
        CHECK_THAT(md, Catch::StartsWith("# Liang-Barsky line clipping — worked example\n"));
        CHECK_THAT(md, Catch::Contains("P1 = (4, 5)"));
    }
}

TEST_CASE("export: in exam practice the document is the exam problem", "[gui][export][exam]") {
    cg::viewer::Session s(registry());
    const cg::Algorithm& a = *registry().find("liang-barsky");
    s.start_exam(a, 7);
    const std::string md = cg::viewer::export_worked(s, false);
    CHECK_THAT(md, Catch::StartsWith("# Liang-Barsky line clipping — worked example: exam problem, "
                                     "seed 7\n"));
    CHECK_THAT(md, Catch::Contains(cg::make_exam(a, 7).question));
}

TEST_CASE("export: the file type follows the name, and refused input is not exported",
          "[gui][export][errors]") {
    CHECK(cg::viewer::exports_json("out/worked.json"));
    CHECK_FALSE(cg::viewer::exports_json("worked.md"));
    CHECK_FALSE(cg::viewer::exports_json("json"));
    CHECK(cg::viewer::default_export_path(*registry().find("liang-barsky")) ==
          "worked-liang-barsky.md");

    cg::viewer::Session s(registry());
    CHECK_THROWS_AS(cg::viewer::export_worked(s, false), cg::InputError);  // nothing runs
    s.choose(*registry().find("liang-barsky"));
    CHECK(s.export_path == "worked-liang-barsky.md");
    cg::json bad = s.input;
    bad["p0"] = "nowhere";
    CHECK_FALSE(s.edit(bad));
    CHECK_THROWS_WITH(cg::viewer::export_worked(s, false), Catch::Contains("p0"));
}
