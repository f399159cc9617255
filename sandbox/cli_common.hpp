// What the command line's commands share: the user-facing error, where inputs come from, and
// where output goes. Every error is one line on stderr, "cgsandbox: <source>: <message>",
// with exit code 2 (cli.cpp catches UserError).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "io/lesson.hpp"
#include "io/registry.hpp"

namespace cg::cli {

constexpr int kExitBadInput = 2;
constexpr std::size_t kMaxSteps = 50'000'000;  // no algorithm here comes near; a hang guard

// An error for the user: printed as "cgsandbox: <source>: <field>: <reason>".
struct UserError {
    std::string source;  // file name, "<stdin>", or empty
    std::string message;
};

[[noreturn]] void fail(const std::string& source, const InputError& e);
const Algorithm& find_algorithm(const Registry& registry, const std::string& id);
std::string source_name(const std::string& path);
// The input from --input FILE (or "-"), or the algorithm's example when none is given.
json load_input(const Algorithm& algorithm, const std::string& path);
std::unique_ptr<Run> create_run(const Algorithm& algorithm, const json& input,
                                const std::string& source);
// Writes text to --out FILE, or to stdout.
void emit(const std::string& text, const std::string& out_path);
LessonLibrary load_lesson_library(const Registry& registry);
// A preset of `lesson` by name; a wrong name lists the right ones.
const LessonPreset& find_preset(const Lesson& lesson, const std::string& name);

// An input chosen the way the study commands take it: --input FILE, --preset NAME (of the
// algorithm's lesson), --seed N (the exam generator's problem N), or else the example.
struct ChosenInput {
    json input;
    std::string source;  // for error messages: the file, "lessons/110-….json", "exam problem 3"
};
ChosenInput choose_input(const Registry& registry, const Algorithm& algorithm,
                         const std::string& input_path, const std::string& preset,
                         std::optional<std::uint64_t> seed);

}  // namespace cg::cli
