#include "study/bug.hpp"

#include <algorithm>

#include "core/rng.hpp"

namespace cg::study {

namespace {

// `kind` is "name" or "name:argument".
std::pair<std::string, std::string> split_kind(const std::string& kind) {
    const auto colon = kind.find(':');
    if (colon == std::string::npos) return {kind, ""};
    return {kind.substr(0, colon), kind.substr(colon + 1)};
}

Var* var_of(StepInfo& s, const std::string& name) {
    for (Var& v : s.vars)
        if (v.name == name) return &v;
    return nullptr;
}

bool is_number(const Value& v) {
    return std::holds_alternative<double>(v) || std::holds_alternative<long long>(v);
}

std::optional<Value> negate(const Value& v) {
    if (const auto* d = std::get_if<double>(&v)) return Value{-*d};
    if (const auto* i = std::get_if<long long>(&v)) return Value{-*i};
    if (const auto* vec = std::get_if<std::vector<double>>(&v)) {
        std::vector<double> r(*vec);
        for (double& x : r) x = -x;
        return Value{r};
    }
    return std::nullopt;
}

std::optional<Value> transpose(const Value& v) {
    const auto* m = std::get_if<std::vector<std::vector<double>>>(&v);
    if (!m || m->empty()) return std::nullopt;
    const std::size_t n = m->size();
    for (const auto& row : *m)
        if (row.size() != n) return std::nullopt;
    std::vector<std::vector<double>> t(n, std::vector<double>(n));
    for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < n; ++c) t[c][r] = (*m)[r][c];
    return Value{t};
}

std::optional<Value> reverse(const Value& v) {
    if (const auto* vec = std::get_if<std::vector<double>>(&v); vec && vec->size() >= 2)
        return Value{std::vector<double>(vec->rbegin(), vec->rend())};
    if (const auto* m = std::get_if<std::vector<std::vector<double>>>(&v); m && m->size() >= 2)
        return Value{std::vector<std::vector<double>>(m->rbegin(), m->rend())};
    return std::nullopt;
}

bool same_shape(const Value& a, const Value& b) {
    if (is_number(a) && is_number(b)) return true;
    if (a.index() != b.index()) return false;
    if (const auto* va = std::get_if<std::vector<double>>(&a))
        return va->size() == std::get<std::vector<double>>(b).size();
    if (const auto* ma = std::get_if<std::vector<std::vector<double>>>(&a))
        return ma->size() == std::get<std::vector<std::vector<double>>>(b).size();
    return true;
}

// A wrong value is one a grader would mark wrong: beyond the exam's tolerance.
bool visibly_different(const Value& right, const Value& wrong) {
    return !values_agree(to_json(right), to_json(wrong), 1e-3);
}

// The mistake's change to one step: the variables it sets, or the event it relabels.
struct Change {
    std::vector<Var> vars;  // new values
    std::string event;      // "" when the event stays
};

std::optional<Change> change_for(const Mistake& m, const Trace& trace, std::size_t at) {
    const StepInfo& s = trace.steps[at];
    if (s.event != m.event) return std::nullopt;
    const auto [kind, arg] = split_kind(m.kind);
    if (kind == "event") {
        if (arg == s.event) return std::nullopt;
        return Change{{}, arg};
    }
    const Var* v = find_var(s, m.var);
    if (!v) return std::nullopt;
    std::optional<Value> wrong;
    Change c;
    if (kind == "negate") {
        wrong = negate(v->value);
    } else if (kind == "transpose") {
        wrong = transpose(v->value);
    } else if (kind == "reverse") {
        wrong = reverse(v->value);
    } else if (kind == "off-by-one") {
        if (const auto* i = std::get_if<long long>(&v->value)) wrong = Value{*i + 1};
    } else if (kind == "not") {
        if (const auto* b = std::get_if<bool>(&v->value)) wrong = Value{!*b};
    } else if (kind == "copy") {
        const Var* other = find_var(s, arg);
        if (other && same_shape(v->value, other->value)) wrong = other->value;
    } else if (kind == "swap") {
        const Var* other = find_var(s, arg);
        if (!other || !same_shape(v->value, other->value) ||
            !visibly_different(v->value, other->value))
            return std::nullopt;
        c.vars.push_back({other->name, v->value});
        wrong = other->value;
    } else if (kind == "keep" || kind == "other") {
        // The value before this step: the same variable in the step before.
        const Var* before = at > 0 ? find_var(trace.steps[at - 1], m.var) : nullptr;
        if (!before || !same_shape(v->value, before->value)) return std::nullopt;
        if (kind == "keep") {
            wrong = before->value;
        } else {
            // max(before, candidate) read as min: the one of the two that was not chosen.
            const Var* candidate = find_var(s, arg);
            if (!candidate || !same_shape(v->value, candidate->value)) return std::nullopt;
            if (!visibly_different(v->value, before->value))
                wrong = candidate->value;
            else if (!visibly_different(v->value, candidate->value))
                wrong = before->value;
        }
    }
    if (!wrong || !visibly_different(v->value, *wrong)) return std::nullopt;
    c.vars.insert(c.vars.begin(), Var{v->name, *wrong});
    return c;
}

void apply(StepInfo& s, const Change& c) {
    if (!c.event.empty()) {
        s.event = c.event;
    }
    for (const Var& w : c.vars)
        if (Var* v = var_of(s, w.name)) v->value = w.value;
}

}  // namespace

