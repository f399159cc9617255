// Phong and Blinn-Phong lighting at a point, the picture.
// 3D: the point P on a patch of its tangent plane, n, v and the eye, every light (a point light
// where it is, a directional one as incoming rays), and for the light in hand l and the vector
// the model compares (r with v, or h with n), each at least 30 px long. When n, l and v lie in
// one plane (the course's figures) the view looks at that plane face-on, orthographic, so the
// angles of incidence and reflection read true.
// Chart: the highlight's fall-off cos^p θ against θ in degrees for the material's p (and p/4,
// 4p for comparison), its half-width where it falls to 1/2, and this light's θ on the curve.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "core/format.hpp"
#include "rays/phong_lighting.hpp"
#include "rays/quadric.hpp"  // unit()

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Phase = PhongLighting::Phase;
using Model = PhongLighting::Model;
using Light = PhongLighting::Light;

constexpr double kPi = 3.141592653589793;

std::string light_name(int k) {
    return "light " + std::to_string(k);
}

// The direction toward a light from P (as the LightDir step computes it).
dvec3 toward(const Light& L, dvec3 P) {
    return L.directional ? unit(-L.direction) : unit(L.position - P);
}

// The face-on view of the plane of n and l (else n and v) when the third vector lies in it:
// looking along l × n, n up, l on the left.
ViewHint3 plane_view(dvec3 n, dvec3 l, dvec3 v) {
    dvec3 a = l, b = v;
    if (glm::length(glm::cross(n, a)) < 1e-9) std::swap(a, b);
    const dvec3 look = glm::cross(a, n);
    if (glm::length(look) < 1e-9) return {};
    const dvec3 w = glm::normalize(look);
    if (std::fabs(glm::dot(w, b)) > 1e-6) return {};  // not one plane: the default view
    return {w, n, true};
}

}  // namespace

void PhongLighting::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const dvec3 P = in.point;
    const double size = std::max(1.0, 0.5 * glm::length(in.eye - P));
    const dvec3 n = unit(in.normal);
    const dvec3 v = unit(in.eye - P);
    const int current = s.k >= 0 && s.k < static_cast<int>(s.out.lights.size()) ? s.k : -1;

    // ---- 3D ----
    dvec3 t1 = unit(glm::cross(n, std::fabs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 t2 = glm::cross(n, t1);
    const double w = 0.6 * size;
    scene.faces3.push_back(
        {{P - w * t1 - w * t2, P + w * t1 - w * t2, P + w * t1 + w * t2, P - w * t1 + w * t2},
         {Role::Subject, 1.0f},
         0.3f,
         true,
         false});
    scene.points3.push_back({P, "P", {Role::Subject}, 6.0f});
    scene.points3.push_back({in.eye, "eye", {Role::Neutral}, 5.0f});
    const bool view_step = s.last == Phase::View && s.phase != Phase::View;
    const Role nv_role = view_step ? Role::Active : Role::Neutral;
    scene.segments3.push_back({P, P + size * n, "n", {nv_role, 2.0f}, true, 30.0f});
    scene.segments3.push_back(
        {P, P + size * v, "v", {view_step ? Role::Active : Role::Window, 2.0f}, true, 30.0f});
    scene.segments3.push_back({P, in.eye, "", {Role::Construction, 1.0f, true}, false});

    // Framed on P with its vectors and the eye; a light is framed when it is near.
    dvec3 lo = P - dvec3(1.1 * size), hi = P + dvec3(1.1 * size);
    lo = glm::min(lo, in.eye), hi = glm::max(hi, in.eye);
    for (int i = 0; i < static_cast<int>(in.lights.size()); ++i) {
        const Light& L = in.lights[i];
        const Role role =
            i == current && s.phase != Phase::Done ? Role::Active : Role::Construction;
        if (L.directional) {
            const dvec3 d = unit(L.direction);
            const dvec3 from = P - 1.8 * size * d;
            scene.segments3.push_back(
                {from, from + 0.8 * size * d, light_name(i) + " (sun)", {role, 1.5f}, true});
            lo = glm::min(lo, from), hi = glm::max(hi, from);
        } else {
            scene.points3.push_back({L.position, light_name(i), {role}, 7.0f});
            scene.segments3.push_back({L.position, P, "", {role, 1.0f, true}, false});
            if (glm::length(L.position - P) <= 4 * size)
                lo = glm::min(lo, L.position), hi = glm::max(hi, L.position);
        }
    }
    add_focus(scene, lo, hi);
    if (current >= 0) {
        const LightTerms& t = s.out.lights[current];
        scene.segments3.push_back({P, P + size * t.l, "l", {Role::Active, 2.5f}, true, 30.0f, 2});
        if (s.last == Phase::Specular || s.phase == Phase::Done || s.phase == Phase::LightDir) {
            if (in.model == Model::Phong)
                scene.segments3.push_back(
                    {P, P + size * t.r, "r", {Role::Kept, 2.5f}, true, 30.0f, 2});
            else if (t.h != dvec3(0.0))
                scene.segments3.push_back(
                    {P, P + size * t.h, "h", {Role::Kept, 2.5f}, true, 30.0f, 2});
        }
    }
    scene.extent3 = 1.5 * size;
    if (!in.lights.empty()) {
        const int k = current >= 0 ? current : 0;
        scene.view3 = plane_view(n, toward(in.lights[k], P), v);
    }

    // ---- the chart: cos^p θ against θ in degrees ----
    const double p = in.material.shininess;
    const bool phong = in.model == Model::Phong;
    Panel& chart = add_chart(scene,
                             phong ? "the highlight cos^p θ, θ between r and v"
                                   : "the highlight cos^p θ, θ between n and h",
                             Axis{"θ (°)", -90, 90}, Axis{"cos^p θ", 0, 1.08});
    chart.weight = 1.5;
    auto curve = [&](double pp, Style style, const std::string& name) {
        std::vector<dvec2> pts;
        for (int i = 0; i <= 180; ++i) {
            const double deg = -90.0 + i, c = std::cos(deg * kPi / 180);
            pts.push_back({deg, std::pow(std::max(c, 0.0), pp)});
        }
        add_line(chart, std::move(pts), style, name);
    };
    const double big = 4 * std::max(p, 0.25);
    if (p > 0) curve(p / 4, {Role::Construction, 1.0f, true}, "p = " + num(p / 4, 3));
    curve(big, {Role::Subject, 1.0f}, "p = " + num(big, 3));
    curve(p, {Role::Active, 2.5f}, "p = " + num(p, 3));
    // Half-width: cos^p θ = 1/2 at θ = acos(2^(−1/p)).
    if (p > 0) {
        const double half = std::acos(std::pow(0.5, 1 / p)) * 180 / kPi;
        chart.segments.push_back({{-half, 0.5},
                                  {half, 0.5},
                                  "half-width " + num(half, 3) + "°",
                                  {Role::Active, 1.5f, true},
                                  false,
                                  1});
    }
    if (current >= 0 && (s.last == Phase::Specular || s.phase == Phase::Done) &&
        s.out.lights[current].n_dot_l > 0) {
        const LightTerms& t = s.out.lights[current];
        const double c = phong ? t.r_dot_v : t.n_dot_h;
        const double deg = std::acos(std::clamp(c, -1.0, 1.0)) * 180 / kPi;
        if (deg <= 90)
            chart.points.push_back({{deg, std::pow(std::max(c, 0.0), p)},
                                    light_name(current) + ": θ = " + num(deg, 3) + "°",
                                    {Role::Kept},
                                    6.0f,
                                    2});
    }
}

}  // namespace cg
