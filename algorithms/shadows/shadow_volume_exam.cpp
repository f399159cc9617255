// Shadow volume exam problems: a tetrahedron of small integer vertices floating over the floor
// y = 0, a point light above it, an eye off to the side and one eye ray aimed at an integer point
// of the floor — in the shadow half of the time. No face is edge-on to the light, and the ray
// passes no shadow quad's edge and no corner nearly (moving the eye or the target by 10⁻⁴ changes
// nothing), so the count is unambiguous. The question asks which faces are lit, the silhouette,
// the signs of the crossings, the count and the verdict.
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "shadows/shadow_volume.hpp"

namespace cg {

namespace {

using glm::dvec3;

// The same count, crossings and verdict when the eye or the target moves a little, no face
// edge-on, the shadow ray agreeing, the ray landing on the floor.
bool clear_case(const ShadowVolume::Input& in) {
    try {
        ShadowVolume::validate(in);
    } catch (const InputError&) {
        return false;
    }
    const auto r = ShadowVolume::solve(in);
    const auto& ray = r.rays[0];
    if (ray.surface != ShadowVolume::kFloor || ray.in_shadow != ray.shadow_ray) return false;
    const auto mesh = ShadowVolume::build_mesh(in);
    for (std::size_t f = 0; f < in.faces.size(); ++f)
        if (glm::dot(mesh.normals[f], in.light - in.vertices[in.faces[f][0]]) == 0) return false;
    for (int axis = 0; axis < 3; ++axis)
        for (double h : {-1e-4, 1e-4}) {
            for (int which = 0; which < 2; ++which) {
                ShadowVolume::Input moved = in;
                if (which == 0)
                    moved.eye[axis] += h;
                else
                    moved.targets[0][axis] += axis == 1 ? 0 : h;
                const auto m = ShadowVolume::solve(moved);
                const auto& mr = m.rays[0];
                if (mr.surface != ray.surface || mr.crossings != ray.crossings ||
                    mr.count != ray.count || mr.shadow_ray != ray.shadow_ray ||
                    mr.start != ray.start)
                    return false;
            }
        }
    return true;
}

}  // namespace

ShadowVolume::Input ShadowVolume::exam_input(Rng& rng) {
    const bool want_shadow = rng.chance(0.5);
    Input best;
    for (int attempt = 0; attempt < 400; ++attempt) {
        Input in;
        const double base = double(rng.integer(1, 2));
        in.vertices.clear();
        for (int k = 0; k < 3; ++k)
            in.vertices.push_back({double(rng.integer(-2, 2)), base, double(rng.integer(-2, 2))});
        in.vertices.push_back({double(rng.integer(-1, 1)), base + double(rng.integer(1, 2)),
                               double(rng.integer(-1, 1))});
        in.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
        const dvec3 a = in.vertices[1] - in.vertices[0], b = in.vertices[2] - in.vertices[0],
                    c = in.vertices[3] - in.vertices[0];
        const double vol = glm::dot(a, glm::cross(b, c));
        if (vol == 0) continue;
        if (vol < 0)
            for (auto& f : in.faces) std::swap(f[1], f[2]);
        in.light = {double(rng.integer(-2, 2)), double(rng.integer(5, 7)),
                    double(rng.integer(-2, 2))};
        in.eye = {double(rng.integer(4, 7)), double(rng.integer(2, 5)), double(rng.integer(3, 7))};
        in.targets = {{double(rng.integer(-4, 4)), 0, double(rng.integer(-4, 4))}};
        in.has_floor = true;
        in.floor = 0;
        if (!clear_case(in)) continue;
        best = in;
        if (solve(in).rays[0].in_shadow == want_shadow) return in;
    }
    if (best.vertices.empty()) {  // never seen: a fixed clear case
        best.vertices = {{-1, 1, -1}, {1, 1, -1}, {0, 1, 1}, {0, 2, 0}};
        best.faces = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
        best.light = {0, 6, 0};
        best.eye = {5, 3, 5};
        best.targets = {{0, 0, 0}};
    }
    return best;
}

std::string ShadowVolume::question(const Input& in) {
    std::string verts, faces;
    for (std::size_t k = 0; k < in.vertices.size(); ++k)
        verts +=
            (k ? ", " : "") + std::string("v") + std::to_string(k) + " = " + num(in.vertices[k]);
    for (std::size_t f = 0; f < in.faces.size(); ++f)
        faces += (f ? ", " : "") + std::string("f") + std::to_string(f) + " = (" +
                 std::to_string(in.faces[f][0]) + ", " + std::to_string(in.faces[f][1]) + ", " +
                 std::to_string(in.faces[f][2]) + ")";
    return "A tetrahedron " + verts + " with faces " + faces +
           " (counter-clockwise seen from outside) floats over the floor y = " + num(in.floor) +
           " under a point light at L = " + num(in.light) +
           ". Which faces face the light (lit: one true/false per face, n_f · (L − a) > 0)? Which "
           "edges are silhouette edges (silhouette: each [a, b] as it runs in its lit face, in "
           "the order the faces first use them)? For the eye ray from E = " +
           num(in.eye) + " to the floor point P = " + num(in.targets[0]) +
           ", give the +1/−1 of each shadow quad it crosses before P, in order "
           "(rays/0/crossings: +1 where n_q · d < 0, n_q = (a − L) × (b − L)), the count "
           "(rays/0/count) and whether P is in shadow (rays/0/in_shadow).";
}

std::vector<std::string> ShadowVolume::answer_fields(const Input&) {
    return {"lit", "silhouette", "rays/0/crossings", "rays/0/count", "rays/0/in_shadow"};
}

}  // namespace cg
