// The CLI as a user reaches it: build/bin/cgsandbox, its output and its exit codes.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/json.hpp"
#include "support/process.hpp"

using cg::json;
using cg::test::cgsandbox;

namespace {
const std::string kGood =
    R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 6]})";
}

TEST_CASE("process: a run whose LeakSanitizer tracer crashed is tried once more without the leak check, any other failure is not", "[cli]") {
    const std::string count = cg::test::output_path("lsan-retry.count");
    auto runs = [&] {
        std::ifstream f(count);
        return std::string(std::istreambuf_iterator<char>(f), {});
    };
    std::filesystem::remove(count);
    // The first run "crashes"; the second, seeing detect_leaks=0, succeeds.
    auto r = cg::test::run_process(
        {"sh", "-c", "echo run >> " + count + "; case \"$ASAN_OPTIONS\" in *detect_leaks=0) exit 0;; esac;" +
                         " echo '==1==LeakSanitizer has encountered a fatal error' >&2; exit 1"});
    CHECK(r.exit_code == 0);
    CHECK(runs() == "run\nrun\n");
    std::filesystem::remove(count);
    r = cg::test::run_process({"sh", "-c", "echo run >> " + count + "; echo 'detected memory leaks' >&2; exit 1"});
    CHECK(r.exit_code == 1);
    CHECK(runs() == "run\n");
}

TEST_CASE("cli: list names each algorithm with its title", "[cli]") {
    auto r = cgsandbox({"list"});
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("liang-barsky\tLiang-Barsky line clipping\n"));
}

TEST_CASE("cli: example prints an input that runs", "[cli]") {
    auto ex = cgsandbox({"example", "liang-barsky"});
    REQUIRE(ex.exit_code == 0);
    json input = json::parse(ex.out);
    CHECK(input.contains("window"));
    auto r = cgsandbox({"run", "liang-barsky", "--input", "-"}, ex.out);
    CHECK(r.exit_code == 0);
    CHECK(r.err.empty());
}

TEST_CASE("cli: run prints the result as one JSON object", "[cli]") {
    auto r = cgsandbox({"run", "liang-barsky", "--input", cg::test::write_temp("good.json", kGood)});
    REQUIRE(r.exit_code == 0);
    // The five values, then the table of edges a student writes.
    CHECK(r.out ==
          R"({"visible":true,"t_enter":0.25,"t_leave":0.5,"q0":[1.0,3.0],"q1":[2.0,4.0],)"
          R"("edges":{"left":{"p":-4.0,"q":-1.0,"r":0.25,"crossing":"enters"},)"
          R"("right":{"p":4.0,"q":5.0,"r":1.25,"crossing":"leaves"},)"
          R"("bottom":{"p":-4.0,"q":1.0,"r":-0.25,"crossing":"enters"},)"
          R"("top":{"p":4.0,"q":2.0,"r":0.5,"crossing":"leaves"}}})" "\n");

    auto missed = cgsandbox({"run", "liang-barsky", "--input", "-"},
                            R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 5], "p1": [6, 5]})");
    REQUIRE(missed.exit_code == 0);
    // Parallel to the top edge and above it: rejected there, r null where p = 0.
    CHECK(missed.out ==
          R"({"visible":false,"t_enter":0.16666666666666666,"t_leave":0.8333333333333334,)"
          R"("q0":null,"q1":null,"edges":{"left":{"p":-6.0,"q":-1.0,"r":0.16666666666666666,)"
          R"("crossing":"enters"},"right":{"p":6.0,"q":5.0,"r":0.8333333333333334,)"
          R"("crossing":"leaves"},"bottom":{"p":0.0,"q":4.0,"r":null,)"
          R"("crossing":"parallel inside"},"top":{"p":0.0,"q":-1.0,"r":null,)"
          R"("crossing":"parallel outside"}}})" "\n");
}

TEST_CASE("cli: run --trace prints one JSON line per step, then the result", "[cli]") {
    auto r = cgsandbox({"run", "liang-barsky", "--trace"});
    REQUIRE(r.exit_code == 0);
    std::vector<json> lines;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) lines.push_back(json::parse(line));
    REQUIRE(lines.size() == 7);
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
        CHECK(lines[i]["index"] == i + 1);
        CHECK(lines[i]["event"].is_string());
        CHECK(lines[i]["line"].is_number_integer());
        CHECK(lines[i]["narration"].is_string());
        CHECK(lines[i]["variables"].is_object());
    }
    CHECK(lines[1]["event"] == "entering");
    CHECK(lines[1]["variables"]["r_k"] == 0.25);
    CHECK(lines.back()["visible"] == true);
    // Byte-identical on a second run.
    CHECK(cgsandbox({"run", "liang-barsky", "--trace"}).out == r.out);
}

