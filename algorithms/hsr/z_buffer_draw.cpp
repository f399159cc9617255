// The z-buffer, the picture. In the world, in screen pixels: the colour buffer as it fills, every
// polygon's outline (dashed; the one being drawn orange) with its name, and, one pixel at a time,
// the pixel being compared with its depth z on the polygon. Beside it, an image panel: the depth
// buffer (near dark, far light, still ∞ left empty), the polygon being drawn outlined on it and
// the pixel just compared boxed green (z won: written) or red (the buffer's nearer depth stays),
// labelled with what the buffer held and holds.
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "hsr/z_buffer.hpp"

namespace cg {

namespace {

std::vector<glm::dvec2> cell(int i, int j) {
    const glm::dvec2 c(i, j);
    return {c, c + glm::dvec2(1, 0), c + glm::dvec2(1, 1), c + glm::dvec2(0, 1)};
}

std::string depth_text(double z) {
    return std::isinf(z) ? "∞" : num(z, 4);
}

}  // namespace

void ZBuffer::draw(const State& s, Scene& scene) {
    const auto& sc = s.in.scene;
    const int w = static_cast<int>(sc.width), h = static_cast<int>(sc.height);
    const double W = w, H = h;
    const Result r = result(s);

    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (const auto& p : sc.polygons)
        for (const auto& v : p.vertices) zmin = std::min(zmin, v.z), zmax = std::max(zmax, v.z);

    PixelGrid2 colour, depth;
    colour.width = depth.width = w;
    colour.height = depth.height = h;
    colour.rgba.assign(r.ids.size(), 0);
    depth.rgba.assign(r.ids.size(), 0);
    for (std::size_t a = 0; a < r.ids.size(); ++a) {
        if (r.ids[a] < 0) continue;
        colour.rgba[a] = pack_rgba(sc.polygons[static_cast<std::size_t>(r.ids[a])].color);
        const double t =
            zmax > zmin ? std::clamp((r.depth[a] - zmin) / (zmax - zmin), 0.0, 1.0) : 0.5;
        const double grey = (40 + 190 * t) / 255;  // near dark, far light
        depth.rgba[a] = pack_rgba({grey, grey, grey});
    }
    scene.grids.push_back(std::move(colour));
    scene.polygons.push_back(
        {{{0, 0}, {W, 0}, {W, H}, {0, H}}, {Role::Construction, 1.0f}, true, false});
    scene.labels.push_back({{W / 2, H + 0.6}, "colour buffer", {Role::Neutral}});
    Panel& panel =
        add_image(scene, "depth: near dark, far light, ∞ blank", std::move(depth));
    panel.weight = 1.5;  // as large as the colour buffer beside it

    // Every polygon's outline, thin; the one being drawn, thick and orange, on both buffers.
    const bool finished = s.phase == Phase::Done || s.phase == Phase::Finish;
    int current = -1;
    if (s.last == Phase::Polygon)
        current = s.k - 1;
    else if (s.last == Phase::Setup || s.last == Phase::Pixel)
        current = s.phase == Phase::Setup ? s.k - 1 : s.k;
    if (finished && s.last != Phase::Polygon && s.last != Phase::Pixel) current = -1;
    for (std::size_t k = 0; k < sc.polygons.size(); ++k) {
        std::vector<glm::dvec2> outline;
        for (const auto& v : sc.polygons[k].vertices) outline.emplace_back(v.x, v.y);
        const bool active = static_cast<int>(k) == current;
        const Style style = active ? Style{Role::Active, 3.0f} : Style{Role::Subject, 1.5f, true};
        scene.polygons.push_back({outline, style, true, false});
        if (active) {
            panel.polygons.push_back({outline, style, true, false});
            glm::dvec2 lo = outline[0], hi = outline[0];
            for (const glm::dvec2 p : outline) lo = glm::min(lo, p), hi = glm::max(hi, p);
            add_focus(scene, lo, hi);
        }
        scene.labels.push_back(
            {outline[0], "P" + std::to_string(k), {active ? Role::Active : Role::Subject}});
        for (std::size_t i = 0; i < outline.size(); ++i) {
            const std::string base =
                "/polygons/" + std::to_string(k) + "/vertices/" + std::to_string(i);
            scene.handles.push_back({outline[i],
                                     "P" + std::to_string(k) + " vertex " + std::to_string(i),
                                     base + "/0", base + "/1"});
        }
    }
    // The pixel just compared, on both buffers.
    if (s.last == Phase::Pixel) {
        const Style box{s.won ? Role::Kept : Role::Discarded, 3.0f};
        scene.polygons.push_back({cell(s.pi, s.pj), box, true, false});
        panel.polygons.push_back({cell(s.pi, s.pj), box, true, false});
        const glm::dvec2 centre(s.pi + 0.5, s.pj + 0.5);
        scene.points.push_back({centre, "z = " + num(s.z, 4), {Role::Active}, 4.0f});
        panel.points.push_back({centre,
                                s.won ? depth_text(s.z_old) + " → " + depth_text(s.z)
                                      : depth_text(s.z_old) + " stays",
                                {s.won ? Role::Kept : Role::Discarded},
                                4.0f,
                                60});
    }
}

}  // namespace cg
