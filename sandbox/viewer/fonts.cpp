#include "viewer/fonts.hpp"

#include <imgui.h>

#include <filesystem>

namespace cg::viewer {

namespace {

constexpr const char* kSansPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kMonoPath = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr const char* kBoldPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

// The characters the course's text uses. Whole blocks where text is built from them (Latin-1,
// the combining marks that put a hat on d̂, Greek, punctuation and spaces, sub- and superscript
// digits); elsewhere only the characters that appear in algorithms/, sandbox/ and lessons/
// (written out or as \u escapes) — each glyph is rasterised
// into the atlas at start-up, six times (one per font), and the whole blocks cost 2,119 glyphs a
// font and a 2048 × 4096 atlas. A test (tests/gui/test_fonts.cpp) reads those folders and names
// any character missing here: add it to this table. The atlas keeps a pointer to the array
// until it is built, so it must outlive the call: a constant with static storage does.
constexpr ImWchar kGlyphRanges[] = {
    0x0020, 0x00FF,  // Basic Latin, Latin-1 (² ³ · ×)
    0x0300, 0x036F,  // Combining Diacritical Marks (the hat of a unit vector: d̂, n̂, q̂)
    0x0370, 0x03FF,  // Greek (θ φ γ)
    0x2000, 0x206F,  // General Punctuation (– — … • and the thin and em spaces)
    0x2070, 0x209F,  // Superscripts and Subscripts (⁰ ⁱ ₀ ₁ ⁿ)
    0x0101, 0x0101, 0x02B0, 0x02B0, 0x02B2, 0x02B3,  // āʰʲʳ
    0x02B7, 0x02B8, 0x02C6, 0x02C6, 0x02E1, 0x02E3,  // ʷʸˆˡˢˣ
    0x1D40, 0x1D40, 0x1D43, 0x1D43, 0x1D47, 0x1D49,  // ᵀᵃᵇᵈᵉ
    0x1D4D, 0x1D4D, 0x1D4F, 0x1D50, 0x1D52, 0x1D52,  // ᵍᵏᵐᵒ
    0x1D56, 0x1D58, 0x1D5B, 0x1D5B, 0x1D62, 0x1D65,  // ᵖᵗᵘᵛᵢᵣᵤᵥ
    0x1D9C, 0x1D9C, 0x1DA0, 0x1DA0, 0x1DBB, 0x1DBB,  // ᶜᶠᶻ
    0x2102, 0x2102, 0x210F, 0x210F, 0x2113, 0x2113,  // ℂℏℓ
    0x2115, 0x2115, 0x211A, 0x211A, 0x211D, 0x211D,  // ℕℚℝ
    0x2124, 0x2124, 0x215B, 0x215B, 0x2190, 0x2194,  // ℤ⅛←↑→↓↔
    0x21A6, 0x21A6, 0x21D0, 0x21D0, 0x21D2, 0x21D2,  // ↦⇐⇒
    0x21D4, 0x21D4, 0x2200, 0x2200, 0x2202, 0x2205,  // ⇔∀∂∃∄∅
    0x2207, 0x2209, 0x220B, 0x220B, 0x220F, 0x220F,  // ∇∈∉∋∏
    0x2211, 0x2213, 0x2216, 0x2218, 0x221A, 0x221B,  // ∑−∓∖∗∘√∛
    0x221D, 0x221E, 0x2220, 0x2220, 0x2225, 0x2225,  // ∝∞∠∥
    0x2227, 0x222E, 0x223C, 0x223C, 0x2243, 0x2243,  // ∧∨∩∪∫∬∭∮∼≃
    0x2248, 0x2248, 0x2260, 0x2261, 0x2264, 0x2265,  // ≈≠≡≤≥
    0x226A, 0x226B, 0x2272, 0x2273, 0x2282, 0x2283,  // ≪≫≲≳⊂⊃
    0x2286, 0x2287, 0x2295, 0x2295, 0x2297, 0x2297,  // ⊆⊇⊕⊗
    0x22A4, 0x22A5, 0x22C5, 0x22C6, 0x22EE, 0x22EF,  // ⊤⊥⋅⋆⋮⋯
    0x22F1, 0x22F1, 0x2308, 0x230B, 0x25A0, 0x25A1,  // ⋱⌈⌉⌊⌋■□
    0x25B3, 0x25B3, 0x25B6, 0x25B7, 0x25C0, 0x25C0,  // △▶▷◀
    0x26A0, 0x26A0, 0x2713, 0x2713, 0x2717, 0x2717,  // ⚠✓✗
    0x27E8, 0x27E9, 0x27FA, 0x27FA,  // ⟨⟩⟺
    0x2C7C, 0x2C7C,  // ⱼ
    0,
};

ImFont* add_font(const char* path, float size) {
    ImFontConfig config;
    config.OversampleH = 2;
    config.OversampleV = 2;
    return ImGui::GetIO().Fonts->AddFontFromFileTTF(path, size, &config, kGlyphRanges);
}

// A combining mark (the hat of d̂) belongs over the letter before it. ImGui draws text glyph by
// glyph, advancing by each glyph's width, and the fonts give the marks a width of their own (the
// monospaced face a whole cell), so "d̂" came out as "d ˆ". Once the atlas is built, each mark
// gets no width and moves back over the middle of a typical letter ('x'), so it sits on the
// letter it follows.
void overlay_combining_marks(ImFont* font) {
    const ImFontGlyph* x = font->FindGlyphNoFallback('x');
    if (!x) return;
    for (ImWchar c = 0x0300; c <= 0x036F; ++c) {
        auto* g = const_cast<ImFontGlyph*>(font->FindGlyphNoFallback(c));
        if (!g) continue;
        const float shift = -0.5f * x->AdvanceX - 0.5f * (g->X0 + g->X1);
        g->X0 += shift;
        g->X1 += shift;
        g->AdvanceX = 0;
        if (c < font->IndexAdvanceX.Size) font->IndexAdvanceX[c] = 0;
    }
}

void apply_style() {
    ImGui::StyleColorsLight();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0;
    style.FrameRounding = 3;
    style.GrabRounding = 3;
    style.WindowBorderSize = 1;
    // Every field, check box and radio button outlined: unselected radio buttons were nearly
    // invisible, light grey on the light panels.
    style.FrameBorderSize = 1;
    style.AntiAliasedLinesUseTex = false;
    style.Colors[ImGuiCol_Border] = ImVec4(0.62f, 0.64f, 0.68f, 0.75f);
    style.FramePadding = ImVec2(6, 4);
    style.ItemSpacing = ImVec2(8, 6);
    style.Colors[ImGuiCol_WindowBg] = ImVec4(0.965f, 0.965f, 0.97f, 1.0f);
    style.Colors[ImGuiCol_TitleBg] = ImVec4(0.89f, 0.90f, 0.92f, 1.0f);
    style.Colors[ImGuiCol_TitleBgActive] = style.Colors[ImGuiCol_TitleBg];
}

}  // namespace

bool in_glyph_ranges(char32_t c) {
    for (const ImWchar* r = kGlyphRanges; r[0]; r += 2)
        if (c >= r[0] && c <= r[1]) return true;
    return false;
}

Fonts setup_fonts_and_style() {
    apply_style();
    ImGuiIO& io = ImGui::GetIO();
    Fonts fonts;
    std::error_code error;
    if (std::filesystem::exists(kSansPath, error) && std::filesystem::exists(kMonoPath, error)) {
        fonts.ui = add_font(kSansPath, 16.0f);  // the first font added is ImGui's default
        fonts.mono = add_font(kMonoPath, 14.0f);
        fonts.large = add_font(kSansPath, 19.0f);
        fonts.small = add_font(kSansPath, 13.0f);
        // Headings; without the bold face they are set in the regular one.
        fonts.bold =
            std::filesystem::exists(kBoldPath, error) ? add_font(kBoldPath, 16.0f) : fonts.ui;
        fonts.title =
            std::filesystem::exists(kBoldPath, error) ? add_font(kBoldPath, 19.0f) : fonts.large;
    }
    if (!fonts.ui || !fonts.mono || !fonts.large || !fonts.small || !fonts.bold || !fonts.title) {
        io.Fonts->Clear();
        fonts.ui = fonts.mono = fonts.large = fonts.small = fonts.bold = fonts.title =
            io.Fonts->AddFontDefault();
    }
    io.Fonts->Build();
    for (ImFont* font : io.Fonts->Fonts) overlay_combining_marks(font);
    return fonts;
}

}  // namespace cg::viewer
