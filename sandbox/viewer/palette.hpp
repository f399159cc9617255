// The viewer's colours: one per cg::Role, so every algorithm speaks the same visual language.
//
// All colours are 0xRRGGBBAA, like cg::Style::rgba. Strokes use a role's colour as it is;
// fills use the same colour at kFillAlpha so the geometry underneath stays visible. The GUI
// tests look for these exact colours in rendered pixels, so they are saturated, far apart
// from each other, and far from the greys of the grid.
#pragma once

#include <cstdint>
#include <string_view>

#include "core/scene.hpp"

namespace cg::viewer {

constexpr std::uint32_t role_rgba(Role role) {
    switch (role) {
        case Role::Window:
            return 0x1f77b4ff;  // blue
        case Role::Subject:
            return 0x7f7f7fff;  // grey
        case Role::Kept:
            return 0x2ca02cff;  // green
        case Role::Discarded:
            return 0xd62728ff;  // red
        case Role::Active:
            return 0xff7f0eff;  // orange
        case Role::Entering:
            return 0x009e94ff;  // teal
        case Role::Leaving:
            return 0xd0189cff;  // magenta
        case Role::Construction:
            return 0xb8b8b8ff;  // light grey
        case Role::Neutral:
        case Role::Count:
            break;
    }
    return 0x404040ff;  // Neutral: dark grey
}

constexpr std::uint32_t with_alpha(std::uint32_t rgba, std::uint32_t alpha) {
    return (rgba & 0xffffff00u) | (alpha & 0xffu);
}

// The colour a primitive is drawn in: its explicit rgba when it has one, else its role's.
constexpr std::uint32_t style_rgba(const Style& style) {
    return style.rgba != 0 ? style.rgba : role_rgba(style.role);
}

// Scales the RGB channels towards black: label text in a role's colour, but readable.
constexpr std::uint32_t darker(std::uint32_t rgba, float factor) {
    auto channel = [&](int shift) {
        return static_cast<std::uint32_t>(static_cast<float>((rgba >> shift) & 0xffu) * factor)
               << shift;
    };
    return channel(24) | channel(16) | channel(8) | (rgba & 0xffu);
}

constexpr std::uint32_t kFillAlpha = 0x38;          // polygons with filled = true
constexpr std::uint32_t kOutsideShadeAlpha = 0x1e;  // the outside of a half-plane

// The canvas.
constexpr std::uint32_t kCanvasBackground = 0xffffffff;
constexpr std::uint32_t kGridMinor = 0xf1f1f1ff;
constexpr std::uint32_t kGridMajor = 0xdededeff;
constexpr std::uint32_t kAxis = 0x8a8a8aff;
constexpr std::uint32_t kTickLabel = 0x707070ff;
constexpr std::uint32_t kCaptionText = 0x202020ff;
constexpr std::uint32_t kHintText = 0x9a9a9aff;
constexpr std::uint32_t kLabelHalo = 0xffffffcc;  // behind labels, so lines don't strike them

// Handles: the draggable points bound to input fields.
constexpr std::uint32_t kHandleHalo = 0xffffffb0;  // keeps the outline visible on dark lines
constexpr std::uint32_t kHandleOutline = 0x404040ff;
constexpr std::uint32_t kHandleHover = 0xff7f0eff;

// The panels.
constexpr std::uint32_t kActiveLine = 0xff7f0e40;  // the pseudocode line of the current step
constexpr std::uint32_t kBreakpoint = 0xd62728ff;
constexpr std::uint32_t kErrorText = 0xd62728ff;
constexpr std::uint32_t kOkText = 0x2a7d2aff;
constexpr std::uint32_t kChangedValue = 0xc25400ff;  // a variable this step changed
constexpr std::uint32_t kMathText = 0x0b5e6bff;      // the step's formula, under the narration

// Lessons and exam practice. The GUI tests look for kSectionTitle in the lesson panel and for
// kExamQuestion behind the exam's question, so both differ from everything else on screen.
constexpr std::uint32_t kSectionTitle = 0x1f4e8cff;    // a lesson's section headings
constexpr std::uint32_t kNoteBackground = 0xe4effaff;  // "What this means: …"
constexpr std::uint32_t kNoteAccent = 0x1f77b4ff;      // ... its left bar and label
constexpr std::uint32_t kExamQuestion = 0xfff3c4ff;    // the question's box: exam paper yellow
constexpr std::uint32_t kWarningText = 0xa15c00ff;     // broken lesson files
constexpr std::uint32_t kCheckButton = 0x2e7d32ff;     // the exam's Check

// How much the exam weighs a lesson's topic: the badge beside its title.
constexpr std::uint32_t exam_weight_rgba(std::string_view weight) {
    if (weight == "high") return 0xc62828ff;
    if (weight == "medium") return 0xe07b00ff;
    if (weight == "low") return 0x3a7fc1ff;
    return 0x9a9a9aff;  // none
}

}  // namespace cg::viewer
