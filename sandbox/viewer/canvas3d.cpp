// Sections: [camera] [fitting] [interaction] [collecting] [painting] [draw_scene3].
#include "viewer/canvas3d.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "viewer/canvas_draw.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/labels.hpp"
#include "viewer/palette.hpp"

namespace cg::viewer {

// --- [camera] --------------------------------------------------------------------------------

double Projector::focal() const {
    const double height = std::max(canvas.max.y - canvas.min.y, 1.0);
    return height / 2 / std::tan(glm::radians(view.fov_y_deg) / 2);
}

glm::dvec2 Projector::project_view(glm::dvec3 v) const {
    const double f = focal() / (view.orthographic ? view.distance : depth(v));
    const glm::dvec2 c = centre();
    return {c.x + f * v.x, c.y - f * v.y};
}

std::optional<glm::dvec2> Projector::screen(glm::dvec3 world) const {
    const glm::dvec3 v = to_view(world);
    if (depth(v) < near()) return std::nullopt;
    return project_view(v);
}

glm::dquat default_rotation() {
    // Turn the world 35° about y (so +x comes towards us on the right, +z on the left), then
    // tip it 20° about x so that we look down on the floor a little.
    return glm::angleAxis(glm::radians(20.0), glm::dvec3(1, 0, 0)) *
           glm::angleAxis(glm::radians(-35.0), glm::dvec3(0, 1, 0));
}

glm::dquat look_rotation(glm::dvec3 look, glm::dvec3 up) {
    const double l = glm::length(look);
    if (!(l > 0) || !std::isfinite(l)) return default_rotation();
    const glm::dvec3 f = look / l;
    glm::dvec3 r = glm::cross(f, up);
    if (glm::length(r) < 1e-9) return default_rotation();
    r = glm::normalize(r);
    const glm::dvec3 u = glm::cross(r, f);
    // The view's axes are r (right), u (up) and −f (toward the viewer): the rows of world → view.
    return glm::normalize(glm::quat_cast(glm::transpose(glm::dmat3(r, u, -f))));
}

// --- [fitting] -------------------------------------------------------------------------------

namespace {

template <class F>
void for_each_point(const Scene& scene, F&& f) {
    for (const Face3& face : scene.faces3)
        for (glm::dvec3 p : face.points) f(p);
    for (const Segment3& s : scene.segments3) f(s.a), f(s.b);
    for (const Point3& p : scene.points3) f(p.p);
    for (const Label3& l : scene.labels3) f(l.p);
    for (const Frame3& fr : scene.frames3) {
        f(fr.origin);
        f(fr.origin + fr.x * fr.length), f(fr.origin + fr.y * fr.length);
        f(fr.origin + fr.z * fr.length);
    }
}

bool finite(glm::dvec3 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace

View3 fit_view3(const Scene& scene, glm::dvec2 size) {
    View3 v;
    v.rotation = scene.view3.look == glm::dvec3(0)
                     ? default_rotation()
                     : look_rotation(scene.view3.look, scene.view3.up);
    v.orthographic = scene.view3.orthographic;
    // What to frame: the focus elements when the step marks some (each one's own corners, so a
    // cube and an eye far off it are framed as they are, not as the box round both); else the
    // cube of half-side extent3 round the origin when the scene gives one; else everything.
    std::vector<glm::dvec3> points;
    auto add = [&](glm::dvec3 p) {
        if (finite(p)) points.push_back(p);
    };
    auto corners = [&](glm::dvec3 lo, glm::dvec3 hi) {
        for (int i = 0; i < 8; ++i)
            add({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    };
    if (!scene.focus3.empty()) {
        for (const Focus3& f : scene.focus3) corners(f.lo, f.hi);
    } else if (scene.extent3 > 0 && std::isfinite(scene.extent3)) {
        corners(glm::dvec3(-scene.extent3), glm::dvec3(scene.extent3));
    } else {
        for_each_point(scene, add);
    }
    if (points.empty()) corners(glm::dvec3(-1), glm::dvec3(1));
    // The target is the middle of what is framed as the camera sees it (in view coordinates).
    const double inf = std::numeric_limits<double>::infinity();
    glm::dvec3 lo(inf), hi(-inf);
    for (glm::dvec3 p : points) {
        const glm::dvec3 q = v.rotation * p;
        lo = glm::min(lo, q), hi = glm::max(hi, q);
    }
    if (glm::length(hi - lo) < 1e-9) lo -= glm::dvec3(0.5), hi += glm::dvec3(0.5);
    v.target = glm::conjugate(v.rotation) * ((lo + hi) / 2.0);
    // Every point, in view coordinates round the target, must land within 80% of the canvas's
    // half-width and half-height (room for labels): for a pinhole at distance d, a point c lands
    // f·c.x / (d − c.z) from the centre, so d ≥ c.z + f·|c.x| / half_width.
    const double focal = std::max(size.y, 1.0) / 2 / std::tan(glm::radians(v.fov_y_deg) / 2);
    const double hw = 0.80 * std::max(size.x, 1.0) / 2, hh = 0.80 * std::max(size.y, 1.0) / 2;
    const glm::dvec3 middle = (lo + hi) / 2.0;
    double distance = 0, deepest = -inf;
    auto fit = [&](glm::dvec3 c) {
        const double z = v.orthographic ? 0 : c.z;
        distance =
            std::max({distance, z + focal * std::fabs(c.x) / hw, z + focal * std::fabs(c.y) / hh});
        deepest = std::max(deepest, c.z);
    };
    for (glm::dvec3 p : points) fit(v.rotation * p - middle);
    if (hi.x - lo.x < 1e-9 || hi.y - lo.y < 1e-9)  // a point or a line seen end-on: some room
        fit(glm::dvec3(0.5 * std::max(glm::length(hi - lo), 1.0), 0, 0));
    // In perspective the camera stays outside what it frames, with room before the near plane.
    if (!v.orthographic) distance = std::max(distance, 1.3 * deepest);
    v.distance = distance > 0 && std::isfinite(distance) ? distance : 10;
    return v;
}

// --- [interaction] ---------------------------------------------------------------------------

bool interact3(Camera3& c, const Box& canvas) {
    ImGui::SetCursorScreenPos(im(canvas.min));
    ImGui::InvisibleButton("canvas3d", im(canvas.max - canvas.min),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    ImGui::SetItemAllowOverlap();  // the sliders drawn over the canvas take their clicks
    const ImGuiIO& io = ImGui::GetIO();
    const glm::dvec2 size = canvas.max - canvas.min;
    // The ball's coordinates: pixels from the canvas's bottom-left corner, y up.
    auto ball = [&](ImVec2 mouse) {
        return trackball::to_ball({mouse.x - canvas.min.x, canvas.max.y - mouse.y}, size);
    };
    const bool hovered = ImGui::IsItemHovered();
    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) return true;
    if (!ImGui::IsItemActive()) c.orbiting = c.panning = false;
    if (ImGui::IsItemActivated()) {
        if (io.MouseClicked[ImGuiMouseButton_Left]) {
            c.orbiting = true;
            c.grab = ball(io.MousePos);
            c.grab_rotation = c.view.rotation;
        } else {
            c.panning = true;
        }
    }
    if (c.orbiting) {
        // Always from the drag's start: the arcball's rotation depends only on S and T.
        c.view.rotation =
            glm::normalize(trackball::arcball(c.grab, ball(io.MousePos)) * c.grab_rotation);
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeAll);
    } else if (c.panning) {
        // Move the target across the view plane so the point under the mouse follows it.
        const Projector proj{canvas, c.view};
        const double world_per_pixel = c.view.distance / proj.focal();
        const glm::dvec3 shift_view(-io.MouseDelta.x * world_per_pixel,
                                    io.MouseDelta.y * world_per_pixel, 0);
        c.view.target += glm::conjugate(c.view.rotation) * shift_view;
        ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
    }
    if (hovered && io.MouseWheel != 0)
        c.view.distance = std::clamp(c.view.distance * std::pow(1.15, -io.MouseWheel), 1e-6, 1e9);
    return false;
}

// --- [collecting] ----------------------------------------------------------------------------
// Every primitive becomes screen-space items with a depth; the painter sorts them.

namespace {

constexpr std::uint32_t kAxisX = 0xd62728ff, kAxisY = 0x2ca02cff, kAxisZ = 0x1f77b4ff;
constexpr std::uint32_t kBackFace = 0xa8a8a8ff;
constexpr std::uint32_t kFloor = 0xe8e8e8ff;

struct Line {
    glm::dvec2 a, b;
    std::uint32_t rgba;
    float width;
    bool dashed, arrow;
};
struct Fill {
    std::vector<glm::dvec2> points;
    std::uint32_t fill, outline;  // outline 0: none
};
struct Dot {
    glm::dvec2 c;
    std::uint32_t rgba;
    float radius;
};
struct Item {
    double depth;  // larger: farther, drawn first
    enum Kind : std::uint8_t { kLine, kFill, kDot } kind;
    int index;
};

// A mesh edge by its two world-space ends, either way round: a segment drawn along a face's
// edge (an outline, a silhouette, a crease) is found by it.
struct EdgeKey {
    glm::dvec3 a, b;
    EdgeKey(glm::dvec3 p, glm::dvec3 q) : a(p), b(q) {
        if (std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z)) std::swap(a, b);
    }
    bool operator==(const EdgeKey&) const = default;
};
struct EdgeKeyHash {
    std::size_t operator()(const EdgeKey& k) const {
        std::size_t h = 0;
        for (double v : {k.a.x, k.a.y, k.a.z, k.b.x, k.b.y, k.b.z})
            h = h * 1000003u ^ std::hash<double>{}(v);
        return h;
    }
};

struct Collector {
    const Projector& proj;
    std::vector<Line> lines;
    std::vector<Fill> fills;
    std::vector<Dot> dots;
    std::vector<Item> items;
    std::vector<LabelRequest> labels;
    // The nearest depth of the faces along each face edge. A segment lying on a face's edge
    // has the face's depth at best (its midpoint's against the face's centroid: either can be
    // the nearer), so by depth alone the face would paint over it about half the time; a
    // segment on an edge is drawn just in front of the nearest face that has that edge.
    std::unordered_map<EdgeKey, double, EdgeKeyHash> face_edges;

    // A segment cut at the near plane; returns false when wholly behind it.
    bool clip_near(glm::dvec3& a, glm::dvec3& b) const {
        const double da = proj.depth(a) - proj.near(), db = proj.depth(b) - proj.near();
        if (da < 0 && db < 0) return false;
        if (da < 0) a += (b - a) * (da / (da - db));
        if (db < 0) b += (a - b) * (db / (db - da));
        return true;
    }

    void line(glm::dvec3 wa, glm::dvec3 wb, std::uint32_t rgba, float width, bool dashed,
              bool arrow, const std::string& label = {}, int priority = 0, float min_pixels = 0) {
        glm::dvec3 a = proj.to_view(wa), b = proj.to_view(wb);
        if (!finite(a) || !finite(b)) return;
        const glm::dvec3 b_before = b;
        if (!clip_near(a, b)) return;
        arrow = arrow && b == b_before;  // no head on a cut end
        glm::dvec2 sa = proj.project_view(a), sb = proj.project_view(b);
        if (min_pixels > 0 && b == b_before) {
            // Too short to see from here: lengthened on screen along its own direction (or,
            // seen end-on, along the view's projection of its 3D direction).
            const double length = glm::length(sb - sa);
            if (length < min_pixels) {
                glm::dvec2 dir = sb - sa;
                if (length < 1e-6) dir = glm::dvec2(b.x - a.x, -(b.y - a.y));
                if (glm::length(dir) > 1e-12) sb = sa + glm::normalize(dir) * double(min_pixels);
            }
        }
        lines.push_back({sa, sb, rgba, width, dashed, arrow});
        double depth = (proj.depth(a) + proj.depth(b)) / 2;
        if (!face_edges.empty()) {
            if (auto e = face_edges.find(EdgeKey(wa, wb)); e != face_edges.end())
                depth = std::min(depth, e->second * (1 - 1e-9));
        }
        items.push_back({depth, Item::kLine, static_cast<int>(lines.size() - 1)});
        if (!label.empty())
            labels.push_back(
                {label, darker(rgba | 0xffu, 0.8f), priority, arrow ? sb : (sa + sb) / 2.0, 8});
    }

    void face(const Face3& f) {
        if (f.points.size() < 3) return;
        std::vector<glm::dvec2> screen;
        double depth = 0;
        for (glm::dvec3 p : f.points) {
            const glm::dvec3 v = proj.to_view(p);
            if (!finite(v) || proj.depth(v) < proj.near()) return;  // rare: skip, don't distort
            screen.push_back(proj.project_view(v));
            depth += proj.depth(v);
        }
        // Front side: counter-clockwise as seen, i.e. positive area with y up (screen y is down).
        double area2 = 0;
        for (std::size_t i = 0; i < screen.size(); ++i) {
            const glm::dvec2 p = screen[i], q = screen[(i + 1) % screen.size()];
            area2 += p.x * (-q.y) - (-p.y) * q.x;
        }
        const bool back = !f.two_sided && area2 < 0;
        const std::uint32_t base = back ? kBackFace : style_rgba(f.style);
        const double alpha =
            std::clamp(static_cast<double>(f.alpha) * (back ? 0.6 : 1.0), 0.0, 1.0);
        fills.push_back({std::move(screen),
                         with_alpha(base, static_cast<std::uint32_t>(alpha * 255)),
                         f.outline ? darker(base | 0xffu, back ? 0.9f : 0.75f) : 0u});
        depth /= static_cast<double>(f.points.size());
        items.push_back({depth, Item::kFill, static_cast<int>(fills.size() - 1)});
        for (std::size_t i = 0; i < f.points.size(); ++i) {
            auto [e, fresh] = face_edges.try_emplace(
                EdgeKey(f.points[i], f.points[(i + 1) % f.points.size()]), depth);
            if (!fresh) e->second = std::min(e->second, depth);
        }
    }

    void dot(glm::dvec3 w, std::uint32_t rgba, float radius, const std::string& label,
             int priority) {
        const glm::dvec3 v = proj.to_view(w);
        if (!finite(v) || proj.depth(v) < proj.near()) return;
        dots.push_back({proj.project_view(v), rgba, std::clamp(radius, 1.0f, 30.0f)});
        items.push_back({proj.depth(v), Item::kDot, static_cast<int>(dots.size() - 1)});
        if (!label.empty())
            labels.push_back(
                {label, darker(rgba, 0.8f), priority, dots.back().c, dots.back().radius + 5});
    }

    void text(glm::dvec3 w, const std::string& t, std::uint32_t rgba, int priority) {
        if (t.empty()) return;
        if (auto s = proj.screen(w)) labels.push_back({t, darker(rgba, 0.8f), priority, *s, 6});
    }

    void frame(const Frame3& f) {
        const std::uint32_t alpha =
            static_cast<std::uint32_t>(std::clamp(f.alpha, 0.0f, 1.0f) * 255);
        const glm::dvec3 axes[3] = {f.x, f.y, f.z};
        const std::uint32_t colours[3] = {kAxisX, kAxisY, kAxisZ};
        const char* names[3] = {"x", "y", "z"};
        for (int i = 0; i < 3; ++i) {
            const glm::dvec3 tip = f.origin + axes[i] * f.length;
            line(f.origin, tip, with_alpha(colours[i], alpha), 2.5f, false, true);
            text(tip, f.name.empty() ? names[i] : f.name + names[i], colours[i], 5);
        }
    }

    // The floor y = 0 as a faint grid round the target, and the world axes through the origin
    // (not when the scene draws a frame of its own there: its letters would be doubled).
    void floor_and_axes(double radius, bool axes_too) {
        const double step = nice_step(radius / 4);
        const int n = 4;
        const double cx = std::round(proj.view.target.x / step) * step;
        const double cz = std::round(proj.view.target.z / step) * step;
        for (int i = -n; i <= n; ++i) {
            const double o = i * step;
            line({cx + o, 0, cz - n * step}, {cx + o, 0, cz + n * step}, kFloor, 1.0f, false,
                 false);
            line({cx - n * step, 0, cz + o}, {cx + n * step, 0, cz + o}, kFloor, 1.0f, false,
                 false);
        }
        if (!axes_too) return;
        const double length = 2 * step;
        const glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        const std::uint32_t colours[3] = {kAxisX, kAxisY, kAxisZ};
        const char* names[3] = {"x", "y", "z"};
        for (int i = 0; i < 3; ++i) {
            line({0, 0, 0}, axes[i] * length, with_alpha(colours[i], 0x90), 1.5f, false, true);
            text(axes[i] * length, names[i], colours[i], 0);
        }
    }
};

// --- [painting] ------------------------------------------------------------------------------

void paint_fill(ImDrawList* dl, const Fill& f) {
    if (f.fill & 0xffu) {
        const std::vector<int> triangles = triangulate(f.points);
        dl->PrimReserve(static_cast<int>(triangles.size()), static_cast<int>(f.points.size()));
        const ImDrawIdx base = static_cast<ImDrawIdx>(dl->_VtxCurrentIdx);
        const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
        for (glm::dvec2 q : f.points) dl->PrimWriteVtx(im(q), uv, im_colour(f.fill));
        for (int i : triangles) dl->PrimWriteIdx(static_cast<ImDrawIdx>(base + i));
    }
    if (f.outline) {
        std::vector<ImVec2> pts;
        for (glm::dvec2 q : f.points) pts.push_back(im(q));
        dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), im_colour(f.outline),
                        ImDrawFlags_Closed, 1.5f);
    }
}

void paint_line(ImDrawList* dl, const Line& l) {
    const ImU32 colour = im_colour(l.rgba);
    const double length = glm::length(l.b - l.a);
    glm::dvec2 end = l.b;
    if (l.arrow && length > 1) {
        const double head = std::min(7.0 + 3.0 * l.width, length / 2);
        const glm::dvec2 dir = (l.b - l.a) / length, side{-dir.y, dir.x};
        const glm::dvec2 base = l.b - dir * head;
        dl->AddTriangleFilled(im(l.b), im(base + side * head * 0.45), im(base - side * head * 0.45),
                              colour);
        end = l.b - dir * head * 0.7;
    }
    if (!l.dashed) {
        dl->AddLine(im(l.a), im(end), colour, l.width);
        return;
    }
    const double total = glm::length(end - l.a), dash = 4 + 2.5 * l.width, gap = 3 + 1.5 * l.width;
    if (total == 0) return;
    const glm::dvec2 dir = (end - l.a) / total;
    for (double t = 0; t < total; t += dash + gap)
        dl->AddLine(im(l.a + dir * t), im(l.a + dir * std::min(t + dash, total)), colour, l.width);
}

void paint_dot(ImDrawList* dl, const Dot& d) {
    dl->AddCircleFilled(im(d.c), d.radius + 1.5f, IM_COL32_WHITE);
    dl->AddCircleFilled(im(d.c), d.radius, im_colour(d.rgba));
}

}  // namespace

// --- [draw_scene3] ---------------------------------------------------------------------------

void draw_scene3(ImDrawList* dl, const Projector& proj, const Scene& scene, const Fonts& fonts,
                 const std::vector<Box>& keep_clear, Recording recording) {
    Collector c{proj, {}, {}, {}, {}, {}, {}};
    const double radius = proj.view.distance * std::sin(glm::radians(proj.view.fov_y_deg) / 2);
    const bool own_origin_frame =
        std::any_of(scene.frames3.begin(), scene.frames3.end(),
                    [](const Frame3& f) { return f.name.empty() && f.origin == glm::dvec3(0); });
    c.floor_and_axes(radius, !own_origin_frame);
    const std::size_t first_scene_item = c.items.size();
    for (const Face3& f : scene.faces3) c.face(f);
    for (const Segment3& s : scene.segments3)
        c.line(s.a, s.b, style_rgba(s.style), std::clamp(s.style.width, 0.5f, 20.0f),
               s.style.dashed, s.arrow, s.label, label_priority(s.priority, s.style, 1),
               s.min_pixels);
    for (const Frame3& f : scene.frames3) c.frame(f);
    for (const Point3& p : scene.points3)
        c.dot(p.p, style_rgba(p.style), p.radius, p.label, label_priority(p.priority, p.style, 3));
    for (const Label3& l : scene.labels3)
        c.text(l.p, l.text, style_rgba(l.style), label_priority(l.priority, l.style, 2));

    // The floor and axes always lie under the scene; the scene's own items back to front.
    std::stable_sort(c.items.begin() + static_cast<std::ptrdiff_t>(first_scene_item), c.items.end(),
                     [](const Item& a, const Item& b) { return a.depth > b.depth; });
    LabelPlacer placer(proj.canvas);
    for (const Box& b : keep_clear) placer.keep_clear(b);
    for (std::size_t i = 0; i < c.items.size(); ++i) {
        const Item& it = c.items[i];
        switch (it.kind) {
            case Item::kFill:
                paint_fill(dl, c.fills[it.index]);
                break;
            case Item::kLine: {
                const Line& l = c.lines[it.index];
                paint_line(dl, l);
                if (i >= first_scene_item) placer.avoid_segment(l.a, l.b);
                break;
            }
            case Item::kDot: {
                const Dot& d = c.dots[it.index];
                paint_dot(dl, d);
                placer.avoid_box({d.c - glm::dvec2(d.radius), d.c + glm::dvec2(d.radius)});
                break;
            }
        }
    }
    const std::vector<PlacedLabel> placed = placer.place_all(
        std::move(c.labels), [&](const std::string& t) { return label_size(fonts, t); });
    paint_labels(dl, placed, placer, fonts, recording.record, recording.panel);
}

Box screen_bounds(const Projector& proj, const Focus3& f) {
    Box b{{DBL_MAX, DBL_MAX}, {-DBL_MAX, -DBL_MAX}};
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 p(i & 1 ? f.hi.x : f.lo.x, i & 2 ? f.hi.y : f.lo.y,
                           i & 4 ? f.hi.z : f.lo.z);
        if (auto s = proj.screen(p)) b.min = glm::min(b.min, *s), b.max = glm::max(b.max, *s);
    }
    if (b.min.x > b.max.x) return {{0, 0}, {0, 0}};
    return b;
}

}  // namespace cg::viewer
