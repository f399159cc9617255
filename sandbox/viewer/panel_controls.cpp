// The bottom panel. Sections: [stepping] [narration] [log] [files].
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <fstream>
#include <string>

#include "viewer/im_colour.hpp"
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
    if (ImGui::Button("|< Reset")) s.reset();
    tooltip("Back to step 0  (Home)");
    ImGui::SameLine();
    if (ImGui::Button("< Back")) s.step_back();
    tooltip("One step back  (←)");
    ImGui::SameLine();
    if (ImGui::Button("Step >")) s.step_forward();
    tooltip("One step  (→ or Space)");
    ImGui::SameLine();
    if (ImGui::Button("Run to end >|")) s.run_to_end();
    tooltip("All remaining steps at once, stopping at a breakpoint  (End)");
    ImGui::SameLine();
    if (ImGui::Button(s.playing ? "Pause##play" : "Play##play",
                      ImVec2(ImGui::GetFontSize() * 4, 0)))
        s.toggle_play();
    tooltip("Step on by itself, stopping at a breakpoint  (P)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9);
    ImGui::SliderFloat("##speed", &s.steps_per_second, 0.5f, 60.0f, "%.1f steps/s",
                       ImGuiSliderFlags_Logarithmic);
    tooltip("Play's speed");

    const std::optional<std::size_t> n = s.length();
    const std::string counter =
        "step " + std::to_string(s.index()) + " / " + (n ? std::to_string(*n) : "?");
    ImGui::SameLine();
    ImGui::TextUnformatted(counter.c_str());

    // Scrubbing: a slider over the whole run (or over what is known of it).
    ImU64 step = s.index(), first = 0;
    ImU64 last = n ? *n : std::max<ImU64>(2 * step, step + 20);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::SliderScalar("##scrub", ImGuiDataType_U64, &step, &first, &last, "go to step %llu"))
        s.jump(step);
}

// --- [narration] -----------------------------------------------------------------------------

void draw_narration(Session& s) {
    ImGui::PushFont(s.fonts.large);
    if (const StepInfo* info = s.last_step()) {
        text_wrapped(info->narration);
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kHintText));
        text_wrapped("Step 0: nothing has happened yet. Press Step > (→ or Space) to begin.");
        ImGui::PopStyleColor();
    }
    ImGui::PopFont();
    if (s.timeline && s.timeline->hit_step_limit())
        ImGui::TextColored(im_vec4(kErrorText), "Stopped: the run reached the step limit.");
}

// --- [log] -----------------------------------------------------------------------------------

// Steps 1..k, newest at the bottom; clicking an entry goes back to that step.
void draw_log(Session& s, float height) {
    ImGui::BeginChild("log", ImVec2(0, height), true);
    const NarrationLog& log = s.log();
    const float wrap = ImGui::GetContentRegionAvail().x;
    const bool was_at_bottom = ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 1;
    std::size_t clicked = 0;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    for (std::size_t i = 0; i < log.steps.size(); ++i) {
        const std::size_t step = log.first + i;
        const std::string text =
            wrap_at_spaces(ImGui::GetFont(), ImGui::GetFontSize(),
                           std::to_string(step) + ".  " + log.steps[i].narration, wrap);
        const ImVec2 size = ImGui::CalcTextSize(text.c_str());
        ImGui::PushID(static_cast<int>(i));
        const ImVec2 at = ImGui::GetCursorScreenPos();
        if (ImGui::Selectable("##entry", step == log.index, 0, ImVec2(0, size.y))) clicked = step;
        dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, ImGui::GetColorU32(ImGuiCol_Text),
                    text.c_str());
        ImGui::PopID();
    }
    if (log.steps.empty()) ImGui::TextDisabled("The narration of each step appears here.");
    if (was_at_bottom) ImGui::SetScrollHereY(1.0f);  // follow new steps unless scrolled up
    ImGui::EndChild();
    if (clicked) s.jump(clicked);  // after the loop: jumping rebuilds the log
}

// --- [files] ---------------------------------------------------------------------------------

void save_checkpoint(Session& s) {
    std::ofstream f(s.checkpoint_path);
    f << checkpoint_to_json(s.checkpoint()).dump(2) << "\n";
    if (f)
        s.set_status("Saved " + s.checkpoint_path, false);
    else
        s.set_status("cannot write " + s.checkpoint_path, true);
}

void open_checkpoint(Session& s) {
    try {
        const Checkpoint c =
            checkpoint_from_json(parse_json(read_text_file(s.checkpoint_path)), s.registry);
        s.load(c);
        s.set_status("Opened " + s.checkpoint_path, false);
    } catch (const std::exception& e) {  // InputError names the field; JSON errors the place
        s.set_status(s.checkpoint_path + ": " + e.what(), true);
    }
}

void draw_files(Session& s) {
    if (ImGui::Button("Screenshot")) s.screenshot_requested = true;
    tooltip("Save the whole window as cgsandbox-<id>-step<k>.png here");
    ImGui::SameLine(0, ImGui::GetFontSize() * 1.5f);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Checkpoint");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 16);
    ImGui::InputText("##checkpoint", &s.checkpoint_path);
    tooltip("A checkpoint file: algorithm, input, step and view");
    ImGui::SameLine();
    if (ImGui::Button("Save")) save_checkpoint(s);
    ImGui::SameLine();
    if (ImGui::Button("Open")) open_checkpoint(s);
    if (!s.status.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(im_vec4(s.status_is_error ? kErrorText : kOkText), "%s",
                           s.status.c_str());
    }
}

}  // namespace

void draw_controls_panel(Session& s) {
    draw_stepping(s);
    draw_narration(s);
    const float files_row = ImGui::GetFrameHeightWithSpacing();
    draw_log(s,
             std::max(ImGui::GetContentRegionAvail().y - files_row, ImGui::GetFrameHeight() * 2));
    draw_files(s);
}

}  // namespace cg::viewer
