// The viewer's fonts: the glyphs the course's text needs, placed where they belong.
#include <catch2/catch.hpp>

#include <imgui.h>

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
