// The study modes' files (docs/study-modes.md): a student's trace for `cgsandbox check` and a
// predictions file for `cgsandbox predict`, read and graded against an algorithm's example
// run, and a bug planted from a seed. Byte 0 picks the algorithm, byte 1 the mode and the
// seed; the rest is the file. Only InputError may escape, and every report must print.
#include <map>

#include "fuzz_support.hpp"
#include "study/bug.hpp"
#include "study/check.hpp"
#include "study/predict.hpp"

namespace {

const cg::study::Trace& example_trace(const cg::Algorithm& a) {
    static std::map<std::string, cg::study::Trace> traces;
    auto it = traces.find(a.spec->id);
    if (it == traces.end())
        it = traces.emplace(a.spec->id, cg::study::record(a, a.example())).first;
    return it->second;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const cg::Algorithm& a = cg::fuzz::pick(data[0]);
    const cg::Spec& spec = *a.spec;
    const cg::study::Trace& truth = example_trace(a);
    const std::string text(reinterpret_cast<const char*>(data + 2), size - 2);
    try {
        switch (data[1] % 3) {
            case 0: {
                const auto report =
                    cg::study::check_trace(spec, truth, cg::study::read_json_lines(text));
                (void)cg::study::check_json(report).dump();
                (void)cg::study::check_text(spec, report);
                if (report.agree && report.steps_given != truth.steps.size())
                    cg::fuzz::fail("a trace of another length agreed");
                break;
            }
            case 1: {
                std::vector<cg::study::Prediction> ps;
                const auto lines = cg::study::read_json_lines(text);
                for (std::size_t i = 0; i < lines.size(); ++i)
                    ps.push_back(
                        cg::study::prediction_from_json(lines[i], "line " + std::to_string(i + 1)));
                const auto report = cg::study::grade_predictions(spec, truth, ps);
                (void)cg::study::report_json(report).dump();
                (void)cg::study::report_text(report);
                if (report.right > report.grades.size()) cg::fuzz::fail("more right than graded");
                break;
            }
            default: {
                const auto bug = cg::study::plant_bug(spec, truth, data[1] / 3);
                if (bug.step < 1 || bug.step > truth.steps.size())
                    cg::fuzz::fail("a bug off the run");
                if (bug.steps.size() != truth.steps.size())
                    cg::fuzz::fail("a tampered trace of another length");
                std::size_t answer =
                    text.empty() ? 1 : static_cast<unsigned char>(text[0]) % truth.steps.size() + 1;
                (void)cg::study::grade_bug_answer(spec, bug, answer);
                break;
            }
        }
    } catch (const cg::InputError&) {
    }
    return 0;
}
