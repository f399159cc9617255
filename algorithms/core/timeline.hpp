// Stepping forward and back through a run, with bounded memory.
//
// A Timeline owns a Run and the history needed to revisit any earlier step. It keeps
//   - checkpoints: the state at every multiple of `stride`, and
//   - a window: every state (with its StepInfo) of a short stretch around the current step.
// Going back inside the window is a copy; going back past it replays at most `stride` steps
// from the nearest checkpoint and refills the window, so a back-step costs O(1) amortised.
// When the checkpoints grow past 2·stride the stride doubles and every other checkpoint is
// dropped, so memory grows like the square root of the run's length, never like the length.
// A byte budget caps it too, for algorithms whose states are big (a z-buffer's pixels, as
// Run::bytes reports them): the window and the checkpoints each keep to half of it, the window
// by dropping its oldest states, the checkpoints by doubling the stride early. Stepping back then
// replays more, but memory stays within the budget.
// Replay is exact because every algorithm is deterministic: the same state stepped gives the
// same next state, which the tests check.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "core/run.hpp"

namespace cg {

class Timeline {
public:
    // A run that has not finished after `max_steps` steps stops there (a guard against a
    // runaway algorithm; every algorithm here terminates far earlier).
    // States kept for stepping back stay within `max_bytes` (as Run::bytes counts them), except
    // that the start and the current state are always kept.
    static constexpr std::size_t kDefaultMaxBytes = std::size_t{512} << 20;  // 512 MiB
    explicit Timeline(std::unique_ptr<Run> initial, std::size_t max_steps = 50'000'000,
                      std::size_t max_bytes = kDefaultMaxBytes);

    std::size_t index() const { return index_; }  // steps taken to reach the current state
    const Run& current() const { return *at(index_).state; }
    // The step that led into the current state; null at the start.
    const StepInfo* last_step() const { return index_ ? &at(index_).info : nullptr; }
    bool at_end() const { return current().done() || index_ >= max_steps_; }
    bool hit_step_limit() const { return !current().done() && index_ >= max_steps_; }
    // The number of steps in the whole run, once the end has been reached.
    std::optional<std::size_t> length() const { return length_; }

    bool forward();               // false when already at the end
    bool back();                  // false when already at the start
    void jump(std::size_t n);     // to the state after n steps (or the end, if sooner)
    void to_end() { jump(max_steps_); }
    void reset() { jump(0); }

    // The StepInfos of steps first..last (1-based, inclusive), replaying where needed.
    std::vector<StepInfo> steps(std::size_t first, std::size_t last) const;

    // Memory accounting, for the tests.
    std::size_t stride() const { return stride_; }
    std::size_t stored_states() const { return checkpoints_.size() + window_.size(); }
    std::size_t stored_bytes() const { return checkpoint_bytes_ + window_bytes_; }

private:
    struct Entry {
        std::unique_ptr<Run> state;
        StepInfo info;  // the step that led into this state (empty for state 0)
        std::size_t bytes = 0;  // state->bytes(), once
        Entry copy() const { return {state->clone(), info, bytes}; }
    };

    const Entry& at(std::size_t i) const { return window_[i - window_first_]; }
    bool in_window(std::size_t i) const {
        return i >= window_first_ && i < window_first_ + window_.size();
    }
    void push_next();  // steps the last state of the window once, appending the result
    void restart_window(std::size_t i);  // window := {state i}, from the nearest checkpoint
    void note_checkpoint(std::size_t i, const Entry& e);
    void fast_forward(std::size_t n);  // towards n without narrating what the window drops
    void clear_window();
    void push_window(Entry e);
    void trim_window();  // drops the oldest states while over the window's limits
    std::size_t window_capacity() const;  // states the window keeps, by count and by bytes

    std::size_t max_steps_;
    std::size_t stride_ = 16;
    std::vector<Entry> checkpoints_;  // checkpoints_[k] is the state after k·stride_ steps
    std::deque<Entry> window_;        // window_[k] is the state after window_first_ + k steps
    std::size_t window_first_ = 0;
    std::size_t max_bytes_;
    std::size_t checkpoint_bytes_ = 0, window_bytes_ = 0;
    std::size_t index_ = 0;
    std::optional<std::size_t> length_;
};

}  // namespace cg
