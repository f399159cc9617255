// Sections: [view fitting] [interaction] [title] [views] [draw_canvas]: the title strip over
// the views the layout gives (layout.hpp) — the 2D world, the 3D view (canvas3d.cpp), the
// scene's charts and images (panel_draw.cpp).
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
#include "viewer/layout.hpp"
#include "viewer/palette.hpp"
#include "viewer/text_wrap.hpp"

namespace cg::viewer {

// --- [view fitting] --------------------------------------------------------------------------

Box bounds_of(const Layer2& layer) {
    const double inf = std::numeric_limits<double>::infinity();
    Box b{{inf, inf}, {-inf, -inf}};
    auto add = [&](glm::dvec2 p) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
    };
    for (const PixelGrid2& g : layer.grids)
        add(g.origin), add(g.origin + glm::dvec2(g.width, g.height));
    for (const Polygon2& poly : layer.polygons)
        for (glm::dvec2 p : poly.points) add(p);
    for (const Segment2& s : layer.segments) add(s.a), add(s.b);
    for (const Point2& p : layer.points) add(p.p);
    for (const Label2& l : layer.labels) add(l.p);
    for (const Handle2& h : layer.handles) add(h.p);
    return b;
}

View2 fit_view(const Layer2& layer, glm::dvec2 size, double margin) {
    return fit_box(bounds_of(layer), size, margin);
}

View2 fit_box(const Box& b, glm::dvec2 size, double margin) {
    if (b.min.x > b.max.x) return View2{};  // nothing bounded: the origin at the default zoom
    const double inf = std::numeric_limits<double>::infinity();
    const glm::dvec2 room{std::max(size.x - 2 * margin, 40.0), std::max(size.y - 2 * margin, 40.0)};
    const glm::dvec2 extent = b.max - b.min;
    double zoom = 50;
    if (extent.x > 0 || extent.y > 0)
        zoom = std::min(extent.x > 0 ? room.x / extent.x : inf,
                        extent.y > 0 ? room.y / extent.y : inf);
    return View2{(b.min + b.max) / 2.0, std::clamp(zoom, 1e-9, 1e9)};
}

// --- [interaction] ---------------------------------------------------------------------------

namespace {

constexpr double kGrabPixels = 9;  // how near the mouse must be to pick a handle up

int handle_under(const std::vector<Handle2>& handles, const ScreenMap& map, glm::dvec2 mouse) {
    int best = -1;
    double best_distance = kGrabPixels;
    for (std::size_t i = 0; i < handles.size(); ++i) {
        const glm::dvec2 d = map.to_screen(handles[i].p) - mouse;
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

// Moves `handle` to `target` (map units) rounded to a few pixels' worth, so that its input
// gets round numbers at any zoom; or, for a handle on cell centres, to the centre of the cell
// of `cells` under it. Returns false when its fields are missing (said in the status line).
bool drag_handle(Session& s, const Handle2& handle, glm::dvec2 target, const ScreenMap& map,
                 const PixelGrid2* cells = nullptr) {
    glm::dvec2 value;
    if (handle.cell_centres && cells) {
        const glm::dvec2 cell = glm::floor(target - cells->origin);
        value = cells->origin + glm::clamp(cell, glm::dvec2(0),
                                           glm::dvec2(cells->width - 1, cells->height - 1)) +
                0.5;
    } else {
        value = {snap(target.x, nice_step(5 / map.view.zoom)),
                 snap(target.y, nice_step(5 / (map.view.zoom * std::abs(map.y_scale))))};
    }
    json edited = s.input;
    if (!set_number(edited, handle.x_field, value.x) ||
        !set_number(edited, handle.y_field, value.y)) {
        s.set_status("cannot move " + handle.name + ": its input fields " + handle.x_field + ", " +
                         handle.y_field + " do not exist",
                     true);
        return false;
    }
    if (edited != s.input) s.edit(std::move(edited));  // same step, new input
    return true;
}

// The tooltip and cursor over a handle.
void show_handle(const Handle2& h) {
    ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
    ImGui::SetTooltip("%s  %s", h.name.c_str(), num(h.p).c_str());
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
    if (hot < 0 && hovered && !c.panning) hot = handle_under(scene.handles, map, mouse);
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
        if (!drag_handle(s, scene.handles[c.dragged_handle], map.to_world(mouse) + c.grab_offset,
                         map))
            c.dragged_handle = -1;
    } else if (c.panning) {
        c.view.center.x -= io.MouseDelta.x / c.view.zoom;
        c.view.center.y += io.MouseDelta.y / c.view.zoom;
    }
    if (hovered && io.MouseWheel != 0) zoom_at(c.view, map, mouse, io.MouseWheel);

    if (hot >= 0 && hot < static_cast<int>(scene.handles.size())) {
        show_handle(scene.handles[hot]);
    } else if (c.panning) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeAll);
    }
    return hot;
}

