// Running an algorithm as the CLI and the viewer do: found by id in the registry, given JSON,
// stepped to the end with every step narrated. For tests of the JSON contract: the field
// names, the error messages, the result as JSON and the narration of each step.
#pragma once

#include <string>
#include <vector>

#include "core/step.hpp"
#include "io/registry.hpp"
#include "support/traced.hpp"  // events(): the event ids of a JsonTraced too

namespace cg::test {

inline const Registry& registry() {
    static const Registry r = builtin_registry();
    return r;
}

// The algorithm with this id; a test of a missing id fails here rather than crashing.
inline const Algorithm& algorithm(const std::string& id) {
    const Algorithm* a = registry().find(id);
    if (!a) throw std::runtime_error("no algorithm " + id + " in the registry");
    return *a;
}

// A finished run: the result as the CLI prints it and every step's narration.
struct JsonTraced {
    json result;
    std::vector<StepInfo> steps;
};

inline JsonTraced run_json(const std::string& id, const json& input) {
    const Algorithm& a = algorithm(id);
    auto run = a.create(input);
    JsonTraced t;
    while (!run->done()) {
        StepInfo info;
        run->step(&info);
        t.steps.push_back(info);
    }
    t.result = a.result(*run);
    return t;
}

inline JsonTraced run_json(const std::string& id, const std::string& text) {
    return run_json(id, parse_json(text));
}

// Only the result, stepping without narration (as the CLI's `run` does).
inline json result_of(const std::string& id, const json& input) {
    const Algorithm& a = algorithm(id);
    auto run = a.create(input);
    while (!run->done()) run->step(nullptr);
    return a.result(*run);
}

inline json result_of(const std::string& id, const std::string& text) {
    return result_of(id, parse_json(text));
}

// The InputError message a JSON text gets, or "(accepted)" when the run goes through.
inline std::string error_of(const std::string& id, const std::string& text) {
    try {
        result_of(id, text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

// The typed input the JSON adapter (the algorithm's _json.cpp) reads from a JSON input: taken
// from the started state, for algorithms whose state shares its input as `in`.
template <class A>
typename A::Input input_of(const std::string& id, const json& input) {
    auto run = algorithm(id).create(input);
    return *static_cast<RunOf<A>&>(*run).state.in;
}

}  // namespace cg::test
