// A row of widget groups that wraps like words: a group that would not fit in what is left of
// the row starts the next one, so narrow windows get two short rows instead of a clipped one.
#pragma once

#include <imgui.h>

namespace cg::viewer {

// Call before each group but the first; `width` is the group's width in pixels.
inline void flow(float width, float gap = -1.0f) {
    ImGui::SameLine(0, gap);
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

inline float button_width(const char* label) {
    return ImGui::CalcTextSize(label, nullptr, true).x + ImGui::GetStyle().FramePadding.x * 2;
}

}  // namespace cg::viewer
