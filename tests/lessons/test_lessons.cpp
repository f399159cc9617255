// Lessons, exam generators and worked examples, for every algorithm and every lesson file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/format.hpp"

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
    variant("i-bad-kind", [](cg::json& j) { j["sections"][0]["kind"] = "trivia"; });

    const cg::LessonLibrary lib = cg::load_lessons(dir.string(), registry());
    REQUIRE(lib.lessons.size() == 1);
    CHECK(lib.lessons[0].id == "liang-barsky");
    REQUIRE(lib.errors.size() == 9);
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
    CHECK_THAT(error_for("i-bad-kind.json"),
               Catch::Contains("sections[0].kind: must be \"by-hand\", \"mistakes\" or \"compare\" "
                               "(got \"trivia\")"));

    // The viewer checks a preset's input only when it is loaded: the lesson with the bad preset
    // is listed, its preset input kept as written (the session test loads it).
    const cg::LessonLibrary deferred =
        cg::load_lessons(dir.string(), registry(), cg::PresetCheck::WhenLoaded);
    REQUIRE(deferred.lessons.size() == 2);
    CHECK(deferred.errors.size() == 8);
    REQUIRE(deferred.find("e-bad-preset"));
    CHECK(deferred.find("e-bad-preset")->presets[1].input["p0"] == cg::json({0, "two"}));

    // The CLI lists the good one and reports each broken file on stderr.
    auto r = cg::test::run_process({"env", "CGSANDBOX_LESSONS=" + dir.string(), CG_BINARY, "lessons", "--check"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::StartsWith("liang-barsky\t"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 9);
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

TEST_CASE("worked: every algorithm's example, lesson preset and exam seed has a worked example",
          "[worked]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    for (const cg::Algorithm& a : registry().all()) {
        CAPTURE(a.spec->id);
        std::vector<std::pair<std::string, cg::json>> inputs{{"example", a.example()}};
        if (const cg::Lesson* l = lib.for_algorithm(a.spec->id))
            for (const auto& p : l->presets) inputs.emplace_back(p.name, p.input);
        for (const auto& [name, input] : inputs) {
            CAPTURE(name);
            // An input not of the exam's shape (radiosity's example gathers, so it has no first
            // shot to ask about) is worked as a plain run: every field of its result answered.
            const cg::ExamProblem p = cg::exam_for_input(a, input);
            const cg::WorkedExample w = cg::work(a, p);
            const std::string md = cg::worked_markdown(w);
            CHECK(md.find("**Answer.**") != std::string::npos);
            if (p.answers.empty()) CHECK(md.find("| " + w.result.begin().key() + " |") != std::string::npos);
            for (const std::string& f : p.answers) CHECK(p.expected.contains(f));
        }
        // The generator's own problems keep their question and answers.
        if (cg::has_exam(a))
            for (std::uint64_t seed = 1; seed <= 3; ++seed) {
                const cg::ExamProblem made = cg::make_exam(a, seed);
                const cg::ExamProblem again = cg::exam_for_input(a, made.input);
                CHECK(again.question == made.question);
                CHECK(again.answers == made.answers);
            }
    }
    // Through the CLI, the two that aborted on their own examples (exit 134).
    for (const char* id : {"radiosity", "shadow-map"}) {
        CAPTURE(id);
        const auto r = cg::test::cgsandbox({"worked", id});
        CHECK(r.exit_code == 0);
        CHECK_THAT(r.out, Catch::Contains("**Answer.**"));
    }
}

TEST_CASE("worked: an unknown preset lists the known ones", "[worked][errors]") {
    auto r = cg::test::cgsandbox({"worked", "liang-barsky", "--preset", "nope"});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("no preset \"nope\"") && Catch::Contains("a segment crossing two edges"));
}

