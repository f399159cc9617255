#include "core/timeline.hpp"

#include <algorithm>

namespace cg {

Timeline::Timeline(std::unique_ptr<Run> initial, std::size_t max_steps, std::size_t max_bytes)
    : max_steps_(max_steps), max_bytes_(max_bytes) {
    const std::size_t bytes = initial->bytes();
    Entry start{std::move(initial), {}, bytes};
    checkpoints_.push_back(start.copy());
    checkpoint_bytes_ = bytes;
    push_window(std::move(start));
    if (current().done()) length_ = 0;
}

void Timeline::clear_window() {
    window_.clear();
    window_bytes_ = 0;
}

void Timeline::push_window(Entry e) {
    window_bytes_ += e.bytes;
    window_.push_back(std::move(e));
    trim_window();
}

std::size_t Timeline::window_capacity() const {
    const std::size_t each = std::max<std::size_t>(window_.back().bytes, 1);
    return std::max<std::size_t>(1, std::min(2 * stride_ + 1, max_bytes_ / 2 / each));
}

void Timeline::trim_window() {
    // The window never holds more than two strides, nor more than half the byte budget; the
    // current state is never dropped because callers only push when the current state is the
    // window's last.
    while (window_.size() > 1 && (window_.size() > 2 * stride_ + 1 || window_bytes_ > max_bytes_ / 2)) {
        window_bytes_ -= window_.front().bytes;
        window_.pop_front();
        ++window_first_;
    }
}

void Timeline::note_checkpoint(std::size_t i, const Entry& e) {
    if (i % stride_ != 0 || i / stride_ != checkpoints_.size()) return;  // not new
    checkpoints_.push_back(e.copy());
    checkpoint_bytes_ += e.bytes;
    // Keep the number of checkpoints near the stride (n/stride + 2·stride states in all), and
    // their bytes within half the budget (the start is always kept).
    while ((checkpoints_.size() > 2 * stride_ && checkpoints_.size() > 64) ||
           (checkpoint_bytes_ > max_bytes_ / 2 && checkpoints_.size() > 1)) {
        std::vector<Entry> thinned;
        std::size_t bytes = 0;
        for (std::size_t k = 0; k < checkpoints_.size(); k += 2) {
            bytes += checkpoints_[k].bytes;
            thinned.push_back(std::move(checkpoints_[k]));
        }
        checkpoints_ = std::move(thinned);
        checkpoint_bytes_ = bytes;
        stride_ *= 2;
    }
}

void Timeline::push_next() {
    const Entry& last = window_.back();
    Entry next{last.state->clone(), {}, 0};
    next.state->step(&next.info);
    next.bytes = next.state->bytes();
    std::size_t i = window_first_ + window_.size();
    note_checkpoint(i, next);
    if (next.state->done()) length_ = i;
    push_window(std::move(next));
}

void Timeline::restart_window(std::size_t i) {
    std::size_t k = std::min(i / stride_, checkpoints_.size() - 1);
    clear_window();
    window_first_ = k * stride_;
    push_window(checkpoints_[k].copy());
    fast_forward(i);  // in place up to the stretch the window will keep (big states)
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
    // Only the last window_capacity() states before n will stay in the window; the ones before
    // them are stepped in place without narration, except where a checkpoint is due (its step's
    // narration is kept with it) and the very last one (it becomes the window's first).
    std::size_t i = window_first_ + window_.size() - 1;
    const std::size_t capacity = window_capacity();
    if (n <= i + capacity || window_.back().state->done()) return;
    const std::size_t until = n - capacity;
    std::unique_ptr<Run> run = window_.back().state->clone();
    StepInfo info;
    bool keep = false;
    while (i < until && !run->done()) {
        keep = (i + 1) % stride_ == 0 || i + 1 == until;
        info = {};
        run->step(keep ? &info : nullptr);
        ++i;
        if (run->done()) length_ = i;
        if (keep) note_checkpoint(i, Entry{run->clone(), info, run->bytes()});
    }
    if (!keep) {
        // It ended on a quiet step, whose narration the end state needs: replay the last
        // stretch from its checkpoint (at most a stride of steps).
        restart_window(i);
        return;
    }
    clear_window();
    window_first_ = i;
    const std::size_t bytes = run->bytes();
    push_window(Entry{std::move(run), std::move(info), bytes});
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
