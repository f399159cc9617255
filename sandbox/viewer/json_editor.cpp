#include "viewer/json_editor.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace cg::viewer {

namespace {

constexpr std::size_t kInlineNumbers = 4;  // [x, y], [x, y, z], [r, g, b, a] fit on one row
constexpr const char* kNumberFormat = "%.6g";

// Each widget is told to `note` by its field's JSON pointer ("/window/xmin", "/p0").
using Note = std::function<void(const std::string&)>;

bool edit_value(const char* label, json& v, const std::string& path, const Note& note);

// Keeps integers integers, so a field the algorithm reads as a count still reads.
void assign_number(json& field, double d) {
    if (field.is_number_integer() && d == std::floor(d) && std::abs(d) < 1e15)
        field = static_cast<long long>(d);
    else
        field = d;
}

bool is_short_number_array(const json& v) {
    return v.is_array() && !v.empty() && v.size() <= kInlineNumbers &&
           std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); });
}

bool edit_inline_numbers(const char* label, json& v, const std::string& path, const Note& note) {
    std::vector<double> values;
    for (const json& e : v) values.push_back(e.get<double>());
    const bool edited = ImGui::InputScalarN(label, ImGuiDataType_Double, values.data(),
                                            static_cast<int>(values.size()), nullptr, nullptr,
                                            kNumberFormat);
    note(path);
    if (!edited) return false;
    for (std::size_t i = 0; i < values.size(); ++i) assign_number(v[i], values[i]);
    return true;
}

bool edit_object(json& v, const std::string& path, const Note& note) {
    bool changed = false;
    for (auto& item : v.items()) {
        ImGui::PushID(item.key().c_str());
        changed |= edit_value(item.key().c_str(), item.value(), path + "/" + item.key(), note);
        ImGui::PopID();
    }
    return changed;
}

// A list whose length the student may change: + repeats the last element, − drops it.
bool edit_list(const char* label, json& v, const std::string& path, const Note& note) {
    const std::string header = std::string(label) + " [" + std::to_string(v.size()) + "]";
    const bool open =
        ImGui::TreeNodeEx("list", ImGuiTreeNodeFlags_DefaultOpen, "%s", header.c_str());
    bool changed = false;
    ImGui::SameLine();
    if (ImGui::SmallButton("+") && !v.empty()) {
        v.push_back(v.back());
        changed = true;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("−") && !v.empty()) {
        v.erase(v.size() - 1);
        changed = true;
    }
    if (open) {
        for (std::size_t i = 0; i < v.size() && !changed; ++i) {
            ImGui::PushID(static_cast<int>(i));
            changed |= edit_value(("[" + std::to_string(i) + "]").c_str(), v[i],
                                  path + "/" + std::to_string(i), note);
            ImGui::PopID();
        }
        ImGui::TreePop();
    }
    return changed;
}

bool edit_value(const char* label, json& v, const std::string& path, const Note& note) {
    switch (v.type()) {
        case json::value_t::object: {
            bool changed = false;
            if (ImGui::TreeNodeEx(label, ImGuiTreeNodeFlags_DefaultOpen)) {
                changed = edit_object(v, path, note);
                ImGui::TreePop();
            }
            return changed;
        }
        case json::value_t::array:
            return is_short_number_array(v) ? edit_inline_numbers(label, v, path, note)
                                            : edit_list(label, v, path, note);
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
        case json::value_t::number_float: {
            double d = v.get<double>();
            const bool edited = ImGui::InputDouble(label, &d, 0, 0, kNumberFormat);
            note(path);
            if (!edited) return false;
            assign_number(v, d);
            return true;
        }
        case json::value_t::boolean: {
            bool b = v.get<bool>();
            const bool edited = ImGui::Checkbox(label, &b);
            note(path);
            if (!edited) return false;
            v = b;
            return true;
        }
        case json::value_t::string: {
            std::string text = v.get<std::string>();
            const bool edited = ImGui::InputText(label, &text);
            note(path);
            if (!edited) return false;
            v = text;
            return true;
        }
        default:
            ImGui::TextDisabled("%s: %s", label, v.dump().c_str());
            return false;
    }
}

}  // namespace

bool edit_json_fields(json& object, const std::function<void(const std::string&)>& note) {
    // Leave room on the right for the field names, which ImGui puts after the widget.
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 5.0f);
    const Note each = note ? note : [](const std::string&) {};
    const bool changed =
        object.is_object() ? edit_object(object, "", each) : edit_value("input", object, "", each);
    ImGui::PopItemWidth();
    return changed;
}

}  // namespace cg::viewer
