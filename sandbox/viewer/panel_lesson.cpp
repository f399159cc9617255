// The Lessons tab: the browser (every lesson by topic in course order, with how much the exam
// weighs it) and the open lesson (title, presets, text). Sections: [badge] [lesson text]
// [browser] [lesson].
#include <imgui.h>

#include <cfloat>
#include <string>

#include "viewer/im_colour.hpp"
#include "viewer/math_text.hpp"
#include "viewer/palette.hpp"
#include "viewer/panels.hpp"
#include "viewer/text_wrap.hpp"

namespace cg::viewer {

namespace {

// --- [badge] ---------------------------------------------------------------------------------

std::string badge_text(const std::string& weight) {
    return "exam: " + weight;
}

ImVec2 badge_size(const Fonts& f, const std::string& weight) {
    const ImVec2 text =
        f.small->CalcTextSizeA(f.small->FontSize, FLT_MAX, 0, badge_text(weight).c_str());
    return ImVec2(text.x + 12, text.y + 4);
}

// A pill in the weight's colour, white text on it, its top-left corner at `at`.
void draw_badge(const Fonts& f, ImVec2 at, const std::string& weight) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 size = badge_size(f, weight);
    dl->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), im_colour(exam_weight_rgba(weight)),
                      size.y / 2);
    dl->AddText(f.small, f.small->FontSize, ImVec2(at.x + 6, at.y + 2), IM_COL32_WHITE,
                badge_text(weight).c_str());
}

void weight_tooltip(const Lesson& l) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 26);
    ImGui::TextColored(im_vec4(darker(exam_weight_rgba(l.exam_weight), 0.85f)), "Exam weight: %s",
                       l.exam_weight.c_str());
    if (!l.exam_note.empty()) ImGui::TextUnformatted(text_to_unicode(l.exam_note).c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// --- [lesson text] ---------------------------------------------------------------------------

// A paragraph's "[step N]" links: the text shows "(step N)", and a button under the paragraph
// opens that step of the section's preset.
void draw_step_buttons(Session& s, const Lesson& l, const LessonSection& section,
                       const std::vector<StepLink>& links) {
    const LessonPreset* preset = linked_preset(l, section);
    if (links.empty() || !preset) return;
    ImGui::Indent();
    for (std::size_t i = 0; i < links.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        const std::string label = "Show step " + std::to_string(links[i].step);
        ImGui::PushID(static_cast<int>(links[i].at));
        if (ImGui::SmallButton(label.c_str())) {
            if (s.loaded_preset() != preset) s.load_preset(*preset);
            s.jump(links[i].step);
        }
        s.note_widget("step link:" + section.title + ":" + std::to_string(links[i].step));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Step %zu of \"%s\"", links[i].step, preset->name.c_str());
        ImGui::PopID();
    }
    ImGui::Unindent();
}

// Paragraphs, "- " bullets, and $math$ as Unicode; a blank line is a little space; "[step N]"
// a button to that step.
void draw_lesson_text(Session& s, const Lesson& l, const LessonSection& section) {
    const std::string& text = section.text;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string raw = text.substr(start, end - start);
        const std::vector<StepLink> links = step_links(raw);
        for (auto it = links.rbegin(); it != links.rend(); ++it)
            raw.replace(it->at, it->size, "(step " + std::to_string(it->step) + ")");
        const std::string line = text_to_unicode(raw);
        ImGui::PushID(static_cast<int>(start));
        if (line.find_first_not_of(' ') == std::string::npos) {
            ImGui::Spacing();
        } else if (line.rfind("- ", 0) == 0 || line.rfind("* ", 0) == 0) {
            ImGui::Bullet();  // leaves the cursor beside the dot, so the lines align after it
            text_wrapped(line.substr(2));
        } else {
            text_wrapped(line);
        }
        draw_step_buttons(s, l, section, links);
        ImGui::PopID();
        start = end + 1;
    }
}

// --- [browser] -------------------------------------------------------------------------------

