#include "io/lesson.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace cg {

const LessonPreset* Lesson::preset(const std::string& name) const {
    for (const auto& p : presets)
        if (p.name == name) return &p;
    return nullptr;
}

const LessonEventNote* Lesson::note_for(const std::string& event) const {
    for (const auto& e : events)
        if (e.event == event) return &e;
    return nullptr;
}

namespace {

std::string non_empty(const Reader& r, const char* key) {
    std::string s = r.string(key);
    if (s.find_first_not_of(" \t\n") == std::string::npos) throw InputError(r.field(key), "must not be empty");
    return s;
}

const json& non_empty_array(const Reader& r, const char* key) {
    const json& v = r.get(key);
    if (!v.is_array() || v.empty())
        throw InputError(r.field(key), "must be a non-empty list, got " + describe(v));
    return v;
}

}  // namespace

Lesson parse_lesson(const json& j, const Registry& registry, PresetCheck presets_check) {
    Reader r(j);
    r.only({"id", "title", "topic", "order", "exam", "algorithm", "presets", "sections", "events"});
    Lesson l;
    l.id = non_empty(r, "id");
    l.title = non_empty(r, "title");
    l.topic = non_empty(r, "topic");
    l.order = r.number("order");
    l.algorithm = r.string("algorithm");
    const Algorithm* algorithm = registry.find(l.algorithm);
    if (!algorithm) throw InputError("algorithm", "unknown algorithm \"" + l.algorithm + "\"");

    Reader exam = r.object("exam");
    exam.only({"weight", "note"});
    l.exam_weight = exam.string("weight");
    if (l.exam_weight != "high" && l.exam_weight != "medium" && l.exam_weight != "low" &&
        l.exam_weight != "none")
        throw InputError("exam.weight", "must be high, medium, low or none, got \"" + l.exam_weight + "\"");
    l.exam_note = exam.has("note") ? exam.string("note") : "";

    const json& presets = non_empty_array(r, "presets");
    for (std::size_t i = 0; i < presets.size(); ++i) {
        const std::string at = "presets[" + std::to_string(i) + "]";
        Reader p(presets[i], at);
        p.only({"name", "input"});
        LessonPreset preset{non_empty(p, "name"), p.get("input")};
        if (l.preset(preset.name)) throw InputError(p.field("name"), "repeats \"" + preset.name + "\"");
        if (presets_check == PresetCheck::Now) {
            try {
                algorithm->check(preset.input);
            } catch (const InputError& e) {
                throw InputError(p.field("input") + (e.field().empty() ? "" : "." + e.field()),
                                 e.reason());
            }
        }
        l.presets.push_back(std::move(preset));
    }

    const json& sections = non_empty_array(r, "sections");
    for (std::size_t i = 0; i < sections.size(); ++i) {
        Reader s(sections[i], "sections[" + std::to_string(i) + "]");
        s.only({"title", "text", "kind", "preset"});
        LessonSection section;
        section.title = non_empty(s, "title");
        section.text = non_empty(s, "text");
        if (s.has("kind")) {
            // What an exam-minded section is: the question worked by hand, the common mistakes,
            // or the advantages and limits the course asks to compare.
            section.kind = non_empty(s, "kind");
            if (section.kind != "by-hand" && section.kind != "mistakes" && section.kind != "compare")
                throw InputError(s.field("kind"), "must be \"by-hand\", \"mistakes\" or "
                                                  "\"compare\" (got \"" + section.kind + "\")");
        }
        // A question worked by hand names the preset it works, so that its numbers can be held
        // to that preset's run (tests/lessons/test_by_hand.cpp) and the viewer can load it; a
        // mistakes section may name the preset its [step N] links open (else the first).
        if (s.has("preset")) {
            if (section.kind != "by-hand" && section.kind != "mistakes")
                throw InputError(s.field("preset"),
                                 "only a \"by-hand\" or \"mistakes\" section names a preset");
            section.preset = non_empty(s, "preset");
            if (!l.preset(section.preset))
                throw InputError(s.field("preset"), "is not a preset of this lesson (got \"" +
                                                        section.preset + "\")");
        } else if (section.kind == "by-hand") {
            throw InputError(s.field("preset"), "a \"by-hand\" section names the preset it "
                                                "works (one of the lesson's presets)");
        }
        l.sections.push_back(std::move(section));
    }

    if (r.has("events")) {
        const json& events = r.get("events");
        if (!events.is_object()) throw InputError("events", "must be an object, got " + describe(events));
        for (auto it = events.begin(); it != events.end(); ++it) {
            const std::string field = "events." + it.key();
            bool known = false;
            std::string list;
            for (const EventKind& e : algorithm->spec->events) {
                known = known || e.id == it.key();
                list += (list.empty() ? "" : ", ") + e.id;
            }
            if (!known)
                throw InputError(field, "is not an event of " + l.algorithm + " (its events: " + list + ")");
            if (!it.value().is_string() || it.value().get<std::string>().empty())
                throw InputError(field, "must be a non-empty string");
            l.events.push_back({it.key(), it.value().get<std::string>()});
        }
    }
    return l;
}

LessonLibrary load_lessons(const std::string& dir, const Registry& registry, PresetCheck presets) {
    LessonLibrary lib;
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
    if (ec) {
        lib.errors.push_back(dir + ": cannot read the lessons folder (" + ec.message() + ")");
        return lib;
    }
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
        try {
            std::ifstream f(path, std::ios::binary);
            std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
            Lesson l = parse_lesson(parse_json(text), registry, presets);
            l.file = path.string();
            if (lib.find(l.id)) throw InputError("id", "repeats the id \"" + l.id + "\" of another lesson");
            lib.lessons.push_back(std::move(l));
        } catch (const InputError& e) {
            lib.errors.push_back(path.string() + ": " + e.what());
        }
    }
    std::stable_sort(lib.lessons.begin(), lib.lessons.end(), [](const Lesson& a, const Lesson& b) {
        return a.order != b.order ? a.order < b.order : a.id < b.id;
    });
    return lib;
}

const Lesson* LessonLibrary::find(const std::string& id) const {
    for (const auto& l : lessons)
        if (l.id == id) return &l;
    return nullptr;
}

const Lesson* LessonLibrary::for_algorithm(const std::string& algorithm) const {
    for (const auto& l : lessons)
        if (l.algorithm == algorithm) return &l;
    return nullptr;
}

std::string default_lessons_dir() {
    if (const char* env = std::getenv("CGSANDBOX_LESSONS"); env && *env) return env;
#ifdef CG_LESSONS_DIR
    return CG_LESSONS_DIR;
#else
    return "lessons";
#endif
}

std::vector<StepLink> step_links(const std::string& text) {
    std::vector<StepLink> links;
    static const std::string kOpen = "[step ";
    for (std::size_t at = text.find(kOpen); at != std::string::npos; at = text.find(kOpen, at + 1)) {
        std::size_t i = at + kOpen.size();
        std::size_t step = 0;
        const std::size_t digits = i;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9' && i - digits < 9)
            step = step * 10 + static_cast<std::size_t>(text[i++] - '0');
        if (i == digits || i >= text.size() || text[i] != ']') continue;
        links.push_back({at, i + 1 - at, step});
    }
    return links;
}

const LessonPreset* linked_preset(const Lesson& l, const LessonSection& s) {
    if (!s.preset.empty()) return l.preset(s.preset);
    return l.presets.empty() ? nullptr : &l.presets.front();
}

}  // namespace cg
