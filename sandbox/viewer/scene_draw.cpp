// A cg::Scene as ImDrawList calls. Sections: [strokes and fills] [pixel grids] [primitives]
// [labels] [draw_scene].
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "viewer/canvas_draw.hpp"
#include "viewer/grid_texture.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/labels.hpp"
#include "viewer/palette.hpp"

namespace cg::viewer {

namespace {

// Geometry may reach this far outside the canvas before it is clipped, so that zooming far
// in keeps float coordinates and ImGui's vertex buffers sane.
constexpr double kSafeMargin = 2000;

struct Pen {
    ImU32 colour;
    float width;
    bool dashed;
};

Pen pen_of(const Style& style) {
    return {im_colour(style_rgba(style)), std::clamp(style.width, 0.5f, 20.0f), style.dashed};
}

// Everything draw_scene's parts share.
struct Painter {
    ImDrawList* dl;
    const ScreenMap& map;
    const Fonts& fonts;
    Box safe;
    LabelPlacer placer;
    std::vector<LabelRequest> labels;
    GridTextures* textures = nullptr;  // big grids as one texture, when there is a GL context
    std::size_t grids = 0;             // grid texture slots used so far (each its own texture)
    Box drawn{{DBL_MAX, DBL_MAX}, {-DBL_MAX, -DBL_MAX}};  // the screen bounds of what was drawn

    glm::dvec2 text_size(const std::string& text) const { return label_size(fonts, text); }
    void note(glm::dvec2 q) {
        if (!map.canvas.contains(q)) q = glm::clamp(q, map.canvas.min, map.canvas.max);
        drawn.min = glm::min(drawn.min, q);
        drawn.max = glm::max(drawn.max, q);
    }
    void note(const std::vector<glm::dvec2>& qs) {
        for (glm::dvec2 q : qs) note(q);
    }
};

// --- [strokes and fills] ---------------------------------------------------------------------

void dashed_polyline(ImDrawList* dl, const std::vector<glm::dvec2>& pts, bool closed,
                     const Pen& pen) {
    const double dash = 4 + 2.5 * pen.width, period = dash + 3 + 1.5 * pen.width;
    double phase = 0;  // carried across corners so the pattern flows around them
    const std::size_t edges = closed ? pts.size() : pts.size() - 1;
    for (std::size_t i = 0; i < edges; ++i) {
        const glm::dvec2 a = pts[i], b = pts[(i + 1) % pts.size()];
        const double length = glm::length(b - a);
        if (length == 0) continue;
        const glm::dvec2 dir = (b - a) / length;
        for (double t = 0; t < length;) {
            const bool on = phase < dash;
            const double run = std::min((on ? dash : period) - phase, length - t);
            if (on) dl->AddLine(im(a + dir * t), im(a + dir * (t + run)), pen.colour, pen.width);
            t += run;
            phase = std::fmod(phase + run, period);
        }
    }
}

void stroke(Painter& p, const std::vector<glm::dvec2>& screen, bool closed, const Pen& pen) {
    if (screen.size() < 2) return;
    const bool safe =
        std::all_of(screen.begin(), screen.end(), [&](glm::dvec2 q) { return p.safe.contains(q); });
    if (safe) {
        if (pen.dashed) return dashed_polyline(p.dl, screen, closed, pen);
        std::vector<ImVec2> pts;
        for (glm::dvec2 q : screen) pts.push_back(im(q));
        p.dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), pen.colour,
                          closed ? ImDrawFlags_Closed : ImDrawFlags_None, pen.width);
        return;
    }
    const std::size_t edges = closed ? screen.size() : screen.size() - 1;
    for (std::size_t i = 0; i < edges; ++i)
        if (auto s = clip_segment(screen[i], screen[(i + 1) % screen.size()], p.safe)) {
            if (pen.dashed)
                dashed_polyline(p.dl, {s->first, s->second}, false, pen);
            else
                p.dl->AddLine(im(s->first), im(s->second), pen.colour, pen.width);
        }
}

// Fills any simple polygon, concave too, as triangles without an anti-aliased fringe: the
// outline drawn over it gives the smooth edge, and shared triangle edges leave no seams.
void fill(Painter& p, std::vector<glm::dvec2> screen, ImU32 colour) {
    if (!std::all_of(screen.begin(), screen.end(),
                     [&](glm::dvec2 q) { return p.safe.contains(q); }))
        screen = clip_polygon_to_box(std::move(screen), p.safe);
    if (screen.size() < 3 || screen.size() > 60000) return;  // 16-bit indices
    const std::vector<int> triangles = triangulate(screen);
    ImDrawList* dl = p.dl;
    dl->PrimReserve(static_cast<int>(triangles.size()), static_cast<int>(screen.size()));
    const ImDrawIdx base = static_cast<ImDrawIdx>(dl->_VtxCurrentIdx);
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();  // untextured: the atlas's white texel
    for (glm::dvec2 q : screen) dl->PrimWriteVtx(im(q), uv, colour);
    for (int i : triangles) dl->PrimWriteIdx(static_cast<ImDrawIdx>(base + i));
}

