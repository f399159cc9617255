#include "viewer/fonts.hpp"

#include <imgui.h>

#include <filesystem>

namespace cg::viewer {

namespace {

constexpr const char* kSansPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kMonoPath = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr const char* kBoldPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

// Unicode blocks the course's text uses. The atlas keeps a pointer to this array until it is
// built, so it must outlive the call: a constant with static storage does.
constexpr ImWchar kGlyphRanges[] = {
    0x0020, 0x024F,  // Basic Latin, Latin-1 (² ³ ·), Latin Extended
    0x02B0, 0x02FF,  // Spacing Modifier Letters (superscripts ʰ ʲ ʳ ˢ ˣ)
    0x0300, 0x036F,  // Combining Diacritical Marks (the hat of a unit vector: d̂, n̂, q̂)
    0x0370, 0x03FF,  // Greek (θ φ γ)
    0x1D00, 0x1DBF,  // Phonetic Extensions (superscripts ᵃ ᵏ ᵀ, subscript ᵢ)
    0x2000, 0x206F,  // General Punctuation (– — … • thin and em spaces)
    0x2070, 0x209F,  // Superscripts and Subscripts (₀ ₁ ⁿ)
    0x2100, 0x214F,  // Letterlike Symbols (ℝ ℓ)
    0x2190, 0x21FF,  // Arrows (← →)
    0x2200, 0x22FF,  // Mathematical Operators (− ≤ ≥ ∞)
    0x2300, 0x23FF,  // Miscellaneous Technical (⌈ ⌉)
    0x25A0, 0x25FF,  // Geometric Shapes (▷ ■)
    0x2600, 0x26FF,  // Miscellaneous Symbols (⚠)
    0x2700, 0x27BF,  // Dingbats (✓ ✗)
    0x27C0, 0x27EF,  // Miscellaneous Mathematical Symbols-A (⟨ ⟩)
    0x2C60, 0x2C7F,  // Latin Extended-C (subscript ⱼ)
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
