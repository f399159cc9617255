// Sections: [view fitting] [interaction] [caption] [draw_canvas]: the 2D canvas, the 3D one
// (canvas3d.cpp), or both side by side.
#include "viewer/canvas.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/common.hpp>
#include <limits>
#include <string>

#include "core/format.hpp"
#include "viewer/canvas3d.hpp"
#include "viewer/canvas_draw.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/palette.hpp"

namespace cg::viewer {

// --- [view fitting] --------------------------------------------------------------------------

View2 fit_view(const Scene& scene, glm::dvec2 size) {
    const double inf = std::numeric_limits<double>::infinity();
    glm::dvec2 lo{inf, inf}, hi{-inf, -inf};
    auto add = [&](glm::dvec2 p) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    };
    for (const PixelGrid2& g : scene.grids)
        add(g.origin), add(g.origin + glm::dvec2(g.width, g.height));
    for (const Polygon2& poly : scene.polygons)
        for (glm::dvec2 p : poly.points) add(p);
    for (const Segment2& s : scene.segments) add(s.a), add(s.b);
    for (const Point2& p : scene.points) add(p.p);
    for (const Label2& l : scene.labels) add(l.p);
    for (const Handle2& h : scene.handles) add(h.p);
    if (lo.x > hi.x) return View2{};  // nothing bounded: the origin at the default zoom

    // Margins in pixels: room for labels beside the geometry, and for the caption on top.
    constexpr double kSide = 60, kTop = 80, kBottom = 45;
    const glm::dvec2 room{std::max(size.x - 2 * kSide, 40.0),
                          std::max(size.y - kTop - kBottom, 40.0)};
    const glm::dvec2 extent = hi - lo;
    double zoom = 50;
    if (extent.x > 0 || extent.y > 0)
        zoom = std::min(extent.x > 0 ? room.x / extent.x : inf,
                        extent.y > 0 ? room.y / extent.y : inf);
    zoom = std::clamp(zoom, 1e-9, 1e9);
    // Centre the geometry in the room left between the margins (the caption's is larger).
    glm::dvec2 centre = (lo + hi) / 2.0;
    centre.y += (kTop - kBottom) / 2 / zoom;
    return View2{centre, zoom};
}

// --- [interaction] ---------------------------------------------------------------------------

namespace {

constexpr double kGrabPixels = 9;  // how near the mouse must be to pick a handle up

int handle_under(const Scene& scene, const ScreenMap& map, glm::dvec2 mouse) {
    int best = -1;
    double best_distance = kGrabPixels;
    for (std::size_t i = 0; i < scene.handles.size(); ++i) {
        const glm::dvec2 d = map.to_screen(scene.handles[i].p) - mouse;
        const double distance = std::max(std::abs(d.x), std::abs(d.y));
        if (distance <= best_distance) best = static_cast<int>(i), best_distance = distance;
    }
    return best;
}

// Rounds to `step` and then to the decimal digits that step has, so the input gets 2.3 and
// not 2.3000000000000003.
double snap(double v, double step) {
    const int digits = std::clamp(static_cast<int>(-std::floor(std::log10(step))), 0, 15);
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, std::round(v / step) * step);
    return std::strtod(text, nullptr);
}

// Writes a number at a JSON pointer that must already exist; whole numbers stay integers.
bool set_number(json& input, const std::string& pointer, double v) {
    try {
        json& field = input.at(json::json_pointer(pointer));
        if (v == std::floor(v) && std::abs(v) < 1e15)
            field = static_cast<long long>(v);
        else
            field = v;
        return true;
    } catch (const json::exception&) {
        return false;
    }
}

void drag_handle(Session& s, const Handle2& handle, glm::dvec2 target, double zoom) {
    const double step = nice_step(5 / zoom);  // a few pixels: round numbers at any zoom
    json edited = s.input;
    if (!set_number(edited, handle.x_field, snap(target.x, step)) ||
        !set_number(edited, handle.y_field, snap(target.y, step))) {
        s.set_status("cannot move " + handle.name + ": its input fields " + handle.x_field + ", " +
                         handle.y_field + " do not exist",
                     true);
        s.canvas.dragged_handle = -1;
        return;
    }
    if (edited != s.input) s.edit(std::move(edited));  // same step, new input
}