std::vector<glm::dvec2> to_screen(const ScreenMap& map, const std::vector<glm::dvec2>& world) {
    std::vector<glm::dvec2> out;
    out.reserve(world.size());
    for (glm::dvec2 w : world) out.push_back(map.to_screen(w));
    return out;
}

// --- [pixel grids] ---------------------------------------------------------------------------

constexpr std::uint32_t kRoleCellAlpha = 0xa0;     // cells in the grid's role colour
constexpr std::uint32_t kCellBorder = 0x00000030;  // over white and over colour alike
constexpr std::uint32_t kEmptyCentre = 0x9a9a9aff;
constexpr std::uint32_t kFilledCentre = 0x00000080;
constexpr double kBorderPixels = 6;   // cell size from which borders are drawn
constexpr double kCentrePixels = 14;  // ... and centre dots

// Cells [i0, i1) × [j0, j1) as filled rectangles: runs of one colour merged into one; below one
// screen pixel per cell, blocks of cells drawn as one in the colour of their first filled cell.
void draw_cell_runs(Painter& p, const PixelGrid2& g, int i0, int i1, int j0, int j1, ImU32 role) {
    const double size = p.map.view.zoom;  // screen pixels per cell
    auto cell_at = [&](int i, int j) {
        return g.rgba[static_cast<std::size_t>(j) * static_cast<std::size_t>(g.width) + i];
    };
    auto corner = [&](double i, double j) {  // a cell corner on screen, kept near the canvas
        const glm::dvec2 s = p.map.to_screen(g.origin + glm::dvec2(i, j));
        return glm::clamp(s, p.safe.min, p.safe.max);
    };
    const int stride = size >= 1 ? 1 : static_cast<int>(std::ceil(1 / size));
    auto block = [&](int i, int j) {
        for (int b = j; b < std::min(j + stride, j1); ++b)
            for (int a = i; a < std::min(i + stride, i1); ++a)
                if (const std::uint32_t v = cell_at(a, b)) return v;
        return std::uint32_t{0};
    };
    for (int j = j0; j < j1; j += stride) {
        const double top = std::min(j + stride, g.height);
        int start = i0;
        std::uint32_t run = 0;
        for (int i = i0;; i += stride) {
            const bool end = i >= i1;
            const std::uint32_t v = end ? 0 : block(i, j);
            if (end || v != run) {
                if (run != 0)
                    p.dl->AddRectFilled(im(corner(start, top)), im(corner(std::min(i, i1), j)),
                                        run == PixelGrid2::kRoleColour ? role : im_colour(run));
                start = i, run = v;
            }
            if (end) break;
        }
    }
}

// The visible cells — one texture for a big grid when there is a GL context (a ray-traced
// image), else filled rectangles — then, zoomed in, the cell borders and the sample points at
// the centres.
void draw_pixel_grid(Painter& p, const PixelGrid2& g) {
    if (g.width <= 0 || g.height <= 0 ||
        g.rgba.size() != static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height))
        return;
    const std::size_t slot = p.grids++;
    const Box& c = p.map.canvas;
    const glm::dvec2 lo = p.map.to_world({c.min.x, c.max.y}) - g.origin;
    const glm::dvec2 hi = p.map.to_world({c.max.x, c.min.y}) - g.origin;
    auto cells = [](double v, int n) { return static_cast<int>(std::clamp(v, 0.0, double(n))); };
    const int i0 = cells(std::floor(lo.x), g.width), i1 = cells(std::ceil(hi.x), g.width);
    const int j0 = cells(std::floor(lo.y), g.height), j1 = cells(std::ceil(hi.y), g.height);
    if (i0 >= i1 || j0 >= j1) return;
    p.note(p.map.to_screen(g.origin + glm::dvec2(i0, j0)));
    p.note(p.map.to_screen(g.origin + glm::dvec2(i1, j1)));

    const double size = p.map.view.zoom;  // screen pixels per cell
    const ImU32 role = im_colour(with_alpha(role_rgba(g.role), kRoleCellAlpha));
    if (p.textures && g.rgba.size() >= GridTextures::kMinCells) {
        // The visible cells as one quad (texture row 0 is the grid's top row).
        const ImTextureID id = p.textures->texture(slot, g, role);
        const double w = g.width, h = g.height;
        p.dl->AddImage(id, im(p.map.to_screen(g.origin + glm::dvec2(i0, j1))),
                       im(p.map.to_screen(g.origin + glm::dvec2(i1, j0))),
                       ImVec2(static_cast<float>(i0 / w), static_cast<float>((h - j1) / h)),
                       ImVec2(static_cast<float>(i1 / w), static_cast<float>((h - j0) / h)));
    } else {
        draw_cell_runs(p, g, i0, i1, j0, j1, role);
    }
    if (!g.grid_lines || size < kBorderPixels) return;

    auto cell_at = [&](int i, int j) {
        return g.rgba[static_cast<std::size_t>(j) * static_cast<std::size_t>(g.width) + i];
    };
    auto corner = [&](double i, double j) {
        const glm::dvec2 s = p.map.to_screen(g.origin + glm::dvec2(i, j));
        return glm::clamp(s, p.safe.min, p.safe.max);
    };
    const ImU32 border = im_colour(kCellBorder);
    for (int i = i0; i <= i1; ++i) p.dl->AddLine(im(corner(i, j0)), im(corner(i, j1)), border);
    for (int j = j0; j <= j1; ++j) p.dl->AddLine(im(corner(i0, j)), im(corner(i1, j)), border);
    if (size < kCentrePixels) return;
    const float radius = static_cast<float>(std::clamp(size * 0.06, 1.5, 3.0));
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) {
            const glm::dvec2 centre = p.map.to_screen(g.origin + glm::dvec2(i + 0.5, j + 0.5));
            if (!c.contains(centre)) continue;
            p.dl->AddCircleFilled(im(centre), radius,
                                  im_colour(cell_at(i, j) ? kFilledCentre : kEmptyCentre), 8);
        }
}

