// Lessons, exam generators and worked examples, for every algorithm and every lesson file.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "io/worked.hpp"
#include "support/process.hpp"
#include "support/sweep.hpp"

namespace fs = std::filesystem;

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

// Every event an algorithm emits on these inputs.
std::set<std::string> emitted(const cg::Algorithm& a, const std::vector<cg::json>& inputs) {
    std::set<std::string> events;
    for (const cg::json& in : inputs) {
        auto run = a.create(in);
        while (!run->done()) {
            cg::StepInfo info;
            run->step(&info);
            events.insert(info.event);
        }
    }
    return events;
}

std::string read(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("lessons: every lesson file loads, its presets run, its notes name real events", "[lessons]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    for (const auto& e : lib.errors) FAIL_CHECK(e);
    REQUIRE_FALSE(lib.lessons.empty());
    double last_order = -1e300;
    for (const cg::Lesson& l : lib.lessons) {
        CAPTURE(l.file);
        CHECK(l.order >= last_order);  // listed in course order
        last_order = l.order;
        const cg::Algorithm* a = registry().find(l.algorithm);
        REQUIRE(a);
        std::vector<cg::json> inputs;
        for (const auto& p : l.presets) inputs.push_back(p.input);
        // Exam problems reach the rarer events (degenerate cases) too.
        if (cg::has_exam(*a))
            for (std::uint64_t seed = 0; seed < 300; ++seed) inputs.push_back(a->exam_input(seed));
        const std::set<std::string> events = emitted(*a, inputs);
        for (const cg::LessonEventNote& note : l.events) {
            CAPTURE(note.event);
            CHECK(events.count(note.event) == 1);
        }
        CHECK(l.sections.size() >= 3);
    }
}

TEST_CASE("lessons: every algorithm has a lesson and an exam generator", "[lessons][exam]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    for (const cg::Algorithm& a : registry().all()) {
        CAPTURE(a.spec->id);
        CHECK(lib.for_algorithm(a.spec->id) != nullptr);
        CHECK(cg::has_exam(a));
    }
}

