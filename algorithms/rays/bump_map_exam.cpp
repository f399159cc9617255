// Bump-map exam problems: "the plane z = 0 (u = x, v = y), or the unit sphere at its equator,
// carries the bumps B(u, v) = A sin(2π f u) sin(2π f v); at P give B_u, B_v (by hand: the
// derivatives), Blinn's perturbation D and the perturbed normal". A ∈ {0.05, 0.1}, f ∈ {1, 2},
// and P where the sines are 0, ±1 or ±√½ (u, v multiples of 1/8 over f), so the derivatives are
// short multiples of π. About one time in four a degenerate case: the amplitude 0 (a constant
// B leaves n unchanged), a flat spot (both derivatives 0), or the sphere's pole (no frame).
// The algorithm's own B_u, B_v are central differences with h = 1e-5: they agree with the
// derivatives to far better than the grading's three digits.
#include <array>
#include <cmath>

#include "core/format.hpp"
#include "rays/bump_map.hpp"
#include "rays/ray_quadric.hpp"

namespace cg {

namespace {

template <class T, std::size_t N>
const T& pick(Rng& rng, const std::array<T, N>& values) {
    return values[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(N) - 1))];
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

BumpMap::Input BumpMap::exam_input(Rng& rng) {
    Input in;
    HeightField& h = in.height;
    h.kind = HeightKind::Sines;
    h.amplitude = pick(rng, std::array<double, 2>{0.05, 0.1});
    const double f = pick(rng, std::array<double, 2>{1, 2});
    h.frequency = {f, f};
    h.step = 1e-5;
    const int degenerate = rng.chance(0.25) ? static_cast<int>(rng.integer(1, 3)) : 0;
    if (rng.chance(0.7)) {  // the plane z = 0
        in.surface.kind = UvKind::Plane;
        in.surface.origin = {0, 0, 0};
        in.surface.normal = {0, 0, 1};
        in.surface.u_axis = {1, 0, 0};
        in.surface.scale = 1;
        double u = static_cast<double>(rng.integer(0, 7)) / (8 * f);
        double v = static_cast<double>(rng.integer(0, 7)) / (8 * f);
        if (degenerate == 1) h.amplitude = 0;
        if (degenerate == 2) u = v = 1 / (4 * f);  // the top of a bump: flat
        in.point = {u, v, 0};
    } else {  // the unit sphere, on its equator (or, degenerate, at the pole)
        in.surface.kind = UvKind::Quadric;
        in.surface.quadric.kind = QuadricKind::Sphere;
        const double phi = 45.0 * static_cast<double>(rng.integer(-3, 4)) * kPi / 180;
        in.point = {std::cos(phi), std::sin(phi), 0};
        if (std::fabs(in.point.x) < 1e-15) in.point.x = 0;
        if (std::fabs(in.point.y) < 1e-15) in.point.y = 0;
        if (degenerate == 3) in.point = {0, 0, 1};
        if (degenerate == 1) h.amplitude = 0;
    }
    return in;
}

std::string BumpMap::question(const Input& in) {
    const HeightField& h = in.height;
    std::string s = "The ";
    const UvSurface& f = in.surface;
    if (f.kind == UvKind::Plane && f.normal == glm::dvec3(0, 0, 1) &&
        f.u_axis == glm::dvec3(1, 0, 0) && f.scale == 1 && f.origin == glm::dvec3(0.0))
        s += "plane z = 0, parametrised by u = x, v = y (P_u = (1, 0, 0), P_v = (0, 1, 0)),";
    else if (f.kind == UvKind::Plane)
        s += "plane through " + num(f.origin) + " with normal " + num(f.normal) + ", u axis " +
             num(f.u_axis) + " and scale " + num(f.scale) + " (P_u = s·a, P_v = s·(n × a)),";
    else if (f.kind == UvKind::Triangle)
        s += "triangle " + num(f.p[0]) + ", " + num(f.p[1]) + ", " + num(f.p[2]) + " with (u, v) " +
             num(f.uv[0]) + ", " + num(f.uv[1]) + ", " + num(f.uv[2]) + " at its corners,";
    else if (f.quadric.kind == QuadricKind::Sphere)
        s +=
            "sphere " + quadric_equation(f.quadric, false) +
            ", parametrised by u = ½ + φ/(2π), v = 1 − θ/π (P(u, v) = r (sin θ cos φ, sin θ sin φ, "
            "cos θ)),";
    else
        s += std::string(quadric_kind_name(f.quadric.kind)) + " " +
             quadric_equation(f.quadric, false) + ", parametrised by its angle and height,";
    switch (h.kind) {
        case HeightKind::Sines:
            s += " carries the bumps B(u, v) = " + num(h.amplitude) + "·sin(2π·" +
                 num(h.frequency.x) + "u)·sin(2π·" + num(h.frequency.y) + "v)";
            break;
        case HeightKind::Noise:
            s += " carries the bumps B(u, v) = " + num(h.amplitude) + "·noise(" +
                 num(h.frequency.x) + "u, " + num(h.frequency.y) + "v, 0) (Perlin noise, seed " +
                 std::to_string(h.seed) + ")";
            break;
        case HeightKind::Image:
            s += " carries the bumps B(u, v) = " + num(h.amplitude) + "·grey(the " +
                 std::to_string(h.image.image.width) + " × " +
                 std::to_string(h.image.image.height) + " height image, bilinear)";
            break;
    }
    s += ". At P = " + num(in.point, 4) +
         ", give B_u and B_v, the perturbed normal n' = (n + D)/|n + D| with n = P_u × P_v and "
         "D = (B_u (n × P_v) − B_v (n × P_u))/|n| (perturbed_normal), and the angle between n and "
         "n' in degrees (tilt_deg).";
    return s;
}

std::vector<std::string> BumpMap::answer_fields() {
    return {"B_u", "B_v", "perturbed_normal", "tilt_deg"};
}

}  // namespace cg
