// Placing text labels: never over another label, the title or a panel's edge.
//
// Each label has an anchor (the point, the segment's middle, the arrow's tip) and a priority;
// the placer takes them highest priority first. For each it tries the places round the anchor
// (right-above first, like a textbook), then the same directions farther out with a short
// leader line back to the anchor, then the label's short form ("t_enter = 0.25" → "t_enter"),
// and takes the cheapest place that overlaps no label already placed, no region kept clear and
// does not leave the bounds; among those, covering a point marker costs more than crossing a
// line, and a leader costs a little. A label with no such place is dropped: the least important
// ones go first, since they are placed last. Greedy and simple, which is plenty for the dozens
// of labels a teaching scene has.
#pragma once

#include <imgui.h>

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "viewer/fonts.hpp"
#include "viewer/geometry.hpp"

namespace cg::viewer {

struct LayoutRecord;

// A label waiting for a place.
struct LabelRequest {
    std::string text;
    std::uint32_t rgba = 0;  // the text's colour
    int priority = 0;        // higher is placed first (label_priority)
    glm::dvec2 anchor{0, 0};
    double gap = 6;  // from the anchor to the nearest candidate, pixels
    // Candidate top-left corners, best first, instead of the places round the anchor (a
    // half-plane's label runs along its line); they get no leader.
    std::vector<glm::dvec2> corners = {};
};

struct PlacedLabel {
    std::string text;  // as drawn: the short form when that is what fitted
    Box box;           // the text's box with its halo
    std::uint32_t rgba = 0;
    int priority = 0;
    std::optional<glm::dvec2> leader;  // from the box's nearest point to the anchor
    glm::dvec2 anchor{0, 0};
};

// The priority of a label of a primitive with `style`, its own `priority` and its kind's
// `base` (points 3, free labels 2, segments 1, half-planes 0): the explicit priority counts
// most, then the role (Active first, Construction last), then the kind.
int label_priority(int priority, const Style& style, int base);

// "t_enter = 0.25" → "t_enter"; "F4 culled" → "F4"; "" when the text has no shorter form.
std::string short_form(const std::string& text);

class LabelPlacer {
  public:
    explicit LabelPlacer(const Box& bounds) : bounds_(bounds) {}

    void avoid_segment(glm::dvec2 a, glm::dvec2 b) { segments_.push_back({a, b}); }
    void avoid_box(const Box& box) { markers_.push_back(box); }
    // A region labels must not enter (the caption, the sliders, a legend).
    void keep_clear(const Box& box) { taken_.push_back(box); }

    // Places the requests, highest priority first (ties in the order given); returns those that
    // found a place. `measure` gives a text's box size, halo included.
    std::vector<PlacedLabel> place_all(
        std::vector<LabelRequest> requests,
        const std::function<glm::dvec2(const std::string&)>& measure);

    // The requests that found no place, in the order they were tried.
    const std::vector<LabelRequest>& dropped() const { return dropped_; }

    // Candidates round a point marker `gap` pixels away: right-above first, like a textbook.
    static std::vector<glm::dvec2> around(glm::dvec2 anchor, glm::dvec2 size, double gap);

  private:
    bool free(const Box& box) const;    // inside the bounds, over no label or kept-clear region
    double cost(const Box& box) const;  // what it covers: markers, then lines

    Box bounds_;
    std::vector<Span> segments_;
    std::vector<Box> markers_;
    std::vector<Box> taken_;
    std::vector<LabelRequest> dropped_;
};

// Draws placed labels: the leader, the halo, the text; records them, and the labels the placer
// dropped, when `record` is given, as lying in panel `panel`.
void paint_labels(ImDrawList* dl, const std::vector<PlacedLabel>& labels, const LabelPlacer& placer,
                  const Fonts& fonts, LayoutRecord* record, int panel);

// The text box size of a label in the canvas's label font, halo included.
glm::dvec2 label_size(const Fonts& fonts, const std::string& text);

}  // namespace cg::viewer
