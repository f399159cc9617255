#include "viewer/text_wrap.hpp"

#include <imgui.h>

#include <cfloat>
#include <string_view>

namespace cg::viewer {

namespace {

constexpr std::string_view kEmSpace = "\u2003";  // a formula's \quad: a break between parts

// The next separator at or after `from`: a space, a newline or an em space (its length, or
// 0 at the end of the text).
std::size_t next_separator(const std::string& text, std::size_t from, std::size_t& length) {
    const std::size_t plain = text.find_first_of(" \n", from);
    const std::size_t em = text.find(kEmSpace, from);
    if (em < plain) {
        length = kEmSpace.size();
        return em;
    }
    length = plain == std::string::npos ? 0 : 1;
    return plain == std::string::npos ? text.size() : plain;
}

}  // namespace

std::string wrap_at_spaces(const ImFont* font, float size, const std::string& text, float width) {
    auto measure = [&](const std::string& s) {
        return font->CalcTextSizeA(size, FLT_MAX, 0, s.c_str()).x;
    };
    std::string out, line, gap;  // gap: the separator before the next word on this line
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t length = 0;
        const std::size_t end = next_separator(text, start, length);
        const std::string word = text.substr(start, end - start);
        if (!line.empty() && measure(line + gap + word) > width) {
            out += line + "\n";
            line = word;
        } else {
            line += (line.empty() ? "" : gap) + word;
        }
        gap = length ? text.substr(end, length) : "";
        if (gap == "\n") {  // keep the text's own line breaks
            out += line + "\n";
            line.clear();
        }
        if (length == 0) break;
        start = end + length;
    }
    return out + line;
}

std::string wrap_formula(const ImFont* font, float size, const std::string& text, float width) {
    auto measure = [&](const std::string& s) {
        return font->CalcTextSizeA(size, FLT_MAX, 0, s.c_str()).x;
    };
    std::string out, line;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(kEmSpace, start);
        if (end == std::string::npos) end = text.size();
        const std::string part = text.substr(start, end - start);
        const std::string joined = line.empty() ? part : line + std::string(kEmSpace) + part;
        if (line.empty() || measure(joined) <= width) {
            line = joined;
        } else {
            out += wrap_at_spaces(font, size, line, width) + "\n";
            line = part;
        }
        start = end + kEmSpace.size();
    }
    return out + wrap_at_spaces(font, size, line, width);
}

void text_wrapped(const std::string& text) {
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::TextUnformatted(
        wrap_at_spaces(ImGui::GetFont(), ImGui::GetFontSize(), text, width).c_str());
}

}  // namespace cg::viewer