void zoom_at(View2& view, const ScreenMap& map, glm::dvec2 mouse, float wheel) {
    const glm::dvec2 before = map.to_world(mouse);
    view.zoom = std::clamp(view.zoom * std::pow(1.2, wheel), 1e-9, 1e9);
    const glm::dvec2 after = ScreenMap{map.canvas, view}.to_world(mouse);
    view.center += before - after;  // the point under the mouse stays put
}

// Returns the handle to highlight (hovered or dragged), or -1.
int interact(Session& s, const Scene& scene, const ScreenMap& map) {
    CanvasState& c = s.canvas;
    ImGui::SetCursorScreenPos(im(map.canvas.min));
    ImGui::InvisibleButton("canvas", im(map.canvas.max - map.canvas.min),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    ImGui::SetItemAllowOverlap();  // the sliders drawn over the canvas take their clicks
    const ImGuiIO& io = ImGui::GetIO();
    const glm::dvec2 mouse = dv(io.MousePos);
    const bool hovered = ImGui::IsItemHovered();

    if (!ImGui::IsItemActive()) c.dragged_handle = -1, c.panning = false;
    int hot = c.dragged_handle;
    if (hot < 0 && hovered && !c.panning) hot = handle_under(scene, map, mouse);
    if (ImGui::IsItemActivated()) {
        // The left button on a handle drags it; any other press pans.
        if (io.MouseClicked[ImGuiMouseButton_Left] && hot >= 0) {
            c.dragged_handle = hot;
            c.grab_offset = scene.handles[hot].p - map.to_world(mouse);
        } else {
            c.panning = true;
        }
    }

    if (c.dragged_handle >= 0 && c.dragged_handle < static_cast<int>(scene.handles.size())) {
        drag_handle(s, scene.handles[c.dragged_handle], map.to_world(mouse) + c.grab_offset,
                    map.view.zoom);
    } else if (c.panning) {
        c.view.center.x -= io.MouseDelta.x / c.view.zoom;
        c.view.center.y += io.MouseDelta.y / c.view.zoom;
    }
    if (hovered && io.MouseWheel != 0) zoom_at(c.view, map, mouse, io.MouseWheel);

    if (hot >= 0 && hot < static_cast<int>(scene.handles.size())) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
        const Handle2& h = scene.handles[hot];
        ImGui::SetTooltip("%s  %s", h.name.c_str(), num(h.p).c_str());
    } else if (c.panning) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeAll);
    }
    return hot;
}

// --- [caption] -------------------------------------------------------------------------------

// What the picture shows, in its top-left corner, so that a saved PNG explains itself; in the
// window also how to use the canvas.
struct Caption {
    std::string title, detail, hint;
    Box box{{0, 0}, {0, 0}};
};

Caption make_caption_box(Caption c, const ScreenMap& map, const Fonts& f);

Caption make_caption(const ScreenMap& map, Session& s, bool interactive) {
    Caption c;
    if (!s.algorithm) return c;
    c.title = s.algorithm->spec->title;
    const std::optional<std::size_t> n = s.length();
    c.detail = "step " + std::to_string(s.index()) + " / " + (n ? std::to_string(*n) : "?");
    if (const StepInfo* info = s.shown_step(); info && !info->event.empty())
        c.detail += "  ·  " + info->event;
    if (!s.input_error.empty()) c.detail += "  ·  input refused: showing the last good run";
    if (s.solution_hidden())  // its length would hint at the answer
        c.detail = "exam problem " + std::to_string(s.exam.problem.seed) + "  ·  solution hidden";
    // (Not on a narrow canvas, half of Compare's: it would run past the edge.)
    if (interactive && map.canvas.max.x - map.canvas.min.x >= 560)
        c.hint = "wheel: zoom  ·  right-drag: pan  ·  drag ■ to edit the input";
    return make_caption_box(c, map, s.fonts);
}

