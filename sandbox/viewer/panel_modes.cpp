// The study modes in the Step panel and on the canvas (session_modes.cpp has the logic).
// Sections: [mode row] [predict] [find the bug] [compare].
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "viewer/canvas.hpp"
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

void coloured(std::uint32_t rgba, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(rgba));
    text_wrapped(text);
    ImGui::PopStyleColor();
}

void small_hint(const Session& s, const std::string& text) {
    ImGui::PushFont(s.fonts.small);
    coloured(kTickLabel, text);
    ImGui::PopFont();
}

void heading(const Session& s, const std::string& text) {
    ImGui::PushFont(s.fonts.bold);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopFont();
}

// The current (real) step's narration, under a mode's own controls.
void narration(Session& s) {
    const StepInfo* info = s.last_step();
    if (!info) return;
    ImGui::Spacing();
    text_wrapped("Step " + std::to_string(s.index()) + ": " + info->narration);
    if (!info->math.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kMathText));
        ImGui::TextUnformatted(wrap_formula(ImGui::GetFont(), ImGui::GetFontSize(),
                                            math_to_unicode(info->math),
                                            ImGui::GetContentRegionAvail().x)
                                   .c_str());
        ImGui::PopStyleColor();
    }
}

}  // namespace

// --- [mode row] ------------------------------------------------------------------------------

void draw_modes_row(Session& s) {
    const bool locked = s.solution_hidden() || !s.timeline;
    ImGui::BeginDisabled(locked);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Mode");
    constexpr std::pair<Mode, const char*> modes[] = {
        {Mode::Watch, "Watch"}, {Mode::Predict, "Predict"}, {Mode::Bug, "Find the bug"}};
    constexpr const char* tips[] = {
        "Step freely and watch  (M: next mode)",
        "Predict each step's event and numbers before it is shown  (M: next mode)",
        "The working with one planted mistake: name the first wrong step  (M: next mode)"};
    for (std::size_t i = 0; i < std::size(modes); ++i) {
        ImGui::SameLine();
        if (ImGui::RadioButton(modes[i].second, s.study.mode == modes[i].first) &&
            s.study.mode != modes[i].first)
            s.set_mode(modes[i].first);
        s.note_widget(std::string("mode:") + modes[i].second);
        tooltip(tips[i]);
    }
    // Compare: side B chosen from the variants, the algorithms reading the same input, or an
    // edited copy of this input.
    const std::vector<CompareOption> options = s.compare_options();
    CompareState& c = s.study.compare;
    c.choice = std::clamp(c.choice, 0, std::max(0, static_cast<int>(options.size()) - 1));
    float combo = ImGui::GetFontSize() * 6;
    for (const CompareOption& o : options)
        combo = std::max(combo,
                         ImGui::CalcTextSize(o.label.c_str()).x + ImGui::GetFrameHeight() * 1.6f);
    combo = std::min(combo, ImGui::GetFontSize() * 17);
    flow(combo + button_width("Close compare") + ImGui::GetFontSize() * 3);
    ImGui::TextDisabled("|");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(combo);
    const char* preview = options.empty() ? "" : options[c.choice].label.c_str();
    if (ImGui::BeginCombo("##compare with", preview)) {
        for (int i = 0; i < static_cast<int>(options.size()); ++i) {
            if (ImGui::Selectable(options[i].label.c_str(), i == c.choice)) {
                c.choice = i;
                if (c.open) s.open_compare(i);
            }
            s.note_widget("compare option:" + options[i].label);
        }
        ImGui::EndCombo();
    }
    s.note_widget("compare with");
    tooltip(
        "Side B: a variant of this algorithm, another algorithm reading the same input, or "
        "an edited copy of this input");
    ImGui::SameLine();
    if (ImGui::Button(c.open ? "Close compare" : "Compare")) {
        if (c.open)
            s.close_compare();
        else
            s.open_compare(c.choice);
    }
    s.note_widget("Compare");
    tooltip("A second run beside this one, stepped together  (C)");
    if (c.open && !options.empty() && options[c.choice].kind == CompareOption::Kind::Edited) {
        ImGui::SameLine();
        if (ImGui::Button("Edit B")) c.editing = !c.editing;
        s.note_widget("Edit B");
        tooltip("Edit side B's input (JSON) and apply it");
    }
    ImGui::EndDisabled();
}

