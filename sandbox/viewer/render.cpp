// `cgsandbox render`: the viewer's picture of one checkpoint, drawn offscreen into a PNG, and
// what its canvas placed where (--layout).
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <fstream>

#include "viewer/app.hpp"
#include "viewer/grid_texture.hpp"
#include "viewer/host.hpp"
#include "viewer/layout_pass.hpp"
#include "viewer/palette.hpp"
#include "viewer/session.hpp"
#include "viewer/ui.hpp"

namespace cg::viewer {

namespace {

void write_layout(const std::string& path, const LayoutRecord& record) {
    std::ofstream out(path, std::ios::binary);
    out << layout_json(record).dump(2) << "\n";
    if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace

void render_png(const Registry& registry, const Checkpoint& checkpoint, int width, int height,
                const std::string& out_path, bool full_ui, const std::string& layout_path) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw std::runtime_error("image size " + std::to_string(width) + "x" +
                                 std::to_string(height) + " is out of range");
    Session s(registry);
    s.probe_seconds = 2.0;  // a PNG should say "k / n" if it reasonably can
    open_checkpoint(s, checkpoint, load_lessons(default_lessons_dir(), registry));

    if (out_path.empty()) {  // the layout alone: no GPU, no window
        LayoutPass pass;
        write_layout(layout_path, pass.record(s, width, height, full_ui));
        return;
    }
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
    LayoutRecord record;
    for (int frame = 0; frame < 3; ++frame) {
        if (frame == 2 && !layout_path.empty()) s.layout_record = &record;
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        draw_ui(s, io.DisplaySize, full_ui, false);
        ImGui::Render();
        target.bind();
        clear_frame(host.gl(), width, height, s);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    write_png(out_path, width, height, read_pixels(host.gl(), width, height));
    if (!layout_path.empty()) write_layout(layout_path, record);
}

}  // namespace cg::viewer

namespace cg::viewer {

void contact_sheet(const Registry& registry, const LessonLibrary& lessons, const Lesson& lesson,
                   int width, int height, const std::string& out_path) {
    const Algorithm* algorithm = registry.find(lesson.algorithm);
    if (!algorithm) throw std::runtime_error("lesson " + lesson.id + ": unknown algorithm");
    GuiHost host("CG Sandbox", width, height, GuiHost::Mode::Offscreen);
    OffscreenTarget target(host.gl(), width, height);
    GridTextures textures(host.gl());
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);

    // Each preset's first, middle and last step: the canvas as the window shows it.
    struct Tile {
        std::vector<std::uint8_t> rgba;
        int w = 0, h = 0;
    };
    std::vector<std::vector<Tile>> rows;
    int tile_w = 0, tile_h = 0;
    for (const LessonPreset& p : lesson.presets) {
        std::size_t n = 0;
        for (auto run = algorithm->create(p.input); !run->done(); ++n) run->step(nullptr);
        rows.emplace_back();
        for (const std::size_t step : {std::size_t{0}, n / 2, n}) {
            Session s(registry);
            s.probe_seconds = 2.0;
            s.textures = &textures;
            Checkpoint c;
            c.algorithm = lesson.algorithm;
            c.input = p.input;
            c.step = step;
            c.lesson = lesson.id;
            c.preset = p.name;
            open_checkpoint(s, c, lessons);
            s.fonts = host.fonts();
            for (int frame = 0; frame < 3; ++frame) {
                ImGui_ImplOpenGL3_NewFrame();
                ImGui::NewFrame();
                draw_ui(s, io.DisplaySize, true, false);
                ImGui::Render();
                target.bind();
                clear_frame(host.gl(), width, height, s);
                ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            }
            const std::vector<std::uint8_t> all = read_pixels(host.gl(), width, height);
            const Box& c_box = s.canvas_rect;
            const int x0 = std::clamp(int(c_box.min.x), 0, width),
                      y0 = std::clamp(int(c_box.min.y), 0, height);
            const int x1 = std::clamp(int(c_box.max.x), x0, width),
                      y1 = std::clamp(int(c_box.max.y), y0, height);
            Tile t{{}, x1 - x0, y1 - y0};
            for (int y = y0; y < y1; ++y)
                t.rgba.insert(t.rgba.end(), all.begin() + 4 * (std::size_t(y) * width + x0),
                              all.begin() + 4 * (std::size_t(y) * width + x1));
            tile_w = std::max(tile_w, t.w), tile_h = std::max(tile_h, t.h);
            rows.back().push_back(std::move(t));
        }
    }
    // Three tiles a row, one row a preset, 8 px of grey between them.
    constexpr int kGap = 8;
    const int sheet_w = 3 * tile_w + 4 * kGap;
    const int sheet_h = static_cast<int>(rows.size()) * (tile_h + kGap) + kGap;
    std::vector<std::uint8_t> sheet(std::size_t(sheet_w) * sheet_h * 4, 0x90);
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t k = 0; k < rows[r].size(); ++k) {
            const Tile& t = rows[r][k];
            const int ox = kGap + int(k) * (tile_w + kGap), oy = kGap + int(r) * (tile_h + kGap);
            for (int y = 0; y < t.h; ++y)
                std::copy_n(t.rgba.begin() + 4 * std::size_t(y) * t.w, 4 * t.w,
                            sheet.begin() + 4 * (std::size_t(oy + y) * sheet_w + ox));
        }
    write_png(out_path, sheet_w, sheet_h, sheet);
}

}  // namespace cg::viewer
