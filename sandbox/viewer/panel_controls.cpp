// The bottom panel. Sections: [stepping] [now] [log] [layout]; the files row is in
// panel_files.cpp.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

#include "viewer/flow.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/math_text.hpp"
#include "viewer/palette.hpp"
#include "viewer/panels.hpp"
#include "viewer/text_wrap.hpp"

namespace cg::viewer {

namespace {

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

// --- [stepping] ------------------------------------------------------------------------------

void draw_stepping(Session& s) {
    // Narrow windows get symbols for the buttons whose tooltips say what they do.
    const bool compact = ImGui::GetContentRegionAvail().x < 800;
    ImGui::BeginDisabled(s.solution_hidden());  // an exam's steps are its solution
    if (ImGui::Button(compact ? "|<" : "|< Reset")) s.reset();
    s.note_widget("Reset");
    tooltip("Back to step 0  (Home)");
    ImGui::SameLine();
    if (ImGui::Button(compact ? "<" : "< Back")) s.step_back();
    s.note_widget("Back");
    tooltip("One step back  (←)");
    ImGui::SameLine();
    if (ImGui::Button("Step >")) s.step_forward();
    s.note_widget("Step");
    tooltip("One step  (→ or Space)");
    ImGui::SameLine();
    if (ImGui::Button(compact ? ">|" : "Run to end >|")) s.run_to_end();
    s.note_widget("Run to end");
    tooltip("All remaining steps at once, stopping at a breakpoint  (End)");
    ImGui::SameLine();
    if (ImGui::Button(s.playing ? "Pause##play" : "Play##play",
                      ImVec2(ImGui::GetFontSize() * 4, 0)))
        s.toggle_play();
    s.note_widget("Play");
    tooltip("Step on by itself, stopping at a breakpoint  (P)");
    // The sliders' numbers go beside them, not on them, where the grab would cover them.
    // An animation (its steps are frames) plays at real time, slowed down or sped up.
    const bool animation = s.algorithm && !s.algorithm->spec->clock.empty();
    char rate[32];
    if (animation)
        std::snprintf(rate, sizeof rate, "%.2f× real time", s.time_scale);
    else
        std::snprintf(rate, sizeof rate, "%.1f steps/s", s.steps_per_second);
    const float speed = ImGui::GetFontSize() * (compact ? 4 : 6);
    flow(speed + ImGui::GetStyle().ItemInnerSpacing.x +
         ImGui::CalcTextSize(animation ? "0.10× real time" : "60.0 steps/s").x);
    ImGui::SetNextItemWidth(speed);
    if (animation)
        ImGui::SliderFloat("##speed", &s.time_scale, 0.1f, 4.0f, "", ImGuiSliderFlags_Logarithmic);
    else
        ImGui::SliderFloat("##speed", &s.steps_per_second, 0.5f, 60.0f, "",
                           ImGuiSliderFlags_Logarithmic);
    s.note_widget("speed");
    tooltip(animation ? "Play's speed: 1 is real time (the simulated seconds pass as seconds)"
                      : "Play's speed");
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(rate);

    const std::optional<std::size_t> n = s.length();
    // An exam's length would give its answer away (a short run was rejected early).
    const std::string counter = s.solution_hidden() ? "solution hidden"
                                                    : "step " + std::to_string(s.index()) + " / " +
                                                          (n ? std::to_string(*n) : "?");
    flow(ImGui::CalcTextSize(counter.c_str()).x + ImGui::GetFontSize() * 8);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(counter.c_str());

    // Scrubbing: a slider over the whole run (or over what is known of it).
    ImU64 step = s.index(), first = 0;
    ImU64 last = n && !s.solution_hidden() ? *n : std::max<ImU64>(2 * step, step + 20);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::SliderScalar("##scrub", ImGuiDataType_U64, &step, &first, &last, ""))
        s.jump(step);
    s.note_widget("scrub");
    if (ImGui::IsItemHovered() || ImGui::IsItemActive())
        ImGui::SetTooltip("Drag to go to any step (now %llu)",
                          static_cast<unsigned long long>(step));
    ImGui::EndDisabled();
}

// --- [now] -----------------------------------------------------------------------------------

// The open lesson's note on the current event, on a tinted card so it is read with the
// narration it explains.
void draw_note(Session& s, const std::string& text) {
    constexpr float kPad = 6, kBar = 3;
    const char* label = "What this means";
    const float width = ImGui::GetContentRegionAvail().x;
    const std::string body = wrap_at_spaces(ImGui::GetFont(), ImGui::GetFontSize(),
                                            text_to_unicode(text), width - 2 * kPad - kBar);
    const ImFont* bold = s.fonts.bold;
    const float label_height = bold->FontSize + 2;
    const float height = 2 * kPad + label_height + ImGui::CalcTextSize(body.c_str()).y;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(at, ImVec2(at.x + width, at.y + height), im_colour(kNoteBackground), 4);
    dl->AddRectFilled(at, ImVec2(at.x + kBar, at.y + height), im_colour(kNoteAccent));
    const float x = at.x + kBar + kPad;
    dl->AddText(bold, bold->FontSize, ImVec2(x, at.y + kPad), im_colour(darker(kNoteAccent, 0.75f)),
                label);
    dl->AddText(ImVec2(x, at.y + kPad + label_height), ImGui::GetColorU32(ImGuiCol_Text),
                body.c_str());
    ImGui::Dummy(ImVec2(width, height));
}

// What the current step did: the narration, its formula, and what the lesson says about it.
void draw_now(Session& s) {
    if (draw_mode_now(s)) return;
    ImGui::PushFont(s.fonts.large);
    const StepInfo* info = s.last_step();
    if (s.solution_hidden()) {
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kCaptionText));
        text_wrapped("Exam problem " + std::to_string(s.exam.problem.seed) +
                     ": work it out on paper, type your answers in the Exam tab and press "
                     "Check. The solution stays hidden until you ask for it.");
        ImGui::PopStyleColor();
    } else if (info) {
        text_wrapped(info->narration);
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kHintText));
        text_wrapped("Step 0: nothing has happened yet. Press Step > (→ or Space) to begin.");
        ImGui::PopStyleColor();
    }
    ImGui::PopFont();
    if (s.solution_hidden() || !info) return;
    if (!info->math.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kMathText));
        ImGui::TextUnformatted(wrap_formula(ImGui::GetFont(), ImGui::GetFontSize(),
                                            math_to_unicode(info->math),
                                            ImGui::GetContentRegionAvail().x)
                                   .c_str());
        ImGui::PopStyleColor();
    }
    if (s.timeline && s.timeline->hit_step_limit())
        ImGui::TextColored(im_vec4(kErrorText), "Stopped: the run reached the step limit.");
    if (const Lesson* l = s.lesson())
        if (const LessonEventNote* note = l->note_for(info->event)) {
            ImGui::Spacing();
            draw_note(s, note->text);
        }
}

