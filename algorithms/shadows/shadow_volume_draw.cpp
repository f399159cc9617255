// Shadow volumes, the picture (3D). The floor, the occluder (lit faces warm, dark faces grey;
// the face being classified orange, saying whether it faces the light), the edge being tested
// (orange: a silhouette edge between a lit and a dark face; red: an inner edge), the silhouette
// edges bold green with their translucent shadow quads (drawn down to the floor, or a fixed
// length), the light L, and the current eye ray with its surface point P, its +1/−1 crossings
// with the running count and the shadow ray at the verdict. The camera frames the occluder and
// the light (and, while a ray is walked, the eye and P).
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "shadows/shadow_volume.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Phase = ShadowVolume::Phase;
using Input = ShadowVolume::Input;
using Mesh = ShadowVolume::Mesh;
using State = ShadowVolume::State;
using Crossing = ShadowVolume::Crossing;
using Ray = ShadowVolume::Ray;

bool finite3(const dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
std::string idx(int k) {
    return std::to_string(k);
}

}  // namespace

void ShadowVolume::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const Mesh& mesh = *s.mesh;
    // The scene's size, for the quads' length and the floor's extent.
    dvec3 lo(1e300), hi(-1e300);
    auto cover = [&](const dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); };
    for (const dvec3& v : in.vertices) cover(v);
    cover(in.light);
    cover(in.eye);
    for (const dvec3& t : in.targets) cover(t);
    const double size = std::max(glm::length(hi - lo), 1e-9);
    // Where an extruded vertex is drawn: on the floor when it is below the light, else a fixed
    // length beyond the vertex.
    auto extrude = [&](const dvec3& a) {
        const dvec3 d = a - in.light;
        if (in.has_floor && in.light.y > in.floor && a.y < in.light.y && a.y >= in.floor) {
            const double u = (in.light.y - in.floor) / (in.light.y - a.y);
            if (u * glm::length(d) <= 4 * size) {
                dvec3 p = in.light + u * d;
                p.y = in.floor;
                return p;
            }
        }
        return a + d / glm::length(d) * size;
    };
    std::vector<dvec3> ends;
    for (const auto& q : s.silhouette) ends.push_back(extrude(in.vertices[q[0]]));

    if (in.has_floor) {
        dvec3 flo = lo, fhi = hi;
        for (const dvec3& e : ends) flo = glm::min(flo, e), fhi = glm::max(fhi, e);
        for (const Ray& r : s.rays)
            if (r.surface != kNone) flo = glm::min(flo, r.hit), fhi = glm::max(fhi, r.hit);
        const double m = 0.1 * size;
        const double y = in.floor;
        scene.faces3.push_back({{{flo.x - m, y, flo.z - m},
                                 {flo.x - m, y, fhi.z + m},
                                 {fhi.x + m, y, fhi.z + m},
                                 {fhi.x + m, y, flo.z - m}},
                                {Role::Window, 1.0f},
                                0.15f});
        scene.labels3.push_back({{fhi.x + m, y, fhi.z + m}, "floor", {Role::Window}});
    }

    // The occluder.
    for (std::size_t f = 0; f < in.faces.size(); ++f) {
        std::vector<dvec3> pts{in.vertices[in.faces[f][0]], in.vertices[in.faces[f][1]],
                               in.vertices[in.faces[f][2]]};
        const bool known = f < s.lit.size();
        const bool now = s.last == Phase::Face && int(f) == s.face && s.edge < 0;
        Style st{Role::Subject, now ? 2.5f : 1.0f};
        if (known) st.rgba = s.lit[f] ? 0xf2c14eff : 0x5a5a6aff;
        if (now) st.role = Role::Active;
        scene.faces3.push_back({pts, st, known ? 0.8f : 0.4f, true, true});
        if (now && known)  // the face just classified: does it face the light?
            scene.labels3.push_back({(pts[0] + pts[1] + pts[2]) / 3.0,
                                     s.lit[f] ? "faces L: lit" : "faces away: dark",
                                     {Role::Active},
                                     20});
    }
    for (std::size_t k = 0; k < in.vertices.size(); ++k)
        scene.labels3.push_back({in.vertices[k], idx(int(k)), {Role::Subject}});
    // The edge being tested.
    if (s.last == Phase::Edge && s.edge >= 0) {
        const auto& e = mesh.edges[s.edge];
        const bool sil = s.lit[e.f] != s.lit[e.g];
        scene.segments3.push_back({in.vertices[e.a],
                                   in.vertices[e.b],
                                   sil ? "silhouette: lit | dark" : "inner: both faces alike",
                                   {sil ? Role::Active : Role::Discarded, 4.0f},
                                   false,
                                   0,
                                   20});
    }

    // The silhouette and the quads.
    for (std::size_t k = 0; k < s.silhouette.size(); ++k) {
        const auto& q = s.silhouette[k];
        const dvec3 a = in.vertices[q[0]], b = in.vertices[q[1]];
        const dvec3 ea = ends[k], eb = extrude(b);
        scene.segments3.push_back({a, b, "", {Role::Kept, 4.0f}, false});
        scene.faces3.push_back(
            {{a, b, eb, ea}, {Role::Neutral, 1.0f, false, 0x303040ffu}, 0.18f, true, true});
    }

    // The light.
    scene.points3.push_back({in.light, "L", {Role::Active}, 8.0f});

    // The eye and the current ray.
    scene.points3.push_back({in.eye, "E", {Role::Window}, 6.0f});
    const bool walking = s.ray >= 0 && (s.phase == Phase::Crossing || s.phase == Phase::Verdict ||
                                        s.last == Phase::Verdict || s.last == Phase::RayStart);
    if (walking) {
        const bool finished =
            s.last == Phase::Verdict ||
            (s.last == Phase::RayStart && s.rays.size() > 0 && s.rays.back().surface == kNone &&
             s.phase != Phase::Crossing && s.phase != Phase::Verdict);
        const Ray& r = finished ? s.rays.back() : s.current;
        const int k = finished ? int(s.rays.size()) - 1 : s.ray;
        const dvec3 target = in.targets[k];
        const dvec3 d = target - in.eye;
        if (r.surface == kNone) {
            scene.segments3.push_back(
                {in.eye, in.eye + d * 1.5, "miss", {Role::Discarded, 2.0f, true}, true});
        } else {
            scene.segments3.push_back({in.eye, r.hit, "", {Role::Window, 2.0f}, false});
            // Beyond P, dashed: the crossings there are not counted.
            scene.segments3.push_back({r.hit,
                                       r.hit + d / glm::length(d) * 0.25 * size,
                                       "",
                                       {Role::Construction, 1.0f, true},
                                       false});
            const auto cs =
                finished ? crossings(in, s.silhouette, target) : std::vector<Crossing>{};
            const auto& list = finished ? cs : s.crossings;
            int shown = finished ? int(list.size()) : s.cross + 1;
            int running = r.start;
            for (int c = 0; c < int(list.size()); ++c) {
                const Crossing& x = list[c];
                const dvec3 X = in.eye + x.t * d;
                const bool before = x.t < r.t_hit;
                if (!before) {
                    scene.points3.push_back({X, "", {Role::Construction}, 3.0f});
                    continue;
                }
                if (c >= shown) {
                    scene.points3.push_back({X, "", {Role::Construction}, 3.0f});
                    continue;
                }
                running += x.sign;
                const bool now = !finished && c == s.cross;
                scene.points3.push_back({X,
                                         (x.sign > 0 ? "+1 → " : "−1 → ") + std::to_string(running),
                                         {x.sign > 0 ? Role::Entering : Role::Leaving},
                                         now ? 7.0f : 5.0f});
                if (now) {
                    const auto& q = s.silhouette[x.quad];
                    scene.segments3.push_back(
                        {in.vertices[q[0]], in.vertices[q[1]], "", {Role::Active, 5.0f}, false});
                }
            }
            const bool verdict = finished;
            scene.points3.push_back(
                {r.hit,
                 verdict ? (r.in_shadow ? "P: count " + std::to_string(r.count) + ", shadow"
                                        : "P: count 0, lit")
                         : "P",
                 {verdict ? (r.in_shadow ? Role::Discarded : Role::Kept) : Role::Active},
                 7.0f});
            if (verdict)
                scene.segments3.push_back(
                    {r.hit,
                     in.light,
                     r.shadow_ray ? "shadow ray: blocked" : "shadow ray: clear",
                     {r.shadow_ray ? Role::Discarded : Role::Kept, 1.5f, true},
                     false});
        }
    }
    // Earlier rays' surface points, small.
    const std::size_t earlier = s.rays.size() - (s.last == Phase::Verdict ? 1 : 0);
    for (std::size_t k = 0; k < earlier && k < s.rays.size(); ++k)
        if (s.rays[k].surface != kNone)
            scene.points3.push_back(
                {s.rays[k].hit, "", {s.rays[k].in_shadow ? Role::Discarded : Role::Kept}, 4.0f});
    // The camera frames the occluder and the light, and while a ray is walked its eye and
    // surface point too.
    dvec3 flo = in.light, fhi = in.light;
    for (const dvec3& v : in.vertices) flo = glm::min(flo, v), fhi = glm::max(fhi, v);
    if (walking) {
        flo = glm::min(flo, in.eye), fhi = glm::max(fhi, in.eye);
        const Ray& r = s.last == Phase::Verdict && !s.rays.empty() ? s.rays.back() : s.current;
        if (r.surface != kNone && finite3(r.hit))
            flo = glm::min(flo, r.hit), fhi = glm::max(fhi, r.hit);
    }
    if (finite3(flo) && finite3(fhi)) add_focus(scene, flo, fhi);
    drop_non_finite3(scene);
}

}  // namespace cg
