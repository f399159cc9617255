#include "viewer/labels.hpp"

#include <algorithm>

namespace cg::viewer {

namespace {

double overlap_area(const Box& a, const Box& b) {
    const double w = std::min(a.max.x, b.max.x) - std::max(a.min.x, b.min.x);
    const double h = std::min(a.max.y, b.max.y) - std::max(a.min.y, b.min.y);
    return w > 0 && h > 0 ? w * h : 0;
}

}  // namespace

double LabelPlacer::cost(const Box& box) const {
    // Weights: hiding another label is worst, then covering a marker, then crossing a line;
    // leaving the canvas hides the text altogether.
    const double area = (box.max.x - box.min.x) * (box.max.y - box.min.y);
    double c = 0;
    if (overlap_area(box, canvas_.grown(-2)) < area) c += 1000;
    for (const Box& l : labels_)
        if (l.overlaps(box)) c += 100 + 100 * overlap_area(box, l) / area;
    for (const Box& m : markers_)
        if (m.overlaps(box)) c += 30;
    const Box tight = box.grown(-1);
    for (const Span& s : segments_)
        if (clip_segment(s.first, s.second, tight)) c += 10;
    return c;
}

Box LabelPlacer::place(glm::dvec2 size, const std::vector<glm::dvec2>& corners) {
    Box best{corners.front(), corners.front() + size};
    double best_cost = cost(best);
    for (std::size_t i = 1; i < corners.size() && best_cost > 0; ++i) {
        const Box candidate{corners[i], corners[i] + size};
        const double c = cost(candidate);
        if (c < best_cost) best = candidate, best_cost = c;
    }
    labels_.push_back(best);
    return best;
}

std::vector<glm::dvec2> LabelPlacer::around(glm::dvec2 anchor, glm::dvec2 size, double gap) {
    const double d = gap * 0.7071;  // the diagonal candidates keep the same distance
    const double w = size.x, h = size.y;
    return {
        {anchor.x + d, anchor.y - d - h},              // right, above
        {anchor.x + d, anchor.y + d},                  // right, below
        {anchor.x - d - w, anchor.y - d - h},          // left, above
        {anchor.x - d - w, anchor.y + d},              // left, below
        {anchor.x + gap, anchor.y - h / 2},            // right
        {anchor.x - gap - w, anchor.y - h / 2},        // left
        {anchor.x - w / 2, anchor.y - gap - h},        // above
        {anchor.x - w / 2, anchor.y + gap},            // below
        {anchor.x + 2 * gap, anchor.y - 2 * gap - h},  // further out, when crowded
        {anchor.x - 2 * gap - w, anchor.y + 2 * gap},
    };
}

}  // namespace cg::viewer
