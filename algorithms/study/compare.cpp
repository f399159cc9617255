#include "study/compare.hpp"

#include <cmath>

namespace cg::study {

Side parse_side(const Registry& registry, const std::string& text) {
    const auto at = text.find('@');
    const std::string id = text.substr(0, at);
    Side side;
    side.algorithm = registry.find(id);
    if (!side.algorithm)
        throw InputError("", "unknown algorithm \"" + id + "\"; `cgsandbox list` shows them");
    side.label = text;
    if (at == std::string::npos) return side;
    const std::string name = text.substr(at + 1);
    std::string names;
    for (const Variant& v : side.algorithm->spec->study.variants) {
        if (v.name == name) side.variant = &v;
        names += (names.empty() ? "" : ", ") + v.name;
    }
    if (!side.variant)
        throw InputError("", id + " has no variant \"" + name + "\"" +
                                 (names.empty() ? std::string(" (it has none)")
                                                : " (its variants: " + names + ")"));
    return side;
}

json side_input(const Side& side, json input) {
    if (!side.variant) return input;
    const json value = json::parse(side.variant->value);
    input[json::json_pointer(side.variant->field)] = value;
    return input;
}

void check_comparable(const Side& a, const Side& b) {
    const Spec& sa = *a.algorithm->spec;
    const Spec& sb = *b.algorithm->spec;
    if (sa.id == sb.id) return;
    const std::string ka = sa.study.input_kind, kb = sb.study.input_kind;
    if (!ka.empty() && ka == kb) return;
    auto kind = [](const std::string& k) {
        return k.empty() ? std::string("its own kind of input") : "a " + k + " input";
    };
    throw InputError(
        "", sa.id + " reads " + kind(ka) + " and " + sb.id + " reads " + kind(kb) +
                ": compare needs two algorithms that share an input kind, or one algorithm twice");
}

namespace {

bool numbers_agree(double a, double b) {
    return a == b || std::fabs(a - b) <= 1e-9 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

void diff(const json& a, const json& b, const std::string& where, Comparison& c) {
    if (a.is_number() && b.is_number()) {
        if (numbers_agree(a.get<double>(), b.get<double>())) return;
    } else if (a.is_array() && b.is_array() && a.size() == b.size()) {
        for (std::size_t i = 0; i < a.size(); ++i)
            diff(a[i], b[i], where + "/" + std::to_string(i), c);
        return;
    } else if (a.is_object() && b.is_object()) {
        for (auto it = a.begin(); it != a.end(); ++it)
            diff(it.value(), b.contains(it.key()) ? b.at(it.key()) : json(nullptr),
                 where + "/" + it.key(), c);
        for (auto it = b.begin(); it != b.end(); ++it)
            if (!a.contains(it.key())) diff(json(nullptr), it.value(), where + "/" + it.key(), c);
        return;
    } else if (a == b) {
        return;
    }
    c.agree = false;
    ++c.difference_count;
    if (c.differences.size() < kMaxListed)
        c.differences.push_back({where.empty() ? "/" : where, a, b});
}

// A cost field may name a field of an object in the result: "counts/box_tests".
json costs_of(const Spec& spec, const json& result) {
    json j = json::object();
    for (const std::string& field : spec.study.costs) {
        const json::json_pointer at("/" + field);
        if (result.contains(at)) j[field] = result.at(at);
    }
    return j;
}

}  // namespace

std::optional<std::size_t> first_differing_step(const Trace& a, const Trace& b, std::string* note) {
    const std::size_t common = std::min(a.steps.size(), b.steps.size());
    for (std::size_t i = 0; i < common; ++i) {
        const StepInfo& x = a.steps[i];
        const StepInfo& y = b.steps[i];
        std::string why;
        if (x.event != y.event)
            why = "the event: " + x.event + " against " + y.event;
        else if (x.line != y.line)
            why = "the pseudocode line: " + std::to_string(x.line) + " against " +
                  std::to_string(y.line);
        else {
            for (const Var& v : x.vars) {
                const Var* w = find_var(y, v.name);
                if (!w) {
                    why = v.name + " is only on the first side";
                    break;
                }
                Comparison c;
                diff(to_json(v.value), to_json(w->value), "", c);
                if (!c.agree) {
                    why = v.name + ": " + show(to_json(v.value)) + " against " +
                          show(to_json(w->value));
                    break;
                }
            }
            if (why.empty() && y.vars.size() != x.vars.size())
                why = "the second side reports other variables";
        }
        if (!why.empty()) {
            if (note) *note = why;
            return i;
        }
    }
    if (a.steps.size() != b.steps.size()) {
        if (note)
            *note = "one run ends after " + std::to_string(common) + " steps, the other goes on";
        return common;
    }
    return std::nullopt;
}

Comparison compare(const Side& a, const Trace& ta, const Side& b, const Trace& tb) {
    check_comparable(a, b);
    Comparison c;
    const Spec& sa = *a.algorithm->spec;
    const Spec& sb = *b.algorithm->spec;
    c.steps_a = ta.steps.size();
    c.steps_b = tb.steps.size();
    if (sa.id == sb.id) {
        diff(ta.result, tb.result, "", c);
        std::string note;
        if (auto k = first_differing_step(ta, tb, &note)) {
            c.first_step = *k + 1;
            c.first_step_note = note;
        }
    } else {
        for (const std::string& field : sa.study.compare) {
            const json none;
            diff(ta.result.contains(field) ? ta.result.at(field) : none,
                 tb.result.contains(field) ? tb.result.at(field) : none, "/" + field, c);
        }
    }
    c.costs[a.label] = costs_of(sa, ta.result);
    c.costs[b.label == a.label ? b.label + " (second)" : b.label] = costs_of(sb, tb.result);
    return c;
}

json comparison_json(const Side& a, const Side& b, const Comparison& c) {
    json differences = json::array();
    for (const Difference& d : c.differences)
        differences.push_back({{"where", d.where}, {"a", d.a}, {"b", d.b}});
    json j = {{"agree", c.agree},
              {"a", a.label},
              {"b", b.label},
              {"differences", std::move(differences)},
              {"difference_count", c.difference_count},
              {"costs", c.costs},
              {"steps", {{"a", c.steps_a}, {"b", c.steps_b}}}};
    if (a.algorithm == b.algorithm)
        j["first_step"] = c.first_step ? json{{"step", *c.first_step}, {"what", c.first_step_note}}
                                       : json(nullptr);
    return j;
}

}  // namespace cg::study
