#include "viewer/text_wrap.hpp"

#include <imgui.h>

#include <cfloat>

namespace cg::viewer {

std::string wrap_at_spaces(const ImFont* font, float size, const std::string& text, float width) {
    auto measure = [&](const std::string& s) {
        return font->CalcTextSizeA(size, FLT_MAX, 0, s.c_str()).x;
    };
    std::string out, line;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find_first_of(" \n", start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        if (!line.empty() && measure(line + " " + word) > width) {
            out += line + "\n";
            line = word;
        } else {
            line += (line.empty() ? "" : " ") + word;
        }
        if (end < text.size() && text[end] == '\n') {  // keep the text's own line breaks
            out += line + "\n";
            line.clear();
        }
        start = end + 1;
    }
    return out + line;
}

void text_wrapped(const std::string& text) {
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::TextUnformatted(
        wrap_at_spaces(ImGui::GetFont(), ImGui::GetFontSize(), text, width).c_str());
}

}  // namespace cg::viewer
