// The Exam tab: a generated problem, the student's answers graded, then the solution
// one step at a time. Sections: [problem] [answers] [solution].
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <string>

#include "core/format.hpp"
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

void hint(const Session& s, const std::string& text) {
    ImGui::PushFont(s.fonts.small);
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kTickLabel));
    text_wrapped(text);
    ImGui::PopStyleColor();
    ImGui::PopFont();
}

// An expected value as a student writes it: "(2, 4)", "0.25", "yes", "none".
std::string show(const json& v) {
    if (v.is_null()) return "none";
    if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
    if (v.is_number()) return num(v.get<double>());
    if (v.is_string()) return v.get<std::string>();
    if (v.is_array()) {
        std::string out = "(";
        for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + show(v[i]);
        return out + ")";
    }
    return v.dump();
}

// --- [problem] -------------------------------------------------------------------------------

void draw_seed_row(Session& s, const Algorithm& a) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Problem no.");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5);
    ImU64 seed = s.exam.seed;
    if (ImGui::InputScalar("##seed", ImGuiDataType_U64, &seed)) s.exam.seed = seed;
    s.note_widget("exam seed");
    tooltip("The problem's seed: the same number always gives the same problem");
    if (ImGui::IsItemDeactivatedAfterEdit()) s.try_start_exam(a, s.exam.seed);
    if (!s.exam.active) {
        ImGui::SameLine();
        if (ImGui::Button("Start")) s.try_start_exam(a, s.exam.seed);
        s.note_widget("Start exam");
        return;
    }
    flow(button_width("New problem") + button_width("Leave") + ImGui::GetStyle().ItemSpacing.x);
    if (ImGui::Button("New problem")) {
        s.exam.seed = s.exam.problem.seed + 1;
        s.try_start_exam(a, s.exam.seed);
    }
    s.note_widget("New problem");
    tooltip("The next problem (seed + 1)");
    ImGui::SameLine();
    if (ImGui::Button("Leave")) s.leave_exam();
    s.note_widget("Leave exam");
    tooltip("Back to free stepping; the problem's input stays loaded");
}

// The question on a yellow card, like an exam sheet.
void draw_question(Session& s) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float pad = style.WindowPadding.x;
    const float width = ImGui::GetContentRegionAvail().x;
    const std::string text =
        wrap_at_spaces(ImGui::GetFont(), ImGui::GetFontSize(),
                       text_to_unicode(s.exam.problem.question), width - 2 * pad);
    const float height = ImGui::GetFontSize() + style.ItemSpacing.y +
                         ImGui::CalcTextSize(text.c_str()).y + 2 * style.WindowPadding.y;
    ImGui::PushStyleColor(ImGuiCol_ChildBg, im_vec4(kExamQuestion));
    ImGui::PushStyleVar(ImGuiStyleVar_ChildRounding, 4.0f);
    ImGui::BeginChild("question", ImVec2(0, height), true, ImGuiWindowFlags_NoScrollbar);
    ImGui::PushFont(s.fonts.bold);
    ImGui::Text("Problem %llu", static_cast<unsigned long long>(s.exam.problem.seed));
    ImGui::PopFont();
    ImGui::TextUnformatted(text.c_str());
    ImGui::EndChild();
    ImGui::PopStyleVar();
    ImGui::PopStyleColor();
}

// --- [answers] -------------------------------------------------------------------------------

const FieldGrade* grade_of(const Session& s, const std::string& field) {
    const auto it = std::find_if(s.exam.grades.begin(), s.exam.grades.end(),
                                 [&](const FieldGrade& g) { return g.field == field; });
    return it == s.exam.grades.end() ? nullptr : &*it;
}

// A run of answer fields a/row/column with the same a: drawn as a table, a row per row name
// and a column per column name, in the order the fields come.
struct TableGroup {
    std::size_t first = 0, last = 0;  // indices into the answers, inclusive
    std::string name;                 // a
    std::vector<std::string> rows, columns;
};

std::vector<std::string> split_path(const std::string& f) {
    std::vector<std::string> parts;
    std::size_t at = 0;
    for (std::size_t slash; (slash = f.find('/', at)) != std::string::npos; at = slash + 1)
        parts.push_back(f.substr(at, slash - at));
    parts.push_back(f.substr(at));
    return parts;
}

void group_answers(const std::vector<std::string>& answers, std::vector<std::size_t>& single,
                   std::vector<TableGroup>& tables) {
    for (std::size_t i = 0; i < answers.size();) {
        const auto parts = split_path(answers[i]);
        std::size_t j = i;
        TableGroup t;
        while (j < answers.size()) {
            const auto q = split_path(answers[j]);
            if (q.size() != 3 || parts.size() != 3 || q[0] != parts[0]) break;
            if (std::find(t.rows.begin(), t.rows.end(), q[1]) == t.rows.end()) t.rows.push_back(q[1]);
            if (std::find(t.columns.begin(), t.columns.end(), q[2]) == t.columns.end())
                t.columns.push_back(q[2]);
            ++j;
        }
        if (j - i >= 2) {
            t.first = i, t.last = j - 1, t.name = parts[0];
            tables.push_back(std::move(t));
            i = j;
        } else {
            single.push_back(i++);
        }
    }
}

