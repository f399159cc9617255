#include "cli.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "checkpoint.hpp"
#include "cli_common.hpp"
#include "cli_study.hpp"
#include "accel/complexity.hpp"
#include "hsr/complexity.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "io/registry.hpp"
#include "io/worked.hpp"
#include "rays/rt_scene_json.hpp"
#include "rays/texture_json.hpp"
#include "viewer/app.hpp"
#include "viewer/gl.hpp"

namespace cg {

namespace {

using namespace cli;

int cmd_list(const Registry& registry) {
    for (const Algorithm& a : registry.all())
        std::cout << a.spec->id << "\t" << a.spec->title << "\n";
    return 0;
}

int cmd_example(const Registry& registry, const std::string& id) {
    std::cout << pretty(find_algorithm(registry, id).example()) << "\n";
    return 0;
}

int cmd_run(const Registry& registry, const std::string& id, const std::string& input_path,
            bool trace) {
    const Algorithm& algorithm = find_algorithm(registry, id);
    const std::string source = input_path.empty() ? "example input" : source_name(input_path);
    std::unique_ptr<Run> run = create_run(algorithm, load_input(algorithm, input_path), source);
    std::string out;
    std::size_t index = 0;
    while (!run->done()) {
        if (++index > kMaxSteps) throw UserError{source, "run exceeded the step limit"};
        if (trace) {
            StepInfo info;
            run->step(&info);
            out += step_to_json(index, info).dump() + "\n";
        } else {
            run->step(nullptr);
        }
    }
    out += algorithm.result(*run).dump() + "\n";
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
}

struct WorkedOptions {
    std::string id, input_path, preset, format = "md", out_path;
};

int cmd_worked(const Registry& registry, const WorkedOptions& o) {
    const Algorithm& algorithm = find_algorithm(registry, o.id);
    json input;
    std::string source, subtitle;
    if (!o.preset.empty()) {
        if (!o.input_path.empty()) throw UserError{"", "give --input or --preset, not both"};
        const LessonLibrary lessons = load_lesson_library(registry);
        const Lesson* lesson = lessons.for_algorithm(o.id);
        if (!lesson) throw UserError{"", "no lesson for " + o.id + ", so no presets"};
        const LessonPreset& preset = find_preset(*lesson, o.preset);
        input = preset.input;
        source = lesson->file;
        subtitle = preset.name;
    } else {
        source = o.input_path.empty() ? "example input" : source_name(o.input_path);
        input = load_input(algorithm, o.input_path);
    }
    WorkedExample w;
    try {
        w = work(algorithm, exam_for_input(algorithm, input), subtitle);
    } catch (const InputError& e) {
        fail(source, e);
    }
    emit(o.format == "json" ? pretty(worked_json(w)) + "\n" : worked_markdown(w), o.out_path);
    return 0;
}

struct ExamOptions {
    std::string id, format = "md", out_path;
    std::uint64_t seed = 1;
    bool answers = false;
};

int cmd_exam(const Registry& registry, const ExamOptions& o) {
    const Algorithm& algorithm = find_algorithm(registry, o.id);
    ExamProblem problem;
    try {
        problem = make_exam(algorithm, o.seed);
    } catch (const InputError& e) {
        throw UserError{"", e.what()};
    }
    if (o.format == "json") {
        emit(pretty(exam_to_json(problem)) + "\n", o.out_path);
        return 0;
    }
    std::string md = "# " + algorithm.spec->title + " — exam problem (seed " + std::to_string(o.seed) +
                     ")\n\n" + problem.question + "\n";
    if (o.answers) {
        WorkedExample w = work(algorithm, problem, "seed " + std::to_string(o.seed));
        std::string worked = worked_markdown(w);
        // The worked example repeats the question; keep its solution and answer parts.
        auto at = worked.find("**Input.**");
        md += "\n" + (at == std::string::npos ? worked : worked.substr(at));
    }
    emit(md, o.out_path);
    return 0;
}

int cmd_lessons(const Registry& registry, bool check) {
    const LessonLibrary lessons = load_lesson_library(registry);
    for (const Lesson& l : lessons.lessons)
        std::cout << l.id << "\t" << l.topic << "\t" << l.title << "\t(exam: " << l.exam_weight << ")\n";
    for (const std::string& e : lessons.errors) std::cerr << "cgsandbox: " << e << "\n";
    return check && !lessons.errors.empty() ? kExitBadInput : 0;
}

struct RenderOptions {
    std::string id, input_path, checkpoint_path, out_path, size = "800x600";
    std::string lesson, preset, layout_path;
    std::optional<std::uint64_t> exam_seed;
    long long step = -1;  // -1: the end of the run (in exam practice: step 0)
    bool full_ui = false;
};

// --lesson ID [--preset NAME]: the lesson's algorithm on the preset (default: its first), with
// the lesson open; --preset alone takes the algorithm's lesson, as `worked` does.
void apply_lesson(const Registry& registry, const RenderOptions& o, Checkpoint& c,
                  std::string& source) {
    const LessonLibrary lessons = load_lesson_library(registry);
    const Lesson* lesson = nullptr;
    if (!o.lesson.empty()) {
        lesson = lessons.find(o.lesson);
        if (!lesson) {
            std::string hint = lessons.errors.empty()
                                   ? "`cgsandbox lessons` lists them"
                                   : "`cgsandbox lessons --check` lists them and the broken files";
            throw UserError{"", "no lesson \"" + o.lesson + "\"; " + hint};
        }
        if (!o.id.empty() && o.id != lesson->algorithm)
            throw UserError{"", "lesson \"" + o.lesson + "\" is about " + lesson->algorithm +
                                    ", not " + o.id};
    } else {
        lesson = lessons.for_algorithm(o.id);
        if (!lesson) throw UserError{"", "no lesson for " + o.id + ", so no presets"};
    }
    c.algorithm = lesson->algorithm;
    c.lesson = lesson->id;
    if (!o.input_path.empty()) {
        if (!o.preset.empty()) throw UserError{"", "give --input or --preset, not both"};
        return;  // the lesson beside the student's own input
    }
    const LessonPreset& preset =
        o.preset.empty() ? lesson->presets.front() : find_preset(*lesson, o.preset);
    c.input = preset.input;
    c.preset = preset.name;
    source = lesson->file;
}

int cmd_render(const Registry& registry, const RenderOptions& o) {
    if (o.out_path.empty() && o.layout_path.empty())
        throw UserError{"", "render needs --out FILE.png, --layout FILE.json, or both"};
    Checkpoint c;
    std::string source;
    const bool studying = !o.lesson.empty() || !o.preset.empty() || o.exam_seed;
    if (!o.checkpoint_path.empty() && studying)
        throw UserError{"", "--checkpoint carries its own lesson and exam; give it alone"};
    if (!o.checkpoint_path.empty()) {
        source = source_name(o.checkpoint_path);
        try {
            json j = parse_json(read_text_file(o.checkpoint_path));
            rebase_image_paths(j, folder_of(o.checkpoint_path));  // images beside the file
            c = checkpoint_from_json(j, registry);
        } catch (const InputError& e) {
            fail(source, e);
        }
        if (o.step >= 0) c.step = static_cast<std::size_t>(o.step);
    } else {
        if (o.id.empty() && o.lesson.empty())
            throw UserError{"", "render needs an algorithm ID, --lesson ID or --checkpoint FILE"};
        c.algorithm = o.id;
        if (!o.lesson.empty() || !o.preset.empty()) apply_lesson(registry, o, c, source);
        const Algorithm& algorithm = find_algorithm(registry, c.algorithm);
        if (source.empty()) {
            source = o.input_path.empty() ? "example input" : source_name(o.input_path);
            c.input = load_input(algorithm, o.input_path);
        }
        c.step = o.step < 0 ? kMaxSteps : static_cast<std::size_t>(o.step);
        if (o.exam_seed) {  // the problem's own input, its solution hidden unless --step
            if (!o.input_path.empty() || !c.preset.empty())
                throw UserError{"", "--exam makes its own input; give no --input or --preset"};
            try {
                c.input = make_exam(algorithm, *o.exam_seed).input;
            } catch (const InputError& e) {
                throw UserError{"", e.what()};
            }
            c.exam_seed = o.exam_seed;
            c.step = o.step < 0 ? 0 : static_cast<std::size_t>(o.step);
            source = "exam problem " + std::to_string(*o.exam_seed);
        }
    }
    int width = 0, height = 0;
    char x = 0, extra = 0;
    if (std::sscanf(o.size.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || x != 'x' ||
        width < 16 || height < 16 || width > 8192 || height > 8192)
        throw UserError{"", "--size must be WxH with 16 <= W, H <= 8192, got \"" + o.size + "\""};
    // Check the input before opening any window, so bad input is reported as such.
    create_run(find_algorithm(registry, c.algorithm), c.input, source);
    try {
        viewer::render_png(registry, c, width, height, o.out_path, o.full_ui, o.layout_path);
    } catch (const InputError& e) {
        fail(source, e);
    } catch (const std::exception& e) {
        std::cerr << "cgsandbox: render: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

// contact-sheet: a lesson's presets at their first, middle and last step, for looking over.
int cmd_contact_sheet(const Registry& registry, const std::vector<std::string>& ids,
                      const std::string& out_dir, const std::string& size) {
    int width = 0, height = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || x != 'x' ||
        width < 320 || height < 240 || width > 8192 || height > 8192)
        throw UserError{"", "--size must be WxH with 320 <= W <= 8192, 240 <= H <= 8192, got \"" +
                                size + "\""};
    const LessonLibrary lessons = load_lesson_library(registry);
    std::vector<const Lesson*> chosen;
    for (const std::string& id : ids) {
        const Lesson* l = lessons.find(id);
        if (!l) throw UserError{"", "no lesson \"" + id + "\"; `cgsandbox lessons` lists them"};
        chosen.push_back(l);
    }
    if (ids.empty())
        for (const Lesson& l : lessons.lessons) chosen.push_back(&l);
    std::error_code error;
    std::filesystem::create_directories(out_dir, error);
    for (const Lesson* l : chosen) {
        const std::string path = out_dir + "/" + l->id + ".png";
        try {
            viewer::contact_sheet(registry, lessons, *l, width, height, path);
        } catch (const std::exception& e) {
            std::cerr << "cgsandbox: contact-sheet: " << l->id << ": " << e.what() << "\n";
            return 1;
        }
        std::cout << path << "\n";
    }
    return 0;
}

struct SceneRenderOptions {
    std::string scene_path, out_path, size;
    int threads = 0;
};

// render-scene: the whole image with the plain tracer on every core, no display needed.
int cmd_render_scene(const SceneRenderOptions& o) {
    const std::string source = source_name(o.scene_path);
    json j;
    rt::Scene scene;
    try {
        j = parse_json(read_text_file(o.scene_path));
        if (o.scene_path != "-") rebase_image_paths(j, folder_of(o.scene_path));
        if (!o.size.empty()) {
            int width = 0, height = 0;
            char x = 0, extra = 0;
            if (std::sscanf(o.size.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 ||
                x != 'x' || width < 1 || height < 1 ||
                static_cast<long long>(width) * height > rt::kMaxPixels)
                throw UserError{"", "--size must be WxH with W, H ≥ 1 and W·H ≤ 4096·4096, got \"" +
                                        o.size + "\""};
            if (j.is_object() && j.contains("camera") && j["camera"].is_object())
                j["camera"]["size"] = {width, height};
        }
        scene = rt::scene_from_json(j, {"stepping"});
        rt::validate(scene);
    } catch (const InputError& e) {
        fail(source, e);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const rt::Image img = rt::render(scene, o.threads);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // PNG rows go top first; the image's row 0 is the bottom.
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(img.width) * img.height * 4);
    for (int jj = 0; jj < img.height; ++jj)
        for (int i = 0; i < img.width; ++i) {
            const std::uint32_t v = img.rgba[static_cast<std::size_t>(jj) * img.width + i];
            std::uint8_t* out =
                &bytes[(static_cast<std::size_t>(img.height - 1 - jj) * img.width + i) * 4];
            out[0] = v >> 24, out[1] = (v >> 16) & 0xff, out[2] = (v >> 8) & 0xff, out[3] = 0xff;
        }
    try {
        viewer::write_png(o.out_path, img.width, img.height, bytes);
    } catch (const std::exception&) {
        throw UserError{o.out_path, "cannot write the PNG file"};
    }
    const rt::RayCounts& r = img.rays;
    std::printf("%s: %d×%d, %llu rays (%llu primary, %llu shadow, %llu reflected, %llu refracted) "
                "in %.3f s (%.2f M rays/s), checksum %s\n",
                o.out_path.c_str(), img.width, img.height,
                static_cast<unsigned long long>(r.total()), static_cast<unsigned long long>(r.primary),
                static_cast<unsigned long long>(r.shadow), static_cast<unsigned long long>(r.reflected),
                static_cast<unsigned long long>(r.refracted), seconds,
                seconds > 0 ? r.total() / seconds / 1e6 : 0.0,
                rt::image_checksum(img.rgba, img.width, img.height).c_str());
    return 0;
}

}  // namespace

int cli_main(int argc, char** argv) {
    const Registry registry = builtin_registry();
    if (argc <= 1) return viewer::run_viewer(registry, std::nullopt);

    CLI::App app{
        "CG Sandbox: step through the algorithms of a computer-graphics course.\n"
        "Without a command, opens the viewer."};
    app.require_subcommand(0, 1);

    auto* list = app.add_subcommand("list", "List the algorithms: id and title, one per line");

    std::string id;
    auto* example = app.add_subcommand("example", "Print a valid sample input as JSON");
    example->add_option("ID", id, "Algorithm id (see `list`)")->required();

    std::string input_path;
    bool trace = false;
    auto* run = app.add_subcommand(
        "run", "Run to the end and print the result as one JSON object\n"
               "(with --trace, first one JSON line per step)");
    run->add_option("ID", id, "Algorithm id (see `list`)")->required();
    run->add_option("--input,-i", input_path, "Input JSON file, or - for stdin (default: the example)");
    run->add_flag("--trace,-t", trace, "Print each step: index, event, line, narration, variables");

    RenderOptions ro;
    auto* render = app.add_subcommand("render", "Save the viewer's picture of one step as PNG");
    render->add_option("ID", ro.id, "Algorithm id (not needed with --checkpoint)");
    render->add_option("--input,-i", ro.input_path, "Input JSON file, or - for stdin (default: the example)");
    render->add_option("--checkpoint,-c", ro.checkpoint_path, "A checkpoint saved by the viewer");
    render->add_option("--step,-s", ro.step, "Step to show (default: the end, or the checkpoint's)")
        ->check(CLI::NonNegativeNumber);
    render->add_option("--out,-o", ro.out_path, "Output PNG file (needed unless --layout is given)");
    render->add_option("--layout", ro.layout_path,
                       "Also write what the canvas placed where, as JSON (alone: no GPU needed)");
    render->add_option("--size", ro.size, "Image size WxH (default 800x600)");
    render->add_flag("--full", ro.full_ui, "The whole viewer window, not only the canvas");
    render->add_option("--lesson,-l", ro.lesson,
                       "Open this lesson (see `lessons`) on its first preset; with --full its text "
                       "is shown");
    render->add_option("--preset,-p", ro.preset, "A preset of the lesson (or the algorithm's lesson)");
    render->add_option("--exam,-e", ro.exam_seed,
                       "Exam practice on the problem with this seed (solution hidden unless --step)");

    WorkedOptions wo;
    auto* worked = app.add_subcommand(
        "worked", "Write the full worked solution: question, pseudocode, every step, answer");
    worked->add_option("ID", wo.id, "Algorithm id (see `list`)")->required();
    worked->add_option("--input,-i", wo.input_path, "Input JSON file, or - for stdin (default: the example)");
    worked->add_option("--preset,-p", wo.preset, "A preset of the algorithm's lesson, by name");
    worked->add_option("--format,-f", wo.format, "md (Markdown with LaTeX math) or json")
        ->check(CLI::IsMember({"md", "json"}));
    worked->add_option("--out,-o", wo.out_path, "Write to this file instead of stdout");

    ExamOptions eo;
    auto* exam = app.add_subcommand("exam", "An exam-style problem from a seed");
    exam->add_option("ID", eo.id, "Algorithm id (see `list`)")->required();
    exam->add_option("--seed,-s", eo.seed, "The problem's seed: same seed, same problem")->required();
    exam->add_flag("--answers,-a", eo.answers, "Add the worked solution and the answers");
    exam->add_option("--format,-f", eo.format,
                     "md (the question, Markdown) or json ({question, input, answers, expected})")
        ->check(CLI::IsMember({"md", "json"}));
    exam->add_option("--out,-o", eo.out_path, "Write to this file instead of stdout");

    bool check_lessons = false;
    auto* lessons = app.add_subcommand("lessons", "List the lessons in course order; report broken files");
    lessons->add_flag("--check", check_lessons, "Exit 2 if any lesson file is broken");

    std::string topic;
    std::vector<long long> sides{8, 16, 32, 64};
    std::vector<int> counts{1, 4, 16};
    int trials = 5;
    std::vector<int> primitive_counts{10, 100, 1000, 10000, 100000, 1000000};
    int rays = 1000;
    auto* complexity = app.add_subcommand("complexity", "Count the basic operations on growing random scenes");
    complexity
        ->add_option("TOPIC", topic,
                     "hsr (hidden-surface removal) or accel (brute force, BVH, grid)")
        ->required()
        ->check(CLI::IsMember({"hsr", "accel"}));
    complexity->add_option("--sizes", sides, "Screen sides in pixels (default 8 16 32 64)")->check(CLI::Range(1, 1024));
    complexity->add_option("--polygons", counts, "Polygon counts (default 1 4 16)")->check(CLI::Range(0, 1000));
    complexity->add_option("--trials", trials, "Random scenes per row (default 5)")->check(CLI::Range(1, 1000));
    complexity
        ->add_option("--counts", primitive_counts,
                     "accel: primitive counts (default 10 100 … 1000000)")
        ->check(CLI::Range(1, 2000000));
    complexity->add_option("--rays", rays, "accel: random rays per scene (default 1000)")
        ->check(CLI::Range(1, 1000000));

    SceneRenderOptions so;
    std::vector<std::string> sheet_ids;
    std::string sheet_dir = "contact-sheets", sheet_size = "1280x720";
    auto* sheet = app.add_subcommand(
        "contact-sheet", "Each lesson's presets at their first, middle and last step, one PNG a lesson");
    sheet->add_option("LESSON", sheet_ids, "Lesson ids (default: every lesson)");
    sheet->add_option("--out-dir,-o", sheet_dir, "Folder for <lesson>.png (default contact-sheets)");
    sheet->add_option("--size", sheet_size, "The window's size WxH (default 1280x720)");

    auto* render_scene = app.add_subcommand(
        "render-scene", "Ray trace a scene file to a PNG, on every core (no display needed)");
    render_scene->add_option("SCENE", so.scene_path, "Scene JSON file (see the README), or - for stdin")
        ->required();
    render_scene->add_option("--out,-o", so.out_path, "Output PNG file")->required();
    render_scene->add_option("--size", so.size, "Image size WxH (default: the scene's camera.size)");
    render_scene->add_option("--threads", so.threads, "Threads (default: one per core)")
        ->check(CLI::Range(0, 256));

    const cli::StudyCommands study(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "cgsandbox: " << e.what() << " (see --help)\n";
        return cli::kExitBadInput;
    }

    try {
        if (*list) return cmd_list(registry);
        if (*example) return cmd_example(registry, id);
        if (*run) return cmd_run(registry, id, input_path, trace);
        if (*render) return cmd_render(registry, ro);
        if (*worked) return cmd_worked(registry, wo);
        if (*exam) return cmd_exam(registry, eo);
        if (*lessons) return cmd_lessons(registry, check_lessons);
        if (*render_scene) return cmd_render_scene(so);
        if (*sheet) return cmd_contact_sheet(registry, sheet_ids, sheet_dir, sheet_size);
        if (auto code = study.run(registry)) return *code;
        if (*complexity) {
            if (topic == "accel")  // brute force run and compared on every ray up to n = 10⁴
                std::cout << accel::complexity_table(
                    accel::complexity(primitive_counts, rays, 1, 10000));
            else
                std::cout << hsr::complexity_table(hsr::complexity(sides, counts, trials, 1));
            return 0;
        }
        return viewer::run_viewer(registry, std::nullopt);
    } catch (const cli::UserError& e) {
        std::cerr << "cgsandbox: " << (e.source.empty() ? "" : e.source + ": ") << e.message << "\n";
        return cli::kExitBadInput;
    }
}

}  // namespace cg
