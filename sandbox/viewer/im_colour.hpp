// Our 0xRRGGBBAA colours in ImGui's two formats.
#pragma once

#include <imgui.h>

#include <cstdint>

namespace cg::viewer {

inline ImU32 im_colour(std::uint32_t rgba) {
    return IM_COL32((rgba >> 24) & 0xffu, (rgba >> 16) & 0xffu, (rgba >> 8) & 0xffu, rgba & 0xffu);
}

inline ImVec4 im_vec4(std::uint32_t rgba) {
    return ImGui::ColorConvertU32ToFloat4(im_colour(rgba));
}

}  // namespace cg::viewer
