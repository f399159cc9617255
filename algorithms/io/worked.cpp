#include "io/worked.hpp"

#include "core/format.hpp"

namespace cg {

WorkedExample work(const Algorithm& a, ExamProblem problem, std::string subtitle) {
    WorkedExample w;
    w.algorithm = &a;
    w.subtitle = std::move(subtitle);
    auto run = a.create(problem.input);
    while (!run->done()) {
        StepInfo info;
        run->step(&info);
        w.steps.push_back(std::move(info));
    }
    w.result = a.result(*run);
    w.problem = std::move(problem);
    return w;
}

namespace {

// A result value as a reader expects it: numbers short, points in parentheses.
std::string show(const json& v) {
    if (v.is_null()) return "none";
    if (v.is_number()) return num(v.get<double>());
    if (v.is_array()) {
        bool flat = !v.empty();  // an empty list is a list, not a point
        for (const json& e : v) flat = flat && e.is_number();
        std::string s = flat ? "(" : "[";
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + show(v[i]);
        return s + (flat ? ")" : "]");
    }
    if (v.is_string()) return v.get<std::string>();
    return v.dump();
}

}  // namespace

std::string worked_markdown(const WorkedExample& w) {
    const Spec& spec = *w.algorithm->spec;
    std::string md = "# " + spec.title + " — worked example";
    if (!w.subtitle.empty()) md += ": " + w.subtitle;
    md += "\n\n**Question.** " + w.problem.question + "\n\n";
    md += "**Input.**\n\n```json\n" + pretty(w.problem.input) + "\n```\n\n";
    md += "**Pseudocode.**\n\n```text\n";
    for (std::size_t i = 0; i < spec.pseudocode.size(); ++i) {
        std::string n = std::to_string(i + 1);
        md += std::string(3 - std::min<std::size_t>(3, n.size()), ' ') + n + "  " + spec.pseudocode[i] + "\n";
    }
    md += "```\n\n**Solution.**\n\n";
    for (std::size_t i = 0; i < w.steps.size(); ++i) {
        const StepInfo& s = w.steps[i];
        md += std::to_string(i + 1) + ". *" + s.event + "* (line " + std::to_string(s.line) + ") — " +
              s.narration + "\n";
        if (!s.math.empty()) md += "\n   $$" + s.math + "$$\n";
        md += "\n";
    }
    md += "**Answer.**\n\n| | |\n|---|---|\n";
    const auto& fields = w.problem.answers;
    if (!fields.empty()) {
        for (const std::string& f : fields) md += "| " + f + " | " + show(answer_value(w.result, f)) + " |\n";
    } else {
        for (auto it = w.result.begin(); it != w.result.end(); ++it)
            md += "| " + it.key() + " | " + show(it.value()) + " |\n";
    }
    return md;
}

json worked_json(const WorkedExample& w) {
    json steps = json::array();
    for (std::size_t i = 0; i < w.steps.size(); ++i) steps.push_back(step_to_json(i + 1, w.steps[i]));
    return json{{"algorithm", w.algorithm->spec->id},
                {"title", w.algorithm->spec->title},
                {"subtitle", w.subtitle},
                {"question", w.problem.question},
                {"input", w.problem.input},
                {"pseudocode", w.algorithm->spec->pseudocode},
                {"steps", std::move(steps)},
                {"result", w.result},
                {"answers", w.problem.answers}};
}

}  // namespace cg
