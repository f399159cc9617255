// The left panel: which algorithm, on which input.
#include <imgui.h>

#include "viewer/im_colour.hpp"
#include "viewer/json_editor.hpp"
#include "viewer/palette.hpp"
#include "viewer/panels.hpp"
#include "viewer/text_wrap.hpp"

namespace cg::viewer {

namespace {

// The registry is in course order, so a topic heading goes wherever the topic changes.
void draw_picker(Session& s) {
    const char* preview = s.algorithm ? s.algorithm->spec->title.c_str() : "(choose an algorithm)";
    ImGui::SetNextItemWidth(-FLT_MIN);
    const bool open = ImGui::BeginCombo("##algorithm", preview, ImGuiComboFlags_HeightLarge);
    if (!open) s.note_widget("algorithms");  // (open, the last item is in its list)
    if (open) {
        const std::string* topic = nullptr;
        for (const Algorithm& a : s.registry.all()) {
            if (!topic || *topic != a.spec->topic) {
                topic = &a.spec->topic;
                ImGui::TextDisabled("%s", topic->c_str());
            }
            const bool selected = &a == s.algorithm;
            ImGui::Indent();
            if (ImGui::Selectable((a.spec->title + "##" + a.spec->id).c_str(), selected) &&
                !selected)
                s.choose(a);
            s.note_widget("algorithm:" + a.spec->id);
            if (selected) ImGui::SetItemDefaultFocus();
            ImGui::Unindent();
        }
        ImGui::EndCombo();
    }
    if (s.algorithm)
        ImGui::TextDisabled("%s  ·  %s", s.algorithm->spec->id.c_str(),
                            s.algorithm->spec->topic.c_str());
}

}  // namespace

void draw_algorithm_panel(Session& s) {
    draw_picker(s);
    ImGui::Separator();
    if (ImGui::Button("Example input") && s.algorithm) s.choose(*s.algorithm);
    s.note_widget("Example input");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Start again from the algorithm's own example");
    ImGui::SameLine();
    if (ImGui::Button("Reset view")) s.canvas.fit_pending = true;
    s.note_widget("Reset view");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Fit the canvas to the scene");
    if (const Lesson* l = s.algorithm ? s.lessons.for_algorithm(s.algorithm->spec->id) : nullptr) {
        if (ImGui::Button("Read the lesson")) s.open_lesson(*l);
        s.note_widget("Read the lesson");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", l->title.c_str());
    }

    draw_costs_panel(s);

    if (!s.input_error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kErrorText));
        text_wrapped(s.input_error);
        ImGui::PopStyleColor();
    }
    ImGui::Spacing();
    ImGui::TextDisabled("Input");
    ImGui::BeginChild("input", ImVec2(0, -ImGui::GetTextLineHeightWithSpacing() * 2.5f));
    // An exam problem's input is the problem: it is shown, not edited.
    ImGui::BeginDisabled(s.exam.active);
    json edited = s.input;
    if (edit_json_fields(edited, [&](const std::string& field) { s.note_widget("field:" + field); }))
        s.edit(std::move(edited));
    ImGui::EndDisabled();
    ImGui::EndChild();
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kHintText));
    ImGui::TextWrapped("%s", s.exam.active
                                 ? "This is the exam problem's input; leave exam practice to "
                                   "edit it."
                                 : "Edit a value, or drag a ■ handle on the canvas: the run "
                                   "restarts at the same step.");
    ImGui::PopStyleColor();
}

}  // namespace cg::viewer
