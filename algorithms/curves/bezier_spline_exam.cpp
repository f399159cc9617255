// Bézier spline exam problems, two kinds:
//   - (about half) two cubic segments with integer control points meeting at a joint that is,
//     by construction, C2, C1 but not C2, G1 with β in {1/3, 1/2, 2, 3}, C0 only, or (one time
//     in ten) broken: "which continuity holds at this joint?";
//   - (the other half) four Catmull-Rom points with integer coordinates: "give the Bézier
//     control points of the segments (the middle one is the segment between P1 and P2)".
// Both ask for the same answer fields: the segments (as given, for the first kind) and the joints.
#include <cmath>

#include "core/format.hpp"
#include "curves/bezier_spline.hpp"

namespace cg {

namespace {

// Exam problems are 2D: points with z = 0, written [x, y].
glm::dvec3 random_point(Rng& rng, int x0, int x1, int y0, int y1) {
    const double x = static_cast<double>(rng.integer(x0, x1));
    return {x, static_cast<double>(rng.integer(y0, y1)), 0};
}

std::string xy_text(glm::dvec3 p) {
    return num(glm::dvec2(p.x, p.y));
}

std::string segment_text(const BezierSpline::Segment& s, const char* letter) {
    std::string out;
    for (int i = 0; i < 4; ++i)
        out += (i ? ", " : "") + std::string(letter) + std::to_string(i) + " = " +
               xy_text(s[static_cast<std::size_t>(i)]);
    return out;
}

}  // namespace

BezierSpline::Input BezierSpline::exam_input(Rng& rng) {
    Input in;
    if (rng.chance(0.5)) {
        in.mode = Mode::CatmullRom;
        double x = static_cast<double>(rng.integer(0, 1));
        for (int i = 0; i < 4; ++i) {
            in.points.push_back({x, static_cast<double>(rng.integer(0, 6)), 0});
            x += static_cast<double>(rng.integer(2, 4));
        }
        return in;
    }
    in.mode = Mode::Segments;
    const long long kind = rng.integer(0, 9);
    Segment a, b;
    a[0] = random_point(rng, 0, 1, 0, 3);
    a[1] = random_point(rng, 1, 3, 2, 6);
    a[2] = random_point(rng, 3, 5, 1, 6);
    // A short last leg when the joint will be C1: Q2 = P1 + 4 (P3 − P2) closes the A-frame.
    if (kind <= 3)
        a[3] = a[2] + random_point(rng, 1, 2, -1, 1);
    else
        do a[3] = random_point(rng, 5, 7, 0, 5);
        while (a[3] == a[2]);
    const glm::dvec3 out = a[3] - a[2];
    b[0] = a[3];
    b[3] = a[3] + random_point(rng, 3, 5, -3, 3);
    switch (kind) {
        case 0:
        case 1:  // C2: Q1 continues the last leg, and the A-frame closes
            b[1] = b[0] + out;
            b[2] = 2.0 * b[1] - 2.0 * a[2] + a[1];
            break;
        case 2:
        case 3:  // C1, not C2
            b[1] = b[0] + out;
            do b[2] = b[1] + random_point(rng, 0, 3, -3, 3);
            while (b[2] == 2.0 * b[1] - 2.0 * a[2] + a[1]);
            break;
        case 4:
        case 5: {  // G1: the same direction, a different length (β ≠ 1)
            static constexpr double kLength[] = {2, 3, 0.5};  // Q1 − Q0 = k (P3 − P2): β = 1/k
            double k = kLength[rng.integer(0, 2)];
            if (k == 0.5 &&
                (static_cast<long long>(out.x) % 2 || static_cast<long long>(out.y) % 2))
                k = 2;
            b[1] = b[0] + k * out;
            b[2] = b[1] + random_point(rng, 0, 3, -3, 3);
            break;
        }
        case 6:
        case 7:
        case 8: {  // C0 only: a corner
            do b[1] = b[0] + random_point(rng, 1, 3, -3, 3);
            while (out.x * (b[1] - b[0]).y - out.y * (b[1] - b[0]).x == 0);
            b[2] = b[1] + random_point(rng, 0, 3, -3, 3);
            break;
        }
        default:  // broken: the second piece starts elsewhere
        {
            // The same draws as before the points became 3D: GCC evaluated the two arguments
            // of glm::dvec2(rng…, rng…) right to left, so y is drawn first.
            const double dy = static_cast<double>(rng.integer(-1, 1));
            const double dx = static_cast<double>(rng.integer(1, 2));
            b[0] = a[3] + glm::dvec3(dx, dy, 0);
        }
            b[1] = b[0] + out;
            b[2] = b[1] + random_point(rng, 0, 3, -3, 3);
            break;
    }
    in.segments = {a, b};
    return in;
}

std::string BezierSpline::question(const Input& in) {
    if (in.mode == Mode::Segments && in.segments.size() == 2)
        return "Two cubic Bézier segments are placed one after the other: P0 .. P3 with " +
               segment_text(in.segments[0], "P") + ", and Q0 .. Q3 with " +
               segment_text(in.segments[1], "Q") +
               ". Which continuity holds at the joint? For the joint give c0 (P3 = Q0), c1 (also "
               "P3 − P2 = "
               "Q1 − Q0), g1 (also P3 − P2 = β (Q1 − Q0) for some β > 0), beta (β when g1 holds, "
               "else none) "
               "and c2 (c1 and (P3 − P2) − (P2 − P1) = (Q2 − Q1) − (Q1 − Q0)). The segments of the "
               "answer "
               "are the two given.";
    std::string points;
    for (std::size_t i = 0; i < in.points.size(); ++i)
        points +=
            (i ? ", " : "") + std::string("P") + std::to_string(i) + " = " + xy_text(in.points[i]);
    return "A Catmull-Rom spline passes through " + points +
           ". Its derivatives are v_i = (P_{i+1} − P_{i−1}) / 2 inside and the one-sided "
           "differences "
           "v_0 = P1 − P0, v_N = P_N − P_{N−1} at the ends. Give the Bézier control points of "
           "every "
           "segment, [P_i, P_i + v_i/3, P_{i+1} − v_{i+1}/3, P_{i+1}] (the middle one is the "
           "segment "
           "between P1 and P2), and for each joint c0, c1, g1, beta and c2.";
}

std::vector<std::string> BezierSpline::answer_fields() {
    return {"segments", "joints"};
}

}  // namespace cg
