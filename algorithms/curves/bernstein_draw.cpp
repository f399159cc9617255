// Bernstein polynomials, the picture. The world: the control polygon (points coloured as their
// basis functions, sized by their weight once the point is known; a negative weight red), the
// curve (dashed beyond [0, 1] when extrapolating), the convex hull once it is tested, P(t), and
// with a transform the mapped polygon and curve with T(P(t)). Beside it a chart of every
// B_i^n(t) over the parameter range, the line u = t, and the values found so far as dots on it.
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "core/format.hpp"
#include "curves/bernstein.hpp"
#include "curves/bezier.hpp"

namespace cg {

namespace {

using curves::point_name;
using Phase = Bernstein::Phase;

double ipow(double x, int k) {
    double r = 1;
    for (int j = 0; j < k; ++j) r *= x;
    return r;
}

std::string basis_name(int i, int n) {
    return "B" + curves::subscript(i) + curves::superscript(n);
}

}  // namespace

void Bernstein::draw(const State& s, Scene& scene) {
    const int n = static_cast<int>(s.in.control_points.size()) - 1;
    const double t = s.in.t;
    const auto& pts = s.in.control_points;
    std::vector<glm::dvec3> control;
    for (glm::dvec2 p : pts) control.push_back({p.x, p.y, 0});
    const bool weighted = s.phase >= Phase::Hull;  // the point is known: size points by weight

    std::vector<glm::dvec2> mapped;
    if (s.in.transform)
        for (glm::dvec2 p : pts) mapped.push_back(apply(*s.in.transform, p));
    const double u0 = std::min(t, 0.0), u1 = std::max(t, 1.0);
    // The values plotted: [0, 1], widened when extrapolation makes the polynomials leave it.
    double v0 = 0, v1 = 1;
    std::vector<std::vector<glm::dvec2>> curves(static_cast<std::size_t>(n + 1));
    for (int j = 0; j <= 100; ++j) {
        const double u = u0 + (u1 - u0) * j / 100;
        for (int i = 0; i <= n; ++i) {
            const double b = curves::binomial(n, i) * ipow(1 - u, n - i) * ipow(u, i);
            curves[static_cast<std::size_t>(i)].push_back({u, b});
            v0 = std::min(v0, b), v1 = std::max(v1, b);
        }
    }

    // The curve side: the hull under everything, the curve, the control polygon.
    if (s.phase >= Phase::Affine)
        scene.polygons.push_back({s.hull, {Role::Window, 1.5f}, true, true});
    scene.polygons.push_back(
        {curves::bezier_polyline(control, 0, 1), {Role::Construction, 3.0f}, false, false});
    if (t < 0 || t > 1)
        scene.polygons.push_back({curves::bezier_polyline(control, u0, u1),
                                  {Role::Construction, 2.0f, true},
                                  false,
                                  false});
    scene.polygons.push_back({pts, {Role::Subject, 1.5f}, false, false});
    if (s.in.transform) {  // the mapped control polygon and its curve
        std::vector<glm::dvec3> image;
        for (glm::dvec2 p : mapped) image.push_back({p.x, p.y, 0});
        scene.polygons.push_back(
            {curves::bezier_polyline(image, 0, 1), {Role::Construction, 3.0f}, false, false});
        scene.polygons.push_back({mapped, {Role::Leaving, 1.5f}, false, false});
        for (int i = 0; i <= n; ++i)
            scene.points.push_back({mapped[static_cast<std::size_t>(i)],
                                    "T(" + point_name(i) + ")",
                                    {Role::Leaving},
                                    3.5f});
    }
    for (int i = 0; i <= n; ++i) {
        const double b = s.basis[static_cast<std::size_t>(i)];
        // Sized by the weight once the point is known; a negative weight (extrapolating) in red.
        const float radius =
            weighted ? static_cast<float>(3 + 10 * std::min(std::fabs(b), 1.5)) : 4.5f;
        const bool negative = weighted && b < 0;
        scene.points.push_back(
            {pts[static_cast<std::size_t>(i)],
             point_name(i) + (negative ? ": weight < 0" : ""),
             {Role::Discarded, 1.5f, false, negative ? 0u : curves::shade(i + 1)},
             radius});
    }
    if (weighted)
        scene.points.push_back(
            {s.point,
             "P(" + num(t, 4) + ")",
             {s.inside_hull || s.phase == Phase::Hull ? Role::Kept : Role::Discarded},
             6.0f});
    if (s.phase == Phase::Done && s.in.transform) {
        scene.points.push_back({s.image_of_point, "T(P(t)) = Σ B·T(P)", {Role::Entering}, 8.0f});
        scene.points.push_back({s.transformed_point, "", {Role::Kept}, 4.0f});
    }

    // The chart: every B_i^n over the parameter range, the line u = t, the values so far (the
    // newest, the step's subject, placed first).
    Panel& chart = add_chart(scene,
                             basis_name(0, n) + "(t) … " + basis_name(n, n) + "(t) at t = " +
                                 num(t, 4),
                             Axis{"t", u0, u1}, Axis{"B(t)", v0, v1});
    for (int i = 0; i <= n; ++i) {
        const bool known = i <= s.i;
        add_line(chart, curves[static_cast<std::size_t>(i)],
                 {Role::Neutral, known ? 2.0f : 1.0f, false, curves::shade(i + 1)});
    }
    chart.segments.push_back({{t, v0}, {t, v1}, "", {Role::Active, 1.5f, true}, false});
    for (int i = 0; i <= s.i; ++i) {
        const double b = s.basis[static_cast<std::size_t>(i)];
        const bool newest = i == s.i && s.phase <= Phase::Sum;
        chart.points.push_back({{t, b},
                                basis_name(i, n) + " = " + num(b, 3),
                                {Role::Neutral, 1.5f, false, curves::shade(i + 1)},
                                newest ? 6.0f : 4.5f,
                                newest ? 60 : 0});
    }

    for (int i = 0; i <= n; ++i) {
        const std::string base = "/control_points/" + std::to_string(i) + "/";
        scene.handles.push_back(
            {pts[static_cast<std::size_t>(i)], point_name(i), base + "0", base + "1"});
    }
}

}  // namespace cg
