// What to draw for the current state, described without knowing how it is drawn.
//
// An algorithm fills a Scene; the viewer (ImGui draw lists) or any other renderer turns it
// into pixels. Colours are semantic roles so that every algorithm speaks the same visual
// language (the window is always blue, kept geometry green, the active test orange) and the
// GUI tests can look for a role's colour in the pixels. A primitive may override the role's
// colour with an explicit RGBA for data that carries its own colour (a polygon's fill).
//
// A scene has up to two main views and any number of panels, each with coordinates of its own:
//   - the 2D world (the Scene's own Layer2: world coordinates, right-handed, y up, on a grid);
//   - the 3D view (faces3, segments3, …, seen through the viewer's orbiting camera);
//   - panels: a chart (axes with their own ticks and units; series as lines, dots or bars), an
//     image (a raster shown pixel-exact, filling its panel, its title outside it) or a diagram
//     (a drawing in units of its own: a tree, a table of boxes).
// The viewer lays the views out side by side or stacked, fits each to its content, and never
// draws a chart or an image on the world's grid. `focus2`/`focus3` mark what the step is about:
// the 3D camera frames it, and the layout checks that it is large enough to see.
//
// Handles are the draggable points: each is bound to the input fields it edits (JSON pointers
// such as "/p0/0"), so the viewer can offer dragging for any algorithm without knowing what
// the fields mean.
//
// Labels are placed by the viewer, not where they are anchored: each has a priority (higher is
// placed first and dropped last; the role adds to it, Active most); a label that finds no free
// place beside its anchor gets a short leader line, then a shortened text ("t = 0.5" → "t"),
// and is dropped rather than drawn over another label, the title or a panel's edge.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

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
    float width = 2.0f;  // line width in screen pixels
    bool dashed = false;
    std::uint32_t rgba = 0;  // 0xRRGGBBAA overriding the role colour; 0 = use the role
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
    int priority = 0;     // of its label (see the top of this file)
};

struct Segment2 {
    glm::dvec2 a, b;
    std::string label;  // drawn at the midpoint
    Style style;
    bool arrow = false;  // arrowhead at b
    int priority = 0;    // of its label
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
    int priority = 0;
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
    // A drag puts the point at the centre of the cell under the mouse (a pixel of an image
    // panel's first grid, inside it) instead of at a round number near the mouse.
    bool cell_centres = false;
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
    int priority = 0;     // of its label
};

struct Segment3 {
    glm::dvec3 a, b;
    std::string label;  // drawn at the midpoint
    Style style;
    bool arrow = false;  // arrowhead at b (a vector, an axis, a normal)
    // At least this long on screen, in pixels, lengthened from a along b − a when the camera
    // makes it shorter: a normal or a direction that must be seen whatever the zoom. 0: as is.
    float min_pixels = 0;
    int priority = 0;  // of its label
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
    int priority = 0;
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

// ---- The 2D primitives of one coordinate system: the world, or a panel's own ----

struct Layer2 {
    std::vector<PixelGrid2> grids;        // drawn first, under everything
    std::vector<HalfPlane2> half_planes;  // then these, under the rest
    std::vector<Polygon2> polygons;
    std::vector<Segment2> segments;
    std::vector<Point2> points;
    std::vector<Label2> labels;
    std::vector<Handle2> handles;

    bool has_2d() const {
        return !grids.empty() || !half_planes.empty() || !polygons.empty() || !segments.empty() ||
               !points.empty() || !labels.empty();
    }
};

// ---- Panels: a chart or an image beside the main views, in coordinates of its own ----

// A chart's axis: its label (with the unit: "t (s)", "E (J)") and the range shown.
struct Axis {
    std::string label;
    double lo = 0, hi = 0;      // lo < hi: this range; otherwise fitted to the data, padded
    bool log = false;           // logarithmic (values must be above 0; others are left out)
    bool include_zero = false;  // a fitted range reaches 0 (an energy, a count: not a wobble)
    double step = 0;            // ticks at multiples of this (1: whole numbers); 0: by the room
    bool reversed = false;      // y only: growing downward (a screen's rows)
    // Categories instead of numbers: names[k] is written at the tick k (rows of a table, the
    // slabs x, y, z, a drawing order); the range then defaults to −0.5 … size − 0.5.
    std::vector<std::string> names = {};
};

// A line of a chart's legend: the series' style beside its name.
struct LegendEntry {
    std::string text;
    Style style;
    bool marker = false;  // a dot rather than a line
};

enum class PanelKind : std::uint8_t {
    Chart,    // x and y in the axes' units, scaled apart; ticks and numbers of its own
    Image,    // grids[0] is the raster; one cell a pixel or more, square; overlays in cell units
    Diagram,  // a drawing in units of its own (a tree, a flow): fitted, one scale, no ticks
};

// The primitives (Layer2) are in the panel's coordinates: a chart's data (x, y), an image's
// cells ((0, 0) at the raster's bottom-left corner, y up, as PixelGrid2 has it).
struct Panel : Layer2 {
    PanelKind kind = PanelKind::Chart;
    std::string title;  // over the panel, never over its content
    Axis x, y;          // a chart's axes
    std::vector<LegendEntry> legend;
    double weight = 1;  // its share of the canvas against the other views (the main view: 1.5)
    bool equal_aspect = false;  // a chart whose x and y units are equally long: a square stays one
};

// The bounds of something the step is about, for framing and for the layout's check that it
// can be seen (at least 24 px across). 2D: in the world (panel -1) or in panel `panel`.
struct Focus2 {
    glm::dvec2 lo, hi;
    int panel = -1;
};
struct Focus3 {
    glm::dvec3 lo, hi;
};

// How the 3D view looks at the scene when it is fitted (and on a reset): by default from above
// the +x/+z quadrant in perspective; a planar construction asks for a view along the normal of
// its plane, orthographic, so that right angles look right.
struct ViewHint3 {
    glm::dvec3 look{0, 0, 0};  // the direction the camera looks along; zero: the default view
    glm::dvec3 up{0, 1, 0};    // what is up on screen (must not be parallel to look)
    bool orthographic = false;
};

struct Scene : Layer2 {
    // 3D content (empty for 2D algorithms). `extent3` is the radius of the region worth
    // showing around the origin, for the canvas's initial zoom (0: fit to the content).
    std::vector<Face3> faces3;
    std::vector<Segment3> segments3;
    std::vector<Point3> points3;
    std::vector<Label3> labels3;
    std::vector<Frame3> frames3;
    double extent3 = 0;
    ViewHint3 view3;
    // The world's grid, axes and tick numbers; false for a diagram (a tree, a flow) whose
    // coordinates mean nothing to the student.
    bool world_grid = true;