// --- [log] -----------------------------------------------------------------------------------

// Steps 1..k, newest at the bottom; clicking an entry goes back to that step.
void draw_log(Session& s, float height) {
    ImGui::BeginChild("log", ImVec2(0, height), true);
    const NarrationLog& log = s.log();
    const float wrap = ImGui::GetContentRegionAvail().x;
    const bool was_at_bottom = ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 1;
    std::size_t clicked = 0;
    // Wrapping is the log's cost (up to 500 entries): done once for a width, and only the
    // entries in sight are drawn, the others stand in as empty space of their height.
    const float font = ImGui::GetFontSize();
    if (log.wrapped.size() != log.steps.size() || log.wrapped_width != wrap ||
        log.wrapped_font != font) {
        log.wrapped.clear(), log.heights.clear();
        for (std::size_t i = 0; i < log.steps.size(); ++i) {
            // Find the bug hides the narration: the event stands for it.
            const StepInfo& entry = log.steps[i];
            const std::string said =
                entry.narration.empty() ? "(" + entry.event + ")" : entry.narration;
            log.wrapped.push_back(wrap_at_spaces(ImGui::GetFont(), font,
                                                 std::to_string(log.first + i) + ".  " + said,
                                                 wrap));
            log.heights.push_back(ImGui::CalcTextSize(log.wrapped.back().c_str()).y);
        }
        log.wrapped_width = wrap, log.wrapped_font = font;
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    for (std::size_t i = 0; i < log.steps.size(); ++i) {
        const std::size_t step = log.first + i;
        const ImVec2 size(wrap, log.heights[i]);
        if (!ImGui::IsRectVisible(size)) {
            ImGui::Dummy(size);
            continue;
        }
        ImGui::PushID(static_cast<int>(i));
        const ImVec2 at = ImGui::GetCursorScreenPos();
        if (ImGui::Selectable("##entry", step == log.index, 0, ImVec2(0, size.y))) clicked = step;
        dl->AddText(ImGui::GetFont(), font, at, ImGui::GetColorU32(ImGuiCol_Text),
                    log.wrapped[i].c_str());
        ImGui::PopID();
    }
    if (log.steps.empty()) ImGui::TextDisabled("The narration of each step appears here.");
    if (was_at_bottom) ImGui::SetScrollHereY(1.0f);  // follow new steps unless scrolled up
    ImGui::EndChild();
    if (clicked) s.jump(clicked);  // after the loop: jumping rebuilds the log
}

}  // namespace

// --- [layout] --------------------------------------------------------------------------------

void draw_controls_panel(Session& s) {
    draw_stepping(s);
    draw_modes_row(s);  // after the stepping row: Tab, then → and Space, reach Back first
    // The files row's height is last frame's: it wraps onto more rows in a narrow window.
    const float files = s.files_height > 0 ? s.files_height : ImGui::GetFrameHeightWithSpacing();
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const float body =
        std::max(ImGui::GetContentRegionAvail().y - files - spacing, ImGui::GetFrameHeight() * 2);
    const float width = ImGui::GetContentRegionAvail().x;
    if (width >= 760) {  // side by side: the step now, and the story so far
        // Predicting, the question and its fields take more of the row than a narration.
        const float share = s.study.mode == Mode::Predict ? 0.68f : 0.6f;
        ImGui::BeginChild("now", ImVec2(std::round(width * share), body));
        draw_now(s);
        ImGui::EndChild();
        ImGui::SameLine();
        draw_log(s, body);
    } else if (body >= ImGui::GetFontSize() * 9) {  // stacked, the step now first
        const float now = std::round(body * 0.6f);
        ImGui::BeginChild("now", ImVec2(0, now));
        draw_now(s);
        ImGui::EndChild();
        draw_log(s, std::max(body - now - spacing, ImGui::GetFrameHeight()));
    } else {  // too small for both: the step now matters more than the story so far
        ImGui::BeginChild("now", ImVec2(0, body));
        draw_now(s);
        ImGui::EndChild();
    }
    const float top = ImGui::GetCursorPosY();
    draw_files_row(s);
    s.files_height = ImGui::GetCursorPosY() - top;
}

}  // namespace cg::viewer
