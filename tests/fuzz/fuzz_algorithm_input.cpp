// Every algorithm's JSON input, through the path the CLI and the viewer take: parse, create
// (validation), then run to the end narrating and drawing every step, and the result, with
// the oracles of oracles.hpp (finite pictures and results, resumable copies, silent runs).
// Byte 0 picks the registered algorithm; the rest is the JSON text, mutated within its shape
// (json_mutator.hpp) so that most executions reach an algorithm. Only InputError may escape
// validation: any other exception, a crash, a sanitizer report or a broken oracle is a bug.
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fuzz_support.hpp"
#include "json_mutator.hpp"
#include "oracles.hpp"

namespace {

// Per algorithm: inputs tried, inputs accepted (run to the end or the cap), steps taken. Printed
// at exit, for the README's fuzz table.
struct Counts {
    unsigned long long tried = 0, accepted = 0, steps = 0;
};
std::vector<Counts>& counts() {
    static std::vector<Counts> c(cg::fuzz::registry().all().size());
    return c;
}

void print_counts() {
    const auto& all = cg::fuzz::registry().all();
    unsigned long long tried = 0, accepted = 0;
    for (std::size_t k = 0; k < all.size(); ++k) {
        const Counts& c = counts()[k];
        tried += c.tried, accepted += c.accepted;
        std::fprintf(stderr, "algorithm %s: %llu inputs, %llu accepted (%.0f%%), %llu steps\n",
                     all[k].spec->id.c_str(), c.tried, c.accepted,
                     c.tried ? 100.0 * double(c.accepted) / double(c.tried) : 0.0, c.steps);
    }
    std::fprintf(stderr, "algorithms: %llu inputs, %llu accepted (%.1f%%)\n", tried, accepted,
                 tried ? 100.0 * double(accepted) / double(tried) : 0.0);
}

// Whether the prefixed JSON passes validation: the mutator keeps the first of a few tries
// that does, so the corpus's invalid members (kept for the validators' coverage) do not pull
// most executions back into the validators.
bool accepted(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return false;
    try {
        (void)cg::fuzz::pick(data[0]).create(
            cg::parse_json(std::string(reinterpret_cast<const char*>(data) + 1, size - 1)));
        return true;
    } catch (const cg::InputError&) {
        return false;
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    counts();
    std::atexit(print_counts);
    return 0;
}

CG_FUZZ_JSON_MUTATOR(1, accepted)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const cg::Algorithm& a = cg::fuzz::pick(data[0]);
    Counts& count = counts()[data[0] % counts().size()];
    ++count.tried;
    cg::json input;
    try {
        input = cg::parse_json(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
    } catch (const cg::InputError&) {
        return 0;
    }
    try {
        const cg::fuzz::Outcome o = cg::fuzz::check_algorithm_input(a, input);
        count.accepted += o.accepted;
        count.steps += o.steps;
    } catch (const cg::fuzz::OracleViolation& e) {
        cg::fuzz::fail(e.what());
    }
    return 0;
}
