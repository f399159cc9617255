// One running algorithm behind a uniform interface.
//
// An algorithm is written as a plain struct of static functions over its own value types:
//
//     struct LiangBarsky {
//         using Input = ...; using State = ...; using Result = ...;
//         static const Spec& spec();
//         static State start(const Input&);             // validates, throws InputError
//         static void step(State&, StepInfo* info);      // one teachable step; info may be null
//         static bool done(const State&);
//         static Result result(const State&);
//         static void draw(const State&, Scene&);
//     };
//
// The State is a copyable value with a defaulted operator==, so a copy is a snapshot and the
// determinism tests can compare states. RunOf<A> wraps it for the registry, the timeline and
// the viewer, which never see the concrete types. Passing a null StepInfo skips the narration
// so that running to completion costs about as much as a plain loop.
#pragma once

#include <concepts>
#include <cstddef>
#include <memory>
#include <vector>

#include "core/format.hpp"
#include "core/scene.hpp"
#include "core/step.hpp"

namespace cg {

// For an algorithm's optional `static std::size_t bytes(const State&)` (see Run::bytes): the
// heap memory a vector holds, and a vector of vectors.
template <class T>
std::size_t heap_bytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}
template <class T>
std::size_t heap_bytes(const std::vector<std::vector<T>>& v) {
    std::size_t n = v.capacity() * sizeof(std::vector<T>);
    for (const auto& x : v) n += heap_bytes(x);
    return n;
}

class Run {
public:
    virtual ~Run() = default;
    virtual std::unique_ptr<Run> clone() const = 0;
    virtual const Spec& spec() const = 0;
    virtual bool done() const = 0;
    virtual void step(StepInfo* info) = 0;  // precondition: !done()
    virtual void draw(Scene& scene) const = 0;
    virtual bool same_state(const Run& other) const = 0;
    // About how much memory this state holds, for the timeline's memory budget: the object
    // itself plus what an algorithm with big states (pixel buffers, long lists) reports through
    // an optional `static std::size_t bytes(const State&)` (its heap memory).
    virtual std::size_t bytes() const { return sizeof(*this); }
};

template <class A>
class RunOf final : public Run {
public:
    explicit RunOf(typename A::State s) : state(std::move(s)) {}

    std::unique_ptr<Run> clone() const override { return std::make_unique<RunOf>(*this); }
    const Spec& spec() const override { return A::spec(); }
    bool done() const override { return A::done(state); }
    // The narration as the student reads it: one minus sign (text_minus) whatever the
    // algorithm's sentence wrote.
    void step(StepInfo* info) override {
        A::step(state, info);
        if (info) info->narration = text_minus(info->narration);
    }
    void draw(Scene& scene) const override { A::draw(state, scene); }
    bool same_state(const Run& other) const override {
        auto* o = dynamic_cast<const RunOf*>(&other);
        return o && o->state == state;
    }
    std::size_t bytes() const override {
        if constexpr (requires(const typename A::State& st) {
                          { A::bytes(st) } -> std::convertible_to<std::size_t>;
                      })
            return sizeof(*this) + A::bytes(state);
        else
            return sizeof(*this);
    }

    typename A::State state;
};

// Steps a state to the end without narration: the "plain loop" path of the benchmarks.
// `flatten` asks the compiler to inline the step (with link-time optimisation, across files),
// so the loop costs what a hand-written one would. The spent state is handed to result() as
// an rvalue, as a hand-written loop would move its lists into its result: an algorithm whose
// result is big may add `static Result result(State&&)` to move them out instead of copying
// (Sutherland-Hodgman does); `result(const State&)` still serves everyone else.
//
// A temporary state (`run_to_end<A>(A::start(in))`) is stepped where it stands: taking it by
// value made the inlined call copy it once more, and for a state of a few hundred bytes
// (ray-quadric's, with its matrices) that copy cost as much as a step. A named state is
// copied first and left as it was.
template <class A>
[[gnu::flatten]] typename A::Result run_to_end(typename A::State&& s) {
    while (!A::done(s)) A::step(s, nullptr);
    return A::result(std::move(s));
}
template <class A>
typename A::Result run_to_end(const typename A::State& s) {
    return run_to_end<A>(typename A::State(s));
}

}  // namespace cg