    std::vector<Panel> panels;  // charts and images, beside the world and the 3D view
    std::vector<Focus2> focus2;
    std::vector<Focus3> focus3;  // the 3D camera frames these when there are any

    bool has_3d() const {
        return !faces3.empty() || !segments3.empty() || !points3.empty() || !labels3.empty() ||
               !frames3.empty();
    }
    void clear() { *this = Scene{}; }
};

// ---- Building panels and focus ----

// A new chart panel, returned for filling: its series go in as lines, dots or bars. The
// reference is into scene.panels: fill the panel before adding the next one, which may move it.
inline Panel& add_chart(Scene& scene, std::string title, Axis x, Axis y) {
    Panel p;
    p.kind = PanelKind::Chart;
    p.title = std::move(title);
    p.x = std::move(x);
    p.y = std::move(y);
    scene.panels.push_back(std::move(p));
    return scene.panels.back();
}

// A new diagram panel: a drawing whose coordinates mean nothing to the student (a tree, a
// table of boxes), fitted to its panel at one scale, without axes.
inline Panel& add_diagram(Scene& scene, std::string title) {
    Panel p;
    p.kind = PanelKind::Diagram;
    p.title = std::move(title);
    scene.panels.push_back(std::move(p));
    return scene.panels.back();
}

// A new image panel showing `raster` (its origin is set to (0, 0)).
inline Panel& add_image(Scene& scene, std::string title, PixelGrid2 raster) {
    Panel p;
    p.kind = PanelKind::Image;
    p.title = std::move(title);
    raster.origin = {0, 0};
    p.grids.push_back(std::move(raster));
    scene.panels.push_back(std::move(p));
    return scene.panels.back();
}

// A series as a polyline, named in the legend when `name` is given.
inline void add_line(Panel& chart, std::vector<glm::dvec2> points, Style style,
                     std::string name = {}) {
    if (!name.empty()) chart.legend.push_back({std::move(name), style, false});
    chart.polygons.push_back({std::move(points), style, false, false});
}

// A series as dots.
inline void add_dots(Panel& chart, const std::vector<glm::dvec2>& points, Style style,
                     std::string name = {}, float radius = 3.5f) {
    if (!name.empty()) chart.legend.push_back({std::move(name), style, true});
    for (glm::dvec2 p : points) chart.points.push_back({p, "", style, radius});
}

// A series as bars from y = 0, each `width` wide (in x units) and centred on its x.
inline void add_bars(Panel& chart, const std::vector<glm::dvec2>& points, double width, Style style,
                     std::string name = {}) {
    if (!name.empty()) chart.legend.push_back({std::move(name), style, false});
    for (glm::dvec2 p : points) {
        const double a = p.x - width / 2, b = p.x + width / 2;
        chart.polygons.push_back({{{a, 0}, {b, 0}, {b, p.y}, {a, p.y}}, style, true, true});
    }
}

inline void add_focus(Scene& scene, glm::dvec3 a, glm::dvec3 b) {
    scene.focus3.push_back({glm::min(a, b), glm::max(a, b)});
}
inline void add_focus(Scene& scene, glm::dvec2 a, glm::dvec2 b, int panel = -1) {
    scene.focus2.push_back({glm::min(a, b), glm::max(a, b), panel});
}

// Leaves out the 3D faces, segments, points and labels with a coordinate that is not finite:
// an input near the limits of a double (coordinates of 1e300) can overflow the picture's own
// arithmetic, and such a primitive has nothing to draw.
inline void drop_non_finite3(Scene& scene) {
    const auto bad = [](const glm::dvec3& q) {
        return !std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z);
    };
    std::erase_if(scene.faces3, [&](const Face3& f) {
        return std::any_of(f.points.begin(), f.points.end(), bad);
    });
    std::erase_if(scene.segments3, [&](const Segment3& g) { return bad(g.a) || bad(g.b); });
    std::erase_if(scene.points3, [&](const Point3& q) { return bad(q.p); });
    std::erase_if(scene.labels3, [&](const Label3& q) { return bad(q.p); });
}

}  // namespace cg
