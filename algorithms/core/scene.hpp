// What to draw for the current state, described without knowing how it is drawn.
//
// An algorithm fills a Scene; the viewer (ImGui draw lists) or any other renderer turns it
// into pixels. Colours are semantic roles so that every algorithm speaks the same visual
// language (the window is always blue, kept geometry green, the active test orange) and the
// GUI tests can look for a role's colour in the pixels. A primitive may override the role's
// colour with an explicit RGBA for data that carries its own colour (a polygon's fill).
//
// Coordinates are world coordinates, right-handed, y up. Handles are the draggable points:
// each is bound to the input fields it edits (JSON pointers such as "/p0/0"), so the viewer
// can offer dragging for any algorithm without knowing what the fields mean.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace cg {

enum class Role : std::uint8_t {
    Neutral,       // plain geometry, dark grey
    Window,        // a clip window / region of interest, blue
    Subject,       // the input being processed, grey
    Kept,          // what survives (the clipped segment), green
    Discarded,     // what is thrown away, red
    Active,        // the thing being tested in this step, orange
    Entering,      // an entering intersection, teal
    Leaving,       // a leaving intersection, magenta
    Construction,  // helper lines, light grey, dashed
    Count
};

struct Style {
    Role role = Role::Neutral;
    float width = 2.0f;        // line width in screen pixels
    bool dashed = false;
    std::uint32_t rgba = 0;    // 0xRRGGBBAA overriding the role colour; 0 = use the role
    bool operator==(const Style&) const = default;
};

struct Point2 {
    glm::dvec2 p;
    std::string label;
    Style style;
    float radius = 5.0f;  // screen pixels
};

struct Segment2 {
    glm::dvec2 a, b;
    std::string label;  // drawn at the midpoint
    Style style;
    bool arrow = false;  // arrowhead at b
};

struct Polygon2 {
    std::vector<glm::dvec2> points;
    Style style;
    bool closed = true;
    bool filled = false;  // filled with the role colour at low alpha (or rgba as given)
};

// The half-plane {x : (x - point) . inward >= 0}: its boundary line is drawn across the
// whole view and the outside is shaded, so a student sees which side a test keeps.
struct HalfPlane2 {
    glm::dvec2 point;
    glm::dvec2 inward;
    std::string label;
    Style style;
};

struct Label2 {
    glm::dvec2 p;
    std::string text;
    Style style;
};

// A raster of square cells, one world unit each: cell (i, j) covers [i, i+1) × [j, j+1) from
// `origin`, so its centre is origin + (i + 0.5, j + 0.5) — the project's pixel convention.
// Drawn under everything else. A cell's value is its colour, 0xRRGGBBAA; 0 leaves it empty,
// and kRoleColour paints it in `role`'s colour (so an algorithm need not know the palette).
struct PixelGrid2 {
    static constexpr std::uint32_t kRoleColour = 1;  // "the role's colour" (alpha 1: no real one)
    glm::dvec2 origin{0, 0};
    int width = 0, height = 0;        // in cells
    std::vector<std::uint32_t> rgba;  // width × height, row-major, row 0 at the bottom (y up)
    Role role = Role::Kept;           // the colour of kRoleColour cells
    bool grid_lines = true;           // cell borders and centre dots, when zoomed in enough
};

struct Handle2 {
    glm::dvec2 p;
    std::string name;     // shown on hover: "P0"
    std::string x_field;  // JSON pointer of the input field the x coordinate edits
    std::string y_field;  // ... and the y coordinate
};

struct Scene {
    std::vector<PixelGrid2> grids;        // drawn first, under everything
    std::vector<HalfPlane2> half_planes;  // then these, under the rest
    std::vector<Polygon2> polygons;
    std::vector<Segment2> segments;
    std::vector<Point2> points;
    std::vector<Label2> labels;
    std::vector<Handle2> handles;

    void clear() { *this = Scene{}; }
};

}  // namespace cg
