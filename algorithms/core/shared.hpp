// An immutable value shared between copies of a state.
//
// A state machine's input never changes while it runs, yet every State carries it, and a
// State is copied whenever the timeline keeps a checkpoint, the viewer branches a run or the
// tests take a snapshot. Shared<T> holds the input once: copies share it (a reference count,
// no allocation), and equality still compares the values, so two states built from equal
// inputs compare equal as before.
#pragma once

#include <memory>
#include <utility>

namespace cg {

template <class T>
class Shared {
public:
    // A default Shared points at the type's one default value without owning it (shared_ptr's
    // aliasing constructor with no owner): no control block, so making, copying and replacing
    // it touch no reference count. `State s; s.in = std::move(in);` costs only the move.
    Shared() : p_(std::shared_ptr<const T>(), &empty()) {}
    explicit Shared(T value) : p_(std::make_shared<const T>(std::move(value))) {}

    const T& operator*() const { return *p_; }
    const T* operator->() const { return p_.get(); }
    const T& get() const { return *p_; }

    bool operator==(const Shared& o) const { return p_ == o.p_ || *p_ == *o.p_; }

private:
    // One default value per type, so that default-constructed states do not allocate.
    static const T& empty() {
        static const T e{};
        return e;
    }
    std::shared_ptr<const T> p_;
};

}  // namespace cg
