// Shading, the picture. The world is the image plane, in pixels: the run's image so far (top
// left) with the mesh's edges, the triangle being drawn, its current span and the span's ends,
// the chosen pixel and its row, and the vertices to drag; beside it the other two models'
// finished images (top right, bottom left) with the same row and pixel marked. A chart beside
// the world plots the intensity (r + g + b)/3 along the chosen row for every model — flat's
// steps (the Mach bands' cause), Gouraud's kinks, Phong's highlight — with the pixel's column.
#include <algorithm>
#include <cmath>

#include "clipping/liang_barsky.hpp"
#include "core/format.hpp"
#include "shading/shading.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Color = Shading::Color;
using Input = Shading::Input;
using Model = Shading::Model;
using Phase = Shading::Phase;
using Sample = Shading::Sample;

dvec2 xy(dvec3 p) {
    return {p.x, p.y};
}

std::string vname(int v) {
    return "V" + std::to_string(v);
}

}  // namespace

namespace {

// What the eye reads: the mean of the clamped channels.
double intensity(Color c) {
    return (std::clamp(c.r, 0.0, 1.0) + std::clamp(c.g, 0.0, 1.0) + std::clamp(c.b, 0.0, 1.0)) / 3;
}

constexpr long long kComparisonPixels = 128 * 128;  // larger images are not compared
constexpr std::uint32_t kBackground = Shading::kBackground;

// The world's layout, cells the image's size: the run's image top left, the other two models
// top right and bottom left (the intensity profile is a chart beside them).
struct Layout {
    double W = 0, H = 0, gap = 0;
    dvec2 origin(int slot) const {  // slot 0, 1, 2: the images
        return {slot % 2 ? W + gap : 0.0, slot / 2 ? -H - gap : 0.0};
    }
};

// Slot 0 is the run; the other two models follow in the course's order.
std::array<Model, 3> slots(Model current) {
    std::array<Model, 3> out{current, current, current};
    int n = 1;
    for (Model m : {Model::Flat, Model::Gouraud, Model::Phong})
        if (m != current) out[n++] = m;
    return out;
}

Role model_role(Model m) {
    switch (m) {
        case Model::Flat:
            return Role::Leaving;
        case Model::Gouraud:
            return Role::Entering;
        case Model::Phong:
            return Role::Kept;
    }
    return Role::Neutral;
}

void fill_comparison(const Shading::State& s, Shading::Comparison& c) {
    const Input& in = *s.in;
    if (in.width * in.height > kComparisonPixels) return;
    for (Model m : {Model::Flat, Model::Gouraud, Model::Phong}) {
        if (m == in.model) continue;
        Input other = in;
        other.model = m;
        Shading::Result r;
        try {
            r = Shading::render(other);
        } catch (const InputError&) {
            continue;  // (a zero vertex normal: only flat has no use for the normals)
        }
        auto& rgba = c.rgba[static_cast<int>(m)];
        rgba.resize(static_cast<std::size_t>(r.width) * r.height);
        for (int j = 0; j < r.height; ++j)
            for (int i = 0; i < r.width; ++i) {
                const Sample& p = r.at(i, j);
                rgba[static_cast<std::size_t>(j) * r.width + i] =
                    p.triangle < 0 ? kBackground : pack_rgba(p.color);
            }
        auto& profile = c.profile[static_cast<int>(m)];
        for (int i = 0; i < r.width; ++i) {
            const Sample& p = r.at(i, s.pixel_j);
            profile.push_back(p.triangle < 0 ? -1.0 : intensity(p.color));
        }
    }
}

Polygon2 rectangle(dvec2 lo, dvec2 hi, Style style) {
    return {{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, style, true, false};
}

// The mesh's edges over an image whose origin is o, clipped to it.
void mesh_edges(const Input& in, dvec2 o, Scene& scene) {
    if (in.mesh.triangles.size() > 400) return;
    for (const auto& t : in.mesh.triangles)
        for (int m = 0; m < 3; ++m) {
            dvec2 a = xy(in.mesh.vertices[t[m]]), b = xy(in.mesh.vertices[t[(m + 1) % 3]]);
            if (LiangBarsky::clip_segment({0, 0, double(in.width), double(in.height)}, a, b))
                scene.segments.push_back({o + a, o + b, "", {Role::Construction, 1.0f}, false});
        }
}

void image_frame(const Layout& L, int slot, int pixel_i, int pixel_j, const std::string& title,
                 Role role, Scene& scene) {
    const dvec2 o = L.origin(slot);
    scene.polygons.push_back(rectangle(o, o + dvec2(L.W, L.H), {Role::Construction, 1.0f}));
    scene.labels.push_back({o + dvec2(0, L.H + 0.2), title, {role}});
    // The chosen row, and the chosen pixel.
    scene.polygons.push_back(rectangle(o + dvec2(0, pixel_j), o + dvec2(L.W, pixel_j + 1.0),
                                       {Role::Window, 1.0f, true}));
    scene.polygons.push_back(rectangle(o + dvec2(pixel_i, pixel_j),
                                       o + dvec2(pixel_i + 1.0, pixel_j + 1.0),
                                       {Role::Active, 2.0f}));
}

// The intensity along the chosen row, in the chart: one polyline per model, broken where a pixel
// is uncovered, named once in the legend.
void profile_line(Panel& chart, const std::vector<double>& values, Model m, bool current) {
    const Style style{model_role(m), current ? 3.0f : 1.5f, !current && m == Model::Flat};
    bool named = false;
    std::vector<dvec2> run;
    auto flush = [&] {
        if (run.size() == 1) run.push_back(run[0] + dvec2(0.5, 0));
        if (run.size() >= 2) {
            add_line(chart, run, style,
                     named ? std::string()
                           : Shading::model_name(m) + (current ? " (this run)" : ""));
            named = true;
        }
        run.clear();
    };
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (values[i] < 0) {
            flush();
            continue;
        }
        run.push_back({i + 0.5, values[i]});
    }
    flush();
}

}  // namespace

