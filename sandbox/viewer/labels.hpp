// Placing text labels where they cover the least.
//
// Each label offers a few candidate positions beside its anchor, in order of preference; the
// placer takes the one that overlaps the fewest things already on the canvas (other labels,
// point markers, lines), preferring earlier candidates on ties. Greedy and simple, which is
// plenty for the handful of labels a teaching scene has.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "viewer/geometry.hpp"

namespace cg::viewer {

class LabelPlacer {
  public:
    explicit LabelPlacer(const Box& canvas) : canvas_(canvas) {}

    void avoid_segment(glm::dvec2 a, glm::dvec2 b) { segments_.push_back({a, b}); }
    void avoid_box(const Box& box) { markers_.push_back(box); }
    // A region labels must not enter, drawn over them later (the caption).
    void keep_clear(const Box& box) { labels_.push_back(box); }

    // Chooses among candidate top-left corners for a box of `size`, remembers it, returns it.
    Box place(glm::dvec2 size, const std::vector<glm::dvec2>& corners);

    // Candidates around a point marker `gap` pixels away: right-above first, like a textbook.
    static std::vector<glm::dvec2> around(glm::dvec2 anchor, glm::dvec2 size, double gap);

  private:
    double cost(const Box& box) const;

    Box canvas_;
    std::vector<Span> segments_;
    std::vector<Box> markers_;
    std::vector<Box> labels_;
};

}  // namespace cg::viewer