namespace {

// The numbers in a text written in scientific notation — %g's "5.55e-17", or the short
// "5.55 × 10⁻¹⁷" — with their values.
std::vector<std::pair<std::string, double>> scientific_numbers(const std::string& text) {
    static const std::string superscripts[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::vector<std::pair<std::string, double>> out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(text[i])) ||
            (i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.')))
            continue;
        std::size_t j = i;
        while (j < text.size() && (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.')) ++j;
        const double mantissa = std::strtod(text.substr(i, j - i).c_str(), nullptr);
        const bool negative = (i >= 1 && text[i - 1] == '-') || (i >= 3 && text.compare(i - 3, 3, "−") == 0);
        int exponent = 0;
        bool found = false;
        std::size_t end = j;
        if (j + 1 < text.size() && (text[j] == 'e' || text[j] == 'E') &&
            (text[j + 1] == '-' || text[j + 1] == '+' || std::isdigit(static_cast<unsigned char>(text[j + 1])))) {
            std::size_t k = j + 1;
            if (text[k] == '-' || text[k] == '+') ++k;
            const std::size_t digits = k;
            while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
            if (k > digits) {
                exponent = std::stoi(text.substr(j + 1, k - j - 1));
                found = true;
                end = k;
            }
        } else if (text.compare(j, 12, " \\times 10^{") == 0) {  // LaTeX: 2.5 \times 10^{-5}
            const std::size_t close = text.find('}', j + 12);
            if (close != std::string::npos) {
                exponent = std::stoi(text.substr(j + 12, close - j - 12));
                found = true;
                end = close + 1;
            }
        } else {
            // "× 10⁻⁵" after the mantissa, or "10⁻⁵" alone (the mantissa 1 left out).
            std::size_t k = j;
            bool times = false;
            if (text.compare(k, 6, " × 10") == 0) k += 6, times = true;  // "×" is two bytes
            else if (text.compare(i, j - i, "10") == 0) k = j, times = false;
            else k = std::string::npos;
            if (k != std::string::npos) {
                bool minus = false;
                if (text.compare(k, 3, "⁻") == 0) minus = true, k += 3;
                int e = 0, n = 0;
                for (bool more = true; more;) {
                    more = false;
                    for (int d = 0; d < 10; ++d)
                        if (text.compare(k, superscripts[d].size(), superscripts[d]) == 0) {
                            e = e * 10 + d, ++n, k += superscripts[d].size(), more = true;
                            break;
                        }
                }
                if (n > 0) {
                    exponent = minus ? -e : e;
                    found = true;
                    end = k;
                }
                (void)times;
            }
        }
        const bool bare_power = text.compare(i, j - i, "10") == 0 && end > j && text.compare(j, 6, " × 10") != 0;
        // "10²" is ten squared (b² with b = 10): a bare power of ten is how num() writes only
        // the tiny (10⁻⁵) and the huge (10¹⁵).
        if (bare_power && exponent >= 0 && exponent < 15) found = false;
        if (!found) continue;
        const double v = (bare_power ? 1.0 : mantissa) * std::pow(10.0, exponent) * (negative ? -1 : 1);
        out.push_back({text.substr(i, end - i), v});
        i = end;
    }
    return out;
}

}  // namespace

TEST_CASE("numbers: a sandbox text shows no rounding noise in scientific notation",
          "[lessons][numbers]") {
    CHECK(scientific_numbers("t = 5.55e-17 and s = 1e+06").size() == 2);
    REQUIRE(scientific_numbers("2.5 × 10⁻⁵ and 10¹⁵").size() == 2);
    CHECK(scientific_numbers("2.5 × 10⁻⁵ and 10¹⁵")[0].second == Approx(2.5e-5));
    CHECK(scientific_numbers("2.5 × 10⁻⁵ and 10¹⁵")[1].second == Approx(1e15));
    CHECK(scientific_numbers("b² = 10² = 100").empty());
    CHECK(scientific_numbers("F4 culled, x2 = 3, Liang-Barsky").empty());
    // The formatter: rounding noise of a zero is 0, one minus sign, short powers of ten.
    CHECK(cg::num(5.551115123125783e-17) == "0");
    CHECK(cg::num(-1.2246467991473532e-16) == "0");
    CHECK(cg::num(-0.0) == "0");
    CHECK(cg::num(-2.5) == "−2.5");
    CHECK(cg::num(0.49999999999999994) == "0.5");
    CHECK(cg::num(2.9999999999999996) == "3");
    CHECK(cg::num(2.5e-5) == "2.5 × 10⁻⁵");
    CHECK(cg::num(-1e-5) == "−10⁻⁵");
    CHECK(cg::num(1234567.0) == "1234567");
    CHECK(cg::num(1309.87, 3) == "1310");
    CHECK(cg::num(2e15) == "2 × 10¹⁵");
    CHECK(cg::tex(-2.5e-5) == "-2.5 \\times 10^{-5}");
    CHECK(cg::text_minus("t = -0.5, x-axis, (-1, 2), a - b, Liang-Barsky, x-2") ==
          "t = −0.5, x-axis, (−1, 2), a − b, Liang-Barsky, x-2");
}

TEST_CASE("numbers: no narrated step of any lesson preset prints rounding noise",
          "[lessons][numbers]") {
    // Rounding noise: a value within 1e-12 of zero, or of a whole number, in scientific
    // notation (5.55e-17, −1.22 × 10⁻¹⁶, 1 + 4e-16 shown as 1e+00).
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    std::size_t steps = 0, noisy = 0;
    for (const cg::Lesson& l : lib.lessons) {
        const cg::Algorithm* a = registry().find(l.algorithm);
        REQUIRE(a);
        for (const cg::LessonPreset& p : l.presets) {
            auto run = a->create(p.input);
            for (std::size_t k = 1; !run->done(); ++k) {
                cg::StepInfo info;
                run->step(&info);
                ++steps;
                for (const std::string* text : {&info.narration, &info.math})
                    for (const auto& [shown, v] : scientific_numbers(*text)) {
                        // (A big whole number, 10⁶, is not noise; 3e+00 is.)
                        const bool noise = std::fabs(v) < 1e-12 ||
                                           (std::fabs(v) < 1e6 &&
                                            std::fabs(v - std::round(v)) < 1e-12 * std::fabs(v));
                        if (noise && ++noisy <= 40)
                            FAIL_CHECK(l.id << " \"" << p.name << "\" step " << k << ": " << shown
                                            << " in: " << *text);
                    }
            }
        }
    }
    INFO(steps << " steps read");
    CHECK(noisy == 0);
    CHECK(steps > 10000);
}

TEST_CASE("lessons: the Liang-Barsky by-hand table is the algorithm's own run", "[lessons][by-hand]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    const cg::Lesson* l = lib.find("liang-barsky");
    REQUIRE(l);
    const auto by_hand = std::find_if(l->sections.begin(), l->sections.end(),
                                      [](const cg::LessonSection& s) { return s.kind == "by-hand"; });
    REQUIRE(by_hand != l->sections.end());
    const std::string& text = by_hand->text;
    const cg::LessonPreset* preset = l->preset("a segment crossing two edges");
    REQUIRE(preset);
    const cg::Algorithm& a = *registry().find("liang-barsky");
    auto run = a.create(preset->input);
    while (!run->done()) run->step(nullptr);
    const cg::json r = a.result(*run);
    // Every row of the table, as the run has it: "p = −4, q = −1, r = 0.25, enters".
    REQUIRE(r["edges"].size() == 4);
    for (const auto& [edge, row] : r["edges"].items()) {
        CAPTURE(edge);
        const std::string line = "- " + edge + " (";
        CHECK(text.find(line) != std::string::npos);
        const std::string cells = "p = " + cg::num(row["p"].get<double>()) +
                                  ", q = " + cg::num(row["q"].get<double>()) +
                                  ", r = " + cg::num(row["r"].get<double>()) + ", " +
                                  row["crossing"].get<std::string>();
        CHECK(text.find(line) < text.find(cells));
        CHECK(text.find(cells) != std::string::npos);
    }
    // The answer.
    const glm::dvec2 q0(r["q0"][0].get<double>(), r["q0"][1].get<double>());
    const glm::dvec2 q1(r["q1"][0].get<double>(), r["q1"][1].get<double>());
    CHECK(text.find("Q_0 = P(" + cg::num(r["t_enter"].get<double>()) + ") = " + cg::num(q0)) !=
          std::string::npos);
    CHECK(text.find("Q_1 = P(" + cg::num(r["t_leave"].get<double>()) + ") = " + cg::num(q1)) !=
          std::string::npos);
}

TEST_CASE("lessons: paragraphs are short enough to read at a glance", "[lessons]") {
    // A paragraph (a line of a section's text) of at most 600 characters: about six lines of
    // the lesson panel at 1280 × 720. The longest were 1,200-character blocks of formulas.
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    std::size_t paragraphs = 0;
    for (const cg::Lesson& l : lib.lessons)
        for (const cg::LessonSection& s : l.sections) {
            std::size_t start = 0;
            while (start <= s.text.size()) {
                std::size_t end = s.text.find('\n', start);
                if (end == std::string::npos) end = s.text.size();
                const std::string paragraph = s.text.substr(start, end - start);
                // Characters, not bytes: θ, − and ≤ take two or three bytes each.
                const auto characters = std::count_if(paragraph.begin(), paragraph.end(),
                                                      [](char c) { return (c & 0xC0) != 0x80; });
                CAPTURE(l.id, s.title, paragraph);
                CHECK(characters <= 600);
                ++paragraphs;
                start = end + 1;
            }
        }
    CHECK(paragraphs > 1000);
}

TEST_CASE("lessons: the comparisons the course asks for have a compare section", "[lessons]") {
    // The course asks to compare the hidden-surface algorithms, the shading models, Phong with
    // Blinn-Phong, the two trackballs, Euler angles with quaternions and radiosity with ray
    // tracing: each of those lessons says the advantages and limits in a "compare" section.
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    for (const char* id : {"backface-cull", "z-buffer", "painters", "warnock", "shading",
                           "phong-lighting", "virtual-sphere", "arcball", "euler-angles",
                           "quaternion", "radiosity"}) {
        CAPTURE(id);
        const cg::Lesson* l = lib.find(id);
        REQUIRE(l);
        CHECK(std::any_of(l->sections.begin(), l->sections.end(),
                          [](const cg::LessonSection& s) { return s.kind == "compare"; }));
    }
}

TEST_CASE("lessons: a painter's preset shows the marking rule split a cycle", "[lessons]") {
    // The rule the lesson teaches: a polygon moved to the far end is marked, and a marked one
    // that would have to move again is split. One preset must take that path.
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    const cg::Lesson* l = lib.find("painters");
    REQUIRE(l);
    int presets_with_cycle = 0;
    for (const cg::LessonPreset& p : l->presets) {
        auto run = registry().find("painters")->create(p.input);
        int moves_before_split = 0;
        bool cyclic_split = false;
        while (!run->done()) {
            cg::StepInfo info;
            run->step(&info);
            if (info.event == "move") ++moves_before_split;
            if (info.event == "split" && moves_before_split > 0 &&
                info.narration.find("moved already") != std::string::npos)
                cyclic_split = true;
        }
        presets_with_cycle += cyclic_split;
    }
    CHECK(presets_with_cycle >= 1);
}
