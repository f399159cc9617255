#include "viewer/labels.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "viewer/canvas_draw.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/layout.hpp"
#include "viewer/palette.hpp"

namespace cg::viewer {

namespace {

double overlap_area(const Box& a, const Box& b) {
    const double w = std::min(a.max.x, b.max.x) - std::max(a.min.x, b.min.x);
    const double h = std::min(a.max.y, b.max.y) - std::max(a.min.y, b.min.y);
    return w > 0 && h > 0 ? w * h : 0;
}

int role_rank(Role role) {
    switch (role) {
        case Role::Active:
            return 6;
        case Role::Entering:
        case Role::Leaving:
            return 5;
        case Role::Kept:
        case Role::Discarded:
            return 4;
        case Role::Window:
            return 3;
        case Role::Subject:
        case Role::Neutral:
        case Role::Count:
            return 2;
        case Role::Construction:
            return 1;
    }
    return 2;
}

// The nearest point of `box` to `p`.
glm::dvec2 nearest_on(const Box& box, glm::dvec2 p) {
    return glm::clamp(p, box.min, box.max);
}

// Costs of the fallbacks, against what a place covers (a marker 30, a line 10).
constexpr double kLeaderCost = 25, kFartherCost = 40, kShortCost = 60;

}  // namespace

int label_priority(int priority, const Style& style, int base) {
    return priority * 100 + role_rank(style.role) * 10 + base;
}

std::string short_form(const std::string& text) {
    for (const char* sep : {" = ", "=", " ≈ ", ": ", " ("}) {
        const auto at = text.find(sep);
        if (at != std::string::npos && at > 0) return text.substr(0, at);
    }
    const auto space = text.find(' ');
    if (space != std::string::npos && space > 0) return text.substr(0, space);
    return {};
}

bool LabelPlacer::free(const Box& box) const {
    const Box inner = bounds_.grown(-2);
    if (box.min.x < inner.min.x || box.min.y < inner.min.y || box.max.x > inner.max.x ||
        box.max.y > inner.max.y)
        return false;
    for (const Box& t : taken_)
        if (t.overlaps(box)) return false;
    return true;
}

double LabelPlacer::cost(const Box& box) const {
    double c = 0;
    const double area = std::max((box.max.x - box.min.x) * (box.max.y - box.min.y), 1.0);
    for (const Box& m : markers_)
        if (m.overlaps(box)) c += 30 + 30 * overlap_area(box, m) / area;
    const Box tight = box.grown(-1);
    for (const Span& s : segments_)
        if (clip_segment(s.first, s.second, tight)) c += 10;
    return c;
}

std::vector<glm::dvec2> LabelPlacer::around(glm::dvec2 anchor, glm::dvec2 size, double gap) {
    const double d = gap * 0.7071;  // the diagonal candidates keep the same distance
    const double w = size.x, h = size.y;
    return {
        {anchor.x + d, anchor.y - d - h},        // right, above
        {anchor.x + d, anchor.y + d},            // right, below
        {anchor.x - d - w, anchor.y - d - h},    // left, above
        {anchor.x - d - w, anchor.y + d},        // left, below
        {anchor.x + gap, anchor.y - h / 2},      // right
        {anchor.x - gap - w, anchor.y - h / 2},  // left
        {anchor.x - w / 2, anchor.y - gap - h},  // above
        {anchor.x - w / 2, anchor.y + gap},      // below
    };
}

std::vector<PlacedLabel> LabelPlacer::place_all(
    std::vector<LabelRequest> requests,
    const std::function<glm::dvec2(const std::string&)>& measure) {
    std::stable_sort(
        requests.begin(), requests.end(),
        [](const LabelRequest& a, const LabelRequest& b) { return a.priority > b.priority; });
    std::vector<PlacedLabel> placed;
    for (LabelRequest& r : requests) {
        if (r.text.empty()) continue;
        r.text = text_minus(r.text);  // one minus sign, as in the narration
        struct Best {
            double cost = DBL_MAX;
            Box box{};
            bool leader = false, shortened = false;
        } best;
        auto consider = [&](const Box& box, double extra, bool leader, bool shortened) {
            if (extra >= best.cost || !free(box)) return;
            const double c = extra + cost(box);
            if (c < best.cost) best = {c, box, leader, shortened};
        };
        const std::string short_text = short_form(r.text);
        const glm::dvec2 size = measure(r.text);
        if (!r.corners.empty()) {
            for (glm::dvec2 c : r.corners) {
                consider({c, c + size}, 0, false, false);
                if (best.cost == 0) break;
            }
        } else {
            // Near the anchor; farther out with a leader; farther still; then the short form.
            const double rings[] = {r.gap, r.gap * 2 + 14, r.gap * 3 + 34};
            const double extras[] = {0, kLeaderCost, kFartherCost};
            for (int ring = 0; ring < 3 && best.cost > extras[ring]; ++ring)
                for (glm::dvec2 c : around(r.anchor, size, rings[ring])) {
                    consider({c, c + size}, extras[ring], ring > 0, false);
                    if (best.cost == extras[ring]) break;
                }
        }
        glm::dvec2 short_size{0, 0};
        if (best.cost > kShortCost && !short_text.empty()) {
            short_size = measure(short_text);
            for (int ring = 0; ring < 2; ++ring)
                for (glm::dvec2 c : around(r.anchor, short_size, ring ? r.gap * 2 + 14 : r.gap))
                    consider({c, c + short_size}, kShortCost + (ring ? kLeaderCost : 0), ring > 0,
                             true);
        }
        if (best.cost == DBL_MAX) {  // no place: dropped
            dropped_.push_back(std::move(r));
            continue;
        }
        taken_.push_back(best.box);
        PlacedLabel p{best.shortened ? short_text : std::move(r.text),
                      best.box,
                      r.rgba,
                      r.priority,
                      {},
                      r.anchor};
        if (best.leader) p.leader = nearest_on(best.box, r.anchor);
        placed.push_back(std::move(p));
    }
    return placed;
}

glm::dvec2 label_size(const Fonts& fonts, const std::string& text) {
    const ImVec2 s = fonts.ui->CalcTextSizeA(fonts.ui->FontSize, FLT_MAX, 0, text.c_str());
    return {s.x + 6, s.y + 2};  // with the halo's padding
}

void paint_labels(ImDrawList* dl, const std::vector<PlacedLabel>& labels, const LabelPlacer& placer,
                  const Fonts& fonts, LayoutRecord* record, int panel) {
    const float size = fonts.ui->FontSize;
    for (const PlacedLabel& l : labels) {
        if (l.leader)
            dl->AddLine(im(l.anchor), im(*l.leader), im_colour(with_alpha(l.rgba, 0x90)), 1.0f);
        dl->AddRectFilled(im(l.box.min), im(l.box.max), im_colour(kLabelHalo), 3.0f);
        dl->AddText(fonts.ui, size, im(l.box.min + glm::dvec2(3, 1)), im_colour(l.rgba),
                    l.text.c_str());
        if (record) record->labels.push_back({l.text, l.box, panel, l.priority});
    }
    if (record)
        for (const LabelRequest& r : placer.dropped())
            record->dropped.push_back(
                {r.text, {r.anchor - glm::dvec2(1), r.anchor + glm::dvec2(1)}, panel, r.priority});
}

}  // namespace cg::viewer
