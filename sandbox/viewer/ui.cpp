#include "viewer/ui.hpp"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "viewer/canvas.hpp"
#include "viewer/gl.hpp"
#include "viewer/palette.hpp"
#include "viewer/panels.hpp"

namespace cg::viewer {

namespace {

// The window's regions: the right column runs the full height (pseudocode, variables,
// events), the bottom row spans the rest of the width (controls and narration), and the
// left panel (algorithm, lessons, exam) and the canvas share what is left above it. The left
// panel is wider while a lesson or an exam is in it: that is text to read; the bottom row is
// taller while predicting: the question, its fields, Reveal and the verdict all show at once.
// Either side panel folds to a strip (kFoldedWidth): at 1280×720 the canvas gets half the
// width with both open, and nearly all of it with both folded.
struct Layout {
    ImVec2 left_pos, left_size;
    ImVec2 canvas_pos, canvas_size;
    ImVec2 bottom_pos, bottom_size;
    ImVec2 code_pos, code_size, vars_pos, vars_size, events_pos, events_size;
};

constexpr float kFoldedWidth = 30;

struct LayoutWish {
    bool reading = false;     // a lesson or an exam open in the left panel
    bool predicting = false;  // Predict mode: its controls in the bottom row
    bool fold_left = false, fold_right = false;
};

// `code_height(width)` is the height the pseudocode needs in a column that wide; the variables
// and events share what is left.
template <class CodeHeight>
Layout compute_layout(ImVec2 d, CodeHeight code_height, LayoutWish w) {
    const float left = w.fold_left ? kFoldedWidth
                       : w.reading ? std::clamp(d.x * 0.25f, 250.0f, 460.0f)
                                   : std::clamp(d.x * 0.21f, 200.0f, 360.0f);
    const float right = w.fold_right ? kFoldedWidth : std::clamp(d.x * 0.24f, 230.0f, 460.0f);
    float code = w.fold_right ? d.y : code_height(right);
    const float bottom = w.predicting ? std::clamp(d.y * 0.44f, 300.0f, 420.0f)
                                      : std::clamp(d.y * (w.reading ? 0.33f : 0.30f), 240.0f, 330.0f);
    const float top = std::max(d.y - bottom, 100.0f);
    const float middle = std::max(d.x - left - right, 100.0f);
    if (!w.fold_right) code = std::round(std::clamp(code, d.y * 0.2f, d.y * 0.45f));
    const float vars = w.fold_right ? 0 : std::round((d.y - code) * 0.4f);
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

// The panels Tab and Shift-Tab move the keyboard through, in order: those with controls (the
// canvas has its sliders, the pseudocode its breakpoints).
constexpr const char* kKeyboardPanels[] = {"Study", "Canvas", "Step", "Pseudocode"};

template <class Draw>
void panel(Session& s, const char* title, ImVec2 pos, ImVec2 size, ImGuiWindowFlags extra,
           Draw draw) {
    ImGui::SetNextWindowPos(pos);
    ImGui::SetNextWindowSize(size);
    ImGui::SetNextWindowBgAlpha(0.0f);  // the frame is cleared to its colour (clear_frame)
    if (ImGui::Begin(title, nullptr, kFixed | extra)) draw();
    if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows)) {
        s.focused_panel = title;
        // Where the keys go, while they move through the controls: a ring round the panel.
        if (ImGui::GetIO().NavVisible)
            ImGui::GetForegroundDrawList()->AddRect(
                pos, ImVec2(pos.x + size.x, pos.y + size.y),
                ImGui::GetColorU32(ImGuiCol_NavHighlight), 0, 0, 3.0f);
    }
    ImGui::End();  // always, whatever Begin returned
}

// Tab / Shift-Tab: the next or previous panel gets the keyboard, its first control the
// navigation cursor (then the arrows move between controls and Space presses one); Escape
// gives the keys back to stepping.
void move_keyboard(Session& s) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    if (s.leave_panels) {
        s.leave_panels = false;
        ImGui::FocusWindow(nullptr);
        g.NavDisableHighlight = true;
    }
    if (s.panel_step == 0) return;
    const int n = static_cast<int>(std::size(kKeyboardPanels));
    int current = -1;
    for (int i = 0; i < n; ++i)
        if (s.focused_panel == kKeyboardPanels[i]) current = i;
    const int next = current < 0 ? (s.panel_step > 0 ? 0 : n - 1) : (current + s.panel_step + n) % n;
    s.panel_step = 0;
    if (ImGuiWindow* w = ImGui::FindWindowByName(kKeyboardPanels[next])) {
        ImGui::FocusWindow(w);
        ImGui::NavInitWindow(w, true);
        g.NavDisableHighlight = false;
        g.NavDisableMouseHover = true;
    }
}

