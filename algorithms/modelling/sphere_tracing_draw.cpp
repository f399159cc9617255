// Sphere tracing, the picture: the slice plane holding the ray. The scene's surface f = 0 in
// that plane is traced by marching squares on a grid of f (so a union, a difference or a smooth
// blend shows as what the march really sees), the ray dashed, the marched part solid, and at
// every sample its unbounding circle (the unbounding sphere cut by the plane: radius d_k around
// p_k), the current one in orange.
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "modelling/sphere_tracing.hpp"

namespace cg {

namespace {

using Input = SphereTracing::Input;
using State = SphereTracing::State;

constexpr int kGrid = 56;    // marching-squares cells along the longer side
constexpr int kCircle = 48;  // points on an unbounding circle
constexpr int kMaxCircles = 200;

// The plane z = o.z in world x and y when the ray is horizontal; otherwise the plane through o
// spanned by d̂ and the part of "up" (y, or x for a vertical ray) across it.
struct Slice {
    glm::dvec3 o, e1, e2;
    bool world = false;
    glm::dvec2 to2(glm::dvec3 p) const { return {glm::dot(p - o, e1), glm::dot(p - o, e2)}; }
    glm::dvec3 to3(glm::dvec2 q) const { return o + q.x * e1 + q.y * e2; }
};

Slice slice_of(const Input& in, glm::dvec3 u) {
    if (u.z == 0) return {{0, 0, in.origin.z}, {1, 0, 0}, {0, 1, 0}, true};
    const glm::dvec3 up = std::abs(u.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    return {in.origin, u, glm::normalize(up - glm::dot(up, u) * u), false};
}

double bounding_radius(const SphereTracing::Shape& s) {
    switch (s.kind) {
        case SphereTracing::Kind::Sphere:
            return s.size.x;
        case SphereTracing::Kind::Box:
            return glm::length(s.size);
        case SphereTracing::Kind::Torus:
            return s.size.x + s.size.y;
    }
    return 0;
}

// f = 0 on the grid by marching squares, linear along each cell edge; a saddle cell is
// resolved by the value at its centre.
void outline(const Input& in, const Slice& sl, glm::dvec2 lo, glm::dvec2 hi, Scene& scene) {
    const double h = std::max(hi.x - lo.x, hi.y - lo.y) / kGrid;
    const int nx = std::max(1, int(std::ceil((hi.x - lo.x) / h)));
    const int ny = std::max(1, int(std::ceil((hi.y - lo.y) / h)));
    std::vector<double> f(std::size_t(nx + 1) * std::size_t(ny + 1));
    auto at = [&](int i, int j) -> double& { return f[std::size_t(j) * std::size_t(nx + 1) + i]; };
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            at(i, j) = SphereTracing::distance(in, sl.to3(lo + h * glm::dvec2(i, j)));
    const Style style{Role::Neutral, 2.5f};
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            // Corners counter-clockwise from the lower left, and the edge crossings between them.
            const std::array<glm::dvec2, 4> c = {
                lo + h * glm::dvec2(i, j), lo + h * glm::dvec2(i + 1, j),
                lo + h * glm::dvec2(i + 1, j + 1), lo + h * glm::dvec2(i, j + 1)};
            const std::array<double, 4> v = {at(i, j), at(i + 1, j), at(i + 1, j + 1),
                                             at(i, j + 1)};
            std::array<glm::dvec2, 4> x;
            int n = 0;
            for (int e = 0; e < 4; ++e) {
                const double a = v[e], b = v[(e + 1) % 4];
                if ((a < 0) != (b < 0)) {
                    x[n] = c[e] + (a / (a - b)) * (c[(e + 1) % 4] - c[e]);
                    ++n;
                }
            }
            if (n == 2) {
                scene.segments.push_back({x[0], x[1], "", style});
            } else if (n == 4) {
                const double centre = (v[0] + v[1] + v[2] + v[3]) / 4;
                // The crossings pair around the corners whose sign differs from the centre's.
                const bool pair01 = (v[1] < 0) != (centre < 0);
                scene.segments.push_back({x[0], x[pair01 ? 1 : 3], "", style});
                scene.segments.push_back({x[2], x[pair01 ? 3 : 1], "", style});
            }
        }
}

void circle(glm::dvec2 c, double r, Style style, Scene& scene) {
    Polygon2 poly{{}, style, true, false};
    poly.points.reserve(kCircle);
    for (int i = 0; i < kCircle; ++i) {
        const double a = 2 * M_PI * i / kCircle;
        poly.points.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    scene.polygons.push_back(std::move(poly));
}

}  // namespace

void SphereTracing::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Slice sl = slice_of(in, s.unit);
    const glm::dvec2 o2 = sl.to2(in.origin);
    const glm::dvec2 u2 = sl.to2(sl.o + s.unit);