// The handles of a panel (Panel::handles; not on a log axis), `index` in Scene::panels, drawn
// in `box` by `map`: hovering one names it, the left button drags it. What is hot is kept in
// the canvas state, for the panel to draw highlighted next frame. The drag may restart the run:
// `panel` is not used after it.
void interact_panel(Session& s, const Panel& panel, int index, const Box& box,
                    const ScreenMap& map) {
    CanvasState& c = s.canvas;
    if (panel.handles.empty() || panel.x.log || panel.y.log) return;
    ImGui::PushID(index);
    ImGui::SetCursorScreenPos(im(box.min));
    ImGui::InvisibleButton("panel", im(box.max - box.min));
    ImGui::PopID();
    const glm::dvec2 mouse = dv(ImGui::GetIO().MousePos);
    const int count = static_cast<int>(panel.handles.size());
    if (!ImGui::IsItemActive() && c.panel_dragged == index) c.panel_dragged = -1;
    int hot = -1;
    if (c.panel_dragged == index)
        hot = c.panel_hot_handle < count ? c.panel_hot_handle : -1;
    else if (ImGui::IsItemHovered())
        hot = handle_under(panel.handles, map, mouse);
    if (ImGui::IsItemActivated() && hot >= 0) {
        c.panel_dragged = index;
        c.grab_offset = panel.handles[hot].p - map.to_world(mouse);
    }
    if (hot >= 0) {
        c.panel_hot = index, c.panel_hot_handle = hot;
        show_handle(panel.handles[hot]);
    } else if (c.panel_hot == index) {
        c.panel_hot = c.panel_hot_handle = -1;
    }
    if (c.panel_dragged == index && hot >= 0) {
        const Handle2 handle = panel.handles[hot];  // a copy: the run may restart
        const PixelGrid2* cells = panel.grids.empty() ? nullptr : &panel.grids.front();
        if (!drag_handle(s, handle, map.to_world(mouse) + c.grab_offset, map, cells))
            c.panel_dragged = -1;
    }
}

// --- [title] ---------------------------------------------------------------------------------

// What the picture shows, in a strip over the views, so that a saved PNG explains itself: the
// algorithm, then the step and its event; in the window also how to use the canvas, when
// there is room. The strip grows to hold a title that does not fit on one line: never cut.
struct Title {
    std::string title, detail, hint;
};

Title make_title(Session& s, bool interactive, bool three, bool world) {
    Title t;
    if (!s.algorithm) return t;
    t.title = s.algorithm->spec->title;
    const std::optional<std::size_t> n = s.length();
    t.detail = "step " + std::to_string(s.index()) + " / " + (n ? std::to_string(*n) : "?");
    if (const StepInfo* info = s.shown_step(); info && !info->event.empty())
        t.detail += "  ·  " + info->event;
    if (!s.input_error.empty()) t.detail += "  ·  input refused: showing the last good run";
    if (s.solution_hidden())  // its length would hint at the answer
        t.detail = "exam problem " + std::to_string(s.exam.problem.seed) + "  ·  solution hidden";
    if (interactive)
        t.hint = three   ? "drag: orbit  ·  right-drag: pan  ·  wheel: zoom  ·  F: frame"
                 : world ? "wheel: zoom  ·  right-drag: pan  ·  drag ■: edit  ·  F: frame"
                         : "";
    return t;
}

