// Fonts and the ImGui style, shared by the window and the offscreen renderer so a PNG looks
// exactly like the screen.
#pragma once

struct ImFont;

namespace cg::viewer {

struct Fonts {
    ImFont* ui = nullptr;     // panels, canvas labels
    ImFont* mono = nullptr;   // pseudocode, variable names
    ImFont* large = nullptr;  // the current narration
    ImFont* small = nullptr;  // tick labels, the canvas caption's second line
    ImFont* bold = nullptr;   // lesson section titles, the exam's field names
    ImFont* title = nullptr;  // a lesson's title
};

// Adds the DejaVu fonts to the current ImGui context's atlas with the glyphs the narrations
// use (− ≤ ≥ ← → · ▷ θ φ ² ₀ ✓ ✗ ⌈ ⌉ …); falls back to ImGui's built-in font when they are missing.
// Also sets the light style that matches the white canvas.
Fonts setup_fonts_and_style();

// Whether code point c is among the glyphs the atlas is built with (others show as "?").
bool in_glyph_ranges(char32_t c);

}  // namespace cg::viewer
