// Word wrapping that breaks only at spaces. ImGui's own wrapping also breaks after '.', so
// a narration's "1.25" could end up split over two lines as "1." and "25".
#pragma once

#include <string>

struct ImFont;

namespace cg::viewer {

// `text` with newlines put in place of spaces (or em spaces, which separate the parts of a
// formula) so that no line is wider than `width` pixels (a single word wider than that gets
// a line of its own).
std::string wrap_at_spaces(const ImFont* font, float size, const std::string& text, float width);

// A formula whose parts are separated by em spaces (LaTeX's \quad): whole parts go on a line
// while they fit, so "r₁ = q₁/p₁ = 0.25" is not split in the middle; a part too long for a
// line of its own is wrapped at its spaces.
std::string wrap_formula(const ImFont* font, float size, const std::string& text, float width);

// Like ImGui::TextWrapped with the current font and the available width.
void text_wrapped(const std::string& text);

}  // namespace cg::viewer