// --- [primitives] ----------------------------------------------------------------------------

void draw_half_plane(Painter& p, const HalfPlane2& h) {
    if (h.inward.x == 0 && h.inward.y == 0) return;
    const Box& c = p.map.canvas;
    const Box view{p.map.to_world({c.min.x, c.max.y}), p.map.to_world({c.max.x, c.min.y})};
    const std::uint32_t rgba = style_rgba(h.style);

    // Shade the outside: the visible rectangle cut down to (x - point) . (-inward) >= 0.
    const std::vector<glm::dvec2> corners{
        view.min, {view.max.x, view.min.y}, view.max, {view.min.x, view.max.y}};
    fill(p, to_screen(p.map, clip_polygon(corners, h.point, -h.inward)),
         im_colour(with_alpha(rgba, kOutsideShadeAlpha)));

    const auto line = clip_line(h.point, {-h.inward.y, h.inward.x}, view);
    if (!line) return;
    const glm::dvec2 a = p.map.to_screen(line->first), b = p.map.to_screen(line->second);
    stroke(p, {a, b}, false, pen_of(h.style));
    p.placer.avoid_segment(a, b);
    if (h.label.empty()) return;

    // The label sits just outside the line, near its top (or right) end, where it is least
    // likely to cover the scene; a few places along the line are the fallbacks.
    const bool a_first = std::abs(b.y - a.y) > std::abs(b.x - a.x) ? a.y < b.y : a.x > b.x;
    const glm::dvec2 from = a_first ? a : b, to = a_first ? b : a;
    glm::dvec2 out = glm::normalize(glm::dvec2(-h.inward.x, h.inward.y));  // screen is y down
    const glm::dvec2 size = p.text_size(h.label);
    LabelRequest label{h.label, darker(rgba, 0.8f), label_priority(0, h.style, 0), from, 6};
    for (double side : {1.0, -1.0}) {
        const glm::dvec2 n = out * side;
        const double reach = 6 + std::abs(n.x) * size.x / 2 + std::abs(n.y) * size.y / 2;
        for (double t : {0.08, 0.25, 0.5, 0.75, 0.92}) {
            const glm::dvec2 centre = from + (to - from) * t + n * reach;
            label.corners.push_back(centre - size / 2.0);
        }
    }
    p.labels.push_back(std::move(label));
}

void draw_polygon(Painter& p, const Polygon2& poly) {
    const std::vector<glm::dvec2> screen = to_screen(p.map, poly.points);
    const std::uint32_t rgba = style_rgba(poly.style);
    // An explicit colour with its own alpha is the fill as given; a role fills faintly.
    if (poly.filled)
        fill(p, screen,
             im_colour(poly.style.rgba != 0 && (poly.style.rgba & 0xffu) != 0xffu
                           ? rgba
                           : with_alpha(rgba, kFillAlpha)));
    stroke(p, screen, poly.closed, pen_of(poly.style));
    p.note(screen);
    const std::size_t edges = poly.closed ? screen.size() : screen.size() - 1;
    for (std::size_t i = 0; i < edges && screen.size() > 1; ++i)
        p.placer.avoid_segment(screen[i], screen[(i + 1) % screen.size()]);
}