// One lesson: its title (wrapped) and badge; clicking opens it.
void browser_entry(Session& s, const Lesson& l) {
    const ImVec2 badge = badge_size(s.fonts, l.exam_weight);
    const float width = ImGui::GetContentRegionAvail().x;
    const std::string title =
        wrap_at_spaces(ImGui::GetFont(), ImGui::GetFontSize(), l.title, width - badge.x - 12);
    const ImVec2 size = ImGui::CalcTextSize(title.c_str());
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::PushID(l.file.c_str());
    if (ImGui::Selectable("##lesson", s.lesson() == &l, 0, ImVec2(0, size.y))) s.open_lesson(l);
    s.note_widget("lesson:" + l.id);
    weight_tooltip(l);
    ImGui::PopID();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddText(at, ImGui::GetColorU32(ImGuiCol_Text), title.c_str());
    draw_badge(s.fonts, ImVec2(at.x + width - badge.x, at.y + 1), l.exam_weight);
}

void draw_browser(Session& s) {
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kHintText));
    text_wrapped(
        "The course in order. Pick a lesson to read it beside the canvas and step "
        "through its examples.");
    ImGui::PopStyleColor();
    // Broken files are listed, not fatal: the other lessons still work.
    if (!s.lessons.errors.empty()) {
        ImGui::PushFont(s.fonts.small);
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kWarningText));
        for (const std::string& e : s.lessons.errors) text_wrapped("⚠ " + e);
        ImGui::PopStyleColor();
        ImGui::PopFont();
    }
    if (s.lessons.lessons.empty()) {
        ImGui::Spacing();
        text_wrapped("No lessons found in " + default_lessons_dir() + ".");
        return;
    }
    const std::string* topic = nullptr;
    for (const Lesson& l : s.lessons.lessons) {
        if (!topic || *topic != l.topic) {
            topic = &l.topic;
            ImGui::Spacing();
            ImGui::PushFont(s.fonts.bold);
            ImGui::TextColored(im_vec4(kSectionTitle), "%s", topic->c_str());
            ImGui::PopFont();
        }
        browser_entry(s, l);
    }
}

// --- [lesson] --------------------------------------------------------------------------------

void draw_preset_picker(Session& s, const Lesson& l) {
    const LessonPreset* current = s.loaded_preset();
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Example");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-FLT_MIN);
    const char* preview = current         ? current->name.c_str()
                          : s.exam.active ? "(the exam problem)"
                                          : "(your own input)";
    const bool open = ImGui::BeginCombo("##preset", preview, ImGuiComboFlags_HeightLarge);
    if (!open) s.note_widget("presets");  // (open, the last item is in its list)
    if (open) {
        for (const LessonPreset& p : l.presets) {
            const bool selected = &p == current;
            // Choosing the current one again restarts it, which is what a student expects.
            if (ImGui::Selectable(p.name.c_str(), selected)) s.load_preset(p);
            s.note_widget("preset:" + p.name);
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Load one of the lesson's inputs (the run restarts at step 0)");
}

void draw_lesson(Session& s, const Lesson& l) {
    if (ImGui::SmallButton("← All lessons")) s.browsing = true;
    s.note_widget("All lessons");
    const ImVec2 badge = badge_size(s.fonts, l.exam_weight);
    ImGui::SameLine(ImGui::GetContentRegionMax().x - badge.x);
    draw_badge(s.fonts, ImGui::GetCursorScreenPos(), l.exam_weight);
    ImGui::Dummy(badge);
    weight_tooltip(l);

    ImGui::PushFont(s.fonts.title);
    text_wrapped(l.title);
    ImGui::PopFont();
    ImGui::PushFont(s.fonts.small);
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kTickLabel));
    text_wrapped(l.topic + "  ·  " + s.algorithm->spec->title);
    if (!l.exam_note.empty()) text_wrapped("Exam: " + text_to_unicode(l.exam_note));
    ImGui::PopStyleColor();
    ImGui::PopFont();
    draw_preset_picker(s, l);
    ImGui::Separator();

    ImGui::BeginChild("lesson text");
    for (const LessonSection& section : l.sections) {
        ImGui::PushFont(s.fonts.bold);
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(kSectionTitle));
        text_wrapped(section.title);
        ImGui::PopStyleColor();
        ImGui::PopFont();
        ImGui::PushID(&section);
        draw_lesson_text(s, l, section);
        ImGui::PopID();
        ImGui::Spacing();
        ImGui::Spacing();
    }
    ImGui::EndChild();
}

}  // namespace

void draw_lessons_panel(Session& s) {
    const Lesson* open = s.lesson();
    if (open && !s.browsing)
        draw_lesson(s, *open);
    else
        draw_browser(s);
}

}  // namespace cg::viewer