void Shading::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const int w = s.image.width(), h = s.image.height();
    Layout L;
    L.W = w, L.H = h;
    L.gap = std::max(3.0, std::round(0.15 * std::max(w, h)));
    const auto order = slots(in.model);
    const bool compare = in.width * in.height <= kComparisonPixels;
    if (compare) std::call_once(s.comparison.p->once, [&] { fill_comparison(s, *s.comparison.p); });
    const Comparison& cmp = *s.comparison.p;

    // The run's image so far.
    PixelGrid2 grid;
    grid.width = w, grid.height = h;
    grid.rgba.resize(static_cast<std::size_t>(w) * h);
    std::vector<double> profile(static_cast<std::size_t>(w), -1.0);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const Sample& p = s.image.at(i, j);
            grid.rgba[static_cast<std::size_t>(j) * w + i] =
                p.triangle < 0 ? kBackground : pack_rgba(p.color);
            if (j == s.pixel_j && p.triangle >= 0) profile[i] = intensity(p.color);
        }
    grid.grid_lines = w * h <= 16 * 16;  // cell borders for the small (exam) images
    scene.grids.push_back(std::move(grid));
    image_frame(L, 0, s.pixel_i, s.pixel_j, Shading::model_name(in.model) + " shading (this run)",
                model_role(in.model), scene);
    mesh_edges(in, {0, 0}, scene);

    // The other two models, finished.
    if (compare)
        for (int slot = 1; slot < 3; ++slot) {
            const Model m = order[slot];
            const auto& rgba = cmp.rgba[static_cast<int>(m)];
            if (rgba.empty()) continue;
            PixelGrid2 g;
            g.origin = L.origin(slot);
            g.width = w, g.height = h;
            g.rgba = rgba;
            g.grid_lines = false;
            scene.grids.push_back(std::move(g));
            image_frame(L, slot, s.pixel_i, s.pixel_j, Shading::model_name(m) + " shading (finished)",
                        model_role(m), scene);
            mesh_edges(in, L.origin(slot), scene);
        }

    // The intensity profile along the chosen row: a chart over the image's columns, 0 to 1, the
    // chosen pixel's column dashed orange (the others first, this run on top).
    Panel& chart = add_chart(scene, "intensity along row " + std::to_string(s.pixel_j),
                             Axis{"column i", 0, double(w)}, Axis{"(r + g + b)/3", 0, 1});
    chart.weight = 0.8;  // the images keep the larger share
    chart.segments.push_back(
        {{s.pixel_i + 0.5, 0}, {s.pixel_i + 0.5, 1}, "", {Role::Active, 1.0f, true}, false});
    if (compare)
        for (int slot = 2; slot >= 1; --slot) {
            const Model m = order[slot];
            if (!cmp.profile[static_cast<int>(m)].empty())
                profile_line(chart, cmp.profile[static_cast<int>(m)], m, false);
        }
    profile_line(chart, profile, in.model, true);
    if (!chart.legend.empty() && chart.legend.back().style.width > 2.5f)  // this run first
        std::rotate(chart.legend.begin(), chart.legend.end() - 1, chart.legend.end());

    // The triangle being drawn, its current span and the span's ends.
    const bool finished = s.phase == Phase::Done;
    if (!finished && s.face.k >= 0 && s.last != Phase::Normals && s.last != Phase::VertexColors) {
        std::vector<dvec2> tri;
        for (const dvec3& p : s.face.p) tri.push_back(xy(p));
        scene.polygons.push_back({tri, {Role::Active, 2.0f}, true, false});
        if ((s.last == Phase::Span || s.last == Phase::Pixel) && s.i_first < s.i_end) {
            const double y = s.j + 0.5;
            scene.polygons.push_back(rectangle({double(s.i_first), double(s.j)},
                                               {double(s.i_end), s.j + 1.0}, {Role::Active, 2.5f}));
            scene.points.push_back(
                {{std::clamp(s.x_left, -1.0, L.W + 1), y}, "", {Role::Entering}, 4.0f});
            scene.points.push_back(
                {{std::clamp(s.x_right, -1.0, L.W + 1), y}, "", {Role::Leaving}, 4.0f});
        }
    }
    if (s.last == Phase::Pixel && !finished)
        scene.points.push_back(
            {{s.pixel_i + 0.5, s.pixel_j + 0.5},
             "(" + std::to_string(s.pixel_i) + ", " + std::to_string(s.pixel_j) + ")",
             {Role::Active},
             5.0f});

    // The vertices: names when few, handles to drag.
    const std::size_t n = in.mesh.vertices.size();
    for (std::size_t v = 0; v < n && n <= 400; ++v) {
        const dvec3 p = in.mesh.vertices[v];
        if (n <= 12) scene.labels.push_back({xy(p), vname(static_cast<int>(v)), {Role::Neutral}});
        const std::string V = std::to_string(v);
        scene.handles.push_back({xy(p), vname(static_cast<int>(v)), "/mesh/vertices/" + V + "/0",
                                 "/mesh/vertices/" + V + "/1"});
    }
}

}  // namespace cg
