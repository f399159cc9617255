// Ray-quadric intersection, the picture.
// 3D: the surface as a translucent mesh around the action (its model frame M when it is
// transformed), the ray E + t d as an arrow, its roots on it (the chosen one green, the refused
// ones red), the hit P and the normal n (at least 30 px long). The camera frames the ray and
// the surface.
// Chart: f(t) = a t² + b t + c in its own units (t across, f up), f(0) = F(E) at the eye, the
// vertex with Δ once the discriminant is known, and the roots on the t axis.
// The step's subject is orange: the ray, then f(t), the vertex, the roots, P, n.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "rays/quadric_mesh.hpp"
#include "rays/ray_quadric.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Phase = RayQuadric::Phase;
using Verdict = RayQuadric::Verdict;

std::string root_name(const QuadraticRoots& r, int i) {
    return r.count == 1 ? "t" : (i == 0 ? "t₁" : "t₂");
}

// "t² − 16t + 60", "t − 3": the polynomial as a person writes it.
std::string poly_text(double a, double b, double c) {
    std::string out;
    auto term = [&](double k, const char* power) {
        if (k == 0) return;
        const bool unit = *power && std::fabs(k) == 1;
        const std::string mag = unit ? "" : num(std::fabs(k), 4);
        if (out.empty())
            out = (k < 0 ? "−" : "") + mag + power;
        else
            out += (k < 0 ? " − " : " + ") + mag + power;
    };
    term(a, "t²");
    term(b, "t");
    term(c, "");
    return out.empty() ? "0" : out;
}

Role verdict_role(Verdict v, Role pending) {
    if (v == Verdict::Chosen) return Role::Kept;
    if (v == Verdict::Behind || v == Verdict::OutsideSlab) return Role::Discarded;
    if (v == Verdict::Farther) return Role::Construction;
    return pending;
}

}  // namespace