// --- [predict] -------------------------------------------------------------------------------

namespace {

std::string grade_line(const study::PredictGrade& g) {
    std::string out = "Step " + std::to_string(g.step) + ": " + (g.correct ? "right" : "wrong") +
                      ". It was " + g.expected_event;
    for (const study::VarGrade& v : g.vars) {
        out += ", " + v.name + " = " + study::show(v.expected);
        if (!v.correct) out += " (you: " + (v.given.is_null() ? "—" : study::show(v.given)) + ")";
    }
    if (!g.event_correct) out += " (you: " + (g.given_event.empty() ? "—" : g.given_event) + ")";
    return out + ".";
}

void draw_predict(Session& s) {
    PredictState& p = s.study.predict;
    const study::Trace* t = s.study.trace.get();
    if (!t || !s.algorithm) return;
    const Spec& spec = *s.algorithm->spec;
    const std::size_t answered = p.grades.size();
    heading(s, "Predict, then reveal");
    ImGui::SameLine();
    const std::string score = std::to_string(p.right) + " right of " + std::to_string(answered);
    ImGui::TextUnformatted(("  ·  score: " + score).c_str());
    s.note_widget("predict score");

    if (!p.grades.empty()) {  // the last verdict, with the truth
        const study::PredictGrade& g = p.grades.back();
        coloured(g.correct ? kOkText : kErrorText, grade_line(g));
        s.note_widget("predict verdict");
    }

    if (s.can_predict()) {
        const std::size_t next = p.reached + 1;
        ImGui::PushFont(s.fonts.bold);
        ImGui::Text("Step %zu: what happens next?", next);
        ImGui::PopFont();
        int key = 1;
        for (const EventKind& e : spec.events) {
            const std::string label = (key <= 9 ? std::to_string(key) + " " : std::string()) + e.id;
            flow(ImGui::CalcTextSize(label.c_str()).x + ImGui::GetFrameHeight() * 2);
            if (ImGui::RadioButton(label.c_str(), p.event == e.id)) s.choose_prediction(e.id);
            s.note_widget("predict event:" + e.id);
            tooltip(e.meaning.c_str());
            ++key;
        }
        if (const EventKind* chosen = study::find_event(spec, p.event))
            small_hint(s, chosen->id + ": " + chosen->meaning);
        const std::vector<std::string>& names = s.predict_vars();
        p.typed.resize(names.size());
        ImGui::PushFont(s.fonts.mono);
        for (std::size_t i = 0; i < names.size(); ++i) {
            ImGui::AlignTextToFramePadding();
            ImGui::TextUnformatted((names[i] + " =").c_str());
            ImGui::SameLine();
            ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
            if (ImGui::InputText(("##predict" + names[i]).c_str(), &p.typed[i],
                                 ImGuiInputTextFlags_EnterReturnsTrue))
                s.reveal_prediction();
            s.note_widget("predict var:" + names[i]);
            ImGui::SameLine();
        }
        ImGui::PopFont();
        ImGui::BeginDisabled(p.event.empty());
        if (ImGui::Button("Reveal")) s.reveal_prediction();
        ImGui::EndDisabled();
        s.note_widget("Reveal");
        tooltip("Grade the prediction (3 significant figures) and take the step  (Enter)");
    } else if (s.index() < p.reached) {
        small_hint(s, "Stepped back: the steps up to " + std::to_string(p.reached) +
                          " are revealed; step on to predict the next.");
    } else if (p.reached >= t->steps.size()) {  // the run is over: the steps to revisit
        ImGui::PushFont(s.fonts.bold);
        ImGui::Text("Run over: %zu right of %zu.", p.right, answered);
        ImGui::PopFont();
        s.note_widget("predict summary");
        std::vector<std::size_t> wrong;
        for (const study::PredictGrade& g : p.grades)
            if (!g.correct) wrong.push_back(g.step);
        if (wrong.empty()) {
            coloured(kOkText, "Every prediction was right.");
        } else {
            ImGui::AlignTextToFramePadding();
            ImGui::TextUnformatted("Wrong:");
            for (std::size_t k : wrong) {
                const std::string label = "step " + std::to_string(k);
                flow(button_width(label.c_str()));
                if (ImGui::Button(label.c_str())) s.jump(k);
                s.note_widget("wrong " + label);
            }
        }
    }
    narration(s);
}

// --- [find the bug] --------------------------------------------------------------------------

void draw_bug(Session& s) {
    BugState& b = s.study.bug;
    if (!b.bug) return;
    heading(s, "Find the bug");
    ImGui::SameLine();
    ImGui::TextUnformatted("  bug no.");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4);
    ImU64 seed = b.seed;
    if (ImGui::InputScalar("##bug seed", ImGuiDataType_U64, &seed)) b.seed = seed;
    s.note_widget("bug seed");
    if (ImGui::IsItemDeactivatedAfterEdit()) s.plant_bug();
    tooltip("The bug's seed: the same number plants the same mistake");
    ImGui::SameLine();
    if (ImGui::Button("New bug")) {
        ++b.seed;
        s.plant_bug();
    }
    s.note_widget("New bug");
    tooltip("Another planted mistake (seed + 1)");

