#include "study/check.hpp"

#include <algorithm>
#include <cctype>

namespace cg::study {

std::vector<json> read_json_lines(const std::string& text) {
    std::vector<json> lines;
    std::size_t start = 0, number = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        ++number;
        std::string line = text.substr(start, end - start);
        start = end + 1;
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        json j = json::parse(line, nullptr, false);
        const std::string where = "line " + std::to_string(number);
        if (j.is_discarded()) throw InputError(where, "not valid JSON");
        if (!j.is_object())
            throw InputError(where, "each line must be a JSON object, got " + describe(j));
        lines.push_back(std::move(j));
    }
    return lines;
}

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    std::erase_if(s, [](char c) { return c == '_' || c == ' ' || c == '-'; });
    return s;
}

// The expected variable a renamed one most likely stands for: same name ignoring case and
// underscores, or the only expected variable not given whose value agrees.
std::string likely_rename(const std::string& given_name, const json& given_value,
                          const StepInfo& truth, const json& given_vars, double tolerance) {
    for (const Var& v : truth.vars)
        if (lower(v.name) == lower(given_name)) return v.name;
    std::string candidate;
    for (const Var& v : truth.vars) {
        if (given_vars.contains(v.name)) continue;
        if (!values_agree(to_json(v.value), given_value, tolerance)) continue;
        if (!candidate.empty()) return "";  // ambiguous
        candidate = v.name;
    }
    return candidate;
}

bool is_step_line(const json& j) {
    return j.contains("event");
}

void describe_step(const Spec& spec, const StepInfo& s, CheckReport& r) {
    r.event = s.event;
    if (const EventKind* e = find_event(spec, s.event)) r.meaning = e->meaning;
    r.line = s.line;
    if (s.line >= 1 && static_cast<std::size_t>(s.line) <= spec.pseudocode.size())
        r.pseudocode = spec.pseudocode[s.line - 1];
    r.narration = s.narration;
    r.expected_variables = json::object();
    for (const Var& v : s.vars) r.expected_variables[v.name] = to_json(v.value);
}

// The differences of one step; empty when it agrees.
std::vector<Mismatch> compare_step(const Spec& spec, const StepInfo& truth, const json& line,
                                   std::size_t index, double tolerance) {
    std::vector<Mismatch> out;
    for (const char* key : {"index", "step"}) {
        if (!line.contains(key)) continue;
        const json& k = line.at(key);
        if (!k.is_number_integer() || k.get<long long>() != static_cast<long long>(index))
            out.push_back({key, index, k,
                           "your line " + std::to_string(index) + " calls itself step " + k.dump() +
                               ": a step is missing or repeated before it"});
    }
    const json& ev = line.at("event");
    if (!ev.is_string()) {
        out.push_back({"event", truth.event, ev, "the event must be a string"});
    } else if (ev.get<std::string>() != truth.event) {
        const std::string given = ev.get<std::string>();
        std::string note = find_event(spec, given)
                               ? "a different case of the algorithm"
                               : "\"" + given + "\" is not an event of " + spec.id +
                                     " (its events: " + event_names(spec) + ")";
        out.push_back({"event", truth.event, ev, note});
    }
    if (!line.contains("variables")) return out;
    const json& vars = line.at("variables");
    if (!vars.is_object()) {
        out.push_back(
            {"variables", json::object(), vars, "variables must be an object {name: value}"});
        return out;
    }
    for (auto it = vars.begin(); it != vars.end(); ++it) {
        const Var* v = find_var(truth, it.key());
        if (!v) {
            const std::string guess = likely_rename(it.key(), it.value(), truth, vars, tolerance);
            out.push_back(
                {it.key(), nullptr, it.value(),
                 "this step has no variable \"" + it.key() + "\"" +
                     (guess.empty() ? "" : " (renamed? the sandbox calls it \"" + guess + "\")") +
                     "; its variables are " + var_names(truth)});
            continue;
        }
        const json expected = to_json(v->value);
        if (!values_agree(expected, it.value(), tolerance))
            out.push_back({it.key(), expected, it.value(),
                           "expected " + show(expected) + ", got " + show(it.value())});
    }
    return out;
}

}  // namespace

