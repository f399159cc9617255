#include "core/timeline.hpp"

#include <algorithm>

namespace cg {

Timeline::Timeline(std::unique_ptr<Run> initial, std::size_t max_steps) : max_steps_(max_steps) {
    Entry start{std::move(initial), {}};
    checkpoints_.push_back(start.copy());
    window_.push_back(std::move(start));
    if (current().done()) length_ = 0;
}

void Timeline::note_checkpoint(std::size_t i, const Entry& e) {
    if (i % stride_ != 0 || i / stride_ != checkpoints_.size()) return;  // not new
    checkpoints_.push_back(e.copy());
    // Keep the number of checkpoints near the stride: n/stride + 2·stride states in all.
    if (checkpoints_.size() > 2 * stride_ && checkpoints_.size() > 64) {
        std::vector<Entry> thinned;
        for (std::size_t k = 0; k < checkpoints_.size(); k += 2)
            thinned.push_back(std::move(checkpoints_[k]));
        checkpoints_ = std::move(thinned);
        stride_ *= 2;
    }
}

void Timeline::push_next() {
    const Entry& last = window_.back();
    Entry next{last.state->clone(), {}};
    next.state->step(&next.info);
    std::size_t i = window_first_ + window_.size();
    note_checkpoint(i, next);
    if (next.state->done()) length_ = i;
    window_.push_back(std::move(next));
    // The window never holds more than two strides; the current state is never dropped
    // because callers only push when the current state is the window's last.
    while (window_.size() > 2 * stride_ + 1) {
        window_.pop_front();
        ++window_first_;
    }
}

void Timeline::restart_window(std::size_t i) {
    std::size_t k = std::min(i / stride_, checkpoints_.size() - 1);
    window_.clear();
    window_.push_back(checkpoints_[k].copy());
    window_first_ = k * stride_;
    while (window_first_ + window_.size() <= i && !window_.back().state->done()) push_next();
}

bool Timeline::forward() {
    if (at_end()) return false;
    if (!in_window(index_ + 1)) push_next();  // the current state is the window's last
    ++index_;
    return true;
}

bool Timeline::back() {
    if (index_ == 0) return false;
    if (!in_window(index_ - 1)) restart_window(index_ - 1);
    --index_;
    return true;
}

void Timeline::jump(std::size_t n) {
    if (length_) n = std::min(n, *length_);
    n = std::min(n, max_steps_);
    if (in_window(n)) {
        index_ = n;
        return;
    }
    // Start from whichever is closer below n: the window's last state or the nearest
    // checkpoint. States after the current one in the window are valid successors, so
    // stepping on from the window's end is right in either case.
    std::size_t k = std::min(n / stride_, checkpoints_.size() - 1);
    std::size_t window_last = window_first_ + window_.size() - 1;
    if (n < window_first_ || k * stride_ > window_last) restart_window(std::min(n, k * stride_));
    fast_forward(n);
    while (window_first_ + window_.size() <= n && !window_.back().state->done()) push_next();
    index_ = std::min(n, window_first_ + window_.size() - 1);
}

void Timeline::fast_forward(std::size_t n) {
    // Only the last 2·stride states before n will stay in the window; the ones before them
    // are stepped in place without narration, except where a checkpoint is due (its step's
    // narration is kept with it) and the very last one (it becomes the window's first).
    std::size_t i = window_first_ + window_.size() - 1;
    if (n <= i + 2 * stride_ + 1 || window_.back().state->done()) return;
    const std::size_t until = n - (2 * stride_ + 1);
    std::unique_ptr<Run> run = window_.back().state->clone();
    StepInfo info;
    bool keep = false;
    while (i < until && !run->done()) {
        keep = (i + 1) % stride_ == 0 || i + 1 == until;
        info = {};
        run->step(keep ? &info : nullptr);
        ++i;
        if (run->done()) length_ = i;
        if (keep) note_checkpoint(i, Entry{run->clone(), info});
    }
    if (!keep) {
        // It ended on a quiet step, whose narration the end state needs: replay the last
        // stretch from its checkpoint (at most a stride of steps).
        restart_window(i);
        return;
    }
    window_.clear();
    window_.push_back(Entry{std::move(run), std::move(info)});
    window_first_ = i;
}

std::vector<StepInfo> Timeline::steps(std::size_t first, std::size_t last) const {
    std::vector<StepInfo> out;
    if (first == 0) first = 1;
    if (length_) last = std::min(last, *length_);
    std::unique_ptr<Run> run;  // the state after i - 1 steps, when outside the window
    for (std::size_t i = first; i <= last; ++i) {
        if (in_window(i)) {
            out.push_back(at(i).info);
            run.reset();
            continue;
        }
        if (!run) {
            if (in_window(i - 1)) {
                run = at(i - 1).state->clone();
            } else {
                std::size_t k = std::min((i - 1) / stride_, checkpoints_.size() - 1);
                run = checkpoints_[k].state->clone();
                for (std::size_t j = k * stride_; j < i - 1 && !run->done(); ++j) run->step(nullptr);
            }
        }
        if (run->done()) break;
        StepInfo info;
        run->step(&info);
        out.push_back(std::move(info));
    }
    return out;
}

}  // namespace cg