    const std::size_t k = s.index();
    if (!b.over) {
        small_hint(s,
                   "One step of this working has a planted mistake; the picture is the right "
                   "run's. Step through, check the Variables against the picture, and name "
                   "the first wrong step.");
        if (const StepInfo* shown = s.shown_step(); shown && k > 0)
            text_wrapped("Step " + std::to_string(k) + ": " + shown->event +
                         "  (narration hidden: the working is in the Variables panel)");
        else
            text_wrapped("Step 0: step on (→ or Space) to read the working.");
        ImGui::BeginDisabled(k == 0);
        if (ImGui::Button("First wrong step is this one")) s.answer_bug(k);
        ImGui::EndDisabled();
        s.note_widget("Bug answer");
        tooltip("Name this step as the first wrong one  (B)");
        ImGui::SameLine();
        if (ImGui::Button("Give up")) s.give_up_bug();
        s.note_widget("Give up");
        tooltip("Show where the mistake is and what it was");
    }
    if (b.grade) {
        ImGui::Spacing();
        const bool right = b.grade->correct;
        const std::size_t n = b.answered_step;
        // A wrong answer says only which way to look: the explanation would give it away.
        const std::string headline =
            right    ? "Right: step " + std::to_string(n) + " is the first wrong one."
            : b.over ? "The first wrong step was " + std::to_string(b.bug->step) + "."
            : n < b.bug->step
                ? "Not step " + std::to_string(n) + ": it is right. The mistake comes later."
                : "Not step " + std::to_string(n) + ": the first mistake comes before it.";
        ImGui::PushFont(s.fonts.bold);
        coloured(right ? kOkText : kErrorText, headline);
        ImGui::PopFont();
        s.note_widget(right ? "bug verdict right" : "bug verdict wrong");
        if (b.over) {
            // The library's text: its verdict line (said above), then the explanation and
            // the right step with its pseudocode line.
            const std::string& text = b.grade->text;
            const std::size_t body = text.find('\n');
            text_wrapped(body == std::string::npos ? text : text.substr(body + 1));
            if (k != b.bug->step) {
                const std::string go = "Go to step " + std::to_string(b.bug->step);
                if (ImGui::Button(go.c_str())) s.jump(b.bug->step);
                s.note_widget("Go to bug");
            }
            small_hint(s, "New bug for another mistake, or Watch to leave.");
        }
    }
}

// --- [compare] -------------------------------------------------------------------------------

