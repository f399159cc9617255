// The viewer's fonts: the glyphs the course's text needs, placed where they belong.
#include <catch2/catch.hpp>

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "viewer/fonts.hpp"

TEST_CASE("fonts: a combining mark sits on the letter before it and takes no width",
          "[gui][math]") {
    // d̂ (d, U+0302) was drawn as "d?" and then as "d ˆ": the hat needs a glyph and no advance.
    ImGuiContext* context = ImGui::CreateContext();
    const cg::viewer::Fonts fonts = cg::viewer::setup_fonts_and_style();
    for (ImFont* font : {fonts.ui, fonts.mono, fonts.bold}) {
        const ImFontGlyph* hat = font->FindGlyphNoFallback(0x0302);
        REQUIRE(hat != nullptr);
        CHECK(hat->AdvanceX == 0);
        const ImFontGlyph* d = font->FindGlyphNoFallback('d');
        REQUIRE(d != nullptr);
        // Drawn after a 'd' (pen at d's advance), the hat lies over the d, not beyond it.
        CHECK(hat->X1 <= 0.5f);
        CHECK(d->AdvanceX + hat->X0 >= 0);
        const char* text = "d\xcc\x82";  // d̂
        CHECK(font->CalcTextSizeA(font->FontSize, 1e9f, 0, text).x ==
              font->CalcTextSizeA(font->FontSize, 1e9f, 0, "d").x);
    }
    ImGui::DestroyContext(context);
}

namespace {

// Every character past ASCII in the text the viewer shows: the algorithms' narrations and
// pictures, the viewer's own labels, the lessons. Each with the first file it appears in.
std::map<char32_t, std::string> characters_used() {
    std::map<char32_t, std::string> used;
    for (const char* folder : {"algorithms", "sandbox", "lessons"})
        for (const auto& entry :
             std::filesystem::recursive_directory_iterator(std::string(CG_SOURCE_DIR) + "/" + folder)) {
            const std::string ext = entry.path().extension().string();
            if (ext != ".cpp" && ext != ".hpp" && ext != ".json") continue;
            std::ifstream in(entry.path(), std::ios::binary);
            const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            // Written as an escape in a C++ string, "\u2009".
            for (std::size_t i = text.find("\\u"); i != std::string::npos; i = text.find("\\u", i + 1))
                if (i + 6 <= text.size() && std::all_of(text.begin() + i + 2, text.begin() + i + 6,
                                                        [](char h) { return std::isxdigit(static_cast<unsigned char>(h)); }))
                    used.emplace(static_cast<char32_t>(std::stoul(text.substr(i + 2, 4), nullptr, 16)),
                                 entry.path().lexically_relative(CG_SOURCE_DIR).string());
            for (std::size_t i = 0; i < text.size();) {
                const auto b = static_cast<unsigned char>(text[i]);
                const int n = b < 0x80 ? 1 : b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : 2;
                char32_t c = n == 1 ? b : b & (0x3F >> (n - 1));
                for (int k = 1; k < n && i + k < text.size(); ++k)
                    c = (c << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
                if (c >= 0x80) used.emplace(c, entry.path().lexically_relative(CG_SOURCE_DIR).string());
                i += n;
            }
        }
    return used;
}

std::string utf8(char32_t c) {
    std::string s;
    if (c < 0x800) {
        s += static_cast<char>(0xC0 | (c >> 6));
    } else {
        if (c < 0x10000) {
            s += static_cast<char>(0xE0 | (c >> 12));
        } else {
            s += static_cast<char>(0xF0 | (c >> 18));
            s += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        }
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    }
    return s + static_cast<char>(0x80 | (c & 0x3F));
}

}  // namespace

TEST_CASE("fonts: every character the course's text uses is in the atlas, with a glyph",
          "[gui][fonts]") {
    // The atlas holds only the characters listed in fonts.cpp's kGlyphRanges (a smaller atlas
    // builds faster at start-up); one missing from the list would show as "?".
    const auto used = characters_used();
    CHECK(used.size() > 150);
    ImGuiContext* context = ImGui::CreateContext();
    const cg::viewer::Fonts fonts = cg::viewer::setup_fonts_and_style();
    for (const auto& [c, file] : used) {
        INFO("U+" << std::hex << std::uppercase << static_cast<unsigned>(c) << " \"" << utf8(c)
                  << "\", used in " << file << ": add it to kGlyphRanges in sandbox/viewer/fonts.cpp");
        CHECK(cg::viewer::in_glyph_ranges(c));
        if (c >= 0x300 && c <= 0x36F) continue;  // combining marks: checked above
        if (c == 0xA0) continue;                 // the no-break space: a space, drawn as none
        CHECK(fonts.ui->FindGlyphNoFallback(static_cast<ImWchar>(c)) != nullptr);
    }
    CHECK_FALSE(cg::viewer::in_glyph_ranges(U'\u2600'));  // ☀: not used, not built
    ImGui::DestroyContext(context);
}
