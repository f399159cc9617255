// Sections: [helpers] [spec] [advance] [narrate] [result and render] [draw]
#include "hsr/warnock.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "core/format.hpp"
#include "raster/orient2d.hpp"

namespace cg {

namespace {

using glm::dvec2;
using Class = Warnock::Class;
using Outcome = Warnock::Outcome;
using Area = Warnock::Area;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLinePush = 1,
    kLinePop,
    kLineClassify,
    kLineDrop,
    kLineEmpty,
    kLineSingle,
    kLineSurrounder,
    kLinePixel,
    kLineSplit,
    kLineDone,
};

constexpr const char* kClassName[] = {"surrounding", "intersecting", "contained", "disjoint"};
constexpr int kUndecided = -2;

// hsr::covers for a counter-clockwise outline: inside every edge, on an edge only when it is a
// left edge (going down) or a top edge (horizontal, going −x): the top-left rule.
bool covers_ccw(const std::vector<dvec2>& v, double x, double y) {
    const dvec2 c{x, y};
    const std::size_t n = v.size();
    for (std::size_t k = 0; k < n; ++k) {
        const dvec2 a = v[k], b = v[(k + 1) % n];
        const int o = orient2d(a, b, c);
        if (o < 0) return false;
        if (o == 0 && !(b.y < a.y || (b.y == a.y && b.x < a.x))) return false;
    }
    return true;
}

// How far depth_at may be off by rounding, as a margin: relative to the size of the terms.
double rounding_scale(const hsr::Plane& p, double W, double H) {
    return (std::fabs(p.a) * W + std::fabs(p.b) * H + std::fabs(p.d)) / std::fabs(p.c);
}

// Is polygon s strictly nearer than polygon q at all four corners of the area (with margin)?
bool nearer_at_corners(const hsr::Plane& s, const hsr::Plane& q, const Area& a, double W, double H) {
    const double margin = 1e-9 * (1 + rounding_scale(s, W, H) + rounding_scale(q, W, H));
    const double xs[2] = {double(a.x), double(a.x + a.w)}, ys[2] = {double(a.y), double(a.y + a.h)};
    for (double x : xs)
        for (double y : ys)
            if (!(hsr::depth_at(q, x, y) - hsr::depth_at(s, x, y) > margin)) return false;
    return true;
}

// What an area's examination needs, as plain references: shared by the state machine and the
// straight-line render().
struct Examiner {
    const Warnock::Input& in;
    const std::vector<hsr::Plane>& planes;
    const std::vector<std::vector<dvec2>>& outlines;
    std::vector<int>& ids;

    void fill(const Area& a, int id) {
        const std::size_t W = static_cast<std::size_t>(in.scene.width);
        for (int j = a.y; j < a.y + a.h; ++j)
            std::fill_n(ids.begin() + static_cast<std::ptrdiff_t>(j * W + a.x), a.w, id);
    }
    void fill_covered(const Area& a, int id) {
        const std::size_t W = static_cast<std::size_t>(in.scene.width);
        for (int j = a.y; j < a.y + a.h; ++j)
            for (int i = a.x; i < a.x + a.w; ++i)
                ids[j * W + i] = covers_ccw(outlines[id], i + 0.5, j + 0.5) ? id : -1;
    }
    int nearest_at(const int* list, std::size_t count, int i, int j) const {
        int best = -1;
        double best_z = 0;
        for (std::size_t k = 0; k < count; ++k) {
            const int id = list[k];
            if (!covers_ccw(outlines[id], i + 0.5, j + 0.5)) continue;
            const double z = hsr::depth_at(planes[id], i + 0.5, j + 0.5);
            if (best < 0 || hsr::in_front(z, id, best_z, best)) best = id, best_z = z;
        }
        return best;
    }
    // The surrounding polygon in front of all others over the area, or −1.
    int surrounder(const int* list, const Class* classes, std::size_t count, const Area& a) const {
        const double W = double(in.scene.width), H = double(in.scene.height);
        for (std::size_t k = 0; k < count; ++k) {
            if (classes[k] != Class::Surrounding) continue;
            bool front = true;
            for (std::size_t q = 0; q < count && front; ++q)
                if (q != k) front = nearer_at_corners(planes[list[k]], planes[list[q]], a, W, H);
            if (front) return list[k];
        }
        return -1;
    }
    // Decide a simple area (drawing it), or say Split. `list` holds the non-disjoint polygons.
    Outcome decide(const Area& a, const int* list, const Class* classes, std::size_t count, int& drawn) {
        drawn = -1;
        if (count == 0) {
            fill(a, -1);
            return Outcome::Empty;
        }
        if (count == 1) {
            drawn = list[0];
            fill_covered(a, drawn);
            return Outcome::Single;
        }
        if ((drawn = surrounder(list, classes, count, a)) >= 0) {
            fill(a, drawn);
            return Outcome::Surrounder;
        }
        if (a.w == 1 && a.h == 1) {
            drawn = nearest_at(list, count, a.x, a.y);
            ids[static_cast<std::size_t>(a.y * in.scene.width + a.x)] = drawn;
            return Outcome::Pixel;
        }
        return Outcome::Split;
    }
};

// The four (or two) quarters in the order they are examined: bottom-left, bottom-right,
// top-left, top-right.
int children(const Area& a, Area out[4]) {
    const int wl = a.w > 1 ? a.w / 2 : a.w, hb = a.h > 1 ? a.h / 2 : a.h;
    int n = 0;
    out[n++] = {a.x, a.y, wl, hb, 0, 0, a.depth + 1};
    if (a.w > 1) out[n++] = {a.x + wl, a.y, a.w - wl, hb, 0, 0, a.depth + 1};
    if (a.h > 1) {
        out[n++] = {a.x, a.y + hb, wl, a.h - hb, 0, 0, a.depth + 1};
        if (a.w > 1) out[n++] = {a.x + wl, a.y + hb, a.w - wl, a.h - hb, 0, 0, a.depth + 1};
    }
    return n;
}

}  // namespace