void draw_compare_summary(Session& s) {
    const CompareState& c = s.study.compare;
    if (!c.result) return;
    const study::Comparison& r = *c.result;
    heading(s, "Compare: A " + c.side_a.label + "  ·  B " + c.side_b.label);
    if (r.agree)
        coloured(kOkText, "The results agree.");
    else
        coloured(kErrorText, "The results differ in " + std::to_string(r.difference_count) +
                                 (r.difference_count == 1 ? " place." : " places."));
    s.note_widget("compare verdict");
    if (r.first_step) {
        text_wrapped("first difference: step " + std::to_string(*r.first_step) + " (" +
                     r.first_step_note + ")");
        s.note_widget("first difference");
        const std::string go = "Go to step " + std::to_string(*r.first_step);
        if (ImGui::Button(go.c_str())) s.jump(*r.first_step);
        s.note_widget("Go to first difference");
        tooltip("Both runs to the first step where they part");
    } else if (c.side_a.algorithm == c.side_b.algorithm) {
        text_wrapped("Every step agrees (" + std::to_string(r.steps_a) + " steps).");
    }
    ImGui::TextDisabled("steps: A %zu, B %zu", r.steps_a, r.steps_b);
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    if (!r.differences.empty() && ImGui::BeginTable("differences", 3, flags)) {
        ImGui::TableSetupColumn("where");
        ImGui::TableSetupColumn("A");
        ImGui::TableSetupColumn("B");
        ImGui::TableHeadersRow();
        constexpr std::size_t kShown = 5;
        for (std::size_t i = 0; i < r.differences.size() && i < kShown; ++i) {
            const study::Difference& d = r.differences[i];
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::PushFont(s.fonts.mono);
            ImGui::TextUnformatted(d.where.c_str());
            ImGui::PopFont();
            ImGui::TableNextColumn();
            text_wrapped(study::show(d.a));
            ImGui::TableNextColumn();
            text_wrapped(study::show(d.b));
        }
        ImGui::EndTable();
        if (r.difference_count > kShown)
            ImGui::TextDisabled("... and %zu more", r.difference_count - kShown);
    }
    // The costs side by side: one row per cost either side reports.
    const json& costs = r.costs;
    const json* ca = costs.contains(c.side_a.label) ? &costs[c.side_a.label] : nullptr;
    const json* cb = costs.contains(c.side_b.label) ? &costs[c.side_b.label] : nullptr;
    std::vector<std::string> names;
    for (const json* side : {ca, cb})
        if (side && side->is_object())
            for (auto it = side->begin(); it != side->end(); ++it)
                if (std::find(names.begin(), names.end(), it.key()) == names.end())
                    names.push_back(it.key());
    if (!names.empty() && ImGui::BeginTable("costs", 3, flags)) {
        ImGui::TableSetupColumn("cost");
        ImGui::TableSetupColumn(("A " + c.side_a.label).c_str());
        ImGui::TableSetupColumn(("B " + c.side_b.label).c_str());
        ImGui::TableHeadersRow();
        for (const std::string& n : names) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(n.c_str());
            for (const json* side : {ca, cb}) {
                ImGui::TableNextColumn();
                const bool has = side && side->contains(n);
                ImGui::TextUnformatted(has ? study::show((*side)[n]).c_str() : "—");
            }
        }
        ImGui::EndTable();
        s.note_widget("compare costs");
    }
}

}  // namespace

bool draw_mode_now(Session& s) {
    if (s.comparing()) {
        draw_compare_summary(s);
        return true;
    }
    switch (s.study.mode) {
        case Mode::Watch:
            return false;
        case Mode::Predict:
            draw_predict(s);
            return true;
        case Mode::Bug:
            draw_bug(s);
            return true;
    }
    return false;
}