constexpr std::uint32_t kTitleStrip = 0xf7f8faff;
constexpr std::uint32_t kTitleRule = 0xdcdfe4ff;

// Draws the strip at the top of `canvas`; returns its height.
double draw_title(ImDrawList* dl, const Box& canvas, const Title& t, const Fonts& f,
                  LayoutRecord* record) {
    if (t.title.empty()) return 0;
    const double width = canvas.max.x - canvas.min.x, pad = 8;
    const float wrap = static_cast<float>(std::max(width - 2 * pad, 10.0));
    // Wrapped at spaces only (ImGui's wrapping also breaks after a number's point).
    const std::string title_text = wrap_at_spaces(f.ui, f.ui->FontSize, t.title, wrap);
    const std::string detail_text = wrap_at_spaces(f.small, f.small->FontSize, t.detail, wrap);
    auto size = [](ImFont* font, const std::string& s) {
        return glm::dvec2(dv(font->CalcTextSizeA(font->FontSize, FLT_MAX, 0, s.c_str())));
    };
    const glm::dvec2 title = size(f.ui, title_text);
    const glm::dvec2 detail = size(f.small, detail_text);
    const glm::dvec2 hint = size(f.small, t.hint);
    // One line when the title and the detail fit side by side, else the detail under it.
    const bool one_line = title.y <= f.ui->FontSize * 1.5 && title.x + 24 + detail.x <= wrap;
    const double height = one_line ? title.y + 2 * pad - 2 : title.y + detail.y + 2 * pad;
    const Box strip{canvas.min, {canvas.max.x, canvas.min.y + height}};
    dl->AddRectFilled(im(strip.min), im(strip.max), im_colour(kTitleStrip));
    dl->AddLine(im({strip.min.x, strip.max.y - 0.5}), im({strip.max.x, strip.max.y - 0.5}),
                im_colour(kTitleRule));
    const glm::dvec2 at = canvas.min + glm::dvec2(pad, pad - 1);
    dl->AddText(f.ui, f.ui->FontSize, im(at), im_colour(kCaptionText), title_text.c_str());
    const glm::dvec2 detail_at =
        one_line
            ? glm::dvec2(at.x + title.x + 24, at.y + (f.ui->FontSize - f.small->FontSize) / 2 + 1)
            : glm::dvec2(at.x, at.y + title.y + 1);
    dl->AddText(f.small, f.small->FontSize, im(detail_at), im_colour(kTickLabel),
                detail_text.c_str());
    // The hint, right-aligned on the last line, when it does not touch the text before it.
    const double hint_x = canvas.max.x - pad - hint.x;
    if (!t.hint.empty() && hint_x > detail_at.x + detail.x + 24)
        dl->AddText(f.small, f.small->FontSize, im({hint_x, detail_at.y}), im_colour(kHintText),
                    t.hint.c_str());
    if (record) {
        record->title = strip;
        record->title_fits = height <= canvas.max.y - canvas.min.y;
    }
    return height;
}

// --- [views] ---------------------------------------------------------------------------------

// Room kept at the bottom of the main view for the sliders drawn over it.
double sliders_height(const Session& s) {
    return s.algorithm ? (ImGui::GetFrameHeight() + 4) * double(s.algorithm->spec->sliders.size())
                       : 0;
}

