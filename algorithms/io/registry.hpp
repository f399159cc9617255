// The registry: every algorithm by id, behind one type-erased interface.
//
// The viewer, the CLI and the tests know algorithms only through this. An algorithm joins by
// providing its JSON adapter (a specialisation of JsonIo, in its own *_json.cpp) and one line
// in algorithms/algorithms.def.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/run.hpp"
#include "io/json.hpp"

namespace cg {

struct Algorithm {
    const Spec* spec = nullptr;
    std::function<json()> example;                              // a valid sample input
    std::function<std::unique_ptr<Run>(const json&)> create;    // throws InputError
    std::function<json(const Run&)> result;                     // the result of a finished run
};

class Registry {
public:
    explicit Registry(std::vector<Algorithm> algorithms) : algorithms_(std::move(algorithms)) {}
    const std::vector<Algorithm>& all() const { return algorithms_; }
    const Algorithm* find(std::string_view id) const;

private:
    std::vector<Algorithm> algorithms_;
};

// Every algorithm of algorithms.def, in course order.
Registry builtin_registry();

// Specialised by each algorithm in its *_json.cpp:
//     static typename A::Input input(const json&);    // strict, naming fields; then A::start validates
//     static json result(const typename A::Result&);
//     static json example();
template <class A>
struct JsonIo;

template <class A>
Algorithm make_algorithm() {
    return Algorithm{
        &A::spec(),
        [] { return JsonIo<A>::example(); },
        [](const json& j) -> std::unique_ptr<Run> {
            return std::make_unique<RunOf<A>>(A::start(JsonIo<A>::input(j)));
        },
        [](const Run& run) {
            return JsonIo<A>::result(A::result(static_cast<const RunOf<A>&>(run).state));
        },
    };
}

}  // namespace cg
