// The registry: every algorithm by id, behind one type-erased interface.
//
// The viewer, the CLI and the tests know algorithms only through this. An algorithm joins by
// providing its JSON adapter (a specialisation of JsonIo, in its own *_json.cpp, which also
// makes its Algorithm with make_algorithm<A>(plain) or make_algorithm<A>(NoPlain{why})) and
// one line in algorithms/algorithms.def.
#pragma once

#include <concepts>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "io/json.hpp"

namespace cg {

struct Algorithm {
    const Spec* spec = nullptr;
    std::function<json()> example;                              // a valid sample input
    std::function<std::unique_ptr<Run>(const json&)> create;    // throws InputError
    // Accepts and refuses exactly what create() does, with the same error, but prepares no run
    // (no hierarchy built, no study measured): what loading a lesson's presets needs.
    std::function<void(const json&)> check;
    std::function<json(const Run&)> result;                     // the result of a finished run

    // Exam practice; empty when the algorithm has no generator (see io/exam.hpp).
    std::function<json(std::uint64_t seed)> exam_input;  // a fresh exam-style input
    std::function<std::string(const json&)> question;    // the question for an input
    // The result fields that answer it; "a/b" names field b of the object in field a.
    std::function<std::vector<std::string>(const json&)> answer_fields;

    // The algorithm's straight-line function (no stepping, no narration) on an input create()
    // accepted, written as result JSON: the fuzz oracle holds run-to-end's result to it. Empty
    // when the algorithm has none, and then `no_plain` says why (a conformance test asks).
    std::function<json(const json&)> plain;
    std::string no_plain;
};

// What an algorithm without a plain function gives make_algorithm instead: the reason.
struct NoPlain {
    const char* why;
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
//     static json input_json(const typename A::Input&);
//     static json result(const typename A::Result&);
//     static json example();
template <class A>
struct JsonIo;

// An algorithm with an exam generator also has (in its <name>_exam.cpp, GLM + std only):
//     static Input exam_input(Rng&);                  // nice numbers, sometimes degenerate
//     static std::string question(const Input&);
//     static std::vector<std::string> answer_fields();
// or, when the question asks different things of different inputs,
//     static std::vector<std::string> answer_fields(const Input&);
template <class A>
concept HasFixedAnswers = requires {
    { A::answer_fields() } -> std::convertible_to<std::vector<std::string>>;
};
template <class A>
concept HasInputAnswers = requires(const typename A::Input& in) {
    { A::answer_fields(in) } -> std::convertible_to<std::vector<std::string>>;
};
template <class A>
concept HasExam = requires(Rng& rng, const typename A::Input& in) {
    { A::exam_input(rng) } -> std::same_as<typename A::Input>;
    { A::question(in) } -> std::convertible_to<std::string>;
} && (HasFixedAnswers<A> || HasInputAnswers<A>);

// An algorithm whose start() prepares something heavy (a hierarchy, a study's measurements)
// says in a static check(const Input&) what start() would refuse, without preparing it; for
// the others check() is start() discarded. The fuzz oracle holds check() to create() on every
// input it runs (tests/fuzz/oracles.hpp).
template <class A>
concept HasCheck = requires(const typename A::Input& in) { A::check(in); };

template <class A>
Algorithm make_algorithm() {
    Algorithm a{
        &A::spec(),
        [] { return JsonIo<A>::example(); },
        [](const json& j) -> std::unique_ptr<Run> {
            return std::make_unique<RunOf<A>>(A::start(JsonIo<A>::input(j)));
        },
        [](const json& j) {
            if constexpr (HasCheck<A>)
                A::check(JsonIo<A>::input(j));
            else
                (void)A::start(JsonIo<A>::input(j));
        },
        [](const Run& run) {
            return JsonIo<A>::result(A::result(static_cast<const RunOf<A>&>(run).state));
        },
        {},
        {},
        {},
        {},
        {},
    };
    if constexpr (HasExam<A>) {
        a.exam_input = [](std::uint64_t seed) {
            Rng rng(seed);
            return JsonIo<A>::input_json(A::exam_input(rng));
        };
        a.question = [](const json& j) { return text_minus(A::question(JsonIo<A>::input(j))); };
        if constexpr (HasInputAnswers<A>)
            a.answer_fields = [](const json& j) { return A::answer_fields(JsonIo<A>::input(j)); };
        else
            a.answer_fields = [](const json&) { return A::answer_fields(); };
    }
    return a;
}

// The same, with the plain function (any callable Result(const Input&)) or NoPlain{why}.
template <class A, class Plain>
Algorithm make_algorithm(Plain plain) {
    Algorithm a = make_algorithm<A>();
    if constexpr (std::is_same_v<Plain, NoPlain>) {
        a.no_plain = plain.why;
    } else {
        static_assert(std::is_invocable_r_v<typename A::Result, Plain, const typename A::Input&>,
                      "the plain function takes the algorithm's Input and returns its Result");
        a.plain = [plain](const json& j) { return JsonIo<A>::result(plain(JsonIo<A>::input(j))); };
    }
    return a;
}

}  // namespace cg
