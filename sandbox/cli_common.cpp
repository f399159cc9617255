#include "cli_common.hpp"

#include <cstdio>

#include "checkpoint.hpp"
#include "io/exam.hpp"
#include "rays/texture_json.hpp"

namespace cg::cli {

[[noreturn]] void fail(const std::string& source, const InputError& e) {
    throw UserError{source, e.what()};
}

const Algorithm& find_algorithm(const Registry& registry, const std::string& id) {
    if (const Algorithm* a = registry.find(id)) return *a;
    throw UserError{"", "unknown algorithm \"" + id + "\"; `cgsandbox list` shows them"};
}

std::string source_name(const std::string& path) {
    return path == "-" ? "<stdin>" : path;
}

json load_input(const Algorithm& algorithm, const std::string& path) {
    if (path.empty()) return algorithm.example();
    try {
        json j = parse_json(read_text_file(path));
        if (path != "-") rebase_image_paths(j, folder_of(path));  // images beside the file
        return j;
    } catch (const InputError& e) {
        fail(source_name(path), e);
    }
}

std::unique_ptr<Run> create_run(const Algorithm& algorithm, const json& input,
                                const std::string& source) {
    try {
        return algorithm.create(input);
    } catch (const InputError& e) {
        fail(source, e);
    }
}

void emit(const std::string& text, const std::string& out_path) {
    if (out_path.empty()) {
        std::fwrite(text.data(), 1, text.size(), stdout);
        return;
    }
    std::FILE* f = std::fopen(out_path.c_str(), "wb");
    if (!f || std::fwrite(text.data(), 1, text.size(), f) != text.size() || std::fclose(f) != 0)
        throw UserError{out_path, "cannot write the file"};
}

LessonLibrary load_lesson_library(const Registry& registry) {
    return load_lessons(default_lessons_dir(), registry);
}

const LessonPreset& find_preset(const Lesson& lesson, const std::string& name) {
    if (const LessonPreset* preset = lesson.preset(name)) return *preset;
    std::string names;
    for (const auto& p : lesson.presets) names += (names.empty() ? "\"" : ", \"") + p.name + "\"";
    throw UserError{lesson.file, "no preset \"" + name + "\" (presets: " + names + ")"};
}

ChosenInput choose_input(const Registry& registry, const Algorithm& algorithm,
                         const std::string& input_path, const std::string& preset,
                         std::optional<std::uint64_t> seed) {
    const int given = !input_path.empty() + !preset.empty() + seed.has_value();
    if (given > 1) throw UserError{"", "give one of --input, --preset and --seed"};
    if (!preset.empty()) {
        const LessonLibrary lessons = load_lesson_library(registry);
        const Lesson* lesson = lessons.for_algorithm(algorithm.spec->id);
        if (!lesson) throw UserError{"", "no lesson for " + algorithm.spec->id + ", so no presets"};
        return {find_preset(*lesson, preset).input, lesson->file};
    }
    if (seed) {
        try {
            return {make_exam(algorithm, *seed).input, "exam problem " + std::to_string(*seed)};
        } catch (const InputError& e) {
            throw UserError{"", e.what()};
        }
    }
    return {load_input(algorithm, input_path),
            input_path.empty() ? "example input" : source_name(input_path)};
}

}  // namespace cg::cli