// The 2D world in `box`.
ScreenMap draw_world(Session& s, const Box& box, bool interactive, Recording rec,
                     const std::vector<Box>& keep_clear) {
    const glm::dvec2 size = box.max - box.min;
    if (s.canvas.fit_pending || s.canvas.fitted_world != size) {
        const double sliders = sliders_height(s);
        // Everything the world draws: a 2D construction is framed whole (its focus elements
        // only say what must be large enough to see).
        s.canvas.view = fit_view(s.scene(), glm::max(size - glm::dvec2(0, sliders), glm::dvec2(1)));
        s.canvas.view.center.y -= sliders / 2 / s.canvas.view.zoom;
        s.canvas.fitted_world = size;
    }
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
    dl->PushClipRect(im(box.min), im(box.max), true);
    // No background of its own: the frame is cleared to the canvas's colour (kCanvasBackground)
    // before ImGui draws, and a software rasteriser pays for every pixel filled twice.
    if (scene->world_grid) draw_grid(dl, map, s.fonts);
    const Box drawn = draw_scene(dl, map, *scene, s.fonts, hot, keep_clear, s.textures, rec);
    if (rec.record) rec.record->panels[rec.panel].content = drawn;
    dl->PopClipRect();
    return map;
}

// The 3D view in `box`.
Projector draw_view3(Session& s, const Box& box, bool interactive, Recording rec,
                     const std::vector<Box>& keep_clear) {
    Camera3& camera = s.canvas.camera3;
    const glm::dvec2 size = box.max - box.min;
    if (s.canvas.fit_pending || s.canvas.fitted_3d != size) {
        camera.view = fit_view3(s.scene(), size);
        s.canvas.fitted_3d = size;
    }
    if (interactive && interact3(camera, box)) camera.view = fit_view3(s.scene(), size);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(im(box.min), im(box.max), true);
    // (The background is the frame's clear colour, as for the 2D canvas.)
    const Projector proj{box, camera.view};
    draw_scene3(dl, proj, s.scene(), s.fonts, keep_clear, rec);
    if (rec.record) rec.record->panels[rec.panel].content = box;
    dl->PopClipRect();
    return proj;
}

// The algorithm's sliders (Spec::sliders) over the main view's bottom-left corner: dragging
// one edits that number in the input and re-runs at the same step, so the construction follows
// the slider. Hidden while an exam's solution is.
void draw_sliders(Session& s, const Box& area) {
    if (!s.algorithm || s.solution_hidden()) return;
    const float row = ImGui::GetFrameHeight() + 4;
    const float width = static_cast<float>(std::min(380.0, area.max.x - area.min.x - 40));
    if (width < 80) return;
    float y = static_cast<float>(area.max.y) - 12 -
              row * static_cast<float>(s.algorithm->spec->sliders.size());
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
        const bool changed =
            ImGui::SliderScalar(("##slider" + slider.field).c_str(), ImGuiDataType_Double, &v,
                                &slider.min, &slider.max, format.c_str());
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

// Where the sliders will be, for the labels to keep clear of.
Box sliders_box(const Session& s, const Box& area) {
    const double h = sliders_height(s);
    if (h == 0 || s.solution_hidden()) return {{0, 0}, {0, 0}};
    return {{area.min.x + 6, area.max.y - 12 - h - 4},
            {area.min.x + 18 + std::min(380.0, area.max.x - area.min.x - 40), area.max.y - 6}};
}

}  // namespace

// --- [draw_canvas] ---------------------------------------------------------------------------

