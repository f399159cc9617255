#include "support/process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

extern char** environ;

namespace cg::test {

namespace {
std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}
}  // namespace

std::string output_path(const std::string& name) {
    std::filesystem::create_directories(CG_TEST_OUTPUT_DIR);
    return std::string(CG_TEST_OUTPUT_DIR) + "/" + std::to_string(::getpid()) + "-" + name;
}

std::string write_temp(const std::string& name, const std::string& text) {
    std::string path = output_path(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

namespace {

// `env`: the environment to run with (this process's own by default).
ProcessResult run_once(const std::vector<std::string>& argv, const std::string& stdin_text,
                       char* const* env = environ) {
    static int counter = 0;  // distinct temp files per call within this test process
    const std::string base = output_path("proc" + std::to_string(counter++));
    const std::string in_path = base + ".in", out_path = base + ".out", err_path = base + ".err";
    std::ofstream(in_path, std::ios::binary) << stdin_text;

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, in_path.c_str(), O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), env);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw std::runtime_error("cannot start " + argv[0]);
    int status = 0;
    waitpid(pid, &status, 0);

    ProcessResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(out_path);
    r.err = slurp(err_path);
    std::filesystem::remove(in_path);
    std::filesystem::remove(out_path);
    std::filesystem::remove(err_path);
    return r;
}

}  // namespace

// Under the sanitizers, LeakSanitizer's own tracer sometimes crashes at a program's exit
// ("Tracer caught signal 11", then "LeakSanitizer has encountered a fatal error") while it
// stops the world: seen with a GUI render (Mesa's threads about) under a loaded `ctest -j2`,
// twice in a row. That is LSan failing, not a leak found (a leak reads "detected memory
// leaks"), so such a run is repeated with ASAN_OPTIONS's detect_leaks=0 — everything else the
// run checks is still checked, and every other run keeps its leak check.
ProcessResult run_process(const std::vector<std::string>& argv, const std::string& stdin_text) {
    ProcessResult r = run_once(argv, stdin_text);
    if (r.exit_code == 0 || r.err.find("LeakSanitizer has encountered a fatal error") == std::string::npos)
        return r;
    std::vector<std::string> vars;
    std::string asan = "ASAN_OPTIONS=";
    for (char* const* e = environ; *e; ++e) {
        const std::string v = *e;
        if (v.rfind("ASAN_OPTIONS=", 0) == 0) asan = v + ":";
        else vars.push_back(v);
    }
    vars.push_back(asan + "detect_leaks=0");
    std::vector<char*> env;
    for (std::string& v : vars) env.push_back(v.data());
    env.push_back(nullptr);
    return run_once(argv, stdin_text, env.data());
}

ProcessResult cgsandbox(const std::vector<std::string>& args, const std::string& stdin_text) {
    std::vector<std::string> argv{CG_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv, stdin_text);
}

}  // namespace cg::test
