#include "study/trace.hpp"

#include "core/format.hpp"
#include "io/exam.hpp"

namespace cg::study {

Trace record(const Algorithm& algorithm, const json& input, std::size_t max_steps) {
    Trace trace;
    std::unique_ptr<Run> run = algorithm.create(input);
    while (!run->done()) {
        if (trace.steps.size() == max_steps)
            throw InputError("", "the run has more than " + std::to_string(max_steps) +
                                     " steps, too many to study step by step; try a smaller input");
        run->step(&trace.steps.emplace_back());
    }
    trace.result = algorithm.result(*run);
    return trace;
}

const Var* find_var(const StepInfo& step, std::string_view name) {
    for (const Var& v : step.vars)
        if (v.name == name) return &v;
    return nullptr;
}

std::string var_names(const StepInfo& step) {
    std::string s;
    for (const Var& v : step.vars) s += (s.empty() ? "" : ", ") + v.name;
    return s.empty() ? "none" : s;
}

std::string event_names(const Spec& spec) {
    std::string s;
    for (const EventKind& e : spec.events) s += (s.empty() ? "" : ", ") + e.id;
    return s;
}

const EventKind* find_event(const Spec& spec, std::string_view id) {
    for (const EventKind& e : spec.events)
        if (e.id == id) return &e;
    return nullptr;
}

bool values_agree(const json& expected, const json& given, double tolerance) {
    return answer_matches(expected, given, tolerance);
}

std::string show(const json& v) {
    if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
    if (v.is_number()) return num(v.get<double>());
    if (v.is_string()) return "\"" + v.get<std::string>() + "\"";
    if (v.is_null()) return "none";
    if (v.is_array()) {
        const bool nested = !v.empty() && v.front().is_array();
        std::string s = nested ? "[" : "(";
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + show(v[i]);
        return s + (nested ? "]" : ")");
    }
    return v.dump();
}

}  // namespace cg::study
