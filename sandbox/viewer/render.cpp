// `cgsandbox render`: the viewer's picture of one checkpoint, drawn offscreen into a PNG.
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cfloat>

#include "viewer/app.hpp"
#include "viewer/grid_texture.hpp"
#include "viewer/host.hpp"
#include "viewer/palette.hpp"
#include "viewer/session.hpp"
#include "viewer/ui.hpp"

namespace cg::viewer {

void render_png(const Registry& registry, const Checkpoint& checkpoint, int width, int height,
                const std::string& out_path, bool full_ui) {
    const Algorithm* algorithm = registry.find(checkpoint.algorithm);
    if (!algorithm)
        throw InputError("algorithm", "unknown algorithm \"" + checkpoint.algorithm + "\"");
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw std::runtime_error("image size " + std::to_string(width) + "x" +
                                 std::to_string(height) + " is out of range");

    // The run first: bad input is reported as such, before any window is opened.
    Session s(registry);
    s.probe_seconds = 2.0;  // a PNG should say "k / n" if it reasonably can
    if (checkpoint.exam_seed)
        s.start_exam(*algorithm, *checkpoint.exam_seed);
    else
        s.start(*algorithm, checkpoint.input, checkpoint.step);
    // Then as the viewer opens it: the lesson, the exam, the view. A lesson that cannot be
    // found is an error here, where the viewer would only say so.
    s.lessons = load_lessons(default_lessons_dir(), registry);
    s.load(checkpoint);
    if (s.status_is_error) throw std::runtime_error(s.status);

    GuiHost host("CG Sandbox", width, height, GuiHost::Mode::Offscreen);
    s.fonts = host.fonts();
    // Drawing into our own framebuffer makes the picture exactly width x height whatever the
    // screen is; ImGui is told the size directly and never sees a mouse.
    OffscreenTarget target(host.gl(), width, height);
    GridTextures textures(host.gl());
    s.textures = &textures;
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);

    // A few frames, so that auto-sized columns and scrolled lists settle before the last.
    for (int frame = 0; frame < 3; ++frame) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        draw_ui(s, io.DisplaySize, full_ui, false);
        ImGui::Render();
        target.bind();
        clear_frame(host.gl(), width, height, s);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    write_png(out_path, width, height, read_pixels(host.gl(), width, height));
}

}  // namespace cg::viewer
