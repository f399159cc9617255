// A run of one algorithm's state machine with every step narrated: the steps and the result,
// for tests that check the narration and the numbers of one input.
#pragma once

#include <string>
#include <vector>

#include "core/step.hpp"

namespace cg::test {

template <class A>
struct Traced {
    typename A::Result result;
    std::vector<StepInfo> steps;
};

template <class A>
Traced<A> run_traced(const typename A::Input& in) {
    Traced<A> t;
    auto s = A::start(in);
    while (!A::done(s)) {
        StepInfo info;
        A::step(s, &info);
        t.steps.push_back(info);
    }
    t.result = A::result(s);
    return t;
}

// The event ids of a traced run's steps, in order: anything with a `steps` list of StepInfo.
template <class T>
std::vector<std::string> events(const T& traced) {
    std::vector<std::string> e;
    for (const StepInfo& s : traced.steps) e.push_back(s.event);
    return e;
}

}  // namespace cg::test
