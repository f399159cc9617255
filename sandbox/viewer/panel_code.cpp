// The right column: the pseudocode with the active line, the variables, the event legend.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>

#include "core/format.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/palette.hpp"
#include "viewer/panels.hpp"
#include "viewer/text_wrap.hpp"

namespace cg::viewer {

namespace {

// The step before the current one, from the narration log, to spot changed variables.
const StepInfo* previous_step(Session& s) {
    const NarrationLog& log = s.log();
    return log.steps.size() >= 2 ? &log.steps[log.steps.size() - 2] : nullptr;
}

bool changed_since(const Var& v, const StepInfo* before) {
    if (!before) return false;
    const auto same = std::find_if(before->vars.begin(), before->vars.end(),
                                   [&](const Var& b) { return b.name == v.name; });
    return same == before->vars.end() || same->value != v.value;
}

}  // namespace

void draw_pseudocode_panel(Session& s) {
    if (!s.algorithm) return;
    const std::vector<std::string>& lines = s.algorithm->spec->pseudocode;
    const int active = s.last_step() ? s.last_step()->line : 0;

    ImGui::PushFont(s.fonts.mono);
    const float height = ImGui::GetTextLineHeightWithSpacing();
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(0, 0));  // one band per line, no gaps
    const float gutter = 18 + ImGui::CalcTextSize("00").x + 12;    // breakpoint dot, number
    float width = ImGui::GetContentRegionAvail().x;
    for (const std::string& line : lines)
        width = std::max(width, gutter + ImGui::CalcTextSize(line.c_str()).x + 8);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float text_dy = (height - ImGui::GetFontSize()) / 2;

    for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
        const int line = i + 1;
        ImGui::PushID(line);
        const ImVec2 p = ImGui::GetCursorScreenPos();
        const ImVec2 end(p.x + width, p.y + height);
        if (ImGui::InvisibleButton("line", ImVec2(width, height))) {
            if (!s.breakpoints.erase(line)) s.breakpoints.insert(line);
        }
        const bool hovered = ImGui::IsItemHovered();
        if (hovered) ImGui::SetTooltip("Click to toggle a breakpoint on line %d", line);
        if (line == active) {
            dl->AddRectFilled(p, end, im_colour(kActiveLine));
            dl->AddRectFilled(p, ImVec2(p.x + 3, end.y), im_colour(role_rgba(Role::Active)));
            if (s.followed_line != active) ImGui::SetScrollHereY(0.5f);
        } else if (hovered) {
            dl->AddRectFilled(p, end, IM_COL32(0, 0, 0, 14));
        }
        const ImVec2 dot(p.x + 11, p.y + height / 2);
        if (s.breakpoints.count(line))
            dl->AddCircleFilled(dot, 5, im_colour(kBreakpoint));
        else if (hovered)
            dl->AddCircle(dot, 5, im_colour(with_alpha(kBreakpoint, 0x80)));
        char number[16];
        std::snprintf(number, sizeof number, "%2d", line);
        dl->AddText(ImVec2(p.x + 18, p.y + text_dy), im_colour(kTickLabel), number);
        dl->AddText(ImVec2(p.x + gutter, p.y + text_dy), im_colour(kCaptionText), lines[i].c_str());
        ImGui::PopID();
    }
    s.followed_line = active;
    ImGui::PopStyleVar();
    ImGui::PopFont();
}

void draw_variables_panel(Session& s) {
    const StepInfo* info = s.last_step();
    if (!info) {
        ImGui::TextDisabled("No step taken yet.");
        return;
    }
    const StepInfo* before = previous_step(s);
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("variables", 2, flags)) return;
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    for (const Var& v : info->vars) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::PushFont(s.fonts.mono);
        ImGui::TextUnformatted(v.name.c_str());
        ImGui::PopFont();
        ImGui::TableNextColumn();
        const bool changed = changed_since(v, before);
        if (changed) ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kChangedValue));
        text_wrapped(to_text(v.value));
        if (changed) ImGui::PopStyleColor();
        if (changed && ImGui::IsItemHovered()) ImGui::SetTooltip("changed by this step");
    }
    ImGui::EndTable();
}

void draw_events_panel(Session& s) {
    if (!s.algorithm) return;
    const std::string current = s.last_step() ? s.last_step()->event : "";
    const ImGuiTableFlags flags = ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("events", 2, flags)) return;
    ImGui::TableSetupColumn("event", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("meaning", ImGuiTableColumnFlags_WidthStretch);
    for (const EventKind& e : s.algorithm->spec->events) {
        ImGui::TableNextRow();
        const bool now = e.id == current;
        if (now) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, im_colour(kActiveLine));
        ImGui::TableNextColumn();
        ImGui::PushFont(s.fonts.mono);
        ImGui::TextColored(im_vec4(now ? darker(role_rgba(Role::Active), 0.8f) : kCaptionText),
                           "%s", e.id.c_str());
        ImGui::PopFont();
        ImGui::TableNextColumn();
        text_wrapped(e.meaning);
        if (now && s.followed_event != current) ImGui::SetScrollHereY(0.5f);
    }
    ImGui::EndTable();
    s.followed_event = current;
}

}  // namespace cg::viewer
