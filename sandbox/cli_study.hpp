// The study modes on the command line (docs/study-modes.md):
//   predict ID [--input F | --preset P | --seed N] [--answers FILE]   predict, then reveal
//   compare A B [--input F] [--input-b F]                             two runs side by side
//   bug ID --seed N [--answer STEP]                                   find the planted mistake
//   check ID [--input F] --trace MINE.jsonl                           your code against ours
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "io/registry.hpp"

namespace cg::cli {

class StudyCommands {
  public:
    explicit StudyCommands(CLI::App& app);
    // The exit code of the study command given on the command line; nothing if none was.
    std::optional<int> run(const Registry& registry) const;

  private:
    struct Source {  // where a command's input comes from
        std::string input_path, preset;
        std::optional<std::uint64_t> seed;
    };
    int predict(const Registry& registry) const;
    int compare(const Registry& registry) const;
    int bug(const Registry& registry) const;
    int check(const Registry& registry) const;

    CLI::App *predict_ = nullptr, *compare_ = nullptr, *bug_ = nullptr, *check_ = nullptr;
    std::string id_, id_b_, answers_path_, input_b_path_, trace_path_, format_ = "text";
    Source source_;
    std::optional<std::uint64_t> bug_seed_;
    std::optional<long long> bug_answer_;
    double tolerance_ = 1e-3;
};

}  // namespace cg::cli
