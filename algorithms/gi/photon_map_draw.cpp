// Photon mapping, the picture (3D). The objects (glass spheres blue, mirrors grey, diffuse
// surfaces as large translucent squares), the lights, and the stored photons coloured by their
// power (dim red to bright yellow; caustic photons larger). Emitting: the last photon's path
// in orange. Building: the node's splitting plane across its box and its median photon.
// Searching: the query point x, the photons in the heap (green) and, once the heap holds k,
// the sphere of radius r that the estimate E(x) ≈ Σ Φ_p / (π r²) uses. The camera frames the
// step's subject — the path, the node's box, or x's neighbourhood.
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/vec.hpp"
#include "gi/photon_map.hpp"

namespace cg {

using glm::dvec3;

namespace {

// A circle of radius r about c in the plane spanned by the unit a and b.
void circle(cg::Scene& scene, dvec3 c, dvec3 a, dvec3 b, double r, Style st) {
    constexpr int kSegments = 24;
    constexpr double kStep = 2 * 3.14159265358979323846 / kSegments;
    for (int i = 0; i < kSegments; ++i) {
        const double t0 = i * kStep, t1 = (i + 1) * kStep;
        scene.segments3.push_back({c + r * (std::cos(t0) * a + std::sin(t0) * b),
                                   c + r * (std::cos(t1) * a + std::sin(t1) * b), "", st});
    }
}

void sphere(cg::Scene& scene, dvec3 c, double r, Style st) {
    circle(scene, c, {1, 0, 0}, {0, 1, 0}, r, st);
    circle(scene, c, {0, 1, 0}, {0, 0, 1}, r, st);
    circle(scene, c, {0, 0, 1}, {1, 0, 0}, r, st);
}

// Power as colour: dim red to bright yellow, relative to the largest photon's.
std::uint32_t heat(double t) {
    t = std::clamp(t, 0.0, 1.0);
    const auto r = std::uint32_t(160 + 95 * t), g = std::uint32_t(40 + 200 * t),
               b = std::uint32_t(30);
    return (r << 24) | (g << 16) | (b << 8) | 0xffu;
}

}  // namespace

void PhotonMap::draw(const State& s, cg::Scene& scene) {
    const Input& in = *s.in;
    const World& w = *s.world;
    const double L = w.extent;
    scene.extent3 = 1.2 * L;
    for (std::size_t i = 0; i < in.objects.size(); ++i) {
        const Object& o = in.objects[i];
        const Style st{o.material == Material::Glass    ? Role::Window
                       : o.material == Material::Mirror ? Role::Construction
                                                        : Role::Subject,
                       1.5f};
        if (o.shape == Shape::Sphere) {
            sphere(scene, o.center, o.radius, st);
        } else {
            const dvec3 n = unit(o.normal);
            const dvec3 a = std::fabs(n.x) < 0.5 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
            const dvec3 t1 = unit(glm::cross(n, a)), t2 = glm::cross(n, t1);
            const dvec3 c = o.center - glm::dot(o.center, t1) * t1 - glm::dot(o.center, t2) * t2;
            scene.faces3.push_back({{c - L * t1 - L * t2, c + L * t1 - L * t2, c + L * t1 + L * t2,
                                     c - L * t1 + L * t2},
                                    st,
                                    0.15f,
                                    true,
                                    true});
        }
    }
    for (std::size_t l = 0; l < in.lights.size(); ++l)
        scene.points3.push_back(
            {in.lights[l].position, "L" + std::to_string(l), {Role::Active}, 6});

    // The stored photons, coloured by power; caustic photons drawn larger.
    double pmax = 0;
    for (const Photon& p : s.photons) pmax = std::max(pmax, p.power);
    scene.points3.reserve(scene.points3.size() + s.photons.size() + 2);
    for (const Photon& p : s.photons)
        scene.points3.push_back({p.position,
                                 "",
                                 {Role::Neutral, 1, false, heat(p.power / pmax)},
                                 p.caustic ? 3.0f : 2.0f});

    if (s.last == Phase::Emit && s.path.photon >= 0) {  // the last photon's path
        dvec3 a = s.path.origin;
        for (const Bounce& b : s.path.bounces) {
            scene.segments3.push_back({a, b.point, "", {Role::Active, 2}, true});
            a = b.point;
        }
    }
    if (s.last == Phase::Build) {  // the node's splitting plane across its box
        const Node& n = s.node;
        const int a = n.axis, b = (a + 1) % 3, c = (a + 2) % 3;
        // A flat box (photons all on the floor) gets some height, so the plane shows as one.
        dvec3 lo = n.box_lo, hi = n.box_hi;
        for (int i : {b, c}) {
            const double pad = std::max(0.0, 0.05 * L - (hi[i] - lo[i])) / 2;
            lo[i] -= pad, hi[i] += pad;
        }
        auto corner = [&](double u, double v) {
            dvec3 p;
            p[a] = n.split, p[b] = u, p[c] = v;
            return p;
        };
        scene.faces3.push_back({{corner(lo[b], lo[c]), corner(hi[b], lo[c]), corner(hi[b], hi[c]),
                                 corner(lo[b], hi[c])},
                                {Role::Window, 2},
                                0.3f,
                                true,
                                true});
        scene.points3.push_back({s.photons[std::size_t(s.order[std::size_t(n.m)])].position,
                                 "median",
                                 {Role::Active},
                                 5});
    }
    if (s.last == Phase::Query || s.last == Phase::Estimate) {
        scene.points3.push_back({in.query, "x", {Role::Active}, 6});
        for (const Neighbour& n : s.heap)
            scene.points3.push_back(
                {s.photons[std::size_t(n.photon)].position, "", {Role::Kept}, 5});
        if (s.at >= 0 && s.last == Phase::Query)
            scene.points3.push_back({s.photons[std::size_t(s.at)].position, "", {Role::Active}, 5});
        if (int(s.heap.size()) == s.k && s.r2 > 0)
            sphere(scene, in.query, std::sqrt(s.r2), {Role::Kept, 2.5f});
    }

    // The camera frames what the step is about: the photon's path (emitting), the node's box
    // (building), the query's neighbourhood (searching) — each at least 0.6 of the scene's radius
    // across, so the surfaces around stay in sight; before any step, the objects — with the lights.
    dvec3 lo(1e300), hi(-1e300);
    auto cover = [&](const dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); };
    if (s.last == Phase::Emit && s.path.photon >= 0) {
        cover(s.path.origin);
        for (const Bounce& b : s.path.bounces) cover(b.point);
    } else if (s.last == Phase::Build) {
        cover(s.node.box_lo), cover(s.node.box_hi);
    } else if (s.last == Phase::Query || s.last == Phase::Estimate || s.last == Phase::Done) {
        const double r = int(s.heap.size()) == s.k && s.r2 > 0 ? std::sqrt(s.r2) : 0.0;
        cover(in.query - dvec3(r)), cover(in.query + dvec3(r));
    } else {
        for (const Object& o : in.objects)
            if (o.shape == Shape::Sphere)
                cover(o.center - dvec3(o.radius)), cover(o.center + dvec3(o.radius));
        cover(in.query);
    }
    if (!(lo.x <= hi.x)) return;
    const dvec3 mid = (lo + hi) / 2.0, half = glm::max((hi - lo) / 2.0, dvec3(0.3 * L));
    lo = mid - half, hi = mid + half;
    for (const Light& l : in.lights) cover(l.position);  // the lights, always in sight
    add_focus(scene, lo, hi);
}

}  // namespace cg