CheckReport check_trace(const Spec& spec, const Trace& truth, const std::vector<json>& given,
                        double tolerance) {
    CheckReport r;
    r.steps_expected = truth.steps.size();
    std::vector<const json*> steps;
    const json* result = nullptr;
    for (std::size_t i = 0; i < given.size(); ++i) {
        if (is_step_line(given[i])) {
            steps.push_back(&given[i]);
        } else if (i + 1 == given.size()) {
            result = &given[i];
        } else {
            throw InputError("line " + std::to_string(i + 1),
                             "no \"event\": every line but the last (the result) is a step");
        }
    }
    r.steps_given = steps.size();
    const std::size_t common = std::min(steps.size(), truth.steps.size());
    for (std::size_t i = 0; i < common; ++i) {
        auto mismatches = compare_step(spec, truth.steps[i], *steps[i], i + 1, tolerance);
        if (!mismatches.empty()) {
            r.agree = false;
            r.step = i + 1;
            r.mismatches = std::move(mismatches);
            describe_step(spec, truth.steps[i], r);
            return r;
        }
        ++r.steps_agreeing;
    }
    if (steps.size() < truth.steps.size()) {
        r.agree = false;
        r.step = steps.size() + 1;
        r.mismatches.push_back({"steps", truth.steps.size(), steps.size(),
                                "your trace stops after step " + std::to_string(steps.size()) +
                                    "; the run has " + std::to_string(truth.steps.size()) +
                                    " steps"});
        describe_step(spec, truth.steps[steps.size()], r);
        return r;
    }
    if (steps.size() > truth.steps.size()) {
        r.agree = false;
        r.step = truth.steps.size() + 1;
        r.mismatches.push_back({"steps", truth.steps.size(), steps.size(),
                                "the run ends after step " + std::to_string(truth.steps.size()) +
                                    "; your trace goes on to step " +
                                    std::to_string(steps.size())});
        return r;
    }
    if (result) {
        for (auto it = result->begin(); it != result->end(); ++it) {
            const std::string field = "result/" + it.key();
            if (!truth.result.is_object() || !truth.result.contains(it.key())) {
                r.mismatches.push_back(
                    {field, nullptr, it.value(), "the result has no field \"" + it.key() + "\""});
            } else if (!values_agree(truth.result.at(it.key()), it.value(), tolerance)) {
                r.mismatches.push_back(
                    {field, truth.result.at(it.key()), it.value(),
                     "expected " + show(truth.result.at(it.key())) + ", got " + show(it.value())});
            }
        }
        if (!r.mismatches.empty()) r.agree = false;
    }
    return r;
}

json check_json(const CheckReport& r) {
    json mismatches = json::array();
    for (const Mismatch& m : r.mismatches)
        mismatches.push_back(
            {{"what", m.what}, {"expected", m.expected}, {"given", m.given}, {"note", m.note}});
    json j = {{"agree", r.agree},
              {"steps",
               {{"expected", r.steps_expected},
                {"given", r.steps_given},
                {"agreeing", r.steps_agreeing}}},
              {"first_difference", r.step == 0 && r.agree ? json(nullptr) : json(r.step)},
              {"mismatches", std::move(mismatches)}};
    if (!r.event.empty())
        j["expected_step"] = {{"event", r.event},         {"meaning", r.meaning},
                              {"line", r.line},           {"pseudocode", r.pseudocode},
                              {"narration", r.narration}, {"variables", r.expected_variables}};
    return j;
}

std::string check_text(const Spec& spec, const CheckReport& r) {
    if (r.agree)
        return "all " + std::to_string(r.steps_expected) + " steps agree with " + spec.id +
               (r.steps_given ? "" : " (an empty trace)") + "\n";
    std::string s;
    if (r.step == 0)
        s = "all " + std::to_string(r.steps_agreeing) + " steps agree; the result differs:\n";
    else
        s = "step " + std::to_string(r.step) + " differs (" + std::to_string(r.steps_agreeing) +
            (r.steps_agreeing == 1 ? " step before it agrees):\n" : " steps before it agree):\n");
    for (const Mismatch& m : r.mismatches) s += "  " + m.what + ": " + m.note + "\n";
    if (!r.event.empty()) {
        s += "what should happen at step " + std::to_string(r.step) + ": " + r.event;
        if (!r.meaning.empty()) s += " (" + r.meaning + ")";
        s += "\n";
        if (r.line > 0) s += "  line " + std::to_string(r.line) + ":  " + r.pseudocode + "\n";
        if (!r.narration.empty()) s += "  " + r.narration + "\n";
    }
    return s;
}

}  // namespace cg::study
