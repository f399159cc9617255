// Lesson files: parse and check one lesson as the lesson loader does (its presets are run
// through their algorithm's validation). Only InputError may escape.
#include "fuzz_support.hpp"
#include "io/lesson.hpp"

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
