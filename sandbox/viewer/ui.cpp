#include "viewer/ui.hpp"

#include <algorithm>
#include <cmath>

#include "viewer/canvas.hpp"
#include "viewer/panels.hpp"

namespace cg::viewer {

namespace {

// The window's regions: the right column runs the full height (pseudocode, variables,
// events), the bottom row spans the rest of the width (controls and narration), and the
// left panel (algorithm, lessons, exam) and the canvas share what is left above it. The left
// panel is wider while a lesson or an exam is in it: that is text to read.
struct Layout {
    ImVec2 left_pos, left_size;
    ImVec2 canvas_pos, canvas_size;
    ImVec2 bottom_pos, bottom_size;
    ImVec2 code_pos, code_size, vars_pos, vars_size, events_pos, events_size;
};

// `code` is the height the pseudocode needs; the variables and events share what is left.
Layout compute_layout(ImVec2 d, float code, bool reading) {
    const float left =
        reading ? std::clamp(d.x * 0.27f, 250.0f, 460.0f) : std::clamp(d.x * 0.21f, 200.0f, 360.0f);
    const float right = std::clamp(d.x * 0.27f, 230.0f, 460.0f);
    // Taller while reading: the narration, its formula and the lesson's note share it.
    const float bottom = std::clamp(d.y * (reading ? 0.33f : 0.30f), 240.0f, 330.0f);
    const float top = std::max(d.y - bottom, 100.0f);
    const float middle = std::max(d.x - left - right, 100.0f);
    code = std::round(std::clamp(code, d.y * 0.2f, d.y * 0.45f));
    const float vars = std::round((d.y - code) * 0.4f);
    Layout l;
    l.left_pos = {0, 0};
    l.left_size = {left, top};
    l.canvas_pos = {left, 0};
    l.canvas_size = {middle, top};
    l.bottom_pos = {0, top};
    l.bottom_size = {left + middle, d.y - top};
    l.code_pos = {left + middle, 0};
    l.code_size = {right, code};
    l.vars_pos = {left + middle, code};
    l.vars_size = {right, vars};
    l.events_pos = {left + middle, code + vars};
    l.events_size = {right, d.y - code - vars};
    return l;
}

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                    ImGuiWindowFlags_NoBringToFrontOnFocus;

template <class Draw>
void panel(const char* title, ImVec2 pos, ImVec2 size, ImGuiWindowFlags extra, Draw draw) {
    ImGui::SetNextWindowPos(pos);
    ImGui::SetNextWindowSize(size);
    if (ImGui::Begin(title, nullptr, kFixed | extra)) draw();
    ImGui::End();  // always, whatever Begin returned
}

// A tab that can also be selected from code (opening a lesson shows the Lessons tab). The
// request stays until the tab bar has actually switched, which takes it a frame.
template <class Draw>
void tab(Session& s, const char* label, Tab t, Draw draw) {
    const bool requested = s.tab_requested && s.tab == t;
    if (!ImGui::BeginTabItem(label, nullptr, requested ? ImGuiTabItemFlags_SetSelected : 0)) return;
    if (requested) s.tab_requested = false;
    if (!s.tab_requested) s.tab = t;
    ImGui::BeginChild("tab");  // scrolls below the tab bar, which stays put
    draw();
    ImGui::EndChild();
    ImGui::EndTabItem();
}

void draw_left_panel(Session& s) {
    if (!ImGui::BeginTabBar("left")) return;
    tab(s, "Algorithm", Tab::Algorithm, [&] { draw_algorithm_panel(s); });
    tab(s, "Lessons", Tab::Lessons, [&] { draw_lessons_panel(s); });
    tab(s, "Exam", Tab::Exam, [&] { draw_exam_panel(s); });
    ImGui::EndTabBar();
}

void canvas_window(Session& s, ImVec2 pos, ImVec2 size, bool interactive) {
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    panel("Canvas", pos, size,
          ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
              ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBackground,
          [&] { draw_canvas(s, interactive); });
    ImGui::PopStyleVar(2);
}

}  // namespace

void draw_ui(Session& s, ImVec2 display, bool full_ui, bool interactive) {
    if (!full_ui) {
        canvas_window(s, ImVec2(0, 0), display, interactive);
        return;
    }
    float code = ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().WindowPadding.y +
                 ImGui::GetStyle().ScrollbarSize;  // title bar, padding, horizontal scrollbar
    ImGui::PushFont(s.fonts.mono);
    if (s.algorithm)
        code += ImGui::GetTextLineHeightWithSpacing() * s.algorithm->spec->pseudocode.size();
    ImGui::PopFont();
    const Layout l = compute_layout(display, code, s.tab != Tab::Algorithm);
    panel("Study", l.left_pos, l.left_size, ImGuiWindowFlags_NoTitleBar,
          [&] { draw_left_panel(s); });
    canvas_window(s, l.canvas_pos, l.canvas_size, interactive);
    panel("Step", l.bottom_pos, l.bottom_size, ImGuiWindowFlags_NoScrollbar,
          [&] { draw_controls_panel(s); });
    panel("Pseudocode", l.code_pos, l.code_size, ImGuiWindowFlags_HorizontalScrollbar,
          [&] { draw_pseudocode_panel(s); });
    panel("Variables", l.vars_pos, l.vars_size, 0, [&] { draw_variables_panel(s); });
    panel("Events", l.events_pos, l.events_size, 0, [&] { draw_events_panel(s); });
}

}  // namespace cg::viewer
