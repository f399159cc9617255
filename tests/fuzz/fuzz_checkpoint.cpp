// Checkpoint files (the viewer's saved scenes, `cgsandbox render --checkpoint`): read and
// check one, start its algorithm on its input, and move a timeline to its step, drawing it.
// Only InputError may escape.
#include <algorithm>

#include "checkpoint.hpp"
#include "core/scene.hpp"
#include "core/timeline.hpp"
#include "fuzz_support.hpp"
#include "json_mutator.hpp"

// The whole input is one JSON document: mutate it within its shape (json_mutator.hpp).
CG_FUZZ_JSON_MUTATOR(0, nullptr)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        cg::Checkpoint c = cg::checkpoint_from_json(cg::parse_json(text), cg::fuzz::registry());
        (void)cg::checkpoint_to_json(c).dump();
        const cg::Algorithm* a = cg::fuzz::registry().find(c.algorithm);
        if (!a) cg::fuzz::fail("a checkpoint with an unknown algorithm was accepted");
        auto run = a->create(c.input);
        if (cg::fuzz::too_costly(*a, c.input)) return 0;  // valid, but minutes to run
        cg::Timeline timeline(std::move(run), cg::fuzz::kStepCap);
        timeline.jump(std::min<std::size_t>(c.step, cg::fuzz::kStepCap));
        cg::Scene scene;
        timeline.current().draw(scene);
    } catch (const cg::InputError&) {
    }
    return 0;
}
