// The timeline driven by fuzzed commands: step, back, jump, to the end, reset, and reading a
// range of steps, on a registered algorithm's example or one of its exam problems. After every
// command the timeline must be where a plain model of it says, showing the very step a straight
// run produced there (replay through checkpoints is exact), and within its memory bound.
//
// Byte 0 picks the algorithm, byte 1 the input (0: the example, else an exam seed), then each
// command is one byte (its kind) and, for jump and range, two more (the step).
#include <cmath>
#include <map>
#include <vector>

#include "core/timeline.hpp"
#include "fuzz_support.hpp"
#include "io/exam.hpp"

namespace {

struct Reference {
    std::vector<cg::StepInfo> steps;  // steps[i]: the step that led into state i + 1
    std::size_t length = 0;           // steps to the end (capped)
};

const Reference& reference(const cg::Algorithm& a, const cg::json& input, const std::string& key) {
    static std::map<std::string, Reference> cache;
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    Reference r;
    auto run = a.create(input);
    while (!run->done() && r.steps.size() < cg::fuzz::kStepCap) {
        cg::StepInfo info;
        run->step(&info);
        r.steps.push_back(std::move(info));
    }
    r.length = r.steps.size();
    if (cache.size() > 256) cache.clear();
    return cache.emplace(key, std::move(r)).first->second;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const cg::Algorithm& a = cg::fuzz::pick(data[0]);
    cg::json input = a.example();
    std::string key = a.spec->id + "/example";
    if (data[1] != 0 && cg::has_exam(a)) {
        input = a.exam_input(data[1]);
        key = a.spec->id + "/" + std::to_string(data[1]);
    }
    const Reference& ref = reference(a, input, key);
    cg::Timeline t(a.create(input), cg::fuzz::kStepCap);
    std::size_t model = 0;
    auto check = [&](const char* after) {
        if (t.index() != model)
            cg::fuzz::fail(std::string("index after ") + after + ": " + std::to_string(t.index()) +
                           " instead of " + std::to_string(model));
        if (model == 0 ? t.last_step() != nullptr : !(t.last_step() && *t.last_step() == ref.steps[model - 1]))
            cg::fuzz::fail(std::string("the step shown after ") + after + " differs from the straight run's");
        if (t.at_end() != (model == ref.length))
            cg::fuzz::fail(std::string("at_end after ") + after);
        // Memory: at most max(2·stride, 64) + 1 checkpoints and a window of 2·stride + 1 states,
        // with stride <= sqrt(2·length) + 16 (see core/timeline.hpp): O(sqrt(length)).
        const double bound = 4 * std::sqrt(2.0 * static_cast<double>(ref.length)) + 140;
        if (t.stored_states() > bound) cg::fuzz::fail("more states stored than the bound");
    };
    for (std::size_t i = 2; i < size;) {
        const std::uint8_t op = data[i++] % 6;
        const std::size_t arg = i + 1 < size ? (data[i] | data[i + 1] << 8) : 0;
        switch (op) {
            case 0:
                if (t.forward() != (model < ref.length)) cg::fuzz::fail("forward's answer");
                if (model < ref.length) ++model;
                check("forward");
                break;
            case 1:
                if (t.back() != (model > 0)) cg::fuzz::fail("back's answer");
                if (model > 0) --model;
                check("back");
                break;
            case 2:
                i += 2;
                t.jump(arg);
                model = std::min(arg, ref.length);
                check("jump");
                break;
            case 3:
                t.to_end();
                model = ref.length;
                check("to_end");
                break;
            case 4:
                t.reset();
                model = 0;
                check("reset");
                break;
            case 5: {
                i += 2;
                if (ref.length == 0) break;
                const std::size_t first = 1 + arg % ref.length;
                const std::size_t last = std::min(ref.length, first + (arg >> 8) % 64);
                const auto steps = t.steps(first, last);
                if (steps.size() != last - first + 1) cg::fuzz::fail("steps(): wrong count");
                for (std::size_t k = 0; k < steps.size(); ++k)
                    if (!(steps[k] == ref.steps[first - 1 + k])) cg::fuzz::fail("steps(): a different step");
                check("steps");
                break;
            }
        }
    }
    return 0;
}