std::optional<StepInfo> plant(const Mistake& m, const Trace& trace, std::size_t at) {
    if (at >= trace.steps.size()) return std::nullopt;
    auto c = change_for(m, trace, at);
    if (!c) return std::nullopt;
    StepInfo s = trace.steps[at];
    apply(s, *c);
    return s;
}

std::vector<BugSite> bug_sites(const Spec& spec, const Trace& trace) {
    std::vector<BugSite> sites;
    for (std::size_t at = 0; at < trace.steps.size(); ++at)
        for (std::size_t k = 0; k < spec.study.mistakes.size(); ++k)
            if (change_for(spec.study.mistakes[k], trace, at)) sites.push_back({k, at + 1});
    return sites;
}

PlantedBug plant_bug(const Spec& spec, const Trace& trace, std::uint64_t seed) {
    const std::vector<BugSite> sites = bug_sites(spec, trace);
    if (sites.empty())
        throw InputError("",
                         "none of " + spec.id +
                             "'s planted mistakes shows on this input; try another input or seed");
    // First a mistake (each equally likely, whatever its number of sites), then one of its steps.
    std::vector<std::size_t> kinds;
    for (const BugSite& s : sites)
        if (std::find(kinds.begin(), kinds.end(), s.mistake) == kinds.end())
            kinds.push_back(s.mistake);
    std::sort(kinds.begin(), kinds.end());
    Rng rng(seed);
    const std::size_t kind =
        kinds[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(kinds.size()) - 1))];
    std::vector<std::size_t> steps;
    for (const BugSite& s : sites)
        if (s.mistake == kind) steps.push_back(s.step);
    const std::size_t step =
        steps[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(steps.size()) - 1))];

    PlantedBug bug;
    bug.step = step;
    bug.mistake = spec.study.mistakes[kind];
    bug.correct = trace.steps[step - 1];
    bug.steps = trace.steps;
    const Change change = *change_for(bug.mistake, trace, step - 1);
    apply(bug.steps[step - 1], change);
    // Carry each wrong value on while the right one stays what it was at the planted step.
    for (const Var& w : change.vars) {
        const Var* right = find_var(trace.steps[step - 1], w.name);
        for (std::size_t j = step; j < trace.steps.size(); ++j) {
            const Var* later = find_var(trace.steps[j], w.name);
            if (!later || !(later->value == right->value)) break;
            var_of(bug.steps[j], w.name)->value = w.value;
        }
    }
    for (StepInfo& s : bug.steps) s.narration.clear(), s.math.clear();

    std::string what;
    if (!change.event.empty()) {
        what = "the step was classified as " + change.event + "; it is " + bug.correct.event;
    }
    for (const Var& w : change.vars) {
        const Var* right = find_var(bug.correct, w.name);
        what += (what.empty() ? "" : "; ") + w.name + " was given as " + show(to_json(w.value)) +
                ", the right value is " + show(to_json(right->value));
    }
    bug.explanation = "Step " + std::to_string(step) + " (" + bug.correct.event +
                      "): " + bug.mistake.description + ". " + what + ".";
    return bug;
}

BugGrade grade_bug_answer(const Spec& spec, const PlantedBug& bug, std::size_t answer) {
    BugGrade g;
    g.correct = answer == bug.step;
    if (g.correct)
        g.text = "Right: step " + std::to_string(answer) + " is the first wrong step.\n";
    else if (answer < bug.step)
        g.text = "Wrong: step " + std::to_string(answer) + " is right; the first wrong step is " +
                 std::to_string(bug.step) + ".\n";
    else
        g.text = "Wrong: step " + std::to_string(answer) + " comes after the first wrong step, " +
                 std::to_string(bug.step) + ".\n";
    g.text += bug.explanation + "\n";
    g.text += "The right step " + std::to_string(bug.step) + ": " + bug.correct.narration + "\n";
    if (bug.correct.line >= 1 &&
        static_cast<std::size_t>(bug.correct.line) <= spec.pseudocode.size())
        g.text += "  line " + std::to_string(bug.correct.line) + ":  " +
                  spec.pseudocode[bug.correct.line - 1] + "\n";
    return g;
}

}  // namespace cg::study
