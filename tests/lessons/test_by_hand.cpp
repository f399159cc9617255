// The lessons' "by-hand" sections (an exam question worked as on paper) hold only the
// algorithm's own numbers: every number written in one must be a number of the run of the
// preset it names — its input, a step's variables, narration or formula, or the result — as the
// sandbox prints it. So the text cannot drift from the code, whoever edits either.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>

#include "core/format.hpp"

#include "io/lesson.hpp"
#include "io/registry.hpp"
#include "support/registry_run.hpp"

namespace {

using cg::test::registry;

// A number as written: its value and how many decimals it was written with.
struct Written {
    std::string text;
    double value = 0;
    int decimals = 0;
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// The numbers a reader sees in a text. Left out: subscripts and superscripts (P_0, x^{2},
// 10^{-3}'s −3), digits that are part of a name (P1, 3D, 2nd), and LaTeX commands' arguments are
// read like any text. A minus is ASCII '-' (in LaTeX) or U+2212 '−' directly before the digits.
std::vector<Written> numbers_in(const std::string& s) {
    static const std::string kMinus = "\xE2\x88\x92";  // U+2212
    std::vector<Written> out;
    std::size_t i = 0;
    while (i < s.size()) {
        if (!is_digit(s[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < s.size() && is_digit(s[i])) ++i;
        int decimals = 0;
        if (i + 1 < s.size() && s[i] == '.' && is_digit(s[i + 1])) {
            ++i;
            while (i < s.size() && is_digit(s[i])) {
                ++i;
                ++decimals;
            }
        }
        // What comes before: a script marker, a name, a minus sign.
        std::size_t before = start;
        bool negative = false;
        if (before >= 1 && s[before - 1] == '-') {
            negative = true;
            --before;
        } else if (before >= 3 && s.compare(before - 3, 3, kMinus) == 0) {
            negative = true;
            before -= 3;
        }
        const char prev = before >= 1 ? s[before - 1] : ' ';
        const char prev2 = before >= 2 ? s[before - 2] : ' ';
        const char next = i < s.size() ? s[i] : ' ';
        const bool script = prev == '_' || prev == '^' || (prev == '{' && (prev2 == '_' || prev2 == '^'));
        // "x-1" with a name before the minus is subtraction, not a negative number.
        if (negative && (is_letter(prev) || is_digit(prev) || prev == ')')) negative = false;
        const bool in_name = is_letter(start >= 1 ? s[start - 1] : ' ') || is_letter(next) ||
                             (start >= 1 && s[start - 1] == '\\');
        if (script || in_name) continue;
        Written w;
        w.text = (negative ? "-" : "") + s.substr(start, i - start);
        w.value = std::stod(s.substr(start, i - start)) * (negative ? -1 : 1);
        w.decimals = decimals;
        out.push_back(w);
    }
    return out;
}

// Every number of a run, as values.
struct Pool {
    std::vector<double> values;
    std::set<std::string> printed;  // num() of each value, for integers written from a rounding

    void add(double v) {
        if (!std::isfinite(v)) return;
        values.push_back(v);
        printed.insert(cg::num(v));
    }
    void add_json(const cg::json& j) {
        if (j.is_number()) add(j.get<double>());
        else if (j.is_string()) add_text(j.get<std::string>());
        else if (j.is_structured())
            for (const auto& e : j) add_json(e);
    }
    void add_text(const std::string& s) {
        for (const Written& w : numbers_in(s)) add(w.value);
    }
    void add_value(const cg::Value& v) {
        std::visit(
            [&](const auto& x) {
                using T = std::decay_t<decltype(x)>;
                if constexpr (std::is_same_v<T, long long> || std::is_same_v<T, double>)
                    add(static_cast<double>(x));
                else if constexpr (std::is_same_v<T, std::string>)
                    add_text(x);
                else if constexpr (std::is_same_v<T, std::vector<double>>)
                    for (double d : x) add(d);
                else if constexpr (std::is_same_v<T, std::vector<std::vector<double>>>)
                    for (const auto& row : x)
                        for (double d : row) add(d);
            },
            v);
    }
    void seal() { std::sort(values.begin(), values.end()); }

    // Written with d decimals, v matches when it rounds to what is written; an integer must be
    // exact (or be what num() prints for a value of the run).
    bool has(const Written& w) const {
        const double tol = w.decimals > 0 ? 0.5 * std::pow(10.0, -w.decimals) * (1 + 1e-9) + 1e-12
                                          : 1e-9 * std::max(1.0, std::abs(w.value));
        const auto lo = std::lower_bound(values.begin(), values.end(), w.value - tol);
        if (lo != values.end() && *lo <= w.value + tol) return true;
        return w.decimals == 0 && printed.count(cg::num(w.value));
    }
};

Pool run_pool(const cg::Algorithm& a, const cg::json& input) {
    Pool pool;
    pool.add_json(input);
    auto run = a.create(input);
    while (!run->done()) {
        cg::StepInfo info;
        run->step(&info);
        pool.add_text(info.narration);
        pool.add_text(info.math);
        for (const cg::Var& v : info.vars) pool.add_value(v.value);
    }
    pool.add_json(a.result(*run));
    pool.seal();
    return pool;
}


}  // namespace

TEST_CASE("by-hand: the number reader sees what a student reads", "[lessons][by-hand]") {
    auto texts = [](const std::string& s) {
        std::vector<std::string> out;
        for (const Written& w : numbers_in(s)) out.push_back(w.text);
        return out;
    };
    CHECK(texts("p = −4, q = −1, r = 0.25") == std::vector<std::string>{"-4", "-1", "0.25"});
    CHECK(texts("$\\max(0.25, -0.25) = 0.25$") == std::vector<std::string>{"0.25", "-0.25", "0.25"});
    CHECK(texts("$P_0 = (0, 2)$, $x^{2}$, $10^{-3}$, P1 in 3D, $t_{12}$") ==
          std::vector<std::string>{"0", "2", "10"});
    CHECK(texts("$x-1$ and $P_1 - P_0$") == std::vector<std::string>{"1"});
    CHECK(numbers_in("0.125")[0].decimals == 3);

    Pool pool;
    pool.add(1.0 / 3.0);
    pool.add(-0.25);
    pool.add(4.0);
    pool.seal();
    CHECK(pool.has(numbers_in("0.33")[0]));
    CHECK(pool.has(numbers_in("0.3333")[0]));
    CHECK_FALSE(pool.has(numbers_in("0.34")[0]));
    CHECK(pool.has(numbers_in("−0.25")[0]));
    CHECK_FALSE(pool.has(numbers_in("0.25")[0]));  // the sign is part of the number
    CHECK(pool.has(numbers_in("4")[0]));
    CHECK_FALSE(pool.has(numbers_in("3")[0]));     // an integer is exact
}

TEST_CASE("by-hand: a worked question names a preset of its lesson", "[lessons][by-hand]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    const cg::Lesson* l = lib.find("liang-barsky");
    REQUIRE(l);
    cg::json j = cg::json::parse(R"({"id": "x", "title": "X", "topic": "T", "order": 1,
        "algorithm": "liang-barsky", "exam": {"weight": "medium"},
        "presets": [{"name": "one", "input": {}}],
        "sections": [{"title": "By hand", "text": "Worked.", "kind": "by-hand", "preset": "one"}]})");
    j["presets"][0]["input"] = l->presets[0].input;
    CHECK(cg::parse_lesson(j, registry()).sections[0].preset == "one");

    auto error = [&](const std::function<void(cg::json&)>& edit) {
        cg::json bad = j;
        edit(bad);
        try {
            cg::parse_lesson(bad, registry());
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK_THAT(error([](cg::json& b) { b["sections"][0].erase("preset"); }),
               Catch::Contains("sections[0].preset") && Catch::Contains("names the preset"));
    CHECK_THAT(error([](cg::json& b) { b["sections"][0]["preset"] = "two"; }),
               Catch::Contains("sections[0].preset: is not a preset of this lesson (got \"two\")"));
    CHECK_THAT(error([](cg::json& b) { b["sections"][0]["kind"] = "compare"; }),
               Catch::Contains("sections[0].preset: only a \"by-hand\" or \"mistakes\" section names "
                               "a preset"));
}

TEST_CASE("by-hand: every number in a worked question is its preset's run", "[lessons][by-hand]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    REQUIRE(lib.errors.empty());
    int sections = 0, checked = 0;
    for (const cg::Lesson& l : lib.lessons) {
        for (const cg::LessonSection& s : l.sections) {
            if (s.kind != "by-hand") continue;
            CAPTURE(l.id, s.title, s.preset);
            ++sections;
            const cg::LessonPreset* preset = l.preset(s.preset);
            REQUIRE(preset);
            const Pool pool = run_pool(cg::test::algorithm(l.algorithm), preset->input);
            for (const Written& w : numbers_in(s.text)) {
                // Counting words written as numerals (two levels, 4 edges) need no run.
                if (w.decimals == 0 && std::abs(w.value) <= 10) continue;
                CAPTURE(w.text);
                CHECK(pool.has(w));
                ++checked;
            }
        }
    }
    INFO(sections << " worked questions, " << checked << " numbers checked");
    CHECK(sections >= 1);
    CHECK(checked >= 10);
}

TEST_CASE("by-hand: every lesson the exam weighs works a question by hand", "[lessons][by-hand]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    std::vector<std::string> missing;
    int weighed = 0;
    for (const cg::Lesson& l : lib.lessons) {
        if (l.exam_weight != "high" && l.exam_weight != "medium") continue;
        ++weighed;
        if (std::none_of(l.sections.begin(), l.sections.end(),
                         [](const cg::LessonSection& s) { return s.kind == "by-hand"; }))
            missing.push_back(l.id);
    }
    INFO("missing a by-hand section: " << Catch::Detail::stringify(missing));
    CHECK(missing.empty());
    CHECK(weighed >= 36);
}
