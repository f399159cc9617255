#include "cli_study.hpp"

#include <iostream>

#include "checkpoint.hpp"
#include "cli_common.hpp"
#include "io/exam.hpp"
#include "study/bug.hpp"
#include "study/check.hpp"
#include "study/compare.hpp"
#include "study/predict.hpp"

namespace cg::cli {

namespace {

constexpr int kExitDiffers = 1;

void add_source(CLI::App* cmd, std::string& input_path, std::string& preset,
                std::optional<std::uint64_t>& seed) {
    cmd->add_option("--input,-i", input_path,
                    "Input JSON file, or - for stdin (default: the example)");
    cmd->add_option("--preset,-p", preset, "A preset of the algorithm's lesson, by name");
    cmd->add_option("--seed,-s", seed, "The exam generator's problem with this seed");
}

study::Trace record_or_fail(const Algorithm& algorithm, const json& input,
                            const std::string& source) {
    try {
        return study::record(algorithm, input);
    } catch (const InputError& e) {
        fail(source, e);
    }
}

std::vector<json> read_file_json_lines(const std::string& path) {
    try {
        return study::read_json_lines(read_text_file(path));
    } catch (const InputError& e) {
        fail(source_name(path), e);
    }
}

}  // namespace

StudyCommands::StudyCommands(CLI::App& app) {
    predict_ = app.add_subcommand(
        "predict",
        "Predict each step before it is shown: print the questions, or grade a file of "
        "predictions (one JSON object per line: {\"step\", \"event\", \"variables\"})");
    predict_->add_option("ID", id_, "Algorithm id (see `list`)")->required();
    add_source(predict_, source_.input_path, source_.preset, source_.seed);
    predict_->add_option("--answers,-a", answers_path_, "The predictions to grade (JSON Lines)");
    predict_->add_option("--format,-f", format_, "text or json")
        ->check(CLI::IsMember({"text", "json"}));

    compare_ = app.add_subcommand(
        "compare",
        "Run two algorithms (or one in two variants, ID@VARIANT, or on two inputs) on one "
        "input and print where they agree and differ, as one JSON object");
    compare_->add_option("ID_A", id_, "First algorithm: an id, or ID@VARIANT")->required();
    compare_->add_option("ID_B", id_b_, "Second algorithm: an id, or ID@VARIANT")->required();
    add_source(compare_, source_.input_path, source_.preset, source_.seed);
    compare_->add_option("--input-b", input_b_path_,
                         "A second input for the second side (an edited copy)");

    bug_ = app.add_subcommand(
        "bug",
        "Find the bug: print a run's working with one student mistake planted in it "
        "(the format of `run --trace`); with --answer, grade a guess of the first wrong step");
    bug_->add_option("ID", id_, "Algorithm id (see `list`)")->required();
    bug_->add_option("--seed,-s", bug_seed_, "Which mistake, where: same seed, same bug")
        ->required();
    bug_->add_option("--input,-i", source_.input_path,
                     "Input JSON file (default: exam problem SEED, or the example)");
    bug_->add_option("--preset,-p", source_.preset, "A preset of the algorithm's lesson, by name");
    bug_->add_option("--answer", bug_answer_,
                     "Your guess of the first wrong step (exit 0 right, 1 wrong)");

    check_ = app.add_subcommand(
        "check",
        "Check your own implementation: compare its trace (JSON Lines, the format of "
        "`run --trace`) with the sandbox's, step by step. Exit 0 all agree, 1 a step "
        "differs, 2 unreadable input");
    check_->add_option("ID", id_, "Algorithm id (see `list`)")->required();
    add_source(check_, source_.input_path, source_.preset, source_.seed);
    check_->add_option("--trace,-t", trace_path_, "Your trace, one JSON object per step")
        ->required();
    check_->add_option("--tolerance", tolerance_, "Relative tolerance for numbers (default 1e-3)")
        ->check(CLI::Range(0.0, 1.0));
    check_->add_option("--format,-f", format_, "text or json")
        ->check(CLI::IsMember({"text", "json"}));
}

std::optional<int> StudyCommands::run(const Registry& registry) const {
    if (*predict_) return predict(registry);
    if (*compare_) return compare(registry);
    if (*bug_) return bug(registry);
    if (*check_) return check(registry);
    return std::nullopt;
}

int StudyCommands::predict(const Registry& registry) const {
    const Algorithm& algorithm = find_algorithm(registry, id_);
    const Spec& spec = *algorithm.spec;
    const ChosenInput in =
        choose_input(registry, algorithm, source_.input_path, source_.preset, source_.seed);
    const study::Trace trace = record_or_fail(algorithm, in.input, in.source);
    std::string out;
    if (answers_path_.empty()) {  // the questions, one per step
        for (std::size_t k = 1; k <= trace.steps.size(); ++k) {
            const StepInfo* before = k > 1 ? &trace.steps[k - 2] : nullptr;
            out += format_ == "json" ? study::predict_question_json(spec, k, before).dump() + "\n"
                                     : study::predict_question(spec, k, before) + "\n";
        }
        emit(out, "");
        return 0;
    }
    const std::vector<json> lines = read_file_json_lines(answers_path_);
    std::vector<study::Prediction> predictions;
    study::PredictReport report;
    try {
        for (std::size_t i = 0; i < lines.size(); ++i)
            predictions.push_back(
                study::prediction_from_json(lines[i], "prediction " + std::to_string(i + 1)));
        report = study::grade_predictions(spec, trace, predictions);
    } catch (const InputError& e) {
        fail(source_name(answers_path_), e);
    }
    emit(format_ == "json" ? pretty(study::report_json(report)) + "\n" : study::report_text(report),
         "");
    return 0;
}

int StudyCommands::compare(const Registry& registry) const {
    study::Side a, b;
    try {
        a = study::parse_side(registry, id_);
        b = study::parse_side(registry, id_b_);
        study::check_comparable(a, b);
    } catch (const InputError& e) {
        throw UserError{"", e.what()};
    }
    const ChosenInput in =
        choose_input(registry, *a.algorithm, source_.input_path, source_.preset, source_.seed);
    json input_b = in.input;
    std::string source_b = in.source;
    if (!input_b_path_.empty()) {
        input_b = load_input(*b.algorithm, input_b_path_);
        source_b = source_name(input_b_path_);
    }
    const study::Trace ta = record_or_fail(*a.algorithm, study::side_input(a, in.input), in.source);
    const study::Trace tb = record_or_fail(*b.algorithm, study::side_input(b, input_b), source_b);
    const study::Comparison c = study::compare(a, ta, b, tb);
    emit(pretty(study::comparison_json(a, b, c)) + "\n", "");
    return 0;
}

int StudyCommands::bug(const Registry& registry) const {
    const Algorithm& algorithm = find_algorithm(registry, id_);
    const Spec& spec = *algorithm.spec;
    ChosenInput in;
    std::optional<study::PlantedBug> planted;
    if (!source_.input_path.empty() || !source_.preset.empty()) {
        in = choose_input(registry, algorithm, source_.input_path, source_.preset, std::nullopt);
        try {
            planted =
                study::plant_bug(spec, record_or_fail(algorithm, in.input, in.source), *bug_seed_);
        } catch (const InputError& e) {
            fail(in.source, e);
        }
    } else {
        // The exam problem of this seed when the algorithm has a generator and a mistake shows
        // on it; otherwise the example.
        if (has_exam(algorithm)) {
            in = choose_input(registry, algorithm, "", "", bug_seed_);
            try {
                planted = study::plant_bug(spec, record_or_fail(algorithm, in.input, in.source),
                                           *bug_seed_);
            } catch (const InputError&) {
            }
        }
        if (!planted) {
            in = choose_input(registry, algorithm, "", "", std::nullopt);
            try {
                planted = study::plant_bug(spec, record_or_fail(algorithm, in.input, in.source),
                                           *bug_seed_);
            } catch (const InputError& e) {
                fail(in.source, e);
            }
        }
    }
    if (!bug_answer_) {
        std::string out;
        for (std::size_t k = 0; k < planted->steps.size(); ++k)
            out += step_to_json(k + 1, planted->steps[k]).dump() + "\n";
        emit(out, "");
        return 0;
    }
    if (*bug_answer_ < 1 || static_cast<std::size_t>(*bug_answer_) > planted->steps.size())
        throw UserError{"", "--answer must be a step from 1 to " +
                                std::to_string(planted->steps.size()) + ", got " +
                                std::to_string(*bug_answer_)};
    const study::BugGrade g =
        study::grade_bug_answer(spec, *planted, static_cast<std::size_t>(*bug_answer_));
    emit(g.text, "");
    return g.correct ? 0 : kExitDiffers;
}

int StudyCommands::check(const Registry& registry) const {
    const Algorithm& algorithm = find_algorithm(registry, id_);
    const ChosenInput in =
        choose_input(registry, algorithm, source_.input_path, source_.preset, source_.seed);
    const study::Trace trace = record_or_fail(algorithm, in.input, in.source);
    const std::vector<json> lines = read_file_json_lines(trace_path_);
    study::CheckReport report;
    try {
        report = study::check_trace(*algorithm.spec, trace, lines, tolerance_);
    } catch (const InputError& e) {
        fail(source_name(trace_path_), e);
    }
    emit(format_ == "json" ? pretty(study::check_json(report)) + "\n"
                           : study::check_text(*algorithm.spec, report),
         "");
    return report.agree ? 0 : kExitDiffers;
}

}  // namespace cg::cli