// F1 or ?: every key the viewer knows, over the middle of the window.
void draw_help(Session& s, ImVec2 display) {
    if (!s.show_help) return;
    ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowFocus();
    constexpr const char* keys[][2] = {
        {"→  or  Space", "one step"},
        {"←", "one step back"},
        {"Home", "back to step 0"},
        {"End", "run to the end (stops at a breakpoint)"},
        {"P", "play / pause"},
        {"F", "frame: fit the picture to what the step is about"},
        {"[  /  ]", "fold or unfold the left panel / the code column"},
        {"M", "next mode: Watch, Predict, Find the bug"},
        {"1 … 9", "Predict: choose the next step's event"},
        {"Enter", "Predict: reveal the step and grade the prediction"},
        {"B", "Find the bug: this step is the first wrong one"},
        {"C", "Compare: open or close the second run"},
        {"Tab  /  Shift-Tab", "move the keyboard to the next / previous panel"},
        {"↑ ↓ ← →  (in a panel)", "move between its controls"},
        {"Space  or  Enter", "press the control, or edit the field"},
        {"Escape", "leave the panel (the arrows step again), or close this"},
        {"Ctrl-Tab", "switch panels, as ImGui does"},
        {"F1  or  ?", "show or hide this list"},
    };
    if (ImGui::Begin("Keyboard", &s.show_help,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoSavedSettings)) {
        if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            for (const auto& k : keys) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::PushFont(s.fonts.mono);
                ImGui::TextUnformatted(k[0]);
                ImGui::PopFont();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(k[1]);
            }
            ImGui::EndTable();
        }
        ImGui::TextDisabled("Typing in a field: the keys edit it; Enter or a click elsewhere ends.");
    }
    ImGui::End();
}

// A tab that can also be selected from code (opening a lesson shows the Lessons tab). ImGui
// applies ImGuiTabItemFlags_SetSelected at the next frame's layout, so in the frame a request
// is passed the bar still shows the old tab: that frame must not be read back as the
// student's choice. In every other frame the tab the bar shows is the truth, whoever chose
// it — a click included. (The request used to stay pending until its tab came up, and a
// click landing before then was undone by it: the first click on Exam was lost.)
template <class Draw>
void tab(Session& s, const char* label, Tab t, bool passing_request, Draw draw) {
    const ImGuiTabItemFlags flags =
        passing_request && s.tab == t ? ImGuiTabItemFlags_SetSelected : 0;
    const bool open = ImGui::BeginTabItem(label, nullptr, flags);
    s.note_widget(std::string("tab:") + label);
    if (!open) return;
    if (!passing_request) s.tab = t;
    ImGui::BeginChild("tab");  // scrolls below the tab bar, which stays put
    draw();
    ImGui::EndChild();
    ImGui::EndTabItem();
}

// A folded panel: a strip with the button that unfolds it.
void draw_folded(Session& s, const char* button, const char* widget, const char* tip, bool& fold) {
    ImGui::SetCursorPosX(std::max(0.0f, (ImGui::GetWindowWidth() - ImGui::GetFrameHeight()) / 2 - 2));
    if (ImGui::SmallButton(button)) fold = false;
    s.note_widget(widget);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
}