// Sizes the caption's box for its text, in the canvas's top-left corner.
Caption make_caption_box(Caption c, const ScreenMap& map, const Fonts& f) {
    double width = f.ui->CalcTextSizeA(f.ui->FontSize, FLT_MAX, 0, c.title.c_str()).x;
    double height = f.ui->FontSize + 12;
    for (const std::string* line : {&c.detail, &c.hint}) {
        if (line->empty()) continue;
        width = std::max<double>(
            width, f.small->CalcTextSizeA(f.small->FontSize, FLT_MAX, 0, line->c_str()).x);
        height += f.small->FontSize + 2;
    }
    c.box.min = map.canvas.min + glm::dvec2(10, 10);
    c.box.max = c.box.min + glm::dvec2(width + 16, height);
    return c;
}

void draw_caption(ImDrawList* dl, const Caption& c, const Fonts& f) {
    if (c.title.empty()) return;
    dl->AddRectFilled(im(c.box.min), im(c.box.max), IM_COL32(255, 255, 255, 230), 4.0f);
    dl->AddRect(im(c.box.min), im(c.box.max), IM_COL32(0, 0, 0, 40), 4.0f);
    glm::dvec2 at = c.box.min + glm::dvec2(8, 5);
    dl->AddText(f.ui, f.ui->FontSize, im(at), im_colour(kCaptionText), c.title.c_str());
    at.y += f.ui->FontSize + 2;
    dl->AddText(f.small, f.small->FontSize, im(at), im_colour(kTickLabel), c.detail.c_str());
    at.y += f.small->FontSize + 2;
    if (!c.hint.empty())
        dl->AddText(f.small, f.small->FontSize, im(at), im_colour(kHintText), c.hint.c_str());
}

}  // namespace

// --- [draw_canvas] ---------------------------------------------------------------------------

namespace {

// The 2D canvas in `box`; returns the caption's box so the 3D canvas can keep clear of it.
void draw_canvas2d(Session& s, const Box& box, bool interactive, bool with_caption) {
    const Scene* scene = &s.scene();
    ScreenMap map{box, s.canvas.view};
    int hot = -1;
    if (interactive) {
        hot = interact(s, *scene, map);
        scene = &s.scene();  // a dragged handle may have restarted the run
        map.view = s.canvas.view;
        if (hot >= static_cast<int>(scene->handles.size())) hot = -1;
    }
    if (s.record_widgets)  // where each handle is, for the GUI tests to grab
        for (const Handle2& h : scene->handles) {
            const glm::dvec2 at = map.to_screen(h.p);
            const Box spot{at - glm::dvec2(4), at + glm::dvec2(4)};
            s.widgets["handle:" + h.name] = {spot, map.canvas, map.canvas.contains(at)};
        }

    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(im(map.canvas.min), im(map.canvas.max), true);
    // No background of its own: the frame is cleared to the canvas's colour (kCanvasBackground)
    // before ImGui draws, and a software rasteriser pays for every pixel filled twice.
    draw_grid(dl, map, s.fonts);
    Caption caption;
    if (with_caption) caption = make_caption(map, s, interactive);
    draw_scene(dl, map, *scene, s.fonts, hot, {caption.box.grown(4)}, s.textures);
    if (with_caption) draw_caption(dl, caption, s.fonts);
    dl->PopClipRect();
}

void draw_canvas3d(Session& s, const Box& box, bool interactive) {
    Camera3& camera = s.canvas.camera3;
    if (interactive && interact3(camera, box)) camera.view = fit_view3(s.scene(), box.max - box.min);
    const Scene& scene = s.scene();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(im(box.min), im(box.max), true);
    // (The background is the frame's clear colour, as for the 2D canvas.)
    ScreenMap map{box, s.canvas.view};
    Caption caption = make_caption(map, s, false);
    if (interactive && box.max.x - box.min.x >= 560)
        caption.hint = "drag: orbit (arcball)  ·  right-drag: pan  ·  wheel: zoom  ·  double-click: reset";
    caption = make_caption_box(caption, map, s.fonts);
    draw_scene3(dl, Projector{box, camera.view}, scene, s.fonts, {caption.box.grown(4)});
    draw_caption(dl, caption, s.fonts);
    dl->PopClipRect();
}

// The algorithm's sliders (Spec::sliders) over the canvas's bottom-left corner: dragging one
// edits that number in the input and re-runs at the same step, so the construction follows
// the slider. Hidden while an exam's solution is.
void draw_sliders(Session& s, const Box& area) {
    if (!s.algorithm || s.solution_hidden()) return;
    const float row = ImGui::GetFrameHeight() + 4;
    const float width = static_cast<float>(std::min(380.0, area.max.x - area.min.x - 40));
    if (width < 80) return;
    float y = static_cast<float>(area.max.y) - 12 - row * static_cast<float>(s.algorithm->spec->sliders.size());
    for (const Slider& slider : s.algorithm->spec->sliders) {
        const json::json_pointer pointer(slider.field);
        if (!s.input.contains(pointer) || !s.input.at(pointer).is_number()) continue;
        double v = s.input.at(pointer).get<double>();
        const ImVec2 at(static_cast<float>(area.min.x) + 12, y);
        ImDrawList* dl = ImGui::GetWindowDrawList();
        dl->AddRectFilled(ImVec2(at.x - 4, at.y - 3), ImVec2(at.x + width + 4, at.y + row - 1),
                          IM_COL32(255, 255, 255, 235), 4.0f);
        dl->AddRect(ImVec2(at.x - 4, at.y - 3), ImVec2(at.x + width + 4, at.y + row - 1),
                    im_colour(kNoteAccent), 4.0f);
        ImGui::SetCursorScreenPos(at);
        ImGui::SetNextItemWidth(width);
        ImGui::PushStyleColor(ImGuiCol_FrameBg, im_vec4(kNoteBackground));
        const std::string format = slider.label + " = %.3f";
        const bool changed = ImGui::SliderScalar(("##slider" + slider.field).c_str(),
                                                 ImGuiDataType_Double, &v, &slider.min,
                                                 &slider.max, format.c_str());
        ImGui::PopStyleColor();
        if (changed) {
            // Four significant digits: the input reads 0.35, not 0.35000000000000003.
            char text[32];
            std::snprintf(text, sizeof text, "%.4g", v);
            json edited = s.input;
            edited[pointer] = std::strtod(text, nullptr);
            if (edited != s.input) s.edit(std::move(edited));
        }
        y += row;
    }
}

}  // namespace

