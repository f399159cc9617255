// Lesson files: parse and check one lesson as the lesson loader does (its presets are run
// through their algorithm's validation). Only InputError may escape.
#include "fuzz_support.hpp"
#include "json_mutator.hpp"
#include "io/lesson.hpp"

// The whole input is one JSON document: mutate it within its shape (json_mutator.hpp).
CG_FUZZ_JSON_MUTATOR(0, nullptr)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        cg::Lesson lesson = cg::parse_lesson(cg::parse_json(text), cg::fuzz::registry());
        for (const auto& s : lesson.sections) (void)s.text.size();
        for (const auto& p : lesson.presets) (void)lesson.preset(p.name);
        for (const auto& e : lesson.events) (void)lesson.note_for(e.event);
    } catch (const cg::InputError&) {
    }
    return 0;
}