void draw_segment(Painter& p, const Segment2& s) {
    const glm::dvec2 a = p.map.to_screen(s.a), b = p.map.to_screen(s.b);
    const Pen pen = pen_of(s.style);
    const double length = glm::length(b - a);
    if (s.arrow && length > 1) {
        // The head's size grows with the line, but never past half the segment.
        const double head = std::min(7.0 + 3.0 * pen.width, length / 2);
        const glm::dvec2 dir = (b - a) / length, side{-dir.y, dir.x};
        const glm::dvec2 base = b - dir * head;
        stroke(p, {a, b - dir * head * 0.7}, false, pen);
        const double half = head * 0.45;
        p.dl->AddTriangleFilled(im(b), im(base + side * half), im(base - side * half), pen.colour);
    } else {
        stroke(p, {a, b}, false, pen);
    }
    p.placer.avoid_segment(a, b);
    p.note(a), p.note(b);
    if (!s.label.empty())
        p.labels.push_back({s.label, darker(style_rgba(s.style), 0.8f),
                            label_priority(s.priority, s.style, 1), (a + b) / 2.0, 8});
}

void draw_point(Painter& p, const Point2& pt) {
    const glm::dvec2 c = p.map.to_screen(pt.p);
    if (!p.safe.contains(c)) return;
    const float r = std::clamp(pt.radius, 1.0f, 30.0f);
    const std::uint32_t rgba = style_rgba(pt.style);
    p.dl->AddCircleFilled(im(c), r + 1.5f, IM_COL32_WHITE);  // the outline keeps it off lines
    p.dl->AddCircleFilled(im(c), r, im_colour(rgba));
    p.placer.avoid_box({c - glm::dvec2(r), c + glm::dvec2(r)});
    p.note(c - glm::dvec2(r)), p.note(c + glm::dvec2(r));
    if (!pt.label.empty())
        p.labels.push_back(
            {pt.label, darker(rgba, 0.8f), label_priority(pt.priority, pt.style, 3), c, r + 5});
}

void draw_handle(Painter& p, const Handle2& h, bool hot) {
    const glm::dvec2 c = p.map.to_screen(h.p);
    if (!p.safe.contains(c)) return;
    // A hollow square, so the point or arrowhead usually sitting at a handle stays visible.
    const double half = hot ? 7.0 : 5.0;
    const ImVec2 lo = im(c - glm::dvec2(half)), hi = im(c + glm::dvec2(half));
    if (hot) p.dl->AddRectFilled(lo, hi, im_colour(with_alpha(kHandleHover, 0x90)));
    p.dl->AddRect(lo, hi, im_colour(kHandleHalo), 0, 0, 3.0f);
    p.dl->AddRect(lo, hi, im_colour(hot ? darker(kHandleHover, 0.8f) : kHandleOutline), 0, 0, 1.5f);
    p.placer.avoid_box({c - glm::dvec2(half), c + glm::dvec2(half)});
}

}  // namespace

// --- [draw_scene] ----------------------------------------------------------------------------

Box draw_scene(ImDrawList* dl, const ScreenMap& map, const Layer2& layer, const Fonts& fonts,
               int hot_handle, const std::vector<Box>& keep_clear, GridTextures* textures,
               Recording recording, std::size_t first_texture_slot) {
    Painter p{dl,
              map,
              fonts,
              map.canvas.grown(kSafeMargin),
              LabelPlacer(map.canvas),
              {},
              textures,
              first_texture_slot};
    for (const Box& b : keep_clear) p.placer.keep_clear(b);
    for (const PixelGrid2& g : layer.grids) draw_pixel_grid(p, g);
    for (const HalfPlane2& h : layer.half_planes) draw_half_plane(p, h);
    for (const Polygon2& poly : layer.polygons) draw_polygon(p, poly);
    for (const Segment2& s : layer.segments) draw_segment(p, s);
    for (const Point2& pt : layer.points) draw_point(p, pt);
    for (std::size_t i = 0; i < layer.handles.size(); ++i)
        draw_handle(p, layer.handles[i], static_cast<int>(i) == hot_handle);
    for (const Label2& l : layer.labels) {
        if (l.text.empty()) continue;
        const glm::dvec2 at = map.to_screen(l.p);
        p.labels.push_back({l.text, darker(style_rgba(l.style), 0.8f),
                            label_priority(l.priority, l.style, 2), at, 9});
    }
    const std::vector<PlacedLabel> placed = p.placer.place_all(
        std::move(p.labels), [&](const std::string& t) { return p.text_size(t); });
    paint_labels(dl, placed, p.placer, fonts, recording.record, recording.panel);
    for (const PlacedLabel& l : placed) p.note(l.box.min), p.note(l.box.max);
    return p.drawn;
}

}  // namespace cg::viewer
