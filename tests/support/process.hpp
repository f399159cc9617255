// Running build/bin/cgsandbox as a user would, for the CLI and GUI tests.
#pragma once

#include <string>
#include <vector>

namespace cg::test {

struct ProcessResult {
    int exit_code = -1;  // the exit status, or 128 + signal when killed by one
    std::string out, err;
};

// Runs argv[0] (looked up in PATH) with `stdin_text` on its standard input.
ProcessResult run_process(const std::vector<std::string>& argv, const std::string& stdin_text = "");

// `cgsandbox <args...>`.
ProcessResult cgsandbox(const std::vector<std::string>& args, const std::string& stdin_text = "");

// A fresh path under the build tree's test-output directory.
std::string output_path(const std::string& name);

// Writes text to a fresh file under test-output and returns its path.
std::string write_temp(const std::string& name, const std::string& text);

}  // namespace cg::test
