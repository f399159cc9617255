#include "io/exam.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"

namespace cg {

bool has_exam(const Algorithm& a) { return static_cast<bool>(a.exam_input); }

// The exam's question and answers when the input is of the shape the generator writes (every
// answer field is in the run's result); for any other input — an algorithm's example, a
// lesson's preset, the student's own — a plain "run it" with every field of the result, as
// the generator's question would speak of fields the run does not have.
ExamProblem exam_for_input(const Algorithm& a, const json& input) {
    ExamProblem p;
    p.algorithm = a.spec->id;
    p.input = input;
    auto run = a.create(input);
    while (!run->done()) run->step(nullptr);
    const json result = a.result(*run);
    p.expected = json::object();
    p.question = "Run " + a.spec->title + " on the input below.";
    // A generator's question reads the input as the generator writes it (the first cell's
    // values, boid 0): one that finds it otherwise says so by throwing, and the plain question
    // stands.
    try {
        const std::vector<std::string> fields = a.answer_fields(input);
        const bool exam_shaped =
            std::all_of(fields.begin(), fields.end(), [&](const std::string& f) {
                return result.contains(json::json_pointer("/" + f));
            });
        if (!exam_shaped) return p;
        if (a.question) p.question = a.question(input);
        p.answers = fields;
    } catch (const std::exception&) {
        return p;
    }
    for (const std::string& field : p.answers) p.expected[field] = answer_value(result, field);
    return p;
}

// A JSON pointer without its first "/".
const json& answer_value(const json& result, const std::string& field) {
    return result.at(json::json_pointer("/" + field));
}

ExamProblem make_exam(const Algorithm& a, std::uint64_t seed) {
    if (!has_exam(a)) throw InputError("", a.spec->id + " has no exam generator yet");
    ExamProblem p = exam_for_input(a, a.exam_input(seed));
    p.seed = seed;
    return p;
}

json exam_to_json(const ExamProblem& p) {
    return json{{"question", p.question},
                {"input", p.input},
                {"answers", p.answers},
                {"expected", p.expected}};
}

bool answer_matches(const json& expected, const json& given, double tolerance) {
    if (expected.is_number()) {
        if (!given.is_number()) return false;
        const double e = expected.get<double>(), g = given.get<double>();
        return std::fabs(e - g) <= tolerance * std::max(1.0, std::fabs(e));
    }
    if (expected.is_array()) {
        if (!given.is_array() || given.size() != expected.size()) return false;
        for (std::size_t i = 0; i < expected.size(); ++i)
            if (!answer_matches(expected[i], given[i], tolerance)) return false;
        return true;
    }
    if (expected.is_object()) {
        if (!given.is_object() || given.size() != expected.size()) return false;
        for (auto it = expected.begin(); it != expected.end(); ++it)
            if (!given.contains(it.key()) || !answer_matches(it.value(), given.at(it.key()), tolerance))
                return false;
        return true;
    }
    if (expected.is_string() && given.is_string()) {  // words: "enters" is "Enters"
        auto lower = [](std::string s) {
            std::transform(s.begin(), s.end(), s.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            return s;
        };
        return lower(expected.get<std::string>()) == lower(given.get<std::string>());
    }
    return expected == given;  // booleans, null
}

namespace {
std::string show_expected(const json& v) {
    if (v.is_number()) return num(v.get<double>());
    if (v.is_array()) {
        std::string s = "[";
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + show_expected(v[i]);
        return s + "]";
    }
    return v.dump();
}
}  // namespace

std::vector<FieldGrade> grade(const ExamProblem& p, const json& given, double tolerance) {
    std::vector<FieldGrade> grades;
    for (const std::string& field : p.answers) {
        FieldGrade g{field, false, ""};
        const json& expected = p.expected.at(field);
        if (!given.is_object() || !given.contains(field)) {
            g.why = "no answer given; expected " + show_expected(expected);
        } else if (answer_matches(expected, given.at(field), tolerance)) {
            g.correct = true;
        } else {
            g.why = "expected " + show_expected(expected) + ", got " + show_expected(given.at(field));
        }
        grades.push_back(g);
    }
    return grades;
}

json parse_answer(const std::string& text) {
    std::string t = text;
    // A minus sign copied from the sandbox's own text (U+2212) reads as '-'.
    for (std::size_t at; (at = t.find(kMinus)) != std::string::npos;) t.replace(at, 3, "-");
    t.erase(0, t.find_first_not_of(" \t\r\n"));
    t.erase(t.find_last_not_of(" \t\r\n") + 1);
    std::string lower = t;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    if (lower == "yes" || lower == "visible") return true;
    if (lower == "no") return false;
    if (lower == "none" || lower == "-" || lower.empty()) return nullptr;
    // "(1, 3)" reads as the point [1, 3].
    if (t.size() >= 2 && t.front() == '(' && t.back() == ')') t = "[" + t.substr(1, t.size() - 2) + "]";
    json v = json::parse(t, nullptr, false);
    if (v.is_discarded()) return t;  // kept as text: it will simply not match
    return v;
}

}  // namespace cg