TEST_CASE("cli: bad input is one clear line naming file and field, exit 2", "[cli][errors]") {
    struct Case {
        const char* name;
        std::string text;
        std::string expected;  // what stderr must contain after the file name
    };
    const std::vector<Case> cases = {
        {"missing field", R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5}, "p0": [0, 2], "p1": [4, 6]})",
         "window.ymax: is missing"},
        {"wrong type", R"({"window": {"xmin": "one", "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 6]})",
         "window.xmin: must be a number, got a string (\"one\")"},
        {"point of wrong size", R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0], "p1": [4, 6]})",
         "p0: must be a point [x, y]"},
        {"null coordinate", R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, null], "p1": [4, 6]})",
         "p0[1]: must be a number, got null"},
        {"NaN literal", R"({"window": {"xmin": NaN, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 6]})",
         "window.xmin: not valid JSON: parse error at line 1"},
        {"infinity by overflow", R"({"window": {"xmin": 1e999, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 6]})",
         "window.xmin: not valid JSON: number overflow"},
        {"xmin > xmax", R"({"window": {"xmin": 6, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 6]})",
         "window.xmin: must not exceed window.xmax (6 > 5)"},
        {"unknown field", R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 6], "p2": [1, 1]})",
         "p2: is not a known field (expected: window, p0, p1)"},
        {"not an object", "[1, 2, 3]", "the input must be a JSON object"},
        {"empty file", "", "not valid JSON"},
        {"overflowing differences", R"({"window": {"xmin": -1e308, "ymin": 1, "xmax": 1e308, "ymax": 4}, "p0": [0, 2], "p1": [4, 6]})",
         "differences overflow"},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.name) {
            const std::string path = cg::test::write_temp("bad.json", c.text);
            auto r = cgsandbox({"run", "liang-barsky", "--input", path});
            CHECK(r.exit_code == 2);
            CHECK(r.out.empty());
            CHECK_THAT(r.err, Catch::StartsWith("cgsandbox: " + path + ": ") && Catch::Contains(c.expected));
            CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        }
    }
    SECTION("from stdin the source is named <stdin>") {
        auto r = cgsandbox({"run", "liang-barsky", "--input", "-"}, "{");
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.err, Catch::StartsWith("cgsandbox: <stdin>: not valid JSON"));
    }
    SECTION("a missing file") {
        auto r = cgsandbox({"run", "liang-barsky", "--input", "/nonexistent/in.json"});
        CHECK(r.exit_code == 2);
        CHECK(r.err == "cgsandbox: /nonexistent/in.json: cannot open file\n");
    }
    SECTION("an unknown algorithm") {
        auto r = cgsandbox({"run", "no-such-thing"});
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.err, Catch::Contains("unknown algorithm \"no-such-thing\""));
    }
    SECTION("an unknown option") {
        auto r = cgsandbox({"run", "liang-barsky", "--frobnicate"});
        CHECK(r.exit_code == 2);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
}

TEST_CASE("cli: --help works on every command", "[cli]") {
    for (const char* cmd : {"list", "example", "run", "render", "predict", "compare", "bug", "check"}) {
        auto r = cgsandbox({cmd, "--help"});
        CAPTURE(cmd);
        CHECK(r.exit_code == 0);
        CHECK_THAT(r.out, Catch::Contains("Usage") || Catch::Contains("USAGE") || Catch::Contains("usage"));
    }
    CHECK(cgsandbox({"--help"}).exit_code == 0);
}

TEST_CASE("cli: complexity accel prints tests per ray for each n, checked against brute force",
          "[cli]") {
    auto r = cgsandbox({"complexity", "accel", "--counts", "10", "100", "--rays", "20"});
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("brute force: n tests") && Catch::Contains("bvh box") &&
                          Catch::Contains("grid prim") && Catch::Contains("20/20"));
    auto bad = cgsandbox({"complexity", "accel", "--counts", "0"});
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.err, Catch::Contains("--counts"));
}

