#include "viewer/layout_pass.hpp"

#include <imgui.h>

#include <cfloat>
#include <stdexcept>

#include "viewer/session.hpp"
#include "viewer/ui.hpp"

namespace cg::viewer {

void open_checkpoint(Session& s, const Checkpoint& checkpoint, const LessonLibrary& lessons) {
    const Algorithm* algorithm = s.registry.find(checkpoint.algorithm);
    if (!algorithm)
        throw InputError("algorithm", "unknown algorithm \"" + checkpoint.algorithm + "\"");
    // The run first: bad input is reported as such. Then as the viewer opens it: the lesson,
    // the exam, the view. A lesson that cannot be found is an error here, where the viewer
    // would only say so.
    if (checkpoint.exam_seed)
        s.start_exam(*algorithm, *checkpoint.exam_seed);
    else
        s.start(*algorithm, checkpoint.input, checkpoint.step);
    s.lessons = lessons;
    s.load(checkpoint);
    if (s.status_is_error) throw std::runtime_error(s.status);
}

namespace {

// Makes a context current for a scope and puts the one before back.
struct CurrentContext {
    ImGuiContext* before;
    explicit CurrentContext(ImGuiContext* c) : before(ImGui::GetCurrentContext()) {
        ImGui::SetCurrentContext(c);
    }
    ~CurrentContext() { ImGui::SetCurrentContext(before); }
};

}  // namespace

LayoutPass::LayoutPass() {
    ImGuiContext* before = ImGui::GetCurrentContext();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    // As the OpenGL 3.3 renderer the window uses: a draw list may pass 65,536 vertices.
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    fonts_ = setup_fonts_and_style();  // builds the atlas: all a frame needs of the fonts
    ImGui::SetCurrentContext(before);
}

LayoutPass::~LayoutPass() {
    ImGuiContext* before = ImGui::GetCurrentContext();
    ImGui::DestroyContext(context_);
    if (before != context_) ImGui::SetCurrentContext(before);
}

LayoutRecord LayoutPass::record(Session& s, int width, int height, bool full_ui) {
    const CurrentContext current(context_);
    s.fonts = fonts_;
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    LayoutRecord record;
    // As `render` does: a few frames, so that auto-sized columns settle before the last.
    for (int frame = 0; frame < 3; ++frame) {
        if (frame == 2) s.layout_record = &record;
        ImGui::NewFrame();
        draw_ui(s, io.DisplaySize, full_ui, false);
        ImGui::Render();
    }
    s.layout_record = nullptr;
    return record;
}

}  // namespace cg::viewer