void draw_left_panel(Session& s) {
    if (s.fold_left) {
        draw_folded(s, "»##unfold", "unfold left", "Show the lessons, the algorithm and the exam  ([)",
                    s.fold_left);
        return;
    }
    if (!ImGui::BeginTabBar("left")) return;  // not drawn: a request waits for the next frame
    const bool passing_request = s.tab_requested;
    s.tab_requested = false;
    tab(s, "Algorithm", Tab::Algorithm, passing_request, [&] { draw_algorithm_panel(s); });
    tab(s, "Lessons", Tab::Lessons, passing_request, [&] { draw_lessons_panel(s); });
    tab(s, "Exam", Tab::Exam, passing_request, [&] { draw_exam_panel(s); });
    if (ImGui::TabItemButton("«", ImGuiTabItemFlags_Trailing | ImGuiTabItemFlags_NoTooltip))
        s.fold_left = true;
    s.note_widget("fold left");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Fold this panel: more room for the picture  ([)");
    ImGui::EndTabBar();
}

// The code column's fold button, at the right end of the pseudocode panel's title bar.
void draw_fold_right(Session& s) {
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    const ImRect bar = window->TitleBarRect();
    const ImVec2 keep = ImGui::GetCursorScreenPos();
    const ImVec2 extent = window->DC.CursorMaxPos;  // the button is not part of the content
    const float w = ImGui::CalcTextSize("»").x + ImGui::GetStyle().FramePadding.x * 2;
    ImGui::PushClipRect(bar.Min, bar.Max, false);
    ImGui::SetCursorScreenPos(
        ImVec2(bar.Max.x - w - 6, bar.Min.y + (bar.GetHeight() - ImGui::GetFontSize()) / 2));
    if (ImGui::SmallButton("»##fold")) s.fold_right = true;
    s.note_widget("fold right");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Fold the pseudocode, variables and events: more room for the picture  (])");
    ImGui::PopClipRect();
    ImGui::SetCursorScreenPos(keep);
    window->DC.CursorMaxPos = extent;
}

}  // namespace

namespace {

void canvas_window(Session& s, ImVec2 pos, ImVec2 size, bool interactive) {
    s.canvas_rect = Box{{pos.x, pos.y}, {pos.x + size.x, pos.y + size.y}};
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    panel(s, "Canvas", pos, size,
          ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
              ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBackground,
          [&] {
              if (s.comparing())
                  draw_compare_canvases(s, interactive);
              else
                  draw_canvas(s, interactive);
          });
    ImGui::PopStyleVar(2);
}

}  // namespace

void draw_ui(Session& s, ImVec2 display, bool full_ui, bool interactive) {
    if (s.record_widgets) s.widgets.clear();  // what this frame draws, no older
    s.sync_study();
    if (!full_ui) {
        canvas_window(s, ImVec2(0, 0), display, interactive);
        return;
    }
    const Layout l = compute_layout(
        display, [&](float width) { return pseudocode_height(s, width); },
        {s.tab != Tab::Algorithm, s.study.mode == Mode::Predict, s.fold_left, s.fold_right});
    if (interactive) move_keyboard(s);
    s.focused_panel.clear();
    panel(s, "Study", l.left_pos, l.left_size, ImGuiWindowFlags_NoTitleBar,
          [&] { draw_left_panel(s); });
    canvas_window(s, l.canvas_pos, l.canvas_size, interactive);
    panel(s, "Step", l.bottom_pos, l.bottom_size, ImGuiWindowFlags_NoScrollbar,
          [&] { draw_controls_panel(s); });
    if (s.fold_right) {
        panel(s, "Code", l.code_pos, l.code_size, ImGuiWindowFlags_NoTitleBar, [&] {
            draw_folded(s, "«##unfold", "unfold right", "Show the pseudocode, variables and events  (])",
                        s.fold_right);
        });
    } else {
        panel(s, "Pseudocode", l.code_pos, l.code_size, 0, [&] {
            draw_fold_right(s);
            draw_pseudocode_panel(s);
        });
        panel(s, "Variables", l.vars_pos, l.vars_size, 0, [&] { draw_variables_panel(s); });
        panel(s, "Events", l.events_pos, l.events_size, 0, [&] { draw_events_panel(s); });
    }
    draw_compare_editor(s);
    draw_help(s, display);
}

void clear_frame(const Gl& gl, int fb_width, int fb_height, const Session& s) {
    const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    auto byte = [](float c) { return static_cast<std::uint32_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255)); };
    gl.clear(fb_width, fb_height, byte(bg.x) << 24 | byte(bg.y) << 16 | byte(bg.z) << 8 | 0xffu);
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const double sx = display.x > 0 ? fb_width / display.x : 1;
    const double sy = display.y > 0 ? fb_height / display.y : 1;
    const Box& c = s.canvas_rect;
    const int x0 = static_cast<int>(std::lround(c.min.x * sx)), y0 = static_cast<int>(std::lround(c.min.y * sy));
    const int x1 = static_cast<int>(std::lround(c.max.x * sx)), y1 = static_cast<int>(std::lround(c.max.y * sy));
    gl.clear_rect(x0, y0, x1 - x0, y1 - y0, fb_height, kCanvasBackground);
}

}  // namespace cg::viewer
