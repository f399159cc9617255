// Liang-Barsky exam problems: a window with integer corners and a segment whose direction
// components divide the q_k evenly enough that every r_k is a short decimal (|dx|, |dy| in
// {1, 2, 4, 5, 8, 10}), so the whole table can be worked by hand. About one problem in four is
// degenerate the way exams like: parallel to an edge, through a corner, or of zero length.
#include <cmath>

#include "clipping/liang_barsky.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

double nice_delta(Rng& rng) {
    static constexpr int kSteps[] = {1, 2, 4, 5, 8, 10};
    const double d = kSteps[rng.integer(0, 5)];
    return rng.chance(0.5) ? d : -d;
}

}  // namespace

LiangBarsky::Input LiangBarsky::exam_input(Rng& rng) {
    Input in;
    in.window.xmin = static_cast<double>(rng.integer(0, 3));
    in.window.ymin = static_cast<double>(rng.integer(0, 3));
    in.window.xmax = in.window.xmin + static_cast<double>(rng.integer(3, 8));
    in.window.ymax = in.window.ymin + static_cast<double>(rng.integer(3, 6));
    const auto& w = in.window;
    in.p0 = {static_cast<double>(rng.integer(static_cast<long long>(w.xmin) - 3, static_cast<long long>(w.xmax) + 1)),
             static_cast<double>(rng.integer(static_cast<long long>(w.ymin) - 3, static_cast<long long>(w.ymax) + 1))};
    glm::dvec2 d{nice_delta(rng), nice_delta(rng)};
    switch (rng.integer(0, 11)) {
        case 0: d.x = 0; break;                        // vertical: parallel to left and right
        case 1: d.y = 0; break;                        // horizontal: parallel to bottom and top
        case 2: d = {0, 0}; break;                     // a single point
        case 3: {                                      // through the corner (xmin, ymax)
            in.p0 = {w.xmin - 2, w.ymax - 2};
            d = {4, 4};
            break;
        }
        default: break;
    }
    in.p1 = in.p0 + d;
    return in;
}

std::string LiangBarsky::question(const Input& in) {
    const auto& w = in.window;
    return "Clip the segment from P0 = " + num(in.p0) + " to P1 = " + num(in.p1) +
           " against the window [" + num(w.xmin) + ", " + num(w.xmax) + "] × [" + num(w.ymin) +
           ", " + num(w.ymax) +
           "] with the Liang-Barsky algorithm. For each edge (left, right, bottom, top) give p_k, "
           "q_k and, where p_k ≠ 0, r_k = q_k / p_k, and what the line does there (enters, leaves, "
           "parallel inside or parallel outside). "
           "Stop as soon as the segment is rejected. Then give t_enter and t_leave (at the end, or "
           "when rejected), whether any part is visible, and the clipped endpoints Q0 and Q1 "
           "(none if nothing is visible).";
}

// The table first, a row an edge tested (p, q, r where p ≠ 0, what the line does), then the
// five final values: every number the question asks for is graded.
std::vector<std::string> LiangBarsky::answer_fields(const Input& in) {
    std::vector<std::string> fields;
    for (const EdgeTest& e : clip(in).edges) {
        const std::string at = std::string("edges/") + kEdgeName[e.k] + "/";
        fields.push_back(at + "p");
        fields.push_back(at + "q");
        if (e.p != 0) fields.push_back(at + "r");
        fields.push_back(at + "crossing");
    }
    for (const char* f : {"visible", "t_enter", "t_leave", "q0", "q1"}) fields.push_back(f);
    return fields;
}

}  // namespace cg