void draw_canvas(Session& s, bool interactive) {
    const glm::dvec2 origin = dv(ImGui::GetCursorScreenPos());
    const glm::dvec2 size = glm::max(dv(ImGui::GetContentRegionAvail()), glm::dvec2(1, 1));
    const Scene& scene = s.scene();
    // A scene with 3D content gets the 3D canvas; with 2D content as well (a plot, the
    // viewport's disc), the two side by side: 3D on the left, 2D on the right.
    const bool three = scene.has_3d(), two = !three || scene.has_2d();
    Box box2{origin, origin + size}, box3 = box2;
    if (three && two) {
        const double split = std::round(size.x * 0.58);
        box3.max.x = origin.x + split;
        box2.min.x = origin.x + split + 2;
    }
    if (s.canvas.fit_pending && size.x > 16 && size.y > 16) {
        if (two) {
            // Room at the bottom for the sliders drawn over the canvas.
            const double sliders =
                s.algorithm ? (ImGui::GetFrameHeight() + 4) * s.algorithm->spec->sliders.size() : 0;
            const glm::dvec2 room = box2.max - box2.min - glm::dvec2(0, sliders);
            s.canvas.view = fit_view(scene, glm::max(room, glm::dvec2(1, 1)));
            s.canvas.view.center.y -= sliders / 2 / s.canvas.view.zoom;
        }
        if (three) s.canvas.camera3.view = fit_view3(scene, box3.max - box3.min);
        s.canvas.fit_pending = false;
    }
    if (three) draw_canvas3d(s, box3, interactive);
    if (two) draw_canvas2d(s, box2, interactive, !three);
    draw_sliders(s, two ? box2 : box3);
    if (!s.timeline) {
        ImDrawList* dl = ImGui::GetWindowDrawList();
        const char* text = "Nothing to show: the input was refused (see the Input panel).";
        const glm::dvec2 at = (origin + size * 0.5) - glm::dvec2(200, 10);
        dl->AddText(s.fonts.ui, s.fonts.ui->FontSize, im(at), im_colour(kErrorText), text);
    }
}

}  // namespace cg::viewer