void RayQuadric::draw(const State& s, Scene& scene) {
    const Quadric& q = s.in->quadric;
    const double L = largest_param(q);
    const bool solved = s.last >= Phase::Roots;
    const bool have_quad = s.last >= Phase::Coefficients;
    const bool have_roots = s.last >= Phase::Roots && s.roots.count > 0;

    // Where along the ray is worth drawing: up to past the farthest root, or a few sizes.
    const RayQuadratic model = ray_quadratic(prepare(q), s.in->origin, s.in->direction);
    double t_far = 0;
    if (have_roots) t_far = std::max(t_far, s.roots.t[s.roots.count - 1]);
    const double speed = std::max(glm::length(model.direction), 1e-300);
    if (t_far <= 0) t_far = (glm::length(model.origin) + 2 * L) / speed;
    const double t_end = 1.2 * t_far;

    // ---- 3D ----
    // The surface's z range in model space: around the roots and the eye, within the slab.
    double reach = 2 * L;
    if (have_roots)
        for (int i = 0; i < s.roots.count; ++i)
            reach = std::max(reach,
                             1.25 * std::fabs(model.origin.z + s.roots.t[i] * model.direction.z));
    reach = std::min(reach, 50 * L);
    double z_lo, z_hi;
    drawn_z_range(q, reach, z_lo, z_hi);
    const std::size_t first_face = scene.faces3.size();
    add_quadric_mesh(q, z_lo, z_hi, {Role::Subject, 1.0f}, 0.18f, 24, 12, scene.faces3);
    if (s.phase != Phase::ToModel && s.prepared.transformed) {
        const glm::dmat4& m = q.world_from_model;
        scene.frames3.push_back({dvec3(m[3]), dvec3(m[0]), dvec3(m[1]), dvec3(m[2]), L, "M", 0.8f});
    }

    const dvec3 E = s.in->origin, d = s.in->direction;
    const bool ray_active = s.phase == Phase::ToModel || s.last == Phase::ToModel;
    scene.segments3.push_back(
        {E, E + t_end * d, "E + t d", {ray_active ? Role::Active : Role::Neutral, 2.0f}, true});
    scene.points3.push_back({E, "E", {ray_active ? Role::Active : Role::Neutral}, 5.0f});
    const bool roots_active = s.last == Phase::Roots;
    const bool have_point = s.last >= Phase::HitPoint && s.hit.hit;
    if (have_roots) {
        for (int i = 0; i < s.roots.count; ++i) {
            const double t = s.roots.t[i];
            const Role role =
                verdict_role(s.verdict[i], roots_active ? Role::Active : Role::Entering);
            if (t < 0)  // the line behind the eye, dashed, to reach a root there
                scene.segments3.push_back(
                    {E, E + t * d, "", {Role::Construction, 1.0f, true}, false});
            // The chosen root is P once the point is computed: one label for one thing.
            const bool is_p = have_point && s.verdict[i] == Verdict::Chosen;
            // At a singular point (a cone's apex) the normal step has nothing to draw but P.
            const bool no_normal = is_p && s.last == Phase::Normal && !s.hit.has_normal;
            const std::string name = no_normal ? "P: ∇F = 0, no normal"
                                     : is_p    ? "P"
                                               : root_name(s.roots, i);
            const bool active = is_p && (s.last == Phase::HitPoint || no_normal);
            scene.points3.push_back(
                {E + t * d, name, {active ? Role::Active : role}, 6.0f, is_p ? 2 : 0});
        }
    }
    if (s.last == Phase::Normal && s.hit.has_normal)
        scene.segments3.push_back({s.hit.point,
                                   s.hit.point + 0.8 * L * s.hit.normal,
                                   "n",
                                   {Role::Active, 2.5f},
                                   true,
                                   30.0f,
                                   3});
    scene.extent3 = std::max(3 * L, glm::length(E) * 1.1);

    // Framed on the ray (from the eye to past its last root) and the surface drawn around it.
    dvec3 lo = glm::min(E, E + t_far * d), hi = glm::max(E, E + t_far * d);
    if (have_roots && s.roots.t[0] < 0) {
        lo = glm::min(lo, E + s.roots.t[0] * d);
        hi = glm::max(hi, E + s.roots.t[0] * d);
    }
    for (std::size_t i = first_face; i < scene.faces3.size(); ++i)
        for (const dvec3& p : scene.faces3[i].points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    add_focus(scene, lo, hi);

    // ---- the chart: f(t) over a range holding the eye (t = 0), the roots and the vertex ----
    if (!have_quad) return;
    const RayQuadratic& f = s.quad;
    double t_lo = 0, t_hi = t_far;
    if (s.roots.count > 0 && solved) {
        t_lo = std::min(t_lo, s.roots.t[0]);
        t_hi = std::max(t_hi, s.roots.t[s.roots.count - 1]);
    }
    const double vertex_t = f.a != 0 ? -f.b / (2 * f.a) : NAN;
    if (std::isfinite(vertex_t) && std::fabs(vertex_t) < 1e6 * std::max(1.0, t_hi - t_lo))
        t_lo = std::min(t_lo, vertex_t), t_hi = std::max(t_hi, vertex_t);
    if (!(t_hi > t_lo)) t_hi = t_lo + 1;
    const double pad = 0.15 * (t_hi - t_lo);
    t_lo -= pad, t_hi += pad;
    auto at = [&](double t) { return (f.a * t + f.b) * t + f.c; };
    constexpr int kSamples = 120;
    std::vector<dvec2> curve;
    for (int i = 0; i <= kSamples; ++i) {
        const double t = t_lo + (t_hi - t_lo) * i / kSamples;
        const double v = at(t);
        if (std::isfinite(v)) curve.push_back({t, v});  // not only for absurdly long rays
    }
    // f's range with 0 in it (the roots' line), padded so that a dot on f = 0 is whole.
    double f_lo = 0, f_hi = 0;
    for (const dvec2& p : curve) f_lo = std::min(f_lo, p.y), f_hi = std::max(f_hi, p.y);
    const double f_pad = f_hi > f_lo ? 0.08 * (f_hi - f_lo) : 1;
    Panel& chart = add_chart(scene, "f(t) = F(E + t d) = " + poly_text(f.a, f.b, f.c),
                             Axis{"t", t_lo, t_hi}, Axis{"f(t)", f_lo - f_pad, f_hi + f_pad});
    chart.weight = 1.3;
    const bool curve_active = s.last == Phase::Coefficients;
    add_line(chart, curve, {curve_active ? Role::Active : Role::Subject, 2.5f});
    // The eye: f(0) = c = F(E), its sign says inside or outside.
    chart.points.push_back({{0, f.c}, "eye: f(0) = " + num(f.c, 4), {Role::Neutral}, 4.5f});

    if (s.last == Phase::Discriminant) {
        // The step's question: does the parabola (or line) reach f = 0?
        const char* flat = s.roots.kind == QuadraticCase::Linear       ? "a = 0: a line"
                           : s.roots.kind == QuadraticCase::NoSolution ? "a = b = 0: no t"
                           : s.roots.kind == QuadraticCase::InSurface  ? "f ≡ 0: every t"
                                                                       : nullptr;
        if (flat) {
            const double t = (t_lo + t_hi) / 2;
            chart.points.push_back({{t, at(t)}, flat, {Role::Active}, 4.0f, 3});
        } else if (std::isfinite(vertex_t)) {
            const double D = s.roots.discriminant;
            const std::string sign = D > 0 ? " > 0" : D < 0 ? " < 0" : "";
            chart.points.push_back(
                {{vertex_t, at(vertex_t)}, "Δ = " + num(D, 4) + sign, {Role::Active}, 6.0f, 3});
        }
    }
    if (solved)
        for (int i = 0; i < s.roots.count; ++i) {
            const Role role =
                verdict_role(s.verdict[i], roots_active ? Role::Active : Role::Entering);
            chart.points.push_back({{s.roots.t[i], 0},
                                    root_name(s.roots, i) + " = " + num(s.roots.t[i], 4),
                                    {role},
                                    6.0f,
                                    2});
        }
}

}  // namespace cg