void draw_canvas(Session& s, bool interactive) {
    const glm::dvec2 origin = dv(ImGui::GetCursorScreenPos());
    const glm::dvec2 size = glm::max(dv(ImGui::GetContentRegionAvail()), glm::dvec2(1, 1));
    const Box canvas{origin, origin + size};
    LayoutRecord* record = s.layout_record;
    s.layout_record = nullptr;  // one frame's
    if (record) *record = LayoutRecord{}, record->canvas = canvas;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    if (!s.timeline) {
        const char* text = "Nothing to show: the input was refused (see the Input panel).";
        const glm::dvec2 at = (origin + size * 0.5) - glm::dvec2(200, 10);
        dl->AddText(s.fonts.ui, s.fonts.ui->FontSize, im(at), im_colour(kErrorText), text);
        return;
    }
    const Scene& scene = s.scene();
    Box area = canvas;
    area.min.y +=
        draw_title(dl, canvas, make_title(s, interactive, scene.has_3d(), shows_world(scene)),
                   s.fonts, record);
    const std::vector<ViewSlot> views = layout_views(scene, area, 6, [&](const Panel& p, double w) {
        return panel_header_height(p, w, s.fonts);
    });
    if (record)
        for (const ViewSlot& v : views) record->panels.push_back({v.kind, v.box, v.box});

    // The main view holds the sliders; labels keep clear of them.
    const Box main = views.empty() ? area : views.front().box;
    const std::vector<Box> keep_clear{sliders_box(s, main)};
    std::optional<ScreenMap> world_map;
    std::optional<Projector> proj;
    std::vector<ScreenMap> panel_maps(scene.panels.size());
    std::size_t texture_slot = scene.grids.size();  // the world's grids come first
    for (std::size_t i = 0; i < views.size(); ++i) {
        const ViewSlot& v = views[i];
        const Recording rec{record, static_cast<int>(i)};
        const std::vector<Box> clear =
            v.box.overlaps(keep_clear.front()) ? keep_clear : std::vector<Box>{};
        switch (v.kind) {
            case ViewKind::World2d:
                world_map = draw_world(s, v.box, interactive, rec, clear);
                break;
            case ViewKind::View3d:
                proj = draw_view3(s, v.box, interactive, rec, clear);
                break;
            case ViewKind::Chart:
            case ViewKind::Image:
            case ViewKind::Diagram: {
                const Panel& p = scene.panels[v.panel];
                const int hot = s.canvas.panel_hot == v.panel ? s.canvas.panel_hot_handle : -1;
                panel_maps[v.panel] =
                    draw_panel(dl, v.box, p, s.fonts, s.textures, texture_slot, rec, hot);
                if (s.record_widgets)  // where each handle is, for the GUI tests to grab
                    for (const Handle2& h : p.handles) {
                        const glm::dvec2 at = panel_maps[v.panel].to_screen(h.p);
                        s.widgets["handle:" + h.name] = {
                            {at - glm::dvec2(4), at + glm::dvec2(4)}, v.box, v.box.contains(at)};
                    }
                texture_slot += p.grids.size();
                break;
            }
        }
    }
    s.canvas.fit_pending = false;
    if (record) {
        // The focus elements where they landed on screen.
        auto index_of = [&](ViewKind kind, int panel) {
            for (std::size_t i = 0; i < views.size(); ++i)
                if (views[i].kind == kind && views[i].panel == panel) return static_cast<int>(i);
            return -1;
        };
        for (const Focus2& f : scene.focus2) {
            const bool in_world = f.panel < 0;
            if (in_world && !world_map) continue;
            if (!in_world && f.panel >= static_cast<int>(scene.panels.size())) continue;
            const ScreenMap& map = in_world ? *world_map : panel_maps[f.panel];
            const glm::dvec2 a = map.to_screen(f.lo), b = map.to_screen(f.hi);
            const int at = in_world ? index_of(ViewKind::World2d, -1)
                                    : index_of(view_kind(scene.panels[f.panel]), f.panel);
            record->focus.push_back({{glm::min(a, b), glm::max(a, b)}, at});
        }
        if (proj)
            for (const Focus3& f : scene.focus3)
                record->focus.push_back({screen_bounds(*proj, f), index_of(ViewKind::View3d, -1)});
    }
    // Last, as a drag restarts the run and `scene` with it.
    if (interactive)
        for (const ViewSlot& v : views)
            if (v.panel >= 0 && v.panel < static_cast<int>(s.scene().panels.size()))
                interact_panel(s, s.scene().panels[v.panel], v.panel, v.box, panel_maps[v.panel]);
    draw_sliders(s, main);
}

}  // namespace cg::viewer