TEST_CASE("lessons: broken files give clear errors and the others still load", "[lessons][errors]") {
    const fs::path dir = cg::test::output_path("broken-lessons");
    fs::create_directories(dir);
    fs::copy_file(CG_SOURCE_DIR "/lessons/040-liang-barsky.json", dir / "good.json",
                  fs::copy_options::overwrite_existing);
    const cg::json good = cg::json::parse(read(CG_SOURCE_DIR "/lessons/040-liang-barsky.json"));
    auto variant = [&](const std::string& name, auto&& edit) {
        cg::json j = good;
        j["id"] = name;
        edit(j);
        std::ofstream(dir / (name + ".json")) << j.dump(1);
    };
    std::ofstream(dir / "a-syntax.json") << "{\"id\": \"x\",\n  \"title\": }";
    variant("b-unknown-algorithm", [](cg::json& j) { j["algorithm"] = "no-such-thing"; });
    variant("c-unknown-event", [](cg::json& j) { j["events"]["exploding"] = "boom"; });
    variant("d-missing-title", [](cg::json& j) { j.erase("title"); });
    variant("e-bad-preset", [](cg::json& j) { j["presets"][1]["input"]["p0"] = {0, "two"}; });
    variant("f-bad-weight", [](cg::json& j) { j["exam"]["weight"] = "enormous"; });
    variant("g-no-presets", [](cg::json& j) { j["presets"] = cg::json::array(); });
    variant("h-extra-field", [](cg::json& j) { j["colour"] = "red"; });

    const cg::LessonLibrary lib = cg::load_lessons(dir.string(), registry());
    REQUIRE(lib.lessons.size() == 1);
    CHECK(lib.lessons[0].id == "liang-barsky");
    REQUIRE(lib.errors.size() == 8);
    auto error_for = [&](const std::string& file) {
        for (const auto& e : lib.errors)
            if (e.find(file) != std::string::npos) return e;
        return std::string("(none)");
    };
    CHECK_THAT(error_for("a-syntax.json"), Catch::Contains("title: not valid JSON: parse error at line 2"));
    CHECK_THAT(error_for("b-unknown-algorithm.json"), Catch::Contains("algorithm: unknown algorithm \"no-such-thing\""));
    CHECK_THAT(error_for("c-unknown-event.json"), Catch::Contains("events.exploding: is not an event of liang-barsky"));
    CHECK_THAT(error_for("d-missing-title.json"), Catch::Contains("title: is missing"));
    CHECK_THAT(error_for("e-bad-preset.json"), Catch::Contains("presets[1].input.p0[1]: must be a number"));
    CHECK_THAT(error_for("f-bad-weight.json"), Catch::Contains("exam.weight: must be high, medium, low or none"));
    CHECK_THAT(error_for("g-no-presets.json"), Catch::Contains("presets: must be a non-empty list"));
    CHECK_THAT(error_for("h-extra-field.json"), Catch::Contains("colour: is not a known field"));

    // The CLI lists the good one and reports each broken file on stderr.
    auto r = cg::test::run_process({"env", "CGSANDBOX_LESSONS=" + dir.string(), CG_BINARY, "lessons", "--check"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::StartsWith("liang-barsky\t"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 8);
}

TEST_CASE("exam: 1,000 seeds per algorithm give valid problems whose answers match the result", "[exam]") {
    for (const cg::Algorithm& a : registry().all()) {
        if (!cg::has_exam(a)) continue;
        CAPTURE(a.spec->id);
        for (std::uint64_t seed = 0; seed < cg::test::sweep(1000); ++seed) {
            CAPTURE(seed);
            const cg::ExamProblem p = cg::make_exam(a, seed);
            REQUIRE_FALSE(p.question.empty());
            REQUIRE_FALSE(p.answers.empty());
            // The input survives a round trip through text, as a student's file would.
            auto run = a.create(cg::parse_json(p.input.dump()));
            while (!run->done()) run->step(nullptr);
            const cg::json result = a.result(*run);
            for (const auto& field : p.answers)
                REQUIRE(p.expected.at(field) == cg::answer_value(result, field));
            // Right answers are graded right; a changed answer is graded wrong.
            for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
            cg::json wrong = p.expected;
            const std::string& f = p.answers[seed % p.answers.size()];
            if (wrong[f].is_number()) wrong[f] = wrong[f].get<double>() + 0.5;
            else if (wrong[f].is_boolean()) wrong[f] = !wrong[f].get<bool>();
            else if (wrong[f].is_null()) wrong[f] = cg::json::array({1, 2});
            else wrong[f] = nullptr;
            bool some_wrong = false;
            for (const auto& g : cg::grade(p, wrong)) some_wrong = some_wrong || !g.correct;
            CHECK(some_wrong);
        }
        // Same seed, same problem.
        CHECK(cg::exam_to_json(cg::make_exam(a, 42)) == cg::exam_to_json(cg::make_exam(a, 42)));
        CHECK(cg::exam_to_json(cg::make_exam(a, 42)) != cg::exam_to_json(cg::make_exam(a, 43)));
    }
}

TEST_CASE("exam: answers are read forgivingly and graded with a tolerance", "[exam]") {
    CHECK(cg::parse_answer(" (1, 3) ") == cg::json::array({1, 3}));
    CHECK(cg::parse_answer("yes") == true);
    CHECK(cg::parse_answer("none").is_null());
    CHECK(cg::parse_answer("0.333") == 0.333);
    CHECK(cg::answer_matches(1.0 / 3, cg::parse_answer("0.333")));
    CHECK_FALSE(cg::answer_matches(1.0 / 3, cg::parse_answer("0.33")));
    CHECK(cg::answer_matches(cg::json::array({1.0, 3.0}), cg::parse_answer("[1, 3.0001]")));
    CHECK_FALSE(cg::answer_matches(cg::json::array({1.0, 3.0}), cg::parse_answer("[1]")));
    CHECK_FALSE(cg::answer_matches(nullptr, cg::parse_answer("0")));
}

TEST_CASE("exam: the CLI's expected answers agree with `cgsandbox run` on the same input", "[exam][cli]") {
    for (const cg::Algorithm& a : registry().all()) {
        if (!cg::has_exam(a)) continue;
        for (int seed : {1, 7, 123}) {
            if (cg::test::kSanitized && seed != 1) break;  // one seed is enough to sanitize
            auto exam = cg::test::cgsandbox({"exam", a.spec->id, "--seed", std::to_string(seed), "--format", "json"});
            REQUIRE(exam.exit_code == 0);
            const cg::json p = cg::json::parse(exam.out);
            auto run = cg::test::cgsandbox({"run", a.spec->id, "--input", "-"}, p["input"].dump());
            REQUIRE(run.exit_code == 0);
            const cg::json result = cg::json::parse(run.out);
            for (const auto& field : p["answers"]) CHECK(p["expected"][field.get<std::string>()] == cg::answer_value(result, field.get<std::string>()));
            auto text = cg::test::cgsandbox({"exam", a.spec->id, "--seed", std::to_string(seed)});
            CHECK_THAT(text.out, Catch::Contains(p["question"].get<std::string>()));
        }
    }
}

TEST_CASE("worked: the Liang-Barsky worked example matches its golden file", "[worked]") {
    const std::string golden = read(CG_SOURCE_DIR "/tests/golden/liang-barsky-crossing-two-edges.md");
    REQUIRE_FALSE(golden.empty());
    auto r = cg::test::cgsandbox({"worked", "liang-barsky", "--preset", "a segment crossing two edges"});
    REQUIRE(r.exit_code == 0);
    CHECK(r.out == golden);
    // --out writes the same bytes; JSON carries the same steps.
    const std::string out = cg::test::output_path("worked.md");
    REQUIRE(cg::test::cgsandbox({"worked", "liang-barsky", "--preset", "a segment crossing two edges", "--out", out}).exit_code == 0);
    CHECK(read(out) == golden);
    auto j = cg::test::cgsandbox({"worked", "liang-barsky", "--preset", "a segment crossing two edges", "--format", "json"});
    const cg::json doc = cg::json::parse(j.out);
    CHECK(doc["steps"].size() == 6);
    CHECK(doc["result"]["q1"] == cg::json::array({2.0, 4.0}));
}

TEST_CASE("worked: an unknown preset lists the known ones", "[worked][errors]") {
    auto r = cg::test::cgsandbox({"worked", "liang-barsky", "--preset", "nope"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("no preset \"nope\"") && Catch::Contains("a segment crossing two edges"));
}