// The table's boxes; returns whether Enter was pressed in one. Wrong answers say why under it.
bool draw_answer_table(Session& s, const TableGroup& t) {
    const ExamProblem& p = s.exam.problem;
    bool enter = false;
    ImGui::PushFont(s.fonts.mono);
    ImGui::TextUnformatted(t.name.c_str());
    ImGui::PopFont();
    const ImGuiTableFlags flags = ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerH;
    std::vector<std::string> why;
    ImGui::PushID(t.name.c_str());
    if (ImGui::BeginTable("answer table", static_cast<int>(t.columns.size()) + 1, flags)) {
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed);
        for (const std::string& c : t.columns)
            ImGui::TableSetupColumn(c.c_str(), ImGuiTableColumnFlags_WidthStretch,
                                    c == "crossing" ? 2.0f : 1.0f);
        ImGui::TableHeadersRow();
        for (const std::string& row : t.rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextUnformatted(row.c_str());
            for (const std::string& c : t.columns) {
                ImGui::TableNextColumn();
                const std::string field = t.name + "/" + row + "/" + c;
                const auto it = std::find(p.answers.begin() + static_cast<long>(t.first),
                                          p.answers.begin() + static_cast<long>(t.last) + 1, field);
                if (it == p.answers.begin() + static_cast<long>(t.last) + 1) {
                    ImGui::AlignTextToFramePadding();
                    ImGui::TextDisabled("—");  // not asked: r where p = 0, say
                    continue;
                }
                const std::size_t i = static_cast<std::size_t>(it - p.answers.begin());
                const FieldGrade* g = grade_of(s, field);
                ImGui::PushID(static_cast<int>(i));
                ImGui::SetNextItemWidth(g ? -ImGui::GetFontSize() * 1.2f : -1);
                ImGui::InputText("##answer", &s.exam.typed[i]);
                s.note_widget("answer:" + field);
                enter = enter || (ImGui::IsItemDeactivated() &&
                                  ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)));
                if (g) {
                    ImGui::SameLine(0, 2);
                    ImGui::TextColored(im_vec4(g->correct ? kOkText : kErrorText), "%s",
                                       g->correct ? "✓" : "✗");
                    if (!g->correct && !g->why.empty()) why.push_back(row + " " + c + ": " + g->why);
                } else if (s.exam.answers_shown && p.expected.contains(field)) {
                    why.push_back(row + " " + c + ": " + show(p.expected.at(field)));
                }
                ImGui::PopID();
            }
        }
        ImGui::EndTable();
    }
    ImGui::PopID();
    if (!why.empty()) {
        const bool graded = !s.exam.grades.empty();
        ImGui::PushFont(s.fonts.small);
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(graded ? kErrorText : kOkText));
        for (const std::string& w : why) text_wrapped(w);
        ImGui::PopStyleColor();
        ImGui::PopFont();
    }
    ImGui::Spacing();
    return enter;
}