TEST_CASE("cli: the viewer without a display says so in one line", "[cli][gui]") {
    auto r = cg::test::run_process({"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", CG_BINARY});
    CHECK(r.exit_code != 0);
    CHECK(r.exit_code < 128);  // not a crash
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_THAT(r.err, Catch::Contains("display") && Catch::Contains("xvfb-run") &&
                          Catch::Contains("cgsandbox render"));
}

// --- the study modes (docs/study-modes.md) ---

namespace {
std::vector<json> json_lines(const std::string& text) {
    std::vector<json> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(json::parse(line));
    return lines;
}
}  // namespace

TEST_CASE("cli: predict prints one question per step, and grades a file of predictions", "[cli][study]") {
    auto q = cgsandbox({"predict", "liang-barsky"});
    REQUIRE(q.exit_code == 0);
    for (int k = 1; k <= 6; ++k) CHECK_THAT(q.out, Catch::Contains("Step " + std::to_string(k) + ". "));
    CHECK_THAT(q.out, !Catch::Contains("Step 7. "));
    CHECK_THAT(q.out, Catch::Contains("entering: p_k < 0"));
    auto qj = cgsandbox({"predict", "liang-barsky", "--format", "json"});
    CHECK(json_lines(qj.out).size() == 6);

    // Perfect predictions, made from the trace itself: every step right.
    std::vector<json> trace = json_lines(cgsandbox({"run", "liang-barsky", "--trace"}).out);
    trace.pop_back();  // the result
    std::string answers;
    for (const json& s : trace)
        answers += json{{"step", s["index"]}, {"event", s["event"]}, {"variables", s["variables"]}}.dump() + "\n";
    auto r = cgsandbox({"predict", "liang-barsky", "--answers", cg::test::write_temp("answers.jsonl", answers)});
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("score: 6 of 6 predicted steps right"));

    // Step 3 predicted as entering: wrong, with the truth, listed to revisit.
    std::string wrong;
    for (const json& s : trace)
        wrong += json{{"step", s["index"]}, {"event", s["index"] == 3 ? "entering" : s["event"]}, {"variables", s["variables"]}}.dump() + "\n";
    r = cgsandbox({"predict", "liang-barsky", "--answers", cg::test::write_temp("wrong.jsonl", wrong)});
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("step 3: wrong — leaving"));
    CHECK_THAT(r.out, Catch::Contains("(the step is leaving, not entering"));
    CHECK_THAT(r.out, Catch::Contains("score: 5 of 6"));
    CHECK_THAT(r.out, Catch::Contains("to revisit: steps 3"));
    r = cgsandbox({"predict", "liang-barsky", "--format", "json", "--answers", cg::test::write_temp("wrong.jsonl", wrong)});
    const json j = json::parse(r.out);
    CHECK(j["score"]["right"] == 5);
    CHECK(j["wrong"] == json::array({3}));

    auto bad = cgsandbox({"predict", "liang-barsky", "--answers", cg::test::write_temp("bad.jsonl", "{\"step\": 1, \"event\": \"setup\"}\n{\"step\": \"two\"}\n")});
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.err, Catch::Contains("bad.jsonl: prediction 2.step"));
    auto both = cgsandbox({"predict", "liang-barsky", "--seed", "3", "--preset", "x"});
    CHECK(both.exit_code == 2);
    CHECK_THAT(both.err, Catch::Contains("give one of --input, --preset and --seed"));
    CHECK(cgsandbox({"predict", "liang-barsky", "--seed", "3"}).exit_code == 0);
}

TEST_CASE("cli: check compares a student's trace: exit 0 agree, 1 differ, 2 unreadable", "[cli][study]") {
    const std::string mine = cgsandbox({"run", "liang-barsky", "--trace"}).out;
    auto r = cgsandbox({"check", "liang-barsky", "--trace", cg::test::write_temp("mine.jsonl", mine)});
    CHECK(r.exit_code == 0);
    CHECK(r.out == "all 6 steps agree with liang-barsky\n");

    std::string off = mine;
    off.replace(off.find("\"t_leave\":0.5"), 13, "\"t_leave\":0.6");
    r = cgsandbox({"check", "liang-barsky", "--trace", cg::test::write_temp("off.jsonl", off)});
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::StartsWith("step 5 differs (4 steps before it agree):\n  t_leave: expected 0.5, got 0.6\n"));
    CHECK_THAT(r.out, Catch::Contains("line 10:"));
    r = cgsandbox({"check", "liang-barsky", "--format", "json", "--trace", cg::test::write_temp("off.jsonl", off)});
    CHECK(r.exit_code == 1);
    const json j = json::parse(r.out);
    CHECK(j["first_difference"] == 5);
    CHECK(j["expected_step"]["event"] == "leaving");

    r = cgsandbox({"check", "liang-barsky", "--trace", cg::test::write_temp("broken.jsonl", "{\"event\": \"setup\"}\n[1]\n")});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("broken.jsonl: line 2: each line must be a JSON object"));
    r = cgsandbox({"check", "liang-barsky", "--trace", "/nonexistent/mine.jsonl"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("/nonexistent/mine.jsonl"));
    r = cgsandbox({"check", "liang-barsky", "--input", "-", "--trace", cg::test::write_temp("mine.jsonl", mine)}, "{\"window\": 1}");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("<stdin>: window"));
}

