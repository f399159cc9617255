#include "viewer/export.hpp"

#include "io/worked.hpp"

namespace cg::viewer {

std::string export_worked(const Session& s, bool as_json) {
    if (!s.algorithm) throw InputError("", "no algorithm is running");
    if (!s.input_error.empty())
        throw InputError("", "the input was refused (" + s.input_error + "); fix it first");
    WorkedExample w;
    if (s.exam.active) {
        w = work(*s.algorithm, s.exam.problem,
                 "exam problem, seed " + std::to_string(s.exam.problem.seed));
    } else {
        const LessonPreset* p = s.loaded_preset();
        // Exactly what `cgsandbox worked ID --preset NAME` (or --input) writes.
        w = work(*s.algorithm, exam_for_input(*s.algorithm, s.input), p ? p->name : "");
    }
    return as_json ? pretty(worked_json(w)) + "\n" : worked_markdown(w);
}

bool exports_json(const std::string& path) {
    constexpr std::string_view kJson = ".json";
    return path.size() >= kJson.size() &&
           path.compare(path.size() - kJson.size(), kJson.size(), kJson) == 0;
}

std::string default_export_path(const Algorithm& a) {
    return "worked-" + a.spec->id + ".md";
}

}  // namespace cg::viewer
