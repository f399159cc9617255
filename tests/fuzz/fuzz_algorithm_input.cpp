// Every algorithm's JSON input, through the path the CLI and the viewer take: parse, create
// (validation), then run to the end narrating and drawing every step, and the result.
// Byte 0 picks the registered algorithm; the rest is the JSON text. Only InputError may
// escape validation: any other exception, a crash, a sanitizer report or a non-finite number
// where the viewer would draw it is a bug.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/scene.hpp"
#include "fuzz_support.hpp"

namespace {

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void check_scene(const cg::Scene& s) {
    for (const auto& p : s.points) if (!finite(p.p)) cg::fuzz::fail("non-finite point");
    for (const auto& g : s.segments) if (!finite(g.a) || !finite(g.b)) cg::fuzz::fail("non-finite segment");
    for (const auto& p : s.polygons)
        for (auto q : p.points) if (!finite(q)) cg::fuzz::fail("non-finite polygon");
}

// Per algorithm: inputs tried, inputs accepted (run to the end or the cap), steps taken. Printed
// at exit, for the README's reliability table.
struct Counts {
    unsigned long long tried = 0, accepted = 0, steps = 0;
};
std::vector<Counts>& counts() {
    static std::vector<Counts> c(cg::fuzz::registry().all().size());
    return c;
}

void print_counts() {
    const auto& all = cg::fuzz::registry().all();
    for (std::size_t k = 0; k < all.size(); ++k)
        std::fprintf(stderr, "algorithm %s: %llu inputs, %llu accepted, %llu steps\n",
                     all[k].spec->id.c_str(), counts()[k].tried, counts()[k].accepted, counts()[k].steps);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    counts();
    std::atexit(print_counts);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const cg::Algorithm& a = cg::fuzz::pick(data[0]);
    Counts& count = counts()[data[0] % counts().size()];
    ++count.tried;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    std::unique_ptr<cg::Run> run;
    try {
        const cg::json input = cg::parse_json(text);
        run = a.create(input);
        if (cg::fuzz::too_costly(a, input)) return 0;  // valid, but minutes to run
    } catch (const cg::InputError&) {
        return 0;  // refused, with a message naming the field: fine
    }
    ++count.accepted;
    for (std::size_t i = 1; !run->done() && i <= cg::fuzz::kStepCap; ++i) {
        cg::StepInfo info;
        run->step(&info);
        ++count.steps;
        (void)cg::step_to_json(i, info).dump();
        // The picture of the first steps and then of every 1024th: a big grid's picture costs
        // as much as its pixels, and a viewer draws one step per frame, not thousands.
        if (i <= 64 || i % 1024 == 0) {
            cg::Scene scene;
            run->draw(scene);
            check_scene(scene);
        }
    }
    cg::Scene scene;
    run->draw(scene);
    check_scene(scene);
    if (run->done()) (void)a.result(*run).dump();
    return 0;
}