TEST_CASE("cli: bug plants one mistake, deterministically, and grades the first wrong step", "[cli][study]") {
    auto planted = cgsandbox({"bug", "liang-barsky", "--seed", "4", "--input", cg::test::write_temp("good.json", kGood)});
    REQUIRE(planted.exit_code == 0);
    CHECK(cgsandbox({"bug", "liang-barsky", "--seed", "4", "--input", cg::test::write_temp("good.json", kGood)}).out == planted.out);
    std::vector<json> truth = json_lines(cgsandbox({"run", "liang-barsky", "--trace", "--input", cg::test::write_temp("good.json", kGood)}).out);
    const std::vector<json> working = json_lines(planted.out);
    REQUIRE(working.size() + 1 == truth.size());
    long long first = 0;
    for (std::size_t i = 0; i < working.size() && !first; ++i) {
        CHECK(working[i]["narration"] == "");  // hidden: it would give the step away
        if (working[i]["event"] != truth[i]["event"] || working[i]["variables"] != truth[i]["variables"])
            first = static_cast<long long>(i) + 1;
    }
    REQUIRE(first > 0);
    auto right = cgsandbox({"bug", "liang-barsky", "--seed", "4", "--input", cg::test::write_temp("good.json", kGood), "--answer", std::to_string(first)});
    CHECK(right.exit_code == 0);
    CHECK_THAT(right.out, Catch::StartsWith("Right: step " + std::to_string(first)));
    auto wrong = cgsandbox({"bug", "liang-barsky", "--seed", "4", "--input", cg::test::write_temp("good.json", kGood), "--answer", first == 1 ? "2" : "1"});
    CHECK(wrong.exit_code == 1);
    CHECK_THAT(wrong.out, Catch::StartsWith("Wrong: "));
    CHECK_THAT(wrong.out, Catch::Contains("The right step " + std::to_string(first) + ": "));
    auto out_of_range = cgsandbox({"bug", "liang-barsky", "--seed", "4", "--answer", "99"});
    CHECK(out_of_range.exit_code == 2);
    CHECK_THAT(out_of_range.err, Catch::Contains("--answer must be a step from 1 to"));
    CHECK(cgsandbox({"bug", "liang-barsky"}).exit_code == 2);  // --seed is required
}

TEST_CASE("cli: compare runs two sides on one input and says where they part", "[cli][study]") {
    auto r = cgsandbox({"compare", "z-buffer", "warnock", "--input", "-"}, cgsandbox({"example", "warnock"}).out);
    REQUIRE(r.exit_code == 0);
    json j = json::parse(r.out);
    CHECK(j["agree"] == true);
    CHECK(j["costs"]["z-buffer"].contains("compares"));
    CHECK(j["costs"]["warnock"].contains("areas"));

    r = cgsandbox({"compare", "liang-barsky", "liang-barsky", "--input-b", "-"},
                  R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 2]})");
    REQUIRE(r.exit_code == 0);
    j = json::parse(r.out);
    CHECK(j["agree"] == false);
    CHECK(j["first_step"]["step"] == 1);

    r = cgsandbox({"compare", "phong-lighting@phong", "phong-lighting@blinn-phong"});
    REQUIRE(r.exit_code == 0);
    j = json::parse(r.out);
    CHECK(j["agree"] == false);  // the highlight differs

    r = cgsandbox({"compare", "z-buffer", "liang-barsky"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("compare needs two algorithms that share an input kind"));
    r = cgsandbox({"compare", "liang-barsky@fast", "liang-barsky"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("no variant \"fast\""));
}
