#include "study/predict.hpp"

#include <algorithm>

namespace cg::study {

const std::vector<std::string>& predictable_vars(const Spec& spec, std::string_view event) {
    static const std::vector<std::string> none;
    for (const Predictable& p : spec.study.predict)
        if (p.event == event) return p.vars;
    return none;
}

PredictGrade grade_prediction(const Spec& spec, const StepInfo& truth, const Prediction& p,
                              double tolerance) {
    PredictGrade g;
    g.step = p.step;
    g.expected_event = truth.event;
    g.given_event = p.event;
    g.event_correct = p.event == truth.event;
    g.correct = g.event_correct;
    for (const std::string& name : predictable_vars(spec, truth.event)) {
        const Var* v = find_var(truth, name);
        if (!v) continue;  // this step does not report it (a declared var is checked by the tests)
        VarGrade vg{name, false, to_json(v->value), nullptr};
        if (p.variables.is_object() && p.variables.contains(name)) {
            vg.given = p.variables.at(name);
            vg.correct = values_agree(vg.expected, vg.given, tolerance);
        }
        g.correct = g.correct && vg.correct;
        g.vars.push_back(std::move(vg));
    }
    if (!g.correct) {
        if (!g.event_correct)
            g.why = "the step is " + truth.event + ", not " +
                    (p.event.empty() ? std::string("(no event given)") : p.event);
        for (const VarGrade& vg : g.vars) {
            if (vg.correct) continue;
            g.why += (g.why.empty() ? "" : "; ") + vg.name + " = " + show(vg.expected) +
                     (vg.given.is_null() ? " (not given)" : ", not " + show(vg.given));
        }
    }
    return g;
}

namespace {
std::string asked(const Spec& spec, const std::string& event) {
    std::string s;
    for (const std::string& v : predictable_vars(spec, event)) s += (s.empty() ? "" : ", ") + v;
    return s;
}
}  // namespace

std::string predict_question(const Spec& spec, std::size_t step, const StepInfo* before) {
    std::string q = "Step " + std::to_string(step) + ". ";
    q += before ? "So far: " + before->narration + "\n" : "The run starts.\n";
    q += "What happens next? One of:\n";
    for (const EventKind& e : spec.events) {
        q += "  " + e.id + ": " + e.meaning;
        const std::string nums = asked(spec, e.id);
        if (!nums.empty()) q += " (then give " + nums + ")";
        q += "\n";
    }
    return q;
}

json predict_question_json(const Spec& spec, std::size_t step, const StepInfo* before) {
    json choices = json::array();
    for (const EventKind& e : spec.events)
        choices.push_back(
            {{"event", e.id}, {"meaning", e.meaning}, {"variables", predictable_vars(spec, e.id)}});
    return {{"step", step},
            {"so_far", before ? before->narration : ""},
            {"line", before ? before->line : 0},
            {"choices", std::move(choices)}};
}

Prediction prediction_from_json(const json& j, const std::string& where) {
    if (!j.is_object())
        throw InputError(
            where,
            "a prediction is an object {\"step\", \"event\", \"variables\"}, got " + describe(j));
    Reader r(j, where);
    r.only({"step", "event", "variables"});
    Prediction p;
    const long long step = r.integer("step");
    if (step < 1)
        throw InputError(r.field("step"), "steps count from 1, got " + std::to_string(step));
    p.step = static_cast<std::size_t>(step);
    p.event = r.string("event");
    if (r.has("variables")) {
        const json& v = r.get("variables");
        if (!v.is_object())
            throw InputError(r.field("variables"),
                             "must be an object {name: value}, got " + describe(v));
        p.variables = v;
    }
    return p;
}

PredictReport grade_predictions(const Spec& spec, const Trace& trace,
                                const std::vector<Prediction>& predictions, double tolerance) {
    PredictReport r;
    r.steps = trace.steps.size();
    std::vector<const Prediction*> sorted;
    for (const Prediction& p : predictions) sorted.push_back(&p);
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const Prediction* a, const Prediction* b) { return a->step < b->step; });
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        const Prediction& p = *sorted[i];
        const std::string where = "step " + std::to_string(p.step);
        if (i > 0 && sorted[i - 1]->step == p.step) throw InputError(where, "predicted twice");
        if (p.step > trace.steps.size())
            throw InputError(where,
                             "the run has only " + std::to_string(trace.steps.size()) + " steps");
        r.grades.push_back(grade_prediction(spec, trace.steps[p.step - 1], p, tolerance));
        if (r.grades.back().correct)
            ++r.right;
        else
            r.wrong.push_back(p.step);
    }
    return r;
}

json report_json(const PredictReport& r) {
    json steps = json::array();
    for (const PredictGrade& g : r.grades) {
        json vars = json::array();
        for (const VarGrade& v : g.vars)
            vars.push_back({{"name", v.name},
                            {"correct", v.correct},
                            {"expected", v.expected},
                            {"given", v.given}});
        steps.push_back({{"step", g.step},
                         {"correct", g.correct},
                         {"event",
                          {{"correct", g.event_correct},
                           {"expected", g.expected_event},
                           {"given", g.given_event}}},
                         {"variables", std::move(vars)},
                         {"why", g.why}});
    }
    return {{"score", {{"right", r.right}, {"answered", r.grades.size()}, {"steps", r.steps}}},
            {"wrong", r.wrong},
            {"steps", std::move(steps)}};
}

std::string report_text(const PredictReport& r) {
    std::string s;
    for (const PredictGrade& g : r.grades) {
        s += "step " + std::to_string(g.step) + ": " + (g.correct ? "right" : "wrong") + " — " +
             g.expected_event;
        for (const VarGrade& v : g.vars) s += ", " + v.name + " = " + show(v.expected);
        if (!g.correct) s += "  (" + g.why + ")";
        s += "\n";
    }
    s += "score: " + std::to_string(r.right) + " of " + std::to_string(r.grades.size()) +
         " predicted steps right";
    if (r.grades.size() < r.steps)
        s += " (" + std::to_string(r.steps - r.grades.size()) + " of the run's " +
             std::to_string(r.steps) + " steps not predicted)";
    s += "\n";
    if (!r.wrong.empty()) {
        s += "to revisit: steps";
        for (std::size_t k : r.wrong) s += " " + std::to_string(k);
        s += "\n";
    }
    return s;
}

}  // namespace cg::study
