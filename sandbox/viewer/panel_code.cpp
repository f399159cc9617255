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

namespace {

// The gutter before each line: the breakpoint dot and the line number.
float code_gutter() { return 18 + ImGui::CalcTextSize("00").x + 12; }

// One pseudocode line as the rows it takes in `width` pixels: broken at spaces (the course's
// lines are long), each continuation row indented under the line's own text — never a
// sideways scroll to read the end of a line. The current font is the monospaced one.
std::vector<std::string> code_rows(const std::string& line, float width) {
    const ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize();
    auto measure = [&](const std::string& t) {
        return font->CalcTextSizeA(size, FLT_MAX, 0, t.c_str()).x;
    };
    if (measure(line) <= width) return {line};
    // Words with the spaces before them: a break goes before a word and drops its spaces.
    const std::size_t start = std::min(line.find_first_not_of(' '), line.size());
    const std::string indent(start + 4, ' ');
    std::vector<std::string> rows;
    std::string row = line.substr(0, start);
    bool row_has_word = false;
    for (std::size_t at = start; at < line.size();) {
        const std::size_t word = std::min(line.find_first_not_of(' ', at), line.size());
        const std::size_t end = std::min(line.find(' ', word), line.size());
        const std::string spaces = line.substr(at, word - at), text = line.substr(word, end - word);
        if (row_has_word && measure(row + spaces + text) > width) {
            rows.push_back(row);
            row = indent + text;
        } else {
            row += spaces + text;
        }
        row_has_word = true;
        at = end;
    }
    rows.push_back(row);
    return rows;
}

// The width the lines wrap to in a panel `panel_width` wide (room kept for a scrollbar).
float code_text_width(float panel_width) {
    const ImGuiStyle& style = ImGui::GetStyle();
    return panel_width - 2 * style.WindowPadding.x - style.ScrollbarSize - code_gutter() - 8;
}

}  // namespace

float pseudocode_height(Session& s, float panel_width) {
    const ImGuiStyle& style = ImGui::GetStyle();
    float height = ImGui::GetFrameHeight() + 2 * style.WindowPadding.y;  // title bar, padding
    if (!s.algorithm) return height;
    ImGui::PushFont(s.fonts.mono);
    const float width = code_text_width(panel_width);
    std::size_t rows = 0;
    for (const std::string& line : s.algorithm->spec->pseudocode)
        rows += code_rows(line, width).size();
    height += ImGui::GetTextLineHeightWithSpacing() * static_cast<float>(rows);
    ImGui::PopFont();
    return height;
}

void draw_pseudocode_panel(Session& s) {
    if (!s.algorithm) return;
    const std::vector<std::string>& lines = s.algorithm->spec->pseudocode;
    const int active = s.shown_step() ? s.shown_step()->line : 0;

    ImGui::PushFont(s.fonts.mono);
    const float row_height = ImGui::GetTextLineHeightWithSpacing();
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(0, 0));  // one band per line, no gaps
    const float gutter = code_gutter();
    const float width = ImGui::GetContentRegionAvail().x;
    const float text_width = code_text_width(ImGui::GetWindowWidth());
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float text_dy = (row_height - ImGui::GetFontSize()) / 2;
    ImVec2 text_lo(FLT_MAX, FLT_MAX), text_hi(-FLT_MAX, -FLT_MAX);  // where the text went

    for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
        const int line = i + 1;
        const std::vector<std::string> rows = code_rows(lines[i], text_width);
        const float height = row_height * static_cast<float>(rows.size());
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
        const ImVec2 dot(p.x + 11, p.y + row_height / 2);
        if (s.breakpoints.count(line))
            dl->AddCircleFilled(dot, 5, im_colour(kBreakpoint));
        else if (hovered)
            dl->AddCircle(dot, 5, im_colour(with_alpha(kBreakpoint, 0x80)));
        char number[16];
        std::snprintf(number, sizeof number, "%2d", line);
        dl->AddText(ImVec2(p.x + 18, p.y + text_dy), im_colour(kTickLabel), number);
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const ImVec2 at(p.x + gutter, p.y + text_dy + row_height * static_cast<float>(r));
            dl->AddText(at, im_colour(kCaptionText), rows[r].c_str());
            const ImVec2 size = ImGui::CalcTextSize(rows[r].c_str());
            text_lo = ImVec2(std::min(text_lo.x, at.x), std::min(text_lo.y, at.y));
            text_hi = ImVec2(std::max(text_hi.x, at.x + size.x), std::max(text_hi.y, at.y + size.y));
        }
        ImGui::PopID();
    }
    if (s.record_widgets && !lines.empty()) {  // the tests check no row runs past the edge
        const ImVec2 lo = ImGui::GetWindowPos();
        const float right = lo.x + ImGui::GetWindowWidth() - ImGui::GetStyle().WindowPadding.x;
        s.widgets["pseudocode text"] = {Box{{text_lo.x, text_lo.y}, {text_hi.x, text_hi.y}},
                                        Box{{lo.x, lo.y}, {right, lo.y + ImGui::GetWindowHeight()}},
                                        text_hi.x <= right};
    }
    s.followed_line = active;
    ImGui::PopStyleVar();
    ImGui::PopFont();
}

void draw_variables_panel(Session& s) {
    const StepInfo* info = s.shown_step();  // Find the bug: the planted working
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
    const std::string current = s.shown_step() ? s.shown_step()->event : "";
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
