// The bottom panel's last row: screenshot, checkpoints, the worked-example export, and the
// message of the last of these.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "rays/texture_json.hpp"
#include "viewer/deliver.hpp"
#include "viewer/export.hpp"
#include "viewer/flow.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/palette.hpp"
#include "viewer/panels.hpp"
#include "viewer/text_wrap.hpp"
#ifdef __EMSCRIPTEN__
#include "browser.hpp"  // sandbox/web/: uploads and links instead of files
#endif

namespace cg::viewer {

namespace {

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

bool write_file(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    f.close();
    return f && deliver(path, "application/octet-stream");
}

void save_checkpoint(Session& s) {
    if (write_file(s.checkpoint_path, checkpoint_to_json(s.checkpoint()).dump(2) + "\n"))
        s.set_status(delivered("Saved", s.checkpoint_path), false);
    else
        s.set_status("cannot write " + s.checkpoint_path, true);
}

[[maybe_unused]] void open_checkpoint(Session& s) {  // the web build uploads instead
    try {
        json j = parse_json(read_text_file(s.checkpoint_path));
        rebase_image_paths(j, folder_of(s.checkpoint_path));  // texture images beside the file
        const Checkpoint c = checkpoint_from_json(j, s.registry);
        s.set_status("Opened " + s.checkpoint_path, false);
        s.load(c);                       // after: an unknown lesson in it replaces the message
    } catch (const std::exception& e) {  // InputError names the field; JSON errors the place
        s.set_status(s.checkpoint_path + ": " + e.what(), true);
    }
}

void export_worked_example(Session& s) {
    try {
        const std::string text = export_worked(s, exports_json(s.export_path));
        if (write_file(s.export_path, text))
            s.set_status(delivered("Wrote", s.export_path), false);
        else
            s.set_status("cannot write " + s.export_path, true);
    } catch (const std::exception& e) {
        s.set_status(std::string("cannot export: ") + e.what(), true);
    }
}

}  // namespace

void draw_files_row(Session& s) {
    const float em = ImGui::GetFontSize();
    const float gap = ImGui::GetStyle().ItemSpacing.x;
    const float path = em * 9;

    if (ImGui::Button("Screenshot")) s.screenshot_requested = true;
    s.note_widget("Screenshot");
    tooltip("Save the whole window as cgsandbox-<id>-step<k>.png here");

#ifdef __EMSCRIPTEN__
    const float share = button_width("Copy link") + gap;
#else
    const float share = 0;
#endif
    flow(ImGui::CalcTextSize("Checkpoint").x + path + button_width("Save") + button_width("Open") +
             3 * gap + share,
         em * 1.5f);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Checkpoint");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(path);
    ImGui::InputText("##checkpoint", &s.checkpoint_path);
    s.note_widget("checkpoint path");
    tooltip("A checkpoint file: algorithm, input, step, view, and the open lesson or exam");
    ImGui::SameLine();
    if (ImGui::Button("Save")) save_checkpoint(s);
    s.note_widget("Save");
    ImGui::SameLine();
#ifdef __EMSCRIPTEN__
    // The browser's file picker: the page opens the chosen file (sandbox/web/main.cpp).
    if (ImGui::Button("Open")) web::upload_checkpoint();
    s.note_widget("Open");
    tooltip("Open a checkpoint file from this computer");
    ImGui::SameLine();
    if (ImGui::Button("Copy link")) {
        const std::string url = web::share_link(s.checkpoint());
        s.set_status("Link to this step (in the address bar, and copied): " + url, false);
    }
    s.note_widget("Copy link");
    tooltip("This step as a link: the checkpoint in the address after #");
#else
    if (ImGui::Button("Open")) open_checkpoint(s);
    s.note_widget("Open");
#endif

    const char* exp = "Export worked example…";
    // Wide enough for "worked-sutherland-hodgman.md", within reason.
    const float export_path = std::clamp(
        ImGui::CalcTextSize(s.export_path.c_str()).x + ImGui::GetStyle().FramePadding.x * 2 + 4,
        em * 9, em * 16);
    flow(export_path + button_width(exp) + gap, em * 1.5f);
    ImGui::SetNextItemWidth(export_path);
    ImGui::InputText("##export", &s.export_path);
    s.note_widget("export path");
    tooltip("Where to write the worked example: Markdown, or JSON if the name ends in .json");
    ImGui::SameLine();
    if (ImGui::Button(exp)) export_worked_example(s);
    s.note_widget("Export");
    tooltip(
        "The current run written out: question, input, pseudocode, every step with its "
        "formula, and the answer (as `cgsandbox worked` writes it)");

    if (s.status.empty()) return;
    const float width = ImGui::CalcTextSize(s.status.c_str()).x;
    flow(width, em);
    ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(s.status_is_error ? kErrorText : kOkText));
    text_wrapped(s.status);
    ImGui::PopStyleColor();
}

}  // namespace cg::viewer
