#include "viewer/fonts.hpp"

#include <imgui.h>

#include <filesystem>

namespace cg::viewer {

namespace {

constexpr const char* kSansPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kMonoPath = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";

// Unicode blocks the course's text uses. The atlas keeps a pointer to this array until it is
// built, so it must outlive the call: a constant with static storage does.
constexpr ImWchar kGlyphRanges[] = {
    0x0020, 0x024F,  // Basic Latin, Latin-1 (² ³ ·), Latin Extended
    0x0370, 0x03FF,  // Greek (θ φ γ)
    0x2000, 0x206F,  // General Punctuation (– — …)
    0x2070, 0x209F,  // Superscripts and Subscripts (₀ ₁ ⁿ)
    0x2190, 0x21FF,  // Arrows (← →)
    0x2200, 0x22FF,  // Mathematical Operators (− ≤ ≥ ∞)
    0x25A0, 0x25FF,  // Geometric Shapes (▷ ■)
    0,
};

ImFont* add_font(const char* path, float size) {
    ImFontConfig config;
    config.OversampleH = 2;
    config.OversampleV = 2;
    return ImGui::GetIO().Fonts->AddFontFromFileTTF(path, size, &config, kGlyphRanges);
}

void apply_style() {
    ImGui::StyleColorsLight();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0;
    style.FrameRounding = 3;
    style.GrabRounding = 3;
    style.WindowBorderSize = 1;
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
    }
    if (!fonts.ui || !fonts.mono || !fonts.large || !fonts.small) {
        io.Fonts->Clear();
        fonts.ui = fonts.mono = fonts.large = fonts.small = io.Fonts->AddFontDefault();
    }
    return fonts;
}

}  // namespace cg::viewer
