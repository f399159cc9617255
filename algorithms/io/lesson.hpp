// Lessons: data files in lessons/ that turn an algorithm into a lecture a student can step.
//
// A lesson is one JSON file:
//     {"id", "title", "topic", "order" (position in the course), "algorithm" (registry id),
//      "exam": {"weight": "high" | "medium" | "low" | "none", "note": "..."},
//      "presets": [{"name", "input"}, ...],          // at least one; each must run
//      "sections": [{"title", "text"}, ...],         // the teaching text, in order
//      "events": {"<event kind>": "text", ...}}      // optional; shown when a step emits it
// Text is Markdown-ish: paragraphs, "- " bullets, inline math between $ … $ in LaTeX, which
// the viewer shows as readable Unicode and the Markdown export keeps. Adding a lesson needs
// no code change: drop the file in lessons/.
#pragma once

#include <string>
#include <vector>

#include "io/registry.hpp"

namespace cg {

struct LessonPreset {
    std::string name;
    json input;
};

struct LessonSection {
    std::string title;
    std::string text;
    std::string kind;    // "" (teaching), "by-hand", "mistakes" or "compare"
    std::string preset;  // by-hand: the preset the question works; mistakes: the one its
                         // [step N] links open (empty: the lesson's first)
};

struct LessonEventNote {
    std::string event;  // an event kind the algorithm emits
    std::string text;
};

struct Lesson {
    std::string file;  // where it was read from
    std::string id, title, topic;
    double order = 0;  // course order; lessons are listed by it
    std::string exam_weight, exam_note;
    std::string algorithm;
    std::vector<LessonPreset> presets;
    std::vector<LessonSection> sections;
    std::vector<LessonEventNote> events;

    const LessonPreset* preset(const std::string& name) const;
    const LessonEventNote* note_for(const std::string& event) const;
};

// When a lesson's preset inputs are checked against the algorithm: as the file is read (the
// CLI, the tests, `cgsandbox lessons`), or when a preset is loaded (the viewer: checking all
// 475 at start-up took half a second of the browser build's first frame; a preset the
// algorithm refuses then opens in the input editor with its error, as any refused input does).
enum class PresetCheck { Now, WhenLoaded };

// Parses and checks one lesson: the algorithm exists, every event kind is one it declares,
// every preset input is accepted by it (unless `presets` defers that). Throws InputError naming
// the field ("presets[1].input.p0[0]: must be a number ..."); the caller adds the file.
Lesson parse_lesson(const json& j, const Registry& registry, PresetCheck presets = PresetCheck::Now);

// "[step N]" in a section's text: a link to step N (as `run --trace` numbers them, from 1) of
// the section's preset, which the viewer shows as a button. `at`/`size` locate it in the text.
struct StepLink {
    std::size_t at = 0, size = 0;
    std::size_t step = 0;
};
std::vector<StepLink> step_links(const std::string& text);
// The preset a section's links open: its own, or the lesson's first.
const LessonPreset* linked_preset(const Lesson& l, const LessonSection& s);

struct LessonLibrary {
    std::vector<Lesson> lessons;      // sorted by order, then id
    std::vector<std::string> errors;  // "lessons/x.json: field: reason", one per broken file
    const Lesson* find(const std::string& id) const;
    const Lesson* for_algorithm(const std::string& algorithm) const;
};

// Loads every *.json in `dir`; a broken file becomes an error line, the others still load.
LessonLibrary load_lessons(const std::string& dir, const Registry& registry,
                           PresetCheck presets = PresetCheck::Now);

// The lessons folder: $CGSANDBOX_LESSONS if set, else the source tree's lessons/.
std::string default_lessons_dir();

}  // namespace cg
