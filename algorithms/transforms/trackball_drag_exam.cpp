// Virtual-sphere and arcball exam problems: a 300 × 200 or 200 × 200 viewport (the ball is the
// disc of diameter 200 at the centre, so one ball radius is 100 pixels) and two or three mouse
// samples placed where the ball coordinates are short decimals whose lift onto the sphere is
// exact (m = (0.6, 0) lifts to (0.6, 0, 0.8); (0.36, 0.48) to (0.36, 0.48, 0.8)). Now and then a
// sample lies outside the ball (the rim case), repeats the one before (no rotation), or the
// path returns to its start.
#include <array>
#include <cmath>

#include "core/format.hpp"
#include "transforms/trackball_drag.hpp"

namespace cg {

namespace {

// Ball coordinates whose sphere point is exact: z = 0.8, 0.6, 1, or on the rim.
constexpr std::array<glm::dvec2, 9> kInside = {{{0, 0},
                                                {0.6, 0},
                                                {0, 0.6},
                                                {0.8, 0},
                                                {0, 0.8},
                                                {0.36, 0.48},
                                                {0.48, 0.36},
                                                {0.48, 0.64},
                                                {0.64, 0.48}}};
constexpr std::array<glm::dvec2, 3> kOutside = {{{1.2, 0}, {1.2, 0.9}, {1.2, 0.5}}};

glm::dvec2 pick_m(Rng& rng, bool outside) {
    glm::dvec2 m = outside ? kOutside[static_cast<std::size_t>(rng.integer(0, 2))]
                           : kInside[static_cast<std::size_t>(rng.integer(0, 8))];
    if (rng.chance(0.5)) m.x = -m.x;
    if (rng.chance(0.5)) m.y = -m.y;
    return m;
}

}  // namespace

template <TrackballKind K>
typename TrackballDrag<K>::Input TrackballDrag<K>::exam_input(Rng& rng) {
    Input in;
    in.viewport = rng.chance(0.5) ? glm::dvec2(300, 200) : glm::dvec2(200, 200);
    const glm::dvec2 c = in.viewport * 0.5;
    const bool wide = in.viewport.x > in.viewport.y;
    const int n = rng.chance(0.35) ? 3 : 2;
    for (int k = 0; k < n; ++k) {
        // Outside samples need room: only the wide viewport has it (|m.x| up to 1.5).
        const bool outside = wide && rng.chance(0.2);
        glm::dvec2 m = pick_m(rng, outside);
        if (k > 0 && rng.chance(0.06)) m = (in.samples.back() - c) / 100.0;  // no motion
        in.samples.push_back(c + 100.0 * m);
    }
    if (n == 3 && rng.chance(0.3)) in.samples.back() = in.samples.front();  // a closed loop
    for (glm::dvec2& p : in.samples) p = {std::round(p.x), std::round(p.y)};
    return in;
}

template <TrackballKind K>
std::string TrackballDrag<K>::question(const Input& in) {
    std::string q = "A " + num(in.viewport.x) + " × " + num(in.viewport.y) +
                     " pixel viewport (origin bottom-left, y up) holds a ball of diameter d = "
                     "min(width, height) at its centre. The mouse is dragged through ";
    for (std::size_t k = 0; k < in.samples.size(); ++k)
        q += (k ? (k + 1 == in.samples.size() ? " and " : ", ") : "") + std::string("S") +
             std::to_string(k) + " = " + num(in.samples[k]);
    q += kArcball ? ". Using the arcball (each sample lifted onto the unit sphere, q = (s · t, s × t) "
                    "per pair; a sample outside the ball goes to its rim)"
                  : ". Using the virtual sphere (S lifted onto the unit sphere, the motion T − S "
                    "in ball units as a tangential velocity: axis s × (T − S), angle |T − S| "
                    "radians; when S is outside the ball, a turn about z by the angle S and T "
                    "make at the centre)";
    q += ", give each pair's unit axis, angle in degrees and whether the rim case applied (pairs: "
         "[{axis, angle_deg, rim}, …]), the whole drag's rotation as a unit quaternion [w, x, y, z] "
         "with w ≥ 0 (rotation), and its 3×3 matrix (matrix, rows).";
    return q;
}

template <TrackballKind K>
std::vector<std::string> TrackballDrag<K>::answer_fields() {
    return {"pairs", "rotation", "matrix"};
}

// The exam members of both instantiations (the rest are instantiated in trackball_drag.cpp).
#define CG_TRACKBALL_EXAM(K)                                                        \
    template TrackballDrag<K>::Input TrackballDrag<K>::exam_input(Rng&);            \
    template std::string TrackballDrag<K>::question(const Input&);                  \
    template std::vector<std::string> TrackballDrag<K>::answer_fields();
CG_TRACKBALL_EXAM(TrackballKind::VirtualSphere)
CG_TRACKBALL_EXAM(TrackballKind::Arcball)
#undef CG_TRACKBALL_EXAM

}  // namespace cg
