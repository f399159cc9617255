// The viewer's frame time: one whole viewer frame (the UI laid out, every panel drawn, the
// draw lists rendered by OpenGL and finished) at 1280×800, offscreen on Mesa's llvmpipe — what
// a student without a GPU gets. One benchmark per lesson: its presets in turn, each at its
// first, middle and last step, with the lesson open beside the canvas. Reported per lesson:
// the median and the worst frame in milliseconds (counters median_ms, worst_ms); the goal is
// every lesson within 16 ms (60 frames a second).
//
// Also the ray tracer stepping pixel by pixel through a 640×480 image, half filled in.
#include <backends/imgui_impl_opengl3.h>
#include <benchmark/benchmark.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <memory>
#include <vector>

#include <SDL.h>
#include <sys/resource.h>

#include "io/lesson.hpp"
#include "io/registry.hpp"
#include "viewer/gl.hpp"
#include "viewer/grid_texture.hpp"
#include "viewer/host.hpp"
#include "viewer/palette.hpp"
#include "viewer/session.hpp"
#include "viewer/ui.hpp"

namespace {

using cg::viewer::Session;

constexpr int kWidth = 1280, kHeight = 800;

struct Env {
    cg::Registry registry = cg::builtin_registry();
    cg::LessonLibrary lessons = cg::load_lessons(cg::default_lessons_dir(), registry);
    cg::viewer::GuiHost host{"frames", kWidth, kHeight, cg::viewer::GuiHost::Mode::Offscreen};
    cg::viewer::OffscreenTarget target{host.gl(), kWidth, kHeight};
    cg::viewer::GridTextures textures{host.gl()};
};

Env& env() {
    static Env e;
    return e;
}

// "llvmpipe (LLVM 15.0.6, 256 bits)": which OpenGL drew the frames, for the report.
std::string renderer() {
    using GetString = const unsigned char* (*)(unsigned int);
    env();
    const auto get = reinterpret_cast<GetString>(SDL_GL_GetProcAddress("glGetString"));
    const unsigned char* r = get ? get(0x1F01 /* GL_RENDERER */) : nullptr;
    return r ? reinterpret_cast<const char*>(r) : "unknown";
}

double process_cpu_ms() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 +
           (u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e3;
}

// One frame as the viewer draws it, timed from ImGui's NewFrame to the GPU's finish.
double frame_ms(Session& s) {
    Env& e = env();
    const auto start = std::chrono::steady_clock::now();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(kWidth, kHeight);
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    cg::viewer::draw_ui(s, io.DisplaySize, true, true);
    ImGui::Render();
    e.target.bind();
    cg::viewer::clear_frame(e.host.gl(), kWidth, kHeight, s);  // as the viewer does
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    e.host.gl().Finish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// A session on `input` at step `step` (clamped to the end), lesson `l` open beside it.
std::unique_ptr<Session> session_at(const cg::Lesson* l, const cg::Algorithm& a,
                                    const cg::json& input, std::size_t step) {
    Env& e = env();
    auto s = std::make_unique<Session>(e.registry);
    s->fonts = e.host.fonts();
    s->textures = &e.textures;
    s->lessons = e.lessons;
    s->start(a, input, step);
    if (l) {
        for (const cg::Lesson& x : s->lessons.lessons)
            if (x.id == l->id) s->open_lesson(x);
        s->start(a, input, step);  // open_lesson loads its first preset: back to ours
    }
    s->tab = l ? cg::viewer::Tab::Lessons : cg::viewer::Tab::Algorithm;
    return s;
}

// Times frames of the sessions in turn; reports the median and the worst.
void time_frames(benchmark::State& state, std::vector<std::unique_ptr<Session>>& sessions) {
    for (auto& s : sessions)  // first frames build caches (the narration log, fitted views)
        for (int i = 0; i < 3; ++i) frame_ms(*s);
    std::vector<double> times;
    std::size_t k = 0;
    const double cpu_before = process_cpu_ms();
    double vertices = 0, draws = 0;
    double worst = -1, worst_session = 0;
    for (auto _ : state) {
        const std::size_t at = k++ % sessions.size();
        const double ms = frame_ms(*sessions[at]);
        state.SetIterationTime(ms / 1000);
        times.push_back(ms);
        if (ms > worst) worst = ms, worst_session = static_cast<double>(at);
        const ImDrawData* dd = ImGui::GetDrawData();
        vertices = std::max(vertices, double(dd->TotalVtxCount));
        int cmds = 0;
        for (int i = 0; i < dd->CmdListsCount; ++i) cmds += dd->CmdLists[i]->CmdBuffer.Size;
        draws = std::max(draws, double(cmds));
    }
    state.counters["max_draw_calls"] = draws;
    // The CPU time of all the process's threads (llvmpipe rasterises on its own), per frame:
    // what the frame costs whatever else the machine is doing.
    state.counters["cpu_ms"] = (process_cpu_ms() - cpu_before) / static_cast<double>(times.size());
    state.counters["max_vertices"] = vertices;
    std::sort(times.begin(), times.end());
    state.counters["median_ms"] = times[times.size() / 2];
    state.counters["worst_ms"] = times.back();
    state.counters["sessions"] = static_cast<double>(sessions.size());
    // Which session the worst frame was (a lesson's: preset worst_session / 3, at its first,
    // middle or last step as worst_session % 3), to look into.
    state.counters["worst_session"] = worst_session;
    state.SetLabel(renderer());
}

void BM_LessonFrame(benchmark::State& state, std::string lesson_id) {
    Env& e = env();
    const cg::Lesson* lesson = e.lessons.find(lesson_id);
    const cg::Algorithm& a = *e.registry.find(lesson->algorithm);
    std::vector<std::unique_ptr<Session>> sessions;
    for (const cg::LessonPreset& p : lesson->presets) {
        auto probe = session_at(lesson, a, p.input, 0);
        probe->probe_seconds = 2.0;
        const std::size_t n = probe->length().value_or(probe->index());
        for (const std::size_t step : {std::size_t{0}, n / 2, n})
            sessions.push_back(session_at(lesson, a, p.input, step));
    }
    time_frames(state, sessions);
}

// The ray tracer's `pixels` stepping on a 640×480 image, half of it traced: the image panel
// shows 153,600 coloured cells.
void BM_RayTracerPixels640(benchmark::State& state) {
    Env& e = env();
    const cg::Algorithm& a = *e.registry.find("ray-tracer");
    cg::json input = a.example();
    input["camera"]["size"] = {640, 480};
    input["stepping"] = {{"granularity", "pixels"}};
    std::vector<std::unique_ptr<Session>> sessions;
    sessions.push_back(session_at(nullptr, a, input, 640 * 240));
    time_frames(state, sessions);
}

// Every lesson, in course order, as its own benchmark.
const bool registered = [] {
    for (const cg::Lesson& l : env().lessons.lessons)
        benchmark::RegisterBenchmark(("BM_LessonFrame/" + l.id).c_str(), BM_LessonFrame, l.id)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond)
            ->MinTime(0.5);
    benchmark::RegisterBenchmark("BM_RayTracerPixels640", BM_RayTracerPixels640)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond)
        ->MinTime(0.5);
    return true;
}();

}  // namespace
