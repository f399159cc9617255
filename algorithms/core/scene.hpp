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

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

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

// 0xRRGGBBAA from a colour with channels in [0, 1] (clamped), rounded to the nearest byte: for
// Style::rgba and PixelGrid2 cells.
inline std::uint32_t pack_rgba(glm::dvec3 c, double alpha = 1.0) {
    auto byte = [](double x) {
        return static_cast<std::uint32_t>(std::lround(255 * std::clamp(x, 0.0, 1.0)));
    };
    return byte(c.x) << 24 | byte(c.y) << 16 | byte(c.z) << 8 | byte(alpha);
}

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

// ---- 3D: drawn on the viewer's 3D canvas (orbited by the project's own arcball) ----
// World coordinates, right-handed (x right, y up, z toward the viewer in the default view).
// The canvas sorts everything by depth and draws back to front, so translucent surfaces and
// labels read correctly; a scene with any 3D primitive opens the 3D canvas.

struct Point3 {
    glm::dvec3 p;
    std::string label;
    Style style;
    float radius = 5.0f;  // screen pixels
};

struct Segment3 {
    glm::dvec3 a, b;
    std::string label;  // drawn at the midpoint
    Style style;
    bool arrow = false;  // arrowhead at b (a vector, an axis, a normal)
};

// A flat polygon (triangle, quad, face), filled at `alpha` in its role colour or rgba.
// `two_sided = false` greys it out when its front (counter-clockwise) side faces away, so
// back faces are visible as such in any view.
struct Face3 {
    std::vector<glm::dvec3> points;
    Style style;
    float alpha = 0.5f;
    bool outline = true;
    bool two_sided = true;
};

struct Label3 {
    glm::dvec3 p;
    std::string text;
    Style style;
};

// A coordinate frame: the columns of `axes` drawn as x (red), y (green), z (blue) arrows
// from `origin`, each `length` long, labelled "<name>x"... — world axes, rotated frames.
struct Frame3 {
    glm::dvec3 origin{0, 0, 0};
    glm::dvec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    double length = 1.0;
    std::string name;  // "" for the world frame; "R" labels the axes R·x, R·y, R·z
    float alpha = 1.0f;
};

struct Scene {
    std::vector<PixelGrid2> grids;        // drawn first, under everything
    std::vector<HalfPlane2> half_planes;  // then these, under the rest
    std::vector<Polygon2> polygons;
    std::vector<Segment2> segments;
    std::vector<Point2> points;
    std::vector<Label2> labels;
    std::vector<Handle2> handles;

    // 3D content (empty for 2D algorithms). `extent3` is the radius of the region worth
    // showing around the origin, for the canvas's initial zoom (0: fit to the content).
    std::vector<Face3> faces3;
    std::vector<Segment3> segments3;
    std::vector<Point3> points3;
    std::vector<Label3> labels3;
    std::vector<Frame3> frames3;
    double extent3 = 0;

    bool has_3d() const {
        return !faces3.empty() || !segments3.empty() || !points3.empty() || !labels3.empty() ||
               !frames3.empty();
    }
    bool has_2d() const {
        return !grids.empty() || !half_planes.empty() || !polygons.empty() || !segments.empty() ||
               !points.empty() || !labels.empty();
    }
    void clear() { *this = Scene{}; }
};

}  // namespace cg