void draw_answers(Session& s) {
    const ExamProblem& p = s.exam.problem;
    ImGui::PushFont(s.fonts.bold);
    ImGui::TextUnformatted("Your answers");
    ImGui::PopFont();
    // No-break spaces keep each example on one line.
    hint(s,
         "Decimals (0.25, not 1/4) · a point as (x,\u00a0y) · a list as "
         "[(1,\u00a00),\u00a0(0,\u00a03)] · yes / no · none · a word as asked (enters)");

    // Fields a/row/column (Liang-Barsky's edges/left/p …) are a table the student writes row by
    // row; the others one box a line.
    std::vector<std::size_t> single;
    std::vector<TableGroup> tables;
    group_answers(p.answers, single, tables);

    ImGui::PushFont(s.fonts.mono);
    float label = 0;
    for (std::size_t i : single) label = std::max(label, ImGui::CalcTextSize(p.answers[i].c_str()).x);
    ImGui::PopFont();
    const float mark = ImGui::GetFontSize() * 1.6f;
    bool enter = false;
    std::size_t next_table = 0, next_single = 0;
    for (std::size_t i = 0; i < p.answers.size() && i < s.exam.typed.size(); ++i) {
        if (next_table < tables.size() && tables[next_table].first == i) {
            enter = draw_answer_table(s, tables[next_table]) || enter;
            i = tables[next_table++].last;
            continue;
        }
        if (next_single >= single.size() || single[next_single] != i) continue;
        ++next_single;
        const std::string& field = p.answers[i];
        const FieldGrade* g = grade_of(s, field);
        ImGui::PushID(static_cast<int>(i));
        ImGui::AlignTextToFramePadding();
        ImGui::PushFont(s.fonts.mono);
        ImGui::TextUnformatted(field.c_str());
        ImGui::PopFont();
        ImGui::SameLine(label + ImGui::GetStyle().ItemSpacing.x * 2);
        ImGui::SetNextItemWidth(-mark);
        ImGui::InputText("##answer", &s.exam.typed[i]);
        s.note_widget("answer:" + field);
        enter = enter || (ImGui::IsItemDeactivated() &&
                          ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)));
        if (g) {
            ImGui::SameLine();
            ImGui::TextColored(im_vec4(g->correct ? kOkText : kErrorText), "%s",
                               g->correct ? "✓" : "✗");
        }
        // One small line under the box: why it is wrong (which names the expected value), or
        // the expected value when the answers are shown.
        const bool wrong = g && !g->correct && !g->why.empty();
        const bool answer = s.exam.answers_shown && p.expected.contains(field) && !wrong;
        if (wrong || answer) {
            const float indent = label + ImGui::GetStyle().ItemSpacing.x * 2;
            ImGui::Indent(indent);
            ImGui::PushFont(s.fonts.small);
            ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(wrong ? kErrorText : kOkText));
            text_wrapped(wrong ? g->why : "answer: " + show(p.expected.at(field)));
            ImGui::PopStyleColor();
            ImGui::PopFont();
            ImGui::Unindent(indent);
        }
        ImGui::PopID();
    }

    ImGui::PushStyleColor(ImGuiCol_Button, im_vec4(kCheckButton));
    ImGui::PushStyleColor(ImGuiCol_ButtonHovered, im_vec4(darker(kCheckButton, 0.9f)));
    ImGui::PushStyleColor(ImGuiCol_ButtonActive, im_vec4(darker(kCheckButton, 0.8f)));
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(0xffffffff));
    const bool check = ImGui::Button("Check");
    s.note_widget("Check");
    if (check || enter) s.check_exam();
    ImGui::PopStyleColor(4);
    tooltip("Grade every answer (Enter in a box does the same)");
    ImGui::SameLine();
    if (!s.exam.grades.empty()) {
        const auto right = std::count_if(s.exam.grades.begin(), s.exam.grades.end(),
                                         [](const FieldGrade& g) { return g.correct; });
        const bool all = right == static_cast<long>(s.exam.grades.size());
        ImGui::TextColored(im_vec4(all ? kOkText : kErrorText), "%ld of %zu right%s", right,
                           s.exam.grades.size(), all ? " — well done" : "");
    } else {
        ImGui::AlignTextToFramePadding();
        ImGui::TextDisabled("numbers to 3 significant digits");
        tooltip("0.333 counts as right for 1/3; 0.33 does not");
    }
}

// --- [solution] ------------------------------------------------------------------------------

void draw_solution(Session& s) {
    if (!s.exam.revealed) {
        if (ImGui::Button("Show solution step by step")) s.reveal_next_step();
        s.note_widget("Show solution");
        tooltip("Unlocks stepping: each step of the worked solution, with the picture");
    } else if (!s.at_end()) {
        if (ImGui::Button("Next solution step >")) s.step_forward();
        s.note_widget("Next solution step");
        tooltip("The same as Step > below (→ or Space)");
    } else {
        ImGui::AlignTextToFramePadding();
        ImGui::TextColored(im_vec4(kOkText), "Solution complete");
    }
    ImGui::SameLine();
    if (ImGui::Button(s.exam.answers_shown ? "Hide answers" : "Show answers"))
        s.exam.answers_shown = !s.exam.answers_shown;
    if (s.exam.revealed) hint(s, "The narration log below lists the solution's steps so far.");
}

}  // namespace

void draw_exam_panel(Session& s) {
    if (!s.algorithm) {
        ImGui::TextDisabled("Choose an algorithm first.");
        return;
    }
    const Algorithm& a = *s.algorithm;
    if (!has_exam(a)) {
        text_wrapped("There are no exam problems for " + a.spec->title + " yet.");
        return;
    }
    draw_seed_row(s, a);
    if (!s.exam.active) {
        ImGui::Spacing();
        hint(s, "Practise " + a.spec->title +
                    " on an exam-style problem. The canvas shows the problem's input; the "
                    "steps stay hidden while you work it out. Type your answers, press Check, "
                    "then step through the solution.");
        return;
    }
    draw_question(s);
    ImGui::Spacing();
    draw_answers(s);
    ImGui::Spacing();
    ImGui::Separator();
    draw_solution(s);
}

}  // namespace cg::viewer