Warnock::Class Warnock::classify(const std::vector<dvec2>& v, double x0, double y0, double x1, double y1) {
    dvec2 lo = v[0], hi = v[0];
    for (const dvec2& p : v) lo = glm::min(lo, p), hi = glm::max(hi, p);
    // Separating axes x and y: the bounding boxes' interiors do not overlap.
    if (hi.x <= x0 || lo.x >= x1 || hi.y <= y0 || lo.y >= y1) return Class::Disjoint;
    const dvec2 corners[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    bool all_inside = true;  // every corner on or inside every edge: the area is within the polygon
    const std::size_t n = v.size();
    for (std::size_t k = 0; k < n; ++k) {
        const dvec2 a = v[k], b = v[(k + 1) % n];
        int outside = 0;
        for (const dvec2& c : corners) outside += orient2d(a, b, c) <= 0;
        if (outside == 4) return Class::Disjoint;  // this edge's line separates them (touching is apart)
        for (const dvec2& c : corners) all_inside = all_inside && orient2d(a, b, c) >= 0;
    }
    if (all_inside) return Class::Surrounding;
    if (lo.x >= x0 && hi.x <= x1 && lo.y >= y0 && hi.y <= y1) return Class::Contained;
    return Class::Intersecting;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Warnock::spec() {
    static const Spec spec{
        "warnock",
        "Warnock's area subdivision",
        "Hidden Surface Removal",
        {
            "push the whole screen with every polygon",
            "while the stack is not empty: pop an area A with its polygon list",
            "    classify each polygon: surrounding, intersecting, contained or disjoint",
            "    drop the disjoint ones",
            "    if no polygon is left: A is background",
            "    else if one is left: draw its pixels in A, background elsewhere",
            "    else if a surrounding polygon is nearer than all others at A's 4 corners: fill A with it",
            "    else if A is one pixel: draw the nearest polygon at its centre",
            "    else split A at its middle; push top-right, top-left, bottom-right, bottom-left",
            "done: every pixel is drawn",
        },
        {
            {"empty", "no polygon overlaps the area: background"},
            {"single", "one polygon overlaps the area: drawn where it covers pixel centres"},
            {"surrounder", "a surrounding polygon is in front of all others: it fills the area"},
            {"pixel", "a one-pixel area: the nearest polygon at the centre is drawn"},
            {"split", "the area is not simple: split into four (or two) smaller areas"},
            {"done", "the stack is empty: every pixel is decided"},
        },
        {},  // no sliders
        {
            .predict = {
                {"split", {}},
                {"single", {}},
                {"surrounder", {}},
                {"empty", {}},
                {"pixel", {}},
            },
            .mistakes = {
                {"single", "", "event:split",
                 "kept subdividing an area that holds a single polygon"},
                {"surrounder", "", "event:split",
                 "missed the surrounding polygon in front and split"},
                {"split", "", "event:single", "drew an area with overlapping polygons as simple"},
            },
            .input_kind = "hsr-scene",
            .compare = {"ids"},
            .costs = {"areas", "classifications"},
        },
    };
    return spec;
}

void Warnock::validate(const Input& in) { hsr::validate(in.scene); }

Warnock::State Warnock::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    const auto& sc = in.scene;
    for (const auto& p : sc.polygons) {
        s.planes.push_back(hsr::plane_of(p));
        s.outlines.push_back(hsr::ccw_outline(p));
    }
    s.ids.assign(static_cast<std::size_t>(sc.width * sc.height), kUndecided);
    for (std::size_t k = 0; k < sc.polygons.size(); ++k) s.lists.push_back(static_cast<int>(k));
    s.stack.push_back({0, 0, static_cast<int>(sc.width), static_cast<int>(sc.height), 0,
                       static_cast<std::uint32_t>(sc.polygons.size()), 0});
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void Warnock::advance(State& s) {
    switch (s.phase) {
        case Phase::Area: {  // Examine the area on top of the stack
            const Area a = s.stack.back();
            s.stack.pop_back();
            s.lists.resize(a.list + a.count);  // what lies above belonged to finished areas
            s.area = a;
            s.visited.push_back(a);
            ++s.areas;
            s.polys.assign(s.lists.begin() + a.list, s.lists.end());
            s.classes.resize(s.polys.size());
            const auto base = static_cast<std::uint32_t>(s.lists.size());
            std::vector<Class> kept;
            kept.reserve(s.polys.size());
            for (std::size_t k = 0; k < s.polys.size(); ++k) {
                s.classes[k] = classify(s.outlines[s.polys[k]], a.x, a.y, a.x + a.w, a.y + a.h);
                if (s.classes[k] != Class::Disjoint) s.lists.push_back(s.polys[k]), kept.push_back(s.classes[k]);
            }
            s.classifications += static_cast<long long>(s.polys.size());
            const std::size_t count = s.lists.size() - base;
            Examiner ex{s.in, s.planes, s.outlines, s.ids};
            s.outcome = ex.decide(a, s.lists.data() + base, kept.data(), count, s.drawn);
            if (s.outcome == Outcome::Split) {
                Area q[4];
                const int n = children(a, q);
                for (int c = n - 1; c >= 0; --c) {
                    q[c].list = base, q[c].count = static_cast<std::uint32_t>(count);
                    s.stack.push_back(q[c]);
                }
            } else {
                s.lists.resize(base);
            }
            if (s.stack.empty()) s.phase = Phase::Finish;
            return;
        }
        case Phase::Finish:  // Every area is drawn
            s.outcome = Outcome::None;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string area_text(const Area& a) {
    return "[" + std::to_string(a.x) + ", " + std::to_string(a.x + a.w) + ") × [" + std::to_string(a.y) +
           ", " + std::to_string(a.y + a.h) + ")";
}

std::string area_tex(const Area& a) {
    return "[" + std::to_string(a.x) + ", " + std::to_string(a.x + a.w) + ") \\times [" +
           std::to_string(a.y) + ", " + std::to_string(a.y + a.h) + ")";
}

}  // namespace

void Warnock::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    if (s.phase == Phase::Done) {
        info.event = "done";
        info.line = kLineDone;
        info.narration = "The stack is empty: " + std::to_string(s.areas) + " areas examined with " +
                         std::to_string(s.classifications) + " polygon classifications; every pixel is drawn.";
        info.math = "\\text{areas} = " + std::to_string(s.areas) + ",\\quad \\text{classifications} = " +
                    std::to_string(s.classifications);
        info.vars = {{"areas", s.areas}, {"classifications", s.classifications}};
        return;
    }
    const Area& a = s.area;
    std::string head = "Area " + std::to_string(s.areas) + ", " + area_text(a) + " (" + std::to_string(a.w) +
                       " × " + std::to_string(a.h) + "): ";
    std::vector<std::string> by_class[4];
    for (std::size_t k = 0; k < s.polys.size(); ++k)
        by_class[static_cast<int>(s.classes[k])].push_back("P" + std::to_string(s.polys[k]));
    std::string classes;
    for (int c = 0; c < 4; ++c) {
        if (by_class[c].empty()) continue;
        std::string names;
        for (const auto& n : by_class[c]) names += (names.empty() ? "" : ", ") + n;
        classes += (classes.empty() ? "" : "; ") + names + " " + kClassName[c];
    }
    head += s.polys.empty() ? "no polygons passed down. " : classes + ". ";
    const std::string D = "P" + std::to_string(s.drawn);
    info.math = "A = " + area_tex(a);
    switch (s.outcome) {
        case Outcome::Empty:
            info.event = "empty";
            info.line = kLineEmpty;
            info.narration = head + "No polygon is left: the area is background.";
            break;
        case Outcome::Single:
            info.event = "single";
            info.line = kLineSingle;
            info.narration = head + "Only " + D + " is left: draw it at the pixel centres it covers.";
            break;
        case Outcome::Surrounder:
            info.event = "surrounder";
            info.line = kLineSurrounder;
            info.narration = head + D + " surrounds the area and is nearer than every other polygon at all four "
                             "corners (" + num(dvec2(a.x, a.y)) + ", " + num(dvec2(a.x + a.w, a.y)) + ", " +
                             num(dvec2(a.x, a.y + a.h)) + ", " + num(dvec2(a.x + a.w, a.y + a.h)) +
                             "): fill the area with it.";
            {
                std::string zs;
                for (double y : {double(a.y), double(a.y + a.h)})
                    for (double x : {double(a.x), double(a.x + a.w)})
                        zs += (zs.empty() ? "" : ", ") + tex(hsr::depth_at(s.planes[s.drawn], x, y), 4);
                info.math += ",\\quad z_{" + std::to_string(s.drawn) + "}(\\text{corners}) = " + zs;
            }
            break;
        case Outcome::Pixel: {
            info.event = "pixel";
            info.line = kLinePixel;
            const double x = a.x + 0.5, y = a.y + 0.5;
            std::string zs;
            for (std::size_t k = 0; k < s.polys.size(); ++k) {
                if (s.classes[k] == Class::Disjoint) continue;
                const int id = s.polys[k];
                if (!covers_ccw(s.outlines[id], x, y)) continue;
                zs += (zs.empty() ? "" : ", ") + std::string("z_") + std::to_string(id) + " = " +
                      num(hsr::depth_at(s.planes[id], x, y), 4);
            }
            info.narration = head + "One pixel: at its centre " + num(dvec2(x, y)) +
                             (zs.empty() ? " no polygon covers it: background."
                                         : " " + zs + ", so " + D + " is nearest and drawn.");
            info.math += ",\\quad \\text{centre } " + tex(dvec2(x, y));
            break;
        }
        default: {
            info.event = "split";
            info.line = kLineSplit;
            Area q[4];
            const int n = children(a, q);
            std::string parts;
            static constexpr const char* kFour[] = {"bottom-left", "bottom-right", "top-left", "top-right"};
            for (int c = 0; c < n; ++c) {
                const char* name = n == 4 ? kFour[c] : (a.w == 1 ? (c == 0 ? "bottom" : "top") : (c == 0 ? "left" : "right"));
                parts += (parts.empty() ? "" : ", ") + std::string(name) + " " + area_text(q[c]);
            }
            info.narration = head + "Not simple: split into " + parts + ".";
            break;
        }
    }
    info.vars = {{"area", std::vector<double>{double(a.x), double(a.y), double(a.w), double(a.h)}},
                 {"level", static_cast<long long>(a.depth)},
                 {"stack", static_cast<long long>(s.stack.size())},
                 {"areas", s.areas},
                 {"classifications", s.classifications}};
}

void Warnock::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and render] --------------------------------------------------------------------

Warnock::Result Warnock::result(const State& s) {
    Result r;
    r.width = s.in.scene.width, r.height = s.in.scene.height;
    r.ids = s.ids;
    for (int& id : r.ids) id = std::max(id, -1);  // undecided pixels show as background
    r.areas = s.areas;
    r.classifications = s.classifications;
    return r;
}

namespace {

void render_area(Examiner& ex, const Area& a, const std::vector<int>& list, Warnock::Result& r) {
    ++r.areas;
    r.classifications += static_cast<long long>(list.size());
    std::vector<int> kept;
    std::vector<Class> classes;
    for (int id : list) {
        const Class c = Warnock::classify(ex.outlines[id], a.x, a.y, a.x + a.w, a.y + a.h);
        if (c != Class::Disjoint) kept.push_back(id), classes.push_back(c);
    }
    int drawn;
    if (ex.decide(a, kept.data(), classes.data(), kept.size(), drawn) != Outcome::Split) return;
    Area q[4];
    const int n = children(a, q);
    for (int c = 0; c < n; ++c) render_area(ex, q[c], kept, r);
}

}  // namespace

Warnock::Result Warnock::render(const Input& in) {
    Result r;
    const auto& sc = in.scene;
    r.width = sc.width, r.height = sc.height;
    r.ids.assign(static_cast<std::size_t>(sc.width * sc.height), -1);
    std::vector<hsr::Plane> planes;
    std::vector<std::vector<dvec2>> outlines;
    std::vector<int> all;
    for (std::size_t k = 0; k < sc.polygons.size(); ++k) {
        planes.push_back(hsr::plane_of(sc.polygons[k]));
        outlines.push_back(hsr::ccw_outline(sc.polygons[k]));
        all.push_back(static_cast<int>(k));
    }
    Examiner ex{in, planes, outlines, r.ids};
    render_area(ex, {0, 0, static_cast<int>(sc.width), static_cast<int>(sc.height), 0, 0, 0}, all, r);
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

void Warnock::draw(const State& s, Scene& scene) {
    const auto& sc = s.in.scene;
    const int w = static_cast<int>(sc.width), h = static_cast<int>(sc.height);
    PixelGrid2 grid;
    grid.width = w, grid.height = h;
    grid.rgba.assign(s.ids.size(), 0);
    for (std::size_t a = 0; a < s.ids.size(); ++a)
        if (s.ids[a] >= 0) grid.rgba[a] = pack_rgba(sc.polygons[static_cast<std::size_t>(s.ids[a])].color);
        else if (s.ids[a] == -1) grid.rgba[a] = 0xe4e4e4ffu;  // decided: background
    scene.grids.push_back(std::move(grid));

    auto rect = [](const Area& a) {
        return std::vector<dvec2>{{double(a.x), double(a.y)}, {double(a.x + a.w), double(a.y)},
                                  {double(a.x + a.w), double(a.y + a.h)}, {double(a.x), double(a.y + a.h)}};
    };
    for (const Area& a : s.visited) scene.polygons.push_back({rect(a), {Role::Neutral, 1.0f}, true, false});

    // Polygons in their class for the area just examined: surrounding green (Kept), intersecting
    // teal (Entering), contained magenta (Leaving), disjoint or not passed down light grey dashed.
    static constexpr Role kRole[] = {Role::Kept, Role::Entering, Role::Leaving, Role::Construction};
    const bool examining = s.phase != Phase::Done && s.areas > 0;
    for (std::size_t k = 0; k < sc.polygons.size(); ++k) {
        Class c = Class::Disjoint;
        bool listed = false;
        if (examining)
            for (std::size_t q = 0; q < s.polys.size(); ++q)
                if (s.polys[q] == static_cast<int>(k)) c = s.classes[q], listed = true;
        std::vector<dvec2> outline;
        for (const auto& v : sc.polygons[k].vertices) outline.emplace_back(v.x, v.y);
        const Role role = examining ? kRole[static_cast<int>(c)] : Role::Subject;
        scene.polygons.push_back({outline, {role, 2.0f, examining && c == Class::Disjoint}, true, false});
        std::string label = "P" + std::to_string(k);
        if (examining) label += listed ? std::string(": ") + kClassName[static_cast<int>(c)] : ": not passed down";
        scene.labels.push_back({outline[0], label, {role}});
        for (std::size_t i = 0; i < outline.size(); ++i) {
            const std::string base = "/polygons/" + std::to_string(k) + "/vertices/" + std::to_string(i);
            scene.handles.push_back({outline[i], "P" + std::to_string(k) + " vertex " + std::to_string(i),
                                     base + "/0", base + "/1"});
        }
    }
    if (examining) scene.polygons.push_back({rect(s.area), {Role::Active, 3.5f}, true, false});
    for (const Area& a : s.stack) scene.polygons.push_back({rect(a), {Role::Construction, 1.0f, true}, true, false});
}

}  // namespace cg
