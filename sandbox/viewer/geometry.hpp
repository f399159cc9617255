// Small 2D helpers for drawing in screen space: clipping to a box (the course's own
// Liang-Barsky and Sutherland-Hodgman, used here for real), and cutting a polygon into
// triangles so that concave polygons can be filled.
#pragma once

#include <glm/vec2.hpp>
#include <optional>
#include <utility>
#include <vector>

namespace cg::viewer {

struct Box {
    glm::dvec2 min, max;
    bool contains(glm::dvec2 p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
    }
    bool overlaps(const Box& o) const {
        return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
    }
    Box grown(double d) const { return {min - glm::dvec2(d), max + glm::dvec2(d)}; }
};

using Span = std::pair<glm::dvec2, glm::dvec2>;

// The part of segment ab inside the box, if any.
std::optional<Span> clip_segment(glm::dvec2 a, glm::dvec2 b, const Box& box);
// The part of the infinite line through p along dir inside the box, if any.
std::optional<Span> clip_line(glm::dvec2 p, glm::dvec2 dir, const Box& box);
// The part of a polygon where (x - p) . n >= 0.
std::vector<glm::dvec2> clip_polygon(const std::vector<glm::dvec2>& polygon, glm::dvec2 p,
                                     glm::dvec2 n);
std::vector<glm::dvec2> clip_polygon_to_box(std::vector<glm::dvec2> polygon, const Box& box);

// Triangles covering a simple polygon (either orientation) by ear clipping, as index
// triples; a self-intersecting polygon gets a best effort (a fan for what is left).
std::vector<int> triangulate(const std::vector<glm::dvec2>& polygon);

}  // namespace cg::viewer