namespace {

// One side of Compare: its canvas, and under it its label, pseudocode line and narration.
void draw_side(Session& side, Session& owner, const char* name, const std::string& label,
               ImVec2 size, bool interactive) {
    ImGui::BeginChild(name, size, false,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const float strip = std::round(line * 4.3f);
    ImGui::BeginChild("canvas", ImVec2(size.x, std::max(size.y - strip, 20.0f)), false,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    draw_canvas(side, interactive);
    ImGui::EndChild();
    owner.note_widget(std::string("compare canvas ") + name);
    ImGui::Indent(8);
    const StepInfo* info = side.last_step();
    const int at = info ? info->line : 0;
    const std::vector<std::string>& code = side.algorithm->spec->pseudocode;
    std::string code_line = at > 0 && at <= static_cast<int>(code.size()) ? code[at - 1] : "";
    code_line.erase(0, std::min(code_line.find_first_not_of(' '), code_line.size()));
    // The first step where the two runs part is marked on both sides.
    const study::Comparison* result =
        owner.study.compare.result ? &*owner.study.compare.result : nullptr;
    const bool parting = result && result->first_step && *result->first_step == owner.index();
    ImGui::PushFont(owner.fonts.bold);
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(parting ? kErrorText : kCaptionText));
    // What matters first, for a narrow half: the step and the mark; the label may be cut.
    ImGui::TextUnformatted((std::string(name) + "  ·  step " + std::to_string(side.index()) +
                            (parting ? "  ·  first difference" : "") + "  ·  " + label)
                               .c_str());
    ImGui::PopStyleColor();
    ImGui::PopFont();
    ImGui::PushFont(owner.fonts.mono);
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kMathText));
    ImGui::TextUnformatted(at > 0 ? ("line " + std::to_string(at) + ": " + code_line).c_str()
                                  : "—");
    ImGui::PopStyleColor();
    ImGui::PopFont();
    const std::string text = info ? info->narration : "Step 0: nothing has happened yet.";
    ImGui::PushFont(owner.fonts.small);
    ImGui::TextUnformatted(
        wrap_at_spaces(ImGui::GetFont(), ImGui::GetFontSize(), text, size.x - 16).c_str());
    ImGui::PopFont();
    ImGui::Unindent(8);
    ImGui::EndChild();
}

}  // namespace

void draw_compare_canvases(Session& s, bool interactive) {
    CompareState& c = s.study.compare;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float half = std::floor((avail.x - 2) / 2);
    draw_side(s, s, "A", c.side_a.label, ImVec2(half, avail.y), interactive);
    ImGui::SameLine(0, 2);
    draw_side(*c.b, s, "B", c.side_b.label, ImVec2(avail.x - half - 2, avail.y), false);
    ImGui::GetWindowDrawList()->AddLine(ImVec2(origin.x + half + 1, origin.y),
                                        ImVec2(origin.x + half + 1, origin.y + avail.y),
                                        im_colour(kAxis), 2.0f);
}

void draw_compare_editor(Session& s) {
    CompareState& c = s.study.compare;
    if (!c.open || !c.editing) return;
    // Over side B's canvas, its bottom-right corner: side A stays in sight.
    const Box& canvas = s.canvas_rect;
    ImGui::SetNextWindowPos(
        ImVec2(static_cast<float>(canvas.max.x) - 8, static_cast<float>(canvas.max.y) - 8),
        ImGuiCond_Appearing, ImVec2(1, 1));
    ImGui::SetNextWindowSize(
        ImVec2(std::min(420.0f, static_cast<float>(canvas.max.x - canvas.min.x) / 2),
               std::min(420.0f, static_cast<float>(canvas.max.y - canvas.min.y) - 16)),
        ImGuiCond_Appearing);
    if (ImGui::Begin("Side B's input", &c.editing,
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
        small_hint(s, "Side B runs the same algorithm on this input. Edit it and Apply.");
        ImGui::PushFont(s.fonts.mono);
        ImGui::InputTextMultiline("##side b", &c.edited_text,
                                  ImVec2(-FLT_MIN, ImGui::GetContentRegionAvail().y -
                                                       ImGui::GetFrameHeightWithSpacing() * 2));
        ImGui::PopFont();
        s.note_widget("side B input");
        if (ImGui::Button("Apply")) s.open_compare(c.choice);
        s.note_widget("Apply B");
        ImGui::SameLine();
        if (ImGui::Button("Reset to A's input")) {
            c.edited_text = s.input.dump(2);
            s.open_compare(c.choice);
        }
        if (!c.error.empty()) coloured(kErrorText, c.error);
    }
    ImGui::End();
}

}  // namespace cg::viewer