    // The region: the shapes cut by the plane, the origin, and the whole march as far as it
    // stays near them (a ray escaping to t = 100 should not shrink the shapes to dots).
    glm::dvec2 lo = o2, hi = o2;
    for (const Shape& sh : in.shapes) {
        const double r = bounding_radius(sh);
        const glm::dvec2 c = sl.to2(sh.centre);
        const double off = glm::dot(sh.centre - sl.o, glm::cross(sl.e1, sl.e2));
        if (std::abs(off) > r) continue;
        lo = glm::min(lo, c - glm::dvec2(r));
        hi = glm::max(hi, c + glm::dvec2(r));
    }
    // (No shape cut by the plane: show the march itself, up to max_distance.)
    double reach = glm::length(hi - lo) * 1.2;
    if (reach == 0) reach = in.max_distance;
    const Result whole = compute(in);
    const double t_end = std::min({whole.t, in.max_distance, reach});
    lo = glm::min(lo, o2 + t_end * u2);
    hi = glm::max(hi, o2 + t_end * u2);
    const glm::dvec2 pad(0.08 * std::max(hi.x - lo.x, hi.y - lo.y) + 1e-9);
    lo -= pad;
    hi += pad;

    outline(in, sl, lo, hi, scene);

    // The ray to the region's edge, dashed; the part marched so far, solid.
    const double span = glm::length(hi - lo);
    scene.segments.push_back({o2,
                              o2 + std::min(in.max_distance, span) * u2,
                              "",
                              {Role::Construction, 1.5f, true},
                              true});
    scene.points.push_back({o2, "o", {Role::Neutral}, 4.0f});

    const std::size_t n = s.ts.size();
    const std::size_t first = n > std::size_t(kMaxCircles) ? n - kMaxCircles : 0;
    for (std::size_t j = first; j < n; ++j) {
        const bool current = j + 1 == n;
        const glm::dvec2 p = o2 + s.ts[j] * u2;
        const double d = s.ds[j];
        const Style st = d < 0     ? Style{Role::Discarded, current ? 2.0f : 1.0f}
                         : current ? Style{Role::Active, 2.0f}
                                   : Style{Role::Construction, 1.0f};
        if (std::abs(d) > 0) circle(p, std::abs(d), st, scene);
        // Labelled where the next step is long enough to keep the labels apart (p0 is "o").
        if (!current)
            scene.points.push_back({p,
                                    j > 0 && d > 0.06 * span ? "p" + std::to_string(j) : "",
                                    {Role::Neutral},
                                    3.0f});
    }
    if (n > 0) {
        const glm::dvec2 p = o2 + s.ts[n - 1] * u2;
        scene.segments.push_back({o2, p, "", {Role::Kept, 2.5f}});
        const double d = s.ds[n - 1];
        // The radius drawn, and the distance on the point's own label (a label on the radius
        // drifts away from a small circle).
        scene.segments.push_back(
            {p, p + std::abs(d) * glm::dvec2(0, 1), "", {Role::Active, 1.0f, true}});
        const std::string k = std::to_string(n - 1);
        scene.points.push_back({p, "p" + k + ": d" + k + " = " + num(d, 4), {Role::Active}, 6.0f});
    }
    if (s.phase == Phase::Done) {
        const Result r = result(s);
        const glm::dvec2 p = o2 + std::min(r.t, span) * u2;
        if (r.outcome == Outcome::Hit)
            scene.points.push_back({p, "hit, t = " + num(r.t, 4), {Role::Kept}, 7.0f});
        else
            scene.labels.push_back(
                {p,
                 r.outcome == Outcome::Escaped ? "miss: t > max_distance" : "miss: out of steps",
                 {Role::Discarded}});
    }
    if (sl.world) {
        scene.handles.push_back({o2, "origin", "/origin/0", "/origin/1"});
        for (std::size_t i = 0; i < in.shapes.size(); ++i) {
            const std::string base = "/shapes/" + std::to_string(i) + "/centre/";
            scene.handles.push_back(
                {sl.to2(in.shapes[i].centre),
                 std::string(kind_name(in.shapes[i].kind)) + " " + std::to_string(i), base + "0",
                 base + "1"});
        }
    }
}

}  // namespace cg
