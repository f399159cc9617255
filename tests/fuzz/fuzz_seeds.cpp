// Writes the fuzz targets' seed corpora for every registered algorithm, so that a new
// algorithm is fuzzed from its own example without anyone adding files:
//   <dir>/fuzz_algorithm_input/  byte 0 = the algorithm's index, then its example, each lesson
//                                preset and a few exam problems
//   <dir>/fuzz_checkpoint/       a checkpoint on each of those inputs, at a few steps
//   <dir>/fuzz_timeline/         each algorithm with its example and two exam seeds, and a
//                                command string that walks forward, back, jumps and ends
//   <dir>/fuzz_study/            byte 0 = the algorithm's index, byte 1 = the mode (check,
//                                predict, bug), then its example's trace as JSON Lines
// The lessons' own files seed fuzz_lesson directly (lessons/).
#include <filesystem>
#include <fstream>
#include <iostream>

#include "checkpoint.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"

namespace fs = std::filesystem;

namespace {

void write(const fs::path& dir, const std::string& name, const std::string& bytes) {
    fs::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary) << bytes;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: fuzz_seeds OUT_DIR LESSONS_DIR\n";
        return 2;
    }
    const fs::path out = argv[1];
    const cg::Registry registry = cg::builtin_registry();
    const cg::LessonLibrary lessons = cg::load_lessons(argv[2], registry);
    const auto& all = registry.all();
    for (std::size_t k = 0; k < all.size(); ++k) {
        const cg::Algorithm& a = all[k];
        const std::string id = a.spec->id;
        std::vector<std::pair<std::string, cg::json>> inputs{{"example", a.example()}};
        if (const cg::Lesson* l = lessons.for_algorithm(id))
            for (std::size_t p = 0; p < l->presets.size(); ++p)
                inputs.push_back({"preset" + std::to_string(p), l->presets[p].input});
        if (cg::has_exam(a))
            for (std::uint64_t seed = 1; seed <= 3; ++seed)
                inputs.push_back({"exam" + std::to_string(seed), a.exam_input(seed)});
        for (const auto& [name, input] : inputs) {
            write(out / "fuzz_algorithm_input", id + "-" + name, std::string(1, char(k)) + input.dump());
            for (std::size_t step : {0, 3, 1000}) {
                cg::Checkpoint c;
                c.algorithm = id;
                c.input = input;
                c.step = step;
                if (step == 3) c.view = cg::View2{{1, 2}, 40};
                write(out / "fuzz_checkpoint", id + "-" + name + "-" + std::to_string(step),
                      cg::checkpoint_to_json(c).dump());
            }
        }
        std::string lines;
        {
            auto run = a.create(a.example());
            for (std::size_t i = 1; !run->done() && i <= 200; ++i) {
                cg::StepInfo info;
                run->step(&info);
                lines += cg::step_to_json(i, info).dump() + "\n";
            }
        }
        for (char mode : {0, 1, 2})
            write(out / "fuzz_study", id + "-" + std::to_string(int(mode)), std::string{char(k), mode} + lines);
        // forward ×3, back, jump 0x0105, range, to_end, back ×2, reset, forward
        const std::string walk = {0, 0, 0, 1, 2, 5, 1, 5, 7, 0, 3, 1, 1, 4, 0};
        for (unsigned char input : {0, 1, 2})
            write(out / "fuzz_timeline", id + "-" + std::to_string(input),
                  std::string{char(k), char(input)} + walk);
    }
    return 0;
}
