// The painter's algorithm, the picture. In the world, in screen pixels: the colour buffer as the
// settled polygons are painted over it back to front, every input polygon's outline (dashed,
// with handles), and while ordering the pieces of the list — P, the list's far end, orange; the Q
// it is tested against teal; pieces just made by a split orange — with the pair's verdict under
// the buffer. Beside it a chart of the list itself: one bar per piece spanning its z extent,
// in drawing order left to right, the x axis naming the places 1st, 2nd, … (settled pieces
// first, drawn ones green, then the list still to settle, a dashed line between), so that which
// z extents overlap, and why P may or may not be drawn before Q, reads off the bars.
#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "hsr/painters.hpp"

namespace cg {

namespace {

using glm::dvec2;
using Piece = Painters::Piece;
using Phase = Painters::Phase;
using Outcome = Painters::Outcome;

std::vector<dvec2> outline_of(const Piece& p) {
    std::vector<dvec2> o;
    for (const auto& v : p.vertices) o.emplace_back(v.x, v.y);
    return o;
}

// 1st, 2nd, 3rd, 4th, …, 11th, 12th, 13th, …, 21st.
std::string ordinal(std::size_t k) {
    const std::size_t ten = k % 10, hundred = k % 100;
    const char* suffix = hundred >= 11 && hundred <= 13 ? "th"
                         : ten == 1                     ? "st"
                         : ten == 2                     ? "nd"
                         : ten == 3                     ? "rd"
                                                        : "th";
    return std::to_string(k) + suffix;
}

// A piece's bar in the chart at x: its z extent, with the name over it.
void bar(Panel& chart, const Piece& p, double x, double z_span, Role role, const std::string& label,
         int priority) {
    constexpr double kHalf = 0.3;
    const double lo = p.lo.z, hi = std::max(p.hi.z, p.lo.z + z_span * 0.01);  // a flat one shows
    const bool hot = role == Role::Active || role == Role::Entering;
    chart.polygons.push_back({{{x - kHalf, lo}, {x + kHalf, lo}, {x + kHalf, hi}, {x - kHalf, hi}},
                              {role, hot ? 3.0f : 1.5f},
                              true,
                              true});
    chart.labels.push_back({{x, hi}, label, {role}, priority});
}

}  // namespace

void Painters::draw(const State& s, Scene& scene) {
    const auto& sc = s.in.scene;
    const int w = static_cast<int>(sc.width), h = static_cast<int>(sc.height);
    const double W = w, H = h;

    // The colour buffer as drawn so far.
    PixelGrid2 colour;
    colour.width = w, colour.height = h;
    colour.rgba.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
    for (std::size_t a = 0; a < s.ids.size(); ++a)
        if (s.ids[a] >= 0)
            colour.rgba[a] = pack_rgba(sc.polygons[static_cast<std::size_t>(s.ids[a])].color);
    scene.grids.push_back(std::move(colour));
    scene.polygons.push_back(
        {{{0, 0}, {W, 0}, {W, H}, {0, H}}, {Role::Construction, 1.0f}, true, false});
    scene.labels.push_back({{W / 2, H + 0.6}, "colour buffer", {Role::Neutral}});

    // Outlines: the input polygons thin (with handles); while ordering, the pieces of the list,
    // P orange and Q teal; while drawing, the polygon just drawn orange.
    for (std::size_t k = 0; k < sc.polygons.size(); ++k) {
        std::vector<dvec2> outline;
        for (const auto& v : sc.polygons[k].vertices) outline.emplace_back(v.x, v.y);
        scene.polygons.push_back({outline, {Role::Subject, 1.0f, true}, true, false});
        for (std::size_t i = 0; i < outline.size(); ++i) {
            const std::string base =
                "/polygons/" + std::to_string(k) + "/vertices/" + std::to_string(i);
            scene.handles.push_back({outline[i],
                                     "P" + std::to_string(k) + " vertex " + std::to_string(i),
                                     base + "/0", base + "/1"});
        }
    }
    const bool ordering = s.last == Phase::Pair || s.last == Phase::Settle || s.last == Phase::Sort;
    std::string p_name, q_name;
    if (s.last == Phase::Pair) p_name = s.pair.p, q_name = s.pair.q;
    if (s.last == Phase::Settle || s.last == Phase::Draw) p_name = s.name;
    auto show = [&](const Piece& p, Role role, float width) {
        const auto o = outline_of(p);
        if (o.empty()) return;
        scene.polygons.push_back({o, {role, width}, true, false});
        dvec2 centre(0);
        for (const auto& v : o) centre += v;
        scene.labels.push_back({centre / double(o.size()), p.name, {role}});
    };
    // After a split, the new pieces are shown as the ones just made (orange).
    const bool split = s.last == Phase::Pair && s.pair.outcome == Outcome::Split;
    auto made = [&](const Piece& p) {
        return split && std::find(s.made.begin(), s.made.end(), p.name) != s.made.end();
    };
    if (ordering)
        for (const Piece& p : s.list) {
            const bool hot = p.name == p_name || made(p);
            show(p, hot ? Role::Active : p.name == q_name ? Role::Entering : Role::Subject,
                 hot || p.name == q_name ? 3.0f : 1.5f);
        }
    for (const Piece& p : s.settled)
        if (p.name == p_name)
            show(p, Role::Active, 3.0f);
        else if (p.name == q_name)
            show(p, Role::Entering, 3.0f);

    // The pair's verdict, under the buffer.
    if (s.last == Phase::Pair) {
        Decision d = s.pair;
        d.outcome = Outcome::Pass;
        std::string k = test_code(d);
        if (k == "same" || k == "-") k.clear();
        const std::string what =
            s.pair.outcome == Outcome::Pass
                ? (k.empty() ? "same polygon" : "test " + k + ": " + test_name(s.pair.test))
            : s.pair.outcome == Outcome::Move
                ? "test " + k + "′: " + s.pair.q + " moves to the far end"
                : "split " + s.split_name + " by " + cut_text(s.split_cut);
        scene.labels.push_back(
            {{W / 2, -1.2},
             s.pair.p + " vs " + s.pair.q + " — " + what,
             {s.pair.outcome == Outcome::Split ? Role::Discarded : Role::Active},
             40});
    }

    // The list as a chart: settled pieces, then the list; before the sort, the input polygons.
    std::vector<Piece> input;
    if (s.settled.empty() && s.list.empty())
        for (std::size_t k = 0; k < sc.polygons.size(); ++k) {
            Piece p;
            p.name = "P" + std::to_string(k);
            p.lo = p.hi = sc.polygons[k].vertices.front();
            for (const auto& v : sc.polygons[k].vertices)
                p.lo = glm::min(p.lo, v), p.hi = glm::max(p.hi, v);
            input.push_back(std::move(p));
        }
    const std::size_t n = input.size() + s.settled.size() + s.list.size();
    if (n == 0) return;
    double zlo = 1e300, zhi = -1e300;
    for (const std::vector<Piece>* v :
         std::initializer_list<const std::vector<Piece>*>{&input, &s.settled, &s.list})
        for (const Piece& p : *v) zlo = std::min(zlo, p.lo.z), zhi = std::max(zhi, p.hi.z);
    const double span = std::max(zhi - zlo, 1e-9);
    // The x axis is a category axis: the k-th bar is the (k+1)-th drawn (or, before the sort,
    // the (k+1)-th of the input).
    Axis order{input.empty() ? "drawing order" : "input order"};
    for (std::size_t k = 1; k <= n; ++k) order.names.push_back(ordinal(k));
    Panel& chart = add_chart(scene,
                             input.empty() ? "the list: z extents in drawing order"
                                           : "z extents, not yet sorted",
                             order,
                             Axis{"z (far ↑)", zlo - 0.12 * span, zhi + 0.18 * span});
    double x = 0;
    for (const Piece& p : input) bar(chart, p, x++, span, Role::Subject, p.name, 0);
    for (std::size_t k = 0; k < s.settled.size(); ++k) {
        const Piece& p = s.settled[k];
        const Role role = p.name == p_name ? Role::Active
                          : k < s.drawn    ? Role::Kept
                                           : Role::Neutral;
        bar(chart, p, x++, span, role, p.name, p.name == p_name ? 30 : 0);
    }
    if (!s.settled.empty() && !s.list.empty())
        chart.segments.push_back({{x - 0.5, zlo - 0.12 * span},
                                  {x - 0.5, zhi + 0.18 * span},
                                  "",
                                  {Role::Construction, 1.0f, true}});
    for (const Piece& p : s.list) {
        const bool hot = p.name == p_name || made(p);
        const Role role = hot ? Role::Active : p.name == q_name ? Role::Entering : Role::Subject;
        bar(chart, p, x++, span, role, p.name + (p.marked ? " marked" : ""),
            hot || p.name == q_name ? 30 : 0);
    }
    // A legend line for each role the bars show.
    auto shows = [&](Role r) {
        return std::any_of(chart.polygons.begin(), chart.polygons.end(),
                           [&](const Polygon2& p) { return p.style.role == r; });
    };
    if (shows(Role::Kept)) chart.legend.push_back({"drawn", {Role::Kept, 2.0f}, false});
    if (shows(Role::Active))
        chart.legend.push_back({s.last == Phase::Draw ? "drawn now"
                                : split               ? "P, and the new pieces"
                                                      : "P",
                                {Role::Active, 3.0f}, false});
    if (shows(Role::Entering)) chart.legend.push_back({"Q", {Role::Entering, 3.0f}, false});
}

}  // namespace cg
